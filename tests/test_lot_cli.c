/*
** test_lot_cli.c: `fliplab lot` as a user runs it: the output lines in
** order, --check, --compare, the CSV and SVG outputs, thread invariance,
** the naive-Delaunay plugin on near-degenerate input (never a hang), the
** budget, and bad input (one line, non-zero exit, no output file).
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

#include "testutil.h"

#define TLC_CAP (1 << 20)

static char tlc_out[TLC_CAP], tlc_err[TLC_CAP];

static int tlc_run(const char *args) {
  return testutil_run(args, tlc_out, sizeof tlc_out, tlc_err, sizeof tlc_err);
}

/* The key lines in the documented order. */
static void test_output_lines(void **state) {
  (void)state;
  assert_int_equal(tlc_run("lot --rule P_1 --random 500 --seed 3 --check"), 0);
  static const char *const keys[] = {"# fliplab lot: rule P_1", "\npoints: 500 (hull ",
                                     "\ntriangles: ", "\nflips: ", "\nstatus: converged",
                                     "\ntime: ", "\ncheck: ok"};
  const char *at = tlc_out;
  for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++) {
    const char *f = strstr(at, keys[k]);
    if (f == NULL) fail_msg("missing or out of order: '%s' in\n%s", keys[k], tlc_out);
    at = f + 1;
  }
  /* 2n - h - 2 */
  unsigned h = 0, t = 0;
  assert_int_equal(sscanf(strstr(tlc_out, "points:"), "points: 500 (hull %u", &h), 1);
  assert_int_equal(sscanf(strstr(tlc_out, "triangles:"), "triangles: %u", &t), 1);
  assert_int_equal(t, 2 * 500 - h - 2);
}

static void test_help_lists_options(void **state) {
  (void)state;
  assert_int_equal(tlc_run("lot --help"), 0);
  static const char *const opts[] = {"--rule", "--points", "--random", "--sampler", "--seed",
                                     "--algorithm", "--order", "--max-flips", "--check",
                                     "--compare", "--out", "--svg", "--shade", "--tie-eps",
                                     "--threads"};
  for (size_t i = 0; i < sizeof opts / sizeof opts[0]; i++) {
    char line[64];
    snprintf(line, sizeof line, "\n  %s ", opts[i]);
    if (strstr(tlc_out, line) == NULL) fail_msg("--help does not describe %s", opts[i]);
  }
  assert_non_null(strstr(tlc_out, "(default: 1000 n + 10^7)"));
}

/* --out: i,j,k,badness, anticlockwise triangles of input rows; DT leaves
** badness empty; the file reads back through --points. */
static void test_csv_and_svg(void **state) {
  (void)state;
  char csv[512], svg[512], pts[512];
  testutil_tmppath(csv, sizeof csv, "lot_out.csv");
  testutil_tmppath(svg, sizeof svg, "lot_out.svg");
  testutil_tmppath(pts, sizeof pts, "lot_pts.csv");
  testutil_write_file(pts, "x,y\n0,0\n1,0\n1,1\n0,1\n0.5,0.25\n");
  char cmd[2048];
  snprintf(cmd, sizeof cmd, "lot --rule P_1 --points %s --out %s --svg %s --shade --compare DT",
           pts, csv, svg);
  assert_int_equal(tlc_run(cmd), 0);
  char *c = testutil_read_file(csv);
  assert_non_null(c);
  assert_true(strncmp(c, "i,j,k,badness\n", 14) == 0);
  assert_int_equal(testutil_count(c, "\n"), 1 + 4);   /* 2*5 - 4 - 2 triangles */
  unsigned i, j, k;
  double b;
  assert_int_equal(sscanf(c + 14, "%u,%u,%u,%lf", &i, &j, &k, &b), 4);
  assert_true(b > 0);
  free(c);
  char *s = testutil_read_file(svg);
  assert_non_null(s);
  assert_non_null(strstr(s, "<svg"));
  assert_non_null(strstr(s, "Delaunay triangulation"));
  assert_non_null(strstr(s, "</svg>"));
  free(s);
  snprintf(cmd, sizeof cmd, "lot --rule DT --points %s --out %s", pts, csv);
  assert_int_equal(tlc_run(cmd), 0);
  c = testutil_read_file(csv);
  assert_non_null(strstr(c, ",\n"));   /* empty badness */
  free(c);
  assert_non_null(strstr(tlc_out, "points: 5 (hull 4, duplicates 0)"));
}

/* The same output (but the time line) for 1 and 2 threads. */
static void tlc_strip_time(char *s) {
  char *t = strstr(s, "\ntime: ");
  if (t == NULL) return;
  char *e = strchr(t + 1, '\n');
  memmove(t, e, strlen(e) + 1);
}

static void test_threads(void **state) {
  (void)state;
  static char a[TLC_CAP];
  static const char *const runs[] = {
    "lot --rule R_1 --random 60 --sampler circle --compare GOT --threads %d",
    "lot --rule -alpha_inf --random 3000 --sampler normal --check --threads %d",
    "lot --rule DT --random 3000 --algorithm flip --check --compare DT --threads %d"};
  for (size_t r = 0; r < sizeof runs / sizeof runs[0]; r++) {
    assert_int_equal(testutil_runf(a, sizeof a, NULL, 0, runs[r], 1), 0);
    assert_int_equal(testutil_runf(tlc_out, sizeof tlc_out, NULL, 0, runs[r], 2), 0);
    tlc_strip_time(a);
    tlc_strip_time(tlc_out);
    assert_string_equal(a, tlc_out);
  }
  assert_non_null(strstr(a, "compare DT: "));
}

/* --compare GOT in convex position: a DT-equivalent rule's LOT is a GOT. */
static void test_compare_got(void **state) {
  (void)state;
  assert_int_equal(tlc_run("lot --rule -r_1 --random 40 --sampler circle --compare GOT"), 0);
  assert_non_null(strstr(tlc_out, "compare GOT: LOT total "));
  assert_non_null(strstr(tlc_out, ": equal ("));
  /* Equal by the certified bounds of got (-alpha: a forward error model),
  ** by the rule's tolerance where there is none (R), and a worse LOT (P_1)
  ** is told apart by both. */
  assert_int_equal(tlc_run("lot --rule -alpha_inf --random 60 --sampler circle --compare GOT"), 0);
  assert_non_null(strstr(tlc_out, ": equal (relative difference "));
  assert_non_null(strstr(tlc_out, "GOT computed to within rounding)"));
  assert_int_equal(tlc_run("lot --rule -r_1 --random 400 --sampler circle --compare GOT"), 0);
  assert_non_null(strstr(tlc_out, ": equal ("));
  assert_non_null(strstr(tlc_out, "within the tie tolerance 1e-12; no certified bound: "));
  assert_int_equal(tlc_run("lot --rule P_1 --random 40 --sampler circle --compare GOT"), 0);
  assert_non_null(strstr(tlc_out, ": NOT equal (relative difference 0.0166, GOT computed"));
  /* The gap is the relative difference of the totals, not of their keys:
  ** for l_2 the keys are sums of squares, about twice as far apart. */
  assert_int_equal(tlc_run("lot --rule P_2 --random 40 --sampler circle --compare GOT"), 0);
  assert_non_null(strstr(tlc_out, ": NOT equal (relative difference 0.013, "));
  assert_int_not_equal(tlc_run("lot --rule P_1 --random 40 --compare GOT"), 0);
  assert_true(testutil_one_line(tlc_err));
  assert_non_null(strstr(tlc_err, "convex position"));
}

/* Theorem 6 through the program: 100 parabola points in input order. */
static void test_parabola_flips(void **state) {
  (void)state;
  assert_int_equal(tlc_run("lot --rule DT --random 100 --sampler parabola --order input"), 0);
  assert_non_null(strstr(tlc_out, "\nflips: 4753\n"));   /* 98 * 97 / 2 */
}

/* The budget: a status line, a triangulation, exit 0; --check says no. */
static void test_budget(void **state) {
  (void)state;
  assert_int_equal(tlc_run("lot --rule DT --random 100 --sampler parabola --order input "
                           "--max-flips 100 --check"), 1);
  assert_non_null(strstr(tlc_out, "\nflips: 100\n"));
  assert_non_null(strstr(tlc_out, "status: budget exhausted after 100 flips"));
  assert_non_null(strstr(tlc_out, "check: FAILED"));
}

/* The naive-Delaunay plugin (thesis 7.5) on near-degenerate input far from
** the origin: a rotated grid and points on a circle.  Every run ends, with
** a status; a converged one is locally optimal for the plugin's own rule
** (--check).  The rotated grid once exposed a bug: the halves of an edge
** split by a new point went unexamined. */
static void test_naive_plugin(void **state) {
  (void)state;
  char grid[512], circ[512];
  testutil_tmppath(grid, sizeof grid, "lot_grid.csv");
  testutil_tmppath(circ, sizeof circ, "lot_circle.csv");
  FILE *f = fopen(grid, "w"), *g = fopen(circ, "w");
  assert_non_null(f);
  assert_non_null(g);
  fprintf(f, "x,y\n");
  for (int i = 0; i < 20; i++)
    for (int j = 0; j < 20; j++)
      fprintf(f, "%.17g,%.17g\n", 1000 + cos(0.3) * i - sin(0.3) * j,
              1000 + sin(0.3) * i + cos(0.3) * j);
  testutil_rng r = {42};
  for (int i = 0; i < 300; i++) {
    double t = 6.283185307179586 * testutil_uniform(&r);
    fprintf(g, "%.17g,%.17g\n", 1e5 + cos(t), 1e5 + sin(t));
  }
  fclose(f);
  fclose(g);
  const char *files[] = {grid, circ};
  const char *how[] = {"--order spatial", "--order random", "--order input", "--algorithm flip"};
  for (int fi = 0; fi < 2; fi++)
    for (int h = 0; h < 4; h++) {
      int rc = testutil_runf(tlc_out, sizeof tlc_out, tlc_err, sizeof tlc_err,
                             "--plugin %s/plugins/naivedt.so lot --rule naiveDT --points %s %s "
                             "--check", FLIPLAB_BUILD_DIR, files[fi], how[h]);
      const char *st = strstr(tlc_out, "\nstatus: ");
      assert_non_null(st);
      if (strncmp(st, "\nstatus: converged", 18) == 0) {
        if (rc != 0 || strstr(tlc_out, "check: ok") == NULL)
          fail_msg("%s %s: converged but not locally optimal:\n%s", files[fi], how[h], tlc_out);
      } else {
        assert_true(strncmp(st, "\nstatus: cycle", 14) == 0 ||
                    strncmp(st, "\nstatus: budget exhausted", 25) == 0);
      }
    }
}

/* Bad input: one line on stderr naming the problem, exit 2, and no output
** file left behind. */
static void test_bad_input(void **state) {
  (void)state;
  char out[512], in[512], cmd[2048];
  testutil_tmppath(out, sizeof out, "lot_never.csv");
  testutil_tmppath(in, sizeof in, "lot_bad.csv");
  static const struct {
    const char *file, *args, *want;
  } cases[] = {
    {"", "", "no points"},
    {"x,y\n1,2\n", "", "1 point"},
    {"0,0\n1,1\n2,2\n3,3\n", "", "collinear"},
    {"0,0\n1,0\nnan,1\n", "", "line 3"},
    {"0,0\n1,0\n0,1e300\n", "", "line 3: y '1e300' is out of range"},
    {"0,0\n1,0\n1e-40,1\n", "", "line 3"},
    {"0,0\n1,0\n0,1,2\n", "", "line 3"},
    /* Lines end with LF, CRLF or a lone CR, and every error names the right one. */
    {"x,y\r\n\r\n0,0\r\n1,0,5\r\n", "", "line 4: expected 2 fields"},
    {"x,y\r0,0\r1,0,5\r", "", "line 3: expected 2 fields"},
    {NULL, "--random 10 --sampler spiral", "unknown sampler 'spiral'"},
    {NULL, "--random 1e12", "memory"},
    {NULL, "--random 10 --order sideways", "unknown order"},
    {NULL, "--random 10 --compare GOT --rule DT", "triangle-based"},
  };
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
    unlink(out);
    if (cases[c].file) {
      testutil_write_file(in, cases[c].file);
      snprintf(cmd, sizeof cmd, "lot --rule DT --points %s --out %s", in, out);
    } else {
      snprintf(cmd, sizeof cmd, "lot %s%s --out %s", strstr(cases[c].args, "--rule") ? "" :
               "--rule DT ", cases[c].args, out);
    }
    int rc = tlc_run(cmd);
    if (rc != 2 || !testutil_one_line(tlc_err) || strstr(tlc_err, cases[c].want) == NULL)
      fail_msg("case %zu: exit %d, stderr '%s' (want '%s')", c, rc, tlc_err, cases[c].want);
    assert_int_equal(access(out, F_OK), -1);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_output_lines),
    cmocka_unit_test(test_help_lists_options),
    cmocka_unit_test(test_csv_and_svg),
    cmocka_unit_test(test_threads),
    cmocka_unit_test(test_compare_got),
    cmocka_unit_test(test_parabola_flips),
    cmocka_unit_test(test_budget),
    cmocka_unit_test(test_naive_plugin),
    cmocka_unit_test(test_bad_input),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
