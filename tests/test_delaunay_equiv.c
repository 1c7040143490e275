/*
** test_delaunay_equiv.c: the rules that the thesis proves (or table 3.4
** reports) equal to the Delaunay rule agree with the exact DT on 100,000
** random convex quadrilaterals away from cocircular ones: R_f for all six
** joints (theorem 3), -alpha_inf (17), -r_1 (16), abc_1 (18), -r/R_1 and
** -r2/A_0 (table 3.4), and the theorem 19/20 quantities rR_1 and
** (Rr^2/A)_0 registered as user measures.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "measure.h"
#include "rule.h"
#include "geom.h"
#include "testutil.h"

#define TDT_QUADS 100000
#define TDT_MAXRULES 16

static double tdt_rR(const geom_tri *t, void *ctx) {
  (void)ctx;
  return t->r * t->R;
}

static double tdt_Rr2A(const geom_tri *t, void *ctx) {
  (void)ctx;
  return t->R * t->r * t->r / t->area;
}

/* How far D is from the circle of ABC, relative to the size of the terms:
** the incircle determinant over the sum of the absolute values of its
** terms (its "permanent").  Floating-point evaluation errs by at most
** ~1e-15 of the permanent, so above 1e-9 the sign is certain and the
** quadrilateral is clearly not cocircular. */
static double tdt_relative_incircle(const geom_point q[4]) {
  double adx = q[0].x - q[3].x, ady = q[0].y - q[3].y;
  double bdx = q[1].x - q[3].x, bdy = q[1].y - q[3].y;
  double cdx = q[2].x - q[3].x, cdy = q[2].y - q[3].y;
  double al = adx * adx + ady * ady, bl = bdx * bdx + bdy * bdy, cl = cdx * cdx + cdy * cdy;
  double det = al * (bdx * cdy - cdx * bdy) + bl * (cdx * ady - adx * cdy) + cl * (adx * bdy - bdx * ady);
  double perm = al * (fabs(bdx * cdy) + fabs(cdx * bdy)) + bl * (fabs(cdx * ady) + fabs(adx * cdy)) +
                cl * (fabs(adx * bdy) + fabs(bdx * ady));
  return det / perm;
}

static void test_dt_equivalent_rules(void **state) {
  (void)state;
  static const char *const names[] = {"R_-inf", "R_-1", "R_0", "R_1", "R_2", "R_inf", "-alpha_inf",
                                      "-r_1", "abc_1", "-r/R_1", "-r2/A_0", "tests2rR_1",
                                      "tests2Rr2A_0"};
  const int nr = (int)(sizeof names / sizeof names[0]);
  measure m1 = {"tests2rR", "rR", "inradius times circumradius (theorem 19)", MEASURE_NONNEG, tdt_rR, NULL};
  measure m2 = {"tests2Rr2A", "Rr^2/A", "R r^2 / A (theorem 20)", MEASURE_NONNEG, tdt_Rr2A, NULL};
  assert_true(measure_register(&m1) >= 0);
  assert_true(measure_register(&m2) >= 0);
  rule rules[TDT_MAXRULES];
  for (int i = 0; i < nr; i++) {
    char err[4096];
    if (rule_parse(names[i], &rules[i], err, sizeof err) < 0) {
      print_error("%s: %s\n", names[i], err);
      fail();
    }
  }
  rule dt = rule_delaunay();
  int disagree[TDT_MAXRULES] = {0}, either[TDT_MAXRULES] = {0}, skipped = 0, n_ac = 0;
  double worst_kept = 1;
  testutil_rng g = {20240601};
  for (int n = 0; n < TDT_QUADS; n++) {
    geom_point q[4];
    testutil_convex_quad(&g, q);
    double rel = fabs(tdt_relative_incircle(q));
    if (rel < 1e-9) {
      skipped++;
      continue;
    }
    if (rel < worst_kept) worst_kept = rel;
    rule_choice d = rule_eval(&dt, q, NULL, NULL);
    assert_true(d == RULE_AC || d == RULE_BD);
    n_ac += d == RULE_AC;
    geom_tri t[4];   /* ABC, ACD, ABD, BCD */
    testutil_quad_tris(q, t);
    for (int i = 0; i < nr; i++) {
      double ac, bd;
      rule_choice c = rule_eval_tris(&rules[i], &t[0], &t[1], &t[2], &t[3], &ac, &bd);
      if (c == d) continue;
      if (c == RULE_EITHER) either[i]++;
      if (disagree[i]++ < 3)
        print_error("%s = %s, DT = %s on (%.17g,%.17g) (%.17g,%.17g) (%.17g,%.17g) (%.17g,%.17g) "
                    "[values %.17g %.17g, relative incircle %.3g]\n",
                    names[i], rule_choice_str(c), rule_choice_str(d), q[0].x, q[0].y, q[1].x, q[1].y,
                    q[2].x, q[2].y, q[3].x, q[3].y, ac, bd, rel);
    }
  }
  print_message("%d quadrilaterals, %d skipped as nearly cocircular (|rel. incircle| < 1e-9), "
                "DT = AC on %d; smallest kept |rel. incircle| %.3g\n",
                TDT_QUADS, skipped, n_ac, worst_kept);
  int total = 0;
  for (int i = 0; i < nr; i++) {
    if (disagree[i])
      print_error("%s disagrees with DT on %d quadrilaterals (%d of them EITHER)\n", names[i],
                  disagree[i], either[i]);
    total += disagree[i];
  }
  measure_unregister_user();
  assert_true(skipped < TDT_QUADS / 1000);
  assert_int_equal(total, 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_dt_equivalent_rules),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
