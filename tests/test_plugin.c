/*
** test_plugin.c: the plugin ABI and loader, and the two example plugins.
**
** The example rules are checked against their documented definitions
** computed independently (the diagonals' intersection point constructed
** explicitly for [109], geom_tri's angles for [156]), for independence of
** the starting vertex, and for thread-count stability; broken plugins
** (missing file, wrong ABI, no entry symbol, name clashes) are refused with
** one-line messages and leave the registries as they were.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "formula.h"
#include "measure.h"
#include "flipgraph.h"
#include "plugin.h"
#include "plugin_loader.h"
#include "rule.h"
#include "testutil.h"

#define PLUGIN_DIR FLIPLAB_BUILD_DIR "/plugins/"

/* Loaded once for the whole program (plugins cannot be unloaded). */
static int setup(void **state) {
  (void)state;
  char err[1024];
  if (plugin_load(PLUGIN_DIR "rule109.so", err, sizeof err) != 0) {
    fprintf(stderr, "%s\n", err);
    return -1;
  }
  if (plugin_load(PLUGIN_DIR "rule156.so", err, sizeof err) != 0) {
    fprintf(stderr, "%s\n", err);
    return -1;
  }
  return 0;
}

static rule parse(const char *name) {
  rule r;
  char err[2048];
  if (rule_parse(name, &r, err, sizeof err) != 0) fail_msg("%s", err);
  return r;
}

static void test_loaded(void **state) {
  (void)state;
  assert_int_equal(plugin_count(), 2);
  rule r109 = parse("rule109"), r156 = parse("rule156"), pa = parse("P2/A_1");
  assert_int_equal(r109.kind, RULE_QUAD);
  assert_int_equal(r156.kind, RULE_QUAD);
  assert_int_equal(pa.kind, RULE_TRIANGLE);
  assert_int_equal(measure_get(pa.measure)->sign, MEASURE_NONNEG);
  /* The plugin measure is P^2/A of the triangle. */
  testutil_rng g = {5};
  for (int n = 0; n < 1000; n++) {
    geom_point p[3];
    for (int i = 0; i < 3; i++) p[i] = (geom_point){testutil_uniform(&g), testutil_uniform(&g)};
    geom_tri t;
    geom_tri_make(&t, p[0], p[1], p[2]);
    assert_true(measure_eval(pa.measure, &t) == t.P * t.P / t.area);
  }
}

/* ---- rule [109] against its definition ------------------------------------ */

static double dist(geom_point p, geom_point q) {
  return hypot(p.x - q.x, p.y - q.y);
}

/* The intersection of AC and BD by solving A + s(C - A) = B + t(D - B). */
static geom_point intersection(const geom_point q[4]) {
  double ex = q[2].x - q[0].x, ey = q[2].y - q[0].y, fx = q[3].x - q[1].x, fy = q[3].y - q[1].y;
  double den = ex * fy - ey * fx;
  double s = ((q[1].x - q[0].x) * fy - (q[1].y - q[0].y) * fx) / den;
  return (geom_point){q[0].x + s * ex, q[0].y + s * ey};
}

/* Away from the boundaries (ratios within 1e-9 of 1/4 or 4, lengths within
** 1e-9 relative), where rounding could legitimately go either way. */
static int expect109(const geom_point q[4], int *clear) {
  geom_point I = intersection(q);
  double rac = dist(q[0], I) / dist(I, q[2]), rbd = dist(q[1], I) / dist(I, q[3]);
  double lac = dist(q[0], q[2]), lbd = dist(q[1], q[3]);
  int ok_ac = rac >= 0.25 && rac <= 4, ok_bd = rbd >= 0.25 && rbd <= 4;
  *clear = fabs(rac - 0.25) > 1e-9 && fabs(rac - 4) > 1e-9 && fabs(rbd - 0.25) > 1e-9 &&
           fabs(rbd - 4) > 1e-9 && fabs(lac - lbd) > 1e-9 * lac;
  int shorter = lac < lbd ? RULE_AC : RULE_BD;
  int ok_short = shorter == RULE_AC ? ok_ac : ok_bd, ok_long = shorter == RULE_AC ? ok_bd : ok_ac;
  if (ok_short) return shorter;
  if (ok_long) return 1 - shorter;
  return shorter;
}

static void test_rule109_definition(void **state) {
  (void)state;
  rule r = parse("rule109");
  testutil_rng g = {109};
  int seen[3] = {0, 0, 0}, fallback = 0;
  for (int n = 0; n < 50000; n++) {
    geom_point q[4];
    testutil_convex_quad(&g, q);
    int clear, want = expect109(q, &clear);
    if (!clear) continue;
    rule_choice got = rule_eval(&r, q, NULL, NULL);
    assert_int_equal(got, want);
    seen[got]++;
    fallback += (dist(q[0], q[2]) < dist(q[1], q[3])) != (got == RULE_AC);
  }
  /* Both answers occur, and the fallback (the longer diagonal) is exercised. */
  assert_true(seen[RULE_AC] > 1000 && seen[RULE_BD] > 1000);
  assert_true(fallback > 100);
}

/* ---- rule [156] against its definition ------------------------------------ */

static void test_rule156_definition(void **state) {
  (void)state;
  rule r = parse("rule156");
  testutil_rng g = {156};
  const double thr = M_PI / 6;
  int fallback = 0;
  for (int n = 0; n < 50000; n++) {
    geom_point q[4];
    testutil_convex_quad(&g, q);
    geom_tri t[4];   /* ABC, ACD, ABD, BCD */
    testutil_quad_tris(q, t);
    double mac = fmin(t[0].alpha, t[1].alpha), mbd = fmin(t[2].alpha, t[3].alpha);
    double lac = dist(q[0], q[2]), lbd = dist(q[1], q[3]);
    if (fabs(lac - lbd) < 1e-9 * lac || fabs(mac - mbd) < 1e-9 || fabs(fmin(mac, mbd) - thr) < 1e-9 ||
        fabs(fmax(mac, mbd) - thr) < 1e-9)
      continue;
    int shorter = lac < lbd ? RULE_AC : RULE_BD;
    double mshort = shorter == RULE_AC ? mac : mbd;
    int want = mshort >= thr ? shorter : (mac > mbd ? RULE_AC : RULE_BD);
    fallback += want != shorter;
    assert_int_equal(rule_eval(&r, q, NULL, NULL), want);
  }
  assert_true(fallback > 100);
}

/* The raw plugin functions, called without fliplab's canonical rotation:
** F(BCDA) must be F(ABCD) with AC and BD swapped. */
static void test_rotation_raw(void **state) {
  (void)state;
  static const char *const files[] = {"rule109.so", "rule156.so"};
  for (int f = 0; f < 2; f++) {
    char path[1024];
    snprintf(path, sizeof path, "%s%s", PLUGIN_DIR, files[f]);
    void *h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    assert_non_null(h);
    void *sym = dlsym(h, FLIPLAB_PLUGIN_ENTRY);
    assert_non_null(sym);
    fliplab_plugin_entry_fn entry;
    memcpy(&entry, &sym, sizeof entry);
    const fliplab_plugin *pl = entry();
    assert_int_equal(pl->abi, FLIPLAB_PLUGIN_ABI);
    assert_int_equal(pl->nrules, 1);
    testutil_rng g = {77};
    int differ = 0;
    for (int n = 0; n < 20000; n++) {
      geom_point q[4];
      testutil_convex_quad(&g, q);
      fliplab_plugin_point p[4], s[4];
      for (int i = 0; i < 4; i++) p[i] = (fliplab_plugin_point){q[i].x, q[i].y};
      for (int i = 0; i < 4; i++) s[i] = p[(i + 1) % 4];
      int a = pl->rules[0].fn(p), b = pl->rules[0].fn(s);
      if (a == FLIPLAB_PLUGIN_EITHER) differ += b != FLIPLAB_PLUGIN_EITHER;
      else differ += b != 1 - a;
    }
    /* Rounding of the two orders could split a boundary case; none in 20000. */
    assert_int_equal(differ, 0);
    dlclose(h);
  }
}

/* Counts do not depend on the thread count. */
static void test_thread_stable(void **state) {
  (void)state;
  rule rules[4] = {parse("rule109"), parse("rule156"), parse("P2/A_1"), parse("P2/A_inf")};
  flipgraph_counts one[4], two[4];
  memset(one, 0, sizeof one);
  memset(two, 0, sizeof two);
  assert_int_equal(flipgraph_tally(rules, 4, 3, 0, 30000, RULE_DEFAULT_TIE_EPS, 1, one, NULL, NULL), 0);
  assert_int_equal(flipgraph_tally(rules, 4, 3, 0, 30000, RULE_DEFAULT_TIE_EPS, 2, two, NULL, NULL), 0);
  assert_memory_equal(one, two, sizeof one);
  for (int r = 0; r < 4; r++) assert_int_equal(one[r].samples, 30000);
  /* A quadrilateral rule may have no sink (type IV); a triangle rule never. */
  assert_int_equal(one[2].type[FLIPGRAPH_IV], 0);
  assert_int_equal(one[3].type[FLIPGRAPH_IV], 0);
  char msg[1024];
  assert_int_equal(formula_check_errors(msg, sizeof msg), 0);
}

/* ---- refusals --------------------------------------------------------------- */

static void refused(const char *path, const char *want) {
  char err[1024];
  int m = measure_count(), q = rule_quad_count(), p = plugin_count();
  assert_int_equal(plugin_load(path, err, sizeof err), -1);
  assert_null(strchr(err, '\n'));
  if (strstr(err, want) == NULL) fail_msg("loading %s: message lacks '%s': %s", path, want, err);
  assert_int_equal(measure_count(), m);
  assert_int_equal(rule_quad_count(), q);
  assert_int_equal(plugin_count(), p);
}

static void test_refusals(void **state) {
  (void)state;
  refused(PLUGIN_DIR "nothere.so", "No such file");
  refused(PLUGIN_DIR "badabi.so", "ABI 42");
  refused(PLUGIN_DIR "noentry.so", "does not export fliplab_plugin_entry");
  refused(PLUGIN_DIR "badname.so", "rule name 'bad...' has the byte 0x0a");   /* a newline */
  refused(PLUGIN_DIR "rule109.so", "already exists");
  refused(PLUGIN_DIR "rule156.so", "already exists");
  refused(FLIPLAB_SOURCE_DIR "/CMakeLists.txt", "cannot load");
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_loaded),
    cmocka_unit_test(test_rule109_definition),
    cmocka_unit_test(test_rule156_definition),
    cmocka_unit_test(test_rotation_raw),
    cmocka_unit_test(test_thread_stable),
    cmocka_unit_test(test_refusals),
  };
  return cmocka_run_group_tests(tests, setup, NULL);
}
