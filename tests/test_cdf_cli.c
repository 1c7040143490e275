/*
** test_cdf_cli.c: `fliplab lot --cdf FILE.csv`: the convex-distance Delaunay
** graph of an empty-shape rule's LOT, its count line, its CSV and its SVG;
** refused with any other rule.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "testutil.h"

static char tcc_out[1 << 16], tcc_err[4096];

/* --cdf with a rule that is not ES:SHAPE: one line, exit 2, no file. */
static void test_cdf_cli_refused(void **state) {
  (void)state;
  char path[512];
  testutil_tmppath(path, sizeof path, "cdf_refused.csv");
  unlink(path);
  const char *rules[] = {"DT", "P_1", "-alpha_inf"};
  for (int i = 0; i < 3; i++) {
    int rc = testutil_runf(tcc_out, sizeof tcc_out, tcc_err, sizeof tcc_err,
                           "lot --rule %s --random 20 --cdf %s", rules[i], path);
    assert_int_equal(rc, 2);
    assert_true(testutil_one_line(tcc_err));
    assert_non_null(strstr(tcc_err, "--cdf needs an empty-shape rule"));
    assert_non_null(strstr(tcc_err, rules[i]));
    assert_int_equal(tcc_out[0], '\0');
    assert_int_equal(access(path, F_OK), -1);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_cdf_cli_refused),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
