/*
** test_paradigm_dc_constrained.c: the row dc-constrained (2.6.2: pieces
** cut alternately or in vertical strips, merged by Guibas and Stolfi's
** zipper, segments inserted by flips at the merge of their ends).  With both kinds of cut, on
** uniform sets, grid sets with duplicates and ties, and integer points on
** two concentric circles (cocircular ties), with segments drawn among the
** Delaunay edges or at random (long ones through other sites, vertical
** ones, ones between sites of equal x, crossing ones) and with
** sampler_segments' non-crossing ones, it gives exactly lot's constrained
** triangulation whenever lot gives one, and refuses on one line whenever
** lot refuses (naming a crossing pair when lot's refusal is a crossing).
** So too with many parallel long segments, vertical ones (on a cut line),
** a convex polygon's sides and chords (cocircular) and a rotated grid with
** segments along its lines.  Most random runs need insertions (a segment
** that is no chain of Delaunay edges, found here by brute force): the
** counts are asserted, so the tests cannot pass on easy sets only.
** Euler's count holds on every run; the parameter is checked.
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

#define TDC_MAXN 48

/* A small set: uniform, a grid with duplicates, or circle points. */
static size_t tdc_points(int f, testutil_rng *g, geom_point *p) {
  size_t n = 4 + testutil_next(g) % (TDC_MAXN - 4), k = 0;
  if (f == 0)
    for (; k < n; k++) p[k] = (geom_point){testutil_uniform(g), testutil_uniform(g)};
  if (f == 1)
    for (; k < n; k++)
      p[k] = (geom_point){(double)(testutil_next(g) % 5), (double)(testutil_next(g) % 5)};
  for (int x = -7; f == 2 && x <= 7; x++)
    for (int y = -7; y <= 7; y++)
      if ((x * x + y * y == 25 || x * x + y * y == 50) && k < TDC_MAXN)
        p[k++] = (geom_point){x, y};
  return k;
}

/* The cuts of dc-constrained for the next run (its parameter): alternating
** (0) or vertical strips (1); every comparison runs both. */
static double tdc_param;

static int tdc_run(const char *row, const geom_point *p, size_t n, const uint32_t *seg,
                   size_t ns, paradigm_result *res, char *err, size_t errlen) {
  rule dt = rule_delaunay();
  paradigm_input in = {.p = p, .n = n, .r = &dt, .problem = PARADIGM_CONSTRAINED,
                       .segments = seg, .nsegments = ns, .seed = 3, .threads = 1,
                       .param = strcmp(row, "dc-constrained") == 0 ? tdc_param : 0};
  return paradigm_run(paradigm_find(row), &in, res, err, errlen);
}

/* Is u-v (distinct points' indices) an edge of tri? */
static int tdc_edge(const paradigm_result *dt, uint32_t u, uint32_t v) {
  for (size_t t = 0; t < dt->ntri; t++)
    for (int k = 0; k < 3; k++) {
      uint32_t a = dt->tri[3 * t + k], b = dt->tri[3 * t + (k + 1) % 3];
      if ((a == u && b == v) || (a == v && b == u)) return 1;
    }
  return 0;
}

/* Is segment u-v (input indices) a chain of edges of dt through the sites
** on it?  By brute force: every distinct site on the closed segment
** (orientation 0, lexicographically between), in lexicographic order,
** each consecutive pair an edge. */
static int tdc_chain(const paradigm_result *dt, const geom_point *p, size_t n,
                     const uint32_t *first, uint32_t u, uint32_t v) {
  u = first[u], v = first[v];
  if (geom_lexless(p[v], p[u])) {
    uint32_t t = u;
    u = v, v = t;
  }
  uint32_t on[TDC_MAXN];
  size_t m = 0;
  for (uint32_t k = 0; k < n; k++)
    if (first[k] == k && geom_orient(p[u], p[v], p[k]) == 0 && !geom_lexless(p[k], p[u])
        && !geom_lexless(p[v], p[k]))
      on[m++] = k;
  for (size_t i = 1; i < m; i++)   /* insertion sort, lexicographic */
    for (size_t j = i; j > 0 && geom_lexless(p[on[j]], p[on[j - 1]]); j--) {
      uint32_t t = on[j];
      on[j] = on[j - 1], on[j - 1] = t;
    }
  int ok = m >= 2;
  for (size_t i = 1; i < m; i++) ok &= tdc_edge(dt, on[i - 1], on[i]);
  return ok;
}

/* One set with its segments: dc-constrained against lot (the incremental
** row), with either kind of cut.  When lot refuses (crossing segments, or a segment whose ends are
** duplicates), dc-constrained must refuse too, on one line naming a
** crossing when lot's does; else it must give lot's triangles
** exactly.  Returns 1 when it served a set with a segment that is no chain
** of Delaunay edges (the merges' insertions ran), 2 when every segment was
** one, 0 when both refused. */
static int tdc_compare(const geom_point *p, size_t n, const uint32_t *seg, size_t ns,
                       const paradigm_result *dt, const uint32_t *first) {
  assert_true(n <= TDC_MAXN);
  char err[512], err2[512];
  paradigm_result ref, res;
  int lot_rc = tdc_run("incremental", p, n, seg, ns, &ref, err, sizeof err), edges = 1;
  for (tdc_param = 0; tdc_param <= 1; tdc_param++) {
    int rc = tdc_run("dc-constrained", p, n, seg, ns, &res, err2, sizeof err2);
    if (lot_rc != 0) {
      if (rc == 0 || (strstr(err, "cross") == NULL) != (strstr(err2, "cross") == NULL)
          || strchr(err2, '\n') != NULL)
        fail_msg("n %zu, %zu segments: lot refused (%s), dc-constrained %s", n, ns, err,
                 rc ? err2 : "served");
      continue;
    }
    if (rc != 0) fail_msg("n %zu, %zu segments, cuts %g: refused: %s", n, ns, tdc_param, err2);
    if (res.ntri != ref.ntri || memcmp(res.tri, ref.tri, 3 * ref.ntri * sizeof *ref.tri) != 0)
      fail_msg("n %zu, %zu segments, cuts %g: differs from lot's constrained triangulation", n,
               ns, tdc_param);
    size_t m = res.distinct, h = 2 * m - 2 - res.ntri;
    assert_int_equal(res.ops.v[OPS_EDGES_MADE] - res.ops.v[OPS_EDGES_DELETED], 3 * m - 3 - h);
    paradigm_result_free(&res);
  }
  if (lot_rc != 0) return 0;
  for (size_t s = 0; s < ns; s++) edges &= tdc_chain(dt, p, n, first, seg[2 * s], seg[2 * s + 1]);
  paradigm_result_free(&ref);
  return edges ? 2 : 1;
}

/* lot's Delaunay triangulation of p into *del and each point's first
** occurrence into first; 0, or -1 when lot refuses the set. */
static int tdc_delaunay(const geom_point *p, size_t n, paradigm_result *del, uint32_t *first) {
  rule dt = rule_delaunay();
  char err[256];
  paradigm_input in = {.p = p, .n = n, .r = &dt, .problem = PARADIGM_DELAUNAY, .threads = 1};
  if (paradigm_run(paradigm_find("incremental"), &in, del, err, sizeof err) != 0) return -1;
  assert_true(lot_distinct(p, n, first) >= 0);
  return 0;
}

static void tdc_set(int f, testutil_rng *g, int *tally) {
  geom_point p[TDC_MAXN];
  uint32_t first[TDC_MAXN], seg[2 * 3 * TDC_MAXN];
  size_t n = tdc_points(f, g, p);
  paradigm_result del;
  if (tdc_delaunay(p, n, &del, first) != 0) return;
  size_t ns = 0;   /* Delaunay edges, by input index (a duplicate's too) */
  for (size_t t = 0; t < del.ntri; t++)
    if (testutil_next(g) % 3 == 0) {
      int k = (int)(testutil_next(g) % 3);
      seg[2 * ns] = del.tri[3 * t + k], seg[2 * ns + 1] = del.tri[3 * t + (k + 1) % 3], ns++;
    }
  assert_int_equal(tdc_compare(p, n, seg, ns, &del, first), 2);   /* Delaunay edges */
  for (size_t s = 0; s < 2; s++) {   /* one or two random segments */
    for (size_t k = 0; k < 2 * (s + 1); k++) seg[k] = (uint32_t)(testutil_next(g) % n);
    if (seg[0] == seg[1] || (s && seg[2] == seg[3])) continue;
    tally[tdc_compare(p, n, seg, s + 1, &del, first)]++;
  }
  paradigm_result_free(&del);
}

/* Uniform sites with sampler_segments' non-crossing segments (seed k). */
static void tdc_sampled(uint64_t k, int *tally) {
  geom_point p[TDC_MAXN];
  uint32_t first[TDC_MAXN], seg[2 * TDC_MAXN];
  size_t n = 8 + k % (TDC_MAXN - 8), ns;
  sampler_points(SAMPLER_UNIFORM, k, n, p);
  sampler_rng sg;
  sampler_seed(&sg, k, GEOM_STREAM_SEGMENTS);
  assert_int_equal(sampler_segments(&sg, p, n, 1 + k % (n / 4), seg, &ns), 0);
  paradigm_result del;
  if (ns == 0 || tdc_delaunay(p, n, &del, first) != 0) return;
  tally[tdc_compare(p, n, seg, ns, &del, first)]++;
  paradigm_result_free(&del);
}

/* Segments that cross many strips or lie on a cut, with the sites they
** need (n at most TDC_MAXN), by kind: 0 many parallel long segments,
** left column to right column, up to 5 random sites between; 1 vertical segments
** (every site of a column on one cut line; sites of equal x joined); 2 the
** sides and some chords of a convex polygon (a fan from vertex 0: no two
** cross), up to 15 random sites about it.  Returns the segments. */
static size_t tdc_special(int kind, testutil_rng *g, geom_point *p, size_t *n, uint32_t *seg) {
  size_t k = 0, ns = 0, rows = 3 + testutil_next(g) % 6;
  for (size_t r = 0; kind == 0 && r < rows; r++) {   /* (0, 2r) - (9, 2r + 1) */
    p[k] = (geom_point){0, 2.0 * (double)r}, p[k + 1] = (geom_point){9, 2.0 * (double)r + 1};
    seg[2 * ns] = (uint32_t)k, seg[2 * ns + 1] = (uint32_t)k + 1, ns++, k += 2;
  }
  for (int x = 0; kind == 1 && x < 4; x++)   /* columns of 2 to 6 sites at x */
    for (size_t j = 0, m = 2 + testutil_next(g) % 5; j < m; j++, k++) {
      p[k] = (geom_point){x, (double)(testutil_next(g) % 9) + 0.5 * (double)j};
      if (j > 0 && testutil_next(g) % 2)   /* may pass other sites of the column */
        seg[2 * ns] = (uint32_t)k - 1, seg[2 * ns + 1] = (uint32_t)k, ns++;
    }
  for (int v = 0; kind == 2 && v < 12; v++, k++) {   /* a cocircular 12-gon */
    static const int c[12][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0},
                                 {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
    p[k] = (geom_point){c[v][0], c[v][1]};
    seg[2 * ns] = (uint32_t)v, seg[2 * ns + 1] = (uint32_t)(v + 1) % 12, ns++;
    if (v > 1 && v < 11 && testutil_next(g) % 3 == 0)
      seg[2 * ns] = 0, seg[2 * ns + 1] = (uint32_t)v, ns++;
  }
  size_t loose = kind == 1 ? 0 : testutil_next(g) % (kind ? 16 : 6);   /* on no segment */
  for (size_t e = 0; e < loose; e++, k++) {
    double u = testutil_uniform(g), v = testutil_uniform(g);
    p[k] = kind == 0 ? (geom_point){1 + 7 * u, 2.0 * (double)rows * v}
                     : (geom_point){6 * u - 3, 6 * v - 3};
  }
  *n = k;
  return ns;
}

static void test_special(void **state) {
  (void)state;
  testutil_rng g = {263};
  int count[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, sets = testutil_reps(300);
  for (int s = 0; s < 3 * sets; s++) {
    geom_point p[TDC_MAXN];
    uint32_t first[TDC_MAXN], seg[4 * TDC_MAXN];
    size_t n, ns = tdc_special(s % 3, &g, p, &n, seg);
    paradigm_result del;
    if (tdc_delaunay(p, n, &del, first) != 0) continue;
    count[s % 3][tdc_compare(p, n, seg, ns, &del, first)]++;
    paradigm_result_free(&del);
  }
  for (int k = 0; k < 3; k++)
    print_message("special kind %d: %d served with insertions, %d with Delaunay edges\n", k,
                  count[k][1], count[k][2]);
  for (int k = 0; k < 3; k++) assert_true(count[k][0] == 0 && count[k][1] > 0);
}

/* A rotated grid with segments along its lines: always served. */
static void tdc_grid(uint64_t k) {
  geom_pslg pg;
  sampler_rng sg;
  sampler_seed(&sg, k, GEOM_STREAM_PSLG);
  assert_int_equal(sampler_pslg_grid(&sg, 6 + k % (TDC_MAXN - 6), &pg), 0);
  uint32_t first[TDC_MAXN];
  paradigm_result del;
  assert_int_equal(tdc_delaunay(pg.pts, pg.npts, &del, first), 0);
  assert_int_equal(tdc_compare(pg.pts, pg.npts, pg.seg, pg.nseg, &del, first), 2);
  paradigm_result_free(&del);
  geom_pslg_free(&pg);
}

static void test_sets(void **state) {
  (void)state;
  testutil_rng g = {262};
  int sets = testutil_reps(1500), tally[3] = {0, 0, 0}, sampled[3] = {0, 0, 0};
  for (int s = 0; s < sets; s++) tdc_set(s % 3, &g, tally);
  print_message("random segments: %d crossing (refused by both), %d served with insertions, "
                "%d with Delaunay edges\n", tally[0], tally[1], tally[2]);
  assert_true(tally[0] > 0 && tally[1] > sets / 2);
  for (int s = 0; s < sets; s++) tdc_sampled((uint64_t)s + 1, sampled);
  print_message("sampler_segments: %d served with insertions, %d with Delaunay edges\n",
                sampled[1], sampled[2]);
  assert_true(sampled[0] == 0 && sampled[1] > sets / 2);
  for (int s = 0; s < sets / 5; s++) tdc_grid((uint64_t)s + 1);
}

static void test_refusals(void **state) {
  (void)state;
  const geom_point sq[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.2}};
  const uint32_t self[] = {1, 1}, diag[] = {0, 2}, side[] = {0, 1};
  char err[512];
  paradigm_result res;
  tdc_param = 2;
  assert_int_equal(tdc_run("dc-constrained", sq, 5, side, 1, &res, err, sizeof err), -1);
  assert_non_null(strstr(err, "dc-constrained: parameter 2: 0 (cuts alternating"));
  tdc_param = 0;
  assert_int_equal(tdc_run("dc-constrained", sq, 5, self, 1, &res, err, sizeof err), -1);
  assert_non_null(strstr(err, "segment 0 joins a point to itself"));
  paradigm_result ref;
  const uint32_t cross[] = {0, 1, 0, 2, 1, 3};   /* the two diagonals cross */
  assert_int_equal(tdc_run("dc-constrained", sq, 4, cross, 3, &res, err, sizeof err), -1);
  assert_non_null(strstr(err, "segments 1 and 2 cross"));
  assert_null(strchr(err, '\n'));
  /* A diagonal, a segment through site 1 (pinched: no Delaunay edge), as
  ** lot has them. */
  const geom_point line[] = {{0, 0}, {1, 0}, {2, 0}, {1, 1}, {1, -1}};
  const geom_point pinch[] = {{0, 0}, {1, 0}, {2, 0}, {0.5, 0.1}, {0.5, -0.1}};
  const uint32_t through[] = {0, 2};
  /* Two segments crossing at a site inside both: lot splits both there. */
  const geom_point xsite[] = {{0, 0}, {2, 2}, {0, 2}, {2, 0}, {1, 1}};
  const uint32_t xseg[] = {0, 1, 2, 3};
  const geom_point *set[] = {sq, line, pinch, xsite};
  const uint32_t *segs[] = {diag, through, through, xseg};
  for (int k = 0; k < 4; k++) {
    size_t ns = k == 3 ? 2 : 1;
    assert_int_equal(tdc_run("dc-constrained", set[k], 5, segs[k], ns, &res, err, sizeof err), 0);
    assert_int_equal(tdc_run("incremental", set[k], 5, segs[k], ns, &ref, err, sizeof err), 0);
    assert_int_equal(res.ntri, ref.ntri);
    assert_memory_equal(res.tri, ref.tri, 3 * ref.ntri * sizeof *ref.tri);
    paradigm_result_free(&res), paradigm_result_free(&ref);
  }
  rule es;
  assert_int_equal(rule_parse("ES:square", &es, err, sizeof err), 0);
  paradigm_input in = {.p = sq, .n = 5, .r = &es, .problem = PARADIGM_CONSTRAINED,
                       .segments = side, .nsegments = 1, .threads = 1};
  assert_int_equal(paradigm_run(paradigm_find("dc-constrained"), &in, &res, err, sizeof err),
                   -1);
  assert_non_null(strstr(err, "needs the rule DT"));
  rule dt = rule_delaunay();
  in.r = &dt, in.problem = PARADIGM_DELAUNAY;
  assert_int_equal(paradigm_run(paradigm_find("dc-constrained"), &in, &res, err, sizeof err),
                   -1);
  assert_non_null(strstr(err, "dc-vertical"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_sets),
    cmocka_unit_test(test_special),
    cmocka_unit_test(test_refusals),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
