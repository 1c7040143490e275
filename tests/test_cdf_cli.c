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

/* --cdf on a constrained run (--segments, --holes, --poly): refused in one
** line naming the option, no file.  (It was accepted, and listed the
** triangles a segment forced in as if an empty homothet circumscribed them.) */
static void test_cdf_cli_constrained(void **state) {
  (void)state;
  char path[512], pts[512], seg[512], hol[512], poly[512];
  testutil_tmppath(path, sizeof path, "cdf_constrained.csv");
  testutil_tmppath(pts, sizeof pts, "cdf_constrained_pts.csv");
  testutil_tmppath(seg, sizeof seg, "cdf_constrained_seg.csv");
  testutil_tmppath(hol, sizeof hol, "cdf_constrained_hol.csv");
  testutil_tmppath(poly, sizeof poly, "cdf_constrained.poly");
  testutil_write_file(pts, "0,0\n4,0\n4,4\n0,4\n1,2\n3,2\n");
  testutil_write_file(seg, "4,5\n");
  testutil_write_file(hol, "2,3.9\n");
  testutil_write_file(poly, "4 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n4 0\n1 1 2\n2 2 3\n3 3 4\n"
                            "4 4 1\n0\n");
  const char *how[3][2] = {{"--segments", seg}, {"--holes", hol}, {"--poly", poly}};
  for (int i = 0; i < 3; i++) {
    unlink(path);
    int rc = i < 2 ? testutil_runf(tcc_out, sizeof tcc_out, tcc_err, sizeof tcc_err,
                                   "lot --rule ES:square --points %s %s %s --cdf %s", pts,
                                   how[i][0], how[i][1], path)
                   : testutil_runf(tcc_out, sizeof tcc_out, tcc_err, sizeof tcc_err,
                                   "lot --rule ES:square --poly %s --cdf %s", poly, path);
    assert_int_equal(rc, 2);
    assert_true(testutil_one_line(tcc_err));
    assert_non_null(strstr(tcc_err, "--cdf takes an unconstrained run"));
    assert_non_null(strstr(tcc_err, how[i][0]));
    assert_int_equal(access(path, F_OK), -1);
  }
  unlink(pts);
  unlink(seg);
  unlink(hol);
  unlink(poly);
}

/* stdout without its time: lines. */
static void tcc_drop_time(char *s) {
  char *w = s;
  for (char *r = s; *r;) {
    char *nl = strchr(r, '\n');
    size_t len = nl ? (size_t)(nl - r) + 1 : strlen(r);
    if (strncmp(r, "time:", 5) != 0) memmove(w, r, len), w += len;
    r += len;
  }
  *w = '\0';
}

/* The graph of rule on the points pts (lot options): the count line, the CSV against the
** triangles of --out, the SVG; stdout is that of the run without --cdf plus
** the one cdf: line.  The counts into kde. */
static void tcc_run(const char *rule, const char *pts, size_t kde[3]) {
  char cdf[512], out[512], svg[512], plain[1 << 16];
  testutil_tmppath(cdf, sizeof cdf, "cdf_graph.csv");
  testutil_tmppath(out, sizeof out, "cdf_tri.csv");
  testutil_tmppath(svg, sizeof svg, "cdf.svg");
  assert_int_equal(testutil_runf(plain, sizeof plain, NULL, 0,
                                 "lot --rule %s %s --out %s", rule, pts, out), 0);
  assert_int_equal(testutil_runf(tcc_out, sizeof tcc_out, tcc_err, sizeof tcc_err,
                                 "lot --rule %s %s --cdf %s --svg %s", rule, pts, cdf, svg),
                   0);
  const char *line = strstr(tcc_out, "\ncdf: ");
  assert_non_null(line);
  assert_int_equal(sscanf(line, "\ncdf: %zu triangles, %zu extra edges (%zu triangles dropped)",
                          &kde[0], &kde[1], &kde[2]), 3);
  size_t nt = 0;
  assert_int_equal(sscanf(strstr(tcc_out, "triangles: "), "triangles: %zu", &nt), 1);
  assert_int_equal(kde[0] + kde[2], nt);
  /* Without the cdf: line, the same stdout as without --cdf. */
  char *end = strchr(line + 1, '\n');
  memmove((char *)line + 1, end + 1, strlen(end + 1) + 1);
  tcc_drop_time(tcc_out), tcc_drop_time(plain);
  assert_string_equal(tcc_out, plain);
  char *g = testutil_read_file(cdf), *t = testutil_read_file(out), *v = testutil_read_file(svg);
  assert_non_null(g), assert_non_null(t), assert_non_null(v);
  assert_int_equal(strncmp(g, "i,j,k\n", 6), 0);
  assert_int_equal(testutil_count(g, "\n"), 1 + kde[0] + kde[1]);
  assert_int_equal(testutil_count(g, ",\n"), kde[1]);   /* edges: k empty */
  size_t rows = 0;
  for (char *r = strchr(g, '\n') + 1; *r; r = strchr(r, '\n') + 1, rows++) {
    char row[64];
    size_t len = (size_t)(strchr(r, '\n') - r);
    assert_true(len < sizeof row - 2);
    if (r[len - 1] == ',') continue;
    snprintf(row, sizeof row, "\n%.*s,", (int)len, r);   /* a row of --out, badness empty */
    assert_non_null(strstr(t, row));
  }
  assert_int_equal(rows, kde[0] + kde[1]);
  assert_non_null(strstr(v, "stroke=\"#c0392b\""));
  assert_non_null(strstr(v, "CDF graph (bold)"));
  free(g), free(t), free(v);
}

static void test_cdf_cli_square(void **state) {
  (void)state;
  size_t kde[3];
  tcc_run("ES:square", "--random 300", kde);
  assert_true(kde[0] > 0 && kde[2] > 0);   /* some triangles round a corner */
  tcc_run("ES:triangle", "--random 10 --seed 1", kde);
  assert_true(kde[1] > 0);                 /* an edge in no kept triangle (figure 4.6) */
}

static void test_cdf_cli_ellipse(void **state) {
  (void)state;
  size_t kde[3];
  tcc_run("ES:ellipse:2,1", "--random 300", kde);
  assert_int_equal(kde[1], 0);
  assert_int_equal(kde[2], 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_cdf_cli_refused),
      cmocka_unit_test(test_cdf_cli_constrained),
      cmocka_unit_test(test_cdf_cli_square),
      cmocka_unit_test(test_cdf_cli_ellipse),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
