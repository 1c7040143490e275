/*
** test_paradigm_dc_polygon.c: the divide and conquer of 2.6.3 (row
** dc-polygon).  On star-shaped, monotone and spiral polygons, a grid comb
** and cocircular polygons, either way round and from a random starting
** vertex, its triangles are exactly the oracle's: lot's constrained
** triangulation of the hull with the sides as segments, restricted to the
** triangles whose centroid is inside (crossing number); on convex polygons
** (PARADIGM_CONVEX) exactly lot's Delaunay triangulation.  Its counts obey
** what holds for any run: edges made - deleted = the 2n - 3 edges of a
** polygon's triangulation, each flip deletes one edge and makes one, and
** every merge tests the diagonal's circle.  Refusals are one line.
*/
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "paradigm.h"
#include "lot.h"
#include "sampler.h"
#include "testutil.h"

#define TDP_MAXN 160

static rule tdp_dt(void) {
  rule r;
  char err[256];
  if (rule_parse("DT", &r, err, sizeof err) != 0) fail_msg("%s", err);
  return r;
}

/* lot's triangulation of p, the sides as segments and the hull kept when
** sides; canonical. */
static uint32_t *tdp_lot(const geom_point *p, size_t n, int sides, size_t *ntri) {
  rule dt = tdp_dt();
  lot_options o;
  lot_options_init(&o, &dt);
  uint32_t seg[2 * TDP_MAXN];
  for (size_t i = 0; i < n; i++) seg[2 * i] = (uint32_t)i, seg[2 * i + 1] = (uint32_t)((i + 1) % n);
  if (sides) o.segments = seg, o.nsegments = n, o.keep_hull = 1;
  lot *L = NULL;
  char err[256];
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) fail_msg("lot: %s", err);
  *ntri = lot_get_stats(L)->triangles;
  uint32_t *tri = malloc(3 * *ntri * sizeof *tri);
  assert_non_null(tri);
  lot_get_triangles(L, tri);
  lot_free(L);
  paradigm_canonical(tri, *ntri);
  return tri;
}

/* Crossing number, for centroids (well inside their polygon). */
static int tdp_inside(const geom_point *p, size_t n, geom_point x) {
  int c = 0;
  for (size_t i = 0, j = n - 1; i < n; j = i++)
    if ((p[i].y > x.y) != (p[j].y > x.y)
        && x.x < (p[j].x - p[i].x) * (x.y - p[i].y) / (p[j].y - p[i].y) + p[i].x)
      c = !c;
  return c;
}

static uint32_t *tdp_oracle(const geom_point *p, size_t n, size_t *ntri) {
  size_t t;
  uint32_t *tri = tdp_lot(p, n, 1, &t);
  *ntri = 0;
  for (size_t k = 0; k < t; k++) {
    const uint32_t *v = tri + 3 * k;
    geom_point c = {(p[v[0]].x + p[v[1]].x + p[v[2]].x) / 3,
                    (p[v[0]].y + p[v[1]].y + p[v[2]].y) / 3};
    if (tdp_inside(p, n, c)) memmove(tri + 3 * (*ntri)++, v, 3 * sizeof *tri);
  }
  return tri;
}

/* dc-polygon on p as problem pb equals ref, and its counts hold. */
static void tdp_check(const geom_point *p, size_t n, paradigm_problem pb, const uint32_t *ref,
                      size_t nref) {
  rule dt = tdp_dt();
  paradigm_input in = {.p = p, .n = n, .r = &dt, .problem = pb, .seed = 5, .threads = 1};
  paradigm_result res;
  char err[512];
  if (paradigm_run(paradigm_find("dc-polygon"), &in, &res, err, sizeof err) != 0)
    fail_msg("dc-polygon, n %zu: %s", n, err);
  if (res.ntri != nref || memcmp(res.tri, ref, 3 * nref * sizeof *ref) != 0)
    fail_msg("dc-polygon, n %zu: %zu triangles differ from the oracle's %zu", n, res.ntri,
             nref);
  const uint64_t *v = res.ops.v;
  assert_int_equal(v[OPS_EDGES_MADE] - v[OPS_EDGES_DELETED], 2 * n - 3);
  assert_int_equal(v[OPS_FLIPS], v[OPS_EDGES_DELETED]);
  if (n >= 4) assert_true(v[OPS_INCIRCLE] >= 1 && v[OPS_ORIENT] >= n);
  assert_true(v[OPS_PEAK_BYTES] > 0);
  paradigm_result_free(&res);
}

/* p as a simple polygon: as given, reversed, and from a random start. */
static void tdp_polygon(const geom_point *p, size_t n, sampler_rng *g) {
  geom_point q[TDP_MAXN];
  size_t s = (size_t)(sampler_next(g) % n);
  for (int way = 0; way < 3; way++) {
    for (size_t i = 0; i < n; i++)
      q[i] = way == 0 ? p[i] : way == 1 ? p[n - 1 - i] : p[(i + s) % n];
    size_t ntri;
    uint32_t *ref = tdp_oracle(q, n, &ntri);
    assert_int_equal(ntri, n - 2);
    tdp_check(q, n, PARADIGM_POLYGON, ref, ntri);
    free(ref);
  }
}

/* A spiral of n (even) vertices: out along one arm, back along the
** other, turns k apart in angle. */
static void tdp_spiral(size_t n, double turn, geom_point *p) {
  size_t h = n / 2;
  for (size_t i = 0; i < h; i++) {
    double t = turn * (double)i, r = 1 + t;
    p[i] = (geom_point){r * cos(t), r * sin(t)};
    p[n - 1 - i] = (geom_point){(r + 0.5) * cos(t), (r + 0.5) * sin(t)};
  }
}

static void test_simple_polygons(void **state) {
  (void)state;
  sampler_rng g;
  sampler_seed(&g, 263, 1);
  geom_point p[TDP_MAXN];
  const size_t sizes[] = {3, 4, 5, 6, 7, 9, 12, 20, 40, 90, TDP_MAXN};
  for (size_t z = 0; z < sizeof sizes / sizeof sizes[0]; z++)
    for (int rep = 0; rep < 24; rep++) {
      size_t n = sizes[z];
      assert_int_equal(rep % 2 ? sampler_monotone(&g, n, p) : sampler_star(&g, n, p), 0);
      tdp_polygon(p, n, &g);
    }
  for (size_t n = 6; n <= TDP_MAXN; n += 14) {
    tdp_spiral(n, 0.35, p);
    tdp_polygon(p, n, &g);
    tdp_spiral(n, 0.9, p);
    tdp_polygon(p, n, &g);
  }
}

/* Ties: collinear neighbours on a 3 x 3 grid, a comb with notches on a
** grid, and the twelve integer points of the circle of radius 5. */
static void test_ties(void **state) {
  (void)state;
  sampler_rng g;
  sampler_seed(&g, 264, 1);
  const geom_point mid[] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  const geom_point comb[] = {{0, 0}, {5, 0}, {5, 2}, {4, 2}, {4, 1}, {3, 1}, {3, 2},
                             {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const geom_point circ[] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3},
                             {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  for (int rep = 0; rep < 8; rep++) {
    tdp_polygon(mid, 8, &g);
    tdp_polygon(comb, 12, &g);
    tdp_polygon(circ, 12, &g);
  }
}

/* Convex polygons (anticlockwise, as PARADIGM_CONVEX wants): the oracle is
** lot's Delaunay triangulation of the vertices. */
static void test_convex(void **state) {
  (void)state;
  sampler_gon_params gp = {SAMPLER_REGION_SQUARE, 0, NULL};
  sampler_rng g;
  sampler_seed(&g, 265, 1);
  geom_point p[TDP_MAXN], q[TDP_MAXN];
  const char *samplers[] = {"vector", "circle"};
  const size_t sizes[] = {3, 4, 5, 8, 20, 60, TDP_MAXN};
  for (size_t s = 0; s < 2; s++)
    for (size_t z = 0; z < sizeof sizes / sizeof sizes[0]; z++)
      for (int rep = 0; rep < 10; rep++) {
        size_t n = sizes[z], ntri, r;
        sampler_gon_info info;
        assert_int_equal(sampler_gon_find(samplers[s])->draw(&g, n, &gp, p, &info), 0);
        r = (size_t)(sampler_next(&g) % n);
        for (size_t i = 0; i < n; i++) q[i] = p[(i + r) % n];
        uint32_t *ref = tdp_lot(q, n, 0, &ntri);
        tdp_check(q, n, PARADIGM_CONVEX, ref, ntri);
        free(ref);
      }
}

static void tdp_refused(const geom_point *p, size_t n, const char *rname, paradigm_problem pb,
                        const char *word) {
  rule r;
  char err[512] = "";
  assert_int_equal(rule_parse(rname, &r, err, sizeof err), 0);
  paradigm_input in = {.p = p, .n = n, .r = &r, .problem = pb, .seed = 1, .threads = 1};
  paradigm_result res;
  assert_int_equal(paradigm_run(paradigm_find("dc-polygon"), &in, &res, err, sizeof err), -1);
  if (strstr(err, word) == NULL || strchr(err, '\n') != NULL)
    fail_msg("dc-polygon: '%s' lacks '%s'", err, word);
  assert_null(res.tri);
}

static void test_refusals(void **state) {
  (void)state;
  const geom_point bowtie[] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  const geom_point repeat[] = {{0, 0}, {2, 0}, {2, 2}, {2, 0}, {0, 2}};
  const geom_point square[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const geom_point square_cw[] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  const geom_point dart[] = {{0, 0}, {4, 0}, {1, 1}, {0, 4}};
  tdp_refused(bowtie, 4, "DT", PARADIGM_POLYGON, "sides 1 and 3");
  tdp_refused(repeat, 5, "DT", PARADIGM_POLYGON, "vertex 4 repeats");
  tdp_refused(square, 4, "ES:square", PARADIGM_POLYGON, "needs the rule DT");
  tdp_refused(square, 4, "DT", PARADIGM_DELAUNAY, "does not solve");
  tdp_refused(square, 4, "DT", PARADIGM_CONSTRAINED, "does not solve");
  tdp_refused(square_cw, 4, "DT", PARADIGM_CONVEX, "clockwise");
  tdp_refused(dart, 4, "DT", PARADIGM_CONVEX, "vertex 3");
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_simple_polygons),
    cmocka_unit_test(test_ties),
    cmocka_unit_test(test_convex),
    cmocka_unit_test(test_refusals),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
