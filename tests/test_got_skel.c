/*
** test_got_skel.c: the skeleton of a point set's GOT (got/got_skel.c) against brute force.
**
** For small point sets (random, random on a small integer grid, full grids, cocircular
** points with rational coordinates, convex position) every triangulation is enumerated
** (classify/siteflip.h) and totalled in key space (rule_key, rule_key_add) for six sum
** rules.  The optimal triangulations are those within a tolerance of the best total far
** above the rounding of a total (so every exact tie is among them) and far below the gaps
** of random data.  Checks: every edge of every optimal triangulation is in the skeleton
** (it never removes a GOT edge, ties included); every CERTAIN edge is in every optimal
** triangulation (for P_1: in every minimum-weight triangulation); hull edges are CERTAIN;
** the skeleton's edges are distinct, ascending and clear of third points.  Also: rules
** that are not sum rules, too many points for an all-pairs rule, and bad input refused.
*/
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "geom.h"
#include "measure.h"
#include "rule.h"
#include "siteflip.h"
#include "sampler.h"
#include "got_skel.h"
#include "testutil.h"

static const char *sk_rules[] = {"P_1", "R_1", "-alpha_1", "a_2", "Pinf_1", "-c/a_1", "P_3",
                                 "-A_1", "-r_1", "R_-1"};
#define SK_NRULES (sizeof sk_rules / sizeof *sk_rules)

/* The key of triangulation u, and the bound below which another total counts as equal:
** 1e-10 of the keys' magnitudes plus 1e-12 a triangle (angles carry absolute errors). */
static double sk_key(const siteflip_graph *g, const rule *r, int u, double *mag) {
  double k = rule_key_identity(r);
  *mag = 0;
  for (int t = 0; t < g->per; t++) {
    double kt = rule_key(r, measure_eval(rule_measure(r), &g->tri[g->node_tri[u * g->per + t]]));
    k = rule_key_add(r, k, kt);
    *mag += fabs(kt);
  }
  return k;
}

static int sk_find(const got_skel *s, int i, int j) {
  for (size_t e = 0; e < s->nedges; e++)
    if ((int)s->edge[2 * e] == i && (int)s->edge[2 * e + 1] == j) return (int)e;
  return -1;
}

static void sk_check_form(const got_skel *s, const geom_point *p, int n) {
  for (size_t e = 0; e < s->nedges; e++) {
    uint32_t a = s->edge[2 * e], b = s->edge[2 * e + 1];
    assert_true(a < b && b < (uint32_t)n);
    if (e > 0) {
      uint32_t a0 = s->edge[2 * e - 2], b0 = s->edge[2 * e - 1];
      assert_true(a0 < a || (a0 == a && b0 < b));
    }
    for (int q = 0; q < n; q++)
      if (q != (int)a && q != (int)b && geom_orient(p[a], p[b], p[q]) == 0)
        assert_false(geom_ahead(p[a], p[b], p[q]) && geom_ahead(p[b], p[a], p[q]));
  }
}

/* The checks above for one set and one rule. */
static void sk_check(const geom_point *p, int n, const siteflip_graph *g, const char *rname) {
  rule r;
  char err[256];
  assert_int_equal(rule_parse(rname, &r, err, sizeof err), 0);
  got_skel s;
  if (got_skel_build(p, (size_t)n, &r, 1, &s, err, sizeof err) != 0) fail_msg("%s", err);
  sk_check_form(&s, p, n);
  double *key = malloc((size_t)g->nnodes * sizeof *key), best = INFINITY, mag = 0, m;
  assert_non_null(key);
  for (int u = 0; u < g->nnodes; u++) {
    key[u] = sk_key(g, &r, u, &m);
    if (key[u] < best) best = key[u], mag = m;
  }
  double tol = 1e-10 * mag + 1e-12 * g->per;
  for (int u = 0; u < g->nnodes; u++) {
    if (!(key[u] <= best + tol)) continue;
    for (int i = 0; i < n; i++)
      for (int j = i + 1; j < n; j++) {
        int has = siteflip_has_edge(g, u, i, j), e = sk_find(&s, i, j);
        if (has && e < 0) fail_msg("%s n=%d: optimal edge %d-%d removed", rname, n, i, j);
        if (!has && e >= 0 && s.state[e] == GOT_EDGE_CERTAIN)
          fail_msg("%s n=%d: certain edge %d-%d not in an optimum", rname, n, i, j);
      }
  }
  free(key);
  got_skel_free(&s);
}

static void sk_check_all(const geom_point *p, int n) {
  char err[256];
  siteflip_graph *g = siteflip_build(p, n, err, sizeof err);
  if (!g) fail_msg("siteflip_build: %s", err);
  for (size_t q = 0; q < SK_NRULES; q++) sk_check(p, n, g, sk_rules[q]);
  siteflip_free(g);
}

/* ---- point sets ---- */

/* The sets siteflip enumerates: no two equal points, not all on one line. */
static int sk_distinct(const geom_point *p, int n) {
  char err[256];
  return siteflip_check(p, n, err, sizeof err) == 0;
}

static void test_random_sets(void **state) {
  (void)state;
  testutil_rng g = {381};
  for (int rep = 0; rep < testutil_reps(600); rep++) {
    int n = 3 + (int)(testutil_next(&g) % 7);
    geom_point p[10];
    for (int i = 0; i < n; i++) p[i] = (geom_point){testutil_uniform(&g), testutil_uniform(&g)};
    if (sk_distinct(p, n)) sk_check_all(p, n);
  }
}

/* Points of a 4 x 4 integer grid: collinear triples, equal lengths and exact ties. */
static void test_grid_subsets(void **state) {
  (void)state;
  testutil_rng g = {382};
  for (int rep = 0; rep < testutil_reps(400); rep++) {
    int n = 4 + (int)(testutil_next(&g) % 6);
    geom_point p[10];
    for (int i = 0; i < n; i++)
      p[i] = (geom_point){(double)(testutil_next(&g) % 4), (double)(testutil_next(&g) % 4)};
    if (sk_distinct(p, n)) sk_check_all(p, n);
  }
}

static void test_grids_and_circles(void **state) {
  (void)state;
  for (int w = 2; w <= 4; w++)
    for (int h = 2; h <= 3; h++) {
      geom_point p[12];
      for (int i = 0; i < w * h; i++) p[i] = (geom_point){i % w, i / w};
      sk_check_all(p, w * h);
    }
  /* twelve points on the circle of radius 5, exactly, in a scrambled order */
  const geom_point c[12] = {{3, 4}, {-5, 0}, {4, -3}, {0, 5}, {-3, -4}, {5, 0},
                            {-4, 3}, {0, -5}, {3, -4}, {-4, -3}, {4, 3}, {-3, 4}};
  for (int n = 4; n <= 9; n++) sk_check_all(c, n);
  geom_point cc[10];
  memcpy(cc, c, 9 * sizeof *c);
  cc[9] = (geom_point){0, 0};
  sk_check_all(cc, 10);
}

static void test_convex_position(void **state) {
  (void)state;
  for (int rep = 0; rep < testutil_reps(200); rep++) {
    int n = 4 + rep % 6;
    geom_point p[10];
    sampler_convex(383, (uint64_t)rep, n, p);
    sk_check_all(p, n);
  }
}

/* ---- the diamond search finds every pair that passes the test ---- */

/* The diamond test by brute force: pairs with a point strictly inside each isosceles
** triangle of base angles pi/8 (plain floating point: the sets below have no point within
** rounding of a triangle's side) or a point on the open segment fail; the others pass. */
static size_t sk_diamond_brute(const geom_point *p, int n) {
  double t8 = tan(M_PI / 8);
  size_t cnt = 0;
  for (int a = 0; a < n; a++)
    for (int b = a + 1; b < n; b++) {
      double ux = p[b].x - p[a].x, uy = p[b].y - p[a].y;
      int l = 0, r = 0, on = 0;
      for (int q = 0; q < n && !(l && r) && !on; q++) {
        if (q == a || q == b) continue;
        double vx = p[q].x - p[a].x, vy = p[q].y - p[a].y;
        double cr = ux * vy - uy * vx, da = ux * vx + uy * vy;
        double db = -(ux * (p[q].x - p[b].x) + uy * (p[q].y - p[b].y));
        on = cr == 0 && da > 0 && db > 0;
        if (fabs(cr) < t8 * da && fabs(cr) < t8 * db) l |= cr > 0, r |= cr < 0;
      }
      cnt += !(l && r) && !on;
    }
  return cnt;
}

/* Point i of diamond-search set `rep`: uniform, a thin strip (boundary effects), clusters,
** a disc, a full 32 x 32 grid (collinear points, exact binary fractions), points hugging
** two sides of the square (sectors reaching the boundary), then a strip of 2000 points
** and tight clusters of 1200 (the far rings read by arcs), then eight sets of seven
** clusters of growing sizes (pairs whose diamond holds a point the search never read:
** accepting a pair on the seen points alone, without its rings read whole, fails here). */
static geom_point sk_diamond_point(int rep, int i, testutil_rng *g) {
  double x = testutil_uniform(g), y = testutil_uniform(g);
  if (rep == 1 || rep == 6) y *= rep == 1 ? 0.05 : 0.02;
  if (rep == 2 || rep == 7) {
    double w = rep == 2 ? 0.1 : 0.02;
    x = w * x + (double)(i % 5) * 0.2, y = w * y + (double)(i % 3) * 0.3;
  }
  if (rep == 3) {
    double t = 2 * M_PI * x, rad = sqrt(y);
    x = rad * cos(t), y = rad * sin(t);
  }
  if (rep == 4) x = (double)(i % 32) / 32, y = (double)(i / 32) / 32;
  if (rep == 5 && i % 3 == 0) y *= 1e-3;
  if (rep == 5 && i % 3 == 1) x *= 1e-3;
  if (rep >= 8) {
    int c = i % 7;
    x = c * 0.15 + 0.003 * x * (c + 1), y = (c % 3) * 0.2 + 0.003 * y * (c + 1);
  }
  return (geom_point){x, y};
}

static void test_diamond_search(void **state) {
  (void)state;
  testutil_rng g = {385};
  rule r;
  char err[256];
  assert_int_equal(rule_parse("P_1", &r, err, sizeof err), 0);
  static geom_point p[2500];
  const int size[16] = {600, 650, 700, 750, 1024, 900, 2000, 1200,
                        640, 660, 680, 700, 720, 740, 760, 780};
  for (int rep = 0; rep < 16; rep++) {
    int n = size[rep];
    for (int i = 0; i < n; i++) p[i] = sk_diamond_point(rep, i, &g);
    got_skel s;
    if (got_skel_build(p, (size_t)n, &r, 2, &s, err, sizeof err) != 0) fail_msg("%s", err);
    assert_int_equal(s.candidates, sk_diamond_brute(p, n));
    got_skel_free(&s);
  }
}

/* ---- the same skeleton for any thread count ---- */

/* 6000 uniform points: about 130,000 candidate edges, so the loop's rounds remove in
** parallel sweeps and gather their queues from several blocks of flags, and the triangles'
** incidence is placed by racing threads; 1, 2 and 3 threads must give the same edges and
** states (the output is the same whatever the thread count), and the same rounds. */
static void test_threads(void **state) {
  (void)state;
  enum { N = 6000 };
  static geom_point p[N];
  testutil_rng g = {386};
  rule r;
  char err[256];
  assert_int_equal(rule_parse("P_1", &r, err, sizeof err), 0);
  for (int i = 0; i < N; i++) p[i] = (geom_point){testutil_uniform(&g), testutil_uniform(&g)};
  got_skel s[3];
  for (int t = 0; t < 3; t++)
    if (got_skel_build(p, N, &r, t + 1, &s[t], err, sizeof err) != 0) fail_msg("%s", err);
  assert_true(s[0].candidates > 65536);
  for (int t = 1; t < 3; t++) {
    assert_int_equal(s[t].nedges, s[0].nedges);
    assert_int_equal(s[t].rounds, s[0].rounds);
    assert_memory_equal(s[t].edge, s[0].edge, 2 * s[0].nedges * sizeof *s[0].edge);
    assert_memory_equal(s[t].state, s[0].state, s[0].nedges);
  }
  for (int t = 0; t < 3; t++) got_skel_free(&s[t]);
}

/* ---- refusals ---- */

static void sk_refuse(const geom_point *p, size_t n, const char *rname) {
  rule r;
  char err[256];
  got_skel s;
  assert_int_equal(rule_parse(rname, &r, err, sizeof err), 0);
  err[0] = 0;
  assert_int_equal(got_skel_build(p, n, &r, 1, &s, err, sizeof err), -1);
  assert_true(strlen(err) > 0 && strchr(err, '\n') == NULL);
  assert_null(s.edge);
}

static void test_refusals(void **state) {
  (void)state;
  geom_point p[300];
  testutil_rng g = {384};
  for (int i = 0; i < 300; i++) p[i] = (geom_point){testutil_uniform(&g), testutil_uniform(&g)};
  const char *nonsum[] = {"P_inf", "-alpha_-inf", "DT", "R_inf"};
  for (size_t q = 0; q < 4; q++) sk_refuse(p, 10, nonsum[q]);
  sk_refuse(p, 300, "R_1");          /* all pairs: too many points */
  sk_refuse(p, 2, "P_1");            /* too few */
  const geom_point line[4] = {{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  sk_refuse(line, 4, "P_1");
  const geom_point dup[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 0}};
  sk_refuse(dup, 4, "P_1");
  /* coordinates outside the contract (the orientations skip the tiny-difference test) */
  const geom_point tiny[4] = {{0, 0}, {1, 0}, {0, 1}, {1e-40, 0.5}};
  sk_refuse(tiny, 4, "P_1");
  const geom_point inf[4] = {{0, 0}, {1, 0}, {0, INFINITY}, {0.5, 0.5}};
  sk_refuse(inf, 4, "-alpha_1");
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_random_sets),
    cmocka_unit_test(test_grid_subsets),
    cmocka_unit_test(test_grids_and_circles),
    cmocka_unit_test(test_convex_position),
    cmocka_unit_test(test_diamond_search),
    cmocka_unit_test(test_threads),
    cmocka_unit_test(test_refusals),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
