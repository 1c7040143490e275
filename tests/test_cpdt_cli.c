/*
** test_cpdt_cli.c: `fliplab cpdt` as a user runs it: the CSV's means are
** the library's counts of the same polygons (study_cpdt_polygon and
** cpdt_triangulate recomputed here), the printed slopes are least-squares
** slopes of the printed means, the plot is well-formed; bad options are
** refused in one line with no output file.
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
#include <unistd.h>

#include "cpdt.h"
#include "splitmix.h"
#include "study_cpdt.h"
#include "testutil.h"

static char tcc_out[1 << 16], tcc_err[4096];

/* The mean of scanned, incircle and flips over `trials` polygons of size n,
** recomputed through the library. */
static void tcc_means(int sampler, uint64_t seed, size_t n, uint64_t trials, int alg,
                      double m[3]) {
  geom_point *p = malloc(n * sizeof *p);
  uint32_t *tri = malloc(3 * n * sizeof *tri);
  assert_non_null(p);
  assert_non_null(tri);
  m[0] = m[1] = m[2] = 0;
  for (uint64_t t = 0; t < trials; t++) {
    assert_int_equal(study_cpdt_polygon(sampler, -1, 0, seed, n, t, p), 0);
    cpdt_counts c;
    assert_int_equal(cpdt_triangulate(p, n, alg, seed ^ GEOM_STREAM_CPDT_GON(n, t), tri, &c), 0);
    m[0] += (double)c.scanned, m[1] += (double)c.incircle, m[2] += (double)c.flips;
  }
  for (int k = 0; k < 3; k++) m[k] /= (double)trials;
  free(p);
  free(tri);
}

static void test_table_is_the_library(void **state) {
  (void)state;
  char csv[512], svg[512];
  testutil_tmppath(csv, sizeof csv, "cpdt.csv");
  testutil_tmppath(svg, sizeof svg, "cpdt.svg");
  assert_int_equal(testutil_runf(tcc_out, sizeof tcc_out, tcc_err, sizeof tcc_err,
                                 "cpdt --sizes 10,40,160 --trials 4 --seed 5 --sampler circle "
                                 "--algorithms circum,random,divide --out %s --plot %s",
                                 csv, svg), 0);
  char *t = testutil_read_file(csv);
  assert_non_null(t);
  assert_int_equal(testutil_count(t, "\n"), 1 + 3 * 3);
  static const char *const names[3] = {"circum", "random", "divide"};
  static const int algs[3] = {CPDT_CIRCUM, CPDT_RANDOM, CPDT_DIVIDE};
  for (size_t n = 10; n <= 160; n *= 4)
    for (int a = 0; a < 3; a++) {
      char key[64];
      snprintf(key, sizeof key, "\ncircle,%zu,%s,4,", n, names[a]);
      const char *row = strstr(t, key);
      assert_non_null(row);
      double v[6];
      assert_int_equal(sscanf(row + strlen(key), "%lf,%lf,%lf,%lf,%*f,%*f,%lf", &v[0], &v[1],
                              &v[2], &v[3], &v[4]), 5);
      double m[3];
      tcc_means(study_cpdt_sampler_find("circle"), 5, n, 4, algs[a], m);
      assert_true(v[0] == m[0] && v[2] == m[1] && v[4] == m[2]);
    }
  free(t);
  char *s = testutil_read_file(svg);
  assert_non_null(s);
  assert_non_null(strstr(s, "<svg"));
  assert_non_null(strstr(s, "</svg>\n"));
  assert_int_equal(testutil_count(s, "<polyline"), 3);
  assert_int_equal(testutil_count(s, "slope "), 3);
  free(s);
  /* The printed slope is the least-squares slope of the printed means
  ** (6 digits each, the slope to 3 decimals: 2e-3 covers both roundings). */
  double x[3], y[3][3], sl[3];
  const char *p = strstr(tcc_out, "\n      10 ");
  assert_non_null(p);
  for (int r = 0; r < 3; r++, p = strchr(p + 1, '\n'))
    assert_int_equal(sscanf(p, "%lf %lf %lf %lf", &x[r], &y[r][0], &y[r][1], &y[r][2]), 4);
  assert_int_equal(sscanf(p, " slope %lf %lf %lf", &sl[0], &sl[1], &sl[2]), 3);
  for (int a = 0; a < 3; a++) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int r = 0; r < 3; r++) {
      double u = log(x[r]), v = log(y[r][a]);
      sx += u, sy += v, sxx += u * u, sxy += u * v;
    }
    TESTUTIL_NEAR(sl[a], (3 * sxy - sx * sy) / (3 * sxx - sx * sx), 0, 2e-3);
  }
}

/* Each refusal: exit 2, one line naming the problem, no file written. */
static void test_refusals(void **state) {
  (void)state;
  char csv[512];
  testutil_tmppath(csv, sizeof csv, "cpdt_refused.csv");
  static const struct { const char *args, *says; } bad[] = {
    {"--sampler polygon", "unknown sampler 'polygon'"},
    {"--sampler naive --sizes 10,20", "--sizes: 20: sampler naive takes n up to 10"},
    {"--sampler rejection", "sampler rejection weights its polygons"},
    {"--sampler vector --region disc", "sampler vector draws no points from a region"},
    {"--sampler valtr --region disc", "sampler valtr does not draw in the disc"},
    {"--sampler iteration --region moon", "unknown region 'moon'"},
    {"--sampler circle --law 1", "law 1: sampler circle takes laws 0 .. 0"},
    {"--sizes 31,2", "--sizes"},
    {"--sizes 31,,62", "--sizes"},
    {"--sizes 1e12", "--sizes"},
    {"--algorithms circum,walk", "unknown algorithm 'walk'"},
    {"--algorithms divide,divide", "'divide' given twice"},
    {"--trials 0", "--trials"},
    {"--measure flops", "unknown measure 'flops'"},
    {"--plot x.png", "--plot"},
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    unlink(csv);
    int st = testutil_runf(tcc_out, sizeof tcc_out, tcc_err, sizeof tcc_err,
                           "cpdt --trials 2 %s --out %s", bad[i].args, csv);
    if (st != 2 || !testutil_one_line(tcc_err) || strstr(tcc_err, bad[i].says) == NULL)
      fail_msg("'%s': status %d, stderr '%s'", bad[i].args, st, tcc_err);
    assert_int_equal(access(csv, F_OK), -1);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_table_is_the_library),
    cmocka_unit_test(test_refusals),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
