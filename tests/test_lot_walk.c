/*
** test_lot_walk.c: point location in the triangle-neighbour structure of
** lot/ (lot_mesh_locate, lot/mesh.h) on meshes full of needles.
**
** The meshes are made by inserting points without Delaunay flips and then
** flipping random strictly convex quadrilaterals, so they are far from
** Delaunay (where a walk with a fixed edge order can cycle) and their
** triangles' numbers are scattered.  Every answer of the walk, from every
** kind of start triangle (real or ghost), is checked against a scan of
** all triangles with the exact orientation test: strictly inside, on an
** edge, on a vertex, outside the hull seeing the ghost's edge.  Queries
** include vertices, edge midpoints and points on lines through many
** vertices, where the walk's floating-point filter cannot decide and the
** exact path must.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "mesh.h"
#include "testutil.h"

/* The oracle: where q is, by looking at every triangle. */
typedef struct tw_truth {
  lot_where where;
  int nreal;   /* real triangles whose closure holds q */
} tw_truth;

static int tw_orient(const lot_mesh *m, uint32_t a, uint32_t b, geom_point q) {
  return geom_orient(m->p[a], m->p[b], q);
}

static tw_truth tw_scan(const lot_mesh *m, geom_point q) {
  tw_truth r = {LOT_OUTSIDE, 0};
  int strict = 0, zeros_max = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (lot_is_ghost(m, t)) continue;
    const uint32_t *v = m->tv + LOT_CORNER((size_t)t, 0);
    int o0 = tw_orient(m, v[1], v[2], q), o1 = tw_orient(m, v[2], v[0], q);
    int o2 = tw_orient(m, v[0], v[1], q);
    if (o0 < 0 || o1 < 0 || o2 < 0) continue;
    int zeros = (o0 == 0) + (o1 == 0) + (o2 == 0);
    r.nreal++;
    strict += zeros == 0;
    if (zeros > zeros_max) zeros_max = zeros;
  }
  if (r.nreal == 0) r.where = LOT_OUTSIDE;
  else if (zeros_max == 2) r.where = LOT_ON_VERTEX;
  else if (zeros_max == 1) r.where = LOT_ON_EDGE;
  else r.where = LOT_IN_TRIANGLE;
  if (r.where == LOT_IN_TRIANGLE) assert_int_equal(strict, 1);
  return r;
}

/* Locate q from the start triangle t0 and check the answer. */
static void tw_check(lot_mesh *m, geom_point q, uint32_t t0) {
  m->last = t0;
  uint32_t c;
  lot_where w = lot_mesh_locate(m, q, &c);
  tw_truth truth = tw_scan(m, q);
  if (w != truth.where)
    fail_msg("q (%.17g, %.17g) from triangle %u: walk says %d, scan says %d", q.x, q.y, t0,
             (int)w, (int)truth.where);
  assert_true(lot_slot(c) < 3 && lot_tri_of(c) < m->nt);
  uint32_t t = lot_tri_of(c);
  uint32_t a = m->tv[c], b = m->tv[lot_next3(c)], d = m->tv[lot_prev3(c)];
  switch (w) {
  case LOT_IN_TRIANGLE:
    assert_int_equal(lot_slot(c), 0);
    assert_false(lot_is_ghost(m, t));
    assert_int_equal(tw_orient(m, b, d, q), 1);
    assert_int_equal(tw_orient(m, d, a, q), 1);
    assert_int_equal(tw_orient(m, a, b, q), 1);
    break;
  case LOT_ON_EDGE:   /* the edge opposite c, inside a real triangle */
    assert_false(lot_is_ghost(m, t));
    assert_int_equal(tw_orient(m, b, d, q), 0);
    assert_int_equal(tw_orient(m, d, a, q), 1);
    assert_int_equal(tw_orient(m, a, b, q), 1);
    break;
  case LOT_ON_VERTEX:
    assert_true(a != LOT_GHOST && m->p[a].x == q.x && m->p[a].y == q.y);
    break;
  case LOT_OUTSIDE:   /* a ghost's ghost corner; q sees its edge b -> d */
    assert_int_equal(a, LOT_GHOST);
    assert_int_equal(tw_orient(m, b, d, q), 1);
    break;
  }
}

/* A mesh of the n points p (distinct, not all collinear, p[0..2] anticlockwise)
** inserted in order without flips; returns how many were inserted. */
static uint32_t tw_build(lot_mesh *m, const geom_point *p, uint32_t n) {
  assert_int_equal(lot_mesh_alloc(m, n, LOT_CACHE_NONE), 0);
  for (uint32_t k = 0; k < n; k++) {
    m->p[k] = p[k];
    m->inp[k] = k;
  }
  assert_int_equal(geom_orient(p[0], p[1], p[2]), 1);
  lot_mesh_first(m, 0, 1, 2);
  uint32_t *cand = NULL;
  size_t candcap = 0;
  uint32_t inserted = 3;
  for (uint32_t k = 3; k < n; k++) {
    uint32_t c;
    lot_where w = lot_mesh_locate(m, m->p[k], &c);
    if (w == LOT_ON_VERTEX) continue;
    assert_true(lot_mesh_insert(m, k, w, c, &cand, &candcap) >= 0);
    inserted++;
  }
  free(cand);
  return inserted;
}

/* Flip `count` random strictly convex quadrilaterals: needles, and
** neighbours whose numbers are far apart. */
static void tw_scramble(lot_mesh *m, testutil_rng *g, uint32_t count) {
  for (uint32_t done = 0, tries = 0; done < count && tries < 100 * count; tries++) {
    uint32_t c = LOT_CORNER((uint32_t)(testutil_next(g) % m->nt), (uint32_t)(testutil_next(g) % 3));
    uint32_t cd = m->tn[c];
    if (lot_is_ghost(m, lot_tri_of(c)) || lot_is_ghost(m, lot_tri_of(cd))) continue;
    geom_point pa = m->p[m->tv[c]], pb = m->p[m->tv[lot_next3(c)]];
    geom_point pc = m->p[m->tv[lot_prev3(c)]], pd = m->p[m->tv[cd]];
    if (geom_orient(pa, pb, pd) <= 0 || geom_orient(pa, pd, pc) <= 0) continue;
    lot_mesh_flip(m, c, 0, 0);
    done++;
  }
}

/* Queries: random points (inside and around the hull), every vertex, the
** midpoints of random edges, points on the lines the input was put on;
** each from a random triangle, real or ghost. */
static void tw_queries(lot_mesh *m, testutil_rng *g, double lo, double hi, uint32_t count) {
  for (uint32_t k = 0; k < count; k++) {
    geom_point q;
    uint32_t kind = (uint32_t)(testutil_next(g) % 4);
    if (kind == 0) {
      double span = hi - lo;
      q.x = lo - 0.2 * span + 1.4 * span * testutil_uniform(g);
      q.y = lo - 0.2 * span + 1.4 * span * testutil_uniform(g);
    } else if (kind == 1) {
      q = m->p[testutil_next(g) % m->np];
    } else if (kind == 2) {   /* integer coordinates: the midpoint is exact */
      uint32_t c = LOT_CORNER((uint32_t)(testutil_next(g) % m->nt), (uint32_t)(testutil_next(g) % 3));
      uint32_t u = m->tv[lot_next3(c)], v = m->tv[lot_prev3(c)];
      if (u == LOT_GHOST || v == LOT_GHOST) continue;
      q = (geom_point){(m->p[u].x + m->p[v].x) / 2, (m->p[u].y + m->p[v].y) / 2};
    } else {   /* on the diagonal y = x or the line x = 500 */
      double s = lo + (hi - lo) * (double)(testutil_next(g) % 2001) / 2000;
      q = (testutil_next(g) & 1) ? (geom_point){s, s} : (geom_point){500, s};
    }
    tw_check(m, q, (uint32_t)(testutil_next(g) % m->nt));
  }
}

/* n points with integer coordinates in [0, 1000]: a third on the diagonal
** y = x, a third on the line x = 500, the rest anywhere; the first three
** an anticlockwise triangle; no duplicates needed (the walk merges them). */
static geom_point *tw_points(testutil_rng *g, uint32_t n) {
  geom_point *p = malloc(n * sizeof *p);
  assert_non_null(p);
  p[0] = (geom_point){0, 0};
  p[1] = (geom_point){1000, 0};
  p[2] = (geom_point){0, 1000};
  for (uint32_t k = 3; k < n; k++) {
    double a = (double)(testutil_next(g) % 1001), b = (double)(testutil_next(g) % 1001);
    p[k] = k % 3 == 0 ? (geom_point){a, a} : k % 3 == 1 ? (geom_point){500, b} : (geom_point){a, b};
  }
  return p;
}

static int tw_cmp_x(const void *x, const void *y) {
  const geom_point *a = x, *b = y;
  return a->x < b->x ? -1 : a->x > b->x ? 1 : a->y < b->y ? -1 : a->y > b->y;
}

static void test_walk_on_scrambled_meshes(void **state) {
  (void)state;
  for (uint64_t seed = 1; seed <= 4; seed++) {
    testutil_rng g = {seed};
    uint32_t n = 300 + 200 * (uint32_t)seed;
    geom_point *p = tw_points(&g, n);
    lot_mesh m;
    uint32_t inserted = tw_build(&m, p, n);
    assert_true(inserted > n / 2);
    tw_scramble(&m, &g, 20 * inserted);
    tw_queries(&m, &g, 0, 1000, 1500);
    lot_mesh_free(&m);
    free(p);
  }
}

/* Inserted left to right without flips after a first triangle: the points
** beyond its long edge each see a chain of hull edges and fan to it (long
** thin triangles, insertions through the ghosts), the others split the
** triangles they fall in. */
static void test_walk_on_a_sweep_fan(void **state) {
  (void)state;
  testutil_rng g = {99};
  uint32_t n = 800;
  geom_point *p = tw_points(&g, n);
  qsort(p + 3, n - 3, sizeof *p, tw_cmp_x);
  lot_mesh m;
  tw_build(&m, p, n);
  tw_queries(&m, &g, 0, 1000, 2000);
  tw_scramble(&m, &g, 5 * n);
  tw_queries(&m, &g, 0, 1000, 2000);
  lot_mesh_free(&m);
  free(p);
}

/* The walk is a function of the mesh, the start and the generator's state:
** the same calls on the same mesh give the same corners. */
static void test_walk_reproducible(void **state) {
  (void)state;
  testutil_rng g = {7};
  uint32_t n = 600;
  geom_point *p = tw_points(&g, n);
  lot_mesh m;
  tw_build(&m, p, n);
  tw_scramble(&m, &g, 10 * n);
  enum { K = 500 };
  uint32_t first[K];
  uint64_t state0 = m.walk;
  for (int pass = 0; pass < 2; pass++) {
    testutil_rng h = {11};
    m.walk = state0;
    for (int k = 0; k < K; k++) {
      geom_point q = {1000 * testutil_uniform(&h), 1000 * testutil_uniform(&h)};
      m.last = (uint32_t)(testutil_next(&h) % m.nt);
      uint32_t c;
      lot_mesh_locate(&m, q, &c);
      if (pass == 0) first[k] = c;
      else assert_int_equal(c, first[k]);
    }
  }
  lot_mesh_free(&m);
  free(p);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_walk_on_scrambled_meshes),
    cmocka_unit_test(test_walk_on_a_sweep_fan),
    cmocka_unit_test(test_walk_reproducible),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
