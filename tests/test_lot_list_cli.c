/*
** test_lot_list_cli.c: `fliplab lot --rule A,B,...`: one LOT per rule of the
** same points.  Each rule's block of lines is what the rule alone prints;
** --svg draws one panel per rule (its caption, its triangles inside its
** cell of the grid); what writes one triangulation (--out, --cdf, --shade)
** refuses a list in one line; a bad name in the list is named.
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

static char tll_out[1 << 17], tll_one[1 << 16], tll_err[4096];

/* s without its time: lines (they differ from run to run). */
static void tll_drop_time(char *s) {
  char *w = s;
  for (char *r = s; *r;) {
    char *nl = strchr(r, '\n');
    size_t len = nl ? (size_t)(nl - r) + 1 : strlen(r);
    if (strncmp(r, "time:", 5) != 0) memmove(w, r, len), w += len;
    r += len;
  }
  *w = '\0';
}

static const char *const tll_rules[] = {"DT", "ES:square", "P_1", "ES:ellipse:2 1",
                                        "ES:triangle"};
#define TLL_N 5
#define TLL_LIST "DT,ES:square,P_1,ES:ellipse:2 1,ES:triangle"

/* The list's stdout is the rules' own outputs one after the other (with
** --check and --compare DT), and the exit status 0. */
static void test_lot_list_blocks(void **state) {
  (void)state;
  const char *opts = "--random 150 --seed 9 --check --compare DT";
  assert_int_equal(testutil_runf(tll_out, sizeof tll_out, tll_err, sizeof tll_err,
                                 "lot --rule '" TLL_LIST "' %s", opts), 0);
  assert_string_equal(tll_err, "");
  tll_drop_time(tll_out);
  char want[1 << 17] = "";
  for (int k = 0; k < TLL_N; k++) {
    assert_int_equal(testutil_runf(tll_one, sizeof tll_one, NULL, 0, "lot --rule '%s' %s",
                                   tll_rules[k], opts), 0);
    tll_drop_time(tll_one);
    strcat(want, tll_one);
  }
  assert_string_equal(tll_out, want);
  assert_int_equal(testutil_count(tll_out, "\ncheck: ok"), TLL_N);
}

/* Panel k of the SVG: its caption names rule k and the triangle count of
** the rule alone; its triangle path has one closed move per triangle, and
** every coordinate lies in the panel's cell (3 x 2 grid for 5 panels,
** cells as wide and tall as the SVG says). */
static void tll_panel(const char *svg, const char *cap, size_t ntri, int k, double cw,
                      double ch, double top) {
  const char *c = strstr(svg, cap);
  assert_non_null(c);
  const char *d = strstr(c, "stroke=\"#1f4e79\"");
  assert_non_null(d);
  d = strstr(d, "d=\"") + 3;
  const char *e = strchr(d, '"');
  size_t moves = 0;
  double x0 = (k % 3) * cw, y0 = top + (k / 3) * ch;
  for (const char *q = d; q < e; q++) {
    if (*q != 'M' && *q != 'L') continue;
    double x, y;
    assert_int_equal(sscanf(q + 1, "%lf %lf", &x, &y), 2);
    moves += *q == 'M';
    assert_true(x >= x0 && x <= x0 + cw);
    assert_true(y >= y0 && y <= y0 + ch);
  }
  assert_int_equal(moves, ntri);
}

static void test_lot_list_svg(void **state) {
  (void)state;
  char svg[512];
  testutil_tmppath(svg, sizeof svg, "lot_list.svg");
  assert_int_equal(testutil_runf(tll_out, sizeof tll_out, tll_err, sizeof tll_err,
                                 "lot --rule '" TLL_LIST "' --random 120 --seed 4 --svg %s",
                                 svg), 0);
  char *v = testutil_read_file(svg);
  assert_non_null(v);
  assert_int_equal(testutil_count(v, "stroke=\"#1f4e79\""), TLL_N);   /* no DT panel added */
  assert_non_null(strstr(v, "120 uniform points (seed 4): one LOT per rule"));
  double w, h;
  assert_int_equal(sscanf(v, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%lf\" "
                             "height=\"%lf\"", &w, &h), 2);
  for (int k = 0; k < TLL_N; k++) {
    size_t nt = 0;
    assert_int_equal(testutil_runf(tll_one, sizeof tll_one, NULL, 0,
                                   "lot --rule '%s' --random 120 --seed 4", tll_rules[k]), 0);
    assert_int_equal(sscanf(strstr(tll_one, "triangles: "), "triangles: %zu", &nt), 1);
    char cap[128];
    snprintf(cap, sizeof cap, ">LOT(%s): %zu triangles<", tll_rules[k], nt);
    tll_panel(v, cap, nt, k, w / 3, (h - 34) / 2, 34);
  }
  free(v);
}

/* A list with an output of one triangulation, or a bad name: one line,
** exit 2, nothing on stdout, no file. */
static void test_lot_list_refused(void **state) {
  (void)state;
  char path[512];
  testutil_tmppath(path, sizeof path, "lot_list_refused.csv");
  unlink(path);
  static const struct { const char *args, *msg; } cases[] = {
    {"--rule DT,P_1 --out %s", "--out takes one rule, not a list of 2"},
    {"--rule ES:square,ES:diamond --cdf %s", "--cdf takes one rule, not a list of 2"},
    {"--rule DT,ES:square,P_1 --svg %s.svg --shade", "--shade takes one rule, not a list of 3"},
    {"--rule DT,nosuch_1 --out %s", "nosuch"},
    {"--rule DT,ES:ellipse:2,1 --svg %s.svg", "ellipse:2"},
    {"--rule DT,,P_1 --svg %s.svg", "empty or too long rule name"},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    char args[1024];
    snprintf(args, sizeof args, cases[i].args, path);
    int rc = testutil_runf(tll_out, sizeof tll_out, tll_err, sizeof tll_err,
                           "lot --random 30 %s", args);
    assert_int_equal(rc, 2);
    assert_true(testutil_one_line(tll_err));
    assert_non_null(strstr(tll_err, cases[i].msg));
    assert_string_equal(tll_out, "");
    assert_int_equal(access(path, F_OK), -1);
  }
}

/* One rule with a comma is still read whole ("ES:ellipse:2,1" is one rule,
** as before lists): one block, and its --out is written. */
static void test_lot_list_single_comma(void **state) {
  (void)state;
  char path[512];
  testutil_tmppath(path, sizeof path, "lot_list_one.csv");
  assert_int_equal(testutil_runf(tll_out, sizeof tll_out, tll_err, sizeof tll_err,
                                 "lot --rule ES:ellipse:2,1 --random 40 --out %s", path), 0);
  assert_int_equal(testutil_count(tll_out, "# fliplab lot: rule "), 1);
  assert_int_equal(access(path, F_OK), 0);
  unlink(path);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_lot_list_blocks),
    cmocka_unit_test(test_lot_list_svg),
    cmocka_unit_test(test_lot_list_refused),
    cmocka_unit_test(test_lot_list_single_comma),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
