/*
** test_got_cli.c: `fliplab got` end to end.
**
** - the printed total equals the sum of the listed triangles' badness (P_1)
**   and of the --csv file's badness column (read back through libcsv), and
**   the CSV has n - 2 rows of distinct vertex triples;
** - a polygon file and its clockwise reversal give the same total; the
**   printed triangles use the file's vertex numbers in both cases;
** - --compare DT reports 0 differing diagonals for R_1 (Delaunay
**   equivalent) on a polygon in general position;
** - the runner-up line: "tie" for the unit square under P_1 (both diagonals
**   equal), a gap for a kite;
** - --threads 1 and 2 print the same total and triangles;
** - --svg writes an SVG with one vertex dot per vertex;
** - bad input gets one line on stderr and exit status 2: malformed rows,
**   NaN, duplicate, collinear, non-convex, too few points, DT or unknown
**   rules, absurd sizes, conflicting options.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <csv.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

#define TCLI_CAP (1 << 20)
static char tcli_out[TCLI_CAP], tcli_err[TCLI_CAP];

/* Run `fliplab printf(FMT, ...)` into tcli_out and tcli_err. */
#define TCLI_RUN(...) testutil_runf(tcli_out, sizeof tcli_out, tcli_err, sizeof tcli_err, __VA_ARGS__)

static double tcli_total(const char *out) {
  const char *t = strstr(out, "total badness: ");
  assert_non_null(t);
  return strtod(t + 15, NULL);
}

/* Sum of the badness column of the printed triangle list. */
static double tcli_listed_sum(const char *out, int *count) {
  const char *t = strstr(out, "\ntriangles: ");
  assert_non_null(t);
  t = strchr(t + 1, '\n');
  double s = 0;
  *count = 0;
  while (t && t[1]) {
    unsigned a, b, c;
    double v;
    if (sscanf(t + 1, "%u %u %u %lf", &a, &b, &c, &v) != 4) break;
    s += v;
    (*count)++;
    t = strchr(t + 1, '\n');
  }
  return s;
}

static void test_totals_and_list(void **state) {
  (void)state;
  assert_int_equal(TCLI_RUN("got --rule P_1 --random 12 --seed 3"), 0);
  int count = 0;
  double total = tcli_total(tcli_out), sum = tcli_listed_sum(tcli_out, &count);
  assert_int_equal(count, 10);
  assert_true(fabs(total - sum) <= 1e-9 * total);
  assert_non_null(strstr(tcli_out, "runner-up: "));
  assert_non_null(strstr(tcli_out, "time: "));
}

typedef struct tcli_csv { int row, field; double sum; int v[3]; int ok; } tcli_csv;

static void tcli_field(void *s, size_t len, void *data) {
  tcli_csv *c = data;
  char buf[64];
  if (len >= sizeof buf) len = sizeof buf - 1;
  memcpy(buf, s, len);
  buf[len] = '\0';
  if (c->row == 0) {
    static const char *const head[4] = {"i", "j", "k", "badness"};
    if (c->field >= 4 || strcmp(buf, head[c->field]) != 0) c->ok = 0;
  } else if (c->field < 3) {
    c->v[c->field] = atoi(buf);
  } else {
    c->sum += strtod(buf, NULL);
  }
  c->field++;
}

static void tcli_row(int ch, void *data) {
  (void)ch;
  tcli_csv *c = data;
  if (c->row > 0 && !(c->v[0] < c->v[1] && c->v[1] < c->v[2])) c->ok = 0;
  c->row++;
  c->field = 0;
}

static void test_csv_output(void **state) {
  (void)state;
  char path[512];
  testutil_tmppath(path, sizeof path, "got.csv");
  assert_int_equal(TCLI_RUN("got --rule P_1 --random 30 --csv %s", path), 0);
  double total = tcli_total(tcli_out);
  FILE *f = fopen(path, "rb");
  assert_non_null(f);
  struct csv_parser p;
  assert_int_equal(csv_init(&p, CSV_STRICT), 0);
  tcli_csv c = {0};
  c.ok = 1;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, f)) > 0)
    assert_int_equal(csv_parse(&p, buf, n, tcli_field, tcli_row, &c), n);
  csv_fini(&p, tcli_field, tcli_row, &c);
  csv_free(&p);
  fclose(f);
  remove(path);
  assert_true(c.ok);
  assert_int_equal(c.row, 1 + 28);
  assert_true(fabs(c.sum - total) <= 1e-9 * total);
}

static void test_polygon_file_orientation(void **state) {
  (void)state;
  /* a convex heptagon, anticlockwise, and the same rows clockwise */
  static const double pt[7][2] = {{0, 0}, {4, -1}, {7, 0.5}, {8, 3}, {6, 6}, {2, 6.5}, {-1, 3}};
  char ccw[512], cw[512], text[1024];
  testutil_tmppath(ccw, sizeof ccw, "ccw.csv");
  testutil_tmppath(cw, sizeof cw, "cw.csv");
  size_t u = (size_t)snprintf(text, sizeof text, "x,y\n");
  for (int q = 0; q < 7; q++) u += (size_t)snprintf(text + u, sizeof text - u, "%g,%g\n", pt[q][0], pt[q][1]);
  testutil_write_file(ccw, text);
  u = 0;
  for (int q = 6; q >= 0; q--) u += (size_t)snprintf(text + u, sizeof text - u, "%g,%g\n", pt[q][0], pt[q][1]);
  testutil_write_file(cw, text);
  const char *rules[] = {"P_1", "R_inf", "-alpha_inf", "sigma_2", "abc_0"};
  for (size_t r = 0; r < 5; r++) {
    assert_int_equal(TCLI_RUN("got --rule %s --polygon %s", rules[r], ccw), 0);
    double a = tcli_total(tcli_out);
    assert_int_equal(TCLI_RUN("got --rule %s --polygon %s", rules[r], cw), 0);
    assert_non_null(strstr(tcli_out, "clockwise"));
    double b = tcli_total(tcli_out);
    assert_true(fabs(a - b) <= 1e-9 * fabs(a));
  }
  /* P_1 on a polygon: the listed triangles' vertex numbers are file rows */
  assert_int_equal(TCLI_RUN("got --rule P_1 --polygon %s", cw), 0);
  int count = 0;
  double sum = tcli_listed_sum(tcli_out, &count);
  assert_int_equal(count, 5);
  assert_true(fabs(sum - tcli_total(tcli_out)) <= 1e-9 * sum);
  remove(ccw);
  remove(cw);
}

static void test_compare_dt(void **state) {
  (void)state;
  assert_int_equal(TCLI_RUN("got --rule R_1 --random 60 --seed 5 --compare DT"), 0);
  assert_non_null(strstr(tcli_out, "compare DT: 0 of 57 diagonals differ; 58 of 58 triangles"));
  assert_int_equal(TCLI_RUN("got --rule P_1 --random 60 --seed 5 --compare DT"), 0);
  assert_non_null(strstr(tcli_out, "compare DT: "));
  assert_int_equal(TCLI_RUN("got --rule P_1 --random 10 --compare XX"), 2);
  assert_true(testutil_one_line(tcli_err));
}

static void test_runner_up(void **state) {
  (void)state;
  char path[512];
  testutil_tmppath(path, sizeof path, "square.csv");
  testutil_write_file(path, "0,0\n1,0\n1,1\n0,1\n");
  assert_int_equal(TCLI_RUN("got --rule P_1 --polygon %s", path), 0);
  assert_non_null(strstr(tcli_out, "runner-up: tie"));
  assert_non_null(strstr(tcli_out, "certified: tie not excluded (gap 0 <= error bound "));
  testutil_write_file(path, "0,0\n3,0\n3,1\n0,2\n");
  assert_int_equal(TCLI_RUN("got --rule P_1 --polygon %s", path), 0);
  assert_non_null(strstr(tcli_out, "the optimum is unique"));
  assert_non_null(strstr(tcli_out, "certified: unique optimum (gap "));
  /* a non-convex polygon from a file: a notch, one triangle only */
  testutil_write_file(path, "0,0\n1,0\n2,0\n1,1\n");
  assert_int_equal(TCLI_RUN("got --rule P_1 --polygon %s", path), 0);
  assert_non_null(strstr(tcli_out, "certified: unique optimum (the only triangulation)"));
  testutil_write_file(path, "0,0\n4,0\n4,4\n2,1\n0,4\n");
  assert_int_equal(TCLI_RUN("got --rule P_1 --polygon %s --print-triangles", path), 0);
  assert_non_null(strstr(tcli_out, "triangles: 3"));
  assert_int_equal(TCLI_RUN("got --rule P_1 --polygon %s --compare DT", path), 2);
  assert_true(testutil_one_line(tcli_err));
  assert_non_null(strstr(tcli_err, "convex"));
  /* no error model: never unique */
  assert_int_equal(TCLI_RUN("got --rule lambda_1 --random 40 --sampler star"), 0);
  assert_non_null(strstr(tcli_out, "certified: tie not excluded (gap "));
  assert_non_null(strstr(tcli_out, "error bound inf: "));
  remove(path);
}

/* Vertex numbers on the SVG: the input's rows (a clockwise non-convex
** file), one per vertex up to n = 60, none above. */
static void test_svg_labels(void **state) {
  (void)state;
  char path[512], svg[512];
  testutil_tmppath(path, sizeof path, "notch.csv");
  testutil_tmppath(svg, sizeof svg, "notch.svg");
  testutil_write_file(path, "0,0\n0,4\n2,1\n4,4\n4,0\n");   /* clockwise */
  assert_int_equal(TCLI_RUN("got --rule P_1 --polygon %s --svg %s", path, svg), 0);
  char *s = testutil_read_file(svg);
  assert_non_null(s);
  assert_int_equal(testutil_count(s, "<text"), 1 + 5);
  for (int r = 0; r < 5; r++) {
    char want[32];
    snprintf(want, sizeof want, ">%d</text>", r);
    assert_int_equal(testutil_count(s, want), 1);
  }
  free(s);
  assert_int_equal(TCLI_RUN("got --rule P_1 --random 61 --sampler star --svg %s", svg), 0);
  s = testutil_read_file(svg);
  assert_int_equal(testutil_count(s, "<text"), 1);
  free(s);
  remove(path);
  remove(svg);
}

static void test_simple_samplers(void **state) {
  (void)state;
  const char *s[] = {"star", "monotone"};
  for (int q = 0; q < 2; q++) {
    assert_int_equal(TCLI_RUN("got --rule P_1 --random 300 --sampler %s --seed 4", s[q]), 0);
    assert_non_null(strstr(tcli_out, "certified: unique optimum (gap "));
    assert_non_null(strstr(tcli_out, "triangles: 298"));
  }
  assert_int_equal(TCLI_RUN("got --rule P_1 --random 30 --sampler spiral"), 2);
  assert_non_null(strstr(tcli_err, "star, monotone"));
}

static void test_threads_same_output(void **state) {
  (void)state;
  static char a[TCLI_CAP];
  assert_int_equal(TCLI_RUN("got --rule sigma_2 --random 150 --threads 1 --print-triangles"), 0);
  char *t = strstr(tcli_out, "time: ");
  char *e = strchr(t, '\n');
  memmove(t, e + 1, strlen(e + 1) + 1);   /* drop the time line */
  snprintf(a, sizeof a, "%s", tcli_out);
  assert_int_equal(TCLI_RUN("got --rule sigma_2 --random 150 --threads 2 --print-triangles"), 0);
  t = strstr(tcli_out, "time: ");
  e = strchr(t, '\n');
  memmove(t, e + 1, strlen(e + 1) + 1);
  assert_string_equal(a, tcli_out);
}

static void test_svg(void **state) {
  (void)state;
  char path[512];
  testutil_tmppath(path, sizeof path, "got.svg");
  assert_int_equal(TCLI_RUN("got --rule P_1 --random 200 --svg %s --shade", path), 0);
  char *buf = testutil_read_file(path);
  assert_non_null(buf);
  remove(path);
  assert_true(strncmp(buf, "<svg", 4) == 0);
  assert_non_null(strstr(buf, "</svg>"));
  size_t dots = 0, tris = 0;
  for (char *s = buf; (s = strstr(s, "<circle")) != NULL; s++) dots++;
  for (char *s = buf; (s = strstr(s, "<polygon fill=\"#")) != NULL; s++) tris++;
  free(buf);
  assert_int_equal(dots, 200);
  assert_int_equal(tris, 198);
}

static void test_bad_input(void **state) {
  (void)state;
  static const struct { const char *text, *want; } bad[] = {
    {"0,0\n1,0\nabc,1\n0,1\n", "line 3"},
    {"0,0\n1,0\n1,1,5\n0,1\n", "line 3"},
    {"0,0\n1,0\nnan,1\n0,1\n", "line 3"},
    {"0,0\n1,0\n1,1\n1,0\n", "duplicate"},
    {"0,0\n2,0\n1,0\n1,1\n", "edge 0-1 (lines 1-2) and edge 1-2 (lines 2-3)"},
    {"0,0\n1,1\n1,0\n0,1\n", "edge 0-1 (lines 1-2) and edge 2-3 (lines 3-4) cross"},
    {"0,0\n4,0\n4,4\n2,0\n0,4\n", "edge 0-1 (lines 1-2) and edge 3-4 (lines 4-5) cross or touch"},
    {"0,0\n1,0\n", "at least 3"},
    {"x,y\n0,0\n1,0\n1,1\n\"0\n", "line"},
  };
  char path[512];
  testutil_tmppath(path, sizeof path, "bad.csv");
  for (size_t q = 0; q < sizeof bad / sizeof bad[0]; q++) {
    testutil_write_file(path, bad[q].text);
    assert_int_equal(TCLI_RUN("got --rule P_1 --polygon %s", path), 2);
    if (!testutil_one_line(tcli_err) || strstr(tcli_err, bad[q].want) == NULL)
      fail_msg("case %zu: stderr '%s' (want '%s')", q, tcli_err, bad[q].want);
  }
  remove(path);
  static const char *const cmds[] = {
    "got --rule DT --random 10",
    "got --rule nosuch_1 --random 10",
    "got --rule P_1 --random 1000000000",
    "got --rule P_1 --random 200000",
    "got --rule P_1 --random 2",
    "got --rule P_1 --random 10 --polygon x.csv",
    "got --rule P_1",
    "got --random 10",
    "got --rule P_1 --random 10 --sampler nope",
    "got --rule P_1 --polygon /nonexistent/file.csv",
    "got --rule P_1 --random 10 --threads 0",
    "got --rule P_1 --random 10 --tie-eps -1",
  };
  for (size_t q = 0; q < sizeof cmds / sizeof cmds[0]; q++) {
    int st = TCLI_RUN("%s", cmds[q]);
    if (st != 2 || !testutil_one_line(tcli_err)) fail_msg("'%s': status %d, stderr '%s'", cmds[q], st, tcli_err);
  }
  assert_int_equal(TCLI_RUN("got --rule DT --random 10"), 2);
  assert_non_null(strstr(tcli_err, "triangle-based"));
  assert_int_equal(TCLI_RUN("got --rule P_1 --random 200000"), 2);
  assert_non_null(strstr(tcli_err, "GB"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_totals_and_list),
    cmocka_unit_test(test_simple_samplers),
    cmocka_unit_test(test_svg_labels),
    cmocka_unit_test(test_csv_output),
    cmocka_unit_test(test_polygon_file_orientation),
    cmocka_unit_test(test_compare_dt),
    cmocka_unit_test(test_runner_up),
    cmocka_unit_test(test_threads_same_output),
    cmocka_unit_test(test_svg),
    cmocka_unit_test(test_bad_input),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
