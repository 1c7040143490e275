/*
** got_cert.c: a certified answer to "is this optimum unique?" for every
** GOT run, from a documented forward error bound per measure and joint.
**
** Why a forward bound and not interval arithmetic.  The programme compares
** n^3/6 candidate sums; re-running it in intervals would double its cost
** and the angle measures call atan2, which directed rounding does not make
** rigorous.  Instead we bound, for every triangle t, the error of the key
** the kernels compute, |k^(t) - k(t)| <= rho |k^(t)| + alpha, with rho and
** alpha from the table below, and propagate through the joint.  The bound
** costs O(n) after the programme (plus an O(n) scan of the polygon).
**
** Why the DP's floating values suffice.  Every floating operation the
** programme uses (+, min, max, all rounded to nearest) is monotone in each
** argument, so min over k of fl(x_k + c) = fl(min_k x_k + c): the computed
** optimum K^* is the floating value, evaluated in the DP's association
** order, of the returned triangulation T*, and the computed runner-up K^2
** is the least such value over all T != T* (got_dp.c's recurrence for the
** second smallest only uses monotonicity).  So with E(K) an error bound
** valid for any triangulation whose floating value is K:
**   exact(T*) <= K^* + E(K^*),
**   exact(T)  >= K^(T) - E(K^(T)) >= K^2 - E(K^2)   for every T != T*,
** the second step because K - E(K) is increasing in K (below).  The optimum
** is proven unique when K^2 - K^* > E(K^*) + E(K^2).
**
** Joints (m = n - 2 triangles, u = 2^-53, gamma_k = k u / (1 - k u)):
** - key (+): the keys of one rule have one sign (the measure has one sign
**   and identity, square and -1/x keep it), so with S = sum |k^(t)|, the
**   rounded sum in any order is within gamma_{m-1} S of the exact sum of
**   the k^(t) (Higham, Accuracy and Stability, 4.2), |K^| >= (1 -
**   gamma_{m-1}) S, and E(K) = (gamma_{m-1} + rho) S + m alpha with S <=
**   (|K| + 2 m alpha) / (1 - gamma_{m-1}) (a key whose bound is absolute
**   may have the wrong sign by at most alpha).  E(K) grows like c |K| with
**   c < 1, so K - E(K) is increasing.
** - key min / max: no rounding.  With relative errors, k^ lies in
**   [lo(k), hi(k)] where lo(x) = x - rho |x| and hi(x) = x + rho |x| are
**   increasing in x, so max_t k^(t) lies in [lo(max k), hi(max k)] (same
**   for min): E(K) = rho / (1 - rho) |K| + alpha.
** - l_0 (logarithms of both signs: S is not bounded by |K|) and user
**   measures (no error model): E = infinity, "tie not excluded".
**
** Measures (the kernels of got_kernels.c; coordinates are exact doubles,
** every coordinate difference rounds once):
** - A side length sqrt(dx^2 + dy^2): relative error gamma_4 (dx, dy, two
**   squares, a sum: (1 + u)^4; sqrt halves it; sqrt rounds once; the scale
**   guard below keeps squares normal).  a, -c: gamma_4 (max, min exact).
**   P = (l1 + l2) + l3: gamma_6.  abc: gamma_14.  -c/a: gamma_10.
**   -c/P: gamma_12.  a - c: absolute 2 gamma_5 D, D >= every side length.
** - Pinf = 2 (rx + ry), rx = max - min of three coordinates (one rounding):
**   gamma_2.  Rinf = max(rx, ry) / 2: gamma_1.
** - -A from 2A = (x_k - x_i)(y_j - y_i) - (y_k - y_i)(x_j - x_i): absolute
**   gamma_5 (|l| + |r|) / 2 <= gamma_5 W_x W_y (W = coordinate ranges).
** - Angles: a direction atan2(dy, dx) moves by at most u for the rounding
**   of dx, dy, and libm's atan2 is within 2 ulps (glibc documents 1 ulp
**   for atan2; we assume 2, the one assumption here), 2^-50 for |theta| <=
**   pi; the reversed direction adds 2^-51 (pi's rounding and the sum's);
**   an angle is a difference (2^-51) plus perhaps 2 pi (2^-50): in all
**   below 2^-47 absolute.  The wrap decision cannot go wrong (true
**   differences avoid (-pi, 0), the error is far below pi/2).  -alpha, beta,
**   gamma: absolute 2^-47.  sigma^2 = sum (theta - pi/3)^2 / 3 with sum
**   |theta - pi/3| <= 4 pi / 3 and |theta - pi/3| <= 2 pi / 3: absolute
**   below 2^-45 (the l_2 key of sigma is sigma^2 itself).  sigma (a square
**   root near 0), and every measure with the area in a denominator (R, -r,
**   -a', -r/R, -r^2/A, lambda, d, -rinf, b/(c-a): a thin triangle's area has
**   no relative accuracy a priori): no bound.
** Thin triangles, which got_pairs_eval recomputes through geom_tri_make
** (an exactly rounded twice-area, angles from atan2 of it and of a dot
** product, the largest as pi minus the others), are within these bounds
** too: their angles are within about 8u + 2 atan2 errors < 2^-48, the
** area within u |A|, sigma^2 = (sqrt(x))^2 within 3u of 2.2.
** Keys: square, x^2 (1 + u): relative (1 + rho)^2 (1 + u) - 1; absolute
** 2 b_max alpha + alpha^2 + u (b_max + alpha)^2.  -1/x: relative rho + 2u;
** absolute errors: no bound.  Power keys +-x^p (a power mean l_p): with
** x^ = x (1 + d), |d| <= rho, (x^)^p = x^p (1 + d)^p lies within a factor
** (1 - rho)^-|p| of x^p either way, and pow adds at most 2 ulps (glibc
** documents 1; the one other assumption here, as for atan2): relative
** (1 - rho)^-|p| (1 + 4u) - 1, computed as e + 4u (1 + e) with e =
** expm1(-|p| log1p(-rho)) (no cancellation); absolute errors: no bound.
**
** Scale guard.  The relative bounds assume no underflow: see
** got_cert_scale (non-zero coordinates at least 2^-118 in magnitude, ranges
** at most 2^169: always true inside the coordinate contract, 0 or
** magnitudes in [1e-30, 1e30]); otherwise E = infinity.  An overflowed key is infinite,
** and an infinite key gets E = infinity too.
**
** Rounding of the bound itself: E is computed from positive terms in round
** to nearest (a few dozen operations, relative error below 2^-45) and then
** multiplied by 1 + 2^-40; the final test compares fl(K^2 - K^*) (1 - 2^-50)
** with fl(E^* + E^2) (1 + 2^-50).
*/
#include <math.h>
#include <stddef.h>
#include "measure.h"
#include "got_internal.h"

#define GOT_U 0x1p-53

typedef enum got_errkind { GOT_ERR_NONE, GOT_ERR_REL, GOT_ERR_ABS } got_errkind;
typedef enum got_errscale { GOT_SC_ONE, GOT_SC_DIAM, GOT_SC_AREA } got_errscale;

/* Per measure: kind, k for gamma_k (relative) or the constant (absolute),
** the scale an absolute bound is multiplied by, and b_max (times the same
** scale) for square keys. */
typedef struct got_errmodel {
  got_errkind kind;
  double c;             /* REL: gamma index k; ABS: alpha / scale */
  got_errscale scale;
  double bmax;          /* ABS: |b| <= bmax * scale */
} got_errmodel;

static const got_errmodel got_errmodels[MEASURE_BUILTIN_COUNT] = {
  [MEASURE_NEG_ALPHA] = {GOT_ERR_ABS, 0x1p-47, GOT_SC_ONE, 3.2},
  [MEASURE_BETA] = {GOT_ERR_ABS, 0x1p-47, GOT_SC_ONE, 3.2},
  [MEASURE_GAMMA] = {GOT_ERR_ABS, 0x1p-47, GOT_SC_ONE, 3.2},
  [MEASURE_A] = {GOT_ERR_REL, 4, GOT_SC_ONE, 0},
  [MEASURE_NEG_C] = {GOT_ERR_REL, 4, GOT_SC_ONE, 0},
  [MEASURE_P] = {GOT_ERR_REL, 6, GOT_SC_ONE, 0},
  [MEASURE_ABC] = {GOT_ERR_REL, 14, GOT_SC_ONE, 0},
  [MEASURE_NEG_AREA] = {GOT_ERR_ABS, 5 * GOT_U * (1 + 0x1p-40), GOT_SC_AREA, 0.5},
  [MEASURE_NEG_C_OVER_A] = {GOT_ERR_REL, 10, GOT_SC_ONE, 0},
  [MEASURE_NEG_C_OVER_P] = {GOT_ERR_REL, 12, GOT_SC_ONE, 0},
  [MEASURE_A_MINUS_C] = {GOT_ERR_ABS, 10 * GOT_U * (1 + 0x1p-40), GOT_SC_DIAM, 1},
  [MEASURE_PINF] = {GOT_ERR_REL, 2, GOT_SC_ONE, 0},
  [MEASURE_RINF] = {GOT_ERR_REL, 1, GOT_SC_ONE, 0},
  /* the others: {GOT_ERR_NONE} (zero-initialised) */
};

static double got_gamma(double k) { return k * GOT_U / (1 - k * GOT_U); }

/* Coordinate ranges, and the scale guard: every non-zero |coordinate| at
** least 2^-118, so its ulp is at least 2^-170 and every coordinate is an
** integer multiple of 2^-170: a non-zero difference is at least 2^-170 and
** a product of up to six lengths (an l_2 key of abc) stays normal.  Ranges
** at most 2^169 keep that product finite. */
static int got_cert_scale(const geom_point *p, size_t n, double *wx, double *wy) {
  double x0 = p[0].x, x1 = p[0].x, y0 = p[0].y, y1 = p[0].y, tiny = INFINITY;
  for (size_t i = 0; i < n; i++) {
    x0 = fmin(x0, p[i].x), x1 = fmax(x1, p[i].x);
    y0 = fmin(y0, p[i].y), y1 = fmax(y1, p[i].y);
    double ax = fabs(p[i].x), ay = fabs(p[i].y);
    if (ax > 0) tiny = fmin(tiny, ax);
    if (ay > 0) tiny = fmin(tiny, ay);
  }
  *wx = x1 - x0;
  *wy = y1 - y0;
  return tiny >= 0x1p-118 && *wx <= 0x1p169 && *wy <= 0x1p169;
}

/* Values from measure_eval (geom_tri_make) rather than the kernels: there twice the area
** is within a relative 2^-40 of the exact one (geom.h: the filter accepts it 2^40 above
** its error bound, else it is computed exactly), so the radii have relative bounds too.
** 2^-40 = 8192 u: R = a b c / (2 twice) is within 3 gamma_4 + 3 u + 2^-40 < gamma_8208
** (three sides, two products, a quotient); r = twice / P within gamma_6 + u + 2^-40 and
** a' = twice / a within gamma_4 + u + 2^-40, both below gamma_8208 too.  Used only for
** keys made from measure_eval values (got_cert_model: the point-set skeleton and faces). */
static const got_errmodel got_eval_errmodels[MEASURE_BUILTIN_COUNT] = {
  [MEASURE_R] = {GOT_ERR_REL, 8208, GOT_SC_ONE, 0},
  [MEASURE_NEG_R] = {GOT_ERR_REL, 8208, GOT_SC_ONE, 0},
  [MEASURE_NEG_H] = {GOT_ERR_REL, 8208, GOT_SC_ONE, 0},
};

/* The key error model (rho relative, alpha absolute, in key units) of a
** measure under a key shape; 0, or -1 when there is none.  eval = 1: for values of
** measure_eval, which some measures without a kernel bound have (got_eval_errmodels). */
static int got_key_model(int measure, got_keyfn keyfn, double p, double wx, double wy,
                         int eval, double *rho, double *alpha) {
  if (measure < 0 || measure >= MEASURE_BUILTIN_COUNT) return -1;
  got_errmodel em = got_errmodels[measure];
  if (eval && em.kind == GOT_ERR_NONE) em = got_eval_errmodels[measure];
  if (measure == MEASURE_SIGMA && keyfn == GOT_KEY_FROM_SQ_IDENT)
    em = (got_errmodel){GOT_ERR_ABS, 0x1p-45, GOT_SC_ONE, 0};   /* sigma^2 itself */
  if (em.kind == GOT_ERR_NONE) return -1;
  double diam = (wx + wy) * (1 + 0x1p-40);
  double sc = em.scale == GOT_SC_DIAM ? diam : em.scale == GOT_SC_AREA ? wx * wy * (1 + 0x1p-40) : 1;
  double r = em.kind == GOT_ERR_REL ? got_gamma(em.c) : 0;
  double a = em.kind == GOT_ERR_ABS ? em.c * sc : 0, bmax = em.bmax * sc;
  switch (keyfn) {
    case GOT_KEY_IDENT:
    case GOT_KEY_FROM_SQ_IDENT:
      break;
    case GOT_KEY_SQ:
    case GOT_KEY_NEGSQ:
      r = r > 0 ? (1 + r) * (1 + r) * (1 + GOT_U) - 1 : 0;
      a = a > 0 ? 2 * bmax * a + a * a + GOT_U * (bmax + a) * (bmax + a) : 0;
      break;
    case GOT_KEY_NEGRECIP:
      if (em.kind != GOT_ERR_REL) return -1;
      r += 2 * GOT_U;
      break;
    case GOT_KEY_POWER: {
      if (em.kind != GOT_ERR_REL) return -1;
      double e = expm1(-fabs(p) * log1p(-r));
      r = e + 4 * GOT_U * (1 + e);
      break;
    }
    case GOT_KEY_LOG:            /* logarithms: no bound (above) */
    case GOT_KEY_NEGLOGNEG:
    case GOT_KEY_FROM_SQ_HALFLOG:
      return -1;
  }
  *rho = r * (1 + 0x1p-40);
  *alpha = a * (1 + 0x1p-40);
  return 0;
}

/* E(K) for a triangulation whose floating key is K. */
static double got_cert_bound(double K, size_t m, joint_keyop op, double rho, double alpha) {
  double E;
  if (op == JOINT_KEY_ADD) {
    double g = got_gamma((double)(m > 1 ? m - 1 : 0));
    double S = (fabs(K) + 2 * (double)m * alpha) / (1 - g);
    E = (g + rho) * S + (double)m * alpha;
  } else {
    E = rho / (1 - rho) * fabs(K) + alpha;
  }
  return isfinite(E) ? E * (1 + 0x1p-40) : INFINITY;
}

/* The key shape of values keyed one by one (joint_key of measure_eval),
** whatever the DP's kernels hand out. */
static got_keyfn got_keyfn_plain(got_keyfn keyfn) {
  return keyfn == GOT_KEY_FROM_SQ_IDENT ? GOT_KEY_SQ
       : keyfn == GOT_KEY_FROM_SQ_HALFLOG ? GOT_KEY_LOG : keyfn;
}

/* A triangulation of the result's input has res->ntri triangles (n - 2 for a polygon,
** 2n - h - 2 for a point set); before the triangles are known, a polygon's n - 2. */
double got_cert_err_of(const got_result *res, double key) {
  size_t m = res->ntri > 0 ? res->ntri : res->n >= 3 ? res->n - 2 : 0;
  if (isnan(res->cert_rho) || isnan(res->cert_alpha) || !isfinite(key) || m == 0)
    return INFINITY;
  return got_cert_bound(key, m, joint_get(res->joint)->keyop, res->cert_rho, res->cert_alpha);
}

/* The model of a key shape for triangles among p[0..n-1]: NULL, or why
** there is none. */
static const char *got_cert_check(const geom_point *p, size_t n, int measure, got_keyfn keyfn,
                                  double jp, int eval, double *rho, double *alpha) {
  double wx, wy;
  if (!got_cert_scale(p, n, &wx, &wy))
    return "coordinates outside the certified scale (non-zero |x|, |y| >= 2^-118, "
           "ranges <= 2^169)";
  if (measure >= MEASURE_BUILTIN_COUNT)
    return "no forward error bound for a user-defined measure";
  if (got_key_model(measure, keyfn, jp, wx, wy, eval, rho, alpha) != 0)
    return "no forward error bound for this measure and joint (docs/got.md)";
  return NULL;
}

int got_cert_model(const geom_point *p, size_t n, const rule *r, double *rho, double *alpha,
                   const char **why) {
  *rho = *alpha = NAN;
  if (!rule_is_triangle(r) || n == 0) {
    *why = "no forward error bound for a quadrilateral rule";
    return -1;
  }
  const joint *J = joint_get(rule_joint(r));
  *why = got_cert_check(p, n, rule_measure(r), got_keyfn_of(J->key, rule_sign(r)), J->p, 1,
                        rho, alpha);
  return *why == NULL ? 0 : -1;
}

double got_cert_err_sum(double rho, double alpha, size_t m, double key) {
  if (isnan(rho) || isnan(alpha) || !isfinite(key)) return INFINITY;
  return got_cert_bound(key, m, JOINT_KEY_ADD, rho, alpha);
}

void got_certify(got_result *res, const geom_point *p, size_t n, got_keyfn keyfn,
                 joint_keyop op) {
  double rho = 0, alpha = 0, jp = joint_get(res->joint)->p;
  res->cert_rho = res->cert_alpha = NAN;
  res->cert_err = res->cert_err2 = INFINITY;
  res->cert_unique = 0;
  res->cert_why = got_cert_check(p, n, res->measure, keyfn, jp, 0, &rho, &alpha);
  double prho, palpha;
  if (res->cert_why == NULL &&
      got_cert_check(p, n, res->measure, got_keyfn_plain(keyfn), jp, 0, &prho, &palpha)
          == NULL) {
    res->cert_rho = prho;
    res->cert_alpha = palpha;
  }
  if (res->cert_why == NULL && isfinite(res->key)) {
    res->cert_err = got_cert_bound(res->key, n - 2, op, rho, alpha);
    if (res->has_runner_up && isfinite(res->key2))
      res->cert_err2 = got_cert_bound(res->key2, n - 2, op, rho, alpha);
  }
  if (!res->has_runner_up) {
    res->cert_gap = res->cert_bound = INFINITY;
    res->cert_unique = 1;          /* the only triangulation */
    return;
  }
  res->cert_gap = res->key2 - res->key;
  res->cert_bound = res->cert_err + res->cert_err2;
  res->cert_unique = isfinite(res->cert_bound) &&
                     res->cert_gap * (1 - 0x1p-50) > res->cert_bound * (1 + 0x1p-50);
}
