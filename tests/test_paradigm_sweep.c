/*
** test_paradigm_sweep.c: the constrained sweeps (rows sweep-constrained,
** 2.5.2, and sweep-monotone, 2.5.4).  On thousands of small sets (random
** doubles, subsets of small integer grids with their collinear and
** cocircular points, whole grids, integer points on one circle) with random
** non-crossing segments (sharing ends, through other sites, overlapping),
** sweep-constrained gives exactly lot's constrained Delaunay triangulation
** with the hull kept; with no segments lot's DT.  On random x-monotone
** polygons and convex polygons (either way round) both rows give the
** polygon rows' triangles.  The counts obey the sweep's theorems: one
** event per site and per triangle, edges made minus deleted the result's
** edges.  Refusals are one line.
*/
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

#define TS_MAXN 1600
#define TS_MAXS 400

static rule ts_dt(void) {
  rule r;
  char err[256];
  if (rule_parse("DT", &r, err, sizeof err) != 0) fail_msg("%s", err);
  return r;
}

/* lot's triangulation of p with the segments (whole hull), canonical. */
static uint32_t *ts_lot(const geom_point *p, size_t n, const uint32_t *seg, size_t ns,
                        size_t *ntri) {
  rule dt = ts_dt();
  lot_options o;
  lot_options_init(&o, &dt);
  o.segments = seg, o.nsegments = ns, o.keep_hull = 1;
  lot *L = NULL;
  char err[256];
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) fail_msg("lot: %s", err);
  *ntri = lot_get_stats(L)->triangles;
  uint32_t *tri = malloc((*ntri ? *ntri : 1) * 3 * sizeof *tri);
  assert_non_null(tri);
  lot_get_triangles(L, tri);
  lot_free(L);
  paradigm_canonical(tri, *ntri);
  return tri;
}

static int ts_run(const char *row, const geom_point *p, size_t n, const uint32_t *seg,
                  size_t ns, paradigm_problem pb, paradigm_result *res, char *err,
                  size_t errlen) {
  rule dt = ts_dt();
  paradigm_input in = {.p = p, .n = n, .r = &dt, .problem = pb, .segments = seg,
                       .nsegments = ns, .seed = 3, .threads = 1};
  return paradigm_run(paradigm_find(row), &in, res, err, errlen);
}

/* The sweep's theorems on a whole-hull run of m distinct sites and T
** triangles: n + T events (a site event per site, a circle event per
** triangle), and edges made - deleted = E = m + T - 1 (Euler). */
static void ts_counts(const paradigm_result *r) {
  uint64_t m = r->distinct, t = r->ntri;
  assert_int_equal(r->ops.v[OPS_EVENTS], m + t);
  assert_int_equal(r->ops.v[OPS_EDGES_MADE] - r->ops.v[OPS_EDGES_DELETED], m + t - 1);
}

static uint64_t ts_flips, ts_segs;   /* the tie pass's flips, segments, over all sets */

static void ts_same(const geom_point *p, size_t n, const uint32_t *seg, size_t ns) {
  size_t nref;
  uint32_t *ref = ts_lot(p, n, seg, ns, &nref);
  paradigm_result res;
  char err[512];
  if (ts_run("sweep-constrained", p, n, seg, ns, ns ? PARADIGM_CONSTRAINED : PARADIGM_DELAUNAY,
             &res, err, sizeof err) != 0)
    fail_msg("sweep-constrained, n %zu, %zu segments: %s", n, ns, err);
  if (res.ntri != nref || memcmp(res.tri, ref, 3 * nref * sizeof *ref) != 0) {
    for (size_t i = 0; i < n; i++) print_message("p %zu %.17g %.17g\n", i, p[i].x, p[i].y);
    for (size_t s = 0; s < ns; s++) print_message("s %u %u\n", seg[2 * s], seg[2 * s + 1]);
    fail_msg("n %zu, %zu segments: %zu triangles differ from lot's %zu", n, ns, res.ntri, nref);
  }
  ts_counts(&res);
  ts_flips += res.ops.v[OPS_FLIPS], ts_segs += ns;
  paradigm_result_free(&res);
  free(ref);
}

static int ts_sign(double v) {
  return (v > 0) - (v < 0);
}

/* Do segments ab and cd cross at a point inside both (refused)? */
static int ts_cross(geom_point a, geom_point b, geom_point c, geom_point d) {
  return ts_sign(geom_orient(a, b, c)) * ts_sign(geom_orient(a, b, d)) < 0
         && ts_sign(geom_orient(c, d, a)) * ts_sign(geom_orient(c, d, b)) < 0;
}

/* Up to want random segments between distinct points, none crossing an
** earlier one (ends inside, overlaps and shared ends are allowed). */
static size_t ts_segments(testutil_rng *g, const geom_point *p, size_t n, size_t want,
                          uint32_t *seg) {
  size_t ns = 0;
  for (size_t tries = 0; tries < 4 * want && ns < want; tries++) {
    uint32_t u = (uint32_t)(testutil_next(g) % n), v = (uint32_t)(testutil_next(g) % n);
    if (p[u].x == p[v].x && p[u].y == p[v].y) continue;
    int ok = 1;
    for (size_t s = 0; s < ns && ok; s++)
      ok = !ts_cross(p[u], p[v], p[seg[2 * s]], p[seg[2 * s + 1]]);
    if (ok) seg[2 * ns] = u, seg[2 * ns + 1] = v, ns++;
  }
  return ns;
}

/* A family's points: 0 uniform doubles, 1 a small integer grid's points
** (repeats, collinear and cocircular points), 2 a whole k x k grid, 3
** integer points on the circle x^2 + y^2 = 25^2 plus its centre. */
static size_t ts_points(testutil_rng *g, int fam, size_t n, geom_point *p) {
  static const int circ[][2] = {{25, 0}, {24, 7}, {20, 15}, {15, 20}, {7, 24}, {0, 25}};
  if (fam == 2) {
    size_t k = 2 + n % 6;
    for (size_t i = 0; i < k * k; i++) p[i] = (geom_point){(double)(i % k), (double)(i / k)};
    return k * k;
  }
  for (size_t i = 0; i < n; i++) {
    if (fam == 0) {
      p[i] = (geom_point){testutil_uniform(g), testutil_uniform(g)};
    } else if (fam == 1) {
      p[i] = (geom_point){(double)(testutil_next(g) % 6), (double)(testutil_next(g) % 6)};
    } else {
      size_t c = testutil_next(g) % 25;
      const int *q = circ[c % 6];
      int sx = c / 6 % 2 ? -1 : 1, sy = c / 12 % 2 ? -1 : 1;
      p[i] = c == 24 ? (geom_point){0, 0} : (geom_point){sx * q[0], sy * q[1]};
    }
  }
  return n;
}

/* Thousands of small sets of the four families, with 0 to 3n/2 segments. */
static void test_constrained_lot(void **state) {
  (void)state;
  testutil_rng g = {2552};
  geom_point p[TS_MAXN];
  uint32_t seg[2 * TS_MAXS];
  for (int rep = 0; rep < 4000; rep++) {
    int fam = rep % 4;
    size_t n = ts_points(&g, fam, 3 + (size_t)(testutil_next(&g) % 30), p);
    size_t want = (size_t)(testutil_next(&g) % (3 * n / 2 + 1));
    size_t ns = ts_segments(&g, p, n, want < TS_MAXS ? want : TS_MAXS, seg);
    rule dt = ts_dt();
    paradigm_input in = {.p = p, .n = n, .r = &dt, .problem = PARADIGM_DELAUNAY, .threads = 1};
    paradigm_result chk;
    char err[256];
    /* collinear sets: the runner refuses them (tested elsewhere) */
    if (paradigm_run(paradigm_find("incremental"), &in, &chk, err, sizeof err) != 0) continue;
    paradigm_result_free(&chk);
    ts_same(p, n, seg, ns);
    ts_same(p, n, seg, 0);
  }
  for (int rep = 0; rep < 24; rep++) {   /* a few larger sets: long pieces, deep lists */
    int fam = rep % 3;
    size_t n = ts_points(&g, fam, fam == 2 ? 1599 : 1500, p);
    if (fam == 2) {   /* a 40 x 40 grid */
      for (size_t i = 0; i < 1600; i++) p[i] = (geom_point){(double)(i % 40), (double)(i / 40)};
      n = 1600;
    }
    ts_same(p, n, seg, ts_segments(&g, p, n, TS_MAXS, seg));
  }
  print_message("%llu segments, %llu tie flips\n", (unsigned long long)ts_segs,
                (unsigned long long)ts_flips);
}

/* A random x-monotone polygon of n vertices (distinct x), anticlockwise
** or clockwise: the lower chain left to right, the upper right to left. */
static void ts_monotone(testutil_rng *g, size_t n, int ccw, geom_point *p) {
  double x[TS_MAXN];
  for (size_t i = 0; i < n; i++) x[i] = (double)i + 0.5 * testutil_uniform(g);
  size_t lo = 0, hi = n;
  geom_point q[TS_MAXN];
  q[lo++] = (geom_point){x[0], 0.5};
  for (size_t i = 1; i + 1 < n; i++) {
    double y = testutil_uniform(g);
    if (testutil_next(g) & 1) q[lo++] = (geom_point){x[i], 0.45 * y};
    else q[--hi] = (geom_point){x[i], 0.55 + 0.45 * y};
  }
  q[lo++] = (geom_point){x[n - 1], 0.5};
  for (size_t i = 0; i < n; i++) p[i] = ccw ? q[i] : q[n - 1 - i];
}

/* An x-monotone polygon of small integers with vertical sides (steps of
** the chains at one x) and cocircular vertices: m columns, each with one or
** two vertices below y = 0 and above it, the ends at y = 0.  Its size. */
static size_t ts_staircase(testutil_rng *g, int ccw, geom_point *p) {
  geom_point lo[40], hi[40];
  size_t nl = 0, nh = 0, n = 0;
  int m = 2 + (int)(testutil_next(g) % 8), x = 0;
  for (int k = 0; k < m; k++) {
    double y1 = -1.0 - (double)(testutil_next(g) % 4), y2 = 1.0 + (double)(testutil_next(g) % 4);
    lo[nl++] = (geom_point){x, y1};
    if (testutil_next(g) & 1) lo[nl++] = (geom_point){x, y1 - 1};
    hi[nh++] = (geom_point){x, y2};
    if (testutil_next(g) & 1) hi[nh++] = (geom_point){x, y2 + 1};
    x += 1 + (int)(testutil_next(g) % 2);
  }
  p[n++] = (geom_point){-1, 0};
  for (size_t i = 0; i < nl; i++) p[n++] = lo[i];
  p[n++] = (geom_point){x, 0};
  for (size_t i = nh; i-- > 0;) p[n++] = hi[i];
  for (size_t i = 0; !ccw && i < n / 2; i++) {
    geom_point t = p[i];
    p[i] = p[n - 1 - i], p[n - 1 - i] = t;
  }
  return n;
}

static void ts_polygon_same(const geom_point *p, size_t n, paradigm_problem pb,
                            const char *oracle) {
  paradigm_result ref, res;
  char err[512];
  if (ts_run(oracle, p, n, NULL, 0, pb, &ref, err, sizeof err) != 0) fail_msg("%s", err);
  const char *rows[] = {"sweep-constrained", "sweep-monotone"};
  for (int r = 0; r < 2; r++) {
    if (ts_run(rows[r], p, n, NULL, 0, pb, &res, err, sizeof err) != 0)
      fail_msg("%s, n %zu: %s", rows[r], n, err);
    if (res.ntri != ref.ntri || memcmp(res.tri, ref.tri, 3 * ref.ntri * sizeof *ref.tri))
      fail_msg("%s, n %zu: triangles differ from %s's", rows[r], n, oracle);
    assert_int_equal(res.ntri, n - 2);
    paradigm_result_free(&res);
  }
  paradigm_result_free(&ref);
}

/* x-monotone polygons either way round, random and integer staircases
** (the row incremental's CDT of the polygon), convex polygons of two
** samplers (convex-divide's DT; then clockwise, as simple polygons). */
static void test_polygons(void **state) {
  (void)state;
  testutil_rng g = {254};
  geom_point p[TS_MAXN];
  for (int rep = 0; rep < 600; rep++) {
    size_t n = 3 + (size_t)(testutil_next(&g) % 40);
    ts_monotone(&g, n, rep & 1, p);
    ts_polygon_same(p, n, PARADIGM_POLYGON, "incremental");
    ts_polygon_same(p, ts_staircase(&g, rep & 1, p), PARADIGM_POLYGON, "incremental");
  }
  sampler_gon_params gp = {SAMPLER_REGION_SQUARE, 0, NULL};
  sampler_rng sg;
  sampler_seed(&sg, 25, 4);
  const char *samplers[] = {"vector", "circle"};
  for (int rep = 0; rep < 200; rep++) {
    size_t n = 3 + (size_t)(rep % 50);
    sampler_gon_info info;
    assert_int_equal(sampler_gon_find(samplers[rep & 1])->draw(&sg, n, &gp, p, &info), 0);
    ts_polygon_same(p, n, PARADIGM_CONVEX, "convex-divide");
    ts_polygon_same(p, n, PARADIGM_POLYGON, "incremental");
    for (size_t i = 0; i < n / 2; i++) {   /* clockwise: a simple polygon still */
      geom_point t = p[i];
      p[i] = p[n - 1 - i], p[n - 1 - i] = t;
    }
    ts_polygon_same(p, n, PARADIGM_POLYGON, "incremental");
  }
}

static void ts_refused(const char *row, const geom_point *p, size_t n, const uint32_t *seg,
                       size_t ns, paradigm_problem pb, const char *rule_name, const char *want) {
  rule r;
  char err[512];
  assert_int_equal(rule_parse(rule_name, &r, err, sizeof err), 0);
  paradigm_input in = {.p = p, .n = n, .r = &r, .problem = pb, .segments = seg,
                       .nsegments = ns, .threads = 1};
  paradigm_result res;
  err[0] = '\0';
  assert_int_not_equal(paradigm_run(paradigm_find(row), &in, &res, err, sizeof err), 0);
  if (strstr(err, want) == NULL) fail_msg("%s: '%s' lacks '%s'", row, err, want);
  assert_null(strchr(err, '\n'));
}

/* ES:SHAPE, crossing segments (at a site too), a segment from a point to
** itself, a polygon not x-monotone (naming the vertex), a non-convex "convex" polygon, a
** point set for sweep-monotone. */
static void test_refusals(void **state) {
  (void)state;
  const geom_point sq[] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 3}};
  const uint32_t cross[] = {0, 2, 1, 3}, self[] = {1, 1};
  ts_refused("sweep-constrained", sq, 5, NULL, 0, PARADIGM_DELAUNAY, "ES:square",
             "needs the rule DT");
  ts_refused("sweep-constrained", sq, 5, cross, 2, PARADIGM_CONSTRAINED, "DT",
             "segments 0 and 1 cross");
  /* Crossing at a site inside both: lot splits both there; the sweep
  ** refuses (docs/paradigms.md: it cannot place the crossing exactly). */
  const geom_point xs[] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}};
  ts_refused("sweep-constrained", xs, 5, cross, 2, PARADIGM_CONSTRAINED, "DT",
             "segments 0 and 1 cross");
  ts_refused("sweep-constrained", sq, 5, self, 1, PARADIGM_CONSTRAINED, "DT",
             "segment 0: both ends");
  const geom_point w[] = {{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 2}, {4, 2}, {4, 3}, {0, 3}};
  ts_refused("sweep-monotone", w, 8, NULL, 0, PARADIGM_POLYGON, "DT",
             "polygon is not x-monotone at vertex 7");
  const geom_point v[] = {{0, 0}, {2, 1}, {4, 0}, {2, 3}};
  ts_refused("sweep-monotone", v, 4, NULL, 0, PARADIGM_CONVEX, "DT", "convex polygon: vertex");
  ts_refused("sweep-monotone", sq, 5, NULL, 0, PARADIGM_DELAUNAY, "DT", "x-monotone");
  /* the C shape is simple but not monotone: sweep-constrained serves it */
  paradigm_result res;
  char err[256];
  assert_int_equal(ts_run("sweep-constrained", w, 8, NULL, 0, PARADIGM_POLYGON, &res, err,
                          sizeof err), 0);
  assert_int_equal(res.ntri, 6);
  paradigm_result_free(&res);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_refusals),
    cmocka_unit_test(test_polygons),
    cmocka_unit_test(test_constrained_lot),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
