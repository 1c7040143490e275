/*
** test_lot_sweep_cli.c: `fliplab lot --algorithm sweep` from the command
** line: the header and time lines, --check and --compare DT on every
** sampler, the same --out file as the incremental and flip algorithms
** (unique Delaunay triangulation, and a grid's ties; a polygon rule on a
** grid: its sweep: line and the checked ties), and the refusals (a rule
** other than DT, --order, an unknown algorithm naming sweep among the valid
** ones).
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

static char tsc_out[1 << 16], tsc_err[4096];

static int tsc_run(const char *fmt, const char *a, const char *b) {
  return testutil_runf(tsc_out, sizeof tsc_out, tsc_err, sizeof tsc_err, fmt, a, b);
}

static void test_samplers(void **state) {
  (void)state;
  const char *samplers[] = {"uniform", "normal", "disc", "grid", "parabola", "circle"};
  for (int i = 0; i < 6; i++) {
    assert_int_equal(tsc_run("lot --rule DT --random 3000 --sampler %s --algorithm sweep "
                             "--check --compare DT%s", samplers[i], ""), 0);
    assert_non_null(strstr(tsc_out, "sweep algorithm, tie-eps"));
    assert_non_null(strstr(tsc_out, "(ordering "));
    assert_non_null(strstr(tsc_out, " s, sweep "));
    /* flips only at ties (cocircular sites: grid, circle), to lot's tie-break */
    if (i < 3 || i == 4) assert_non_null(strstr(tsc_out, "flips: 0\n"));
    assert_non_null(strstr(tsc_out, "check: ok"));
    /* the tie-break is shared, so the same triangles as the incremental DT everywhere */
    assert_non_null(strstr(tsc_out, "(100.00% of triangles)"));
  }
}

/* Files a and b hold the same triangles, byte for byte (and some). */
static void tsc_same_files(const char *a, const char *b) {
  char *x = testutil_read_file(a), *y = testutil_read_file(b);
  assert_non_null(x);
  assert_non_null(y);
  assert_true(strlen(x) > 1000);
  assert_string_equal(x, y);
  free(x);
  free(y);
}

/* Byte for byte the incremental and flip algorithms' triangles: where the
** Delaunay triangulation is unique (normal) and on a grid, whose ties lot's
** tie-break settles the same way in all three. */
static void test_same_out(void **state) {
  (void)state;
  const char *dir = FLIPLAB_BUILD_DIR "/tests";
  char a[512], b[512];
  snprintf(a, sizeof a, "%s/sweep_cli_a.csv", dir);
  snprintf(b, sizeof b, "%s/sweep_cli_b.csv", dir);
  const char *samplers[] = {"normal", "grid"}, *others[] = {"incremental", "flip"};
  for (int i = 0; i < 4; i++) {
    assert_int_equal(tsc_run("lot --rule DT --random 5000 --sampler %s --seed 4 "
                             "--algorithm sweep --out %s", samplers[i / 2], a), 0);
    char opt[600];
    snprintf(opt, sizeof opt, "%s --out %s", others[i % 2], b);
    assert_int_equal(tsc_run("lot --rule DT --random 5000 --sampler %s --seed 4 "
                             "--algorithm %s", samplers[i / 2], opt), 0);
    tsc_same_files(a, b);
  }
  remove(a);
  remove(b);
}

/* A polygon on a grid (sites in special position, once refused): the
** sweep: line counts the ties, --check passes and counts the ties it
** checked against the tie-break, and --out is the incremental and flip
** algorithms' byte for byte. */
static void test_polygon_grid(void **state) {
  (void)state;
  const char *dir = FLIPLAB_BUILD_DIR "/tests";
  char a[512], b[512];
  snprintf(a, sizeof a, "%s/sweep_cli_pa.csv", dir);
  snprintf(b, sizeof b, "%s/sweep_cli_pb.csv", dir);
  const char *rules[] = {"ES:square", "ES:diamond"}, *others[] = {"incremental", "flip"};
  for (int i = 0; i < 4; i++) {
    assert_int_equal(tsc_run("lot --rule %s --random 400 --sampler grid --algorithm sweep "
                             "--check --out %s", rules[i / 2], a), 0);
    assert_non_null(strstr(tsc_out, "\nsweep: "));
    assert_non_null(strstr(tsc_out, " ties in special position (decided by a fixed order, "
                                    "then the "));
    assert_non_null(strstr(tsc_out, " ties, every one as the tie-break settles it\n"));
    char opt[600];
    snprintf(opt, sizeof opt, "%s --out %s", others[i % 2], b);
    assert_int_equal(tsc_run("lot --rule %s --random 400 --sampler grid --algorithm %s",
                             rules[i / 2], opt), 0);
    assert_null(strstr(tsc_out, "\nsweep: "));
    tsc_same_files(a, b);
  }
  remove(a);
  remove(b);
}

static void test_refusals(void **state) {
  (void)state;
  assert_int_equal(tsc_run("lot --rule P_1 --random 20 --algorithm sweep%s%s", "", ""), 2);
  assert_non_null(strstr(tsc_err, "needs rule DT or ES:SHAPE (got P_1)"));
  assert_int_equal(tsc_run("lot --rule DT --random 20 --algorithm sweep --order input%s%s",
                           "", ""), 2);
  assert_non_null(strstr(tsc_err, "--order applies to --algorithm incremental only"));
  assert_int_equal(tsc_run("lot --rule DT --random 20 --algorithm sweeps%s%s", "", ""), 2);
  assert_non_null(strstr(tsc_err, "(valid: incremental, flip, sweep)"));
  assert_int_equal(tsc_run("lot --help%s%s", "", ""), 0);
  assert_non_null(strstr(tsc_out, "sweep (rule DT or ES:SHAPE): the sweepline algorithm"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_samplers),
    cmocka_unit_test(test_same_out),
    cmocka_unit_test(test_polygon_grid),
    cmocka_unit_test(test_refusals),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
