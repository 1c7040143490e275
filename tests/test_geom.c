/*
** test_geom.c: geom_tri quantities on hand-computed triangles, their
** bit-for-bit independence of the vertex order, the exact predicates
** (checked against exact rational arithmetic with GMP, including inputs
** where naive floating point gets the sign wrong) and polygon validation.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <gmp.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "geom.h"
#include "ops.h"
#include "testutil.h"

static geom_point tgeom_pt(double x, double y) {
  geom_point p = {x, y};
  return p;
}

/* ---- exact reference predicates (GMP rationals hold every double exactly) ---- */

/* det = (bx-ax)(cy-ay) - (by-ay)(cx-ax), exactly, into det (initialised). */
static void tgeom_orient_det(mpq_t det, geom_point a, geom_point b, geom_point c) {
  mpq_t bx, by, cx, cy, t, u;
  mpq_inits(bx, by, cx, cy, t, u, NULL);
  mpq_set_d(t, a.x);
  mpq_set_d(bx, b.x); mpq_sub(bx, bx, t);
  mpq_set_d(cx, c.x); mpq_sub(cx, cx, t);
  mpq_set_d(t, a.y);
  mpq_set_d(by, b.y); mpq_sub(by, by, t);
  mpq_set_d(cy, c.y); mpq_sub(cy, cy, t);
  mpq_mul(t, bx, cy);
  mpq_mul(u, by, cx);
  mpq_sub(det, t, u);
  mpq_clears(bx, by, cx, cy, t, u, NULL);
}

static int tgeom_orient_exact(geom_point a, geom_point b, geom_point c) {
  mpq_t det;
  mpq_init(det);
  tgeom_orient_det(det, a, b, c);
  int s = mpq_sgn(det);
  mpq_clear(det);
  return s;
}

/* det | adx ady adx^2+ady^2 ; bdx ... ; cdx ... |, > 0 when d is inside the
** circle of anticlockwise a, b, c (Shewchuk's convention, as geom.h). */
static int tgeom_incircle_exact(geom_point a, geom_point b, geom_point c, geom_point d) {
  mpq_t x[3], y[3], l[3], t, u, det, dx, dy;
  geom_point p[3] = {a, b, c};
  mpq_inits(t, u, det, dx, dy, NULL);
  mpq_set_d(dx, d.x);
  mpq_set_d(dy, d.y);
  for (int i = 0; i < 3; i++) {
    mpq_inits(x[i], y[i], l[i], NULL);
    mpq_set_d(x[i], p[i].x); mpq_sub(x[i], x[i], dx);
    mpq_set_d(y[i], p[i].y); mpq_sub(y[i], y[i], dy);
    mpq_mul(t, x[i], x[i]);
    mpq_mul(u, y[i], y[i]);
    mpq_add(l[i], t, u);
  }
  mpq_set_ui(det, 0, 1);
  for (int i = 0; i < 3; i++) {
    int j = (i + 1) % 3, k = (i + 2) % 3;
    /* l_i * (x_j y_k - x_k y_j): the cofactor expansion along the lift column */
    mpq_mul(t, x[j], y[k]);
    mpq_mul(u, x[k], y[j]);
    mpq_sub(t, t, u);
    mpq_mul(t, t, l[i]);
    mpq_add(det, det, t);
  }
  int s = mpq_sgn(det);
  for (int i = 0; i < 3; i++) mpq_clears(x[i], y[i], l[i], NULL);
  mpq_clears(t, u, det, dx, dy, NULL);
  return s;
}

static int tgeom_orient_naive(geom_point a, geom_point b, geom_point c) {
  double d = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  return (d > 0) - (d < 0);
}

/* ---- triangle quantities ---- */

static void tgeom_check_invariants(const geom_tri *t) {
  assert_true(t->a >= t->b && t->b >= t->c && t->c > 0);
  assert_true(t->alpha <= t->beta && t->beta <= t->gamma && t->alpha > 0);
  TESTUTIL_NEAR(t->alpha + t->beta + t->gamma, M_PI, 0, 1e-13);
  TESTUTIL_NEAR(t->P, t->a + t->b + t->c, 1e-15, 0);
  TESTUTIL_NEAR(t->R, t->a * t->b * t->c / (4 * t->area), 1e-13, 0);
  TESTUTIL_NEAR(t->r, 2 * t->area / t->P, 1e-13, 0);
  TESTUTIL_NEAR(t->h, 2 * t->area / t->a, 1e-13, 0);
  /* canonical order: lexicographic by x then y */
  for (int i = 0; i < 2; i++)
    assert_true(t->v[i].x < t->v[i + 1].x ||
                (t->v[i].x == t->v[i + 1].x && t->v[i].y < t->v[i + 1].y));
}

/* Equilateral triangle of side 2: (0,0), (2,0), (1, sqrt3).
** a = b = c = 2, angles pi/3, A = sqrt3 (base 2, height sqrt3), P = 6,
** R = abc/(4A) = 8/(4 sqrt3) = 2/sqrt3, r = 2A/P = 1/sqrt3, h = 2A/a = sqrt3,
** rx = 2, ry = sqrt3. (sqrt3 is rounded, so "2" is only 2 to an ulp.) */
static void test_tri_equilateral(void **state) {
  (void)state;
  double s3 = sqrt(3.0);
  geom_tri t;
  geom_tri_make(&t, tgeom_pt(1, s3), tgeom_pt(2, 0), tgeom_pt(0, 0));
  tgeom_check_invariants(&t);
  TESTUTIL_NEAR(t.a, 2, 1e-15, 0);
  TESTUTIL_NEAR(t.b, 2, 1e-15, 0);
  TESTUTIL_NEAR(t.c, 2, 1e-15, 0);
  TESTUTIL_NEAR(t.alpha, M_PI / 3, 1e-14, 0);
  TESTUTIL_NEAR(t.beta, M_PI / 3, 1e-14, 0);
  TESTUTIL_NEAR(t.gamma, M_PI / 3, 1e-14, 0);
  TESTUTIL_NEAR(t.area, s3, 1e-15, 0);
  TESTUTIL_NEAR(t.P, 6, 1e-15, 0);
  TESTUTIL_NEAR(t.R, 2 / s3, 1e-14, 0);
  TESTUTIL_NEAR(t.r, 1 / s3, 1e-14, 0);
  TESTUTIL_NEAR(t.h, s3, 1e-14, 0);
  TESTUTIL_NEAR(t.rx, 2, 0, 0);
  TESTUTIL_NEAR(t.ry, s3, 0, 0);
  assert_true(t.v[0].x == 0 && t.v[1].x == 1 && t.v[2].x == 2);
}

/* 3-4-5 right triangle (0,0), (4,0), (0,3): a = 5, b = 4, c = 3;
** alpha = atan2(3,4) (opposite 3), beta = atan2(4,3), gamma = pi/2;
** A = 6, P = 12, R = 60/24 = 2.5, r = 12/12 = 1, h = 12/5 = 2.4, rx 4, ry 3. */
static void test_tri_345(void **state) {
  (void)state;
  geom_tri t;
  geom_tri_make(&t, tgeom_pt(4, 0), tgeom_pt(0, 3), tgeom_pt(0, 0));
  tgeom_check_invariants(&t);
  TESTUTIL_NEAR(t.a, 5, 1e-15, 0);
  TESTUTIL_NEAR(t.b, 4, 1e-15, 0);
  TESTUTIL_NEAR(t.c, 3, 1e-15, 0);
  TESTUTIL_NEAR(t.alpha, atan2(3, 4), 1e-14, 0);
  TESTUTIL_NEAR(t.beta, atan2(4, 3), 1e-14, 0);
  TESTUTIL_NEAR(t.gamma, M_PI / 2, 1e-14, 0);
  TESTUTIL_NEAR(t.area, 6, 1e-15, 0);
  TESTUTIL_NEAR(t.P, 12, 1e-15, 0);
  TESTUTIL_NEAR(t.R, 2.5, 1e-15, 0);
  TESTUTIL_NEAR(t.r, 1, 1e-15, 0);
  TESTUTIL_NEAR(t.h, 2.4, 1e-15, 0);
  TESTUTIL_NEAR(t.rx, 4, 0, 0);
  TESTUTIL_NEAR(t.ry, 3, 0, 0);
}

/* Sliver (0,0), (1,0), (0.5, 1e-3): with s = sqrt(0.25 + 1e-6),
** a = 1, b = c = s; base angles theta = atan(1e-3 / 0.5) = atan(2e-3),
** gamma = pi - 2 theta; A = 5e-4; R = 1*s*s/(4*5e-4) = 0.250001/0.002 =
** 125.0005; r = 1e-3/(1 + 2s); h = 1e-3.  The small angle must be accurate
** to ~1e-12 relative (an acos of the law of cosines loses ~1e-10 here). */
static void test_tri_sliver(void **state) {
  (void)state;
  geom_tri t;
  double s = sqrt(0.25 + 1e-6), th = atan(2e-3);
  geom_tri_make(&t, tgeom_pt(0.5, 1e-3), tgeom_pt(1, 0), tgeom_pt(0, 0));
  tgeom_check_invariants(&t);
  TESTUTIL_NEAR(t.a, 1, 1e-15, 0);
  TESTUTIL_NEAR(t.b, s, 1e-15, 0);
  TESTUTIL_NEAR(t.c, s, 1e-15, 0);
  TESTUTIL_NEAR(t.alpha, th, 1e-12, 0);
  TESTUTIL_NEAR(t.beta, th, 1e-12, 0);
  TESTUTIL_NEAR(t.gamma, M_PI - 2 * th, 1e-14, 0);
  TESTUTIL_NEAR(t.area, 5e-4, 1e-13, 0);
  TESTUTIL_NEAR(t.R, 125.0005, 1e-12, 0);
  TESTUTIL_NEAR(t.r, 1e-3 / (1 + 2 * s), 1e-12, 0);
  TESTUTIL_NEAR(t.h, 1e-3, 1e-12, 0);
  TESTUTIL_NEAR(t.rx, 1, 0, 0);
  TESTUTIL_NEAR(t.ry, 1e-3, 0, 0);
}

/* A needle (0,0), (1,0), (0.5, 1e-9): angles 2e-9 (to 1e-18 relative),
** area 5e-10.  Checks the small angle is not computed by an acos that
** rounds cos(2e-9) = 1 - 2e-18 to 1 (which would give alpha = 0). */
static void test_tri_needle(void **state) {
  (void)state;
  geom_tri t;
  geom_tri_make(&t, tgeom_pt(0, 0), tgeom_pt(1, 0), tgeom_pt(0.5, 1e-9));
  TESTUTIL_NEAR(t.alpha, atan(2e-9), 1e-9, 0);
  TESTUTIL_NEAR(t.beta, atan(2e-9), 1e-9, 0);
  TESTUTIL_NEAR(t.area, 5e-10, 1e-9, 0);
  TESTUTIL_NEAR(t.h, 1e-9, 1e-9, 0);
  TESTUTIL_NEAR(t.alpha + t.beta + t.gamma, M_PI, 0, 1e-13);
}

static geom_point tgeom_rand_point(testutil_rng *g, double scale) {
  return tgeom_pt(scale * (2 * testutil_uniform(g) - 1), scale * (2 * testutil_uniform(g) - 1));
}

/* Random triangles: the sorted quantities against an independent
** computation from the coordinates (cross product area, hypot sides, the
** angles from the law of sines/cosines via atan2), and the six vertex
** orders giving bit-identical structs. */
static void test_tri_random(void **state) {
  (void)state;
  testutil_rng g = {12345};
  int done = 0;
  while (done < 20000) {
    double scale = pow(2.0, (double)(int)(testutil_uniform(&g) * 40) - 20);
    geom_point p[3] = {tgeom_rand_point(&g, scale), tgeom_rand_point(&g, scale),
                       tgeom_rand_point(&g, scale)};
    if (tgeom_orient_exact(p[0], p[1], p[2]) == 0) continue;
    double cross = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x);
    double l[3];
    for (int i = 0; i < 3; i++) l[i] = hypot(p[(i + 1) % 3].x - p[(i + 2) % 3].x, p[(i + 1) % 3].y - p[(i + 2) % 3].y);
    /* skip the flattest ones: their angles are ill-conditioned in any method */
    if (fabs(cross) < 1e-6 * l[0] * l[1]) continue;
    done++;
    geom_tri t[6];
    for (int k = 0; k < 6; k++) {
      memset(&t[k], 0xA5, sizeof t[k]);
      const int *o3 = testutil_perm3[k];
      geom_tri_make(&t[k], p[o3[0]], p[o3[1]], p[o3[2]]);
    }
    for (int k = 1; k < 6; k++)
      if (memcmp(&t[0], &t[k], sizeof t[0]) != 0) {
        print_error("vertex order %d%d%d gives a different geom_tri for "
                    "(%.17g,%.17g) (%.17g,%.17g) (%.17g,%.17g)\n",
                    testutil_perm3[k][0], testutil_perm3[k][1], testutil_perm3[k][2], p[0].x,
                    p[0].y, p[1].x, p[1].y, p[2].x, p[2].y);
        fail();
      }
    tgeom_check_invariants(&t[0]);
    /* sort the independent sides descending, keep opposite-vertex pairing */
    double s[3] = {l[0], l[1], l[2]};
    for (int i = 0; i < 3; i++)
      for (int j = i + 1; j < 3; j++)
        if (s[j] > s[i]) { double x = s[i]; s[i] = s[j]; s[j] = x; }
    TESTUTIL_NEAR(t[0].a, s[0], 1e-14, 0);
    TESTUTIL_NEAR(t[0].b, s[1], 1e-14, 0);
    TESTUTIL_NEAR(t[0].c, s[2], 1e-14, 0);
    double A = fabs(cross) / 2;
    TESTUTIL_NEAR(t[0].area, A, 1e-9, 0);
    /* angle opposite side x: atan2(2A, y^2 + z^2 - x^2) (well conditioned) */
    double ang[3];
    for (int i = 0; i < 3; i++) {
      double x = s[i], y = s[(i + 1) % 3], z = s[(i + 2) % 3];
      ang[i] = atan2(4 * A, y * y + z * z - x * x);
    }
    TESTUTIL_NEAR(t[0].gamma, ang[0], 1e-9, 1e-12);
    TESTUTIL_NEAR(t[0].beta, ang[1], 1e-9, 1e-12);
    TESTUTIL_NEAR(t[0].alpha, ang[2], 1e-9, 1e-12);
    double xmin = fmin(p[0].x, fmin(p[1].x, p[2].x)), xmax = fmax(p[0].x, fmax(p[1].x, p[2].x));
    double ymin = fmin(p[0].y, fmin(p[1].y, p[2].y)), ymax = fmax(p[0].y, fmax(p[1].y, p[2].y));
    assert_true(t[0].rx == xmax - xmin);
    assert_true(t[0].ry == ymax - ymin);
  }
}

/* ---- exact predicates ---- */

static void test_orient_easy(void **state) {
  (void)state;
  assert_int_equal(geom_orient(tgeom_pt(0, 0), tgeom_pt(1, 0), tgeom_pt(0, 1)), 1);
  assert_int_equal(geom_orient(tgeom_pt(0, 0), tgeom_pt(0, 1), tgeom_pt(1, 0)), -1);
  /* exactly collinear, representable coordinates */
  assert_int_equal(geom_orient(tgeom_pt(0, 0), tgeom_pt(1, 1), tgeom_pt(2, 2)), 0);
  assert_int_equal(geom_orient(tgeom_pt(0.5, 0.25), tgeom_pt(1.5, 0.75), tgeom_pt(-3.5, -1.75)), 0);
  assert_int_equal(geom_orient(tgeom_pt(1e-300, 0), tgeom_pt(2e-300, 0), tgeom_pt(3e-300, 0)), 0);
  assert_int_equal(geom_orient(tgeom_pt(0, 0), tgeom_pt(0, 0), tgeom_pt(1, 1)), 0);
  /* y = 3x + 1 with dyadic x: all exact */
  assert_int_equal(geom_orient(tgeom_pt(0.125, 1.375), tgeom_pt(1024, 3073), tgeom_pt(-7.5, -21.5)), 0);
  /* one ulp off the line */
  assert_int_equal(geom_orient(tgeom_pt(0, 0), tgeom_pt(1, 1), tgeom_pt(2, nextafter(2, 3))), 1);
  assert_int_equal(geom_orient(tgeom_pt(0, 0), tgeom_pt(1, 1), tgeom_pt(2, nextafter(2, 1))), -1);
}

static void test_incircle_easy(void **state) {
  (void)state;
  geom_point a = tgeom_pt(0, 0), b = tgeom_pt(1, 0), c = tgeom_pt(0, 1);
  assert_int_equal(geom_incircle(a, b, c, tgeom_pt(0.5, 0.5)), 1);
  assert_int_equal(geom_incircle(a, b, c, tgeom_pt(2, 2)), -1);
  /* cocircular: the unit square and the four points (+-1,0), (0,+-1) */
  assert_int_equal(geom_incircle(a, b, tgeom_pt(1, 1), c), 0);
  assert_int_equal(geom_incircle(tgeom_pt(1, 0), tgeom_pt(0, 1), tgeom_pt(-1, 0), tgeom_pt(0, -1)), 0);
  /* integer points on the circle of radius 5: (5,0) (3,4) (0,5) then
  ** (-3,-4), (-4,3), (4,-3), (-5,0), (0,-5) */
  geom_point p = tgeom_pt(5, 0), q = tgeom_pt(3, 4), r = tgeom_pt(0, 5);
  const double on[][2] = {{-3, -4}, {-4, 3}, {4, -3}, {-5, 0}, {0, -5}, {-4, -3}, {3, -4}};
  for (size_t i = 0; i < sizeof on / sizeof on[0]; i++) {
    assert_int_equal(geom_incircle(p, q, r, tgeom_pt(on[i][0], on[i][1])), 0);
    /* scaled by powers of two and translated by integers: still exact */
    geom_point d = tgeom_pt(on[i][0] * 0x1p-30 + 7, on[i][1] * 0x1p-30 - 3);
    assert_int_equal(geom_incircle(tgeom_pt(5 * 0x1p-30 + 7, -3), tgeom_pt(3 * 0x1p-30 + 7, 4 * 0x1p-30 - 3),
                                   tgeom_pt(7, 5 * 0x1p-30 - 3), d), 0);
  }
  /* one ulp inside / outside */
  assert_int_equal(geom_incircle(p, q, r, tgeom_pt(nextafter(-5, 0), 0)), 1);
  assert_int_equal(geom_incircle(p, q, r, tgeom_pt(nextafter(-5, -6), 0)), -1);
}

/* Shewchuk's classic picture: a = (0.5 + i u, 0.5 + j u), u = 2^-53,
** b = (12, 12), c = (24, 24); the naive determinant gets many signs wrong. */
static void test_orient_near_degenerate(void **state) {
  (void)state;
  unsigned long exact0 = geom_exact_calls();
  int naive_wrong = 0, wrong = 0, zero = 0;
  geom_point b = tgeom_pt(12, 12), c = tgeom_pt(24, 24);
  for (int i = 0; i < 256; i++)
    for (int j = 0; j < 256; j++) {
      geom_point a = tgeom_pt(0.5 + i * 0x1p-53, 0.5 + j * 0x1p-53);
      int e = tgeom_orient_exact(a, b, c);
      zero += e == 0;
      naive_wrong += tgeom_orient_naive(a, b, c) != e;
      int got = geom_orient(a, b, c);
      if (got != e) {
        if (wrong < 5)
          print_error("orient((%.17g,%.17g),(12,12),(24,24)) = %d, exact %d\n", a.x, a.y, got, e);
        wrong++;
      }
      /* the predicate is antisymmetric */
      assert_int_equal(geom_orient(b, a, c), -got);
      assert_int_equal(geom_orient(b, c, a), got);
    }
  print_message("orient near-degenerate: %d of 65536 naive signs wrong, %d exact zeros\n",
                naive_wrong, zero);
  assert_true(naive_wrong > 0);  /* the test really is hard */
  assert_int_equal(wrong, 0);
  assert_true(geom_exact_calls() > exact0);
}

/* Near-cocircular: a, b, c on the circle of radius 5 about (1000, 1000),
** d = (996, 1003) (also on it) moved by i, j ulps (ulp(996) = 2^-43). */
static void test_incircle_near_degenerate(void **state) {
  (void)state;
  geom_point a = tgeom_pt(1005, 1000), b = tgeom_pt(1003, 1004), c = tgeom_pt(1000, 1005);
  int naive_wrong = 0, wrong = 0, zero = 0;
  for (int i = -40; i < 40; i++)
    for (int j = -40; j < 40; j++) {
      geom_point d = tgeom_pt(996 + i * 0x1p-43, 1003 + j * 0x1p-43);
      int e = tgeom_incircle_exact(a, b, c, d);
      zero += e == 0;
      double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y;
      double cdx = c.x - d.x, cdy = c.y - d.y;
      double nd = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                  (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                  (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
      naive_wrong += ((nd > 0) - (nd < 0)) != e;
      int got = geom_incircle(a, b, c, d);
      if (got != e) {
        if (wrong < 5) print_error("incircle(..., (%.17g,%.17g)) = %d, exact %d\n", d.x, d.y, got, e);
        wrong++;
      }
      /* rotating a, b, c keeps the answer */
      assert_int_equal(geom_incircle(b, c, a, d), got);
    }
  print_message("incircle near-degenerate: %d of 6400 naive signs wrong, %d exact zeros\n",
                naive_wrong, zero);
  assert_true(naive_wrong > 0);
  assert_true(zero >= 1);
  assert_int_equal(wrong, 0);
}

/* Random points on small grids (many exact degeneracies) and on wide
** ranges of scale, against GMP. */
static void test_predicates_random(void **state) {
  (void)state;
  testutil_rng g = {777};
  int zeros_o = 0, zeros_i = 0;
  for (int n = 0; n < 40000; n++) {
    geom_point p[4];
    int kind = n % 3;
    double scale = pow(2.0, (double)(int)(testutil_uniform(&g) * 200) - 100);
    for (int k = 0; k < 4; k++) {
      if (kind == 0) /* 6x6 grid, scaled by a power of two and shifted */
        p[k] = tgeom_pt((double)(testutil_next(&g) % 6) * scale + 1.5 * scale,
                        (double)(testutil_next(&g) % 6) * scale - 2.25 * scale);
      else if (kind == 1)
        p[k] = tgeom_rand_point(&g, scale);
      else /* points near one spot: differences much smaller than coordinates */
        p[k] = tgeom_pt(1 + 1e-12 * (double)(testutil_next(&g) % 9),
                        3 + 1e-12 * (double)(testutil_next(&g) % 9));
    }
    int eo = tgeom_orient_exact(p[0], p[1], p[2]);
    zeros_o += eo == 0;
    if (geom_orient(p[0], p[1], p[2]) != eo) {
      print_error("orient (%a,%a) (%a,%a) (%a,%a): got %d, exact %d\n", p[0].x, p[0].y,
                  p[1].x, p[1].y, p[2].x, p[2].y, geom_orient(p[0], p[1], p[2]), eo);
      fail();
    }
    if (eo == 0) continue;
    if (eo < 0) { geom_point t = p[1]; p[1] = p[2]; p[2] = t; }
    int ei = tgeom_incircle_exact(p[0], p[1], p[2], p[3]);
    zeros_i += ei == 0;
    if (geom_incircle(p[0], p[1], p[2], p[3]) != ei) {
      print_error("incircle (%a,%a) (%a,%a) (%a,%a) (%a,%a): got %d, exact %d\n", p[0].x, p[0].y,
                  p[1].x, p[1].y, p[2].x, p[2].y, p[3].x, p[3].y,
                  geom_incircle(p[0], p[1], p[2], p[3]), ei);
      fail();
    }
  }
  print_message("random predicates: %d exact collinear, %d exact cocircular cases\n", zeros_o, zeros_i);
  assert_true(zeros_o > 100 && zeros_i > 100);
}

/* geom_orient_valid and geom_incircle_valid (no tiny-difference test) on
** points at the edges of the coordinate contract: 0, magnitudes near 1e-30
** a few ulps apart (the smallest differences the contract allows), near
** 1e30, and both at once; against the GMP oracle.  Every point is checked
** against the contract first, so the test exercises exactly the promise
** the two predicates rely on. */
static double tgeom_contract_coord(testutil_rng *g) {
  static const double base[] = {0, 1e-30, -1e-30, 3e-30, 1e30, -1e30, 7e29, 1.0};
  double b = base[testutil_next(g) % (sizeof base / sizeof base[0])];
  int ulps = (int)(testutil_next(g) % 5);
  /* Inwards: small magnitudes grow, large ones shrink. */
  double to = fabs(b) > 1 ? 0 : b < 0 ? -INFINITY : INFINITY;
  for (int k = 0; k < ulps && b != 0; k++) b = nextafter(b, to);
  return b;
}

static void test_predicates_contract(void **state) {
  (void)state;
  testutil_rng g = {2026};
  int zeros_o = 0, zeros_i = 0;
  for (int n = 0; n < 60000; n++) {
    geom_point p[4];
    for (int k = 0; k < 4; k++) {
      p[k] = tgeom_pt(tgeom_contract_coord(&g), tgeom_contract_coord(&g));
      assert_int_equal(geom_coord_check(p[k].x), GEOM_COORD_OK);
      assert_int_equal(geom_coord_check(p[k].y), GEOM_COORD_OK);
    }
    int eo = tgeom_orient_exact(p[0], p[1], p[2]);
    zeros_o += eo == 0;
    if (geom_orient_valid(p[0], p[1], p[2]) != eo) {
      print_error("orient_valid (%a,%a) (%a,%a) (%a,%a): exact %d\n", p[0].x, p[0].y, p[1].x,
                  p[1].y, p[2].x, p[2].y, eo);
      fail();
    }
    if (eo == 0) continue;
    if (eo < 0) { geom_point t = p[1]; p[1] = p[2]; p[2] = t; }
    int ei = tgeom_incircle_exact(p[0], p[1], p[2], p[3]);
    zeros_i += ei == 0;
    if (geom_incircle_valid(p[0], p[1], p[2], p[3]) != ei) {
      print_error("incircle_valid (%a,%a) (%a,%a) (%a,%a) (%a,%a): exact %d\n", p[0].x, p[0].y,
                  p[1].x, p[1].y, p[2].x, p[2].y, p[3].x, p[3].y, ei);
      fail();
    }
  }
  print_message("contract predicates: %d exact collinear, %d exact cocircular cases\n", zeros_o,
                zeros_i);
  assert_true(zeros_o > 100 && zeros_i > 100);
}

/* Extreme magnitudes: products that underflow into subnormals (where a
** relative error bound no longer covers the absolute rounding error) or
** overflow to infinity.  Coordinates stay normal doubles. */
static void test_predicates_extreme(void **state) {
  (void)state;
  testutil_rng g = {4242};
  static const int exps[] = {-540, -537, -530, -520, -500, -300, -270, 250, 260, 500, 511, 1000};
  int wrong_o = 0, wrong_i = 0, n_o = 0, n_i = 0;
  for (size_t e = 0; e < sizeof exps / sizeof exps[0]; e++)
    for (int n = 0; n < 3000; n++) {
      double scale = ldexp(1.0, exps[e]);
      geom_point p[4];
      for (int k = 0; k < 4; k++)   /* small integers times the scale: nearly degenerate often */
        p[k] = tgeom_pt((double)(int)(testutil_next(&g) % 7) * scale * (1 + 0x1p-30 * (double)(testutil_next(&g) % 3)),
                        (double)(int)(testutil_next(&g) % 7) * scale);
      int eo = tgeom_orient_exact(p[0], p[1], p[2]);
      n_o++;
      if (geom_orient(p[0], p[1], p[2]) != eo) {
        if (wrong_o++ < 3)
          print_error("orient (%a,%a) (%a,%a) (%a,%a): got %d, exact %d\n", p[0].x, p[0].y, p[1].x,
                      p[1].y, p[2].x, p[2].y, geom_orient(p[0], p[1], p[2]), eo);
      }
      if (eo == 0) continue;
      if (eo < 0) { geom_point t = p[1]; p[1] = p[2]; p[2] = t; }
      int ei = tgeom_incircle_exact(p[0], p[1], p[2], p[3]);
      n_i++;
      if (geom_incircle(p[0], p[1], p[2], p[3]) != ei) {
        if (wrong_i++ < 3)
          print_error("incircle (%a,%a) (%a,%a) (%a,%a) (%a,%a): got %d, exact %d\n", p[0].x, p[0].y,
                      p[1].x, p[1].y, p[2].x, p[2].y, p[3].x, p[3].y,
                      geom_incircle(p[0], p[1], p[2], p[3]), ei);
      }
    }
  print_message("extreme scales: orient wrong %d of %d, incircle wrong %d of %d\n", wrong_o, n_o,
                wrong_i, n_i);
  assert_int_equal(wrong_o, 0);
  assert_int_equal(wrong_i, 0);
  /* explicit cases: a right angle at 2^-600 (products 2^-1200 underflow to
  ** 0) and at 2^600 (products overflow) */
  assert_int_equal(geom_orient(tgeom_pt(0, 0), tgeom_pt(0x1p-600, 0), tgeom_pt(0, 0x1p-600)), 1);
  assert_int_equal(geom_orient(tgeom_pt(0, 0), tgeom_pt(0x1p600, 0), tgeom_pt(0, 0x1p600)), 1);
  assert_int_equal(geom_incircle(tgeom_pt(0, 0), tgeom_pt(0x1p-300, 0), tgeom_pt(0, 0x1p-300),
                                 tgeom_pt(0x1p-302, 0x1p-302)), 1);
  assert_int_equal(geom_incircle(tgeom_pt(0, 0), tgeom_pt(0x1p300, 0), tgeom_pt(0, 0x1p300),
                                 tgeom_pt(0x1p298, 0x1p298)), 1);
}

/* |orientation determinant| in GMP rationals, rounded toward zero
** (mpq_get_d truncates): the reference for geom_twice_area_exact. */
static double tgeom_twice_area_gmp(geom_point p, geom_point q, geom_point r) {
  mpq_t det;
  mpq_init(det);
  tgeom_orient_det(det, p, q, r);
  mpq_abs(det, det);
  double v = mpq_get_d(det);
  mpq_clear(det);
  return v;
}

/* A coordinate of the contract: 0 sometimes, else a random sign and
** binary exponent in [e0, e0 + span) (kept inside [1e-30, 1e30]). */
static double tgeom_scaled_coord(testutil_rng *g, int e0, int span) {
  if (testutil_next(g) % 16 == 0) return 0;
  double x = ldexp(1 + testutil_uniform(g), e0 + (int)(testutil_next(g) % (uint64_t)span));
  if (x > 1e30) x = 1e30;
  if (x < 1e-30) x = 1e-30;
  return testutil_next(g) % 2 ? -x : x;
}

/* Nudge x by k ulps (k may be negative), staying inside the contract. */
static double tgeom_nudge(double x, int k) {
  for (int i = 0; i < (k < 0 ? -k : k); i++) x = nextafter(x, k < 0 ? -INFINITY : INFINITY);
  double m = fabs(x);
  return m != 0 && m < 1e-30 ? 0 : m > 1e30 ? copysign(1e30, x) : x;
}

/* geom_twice_area_exact (floating-point expansions) equals the GMP value
** bit for bit on the triangles where it matters: nearly and exactly
** collinear ones at every scale of the contract, needles, points a few
** ulps apart, mixed magnitudes, zero coordinates; and on random ones. */
static void test_twice_area_exact(void **state) {
  (void)state;
  testutil_rng g = {8080};
  int wrong = 0, n = 0, zeros = 0;
  for (int it = 0; it < 300000; it++) {
    int kind = it % 7, e0 = -99 + (int)(testutil_next(&g) % 190);
    int span = kind == 5 ? 200 : 1 + (int)(testutil_next(&g) % 8);
    geom_point p = tgeom_pt(tgeom_scaled_coord(&g, e0, span), tgeom_scaled_coord(&g, e0, span));
    geom_point q = tgeom_pt(tgeom_scaled_coord(&g, e0, span), tgeom_scaled_coord(&g, e0, span));
    geom_point r;
    double s = testutil_uniform(&g) * (kind == 1 ? 1e-12 : kind == 2 ? 3 : 1);
    switch (kind) {
      case 0: case 1: case 2:   /* on the line pq (rounded), then a few ulps off */
        r = tgeom_pt(p.x + s * (q.x - p.x), p.y + s * (q.y - p.y));
        if (fabs(r.x) > 1e30 || fabs(r.y) > 1e30) continue;
        r = tgeom_pt(tgeom_nudge(r.x, (int)(testutil_next(&g) % 7) - 3),
                     tgeom_nudge(r.y, (int)(testutil_next(&g) % 7) - 3));
        break;
      case 3:   /* a needle: r a few ulps from p */
        r = tgeom_pt(tgeom_nudge(p.x, (int)(testutil_next(&g) % 9) - 4),
                     tgeom_nudge(p.y, (int)(testutil_next(&g) % 9) - 4));
        break;
      case 4:   /* a lattice line: exactly collinear often */
        r = tgeom_pt(2 * q.x - p.x, 2 * q.y - p.y);
        if (fabs(r.x) > 1e30 || fabs(r.y) > 1e30) continue;
        if (testutil_next(&g) % 2) r.y = tgeom_nudge(r.y, 1);
        break;
      case 6:   /* the contract's edges: 0, 1e-30 and 1e30 a few ulps inwards */
        p = tgeom_pt(tgeom_contract_coord(&g), tgeom_contract_coord(&g));
        q = tgeom_pt(tgeom_contract_coord(&g), tgeom_contract_coord(&g));
        r = tgeom_pt(tgeom_contract_coord(&g), tgeom_contract_coord(&g));
        break;
      default:   /* anything, magnitudes 2^-99 .. 2^100 mixed */
        r = tgeom_pt(tgeom_scaled_coord(&g, -99, 200), tgeom_scaled_coord(&g, -99, 200));
        break;
    }
    double want = tgeom_twice_area_gmp(p, q, r), got = geom_twice_area_exact(p, q, r);
    n++;
    zeros += want == 0;
    if (memcmp(&got, &want, sizeof got) != 0 && wrong++ < 5)
      print_error("twice area (%a,%a) (%a,%a) (%a,%a): got %a, exact %a\n", p.x, p.y, q.x, q.y,
                  r.x, r.y, got, want);
  }
  print_message("twice area: %d of %d differ from GMP (%d exactly collinear)\n", wrong, n, zeros);
  assert_int_equal(wrong, 0);
  assert_true(zeros > 1000);
  /* beyond [2^-200, 2^200] (the GMP path) and at its edges */
  const geom_point far[][3] = {
    {{0, 0}, {0x1p-300, 0x1p-301}, {0x1p-299, 0x1p-300}},
    {{0x1p300, 1}, {-0x1p300, 3}, {0x1p299, 0x1p-250}},
    {{0x1p-200, 0x1p200}, {0x1p200, -0x1p-200}, {3 * 0x1p-200, 0x1p199}},
    {{0x1.fffffffffffffp199, 1}, {-0x1p200, 0x1p-200}, {0x1p-200, 0x1.fffffffffffffp199}},
  };
  for (size_t k = 0; k < sizeof far / sizeof far[0]; k++) {
    double want = tgeom_twice_area_gmp(far[k][0], far[k][1], far[k][2]);
    double got = geom_twice_area_exact(far[k][0], far[k][1], far[k][2]);
    assert_memory_equal(&got, &want, sizeof got);
  }
}

/* ---- small helpers and polygon validation ---- */

/* geom_segments_cross (and ops_segments_cross, counted) against exact
** integer arithmetic on every pair of segments between points of a 4 x 4
** grid, scaled by 2^40 and shifted so that the filter meets large values:
** ab and cd cross properly exactly when the lines are not parallel and the
** intersection parameters t (on ab) and u (on cd) are strictly inside (0, 1). */
static void test_segments_cross(void **state) {
  (void)state;
  long long gx[16], gy[16];
  for (int i = 0; i < 16; i++) gx[i] = i % 4, gy[i] = i / 4;
  int crossings = 0;
  for (int a = 0; a < 16; a++)
    for (int b = a + 1; b < 16; b++)
      for (int c = 0; c < 16; c++)
        for (int d = c + 1; d < 16; d++) {
          long long rx = gx[b] - gx[a], ry = gy[b] - gy[a], sx = gx[d] - gx[c],
                    sy = gy[d] - gy[c], qx = gx[c] - gx[a], qy = gy[c] - gy[a];
          long long den = rx * sy - ry * sx, tn = qx * sy - qy * sx, un = qx * ry - qy * rx;
          if (den < 0) den = -den, tn = -tn, un = -un;
          int want = den != 0 && 0 < tn && tn < den && 0 < un && un < den;
          geom_point P[4];
          int id[4] = {a, b, c, d};
          for (int k = 0; k < 4; k++)
            P[k] = (geom_point){0x1p40 * (double)gx[id[k]] + 3.0, 0x1p40 * (double)gy[id[k]] - 5.0};
          ops_counts n = {0};
          assert_int_equal(geom_segments_cross(P[0], P[1], P[2], P[3]), want);
          assert_int_equal(ops_segments_cross(&n, P[0], P[1], P[2], P[3]), want);
          assert_true(n.v[OPS_ORIENT] == 2 || n.v[OPS_ORIENT] == 4);
          crossings += want;
        }
  assert_true(crossings > 0);
}

static void test_dist_finite(void **state) {
  (void)state;
  assert_true(geom_dist(tgeom_pt(1, 1), tgeom_pt(4, 5)) == 5);
  assert_true(geom_point_finite(tgeom_pt(1, -2)));
  assert_false(geom_point_finite(tgeom_pt(NAN, 0)));
  assert_false(geom_point_finite(tgeom_pt(0, INFINITY)));
  assert_false(geom_point_finite(tgeom_pt(-INFINITY, 0)));
}

static void test_polygon_check(void **state) {
  (void)state;
  size_t bad = 99;
  int rev = -1;
  geom_point sq[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  assert_int_equal(geom_polygon_check(sq, 4, &bad, &rev), GEOM_OK);
  assert_int_equal(rev, 0);
  assert_true(sq[1].x == 1 && sq[1].y == 0);

  /* clockwise: reversed in place to anticlockwise */
  geom_point cw[5] = {{0, 0}, {0, 2}, {1, 3}, {2, 2}, {2, 0}};
  geom_point orig[5];
  memcpy(orig, cw, sizeof cw);
  rev = -1;
  assert_int_equal(geom_polygon_check(cw, 5, &bad, &rev), GEOM_OK);
  assert_int_equal(rev, 1);
  for (int i = 0; i < 5; i++) assert_int_equal(geom_orient(cw[i], cw[(i + 1) % 5], cw[(i + 2) % 5]), 1);
  /* the same cycle read backwards (from whichever start) */
  int start = -1;
  for (int k = 0; k < 5; k++)
    if (cw[0].x == orig[k].x && cw[0].y == orig[k].y) start = k;
  assert_true(start >= 0);
  for (int i = 0; i < 5; i++)
    assert_true(cw[i].x == orig[(start - i + 5) % 5].x && cw[i].y == orig[(start - i + 5) % 5].y);

  geom_point two[2] = {{0, 0}, {1, 0}};
  assert_int_equal(geom_polygon_check(two, 2, &bad, &rev), GEOM_TOO_FEW);

  geom_point nanp[4] = {{0, 0}, {1, 0}, {NAN, 1}, {0, 1}};
  assert_int_equal(geom_polygon_check(nanp, 4, &bad, &rev), GEOM_NOT_FINITE);
  assert_int_equal(bad, 2);
  geom_point infp[4] = {{0, 0}, {1, 0}, {1, 1}, {0, INFINITY}};
  assert_int_equal(geom_polygon_check(infp, 4, &bad, &rev), GEOM_NOT_FINITE);
  assert_int_equal(bad, 3);

  geom_point dup[4] = {{0, 0}, {1, 0}, {1, 1}, {1, 0}};
  assert_int_equal(geom_polygon_check(dup, 4, &bad, &rev), GEOM_DUPLICATE);
  assert_true(bad == 1 || bad == 3);

  geom_point col[4] = {{0, 0}, {1, 0}, {2, 0}, {1, 1}};
  assert_int_equal(geom_polygon_check(col, 4, &bad, &rev), GEOM_COLLINEAR);

  geom_point dart[4] = {{0, 0}, {2, 1}, {4, 0}, {2, 3}};
  assert_int_equal(geom_polygon_check(dart, 4, &bad, &rev), GEOM_NOT_CONVEX);

  /* a pentagram: every turn the same way, but the boundary winds twice */
  geom_point star[5] = {{0, 10}, {-5.9, -8.1}, {9.5, 3.1}, {-9.5, 3.1}, {5.9, -8.1}};
  assert_int_equal(geom_polygon_check(star, 5, &bad, &rev), GEOM_NOT_CONVEX);

  for (int e = GEOM_OK; e <= GEOM_OUT_OF_SCALE; e++) {
    const char *s = geom_polyerr_str((geom_polyerr)e);
    assert_non_null(s);
    assert_true(strlen(s) > 0 && strchr(s, '\n') == NULL);
  }

  /* The same strictly convex kite at many scales: every exact orientation
  ** is +1.  Inside the coordinate contract (geom.h: every coordinate 0 or
  ** of magnitude in [1e-30, 1e30]) it must pass; outside it the only
  ** acceptable answer is the documented GEOM_OUT_OF_SCALE refusal, never
  ** "not convex". */
  const double scales[] = {1e-300, 0x1p-1000, 1e-160, 1e-31, 1e-30, 1e-20, 1, 1e20,
                           5e29, 6e29, 1e49, 1e160, 1e300};
  int kite_bad = 0;
  for (size_t i = 0; i < sizeof scales / sizeof scales[0]; i++) {
    double k = scales[i];
    geom_point kite[4] = {{0, -k}, {2 * k, 0}, {0, k}, {-k, 0}};
    for (int v = 0; v < 4; v++)
      assert_int_equal(tgeom_orient_exact(kite[v], kite[(v + 1) % 4], kite[(v + 2) % 4]), 1);
    int inside = k >= GEOM_COORD_MIN && 2 * k <= GEOM_COORD_MAX;
    geom_polyerr e = geom_polygon_check(kite, 4, &bad, &rev);
    if (e != (inside ? GEOM_OK : GEOM_OUT_OF_SCALE)) {
      print_error("kite (0,-k) (2k,0) (0,k) (-k,0), k = %g: %s\n", k, geom_polyerr_str(e));
      kite_bad++;
    }
  }
  assert_int_equal(kite_bad, 0);
}

/* geom_tri_make's vertex order is the plain three-comparator network
** (compare-exchange (0,1), (1,2), (0,1), swapping the points when the
** second is lexicographically smaller), bit for bit, whatever the branch-free
** form it is written in: on random triples drawn from a few values, so that
** ties in x, equal points, signed zeros, infinities and NaN all occur, in
** every order. */
static void tgeom_network(geom_point v[3]) {
  static const int ce[3][2] = {{0, 1}, {1, 2}, {0, 1}};
  for (int k = 0; k < 3; k++) {
    geom_point *a = &v[ce[k][0]], *b = &v[ce[k][1]];
    if (b->x < a->x || (b->x == a->x && b->y < a->y)) {
      geom_point s = *a;
      *a = *b;
      *b = s;
    }
  }
}

static void test_tri_canonical_order(void **state) {
  (void)state;
  static const double vals[] = {0.0, -0.0, 1.0, -1.0, 2.5, INFINITY, NAN};
  uint64_t g = 99;
  long bad = 0;
  for (int it = 0; it < 200000; it++) {
    geom_point v[3];
    for (int i = 0; i < 3; i++) {
      g = g * 6364136223846793005u + 1442695040888963407u;
      int lim = it % 4 ? 5 : 7;   /* non-finite values in a quarter of the triples */
      v[i] = (geom_point){vals[(g >> 33) % lim], vals[(g >> 45) % lim]};
    }
    geom_point want[3] = {v[0], v[1], v[2]};
    tgeom_network(want);
    geom_tri t;
    geom_tri_make(&t, v[0], v[1], v[2]);
    if (memcmp(t.v, want, sizeof want) != 0 && bad++ < 3)
      print_error("(%g,%g) (%g,%g) (%g,%g): not the network's order\n", v[0].x, v[0].y, v[1].x,
                  v[1].y, v[2].x, v[2].y);
  }
  assert_int_equal(bad, 0);
}

/* The one number parser: a span is a number only if all of its bytes are
** (a NUL byte inside refuses it), out-of-range values are errors, the scan
** stops where strtod stops, counts are digits only and do not overflow. */
static void test_number_parse(void **state) {
  (void)state;
  double x = 7;
  assert_int_equal(geom_number_parse("0.5", 3, &x), GEOM_NUM_OK);
  assert_true(x == 0.5);
  assert_int_equal(geom_number_parse("0.5\0garbage", 11, &x), GEOM_NUM_NOT_NUMBER);
  assert_int_equal(geom_number_parse("0.5\0", 4, &x), GEOM_NUM_NOT_NUMBER);
  assert_int_equal(geom_number_parse("0.5garbage", 10, &x), GEOM_NUM_NOT_NUMBER);
  assert_int_equal(geom_number_parse("0.5", 2, &x), GEOM_NUM_OK);   /* the span is "0." */
  assert_true(x == 0.0);
  assert_int_equal(geom_number_parse("", 0, &x), GEOM_NUM_NOT_NUMBER);
  /* no blanks around a number, as around a count (a quoted CSV field " 2"
  ** was a number while " 2" as an index was not) */
  assert_int_equal(geom_number_parse(" 2", 2, &x), GEOM_NUM_NOT_NUMBER);
  assert_int_equal(geom_number_parse("2 ", 2, &x), GEOM_NUM_NOT_NUMBER);
  assert_int_equal(geom_number_parse("\t2", 2, &x), GEOM_NUM_NOT_NUMBER);
  assert_int_equal(geom_number_parse("1e400", 5, &x), GEOM_NUM_OUT_OF_RANGE);
  assert_int_equal(geom_number_parse("1e-400", 6, &x), GEOM_NUM_OUT_OF_RANGE);
  assert_int_equal(geom_number_parse("1e-310", 6, &x), GEOM_NUM_OUT_OF_RANGE);   /* subnormal */
  assert_int_equal(geom_number_parse("inf", 3, &x), GEOM_NUM_NOT_FINITE);
  assert_int_equal(geom_number_parse("nan", 3, &x), GEOM_NUM_NOT_FINITE);
  assert_int_equal(geom_number_parse("0x1p3", 5, &x), GEOM_NUM_OK);
  assert_true(x == 8.0);
  char big[300];   /* longer than the parser's stack copy */
  memset(big, '0', sizeof big);
  big[0] = '1';
  big[1] = '.';
  assert_int_equal(geom_number_parse(big, sizeof big, &x), GEOM_NUM_OK);
  assert_true(x == 1.0);
  size_t used = 0;
  assert_int_equal(geom_number_scan("2.5e3*a", 7, &x, &used), GEOM_NUM_OK);
  assert_int_equal(used, 5);
  assert_true(x == 2500.0);
  assert_int_equal(geom_number_scan("1e999+b", 7, &x, &used), GEOM_NUM_OUT_OF_RANGE);
  assert_int_equal(used, 5);
  assert_true(isinf(x));
  assert_int_equal(geom_number_scan("a", 1, &x, &used), GEOM_NUM_NOT_NUMBER);
  assert_int_equal(used, 0);
  uint64_t c = 3;
  assert_int_equal(geom_count_parse("18446744073709551615", 20, &c), 0);
  assert_true(c == UINT64_MAX);
  assert_int_equal(geom_count_parse("18446744073709551616", 20, &c), -1);
  assert_int_equal(geom_count_parse("20\0" "7", 4, &c), -1);
  assert_int_equal(geom_count_parse("20", 2, &c), 0);
  assert_true(c == 20);
  assert_int_equal(geom_count_parse("+1", 2, &c), -1);
  assert_int_equal(geom_count_parse(" 1", 2, &c), -1);
  assert_int_equal(geom_count_parse("", 0, &c), -1);
  assert_int_equal(geom_coord_parse_n("1\0" "5", 3, &x), GEOM_COORD_NOT_NUMBER);
  assert_int_equal(geom_coord_parse_n("1e31", 4, &x), GEOM_COORD_OUT_OF_RANGE);
}

/* geom_coord_check_n finds the first coordinate geom_coord_check refuses,
** in an array of valid ones with each kind of bad one planted at each place. */
static void test_coord_check_n(void **state) {
  (void)state;
  double ok[8] = {0, 1, -1e30, 1e-30, -0.0, 3.5, -2e-30, 1e30};
  assert_int_equal(geom_coord_check_n(ok, 8), 8);
  assert_int_equal(geom_coord_check_n(ok, 0), 0);
  const double bad[] = {NAN, INFINITY, -INFINITY, 1e31, 1e-31, 4e-320, -2e30};
  for (size_t b = 0; b < sizeof bad / sizeof *bad; b++)
    for (size_t at = 0; at < 8; at++) {
      double x[8];
      memcpy(x, ok, sizeof x);
      x[at] = bad[b];
      assert_int_equal(geom_coord_check_n(x, 8), at);
      if (at < 7) x[7] = bad[b];   /* the first one counts */
      assert_int_equal(geom_coord_check_n(x, 8), at);
    }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_tri_equilateral),
    cmocka_unit_test(test_tri_345),
    cmocka_unit_test(test_tri_sliver),
    cmocka_unit_test(test_tri_needle),
    cmocka_unit_test(test_tri_random),
    cmocka_unit_test(test_tri_canonical_order),
    cmocka_unit_test(test_orient_easy),
    cmocka_unit_test(test_incircle_easy),
    cmocka_unit_test(test_orient_near_degenerate),
    cmocka_unit_test(test_incircle_near_degenerate),
    cmocka_unit_test(test_predicates_contract),
    cmocka_unit_test(test_predicates_random),
    cmocka_unit_test(test_predicates_extreme),
    cmocka_unit_test(test_twice_area_exact),
    cmocka_unit_test(test_segments_cross),
    cmocka_unit_test(test_dist_finite),
    cmocka_unit_test(test_polygon_check),
    cmocka_unit_test(test_number_parse),
    cmocka_unit_test(test_coord_check_n),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
