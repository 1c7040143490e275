/*
** predicates.c: orientation, incircle and power tests, exact for double
** inputs.
**
** Each test first evaluates its determinant in floating point and accepts
** the sign when the value is larger than a proven bound on the rounding
** error (the filters; the bounds are Shewchuk's "stage A" bounds, Adaptive
** Precision Floating-Point Arithmetic and Fast Robust Geometric
** Predicates, 1997, section 4, which cover the rounding of the input
** differences as well as of the products and sums).  What a filter cannot
** decide, a determinant exactly zero or nearly so (grids, integer
** coordinates, cocircular sites), is decided here, exactly, by the first
** of three stages that applies:
**
**   1. integers (int64_t, __int128, 256-bit sums), when every coordinate
**      difference is exact in double and all are integer multiples of one
**      power of two, below 2^62 in that unit: integer grids and lattices,
**      integer coordinates below 2^52, and most tuples of sites close
**      together next to their distance from the origin (tens of
**      nanoseconds);
**   2. floating-point expansions (sums of doubles carried exactly), when
**      every coordinate is 0 or of magnitude in [2^-200, 2^200] (the whole
**      coordinate contract) and, for incircle and power, the differences
**      are exact (their spread is then more than 62 bits);
**   3. GMP rationals otherwise (every double is a rational, so mpq
**      arithmetic is exact): the last resort, and the reference the tests
**      compare the other two with (geom_exact_gmp_only).
** All three compute the same exact determinant, so the stage that decides
** changes no answer, only its cost; geom_exact_stage_calls counts them.
*/
#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <string.h>
#include <gmp.h>
#include "fliplab_config.h"
#include "predicates.h"
#include "geom_int_internal.h"
#include "geom_exact_internal.h"

/* GEOM_EPS, and why tiny differences skip the filter: see predicates.h. */

/* One counter per predicate and deciding stage (predicates.h). */
static atomic_ulong geom_exact_count[GEOM_PRED_COUNT][GEOM_STAGE_COUNT];

static void geom_exact_note(geom_pred p, geom_stage s) {
  atomic_fetch_add_explicit(&geom_exact_count[p][s], 1, memory_order_relaxed);
}

unsigned long geom_exact_stage_calls(geom_pred p, geom_stage s) {
  return atomic_load_explicit(&geom_exact_count[p][s], memory_order_relaxed);
}

unsigned long geom_exact_calls(void) {
  unsigned long n = 0;
  for (int p = 0; p < GEOM_PRED_COUNT; p++)
    for (int s = 0; s < GEOM_STAGE_COUNT; s++) n += geom_exact_stage_calls(p, s);
  return n;
}

static atomic_int geom_gmp_only;

int geom_exact_gmp_only(int on) {
  return atomic_exchange_explicit(&geom_gmp_only, on != 0, memory_order_relaxed);
}

int geom_exact_gmp_forced(void) {
  return atomic_load_explicit(&geom_gmp_only, memory_order_relaxed);
}

/* NaN and infinities have no rational value (mpq_set_d would abort): the
** predicates answer 0 for them; callers validate input beforehand. */
static int geom_finite4(geom_point a, geom_point b, geom_point c, geom_point d) {
  return isfinite(a.x) && isfinite(a.y) && isfinite(b.x) && isfinite(b.y)
      && isfinite(c.x) && isfinite(c.y) && isfinite(d.x) && isfinite(d.y);
}

/* The first two stages may run: not in GMP-only mode, and the n points (and
** their weights, w != NULL) moderate: coordinates 0 or of magnitude in
** [2^-200, 2^200], weights 0 or in [2^-400, 2^400] (a weight is a squared
** length), the ranges within which those stages are exact (their arguments
** below). */
static int geom_fast_ok(const geom_point *p, int n, const double *w) {
  int ok = !geom_exact_gmp_forced();
  for (int i = 0; i < n; i++)
    ok &= geom_moderate(p[i].x, 0x1p-200, 0x1p200) & geom_moderate(p[i].y, 0x1p-200, 0x1p200);
  for (int i = 0; w != NULL && i < n; i++) ok &= geom_moderate(w[i], 0x1p-400, 0x1p400);
  return ok;
}

/* The exact paths are rare on most inputs: their entry points are cold and
** out of line, so the filters stay small enough to inline cheaply into
** their callers' hot loops.  On grids and integer inputs, though, they
** decide a large share of all tests, so each entry point hands over at
** once to a function compiled for speed (FLIPLAB_NOINLINE), and the
** expansions stay out of it (their buffers would enlarge its frame). */
#define GEOM_COLD FLIPLAB_COLD

/* ---- stage 3: GMP rationals --------------------------------------------- */

/* The orientation determinant (bx-ax)(cy-ay) - (by-ay)(cx-ax) of finite
** points, exactly, into det (initialised): every double is a rational, so
** mpq arithmetic loses nothing.  The one GMP form of it, behind
** geom_orient_exact and geom_twice_area_gmp. */
static void geom_orient_det_q(mpq_t det, geom_point a, geom_point b, geom_point c) {
  mpq_t t[4];
  for (int i = 0; i < 4; i++) mpq_init(t[i]);
  mpq_set_d(t[0], b.x); mpq_set_d(det, a.x); mpq_sub(t[0], t[0], det);  /* bx - ax */
  mpq_set_d(t[1], c.y); mpq_set_d(det, a.y); mpq_sub(t[1], t[1], det);  /* cy - ay */
  mpq_set_d(t[2], b.y); mpq_sub(t[2], t[2], det);                       /* by - ay */
  mpq_set_d(t[3], c.x); mpq_set_d(det, a.x); mpq_sub(t[3], t[3], det);  /* cx - ax */
  mpq_mul(t[0], t[0], t[1]);
  mpq_mul(t[2], t[2], t[3]);
  mpq_sub(det, t[0], t[2]);
  for (int i = 0; i < 4; i++) mpq_clear(t[i]);
}

static int geom_orient_sign_q(geom_point a, geom_point b, geom_point c) {
  mpq_t det;
  mpq_init(det);
  geom_orient_det_q(det, a, b, c);
  int s = mpq_sgn(det);
  mpq_clear(det);
  return s;
}

/* The lifted determinant of a, b, c, d translated so that d is the origin:
**   | adx ady adx^2+ady^2-(wa-wd) |
**   | bdx bdy bdx^2+bdy^2-(wb-wd) |
**   | cdx cdy cdx^2+cdy^2-(wc-wd) |
** (positive when d's lifted point lies below the plane of the others', abc
** anticlockwise), exactly; w == NULL: all weights 0, the incircle
** determinant.  The one GMP form behind geom_incircle_exact and
** geom_power_exact. */
static int geom_lifted_sign_q(geom_point a, geom_point b, geom_point c, geom_point d,
                              const double w[4]) {
  geom_point pt[3] = {a, b, c};
  mpq_t x[3], y[3], lift[3], t, u, det;
  mpq_inits(t, u, det, NULL);
  for (int i = 0; i < 3; i++) {
    mpq_inits(x[i], y[i], lift[i], NULL);
    mpq_set_d(x[i], pt[i].x); mpq_set_d(t, d.x); mpq_sub(x[i], x[i], t);
    mpq_set_d(y[i], pt[i].y); mpq_set_d(t, d.y); mpq_sub(y[i], y[i], t);
    mpq_mul(lift[i], x[i], x[i]);
    mpq_mul(t, y[i], y[i]);
    mpq_add(lift[i], lift[i], t);
    if (w != NULL) {
      mpq_set_d(t, w[i]);
      mpq_set_d(u, w[3]);
      mpq_sub(t, t, u);
      mpq_sub(lift[i], lift[i], t);
    }
  }
  mpq_set_ui(det, 0, 1);
  for (int i = 0; i < 3; i++) {
    int j = (i + 1) % 3, k = (i + 2) % 3;
    mpq_mul(t, x[j], y[k]);          /* lift_i * (x_j y_k - x_k y_j) */
    mpq_mul(u, x[k], y[j]);
    mpq_sub(t, t, u);
    mpq_mul(t, t, lift[i]);
    mpq_add(det, det, t);
  }
  int s = mpq_sgn(det);
  for (int i = 0; i < 3; i++) mpq_clears(x[i], y[i], lift[i], NULL);
  mpq_clears(t, u, det, NULL);
  return s;
}

/* ---- stage 1: 128-bit integers ------------------------------------------
**
** When every coordinate difference d is exact in double and all are integer
** multiples of one unit u = 2^k with |d/u| < 2^62, the determinant is u^m
** times the same determinant of the integers d/u (m its degree), with the
** same sign, computed in int64_t, __int128 and (the lifted determinant's
** products) 256-bit magnitudes, each routine's bound written above it.  The
** unit comes from the largest |d|: with 2^(e-1) <= max |d| < 2^e, u = 2^(e
** - 62) makes every |d/u| < 2^62; and any unit u' that works has 2^(e-1) <
** 2^62 u', so u' >= u and multiples of u' are multiples of u: testing u
** alone loses no case.  The scaling is exact: with moderate coordinates
** (geom_fast_ok) every nonzero |d| lies in [2^-252, 2^201], so 1/u lies in
** [2^-140, 2^313] and d/u is a normal double in [2^-392, 2^62); a nonzero
** weight difference (moderate weights: in [2^-452, 2^401]) times 1/u^2 is
** at least 2^-732, normal, or overflows to infinity, which the bound test
** refuses.  Where the compiler has no __int128 the stage is skipped and the
** expansions decide. */
/* geom_i128, geom_u128 and geom_u256 where the compiler has __int128:
** geom_int_internal.h. */

/* 1/u = 2^(62 - e) for the n values v (1 when all are 0), e read off the
** exponent field of the largest (a normal double: 2^(e-1) <= m < 2^e for
** the biased exponent e + 1022), 1/u made from its own exponent field. */
double geom_int_scale(const double *v, int n) {
  double m = 0;
  for (int i = 0; i < n; i++) m = fabs(v[i]) > m ? fabs(v[i]) : m;
  if (m == 0) return 1;
  uint64_t b;
  memcpy(&b, &m, sizeof b);
  int e = (int)(b >> 52) - 1022;
  b = (uint64_t)(1023 + 62 - e) << 52;
  memcpy(&m, &b, sizeof m);
  return m;
}

/* z[i] = v[i] s for i < n when every one is an integer of magnitude below
** lim (<= 2^62): 1; else 0. */
int geom_ints(const double *v, int n, double s, double lim, int64_t *z) {
  for (int i = 0; i < n; i++) {
    double t = v[i] * s;
    if (!(fabs(t) < lim) || t != (double)(int64_t)t) return 0;
    z[i] = (int64_t)t;
  }
  return 1;
}

/* The orientation determinant d0 d1 - d2 d3 of exact differences in 128-bit
** integers: 1 and *sign, or 0 when they are not integer multiples of one
** unit below 2^62 in it.  With |z| < 2^62 each product is below 2^124 and
** the difference below 2^125, inside __int128's 2^127. */
static int geom_orient_int(const double d[4], int *sign) {
#if GEOM_HAVE_INT128
  int64_t z[4];
  if (!geom_ints(d, 4, geom_int_scale(d, 4), 0x1p62, z)) return 0;
  geom_i128 det = (geom_i128)z[0] * z[1] - (geom_i128)z[2] * z[3];
  *sign = (det > 0) - (det < 0);
  return 1;
#else
  (void)d, (void)sign;
  return 0;
#endif
}

#if GEOM_HAVE_INT128
/* geom_u256: the magnitudes of the lifted determinant's products
** (geom_int_internal.h). */

/* r += a b, for a, b below 2^127 whose products, summed into r, stay below
** 2^256 (the caller's bound): the four 64 x 64-bit partial products,
** added with their carries. */
void geom_u256_addmul(geom_u256 *r, geom_u128 a, geom_u128 b) {
  uint64_t a0 = (uint64_t)a, a1 = (uint64_t)(a >> 64), b0 = (uint64_t)b, b1 = (uint64_t)(b >> 64);
  geom_u128 p00 = (geom_u128)a0 * b0, p01 = (geom_u128)a0 * b1;
  geom_u128 p10 = (geom_u128)a1 * b0, p11 = (geom_u128)a1 * b1;
  geom_u128 mid = (p00 >> 64) + (uint64_t)p01 + (uint64_t)p10;   /* < 3 2^64 */
  geom_u128 hi = (mid >> 64) + (p01 >> 64) + (p10 >> 64) + p11;  /* the product's top half */
  const uint64_t t[4] = {(uint64_t)p00, (uint64_t)mid, (uint64_t)hi, (uint64_t)(hi >> 64)};
  geom_u128 carry = 0;
  for (int i = 0; i < 4; i++) {
    carry += (geom_u128)r->w[i] + t[i];
    r->w[i] = (uint64_t)carry;
    carry >>= 64;
  }
}

/* The sign of a - b. */
int geom_u256_cmp(const geom_u256 *a, const geom_u256 *b) {
  for (int i = 3; i >= 0; i--)
    if (a->w[i] != b->w[i]) return a->w[i] > b->w[i] ? 1 : -1;
  return 0;
}

/* w[i] = W[i] s2 for i < 3 when every one is an integer below 2^125 in
** magnitude: 1; else 0. */
static int geom_wide_ints(const double W[3], double s2, geom_i128 w[3]) {
  for (int i = 0; i < 3; i++) {
    double t = W[i] * s2;
    if (!(fabs(t) < 0x1p125) || t != (double)(geom_i128)t) return 0;
    w[i] = (geom_i128)t;
  }
  return 1;
}

/* The lifted determinant sum_i L_i (x_j y_k - x_k y_j), L_i = x_i^2 + y_i^2
** - W_i, of integers x = z[0..2], y = z[3..5] below 2^62 in magnitude and W
** below 2^125: x^2 + y^2 < 2^125, so |L| < 2^126, and each minor is below
** 2^125, both in __int128; each product |L m| is below 2^251, and the
** positive and the negative products are summed apart as 256-bit
** magnitudes (below 2^253 each), whose comparison is the sign. */
static int geom_lifted_wide(const int64_t z[6], const geom_i128 w[3]) {
  geom_u256 pos = {{0, 0, 0, 0}}, neg = {{0, 0, 0, 0}};
  for (int i = 0; i < 3; i++) {
    int j = (i + 1) % 3, k = (i + 2) % 3;
    geom_i128 lift = (geom_i128)z[i] * z[i] + (geom_i128)z[3 + i] * z[3 + i] - w[i];
    geom_i128 minor = (geom_i128)z[j] * z[3 + k] - (geom_i128)z[k] * z[3 + j];
    geom_u256_addmul((lift < 0) != (minor < 0) ? &neg : &pos,
                     (geom_u128)(lift < 0 ? -lift : lift), (geom_u128)(minor < 0 ? -minor : minor));
  }
  return geom_u256_cmp(&pos, &neg);
}

/* The same without weights for integers below 2^30 (a grid's common case,
** three multiplications where the wide form takes twelve): x^2 + y^2 <
** 2^61 and each minor below 2^61, both in int64_t; each product is below
** 2^122 and the sum of three below 2^124, inside __int128. */
static int geom_lifted_narrow(const int64_t z[6]) {
  geom_i128 det = 0;
  for (int i = 0; i < 3; i++) {
    int j = (i + 1) % 3, k = (i + 2) % 3;
    int64_t lift = z[i] * z[i] + z[3 + i] * z[3 + i];
    int64_t minor = z[j] * z[3 + k] - z[k] * z[3 + j];
    det += (geom_i128)lift * minor;
  }
  return (det > 0) - (det < 0);
}
#endif

/* The lifted determinant of exact differences x, y (and weight differences
** W, or NULL: the incircle test) in integers: 1 and *sign, or 0 when they
** are not integer multiples of one unit below 2^62 in it (and W of its
** square, below 2^125).  When every integer is a multiple of 2^32 (the
** unit could be 2^32 times coarser: differences within 2^30 of it) and
** there are no weights, the narrow form decides, else the wide one. */
static int geom_lifted_int(const double x[3], const double y[3], const double *W, int *sign) {
#if GEOM_HAVE_INT128
  const double v[6] = {x[0], x[1], x[2], y[0], y[1], y[2]};
  double s = geom_int_scale(v, 6);
  int64_t z[6];
  geom_i128 w[3] = {0, 0, 0};
  if (!geom_ints(v, 6, s, 0x1p62, z) || (W != NULL && !geom_wide_ints(W, s * s, w))) return 0;
  uint64_t low = 0;
  for (int i = 0; i < 6; i++) low |= (uint64_t)z[i] & 0xffffffffu;
  if (W != NULL || low != 0) {
    *sign = geom_lifted_wide(z, w);
    return 1;
  }
  geom_ints(v, 6, s * 0x1p-32, 0x1p30, z);   /* the same integers over 2^32, exactly */
  *sign = geom_lifted_narrow(z);
  return 1;
#else
  (void)x, (void)y, (void)W, (void)sign;
  return 0;
#endif
}

/* ---- stage 2: floating-point expansions ---------------------------------
**
** An expansion (Shewchuk 1997, section 2) is a sum of doubles,
** nonoverlapping and increasing in magnitude, whose sign is the sign of
** its largest component.  The error-free transformations (the sum,
** difference and product of two doubles as two doubles,
** geom_exact_internal.h) and the operations built on them below keep every
** value exact; they need round to
** nearest even, no contraction into FMA (fliplab_config.h), and neither
** overflow nor underflow.  With moderate coordinates every difference term
** is a multiple of 2^-252 below 2^201 in magnitude, so every term of a
** determinant of degree 4 is a multiple of 2^-1008 (a granularity doubles
** hold exactly: 2^-1074) below 2^810, and Dekker's split multiplies no
** value above 2^405 by 2^27 + 1; weight terms (moderate weights: multiples
** of 2^-452 below 2^401) stay within the same ranges. */

/* h = e + b (e has n components; h gets at most n + 1, zeros dropped, at
** least one).  Returns h's length.  h may not alias e. */
int geom_grow_expansion(int n, const double *e, double b, double *h) {
  int k = 0;
  double q = b;
  for (int i = 0; i < n; i++) {
    double hh;
    geom_two_sum(q, e[i], &q, &hh);
    if (hh != 0) h[k++] = hh;
  }
  if (q != 0 || k == 0) h[k++] = q;
  return k;
}

/* h = e + f (n and m components): the components of both merged by
** magnitude, then added from the smallest up, each addition's rounding
** error kept as a component (Shewchuk's fast expansion sum, section 2.6,
** nonoverlapping under round to nearest even).  At most n + m components,
** zeros dropped, at least one.  Cost O(n + m).  h may not alias e or f. */
int geom_expansion_sum(int n, const double *e, int m, const double *f, double *h) {
  int i = 0, j = 0, k = 0;
  double q = 0;
  while (i < n || j < m) {
    double g = j >= m || (i < n && fabs(e[i]) <= fabs(f[j])) ? e[i++] : f[j++], hh;
    geom_two_sum(q, g, &q, &hh);
    if (hh != 0) h[k++] = hh;
  }
  if (q != 0 || k == 0) h[k++] = q;
  return k;
}

/* h = e b: each e_i b as a two-term product, its halves added in turn to a
** running sum (Shewchuk's scale expansion, section 2.7, nonoverlapping
** under round to nearest even).  At most 2n components, zeros dropped, at
** least one.  Cost O(n).  h may not alias e. */
int geom_scale_expansion(int n, const double *e, double b, double *h) {
  double q, hh, p, t, s;
  int k = 0;
  geom_two_product(e[0], b, &q, &hh);
  if (hh != 0) h[k++] = hh;
  for (int i = 1; i < n; i++) {
    geom_two_product(e[i], b, &p, &t);
    geom_two_sum(q, t, &s, &hh);
    if (hh != 0) h[k++] = hh;
    geom_two_sum(p, s, &q, &hh);
    if (hh != 0) h[k++] = hh;
  }
  if (q != 0 || k == 0) h[k++] = q;
  return k;
}

/* e (n components) in place as an expansion of as few components as its
** value allows, at most n (Shewchuk's compress, section 2.8): a sweep
** from the largest component down gathers each run of components that sum
** exactly into one, then a sweep up splits the sums back into
** nonoverlapping parts.  Each step is a fast two-sum, exact when the first
** operand is at least the second in magnitude, which the nonoverlapping
** order gives.  The value is unchanged; the length, which every later
** product multiplies, rarely exceeds what the value's bits need (a few
** components for a polynomial of degree 8 in doubles).  Cost O(n). */
int geom_expansion_compress(int n, double *e) {
  int bottom = n - 1;
  double q = e[bottom];
  for (int i = n - 2; i >= 0; i--) {
    double x = q + e[i], lo = e[i] - (x - q);
    if (lo != 0) {
      e[bottom--] = x;
      q = lo;
    } else {
      q = x;
    }
  }
  int top = 0;
  for (int i = bottom + 1; i < n; i++) {
    double x = e[i] + q, lo = q - (x - e[i]);
    if (lo != 0) e[top++] = lo;
    q = x;
  }
  e[top] = q;
  return top + 1;
}

/* The largest products the lifted determinant forms (geom_lifted_term): a
** lift of at most 5 components times a minor of at most 4. */
#define GEOM_LIFT_MAX 5
#define GEOM_MINOR_MAX 4
#define GEOM_TERM_MAX (2 * GEOM_LIFT_MAX * GEOM_MINOR_MAX)

/* h = e f (geom_exact_internal.h): e scaled by each component of f, the
** parts summed, in scratch (part: 2 n, acc: 2 n m).  Cost O(n m^2). */
int geom_expansion_product(int n, const double *e, int m, const double *f, double *h,
                           double *scratch) {
  double *part = scratch, *acc = scratch + 2 * n;
  int k = geom_scale_expansion(n, e, f[0], h);
  for (int j = 1; j < m; j++) {
    int np = geom_scale_expansion(n, e, f[j], part);
    k = geom_expansion_sum(k, h, np, part, acc);
    memcpy(h, acc, (size_t)k * sizeof *h);
  }
  return k;
}

/* The sign of (e - t), e an expansion of n components (exact). */
static int geom_expansion_cmp(int n, const double *e, double t) {
  double h[34];
  int k = geom_grow_expansion(n, e, -t, h);
  return (h[k - 1] > 0) - (h[k - 1] < 0);
}

/* Adds a * b to the expansion e of *n components (kept in place). */
static void geom_add_product(double *e, int *n, double a, double b) {
  if (a == 0 || b == 0) return;
  double x, y, h[34];
  geom_two_product(a, b, &x, &y);
  int k = *n;
  if (y != 0) {
    k = geom_grow_expansion(k, e, y, h);
    for (int i = 0; i < k; i++) e[i] = h[i];
  }
  k = geom_grow_expansion(k, e, x, h);
  for (int i = 0; i < k; i++) e[i] = h[i];
  *n = k;
}

/* The orientation determinant's differences bx - ax, cy - ay, by - ay,
** cx - ax, each as d[0][k] + d[1][k] (geom_two_diff: the rounded value and
** its error): 1 when every one is exact (every error is 0). */
static int geom_orient_diffs(geom_point a, geom_point b, geom_point c, double d[2][4]) {
  geom_two_diff(b.x, a.x, &d[0][0], &d[1][0]);
  geom_two_diff(c.y, a.y, &d[0][1], &d[1][1]);
  geom_two_diff(b.y, a.y, &d[0][2], &d[1][2]);
  geom_two_diff(c.x, a.x, &d[0][3], &d[1][3]);
  return (d[1][0] == 0) & (d[1][1] == 0) & (d[1][2] == 0) & (d[1][3] == 0);
}

/* The orientation determinant (d0)(d1) - (d2)(d3) of those differences,
** exactly, as an expansion into e (room for 34): each of the 8 products of
** terms is a two-term product, and each of those 16 doubles is added with
** geom_grow_expansion (zero terms skipped, so exact differences cost two
** products).  Returns its length. */
static int geom_orient_expansion(double d[2][4], double e[34]) {
  int n = 1;
  e[0] = 0;
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++) {
      geom_add_product(e, &n, d[i][0], d[j][1]);
      geom_add_product(e, &n, -d[i][2], d[j][3]);
    }
  return n;
}

/* x_i = p_i.x - p_3.x, y_i likewise and W_i = w_i - w_3 (w != NULL), i < 3:
** 1 when every one is exact in double (geom_two_diff's error is 0). */
static int geom_lifted_diffs(const geom_point p[4], const double *w, double x[3], double y[3],
                             double W[3]) {
  int exact = 1;
  for (int i = 0; i < 3; i++) {
    double ex, ey, ew = 0;
    geom_two_diff(p[i].x, p[3].x, &x[i], &ex);
    geom_two_diff(p[i].y, p[3].y, &y[i], &ey);
    if (w != NULL) geom_two_diff(w[i], w[3], &W[i], &ew);
    exact &= (ex == 0) & (ey == 0) & (ew == 0);
  }
  return exact;
}

/* The term L_i (x_j y_k - x_k y_j) of the lifted determinant (W == NULL:
** no weights) as an expansion into h (room for GEOM_TERM_MAX): the lift
** x_i^2 + y_i^2 - W_i has at most 5 components, the minor at most 4. */
static int geom_lifted_term(const double x[3], const double y[3], const double *W, int i,
                            double *h) {
  int j = (i + 1) % 3, k = (i + 2) % 3;
  double sx[2], sy[2], u[2], v[2], sq[4], lift[GEOM_LIFT_MAX], minor[GEOM_MINOR_MAX];
  double scratch[2 * GEOM_LIFT_MAX + GEOM_TERM_MAX];
  geom_two_product(x[i], x[i], &sx[1], &sx[0]);
  geom_two_product(y[i], y[i], &sy[1], &sy[0]);
  int nl = geom_expansion_sum(2, sx, 2, sy, W == NULL ? lift : sq);
  if (W != NULL) nl = geom_grow_expansion(nl, sq, -W[i], lift);
  geom_two_product(x[j], y[k], &u[1], &u[0]);
  geom_two_product(-x[k], y[j], &v[1], &v[0]);
  int nm = geom_expansion_sum(2, u, 2, v, minor);
  return geom_expansion_product(nl, lift, nm, minor, h, scratch);
}

/* The sign of the lifted determinant of exact differences, summed as an
** expansion of at most 3 GEOM_TERM_MAX components. */
static FLIPLAB_NOINLINE int geom_lifted_sign_expansion(const double x[3], const double y[3],
                                                        const double *W) {
  double det[3 * GEOM_TERM_MAX], sum[3 * GEOM_TERM_MAX], term[GEOM_TERM_MAX];
  int n = geom_lifted_term(x, y, W, 0, det);
  for (int i = 1; i < 3; i++) {
    int nt = geom_lifted_term(x, y, W, i, term);
    n = geom_expansion_sum(n, det, nt, term, sum);
    memcpy(det, sum, (size_t)n * sizeof *det);
  }
  return (det[n - 1] > 0) - (det[n - 1] < 0);
}

/* ---- the exact halves of the predicates ---------------------------------- */

/* The exact half of geom_orient (predicates.h holds the filter): stage 1
** when the differences allow it, else stage 2 (exact for any moderate
** coordinates, rounded differences and all), else GMP. */
static FLIPLAB_NOINLINE int geom_orient_stages(geom_point a, geom_point b, geom_point c) {
  const geom_point p[3] = {a, b, c};
  if (geom_fast_ok(p, 3, NULL)) {
    double d[2][4], e[34];
    int s, n;
    if (geom_orient_diffs(a, b, c, d) && geom_orient_int(d[0], &s)) {
      geom_exact_note(GEOM_PRED_ORIENT, GEOM_STAGE_INT);
      return s;
    }
    geom_exact_note(GEOM_PRED_ORIENT, GEOM_STAGE_EXPANSION);
    n = geom_orient_expansion(d, e);
    return (e[n - 1] > 0) - (e[n - 1] < 0);
  }
  geom_exact_note(GEOM_PRED_ORIENT, GEOM_STAGE_GMP);
  return geom_finite4(a, b, c, a) ? geom_orient_sign_q(a, b, c) : 0;
}

GEOM_COLD int geom_orient_exact(geom_point a, geom_point b, geom_point c) {
  return geom_orient_stages(a, b, c);
}

/* The exact half of geom_incircle and geom_power (pred names the counter):
** stages 1 and 2 when the differences are exact, else GMP. */
static FLIPLAB_NOINLINE int geom_lifted_exact(geom_pred pred, const geom_point p[4],
                                               const double *w) {
  double x[3], y[3], W[3];
  if (geom_fast_ok(p, 4, w) && geom_lifted_diffs(p, w, x, y, W)) {
    int s;
    if (geom_lifted_int(x, y, w != NULL ? W : NULL, &s)) {
      geom_exact_note(pred, GEOM_STAGE_INT);
      return s;
    }
    geom_exact_note(pred, GEOM_STAGE_EXPANSION);
    return geom_lifted_sign_expansion(x, y, w != NULL ? W : NULL);
  }
  geom_exact_note(pred, GEOM_STAGE_GMP);
  if (!geom_finite4(p[0], p[1], p[2], p[3])) return 0;
  for (int i = 0; w != NULL && i < 4; i++)
    if (!isfinite(w[i])) return 0;
  return geom_lifted_sign_q(p[0], p[1], p[2], p[3], w);
}

GEOM_COLD int geom_incircle_exact(geom_point a, geom_point b, geom_point c, geom_point d) {
  const geom_point p[4] = {a, b, c, d};
  return geom_lifted_exact(GEOM_PRED_INCIRCLE, p, NULL);
}

GEOM_COLD int geom_power_exact(geom_point a, geom_point b, geom_point c, geom_point d,
                               const double w[4]) {
  const geom_point p[4] = {a, b, c, d};
  return geom_lifted_exact(GEOM_PRED_POWER, p, w);
}

/* ---- comparing squared lengths -------------------------------------------
**
** The sign of |ab|^2 - |cd|^2 (predicates.h).  Filter: each rounded
** difference carries a relative error of at most eps, its square one more
** rounding and the sum of two squares one more, so each rounded squared
** length L^ is within (1 + eps)^4 - 1 < 4.01 eps of its exact value, and the
** final subtraction adds eps |L1^ - L2^|: |fl(L1^ - L2^) - (L1 - L2)| <=
** 5.1 eps (L1^ + L2^) (first-order terms, with room for the second-order
** ones).  Tiny differences and overflow go to the exact path, as for
** geom_orient.  Exact: the four differences as two-term expansions
** (geom_two_diff) and the 16 products of their terms added up
** (geom_add_product), for moderate coordinates; GMP rationals otherwise. */
static GEOM_COLD int geom_dist2_cmp_exact(geom_point a, geom_point b, geom_point c,
                                          geom_point d) {
  const geom_point p[4] = {a, b, c, d};
  if (geom_fast_ok(p, 4, NULL)) {
    double t[2][4], e[34];
    int n = 1;
    geom_two_diff(b.x, a.x, &t[0][0], &t[1][0]);
    geom_two_diff(b.y, a.y, &t[0][1], &t[1][1]);
    geom_two_diff(d.x, c.x, &t[0][2], &t[1][2]);
    geom_two_diff(d.y, c.y, &t[0][3], &t[1][3]);
    e[0] = 0;
    for (int i = 0; i < 2; i++)
      for (int j = 0; j < 2; j++)
        for (int k = 0; k < 4; k++)
          geom_add_product(e, &n, k < 2 ? t[i][k] : -t[i][k], t[j][k]);
    return (e[n - 1] > 0) - (e[n - 1] < 0);
  }
  if (!geom_finite4(a, b, c, d)) return 0;
  mpq_t q[5];
  for (int i = 0; i < 5; i++) mpq_init(q[i]);
  const double v[4][2] = {{b.x, a.x}, {b.y, a.y}, {d.x, c.x}, {d.y, c.y}};
  for (int k = 0; k < 4; k++) {
    mpq_set_d(q[k], v[k][0]);
    mpq_set_d(q[4], v[k][1]);
    mpq_sub(q[k], q[k], q[4]);
    mpq_mul(q[k], q[k], q[k]);
  }
  mpq_add(q[0], q[0], q[1]);
  mpq_add(q[2], q[2], q[3]);
  int s = mpq_cmp(q[0], q[2]);
  for (int i = 0; i < 5; i++) mpq_clear(q[i]);
  return (s > 0) - (s < 0);
}

int geom_dist2_cmp(geom_point a, geom_point b, geom_point c, geom_point d) {
  double x1 = b.x - a.x, y1 = b.y - a.y, x2 = d.x - c.x, y2 = d.y - c.y;
  double l1 = x1 * x1 + y1 * y1, l2 = x2 * x2 + y2 * y2, diff = l1 - l2;
  double bound = 5.1 * GEOM_EPS * (l1 + l2);
  if (!(geom_filter_tiny(x1) | geom_filter_tiny(y1) | geom_filter_tiny(x2)
        | geom_filter_tiny(y2))) {
    if (diff > bound) return 1;
    if (-diff > bound) return -1;
  }
  return geom_dist2_cmp_exact(a, b, c, d);
}

/* ---- |orientation determinant| exactly ----------------------------------
**
** geom_twice_area's slow path (flat triangles: 4% of the candidates some
** LOT rules evaluate), so it avoids GMP's allocations and gcds: the
** determinant as an expansion (geom_orient_expansion), for moderate
** coordinates; other finite coordinates go to GMP rationals.
**
** The exact value T = |det| is then rounded toward zero, as mpq_get_d
** does: a candidate t (the plain sum of the components, within a few
** ulps of T) is moved down while t > T and up while its successor is still
** <= T, each comparison exact (the sign of the expansion minus t).  The
** loop ends exactly at the largest double <= T, whatever the candidate's
** accuracy.  tests/test_geom.c checks the result against GMP bit for bit. */

static GEOM_COLD double geom_twice_area_gmp(geom_point p, geom_point q, geom_point r) {
  geom_exact_note(GEOM_PRED_AREA, GEOM_STAGE_GMP);
  mpq_t det;
  mpq_init(det);
  geom_orient_det_q(det, p, q, r);
  mpq_abs(det, det);
  double v = mpq_get_d(det);   /* rounds toward zero */
  mpq_clear(det);
  return v;
}

GEOM_COLD double geom_twice_area_exact(geom_point p, geom_point q, geom_point r) {
  const geom_point t3[3] = {p, q, r};
  if (!geom_fast_ok(t3, 3, NULL)) return geom_twice_area_gmp(p, q, r);
  geom_exact_note(GEOM_PRED_AREA, GEOM_STAGE_EXPANSION);
  double d[2][4], e[34];
  geom_orient_diffs(p, q, r, d);
  int n = geom_orient_expansion(d, e);
  if (e[n - 1] == 0) return 0;
  if (e[n - 1] < 0)
    for (int i = 0; i < n; i++) e[i] = -e[i];
  double t = 0;
  for (int i = 0; i < n; i++) t += e[i];
  if (!(t >= 0)) t = 0;
  while (geom_expansion_cmp(n, e, t) < 0) t = nextafter(t, 0);
  for (double up = nextafter(t, INFINITY); geom_expansion_cmp(n, e, up) >= 0;
       up = nextafter(t, INFINITY))
    t = up;
  return t;
}

/* The power test's filter.  With d the origin, X_i, Y_i the coordinate
** differences, W_i = w_i - w_d and L_i = X_i^2 + Y_i^2 - W_i, the
** determinant is sum_i L_i (X_j Y_k - X_k Y_j) over the cyclic (i, j, k).
** In floating point each difference carries a relative error eps; the sum
** of squares s_i = fl(fl(x^2) + fl(y^2)) is off by at most 4.01 eps S_i
** (S_i = X_i^2 + Y_i^2, a sum of non-negative terms), and l_i = fl(s_i -
** fl(W_i)) by at most 5.1 eps Lam_i, Lam_i = S_i + |W_i|.  The 2 x 2 minor
** m_i = fl(fl(x_j y_k) - fl(x_k y_j)) is off by at most 4.02 eps M_i, M_i =
** |x_j y_k| + |x_k y_j|; so each product l_i m_i by 10.2 eps Lam_i M_i (with
** its own rounding), and the two additions add 2 eps of the sum.  So
** |fl(det) - det| <= 12.2 eps P + O(eps^2) P, P = sum_i Lam_i M_i, and the
** filter uses 16 eps P, which also covers the rounding of P itself (five
** operations, a factor (1 + eps)^5 at worst).  The bound is relative: as
** for the incircle test, differences below 2^-200 (and weight differences
** below 2^-200) go to the exact path, so no term underflows (the coordinate
** contract and the weight contract of geom.h keep every term of P at
** least 2^-800 otherwise), and overflow makes the comparisons fail. */
int geom_power(geom_point a, geom_point b, geom_point c, geom_point d, const double w[4]) {
  const geom_point p[3] = {a, b, c};
  double x[3], y[3], l[3], lam[3], m[3], mm[3];
  int tiny = 0;
  for (int i = 0; i < 3; i++) {
    x[i] = p[i].x - d.x;
    y[i] = p[i].y - d.y;
    double wi = w[i] - w[3], s = x[i] * x[i] + y[i] * y[i];
    l[i] = s - wi;
    lam[i] = s + fabs(wi);
    tiny |= geom_filter_tiny(x[i]) | geom_filter_tiny(y[i]) | geom_filter_tiny(wi);
  }
  for (int i = 0; i < 3; i++) {
    int j = (i + 1) % 3, k = (i + 2) % 3;
    double u = x[j] * y[k], v = x[k] * y[j];
    m[i] = u - v;
    mm[i] = fabs(u) + fabs(v);
  }
  double det = l[0] * m[0] + l[1] * m[1] + l[2] * m[2];
  double bound = 16.0 * GEOM_EPS * (lam[0] * mm[0] + lam[1] * mm[1] + lam[2] * mm[2]);
  if (!tiny) {
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  return geom_power_exact(a, b, c, d, w);
}

/* The filter of geom_incircle is inline in predicates.h; the function above
** is its exact half. */
