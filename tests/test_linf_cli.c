/*
** test_linf_cli.c: `fliplab linf` as a user runs it: the example's table
** and claims are the library's (study_linf_examine) and the thesis's
** numbers; the Monte Carlo's counts, shares and intervals are the
** library's for the same seed, for any thread count; every bad option is
** refused in one line with exit status 2 and nothing on standard output.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "study.h"
#include "study_linf.h"
#include "testutil.h"

static char tlc_out[1 << 16], tlc_err[4096];

static void test_example_3d(void **state) {
  (void)state;
  assert_int_equal(testutil_runf(tlc_out, sizeof tlc_out, tlc_err, sizeof tlc_err,
                                 "linf --example 3d"), 0);
  /* the thesis's table rows, each centre with its radius and distances */
  static const char *const rows[] = {
    "ACEF     (4, 4, 6)                4           4    6    4    8    4    4",
    "ACDE     (1, 7, 5)                5           5    9    5    5    5    7",
    "ABEF     (6, 4, 6)                4           4    4    6    8    4    4",
    "BCEF     (5, 3, 9)                5           7    5    5    9    5    5",
    "BCDF     (6, 6, 2)                6           0    6    6    6    8    6",
  };
  for (size_t i = 0; i < sizeof rows / sizeof *rows; i++)
    assert_non_null(strstr(tlc_out, rows[i]));
  study_linf_report r;
  assert_int_equal(study_linf_examine(study_linf_example_find("3d"), &r), 0);
  char line[256];
  snprintf(line, sizeof line, "triangulations of the points %llu: locally Delaunay %llu, "
           "Delaunay %llu\n", (unsigned long long)r.tilings, (unsigned long long)r.tilings_local,
           (unsigned long long)r.tilings_global);
  assert_non_null(strstr(tlc_out, line));
  snprintf(line, sizeof line, "the cells triangulate the points: no (%s)\n", r.why);
  assert_non_null(strstr(tlc_out, line));
  assert_non_null(strstr(tlc_out, "locally Delaunay (a circumcube without the neighbours' far "
                                  "vertices): yes\n"));
  assert_non_null(strstr(tlc_out, "l_inf Delaunay simplices (brute force): ABEF ACDE ACEF BCEF\n"));
  study_linf_report_free(&r);
  assert_int_equal(testutil_runf(tlc_out, sizeof tlc_out, NULL, 0, "linf --example pseudo"), 0);
  assert_non_null(strstr(tlc_out, "(4, 5, 4)"));
  assert_non_null(strstr(tlc_out, "(5, 2, 4)"));
  assert_int_equal(testutil_runf(tlc_out, sizeof tlc_out, NULL, 0, "linf --example r5"), 0);
  assert_int_equal(testutil_count(tlc_out, "ABCDEF   ("), 4);
}

/* The printed table is the library's run of the same options. */
static void tlc_montecarlo(int d, uint64_t trials, uint64_t seed, int threads) {
  assert_int_equal(testutil_runf(tlc_out, sizeof tlc_out, tlc_err, sizeof tlc_err,
                                 "linf --montecarlo --dim %d --trials %llu --seed %llu "
                                 "--threads %d", d, (unsigned long long)trials,
                                 (unsigned long long)seed, threads), 0);
  study_linf_mc mc;
  char err[200];
  assert_int_equal(study_linf_montecarlo(d, trials, seed, 1, &mc, err, sizeof err), 0);
  int rows = 0;
  for (int k = 0; k <= LINF_CUBES_MAX; k++) {
    if (mc.count[k] == 0 && (mc.law_total == 0 || mc.law[k] == 0)) continue;
    double lo, hi;
    study_wilson_z(mc.count[k], trials, STUDY_Z99, &lo, &hi);
    char line[200];
    snprintf(line, sizeof line, "\n%-6d %10llu %9.4f   [%.4f, %.4f]", k,
             (unsigned long long)mc.count[k], 100.0 * (double)mc.count[k] / (double)trials, lo,
             hi);
    assert_non_null(strstr(tlc_out, line));
    rows++;
  }
  assert_int_equal(testutil_count(tlc_out, "\n"), 3 + rows);
}

static void test_montecarlo(void **state) {
  (void)state;
  tlc_montecarlo(5, 3000, 7, 1);
  tlc_montecarlo(5, 3000, 7, 2);
  tlc_montecarlo(7, 500, 1, 2);
  tlc_montecarlo(2, 100, 18446744073709551615ull, 1);
}

static void test_bad_options(void **state) {
  (void)state;
  static const struct { const char *args, *says; } bad[] = {
    {"linf", "give one of --example E and --montecarlo"},
    {"linf --example 3d --montecarlo", "give one of"},
    {"linf --example 4d", "unknown example '4d'"},
    {"linf --example", "--example"},
    {"linf --montecarlo --dim 1", "--dim: 1 is out of range (the dimension must be 2 .. 8)"},
    {"linf --montecarlo --dim 9", "--dim: 9 is out of range"},
    {"linf --montecarlo --dim five", "--dim"},
    {"linf --montecarlo --dim -3", "--dim"},
    {"linf --montecarlo --trials 0", "--trials: 0 is out of range"},
    {"linf --montecarlo --trials -5", "--trials"},
    {"linf --montecarlo --trials 1e20", "--trials"},
    {"linf --montecarlo --seed abc", "--seed"},
    {"linf --montecarlo --seed -1", "--seed"},
    {"linf --montecarlo --seed 18446744073709551616", "--seed"},
    {"linf --montecarlo --threads 0", "--threads"},
    {"linf --example 3d --dim 4", "--dim goes with --montecarlo"},
    {"linf --example 3d --seed 2", "--seed goes with --montecarlo"},
    {"linf --montecarl", "did you mean '--montecarlo'"},
  };
  for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
    int st = testutil_run(bad[i].args, tlc_out, sizeof tlc_out, tlc_err, sizeof tlc_err);
    if (st != 2 || !testutil_one_line(tlc_err) || strstr(tlc_err, bad[i].says) == NULL ||
        tlc_out[0] != 0)
      fail_msg("'%s': exit %d, stderr '%s' (want '%s'), stdout '%.80s'", bad[i].args, st,
               tlc_err, bad[i].says, tlc_out);
  }
}

static void test_stdout_full(void **state) {
  (void)state;
  static const char *const cmds[] = {"linf --example 3d", "linf --montecarlo --trials 100"};
  for (size_t i = 0; i < 2; i++) {
    assert_int_equal(testutil_run_to(cmds[i], "/dev/full", tlc_err, sizeof tlc_err), 1);
    assert_true(testutil_one_line(tlc_err));
    assert_non_null(strstr(tlc_err, "standard output"));
  }
  assert_int_equal(testutil_run("linf --help", tlc_out, sizeof tlc_out, NULL, 0), 0);
  assert_non_null(strstr(tlc_out, "docs/linf.md"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_example_3d),
    cmocka_unit_test(test_montecarlo),
    cmocka_unit_test(test_bad_options),
    cmocka_unit_test(test_stdout_full),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
