/*
** test_poly.c: Triangle's .poly files (reports/poly.c).  What is read is
** what the file says (a hand-written file in Triangle's style: 1-based
** numbers, attributes, markers, comments, regions); random graphs written
** and read back bit for bit; every truncation at a line boundary refused
** unless it ends a complete file; every count off by one refused; and each
** kind of bad input refused with one line naming the file's line.
*/
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "report.h"
#include "testutil.h"

/* A square with a square hole, Triangle-style: numbered from 1, one
** attribute and a marker per vertex, segment markers, comments, a region. */
static const char tpoly_square[] =
  "# a square with a square hole\n"
  "8 2 1 1\n"
  "1 0 0 0.5 1\n"
  "2 4 0 0.5 1   # corner\n"
  "3 4 4 0.5 1\n"
  "4 0 4 0.5 1\n"
  "\n"
  "5 1 1 0 -2\n"
  "6 3 1 0 2\n"
  "7 3 3 0 2\n"
  "8 1 3 0 2\n"
  "8 1\n"
  "1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n"
  "5 5 6 2\n6 6 7 2\n7 7 8 2\n8 8 5 2\n"
  "1\n"
  "1 2 2\n"
  "1\n"
  "1 0.5 0.5 7 0.1\n";

static void tpoly_file(const char *name, const char *text, char *path, size_t len) {
  testutil_tmppath(path, len, name);
  testutil_write_file(path, text);
}

static void test_poly_triangle_style(void **state) {
  (void)state;
  char path[512], err[512];
  tpoly_file("poly_square.poly", tpoly_square, path, sizeof path);
  report_poly p;
  assert_int_equal(report_poly_read(path, &p, err, sizeof err), 0);
  assert_int_equal(p.g.npts, 8);
  assert_int_equal(p.g.nseg, 8);
  assert_int_equal(p.g.nholes, 1);
  assert_int_equal(p.first, 1);
  assert_int_equal(p.attributes, 1);
  assert_int_equal(p.regions, 1);
  assert_int_equal(p.markers, 1);
  static const double xy[8][2] = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}, {3, 3}, {1, 3}};
  for (int i = 0; i < 8; i++) {
    assert_true(p.g.pts[i].x == xy[i][0] && p.g.pts[i].y == xy[i][1]);
    /* segment i joins vertex i to the next of its ring, 0-based */
    uint32_t ring = i < 4 ? 0 : 4;
    assert_int_equal(p.g.seg[2 * i], i);
    assert_int_equal(p.g.seg[2 * i + 1], ring + (uint32_t)(i + 1) % 4);
  }
  assert_int_equal(p.seg_line[0], 13);
  assert_true(p.g.hole[0].x == 2 && p.g.hole[0].y == 2);
  report_poly_free(&p);
}

/* Coordinates across the contract's range, signs and exact zeros. */
static double tpoly_coord(testutil_rng *g) {
  uint64_t k = testutil_next(g) % 8;
  if (k == 0) return 0;
  double m = testutil_uniform(g) + 0.5;
  int e = (int)(testutil_next(g) % 190) - 95;   /* magnitudes about 1e-29 .. 1e29 */
  double x = ldexp(m, e) * (k & 1 ? -1 : 1);
  return k < 4 ? x : testutil_uniform(g) - 0.5;
}

static void test_poly_round_trip(void **state) {
  (void)state;
  testutil_rng g = {2026};
  char path[512], err[512];
  testutil_tmppath(path, sizeof path, "poly_round.poly");
  for (int rep = 0; rep < 50; rep++) {
    geom_pslg w = {0};
    w.npts = 3 + testutil_next(&g) % 40;
    w.nseg = testutil_next(&g) % 30;
    w.nholes = testutil_next(&g) % 4;
    w.pts = malloc(w.npts * sizeof *w.pts);
    w.seg = malloc((2 * w.nseg + 1) * sizeof *w.seg);
    w.hole = malloc((w.nholes + 1) * sizeof *w.hole);
    for (size_t i = 0; i < w.npts; i++) w.pts[i] = (geom_point){tpoly_coord(&g), tpoly_coord(&g)};
    for (size_t i = 0; i < w.nseg; i++) {
      w.seg[2 * i] = (uint32_t)(testutil_next(&g) % w.npts);
      w.seg[2 * i + 1] = (uint32_t)((w.seg[2 * i] + 1 + testutil_next(&g) % (w.npts - 1)) % w.npts);
    }
    for (size_t i = 0; i < w.nholes; i++) w.hole[i] = (geom_point){tpoly_coord(&g), tpoly_coord(&g)};
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(report_poly_write(f, &w), 0);
    assert_int_equal(fclose(f), 0);
    report_poly r;
    assert_int_equal(report_poly_read(path, &r, err, sizeof err), 0);
    assert_int_equal(r.g.npts, w.npts);
    assert_int_equal(r.g.nseg, w.nseg);
    assert_int_equal(r.g.nholes, w.nholes);
    assert_int_equal(r.first, 0);
    assert_int_equal(r.markers, 0);   /* written without */
    assert_memory_equal(r.g.pts, w.pts, w.npts * sizeof *w.pts);   /* bit for bit */
    if (w.nseg) assert_memory_equal(r.g.seg, w.seg, 2 * w.nseg * sizeof *w.seg);
    if (w.nholes) assert_memory_equal(r.g.hole, w.hole, w.nholes * sizeof *w.hole);
    report_poly_free(&r);
    free(w.pts);
    free(w.seg);
    free(w.hole);
  }
}

/* The lines of tpoly_square that hold data (comments and blanks excluded),
** as (start, end) offsets. */
static int tpoly_data_lines(const char *s, size_t *start, size_t *end, int max) {
  int n = 0;
  for (size_t i = 0; s[i] && n < max;) {
    size_t j = i;
    while (s[j] && s[j] != '\n') j++;
    if (j > i && s[i] != '#') {
      start[n] = i;
      end[n++] = j + 1;
    }
    i = s[j] ? j + 1 : j;
  }
  return n;
}

/* Cut after k data lines: accepted exactly when k ends the holes section
** (the regions are optional) or the whole file; the refusal names a line. */
static void test_poly_truncated(void **state) {
  (void)state;
  size_t st[64], en[64];
  int n = tpoly_data_lines(tpoly_square, st, en, 64);
  assert_int_equal(n, 22);   /* holes end at 20 */
  char path[512], err[512], buf[2048];
  for (int k = 0; k <= n; k++) {
    size_t len = k ? en[k - 1] : 0;
    memcpy(buf, tpoly_square, len);
    buf[len] = '\0';
    tpoly_file("poly_cut.poly", buf, path, sizeof path);
    report_poly p;
    int rc = report_poly_read(path, &p, err, sizeof err);
    if (k == 20 || k == n) {
      assert_int_equal(rc, 0);
      assert_int_equal(p.regions, k == n);
      report_poly_free(&p);
      continue;
    }
    assert_int_equal(rc, -1);
    assert_null(strchr(err, '\n'));
    assert_non_null(strstr(err, "line "));
    assert_non_null(strstr(err, "the file ends before"));
  }
}

/* Each count of the file one more or one less: always refused. */
static void test_poly_wrong_counts(void **state) {
  (void)state;
  static const char *const count_line[] = {"8 2 1 1\n", "8 1\n", "\n1\n1 2 2\n1\n", "1\n1 0.5"};
  static const char *const more[] = {"9 2 1 1\n", "9 1\n", "\n2\n1 2 2\n1\n", "2\n1 0.5"};
  static const char *const less[] = {"7 2 1 1\n", "7 1\n", "\n0\n1 2 2\n1\n", "0\n1 0.5"};
  char path[512], err[512], buf[2048];
  for (int c = 0; c < 4; c++) {
    for (int d = 0; d < 2; d++) {
      const char *at = strstr(tpoly_square, count_line[c]);
      assert_non_null(at);
      size_t pre = (size_t)(at - tpoly_square);
      snprintf(buf, sizeof buf, "%.*s%s%s", (int)pre, tpoly_square, d ? more[c] : less[c],
               at + strlen(count_line[c]));
      tpoly_file("poly_count.poly", buf, path, sizeof path);
      report_poly p;
      assert_int_equal(report_poly_read(path, &p, err, sizeof err), -1);
      assert_non_null(strstr(err, "line "));
      assert_null(strchr(err, '\n'));
    }
  }
}

typedef struct tpoly_bad {
  const char *text;
  const char *want;   /* a part of the message, with its line */
} tpoly_bad;

static const tpoly_bad tpoly_bads[] = {
  {"", "line 1: the file ends before the first line"},
  {"# only a comment\n", "the file ends before the first line"},
  {"3 3 0 0\n", "line 1: dimension 3: only 2 is supported"},
  {"0 2 0 0\n0 0\n0\n", "line 1: 0 vertices, which in Triangle means a separate .node file"},
  {"2 2 0 0\n", "line 1: fewer than 3 vertices"},
  {"x 2 0 0\n", "line 1: vertex count 'x' is not a non-negative integer"},
  {"3 2 0 2\n", "line 1: boundary marker count 2 is too large"},
  {"3 2 0 0 9\n", "line 1: first line '#vertices 2 #attributes #boundary-markers': expected 1 to 4"},
  {"3\n2 0 0\n", "line 2: the first vertex is numbered 2"},
  {"3\n0 0 0\n2 1 0\n", "line 3: vertex number 2, expected 1"},
  {"3\n0 0 0\n1 1\n", "line 3: vertex line 'i x y [attributes] [marker]': expected 3 fields, got 2"},
  {"3\n0 0 0\n1 1 zero\n", "line 3: y 'zero' is not a number"},
  {"3\n0 0 0\n1 1 1e31\n", "line 3: y '1e31' is out of range"},
  {"3\n0 0 0\n1 1 1e-31\n", "line 3: y '1e-31' is out of range"},
  {"3\n0 0 nan\n", "line 2: y 'nan' is not finite"},
  {"3 2 1\n0 0 0 abc\n", "line 2: attribute 'abc' is not a number"},
  {"3 2 0 1\n0 0 0 1.5\n", "line 2: boundary marker '1.5' is not an integer"},
  {"3\n0 0 0\n1 1 0\n2 0 1\n", "line 4: the file ends before the segment count line"},
  {"3\n0 0 0\n1 1 0\n2 0 1\n1\n0 0 3\n", "line 6: segment endpoint 3 is not a vertex (the "
                                          "vertices are 0 to 2)"},
  {"3\n1 0 0\n2 1 0\n3 0 1\n1\n1 0 1\n", "line 6: segment endpoint 0 is not a vertex"},
  {"3\n0 0 0\n1 1 0\n2 0 1\n1\n0 1 1\n", "line 6: the segment joins a vertex to itself"},
  {"3\n0 0 0\n1 1 0\n2 0 1\n1\n0 1 -2\n", "line 6: segment endpoint '-2' is not a non-negative"},
  {"3\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 0 1 5\n", "line 6: segment line 'i a b [marker]': expected 3"},
  {"3\n0 0 0\n1 1 0\n2 0 1\n0\n", "line 5: the file ends before the hole count line"},
  {"3\n0 0 0\n1 1 0\n2 0 1\n0\n1\n0 inf 0\n", "line 7: hole x 'inf' is not finite"},
  {"3\n0 0 0\n1 1 0\n2 0 1\n0\n0 1\n", "line 6: hole count line '#holes': expected 1 field"},
  {"3\n0 0 0\n1 1 0\n2 0 1\n0\n0\n1\n0 0 0\n", "line 8: region line 'i x y attribute "
                                              "[maximum-area]': expected 4 to 5 fields, got 3"},
  {"3\n0 0 0\n1 1 0\n2 0 1\n0\n0\n1\n0 0 0 a\n", "line 8: regional attribute 'a' is not"},
  {"3\n0 0 0\n1 1 0\n2 0 1\n0\n0\n0\n7\n", "line 8: more lines than the counts announce"},
  {"3\n0 0 0\n1 1 0\n2 0 1\n0\n0\n0 0\n", "line 7: region count line '#regions': expected 1"},
};

static void test_poly_bad_input(void **state) {
  (void)state;
  char path[512], err[512];
  for (size_t i = 0; i < sizeof tpoly_bads / sizeof tpoly_bads[0]; i++) {
    tpoly_file("poly_bad.poly", tpoly_bads[i].text, path, sizeof path);
    report_poly p;
    int rc = report_poly_read(path, &p, err, sizeof err);
    if (rc != -1 || strstr(err, tpoly_bads[i].want) == NULL || strchr(err, '\n') != NULL ||
        strncmp(err, path, strlen(path)) != 0)
      fail_msg("case %zu: rc %d, message '%s', wanted '%s'", i, rc, err, tpoly_bads[i].want);
  }
  report_poly p;
  assert_int_equal(report_poly_read("/nonexistent/x.poly", &p, err, sizeof err), -1);
  assert_non_null(strstr(err, "cannot read '/nonexistent/x.poly'"));
}

/* A NUL byte inside a number makes it no number (the parser reads spans). */
static void test_poly_nul_byte(void **state) {
  (void)state;
  char path[512], err[512];
  testutil_tmppath(path, sizeof path, "poly_nul.poly");
  static const char text[] = "3\n0 0 0\n1 1\0" "5 0\n2 0 1\n0\n0\n";
  FILE *f = fopen(path, "wb");
  assert_non_null(f);
  assert_int_equal(fwrite(text, 1, sizeof text - 1, f), sizeof text - 1);
  assert_int_equal(fclose(f), 0);
  report_poly p;
  assert_int_equal(report_poly_read(path, &p, err, sizeof err), -1);
  assert_non_null(strstr(err, "line 3: x "));
  assert_non_null(strstr(err, "is not a number"));
}

/* CRLF line ends, tabs, comments right after a number, Triangle's defaults
** for a short first line and segment count line. */
static void test_poly_lenient_layout(void **state) {
  (void)state;
  char path[512], err[512];
  tpoly_file("poly_crlf.poly",
             "3\r\n0\t0 0#c\r\n1 1 0\r\n2 0 1\r\n  3\r\n0 0 1\r\n1 1 2\r\n2 2 0\r\n0\r\n",
             path, sizeof path);
  report_poly p;
  assert_int_equal(report_poly_read(path, &p, err, sizeof err), 0);
  assert_int_equal(p.g.npts, 3);
  assert_int_equal(p.g.nseg, 3);
  assert_int_equal(p.g.seg[5], 0);
  assert_int_equal(p.g.nholes, 0);
  report_poly_free(&p);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_poly_triangle_style), cmocka_unit_test(test_poly_round_trip),
    cmocka_unit_test(test_poly_truncated),      cmocka_unit_test(test_poly_wrong_counts),
    cmocka_unit_test(test_poly_bad_input),      cmocka_unit_test(test_poly_nul_byte),
    cmocka_unit_test(test_poly_lenient_layout),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
