/*
** test_cdt.c: constrained triangulations (lot/cdt.c, docs/lot.md).
**
** - The constrained empty-circle property by an independent test-only
**   oracle: for every triangle of the CDT and every site strictly inside
**   its circumcircle, the segment from the triangle's centroid to the site
**   meets a constraint (coordinates are multiples of 3, so the centroid is
**   exact and every test is exact).
** - Every segment is a chain of edges, every other interior edge locally
**   optimal for the rule (lot_check_constrained), Euler's relation with
**   holes; flip, incremental and sweep give the same CDT (the tie-break
**   makes it unique, grids included).
** - Without segments, with segments that are edges already, with every
**   hull edge as a segment: lot's unconstrained triangles, exactly.
** - Holes: the kept triangles are exactly those inside the outer ring and
**   outside every hole (point in polygon, exact), their area the domain's.
** - A simple polygon as a ring of segments: the constrained LOT's total is
**   at least the GOT's; the DT-equivalent sum rules give the CDT, their GOT.
** - Every refusal of the API is one line naming the segment or hole.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "got.h"
#include "lot.h"
#include "rule.h"
#include "sampler.h"
#include "testutil.h"

static rule tc_rule(const char *name) {
  rule r;
  char err[4096];
  if (rule_parse(name, &r, err, sizeof err) != 0) fail_msg("%s: %s", name, err);
  return r;
}

/* Random points with coordinates 3 k, k in [0, range). */
static geom_point *tc_points(uint64_t seed, size_t n, int range) {
  testutil_rng g = {seed};
  geom_point *p = malloc(n * sizeof *p);
  for (size_t i = 0; i < n; i++)
    p[i] = (geom_point){3.0 * (double)(testutil_next(&g) % (uint64_t)range),
                        3.0 * (double)(testutil_next(&g) % (uint64_t)range)};
  return p;
}

typedef struct tc_result {
  uint32_t *tri;
  size_t ntri;
  lot_stats st;
  char err[512];
  int rc;
} tc_result;

static tc_result tc_build(const geom_point *p, size_t n, const lot_options *o) {
  tc_result r = {0};
  lot *L;
  r.rc = lot_build(&L, p, n, o, r.err, sizeof r.err);
  if (r.rc != 0) return r;
  r.st = *lot_get_stats(L);
  r.ntri = r.st.triangles;
  r.tri = malloc((3 * r.ntri + 1) * sizeof *r.tri);
  lot_get_triangles(L, r.tri);
  lot_free(L);
  return r;
}

static lot_options tc_opts(const rule *r, lot_algorithm alg, const uint32_t *seg, size_t nseg) {
  lot_options o;
  lot_options_init(&o, r);
  o.algorithm = alg;
  o.segments = seg;
  o.nsegments = nseg;
  return o;
}

/* The oracle: t's circumcircle holds no site that its centroid sees. */
static void tc_empty_circle(const geom_point *p, size_t n, const tc_result *r,
                            const uint32_t *seg, size_t nseg) {
  for (size_t t = 0; t < r->ntri; t++) {
    const uint32_t *v = r->tri + 3 * t;
    geom_point a = p[v[0]], b = p[v[1]], c = p[v[2]];
    geom_point g = {(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
    assert_true(g.x * 3 == a.x + b.x + c.x && g.y * 3 == a.y + b.y + c.y);
    for (size_t q = 0; q < n; q++) {
      if (geom_incircle(a, b, c, p[q]) <= 0) continue;
      int blocked = 0;
      for (size_t s = 0; s < nseg && !blocked; s++) {
        geom_point s0 = p[seg[2 * s]], s1 = p[seg[2 * s + 1]];
        int q_on = geom_orient(s0, s1, p[q]) == 0 && geom_segments_meet(s0, s1, p[q], p[q]);
        blocked = !q_on && geom_segments_meet(g, p[q], s0, s1);
      }
      if (!blocked) fail_msg("triangle %u %u %u: site %zu inside its circle, visible", v[0], v[1], v[2], q);
    }
  }
}

static void tc_checked(const geom_point *p, size_t n, const tc_result *r, const uint32_t *seg,
                       size_t nseg, const rule *rl) {
  lot_check_result c;
  assert_int_equal(lot_check_constrained(p, n, r->tri, r->ntri, seg, nseg, rl, &c), 0);
  assert_true(c.valid);
  assert_int_equal(c.not_optimal, 0);
  assert_int_equal(c.segments_missing, r->st.segments_removed);
}

static int tc_same(const tc_result *a, const tc_result *b) {
  return a->ntri == b->ntri && memcmp(a->tri, b->tri, 3 * a->ntri * sizeof *a->tri) == 0;
}

/* Random sets with random non-crossing segments: the oracle, the check,
** and one CDT whatever the algorithm. */
static void test_cdt_oracle(void **state) {
  (void)state;
  rule dt = tc_rule("DT");
  for (uint64_t seed = 1; seed <= 40; seed++) {
    size_t n = 20 + 7 * (size_t)seed;
    geom_point *p = tc_points(seed, n, seed % 2 ? 40 : 1000);
    sampler_rng g;
    sampler_seed(&g, seed, 0);
    uint32_t *seg = malloc(2 * n * sizeof *seg);
    size_t nseg;
    assert_int_equal(sampler_segments(&g, p, n, n / 3, seg, &nseg), 0);
    lot_options o = tc_opts(&dt, LOT_INCREMENTAL, seg, nseg);
    o.keep_hull = 1;
    tc_result r = tc_build(p, n, &o);
    if (r.rc != 0) fail_msg("seed %llu: %s", (unsigned long long)seed, r.err);
    tc_empty_circle(p, n, &r, seg, nseg);
    tc_checked(p, n, &r, seg, nseg, &dt);
    assert_int_equal(r.st.segments, nseg);
    for (int alg = 0; alg < 3; alg++) {
      lot_options o2 = tc_opts(&dt, (lot_algorithm)alg, seg, nseg);
      o2.keep_hull = 1;
      tc_result r2 = tc_build(p, n, &o2);
      assert_int_equal(r2.rc, 0);
      if (!tc_same(&r, &r2)) fail_msg("seed %llu: algorithm %d differs", (unsigned long long)seed, alg);
      free(r2.tri);
    }
    free(r.tri);
    free(seg);
    free(p);
  }
}

/* Constrained LOTs of other rules: every segment there, every other edge
** locally optimal, for the flip and incremental algorithms. */
static void test_cdt_rules(void **state) {
  (void)state;
  static const char *const names[] = {"P_1", "-alpha_inf", "sigma_1", "ES:square", "ES:hexagon"};
  for (size_t k = 0; k < sizeof names / sizeof *names; k++) {
    rule rl = tc_rule(names[k]);
    for (uint64_t seed = 1; seed <= 6; seed++) {
      size_t n = 200;
      geom_point *p = tc_points(seed + 100, n, 10000);
      sampler_rng g;
      sampler_seed(&g, seed, 0);
      uint32_t seg[200];
      size_t nseg;
      assert_int_equal(sampler_segments(&g, p, n, 60, seg, &nseg), 0);
      for (int alg = 0; alg < 2; alg++) {
        lot_options o = tc_opts(&rl, alg ? LOT_FLIP : LOT_INCREMENTAL, seg, nseg);
        o.keep_hull = 1;
        tc_result r = tc_build(p, n, &o);
        if (r.rc != 0) fail_msg("%s seed %llu: %s", names[k], (unsigned long long)seed, r.err);
        tc_checked(p, n, &r, seg, nseg, &rl);
        free(r.tri);
      }
      free(p);
    }
  }
}

/* Segments that are edges already change nothing: none, the hull's edges,
** a subset of the unconstrained result's edges. */
static void test_cdt_unchanged(void **state) {
  (void)state;
  static const char *const names[] = {"DT", "P_1", "ES:square"};
  for (size_t k = 0; k < 3; k++) {
    rule rl = tc_rule(names[k]);
    size_t n = 300;
    geom_point *p = tc_points(7 + k, n, 100000);
    lot_options o = tc_opts(&rl, LOT_INCREMENTAL, NULL, 0);
    tc_result base = tc_build(p, n, &o);
    assert_int_equal(base.rc, 0);
    lot *L;
    char err[256];
    assert_int_equal(lot_build(&L, p, n, &o, err, sizeof err), 0);
    size_t h = lot_get_stats(L)->hull;
    uint32_t *hull = malloc(h * sizeof *hull), *seg = malloc((2 * h + 2 * base.ntri) * sizeof *seg);
    lot_get_hull(L, hull);
    lot_free(L);
    for (size_t i = 0; i < h; i++) {
      seg[2 * i] = hull[i];
      seg[2 * i + 1] = hull[(i + 1) % h];
    }
    size_t nseg = h;
    for (size_t t = 0; t < base.ntri; t += 3, nseg++) {   /* one edge of every third triangle */
      seg[2 * nseg] = base.tri[3 * t];
      seg[2 * nseg + 1] = base.tri[3 * t + 1];
    }
    for (int keep = 0; keep < 2; keep++) {
      lot_options oc = tc_opts(&rl, LOT_INCREMENTAL, seg, nseg);
      oc.keep_hull = keep;
      tc_result r = tc_build(p, n, &oc);
      assert_int_equal(r.rc, 0);
      assert_true(tc_same(&base, &r));
      assert_int_equal(r.st.removed, 0);
      free(r.tri);
    }
    free(hull);
    free(seg);
    free(base.tri);
    free(p);
  }
}

/* Exact point in polygon (ring of m points): crossings of a rightward ray. */
static int tc_inside(geom_point q, const geom_point *ring, size_t m) {
  int in = 0;
  for (size_t i = 0, j = m - 1; i < m; j = i++) {
    geom_point a = ring[j], b = ring[i];
    if ((a.y > q.y) != (b.y > q.y)) {
      int o = geom_orient(a, b, q);
      if ((b.y > a.y) ? o > 0 : o < 0) in = !in;
    }
  }
  return in;
}

static double tc_area(const geom_point *ring, size_t m) {
  double s = 0;
  for (size_t i = 0, j = m - 1; i < m; j = i++) s += ring[j].x * ring[i].y - ring[i].x * ring[j].y;
  return s / 2;
}

static void test_cdt_holes(void **state) {
  (void)state;
  rule dt = tc_rule("DT"), p1 = tc_rule("P_1");
  for (uint64_t seed = 1; seed <= 12; seed++) {
    sampler_rng g;
    sampler_seed(&g, seed, 0);
    geom_pslg G;
    size_t nouter = 30, nholes = 1 + seed % 4, m = 8;
    assert_int_equal(sampler_pslg_holes(&g, nouter, nholes, m, &G), 0);
    for (int k = 0; k < 2; k++) {
      lot_options o = tc_opts(k ? &p1 : &dt, LOT_INCREMENTAL, G.seg, G.nseg);
      o.holes = G.hole;
      o.nholes = G.nholes;
      tc_result r = tc_build(G.pts, G.npts, &o);
      if (r.rc != 0) fail_msg("seed %llu: %s", (unsigned long long)seed, r.err);
      tc_checked(G.pts, G.npts, &r, G.seg, G.nseg, k ? &p1 : &dt);
      double area = 0, want = tc_area(G.pts, nouter);
      for (size_t h = 0; h < nholes; h++) want -= fabs(tc_area(G.pts + nouter + h * m, m));
      for (size_t t = 0; t < r.ntri; t++) {
        const uint32_t *v = r.tri + 3 * t;
        geom_point a = G.pts[v[0]], b = G.pts[v[1]], c = G.pts[v[2]];
        area += tc_area((geom_point[]){a, b, c}, 3);
        geom_point mid = {(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
        assert_true(tc_inside(mid, G.pts, nouter));
        for (size_t h = 0; h < nholes; h++) assert_false(tc_inside(mid, G.pts + nouter + h * m, m));
      }
      TESTUTIL_NEAR(area, want, 1e-9, 0);
      /* Euler with holes: T = V + 2H - 2... checked by lot_check_constrained; here the count */
      assert_int_equal(r.ntri, G.npts + 2 * nholes - 2);
      free(r.tri);
    }
    geom_pslg_free(&G);
  }
}

/* The rotated grid with segments along its lines: collinear sites on
** segments, cocircular squares; one CDT for every algorithm. */
static void test_cdt_grid(void **state) {
  (void)state;
  rule dt = tc_rule("DT");
  for (uint64_t seed = 1; seed <= 5; seed++) {
    sampler_rng g;
    sampler_seed(&g, seed, 0);
    geom_pslg G;
    assert_int_equal(sampler_pslg_grid(&g, 150, &G), 0);
    tc_result r0 = {0};
    for (int alg = 0; alg < 2; alg++) {
      lot_options o = tc_opts(&dt, alg ? LOT_FLIP : LOT_INCREMENTAL, G.seg, G.nseg);
      o.keep_hull = 1;
      tc_result r = tc_build(G.pts, G.npts, &o);
      if (r.rc != 0) fail_msg("seed %llu: %s", (unsigned long long)seed, r.err);
      tc_checked(G.pts, G.npts, &r, G.seg, G.nseg, &dt);
      if (alg == 0) r0 = r;
      else {
        assert_true(tc_same(&r0, &r));
        free(r.tri);
      }
    }
    free(r0.tri);
    geom_pslg_free(&G);
  }
}

/* The sum of the triangles' areas. */
static double tc_total_area(const geom_point *p, const tc_result *r) {
  double a = 0;
  for (size_t t = 0; t < r->ntri; t++)
    a += tc_area((geom_point[]){p[r->tri[3 * t]], p[r->tri[3 * t + 1]], p[r->tri[3 * t + 2]]}, 3);
  return a;
}

/* A hole touching the outer boundary at one vertex (a vertex of two fans:
** the case the first Euler check got wrong), and nested rings: an island
** inside a hole stays. */
static void test_cdt_pinch_nested(void **state) {
  (void)state;
  rule dt = tc_rule("DT");
  geom_point p[] = {{0, 0}, {6, 0}, {6, 6}, {0, 6}, {4, 2}, {2, 2},        /* outer, hole at 0-1 */
                    {1, 3}, {5, 3}, {5, 5.5}, {1, 5.5}, {2, 4}, {4, 4}, {3, 5}};
  uint32_t seg[] = {0, 1, 1, 2, 2, 3, 3, 0,                /* the outer square */
                    0, 4, 4, 5, 5, 0,                      /* hole triangle 0 4 5 touching it at 0 */
                    6, 7, 7, 8, 8, 9, 9, 6,                /* a second hole */
                    10, 11, 11, 12, 12, 10};               /* an island inside it */
  geom_point holes[] = {{2, 1.5}, {1.5, 3.5}};
  for (int alg = 0; alg < 2; alg++) {
    lot_options o = tc_opts(&dt, alg ? LOT_FLIP : LOT_INCREMENTAL, seg, 14);
    o.holes = holes;
    o.nholes = 2;
    tc_result r = tc_build(p, 13, &o);
    if (r.rc != 0) fail_msg("%s", r.err);
    tc_checked(p, 13, &r, seg, 14, &dt);
    TESTUTIL_NEAR(tc_total_area(p, &r), 36.0 - 2.0 - 10.0 + 1.0, 1e-12, 0);
    assert_int_equal(r.st.holes, 2);
    assert_int_equal(r.st.segments_removed, 0);
    free(r.tri);
  }
}

/* Segments meeting at a shared end at tiny angles (a fan from the origin
** to (10^6, k): angles of 10^-6 radians), a segment through 30 collinear
** points, and random points around: the oracle and the check, for every
** algorithm, the same CDT. */
static void test_cdt_tiny_angles(void **state) {
  (void)state;
  rule dt = tc_rule("DT"), p1 = tc_rule("P_1");
  enum { FAN = 20, ROW = 30, RND = 60, N = 1 + FAN + ROW + RND };
  geom_point p[N];
  uint32_t seg[2 * (FAN + 1)];
  p[0] = (geom_point){0, 0};
  for (int k = 0; k < FAN; k++) {
    p[1 + k] = (geom_point){3e6, 3.0 * (k + 1)};
    seg[2 * k] = 0;
    seg[2 * k + 1] = (uint32_t)(1 + k);
  }
  for (int k = 0; k < ROW; k++) p[1 + FAN + k] = (geom_point){3.0 * 100000 * (k + 1), -3e5};
  seg[2 * FAN] = 1 + FAN;                 /* the row's first point to its last */
  seg[2 * FAN + 1] = FAN + ROW;
  geom_point *r = tc_points(99, RND, 1000000);
  for (int k = 0; k < RND; k++) p[1 + FAN + ROW + k] = (geom_point){r[k].x, r[k].y - 1.5e6};
  free(r);
  tc_result r0 = {0};
  for (int alg = 0; alg < 3; alg++) {
    lot_options o = tc_opts(&dt, (lot_algorithm)alg, seg, FAN + 1);
    o.keep_hull = 1;
    tc_result t = tc_build(p, N, &o);
    if (t.rc != 0) fail_msg("%s", t.err);
    tc_empty_circle(p, N, &t, seg, FAN + 1);
    tc_checked(p, N, &t, seg, FAN + 1, &dt);
    assert_int_equal(t.st.segments_split, 1);
    assert_int_equal(t.st.constrained, FAN + ROW - 1);
    if (alg == 0) r0 = t;
    else {
      assert_true(tc_same(&r0, &t));
      free(t.tri);
    }
  }
  lot_options o = tc_opts(&p1, LOT_INCREMENTAL, seg, FAN + 1);
  o.keep_hull = 1;
  tc_result t = tc_build(p, N, &o);
  assert_int_equal(t.rc, 0);
  tc_checked(p, N, &t, seg, FAN + 1, &p1);
  free(t.tri);
  free(r0.tri);
}

/* Points on segments split them; duplicates and overlaps merge. */
static void test_cdt_split_merge(void **state) {
  (void)state;
  rule dt = tc_rule("DT");
  /* a column of points 0..5 on x = 0, others off it */
  geom_point p[] = {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 4}, {0, 5}, {-3, 2.5}, {3, 2.5},
                    {-2, 0}, {2, 5}, {0, 5}};
  uint32_t seg[] = {0, 5, 1, 3, 5, 0, 6, 8, 2, 10};
  /* 0-5 through 1..4 (split), 1-3 inside it (merged), 5-0 again (merged), 6-8,
     2-10 (10 duplicates 5: merged, split) */
  lot_options o = tc_opts(&dt, LOT_INCREMENTAL, seg, 5);
  o.keep_hull = 1;
  tc_result r = tc_build(p, 11, &o);
  if (r.rc != 0) fail_msg("%s", r.err);
  assert_int_equal(r.st.segments_split, 4);
  assert_int_equal(r.st.segments_merged, 3);
  assert_int_equal(r.st.constrained, 6);   /* five pieces on x = 0, and 6-8 */
  tc_checked(p, 11, &r, seg, 5, &dt);
  free(r.tri);
}

static void tc_refused(const geom_point *p, size_t n, const uint32_t *seg, size_t nseg,
                       const geom_point *holes, size_t nholes, const char *want) {
  rule dt = tc_rule("DT");
  lot_options o = tc_opts(&dt, LOT_INCREMENTAL, seg, nseg);
  o.holes = holes;
  o.nholes = nholes;
  tc_result r = tc_build(p, n, &o);
  assert_int_equal(r.rc, -1);
  if (strchr(r.err, '\n') != NULL || r.err[0] == 0) fail_msg("not one line: '%s'", r.err);
  if (strstr(r.err, want) == NULL) fail_msg("'%s' lacks '%s'", r.err, want);
}

static void test_cdt_refusals(void **state) {
  (void)state;
  geom_point p[] = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 2}, {3, 2}, {2, 1}, {2, 3}};
  uint32_t cross[] = {0, 1, 4, 5, 6, 7};
  tc_refused(p, 8, cross, 3, NULL, 0, "segments 2 (6-7) and 1 (4-5) cross");
  uint32_t range[] = {0, 9};
  tc_refused(p, 8, range, 1, NULL, 0, "segment 0: point index 9 out of range (8 points)");
  uint32_t same[] = {3, 3};
  tc_refused(p, 8, same, 1, NULL, 0, "segment 0: both ends are point 3");
  uint32_t ring[] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5};
  geom_point on[] = {{2, 2}};
  tc_refused(p, 8, ring, 5, on, 1, "hole 0 (2, 2) lies on segment 4 (4-5)");
  geom_point out[] = {{9, 9}};
  tc_refused(p, 8, ring, 5, out, 1, "hole 0 (9, 9) is outside the convex hull");
  geom_point vert[] = {{1, 2}};
  tc_refused(p, 8, ring, 5, vert, 1, "hole 0 (1, 2) is point 4");
  uint32_t open[] = {4, 5};
  tc_refused(p, 8, open, 1, NULL, 0, "no triangle is left");
}

/* A simple polygon as a closed ring of segments: the constrained LOT is a
** triangulation of the polygon, so its total is at least got's GOT total
** (relative tolerance: GOT's kernels differ from measure_eval in the last
** bits, got.h); for rules equal to DT on every quadrilateral it is the CDT,
** and the GOT of the DT-equivalent sum rules is the CDT too. */
static void test_cdt_got(void **state) {
  (void)state;
  static const char *const lower[] = {"P_1", "sigma_1", "-alpha_inf", "R_inf", "a_2"};
  static const char *const equal[] = {"R_1", "-r_1"};
  rule dt = tc_rule("DT");
  size_t checked = 0;
  for (uint64_t seed = 1; seed <= 25; seed++) {
    size_t n = 8 + (size_t)seed % 17;
    geom_point *p = malloc(n * sizeof *p);
    uint32_t *seg = malloc(2 * n * sizeof *seg);
    sampler_rng g;
    sampler_seed(&g, seed, 7);
    assert_int_equal(seed % 2 ? sampler_star(&g, n, p) : sampler_monotone(&g, n, p), 0);
    for (size_t i = 0; i < n; i++) {
      seg[2 * i] = (uint32_t)i;
      seg[2 * i + 1] = (uint32_t)((i + 1) % n);
    }
    lot_options od = tc_opts(&dt, LOT_INCREMENTAL, seg, n);
    tc_result cdt = tc_build(p, n, &od);
    if (cdt.rc != 0) fail_msg("seed %llu: %s", (unsigned long long)seed, cdt.err);
    assert_int_equal(cdt.ntri, n - 2);
    for (size_t k = 0; k < sizeof lower / sizeof *lower + 2; k++) {
      int eq = k >= sizeof lower / sizeof *lower;
      const char *name = eq ? equal[k - sizeof lower / sizeof *lower] : lower[k];
      rule r = tc_rule(name);
      lot_options o = tc_opts(&r, LOT_INCREMENTAL, seg, n);
      tc_result lt = tc_build(p, n, &o);
      assert_int_equal(lt.rc, 0);
      assert_int_equal(lt.ntri, n - 2);
      got_result gr;
      got_options go = {1, RULE_DEFAULT_TIE_EPS};
      char err[256];
      if (got_solve(p, n, &r, &go, &gr, err, sizeof err) != 0) fail_msg("%s", err);
      double *bad = malloc(lt.ntri * sizeof *bad);
      lot_get_badness(p, lt.tri, lt.ntri, &r, bad);
      double key = rule_total_key(&r, bad, lt.ntri);
      if (key < gr.key && rule_gap(&r, key, gr.key) > 1e-9)
        fail_msg("%s seed %llu: LOT key %.17g below GOT %.17g", name, (unsigned long long)seed,
                 key, gr.key);
      if (eq) {
        assert_true(tc_same(&lt, &cdt));   /* the rule is DT on every quadrilateral */
        uint32_t *gt = malloc(3 * gr.ntri * sizeof *gt);
        for (size_t t = 0; t < gr.ntri; t++) {
          gt[3 * t] = (uint32_t)gr.tri[t].i;
          gt[3 * t + 1] = (uint32_t)gr.tri[t].k;
          gt[3 * t + 2] = (uint32_t)gr.tri[t].j;
        }
        lot_diff d;
        assert_int_equal(lot_compare(gt, gr.ntri, lt.tri, lt.ntri, &d), 0);
        if (d.triangles_common != n - 2)
          fail_msg("%s seed %llu: the GOT is not the CDT", name, (unsigned long long)seed);
        free(gt);
      }
      checked++;
      free(bad);
      free(lt.tri);
      got_result_free(&gr);
    }
    free(cdt.tri);
    free(p);
    free(seg);
  }
  assert_int_equal(checked, 25 * 7);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_cdt_oracle),      cmocka_unit_test(test_cdt_rules),
    cmocka_unit_test(test_cdt_unchanged),   cmocka_unit_test(test_cdt_holes),
    cmocka_unit_test(test_cdt_grid),        cmocka_unit_test(test_cdt_split_merge),
    cmocka_unit_test(test_cdt_refusals),    cmocka_unit_test(test_cdt_got),
    cmocka_unit_test(test_cdt_pinch_nested), cmocka_unit_test(test_cdt_tiny_angles),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
