/*
** test_predicates_exact.c: the fast exact stages of geom/predicates.c
** (integers, floating-point expansions) against the purely exact mode
** (geom_exact_gmp_only: every fallback in GMP rationals, which test_geom.c
** checks against its own rational oracle).  Orientation, incircle and power
** decisions agree on random integer sets, grids of every step, cocircular
** sets (the lattice points of Pythagorean circles, with weights that make
** the power test vanish), collinear sets, huge and tiny scaled lattices up
** to and past the stages' ranges, lattices stretched past the integer
** stage, its overflow bounds, and double inputs with rounded differences;
** each test also checks, from the counters, that the stages it is about
** ran.  Whole triangulations (DT of grids, of a Pythagorean circle, of a
** steep parabola, of a stretched grid; WDT of a weighted grid) come out
** triangle for triangle as in the GMP-only mode, and the DT of the 100 x 100
** grid needs no GMP call at all: a regression guard on counts, not on time.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom.h"
#include "lot.h"
#include "rule.h"
#include "sampler.h"
#include "testutil.h"

/* ---- one tuple against the GMP-only mode ---- */

/* The counters of every predicate and stage, for before/after deltas. */
typedef struct tpe_counts {
  unsigned long c[GEOM_PRED_COUNT][GEOM_STAGE_COUNT];
} tpe_counts;

static tpe_counts tpe_snapshot(void) {
  tpe_counts t;
  for (int p = 0; p < GEOM_PRED_COUNT; p++)
    for (int s = 0; s < GEOM_STAGE_COUNT; s++) t.c[p][s] = geom_exact_stage_calls(p, s);
  return t;
}

static unsigned long tpe_delta(const tpe_counts *since, geom_pred p, geom_stage s) {
  return geom_exact_stage_calls(p, s) - since->c[p][s];
}

/* The three exact predicates on q (orient of q0 q1 q2; incircle and, with
** w, power of all four) and their filtered forms, in the current mode. */
static void tpe_eval(const geom_point q[4], const double *w, int out[6]) {
  out[0] = geom_orient_exact(q[0], q[1], q[2]);
  out[1] = geom_incircle_exact(q[0], q[1], q[2], q[3]);
  out[2] = w != NULL ? geom_power_exact(q[0], q[1], q[2], q[3], w) : 0;
  out[3] = geom_orient(q[0], q[1], q[2]);
  out[4] = geom_incircle(q[0], q[1], q[2], q[3]);
  out[5] = w != NULL ? geom_power(q[0], q[1], q[2], q[3], w) : 0;
}

static int tpe_zeros;   /* exact zeros seen by the running test */

/* Every decision on q equals the GMP-only one (and the filtered forms equal
** the exact ones); fails the test with the tuple in hexadecimal if not. */
static void tpe_check(const geom_point q[4], const double *w) {
  int fast[6], gmp[6];
  tpe_eval(q, w, fast);
  int was = geom_exact_gmp_only(1);
  tpe_eval(q, w, gmp);
  geom_exact_gmp_only(was);
  for (int k = 0; k < 6; k++)
    if (fast[k] != gmp[k] || gmp[k] != gmp[k % 3]) {
      print_error("decision %d: fast %d, GMP %d at (%a,%a) (%a,%a) (%a,%a) (%a,%a)", k, fast[k],
                  gmp[k], q[0].x, q[0].y, q[1].x, q[1].y, q[2].x, q[2].y, q[3].x, q[3].y);
      if (w != NULL) print_error(" weights %a %a %a %a", w[0], w[1], w[2], w[3]);
      print_error("\n");
      fail();
    }
  tpe_zeros += (gmp[0] == 0) + (gmp[1] == 0) + (w != NULL && gmp[2] == 0);
}

/* A random integer-valued double in [-m, m] (every integer when m <= 2^52). */
static double tpe_int(testutil_rng *g, double m) {
  double u = (double)(testutil_next(g) >> 11) * 0x1p-53;   /* [0, 1), 53 bits */
  return floor(u * (2 * m + 1)) - m;
}

/* ---- integer sets and grids ---- */

/* Four points of the lattice o + s (i, j), i, j in [0, 6): collinear and
** cocircular (the corners of every square and rectangle) often. */
static void tpe_lattice(testutil_rng *g, double ox, double oy, double s, geom_point q[4]) {
  for (int k = 0; k < 4; k++)
    q[k] = (geom_point){ox + s * (double)(testutil_next(g) % 6),
                        oy + s * (double)(testutil_next(g) % 6)};
}

/* Integer sets of magnitude 2^bits: half uniform, half from a lattice of
** integer step (grids with every step, offset anywhere), with integer
** weights (equal ones, and ones that make the power test vanish). */
static void test_integer_sets(void **state) {
  (void)state;
  testutil_rng g = {3501};
  static const int bits[] = {2, 8, 20, 28, 29, 30, 31, 40, 50};
  tpe_counts t0 = tpe_snapshot();
  tpe_zeros = 0;
  for (size_t b = 0; b < sizeof bits / sizeof bits[0]; b++) {
    double m = ldexp(1, bits[b]);
    for (int it = 0; it < 4000; it++) {
      geom_point q[4];
      if (it % 2) {
        for (int k = 0; k < 4; k++) q[k] = (geom_point){tpe_int(&g, m), tpe_int(&g, m)};
      } else {
        double s = 1 + floor(testutil_uniform(&g) * fmax(m / 16, 1));
        tpe_lattice(&g, tpe_int(&g, m / 2), tpe_int(&g, m / 2), s, q);
      }
      double w[4], lim = fmin(m * m, 0x1p60);
      for (int k = 0; k < 4; k++) w[k] = it % 3 ? tpe_int(&g, lim) : 7;
      tpe_check(q, w);
    }
  }
  print_message("integer sets: %d exact zeros\n", tpe_zeros);
  assert_true(tpe_zeros > 5000);
  for (int p = GEOM_PRED_ORIENT; p <= GEOM_PRED_POWER; p++)
    assert_true(tpe_delta(&t0, p, GEOM_STAGE_INT) > 10000);
}

/* Lattices o + 2^k (i, j) for k from -260 to 260, translated by multiples
** of coarser and finer powers of two (the "small exponent range" of the
** integer stage: a fine lattice far from the origin), up to and past the
** moderate range [2^-200, 2^200] where GMP takes over. */
static void test_scaled_lattices(void **state) {
  (void)state;
  testutil_rng g = {3502};
  tpe_counts t0 = tpe_snapshot();
  tpe_zeros = 0;
  for (int k = -260; k <= 260; k += 4)
    for (int it = 0; it < 200; it++) {
      int shift = (int)(testutil_next(&g) % 60) - 10;
      double s = ldexp(1, k), o = ldexp(1, k + shift);
      geom_point q[4];
      tpe_lattice(&g, o * tpe_int(&g, 1 << 20), o * tpe_int(&g, 1 << 20), s, q);
      double w[4];
      for (int j = 0; j < 4; j++) w[j] = ldexp(tpe_int(&g, 64), 2 * k);
      tpe_check(q, w);
    }
  print_message("scaled lattices: %d exact zeros\n", tpe_zeros);
  assert_true(tpe_zeros > 10000);
  for (int p = GEOM_PRED_ORIENT; p <= GEOM_PRED_POWER; p++) {
    assert_true(tpe_delta(&t0, p, GEOM_STAGE_INT) > 1000);
    assert_true(tpe_delta(&t0, p, GEOM_STAGE_GMP) > 100);
  }
}

/* Lattices o + (2^kx i, 2^ky j) stretched so that their differences span
** more than the integer stage's 62 bits (|kx - ky| from 40 to 130): exact
** differences, decided by the expansions. */
static void test_stretched_lattices(void **state) {
  (void)state;
  testutil_rng g = {3507};
  tpe_counts t0 = tpe_snapshot();
  tpe_zeros = 0;
  for (int it = 0; it < 30000; it++) {
    int kx = (int)(testutil_next(&g) % 120) - 60, spread = 40 + (int)(testutil_next(&g) % 91);
    int ky = kx + (it % 2 ? spread : -spread);
    geom_point q[4];
    for (int k = 0; k < 4; k++)
      q[k] = (geom_point){ldexp((double)(testutil_next(&g) % 6), kx),
                          ldexp((double)(testutil_next(&g) % 6), ky)};
    double w[4];
    for (int k = 0; k < 4; k++) w[k] = ldexp(tpe_int(&g, 8), 2 * (kx < ky ? kx : ky));
    tpe_check(q, w);
  }
  print_message("stretched lattices: %d exact zeros\n", tpe_zeros);
  assert_true(tpe_zeros > 5000);
  for (int p = GEOM_PRED_ORIENT; p <= GEOM_PRED_POWER; p++)
    assert_true(tpe_delta(&t0, p, GEOM_STAGE_EXPANSION) > 1000);
}

/* ---- cocircular and collinear sets ---- */

/* The lattice points of the circle x^2 + y^2 = r^2 (r a product of primes
** 4k + 1: many of them) into out; returns their count. */
static size_t tpe_circle(double r, geom_point *out, size_t cap) {
  size_t n = 0;
  for (double a = -r; a <= r; a++) {
    double b = sqrt(r * r - a * a);
    if (b != floor(b)) continue;
    if (n < cap) out[n++] = (geom_point){a, b};
    if (b != 0 && n < cap) out[n++] = (geom_point){a, -b};
  }
  return n;
}

/* Four points of a Pythagorean circle about an integer centre, scaled by a
** power of two, sometimes one coordinate moved by an ulp (nearly
** cocircular); the weights w_i = |p_i - c|^2 - K put the four lifted
** points on one plane (a power test of 0), sometimes one moved by 1. */
static void test_cocircular(void **state) {
  (void)state;
  static const double radii[] = {5, 25, 65, 325, 1105, 5525, 32045};
  geom_point on[512];
  testutil_rng g = {3503};
  tpe_counts t0 = tpe_snapshot();
  tpe_zeros = 0;
  for (size_t r = 0; r < sizeof radii / sizeof radii[0]; r++) {
    size_t n = tpe_circle(radii[r], on, 512);
    assert_true(n >= 12);
    for (int it = 0; it < 3000; it++) {
      double sc = ldexp(1, (int)(testutil_next(&g) % 200) - 100);
      double cx = tpe_int(&g, 1e6), cy = tpe_int(&g, 1e6), K = tpe_int(&g, 1e9);
      geom_point q[4];
      double w[4];
      for (int k = 0; k < 4; k++) {
        geom_point p = on[testutil_next(&g) % n];
        q[k] = (geom_point){(cx + p.x) * sc, (cy + p.y) * sc};
        w[k] = (p.x * p.x + p.y * p.y - K) * sc * sc;
      }
      if (it % 3 == 1) q[3].x = nextafter(q[3].x, INFINITY);
      if (it % 3 == 2) w[3] += sc * sc;
      tpe_check(q, w);
    }
  }
  print_message("cocircular sets: %d exact zeros\n", tpe_zeros);
  assert_true(tpe_zeros > 15000);
  assert_true(tpe_delta(&t0, GEOM_PRED_INCIRCLE, GEOM_STAGE_INT) > 1000);
  assert_true(tpe_delta(&t0, GEOM_PRED_POWER, GEOM_STAGE_INT) > 1000);
}

/* Points o + t v on a line with integer t and a dyadic direction v, at
** every scale, sometimes moved by an ulp; and points on a line rounded to
** doubles, at magnitudes far apart (differences rounded too: the
** orientation's expansions decide). */
static void test_collinear(void **state) {
  (void)state;
  testutil_rng g = {3504};
  tpe_counts t0 = tpe_snapshot();
  tpe_zeros = 0;
  for (int it = 0; it < 40000; it++) {
    int k = (int)(testutil_next(&g) % 300) - 150;
    geom_point o = {ldexp(tpe_int(&g, 1e12), k), ldexp(tpe_int(&g, 1e12), k)};
    geom_point v = {ldexp(tpe_int(&g, 1000), k), ldexp(tpe_int(&g, 1000), k)};
    geom_point q[4];
    for (int j = 0; j < 4; j++) {   /* odd it: integer t; even: t of any magnitude, rounded */
      double t = it % 2 ? tpe_int(&g, 1e4) : ldexp(testutil_uniform(&g), (int)(it / 2 % 40));
      q[j] = (geom_point){o.x + t * v.x, o.y + t * v.y};
    }
    if (it % 5 == 0) q[2].y = nextafter(q[2].y, -INFINITY);
    tpe_check(q, NULL);
  }
  print_message("collinear sets: %d exact zeros\n", tpe_zeros);
  assert_true(tpe_zeros > 10000);
  assert_true(tpe_delta(&t0, GEOM_PRED_ORIENT, GEOM_STAGE_INT) > 1000);
  assert_true(tpe_delta(&t0, GEOM_PRED_ORIENT, GEOM_STAGE_EXPANSION) > 1000);
}

/* ---- the integer stage's bounds, and rounded differences ---- */

/* Differences at the integer stage's limits, where an overflow would show,
** and just past them: |x|, |y| up to 2^30 - 1 (the narrow form of the
** lifted determinant) and up to 2^62 - 2^10 (the wide form, and the
** orientation), weights up to 2^125 - 2^73. */
static void test_int_bounds(void **state) {
  (void)state;
  static const double narrow[] = {0x1p30 - 1, -(0x1p30 - 1), 0x1p30 - 2, 0x1p29, 0, 1, 0x1p30};
  static const double wide[] = {0x1p62 - 0x1p10, -(0x1p62 - 0x1p10), 0x1p61, 1, 0, -3};
  static const double weight[] = {0x1p61 - 0x1p9, -(0x1p61 - 0x1p9), 0x1p125 - 0x1p73,
                                  -(0x1p125 - 0x1p73), 0x1p124, 0};
  testutil_rng g = {3505};
  tpe_counts t0 = tpe_snapshot();
  for (int it = 0; it < 30000; it++) {
    geom_point q[4];
    double w[4];
    const double *v = it % 2 ? narrow : wide;
    size_t nv = it % 2 ? sizeof narrow / sizeof narrow[0] : sizeof wide / sizeof wide[0];
    for (int k = 0; k < 3; k++) {
      q[k] = (geom_point){v[testutil_next(&g) % nv], v[testutil_next(&g) % nv]};
      w[k] = weight[testutil_next(&g) % (sizeof weight / sizeof weight[0])];
    }
    q[3] = (geom_point){0, 0};
    w[3] = 0;
    tpe_check(q, w);
  }
  assert_true(tpe_delta(&t0, GEOM_PRED_ORIENT, GEOM_STAGE_INT) > 10000);
  assert_true(tpe_delta(&t0, GEOM_PRED_INCIRCLE, GEOM_STAGE_INT) > 1000);
  assert_true(tpe_delta(&t0, GEOM_PRED_POWER, GEOM_STAGE_INT) > 1000);
}

/* Doubles whose differences round: points on the unit circle (cos, sin),
** Shewchuk's picture (0.5 + i 2^-53, ...) against (12, 12), (24, 24), and
** coordinates of mixed magnitudes; the orientation is decided by
** expansions, the incircle test by GMP where a difference rounds. */
static void test_rounded_differences(void **state) {
  (void)state;
  testutil_rng g = {3506};
  geom_point c[4096];
  sampler_points(SAMPLER_CIRCLE, 7, 4096, c);
  tpe_counts t0 = tpe_snapshot();
  for (int it = 0; it < 4093; it++) tpe_check(c + it, NULL);
  for (int i = 0; i < 64; i++)
    for (int j = 0; j < 64; j++) {
      geom_point q[4] = {{0.5 + i * 0x1p-53, 0.5 + j * 0x1p-53}, {12, 12}, {24, 24},
                         {0.5 + j * 0x1p-52, 0.5 + i * 0x1p-52}};
      tpe_check(q, NULL);
    }
  for (int it = 0; it < 20000; it++) {
    geom_point q[4];
    for (int k = 0; k < 4; k++) {
      double s = ldexp(1, (int)(testutil_next(&g) % 80) - 40);
      q[k] = (geom_point){s * (1 + testutil_uniform(&g)), s * (1 + testutil_uniform(&g))};
    }
    q[2] = (geom_point){q[0].x + 0.5 * (q[1].x - q[0].x), q[0].y + 0.5 * (q[1].y - q[0].y)};
    tpe_check(q, NULL);
  }
  assert_true(tpe_delta(&t0, GEOM_PRED_ORIENT, GEOM_STAGE_EXPANSION) > 100);
  assert_true(tpe_delta(&t0, GEOM_PRED_INCIRCLE, GEOM_STAGE_GMP) > 100);
}

/* ---- whole triangulations ---- */

/* The triangles of rule `name` on p (weights w or NULL), sorted, and the
** redundant sites after them; malloc'd, *len entries. */
static uint32_t *tpe_triangulate(const char *name, const geom_point *p, size_t n,
                                 const double *w, size_t *len) {
  rule r;
  char err[256];
  if (rule_parse(name, &r, err, sizeof err) != 0) fail_msg("%s: %s", name, err);
  lot_options o;
  lot_options_init(&o, &r);
  o.weights = w;
  lot *L;
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) fail_msg("lot_build: %s", err);
  const lot_stats *st = lot_get_stats(L);
  assert_int_equal(st->status, LOT_CONVERGED);
  uint32_t *t = malloc((3 * st->triangles + n + 1) * sizeof *t);
  assert_non_null(t);
  lot_get_triangles(L, t);
  *len = 3 * st->triangles + lot_get_redundant(L, t + 3 * st->triangles);
  lot_free(L);
  return t;
}

/* The triangulation equals the GMP-only mode's, triangle for triangle. */
static void tpe_same_as_gmp(const char *name, const geom_point *p, size_t n, const double *w) {
  size_t a, b;
  uint32_t *fast = tpe_triangulate(name, p, n, w, &a);
  int was = geom_exact_gmp_only(1);
  uint32_t *gmp = tpe_triangulate(name, p, n, w, &b);
  geom_exact_gmp_only(was);
  assert_int_equal(a, b);
  assert_memory_equal(fast, gmp, a * sizeof *fast);
  free(fast);
  free(gmp);
}

/* The DT of the 100 x 100 grid: no GMP call (the integer stage decides
** every degenerate test: 0 here, thousands before it existed), and the
** same triangles as the GMP-only mode. */
static void test_grid_dt_no_gmp(void **state) {
  (void)state;
  enum { N = 10000 };
  geom_point *p = malloc(N * sizeof *p);
  assert_non_null(p);
  sampler_points(SAMPLER_GRID, 1, N, p);
  tpe_counts t0 = tpe_snapshot();
  size_t len;
  free(tpe_triangulate("DT", p, N, NULL, &len));
  unsigned long gmp = tpe_delta(&t0, GEOM_PRED_ORIENT, GEOM_STAGE_GMP)
                    + tpe_delta(&t0, GEOM_PRED_INCIRCLE, GEOM_STAGE_GMP);
  unsigned long fast = tpe_delta(&t0, GEOM_PRED_ORIENT, GEOM_STAGE_INT)
                     + tpe_delta(&t0, GEOM_PRED_INCIRCLE, GEOM_STAGE_INT);
  print_message("DT of the 100 x 100 grid: %lu exact calls in 128-bit integers, %lu in GMP\n",
                fast, gmp);
  assert_int_equal(gmp, 0);
  assert_true(fast > 1000);
  tpe_same_as_gmp("DT", p, N, NULL);
  free(p);
}

/* DT of a grid of step 2^-30 far from the origin, of the lattice points of
** a Pythagorean circle with its centre, of a steep parabola (the wide
** integer form) and of a grid stretched 2^70 times (the expansions); WDT
** of a grid with weights in multiples of 2^-61: each the same
** triangulation as in the GMP-only mode. */
static void test_triangulations_as_gmp(void **state) {
  (void)state;
  enum { N = 4096 };
  geom_point *p = malloc(N * sizeof *p);
  double *w = malloc(N * sizeof *w);
  assert_non_null(p);
  assert_non_null(w);
  sampler_points(SAMPLER_GRID, 1, N, p);
  for (size_t i = 0; i < N; i++) {
    w[i] = (double)((i * 7 + i / 64) % 3) * 0x1p-61;
    p[i] = (geom_point){1e6 + p[i].x * 0x1p-30, -3e5 + p[i].y * 0x1p-30};
  }
  tpe_same_as_gmp("DT", p, N, NULL);
  tpe_same_as_gmp("WDT", p, N, w);
  size_t n = tpe_circle(32045, p, N - 1);
  p[n++] = (geom_point){0, 0};
  tpe_same_as_gmp("DT", p, n, NULL);
  for (size_t i = 0; i < 2000; i++) {
    double x = 1e6 - (double)i;
    p[i] = (geom_point){x, x * x};
  }
  tpe_same_as_gmp("DT", p, 2000, NULL);
  tpe_counts t0 = tpe_snapshot();
  sampler_points(SAMPLER_GRID, 1, N, p);
  for (size_t i = 0; i < N; i++) p[i] = (geom_point){p[i].x * 0x1p40, p[i].y * 0x1p-30};
  tpe_same_as_gmp("DT", p, N, NULL);
  assert_true(tpe_delta(&t0, GEOM_PRED_INCIRCLE, GEOM_STAGE_EXPANSION) > 1000);
  free(p);
  free(w);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_integer_sets),
    cmocka_unit_test(test_scaled_lattices),
    cmocka_unit_test(test_stretched_lattices),
    cmocka_unit_test(test_cocircular),
    cmocka_unit_test(test_collinear),
    cmocka_unit_test(test_int_bounds),
    cmocka_unit_test(test_rounded_differences),
    cmocka_unit_test(test_grid_dt_no_gmp),
    cmocka_unit_test(test_triangulations_as_gmp),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
