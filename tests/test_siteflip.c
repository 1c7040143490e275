/*
** test_siteflip.c: the triangulations and flip graphs of small site sets.
** Counts against Catalan numbers and against an independent brute force
** (every maximal non-crossing set of segments, in integer arithmetic, on
** integer sites that include collinear triples); thesis figure 3.8; the
** DT-equivalent rules; triangle rules never cycle; the best sink is the
** GOT of `got` for convex polygons and the GOT itself is a sink for the
** joints -1, 0, 1, 2; bad site sets are refused with one line.
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
#include "measure.h"
#include "rule.h"
#include "sampler.h"
#include "siteflip.h"
#include "testutil.h"

static siteflip_graph *tsf_build(const geom_point *p, int n) {
  char err[256];
  siteflip_graph *g = siteflip_build(p, n, err, sizeof err);
  if (g == NULL) fail_msg("siteflip_build: %s", err);
  return g;
}

static rule tsf_rule(const char *name) {
  rule r;
  char err[4096];
  if (rule_parse(name, &r, err, sizeof err) != 0) fail_msg("%s: %s", name, err);
  return r;
}

/* ---- counts ------------------------------------------------------------- */

static void test_catalan(void **state) {
  (void)state;
  long cat[13] = {1, 1, 2, 5, 14, 42, 132, 429, 1430, 4862, 16796, 58786, 208012};
  for (int n = 3; n <= 12; n++) {
    geom_point p[12];
    sampler_convex(7, (uint64_t)n, n, p);
    siteflip_graph *g = tsf_build(p, n);
    assert_int_equal(g->nnodes, cat[n - 2]);
    assert_int_equal(g->per, n - 2);
    assert_int_equal(g->ntris, n * (n - 1) * (n - 2) / 6);
    /* every triangulation has n - 3 diagonals, each flippable */
    assert_int_equal(g->nedges, cat[n - 2] * (n - 3) / 2);
    assert_int_equal(g->nquads, n < 4 ? 0 : n * (n - 1) * (n - 2) * (n - 3) / 24);
    siteflip_free(g);
  }
}

static void test_quad_with_interior_site(void **state) {
  (void)state;
  geom_point p[5] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.45, 0.4}};
  siteflip_graph *g = tsf_build(p, 5);
  assert_int_equal(g->nnodes, 3);
  assert_int_equal(g->nedges, 2);
  assert_int_equal(g->per, 4);
  siteflip_free(g);
  /* on the diagonal: the diagonal is blocked, one triangulation (the star) */
  geom_point c[5] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
  g = tsf_build(c, 5);
  assert_int_equal(g->nnodes, 1);
  assert_int_equal(g->nedges, 0);
  siteflip_free(g);
}

/* Independent brute force, integer sites: every set of valid segments with
** no proper crossing, by backtracking over segments, counted when maximal. */
typedef struct tsf_bf {
  int n, nseg, a[28], b[28];
  long long x[8], y[8];
  int cross[28][28];
  int chosen[28];
  long count;
} tsf_bf;

static long long tsf_orient(const tsf_bf *s, int i, int j, int k) {
  long long d = (s->x[j] - s->x[i]) * (s->y[k] - s->y[i]) - (s->y[j] - s->y[i]) * (s->x[k] - s->x[i]);
  return (d > 0) - (d < 0);
}

static int tsf_inside(const tsf_bf *s, int i, int j, int k) {
  if (tsf_orient(s, i, j, k) != 0) return 0;
  long long lx = s->x[i] < s->x[j] ? s->x[i] : s->x[j], hx = s->x[i] ^ s->x[j] ^ lx;
  long long ly = s->y[i] < s->y[j] ? s->y[i] : s->y[j], hy = s->y[i] ^ s->y[j] ^ ly;
  return lx <= s->x[k] && s->x[k] <= hx && ly <= s->y[k] && s->y[k] <= hy;
}

static void tsf_bf_walk(tsf_bf *s, int at) {
  if (at == s->nseg) {
    for (int t = 0; t < s->nseg; t++) {
      if (s->chosen[t]) continue;
      int free_ = 1;
      for (int u = 0; u < s->nseg && free_; u++) free_ = !(s->chosen[u] && s->cross[t][u]);
      if (free_) return;   /* t could be added: not maximal */
    }
    s->count++;
    return;
  }
  int ok = 1;
  for (int u = 0; u < at && ok; u++) ok = !(s->chosen[u] && s->cross[at][u]);
  if (ok) {
    s->chosen[at] = 1;
    tsf_bf_walk(s, at + 1);
    s->chosen[at] = 0;
  }
  tsf_bf_walk(s, at + 1);
}

static long tsf_brute(const geom_point *p, int n) {
  tsf_bf *s = calloc(1, sizeof *s);
  s->n = n;
  for (int i = 0; i < n; i++) {
    s->x[i] = (long long)p[i].x;
    s->y[i] = (long long)p[i].y;
  }
  for (int i = 0; i < n; i++)
    for (int j = i + 1; j < n; j++) {
      int ok = 1;
      for (int k = 0; k < n; k++) ok &= k == i || k == j || !tsf_inside(s, i, j, k);
      if (!ok) continue;   /* a site on it: never an edge */
      s->a[s->nseg] = i;
      s->b[s->nseg++] = j;
    }
  for (int t = 0; t < s->nseg; t++)
    for (int u = 0; u < s->nseg; u++) {
      int i = s->a[t], j = s->b[t], k = s->a[u], l = s->b[u];
      s->cross[t][u] = i != k && i != l && j != k && j != l &&
                       tsf_orient(s, i, j, k) * tsf_orient(s, i, j, l) < 0 &&
                       tsf_orient(s, k, l, i) * tsf_orient(s, k, l, j) < 0;
    }
  tsf_bf_walk(s, 0);
  long c = s->count;
  free(s);
  return c;
}

static void test_brute_force(void **state) {
  (void)state;
  testutil_rng r = {4242};
  int sets = 0, collinear_sets = 0;
  while (sets < 300) {
    int n = 4 + (int)(testutil_next(&r) % 5);   /* 4 .. 8 */
    geom_point p[8];
    for (int i = 0; i < n; i++)
      p[i] = (geom_point){(double)(testutil_next(&r) % 7), (double)(testutil_next(&r) % 7)};
    char err[256];
    if (siteflip_check(p, n, err, sizeof err) != 0) continue;   /* duplicates, all collinear */
    sets++;
    int col = 0;
    for (int i = 0; i < n; i++)
      for (int j = i + 1; j < n; j++)
        for (int k = j + 1; k < n; k++) col |= geom_orient(p[i], p[j], p[k]) == 0;
    collinear_sets += col;
    siteflip_graph *g = tsf_build(p, n);
    long want = tsf_brute(p, n);
    if (g->nnodes != want) {
      for (int i = 0; i < n; i++) print_error("(%g,%g) ", p[i].x, p[i].y);
      fail_msg("siteflip %d triangulations, brute force %ld", g->nnodes, want);
    }
    /* every node distinct, every flip joins nodes differing in one edge */
    for (int e = 0; e < g->nedges; e++) {
      siteflip_mask a = g->node[g->edge[e].ac], b = g->node[g->edge[e].bd];
      int d = __builtin_popcountll(a.lo ^ b.lo) + __builtin_popcountll(a.hi ^ b.hi);
      assert_int_equal(d, 2);
    }
    siteflip_free(g);
  }
  print_message("300 integer site sets, %d with collinear triples\n", collinear_sets);
  assert_true(collinear_sets > 50);
}

/* ---- directed graphs ------------------------------------------------------ */

static double tsf_neg_R(const geom_tri *t, void *ctx) {
  (void)ctx;
  return -t->R;
}

static void test_figure_3_8(void **state) {
  (void)state;
  geom_point p[5] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.45, 0.4}};
  siteflip_graph *g = tsf_build(p, 5);
  assert_true(g->delaunay >= 0);
  /* the star (site 5 joined to all four corners) is Delaunay */
  int star = -1;
  for (int u = 0; u < g->nnodes; u++) {
    int deg = 0;
    for (int k = 0; k < 4; k++) deg += siteflip_has_edge(g, u, k, 4);
    if (deg == 4) star = u;
  }
  assert_int_equal(g->delaunay, star);
  rule_choice dec[8];
  int sinks[3];
  siteflip_result res;
  rule r1 = tsf_rule("R_1");
  assert_int_equal(siteflip_direct(g, &r1, RULE_DEFAULT_TIE_EPS, dec, sinks, &res), 0);
  assert_int_equal(res.nsinks, 1);
  assert_int_equal(sinks[0], star);
  assert_int_equal(res.sink_dt, 1);
  assert_int_equal(res.ties, 0);
  measure m = {"tsfnegR", "-R", "minus the circumradius", MEASURE_NONPOS, tsf_neg_R, NULL};
  assert_true(measure_register(&m) >= 0);
  rule nr = tsf_rule("tsfnegR_1");
  assert_int_equal(siteflip_direct(g, &nr, RULE_DEFAULT_TIE_EPS, dec, sinks, &res), 0);
  assert_int_equal(res.nsinks, 2);
  assert_true(sinks[0] != star && sinks[1] != star);
  assert_int_equal(res.nsources, 1);
  assert_int_equal(res.sink_dt, -1);
  assert_int_equal(res.cycle, 0);
  measure_unregister_user();
  siteflip_free(g);
}

static const char *const tsf_dt_rules[] = {"DT", "R_-inf", "R_-1", "R_0", "R_1", "R_2", "R_inf",
                                          "-alpha_inf", "-r_1", "abc_1", "-r/R_1", "-r2/A_0"};
#define TSF_NDT (int)(sizeof tsf_dt_rules / sizeof tsf_dt_rules[0])

static void test_dt_equivalent(void **state) {
  (void)state;
  rule rules[TSF_NDT];
  for (int i = 0; i < TSF_NDT; i++) rules[i] = tsf_rule(tsf_dt_rules[i]);
  int checked = 0;
  for (int kind = 0; kind < SAMPLER_SITES_COUNT; kind++)
    for (int n = 4; n <= 8; n++)
      for (uint64_t s = 0; s < 40; s++) {
        geom_point p[8];
        assert_int_equal(sampler_sites(kind, 99, s, n, p), 0);
        siteflip_graph *g = tsf_build(p, n);
        rule_choice *dec = malloc((size_t)(g->nquads + 1) * sizeof *dec);
        int *sinks = malloc((size_t)g->nnodes * sizeof *sinks);
        for (int i = 0; i < TSF_NDT; i++) {
          siteflip_result res;
          assert_int_equal(siteflip_direct(g, &rules[i], RULE_DEFAULT_TIE_EPS, dec, sinks, &res), 0);
          if (res.ties) continue;
          if (res.nsinks != 1 || res.sink_dt != 1)
            fail_msg("%s on %s set %d/%llu: %d sinks, sink is DT %d", tsf_dt_rules[i],
                     sampler_sites_name(kind), n, (unsigned long long)s, res.nsinks, res.sink_dt);
          checked++;
        }
        free(dec);
        free(sinks);
        siteflip_free(g);
      }
  assert_true(checked > SAMPLER_SITES_COUNT * 5 * 40 * TSF_NDT * 9 / 10);
}

/* Every triangle rule on small sets: never a cycle, never no sink; for
** convex sets the best sink's total is GOT's (as `got` computes it), and
** for the joints -1, 0, 1, 2 the GOT itself is a sink. */
static void test_triangle_rules(void **state) {
  (void)state;
  int ids[MEASURE_BUILTIN_COUNT];
  for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++) ids[m] = m;
  rule rules[MEASURE_BUILTIN_COUNT * JOINT_COUNT];
  int nr = rule_list_triangle(ids, MEASURE_BUILTIN_COUNT, rules, MEASURE_BUILTIN_COUNT * JOINT_COUNT);
  assert_true(nr >= 120);
  int got_checked = 0;
  for (int kind = 0; kind < SAMPLER_SITES_COUNT; kind++)
    for (int n = 5; n <= 7; n++)
      for (uint64_t s = 0; s < 6; s++) {
        geom_point p[7];
        assert_int_equal(sampler_sites(kind, 5, s, n, p), 0);
        siteflip_graph *g = tsf_build(p, n);
        rule_choice *dec = malloc((size_t)g->nquads * sizeof *dec);
        int *sinks = malloc((size_t)g->nnodes * sizeof *sinks);
        for (int i = 0; i < nr; i++) {
          siteflip_result res;
          assert_int_equal(siteflip_direct(g, &rules[i], RULE_DEFAULT_TIE_EPS, dec, sinks, &res), 0);
          assert_int_equal(res.cycle, 0);
          assert_true(res.nsinks >= 1);
          assert_true(res.has_got);
          if (kind != SAMPLER_SITES_CONVEX || res.ties) continue;
          /* best sink = GOT */
          double best = INFINITY;
          for (int k = 0; k < res.nsinks; k++) {
            double key = siteflip_node_key(g, &rules[i], sinks[k]);
            if (key < best) best = key;
          }
          assert_true(best == siteflip_node_key(g, &rules[i], res.got_node));
          got_options o = {1, RULE_DEFAULT_TIE_EPS};
          got_result gr;
          char err[256];
          assert_int_equal(got_solve(p, (size_t)n, &rules[i], &o, &gr, err, sizeof err), 0);
          TESTUTIL_NEAR(res.got_total, gr.total, 1e-12, 1e-300);
          got_result_free(&gr);
          got_checked++;
          joint_id j = rules[i].joint;
          if (j == JOINT_HARMONIC || j == JOINT_PRODUCT || j == JOINT_SUM || j == JOINT_RSS) {
            int is_sink = 0;
            for (int k = 0; k < res.nsinks; k++) is_sink |= sinks[k] == res.got_node;
            if (!is_sink) fail_msg("%s: GOT is not a sink", rules[i].name);
          }
        }
        free(dec);
        free(sinks);
        siteflip_free(g);
      }
  assert_true(got_checked > 3 * 6 * 100);
}

static void test_bad_input(void **state) {
  (void)state;
  char err[256];
  geom_point dup[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 0}};
  assert_int_not_equal(siteflip_check(dup, 4, err, sizeof err), 0);
  assert_non_null(strstr(err, "sites 2 and 4 are equal"));
  geom_point line[4] = {{0, 0}, {1, 1}, {2, 2}, {5, 5}};
  assert_int_not_equal(siteflip_check(line, 4, err, sizeof err), 0);
  assert_non_null(strstr(err, "collinear"));
  geom_point many[13];
  for (int i = 0; i < 13; i++) many[i] = (geom_point){cos(i), sin(i)};
  assert_null(siteflip_build(many, 13, err, sizeof err));
  assert_non_null(strstr(err, "limited to 12"));
  geom_point nan_[3] = {{0, 0}, {NAN, 0}, {0, 1}};
  assert_int_not_equal(siteflip_check(nan_, 3, err, sizeof err), 0);
  assert_non_null(strstr(err, "site 2"));
  assert_int_not_equal(siteflip_check(nan_, 2, err, sizeof err), 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_catalan),
    cmocka_unit_test(test_quad_with_interior_site),
    cmocka_unit_test(test_brute_force),
    cmocka_unit_test(test_figure_3_8),
    cmocka_unit_test(test_dt_equivalent),
    cmocka_unit_test(test_triangle_rules),
    cmocka_unit_test(test_bad_input),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
