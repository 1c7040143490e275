/*
** test_paradigm_counts.c: the counting layer (geom/ops.h through
** lot_options.ops and the registry's rows) against what can be proved:
**   - every algorithm that serves DT makes and deletes edges so that made
**     minus deleted is the result's edge count (a flip makes one and
**     deletes one; an insertion makes the new vertex's edges);
**   - the sweepline's events are the result's edges plus one (2.5.1: one
**     site event per site, one circle event per triangle, and n + T =
**     E + 1 for every triangulation of n sites);
**   - lot's incremental algorithm on a convex polygon inserted in boundary
**     order flips each vertex in as often as its interior degree in the
**     Delaunay triangulation of the vertices so far (5.4.3, as cpdt/'s
**     incremental algorithm: tests/test_cpdt.c);
**   - Watson's cavity of a site holds exactly the edges Lawson's insertion
**     of it flips away (or splits): in the same order the two algorithms
**     make and delete the same numbers of edges; with ghost triangles each
**     cavity is a disc of k triangles and k + 2 boundary edges, replaced by
**     k + 2 triangles, which is why made - deleted grows by 3 per interior
**     site (checked through the first item);
**   - in random order the history DAG locates in fewer steps than the walk
**     once n is large (logarithmic against a square root);
**   - every incremental variant gives the incremental row's triangles on
**     thousands of small sets from a 5 x 5 grid (ties and duplicates);
**   - counting changes nothing: the same triangles with counting on or off
**     (lot's three algorithms, DT and ES:square), and nothing counted off.
*/
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "lot.h"
#include "paradigm.h"
#include "sampler.h"
#include "testutil.h"

/* Distinct undirected edges of a triangle list. */
static int tpc_edge_cmp(const void *x, const void *y) {
  const uint64_t *a = x, *b = y;
  return (*a > *b) - (*a < *b);
}

static size_t tpc_edges(const uint32_t *tri, size_t ntri) {
  uint64_t *e = malloc((3 * ntri + 1) * sizeof *e);
  assert_non_null(e);
  for (size_t t = 0; t < ntri; t++)
    for (int k = 0; k < 3; k++) {
      uint64_t u = tri[3 * t + (size_t)k], v = tri[3 * t + (size_t)(k + 1) % 3];
      e[3 * t + (size_t)k] = u < v ? u << 32 | v : v << 32 | u;
    }
  qsort(e, 3 * ntri, sizeof *e, tpc_edge_cmp);
  size_t m = 0;
  for (size_t i = 0; i < 3 * ntri; i++) m += i == 0 || e[i] != e[i - 1];
  free(e);
  return m;
}

static paradigm_result tpc_run(const char *name, const geom_point *p, size_t n, double param) {
  rule r = rule_delaunay();
  paradigm_input in = {.p = p, .n = n, .r = &r, .problem = PARADIGM_DELAUNAY, .seed = 3,
                       .threads = 1, .param = param};
  paradigm_result res;
  char err[256];
  if (paradigm_run(paradigm_find(name), &in, &res, err, sizeof err) != 0)
    fail_msg("%s: %s", name, err);
  return res;
}

static const sampler_points_kind tpc_families[] = {SAMPLER_UNIFORM, SAMPLER_GRID,
                                                   SAMPLER_LINES, SAMPLER_DUPS,
                                                   SAMPLER_CIRCLE};

static void test_edges_made_minus_deleted(void **state) {
  (void)state;
  geom_point *p = malloc(3000 * sizeof *p);
  assert_non_null(p);
  for (size_t f = 0; f < sizeof tpc_families / sizeof tpc_families[0]; f++)
    for (size_t n = 50; n <= 3000; n *= 4) {
      sampler_points(tpc_families[f], 11 + n, n, p);
      for (size_t i = 0; i < paradigm_count(); i++) {
        const paradigm_algorithm *a = paradigm_get(i);
        if (!(a->problems & PARADIGM_DELAUNAY) || !(a->rules & PARADIGM_RULE_DT)) continue;
        paradigm_result res = tpc_run(a->name, p, n, 0);
        uint64_t made = res.ops.v[OPS_EDGES_MADE], del = res.ops.v[OPS_EDGES_DELETED];
        if (made - del != tpc_edges(res.tri, res.ntri))
          fail_msg("%s, family %zu, n %zu: made %llu - deleted %llu != %zu edges", a->name, f,
                   n, (unsigned long long)made, (unsigned long long)del,
                   tpc_edges(res.tri, res.ntri));
        assert_true(res.ops.v[OPS_PEAK_BYTES] > 0);
        paradigm_result_free(&res);
      }
    }
  free(p);
}

static void test_sweep_events(void **state) {
  (void)state;
  geom_point *p = malloc(5000 * sizeof *p);
  assert_non_null(p);
  for (size_t f = 0; f < sizeof tpc_families / sizeof tpc_families[0]; f++) {
    sampler_points(tpc_families[f], 5, 5000, p);
    paradigm_result res = tpc_run("sweep", p, 5000, 0);
    assert_int_equal(res.ops.v[OPS_EVENTS], tpc_edges(res.tri, res.ntri) + 1);
    paradigm_result_free(&res);
  }
  free(p);
}

/* Interior degree of vertex v in lot's DT of p[0..n-1]: its triangles less one. */
static uint64_t tpc_interior_degree(const geom_point *p, size_t n, uint32_t v) {
  rule r = rule_delaunay();
  lot_options o;
  lot_options_init(&o, &r);
  lot *L;
  char err[256];
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) fail_msg("%s", err);
  size_t nt = lot_get_stats(L)->triangles;
  uint32_t *tri = malloc(3 * nt * sizeof *tri);
  assert_non_null(tri);
  lot_get_triangles(L, tri);
  uint64_t d = 0;
  for (size_t t = 0; t < nt; t++)
    d += tri[3 * t] == v || tri[3 * t + 1] == v || tri[3 * t + 2] == v;
  free(tri);
  lot_free(L);
  return d - 1;
}

static void test_convex_boundary_order(void **state) {
  (void)state;
  for (uint64_t seed = 1; seed <= 20; seed++) {
    size_t n = 4 + (size_t)(seed * 13 % 90);
    geom_point *p = malloc(n * sizeof *p);
    assert_non_null(p);
    sampler_rng g;
    sampler_seed(&g, seed, 0);
    assert_int_equal(sampler_vector(&g, n, p), 0);
    uint64_t want = 0;
    for (size_t i = 3; i < n; i++) want += tpc_interior_degree(p, i + 1, (uint32_t)i);
    rule r = rule_delaunay();
    lot_options o;
    lot_options_init(&o, &r);
    o.order = LOT_ORDER_INPUT;
    ops_counts c;
    ops_clear(&c);
    lot_options_set_ops(&o, &c);
    lot *L;
    char err[256];
    if (lot_build(&L, p, n, &o, err, sizeof err) != 0) fail_msg("%s", err);
    assert_int_equal(c.v[OPS_FLIPS], want);
    assert_int_equal(c.v[OPS_FLIPS], lot_get_stats(L)->flips);
    lot_free(L);
    free(p);
  }
}

static void test_watson_is_lawson(void **state) {
  (void)state;
  geom_point *p = malloc(4000 * sizeof *p);
  assert_non_null(p);
  for (size_t f = 0; f < sizeof tpc_families / sizeof tpc_families[0]; f++) {
    sampler_points(tpc_families[f], 21, 4000, p);
    paradigm_result w = tpc_run("watson", p, 4000, 0);
    paradigm_result l = tpc_run("incremental-quaternary", p, 4000, 0);
    assert_int_equal(w.ops.v[OPS_EDGES_DELETED], l.ops.v[OPS_EDGES_DELETED]);
    assert_int_equal(w.ops.v[OPS_EDGES_MADE], l.ops.v[OPS_EDGES_MADE]);
    assert_int_equal(w.ops.v[OPS_FLIPS], 0);
    paradigm_result_free(&w);
    paradigm_result_free(&l);
  }
  free(p);
}

static void test_dag_against_walk(void **state) {
  (void)state;
  size_t n = 40000;
  geom_point *p = malloc(n * sizeof *p);
  assert_non_null(p);
  sampler_points(SAMPLER_UNIFORM, 2, n, p);
  paradigm_result d = tpc_run("incremental-dag", p, n, 0);
  paradigm_result w = tpc_run("watson", p, n, 1);   /* the same random order, walked */
  assert_int_equal(d.ntri, w.ntri);
  assert_memory_equal(d.tri, w.tri, 3 * d.ntri * sizeof *d.tri);
  assert_int_equal(d.ops.v[OPS_INCIRCLE], w.ops.v[OPS_INCIRCLE]);   /* the same cavities */
  assert_true(d.ops.v[OPS_LOCATE] < w.ops.v[OPS_LOCATE]);
  paradigm_result_free(&d);
  paradigm_result_free(&w);
  free(p);
}

/* Thousands of small sets drawn from a 5 x 5 grid (collinear and
** cocircular sites, duplicates everywhere): every incremental variant
** gives the incremental row's triangles, for DT and ES:square. */
static void test_small_degenerate_sets(void **state) {
  (void)state;
  static const char *const rows[] = {"watson", "incremental-dag", "incremental-serpentine",
                                     "incremental-spiral", "incremental-quaternary"};
  rule rs[2];
  char err[256];
  if (rule_parse("DT", &rs[0], err, sizeof err) != 0 || rule_parse("ES:square", &rs[1], err,
                                                                   sizeof err) != 0)
    fail_msg("%s", err);
  testutil_rng g = {2024};
  geom_point p[24];
  for (int trial = 0; trial < testutil_reps(3000); trial++) {
    size_t n = 3 + testutil_next(&g) % 22;
    for (size_t i = 0; i < n; i++)
      p[i] = (geom_point){(double)(testutil_next(&g) % 5), (double)(testutil_next(&g) % 5)};
    for (int ri = 0; ri < 2; ri++) {
      paradigm_input in = {.p = p, .n = n, .r = &rs[ri], .problem = PARADIGM_DELAUNAY,
                           .seed = (uint64_t)trial, .threads = 1};
      paradigm_result ref, res;
      if (paradigm_run(paradigm_find("incremental"), &in, &ref, err, sizeof err) != 0) continue;
      for (size_t k = 0; k < sizeof rows / sizeof rows[0]; k++) {
        if (paradigm_run(paradigm_find(rows[k]), &in, &res, err, sizeof err) != 0)
          fail_msg("%s, trial %d: %s", rows[k], trial, err);
        if (res.ntri != ref.ntri || memcmp(res.tri, ref.tri, 3 * ref.ntri * sizeof *ref.tri))
          fail_msg("%s differs from incremental: trial %d, %zu points, %s", rows[k], trial, n,
                   rs[ri].name);
        paradigm_result_free(&res);
      }
      paradigm_result_free(&ref);
    }
  }
}

static void test_counting_changes_nothing(void **state) {
  (void)state;
  geom_point *p = malloc(2000 * sizeof *p);
  assert_non_null(p);
  sampler_points(SAMPLER_CLUSTERED, 9, 2000, p);
  const char *rules[] = {"DT", "ES:square"};
  for (int k = 0; k < 2; k++)
    for (int alg = LOT_INCREMENTAL; alg <= LOT_SWEEP; alg++) {
      rule r;
      char err[256];
      if (rule_parse(rules[k], &r, err, sizeof err) != 0) fail_msg("%s", err);
      uint32_t *tri[2];
      size_t nt[2];
      ops_counts c[2];
      for (int on = 0; on < 2; on++) {
        lot_options o;
        lot_options_init(&o, &r);
        o.algorithm = (lot_algorithm)alg;
        ops_clear(&c[on]);
        if (on) o.ops = &c[on];
        lot *L;
        if (lot_build(&L, p, 2000, &o, err, sizeof err) != 0) fail_msg("%s", err);
        nt[on] = lot_get_stats(L)->triangles;
        tri[on] = malloc(3 * nt[on] * sizeof *tri[on]);
        assert_non_null(tri[on]);
        lot_get_triangles(L, tri[on]);
        lot_free(L);
      }
      assert_int_equal(nt[0], nt[1]);
      assert_memory_equal(tri[0], tri[1], 3 * nt[0] * sizeof *tri[0]);
      for (int i = 0; i < OPS_COUNT; i++) assert_int_equal(c[0].v[i], 0);
      assert_true(c[1].v[OPS_ORIENT] > 0);
      free(tri[0]), free(tri[1]);
    }
  free(p);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_edges_made_minus_deleted),
    cmocka_unit_test(test_sweep_events),
    cmocka_unit_test(test_convex_boundary_order),
    cmocka_unit_test(test_watson_is_lawson),
    cmocka_unit_test(test_dag_against_walk),
    cmocka_unit_test(test_small_degenerate_sets),
    cmocka_unit_test(test_counting_changes_nothing),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
