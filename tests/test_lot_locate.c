/*
** test_lot_locate.c: the public point location and neighbours of lot.h
** (lot_locate, lot/locate.c; lot_get_neighbors, lot/lot.c) against oracles
** that share nothing with them.
**
** Location: for every query the smallest triangle whose closure holds it,
** found by scanning every triangle with the exact orientation test
** (geom_orient, whose filter is tested against exact arithmetic in
** test_geom.c), -1 when none does or the query is not finite.  lot_locate promises exactly that
** answer (on an edge the smaller of two triangles, on a vertex the
** smallest around it), walking or scanning, so both are compared with it.
** Inputs: uniform points under DT and under P_1 (a LOT that is no Delaunay
** triangulation, where a walk in a fixed order can cycle), the integer grid
** (every unit square cocircular: ties everywhere), a collinear-heavy set
** (long rows of points on a few lines, so that queries on those lines sit
** on many edges at once), and a square with a square hole (triangles that
** do not cover their convex hull: the walk's way out needs the scan).
** Queries: random points over and beyond the bounding box, every vertex,
** edge midpoints, points on the lines through the vertices, NaN and
** infinities.
**
** Neighbours: lot_get_neighbors, read off the mesh, equals lot_neighbors,
** made from the triangle list alone, on every input.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lot.h"
#include "predicates.h"
#include "rule.h"
#include "sampler.h"
#include "testutil.h"

/* A triangulation as lot_locate takes it: points, triangles, neighbours. */
typedef struct tll_mesh {
  const geom_point *p;
  size_t n, ntri;
  uint32_t *tri;
  int32_t *nb;
  int convex;            /* the triangles cover their convex hull */
} tll_mesh;

/* The oracle: the smallest triangle whose closure holds q, or -1.  O(ntri). */
static int32_t tll_oracle(const tll_mesh *m, geom_point q) {
  if (!(isfinite(q.x) && isfinite(q.y))) return -1;
  for (size_t t = 0; t < m->ntri; t++) {
    const uint32_t *v = m->tri + 3 * t;
    if (geom_orient(m->p[v[0]], m->p[v[1]], q) >= 0 && geom_orient(m->p[v[1]], m->p[v[2]], q) >= 0
        && geom_orient(m->p[v[2]], m->p[v[0]], q) >= 0)
      return (int32_t)t;
  }
  return -1;
}

/* Build LOT(rule) of p (with segments and holes when given) into *m, and
** check lot_get_neighbors against lot_neighbors. */
static lot *tll_build(const geom_point *p, size_t n, const char *rule_name,
                      const uint32_t *seg, size_t nseg, const geom_point *holes, size_t nholes,
                      tll_mesh *m) {
  rule r;
  char err[256];
  if (rule_parse(rule_name, &r, err, sizeof err) != 0) fail_msg("%s: %s", rule_name, err);
  lot_options o;
  lot_options_init(&o, &r);
  o.segments = seg;
  o.nsegments = nseg;
  o.holes = holes;
  o.nholes = nholes;
  lot *L;
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) fail_msg("lot_build: %s", err);
  const lot_stats *st = lot_get_stats(L);
  *m = (tll_mesh){p, n, st->triangles, malloc(3 * st->triangles * sizeof *m->tri),
                  malloc(3 * st->triangles * sizeof *m->nb), st->removed == 0};
  int32_t *want = malloc(3 * st->triangles * sizeof *want);
  assert_true(m->tri != NULL && m->nb != NULL && want != NULL);
  lot_get_triangles(L, m->tri);
  assert_int_equal(lot_get_neighbors(L, m->nb), 0);
  assert_int_equal(lot_neighbors(m->tri, m->ntri, n, want), 0);
  assert_memory_equal(m->nb, want, 3 * m->ntri * sizeof *want);
  free(want);
  return L;
}

static void tll_free(lot *L, tll_mesh *m) {
  lot_free(L);
  free(m->tri);
  free(m->nb);
}

/* The queries: nr random points over the bounding box widened by a
** quarter, every vertex, every edge's midpoint, points on the horizontal,
** vertical and diagonal lines through vertices, NaN and infinities.
** *nq is set; the caller frees. */
static geom_point *tll_queries(const tll_mesh *m, size_t nr, uint64_t seed, size_t *nq) {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (size_t i = 0; i < m->n; i++) {
    lo[0] = fmin(lo[0], m->p[i].x), hi[0] = fmax(hi[0], m->p[i].x);
    lo[1] = fmin(lo[1], m->p[i].y), hi[1] = fmax(hi[1], m->p[i].y);
  }
  size_t cap = nr + m->n + 3 * m->ntri + 3 * m->n + 4, k = 0;
  geom_point *q = malloc(cap * sizeof *q);
  assert_non_null(q);
  testutil_rng g = {seed};
  double wx = hi[0] - lo[0], wy = hi[1] - lo[1];
  for (size_t i = 0; i < nr; i++)
    q[k++] = (geom_point){lo[0] - wx / 4 + 1.5 * wx * testutil_uniform(&g),
                          lo[1] - wy / 4 + 1.5 * wy * testutil_uniform(&g)};
  for (size_t i = 0; i < m->n; i++) q[k++] = m->p[i];
  for (size_t t = 0; t < m->ntri; t++)
    for (size_t e = 0; e < 3; e++) {
      geom_point a = m->p[m->tri[3 * t + e]], b = m->p[m->tri[3 * t + (e + 1) % 3]];
      q[k++] = (geom_point){(a.x + b.x) / 2, (a.y + b.y) / 2};
    }
  for (size_t i = 0; i < m->n; i++) {   /* on the lines through vertex i */
    geom_point a = m->p[i], b = m->p[(i * 7 + 3) % m->n];
    q[k++] = (geom_point){a.x, b.y};
    q[k++] = (geom_point){b.x, a.y};
    q[k++] = (geom_point){2 * a.x - b.x, 2 * a.y - b.y};
  }
  q[k++] = (geom_point){NAN, 0};
  q[k++] = (geom_point){0, INFINITY};
  q[k++] = (geom_point){-INFINITY, NAN};
  q[k++] = (geom_point){lo[0], NAN};
  *nq = k;
  return q;
}

/* lot_locate, walking and scanning, against the oracle on every query;
** how many queries were inside a triangle (so the inputs are not vacuous). */
static size_t tll_check(const tll_mesh *m, const geom_point *q, size_t nq) {
  int32_t *walk = malloc(nq * sizeof *walk), *scan = malloc(nq * sizeof *scan);
  assert_true(walk != NULL && scan != NULL);
  int flags = m->convex ? LOT_LOCATE_CONVEX : 0;
  assert_int_equal(lot_locate(m->p, m->n, m->tri, m->nb, m->ntri, flags, q, nq, walk), 0);
  assert_int_equal(lot_locate(m->p, m->n, m->tri, NULL, m->ntri, LOT_LOCATE_SCAN, q, nq,
                              scan), 0);
  size_t inside = 0;
  for (size_t i = 0; i < nq; i++) {
    int32_t want = tll_oracle(m, q[i]);
    if (walk[i] != want || scan[i] != want)
      fail_msg("query %zu (%.17g, %.17g): walk %d, scan %d, oracle %d", i, q[i].x, q[i].y,
               walk[i], scan[i], want);
    inside += want >= 0;
  }
  free(walk);
  free(scan);
  return inside;
}

static void tll_run(const geom_point *p, size_t n, const char *rule_name, uint64_t seed) {
  tll_mesh m;
  lot *L = tll_build(p, n, rule_name, NULL, 0, NULL, 0, &m);
  size_t nq;
  geom_point *q = tll_queries(&m, 2000, seed, &nq);
  size_t inside = tll_check(&m, q, nq);
  assert_true(inside >= n && inside < nq);     /* the vertices are inside, NaN is not */
  free(q);
  tll_free(L, &m);
}

static geom_point *tll_sample(sampler_points_kind k, uint64_t seed, size_t n) {
  geom_point *p = malloc(n * sizeof *p);
  assert_non_null(p);
  sampler_points(k, seed, n, p);
  return p;
}

static void test_random(void **state) {
  (void)state;
  for (uint64_t seed = 1; seed <= (uint64_t)testutil_reps(4); seed++) {
    geom_point *p = tll_sample(SAMPLER_UNIFORM, seed, 400);
    p[17] = p[5];                                  /* a duplicate point */
    tll_run(p, 400, "DT", seed);
    tll_run(p, 400, "P_1", seed + 100);
    tll_run(p, 400, "-alpha_inf", seed + 200);
    free(p);
  }
}

static void test_grid(void **state) {
  (void)state;
  geom_point *p = tll_sample(SAMPLER_GRID, 1, 225);   /* 15 x 15: cocircular everywhere */
  tll_run(p, 225, "DT", 7);
  tll_run(p, 225, "R_1", 8);
  free(p);
}

/* Points on three long lines (a row, a column, a diagonal) and a few off
** them: most queries on those lines lie on an edge or a vertex. */
static void test_collinear_heavy(void **state) {
  (void)state;
  size_t n = 0;
  geom_point p[200];
  for (int i = 0; i < 60; i++) {
    p[n++] = (geom_point){i, 0};
    p[n++] = (geom_point){0, i + 1};
    p[n++] = (geom_point){i + 1, i + 1};
  }
  testutil_rng g = {42};
  while (n < 200) p[n++] = (geom_point){60 * testutil_uniform(&g), 60 * testutil_uniform(&g)};
  tll_run(p, n, "DT", 11);
  tll_run(p, n, "P_inf", 12);
}

/* A square with a square hole: the walk meets the hole's boundary and
** must fall back on the scan for the points beyond it. */
static void test_hole(void **state) {
  (void)state;
  geom_point p[] = {{0, 0}, {8, 0}, {8, 8}, {0, 8}, {3, 3}, {5, 3}, {5, 5}, {3, 5},
                    {1, 4}, {7, 4}, {4, 1}, {4, 7}, {2, 6}, {6, 2}};
  uint32_t seg[] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
  geom_point hole[] = {{4, 4}};
  tll_mesh m;
  lot *L = tll_build(p, 14, "DT", seg, 8, hole, 1, &m);
  assert_false(m.convex);
  size_t nq;
  geom_point *q = tll_queries(&m, 3000, 5, &nq);
  size_t inside = tll_check(&m, q, nq);
  int32_t in_hole;
  geom_point centre = {4, 4};
  assert_int_equal(lot_locate(p, 14, m.tri, m.nb, m.ntri, 0, &centre, 1, &in_hole), 0);
  assert_int_equal(in_hole, -1);
  assert_true(inside > 14 && inside < nq);
  free(q);
  tll_free(L, &m);
}

/* No triangles: every answer is -1, with or without neighbours. */
static void test_empty(void **state) {
  (void)state;
  geom_point p[] = {{0, 0}, {1, 0}, {0, 1}}, q[] = {{0.2, 0.2}, {0, 0}, {NAN, 1}};
  int32_t out[3] = {7, 7, 7};
  assert_int_equal(lot_locate(p, 3, NULL, NULL, 0, 0, q, 3, out), 0);
  for (int i = 0; i < 3; i++) assert_int_equal(out[i], -1);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_random),
    cmocka_unit_test(test_grid),
    cmocka_unit_test(test_collinear_heavy),
    cmocka_unit_test(test_hole),
    cmocka_unit_test(test_empty),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
