/*
** joint.c: the six joint functions, their identities and their keys.
**
** Each finite-p joint is written once, for values >= 0 (the "magnitude"
** form g); the sign convention of the spec is then f(x, y) = s g(s x, s y)
** for a measure of sign s.  Negation is exact, and every g below is exactly
** commutative in floating point (x + y == y + x, x * y == y * x, ...), which
** the flip rules need for bit-for-bit independence of the vertex order.
*/
#include <math.h>
#include <string.h>
#include "joint.h"

static double joint_min(double x, double y) { return x < y ? x : y; }
static double joint_max(double x, double y) { return x > y ? x : y; }
/* 1/(1/x + 1/y), and 0 when either is 0: 1/0 = inf makes the sum inf and
** the result 0 without a special case.  +inf is the identity, returned
** exactly: 1/(1/x) is not always x in floating point. */
static double joint_harmonic(double x, double y) {
  if (x == INFINITY) return y;
  if (y == INFINITY) return x;
  return 1.0 / (1.0 / x + 1.0 / y);
}
static double joint_product(double x, double y) { return x * y; }
static double joint_sum(double x, double y) { return x + y; }
static double joint_rss(double x, double y) { return sqrt(x * x + y * y); }

/* Keys for the magnitude form (x >= 0); see joint_key for the signed form. */
static double joint_key_harmonic(double x) { return -1.0 / x; }
static double joint_unkey_harmonic(double k) { return -1.0 / k; }
static double joint_key_identity_fn(double x) { return x; }
static double joint_key_square(double x) { return x * x; }

typedef struct joint_impl {
  joint pub;
  double (*g)(double, double);
  double identity;                  /* of g on values >= 0 */
  double (*key)(double);            /* increasing on values >= 0 */
  double (*unkey)(double);
} joint_impl;

static const joint_impl joint_table[JOINT_COUNT] = {
  [JOINT_MIN] = {{"-inf", "l_-inf", "min(x, y)", 0, JOINT_KEY_MIN, "min", "#0072B2"},
                 joint_min, INFINITY, joint_key_identity_fn, joint_key_identity_fn},
  [JOINT_HARMONIC] = {{"-1", "l_-1", "1/(1/x + 1/y), harmonic", 1, JOINT_KEY_ADD, "harmonic", "#E69F00"},
                      joint_harmonic, INFINITY, joint_key_harmonic, joint_unkey_harmonic},
  [JOINT_PRODUCT] = {{"0", "l_0", "x*y, product (geometric)", 1, JOINT_KEY_ADD, "product", "#009E73"},
                     joint_product, 1.0, log, exp},
  [JOINT_SUM] = {{"1", "l_1", "x + y, sum", 1, JOINT_KEY_ADD, "sum", "#D55E00"},
                 joint_sum, 0.0, joint_key_identity_fn, joint_key_identity_fn},
  [JOINT_RSS] = {{"2", "l_2", "sqrt(x^2 + y^2), root-sum-square", 1, JOINT_KEY_ADD,
                 "root-sum-sq", "#CC79A7"},
                 joint_rss, 0.0, joint_key_square, sqrt},
  [JOINT_MAX] = {{"inf", "l_inf", "max(x, y)", 0, JOINT_KEY_MAX, "max", "#56B4E9"},
                 joint_max, -INFINITY, joint_key_identity_fn, joint_key_identity_fn},
};

const joint *joint_get(joint_id j) {
  return (unsigned)j < JOINT_COUNT ? &joint_table[j].pub : NULL;
}

int joint_find(const char *name) {
  for (int j = 0; j < JOINT_COUNT; j++)
    if (strcmp(joint_table[j].pub.name, name) == 0) return j;
  return -1;
}

double joint_apply(joint_id j, int s, double x, double y) {
  const joint_impl *J = &joint_table[j];
  if (!J->pub.needs_sign || s >= 0) return J->g(x, y);
  return -J->g(-x, -y);
}

double joint_identity(joint_id j, int s) {
  const joint_impl *J = &joint_table[j];
  if (!J->pub.needs_sign || s >= 0) return J->identity;
  return -J->identity;
}

/* For s = -1 the finite-p joints are f(x, y) = -g(|x|, |y|).  With K the
** magnitude key (increasing, K(g(u, v)) = K(u) + K(v)), phi(x) = -K(-x) is
** increasing in x and adds the same way, since the leading minus turns
** "larger magnitude" into "smaller value". */
double joint_key(joint_id j, int s, double x) {
  const joint_impl *J = &joint_table[j];
  if (!J->pub.needs_sign || s >= 0) return J->key(x);
  return -J->key(-x);
}

double joint_unkey(joint_id j, int s, double k) {
  const joint_impl *J = &joint_table[j];
  if (!J->pub.needs_sign || s >= 0) return J->unkey(k);
  return -J->unkey(-k);
}

double joint_key_identity(joint_id j) {
  switch (joint_table[j].pub.keyop) {
    case JOINT_KEY_MIN: return INFINITY;
    case JOINT_KEY_MAX: return -INFINITY;
    default: return 0.0;
  }
}
