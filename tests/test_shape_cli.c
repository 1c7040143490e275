/*
** test_shape_cli.c: empty-shape rules ES:SPEC through the program: lot
** (checked, the two algorithms agreeing), rule and census verdicts
** (theorem 13: type I, one sink), flip, classify, table34, flipgraph, and
** one-line refusals of bad shapes.
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

#define OUTCAP (1 << 20)

static char out[OUTCAP], err[OUTCAP], out2[OUTCAP];

#define RUN(...) testutil_runf(out, sizeof out, err, sizeof err, __VA_ARGS__)

/* Read a whole file into buf (NUL-terminated). */
static void slurp(const char *path, char *buf, size_t cap) {
  FILE *f = fopen(path, "rb");
  assert_non_null(f);
  size_t n = fread(buf, 1, cap - 1, f);
  buf[n] = '\0';
  fclose(f);
}

static void test_lot_check(void **state) {
  (void)state;
  assert_int_equal(RUN("lot --rule ES:square --random 3000 --check"), 0);
  assert_non_null(strstr(out, "check: ok"));
  assert_non_null(strstr(out, "status: converged"));
}

/* The LOT of an empty-shape rule is the empty-shape triangulation: both
** algorithms give the same triangles on sites without ties (uniform), and
** on a grid for shapes whose ties the perturbation settles. */
static void test_algorithms_agree(void **state) {
  (void)state;
  static const char *const cases[][2] = {
    {"ES:square", "uniform"}, {"ES:diamond", "uniform"}, {"ES:hexagon", "uniform"},
    {"ES:triangle", "uniform"}, {"ES:ellipse:2 1 0.5", "uniform"},
    {"ES:hexagon", "grid"}, {"ES:triangle", "grid"}, {"ES:poly:0 0;3 1;4 4;1 3", "grid"},
  };
  char a[4096], b[4096];
  testutil_tmppath(a, sizeof a, "es_inc.csv");
  testutil_tmppath(b, sizeof b, "es_flip.csv");
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    assert_int_equal(RUN("lot --rule '%s' --random 1500 --sampler %s --algorithm incremental "
                         "--check --out %s", cases[i][0], cases[i][1], a), 0);
    assert_int_equal(RUN("lot --rule '%s' --random 1500 --sampler %s --algorithm flip "
                         "--check --out %s", cases[i][0], cases[i][1], b), 0);
    slurp(a, out, sizeof out);
    slurp(b, out2, sizeof out2);
    if (strcmp(out, out2) != 0) fail_msg("%s on %s: the algorithms differ", cases[i][0], cases[i][1]);
  }
  remove(a);
  remove(b);
}

static void test_verdicts(void **state) {
  (void)state;
  assert_int_equal(RUN("rule ES:hexagon --samples 3000"), 0);
  assert_non_null(strstr(out, "I           3000   100.000%"));
  assert_int_equal(RUN("census --sites 6 --samples 200 --sampler disc "
                       "--rules 'ES:square,ES:triangle,ES:poly:0 0;2 0;1 1,ES:ellipse:3 1 1'"), 0);
  const char *rules[] = {"ES:square ", "ES:triangle ", "ES:poly:0 0;2 0;1 1 ", "ES:ellipse:3 1 1 "};
  for (int i = 0; i < 4; i++) {
    const char *l = strstr(out, rules[i]);
    if (l == NULL) fail_msg("no row %s in:\n%s", rules[i], out);
    double one = strtod(l + strlen(rules[i]), NULL);
    assert_true(one == 100.0);
  }
  assert_int_equal(RUN("table34 --rules ES:square,ES:diamond --samples 500"), 0);
  assert_non_null(strstr(out, "Rule ES:square: I 100.00"));
  assert_non_null(strstr(out, "Rule ES:diamond: I 100.00"));
}

/* flip: L_inf decisions by hand.  The squares through A = (0,0), B = (4,0),
** C = (4,1) are [0,4] x [y0, y0 + 4] for y0 in [-3, 0]: D = (1,5) is above
** every one (AC), D = (1,0.75) inside every one (BD), whatever the
** tie-break picks. */
static void test_flip_classify(void **state) {
  (void)state;
  assert_int_equal(RUN("flip ES:square 0 0 4 0 4 1 1 5"), 0);
  assert_non_null(strstr(out, "decision  AC"));
  assert_int_equal(RUN("flip ES:square 0 0 4 0 4 1 1 0.75"), 0);
  assert_non_null(strstr(out, "decision  BD"));
  char p[4096];
  testutil_tmppath(p, sizeof p, "es_pent.csv");
  FILE *f = fopen(p, "w");
  assert_non_null(f);
  fprintf(f, "x1,y1,x2,y2,x3,y3,x4,y4,x5,y5\n0,0,3,0,4,2,1.5,4,-1,2\n");
  fclose(f);
  assert_int_equal(RUN("classify --input %s --rule 'ES:hexagon,ES:poly:0 0;1 0;0 1'", p), 0);
  assert_non_null(strstr(out, "ES:hexagon,"));
  assert_non_null(strstr(out, "ES:poly:0 0;1 0;0 1,"));
  remove(p);
}

static void test_bad_shapes(void **state) {
  (void)state;
  static const char *const bad[][2] = {
    {"ES:poly:0 0;1 0", "too few"}, {"ES:poly:0 0;1 0;1 1;0 1;0.5 0.5", "convex"},
    {"ES:poly:0 0;1 0;0 0", "duplicate"}, {"ES:circle", "unknown shape"},
    {"ES:ngon:2", "3 to"}, {"ES:", "unknown shape"},
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    assert_int_equal(RUN("lot --rule '%s' --random 10", bad[i][0]), 2);
    if (strstr(err, bad[i][1]) == NULL || !testutil_one_line(err))
      fail_msg("'%s': got '%s'", bad[i][0], err);
  }
  /* a comma list cuts "ellipse:2,1": the message says how to write it */
  assert_int_equal(RUN("census --sites 5 --samples 10 --rules ES:ellipse:2,1"), 2);
  assert_non_null(strstr(err, "separate a shape's numbers by blanks"));
  assert_true(testutil_one_line(err));
}

/* The rule owns its shape: lot --cdf reads it off the rule (rule_shape),
** never off the --rule text again.  A name with blanks around it is the
** same rule (one trimming for every rule name), and its CDF graph the same
** file; the text re-read from its fourth character, the CDF of ' ES:square'
** was refused as the unknown shape ':square'. */
static void test_cdf_reads_the_rule(void **state) {
  (void)state;
  static const char *const names[] = {"ES:square", " ES:square", "ES:square ",
                                      "  ES:ellipse:2 1  "};
  char a[4096], b[4096];
  testutil_tmppath(a, sizeof a, "es_cdf_a.csv");
  testutil_tmppath(b, sizeof b, "es_cdf_b.csv");
  assert_int_equal(RUN("lot --rule ES:square --random 400 --cdf %s", a), 0);
  slurp(a, out2, sizeof out2);
  for (size_t i = 1; i < sizeof names / sizeof names[0]; i++) {
    if (RUN("lot --rule '%s' --random 400 --cdf %s", names[i], b) != 0)
      fail_msg("lot --rule '%s' --cdf: %s", names[i], err);
    if (i < 3) {
      slurp(b, out, sizeof out);
      if (strcmp(out, out2) != 0) fail_msg("'%s': another CDF graph", names[i]);
    }
  }
  assert_int_equal(RUN("lot --rule DT --random 40 --cdf %s", b), 2);
  assert_true(testutil_one_line(err));
  assert_non_null(strstr(err, "--cdf needs an empty-shape rule"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_lot_check),
    cmocka_unit_test(test_algorithms_agree),
    cmocka_unit_test(test_verdicts),
    cmocka_unit_test(test_flip_classify),
    cmocka_unit_test(test_bad_shapes),
    cmocka_unit_test(test_cdf_reads_the_rule),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
