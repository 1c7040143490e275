/*
** test_lot_sweep.c: the sweepline algorithm (lot --algorithm sweep).
**
** Its Delaunay triangulation is checked three ways, none of which shares
** code with it: against the incremental and the flip algorithms as sets of
** triangles (on cocircular sites too: the tie-break is lot's), by lot_check
** (structure, Euler's count, the exact empty-circle test on every interior
** edge), and by brute force for small sets (every triangle anticlockwise,
** its circumcircle empty of every site by the exact incircle test, and
** T = 2n - h - 2).  Inputs: every sampler of lot, cocircular and collinear
** sets, columns of equal x, duplicates, tiny and huge coordinates.
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

#include "lot.h"
#include "rule.h"
#include "sampler.h"
#include "testutil.h"

typedef struct ts_result {
  uint32_t *tri;
  size_t ntri, hull, dups;
  uint64_t flips;
} ts_result;

/* Build DT of p with algorithm a; the sorted triangles.  Fails the test
** on an error. */
static ts_result ts_build(const geom_point *p, size_t n, lot_algorithm a) {
  rule r = rule_delaunay();
  lot_options o;
  lot_options_init(&o, &r);
  o.algorithm = a;
  lot *L;
  char err[256];
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) fail_msg("lot_build: %s", err);
  const lot_stats *st = lot_get_stats(L);
  ts_result res = {malloc(3 * (st->triangles + 1) * sizeof *res.tri), st->triangles, st->hull,
                   st->duplicates, st->flips};
  assert_non_null(res.tri);
  lot_get_triangles(L, res.tri);
  lot_free(L);
  return res;
}

/* lot_check on the sweep's triangles: a valid triangulation, locally Delaunay. */
static void ts_check(const geom_point *p, size_t n, const ts_result *s) {
  rule r = rule_delaunay();
  lot_check_result c;
  assert_int_equal(lot_check(p, n, s->tri, s->ntri, &r, &c), 0);
  assert_true(c.valid);
  assert_int_equal(c.not_optimal, 0);
}

/* Brute force: anticlockwise triangles, empty circumcircles (exact), Euler. */
static void ts_brute(const geom_point *p, size_t n, const ts_result *s) {
  for (size_t t = 0; t < s->ntri; t++) {
    geom_point a = p[s->tri[3 * t]], b = p[s->tri[3 * t + 1]], c = p[s->tri[3 * t + 2]];
    assert_int_equal(geom_orient(a, b, c), 1);
    for (size_t k = 0; k < n; k++)
      if (geom_incircle(a, b, c, p[k]) > 0) fail_msg("triangle %zu: site %zu inside", t, k);
  }
  assert_int_equal(s->ntri, 2 * (n - s->dups) - s->hull - 2);
}

/* sweep == incremental == flip as sets of triangles, plus the checks.  Ties
** (cocircular sites) are settled by lot's tie-break, the same for all three;
** the sweep's pass of flips after it (lot.c, lot_flip_all) flips only tied
** edges, so where the Delaunay triangulation is unique (`unique`) it flips
** nothing. */
static void ts_agree(const geom_point *p, size_t n, int unique) {
  ts_result s = ts_build(p, n, LOT_SWEEP);
  ts_check(p, n, &s);
  if (n <= 600) ts_brute(p, n, &s);
  if (unique) assert_int_equal(s.flips, 0);
  for (int a = 0; a < 2; a++) {
    ts_result o = ts_build(p, n, a == 0 ? LOT_INCREMENTAL : LOT_FLIP);
    assert_int_equal(o.ntri, s.ntri);
    assert_memory_equal(o.tri, s.tri, 3 * s.ntri * sizeof *s.tri);
    free(o.tri);
  }
  free(s.tri);
}

static void test_samplers(void **state) {
  (void)state;
  static const size_t ns[] = {3, 4, 5, 10, 57, 300, 5000};
  for (int k = 0; k < SAMPLER_POINTS_COUNT; k++)
    for (size_t i = 0; i < sizeof ns / sizeof *ns; i++)
      for (uint64_t seed = 1; seed <= (uint64_t)testutil_reps(3); seed++) {
        geom_point *p = malloc(ns[i] * sizeof *p);
        assert_non_null(p);
        sampler_points((sampler_points_kind)k, seed, ns[i], p);
        /* grid: every unit square is cocircular; circle: nearly so, and
        ** exactly where rounding puts four sites on one circle; lines:
        ** integer sites, four of them now and then on one circle */
        ts_agree(p, ns[i], k != SAMPLER_GRID && k != SAMPLER_CIRCLE && k != SAMPLER_LINES);
        free(p);
      }
}

/* Random sets on a 5 x 5 integer grid: collinear and cocircular sites,
** duplicates, columns of equal x everywhere. */
static void test_small_grids(void **state) {
  (void)state;
  testutil_rng g = {12345};
  for (int trial = 0; trial < 3000; trial++) {
    size_t n = 3 + testutil_next(&g) % 12;
    geom_point p[16];
    for (size_t i = 0; i < n; i++)
      p[i] = (geom_point){(double)(testutil_next(&g) % 5), (double)(testutil_next(&g) % 5)};
    int ok = 0;   /* skip all-collinear sets (the error is tested below) */
    for (size_t i = 2; i < n && !ok; i++) ok = geom_orient(p[0], p[1], p[i]) != 0;
    for (size_t i = 1; i < n && !ok; i++)
      for (size_t j = i + 1; j < n && !ok; j++) ok = geom_orient(p[0], p[i], p[j]) != 0;
    if (ok) ts_agree(p, n, 0);
  }
}

static void test_adversarial(void **state) {
  (void)state;
  /* two columns; a column and a point; equal x everywhere but one */
  geom_point a[20];
  for (int i = 0; i < 10; i++) {
    a[i] = (geom_point){0, i * 0.37};
    a[10 + i] = (geom_point){1, i * 0.41 + 0.05};
  }
  ts_agree(a, 20, 1);
  geom_point b[] = {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 4}, {-1, 2.5}};
  ts_agree(b, 6, 1);
  geom_point c[] = {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 2.5}};
  ts_agree(c, 6, 1);
  /* a horizontal line and a point; collinear hull edges on every side */
  geom_point d[] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {1.5, 1}};
  ts_agree(d, 5, 1);
  geom_point e[] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}, {0.7, 1.1}};
  ts_agree(e, 9, 0);
  /* twelve exactly cocircular sites: x^2 + y^2 = 25 */
  geom_point f[] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3},
                    {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  ts_agree(f, 12, 0);
  /* three points, either orientation */
  geom_point g[] = {{0, 0}, {0, 1}, {1, 0}};
  ts_agree(g, 3, 1);
}

/* Tiny and huge coordinates inside the contract (1e-30 .. 1e30), and a
** set mixing both (exact fallbacks all over). */
static void test_scales(void **state) {
  (void)state;
  const double sc[] = {1e-30, 1e-20, 1e20, 1e29};   /* the grid's coordinates reach 9 sc */
  geom_point p[400];
  for (size_t s = 0; s < sizeof sc / sizeof *sc; s++) {
    sampler_points(SAMPLER_UNIFORM, 7, 400, p);
    for (int i = 0; i < 400; i++)
      p[i] = (geom_point){(1 + p[i].x) * sc[s], (1 + p[i].y) * sc[s]};
    ts_agree(p, 400, 1);
    sampler_points(SAMPLER_GRID, 7, 100, p);
    for (int i = 0; i < 100; i++) p[i] = (geom_point){p[i].x * sc[s], p[i].y * sc[s]};
    ts_agree(p, 100, 0);
  }
  geom_point m[] = {{1e-30, 1e-30}, {1e30, 0}, {0, 1e30}, {1e30, 1e30}, {2e-30, 1e-30},
                    {1e-30, 3e-30}, {5e29, 5e29}, {5e29, 5e29 + 1e14}};
  ts_agree(m, 8, 0);
}

/* Duplicates are merged into the first occurrence, as the other algorithms do. */
static void test_duplicates(void **state) {
  (void)state;
  geom_point p[] = {{1, 1}, {0, 0}, {1, 1}, {2, 0}, {0, 0}, {1, 3}, {1, 1}};
  ts_result s = ts_build(p, 7, LOT_SWEEP);
  assert_int_equal(s.dups, 3);
  ts_result o = ts_build(p, 7, LOT_INCREMENTAL);
  assert_int_equal(o.ntri, s.ntri);
  assert_memory_equal(o.tri, s.tri, 3 * s.ntri * sizeof *s.tri);
  for (size_t i = 0; i < 3 * s.ntri; i++) assert_true(s.tri[i] == 0 || s.tri[i] == 1 ||
                                                      s.tri[i] == 3 || s.tri[i] == 5);
  free(s.tri);
  free(o.tri);
}

/* No triangle: the messages of the other algorithms; a rule other than DT. */
static void test_errors(void **state) {
  (void)state;
  rule r = rule_delaunay();
  lot_options o;
  lot_options_init(&o, &r);
  o.algorithm = LOT_SWEEP;
  lot *L;
  char err[256];
  geom_point col[] = {{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  assert_int_equal(lot_build(&L, col, 4, &o, err, sizeof err), -1);
  assert_non_null(strstr(err, "all 4 points are collinear"));
  geom_point vert[] = {{0, 0}, {0, 1}, {0, 2}};
  assert_int_equal(lot_build(&L, vert, 3, &o, err, sizeof err), -1);
  assert_non_null(strstr(err, "collinear"));
  geom_point eq[] = {{1, 1}, {1, 1}, {1, 1}};
  assert_int_equal(lot_build(&L, eq, 3, &o, err, sizeof err), -1);
  assert_non_null(strstr(err, "all 3 points are equal"));
  char e2[256];
  if (rule_parse("P_1", &o.r, e2, sizeof e2) != 0) fail_msg("%s", e2);
  geom_point t[] = {{0, 0}, {1, 0}, {0, 1}};
  assert_int_equal(lot_build(&L, t, 3, &o, err, sizeof err), -1);
  assert_non_null(strstr(err, "needs rule DT or ES:SHAPE"));
  assert_null(strchr(err, '\n'));
}

/* The same input gives the same mesh, run after run (and a reflip of the
** sweep's DT by DT changes nothing). */
static void test_reproducible(void **state) {
  (void)state;
  geom_point *p = malloc(20000 * sizeof *p);
  assert_non_null(p);
  sampler_points(SAMPLER_NORMAL, 3, 20000, p);
  ts_result a = ts_build(p, 20000, LOT_SWEEP), b = ts_build(p, 20000, LOT_SWEEP);
  assert_int_equal(a.ntri, b.ntri);
  assert_memory_equal(a.tri, b.tri, 3 * a.ntri * sizeof *a.tri);
  rule r = rule_delaunay();
  lot_options o;
  lot_options_init(&o, &r);
  o.algorithm = LOT_SWEEP;
  lot *L;
  char err[256];
  assert_int_equal(lot_build(&L, p, 20000, &o, err, sizeof err), 0);
  assert_int_equal(lot_reflip(L, &o), 0);
  assert_int_equal(lot_get_stats(L)->flips, 0);
  lot_free(L);
  free(a.tri);
  free(b.tri);
  free(p);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_samplers),     cmocka_unit_test(test_small_grids),
    cmocka_unit_test(test_adversarial),  cmocka_unit_test(test_scales),
    cmocka_unit_test(test_duplicates),   cmocka_unit_test(test_errors),
    cmocka_unit_test(test_reproducible),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
