/*
** test_paradigm.c: the registry of chapter 2's algorithms (paradigms/) and
** its runner: names are unique and found; a refused problem or rule gets its
** one-line reason; every row gives exactly lot's incremental triangles on
** random, grid, cocircular, collinear-heavy and duplicate-heavy sets, for DT
** and two empty-shape rules; the in-shape test with its tie-break agrees
** with lot's choice of diagonal on every convex quadrilateral of a small
** grid (where ties abound); the counting layer's names round-trip; the
** canonical order's bucket sort is qsort's order.
*/
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "paradigm_internal.h"
#include "lot.h"
#include "testutil.h"

static rule tp_rule(const char *name) {
  rule r;
  char err[256];
  if (rule_parse(name, &r, err, sizeof err) != 0) fail_msg("%s", err);
  return r;
}

static void test_registry(void **state) {
  (void)state;
  assert_true(paradigm_count() >= 3);
  for (size_t i = 0; i < paradigm_count(); i++) {
    const paradigm_algorithm *a = paradigm_get(i);
    assert_non_null(a->run);
    assert_true(a->problems != 0);
    assert_ptr_equal(paradigm_find(a->name), a);
    for (size_t j = 0; j < i; j++) assert_string_not_equal(paradigm_get(j)->name, a->name);
  }
  assert_null(paradigm_find("no-such-algorithm"));
  assert_null(paradigm_get(paradigm_count()));
  for (int k = 0; k < OPS_COUNT; k++) assert_int_equal(ops_find(ops_name(k)), k);
  assert_null(ops_name(OPS_COUNT));
  assert_int_equal(ops_find("nothing"), -1);
}

/* Point sets that stress ties and degeneracy (n at most 400). */
static size_t tp_points(int family, testutil_rng *g, geom_point *p) {
  size_t n = 0;
  switch (family) {
    case 0:   /* uniform */
      for (; n < 300; n++) p[n] = (geom_point){testutil_uniform(g), testutil_uniform(g)};
      break;
    case 1:   /* a 13 x 13 grid: every unit square cocircular */
      for (int i = 0; i < 13; i++)
        for (int j = 0; j < 13; j++) p[n++] = (geom_point){i, j};
      break;
    case 2:   /* integer points on circles x^2 + y^2 = 25, 65 (many cocircular) */
      for (int x = -8; x <= 8; x++)
        for (int y = -8; y <= 8; y++)
          if (x * x + y * y == 25 || x * x + y * y == 65) p[n++] = (geom_point){x, y};
      break;
    case 3:   /* three lines of 40 collinear points, and a few off them */
      for (int i = 0; i < 40; i++) {
        p[n++] = (geom_point){i, 0};
        p[n++] = (geom_point){i, i};
        p[n++] = (geom_point){0, i + 1};
      }
      for (int i = 0; i < 10; i++) p[n++] = (geom_point){40 * testutil_uniform(g), 17};
      break;
    default:  /* 300 draws from a 7 x 7 grid: duplicates */
      for (; n < 300; n++)
        p[n] = (geom_point){(double)(testutil_next(g) % 7), (double)(testutil_next(g) % 7)};
      break;
  }
  return n;
}

static void test_rows_agree(void **state) {
  (void)state;
  const char *rules[] = {"DT", "ES:square", "ES:hexagon"};
  geom_point *p = malloc(400 * sizeof *p);
  assert_non_null(p);
  testutil_rng g = {12345};
  char err[256];
  for (int f = 0; f < 5; f++) {
    size_t n = tp_points(f, &g, p);
    for (size_t ri = 0; ri < sizeof rules / sizeof rules[0]; ri++) {
      rule r = tp_rule(rules[ri]);
      paradigm_input in = {.p = p, .n = n, .r = &r, .problem = PARADIGM_DELAUNAY, .seed = 7,
                           .threads = 1};
      paradigm_result ref;
      if (paradigm_run(paradigm_find("incremental"), &in, &ref, err, sizeof err) != 0)
        fail_msg("family %d %s: %s", f, rules[ri], err);
      for (size_t i = 0; i < paradigm_count(); i++) {
        const paradigm_algorithm *a = paradigm_get(i);
        if (!(a->problems & PARADIGM_DELAUNAY)) continue;
        if (!(a->rules & (rule_is_shape(&r) ? PARADIGM_RULE_ES : PARADIGM_RULE_DT))) continue;
        paradigm_result res;
        if (paradigm_run(a, &in, &res, err, sizeof err) != 0)
          fail_msg("%s, family %d %s: %s", a->name, f, rules[ri], err);
        assert_int_equal(res.ntri, ref.ntri);
        if (memcmp(res.tri, ref.tri, 3 * ref.ntri * sizeof *ref.tri) != 0)
          fail_msg("%s differs from incremental: family %d, %s", a->name, f, rules[ri]);
        paradigm_result_free(&res);
      }
      paradigm_result_free(&ref);
    }
  }
  free(p);
}

/* lot's diagonal of the convex quadrilateral q: 1 when it holds q0 q2. */
static int tp_lot_ac(const geom_point q[4], const rule *r) {
  lot_options o;
  lot_options_init(&o, r);
  lot *L;
  char err[256];
  if (lot_build(&L, q, 4, &o, err, sizeof err) != 0) fail_msg("%s", err);
  uint32_t tri[6];
  assert_int_equal(lot_get_stats(L)->triangles, 2);
  lot_get_triangles(L, tri);
  lot_free(L);
  int has0 = 0, has2 = 0;
  for (int k = 0; k < 3; k++) has0 |= tri[k] == 0, has2 |= tri[k] == 2;
  return has0 && has2;
}

static void test_inshape_tiebreak(void **state) {
  (void)state;
  const char *rules[] = {"DT", "ES:square", "ES:diamond"};
  testutil_rng g = {99};
  int tied = 0;
  for (int trial = 0; trial < 3000; trial++) {
    geom_point q[4];
    for (int k = 0; k < 4; k++)
      q[k] = (geom_point){(double)(testutil_next(&g) % 4), (double)(testutil_next(&g) % 4)};
    int convex = 1;
    for (int k = 0; k < 4; k++) convex &= geom_orient(q[k], q[(k + 1) % 4], q[(k + 2) % 4]) > 0;
    if (!convex) continue;
    tied += geom_incircle(q[0], q[1], q[2], q[3]) == 0;
    for (size_t ri = 0; ri < 3; ri++) {
      rule r = tp_rule(rules[ri]);
      int s = paradigm_inshape(&r, NULL, q[0], q[1], q[2], q[3]);
      assert_true(s != 0);
      assert_int_equal(s < 0, tp_lot_ac(q, &r));   /* d outside: keep q0 q2 */
    }
  }
  assert_true(tied > 20);
}

static void test_refusals(void **state) {
  (void)state;
  geom_point p[4] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}};
  rule dt = tp_rule("DT"), r1 = tp_rule("R_1");
  char err[256];
  paradigm_result res;
  paradigm_input in = {.p = p, .n = 4, .r = &dt, .problem = PARADIGM_DELAUNAY, .threads = 1};
  assert_int_equal(paradigm_run(paradigm_find("incremental"), &in, &res, err, sizeof err), -1);
  assert_non_null(strstr(err, "collinear"));
  assert_null(strchr(err, '\n'));
  in.r = &r1;
  assert_int_equal(paradigm_run(paradigm_find("sweep"), &in, &res, err, sizeof err), -1);
  assert_non_null(strstr(err, "R_1"));
  in.r = &dt;
  in.problem = PARADIGM_POLYGON;
  assert_int_equal(paradigm_run(paradigm_find("sweep"), &in, &res, err, sizeof err), -1);
  assert_non_null(strstr(err, "polygon"));
  p[3].y = 1e40;
  in.problem = PARADIGM_DELAUNAY;
  assert_int_equal(paradigm_run(paradigm_find("incremental"), &in, &res, err, sizeof err), -1);
  assert_non_null(strstr(err, "point 4"));
}

/* The canonical order, by the bucket sort, is the lexicographic order of
** the rotated triangles: checked against qsort with a comparison, on
** indices up to n (the bucket sort), up to 5 (buckets past 16 triangles,
** repeated triangles) and up to 2^31 (sparse: qsort), and on small arrays
** (qsort). */
static int tp_cmp(const void *x, const void *y) {
  const uint32_t *s = x, *t = y;
  for (int i = 0; i < 3; i++)
    if (s[i] != t[i]) return s[i] < t[i] ? -1 : 1;
  return 0;
}

static void test_canonical(void **state) {
  (void)state;
  testutil_rng g = {17};
  static const uint32_t range[] = {1u << 31, 0, 5};   /* 0: n */
  for (size_t r = 0; r < sizeof range / sizeof *range; r++)
    for (size_t n = 1; n < 40000; n = 3 * n + 7) {
      uint32_t *tri = malloc(3 * n * sizeof *tri), *want = malloc(3 * n * sizeof *want);
      assert_true(tri != NULL && want != NULL);
      for (size_t t = 0; t < n; t++) {
        uint32_t *v = tri + 3 * t;
        do {
          for (int i = 0; i < 3; i++)
            v[i] = (uint32_t)(testutil_next(&g) % (range[r] ? range[r] : n + 3));
        } while (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]);
        int k = v[0] < v[1] && v[0] < v[2] ? 0 : v[1] < v[2] ? 1 : 2;
        for (int i = 0; i < 3; i++) want[3 * t + (size_t)i] = v[(k + i) % 3];
      }
      qsort(want, n, 3 * sizeof *want, tp_cmp);
      paradigm_canonical(tri, n);
      assert_memory_equal(tri, want, 3 * n * sizeof *tri);
      free(tri), free(want);
    }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_registry),
    cmocka_unit_test(test_rows_agree),
    cmocka_unit_test(test_inshape_tiebreak),
    cmocka_unit_test(test_refusals),
    cmocka_unit_test(test_canonical),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
