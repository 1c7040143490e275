/*
** test_flip_cli.c: the `fliplab flip` and `fliplab list` commands as a user
** runs them: decisions and joint values on quadrilaterals worked out by
** hand, clockwise input (relabelled A, D, C, B as `flip --help` says),
** every bad-input path (one line on stderr, exit status 2, no crash), and
** --help / --version.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define TCLI_CAP 65536

static char tcli_out[TCLI_CAP], tcli_err[TCLI_CAP];

static int tcli_run(const char *args) {
  int st = testutil_run(args, tcli_out, sizeof tcli_out, tcli_err, sizeof tcli_err);
  if (st < 0 || st >= 128) {
    print_error("fliplab %s: status %d (crash?)\nstderr: %s\n", args, st, tcli_err);
    fail();
  }
  return st;
}

/* The value after "KEY" at the start of a line of stdout, as a string. */
static const char *tcli_field(const char *key, char *buf, size_t len) {
  size_t kl = strlen(key);
  for (const char *l = tcli_out; l && *l; l = strchr(l, '\n') ? strchr(l, '\n') + 1 : NULL)
    if (strncmp(l, key, kl) == 0 && (l[kl] == ' ' || l[kl] == '\t')) {
      const char *v = l + kl;
      while (*v == ' ' || *v == '\t') v++;
      size_t n = strcspn(v, "\n");
      if (n >= len) n = len - 1;
      memcpy(buf, v, n);
      buf[n] = '\0';
      return buf;
    }
  print_error("no '%s' line in output:\n%s\n", key, tcli_out);
  fail();
  return NULL;
}

static double tcli_number(const char *key) {
  char buf[128];
  tcli_field(key, buf, sizeof buf);
  char *end;
  double v = strtod(buf, &end);
  if (end == buf) {
    print_error("'%s' is not a number: %s\n", key, buf);
    fail();
  }
  return v;
}

static void tcli_expect_decision(const char *args, const char *want) {
  assert_int_equal(tcli_run(args), 0);
  char buf[64];
  tcli_field("decision", buf, sizeof buf);
  if (strcmp(buf, want) != 0) {
    print_error("fliplab %s: decision %s, want %s\n", args, buf, want);
    fail();
  }
}

static int tcli_contains_ci(const char *hay, const char *needle) {
  size_t n = strlen(needle);
  for (; *hay; hay++) {
    size_t i = 0;
    while (i < n && tolower((unsigned char)hay[i]) == tolower((unsigned char)needle[i])) i++;
    if (i == n) return 1;
  }
  return 0;
}

/* A bad input: exit status 2, nothing on stdout, exactly one line on
** stderr, mentioning one of the (|-separated) keywords. */
static void tcli_expect_error(const char *args, const char *keywords) {
  int st = tcli_run(args);
  int named = 0;
  char kw[256];
  snprintf(kw, sizeof kw, "%s", keywords);
  for (char *k = strtok(kw, "|"); k; k = strtok(NULL, "|")) named |= tcli_contains_ci(tcli_err, k);
  if (st != 2 || tcli_out[0] != '\0' || !testutil_one_line(tcli_err) || !named) {
    print_error("fliplab %s: status %d, stdout [%s], stderr [%s] (want status 2, one line naming %s)\n",
                args, st, tcli_out, tcli_err, keywords);
    fail();
  }
}

/* ---- decisions ---- */

/* A = (0,0), B = (2,-1), C = (3,0), D = (2,1): |AC| = 3, |BD| = 2; the
** sides are sqrt5, sqrt2, sqrt2, sqrt5.  P_1 adds the diagonal twice to the
** quadrilateral's perimeter: f(AC) = 2 sqrt5 + 2 sqrt2 + 6, f(BD) = 2 sqrt5
** + 2 sqrt2 + 4 -> BD (the shorter diagonal). */
static void test_flip_p1(void **state) {
  (void)state;
  double base = 2 * sqrt(5.0) + 2 * sqrt(2.0);
  tcli_expect_decision("flip P_1 0 0 2 -1 3 0 2 1", "BD");
  double ac = tcli_number("f(AC)"), bd = tcli_number("f(BD)");
  assert_true(fabs(ac - (base + 6)) <= 1e-13 * (base + 6));
  assert_true(fabs(bd - (base + 4)) <= 1e-13 * (base + 4));
  char buf[64];
  assert_string_equal(tcli_field("rule", buf, sizeof buf), "P_1");
  /* a negative first coordinate is a number, not an option */
  tcli_expect_decision("flip P_1 -1 0 1 -1 2 0 1 1", "BD");
}

/* DT on cocircular and non-cocircular quadrilaterals.  The kite
** (0,-1) (2,0) (0,1) (-1,0): the circle of ABC has centre (3/4, 0) and
** radius 5/4; D is 7/4 from the centre, outside -> AC; -alpha_inf agrees
** (theorem 17).  The unit square is cocircular -> either. */
static void test_flip_dt(void **state) {
  (void)state;
  tcli_expect_decision("flip DT 0 0 1 0 1 1 0 1", "either");
  assert_null(strstr(tcli_out, "f(AC)"));
  tcli_expect_decision("flip DT 0 -1 2 0 0 1 -1 0", "AC");
  tcli_expect_decision("flip -alpha_inf 0 -1 2 0 0 1 -1 0", "AC");
  tcli_expect_decision("flip R_inf 0 -1 2 0 0 1 -1 0", "AC");
  /* the area sum always ties */
  tcli_expect_decision("flip -A_1 0 -1 2 0 0 1 -1 0", "either");
  double ac = tcli_number("f(AC)"), bd = tcli_number("f(BD)");
  assert_true(fabs(ac + 3) <= 1e-15 && fabs(bd + 3) <= 1e-15);   /* area (3 * 2)/2 = 3 */
  /* names needing shell quoting.  b/(c-a) on the kite: ABC has sides
  ** sqrt5, sqrt5, 2 -> sqrt5/(2 - sqrt5) = -9.472; ACD 2, sqrt2, sqrt2 ->
  ** sqrt2/(sqrt2 - 2) = -2.414; ABD and BCD 3, sqrt5, sqrt2 -> sqrt5/(sqrt2
  ** - 3) = -1.410.  Harmonic, negated: AC -1/(1/9.472 + 1/2.414) = -1.924,
  ** BD -1.410/2 = -0.705 -> AC.  -a' on the square: four congruent
  ** triangles -> either. */
  tcli_expect_decision("flip 'b/(c-a)_-1' 0 -1 2 0 0 1 -1 0", "AC");
  tcli_expect_decision("flip \"-a'_inf\" 0 0 1 0 1 1 0 1", "either");
}

/* Clockwise input is relabelled A, D, C, B (flip --help): the diagonals
** keep their names, so the answer and both values equal those of the
** anticlockwise listing A, D, C, B.  In particular a mirror image (x -> -x,
** same order, hence clockwise) gets the same answer as the original. */
static void test_flip_clockwise(void **state) {
  (void)state;
  assert_int_equal(tcli_run("flip --help"), 0);
  assert_true(tcli_contains_ci(tcli_out, "clockwise"));
  assert_true(strstr(tcli_out, "A, D, C, B") != NULL);

  char dec[64], ac[64], bd[64], buf[64];
  static const char *const rules[] = {"P_1", "R_inf", "-alpha_1", "gamma_inf", "sigma_2"};
  for (size_t i = 0; i < sizeof rules / sizeof rules[0]; i++) {
    char cmd[256];
    /* anticlockwise A D C B of the clockwise quadrilateral below */
    snprintf(cmd, sizeof cmd, "flip %s 0 0 2 -1 3 0.5 2 1", rules[i]);
    assert_int_equal(tcli_run(cmd), 0);
    tcli_field("decision", dec, sizeof dec);
    tcli_field("f(AC)", ac, sizeof ac);
    tcli_field("f(BD)", bd, sizeof bd);
    assert_null(strstr(tcli_out, "note"));
    snprintf(cmd, sizeof cmd, "flip %s 0 0 2 1 3 0.5 2 -1", rules[i]);   /* clockwise */
    assert_int_equal(tcli_run(cmd), 0);
    assert_non_null(strstr(tcli_out, "clockwise"));
    assert_string_equal(tcli_field("decision", buf, sizeof buf), dec);
    assert_string_equal(tcli_field("f(AC)", buf, sizeof buf), ac);
    assert_string_equal(tcli_field("f(BD)", buf, sizeof buf), bd);
  }
  /* mirror of the P_1 quadrilateral: clockwise, still BD */
  tcli_expect_decision("flip P_1 0 0 -2 -1 -3 0 -2 1", "BD");
  tcli_expect_decision("flip DT 0 1 2 0 0 -1 -1 0", "AC");   /* the kite, upside down: clockwise */
}

/* Extreme magnitudes.  The kite (0,-k) (2k,0) (0,k) (-k,0) is strictly
** convex at every scale k; the circle of ABC has centre (3k/4, 0) and
** radius 5k/4, D is 7k/4 from it, so DT = AC, hence also R_inf, -alpha_inf
** and abc_1 (DT-equivalent), and P_1 = AC (|AC| = 2k < |BD| = 3k).  Where
** the magnitudes make the arithmetic overflow or underflow, the program
** may refuse the input (the developer guide: absurd sizes are a clear
** one-line error), but it must not print a wrong decision, a NaN, or call
** the polygon non-convex. */
static void test_flip_extreme(void **state) {
  (void)state;
  static const double ks[] = {1e-300, 1e-160, 1e-100, 1e100, 1e160, 1e300};
  static const char *const rules[] = {"DT", "R_inf", "-alpha_inf", "abc_1", "P_1"};
  int bad = 0;
  for (size_t i = 0; i < sizeof ks / sizeof ks[0]; i++)
    for (size_t j = 0; j < sizeof rules / sizeof rules[0]; j++) {
      char cmd[256], buf[64] = "-";
      double k = ks[i];
      snprintf(cmd, sizeof cmd, "flip %s 0 %.17g %.17g 0 0 %.17g %.17g 0", rules[j], -k, 2 * k, k, -k);
      int st = tcli_run(cmd);
      int ok;
      if (st == 0) {
        tcli_field("decision", buf, sizeof buf);
        ok = strcmp(buf, "AC") == 0 && !tcli_contains_ci(tcli_out, "nan");
      } else {
        ok = st == 2 && testutil_one_line(tcli_err) &&
             !tcli_contains_ci(tcli_err, "convex") && !tcli_contains_ci(tcli_err, "collinear");
      }
      if (!ok) {
        if (bad++ < 12)
          print_error("fliplab %s -> status %d, decision %s; stdout [%s] stderr [%s]\n", cmd, st, buf,
                      tcli_out, tcli_err);
      }
    }
  assert_int_equal(bad, 0);
}

/* ---- bad input ---- */

static void test_flip_errors(void **state) {
  (void)state;
  tcli_expect_error("flip", "expected|usage|argument");
  tcli_expect_error("flip P_1", "expected|usage|argument");
  tcli_expect_error("flip P_1 0 0 1 0 1 1 0", "expected|usage|argument");
  tcli_expect_error("flip P_1 0 0 1 0 1 1 0 1 5", "expected|usage|argument|many");
  tcli_expect_error("flip P_1 0 0 1 0 1 1 0 abc", "y4|abc|number");
  tcli_expect_error("flip P_1 0 0 1 0 1 1 0 1x", "y4|1x|number");
  tcli_expect_error("flip P_1 0 0 1 0 1 1 0 ''", "y4|number|empty");
  tcli_expect_error("flip P_1 0 0 1 0 nan 1 0 1", "x3|nan|finite");
  tcli_expect_error("flip P_1 0 0 1 0 1 inf 0 1", "y3|inf|finite");
  tcli_expect_error("flip P_1 0 0 1 0 1 -inf 0 1", "y3|inf|finite");
  tcli_expect_error("flip P_1 0 0 1e400 0 1 1 0 1", "x2|range|finite|1e400");
  tcli_expect_error("flip P_1 0 0 1 0 1 0 0 1", "duplicate");
  tcli_expect_error("flip P_1 0 0 1 1 1 1 0 1", "duplicate");
  tcli_expect_error("flip P_1 0 0 1 0 2 0 0 1", "collinear");
  tcli_expect_error("flip DT 0 0 0 0 0 0 0 0", "duplicate|collinear");
  tcli_expect_error("flip P_1 0 0 2 1 4 0 2 3", "convex");     /* a dart */
  tcli_expect_error("flip P_1 0 0 1 1 1 0 0 1", "convex");     /* a bow tie */
  tcli_expect_error("flip foo 0 0 1 0 1 1 0 1", "foo|unknown");
  tcli_expect_error("flip R_3x 0 0 1 0 1 1 0 1", "R_3x|unknown");
  tcli_expect_error("flip '' 0 0 1 0 1 1 0 1", "rule|unknown|empty");
  tcli_expect_error("flip P_1 0 0 1 0 1 1 0 1 --tie-eps", "tie-eps");
  tcli_expect_error("flip P_1 0 0 1 0 1 1 0 1 --tie-eps -1", "tie-eps");
  tcli_expect_error("flip P_1 0 0 1 0 1 1 0 1 --tie-eps x", "tie-eps");
  tcli_expect_error("flip P_1 0 0 1 0 1 1 0 1 --bogus", "bogus");
  tcli_expect_error("list extra", "extra|argument");
  tcli_expect_error("frobnicate", "frobnicate|unknown");
}

/* ---- list, help, version ---- */

static void test_list(void **state) {
  (void)state;
  assert_int_equal(tcli_run("list"), 0);
  static const char *const measures[] = {
    "-alpha", "beta", "gamma", "a", "-c", "P", "abc", "-A", "R", "-r", "-a'", "-r/R", "-r2/A",
    "-c/a", "-c/P", "a-c", "b/(c-a)", "lambda", "d", "sigma", "Pinf", "Rinf", "-rinf"};
  static const char *const joints[] = {"-inf", "-1", "0", "1", "2", "inf"};
  const char *jsec = strstr(tcli_out, "Joint");
  assert_non_null(jsec);
  for (size_t i = 0; i < sizeof measures / sizeof measures[0]; i++) {
    char pat[64];
    snprintf(pat, sizeof pat, "\n  %s ", measures[i]);
    const char *hit = strstr(tcli_out, pat);
    if (hit == NULL || hit > jsec) {
      print_error("measure %s not listed\n", measures[i]);
      fail();
    }
  }
  for (size_t i = 0; i < sizeof joints / sizeof joints[0]; i++) {
    char pat[64];
    snprintf(pat, sizeof pat, "\n  %s ", joints[i]);
    if (strstr(jsec, pat) == NULL) {
      print_error("joint %s not listed\n", joints[i]);
      fail();
    }
  }
  assert_non_null(strstr(tcli_out, "DT"));
  assert_non_null(strstr(tcli_out, "23"));
}

static void test_help_version(void **state) {
  (void)state;
  assert_int_equal(tcli_run("--help"), 0);
  assert_true(tcli_contains_ci(tcli_out, "usage"));
  assert_non_null(strstr(tcli_out, "flip"));
  assert_int_equal(tcli_run("list --help"), 0);
  assert_true(tcli_contains_ci(tcli_out, "usage"));
  assert_int_equal(tcli_run("flip -h"), 0);
  assert_true(tcli_contains_ci(tcli_out, "usage"));
  assert_int_equal(tcli_run("--version"), 0);
  assert_true(strncmp(tcli_out, "fliplab ", 8) == 0 && isdigit((unsigned char)tcli_out[8]));
  assert_int_equal(tcli_run(""), 2);   /* no command: usage on stderr */
  assert_true(tcli_contains_ci(tcli_err, "usage"));
}

/* A failing flip prints no result: a user measure's NaN or a plugin rule's
** answer outside AC, BD, EITHER is found before the first line. */
static void test_flip_fails_quietly(void **state) {
  (void)state;
  static const char *const runs[] = {
    "--define 'q >= 0 : sqrt(1.2 - a)' flip q_1 0 0 3 0 3 3 0 3",
    "--plugin " FLIPLAB_BUILD_DIR "/plugins/badret.so flip badret 0 0 1 0 1 1 0 1",
  };
  static const char *const want[] = {"not finite", "returned 7"};
  for (int i = 0; i < 2; i++) {
    assert_int_equal(tcli_run(runs[i]), 1);
    assert_string_equal(tcli_out, "");
    assert_true(testutil_one_line(tcli_err));
    if (strstr(tcli_err, want[i]) == NULL) fail_msg("%s: %s", runs[i], tcli_err);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_flip_p1),
    cmocka_unit_test(test_flip_dt),
    cmocka_unit_test(test_flip_clockwise),
    cmocka_unit_test(test_flip_extreme),
    cmocka_unit_test(test_flip_errors),
    cmocka_unit_test(test_flip_fails_quietly),
    cmocka_unit_test(test_list),
    cmocka_unit_test(test_help_version),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
