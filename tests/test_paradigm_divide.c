/*
** test_paradigm_divide.c: divide and conquer (paradigms/divide.c) against
** lot's incremental algorithm, the oracle of the registry: thousands of
** small sets (3 to 400 sites; uniform, grid subsets, cocircular, duplicates,
** collinear runs) give exactly its triangles, with vertical and with
** alternating cuts; one thread and two give the same triangles and the same
** counts; the counts obey Euler's relation (every merge adds and deletes
** edges so that edges made - edges deleted = 3n - 3 - h, h the sites on the
** hull); paradigm_divide's own array, before the runner's canonical
** order, is the same on one thread and two; the rows refuse the
** constrained problem with its reason, and a set too large for the mesh
** with one line.  The empty-shape rules: tests/test_paradigm_es.c.
*/
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "paradigm_internal.h"
#include "lot.h"
#include "testutil.h"

static const char *const td_rows[2] = {"dc-vertical", "dc-alternating"};

/* Run row a on p; 0 and the result, or -1 when the set is refused (all
** collinear, too few distinct). */
static int td_run(const char *name, const geom_point *p, size_t n, int threads,
                  paradigm_result *res) {
  rule dt = rule_delaunay();
  paradigm_input in = {.p = p, .n = n, .r = &dt, .problem = PARADIGM_DELAUNAY, .seed = 3,
                       .threads = threads};
  char err[256];
  return paradigm_run(paradigm_find(name), &in, res, err, sizeof err);
}

static void td_same(const paradigm_result *a, const paradigm_result *b, const char *what) {
  testutil_same_tri(a->tri, a->ntri, b->tri, b->ntri, what);
}

/* Euler: a triangulation of n sites, h of them on the hull, has 3n - 3 - h
** edges and 2n - 2 - h triangles, so made - deleted = n - 1 + triangles. */
static void td_euler(const paradigm_result *r) {
  uint64_t live = r->ops.v[OPS_EDGES_MADE] - r->ops.v[OPS_EDGES_DELETED];
  assert_int_equal(live, r->distinct - 1 + r->ntri);
  /* Every deletion follows an in-circle test that found a site inside. */
  assert_true(r->ops.v[OPS_INCIRCLE] >= r->ops.v[OPS_EDGES_DELETED]);
  assert_true(r->ops.v[OPS_ORIENT] > 0);
  assert_true(r->ops.v[OPS_PEAK_BYTES] >= 72 * r->distinct);
}

/* 3,000 sets of 3 to 40 sites, then 300 of 40 to 400 (where the
** horizontal cuts start: pieces of 24 sites and more). */
static void test_small_sets(void **state) {
  (void)state;
  geom_point p[400];
  testutil_rng g = {2026};
  int compared = 0;
  for (int trial = 0; trial < testutil_reps(3300); trial++) {
    int f = trial % 6;
    size_t n = testutil_family(f, trial < 3000 ? 3 + testutil_next(&g) % 38
                                         : 40 + testutil_next(&g) % 361, &g, p);
    paradigm_result ref, res;
    if (td_run("incremental", p, n, 1, &ref) != 0) continue;   /* collinear: refused */
    for (int a = 0; a < 2; a++) {
      assert_int_equal(td_run(td_rows[a], p, n, 1 + trial % 2, &res), 0);
      char what[96];
      snprintf(what, sizeof what, "%s, family %d, n %zu, trial %d", td_rows[a], f, n, trial);
      td_same(&ref, &res, what);
      td_euler(&res);
      paradigm_result_free(&res);
      compared++;
    }
    paradigm_result_free(&ref);
  }
  assert_true(compared > testutil_reps(3000));
}

/* Larger sets, one and two threads: the same triangles and the same counts. */
static void test_threads(void **state) {
  (void)state;
  size_t n = 30000;
  geom_point *p = malloc(n * sizeof *p);
  assert_non_null(p);
  testutil_rng g = {77};
  for (int f = 0; f < 3; f++) {
    for (size_t i = 0; i < n; i++)
      p[i] = f == 0 ? (geom_point){testutil_uniform(&g), testutil_uniform(&g)}
           : f == 1 ? (geom_point){(double)(i % 173), (double)(i / 173)}
                    : (geom_point){(double)(testutil_next(&g) % 300),
                                   (double)(testutil_next(&g) % 5)};
    paradigm_result ref;
    assert_int_equal(td_run("incremental", p, n, 1, &ref), 0);
    for (int a = 0; a < 2; a++) {
      paradigm_result one, two;
      assert_int_equal(td_run(td_rows[a], p, n, 1, &one), 0);
      assert_int_equal(td_run(td_rows[a], p, n, 2, &two), 0);
      td_same(&ref, &one, td_rows[a]);
      td_same(&one, &two, td_rows[a]);
      for (int k = 0; k < OPS_COUNT; k++)
        if (k != OPS_EXACT) assert_int_equal(one.ops.v[k], two.ops.v[k]);
      td_euler(&one);
      paradigm_result_free(&one), paradigm_result_free(&two);
    }
    paradigm_result_free(&ref);
  }
  free(p);
}

/* paradigm_divide itself, before the runner's canonical order: one thread
** and two write the same array, triangle for triangle, of 2n - 2 - h
** triangles (they are written into the sites' block, cut to size: a
** convex set, every site on the hull, leaves the most of it unused). */
static void test_raw_threads(void **state) {
  (void)state;
  size_t n = 20000;
  geom_point *p = malloc(n * sizeof *p);
  assert_non_null(p);
  testutil_rng g = {91};
  rule dt = rule_delaunay();
  char err[256];
  for (int f = 0; f < 2; f++) {
    for (size_t i = 0; i < n; i++)   /* uniform; convex: the parabola y = x^2 */
      p[i] = f == 0 ? (geom_point){testutil_uniform(&g), testutil_uniform(&g)}
                    : (geom_point){(double)i - 10000, ((double)i - 10000) * ((double)i - 10000)};
    paradigm_output out[2] = {{0}, {0}};
    for (int t = 0; t < 2; t++) {
      paradigm_input in = {.p = p, .n = n, .r = &dt, .problem = PARADIGM_DELAUNAY,
                           .threads = 1 + t};
      assert_int_equal(paradigm_divide(&in, 1, NULL, &out[t], err, sizeof err), 0);
    }
    if (f == 1) assert_int_equal(out[0].ntri, n - 2);   /* h = n */
    assert_true(out[0].ntri >= n - 2 && out[0].ntri <= 2 * n - 5);
    assert_int_equal(out[0].ntri, out[1].ntri);
    assert_memory_equal(out[0].tri, out[1].tri, 3 * out[0].ntri * sizeof *out[0].tri);
    for (size_t k = 0; k < 3 * out[0].ntri; k++) assert_true(out[0].tri[k] < n);
    free(out[0].tri), free(out[1].tri);
  }
  free(p);
}

static void test_refusals(void **state) {
  (void)state;
  geom_point p[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  uint32_t seg[2] = {0, 3};
  rule dt = rule_delaunay();
  char err[512];
  paradigm_input in = {.p = p, .n = 4, .r = &dt, .threads = 1};
  paradigm_result res;
  for (int a = 0; a < 2; a++) {
    const paradigm_algorithm *alg = paradigm_find(td_rows[a]);
    in.problem = PARADIGM_CONSTRAINED, in.segments = seg, in.nsegments = 1;
    assert_int_equal(paradigm_run(alg, &in, &res, err, sizeof err), -1);
    assert_non_null(strstr(err, "2.6.2"));
    assert_null(strchr(err, '\n'));
  }
  /* Too many sites for 32-bit half-edges: refused before anything is read. */
  paradigm_input big = {.p = p, .n = (size_t)1 << 30, .r = &dt, .threads = 1};
  paradigm_output out = {0};
  assert_int_equal(paradigm_divide(&big, 1, NULL, &out, err, sizeof err), -1);
  assert_non_null(strstr(err, "at most"));
  assert_null(strchr(err, '\n'));
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_small_sets),
    cmocka_unit_test(test_threads),
    cmocka_unit_test(test_raw_threads),
    cmocka_unit_test(test_refusals),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
