/*
** test_lot_enclosed.c: the LOT's enclosed badness cache (lot/lot.c,
** lot_prefers_lazy), which decides a flip of the angle measures under l_1,
** l_inf and l_-inf from enclosures of the four triangles' values
** (measure_bounds) and computes exact values only when they cannot tell.
** Its verdicts at every stage are checked against the exact decision on
** random and adversarial quadrilaterals (symmetric ones with exactly equal
** values, near-symmetric ones at the tie tolerance, needles, flat ones, at
** the coordinate contract's ends), and whole LOTs against those of the
** exact cache (a user copy of the measure, which has no enclosures):
** the same triangles and the same number of flips.
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

#include "joint.h"
#include "lot.h"
#include "measure.h"
#include "rule.h"
#include "sampler.h"
#include "testutil.h"

static const int tle_measures[] = {MEASURE_NEG_ALPHA, MEASURE_BETA, MEASURE_GAMMA,
                                   MEASURE_SIGMA};
static const joint_id tle_joints[] = {JOINT_SUM, JOINT_MIN, JOINT_MAX};
static const double tle_eps[] = {1e-12, 0, 1e-6, 0.5};

/* A triangle's value as the cache holds it: the enclosure, or the exact
** value where there is none; *x the exact value. */
static void tle_enclose(int id, geom_point p, geom_point q, geom_point r, double *lo,
                        double *hi, double *x) {
  geom_tri t;
  geom_tri_make(&t, p, q, r);
  *x = measure_eval(id, &t);
  if (!measure_bounds(id, p, q, r, lo, hi)) *lo = *hi = *x;
}

/* Coordinates scaled by 2^e and clamped into the contract. */
static geom_point tle_scaled(geom_point p, int e) {
  double x = ldexp(p.x, e), y = ldexp(p.y, e);
  x = fabs(x) > 1e30 ? copysign(1e30, x) : fabs(x) < 1e-30 && x != 0 ? copysign(1e-30, x) : x;
  y = fabs(y) > 1e30 ? copysign(1e30, y) : fabs(y) < 1e-30 && y != 0 ? copysign(1e-30, y) : y;
  return (geom_point){x, y};
}

/* Quadrilateral kinds: 0 random convex, 1 a square, rectangle or rhombus
** (the two diagonals' values equal: exact ties), 2 a kite or an isosceles
** trapezoid nudged by a few ulps or by 1e-9 (values near the tie
** tolerance), 3 near-cocircular, 4 a needle (one vertex close to another),
** 5 almost flat (one vertex just off the diagonal); then scaled by
** 2^-99 .. 2^99, and a tenth pushed against the contract's ends. */
static void tle_quad(testutil_rng *g, int kind, geom_point q[4]) {
  double u[4];
  for (int i = 0; i < 4; i++) u[i] = testutil_uniform(g);
  switch (kind) {
    case 0: testutil_convex_quad(g, q); break;
    case 1: {
      double w = 0.5 + u[0], h = testutil_next(g) & 1 ? w : 0.5 + u[1];
      if (testutil_next(g) & 1) {   /* rectangle w x h */
        q[0] = (geom_point){0, 0}; q[1] = (geom_point){w, 0};
        q[2] = (geom_point){w, h}; q[3] = (geom_point){0, h};
      } else {                      /* rhombus */
        q[0] = (geom_point){-w, 0}; q[1] = (geom_point){0, -h};
        q[2] = (geom_point){w, 0}; q[3] = (geom_point){0, h};
      }
      break;
    }
    case 2: {
      double a = 0.3 + u[0], b = 0.3 + u[1], nudge = testutil_next(g) & 1 ? 1e-9 : 0x1p-50;
      q[0] = (geom_point){-a, 0}; q[1] = (geom_point){-b, -1};
      q[2] = (geom_point){b, -1}; q[3] = (geom_point){a * (1 + nudge * (u[2] - 0.5)), 0};
      if (testutil_next(g) & 1) q[1] = (geom_point){0, -b};   /* kite: A B C D symmetric */
      if (q[1].x == 0) q[2] = (geom_point){a, 0}, q[3] = (geom_point){0, b * (1 + nudge * u[3])};
      break;
    }
    case 3:
      for (int i = 0; i < 4; i++) {
        double th = (i + 0.8 * u[i]) * M_PI / 2, rad = 1 + 1e-12 * (u[(i + 1) % 4] - 0.5);
        q[i] = (geom_point){rad * cos(th), rad * sin(th)};
      }
      break;
    case 4:
      testutil_convex_quad(g, q);
      q[1] = (geom_point){q[0].x + 1e-7 * (q[1].x - q[0].x), q[0].y + 1e-7 * (q[1].y - q[0].y)};
      break;
    default:
      testutil_convex_quad(g, q);
      q[1] = (geom_point){0.5 * (q[0].x + q[2].x) + 1e-10 * (q[0].y - q[2].y),
                          0.5 * (q[0].y + q[2].y) - 1e-10 * (q[0].x - q[2].x)};
      break;
  }
  int e = (int)(testutil_next(g) % 199) - 99;
  if (testutil_next(g) % 10 == 0) e = testutil_next(g) & 1 ? 99 : -99;
  for (int i = 0; i < 4; i++) q[i] = tle_scaled(q[i], e);
}

typedef struct tle_count {
  long cases, decided, exact_ties, wrong;
} tle_count;

/* One verdict against the exact decision (flip: it is < 0). */
static void tle_verdict(joint_id j, int s, const double lo[4], const double hi[4], double eps,
                        int flip, const char *stage, tle_count *c) {
  joint_verdict v = joint_compare_bounds(j, s, lo, hi, eps);
  if (v == JOINT_UNSURE || (v == JOINT_LESS) == flip) return;
  if (c->wrong++ < 5)
    print_error("%s: joint %s s=%d eps %g: verdict %s, exact decision %s; enclosures "
                "[%.17g %.17g] [%.17g %.17g] [%.17g %.17g] [%.17g %.17g]\n", stage,
                joint_get(j)->name, s, eps, v == JOINT_LESS ? "flip" : "keep",
                flip ? "flip" : "keep", lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], lo[3], hi[3]);
}

/* Quadrilateral ABCD (anticlockwise), current diagonal BD, the new one AC:
** the three stages of lot_prefers_lazy (the first new triangle with the
** measure's floor for the second; both new; the current ones exact) for
** one measure, joint and tolerance. */
static void tle_check_quad(const geom_point q[4], int id, joint_id j, double eps,
                           tle_count *c) {
  double lo[4], hi[4], x[4];
  tle_enclose(id, q[0], q[1], q[2], &lo[0], &hi[0], &x[0]);   /* ABC: new */
  tle_enclose(id, q[0], q[2], q[3], &lo[1], &hi[1], &x[1]);   /* ACD: new */
  tle_enclose(id, q[0], q[1], q[3], &lo[2], &hi[2], &x[2]);   /* ABD: current */
  tle_enclose(id, q[1], q[2], q[3], &lo[3], &hi[3], &x[3]);   /* BCD: current */
  int s = measure_get(id)->sign, cmp = joint_compare(j, s, x[0], x[1], x[2], x[3], eps);
  c->cases++;
  c->exact_ties += cmp == 0;
  double flo[4] = {lo[0], measure_floor(id), lo[2], lo[3]};
  double fhi[4] = {hi[0], INFINITY, hi[2], hi[3]};
  tle_verdict(j, s, flo, fhi, eps, cmp < 0, "first triangle", c);
  tle_verdict(j, s, lo, hi, eps, cmp < 0, "enclosures", c);
  c->decided += joint_compare_bounds(j, s, lo, hi, eps) != JOINT_UNSURE;
  lo[2] = hi[2] = x[2];
  lo[3] = hi[3] = x[3];
  tle_verdict(j, s, lo, hi, eps, cmp < 0, "current exact", c);
}

/* Every certified verdict, at every stage, is the exact decision; random
** quadrilaterals are nearly all certified from enclosures at the default
** tolerance; symmetric ones give exact ties (so ties are exercised). */
static void test_quad_verdicts(void **state) {
  (void)state;
  testutil_rng g = {2026};
  tle_count all = {0}, random = {0};
  for (int it = 0; it < 30000; it++) {
    geom_point q[4];
    int kind = it % 6;
    tle_quad(&g, kind, q);
    int convex = 1;
    for (int i = 0; i < 4; i++) convex &= geom_orient(q[i], q[(i + 1) % 4], q[(i + 2) % 4]) > 0;
    if (!convex) continue;
    for (size_t m = 0; m < sizeof tle_measures / sizeof tle_measures[0]; m++)
      for (size_t jj = 0; jj < sizeof tle_joints / sizeof tle_joints[0]; jj++)
        for (size_t e = 0; e < sizeof tle_eps / sizeof tle_eps[0]; e++)
          tle_check_quad(q, tle_measures[m], tle_joints[jj], tle_eps[e],
                         kind == 0 && e == 0 ? &random : &all);
  }
  print_message("quadrilaterals: %ld verdicts, %ld exact ties, %ld wrong; random at the "
                "default tolerance: %ld of %ld certified\n", all.cases + random.cases,
                all.exact_ties, all.wrong + random.wrong, random.decided, random.cases);
  assert_int_equal(all.wrong + random.wrong, 0);
  assert_true(all.exact_ties > 1000);
  assert_true(random.decided > 0.99 * (double)random.cases);
}

/* The exact cache's twin of a built-in measure: the same function under
** another name, registered as a user measure (no enclosures). */
static int tle_twin(int id) {
  measure m = *measure_get(id);
  static char names[MEASURE_BUILTIN_COUNT][32];
  snprintf(names[id], sizeof names[id], "twin-of-%s", m.name);
  m.name = names[id];
  int twin = measure_find(m.name);
  return twin >= 0 ? twin : measure_register(&m);
}

static lot *tle_build(const geom_point *p, size_t n, int id, joint_id j, lot_algorithm alg,
                      uint32_t **tri) {
  rule r;
  char err[256];
  if (rule_triangle(id, j, &r, err, sizeof err) != 0) fail_msg("rule: %s", err);
  lot_options o;
  lot_options_init(&o, &r);
  o.algorithm = alg;
  lot *L;
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) fail_msg("lot_build: %s", err);
  *tri = malloc(3 * lot_get_stats(L)->triangles * sizeof **tri);
  assert_non_null(*tri);
  lot_get_triangles(L, *tri);
  return L;
}

/* Whole LOTs: every sampler, both algorithms, the four measures under the
** three joints: the enclosed cache flips exactly as the exact cache does. */
static void test_lot_identical(void **state) {
  (void)state;
  const size_t n = 1500;
  geom_point *p = malloc(n * sizeof *p);
  assert_non_null(p);
  long builds = 0, flips = 0;
  for (int k = 0; k < SAMPLER_POINTS_COUNT; k++) {
    sampler_points((sampler_points_kind)k, 11 + (uint64_t)k, n, p);
    for (size_t m = 0; m < sizeof tle_measures / sizeof tle_measures[0]; m++)
      for (size_t jj = 0; jj < sizeof tle_joints / sizeof tle_joints[0]; jj++)
        for (int alg = 0; alg < 2; alg++) {
          int id = tle_measures[m], twin = tle_twin(id);
          assert_true(twin >= 0);
          uint32_t *ta, *tb;
          lot *A = tle_build(p, n, id, tle_joints[jj], (lot_algorithm)alg, &ta);
          lot *B = tle_build(p, n, twin, tle_joints[jj], (lot_algorithm)alg, &tb);
          const lot_stats *sa = lot_get_stats(A), *sb = lot_get_stats(B);
          if (sa->flips != sb->flips || sa->triangles != sb->triangles ||
              memcmp(ta, tb, 3 * sa->triangles * sizeof *ta) != 0)
            fail_msg("%s, %s_%s, %s: %llu flips, enclosed cache; %llu, exact cache",
                     sampler_points_name((sampler_points_kind)k), measure_get(id)->name,
                     joint_get(tle_joints[jj])->name, alg ? "flip" : "incremental",
                     (unsigned long long)sa->flips, (unsigned long long)sb->flips);
          builds++;
          flips += (long)sa->flips;
          free(ta);
          free(tb);
          lot_free(A);
          lot_free(B);
        }
  }
  print_message("LOTs: %ld builds identical (%ld flips)\n", builds, flips);
  free(p);
  measure_unregister_user();
}

/* Triangles of L after a reflip to measure id under joint j. */
static uint32_t *tle_reflip(lot *L, int id, joint_id j, uint64_t *flips) {
  rule r;
  char err[256];
  if (rule_triangle(id, j, &r, err, sizeof err) != 0) fail_msg("rule: %s", err);
  lot_options o;
  lot_options_init(&o, &r);
  assert_int_equal(lot_reflip(L, &o), 0);
  *flips = lot_get_stats(L)->flips;
  uint32_t *tri = malloc(3 * lot_get_stats(L)->triangles * sizeof *tri);
  assert_non_null(tri);
  lot_get_triangles(L, tri);
  return tri;
}

/* lot_reflip switches the cache between kinds (exact to enclosed, enclosed
** to enclosed or exact) and flips as the exact cache does: from the LOT
** of one rule to another, and on to a third. */
static void test_reflip_identical(void **state) {
  (void)state;
  const size_t n = 1200;
  geom_point *p = malloc(n * sizeof *p);
  assert_non_null(p);
  sampler_points(SAMPLER_NORMAL, 5, n, p);
  static const int from[] = {MEASURE_P, MEASURE_SIGMA, MEASURE_GAMMA};
  for (size_t f = 0; f < sizeof from / sizeof from[0]; f++)
    for (size_t m = 0; m < sizeof tle_measures / sizeof tle_measures[0]; m++) {
      int id = tle_measures[m], twin = tle_twin(id), next = tle_measures[(m + 1) % 4];
      uint32_t *t0, *t1;
      lot *A = tle_build(p, n, from[f], JOINT_SUM, LOT_INCREMENTAL, &t0);
      lot *B = tle_build(p, n, from[f], JOINT_SUM, LOT_INCREMENTAL, &t1);
      free(t0);
      free(t1);
      uint64_t fa, fb;
      uint32_t *ta = tle_reflip(A, id, JOINT_MAX, &fa), *tb = tle_reflip(B, twin, JOINT_MAX, &fb);
      size_t nt = lot_get_stats(A)->triangles;
      assert_true(fa == fb && memcmp(ta, tb, 3 * nt * sizeof *ta) == 0);
      free(ta);
      free(tb);
      ta = tle_reflip(A, next, JOINT_SUM, &fa);
      tb = tle_reflip(B, tle_twin(next), JOINT_SUM, &fb);
      assert_true(fa == fb && memcmp(ta, tb, 3 * nt * sizeof *ta) == 0);
      free(ta);
      free(tb);
      lot_free(A);
      lot_free(B);
    }
  free(p);
  measure_unregister_user();
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_quad_verdicts),
    cmocka_unit_test(test_lot_identical),
    cmocka_unit_test(test_reflip_identical),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
