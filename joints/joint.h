/*
** joint.h: joint functions (thesis table 3.3; docs/joints.md).
**
** A joint combines two badness values: min, harmonic, product, sum,
** root-sum-square, max (the l_p "norms" for p = -inf, -1, 0, 1, 2, inf).
** For measures with values <= 0 the four finite-p joints are applied to
** |x|, |y| and the result negated; min and max are used as they are.
**
** Every joint also has a "key": a strictly increasing map phi of the
** measure's domain with phi(f(x, y)) = phi(x) (+) phi(y), where (+) is
** addition for the finite-p joints and min / max for the others.  The GOT
** dynamic programme works with keys so that long chains neither overflow
** (products of thousands of values) nor pay a sqrt per step.
*/
#ifndef FLIPLAB_JOINT_H
#define FLIPLAB_JOINT_H

#include <math.h>
#include <stddef.h>

/* The built-in joints keep ids 0 .. JOINT_COUNT-1; the power means l_p of
** other exponents (joint_find) get the ids from JOINT_COUNT up, in the
** order they are first named, below JOINT_CAPACITY (arrays indexed by a
** joint id have JOINT_CAPACITY entries; joint_count() ids are defined now). */
typedef enum joint_id {
  JOINT_MIN,       /* l_-inf */
  JOINT_HARMONIC,  /* l_-1 */
  JOINT_PRODUCT,   /* l_0 */
  JOINT_SUM,       /* l_1 */
  JOINT_RSS,       /* l_2 */
  JOINT_MAX,       /* l_inf */
  JOINT_COUNT      /* the built-in joints */
} joint_id;

#define JOINT_CAPACITY 16
#define JOINT_NAME_MAX 16   /* bytes of a joint name, its NUL included */

/* How keys combine. */
typedef enum joint_keyop { JOINT_KEY_ADD, JOINT_KEY_MIN, JOINT_KEY_MAX } joint_keyop;

/* The key K on magnitudes u >= 0 (see "Keys" above): phi(x) = K(x) for
** measures >= 0, -K(-x) for measures <= 0. */
typedef enum joint_shape {
  JOINT_SHAPE_SAME,      /* K(u) = u (min, max, sum) */
  JOINT_SHAPE_NEGRECIP,  /* -1/u (harmonic) */
  JOINT_SHAPE_LOG,       /* log u (product) */
  JOINT_SHAPE_SQUARE,    /* u^2 (root-sum-square) */
  JOINT_SHAPE_POWER      /* u^p for p > 0, -u^p for p < 0 (a power mean) */
} joint_shape;

/* The form the vector engines of classify/ compute a joint in (their
** rewrites are written for these); JOINT_VEC_NONE: no fast path, each
** quadrilateral is decided by joint_compare. */
typedef enum joint_vec {
  JOINT_VEC_MIN, JOINT_VEC_MAX, JOINT_VEC_SUM, JOINT_VEC_PRODUCT, JOINT_VEC_HARMONIC,
  JOINT_VEC_RSS, JOINT_VEC_NONE
} joint_vec;

/* One row of the joint table: everything any part of fliplab knows about
** a joint. */
typedef struct joint {
  const char *name;     /* command-line suffix: "-inf", "-1", "0", "1", "2", "inf", "3" */
  const char *symbol;   /* "l_-inf" ... */
  const char *desc;
  int needs_sign;       /* 1 if the measure must keep one sign (applied to magnitudes) */
  joint_keyop keyop;
  const char *word;     /* one word for tables: "min", "harmonic", ... */
  const char *colour;   /* its colour in pictures (Okabe-Ito, colour-blind safe) */
  double p;             /* the l_p exponent: -inf, -1, 0, 1, 2, inf, or a power mean's */
  joint_shape key;      /* the key's shape */
  const char *key_units;   /* what the keys of a total add up ("sums of squares"),
                              NULL when a key is the value itself or its logarithm */
  joint_vec vec;        /* the vector engines' form */
  int split;            /* joint_compare decides in split form (joint_apply_split) */
  int bounds;           /* joint_compare_bounds can certify verdicts */
} joint;

/* The row of id j, NULL for an id no joint has. */
const joint *joint_get(joint_id j);
/* The id of a joint name: a built-in one, or a real p written as a decimal
** number ("3", "-2", "0.5", "1.0e1"), the power mean l_p (docs/joints.md):
** a p of -1, 0, 1 or 2 is the built-in joint, any other one a row made on
** first use.  -1 if the name is no joint, or names a new p when the table
** is full; joint_parse says which in err. */
int joint_find(const char *name);
int joint_parse(const char *name, char *err, size_t errlen);
int joint_count(void);
/* "-inf, -1, 0, 1, 2, inf" into buf: the built-in names, for messages. */
void joint_names(char *buf, size_t len);

/* f(x, y) for a measure of sign s (+1: values >= 0, -1: values <= 0). */
double joint_apply(joint_id j, int s, double x, double y);
/* The identity e with f(e, x) = x for every x of the domain of sign s. */
double joint_identity(joint_id j, int s);

/* ---- deciding between two joint values --------------------------------
**
** joint_compare_values(a, b, eps): the spec's comparison of two joint
** values: 0 (a tie) when a == b (equal infinities included), either is NaN,
** or both are finite with |a - b| <= eps max(|a|, |b|); otherwise -1 when
** a < b, +1 when a > b.  A finite value never ties with an infinite one.
**
** joint_compare(j, s, x1, y1, x2, y2, eps) is joint_compare_values(f(x1,
** y1), f(x2, y2), eps) for the joint f = joint_apply(j, s, ., .), decided
** as if f were computed with an unbounded exponent: the product and the
** root-sum-square of two doubles can underflow or overflow (areas of 1e-170
** multiply to 0; R = 2^600 squares to inf) and then decide nothing, so
** those two are computed in split form, a mantissa in [1/4, 2) and a
** binary exponent (joint_apply_split), and the two values scaled by the
** same power of two before comparing.  Whenever the plain double
** evaluation neither underflows nor overflows, scaling by powers of two is
** exact, so the decision is the plain one bit for bit (the flip-graph
** engine relies on that: it decides plainly and calls joint_compare only
** for lanes whose values left the normal range).  The other four joints
** cannot leave the range for the values of built-in measures inside the
** coordinate contract (geom.h) and are evaluated plainly. */
int joint_compare_values(double a, double b, double tie_eps);
int joint_compare(joint_id j, int s, double x1, double y1, double x2, double y2,
                  double tie_eps);
/* ---- deciding from enclosures ------------------------------------------
**
** joint_compare_bounds(j, s, lo, hi, eps) decides joint_compare(j, s, x1,
** y1, x2, y2, eps) < 0 for every x1, y1, x2, y2 with lo[k] <= (the k-th of
** them) <= hi[k]: JOINT_LESS when it holds for every choice, JOINT_NOT_LESS
** when it holds for none, JOINT_UNSURE otherwise, and always for the
** joints without enclosures (joint_has_bounds: only min, max and sum, whose
** computed values are monotone in each argument).  A certified verdict is
** the one joint_compare would give on the exact values, bit for bit; a
** caller evaluates those only when the answer is JOINT_UNSURE. */
typedef enum joint_verdict { JOINT_UNSURE, JOINT_LESS, JOINT_NOT_LESS } joint_verdict;
joint_verdict joint_compare_bounds(joint_id j, int s, const double lo[4], const double hi[4],
                                   double tie_eps);
int joint_has_bounds(joint_id j);

/* f(x, y) = m * 2^*e (m = joint_apply(j, s, x, y) and *e = 0 for the
** joints that need no split, and whenever an argument is 0, infinite or NaN). */
double joint_apply_split(joint_id j, int s, double x, double y, int *e);

/* Keys: phi, its inverse, and the identity in key space. */
double joint_key(joint_id j, int s, double x);
double joint_unkey(joint_id j, int s, double k);
double joint_key_identity(joint_id j);

/* The definitions of joint_key and joint_unkey by the row's shape and p,
** inline for loops that key many values (the census's sinks: called with a
** constant shape, each gets its own loop).  With K the key on magnitudes
** (u >= 0: u, -1/u, log u, u^2, +-u^p), a measure of sign -1 takes -K(-x)
** (joint_key's comment in joint.c says why); the identity keys need no
** sign case, -(-x) being x bit for bit. */
static inline double joint_key_power(double p, double u) {
  return p > 0 ? pow(u, p) : -pow(u, p);
}
static inline double joint_unkey_power(double p, double k) {
  return p > 0 ? pow(k, 1 / p) : pow(-k, 1 / p);
}
static inline double joint_key_shape(joint_shape sh, double p, int s, double x) {
  switch (sh) {
    case JOINT_SHAPE_SAME: return x;
    case JOINT_SHAPE_NEGRECIP: return s >= 0 ? -1.0 / x : -(-1.0 / -x);
    case JOINT_SHAPE_LOG: return s >= 0 ? log(x) : -log(-x);
    case JOINT_SHAPE_SQUARE: return s >= 0 ? x * x : -((-x) * (-x));
    case JOINT_SHAPE_POWER: return s >= 0 ? joint_key_power(p, x) : -joint_key_power(p, -x);
  }
  return x;
}
static inline double joint_unkey_shape(joint_shape sh, double p, int s, double k) {
  switch (sh) {
    case JOINT_SHAPE_SAME: return k;
    case JOINT_SHAPE_NEGRECIP: return s >= 0 ? -1.0 / k : -(-1.0 / -k);
    case JOINT_SHAPE_LOG: return s >= 0 ? exp(k) : -exp(-k);
    case JOINT_SHAPE_SQUARE: return s >= 0 ? sqrt(k) : -sqrt(-k);
    case JOINT_SHAPE_POWER: return s >= 0 ? joint_unkey_power(p, k) : -joint_unkey_power(p, -k);
  }
  return k;
}
static inline double joint_key_combine(joint_keyop op, double k1, double k2) {
  return op == JOINT_KEY_ADD ? k1 + k2
       : op == JOINT_KEY_MIN ? (k1 < k2 ? k1 : k2)
                             : (k1 > k2 ? k1 : k2);
}

#endif
