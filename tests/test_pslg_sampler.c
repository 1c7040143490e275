/*
** test_pslg_sampler.c: the planar straight-line graph samplers
** (samplers/pslg.c).  The oracle is a brute-force exact test over every
** pair of segments: two segments may meet only in an end point of one of
** them (a point of the graph), never cross or overlap.  Polygons with
** holes: every ring simple, every hole vertex strictly inside the outer
** ring, no hole inside another, each hole point strictly inside its hole
** and outside the others (crossing parity, exact).  Segments: indices in
** range, no two equal, as many as asked.  The grid: every segment along a
** grid line, rows exactly collinear, about half the column pieces chosen.
** All three: the same seed gives the same graph bit for bit, another seed
** another graph.
*/
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "report.h"
#include "sampler.h"
#include "testutil.h"

static int tps_lexcmp(geom_point a, geom_point b) {
  if (a.x != b.x) return a.x < b.x ? -1 : 1;
  return (a.y > b.y) - (a.y < b.y);
}

/* Segments ab and cd meet at most in an end point of one of them. */
static int tps_pair_ok(geom_point a, geom_point b, geom_point c, geom_point d) {
  if (!geom_segments_meet(a, b, c, d)) return 1;
  int o1 = geom_orient(a, b, c), o2 = geom_orient(a, b, d);
  int o3 = geom_orient(c, d, a), o4 = geom_orient(c, d, b);
  if (o1 == 0 && o2 == 0) {   /* collinear: the overlap must be one point */
    geom_point lo1 = tps_lexcmp(a, b) < 0 ? a : b, hi1 = tps_lexcmp(a, b) < 0 ? b : a;
    geom_point lo2 = tps_lexcmp(c, d) < 0 ? c : d, hi2 = tps_lexcmp(c, d) < 0 ? d : c;
    geom_point L = tps_lexcmp(lo1, lo2) > 0 ? lo1 : lo2, H = tps_lexcmp(hi1, hi2) < 0 ? hi1 : hi2;
    return tps_lexcmp(L, H) == 0;
  }
  /* one intersection point, which is an end point iff one orientation is 0 */
  return o1 == 0 || o2 == 0 || o3 == 0 || o4 == 0;
}

static void tps_assert_noncrossing(const geom_pslg *g) {
  for (size_t s = 0; s < g->nseg; s++) {
    assert_true(g->seg[2 * s] < g->npts && g->seg[2 * s + 1] < g->npts);
    geom_point a = g->pts[g->seg[2 * s]], b = g->pts[g->seg[2 * s + 1]];
    assert_true(tps_lexcmp(a, b) != 0);
    for (size_t t = s + 1; t < g->nseg; t++) {
      geom_point c = g->pts[g->seg[2 * t]], d = g->pts[g->seg[2 * t + 1]];
      if (!tps_pair_ok(a, b, c, d))
        fail_msg("segments %zu and %zu cross or overlap", s, t);
    }
  }
}

/* Winding number of the closed ring v[0..m) around q (q not on it): the
** signed count of upward and downward crossings of q's horizontal line
** to the right of q, by exact orientations. */
static int tps_winding(const geom_point *v, size_t m, geom_point q) {
  int w = 0;
  for (size_t i = 0; i < m; i++) {
    geom_point a = v[i], b = v[(i + 1) % m];
    if (a.y <= q.y && b.y > q.y && geom_orient(a, b, q) > 0) w++;
    if (a.y > q.y && b.y <= q.y && geom_orient(a, b, q) < 0) w--;
  }
  return w;
}

static void tps_assert_simple(const geom_point *v, size_t m) {
  geom_point *c = malloc(m * sizeof *c);
  memcpy(c, v, m * sizeof *c);
  int rev = 0;
  assert_int_equal(geom_simple_polygon_check(c, m, NULL, NULL, &rev), GEOM_OK);
  free(c);
}

static void tps_check_holes(const geom_pslg *g, size_t no, size_t nh, size_t m) {
  assert_int_equal(g->npts, no + nh * m);
  assert_int_equal(g->nseg, no + nh * m);
  assert_int_equal(g->nholes, nh);
  tps_assert_simple(g->pts, no);
  assert_int_equal(tps_winding(g->pts, no, (geom_point){0, 0}), 1);   /* anticlockwise */
  for (size_t h = 0; h < nh; h++) {
    const geom_point *r = g->pts + no + h * m;
    tps_assert_simple(r, m);
    for (size_t k = 0; k < m; k++) assert_int_equal(tps_winding(g->pts, no, r[k]), 1);
    for (size_t o = 0; o < nh; o++) {
      int w = tps_winding(r, m, g->hole[o]);
      assert_int_equal(w != 0, o == h);   /* hole point o is in hole o only */
      if (o != h) assert_int_equal(tps_winding(g->pts + no + o * m, m, r[0]), 0);
    }
  }
  tps_assert_noncrossing(g);
}

static void test_pslg_holes(void **state) {
  (void)state;
  static const size_t cases[][3] = {{3, 0, 3}, {12, 1, 3}, {40, 5, 6}, {100, 30, 4}, {8, 3, 10}};
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
    for (uint64_t seed = 1; seed <= 4; seed++) {
      sampler_rng g;
      sampler_seed(&g, seed, GEOM_STREAM_PSLG);
      geom_pslg p;
      assert_int_equal(sampler_pslg_holes(&g, cases[c][0], cases[c][1], cases[c][2], &p), 0);
      tps_check_holes(&p, cases[c][0], cases[c][1], cases[c][2]);
      geom_pslg_free(&p);
    }
  }
  sampler_rng g;
  sampler_seed(&g, 1, GEOM_STREAM_PSLG);
  geom_pslg p;
  assert_int_equal(sampler_pslg_holes(&g, 2, 1, 3, &p), -1);
  assert_int_equal(sampler_pslg_holes(&g, 5, 1, 2, &p), -1);
}

static void tps_assert_distinct_segments(const uint32_t *seg, size_t m) {
  for (size_t s = 0; s < m; s++)
    for (size_t t = s + 1; t < m; t++) {
      int same = (seg[2 * s] == seg[2 * t] && seg[2 * s + 1] == seg[2 * t + 1]) ||
                 (seg[2 * s] == seg[2 * t + 1] && seg[2 * s + 1] == seg[2 * t]);
      assert_false(same);
    }
}

static void test_pslg_segments(void **state) {
  (void)state;
  static const sampler_points_kind kinds[] = {SAMPLER_UNIFORM, SAMPLER_NORMAL, SAMPLER_GRID,
                                              SAMPLER_CIRCLE, SAMPLER_PARABOLA};
  for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
    size_t n = 1500, m = 400;
    geom_pslg p = {0};
    p.pts = malloc(n * sizeof *p.pts);
    p.seg = malloc(2 * m * sizeof *p.seg);
    p.npts = n;
    sampler_points(kinds[k], 7, n, p.pts);
    sampler_rng g;
    sampler_seed(&g, 7, GEOM_STREAM_SEGMENTS);
    assert_int_equal(sampler_segments(&g, p.pts, n, m, p.seg, &p.nseg), 0);
    if (kinds[k] != SAMPLER_PARABOLA) assert_int_equal(p.nseg, m);
    assert_true(p.nseg > 0);
    tps_assert_noncrossing(&p);
    tps_assert_distinct_segments(p.seg, p.nseg);
    geom_pslg_free(&p);
  }
  /* few candidates: every one of them (one cell, its first point to the
  ** two others), and no more */
  geom_point tri[3] = {{0, 0}, {1, 0}, {0, 1}};
  uint32_t seg[20];
  size_t got;
  sampler_rng g;
  sampler_seed(&g, 1, GEOM_STREAM_SEGMENTS);
  assert_int_equal(sampler_segments(&g, tri, 3, 10, seg, &got), 0);
  assert_int_equal(got, 2);
  tps_assert_distinct_segments(seg, got);
}

static void test_pslg_grid(void **state) {
  (void)state;
  static const size_t ns[] = {3, 10, 49, 50, 400, 1000};
  for (size_t c = 0; c < sizeof ns / sizeof ns[0]; c++) {
    sampler_rng g;
    sampler_seed(&g, 3, GEOM_STREAM_PSLG);
    geom_pslg p;
    assert_int_equal(sampler_pslg_grid(&g, ns[c], &p), 0);
    assert_int_equal(p.npts, ns[c]);
    tps_assert_noncrossing(&p);
    size_t s = (size_t)ceil(sqrt((double)ns[c])), cols = 0;
    for (size_t e = 0; e < p.nseg; e++) {
      uint32_t a = p.seg[2 * e], b = p.seg[2 * e + 1];
      geom_point pa = p.pts[a], pb = p.pts[b];
      if (b == a + s) {
        cols++;
        continue;
      }
      /* a row run: same row, a < b, every point between exactly on it */
      assert_true(a < b && a / s == b / s);
      for (uint32_t q = a + 1; q < b; q++) assert_int_equal(geom_orient(pa, pb, p.pts[q]), 0);
    }
    if (ns[c] >= 400) {   /* column pieces: Binomial(n - s, 1/2), within 5 sigma */
      double mean = 0.5 * (double)(ns[c] - s), sd = sqrt(0.25 * (double)(ns[c] - s));
      assert_true(fabs((double)cols - mean) < 5 * sd);
    }
    geom_pslg_free(&p);
  }
}

/* The same seed, the same graph bit for bit; another seed, another. */
static void test_pslg_reproducible(void **state) {
  (void)state;
  geom_pslg a[3];
  for (int k = 0; k < 3; k++) {
    sampler_rng g;
    sampler_seed(&g, k == 2 ? 8 : 5, GEOM_STREAM_PSLG);
    assert_int_equal(sampler_pslg_holes(&g, 30, 4, 5, &a[k]), 0);
  }
  assert_memory_equal(a[0].pts, a[1].pts, a[0].npts * sizeof *a[0].pts);
  assert_memory_equal(a[0].hole, a[1].hole, a[0].nholes * sizeof *a[0].hole);
  assert_true(memcmp(a[0].pts, a[2].pts, a[0].npts * sizeof *a[0].pts) != 0);
  for (int k = 0; k < 3; k++) geom_pslg_free(&a[k]);
  for (int k = 0; k < 3; k++) {
    sampler_rng g;
    sampler_seed(&g, k == 2 ? 8 : 5, GEOM_STREAM_PSLG);
    assert_int_equal(sampler_pslg_grid(&g, 300, &a[k]), 0);
  }
  assert_int_equal(a[0].nseg, a[1].nseg);
  assert_memory_equal(a[0].seg, a[1].seg, 2 * a[0].nseg * sizeof *a[0].seg);
  assert_true(a[0].nseg != a[2].nseg ||
              memcmp(a[0].seg, a[2].seg, 2 * a[0].nseg * sizeof *a[0].seg) != 0);
  for (int k = 0; k < 3; k++) geom_pslg_free(&a[k]);
  geom_point pts[500];
  uint32_t s[3][200];
  size_t got[3];
  sampler_points(SAMPLER_UNIFORM, 1, 500, pts);
  for (int k = 0; k < 3; k++) {
    sampler_rng g;
    sampler_seed(&g, k == 2 ? 8 : 5, GEOM_STREAM_SEGMENTS);
    assert_int_equal(sampler_segments(&g, pts, 500, 100, s[k], &got[k]), 0);
  }
  assert_memory_equal(s[0], s[1], sizeof s[0]);
  assert_true(memcmp(s[0], s[2], sizeof s[0]) != 0);
}

/* `fliplab sample --sampler holes|segments|grid` writes the sampler's graph
** of (seed, GEOM_STREAM_PSLG or _SEGMENTS): read back, the same bit for bit. */
static void tps_cli_same(const char *args, const geom_pslg *want) {
  char path[512], err[512];
  testutil_tmppath(path, sizeof path, "sample.poly");
  assert_int_equal(testutil_runf(NULL, 0, err, sizeof err, "sample %s --out %s", args, path), 0);
  report_poly r;
  assert_int_equal(report_poly_read(path, &r, err, sizeof err), 0);
  assert_int_equal(r.g.npts, want->npts);
  assert_int_equal(r.g.nseg, want->nseg);
  assert_int_equal(r.g.nholes, want->nholes);
  assert_memory_equal(r.g.pts, want->pts, want->npts * sizeof *want->pts);
  assert_memory_equal(r.g.seg, want->seg, 2 * want->nseg * sizeof *want->seg);
  if (want->nholes) assert_memory_equal(r.g.hole, want->hole, want->nholes * sizeof *want->hole);
  report_poly_free(&r);
}

static void test_pslg_sample_cli(void **state) {
  (void)state;
  sampler_rng g;
  geom_pslg p;
  sampler_seed(&g, 9, GEOM_STREAM_PSLG);
  assert_int_equal(sampler_pslg_holes(&g, 20, 3, 5, &p), 0);
  tps_cli_same("--sampler holes --points 20 --holes 3 --hole-vertices 5 --seed 9", &p);
  geom_pslg_free(&p);
  sampler_seed(&g, 9, GEOM_STREAM_PSLG);
  assert_int_equal(sampler_pslg_grid(&g, 70, &p), 0);
  tps_cli_same("--sampler grid --points 70 --seed 9 --format poly", &p);
  geom_pslg_free(&p);
  p = (geom_pslg){0};
  p.npts = 500;
  p.pts = malloc(500 * sizeof *p.pts);
  p.seg = malloc(2 * 60 * sizeof *p.seg);
  sampler_points(SAMPLER_NORMAL, 9, 500, p.pts);
  sampler_seed(&g, 9, GEOM_STREAM_SEGMENTS);
  assert_int_equal(sampler_segments(&g, p.pts, 500, 60, p.seg, &p.nseg), 0);
  tps_cli_same("--sampler segments --points 500 --segments 60 --point-sampler normal --seed 9", &p);
  geom_pslg_free(&p);
  static const char *const bad[][2] = {
    {"--sampler holes --count 3", "--count applies to --sampler pentagon only"},
    {"--segments 4", "--segments does not apply to --sampler pentagon"},
    {"--sampler grid --holes 2", "--holes does not apply to --sampler grid"},
    {"--sampler grid --format csv", "--sampler grid writes a .poly file (--format poly) only"},
    {"--sampler holes --out x.csv", "this output is poly, not .csv"},
    {"--sampler segments --point-sampler hex", "unknown point sampler 'hex'"},
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    char err[512];
    assert_int_equal(testutil_runf(NULL, 0, err, sizeof err, "sample %s", bad[i][0]), 2);
    assert_true(testutil_one_line(err));
    if (strstr(err, bad[i][1]) == NULL) fail_msg("'%s': got '%s'", bad[i][0], err);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_pslg_holes),
    cmocka_unit_test(test_pslg_segments),
    cmocka_unit_test(test_pslg_grid),
    cmocka_unit_test(test_pslg_reproducible),
    cmocka_unit_test(test_pslg_sample_cli),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
