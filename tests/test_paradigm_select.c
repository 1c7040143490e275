/*
** test_paradigm_select.c: the selection algorithms of 2.4 (paradigms/select.c).
** On thousands of small sets (uniform, grid draws with duplicates, integer
** points on circles, collinear-heavy) every selection row gives exactly the
** incremental row's triangles for DT and four empty-shape rules, and makes
** 3n - 3 - h edges (Euler, h the sites on the hull); the queue's boundary is
** smaller than the stack's (figure 2.11); the bucket grid examines at most
** the thesis's 2/p + 3/sqrt(p) + 1 buckets per triangle on uniform sites,
** and that expectation itself (Miles' moments and Euler's formula on the
** grid) is what the triangles' circumcircles meet; the strip's bound from
** a rounding shape skips no site that beats the candidate (flat and
** co-hyperbolic sets, every polygon) and keeps its searches near DT's; a
** bad bucket size gets one line.
*/
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "paradigm_internal.h"
#include "lot.h"
#include "testutil.h"

static const char *const ts_rows[] = {"select-stack", "select-queue", "select-strip",
                                      "select-buckets"};
#define TS_ROWS (sizeof ts_rows / sizeof ts_rows[0])

static rule ts_rule(const char *name) {
  rule r;
  char err[256];
  if (rule_parse(name, &r, err, sizeof err) != 0) fail_msg("%s", err);
  return r;
}

/* A small set of family f: 3 .. 30 points. */
static size_t ts_points(int f, testutil_rng *g, geom_point *p) {
  size_t n = 3 + testutil_next(g) % 28, k = 0;
  int side = 2 + (int)(testutil_next(g) % 4);
  switch (f) {
    case 0:   /* uniform */
      for (; k < n; k++) p[k] = (geom_point){testutil_uniform(g), testutil_uniform(g)};
      break;
    case 1:   /* draws from a small grid: duplicates, collinear rows, cocircular squares */
      for (; k < n; k++)
        p[k] = (geom_point){(double)(testutil_next(g) % (uint64_t)side),
                            (double)(testutil_next(g) % (uint64_t)side)};
      break;
    case 2:   /* integer points of x^2 + y^2 = 25 or 50, some twice */
      for (int x = -7; x <= 7; x++)
        for (int y = -7; y <= 7; y++)
          if ((x * x + y * y == 25 || x * x + y * y == 50) && k < n && testutil_next(g) % 3)
            p[k++] = (geom_point){x, y};
      if (k > 0) p[k] = p[0], k++;
      break;
    default:  /* points on two lines and a few off them */
      for (; k < n; k++) {
        double t = (double)(testutil_next(g) % 9);
        uint64_t w = testutil_next(g) % 5;
        p[k] = w < 2 ? (geom_point){t, 0} : w < 4 ? (geom_point){t, t / 2}
                     : (geom_point){testutil_uniform(g) * 8, testutil_uniform(g) * 3};
      }
      break;
  }
  return k;
}

/* One set under rule r: every selection row equals the incremental row
** (both refuse a collinear set alike) and makes 3m - 3 - h edges. */
static void ts_compare(const geom_point *p, size_t n, const rule *r, int f) {
  char err[256];
  paradigm_input in = {.p = p, .n = n, .r = r, .problem = PARADIGM_DELAUNAY, .threads = 1};
  paradigm_result ref;
  int rc = paradigm_run(paradigm_find("incremental"), &in, &ref, err, sizeof err);
  for (size_t i = 0; i < TS_ROWS; i++) {
    paradigm_result res;
    int rs = paradigm_run(paradigm_find(ts_rows[i]), &in, &res, err, sizeof err);
    if (rs != rc) fail_msg("%s, family %d, %s, n %zu: %s", ts_rows[i], f, r->name, n, err);
    if (rc != 0) continue;
    if (res.ntri != ref.ntri || memcmp(res.tri, ref.tri, 3 * ref.ntri * sizeof *ref.tri) != 0)
      fail_msg("%s differs from incremental: family %d, %s, n %zu", ts_rows[i], f, r->name, n);
    size_t m = res.distinct, h = 2 * m - 2 - res.ntri;   /* t = 2m - 2 - h */
    assert_int_equal(res.ops.v[OPS_EDGES_MADE], 3 * m - 3 - h);
    assert_true(res.ops.v[OPS_PEAK_BYTES] <= 8 * (3 * m - 3 - h));
    paradigm_result_free(&res);
  }
  if (rc == 0) paradigm_result_free(&ref);
}

static void test_small_sets(void **state) {
  (void)state;
  const char *rules[] = {"DT", "ES:square", "ES:hexagon", "ES:triangle", "ES:ellipse:2 1 0.5"};
  geom_point p[40];
  testutil_rng g = {2024};
  int sets = testutil_reps(800);
  for (int s = 0; s < sets; s++) {
    int f = s % 4;
    size_t n = ts_points(f, &g, p);
    for (size_t ri = 0; ri < sizeof rules / sizeof rules[0]; ri++) {
      rule r = ts_rule(rules[ri]);
      ts_compare(p, n, &r, f);
    }
  }
}

/* Do the open segments pq and rs cross at one point inside both? */
static int ts_cross(geom_point p, geom_point q, geom_point r, geom_point s) {
  return geom_orient(p, q, r) * geom_orient(p, q, s) < 0
      && geom_orient(r, s, p) * geom_orient(r, s, q) < 0;
}

/* Random segments between the n points, kept when they cross no kept one
** (but sites inside them, collinear overlaps and duplicate ends stay):
** the number of segments, 2 indices each in seg. */
static size_t ts_segments(testutil_rng *g, const geom_point *p, size_t n, uint32_t *seg) {
  size_t ns = 0;
  for (size_t t = 0; t < n; t++) {
    uint32_t i = (uint32_t)(testutil_next(g) % n), j = (uint32_t)(testutil_next(g) % n);
    int ok = i != j;
    for (size_t k = 0; ok && k < ns; k++)
      ok = !ts_cross(p[i], p[j], p[seg[2 * k]], p[seg[2 * k + 1]]);
    if (ok) seg[2 * ns] = i, seg[2 * ns + 1] = j, ns++;
  }
  return ns;
}

/* lot itself on the points as given (duplicates and all, segments naming
** input points) must give what the runner's rows give: the check that the
** runner maps the segments to the distinct points. */
static void ts_lot_direct(const geom_point *p, size_t n, const uint32_t *seg, size_t ns,
                          const rule *r, const paradigm_result *ref) {
  lot_options o;
  lot_options_init(&o, r);
  o.segments = seg, o.nsegments = ns, o.keep_hull = 1;
  lot *L;
  char err[256];
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) fail_msg("lot: %s", err);
  size_t t = lot_get_stats(L)->triangles;
  uint32_t *tri = malloc((3 * t + 1) * sizeof *tri);
  assert_non_null(tri);
  lot_get_triangles(L, tri);
  lot_free(L);
  paradigm_canonical(tri, t);
  assert_int_equal(t, ref->ntri);
  assert_memory_equal(tri, ref->tri, 3 * t * sizeof *tri);
  free(tri);
}

/* 2.4.2: select-constrained gives lot's constrained triangulation (with
** the triangles outside the segments kept) on small sets with random
** segments, for DT and two empty-shape rules, and the runner's rows give
** what lot gives on the points as they are (duplicates among them). */
static void test_constrained(void **state) {
  (void)state;
  const char *rules[] = {"DT", "ES:square", "ES:hexagon"};
  geom_point p[40];
  uint32_t seg[80];
  testutil_rng g = {31};
  char err[256], err2[256];
  int sets = testutil_reps(600), agreed = 0;
  for (int st = 0; st < sets; st++) {
    size_t n = ts_points(st % 4, &g, p), ns = ts_segments(&g, p, n, seg);
    for (size_t ri = 0; ri < sizeof rules / sizeof rules[0]; ri++) {
      rule r = ts_rule(rules[ri]);
      paradigm_input in = {.p = p, .n = n, .r = &r, .problem = PARADIGM_CONSTRAINED,
                           .segments = seg, .nsegments = ns, .threads = 1};
      paradigm_result ref, res;
      int rc = paradigm_run(paradigm_find("incremental"), &in, &ref, err, sizeof err);
      int rs = paradigm_run(paradigm_find("select-constrained"), &in, &res, err2, sizeof err2);
      if (rc != rs) fail_msg("set %d, %s: incremental %s; select-constrained %s", st,
                             rules[ri], rc ? err : "ok", rs ? err2 : "ok");
      if (rc != 0) continue;
      if (res.ntri != ref.ntri || memcmp(res.tri, ref.tri, 3 * ref.ntri * sizeof *ref.tri))
        fail_msg("select-constrained differs from incremental: set %d, %s, %zu segments", st,
                 rules[ri], ns);
      agreed += ns > 0;
      if (ri == 0) ts_lot_direct(p, n, seg, ns, &r, &ref);
      paradigm_result_free(&res), paradigm_result_free(&ref);
    }
  }
  print_message("constrained: %d of %d sets x rules agreed with segments\n", agreed, 3 * sets);
  assert_true(agreed > sets);
}

/* n uniform sites of the unit square. */
static geom_point *ts_uniform(testutil_rng *g, size_t n) {
  geom_point *p = malloc(n * sizeof *p);
  assert_non_null(p);
  for (size_t i = 0; i < n; i++) p[i] = (geom_point){testutil_uniform(g), testutil_uniform(g)};
  return p;
}

static void ts_select(const geom_point *p, size_t n, double param, paradigm_select_order o,
                      paradigm_select_search s, paradigm_output *out,
                      paradigm_select_stats *st) {
  rule dt = ts_rule("DT");
  char err[256];
  paradigm_input in = {.p = p, .n = n, .r = &dt, .problem = PARADIGM_DELAUNAY, .threads = 1,
                       .param = param};
  memset(out, 0, sizeof *out);
  if (paradigm_select_run(&in, o, s, out, st, err, sizeof err) != 0) fail_msg("%s", err);
}

/* Figure 2.11: on uniform sites the queue's boundary (a breadth-first
** walk) is smaller than the stack's, in mean and at its peak; both are
** O(sqrt n) here, far below the n edges a boundary could hold.  The peak
** working memory is the boundary's. */
static void test_boundary(void **state) {
  (void)state;
  testutil_rng g = {77};
  size_t n = 10000;
  geom_point *p = ts_uniform(&g, n);
  paradigm_output os, oq;
  paradigm_select_stats ss, sq;
  ts_select(p, n, 0, PARADIGM_SELECT_STACK, PARADIGM_SELECT_BUCKETS, &os, &ss);
  ts_select(p, n, 0, PARADIGM_SELECT_QUEUE, PARADIGM_SELECT_BUCKETS, &oq, &sq);
  print_message("boundary, %zu uniform sites: stack mean %.1f peak %zu, queue mean %.1f "
                "peak %zu\n", n, ss.mean_boundary, ss.peak_boundary, sq.mean_boundary,
                sq.peak_boundary);
  assert_true(sq.mean_boundary < ss.mean_boundary);
  assert_true(sq.peak_boundary < ss.peak_boundary);
  assert_true(ss.peak_boundary < 40 * sqrt((double)n));
  assert_int_equal(os.ops.v[OPS_PEAK_BYTES], 8 * ss.peak_boundary);
  assert_int_equal(os.ntri, oq.ntri);
  assert_int_equal(os.ntri, 2 * n - 2 - ss.hull);
  free(os.tri), free(oq.tri), free(p);
}

/* The grid cells of side w (an infinite grid anchored at 0) that a disc
** of centre (x, y) and radius r meets: closed cells, as the algorithm's. */
static size_t ts_cells_met(double x, double y, double r, double w) {
  size_t k = 0;
  for (double i = floor((x - r) / w); i * w <= x + r; i++)
    for (double j = floor((y - r) / w); j * w <= y + r; j++) {
      double dx = fmax(fmax(i * w - x, x - (i + 1) * w), 0);
      double dy = fmax(fmax(j * w - y, y - (j + 1) * w), 0);
      k += dx * dx + dy * dy <= r * r;
    }
  return k;
}

/* The mean number of cells of side sqrt(p / n) met by the circumdiscs of
** the triangles whose circumcentre lies in [0.2, 0.8]^2 (far from the
** square's sides, where the sites look like a Poisson process of p sites
** per cell). */
static double ts_disc_cells(const geom_point *p, size_t n, const uint32_t *tri, size_t ntri,
                            double prm) {
  double w = sqrt(prm / (double)n), sum = 0;
  size_t used = 0;
  for (size_t t = 0; t < ntri; t++) {
    geom_point a = p[tri[3 * t]], b = p[tri[3 * t + 1]], c = p[tri[3 * t + 2]];
    double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
    double d = 2 * (bx * cy - by * cx), b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    double ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
    double x = a.x + ux, y = a.y + uy;
    if (x < 0.2 || x > 0.8 || y < 0.2 || y > 0.8) continue;
    sum += (double)ts_cells_met(x, y, hypot(ux, uy), w);
    used++;
  }
  return sum / (double)used;
}

/* Mean and standard error of v[0 .. k-1]. */
static void ts_mean_se(const double *v, int k, double *mean, double *se) {
  double s = 0, q = 0;
  for (int i = 0; i < k; i++) s += v[i];
  *mean = s / k;
  for (int i = 0; i < k; i++) q += (v[i] - *mean) * (v[i] - *mean);
  *se = k > 1 ? sqrt(q / (k - 1) / k) : 0;
}

/* Section 2.4.1: a Delaunay circumdisc of radius R meets pi R^2 + 4R + 1
** cells on average over the grid's offset (Euler's formula on the cells
** it cuts), and Miles' moments E[R^k] = Gamma(k/2 + 2) / (pi p)^{k/2} (R
** in cell sides) give b(p) = 2/p + 3/sqrt(p) + 1.  Checked twice on
** uniform sites, n = 20,000, with the standard error over repeated runs:
** the circumdiscs meet b(p) cells within 4 standard errors and 2% (the
** finite sample against the Poisson process), and the bucket search
** examines at most b(p) per triangle (its stopping rule: the cells meeting
** the shrinking caps, never the whole final disc) and, on these sizes, more
** than 0.85 b(p) (the earlier, larger caps). */
static void test_bucket_formula(void **state) {
  (void)state;
  const double ps[] = {0.5, 1, 2, 4};
  int runs = testutil_reps(8) < 3 ? 3 : testutil_reps(8);
  size_t n = 20000;
  testutil_rng g = {4242};
  for (size_t k = 0; k < sizeof ps / sizeof ps[0]; k++) {
    double prm = ps[k], b = 2 / prm + 3 / sqrt(prm) + 1, seen[8], cells[8];
    for (int run = 0; run < runs; run++) {
      geom_point *p = ts_uniform(&g, n);
      paradigm_output o;
      ts_select(p, n, prm, PARADIGM_SELECT_STACK, PARADIGM_SELECT_BUCKETS, &o, NULL);
      seen[run] = (double)o.ops.v[OPS_BUCKETS] / (double)o.ntri;
      cells[run] = ts_disc_cells(p, n, o.tri, o.ntri, prm);
      free(o.tri), free(p);
    }
    double ms, ses, mc, sec;
    ts_mean_se(seen, runs, &ms, &ses);
    ts_mean_se(cells, runs, &mc, &sec);
    print_message("p %.2f: b(p) %.3f, discs meet %.3f +- %.3f, buckets examined %.3f +- %.3f\n",
                  prm, b, mc, sec, ms, ses);
    TESTUTIL_NEAR(mc, b, 0.02, 4 * sec);
    assert_true(ms <= b + 4 * ses);
    assert_true(ms >= 0.85 * b);
  }
}

/* Larger sets: every row but the quadratic scans equals the incremental,
** for DT also at the ends of the coordinate contract and far from the
** origin (the floating-point bounds of the strip and the grid scale with
** them), and for three empty-shape rules (the homothets and the rounding
** shapes' cones and hyperbolas), tiny, far out and huge too. */
static void test_large(void **state) {
  (void)state;
  const double scale[] = {1, 0x1p-40, 0x1p90, 1, 1, 1, 1, 0x1p-40, 1, 0x1p60};
  const double shift[] = {0, 0, 0, 1e6, 0, 0, 0, 0, 1e6, 0};
  const char *rules[] = {"DT", "DT", "DT", "DT", "ES:square", "ES:hexagon", "ES:triangle",
                         "ES:triangle", "ES:hexagon", "ES:ngon:5"};
  testutil_rng g = {5};
  char err[256];
  for (size_t k = 0; k < sizeof scale / sizeof scale[0]; k++) {
    size_t n = k < 7 ? 8000 : 2000;   /* the scaled ES sets: the strip scans far for cones */
    rule dt = ts_rule(rules[k]);
    geom_point *p = ts_uniform(&g, n);
    for (size_t i = 0; i < n / 4; i++) p[i].x = p[i].y;    /* a diagonal of collinear sites */
    for (size_t i = 0; i < n; i++)
      p[i] = (geom_point){p[i].x * scale[k] + shift[k], p[i].y * scale[k] + shift[k]};
    paradigm_input in = {.p = p, .n = n, .r = &dt, .problem = PARADIGM_DELAUNAY, .threads = 1};
    paradigm_result ref, res;
    assert_int_equal(paradigm_run(paradigm_find("incremental"), &in, &ref, err, sizeof err), 0);
    for (size_t i = 2; i < TS_ROWS; i++) {
      if (paradigm_run(paradigm_find(ts_rows[i]), &in, &res, err, sizeof err) != 0)
        fail_msg("%s", err);
      assert_int_equal(res.ntri, ref.ntri);
      assert_memory_equal(res.tri, ref.tri, 3 * ref.ntri * sizeof *ref.tri);
      paradigm_result_free(&res);
    }
    paradigm_result_free(&ref);
    free(p);
  }
}

/* The bucket search stays O(1) per triangle for the polygons whose
** rounding shapes reach far (a flat hyperbola near the hull: its cone
** covered the whole grid, and the buckets per triangle grew with n, from
** 8.1 to 15.3 for ES:hexagon between 10^4 and 10^5 sites): on uniform
** sites the count at 32,000 sites is within 10% of that at 2,000 (it falls
** as the hull's share does), and the triangles are the incremental row's. */
static void test_bucket_rounding(void **state) {
  (void)state;
  const char *rules[] = {"ES:hexagon", "ES:triangle", "ES:diamond", "ES:ngon:5"};
  const size_t sizes[2] = {2000, 32000};
  testutil_rng g = {808};
  char err[256];
  for (size_t k = 0; k < sizeof rules / sizeof rules[0]; k++) {
    rule r = ts_rule(rules[k]);
    double per[2];
    for (int j = 0; j < 2; j++) {
      geom_point *p = ts_uniform(&g, sizes[j]);
      paradigm_input in = {.p = p, .n = sizes[j], .r = &r, .problem = PARADIGM_DELAUNAY,
                           .threads = 1};
      paradigm_result ref, res;
      if (paradigm_run(paradigm_find("incremental"), &in, &ref, err, sizeof err) != 0
          || paradigm_run(paradigm_find("select-buckets"), &in, &res, err, sizeof err) != 0)
        fail_msg("%s: %s", rules[k], err);
      testutil_same_tri(ref.tri, ref.ntri, res.tri, res.ntri, rules[k]);
      per[j] = (double)res.ops.v[OPS_BUCKETS] / (double)res.ntri;
      paradigm_result_free(&ref), paradigm_result_free(&res);
      free(p);
    }
    print_message("%s: buckets per triangle %.3f at %zu sites, %.3f at %zu\n", rules[k], per[0],
                  sizes[0], per[1], sizes[1]);
    assert_true(per[1] <= 1.1 * per[0]);
  }
}

/* Flat sets of 3 to 120 sites, where the rounding shapes reach far and the
** strip's bound from them is tested at its edge: f 0, a band 2^-20 high;
** 1, integer points of a parabola (all on the hull) and sometimes one
** inside; 2, integer points of the hyperbolas x y = +-12, +-24 and x^2 -
** y^2 = +-15, +-48 (the rounding shapes of the square's and the diamond's
** corners, four sites on one of them a tie); 3, two flat clusters 64 apart;
** 4, two rows of integers and one far site above or beside them. */
static size_t ts_flat(int f, testutil_rng *g, geom_point *p) {
  size_t n = 3 + testutil_next(g) % 118, k = 0;
  for (; f == 2 && k < n; k++) {
    double x = (double)(testutil_next(g) % 97) - 48, y = (double)(testutil_next(g) % 97) - 48;
    double xy = fabs(x * y), d = fabs(x * x - y * y);
    if (xy != 12 && xy != 24 && d != 15 && d != 48 && testutil_next(g) % 8) k--;
    else p[k] = (geom_point){x, y};
  }
  for (; k < n; k++) {
    double u = testutil_uniform(g), w = testutil_uniform(g);
    double i = (double)(testutil_next(g) % 300), j = (double)(testutil_next(g) % 2);
    p[k] = f == 0 ? (geom_point){u, w * 0x1p-20}
         : f == 1 ? (geom_point){fmod(i, 64), fmod(i, 64) * fmod(i, 64)}
         : f == 3 ? (geom_point){u + (k % 2 ? 64 : 0), w * 0x1p-10}
                  : (geom_point){i, j};
  }
  if (f == 1 && n % 2) p[0] = (geom_point){31.5, 1200};
  if (f == 4) p[0] = n % 2 ? (geom_point){150, 1e4} : (geom_point){-1e4, 0.5};
  return n;
}

/* select-strip, whose bound from a rounding shape is the shape inside the
** sites' box, against the unbounded scan (select-stack) and the
** incremental row, under every polygon of docs/emptyshape.md's kinds
** (regular with 3 to 40 sides, the square's and the diamond's axis-aligned
** corners, a skew quadrilateral): on the flat sets above, where a bound
** too tight would skip a site that beats the candidate, and on the six
** families of testutil_family (grids, cocircular and collinear sets). */
static void test_strip_rounding(void **state) {
  (void)state;
  static const char *const shapes[] = {"ES:square", "ES:diamond", "ES:triangle", "ES:hexagon",
                                       "ES:octagon", "ES:ngon:5", "ES:ngon:7", "ES:ngon:40",
                                       "ES:poly:0 0;3 -1;4 2;1 3"};
  const char *rows[] = {"select-stack", "select-strip"};
  geom_point p[120];
  testutil_rng g = {1994};
  char err[256], what[160];
  int sets = testutil_reps(990), compared = 0;
  for (int t = 0; t < sets; t++) {
    rule r = ts_rule(shapes[t % 9]);
    int f = t / 9 % 11;
    size_t n = f < 5 ? ts_flat(f, &g, p) : testutil_family(f - 5, 3 + testutil_next(&g) % 60,
                                                            &g, p);
    paradigm_input in = {.p = p, .n = n, .r = &r, .problem = PARADIGM_DELAUNAY, .threads = 1};
    paradigm_result ref, res;
    if (paradigm_run(paradigm_find("incremental"), &in, &ref, err, sizeof err) != 0) continue;
    for (int i = 0; i < 2; i++) {
      snprintf(what, sizeof what, "%s, %s, family %d, n %zu, set %d", rows[i], shapes[t % 9],
               f, n, t);
      if (paradigm_run(paradigm_find(rows[i]), &in, &res, err, sizeof err) != 0)
        fail_msg("%s: %s", what, err);
      testutil_same_tri(ref.tri, ref.ntri, res.tri, res.ntri, what);
      paradigm_result_free(&res);
    }
    paradigm_result_free(&ref);
    compared++;
  }
  assert_true(compared > sets * 9 / 10);
}

/* The strip's bound from a rounding shape keeps its searches about as
** short as DT's: on the same 10,000 uniform sites it tries at most 1.4
** times DT's sites per triangle for the polygons whose rounding shapes
** reach far (1.03 to 1.23 times; without the bound 1.56 to 2.27), and its
** triangles are the incremental row's. */
static void test_strip_cost(void **state) {
  (void)state;
  const char *rules[] = {"DT", "ES:hexagon", "ES:triangle", "ES:diamond", "ES:ngon:5"};
  size_t n = 10000;
  testutil_rng g = {1311};
  geom_point *p = ts_uniform(&g, n);
  double dt = 0;
  char err[256];
  for (size_t k = 0; k < sizeof rules / sizeof rules[0]; k++) {
    rule r = ts_rule(rules[k]);
    paradigm_input in = {.p = p, .n = n, .r = &r, .problem = PARADIGM_DELAUNAY, .threads = 1};
    paradigm_output o;
    paradigm_select_stats st;
    paradigm_result ref;
    memset(&o, 0, sizeof o);
    if (paradigm_select_run(&in, PARADIGM_SELECT_STACK, PARADIGM_SELECT_STRIP, &o, &st, err,
                            sizeof err) != 0
        || paradigm_run(paradigm_find("incremental"), &in, &ref, err, sizeof err) != 0)
      fail_msg("%s: %s", rules[k], err);
    paradigm_canonical(o.tri, o.ntri);
    testutil_same_tri(ref.tri, ref.ntri, o.tri, o.ntri, rules[k]);
    double per = (double)st.examined / (double)o.ntri;
    if (k == 0) dt = per;
    print_message("strip, %s: %.1f sites tried per triangle (DT's times %.3f)\n", rules[k], per,
                  per / dt);
    assert_true(per <= 1.4 * dt);
    free(o.tri), paradigm_result_free(&ref);
  }
  free(p);
}

static void test_bad_param(void **state) {
  (void)state;
  geom_point p[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  rule dt = ts_rule("DT");
  char err[256];
  paradigm_result res;
  const double bad[] = {-1, 1e9, 0.01, NAN};
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    paradigm_input in = {.p = p, .n = 4, .r = &dt, .problem = PARADIGM_DELAUNAY, .threads = 1,
                         .param = bad[i]};
    assert_int_equal(paradigm_run(paradigm_find("select-buckets"), &in, &res, err, sizeof err),
                     -1);
    assert_non_null(strstr(err, "bucket size"));
    assert_null(strchr(err, '\n'));
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_small_sets),
    cmocka_unit_test(test_constrained),
    cmocka_unit_test(test_boundary),
    cmocka_unit_test(test_bucket_formula),
    cmocka_unit_test(test_large),
    cmocka_unit_test(test_bucket_rounding),
    cmocka_unit_test(test_strip_rounding),
    cmocka_unit_test(test_strip_cost),
    cmocka_unit_test(test_bad_param),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
