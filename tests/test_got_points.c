/*
** test_got_points.c: the GOT of a point set (got_points_solve, got/got_points.c) against
** independent checks.
**
** - Enumeration: for every n <= 9 (and 10 on a few sets) on random (disc, square),
**   convex, grid (subsets of a 4 x 4 integer grid: collinear triples everywhere) and
**   cocircular sets (subsets of the 12 integer points of the circle of radius 5, with its
**   centre), every triangulation is enumerated (classify/siteflip.h) and keyed by the rule
**   (siteflip_node_key, from measure_eval); for nine sum rules and both skeletons the
**   returned triangles are one of those triangulations, its key and the optimum's agree
**   with the smallest enumerated key (relative 1e-9: the DP keys come from kernels that
**   differ from measure_eval in the last bits), the runner-up of the trivial skeleton is
**   the second smallest key, and the certified verdict never says unique when the
**   enumeration has two optima within 1e-9 (ties: -A_1 ties every triangulation, grids
**   and the circle tie P_1), and says it for P_1 whenever the enumeration's gap is above
**   1e-6.  The LOT of the same points (incremental) never totals less than the GOT.  The
**   eight rules whose GOT is Delaunay also run through study_got_points (the skeleton
**   "delaunay"): the least key, never "unique" where two optima tie.
** - Convex position: the GOT equals got_solve of the hull polygon bit for bit (key,
**   runner-up, certificate, triangles) for every rule.
** - The result does not depend on the thread count, bit for bit.
** - Bad input: a non-sum rule, duplicates (both rows named), collinear points, fewer than
**   three, a coordinate outside the contract, a bad thread count or skeleton: one line,
**   the same through study_got_points (which checks the points once for the rules whose
**   GOT is Delaunay); got_points_solve_checked keeps the options' refusals.
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
#include "sampler.h"
#include "siteflip.h"
#include "study.h"
#include "testutil.h"

#define TGP_REL 1e-9

static const char *const tgp_rules[] = {"P_1", "a_2", "-A_1", "Rinf_1", "sigma_2", "-c_0",
                                        "P_-1", "-alpha_1", "abc_1"};
#define TGP_NRULES (sizeof tgp_rules / sizeof *tgp_rules)

static rule tgp_rule(const char *name) {
  rule r;
  char err[256];
  assert_int_equal(rule_parse(name, &r, err, sizeof err), 0);
  return r;
}

/* The node of g whose edges are the triangles' edges, or -1. */
static int tgp_node(const siteflip_graph *g, const got_triangle *t, size_t nt) {
  siteflip_mask m = {0, 0};
  for (size_t q = 0; q < nt; q++) {
    int v[3] = {t[q].i, t[q].k, t[q].j};
    for (int e = 0; e < 3; e++) {
      int b = siteflip_seg(g->n, v[e], v[(e + 1) % 3]);
      if (b < 64) m.lo |= (uint64_t)1 << b;
      else m.hi |= (uint64_t)1 << (b - 64);
    }
  }
  for (int u = 0; u < g->nnodes; u++)
    if (g->node[u].lo == m.lo && g->node[u].hi == m.hi) return u;
  return -1;
}

static int tgp_near(double a, double b) {
  return fabs(a - b) <= TGP_REL * fmax(fabs(a), fabs(b)) + 1e-300 || a == b;
}

/* The LOT's total key (incremental) of p under r. */
static double tgp_lot_key(const geom_point *p, size_t n, const rule *r) {
  lot_options o;
  lot_options_init(&o, r);
  lot *L;
  char err[256];
  assert_int_equal(lot_build(&L, p, n, &o, err, sizeof err), 0);
  size_t nt = lot_get_stats(L)->triangles;
  uint32_t *tri = malloc(3 * nt * sizeof *tri);
  double *bad = malloc(nt * sizeof *bad);
  lot_get_triangles(L, tri);
  lot_get_badness(p, tri, nt, r, bad);
  double key = rule_total_key(r, bad, nt);
  free(tri);
  free(bad);
  lot_free(L);
  return key;
}

/* The smallest and second smallest enumerated keys, and how many nodes tie the first. */
static void tgp_best(const siteflip_graph *g, const rule *r, double *k1, double *k2,
                     int *nbest) {
  *k1 = *k2 = INFINITY;
  for (int u = 0; u < g->nnodes; u++) {
    double k = siteflip_node_key(g, r, u);
    if (k < *k1) *k2 = *k1, *k1 = k;
    else if (k < *k2) *k2 = k;
  }
  *nbest = 0;
  for (int u = 0; u < g->nnodes; u++) *nbest += tgp_near(siteflip_node_key(g, r, u), *k1);
}

/* One set, one rule, one skeleton against the enumeration. */
static void tgp_check_one(const geom_point *p, int n, const siteflip_graph *g, const rule *r,
                          got_skeleton sk, const char *what) {
  got_options o = {1, RULE_DEFAULT_TIE_EPS};
  got_result res;
  char err[512];
  if (got_points_solve(p, (size_t)n, r, &o, sk, &res, err, sizeof err) != 0)
    fail_msg("%s, %s, skeleton %s: %s", what, rule_name(r), got_skeleton_name(sk), err);
  double k1, k2;
  int nbest;
  tgp_best(g, r, &k1, &k2, &nbest);
  int u = tgp_node(g, res.tri, res.ntri);
  if (u < 0) fail_msg("%s, %s: the triangles are no triangulation", what, rule_name(r));
  if (!tgp_near(res.key, k1) || !tgp_near(siteflip_node_key(g, r, u), k1))
    fail_msg("%s, %s, %s: key %.17g, its triangles %.17g, enumeration %.17g", what,
             rule_name(r), got_skeleton_name(sk), res.key, siteflip_node_key(g, r, u), k1);
  /* the same triangulation's total summed from measure_eval lies within both bounds */
  double ku = siteflip_node_key(g, r, u), eu = got_cert_err_of(&res, ku);
  if (strcmp(rule_name(r), "P_1") == 0 && !isfinite(eu))
    fail_msg("%s, P_1: no error model for point sets", what);
  if (isfinite(eu) && fabs(res.key - ku) > res.cert_err + eu)
    fail_msg("%s, %s: key %.17g and its triangles' total %.17g differ beyond the certified "
             "bounds %.3g + %.3g", what, rule_name(r), res.key, ku, res.cert_err, eu);
  if (nbest > 1 && res.cert_unique)
    fail_msg("%s, %s: %d optima but certified unique", what, rule_name(r), nbest);
  if (sk == GOT_SKELETON_ALL && g->nnodes > 1 && !tgp_near(res.key2, nbest > 1 ? k1 : k2))
    fail_msg("%s, %s: runner-up %.17g, enumeration %.17g", what, rule_name(r), res.key2,
             nbest > 1 ? k1 : k2);
  if (strcmp(rule_name(r), "P_1") == 0 && nbest == 1 && (k2 - k1) > 1e-6 * fabs(k1))
    assert_true(res.cert_unique);
  double lk = tgp_lot_key(p, (size_t)n, r);
  if (lk < res.key && !tgp_near(lk, res.key))
    fail_msg("%s, %s: the LOT totals less than the GOT (%.17g < %.17g)", what, rule_name(r),
             lk, res.key);
  got_result_free(&res);
}

/* The rules whose GOT is Delaunay, through study_got_points (the skeleton "delaunay" on
** lot's Delaunay triangulation, tests/test_got_dt.c): the least enumerated key, and never
** "unique" where two triangulations tie. */
static const char *const tgp_dt_rules[] = {"R_1", "R_2", "R_0", "R_-1", "-r_1", "abc_1"};

static void tgp_check_delaunay(const geom_point *p, int n, const siteflip_graph *g,
                               const char *name, const char *what) {
  rule r = tgp_rule(name);
  got_options o = {1, RULE_DEFAULT_TIE_EPS};
  got_result res;
  char err[512];
  assert_true(rule_got_cdt_theorem(&r) > 0);
  if (study_got_points(p, (size_t)n, &r, &o, GOT_SKELETON_AUTO, &res, err, sizeof err) != 0)
    fail_msg("%s, %s, skeleton delaunay: %s", what, name, err);
  assert_int_equal(res.skeleton, GOT_SKELETON_DELAUNAY);
  double k1, k2;
  int nbest, u = tgp_node(g, res.tri, res.ntri);
  tgp_best(g, &r, &k1, &k2, &nbest);
  if (u < 0) fail_msg("%s, %s, delaunay: the triangles are no triangulation", what, name);
  if (!tgp_near(res.key, k1) || !tgp_near(siteflip_node_key(g, &r, u), k1))
    fail_msg("%s, %s, delaunay: key %.17g, its triangles %.17g, enumeration %.17g", what,
             name, res.key, siteflip_node_key(g, &r, u), k1);
  if (nbest > 1 && res.cert_unique)
    fail_msg("%s, %s, delaunay: %d optima but certified unique", what, name, nbest);
  got_result_free(&res);
}

static int tgp_checked;

static void tgp_check_set(const geom_point *p, int n, const char *what) {
  char err[256];
  siteflip_graph *g = siteflip_build(p, n, err, sizeof err);
  if (g == NULL) fail_msg("%s: %s", what, err);
  for (size_t i = 0; i < TGP_NRULES; i++) {
    rule r = tgp_rule(tgp_rules[i]);
    tgp_check_one(p, n, g, &r, GOT_SKELETON_ALL, what);
    tgp_check_one(p, n, g, &r, GOT_SKELETON_AUTO, what);
    tgp_checked++;
  }
  for (size_t i = 0; i < sizeof tgp_dt_rules / sizeof *tgp_dt_rules; i++)
    tgp_check_delaunay(p, n, g, tgp_dt_rules[i], what);
  siteflip_free(g);
}

/* n distinct points of list[0..m-1], not all collinear, chosen by seed. */
static void tgp_subset(const geom_point *list, int m, int n, uint64_t seed, geom_point *p) {
  testutil_rng g = {seed * 0x9e3779b97f4a7c15ull + 1};
  for (;;) {
    int idx[32];
    for (int i = 0; i < m; i++) idx[i] = i;
    for (int i = 0; i < n; i++) {
      int j = i + (int)(testutil_next(&g) % (uint64_t)(m - i)), t = idx[i];
      idx[i] = idx[j], idx[j] = t;
      p[i] = list[idx[i]];
    }
    for (int c = 2; c < n; c++)
      if (geom_orient(p[0], p[1], p[c]) != 0) return;
  }
}

static void test_enumeration(void **state) {
  (void)state;
  geom_point grid[16], circle[13] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3},
                                     {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3},
                                     {0, 0}};
  for (int i = 0; i < 16; i++) grid[i] = (geom_point){i % 4, i / 4};
  geom_point p[16];
  char what[128];
  int reps = testutil_reps(6);
  for (int n = 3; n <= 9; n++)
    for (int s = 0; s < reps; s++) {
      for (int kind = 0; kind < SAMPLER_SITES_COUNT && kind <= SAMPLER_SITES_SQUARE; kind++) {
        assert_int_equal(sampler_sites(kind, 38, (uint64_t)(100 * n + s), n, p), 0);
        snprintf(what, sizeof what, "%s n = %d sample %d", sampler_sites_name(kind), n, s);
        tgp_check_set(p, n, what);
      }
      tgp_subset(grid, 16, n, (uint64_t)(n * 10 + s), p);
      snprintf(what, sizeof what, "grid n = %d sample %d", n, s);
      tgp_check_set(p, n, what);
      tgp_subset(circle, 13, n, (uint64_t)(n * 10 + s), p);
      snprintf(what, sizeof what, "circle n = %d sample %d", n, s);
      tgp_check_set(p, n, what);
    }
  for (int n = 10; n <= 11; n++) {
    for (int kind = 0; kind <= SAMPLER_SITES_SQUARE; kind++) {
      assert_int_equal(sampler_sites(kind, 38, (uint64_t)(1000 + n), n, p), 0);
      snprintf(what, sizeof what, "%s n = %d", sampler_sites_name(kind), n);
      tgp_check_set(p, n, what);
    }
    tgp_subset(grid, 16, n, (uint64_t)n, p);
    tgp_check_set(p, n, "grid n = 10, 11");
    tgp_subset(circle, 13, n, (uint64_t)n, p);
    tgp_check_set(p, n, "circle n = 10, 11");
  }
  assert_true(tgp_checked >= 7 * 5 * (int)TGP_NRULES);
}

/* Do a and b hold the same triangles (each as a sorted triple)? */
static int tgp_tri_key(const got_triangle *t, long long *out) {
  int v[3] = {t->i, t->k, t->j};
  for (int a = 0; a < 2; a++)
    for (int b = 0; b < 2 - a; b++)
      if (v[b] > v[b + 1]) {
        int x = v[b];
        v[b] = v[b + 1], v[b + 1] = x;
      }
  *out = ((long long)v[0] << 40) | ((long long)v[1] << 20) | v[2];
  return 0;
}

static int tgp_ll_cmp(const void *a, const void *b) {
  long long x = *(const long long *)a, y = *(const long long *)b;
  return (x > y) - (x < y);
}

static int tgp_node_equal(const got_result *a, const got_result *b) {
  long long ka[64], kb[64];
  for (size_t q = 0; q < a->ntri; q++)
    tgp_tri_key(&a->tri[q], &ka[q]), tgp_tri_key(&b->tri[q], &kb[q]);
  qsort(ka, a->ntri, sizeof *ka, tgp_ll_cmp);
  qsort(kb, b->ntri, sizeof *kb, tgp_ll_cmp);
  return memcmp(ka, kb, a->ntri * sizeof *ka) == 0;
}

/* Points in convex position, anticlockwise: with the trivial skeleton got_solve on them,
** bit for bit; with the LMT-skeleton the same optimum (summed over its faces). */
static void test_convex_is_polygon(void **state) {
  (void)state;
  got_options o = {1, RULE_DEFAULT_TIE_EPS};
  char err[512];
  for (int n = 3; n <= 16; n++)
    for (size_t i = 0; i < TGP_NRULES; i++) {
      geom_point p[16];
      sampler_convex(38, (uint64_t)n, n, p);
      rule r = tgp_rule(tgp_rules[i]);
      got_result a, b;
      assert_int_equal(got_solve(p, (size_t)n, &r, &o, &a, err, sizeof err), 0);
      for (int sk = GOT_SKELETON_AUTO; sk <= GOT_SKELETON_ALL; sk++) {
        if (got_points_solve(p, (size_t)n, &r, &o, (got_skeleton)sk, &b, err, sizeof err))
          fail_msg("%s n = %d: %s", tgp_rules[i], n, err);
        assert_int_equal(a.ntri, b.ntri);
        if (sk == GOT_SKELETON_AUTO) {      /* faces of the LMT-skeleton: sums of face keys */
          assert_true(tgp_near(a.key, b.key));
          if (a.cert_unique) assert_int_equal(tgp_node_equal(&a, &b), 1);
          assert_true(!a.has_runner_up || !b.has_runner_up || b.key2 >= a.key2 ||
                      tgp_near(a.key2, b.key2));
          got_result_free(&b);
          continue;
        }
        assert_true(a.key == b.key);        /* one face, the hull: got_solve's bits */
        assert_int_equal(a.has_runner_up, b.has_runner_up);
        if (a.has_runner_up) assert_true(a.key2 == b.key2);
        assert_int_equal(a.cert_unique, b.cert_unique);
        assert_int_equal(tgp_node_equal(&a, &b), 1);
        got_result_free(&b);
      }
      got_result_free(&a);
    }
}

/* Any thread count gives the same bits. */
static void test_threads(void **state) {
  (void)state;
  size_t n = 200;
  geom_point *p = malloc(n * sizeof *p);
  sampler_rng g;
  sampler_seed(&g, 38, 1);
  assert_int_equal(sampler_vector(&g, n, p), 0);
  rule r = tgp_rule("P_1");
  char err[512];
  got_result a, b;
  got_options o1 = {1, RULE_DEFAULT_TIE_EPS}, o2 = {2, RULE_DEFAULT_TIE_EPS};
  assert_int_equal(got_points_solve(p, n, &r, &o1, GOT_SKELETON_ALL, &a, err, sizeof err), 0);
  assert_int_equal(got_points_solve(p, n, &r, &o2, GOT_SKELETON_ALL, &b, err, sizeof err), 0);
  assert_true(a.key == b.key && a.key2 == b.key2 && a.ntri == b.ntri && a.ntri == n - 2);
  for (size_t q = 0; q < a.ntri; q++)      /* field by field: the struct has padding */
    assert_true(a.tri[q].i == b.tri[q].i && a.tri[q].k == b.tri[q].k &&
                a.tri[q].j == b.tri[q].j && a.tri[q].badness == b.tri[q].badness);
  assert_int_equal(a.faces, 1);
  got_result_free(&a);
  got_result_free(&b);
  free(p);
}

/* One line naming the problem; -1. */
/* Refused with want in one line, by got_points_solve and by study_got_points (which checks
** the points once, then for a rule whose GOT is Delaunay triangulates them and goes on by
** got_points_solve_checked: no error may be lost on that way); by=2 got_points_solve_checked
** itself, for the options' refusals it keeps. */
static void tgp_refused_by(const geom_point *p, size_t n, const char *rname, int threads,
                           int sk, const char *want, int by) {
  rule r = tgp_rule(rname);
  got_options o = {threads, RULE_DEFAULT_TIE_EPS};
  got_result res;
  char err[512] = "";
  got_skeleton s = (got_skeleton)sk;
  int rc = by == 0   ? got_points_solve(p, n, &r, &o, s, &res, err, sizeof err)
           : by == 1 ? study_got_points(p, n, &r, &o, s, &res, err, sizeof err)
                     : got_points_solve_checked(p, n, &r, &o, s, NULL, 0, &res, err, sizeof err);
  assert_int_equal(rc, -1);
  if (strstr(err, want) == NULL || strchr(err, '\n') != NULL)
    fail_msg("%s, way %d: wanted '%s' in '%s'", rname, by, want, err);
  assert_null(res.tri);
}

static void tgp_refused(const geom_point *p, size_t n, const char *rname, int threads,
                        int sk, const char *want) {
  tgp_refused_by(p, n, rname, threads, sk, want, 0);
  tgp_refused_by(p, n, rname, threads, sk, want, 1);
}

static void test_bad_input(void **state) {
  (void)state;
  geom_point p[5] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.5, 0.25}};
  tgp_refused(p, 5, "P_inf", 1, 0, "not a sum rule");
  tgp_refused(p, 5, "R_-inf", 1, 0, "not a sum rule");
  tgp_refused(p, 5, "DT", 1, 0, "not a sum rule");
  tgp_refused(p, 2, "P_1", 1, 0, "at least 3 points");
  tgp_refused(p, 5, "P_1", -1, 0, "threads");
  tgp_refused(p, 5, "P_1", 1, 7, "skeleton");
  geom_point d[5] = {{0, 0}, {1, 0}, {0, 1}, {1, 0}, {0.5, 0.25}};
  tgp_refused(d, 5, "P_1", 1, 0, "points 1 and 3 (0-based rows) are equal");
  geom_point c[4] = {{0, 0}, {1, 1}, {2, 2}, {-3, -3}};
  tgp_refused(c, 4, "P_1", 1, 0, "collinear");
  geom_point o[3] = {{0, 0}, {1, 0}, {0, 1e40}};
  tgp_refused(o, 3, "P_1", 1, 0, "point 2 (0-based row)");
  /* a rule whose GOT is Delaunay: study_got_points's own way, got's messages first */
  tgp_refused(p, 2, "R_1", 1, 0, "at least 3 points");
  tgp_refused(p, 5, "R_1", -1, 0, "threads");
  tgp_refused(p, 5, "R_1", 1, 7, "skeleton");
  tgp_refused(d, 5, "R_1", 1, GOT_SKELETON_DELAUNAY, "points 1 and 3 (0-based rows) are equal");
  tgp_refused(c, 4, "R_1", 1, 0, "collinear");
  tgp_refused(o, 3, "R_1", 1, 0, "point 2 (0-based row)");
  tgp_refused_by(p, 5, "R_1", -1, 0, "threads", 2);
  tgp_refused_by(p, 5, "R_1", 1, 7, "skeleton", 2);
  tgp_refused_by(p, 5, "R_1", 1, GOT_SKELETON_DELAUNAY, "no Delaunay triangulation", 2);
  char err[256];
  assert_int_equal(got_points_check_memory((size_t)1 << 50, err, sizeof err), -1);
  assert_non_null(strstr(err, "GB"));
  assert_int_equal(got_skeleton_find("lmt"), GOT_SKELETON_LMT);
  assert_int_equal(got_skeleton_find("none"), -1);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_enumeration),
    cmocka_unit_test(test_convex_is_polygon),
    cmocka_unit_test(test_threads),
    cmocka_unit_test(test_bad_input),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
