/*
** test_rules.c: flip rules.  Parsing (all 138 triangle rules, DT, bad
** names), the tie comparison, the appendix B counterexamples (P_1,
** -alpha_1, sigma_2 versus DT, perturbed and not), A_1 always tied, DT on
** cocircular quadrilaterals, independence of the first vertex (bit for bit)
** and mirror symmetry for every rule, and the quadrilateral-rule registry.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <gmp.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "measure.h"
#include "rule.h"
#include "geom.h"
#include "joint.h"
#include "testutil.h"

#define TRULE_NALL (MEASURE_BUILTIN_COUNT * JOINT_COUNT)

static rule trule_get(const char *name) {
  rule r;
  char err[4096] = "";
  if (rule_parse(name, &r, err, sizeof err) < 0) {
    print_error("rule_parse(%s) failed: %s\n", name, err);
    fail();
  }
  return r;
}

static rule_choice trule_swap(rule_choice c) {
  return c == RULE_AC ? RULE_BD : c == RULE_BD ? RULE_AC : RULE_EITHER;
}

static geom_point trule_pt(double x, double y) {
  geom_point p = {x, y};
  return p;
}

/* ---- parsing ---- */

static void test_parse_all(void **state) {
  (void)state;
  int n = 0;
  for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++)
    for (int j = 0; j < JOINT_COUNT; j++) {
      char name[96], err[4096] = "";
      snprintf(name, sizeof name, "%s_%s", measure_get(m)->name, joint_get((joint_id)j)->name);
      rule r;
      memset(&r, 0, sizeof r);
      if (rule_parse(name, &r, err, sizeof err) < 0) {
        print_error("rule_parse(%s): %s\n", name, err);
        fail();
      }
      assert_int_equal(r.kind, RULE_TRIANGLE);
      assert_int_equal(r.measure, m);
      assert_int_equal(r.joint, j);
      assert_string_equal(r.name, name);
      rule r2;
      assert_true(rule_parse(r.name, &r2, err, sizeof err) >= 0);   /* round trip */
      assert_true(r2.measure == m && r2.joint == (joint_id)j && strcmp(r2.name, name) == 0);
      rule r3;
      assert_true(rule_triangle(m, (joint_id)j, &r3, err, sizeof err) >= 0);
      assert_string_equal(r3.name, name);
      n++;
    }
  assert_int_equal(n, 138);

  static const struct { const char *name; int measure; joint_id j; } named[] = {
    {"R_inf", MEASURE_R, JOINT_MAX}, {"-alpha_inf", MEASURE_NEG_ALPHA, JOINT_MAX},
    {"P_1", MEASURE_P, JOINT_SUM}, {"-r2/A_0", MEASURE_NEG_R2_OVER_A, JOINT_PRODUCT},
    {"b/(c-a)_-1", MEASURE_B_OVER_C_MINUS_A, JOINT_HARMONIC}, {"-c_-inf", MEASURE_NEG_C, JOINT_MIN},
    {"gamma_inf", MEASURE_GAMMA, JOINT_MAX}, {"-a'_2", MEASURE_NEG_H, JOINT_RSS}};
  for (size_t i = 0; i < sizeof named / sizeof named[0]; i++) {
    rule r = trule_get(named[i].name);
    assert_int_equal(r.kind, RULE_TRIANGLE);
    assert_int_equal(r.measure, named[i].measure);
    assert_int_equal(r.joint, named[i].j);
    assert_string_equal(r.name, named[i].name);
  }
  rule dt = trule_get("DT");
  assert_int_equal(dt.kind, RULE_QUAD);
  assert_int_equal(dt.quad, RULE_DT);
  assert_string_equal(dt.name, "DT");
  rule d2 = rule_delaunay();
  assert_int_equal(d2.kind, RULE_QUAD);
  assert_int_equal(d2.quad, RULE_DT);
  assert_string_equal(d2.name, "DT");
  assert_string_equal(rule_quad_get(RULE_DT)->name, "DT");
}

static void test_list_triangle(void **state) {
  (void)state;
  int all[MEASURE_BUILTIN_COUNT];
  for (int i = 0; i < MEASURE_BUILTIN_COUNT; i++) all[i] = i;
  rule out[TRULE_NALL + 5];
  assert_int_equal(rule_list_triangle(all, MEASURE_BUILTIN_COUNT, out, TRULE_NALL + 5), TRULE_NALL);
  for (int j = 0; j < JOINT_COUNT; j++)   /* joint-major, as table 3.4 */
    for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++) {
      const rule *r = &out[j * MEASURE_BUILTIN_COUNT + m];
      assert_int_equal(r->kind, RULE_TRIANGLE);
      assert_int_equal(r->measure, m);
      assert_int_equal(r->joint, j);
    }
  rule t34[120];
  assert_int_equal(rule_list_triangle(measure_table34, MEASURE_TABLE34_COUNT, t34, 120), 120);
  assert_string_equal(t34[0].name, "R_-inf");
  assert_string_equal(t34[119].name, "-rinf_inf");
}

static void trule_check_bad(const char *name) {
  char err[4096];
  memset(err, 0, sizeof err);
  rule r;
  int rc = rule_parse(name, &r, err, sizeof err);
  if (rc != -1) {
    print_error("rule_parse(\"%s\") returned %d, want -1\n", name, rc);
    fail();
  }
  if (err[0] == '\0' || strchr(err, '\n') != NULL) {
    print_error("rule_parse(\"%s\"): error message not one non-empty line: [%s]\n", name, err);
    fail();
  }
  /* it names the valid choices */
  if (!strstr(err, "DT") || !strstr(err, "-alpha") || !strstr(err, "inf")) {
    print_error("rule_parse(\"%s\"): message does not list valid names: [%s]\n", name, err);
    fail();
  }
  /* a small buffer is truncated, not overrun (ASan watches) */
  char small[8];
  memset(small, 'x', sizeof small);
  assert_int_equal(rule_parse(name, &r, small, sizeof small), -1);
  assert_non_null(memchr(small, '\0', sizeof small));
}

static void test_parse_bad(void **state) {
  (void)state;
  static const char *const bad[] = {"foo", "R_3x", "R", "_1", "", "R_", "P_inf_", "r_1",
                                    "R_inf ", " R_inf", "R__inf", "-alpha_-2x", "R_1_1", "-alpha_", "_"};
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) trule_check_bad(bad[i]);
  char long_name[500];
  memset(long_name, 'R', sizeof long_name - 1);
  long_name[sizeof long_name - 1] = '\0';
  trule_check_bad(long_name);

  rule r;
  char err[4096];
  err[0] = '\0';
  assert_int_equal(rule_triangle(-1, JOINT_SUM, &r, err, sizeof err), -1);
  assert_true(err[0] != '\0');
  err[0] = '\0';
  assert_int_equal(rule_triangle(MEASURE_BUILTIN_COUNT + 3, JOINT_SUM, &r, err, sizeof err), -1);
  assert_true(err[0] != '\0');
  err[0] = '\0';
  assert_int_equal(rule_triangle(MEASURE_R, JOINT_COUNT, &r, err, sizeof err), -1);
  assert_true(err[0] != '\0');
}

/* A user measure of both signs admits only the min and max joints. */
static double trule_signed_fn(const geom_tri *t, void *ctx) {
  (void)ctx;
  return t->beta - 1.0;
}

/* The name grammar: split at the last '_', join back to the same name. */
static void test_name_grammar(void **state) {
  (void)state;
  char m[16], buf[64];
  const char *j = rule_name_split("-r2/A_-inf", m, sizeof m);
  assert_non_null(j);
  assert_string_equal(m, "-r2/A");
  assert_string_equal(j, "-inf");
  assert_int_equal(rule_name_join(buf, sizeof buf, m, j), 10);
  assert_string_equal(buf, "-r2/A_-inf");
  assert_true(rule_name_is("-r2/A_-inf", "-r2/A", "-inf"));
  assert_false(rule_name_is("R_1", "R", "10"));
  assert_false(rule_name_is("R_10", "R", "1"));
  assert_false(rule_name_is("RR_1", "R", "1"));
  j = rule_name_split("a_b_c", m, sizeof m);           /* the last '_' */
  assert_string_equal(m, "a_b");
  assert_string_equal(j, "c");
  assert_null(rule_name_split("DT", m, sizeof m));
  assert_null(rule_name_split("_1", m, sizeof m));     /* no measure part */
  assert_null(rule_name_split("abcdefghijklmnop_1", m, sizeof m));   /* does not fit */
  assert_non_null(rule_name_split("abcdefghijklmno_1", m, sizeof m));
}

static void test_anysign_measure(void **state) {
  (void)state;
  measure m = {"tests2signed", "b-1", "beta minus one (test)", MEASURE_ANYSIGN, trule_signed_fn, NULL};
  int id = measure_register(&m);
  assert_true(id >= MEASURE_BUILTIN_COUNT);
  rule r;
  char err[4096] = "";
  assert_true(rule_triangle(id, JOINT_MIN, &r, err, sizeof err) >= 0);
  assert_true(rule_triangle(id, JOINT_MAX, &r, err, sizeof err) >= 0);
  assert_true(rule_parse("tests2signed_inf", &r, err, sizeof err) >= 0);
  assert_int_equal(r.measure, id);
  for (int j = JOINT_HARMONIC; j <= JOINT_RSS; j++) {
    err[0] = '\0';
    assert_int_equal(rule_triangle(id, (joint_id)j, &r, err, sizeof err), -1);
    assert_true(err[0] != '\0' && strchr(err, '\n') == NULL);
  }
  assert_int_equal(rule_parse("tests2signed_1", &r, err, sizeof err), -1);
  measure_unregister_user();
}

/* ---- comparison ---- */

static void test_compare(void **state) {
  (void)state;
  const double e = RULE_DEFAULT_TIE_EPS;
  assert_int_equal(rule_compare(1, 2, e), RULE_AC);
  assert_int_equal(rule_compare(2, 1, e), RULE_BD);
  assert_int_equal(rule_compare(-2, -1, e), RULE_AC);
  assert_int_equal(rule_compare(1, 1, e), RULE_EITHER);
  assert_int_equal(rule_compare(1, 1 + 1e-13, e), RULE_EITHER);      /* within eps */
  assert_int_equal(rule_compare(1 + 1e-13, 1, e), RULE_EITHER);
  assert_int_equal(rule_compare(-1, -1 - 5e-13, e), RULE_EITHER);
  assert_int_equal(rule_compare(1, 1 + 1e-11, e), RULE_AC);           /* beyond eps */
  assert_int_equal(rule_compare(1 + 1e-11, 1, e), RULE_BD);
  assert_int_equal(rule_compare(1e300, 1e300 * (1 + 1e-13), e), RULE_EITHER);   /* relative */
  assert_int_equal(rule_compare(1e-300, 1e-300 * (1 + 1e-13), e), RULE_EITHER);
  assert_int_equal(rule_compare(1e-300, 2e-300, e), RULE_AC);
  assert_int_equal(rule_compare(0, 0, e), RULE_EITHER);
  assert_int_equal(rule_compare(-0.0, 0.0, e), RULE_EITHER);
  assert_int_equal(rule_compare(0, 1e-300, e), RULE_AC);   /* |d| > eps * 1e-300 */
  /* tie_eps = 0: only equality ties */
  assert_int_equal(rule_compare(1, 1, 0), RULE_EITHER);
  assert_int_equal(rule_compare(1, nextafter(1, 2), 0), RULE_AC);
  /* infinities: equal ones tie, finite vs infinite never */
  assert_int_equal(rule_compare(INFINITY, INFINITY, e), RULE_EITHER);
  assert_int_equal(rule_compare(-INFINITY, -INFINITY, e), RULE_EITHER);
  assert_int_equal(rule_compare(1, INFINITY, e), RULE_AC);
  assert_int_equal(rule_compare(INFINITY, 1, e), RULE_BD);
  assert_int_equal(rule_compare(-INFINITY, -1e300, e), RULE_AC);
  assert_int_equal(rule_compare(-1e300, -INFINITY, e), RULE_BD);
  assert_int_equal(rule_compare(-INFINITY, INFINITY, e), RULE_AC);
  assert_int_equal(rule_compare(1, INFINITY, 1.0), RULE_AC);   /* even a huge eps */
  /* NaN: the header does not say; report what happens */
  print_message("rule_compare(NaN, 1) = %s, (1, NaN) = %s, (NaN, NaN) = %s\n",
                rule_choice_str(rule_compare(NAN, 1, e)), rule_choice_str(rule_compare(1, NAN, e)),
                rule_choice_str(rule_compare(NAN, NAN, e)));
  assert_string_equal(rule_choice_str(RULE_AC), "AC");
  assert_string_equal(rule_choice_str(RULE_BD), "BD");
  assert_string_equal(rule_choice_str(RULE_EITHER), "either");
}

/* ---- appendix B ---- */

/* s = fl(sqrt3/2).  With A = (1,0), C = (-1,0), B = (1/2, s): the circle
** through A, B, C has its centre (0, k) on the bisector of AC with
** 1 + k^2 = 1/4 + (s - k)^2, so k = (s^2 - 3/4)/(2s).  D = (1/2, -s) is at
** squared distance 1/4 + (s + k)^2 from it against the radius^2 1/4 +
** (s - k)^2: D is inside iff s k < 0 iff s^2 < 3/4.  Inside -> DT = BD,
** outside -> AC, never a tie since sqrt3/2 is irrational.  Returns the
** sign of s^2 - 3/4, computed exactly. */
static int trule_appendix_b_sign(double s) {
  mpq_t q, t;
  mpq_inits(q, t, NULL);
  mpq_set_d(q, s);
  mpq_mul(q, q, q);
  mpq_set_ui(t, 3, 4);
  mpq_sub(q, q, t);
  int sg = mpq_sgn(q);
  mpq_clears(q, t, NULL);
  return sg;
}

/* Triangle angles (figure B.1): ABC and CDA are 30-60-90, ABD is
** 120-30-30 and BCD equilateral.  P_1 compares the total length:
** AC: 2(3 + sqrt3) (|AB| = 1, |BC| = sqrt3, |CA| = 2 twice), BD: (2 + sqrt3)
** + 3 sqrt3 = 2 + 4 sqrt3, smaller -> BD.  -alpha_1: AC -(pi/6 + pi/6) =
** -pi/3, BD -(pi/6 + pi/3) = -pi/2, smaller -> BD.  sigma_2 = sqrt of the
** sum of the variances: 30-60-90 has variance ((pi/6)^2 + 0 + (pi/6)^2)/3,
** so AC = (pi/6) sqrt(4/3); 120-30-30 has ((pi/3)^2 + 2 (pi/6)^2)/3 =
** 2 (pi/6)^2 and the equilateral 0, so BD = (pi/6) sqrt2 > AC -> AC. */
static void test_appendix_b(void **state) {
  (void)state;
  double s = sqrt(3.0) / 2, s3 = sqrt(3.0), pi = M_PI;
  rule p1 = trule_get("P_1"), a1 = trule_get("-alpha_1"), s2 = trule_get("sigma_2"), dt = trule_get("DT");
  double ac, bd;

  geom_point q[4] = {{1, 0}, {0.5, s}, {-1, 0}, {0.5, -s}};
  assert_int_equal(rule_eval(&p1, q, &ac, &bd), RULE_BD);
  TESTUTIL_NEAR(ac, 2 * (3 + s3), 1e-14, 0);
  TESTUTIL_NEAR(bd, 2 + 4 * s3, 1e-14, 0);
  assert_int_equal(rule_eval(&a1, q, &ac, &bd), RULE_BD);
  TESTUTIL_NEAR(ac, -pi / 3, 1e-13, 0);
  TESTUTIL_NEAR(bd, -pi / 2, 1e-13, 0);
  assert_int_equal(rule_eval(&s2, q, &ac, &bd), RULE_AC);
  TESTUTIL_NEAR(ac, pi / 6 * sqrt(4.0 / 3), 1e-12, 0);
  TESTUTIL_NEAR(bd, pi / 6 * sqrt(2.0), 1e-12, 0);
  /* the double quadrilateral is not exactly cocircular: DT is decided */
  int sg = trule_appendix_b_sign(s);
  assert_int_not_equal(sg, 0);
  rule_choice want_dt = sg < 0 ? RULE_BD : RULE_AC;
  print_message("appendix B, unperturbed: fl(sqrt3/2)^2 %s 3/4, so DT = %s\n", sg < 0 ? "<" : ">",
                rule_choice_str(want_dt));
  assert_int_equal(rule_eval(&dt, q, NULL, NULL), want_dt);

  /* A moved inside the circle BCD: the circle of A'BC no longer reaches D
  ** (A' inside <=> angle A + angle C > 180 <=> angle B + angle D < 180 <=>
  ** D outside circle A'BC), so DT = AC, while P_1 and -alpha_1 still say BD
  ** by continuity (their values differ by O(1)). */
  const double deltas[] = {1e-3, 1e-6, 1e-9};
  for (size_t i = 0; i < 3; i++) {
    geom_point in[4] = {{1 - deltas[i], 0}, {0.5, s}, {-1, 0}, {0.5, -s}};
    assert_int_equal(rule_eval(&dt, in, NULL, NULL), RULE_AC);
    assert_int_equal(rule_eval(&p1, in, NULL, NULL), RULE_BD);
    assert_int_equal(rule_eval(&a1, in, NULL, NULL), RULE_BD);
    /* A moved outside: DT = BD, sigma_2 still AC */
    geom_point out[4] = {{1 + deltas[i], 0}, {0.5, s}, {-1, 0}, {0.5, -s}};
    assert_int_equal(rule_eval(&dt, out, NULL, NULL), RULE_BD);
    assert_int_equal(rule_eval(&s2, out, NULL, NULL), RULE_AC);
  }
}

/* ---- DT and A_1 on special quadrilaterals ---- */

static void test_dt_cocircular(void **state) {
  (void)state;
  rule dt = trule_get("DT");
  geom_point sq[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  assert_int_equal(rule_eval(&dt, sq, NULL, NULL), RULE_EITHER);
  geom_point dia[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  assert_int_equal(rule_eval(&dt, dia, NULL, NULL), RULE_EITHER);
  geom_point five[4] = {{5, 0}, {3, 4}, {-4, 3}, {0, -5}};
  assert_int_equal(rule_eval(&dt, five, NULL, NULL), RULE_EITHER);
  /* a kite (0,-1) (2,0) (0,1) (-1,0): the circle of ABC has centre (h, 0)
  ** with h^2 + 1 = (2 - h)^2, h = 3/4, radius 5/4; D = (-1,0) is 7/4 from
  ** the centre, strictly outside -> AC */
  geom_point kite[4] = {{0, -1}, {2, 0}, {0, 1}, {-1, 0}};
  assert_int_equal(rule_eval(&dt, kite, NULL, NULL), RULE_AC);
  /* the square's triangle rules: everything symmetric ties */
  rule r = trule_get("R_inf");
  double ac, bd;
  assert_int_equal(rule_eval(&r, sq, &ac, &bd), RULE_EITHER);
}

/* A_1: both triangulations cover the quadrilateral, so the area sums are
** equal in exact arithmetic; the tie tolerance absorbs the rounding. */
static void test_area_sum_ties(void **state) {
  (void)state;
  rule a1 = trule_get("-A_1");
  testutil_rng g = {31};
  int bad = 0;
  for (int n = 0; n < 10000; n++) {
    geom_point q[4];
    testutil_convex_quad(&g, q);
    double ac, bd;
    rule_choice c = rule_eval(&a1, q, &ac, &bd);
    if (c != RULE_EITHER) {
      if (bad < 5)
        print_error("-A_1 = %s on (%.17g,%.17g) (%.17g,%.17g) (%.17g,%.17g) (%.17g,%.17g): "
                    "%.17g vs %.17g (rel %.3g)\n", rule_choice_str(c), q[0].x, q[0].y, q[1].x,
                    q[1].y, q[2].x, q[2].y, q[3].x, q[3].y, ac, bd, fabs(ac - bd) / fabs(ac));
      bad++;
    }
  }
  if (bad) {
    print_error("-A_1 not EITHER on %d of 10000 quadrilaterals\n", bad);
    fail();
  }
}

/* ---- symmetry of every rule ---- */

static int trule_all(rule *out) {
  int all[MEASURE_BUILTIN_COUNT];
  for (int i = 0; i < MEASURE_BUILTIN_COUNT; i++) all[i] = i;
  int n = rule_list_triangle(all, MEASURE_BUILTIN_COUNT, out, TRULE_NALL);
  out[n++] = rule_delaunay();
  return n;
}

/* Rotating ABCD to BCDA swaps the roles of the diagonals; the rule must see
** the same numbers bit for bit (rule.h), so the choice swaps and the two
** values swap exactly; two steps change nothing.  Also rule_eval agrees
** bit for bit with rule_eval_tris on the four triangles. */
static void test_rotation(void **state) {
  (void)state;
  rule rules[TRULE_NALL + 1];
  int nr = trule_all(rules);
  testutil_rng g = {41};
  for (int n = 0; n < 1000; n++) {
    geom_point q[4];
    testutil_convex_quad(&g, q);
    geom_tri t[4];   /* ABC, ACD, ABD, BCD */
    testutil_quad_tris(q, t);
    for (int i = 0; i < nr; i++) {
      double ac0 = 0, bd0 = 0;
      rule_choice c0 = rule_eval(&rules[i], q, &ac0, &bd0);
      assert_int_equal(rule_eval(&rules[i], q, NULL, NULL), c0);
      if (rules[i].kind == RULE_TRIANGLE) {
        double ac1, bd1;
        assert_int_equal(rule_eval_tris(&rules[i], &t[0], &t[1], &t[2], &t[3], &ac1, &bd1), c0);
        assert_memory_equal(&ac0, &ac1, sizeof ac0);
        assert_memory_equal(&bd0, &bd1, sizeof bd0);
      }
      for (int k = 1; k < 4; k++) {
        geom_point p[4];
        for (int v = 0; v < 4; v++) p[v] = q[(v + k) % 4];
        double ac = 0, bd = 0;
        rule_choice c = rule_eval(&rules[i], p, &ac, &bd);
        rule_choice want = (k & 1) ? trule_swap(c0) : c0;
        double wac = (k & 1) ? bd0 : ac0, wbd = (k & 1) ? ac0 : bd0;
        int same = c == want;
        if (rules[i].kind == RULE_TRIANGLE)
          same = same && memcmp(&ac, &wac, sizeof ac) == 0 && memcmp(&bd, &wbd, sizeof bd) == 0;
        if (!same) {
          print_error("%s not rotation invariant (shift %d) on (%.17g,%.17g) (%.17g,%.17g) "
                      "(%.17g,%.17g) (%.17g,%.17g): %s %.17g %.17g vs %s %.17g %.17g\n",
                      rules[i].name, k, q[0].x, q[0].y, q[1].x, q[1].y, q[2].x, q[2].y, q[3].x,
                      q[3].y, rule_choice_str(c), ac, bd, rule_choice_str(want), wac, wbd);
          fail();
        }
      }
    }
  }
}

/* x -> -x reverses the orientation: ABCD becomes A'B'C'D' clockwise, listed
** anticlockwise as D'C'B'A', whose diagonal "AC" is D'B' (the old BD).  The
** values are equal in exact arithmetic but may round differently (the
** mirror image's canonical vertex order differs), so they are compared to
** 1e-9 relative, and decisions away from near-ties (relative gap > 1e-8)
** must swap; DT is exact and must swap always. */
static void test_reflection(void **state) {
  (void)state;
  rule rules[TRULE_NALL + 1];
  int nr = trule_all(rules);
  testutil_rng g = {43};
  int near_ties = 0, value_mismatch = 0;
  for (int n = 0; n < 1000; n++) {
    geom_point q[4], m[4];
    testutil_convex_quad(&g, q);
    for (int v = 0; v < 4; v++) m[v] = trule_pt(-q[3 - v].x, q[3 - v].y);
    for (int i = 0; i < nr; i++) {
      double ac0 = 0, bd0 = 0, ac = 0, bd = 0;
      rule_choice c0 = rule_eval(&rules[i], q, &ac0, &bd0);
      rule_choice c = rule_eval(&rules[i], m, &ac, &bd);
      if (rules[i].kind == RULE_QUAD) {
        assert_int_equal(c, trule_swap(c0));
        continue;
      }
      double tol = rules[i].measure == MEASURE_B_OVER_C_MINUS_A ? 1e-6 : 1e-9;
      int vals_ok = (ac == bd0 || fabs(ac - bd0) <= tol * fabs(bd0)) &&
                    (bd == ac0 || fabs(bd - ac0) <= tol * fabs(ac0));
      if (!vals_ok) {
        if (value_mismatch++ < 5)
          print_error("%s mirror values: %.17g %.17g vs %.17g %.17g\n", rules[i].name, ac, bd, bd0, ac0);
      }
      int near = !(fabs(ac0 - bd0) > 1e-8 * fmax(fabs(ac0), fabs(bd0))) && ac0 != bd0;
      near_ties += near;
      if (!near && c != trule_swap(c0)) {
        print_error("%s mirror decision %s, original %s on (%.17g,%.17g) (%.17g,%.17g) "
                    "(%.17g,%.17g) (%.17g,%.17g)\n", rules[i].name, rule_choice_str(c),
                    rule_choice_str(c0), q[0].x, q[0].y, q[1].x, q[1].y, q[2].x, q[2].y, q[3].x, q[3].y);
        fail();
      }
    }
  }
  print_message("reflection: %d near-tie evaluations not checked\n", near_ties);
  assert_int_equal(value_mismatch, 0);
}

/* ---- the quadrilateral-rule registry ---- */

static int trule_seen_bad;

/* A test rule: always the diagonal at its first vertex; checks it is
** called on an anticlockwise rotation starting at the lexicographically
** smallest vertex (rule.h). */
static rule_choice trule_first_diag(const geom_point q[4], void *ctx) {
  (void)ctx;
  for (int i = 1; i < 4; i++)
    if (q[i].x < q[0].x || (q[i].x == q[0].x && q[i].y < q[0].y)) trule_seen_bad = 1;
  for (int i = 0; i < 4; i++)
    if (geom_orient(q[i], q[(i + 1) % 4], q[(i + 2) % 4]) <= 0) trule_seen_bad = 1;
  return RULE_AC;
}

static void test_quad_registry(void **state) {
  (void)state;
  int n0 = rule_quad_count();
  assert_true(n0 >= 1);
  rule_quad qr = {"tests2first", "diagonal at the lexicographically first vertex", trule_first_diag, NULL};
  int id = rule_quad_register(&qr);
  assert_true(id >= 1);
  assert_int_equal(rule_quad_count(), n0 + 1);
  rule r = trule_get("tests2first");
  assert_int_equal(r.kind, RULE_QUAD);
  assert_int_equal(r.quad, id);
  testutil_rng g = {47};
  for (int n = 0; n < 2000; n++) {
    geom_point q[4];
    testutil_convex_quad(&g, q);
    int lo = 0;
    for (int i = 1; i < 4; i++)
      if (q[i].x < q[lo].x || (q[i].x == q[lo].x && q[i].y < q[lo].y)) lo = i;
    rule_choice want = (lo % 2 == 0) ? RULE_AC : RULE_BD;
    assert_int_equal(rule_eval(&r, q, NULL, NULL), want);
  }
  assert_int_equal(trule_seen_bad, 0);
  rule_quad dup = qr;
  assert_int_equal(rule_quad_register(&dup), -1);   /* name taken */
  rule_quad_unregister_user();
  assert_int_equal(rule_quad_count(), n0);
  rule x;
  char err[4096];
  assert_int_equal(rule_parse("tests2first", &x, err, sizeof err), -1);
}

/* The rule verbs: what a rule is, its decision from badness values (with
** its own tolerance), totals and the one gap formula. */
static void test_verbs(void **state) {
  (void)state;
  rule dt = rule_delaunay(), p1 = trule_get("P_1"), a0 = trule_get("-alpha_inf");
  assert_true(rule_is_delaunay(&dt) && !rule_is_triangle(&dt));
  assert_true(rule_is_triangle(&p1) && !rule_is_delaunay(&p1));
  assert_int_equal(rule_measure(&dt), -1);
  assert_int_equal(rule_measure(&p1), measure_find("P"));
  assert_int_equal(rule_joint(&p1), JOINT_SUM);
  assert_int_equal(rule_sign(&a0), -1);
  assert_string_equal(rule_name(&a0), "-alpha_inf");
  assert_string_equal(rule_measure_name(&a0), "-alpha");
  assert_string_equal(rule_joint_name(&a0), "inf");
  assert_string_equal(rule_measure_name(&dt), "");
  assert_string_equal(rule_joint_name(&dt), "");
  assert_null(rule_quad_of(&p1));
  assert_string_equal(rule_quad_of(&dt)->name, "DT");
  assert_true(rule_tie_eps(&p1) == RULE_DEFAULT_TIE_EPS);
  /* 1 + 2 against 1.5 + 1.5 (1 + 1e-13): a tie, then not with tie_eps 0. */
  assert_int_equal(rule_decide(&p1, 1, 2, 1.5, 1.5 + 1e-13), RULE_EITHER);
  rule_set_tie_eps(&p1, 0);
  assert_int_equal(rule_decide(&p1, 1, 2, 1.5, 1.5 + 1e-13), RULE_AC);
  assert_int_equal(rule_decide(&p1, 1, 2.5, 1.5, 1.5), RULE_BD);
  double ac, bd;
  assert_int_equal(rule_eval_badness(&p1, 1, 2, 1.5, 1.5 + 1e-13, &ac, &bd), RULE_AC);
  assert_true(ac == 3);
  /* Totals: keys combined from the identity. */
  const double bad[3] = {1, 2, 4};
  assert_true(rule_total_key(&p1, bad, 3) == 7);
  rule p0 = trule_get("P_0"), p2 = trule_get("P_2"), pm = trule_get("P_inf");
  assert_true(rule_total_key(&pm, bad, 3) == 4);
  assert_true(rule_unkey(&p2, rule_total_key(&p2, bad, 3)) == sqrt(21));
  TESTUTIL_NEAR(rule_unkey(&p0, rule_total_key(&p0, bad, 3)), 8, 1e-15, 0);
  assert_true(rule_total_key(&p1, bad, 0) == rule_key_identity(&p1));
  /* The gap: |T1 - T2| / max(|T1|, |T2|), in totals, for every joint. */
  assert_true(rule_gap(&p1, 3, 4) == 0.25 && rule_gap(&p1, 4, 3) == 0.25);
  assert_true(rule_gap(&p1, 5, 5) == 0 && rule_gap(&p1, 0, 0) == 0);
  assert_true(rule_gap(&p1, 1, INFINITY) == 1 && rule_gap(&p1, INFINITY, INFINITY) == 0);
  assert_true(rule_gap(&p1, NAN, 1) == 0);
  TESTUTIL_NEAR(rule_gap(&p2, rule_key(&p2, 3), rule_key(&p2, 4)), 0.25, 1e-15, 0);
  TESTUTIL_NEAR(rule_gap(&p0, log(3), log(4)), 0.25, 1e-15, 0);
  TESTUTIL_NEAR(rule_gap(&p0, 5000, 5000 + log(4.0 / 3)), 0.25, 1e-11, 0);   /* e^5000: no double */
  assert_true(rule_gap(&p0, -INFINITY, 0) == 1);   /* a zero product against 1 */
  rule h = trule_get("R_-1");
  TESTUTIL_NEAR(rule_gap(&h, rule_key(&h, 3), rule_key(&h, 4)), 0.25, 1e-15, 0);
}

/* rule_eval_quads: rule_eval's decision and joint values on strictly
** convex anticlockwise quadrilaterals; -1 (and NaN) on their reversals
** (clockwise), on a quadrilateral with three collinear corners and on a
** reflex one, for a triangle rule and for DT. */
static void test_eval_quads(void **state) {
  (void)state;
  enum { M = 6 };
  geom_point q[4 * M] = {
    {0, 0}, {2, 0}, {2, 1}, {0, 1},      {0, 0}, {3, 0.2}, {2, 2}, {-0.5, 1.5},
    {0, 1}, {2, 1}, {2, 0}, {0, 0},      {0, 0}, {1, 0}, {2, 0}, {1, 1},
    {0, 0}, {2, 0}, {0.5, 0.5}, {0, 2},  {1, -1}, {4, 0}, {3, 3}, {0, 2}};
  const int convex[M] = {1, 1, 0, 0, 0, 1};
  const char *names[] = {"P_1", "-alpha_inf", "DT"};
  for (int k = 0; k < 3; k++) {
    rule r;
    char err[256];
    assert_int_equal(rule_parse(names[k], &r, err, sizeof err), 0);
    signed char out[M];
    double ac[M], bd[M];
    rule_eval_quads(&r, q, M, out, ac, bd);
    for (int i = 0; i < M; i++) {
      if (!convex[i]) {
        assert_int_equal(out[i], -1);
        assert_true(isnan(ac[i]) && isnan(bd[i]));
        continue;
      }
      double x, y;
      assert_int_equal(out[i], rule_eval(&r, q + 4 * i, &x, &y));
      assert_true(ac[i] == x || (isnan(ac[i]) && isnan(x)));
      assert_true(bd[i] == y || (isnan(bd[i]) && isnan(y)));
    }
    rule_eval_quads(&r, q, M, out, NULL, NULL);   /* the values are optional */
    assert_int_equal(out[0], rule_eval(&r, q, NULL, NULL));
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_parse_all),
    cmocka_unit_test(test_list_triangle),
    cmocka_unit_test(test_parse_bad),
    cmocka_unit_test(test_name_grammar),
    cmocka_unit_test(test_anysign_measure),
    cmocka_unit_test(test_compare),
    cmocka_unit_test(test_appendix_b),
    cmocka_unit_test(test_dt_cocircular),
    cmocka_unit_test(test_area_sum_ties),
    cmocka_unit_test(test_rotation),
    cmocka_unit_test(test_reflection),
    cmocka_unit_test(test_quad_registry),
    cmocka_unit_test(test_eval_quads),
    cmocka_unit_test(test_verbs),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
