/*
** test_weighted_cli.c: `fliplab lot --rule WDT --weights W.csv` as a user
** runs it: the triangles of --out are the library's regular triangulation
** of the same weighted points, the redundant line names the library's
** sites left out, --check passes; bad weights and weights where they do
** not apply are refused in one line, with no output file.
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

#include "lot.h"
#include "rule.h"
#include "sampler.h"
#include "splitmix.h"
#include "testutil.h"

#define TWC_N 400

static char twc_out[1 << 16], twc_err[4096];
static geom_point twc_p[TWC_N];
static double twc_w[TWC_N];
static char twc_pts[512], twc_wts[512], twc_tri[512];

/* Random points and weights (a few percent redundant), in files. */
static int twc_setup(void **state) {
  (void)state;
  sampler_points(SAMPLER_UNIFORM, 9, TWC_N, twc_p);
  uint64_t s = 99;
  testutil_tmppath(twc_pts, sizeof twc_pts, "wdt_pts.csv");
  testutil_tmppath(twc_wts, sizeof twc_wts, "wdt_w.csv");
  testutil_tmppath(twc_tri, sizeof twc_tri, "wdt_tri.csv");
  FILE *f = fopen(twc_pts, "w"), *g = fopen(twc_wts, "w");
  if (f == NULL || g == NULL) return -1;
  fprintf(f, "x,y\n");
  fprintf(g, "w\n");
  for (int i = 0; i < TWC_N; i++) {
    twc_w[i] = 4e-3 * geom_unit53(geom_splitmix64(&s));
    fprintf(f, "%.17g,%.17g\n", twc_p[i].x, twc_p[i].y);
    fprintf(g, "%.17g\n", twc_w[i]);
  }
  return fclose(f) | fclose(g);
}

/* The program's --out against lot_build; the redundant line against
** lot_get_redundant. */
static void test_same_as_library(void **state) {
  (void)state;
  assert_int_equal(testutil_runf(twc_out, sizeof twc_out, twc_err, sizeof twc_err,
                                 "lot --rule WDT --points %s --weights %s --check --out %s",
                                 twc_pts, twc_wts, twc_tri), 0);
  assert_non_null(strstr(twc_out, "check: ok"));
  rule r;
  char err[256];
  assert_int_equal(rule_parse("WDT", &r, err, sizeof err), 0);
  lot_options o;
  lot_options_init(&o, &r);
  lot_options_set_weights(&o, twc_w);
  lot *L;
  assert_int_equal(lot_build(&L, twc_p, TWC_N, &o, err, sizeof err), 0);
  const lot_stats *st = lot_get_stats(L);
  uint32_t *t = malloc(3 * st->triangles * sizeof *t), red[TWC_N];
  assert_non_null(t);
  lot_get_triangles(L, t);
  size_t nred = lot_get_redundant(L, red);
  assert_true(nred > 0);
  char line[256];
  int len = snprintf(line, sizeof line, "\nredundant: %zu sites", nred);
  assert_non_null(strstr(twc_out, line));
  len = snprintf(line, sizeof line, "rounds):");
  for (size_t k = 0; k < nred && k < 5; k++)
    len += snprintf(line + len, sizeof line - (size_t)len, " %u", red[k]);
  assert_non_null(strstr(twc_out, line));
  char *csv = testutil_read_file(twc_tri), *at = strchr(csv, '\n') + 1;
  for (size_t k = 0; k < st->triangles; k++) {
    unsigned a, b, c;
    assert_int_equal(sscanf(at, "%u,%u,%u", &a, &b, &c), 3);
    assert_true(a == t[3 * k] && b == t[3 * k + 1] && c == t[3 * k + 2]);
    at = strchr(at, '\n') + 1;
  }
  assert_int_equal(*at, '\0');
  free(csv);
  free(t);
  lot_free(L);
}

/* One line, exit 2, no output file. */
static void twc_refused(const char *extra, const char *weights, const char *why) {
  unlink(twc_tri);
  int rc = testutil_runf(twc_out, sizeof twc_out, twc_err, sizeof twc_err,
                         "lot --points %s --weights %s --out %s %s", twc_pts, weights, twc_tri,
                         extra);
  assert_int_equal(rc, 2);
  assert_true(testutil_one_line(twc_err));
  if (strstr(twc_err, why) == NULL) fail_msg("'%s' lacks '%s'", twc_err, why);
  assert_int_equal(access(twc_tri, F_OK), -1);
}

static void test_refused(void **state) {
  (void)state;
  twc_refused("--rule P_1", twc_wts, "weights apply to the weighted Delaunay rule WDT, not P_1");
  twc_refused("--rule WDT --algorithm sweep", twc_wts, "it needs rule DT or ES:SHAPE");
  char bad[512];
  testutil_tmppath(bad, sizeof bad, "wdt_bad.csv");
  testutil_write_file(bad, "w\n0\n1\n");
  twc_refused("--rule WDT", bad, "2 weights for 400 points");
  testutil_write_file(bad, "0\n1e61\n");
  twc_refused("--rule WDT", bad, "line 2: weight '1e61' is out of range (weights must be 0 or");
  testutil_write_file(bad, "0,1\n");
  twc_refused("--rule WDT", bad, "line 1: expected 1 field w, got 2");
  assert_int_equal(testutil_runf(twc_out, sizeof twc_out, twc_err, sizeof twc_err,
                                 "lot --rule WDT --random 30 --weights %s", twc_wts), 2);
  assert_non_null(strstr(twc_err, "--weights needs --points"));
  unlink(bad);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_same_as_library),
    cmocka_unit_test(test_refused),
  };
  return cmocka_run_group_tests(tests, twc_setup, NULL);
}
