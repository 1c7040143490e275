/*
** test_joints_cli.c: the power-mean joints l_p as a user meets them: the
** counts of table34 and census under P_3 equal those of the formula measure
** p3 = P^3 with joint 1 (the same decisions), P_1.0 is P_1 byte for byte,
** GOT with P_3 certifies its optimum, every command takes a power mean, and
** bad joint suffixes are refused with one line naming the rule.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define TJC_BUF (1 << 18)

static char tjc_out[TJC_BUF], tjc_err[TJC_BUF], tjc_out2[TJC_BUF];

#define TJC_RUN(...) testutil_runf(tjc_out, TJC_BUF, tjc_err, TJC_BUF, __VA_ARGS__)

/* The CSV row of rule `rule` in text, from its `skip`-th comma on (the
** counts, without the names). */
static const char *tjc_counts(const char *text, const char *rule, int skip, char *buf,
                              size_t len) {
  char key[64];
  snprintf(key, sizeof key, ",%s,", rule);
  const char *row = strstr(text, key);
  if (row == NULL) fail_msg("no row %s in:\n%s", rule, text);
  while (row > text && row[-1] != '\n') row--;
  for (int c = 0; c < skip; c++) row = strchr(row, ',') + 1;
  size_t n = strcspn(row, "\n");
  snprintf(buf, len, "%.*s", (int)(n < len ? n : len - 1), row);
  return buf;
}

/* table34 and census: P_3 decides as p3_1 with p3 = P^3, so the counts are
** the same (census gaps differ: they are measured in each rule's units). */
static void test_power_counts_as_formula(void **state) {
  (void)state;
  char a[256], b[256];
  assert_int_equal(TJC_RUN("--define 'p3 = P^3' table34 --samples 4000 --seed 5 "
                           "--rules P_3,p3_1,DT --format csv"), 0);
  assert_string_equal(tjc_counts(tjc_out, "P_3", 3, a, sizeof a),
                      tjc_counts(tjc_out, "p3_1", 3, b, sizeof b));
  assert_non_null(strstr(tjc_out, "\nP,3,P_3,4000,"));
  static const char *const samplers[] = {"convex", "disc", "square"};
  for (int k = 0; k < 3; k++) {
    assert_int_equal(TJC_RUN("--define 'p3 = P^3' census --sites 7 --sampler %s --samples 300 "
                             "--seed 4 --rules P_3,p3_1 --format csv", samplers[k]), 0);
    tjc_counts(tjc_out, "P_3", 3, a, sizeof a);
    tjc_counts(tjc_out, "p3_1", 3, b, sizeof b);
    *strrchr(a, ',') = '\0';   /* mean_worst_gap */
    *strrchr(b, ',') = '\0';
    assert_string_equal(a, b);
  }
}

/* P_1.0 is the built-in P_1: the same bytes from table34, census and got. */
static void test_power_builtin_alias(void **state) {
  (void)state;
  static const char *const cmds[] = {
    "table34 --samples 2000 --seed 3 --rules %s,DT --format csv",
    "census --sites 6 --samples 200 --rules %s --format csv",
    "got --rule %s --random 30 --seed 2 --csv /dev/stdout",
  };
  for (int k = 0; k < 3; k++) {
    char cmd[256];
    snprintf(cmd, sizeof cmd, cmds[k], "P_1");
    assert_int_equal(testutil_run(cmd, tjc_out2, TJC_BUF, tjc_err, TJC_BUF), 0);
    snprintf(cmd, sizeof cmd, cmds[k], "P_1.0");
    assert_int_equal(testutil_run(cmd, tjc_out, TJC_BUF, tjc_err, TJC_BUF), 0);
    char *t = strstr(tjc_out, "time"), *t2 = strstr(tjc_out2, "time");   /* got's timing */
    if (t && t2) *t = *t2 = '\0';
    assert_string_equal(tjc_out, tjc_out2);
  }
}

/* GOT with a power mean: a certified unique optimum, in key units. */
static void test_power_got(void **state) {
  (void)state;
  assert_int_equal(TJC_RUN("got --rule P_3 --random 40 --seed 3"), 0);
  assert_non_null(strstr(tjc_out, "joint l_3"));
  assert_non_null(strstr(tjc_out, "certified: unique optimum"));
  assert_non_null(strstr(tjc_out, "key units: sums of x^3"));
  assert_int_equal(TJC_RUN("got --rule P_-2 --random 30 --sampler star"), 0);
  assert_non_null(strstr(tjc_out, "key units: -sums of x^-2"));
  assert_int_equal(TJC_RUN("lot --rule P_3 --random 60 --sampler circle --compare GOT"), 0);
}

/* Every command takes a power mean. */
static void test_power_every_command(void **state) {
  (void)state;
  char pts[512], pent[512];
  testutil_tmppath(pts, sizeof pts, "tjc_sites.csv");
  testutil_tmppath(pent, sizeof pent, "tjc_pent.csv");
  testutil_write_file(pts, "x,y\n0,0\n1,0\n2,1\n1,3\n0,2\n0.5,1\n");
  assert_int_equal(TJC_RUN("flip R_-2 1 0 0.5 0.8660254037844386 -1 0 0.5 -0.8660254037844386"),
                   0);
  assert_non_null(strstr(tjc_out, "rule      R_-2\n"));
  assert_int_equal(TJC_RUN("sample --count 20 --out %s", pent), 0);
  assert_int_equal(TJC_RUN("classify --input %s --rule P_3,sigma_0.5,-alpha_7", pent), 0);
  assert_int_equal(testutil_count(tjc_out, ",sigma_0.5,"), 20);
  assert_int_equal(TJC_RUN("rule P_3 --samples 300 --quads 300 --site-samples 30"), 0);
  assert_non_null(strstr(tjc_out, "joint 3 (l_3)"));
  assert_int_equal(TJC_RUN("flipgraph --rule P_3 --points %s", pts), 0);
  assert_non_null(strstr(tjc_out, "rule: P_3\n"));
  assert_int_equal(TJC_RUN("lot --rule -alpha_-0.5 --random 300"), 0);
  assert_non_null(strstr(tjc_out, "status: converged"));
  assert_int_equal(TJC_RUN("table34 --samples 200 --rules P_3,DT"), 0);
  assert_non_null(strstr(tjc_out, "(power)"));
}

/* Bad suffixes: one line, exit 2, naming the rule. */
static void test_power_bad_names(void **state) {
  (void)state;
  static const char *const bad[] = {"P_3x", "P_nan", "P_1e400", "P_0.001", "P_0x3", "P_",
                                    "P_1e", "P_0.1234567890123456"};
  for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
    assert_int_equal(TJC_RUN("flip '%s' 0 0 1 0 1 1 0 1", bad[k]), 2);
    if (!testutil_one_line(tjc_err)) fail_msg("%s: not one line: %s", bad[k], tjc_err);
    assert_non_null(strstr(tjc_err, bad[k]));
    assert_string_equal(tjc_out, "");
  }
  /* The table holds ten power means besides the built-in joints. */
  assert_int_equal(TJC_RUN("table34 --samples 10 --rules P_3,P_4,P_5,P_6,P_7,P_8,P_9,P_10,"
                           "P_11,P_12,P_13"), 2);
  assert_true(testutil_one_line(tjc_err));
  assert_non_null(strstr(tjc_err, "P_13"));
  assert_non_null(strstr(tjc_err, "at most 10"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_power_counts_as_formula),
    cmocka_unit_test(test_power_builtin_alias),
    cmocka_unit_test(test_power_got),
    cmocka_unit_test(test_power_every_command),
    cmocka_unit_test(test_power_bad_names),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
