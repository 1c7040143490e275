/*
** test_got_dt.c: the GOT of a point set for the rules whose GOT is a Delaunay triangulation
** (rule_got_is_cdt), through the certified Delaunay subdivision (got/got_skel_dt.c, the
** skeleton "delaunay"; studies/gotpoints.c's study_got_points makes lot's Delaunay
** triangulation and hands it over).
**
** - Enumeration: tests/test_got_points.c's sets (n <= 11) also run the eight rules of
**   rule_got_is_cdt with this skeleton against every triangulation.
** - The LMT path (every clear pair a candidate, then the loop) on 20 to 200 random, grid,
**   cocircular and collinear-heavy points, for the rules it can decide: the same total
**   within both certified bounds, the same triangles when either is certified unique, and
**   the same verdict.
** - Grids: every square a cocircular cell, a tied face (not unique), the others triangles.
** - The certificate refuses, in one line, a triangulation with one edge flipped (a
**   non-Delaunay edge), a triangle missing, one turned clockwise, one repeated, a point
**   beyond n; the skeleton "delaunay" is refused for other rules and without a
**   triangulation.
** - The CLI on 10^5 uniform points with R_1: the skeleton is the Delaunay subdivision,
**   unique, Euler's count of triangles.
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
#include "study.h"
#include "testutil.h"

static const char *const tgd_rules[] = {"R_1", "R_2", "R_0", "R_-1", "-r_1", "abc_1"};
#define TGD_NRULES (sizeof tgd_rules / sizeof *tgd_rules)

static rule tgd_rule(const char *name) {
  rule r;
  char err[256];
  assert_int_equal(rule_parse(name, &r, err, sizeof err), 0);
  assert_true(rule_got_cdt_theorem(&r) > 0);
  return r;
}

static void tgd_solve(const geom_point *p, size_t n, const rule *r, got_skeleton sk,
                      got_result *res, const char *what) {
  got_options o = {1, RULE_DEFAULT_TIE_EPS};
  char err[512];
  if (study_got_points(p, n, r, &o, sk, res, err, sizeof err) != 0)
    fail_msg("%s, %s, skeleton %s: %s", what, rule_name(r), got_skeleton_name(sk), err);
}

/* ---- against the all-pairs LMT path ---- */

/* Do a and b hold the same triangles?  Both are sorted (got_points_solve). */
static int tgd_same_triangles(const got_result *a, const got_result *b) {
  if (a->ntri != b->ntri) return 0;
  for (size_t q = 0; q < a->ntri; q++)
    if (a->tri[q].i != b->tri[q].i || a->tri[q].k != b->tri[q].k || a->tri[q].j != b->tri[q].j)
      return 0;
  return 1;
}

static void tgd_against_lmt(const geom_point *p, size_t n, const char *rname,
                            const char *what) {
  rule r = tgd_rule(rname);
  got_result d, l;
  tgd_solve(p, n, &r, GOT_SKELETON_DELAUNAY, &d, what);
  tgd_solve(p, n, &r, GOT_SKELETON_LMT, &l, what);
  assert_int_equal(d.ntri, l.ntri);
  if (fabs(d.key - l.key) > d.cert_err + l.cert_err)
    fail_msg("%s, %s: totals %.17g (delaunay) and %.17g (lmt) beyond the bounds", what,
             rname, d.key, l.key);
  /* the LMT path's certificate (floating totals, certified bounds) implies the theorem's;
  ** the theorem also certifies a Delaunay triangulation with no four points exactly
  ** cocircular where the floating totals are too close to separate (points near a circle) */
  if (l.cert_unique && (!d.cert_unique || !tgd_same_triangles(&d, &l)))
    fail_msg("%s, %s: lmt certifies its triangles unique, delaunay says %s", what, rname,
             d.cert_unique ? "other triangles" : "not unique");
  if (!d.cert_unique && l.cert_unique)
    fail_msg("%s, %s: verdicts differ", what, rname);
  if (d.cert_unique && !l.cert_unique && d.has_runner_up)
    fail_msg("%s, %s: a tied face, yet unique", what, rname);
  got_result_free(&d);
  got_result_free(&l);
}

static void test_against_lmt(void **state) {
  (void)state;
  static const char *const rules[] = {"R_1", "-r_1", "R_-1", "R_2"};
  geom_point p[200];
  char what[128];
  for (size_t n = 20; n <= 200; n *= 3) {
    static const sampler_points_kind kinds[] = {SAMPLER_UNIFORM, SAMPLER_DISC, SAMPLER_CIRCLE,
                                                SAMPLER_LINES};
    for (size_t k = 0; k < sizeof kinds / sizeof *kinds; k++) {
      sampler_points(kinds[k], 38, n, p);
      snprintf(what, sizeof what, "%s n = %zu", sampler_points_name(kinds[k]), n);
      for (size_t i = 0; i < sizeof rules / sizeof *rules; i++)
        tgd_against_lmt(p, n, rules[i], what);
    }
    testutil_rng g = {n};
    for (size_t i = 0; i < n; i++)      /* collinear-heavy: a 12 x 12 grid, some left out */
      p[i] = (geom_point){(double)(testutil_next(&g) % 12), (double)(testutil_next(&g) % 12)};
    size_t m = 0;
    for (size_t i = 0; i < n; i++) {
      size_t j = 0;
      while (j < m && (p[j].x != p[i].x || p[j].y != p[i].y)) j++;
      if (j == m) p[m++] = p[i];
    }
    snprintf(what, sizeof what, "grid points n = %zu", m);
    tgd_against_lmt(p, m, "R_1", what);
  }
  geom_point c[12] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3},   /* cocircular */
                      {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  tgd_against_lmt(c, 12, "R_1", "the circle");
  tgd_against_lmt(c, 12, "-r_1", "the circle");
}

/* ---- grids: tied squares ---- */

static void test_grid_ties(void **state) {
  (void)state;
  enum { S = 6 };
  geom_point p[S * S];
  for (int i = 0; i < S * S; i++) p[i] = (geom_point){i % S, i / S};
  for (size_t i = 0; i < TGD_NRULES; i++) {
    rule r = tgd_rule(tgd_rules[i]);
    got_result res;
    tgd_solve(p, S * S, &r, GOT_SKELETON_AUTO, &res, "grid");
    assert_int_equal(res.skeleton, GOT_SKELETON_DELAUNAY);
    assert_int_equal(res.ntri, 2 * S * S - 4 * (S - 1) - 2);
    assert_int_equal(res.faces_left, (S - 1) * (S - 1));   /* every square a face */
    assert_int_equal(res.largest_face, 4);
    assert_int_equal(res.certain, 2 * S * (S - 1));       /* the squares' sides */
    assert_int_equal(res.cert_unique, 0);                 /* the squares tie */
    assert_int_equal(res.unique, 0);
    got_result_free(&res);
  }
}

/* ---- rules Delaunay by observation only ---- */

/* -r/R_1 and -r2/A_0 are Delaunay on table 3.4's samples, with no proof: `auto` takes the
** all-pairs LMT path for them (the certified one), and `delaunay` is refused in one line. */
static void test_unproven_rules(void **state) {
  (void)state;
  geom_point p[10];
  sampler_points(SAMPLER_UNIFORM, 7, 10, p);   /* no error model: small faces */
  const char *unproven[] = {"-r/R_1", "-r2/A_0"};
  for (int i = 0; i < 2; i++) {
    rule r;
    char err[512];
    assert_int_equal(rule_parse(unproven[i], &r, err, sizeof err), 0);
    assert_true(rule_got_is_cdt(&r));
    assert_int_equal(rule_got_cdt_theorem(&r), 0);
    got_options o = {1, RULE_DEFAULT_TIE_EPS};
    got_result res;
    if (study_got_points(p, 10, &r, &o, GOT_SKELETON_AUTO, &res, err, sizeof err) != 0)
      fail_msg("%s, skeleton auto: %s", unproven[i], err);
    assert_int_not_equal(res.skeleton, GOT_SKELETON_DELAUNAY);
    got_result_free(&res);
    assert_int_equal(study_got_points(p, 10, &r, &o, GOT_SKELETON_DELAUNAY, &res, err,
                                      sizeof err), -1);
    assert_non_null(strstr(err, "not proven"));
    assert_null(strchr(err, '\n'));
  }
}

/* ---- the certificate refuses ---- */

static uint32_t *tgd_dt(const geom_point *p, size_t n, size_t *nt) {
  lot_options o;
  rule dt = rule_delaunay();
  lot_options_init(&o, &dt);
  lot *L;
  char err[256];
  assert_int_equal(lot_build(&L, p, n, &o, err, sizeof err), 0);
  *nt = lot_get_stats(L)->triangles;
  uint32_t *tri = malloc(3 * *nt * sizeof *tri);
  lot_get_triangles(L, tri);
  lot_free(L);
  return tri;
}

static void tgd_refused(const geom_point *p, size_t n, const char *rname, const uint32_t *tri,
                        size_t nt, const char *want) {
  rule r;
  char err[512] = "";
  assert_int_equal(rule_parse(rname, &r, err, sizeof err), 0);
  got_options o = {1, RULE_DEFAULT_TIE_EPS};
  got_result res;
  assert_int_equal(got_points_solve_dt(p, n, &r, &o, GOT_SKELETON_DELAUNAY, tri, nt, &res, err,
                                       sizeof err), -1);
  if (strstr(err, want) == NULL || strchr(err, '\n') != NULL)
    fail_msg("wanted '%s' in '%s'", want, err);
  assert_null(res.tri);
}

/* An interior edge whose quadrilateral is strictly convex and not cocircular, flipped. */
static void tgd_flip_one(const geom_point *p, uint32_t *tri, size_t nt) {
  for (size_t t = 0; t < nt; t++)
    for (size_t u = t + 1; u < nt; u++)
      for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
          uint32_t a = tri[3 * t + i], b = tri[3 * t + (i + 1) % 3], c = tri[3 * t + (i + 2) % 3];
          uint32_t d = tri[3 * u + (j + 2) % 3];
          if (tri[3 * u + j] != b || tri[3 * u + (j + 1) % 3] != a) continue;
          if (geom_orient(p[c], p[a], p[d]) <= 0 || geom_orient(p[d], p[b], p[c]) <= 0 ||
              geom_incircle(p[a], p[b], p[c], p[d]) == 0)
            continue;
          uint32_t t1[3] = {c, a, d}, t2[3] = {d, b, c};
          memcpy(tri + 3 * t, t1, sizeof t1), memcpy(tri + 3 * u, t2, sizeof t2);
          return;
        }
  fail_msg("no edge to flip");
}

static void test_certificate_refuses(void **state) {
  (void)state;
  enum { N = 40 };
  geom_point p[N];
  sampler_points(SAMPLER_UNIFORM, 7, N, p);
  size_t nt;
  uint32_t *tri = tgd_dt(p, N, &nt), *bad = malloc(3 * nt * sizeof *bad);
  got_options o = {1, RULE_DEFAULT_TIE_EPS};
  got_result res;
  char err[512];
  rule r = tgd_rule("R_1");
  assert_int_equal(got_points_solve_dt(p, N, &r, &o, GOT_SKELETON_DELAUNAY, tri, nt, &res, err,
                                       sizeof err), 0);
  got_result_free(&res);
  memcpy(bad, tri, 3 * nt * sizeof *bad);
  tgd_flip_one(p, bad, nt);
  tgd_refused(p, N, "R_1", bad, nt, "is not locally Delaunay");
  /* a triangle dropped: a hole, an uncovered point or a right turn of the boundary */
  memcpy(bad, tri, 3 * nt * sizeof *bad);
  memmove(bad + 3 * (nt / 2), bad + 3 * (nt / 2 + 1), 3 * (nt - nt / 2 - 1) * sizeof *bad);
  tgd_refused(p, N, "R_1", bad, nt - 1, "delaunay certificate: ");
  memcpy(bad, tri, 3 * nt * sizeof *bad);
  uint32_t x = bad[0];
  bad[0] = bad[1], bad[1] = x;
  tgd_refused(p, N, "-r_1", bad, nt, "does not turn anticlockwise");
  memcpy(bad, tri, 3 * nt * sizeof *bad);
  memcpy(bad + 3, bad, 3 * sizeof *bad);
  tgd_refused(p, N, "R_1", bad, nt, "same side: they overlap");
  memcpy(bad, tri, 3 * nt * sizeof *bad);
  bad[4] = N;
  tgd_refused(p, N, "R_1", bad, nt, "beyond the 40 given");
  tgd_refused(p, N, "R_1", tri, nt - 1, "delaunay certificate: ");
  tgd_refused(p, N, "P_1", tri, nt, "need not be a Delaunay triangulation");
  tgd_refused(p, N, "R_1", NULL, 0, "no Delaunay triangulation was given");
  free(tri);
  free(bad);
}

/* ---- the program on 10^5 points ---- */

#define TGD_CAP (1 << 16)
static char tgd_out[TGD_CAP], tgd_err[TGD_CAP];

static void test_cli_large(void **state) {
  (void)state;
  assert_int_equal(testutil_runf(tgd_out, sizeof tgd_out, tgd_err, sizeof tgd_err,
                                 "got --rule R_1 --random 100000 --distribution uniform "
                                 "--no-triangles --no-lot --threads 2"), 0);
  assert_non_null(strstr(tgd_out, "skeleton: delaunay, "));
  assert_non_null(strstr(tgd_out, "certified: unique"));
  assert_non_null(strstr(tgd_out, "seconds: Delaunay triangulation "));
  assert_int_not_equal(testutil_runf(tgd_out, sizeof tgd_out, tgd_err, sizeof tgd_err,
                                     "got --rule P_inf --random 300 --distribution uniform "
                                     "--skeleton delaunay"), 0);
  assert_non_null(strstr(tgd_err, "not a sum rule"));
  assert_true(testutil_one_line(tgd_err));
  assert_int_not_equal(testutil_runf(tgd_out, sizeof tgd_out, tgd_err, sizeof tgd_err,
                                     "got --rule P_1 --random 300 --distribution uniform "
                                     "--skeleton delaunay"), 0);
  assert_non_null(strstr(tgd_err, "need not be a Delaunay triangulation"));
  assert_true(testutil_one_line(tgd_err));
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_against_lmt),
    cmocka_unit_test(test_grid_ties),
    cmocka_unit_test(test_unproven_rules),
    cmocka_unit_test(test_certificate_refuses),
    cmocka_unit_test(test_cli_large),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
