/*
** test_paradigm_es.c: the in-shape algorithms of chapter 2 under every
** empty-shape rule ES:SHAPE: divide and conquer (2.6.6: both cuts),
** Watson's cavity insertion and the history DAG (2.3.6) give exactly lot's
** incremental ES triangulation, the oracle of the registry, on thousands
** of small sets (uniform, grid subsets with duplicates, full grids, points
** on a circle, collinear runs, integer points on two circles) for every
** shape of the registry and a few more (regular polygons, a skew polygon,
** ellipses); on larger sets too, one and two threads giving the same
** triangles and counts; the counts obey Euler's relation; and the rows
** refuse constraints and polygons, saying why.
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

static const char *const te_rows[] = {"dc-vertical", "dc-alternating", "watson",
                                      "incremental-dag"};
#define TE_ROWS (sizeof te_rows / sizeof te_rows[0])

/* The named shapes of docs/emptyshape.md, regular polygons with few and
** many sides, a skew polygon, axis-aligned and turned ellipses. */
static const char *const te_shapes[] = {
  "ES:square", "ES:diamond", "ES:triangle", "ES:hexagon", "ES:octagon", "ES:ngon:5",
  "ES:ngon:7", "ES:ngon:40", "ES:poly:0 0;3 -1;4 2;1 3", "ES:ellipse:2 1",
  "ES:ellipse:3 1 0.5"};
#define TE_SHAPES (sizeof te_shapes / sizeof te_shapes[0])

static rule te_rule(const char *spec) {
  rule r;
  char err[256];
  if (rule_parse(spec, &r, err, sizeof err) != 0) fail_msg("%s: %s", spec, err);
  return r;
}

/* Row name on p under r; 0 and the result, or -1 when refused (the set is
** collinear or has fewer than three distinct sites). */
static int te_run(const char *name, const rule *r, const geom_point *p, size_t n, int threads,
                  paradigm_result *res) {
  paradigm_input in = {.p = p, .n = n, .r = r, .problem = PARADIGM_DELAUNAY, .seed = 5,
                       .threads = threads};
  char err[256];
  return paradigm_run(paradigm_find(name), &in, res, err, sizeof err);
}

static void te_same(const paradigm_result *a, const paradigm_result *b, const char *what) {
  testutil_same_tri(a->tri, a->ntri, b->tri, b->ntri, what);
}

/* n sites of the larger sets' family f: uniform, a grid 113 wide, nearly
** collinear (300 x 5 integer draws), draws from a 40 x 40 grid. */
static void te_points(int f, size_t n, testutil_rng *g, geom_point *p) {
  for (size_t i = 0; i < n; i++) {
    double a = (double)(testutil_next(g) % 300), b = (double)(testutil_next(g) % 40);
    p[i] = f == 0 ? (geom_point){testutil_uniform(g), testutil_uniform(g)}
         : f == 1 ? (geom_point){(double)(i % 113), (double)(i / 113)}
         : f == 2 ? (geom_point){a, (double)(testutil_next(g) % 5)}
                  : (geom_point){fmod(a, 40), b};
  }
}

/* Euler: made - deleted = the result's edges = n - 1 + triangles. */
static void te_euler(const paradigm_result *r) {
  uint64_t live = r->ops.v[OPS_EDGES_MADE] - r->ops.v[OPS_EDGES_DELETED];
  assert_int_equal(live, r->distinct - 1 + r->ntri);
  assert_int_equal(r->ops.v[OPS_INCIRCLE], 0);   /* the rule's test, never the circle's */
}

/* Every row against lot's incremental ES triangulation on small sets of
** every family, the shapes in turn: sets of 3 to 40 sites, then 40 to 400
** (where divide and conquer's horizontal cuts start). */
static void test_small_sets(void **state) {
  (void)state;
  geom_point p[400];
  testutil_rng g = {37};
  int compared = 0;
  for (int trial = 0; trial < testutil_reps(2200); trial++) {
    int f = trial % 6;
    const char *spec = te_shapes[(trial / 6) % TE_SHAPES];
    rule r = te_rule(spec);
    size_t n = testutil_family(f, trial < 2000 ? 3 + testutil_next(&g) % 38
                                               : 40 + testutil_next(&g) % 361, &g, p);
    paradigm_result ref, res;
    if (te_run("incremental", &r, p, n, 1, &ref) != 0) continue;   /* collinear */
    for (size_t a = 0; a < TE_ROWS; a++) {
      char what[160];
      snprintf(what, sizeof what, "%s, %s, family %d, n %zu, trial %d", te_rows[a], spec, f,
               n, trial);
      if (te_run(te_rows[a], &r, p, n, 1 + trial % 2, &res) != 0) fail_msg("%s: refused", what);
      te_same(&ref, &res, what);
      te_euler(&res);
      paradigm_result_free(&res);
      compared++;
    }
    paradigm_result_free(&ref);
  }
  assert_true(compared > testutil_reps(2000) * 3);
}

/* Larger sets, the shapes of the registry with the most special cases
** (square: sites on a side's line; triangle and hexagon: rounding shapes
** near the hull) and an ellipse: uniform, a grid and nearly collinear
** sites.  Divide and conquer with one thread and two: the same triangles
** and the same counts (two threads start at 4,096 sites). */
static void test_large(void **state) {
  (void)state;
  static const char *const shapes[] = {"ES:square", "ES:triangle", "ES:hexagon",
                                       "ES:ellipse:3 1 0.5"};
  size_t n = testutil_reps(4) == 4 ? 12000 : 6000;   /* sanitizers: fewer, still threaded */
  geom_point *p = malloc(n * sizeof *p);
  assert_non_null(p);
  testutil_rng g = {91};
  for (int f = 0; f < 3; f++) {
    te_points(f, n, &g, p);
    for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; k++) {
      rule r = te_rule(shapes[k]);
      paradigm_result ref;
      assert_int_equal(te_run("incremental", &r, p, n, 1, &ref), 0);
      for (size_t a = 0; a < TE_ROWS; a++) {
        char what[160];
        snprintf(what, sizeof what, "%s, %s, family %d", te_rows[a], shapes[k], f);
        paradigm_result one, two;
        assert_int_equal(te_run(te_rows[a], &r, p, n, 1, &one), 0);
        te_same(&ref, &one, what);
        te_euler(&one);
        assert_true(one.ops.v[OPS_INSHAPE] > 0);
        if (a < 2) {
          assert_int_equal(te_run(te_rows[a], &r, p, n, 2, &two), 0);
          te_same(&one, &two, what);
          for (int c = 0; c < OPS_COUNT; c++)
            if (c != OPS_EXACT) assert_int_equal(one.ops.v[c], two.ops.v[c]);
          paradigm_result_free(&two);
        }
        paradigm_result_free(&one);
      }
      paradigm_result_free(&ref);
    }
  }
  free(p);
}

/* Watson's cavity holds exactly the edges Lawson's insertion flips or
** splits when the sites come in the same order (the quaternary buckets),
** under an empty-shape rule as under DT: the same edges made and deleted,
** and no flip.  Every shape of te_shapes, 3,000 uniform sites and a grid
** with duplicates. */
static void test_watson_is_lawson(void **state) {
  (void)state;
  size_t n = 3000;
  geom_point *p = malloc(n * sizeof *p);
  assert_non_null(p);
  testutil_rng g = {58};
  for (int f = 0; f < 4; f += 3) {
    te_points(f, n, &g, p);
    for (size_t k = 0; k < TE_SHAPES; k++) {
      rule r = te_rule(te_shapes[k]);
      paradigm_result w, l;
      assert_int_equal(te_run("watson", &r, p, n, 1, &w), 0);
      assert_int_equal(te_run("incremental-quaternary", &r, p, n, 1, &l), 0);
      te_same(&l, &w, te_shapes[k]);
      assert_int_equal(w.ops.v[OPS_EDGES_DELETED], l.ops.v[OPS_EDGES_DELETED]);
      assert_int_equal(w.ops.v[OPS_EDGES_MADE], l.ops.v[OPS_EDGES_MADE]);
      assert_int_equal(w.ops.v[OPS_FLIPS], 0);
      paradigm_result_free(&w), paradigm_result_free(&l);
    }
  }
  free(p);
}

/* What the four rows do not serve, under DT and ES alike: constraints and
** simple polygons, refused on one line that says why and where to go. */
static void test_refusals(void **state) {
  (void)state;
  geom_point p[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  uint32_t seg[2] = {0, 2};
  rule rs[2] = {rule_delaunay(), te_rule("ES:hexagon")};
  const paradigm_problem pb[2] = {PARADIGM_CONSTRAINED, PARADIGM_POLYGON};
  char err[512];
  for (size_t a = 0; a < TE_ROWS; a++)
    for (int k = 0; k < 4; k++) {
      paradigm_input in = {.p = p, .n = 4, .r = &rs[k % 2], .problem = pb[k / 2],
                           .segments = seg, .nsegments = k / 2 ? 0 : 1, .threads = 1};
      paradigm_result res;
      assert_int_equal(paradigm_run(paradigm_find(te_rows[a]), &in, &res, err, sizeof err), -1);
      assert_null(strchr(err, '\n'));   /* one line */
      assert_non_null(strstr(err, "constraints"));
      assert_non_null(strstr(err, a < 2 ? "dc-constrained" : "stop at segments"));
    }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_small_sets),
    cmocka_unit_test(test_large),
    cmocka_unit_test(test_watson_is_lawson),
    cmocka_unit_test(test_refusals),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
