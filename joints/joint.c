/*
** joint.c: the joint table: the six built-in joints, the power means l_p
** made on first use, their identities and their keys.
**
** Each finite-p joint is written once, for values >= 0 (the "magnitude"
** form g); the sign convention of the spec is then f(x, y) = s g(s x, s y)
** for a measure of sign s.  Negation is exact, and every g below is exactly
** commutative in floating point (x + y == y + x, x * y == y * x, ...), which
** the flip rules need for bit-for-bit independence of the vertex order.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "geom.h"
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

/* The power mean l_p for a real p other than -inf, -1, 0, 1, 2, inf (the
** built-in rows), |p| >= 1/512:  g(u, v) = (u^p + v^p)^(1/p) on magnitudes.
** With big = max(u, v), small = min(u, v) and r = small / big in [0, 1],
**   p > 0:  u^p + v^p = big^p (1 + r^p),      g = big (1 + r^p)^(1/p);
**   p < 0:  u^p + v^p = small^p (1 + r^|p|),  g = small (1 + r^|p|)^(1/p);
** so g = base * c, c = (1 + r^|p|)^(1/p) in [1, 2^(1/p)] or [2^(1/p), 1]:
** within 2^(+-512), so nothing overflows or underflows before the last
** product (u^p itself would, for R = 1e30 and p = 11), and the split form
** (joint_power_split) multiplies c by the mantissa of base instead.  For
** p > 0, 0 is the identity (r = 0 gives c = 1 exactly) and +inf absorbs;
** for p < 0, +inf is the identity, returned exactly as the harmonic joint
** returns it, and 0 absorbs.  NaN gives NaN.  Only max, min and the
** symmetric r enter, so g is exactly commutative. */
static int joint_power_special(double p, double u, double v, double *g) {
  if (isnan(u) || isnan(v)) return *g = NAN, 1;
  double big = joint_max(u, v), small = joint_min(u, v);
  if (p > 0 && !(big > 0 && big < INFINITY)) return *g = big > 0 ? INFINITY : 0.0, 1;
  if (p < 0 && u == INFINITY) return *g = v, 1;
  if (p < 0 && v == INFINITY) return *g = u, 1;
  if (p < 0 && !(small > 0)) return *g = 0.0, 1;
  return 0;
}

static double joint_power_c(double p, double u, double v, double *base) {
  double big = joint_max(u, v), small = joint_min(u, v);
  *base = p > 0 ? big : small;
  return pow(1 + pow(small / big, fabs(p)), 1 / p);
}

static double joint_power(double p, double u, double v) {
  double g, base;
  if (joint_power_special(p, u, v, &g)) return g;
  double c = joint_power_c(p, u, v, &base);
  return base * c;
}

/* g = m 2^e with m = fm c, base = fm 2^e (frexp, exact): m lies in
** [2^-513, 2^512], a normal double, and fl(base c) = fl(fm c) 2^e whenever
** fl(base c) is normal itself: the plain value scaled, as for l_0 and l_2. */
static double joint_power_split(double p, double u, double v, int *e) {
  double g, base;
  *e = 0;
  if (joint_power_special(p, u, v, &g)) return g;
  double c = joint_power_c(p, u, v, &base);
  return frexp(base, e) * c;
}

/* One row of the table: the public part, the joint on magnitudes, its
** identity, and room for the names of a row made at run time. */
typedef struct joint_impl {
  joint pub;
  double (*g)(double p, double x, double y);   /* on values >= 0 */
  double identity;                  /* of g on values >= 0 */
  char text[4][80];                 /* name, symbol, description, key units of a made row */
} joint_impl;

static double joint_g_min(double p, double x, double y) { (void)p; return joint_min(x, y); }
static double joint_g_max(double p, double x, double y) { (void)p; return joint_max(x, y); }
static double joint_g_harmonic(double p, double x, double y) { (void)p; return joint_harmonic(x, y); }
static double joint_g_product(double p, double x, double y) { (void)p; return joint_product(x, y); }
static double joint_g_sum(double p, double x, double y) { (void)p; return joint_sum(x, y); }
static double joint_g_rss(double p, double x, double y) { (void)p; return joint_rss(x, y); }
static double joint_g_power(double p, double x, double y) { return joint_power(p, x, y); }

/* The table: the six built-in joints at their fixed ids; rows from
** JOINT_COUNT up are power means, made by joint_parse (joint_power_row). */
static joint_impl joint_table[JOINT_CAPACITY] = {
  [JOINT_MIN] = {{.name = "-inf", .symbol = "l_-inf", .desc = "min(x, y)", .needs_sign = 0,
                  .keyop = JOINT_KEY_MIN, .word = "min", .colour = "#0072B2", .p = -INFINITY,
                  .key = JOINT_SHAPE_SAME, .vec = JOINT_VEC_MIN, .bounds = 1},
                 joint_g_min, INFINITY, {""}},
  [JOINT_HARMONIC] = {{.name = "-1", .symbol = "l_-1", .desc = "1/(1/x + 1/y), harmonic",
                       .needs_sign = 1, .keyop = JOINT_KEY_ADD, .word = "harmonic",
                       .colour = "#E69F00", .p = -1, .key = JOINT_SHAPE_NEGRECIP,
                       .key_units = "-sums of reciprocals", .vec = JOINT_VEC_HARMONIC},
                      joint_g_harmonic, INFINITY, {""}},
  [JOINT_PRODUCT] = {{.name = "0", .symbol = "l_0", .desc = "x*y, product (geometric)",
                      .needs_sign = 1, .keyop = JOINT_KEY_ADD, .word = "product",
                      .colour = "#009E73", .p = 0, .key = JOINT_SHAPE_LOG,
                      .vec = JOINT_VEC_PRODUCT, .split = 1},
                     joint_g_product, 1.0, {""}},
  [JOINT_SUM] = {{.name = "1", .symbol = "l_1", .desc = "x + y, sum", .needs_sign = 1,
                  .keyop = JOINT_KEY_ADD, .word = "sum", .colour = "#D55E00", .p = 1,
                  .key = JOINT_SHAPE_SAME, .vec = JOINT_VEC_SUM, .bounds = 1},
                 joint_g_sum, 0.0, {""}},
  [JOINT_RSS] = {{.name = "2", .symbol = "l_2", .desc = "sqrt(x^2 + y^2), root-sum-square",
                  .needs_sign = 1, .keyop = JOINT_KEY_ADD, .word = "root-sum-sq",
                  .colour = "#CC79A7", .p = 2, .key = JOINT_SHAPE_SQUARE,
                  .key_units = "sums of squares", .vec = JOINT_VEC_RSS, .split = 1},
                 joint_g_rss, 0.0, {""}},
  [JOINT_MAX] = {{.name = "inf", .symbol = "l_inf", .desc = "max(x, y)", .needs_sign = 0,
                  .keyop = JOINT_KEY_MAX, .word = "max", .colour = "#56B4E9", .p = INFINITY,
                  .key = JOINT_SHAPE_SAME, .vec = JOINT_VEC_MAX, .bounds = 1},
                 joint_g_max, -INFINITY, {""}},
};
static int joint_nrows = JOINT_COUNT;

const joint *joint_get(joint_id j) {
  return (unsigned)j < (unsigned)joint_nrows ? &joint_table[j].pub : NULL;
}

int joint_count(void) {
  return joint_nrows;
}

void joint_names(char *buf, size_t len) {
  size_t used = 0;
  if (len > 0) buf[0] = '\0';
  for (int j = 0; j < JOINT_COUNT && used < len; j++)
    used += (size_t)snprintf(buf + used, len - used, "%s%s", j ? "," : "", joint_table[j].pub.name);
}

int joint_find(const char *name) {
  char err[160];
  int j = joint_parse(name, err, sizeof err);
  return j >= 0 ? j : -1;
}

double joint_apply(joint_id j, int s, double x, double y) {
  const joint_impl *J = &joint_table[j];
  if (!J->pub.needs_sign || s >= 0) return J->g(J->pub.p, x, y);
  return -J->g(J->pub.p, -x, -y);
}

/* ---- comparisons ---------------------------------------------------------- */

int joint_compare_values(double a, double b, double tie_eps) {
  if (a == b || isnan(a) || isnan(b)) return 0;
  /* a, b are not NaN here, so the larger magnitude by a plain comparison is
  ** fmax's value, without libm's call. */
  double ma = fabs(a), mb = fabs(b);
  if (!isinf(a) && !isinf(b) && fabs(a - b) <= tie_eps * (ma > mb ? ma : mb)) return 0;
  return a < b ? -1 : 1;
}

/* g on magnitudes u, v >= 0 in split form, g = m 2^e.
** Product: u = fu 2^eu, v = fv 2^ev with fu, fv in [1/2, 1) (frexp, exact),
** so u v = (fu fv) 2^(eu+ev) and fl(fu fv), in [1/4, 1), is normal: it is
** fl(u v) scaled by 2^-(eu+ev) whenever fl(u v) is normal itself.
** Root-sum-square: with k the larger binary exponent, su = u 2^-k and
** sv = v 2^-k are at most 1, the larger at least 1/2, so su^2 + sv^2 is in
** [1/4, 2]: it cannot overflow, and only a term below 2^-1022 of the other
** (which no rounding of the sum could see) can underflow.  sqrt scales by
** exactly 2^-k, so again the result is the plain one scaled, whenever the
** plain one is computed without underflow or overflow.  Otherwise (an
** argument inf or NaN, a 0 in a product, both 0): no split (e = 0), the
** plain arithmetic of joint.c's g.  The power means: joint_power_split. */
static double joint_split_mag(joint_id j, double u, double v, int *e) {
  *e = 0;
  if (joint_table[j].pub.key == JOINT_SHAPE_POWER) return joint_power_split(joint_table[j].pub.p, u, v, e);
  int plain = j == JOINT_PRODUCT ? !(u > 0 && v > 0 && u < INFINITY && v < INFINITY)
                                 : !(u >= 0 && v >= 0 && u < INFINITY && v < INFINITY && u + v > 0);
  if (plain) return j == JOINT_PRODUCT ? joint_product(u, v) : joint_rss(u, v);
  int eu, ev;
  double fu = frexp(u, &eu), fv = frexp(v, &ev);
  if (j == JOINT_PRODUCT) {
    *e = eu + ev;
    return fu * fv;
  }
  int k = u == 0 ? ev : v == 0 ? eu : eu > ev ? eu : ev;   /* frexp(0) gives exponent 0 */
  double su = ldexp(u, -k), sv = ldexp(v, -k);
  *e = k;
  return sqrt(su * su + sv * sv);
}

double joint_apply_split(joint_id j, int s, double x, double y, int *e) {
  *e = 0;
  if (!joint_table[j].pub.split) return joint_apply(j, s, x, y);
  if (s >= 0) return joint_split_mag(j, x, y, e);
  return -joint_split_mag(j, -x, -y, e);
}

/* joint_apply for the comparisons of the joints without a split form,
** with the three that flip loops use most written out, so that they
** inline instead of calling through the table (a LOT compares two joint
** values for every examined edge).  l_1 as x + y for either sign: for
** s < 0 the table computes -((-x) + (-y)), which rounds to the same value
** (round to nearest is symmetric) except that a zero sum may have the
** other sign, and joint_compare_values does not see the sign of a zero. */
static double joint_apply_plain(joint_id j, int s, double x, double y) {
  switch (j) {
    case JOINT_SUM: return x + y;
    case JOINT_MIN: return joint_min(x, y);
    case JOINT_MAX: return joint_max(x, y);
    default: return joint_apply(j, s, x, y);
  }
}

/* Both values scaled by 2^-E, E the larger exponent of the finite non-zero
** ones (0, inf and NaN are unchanged by scaling and keep their own value):
** exact unless the smaller one falls below 2^-1022 of the larger, where it
** can no longer tie with it (for tie_eps < 1) nor change the order.  (A
** power mean's m lies in [2^-513, 2^512] rather than [1/4, 2): a scaled m
** that leaves the normal range is then below 2^-509 of the other, the
** same conclusion.) */
int joint_compare(joint_id j, int s, double x1, double y1, double x2, double y2,
                  double tie_eps) {
  /* For the joints without a split form e1 = e2 = 0 below and this is the
  ** same comparison. */
  if (!joint_table[j].pub.split)
    return joint_compare_values(joint_apply_plain(j, s, x1, y1), joint_apply_plain(j, s, x2, y2),
                                tie_eps);
  int e1, e2;
  double m1 = joint_apply_split(j, s, x1, y1, &e1);
  double m2 = joint_apply_split(j, s, x2, y2, &e2);
  int n1 = m1 != 0 && isfinite(m1), n2 = m2 != 0 && isfinite(m2);
  int E = n1 && n2 ? (e1 > e2 ? e1 : e2) : n1 ? e1 : n2 ? e2 : 0;
  /* ldexp by 0 is the identity: skip the call. */
  if (n1 && e1 != E) m1 = ldexp(m1, e1 - E);
  if (n2 && e2 != E) m2 = ldexp(m2, e2 - E);
  return joint_compare_values(m1, m2, tie_eps);
}

/* ---- verdicts from enclosures (joint.h) --------------------------------
**
** Why a verdict is the exact comparison's.  For min, max and sum the
** joint as joint_compare computes it (f = joint_apply_plain: min, max,
** x + y for either sign) is non-decreasing in each argument: min and max
** are exact, fl(x + y) is the rounded sum and rounding is monotone.  So
** with A = f(x1, y1) and B = f(x2, y2) computed on values inside the
** enclosures, a1 <= A <= a2 and b1 <= B <= b2 for the f of the lower and
** of the upper ends, and A and B are the very doubles joint_compare
** compares.  joint_compare_values(A, B, eps) is < 0 exactly when A < B
** and not fl(|A - B|) <= fl(eps max(|A|, |B|)).
** - a1 >= b2: A >= B, never < 0.
** - a2 < b1, all four finite: A < B, and B - A >= b1 - a2 as reals, so
**   fl(|A - B|) = fl(B - A) >= fl(b1 - a2) (rounding is monotone), while
**   max(|A|, |B|) <= M = the largest magnitude of a1, a2, b1, b2, so
**   fl(eps max(|A|, |B|)) <= fl(eps M): fl(b1 - a2) > fl(eps M) rules the
**   tie out.  The factor 1 + 2^-20 on the right is a safety margin only
**   (the argument needs none under the build's floating-point contract).
** - all finite, fl(D) < fl(eps m) (1 - 2^-20), D the larger of fl(a2 - b1)
**   and fl(b2 - a1) (|A - B| is at most the larger of the exact
**   differences) and m the larger of the least magnitudes |A| and |B| can
**   have: always a tie, never < 0.
** (The maxima by plain comparisons, not fmax, a libm call: every value is
** finite where they are taken.) */
static double joint_mag_lo(double lo, double hi) {
  return lo > 0 ? lo : hi < 0 ? -hi : 0;
}

static double joint_mag_hi(double lo, double hi) {
  return joint_max(fabs(lo), fabs(hi));
}

/* The verdict from the joint's values at the ends: A in [a1, a2], B in
** [b1, b2]. */
static joint_verdict joint_verdict_of(double a1, double a2, double b1, double b2,
                                      double tie_eps) {
  if (a1 >= b2) return JOINT_NOT_LESS;
  if (!(isfinite(a1) && isfinite(a2) && isfinite(b1) && isfinite(b2))) return JOINT_UNSURE;
  double M = joint_max(joint_mag_hi(a1, a2), joint_mag_hi(b1, b2));
  if (a2 < b1 && b1 - a2 > tie_eps * M * (1 + 0x1p-20)) return JOINT_LESS;
  double D = joint_max(a2 - b1, b2 - a1);
  double m = joint_max(joint_mag_lo(a1, a2), joint_mag_lo(b1, b2));
  return D < tie_eps * m * (1 - 0x1p-20) ? JOINT_NOT_LESS : JOINT_UNSURE;
}

/* joint_apply_plain's operations, one switch for the four values. */
joint_verdict joint_compare_bounds(joint_id j, int s, const double lo[4], const double hi[4],
                                   double tie_eps) {
  (void)s;   /* x + y, min and max do not depend on it */
  switch (j) {
    case JOINT_SUM:
      return joint_verdict_of(joint_sum(lo[0], lo[1]), joint_sum(hi[0], hi[1]),
                              joint_sum(lo[2], lo[3]), joint_sum(hi[2], hi[3]), tie_eps);
    case JOINT_MIN:
      return joint_verdict_of(joint_min(lo[0], lo[1]), joint_min(hi[0], hi[1]),
                              joint_min(lo[2], lo[3]), joint_min(hi[2], hi[3]), tie_eps);
    case JOINT_MAX:
      return joint_verdict_of(joint_max(lo[0], lo[1]), joint_max(hi[0], hi[1]),
                              joint_max(lo[2], lo[3]), joint_max(hi[2], hi[3]), tie_eps);
    default:
      return JOINT_UNSURE;
  }
}

int joint_has_bounds(joint_id j) {
  return joint_table[j].pub.bounds;
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
  return joint_key_shape(joint_table[j].pub.key, joint_table[j].pub.p, s, x);
}

double joint_unkey(joint_id j, int s, double k) {
  return joint_unkey_shape(joint_table[j].pub.key, joint_table[j].pub.p, s, k);
}

double joint_key_identity(joint_id j) {
  switch (joint_table[j].pub.keyop) {
    case JOINT_KEY_MIN: return INFINITY;
    case JOINT_KEY_MAX: return -INFINITY;
    default: return 0.0;
  }
}

/* ---- names and the power-mean rows ----------------------------------------
**
** A joint name is a built-in name or a real p in decimal ("3", "-2", "0.5",
** "1.5e1"; no blanks, no hexadecimal, inf and nan only as the built-in
** "inf" and "-inf").  A p equal to -1, 0, 1 or 2 is that built-in row, so
** "1.0" is "1" bit for bit; any other p gets one row, named by the
** shortest "%.Ng" that reads back as p ("3", "0.5", "1e+20"): rules are
** named with it, so "P_3.0" and "P_3" are one rule, printed "P_3". */

/* p from a name of decimal characters: GEOM_NUM_OK, or why not. */
static geom_numerr joint_power_read(const char *name, double *p) {
  size_t n = strspn(name, "0123456789+-.eE");
  if (n == 0 || name[n] != '\0' || n > 40 || strpbrk(name, "0123456789") == NULL)
    return GEOM_NUM_NOT_NUMBER;
  return geom_number_parse(name, n, p);
}

/* The shortest "%.Ng" of p that reads back as p. */
static void joint_power_name(double p, char nm[32]) {
  int k = 1;
  do snprintf(nm, 32, "%.*g", k, p);
  while (k++ < 17 && strtod(nm, NULL) != p);
}

static void joint_power_row(joint_impl *J, double p) {
  char nm[32];
  joint_power_name(p, nm);
  snprintf(J->text[0], sizeof J->text[0], "%s", nm);
  snprintf(J->text[1], sizeof J->text[1], "l_%s", nm);
  snprintf(J->text[2], sizeof J->text[2], "(x^p + y^p)^(1/p), power mean, p = %s", nm);
  snprintf(J->text[3], sizeof J->text[3], "%ssums of x^%s", p > 0 ? "" : "-", nm);
  J->pub = (joint){.name = J->text[0], .symbol = J->text[1], .desc = J->text[2],
                   .needs_sign = 1, .keyop = JOINT_KEY_ADD, .word = "power", .colour = "#999999",
                   .p = p, .key = JOINT_SHAPE_POWER, .key_units = J->text[3],
                   .vec = JOINT_VEC_NONE, .split = 1, .bounds = 0};
  J->g = joint_g_power;
  J->identity = p > 0 ? 0.0 : INFINITY;
}

/* Rows are made while commands parse their rules, before any engine
** runs: the table is never written while it is read. */
int joint_parse(const char *name, char *err, size_t errlen) {
  for (int j = 0; j < joint_nrows; j++)
    if (strcmp(joint_table[j].pub.name, name) == 0) return j;
  char names[64];
  double p;
  joint_names(names, sizeof names);
  geom_numerr ne = joint_power_read(name, &p);
  if (ne == GEOM_NUM_NOT_NUMBER) {
    snprintf(err, errlen, "unknown joint '%.30s': expected one of {%s} or a real p "
             "(the power mean l_p)", name, names);
    return -1;
  }
  if (ne != GEOM_NUM_OK) {
    snprintf(err, errlen, "joint '%.30s': p %s", name, geom_numerr_str(ne));
    return -2;
  }
  if (p != 0 && !(fabs(p) >= 1.0 / 512)) {
    snprintf(err, errlen, "joint '%.30s': the power mean l_p needs |p| >= 1/512 (or p = 0, "
             "the product)", name);
    return -2;
  }
  for (int j = 0; j < joint_nrows; j++)
    if (joint_table[j].pub.p == p) return j;
  char nm[32];
  joint_power_name(p, nm);
  if (strlen(nm) >= JOINT_NAME_MAX) {
    snprintf(err, errlen, "joint '%.30s': p = %s has more digits than a joint name holds "
             "(%d characters)", name, nm, JOINT_NAME_MAX - 1);
    return -2;
  }
  if (joint_nrows == JOINT_CAPACITY) {
    snprintf(err, errlen, "joint '%.30s': at most %d power means other than {%s} in one run",
             name, JOINT_CAPACITY - JOINT_COUNT, names);
    return -2;
  }
  joint_power_row(&joint_table[joint_nrows], p);
  return joint_nrows++;
}
