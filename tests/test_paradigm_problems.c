/*
** test_paradigm_problems.c: the registry's polygon problems.  Convex
** polygons (chapter 5's rows, cpdt/): every convex-* row gives exactly lot's
** Delaunay triangulation of the vertices, n - 2 triangles, on random convex
** polygons of two samplers, whatever the starting vertex.  Simple polygons
** (the incremental, flip and select-constrained rows): each gives exactly
** the oracle, lot's constrained triangulation of the whole hull with the
** sides as segments restricted to the triangles whose centroid lies inside
** (crossing number), which has n - 2 triangles, for DT and ES:square, either
** way round, also with collinear neighbours and cocircular vertices.
** Refusals are one line naming the vertex or sides.  The divide and
** conquer of 2.6.3 (dc-polygon) also on spiral polygons, a grid comb and
** cocircular polygons from a random start, and on convex polygons, with
** its counts: edges made - deleted = 2n - 3, one flip per edge deleted.
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
#include "cpdt.h"
#include "lot.h"
#include "sampler.h"
#include "testutil.h"

#define TPP_MAXN 200

static rule tpp_rule(const char *name) {
  rule r;
  char err[256];
  if (rule_parse(name, &r, err, sizeof err) != 0) fail_msg("%s", err);
  return r;
}

/* Run row a on the polygon p; fail on an error. */
static paradigm_result tpp_run(const paradigm_algorithm *a, const geom_point *p, size_t n,
                               const rule *r, paradigm_problem pb) {
  paradigm_input in = {.p = p, .n = n, .r = r, .problem = pb, .seed = 7, .threads = 1};
  paradigm_result res;
  char err[512];
  if (paradigm_run(a, &in, &res, err, sizeof err) != 0) fail_msg("%s, n %zu: %s", a->name, n, err);
  return res;
}

/* lot's triangulation of p (with the polygon's sides as segments, the
** whole hull kept, when sides), canonical; *ntri its size. */
static uint32_t *tpp_lot(const geom_point *p, size_t n, const rule *r, int sides, size_t *ntri) {
  lot_options o;
  lot_options_init(&o, r);
  uint32_t seg[2 * TPP_MAXN];
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

static void tpp_equal(const paradigm_result *res, const uint32_t *tri, size_t ntri,
                      const char *name) {
  if (res->ntri != ntri || memcmp(res->tri, tri, 3 * ntri * sizeof *tri) != 0)
    fail_msg("%s: %zu triangles differ from the oracle's %zu", name, res->ntri, ntri);
}

/* The convex rows are named after cpdt's algorithms, serve only convex
** polygons and only DT. */
static void test_convex_registry(void **state) {
  (void)state;
  for (int k = 0; k < CPDT_ALGORITHM_COUNT; k++) {
    char name[64];
    snprintf(name, sizeof name, "convex-%s", cpdt_algorithm_name(k));
    const paradigm_algorithm *a = paradigm_find(name);
    if (a == NULL) fail_msg("no row %s", name);
    assert_int_equal(a->problems, PARADIGM_CONVEX);
    assert_int_equal(a->rules, PARADIGM_RULE_DT);
  }
}

static void tpp_convex_one(const geom_point *p, size_t n, const rule *dt) {
  size_t ntri;
  uint32_t *ref = tpp_lot(p, n, dt, 0, &ntri);
  assert_int_equal(ntri, n - 2);
  for (int k = 0; k < CPDT_ALGORITHM_COUNT; k++) {
    char name[64];
    snprintf(name, sizeof name, "convex-%s", cpdt_algorithm_name(k));
    paradigm_result res = tpp_run(paradigm_find(name), p, n, dt, PARADIGM_CONVEX);
    tpp_equal(&res, ref, ntri, name);
    if (n >= 4) assert_true(res.ops.v[OPS_INCIRCLE] > 0);
    paradigm_result_free(&res);
  }
  free(ref);
}

/* Random convex polygons of "vector" and "circle" (near-cocircular), each
** also from a random starting vertex. */
static void test_convex_rows(void **state) {
  (void)state;
  rule dt = tpp_rule("DT");
  const char *samplers[] = {"vector", "circle"};
  const size_t sizes[] = {3, 4, 5, 8, 20, 60, TPP_MAXN};
  sampler_gon_params gp = {SAMPLER_REGION_SQUARE, 0, NULL};
  sampler_rng g;
  sampler_seed(&g, 37, 1);
  geom_point p[TPP_MAXN], q[TPP_MAXN];
  for (size_t s = 0; s < 2; s++)
    for (size_t z = 0; z < sizeof sizes / sizeof sizes[0]; z++)
      for (int rep = 0; rep < 3; rep++) {
        size_t n = sizes[z];
        sampler_gon_info info;
        assert_int_equal(sampler_gon_find(samplers[s])->draw(&g, n, &gp, p, &info), 0);
        tpp_convex_one(p, n, &dt);
        size_t r = (size_t)(sampler_next(&g) % n);
        for (size_t i = 0; i < n; i++) q[i] = p[(i + r) % n];
        tpp_convex_one(q, n, &dt);
      }
}

/* Crossing number: is x strictly inside p?  (Centroids of triangles are
** far from the boundary for these polygons.) */
static int tpp_inside(const geom_point *p, size_t n, geom_point x) {
  int c = 0;
  for (size_t i = 0, j = n - 1; i < n; j = i++)
    if ((p[i].y > x.y) != (p[j].y > x.y)
        && x.x < (p[j].x - p[i].x) * (x.y - p[i].y) / (p[j].y - p[i].y) + p[i].x)
      c = !c;
  return c;
}

/* The oracle: lot's CDT of the hull restricted to the polygon. */
static uint32_t *tpp_polygon_oracle(const geom_point *p, size_t n, const rule *r,
                                    size_t *ntri) {
  size_t t;
  uint32_t *tri = tpp_lot(p, n, r, 1, &t);
  *ntri = 0;
  for (size_t k = 0; k < t; k++) {
    const uint32_t *v = tri + 3 * k;
    geom_point c = {(p[v[0]].x + p[v[1]].x + p[v[2]].x) / 3,
                    (p[v[0]].y + p[v[1]].y + p[v[2]].y) / 3};
    if (tpp_inside(p, n, c)) memmove(tri + 3 * (*ntri)++, v, 3 * sizeof *tri);
  }
  return tri;
}

/* Every row serving polygons and the rule (sweep-monotone: x-monotone
** polygons only). */
static void tpp_polygon_one(const geom_point *p, size_t n, const rule *r, int monotone) {
  size_t ntri, rows = 0;
  uint32_t *ref = tpp_polygon_oracle(p, n, r, &ntri);
  assert_int_equal(ntri, n - 2);
  unsigned want = rule_is_shape(r) ? PARADIGM_RULE_ES : PARADIGM_RULE_DT;
  for (size_t i = 0; i < paradigm_count(); i++) {
    const paradigm_algorithm *a = paradigm_get(i);
    if (!(a->problems & PARADIGM_POLYGON) || !(a->rules & want)) continue;
    if (!monotone && strcmp(a->name, "sweep-monotone") == 0) continue;
    paradigm_result res = tpp_run(a, p, n, r, PARADIGM_POLYGON);
    tpp_equal(&res, ref, ntri, a->name);
    paradigm_result_free(&res);
    rows++;
  }
  assert_true(rows >= 3);
  free(ref);
}

/* Star-shaped and monotone simple polygons, anticlockwise and reversed. */
static void test_polygon_rows(void **state) {
  (void)state;
  const char *rules[] = {"DT", "ES:square"};
  const size_t sizes[] = {3, 4, 6, 12, 40, 120};
  sampler_rng g;
  sampler_seed(&g, 38, 2);
  geom_point p[TPP_MAXN], q[TPP_MAXN];
  /* Collinear neighbours (allowed) and a 3 x 3 grid's ties: a square with its
  ** side midpoints, and a comb with a notch. */
  const geom_point mid[] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  const geom_point comb[] = {{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (size_t ru = 0; ru < 2; ru++) {
    rule r = tpp_rule(rules[ru]);
    tpp_polygon_one(mid, 8, &r, 1);
    tpp_polygon_one(comb, 8, &r, 1);
    for (size_t z = 0; z < sizeof sizes / sizeof sizes[0]; z++)
      for (int rep = 0; rep < 4; rep++) {
        size_t n = sizes[z];
        int rc = rep % 2 ? sampler_monotone(&g, n, p) : sampler_star(&g, n, p);
        assert_int_equal(rc, 0);
        tpp_polygon_one(p, n, &r, rep % 2);
        for (size_t i = 0; i < n; i++) q[i] = p[n - 1 - i];
        tpp_polygon_one(q, n, &r, rep % 2);
      }
  }
}

/* A refusal: -1 and one line containing `word`. */
static void tpp_refused(const char *name, const geom_point *p, size_t n, const char *rname,
                        paradigm_problem pb, const char *word) {
  rule r = tpp_rule(rname);
  paradigm_input in = {.p = p, .n = n, .r = &r, .problem = pb, .seed = 1, .threads = 1};
  paradigm_result res;
  char err[512] = "";
  assert_int_equal(paradigm_run(paradigm_find(name), &in, &res, err, sizeof err), -1);
  if (strstr(err, word) == NULL || strchr(err, '\n') != NULL)
    fail_msg("%s: '%s' lacks '%s'", name, err, word);
  assert_null(res.tri);
}

static void test_refusals(void **state) {
  (void)state;
  const geom_point dart[] = {{0, 0}, {4, 0}, {1, 1}, {0, 4}};       /* vertex 3 reflex */
  const geom_point square_cw[] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  const geom_point bowtie[] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};     /* sides 1 and 3 cross */
  const geom_point repeat[] = {{0, 0}, {2, 0}, {2, 2}, {2, 0}, {0, 2}};
  const geom_point square[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  tpp_refused("convex-circum", dart, 4, "DT", PARADIGM_CONVEX, "vertex 3");
  tpp_refused("convex-divide", square_cw, 4, "DT", PARADIGM_CONVEX, "clockwise");
  tpp_refused("convex-flip", square, 4, "ES:square", PARADIGM_CONVEX, "needs the rule DT");
  tpp_refused("convex-random", square, 4, "DT", PARADIGM_POLYGON, "does not solve");
  tpp_refused("sweep", square, 4, "DT", PARADIGM_CONVEX, "does not solve");
  tpp_refused("dc-vertical", square, 4, "DT", PARADIGM_POLYGON, "does not solve");
  tpp_refused("dc-polygon", square, 4, "ES:square", PARADIGM_POLYGON, "needs the rule DT");
  tpp_refused("dc-polygon", square, 4, "DT", PARADIGM_DELAUNAY, "does not solve");
  tpp_refused("dc-polygon", square, 4, "DT", PARADIGM_CONSTRAINED, "does not solve");
  tpp_refused("dc-polygon", square_cw, 4, "DT", PARADIGM_CONVEX, "clockwise");
  tpp_refused("dc-polygon", dart, 4, "DT", PARADIGM_CONVEX, "vertex 3");
  for (int k = 0; k < 4; k++) {
    const char *row = k == 0 ? "incremental" : k == 1 ? "flip" : k == 2 ? "select-constrained"
                    : "dc-polygon";
    tpp_refused(row, bowtie, 4, "DT", PARADIGM_POLYGON, "sides 1 and 3");
    tpp_refused(row, repeat, 5, "DT", PARADIGM_POLYGON, "vertex 4 repeats");
  }
  tpp_refused("convex-corners", repeat, 5, "DT", PARADIGM_CONVEX, "vertex 4 repeats");
}

/* dc-polygon on p as problem pb equals ref, and its counts hold. */
static void tpp_dc_check(const geom_point *p, size_t n, paradigm_problem pb,
                         const uint32_t *ref, size_t nref) {
  rule dt = tpp_rule("DT");
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
static void tpp_dc_polygon(const geom_point *p, size_t n, sampler_rng *g) {
  geom_point q[TPP_MAXN];
  rule dt = tpp_rule("DT");
  size_t s = (size_t)(sampler_next(g) % n);
  for (int way = 0; way < 3; way++) {
    for (size_t i = 0; i < n; i++)
      q[i] = way == 0 ? p[i] : way == 1 ? p[n - 1 - i] : p[(i + s) % n];
    size_t ntri;
    uint32_t *ref = tpp_polygon_oracle(q, n, &dt, &ntri);
    assert_int_equal(ntri, n - 2);
    tpp_dc_check(q, n, PARADIGM_POLYGON, ref, ntri);
    free(ref);
  }
}

/* A spiral of n (even) vertices: out along one arm, back along the
** other half a unit outside it, consecutive vertices `turn` radians apart. */
static void tpp_dc_spiral(size_t n, double turn, geom_point *p) {
  size_t h = n / 2;
  for (size_t i = 0; i < h; i++) {
    double t = turn * (double)i, r = 1 + t;
    p[i] = (geom_point){r * cos(t), r * sin(t)};
    p[n - 1 - i] = (geom_point){(r + 0.5) * cos(t), (r + 0.5) * sin(t)};
  }
}

static void test_dc_polygon(void **state) {
  (void)state;
  sampler_rng g;
  sampler_seed(&g, 263, 1);
  geom_point p[TPP_MAXN];
  const size_t sizes[] = {3, 4, 5, 6, 7, 9, 12, 20, 40, 90, TPP_MAXN};
  for (size_t z = 0; z < sizeof sizes / sizeof sizes[0]; z++)
    for (int rep = 0; rep < 24; rep++) {
      size_t n = sizes[z];
      assert_int_equal(rep % 2 ? sampler_monotone(&g, n, p) : sampler_star(&g, n, p), 0);
      tpp_dc_polygon(p, n, &g);
    }
  for (size_t n = 6; n <= TPP_MAXN; n += 14) {
    tpp_dc_spiral(n, 0.35, p);
    tpp_dc_polygon(p, n, &g);
    tpp_dc_spiral(n, 0.9, p);
    tpp_dc_polygon(p, n, &g);
  }
}

/* Ties: collinear neighbours on a 3 x 3 grid, a comb with notches on a
** grid, and the twelve integer points of the circle of radius 5. */
static void test_dc_polygon_ties(void **state) {
  (void)state;
  sampler_rng g;
  sampler_seed(&g, 264, 1);
  const geom_point mid[] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  const geom_point comb[] = {{0, 0}, {5, 0}, {5, 2}, {4, 2}, {4, 1}, {3, 1}, {3, 2},
                             {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const geom_point circ[] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3},
                             {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  for (int rep = 0; rep < 8; rep++) {
    tpp_dc_polygon(mid, 8, &g);
    tpp_dc_polygon(comb, 12, &g);
    tpp_dc_polygon(circ, 12, &g);
  }
  geom_point box[TPP_MAXN];   /* every integer point of a w x h box's boundary: all flat */
  for (int w = 1; w <= 7; w++)
    for (int h = 1; h <= 7; h++) {
      size_t n = 0;
      for (int x = 0; x < w; x++) box[n++] = (geom_point){x, 0};
      for (int y = 0; y < h; y++) box[n++] = (geom_point){w, y};
      for (int x = w; x > 0; x--) box[n++] = (geom_point){x, h};
      for (int y = h; y > 0; y--) box[n++] = (geom_point){0, y};
      tpp_dc_polygon(box, n, &g);
    }
}

/* Convex polygons (anticlockwise, as PARADIGM_CONVEX wants): the oracle is
** lot's Delaunay triangulation of the vertices. */
static void test_dc_polygon_convex(void **state) {
  (void)state;
  sampler_gon_params gp = {SAMPLER_REGION_SQUARE, 0, NULL};
  sampler_rng g;
  sampler_seed(&g, 265, 1);
  geom_point p[TPP_MAXN], q[TPP_MAXN];
  const char *samplers[] = {"vector", "circle"};
  const size_t sizes[] = {3, 4, 5, 8, 20, 60, TPP_MAXN};
  for (size_t s = 0; s < 2; s++)
    for (size_t z = 0; z < sizeof sizes / sizeof sizes[0]; z++)
      for (int rep = 0; rep < 10; rep++) {
        size_t n = sizes[z], ntri, r;
        rule dt = tpp_rule("DT");
        sampler_gon_info info;
        assert_int_equal(sampler_gon_find(samplers[s])->draw(&g, n, &gp, p, &info), 0);
        r = (size_t)(sampler_next(&g) % n);
        for (size_t i = 0; i < n; i++) q[i] = p[(i + r) % n];
        uint32_t *ref = tpp_lot(q, n, &dt, 0, &ntri);
        tpp_dc_check(q, n, PARADIGM_CONVEX, ref, ntri);
        free(ref);
      }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_convex_registry),
    cmocka_unit_test(test_convex_rows),
    cmocka_unit_test(test_polygon_rows),
    cmocka_unit_test(test_refusals),
    cmocka_unit_test(test_dc_polygon),
    cmocka_unit_test(test_dc_polygon_ties),
    cmocka_unit_test(test_dc_polygon_convex),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
