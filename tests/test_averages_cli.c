/*
** test_averages_cli.c: `fliplab averages` prints chapter 5's averages as the
** thesis defines them (docs/averages.md).
**  - T_c's exact value for n = 1 .. 25 is 4^n / C_n - (2n+1), worked here in
**    64-bit integers and reduced; the decimal column is the exact value's;
**  - with --enumerate every row says "yes" for n = 1 .. 9, and the columns
**    enumerated and exact are equal text;
**  - --degrees prints G^d_n for d = 0 .. n-1, whose sum is C_n;
**  - --out writes the same bytes to a file;
**  - bad input (no --n, 0, a reversed or malformed range, too many values,
**    --enumerate past 18, n past the bound) is one line, status 2.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define TA_CAP (1 << 16)
static char ta_out[TA_CAP], ta_err[TA_CAP];

static uint64_t ta_gcd(uint64_t a, uint64_t b) {
  while (b) {
    uint64_t t = a % b;
    a = b;
    b = t;
  }
  return a;
}

/* The row `name` of the output: its exact text, decimal, enumerated, match. */
static int ta_row(const char *out, const char *name, char f[4][128]) {
  char key[40];
  snprintf(key, sizeof key, "\n  %s ", name);
  const char *p = strstr(out, key);
  if (!p) return 0;
  char line[1024];
  p += strlen(key);
  size_t len = strcspn(p, "\n");
  if (len >= sizeof line) fail_msg("row %s too long", name);
  memcpy(line, p, len);
  line[len] = 0;
  memset(f, 0, 4 * 128);
  return sscanf(line, "%127s %127s %127s %127s", f[0], f[1], f[2], f[3]);
}

static void test_tc_exact(void **state) {
  (void)state;
  uint64_t cat = 1;                            /* C_n */
  for (int n = 1; n <= 25; n++) {
    cat = cat * 2 * (2 * (uint64_t)n - 1) / ((uint64_t)n + 1);
    uint64_t num = (UINT64_C(1) << (2 * n)) - (2 * (uint64_t)n + 1) * cat, g = ta_gcd(num, cat);
    char want[64], args[64], f[4][128];
    if (cat / g == 1) snprintf(want, sizeof want, "%" PRIu64, num / g);
    else snprintf(want, sizeof want, "%" PRIu64 "/%" PRIu64, num / g, cat / g);
    snprintf(args, sizeof args, "averages --n %d", n);
    assert_int_equal(testutil_run(args, ta_out, TA_CAP, ta_err, TA_CAP), 0);
    assert_int_equal(ta_row(ta_out, "Tc", f), 2);
    assert_string_equal(f[0], want);
    TESTUTIL_NEAR(strtod(f[1], NULL), (double)num / (double)cat, 1e-11, 0);
  }
}

static void test_enumerate_matches(void **state) {
  (void)state;
  assert_int_equal(testutil_run("averages --n 1..9 --enumerate --degrees", ta_out, TA_CAP,
                                ta_err, TA_CAP), 0);
  assert_int_equal(testutil_count(ta_out, "n = "), 9);
  assert_int_equal(testutil_count(ta_out, " NO\n"), 0);
  /* 9 quantities (6 at n = 1) and n degree counts per block */
  assert_int_equal(testutil_count(ta_out, " yes\n"), 6 + 1 + 8 * 9 + 44);
  char f[4][128];
  assert_int_equal(ta_row(ta_out, "Ti", f), 4);       /* the last block's */
  assert_string_equal(f[0], f[2]);
}

static void test_degrees_sum(void **state) {
  (void)state;
  assert_int_equal(testutil_run("averages --n 12 --degrees", ta_out, TA_CAP, ta_err, TA_CAP), 0);
  uint64_t sum = 0;
  for (int d = 0; d < 12; d++) {
    char name[16], f[4][128];
    snprintf(name, sizeof name, "G^%d", d);
    assert_int_equal(ta_row(ta_out, name, f), 1);
    sum += strtoull(f[0], NULL, 10);
  }
  assert_true(sum == 208012);                  /* C_12 */
  assert_null(strstr(ta_out, "G^12"));
}

static void test_out_file(void **state) {
  (void)state;
  char path[512], args[1024];
  testutil_tmppath(path, sizeof path, "averages_out.txt");
  snprintf(args, sizeof args, "averages --n 3..5 --out %s", path);
  assert_int_equal(testutil_run(args, ta_out, TA_CAP, ta_err, TA_CAP), 0);
  assert_string_equal(ta_out, "");
  char *file = testutil_read_file(path);
  assert_int_equal(testutil_run("averages --n 3..5", ta_out, TA_CAP, ta_err, TA_CAP), 0);
  assert_string_equal(file, ta_out);
  free(file);
}

static void test_bad_input(void **state) {
  (void)state;
  static const char *const bad[][2] = {
    {"averages", "--n N[..M] is required"},
    {"averages --n 0", "need 1 <= N"},
    {"averages --n 5..3", "need 1 <= N"},
    {"averages --n 3..", "expects N or N..M"},
    {"averages --n ..3", "expects N or N..M"},
    {"averages --n 2.5", "expects N or N..M"},
    {"averages --n 1..1001", "at most 1000 values"},
    {"averages --n 100001", "need 1 <= N"},
    {"averages --n 17..19 --enumerate", "n goes up to 18"},
    {"averages --n", "--n"},
  };
  for (size_t q = 0; q < sizeof bad / sizeof *bad; q++) {
    int st = testutil_run(bad[q][0], ta_out, TA_CAP, ta_err, TA_CAP);
    if (st != 2 || !testutil_one_line(ta_err) || !strstr(ta_err, bad[q][1]))
      fail_msg("fliplab %s: status %d, stderr '%s' lacks '%s'", bad[q][0], st, ta_err,
               bad[q][1]);
    assert_string_equal(ta_out, "");
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_tc_exact),
    cmocka_unit_test(test_enumerate_matches),
    cmocka_unit_test(test_degrees_sum),
    cmocka_unit_test(test_out_file),
    cmocka_unit_test(test_bad_input),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
