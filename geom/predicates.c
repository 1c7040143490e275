/*
** predicates.c: orientation and incircle tests, exact for double inputs.
**
** Each test first evaluates its determinant in floating point and accepts
** the sign when the value is larger than a proven bound on the rounding
** error; otherwise it recomputes the determinant exactly with GMP rationals
** (every double is a rational, so mpq arithmetic is exact).  The bounds are
** Shewchuk's "stage A" bounds (Adaptive Precision Floating-Point Arithmetic
** and Fast Robust Geometric Predicates, 1997, section 4), which cover the
** rounding of the input differences as well as of the products and sums.
*/
#include <math.h>
#include <stdatomic.h>
#include <gmp.h>
#include "fliplab_config.h"
#include "predicates.h"

/* GEOM_EPS, and why tiny differences skip the filter: see predicates.h. */

static atomic_ulong geom_exact_count;

unsigned long geom_exact_calls(void) {
  return atomic_load_explicit(&geom_exact_count, memory_order_relaxed);
}

/* NaN and infinities have no rational value (mpq_set_d would abort): the
** predicates answer 0 for them; callers validate input beforehand. */
static int geom_finite4(geom_point a, geom_point b, geom_point c, geom_point d) {
  return isfinite(a.x) && isfinite(a.y) && isfinite(b.x) && isfinite(b.y)
      && isfinite(c.x) && isfinite(c.y) && isfinite(d.x) && isfinite(d.y);
}

/* The exact paths are rare: keep them out of line so the filters stay small
** enough to inline cheaply into their callers' hot loops. */
#define GEOM_COLD FLIPLAB_COLD

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

/* The exact half of geom_orient (geom.h holds the filter). */
GEOM_COLD int geom_orient_exact(geom_point a, geom_point b, geom_point c) {
  atomic_fetch_add_explicit(&geom_exact_count, 1, memory_order_relaxed);
  if (!geom_finite4(a, b, c, a)) return 0;
  mpq_t det;
  mpq_init(det);
  geom_orient_det_q(det, a, b, c);
  int s = mpq_sgn(det);
  mpq_clear(det);
  return s;
}

/* ---- |orientation determinant| exactly, by floating-point expansions ----
**
** geom_twice_area's slow path (flat triangles: 4% of the candidates some
** LOT rules evaluate), so it avoids GMP's allocations and gcds.  The
** determinant (qx-px)(ry-py) - (qy-py)(rx-px) is carried exactly as an
** expansion (Shewchuk 1997, section 2): a sum of doubles, nonoverlapping
** and increasing in magnitude, whose sign is the sign of its largest
** component.  Each coordinate difference is a two-term expansion
** (geom_two_diff), each of the 8 products of terms is one (geom_two_product,
** Dekker's split), and each of those 16 doubles is added with
** geom_grow_expansion.  These error-free transformations need round to
** nearest, no contraction into FMA (fliplab_config.h), and neither overflow
** nor underflow: with every coordinate 0 or of magnitude in [2^-200, 2^200]
** (the contract's [1e-30, 1e30] and more), every difference term is a
** multiple of 2^-252 below 2^201 in magnitude (as in geom.h), so every
** product term is a multiple of 2^-504 below 2^402, all normal, and the
** split's 2^27 + 1 factor stays below 2^229.  Other finite coordinates go
** to GMP rationals.
**
** The exact value T = |det| is then rounded toward zero, as mpq_get_d
** did before: a candidate t (the plain sum of the components, within a few
** ulps of T) is moved down while t > T and up while its successor is still
** <= T, each comparison exact (the sign of the expansion minus t).  The
** loop ends exactly at the largest double <= T, whatever the candidate's
** accuracy.  tests/test_geom.c checks the result against GMP bit for bit. */

/* x + y = a + b exactly, x = fl(a + b). */
static inline void geom_two_sum(double a, double b, double *x, double *y) {
  double s = a + b, bv = s - a, av = s - bv;
  *x = s;
  *y = (a - av) + (b - bv);
}

/* x + y = a - b exactly, x = fl(a - b). */
static inline void geom_two_diff(double a, double b, double *x, double *y) {
  double d = a - b, bv = a - d, av = d + bv;
  *x = d;
  *y = (a - av) + (bv - b);
}

/* hi + lo = a, each with at most 26 significant bits (Dekker). */
static inline void geom_split(double a, double *hi, double *lo) {
  double c = 134217729.0 * a, big = c - a;
  *hi = c - big;
  *lo = a - *hi;
}

/* x + y = a * b exactly, x = fl(a * b). */
static inline void geom_two_product(double a, double b, double *x, double *y) {
  double p = a * b, ahi, alo, bhi, blo;
  geom_split(a, &ahi, &alo);
  geom_split(b, &bhi, &blo);
  double err = ((p - ahi * bhi) - alo * bhi) - ahi * blo;
  *x = p;
  *y = alo * blo - err;
}

/* h = e + b (e has n components; h gets at most n + 1, zeros dropped, at
** least one).  Returns h's length.  h may not alias e. */
static int geom_grow_expansion(int n, const double *e, double b, double *h) {
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

/* Outside [2^-200, 2^200] (beyond the contract: tests and plugins may go
** there) the expansions could underflow or overflow: exact rationals. */
static GEOM_COLD double geom_twice_area_gmp(geom_point p, geom_point q, geom_point r) {
  mpq_t det;
  mpq_init(det);
  geom_orient_det_q(det, p, q, r);
  mpq_abs(det, det);
  double v = mpq_get_d(det);   /* rounds toward zero */
  mpq_clear(det);
  return v;
}

static int geom_coord_moderate(double x) {
  double m = fabs(x);
  return m == 0 || (m >= 0x1p-200 && m <= 0x1p200);
}

GEOM_COLD double geom_twice_area_exact(geom_point p, geom_point q, geom_point r) {
  atomic_fetch_add_explicit(&geom_exact_count, 1, memory_order_relaxed);
  if (!(geom_coord_moderate(p.x) && geom_coord_moderate(p.y) && geom_coord_moderate(q.x)
        && geom_coord_moderate(q.y) && geom_coord_moderate(r.x) && geom_coord_moderate(r.y)))
    return geom_twice_area_gmp(p, q, r);
  double d[4][2];   /* qx - px, ry - py, qy - py, rx - px, each as hi + lo */
  geom_two_diff(q.x, p.x, &d[0][0], &d[0][1]);
  geom_two_diff(r.y, p.y, &d[1][0], &d[1][1]);
  geom_two_diff(q.y, p.y, &d[2][0], &d[2][1]);
  geom_two_diff(r.x, p.x, &d[3][0], &d[3][1]);
  double e[34] = {0};   /* 16 products of 2 terms: at most 32 components, +1 in a compare */
  int n = 1;
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++) {
      geom_add_product(e, &n, d[0][i], d[1][j]);
      geom_add_product(e, &n, -d[2][i], d[3][j]);
    }
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

GEOM_COLD int geom_incircle_exact(geom_point a, geom_point b, geom_point c, geom_point d) {
  atomic_fetch_add_explicit(&geom_exact_count, 1, memory_order_relaxed);
  if (!geom_finite4(a, b, c, d)) return 0;
  return geom_lifted_sign_q(a, b, c, d, NULL);
}

GEOM_COLD int geom_power_exact(geom_point a, geom_point b, geom_point c, geom_point d,
                               const double w[4]) {
  atomic_fetch_add_explicit(&geom_exact_count, 1, memory_order_relaxed);
  if (!geom_finite4(a, b, c, d) || !isfinite(w[0]) || !isfinite(w[1]) || !isfinite(w[2]) ||
      !isfinite(w[3]))
    return 0;
  return geom_lifted_sign_q(a, b, c, d, w);
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
