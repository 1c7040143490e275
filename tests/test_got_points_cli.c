/*
** test_got_points_cli.c: `fliplab got --points` and `--random N --distribution NAME`
** end to end (docs/got.md, "Point sets").
**
** - the printed total equals the sum of the listed triangles' badness (P_1) and of the
**   --csv file's rows, which number 2n - h - 2 (Euler; h hull points); the SVG has a
**   dot per point; the LOT's total printed is at least the GOT's;
** - points in convex position, anticlockwise, with --skeleton all: the total line of
**   `got --polygon` on the same file, byte for byte;
** - --threads 1 and 2 print the same total and triangles;
** - --gap-table: a row per rule; R_1, whose GOT is the Delaunay triangulation, has its
**   LOT (the Delaunay triangulation) equal to the GOT in every set;
** - bad input gets one line on stderr and exit status 2: a non-sum rule, duplicate
**   points (both rows named), collinear points, too many points for memory, an unknown
**   distribution or skeleton, conflicting options, a missing file.
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

#include "testutil.h"

#define TGPC_CAP (1 << 20)
static char tgpc_out[TGPC_CAP], tgpc_err[TGPC_CAP];

#define TGPC_RUN(...) \
  testutil_runf(tgpc_out, sizeof tgpc_out, tgpc_err, sizeof tgpc_err, __VA_ARGS__)

static double tgpc_after(const char *out, const char *key) {
  const char *t = strstr(out, key);
  if (t == NULL) fail_msg("no '%s' in:\n%s", key, out);
  return strtod(t + strlen(key), NULL);
}

/* Sum of the listed triangles' badness, and their count. */
static double tgpc_listed(const char *out, int *count) {
  const char *t = strstr(out, "\ntriangles: ");
  assert_non_null(t);
  t = strchr(t + 1, '\n');
  double s = 0;
  *count = 0;
  for (unsigned a, b, c; t && t[1]; t = strchr(t + 1, '\n')) {
    double v;
    if (sscanf(t + 1, "%u %u %u %lf", &a, &b, &c, &v) != 4) break;
    assert_true(a < b && b < c);
    s += v, (*count)++;
  }
  return s;
}

/* Ten points: a hexagon's corners (h = 6) and four inside. */
static const char tgpc_pts[] =
  "x,y\n2,0\n1,1.7\n-1,1.8\n-2,0.1\n-1.1,-1.7\n1,-1.75\n0.1,0.2\n0.7,-0.4\n-0.6,0.5\n"
  "-0.3,-0.8\n";

static void test_outputs(void **state) {
  (void)state;
  char in[512], csv[512], svg[512];
  testutil_tmppath(in, sizeof in, "gp_in.csv");
  testutil_tmppath(csv, sizeof csv, "gp_out.csv");
  testutil_tmppath(svg, sizeof svg, "gp_out.svg");
  testutil_write_file(in, tgpc_pts);
  assert_int_equal(TGPC_RUN("got --rule P_1 --points %s --csv %s --svg %s --shade", in, csv,
                            svg), 0);
  int count;
  double total = tgpc_after(tgpc_out, "total badness: "), sum = tgpc_listed(tgpc_out, &count);
  assert_int_equal(count, 2 * 10 - 6 - 2);
  assert_true(fabs(total - sum) <= 1e-12 * total);
  assert_true(tgpc_after(tgpc_out, "LOT (incremental): total ") >= total * (1 - 1e-12));
  assert_non_null(strstr(tgpc_out, "certified: unique optimum"));
  assert_non_null(strstr(tgpc_out, "skeleton: lmt, "));
  char *c = testutil_read_file(csv), *s = testutil_read_file(svg);
  assert_non_null(c);
  assert_non_null(s);
  assert_int_equal(testutil_count(c, "\n"), 1 + count);
  assert_non_null(strstr(s, "<svg"));
  free(c);
  free(s);
  char out1[4096];
  assert_int_equal(TGPC_RUN("got --rule a_2 --random 150 --distribution disc --threads 1 "
                            "--print-triangles --no-lot"), 0);
  snprintf(out1, sizeof out1, "%s", strstr(tgpc_out, "total badness"));
  assert_int_equal(TGPC_RUN("got --rule a_2 --random 150 --distribution disc --threads 2 "
                            "--print-triangles --no-lot"), 0);
  assert_memory_equal(out1, strstr(tgpc_out, "total badness"), strcspn(out1, "\n"));
}

/* Points in convex position: the polygon's GOT line for line (total, runner-up). */
static void test_convex_is_polygon(void **state) {
  (void)state;
  char in[512], a[4096];
  testutil_tmppath(in, sizeof in, "gp_convex.csv");
  testutil_write_file(in, "x,y\n0,0\n3,-1\n5,0.5\n6,3\n4,5.5\n1,5\n-1,2.5\n");
  assert_int_equal(TGPC_RUN("got --rule P_1 --polygon %s", in), 0);
  snprintf(a, sizeof a, "%s", strstr(tgpc_out, "total badness"));
  assert_int_equal(TGPC_RUN("got --rule P_1 --points %s --skeleton all", in), 0);
  const char *b = strstr(tgpc_out, "total badness");
  assert_memory_equal(a, b, strcspn(a, "\n") + 1);
}

static void test_gap_table(void **state) {
  (void)state;
  assert_int_equal(TGPC_RUN("got --gap-table 6 --random 12 --rule R_1,P_1 --threads 2"), 0);
  const char *r = strstr(tgpc_out, "\nR_1 ");
  assert_non_null(r);
  assert_non_null(strstr(tgpc_out, "\nP_1 "));
  double mean, lo, hi, max, eq;
  assert_int_equal(sscanf(r, " R_1 %lf [%lf, %lf] %lf %lf%%", &mean, &lo, &hi, &max, &eq), 5);
  assert_true(eq == 100.0 && max <= 1e-12);
}

/* One line on stderr, exit 2, containing want. */
static void tgpc_refused(const char *args, const char *want) {
  int rc = TGPC_RUN("got %s", args);
  if (rc != 2 || !testutil_one_line(tgpc_err) || strstr(tgpc_err, want) == NULL)
    fail_msg("got %s: exit %d, stderr '%s' (wanted '%s')", args, rc, tgpc_err, want);
}

static void test_refusals(void **state) {
  (void)state;
  char in[512], dup[512], col[512], args[2048];
  testutil_tmppath(in, sizeof in, "gp_in2.csv");
  testutil_tmppath(dup, sizeof dup, "gp_dup.csv");
  testutil_tmppath(col, sizeof col, "gp_col.csv");
  testutil_write_file(in, tgpc_pts);
  testutil_write_file(dup, "x,y\n0,0\n1,0\n0,1\n1,0\n");
  testutil_write_file(col, "x,y\n0,0\n1,1\n2,2\n3,3\n");
  snprintf(args, sizeof args, "--rule P_inf --points %s", in);
  tgpc_refused(args, "not a sum rule");
  snprintf(args, sizeof args, "--rule DT --points %s", in);
  tgpc_refused(args, "not triangle-based");
  snprintf(args, sizeof args, "--rule P_1 --points %s", dup);
  tgpc_refused(args, "points 1 and 3 (0-based rows) are equal");
  snprintf(args, sizeof args, "--rule P_1 --points %s", col);
  tgpc_refused(args, "collinear");
  snprintf(args, sizeof args, "--rule P_1 --points %s --compare DT", in);
  tgpc_refused(args, "--compare DT");
  snprintf(args, sizeof args, "--rule P_1 --points %s --gap-table 3", in);
  tgpc_refused(args, "--gap-table");
  snprintf(args, sizeof args, "--rule P_1 --points %s --skeleton none", in);
  tgpc_refused(args, "unknown skeleton");
  snprintf(args, sizeof args, "--rule P_1 --points %s --random 5", in);
  tgpc_refused(args, "exactly one of");
  tgpc_refused("--rule P_1 --points /nonexistent/p.csv", "/nonexistent/p.csv");
  tgpc_refused("--rule P_1 --random 100000000000 --distribution uniform", "GB");
  tgpc_refused("--rule P_1 --random 5 --distribution nope", "unknown sampler 'nope'");
  tgpc_refused("--rule P_1 --random 8 --distribution dups", "are equal");
  tgpc_refused("--rule P_1 --random 8 --distribution uniform --sampler star", "--sampler");
  tgpc_refused("--rule P_1 --random 8 --skeleton all", "apply to point sets");
  tgpc_refused("--rule P_1 --random 8 --no-lot", "apply to point sets");
  tgpc_refused("--rule P_1,R_inf --random 8 --gap-table 2", "R_inf is not a sum rule");
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_outputs),
    cmocka_unit_test(test_convex_is_polygon),
    cmocka_unit_test(test_gap_table),
    cmocka_unit_test(test_refusals),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
