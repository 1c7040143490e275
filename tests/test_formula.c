/*
** test_formula.c: measures defined by a muParser formula.
**
** A formula that spells a built-in measure must be that measure bit for bit
** (so every count built on it is the same), from any thread; the sign
** domain is inferred or checked; bad definitions are refused with one-line
** messages that say where and what; bad values during a run are recorded
** with their triangle, never silently counted.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <omp.h>
#include "formula.h"
#include "measure.h"
#include "flipgraph.h"
#include "rule.h"
#include "testutil.h"

static int teardown(void **state) {
  (void)state;
  measure_unregister_user();
  formula_reset();
  return 0;
}

static int define_ok(const char *def) {
  char err[1024];
  int id = formula_define(def, err, sizeof err);
  if (id < 0) fail_msg("formula_define('%s') failed: %s", def, err);
  return id;
}

/* A definition that must fail: the message is one line and mentions want. */
static void define_bad(const char *def, const char *want) {
  char err[1024];
  int before = measure_count();
  int id = formula_define(def, err, sizeof err);
  if (id >= 0) fail_msg("formula_define('%s') was accepted", def);
  assert_null(strchr(err, '\n'));
  if (strstr(err, want) == NULL) fail_msg("message for '%s' lacks '%s': %s", def, want, err);
  assert_int_equal(measure_count(), before);
}

static void random_tri(testutil_rng *g, geom_tri *t) {
  geom_point p[3];
  for (int i = 0; i < 3; i++) p[i] = (geom_point){2 * testutil_uniform(g) - 1, 2 * testutil_uniform(g) - 1};
  geom_tri_make(t, p[0], p[1], p[2]);
}

/* Formulas spelling built-in measures give the same bits on random
** triangles: a*b*c is evaluated left to right like the C code, and
** -2*A/P = -(2A)/P with 2A exact. */
static void test_same_bits_as_builtin(void **state) {
  (void)state;
  static const struct { const char *def; int builtin; } cases[] = {
    {"q = a*b*c", MEASURE_ABC}, {"nr = -2*A/P", MEASURE_NEG_R}, {"g = gamma", MEASURE_GAMMA},
    {"na = -alpha", MEASURE_NEG_ALPHA}, {"amc = a - c", MEASURE_A_MINUS_C}, {"Rf = R", MEASURE_R},
  };
  int ids[6];
  for (int k = 0; k < 6; k++) ids[k] = define_ok(cases[k].def);
  testutil_rng g = {42};
  for (int n = 0; n < 20000; n++) {
    geom_tri t;
    random_tri(&g, &t);
    if (!(t.area > 0)) continue;
    for (int k = 0; k < 6; k++) {
      double f = measure_eval(ids[k], &t), b = measure_eval(cases[k].builtin, &t);
      if (memcmp(&f, &b, sizeof f) != 0)
        fail_msg("%s: %.17g vs built-in %.17g", cases[k].def, f, b);
    }
  }
  char msg[1024];
  assert_int_equal(formula_check_errors(msg, sizeof msg), 0);
}

/* The check the issue asks for: q = a*b*c gives table 3.4's counts of abc
** for all six joints, through the multi-threaded fast path. */
static void test_tally_matches_builtin(void **state) {
  (void)state;
  int q = define_ok("q = a*b*c");
  rule rules[12];
  char err[512];
  for (int j = 0; j < JOINT_COUNT; j++) {
    assert_int_equal(rule_triangle(MEASURE_ABC, (joint_id)j, &rules[j], err, sizeof err), 0);
    assert_int_equal(rule_triangle(q, (joint_id)j, &rules[6 + j], err, sizeof err), 0);
  }
  flipgraph_counts c[12];
  memset(c, 0, sizeof c);
  assert_int_equal(flipgraph_tally(rules, 12, 7, 0, 20000, RULE_DEFAULT_TIE_EPS, 2, c, NULL, NULL), 0);
  for (int j = 0; j < JOINT_COUNT; j++) {
    assert_int_equal(c[j].samples, 20000);
    assert_memory_equal(&c[j], &c[6 + j], sizeof c[j]);
  }
  char msg[1024];
  assert_int_equal(formula_check_errors(msg, sizeof msg), 0);
}

/* One parser per thread: values computed in parallel equal serial ones. */
static void test_threads(void **state) {
  (void)state;
  int id = define_ok("s = sqrt(a*a + b*b) / (r + h) + sin(alpha) * x1 - y3");
  enum { N = 20000 };
  static geom_tri t[N];
  static double serial[N], parallel[N];
  testutil_rng g = {9};
  for (int i = 0; i < N; i++) {
    do random_tri(&g, &t[i]);
    while (!(t[i].area > 0));
    serial[i] = measure_eval(id, &t[i]);
  }
#pragma omp parallel for num_threads(4) schedule(dynamic, 7)
  for (int i = 0; i < N; i++) parallel[i] = measure_eval(id, &t[i]);
  assert_memory_equal(serial, parallel, sizeof serial);
}

static void test_variables(void **state) {
  (void)state;
  /* Every variable, bound to the right quantity. */
  static const char *const defs[] = {
    "v1 = a + 0*b", "v2 = b", "v3 = c", "v4 = alpha", "v5 = beta", "v6 = gamma", "v7 = A",
    "v8 = P", "v9 = R", "v10 = r", "v11 = h", "v12 = rx", "v13 = ry", "v14 = x1 + 10",
    "v15 = y1 + 10", "v16 = x2 + 10", "v17 = y2 + 10", "v18 = x3 + 10", "v19 = y3 + 10",
    "v20 = pi",
  };
  int id[20];
  for (int k = 0; k < 20; k++) id[k] = define_ok(defs[k]);
  geom_tri t;
  geom_tri_make(&t, (geom_point){0.5, 2}, (geom_point){-1, 0.25}, (geom_point){3, -0.5});
  double want[20] = {t.a, t.b, t.c, t.alpha, t.beta, t.gamma, t.area, t.P, t.R, t.r, t.h,
                     t.rx, t.ry, t.v[0].x + 10, t.v[0].y + 10, t.v[1].x + 10, t.v[1].y + 10,
                     t.v[2].x + 10, t.v[2].y + 10, M_PI};
  for (int k = 0; k < 20; k++) assert_true(measure_eval(id[k], &t) == want[k]);
  /* x1 y1 is the lexicographically smallest vertex. */
  assert_true(t.v[0].x == -1 && t.v[0].y == 0.25);
}

static void test_signs(void **state) {
  (void)state;
  char err[512];
  rule r;
  assert_int_equal(measure_get(define_ok("q = a*b*c"))->sign, MEASURE_NONNEG);
  assert_int_equal(measure_get(define_ok("n = -A"))->sign, MEASURE_NONPOS);
  int z = define_ok("z = a - 1");
  assert_int_equal(measure_get(z)->sign, MEASURE_ANYSIGN);
  /* Both signs: the joints that need one are refused with a reason, min
  ** and max are allowed. */
  for (int j = 0; j < JOINT_COUNT; j++) {
    int rc = rule_triangle(z, (joint_id)j, &r, err, sizeof err);
    if (joint_get((joint_id)j)->needs_sign) {
      assert_int_equal(rc, -1);
      assert_non_null(strstr(err, "both signs"));
      assert_null(strchr(err, '\n'));
    } else {
      assert_int_equal(rc, 0);
    }
  }
  assert_int_equal(rule_parse("z_1", &r, err, sizeof err), -1);
  assert_int_equal(rule_parse("z_inf", &r, err, sizeof err), 0);
  /* Declared signs are kept, and checked against the samples. */
  assert_int_equal(measure_get(define_ok("dd <= 0 : -r"))->sign, MEASURE_NONPOS);
  assert_int_equal(measure_get(define_ok("e >= 0 : R"))->sign, MEASURE_NONNEG);
  define_bad("f >= 0 : -a", "declared >= 0");
  define_bad("f <= 0 : a - c + 1e-300", "declared <= 0");
}

static void test_bad_definitions(void **state) {
  (void)state;
  define_bad("q = a*", "syntax error at position 6");
  define_bad("q = sin(a", "syntax error at position");
  define_bad("q = a b", "syntax error at position 6");
  define_bad("q = a*foo", "unknown variable 'foo'");
  define_bad("q = alpha + theta", "unknown variable 'theta'");
  define_bad("q = ", "empty");
  define_bad("q", "expected NAME = EXPR");
  define_bad("= a", "expected NAME = EXPR");
  define_bad("q >= 1 : a", "expected NAME");
  define_bad("q = a = 3", "assignment");
  define_bad("q = a, b", "comma-separated");
  define_bad("abc = a", "already exists");
  define_bad("q_1 = a", "'_'");
  define_bad("123 = a", "letter");
  define_bad("q = 1/0", "not finite");
  define_ok("q = a");
  define_bad("q = b", "already exists");
}

/* What muParser cannot survive never reaches it, and what it would misread
** is refused: a definition over FORMULA_TEXT_MAX characters (a 2,100-character
** bad token crashed muParser's message formatting), a name over the limit
** (was silently cut, then "unknown rule"), literals outside the doubles
** (1e400 was an "unknown variable", 1e-400 silently 0).  Messages stay short. */
static void test_bounds(void **state) {
  (void)state;
  static char def[3000];
  char err[1024];
  memcpy(def, "q = a+", 6);
  memset(def + 6, '#', 2100);
  def[2106] = '\0';
  define_bad(def, "at most 1024");
  def[6 + 1000] = '\0';                     /* under the limit: a syntax error */
  assert_true(formula_define(def, err, sizeof err) < 0);
  assert_non_null(strstr(err, "syntax error at position 6"));
  assert_true(strlen(err) < 200);
  define_bad("averyveryveryveryverylongnamethatistoolong = a", "at most 31");
  define_bad("q = 1e400*a", "number '1e400' at position 4 is out of range");
  define_bad("q = a*1e-400", "number '1e-400' at position 6 is out of range");
  define_bad("q = a + 2.5E+999", "out of range");
  define_bad("q = a + x1e999", "unknown variable 'x1e999'");   /* a name, not a number */
  define_ok("q = a*1e300 + 0.5e-300");
}

/* Bad values during a run are recorded with the triangle, not dropped. */
static void test_bad_values(void **state) {
  (void)state;
  char msg[1024];
  formula_clear_errors();
  int u = define_ok("u = sqrt(x1)");              /* NaN left of the y axis */
  assert_int_equal(formula_check_errors(msg, sizeof msg), 0);
  rule r;
  char err[512];
  assert_int_equal(rule_parse("u_1", &r, err, sizeof err), 0);
  flipgraph_counts c;
  memset(&c, 0, sizeof c);
  assert_int_equal(flipgraph_tally(&r, 1, 1, 0, 2000, RULE_DEFAULT_TIE_EPS, 2, &c, NULL, NULL), 0);
  assert_int_equal(formula_check_errors(msg, sizeof msg), 1);
  assert_non_null(strstr(msg, "measure 'u'"));
  assert_non_null(strstr(msg, "not finite"));
  assert_null(strchr(msg, '\n'));
  /* The triangle printed with %.17g reproduces the bad value. */
  double x[3], y[3];
  const char *at = strstr(msg, "triangle (");
  assert_non_null(at);
  assert_int_equal(sscanf(at, "triangle (%lf, %lf), (%lf, %lf), (%lf, %lf)", &x[0], &y[0],
                          &x[1], &y[1], &x[2], &y[2]), 6);
  geom_tri t;
  geom_tri_make(&t, (geom_point){x[0], y[0]}, (geom_point){x[1], y[1]}, (geom_point){x[2], y[2]});
  assert_true(isnan(measure_eval(u, &t)));
  formula_clear_errors();
  assert_int_equal(formula_check_errors(msg, sizeof msg), 0);

  /* A value outside the declared sign domain is a bad value too. */
  int k = define_ok("k >= 0 : x1 + 1e6");
  geom_tri far;
  geom_tri_make(&far, (geom_point){-2e6, 0}, (geom_point){-2e6 + 1, 0}, (geom_point){-2e6, 1});
  assert_true(measure_eval(k, &far) < 0);
  assert_int_equal(formula_check_errors(msg, sizeof msg), 1);
  assert_non_null(strstr(msg, "negative"));
  formula_clear_errors();
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test_teardown(test_same_bits_as_builtin, teardown),
    cmocka_unit_test_teardown(test_tally_matches_builtin, teardown),
    cmocka_unit_test_teardown(test_threads, teardown),
    cmocka_unit_test_teardown(test_variables, teardown),
    cmocka_unit_test_teardown(test_signs, teardown),
    cmocka_unit_test_teardown(test_bad_definitions, teardown),
    cmocka_unit_test_teardown(test_bounds, teardown),
    cmocka_unit_test_teardown(test_bad_values, teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
