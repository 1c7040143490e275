/*
** got_kernels.c: per-pair data and the triangle kernels of the GOT programme.
**
** The DP needs b(p_i p_k p_j) for all n^3/6 triples, so the triangle's
** badness must be cheap.  Everything that depends on a pair of vertices is
** computed once, in O(n^2): the side length |p_i p_k| (a sqrt) and the
** direction of the ray p_i -> p_k (an atan2).  A kernel then evaluates one
** measure for a whole run of k with i and j fixed, reading rows i and j of
** those tables contiguously, with no square root or trigonometry in the loop
** (sigma needs one sqrt, as its definition does).
**
** Angles.  For i < k < j on an anticlockwise polygon the triangle i, k, j is
** anticlockwise, and its interior angles are differences of ray directions:
** at i from ray i->k to ray i->j, at k from k->j to k->i (the two pi shifts
** of reversing both rays cancel, leaving dir(i->k) - dir(j->k)), at j from
** j->i to j->k.  A difference lies in (-2pi, 2pi) and is congruent to the
** angle mod 2pi; since the angle is in (0, pi) we add 2pi below -pi/2: an
** angle near pi whose difference rounds to just above -pi is still fixed,
** and an angle near 0 whose difference rounds to -1e-17 stays near 0
** instead of jumping to 2pi.  Error: each direction is atan2 (< 1 ulp of pi)
** so an angle is off by about 1e-15 rad in absolute terms.
**
** Area.  2A = (p_k - p_i) x (p_j - p_i) from the coordinates, which is
** exactly how geom_tri_make computes it up to the choice of the origin
** vertex; for thin triangles both are only as good as the cross product's
** condition number allows.  Everything else is a few products, quotients or
** min/max of these, so kernels agree with measure_eval(geom_tri_make(...))
** to a few ulps (lengths, areas, ratios) or about 1e-15 absolute (angles).
**
** User-defined measures (registry id >= MEASURE_BUILTIN_COUNT) have no
** kernel: they fall back to measure_eval on geom_tri_make, slower but exact.
*/
#include <math.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>
#include "fliplab_config.h"
#if FLIPLAB_HAVE_SSE2
#include <emmintrin.h>
#endif
#include "measure.h"
#include "got_internal.h"

#define GOT_PI 3.14159265358979323846
#define GOT_2PI 6.28318530717958647693
#define GOT_PI3 1.04719755119659774615

typedef void (*got_kernel_fn)(const got_pairs *pd, size_t i, size_t j, size_t k0,
                              size_t k1, double *out);

struct got_pairs {
  size_t n;
  int measure;
  geom_point *p;
  double *x, *y;        /* coordinates, split for contiguous loads */
  double *len;          /* n x n: |p_i p_k|, or NULL */
  double *dir;          /* n x n: direction of p_i -> p_k in (-pi, pi], or NULL */
  got_kernel_fn fn;
  int thin_check;       /* recompute thin triangles exactly (got_pairs_eval) */
  int squared;          /* fn is the kernel of b^2 (got_pairs_new_sq) */
};

/* Which tables a kernel reads; GOT_NEED_AREA (no table) marks kernels that
** use the cross product, which like the angles needs the thin-triangle
** check of got_pairs_eval. */
enum { GOT_NEED_LEN = 1, GOT_NEED_DIR = 2, GOT_NEED_AREA = 4 };

static inline double got_min2(double a, double b) { return a < b ? a : b; }
static inline double got_max2(double a, double b) { return a > b ? a : b; }
static inline double got_min3(double a, double b, double c) { return got_min2(got_min2(a, b), c); }
static inline double got_max3(double a, double b, double c) { return got_max2(got_max2(a, b), c); }
static inline double got_med3(double a, double b, double c) {
  return got_max2(got_min2(a, b), got_min2(got_max2(a, b), c));
}
/* Branch-free, so that the angle loops vectorise. */
static inline double got_wrap(double d) { return d + GOT_2PI * (double)(d < -GOT_PI / 2); }

/* sqrt of m values >= 0.  libm's sqrt keeps a scalar call for errno, which
** stops GCC from vectorising the loop; SSE2's sqrtpd is the same correctly
** rounded IEEE square root, two at a time. */
void got_sqrt_inplace(double *t, size_t m) {
  size_t q = 0;
#if FLIPLAB_HAVE_SSE2
  for (; q + 2 <= m; q += 2) _mm_storeu_pd(t + q, _mm_sqrt_pd(_mm_loadu_pd(t + q)));
#endif
  for (; q < m; q++) t[q] = sqrt(t[q]);
}

/* sign * log(sign * x) for m values x, vectorisable, for the l_0 keys
** (sign = +1: log x for values >= 0; sign = -1: -log(-x) for values <= 0).
** This is fdlibm's __ieee754_log without its branches: x = 2^k (1 + f)
** with 1 + f in [sqrt(1/2), sqrt(2)), found by integer arithmetic on the
** bits (the offset trick of musl/ARM: subtracting the bits of sqrt(1/2)
** leaves k in the exponent field), s = f / (2 + f), and
** log(1 + f) = f - (f^2/2 - s (f^2/2 + R(s^2))) with fdlibm's minimax
** R (error below 2^-58.45), k ln2 split into an exact k * ln2_hi plus
** k * ln2_lo.  Error under 1 ulp, as fdlibm's (tests compare with libm).
** If any value is not a positive normal finite number (after the sign),
** the whole run goes to libm's log, so 0, inf and NaN behave as log. */
static int got_log_special(const double *t, size_t m, double sign) {
  const double lo = 0x1p-1022, hi = 0x1.fffffffffffffp+1023;
  size_t q = 0;
  int bad = 0;
#if FLIPLAB_HAVE_SSE2
  const __m128d vlo = _mm_set1_pd(lo), vhi = _mm_set1_pd(hi), vs = _mm_set1_pd(sign);
  __m128d acc = _mm_setzero_pd();
  for (; q + 2 <= m; q += 2) {
    __m128d x = _mm_mul_pd(_mm_loadu_pd(t + q), vs);
    acc = _mm_or_pd(acc, _mm_or_pd(_mm_cmpnge_pd(x, vlo), _mm_cmpnle_pd(x, vhi)));
  }
  bad = _mm_movemask_pd(acc) != 0;
#endif
  for (; q < m; q++) bad |= !(sign * t[q] >= lo) || !(sign * t[q] <= hi);
  return bad;
}

GOT_CLONES void got_log_inplace(double *t, size_t m, double sign) {
  const double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
  const double Lg1 = 6.666666666666735130e-01, Lg2 = 3.999999999940941908e-01,
               Lg3 = 2.857142874366239149e-01, Lg4 = 2.222219843214978396e-01,
               Lg5 = 1.818357216161805012e-01, Lg6 = 1.531383769920937332e-01,
               Lg7 = 1.479819860511658591e-01;
  const uint64_t off = 0x3fe6a09e667f3bcdULL, bias = 0x3ff0000000000000ULL;
  if (got_log_special(t, m, sign)) {
    for (size_t q = 0; q < m; q++) t[q] = sign * log(sign * t[q]);
    return;
  }
  for (size_t q = 0; q < m; q++) {
    double x = sign * t[q];
    uint64_t b, kb, zb;
    memcpy(&b, &x, sizeof b);
    uint64_t u = b - off + bias;               /* > 0 for normal x */
    uint64_t kf = u >> 52;                     /* k + 1023, in [1, 2047] */
    zb = b - ((u & 0xfff0000000000000ULL) - bias);
    kb = 0x4330000000000000ULL | kf;           /* the double 2^52 + kf */
    double kd, z;
    memcpy(&kd, &kb, sizeof kd);
    memcpy(&z, &zb, sizeof z);
    kd -= 4503599627370496.0 + 1023.0;
    double f = z - 1, sv = f / (2 + f), zz = sv * sv, w = zz * zz;
    double t1 = w * (Lg2 + w * (Lg4 + w * Lg6));
    double t2 = zz * (Lg1 + w * (Lg3 + w * (Lg5 + w * Lg7)));
    double R = t2 + t1, hfsq = 0.5 * f * f;
    t[q] = sign * (kd * ln2_hi - ((hfsq - (sv * (hfsq + R) + kd * ln2_lo)) - f));
  }
}

/* Loop headers shared by the kernels: side lengths, twice the area, the
** three angles, the coordinate ranges. */
#define GOT_LOOP for (size_t k = k0; k < k1; k++)
#define GOT_ROWS_LEN \
  const double *Li = pd->len + i * pd->n, *Lj = pd->len + j * pd->n; \
  const double lij = Li[j];
#define GOT_ROWS_XY \
  const double *X = pd->x, *Y = pd->y; \
  const double xi = X[i], yi = Y[i], xj = X[j], yj = Y[j]; \
  const double ux = xj - xi, uy = yj - yi;
#define GOT_ROWS_DIR \
  const double *Di = pd->dir + i * pd->n, *Dj = pd->dir + j * pd->n; \
  const double dij = Di[j], dji = Dj[i];
#define GOT_SIDES \
  const double l1 = Li[k], l2 = Lj[k]; \
  const double sa = got_max3(l1, l2, lij), sc = got_min3(l1, l2, lij);
#define GOT_AREA2 const double A2 = (X[k] - xi) * uy - (Y[k] - yi) * ux;
#define GOT_ANGLES \
  const double ti = got_wrap(dij - Di[k]), tk = got_wrap(Di[k] - Dj[k]), \
               tj = got_wrap(Dj[k] - dji);
#define GOT_RANGES \
  const double rx = got_max3(xi, X[k], xj) - got_min3(xi, X[k], xj); \
  const double ry = got_max3(yi, Y[k], yj) - got_min3(yi, Y[k], yj);

#define GOT_KERNEL(name, rows, ...) \
  GOT_CLONES static void name(const got_pairs *pd, size_t i, size_t j, size_t k0, size_t k1, \
                   double *out) { \
    rows \
    double *o = out - k0; \
    GOT_LOOP { __VA_ARGS__ } \
  }

GOT_KERNEL(got_k_neg_alpha, GOT_ROWS_DIR, GOT_ANGLES o[k] = -got_min3(ti, tk, tj);)
GOT_KERNEL(got_k_beta, GOT_ROWS_DIR, GOT_ANGLES o[k] = got_med3(ti, tk, tj);)
GOT_KERNEL(got_k_gamma, GOT_ROWS_DIR, GOT_ANGLES o[k] = got_max3(ti, tk, tj);)
GOT_KERNEL(got_k_sigma2, GOT_ROWS_DIR, GOT_ANGLES
  const double ei = ti - GOT_PI3, ek = tk - GOT_PI3, ej = tj - GOT_PI3;
  o[k] = (ei * ei + ek * ek + ej * ej) / 3;)
static void got_k_sigma(const got_pairs *pd, size_t i, size_t j, size_t k0, size_t k1,
                        double *out) {
  got_k_sigma2(pd, i, j, k0, k1, out);
  got_sqrt_inplace(out, k1 - k0);
}
GOT_KERNEL(got_k_a, GOT_ROWS_LEN, GOT_SIDES o[k] = sa; (void)sc;)
GOT_KERNEL(got_k_neg_c, GOT_ROWS_LEN, GOT_SIDES o[k] = -sc; (void)sa;)
GOT_KERNEL(got_k_p, GOT_ROWS_LEN, o[k] = Li[k] + Lj[k] + lij;)
GOT_KERNEL(got_k_abc, GOT_ROWS_LEN, o[k] = Li[k] * Lj[k] * lij;)
GOT_KERNEL(got_k_neg_area, GOT_ROWS_XY, GOT_AREA2 o[k] = -0.5 * A2;)
GOT_KERNEL(got_k_r, GOT_ROWS_LEN GOT_ROWS_XY, GOT_AREA2
  o[k] = Li[k] * Lj[k] * lij / (2 * A2);)
GOT_KERNEL(got_k_neg_r, GOT_ROWS_LEN GOT_ROWS_XY, GOT_AREA2
  o[k] = -A2 / (Li[k] + Lj[k] + lij);)
GOT_KERNEL(got_k_neg_h, GOT_ROWS_LEN GOT_ROWS_XY, GOT_AREA2 GOT_SIDES
  o[k] = -A2 / sa; (void)sc;)
GOT_KERNEL(got_k_neg_r_over_r, GOT_ROWS_LEN GOT_ROWS_XY, GOT_AREA2
  const double P = Li[k] + Lj[k] + lij;
  o[k] = -2 * A2 * A2 / (P * (Li[k] * Lj[k] * lij));)
GOT_KERNEL(got_k_neg_r2_over_a, GOT_ROWS_LEN GOT_ROWS_XY, GOT_AREA2
  const double P = Li[k] + Lj[k] + lij;
  o[k] = -2 * A2 / (P * P);)
GOT_KERNEL(got_k_neg_c_over_a, GOT_ROWS_LEN, GOT_SIDES o[k] = -sc / sa;)
GOT_KERNEL(got_k_neg_c_over_p, GOT_ROWS_LEN, GOT_SIDES
  o[k] = -sc / (Li[k] + Lj[k] + lij); (void)sa;)
GOT_KERNEL(got_k_a_minus_c, GOT_ROWS_LEN, GOT_SIDES o[k] = sa - sc;)
GOT_KERNEL(got_k_b_over_c_minus_a, GOT_ROWS_LEN, GOT_SIDES
  o[k] = -(got_med3(l1, l2, lij) / (sa - sc));)
/* lambda = a^2 / (2A) from squared lengths: no table needed. */
GOT_KERNEL(got_k_lambda, GOT_ROWS_XY, GOT_AREA2
  const double dxi = X[k] - xi, dyi = Y[k] - yi, dxj = X[k] - xj, dyj = Y[k] - yj;
  const double a2 = got_max3(dxi * dxi + dyi * dyi, dxj * dxj + dyj * dyj, ux * ux + uy * uy);
  o[k] = a2 / A2;)
/* d = R (1 - cos(gamma)), cos(gamma) by the law of cosines as in the
** measure's definition; gamma >= 60 deg, so 1 - cos(gamma) >= 1/2. */
GOT_KERNEL(got_k_d, GOT_ROWS_LEN GOT_ROWS_XY, GOT_AREA2 GOT_SIDES
  const double sb = got_med3(l1, l2, lij);
  const double R = sa * sb * sc / (2 * A2);
  o[k] = R * (1 - (sb * sb + sc * sc - sa * sa) / (2 * sb * sc));)
GOT_KERNEL(got_k_pinf, GOT_ROWS_XY, GOT_RANGES o[k] = 2 * (rx + ry); (void)ux; (void)uy;)
GOT_KERNEL(got_k_rinf, GOT_ROWS_XY, GOT_RANGES o[k] = got_max2(rx, ry) / 2; (void)ux; (void)uy;)
GOT_KERNEL(got_k_neg_rinf, GOT_ROWS_XY, GOT_AREA2 GOT_RANGES o[k] = -0.5 * A2 / (rx + ry);)

/* The fallback for user measures: a full geom_tri per triangle. */
static void got_k_generic(const got_pairs *pd, size_t i, size_t j, size_t k0, size_t k1,
                          double *out) {
  for (size_t k = k0; k < k1; k++) {
    geom_tri t;
    geom_tri_make(&t, pd->p[i], pd->p[k], pd->p[j]);
    out[k - k0] = measure_eval(pd->measure, &t);
  }
}

typedef struct got_kernel_entry {
  got_kernel_fn fn;
  int needs;
  got_kernel_fn sq;     /* b^2 without a final sqrt, or NULL (see got_pairs_new_sq) */
} got_kernel_entry;

/* Indexed by the built-in measure ids of badness/measure.h. */
static const got_kernel_entry got_kernels[MEASURE_BUILTIN_COUNT] = {
  [MEASURE_NEG_ALPHA] = {got_k_neg_alpha, GOT_NEED_DIR, NULL},
  [MEASURE_BETA] = {got_k_beta, GOT_NEED_DIR, NULL},
  [MEASURE_GAMMA] = {got_k_gamma, GOT_NEED_DIR, NULL},
  [MEASURE_A] = {got_k_a, GOT_NEED_LEN, NULL},
  [MEASURE_NEG_C] = {got_k_neg_c, GOT_NEED_LEN, NULL},
  [MEASURE_P] = {got_k_p, GOT_NEED_LEN, NULL},
  [MEASURE_ABC] = {got_k_abc, GOT_NEED_LEN, NULL},
  [MEASURE_NEG_AREA] = {got_k_neg_area, GOT_NEED_AREA, NULL},
  [MEASURE_R] = {got_k_r, GOT_NEED_LEN | GOT_NEED_AREA, NULL},
  [MEASURE_NEG_R] = {got_k_neg_r, GOT_NEED_LEN | GOT_NEED_AREA, NULL},
  [MEASURE_NEG_H] = {got_k_neg_h, GOT_NEED_LEN | GOT_NEED_AREA, NULL},
  [MEASURE_NEG_R_OVER_R] = {got_k_neg_r_over_r, GOT_NEED_LEN | GOT_NEED_AREA, NULL},
  [MEASURE_NEG_R2_OVER_A] = {got_k_neg_r2_over_a, GOT_NEED_LEN | GOT_NEED_AREA, NULL},
  [MEASURE_NEG_C_OVER_A] = {got_k_neg_c_over_a, GOT_NEED_LEN, NULL},
  [MEASURE_NEG_C_OVER_P] = {got_k_neg_c_over_p, GOT_NEED_LEN, NULL},
  [MEASURE_A_MINUS_C] = {got_k_a_minus_c, GOT_NEED_LEN, NULL},
  [MEASURE_B_OVER_C_MINUS_A] = {got_k_b_over_c_minus_a, GOT_NEED_LEN, NULL},
  [MEASURE_LAMBDA] = {got_k_lambda, GOT_NEED_AREA, NULL},
  [MEASURE_D] = {got_k_d, GOT_NEED_LEN | GOT_NEED_AREA, NULL},
  [MEASURE_SIGMA] = {got_k_sigma, GOT_NEED_DIR, got_k_sigma2},
  [MEASURE_PINF] = {got_k_pinf, 0, NULL},
  [MEASURE_RINF] = {got_k_rinf, 0, NULL},
  [MEASURE_NEG_RINF] = {got_k_neg_rinf, GOT_NEED_AREA, NULL},
};

int got_measure_has_kernel(int measure) {
  return measure >= 0 && measure < MEASURE_BUILTIN_COUNT && got_kernels[measure].fn != NULL;
}

/* Number of n x n double tables the measure's kernel reads. */
int got_kernel_tables(int measure) {
  if (!got_measure_has_kernel(measure)) return 0;
  int nd = got_kernels[measure].needs;
  return ((nd & GOT_NEED_LEN) != 0) + ((nd & GOT_NEED_DIR) != 0);
}

int got_measure_has_square(int measure) {
  return got_measure_has_kernel(measure) && got_kernels[measure].sq != NULL;
}

got_pairs *got_pairs_new_sq(const geom_point *p, size_t n, int measure, int threads) {
  got_pairs *pd = got_pairs_new(p, n, measure, threads);
  if (pd != NULL && got_measure_has_square(measure)) {
    pd->fn = got_kernels[measure].sq;
    pd->squared = 1;
  }
  return pd;
}

got_pairs *got_pairs_new(const geom_point *p, size_t n, int measure, int threads) {
  got_pairs *pd = calloc(1, sizeof *pd);
  if (pd == NULL) return NULL;
  pd->n = n;
  pd->measure = measure;
  pd->p = malloc(n * sizeof *pd->p);
  pd->x = malloc(n * sizeof *pd->x);
  pd->y = malloc(n * sizeof *pd->y);
  int needs = 0;
  if (got_measure_has_kernel(measure)) {
    pd->fn = got_kernels[measure].fn;
    needs = got_kernels[measure].needs;
    pd->thin_check = (needs & (GOT_NEED_DIR | GOT_NEED_AREA)) != 0;
  } else {
    pd->fn = got_k_generic;
  }
  if (needs & GOT_NEED_LEN) pd->len = malloc(n * n * sizeof *pd->len);
  if (needs & GOT_NEED_DIR) pd->dir = malloc(n * n * sizeof *pd->dir);
  if (pd->p == NULL || pd->x == NULL || pd->y == NULL ||
      ((needs & GOT_NEED_LEN) && pd->len == NULL) ||
      ((needs & GOT_NEED_DIR) && pd->dir == NULL)) {
    got_pairs_free(pd);
    return NULL;
  }
  for (size_t i = 0; i < n; i++) {
    pd->p[i] = p[i];
    pd->x[i] = p[i].x;
    pd->y[i] = p[i].y;
  }
  threads = geom_threads_clamp(threads, 1);
  /* One row per iteration; the lower triangle mirrors the upper one
  ** (lengths exactly, directions by a pi shift), so every value is
  ** computed once and the tables are identical whatever the threads. */
  long ln = (long)n;
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
  for (long li = 0; li < ln; li++) {
    size_t i = (size_t)li;
    for (size_t k = i + 1; k < n; k++) {
      double dx = p[k].x - p[i].x, dy = p[k].y - p[i].y;
      if (pd->len) pd->len[i * n + k] = pd->len[k * n + i] = sqrt(dx * dx + dy * dy);
      if (pd->dir) {
        double th = atan2(dy, dx);
        pd->dir[i * n + k] = th;
        pd->dir[k * n + i] = th > 0 ? th - GOT_PI : th + GOT_PI;
      }
    }
    if (pd->len) pd->len[i * n + i] = 0;
    if (pd->dir) pd->dir[i * n + i] = 0;
  }
  return pd;
}

/* Thin triangles.  The kernels' cross product u x w (u = p_j - p_i,
** w = p_k - p_i) cancels, and their angles are differences of directions
** good to about 1e-15 rad: on a thin triangle either can be wrong in every
** digit, or 0, where geom_tri_make is accurate (geom_twice_area, atan2 of
** the accurate area).  A triangle passes when |fl(u x w)| > 2^-20 (|u|^2 +
** |w|^2): its longest side a has a^2 <= 2 (|u|^2 + |w|^2), so every angle
** has a sine 2A/(bc) >= 2A/a^2 > 2^-22 (the kernels' angles are then good to
** 1e-8 relative), and the cross product's rounding error, below
** 3 eps (|u|^2 + |w|^2), is under 2^-31 of it.  The others are recomputed
** through geom_tri_make; inside the coordinate contract they are rare except
** on flat polygons. */
static void got_pairs_thin(const got_pairs *pd, size_t i, size_t j, size_t k0, size_t k1,
                           double *out) {
  const double *X = pd->x, *Y = pd->y;
  const double ux = X[j] - X[i], uy = Y[j] - Y[i];
  const double u2 = ux * ux + uy * uy;
  for (size_t k = k0; k < k1; k++) {
    double wx = X[k] - X[i], wy = Y[k] - Y[i];
    if (fabs(wx * uy - wy * ux) > 0x1p-20 * (u2 + wx * wx + wy * wy)) continue;
    geom_tri t;
    geom_tri_make(&t, pd->p[i], pd->p[k], pd->p[j]);
    double b = measure_eval(pd->measure, &t);
    out[k - k0] = pd->squared ? b * b : b;
  }
}

void got_pairs_eval(const got_pairs *pd, size_t i, size_t j, size_t k0, size_t k1,
                    double *out) {
  pd->fn(pd, i, j, k0, k1, out);
  if (pd->thin_check) got_pairs_thin(pd, i, j, k0, k1, out);
}

void got_pairs_free(got_pairs *pd) {
  if (pd == NULL) return;
  free(pd->p);
  free(pd->x);
  free(pd->y);
  free(pd->len);
  free(pd->dir);
  free(pd);
}
