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

/* The exact half of geom_orient (geom.h holds the filter). */
GEOM_COLD int geom_orient_exact(geom_point a, geom_point b, geom_point c) {
  atomic_fetch_add_explicit(&geom_exact_count, 1, memory_order_relaxed);
  if (!geom_finite4(a, b, c, a)) return 0;
  mpq_t t[6];
  for (int i = 0; i < 6; i++) mpq_init(t[i]);
  mpq_set_d(t[0], b.x); mpq_set_d(t[4], a.x); mpq_sub(t[0], t[0], t[4]);  /* bx - ax */
  mpq_set_d(t[1], c.y); mpq_set_d(t[4], a.y); mpq_sub(t[1], t[1], t[4]);  /* cy - ay */
  mpq_set_d(t[2], b.y); mpq_sub(t[2], t[2], t[4]);                        /* by - ay */
  mpq_set_d(t[3], c.x); mpq_set_d(t[4], a.x); mpq_sub(t[3], t[3], t[4]);  /* cx - ax */
  mpq_mul(t[4], t[0], t[1]);
  mpq_mul(t[5], t[2], t[3]);
  mpq_sub(t[4], t[4], t[5]);
  int s = mpq_sgn(t[4]);
  for (int i = 0; i < 6; i++) mpq_clear(t[i]);
  return s;
}

/* |orientation determinant| of p, q, r, computed exactly, rounded toward
** zero to a double (geom_twice_area's slow path). */
GEOM_COLD double geom_twice_area_exact(geom_point p, geom_point q, geom_point r) {
  atomic_fetch_add_explicit(&geom_exact_count, 1, memory_order_relaxed);
  mpq_t t[5];
  for (int i = 0; i < 5; i++) mpq_init(t[i]);
  mpq_set_d(t[0], q.x); mpq_set_d(t[4], p.x); mpq_sub(t[0], t[0], t[4]);  /* qx - px */
  mpq_set_d(t[1], r.y); mpq_set_d(t[4], p.y); mpq_sub(t[1], t[1], t[4]);  /* ry - py */
  mpq_set_d(t[2], q.y); mpq_sub(t[2], t[2], t[4]);                        /* qy - py */
  mpq_set_d(t[3], r.x); mpq_set_d(t[4], p.x); mpq_sub(t[3], t[3], t[4]);  /* rx - px */
  mpq_mul(t[0], t[0], t[1]);
  mpq_mul(t[2], t[2], t[3]);
  mpq_sub(t[0], t[0], t[2]);
  mpq_abs(t[0], t[0]);
  double v = mpq_get_d(t[0]);
  for (int i = 0; i < 5; i++) mpq_clear(t[i]);
  return v;
}

/* The incircle determinant of a, b, c, d translated so that d is the origin:
**   | adx ady adx^2+ady^2 |
**   | bdx bdy bdx^2+bdy^2 |
**   | cdx cdy cdx^2+cdy^2 |   (positive when d is inside circle abc, abc anticlockwise) */
GEOM_COLD int geom_incircle_exact(geom_point a, geom_point b, geom_point c, geom_point d) {
  atomic_fetch_add_explicit(&geom_exact_count, 1, memory_order_relaxed);
  if (!geom_finite4(a, b, c, d)) return 0;
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

/* The filter of geom_incircle is inline in predicates.h; the function above
** is its exact half. */
