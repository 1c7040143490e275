/*
** test_threads.c: the thread-count contract of every library entry point
** that takes one (geom.h: 0 for all cores, or 1 .. GEOM_MAX_THREADS, the
** program's --threads range).  Found from outside: got_solve with 100000
** threads overflowed the OpenMP runtime's stacks (through Python it killed
** the interpreter), and negative counts were taken as "all cores".  Entry
** points with an error channel refuse another count with one line; those
** without one run with a clamped count, never a larger team.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "flipgraph.h"
#include "geom.h"
#include "got.h"
#include "rule.h"
#include "sampler.h"
#include "siteflip.h"
#include "testutil.h"

static const int tth_bad[] = {-1, -1000, GEOM_MAX_THREADS + 1, 100000, 0x7fffffff};
#define TTH_NBAD (sizeof tth_bad / sizeof *tth_bad)

static rule tth_rule(const char *name) {
  rule r;
  char err[256];
  if (rule_parse(name, &r, err, sizeof err) != 0) fail_msg("%s: %s", name, err);
  return r;
}

static void test_check_and_clamp(void **state) {
  (void)state;
  char err[128];
  assert_int_equal(geom_threads_check(0, err, sizeof err), 0);
  assert_int_equal(geom_threads_check(1, err, sizeof err), 0);
  assert_int_equal(geom_threads_check(GEOM_MAX_THREADS, err, sizeof err), 0);
  for (size_t i = 0; i < TTH_NBAD; i++) {
    err[0] = '\0';
    assert_int_equal(geom_threads_check(tth_bad[i], err, sizeof err), -1);
    assert_null(strchr(err, '\n'));   /* a message, one line without its end */
    assert_non_null(strstr(err, "threads: expected 0 (all cores) or 1 .. 1024"));
    assert_int_equal(geom_threads_clamp(tth_bad[i], 3), 3);
  }
  assert_int_equal(geom_threads_check(-5, NULL, 0), -1);   /* no message wanted */
  assert_int_equal(geom_threads_clamp(0, 7), 7);
  assert_int_equal(geom_threads_clamp(5, 7), 5);
  assert_int_equal(geom_threads_clamp(0, 100000), GEOM_MAX_THREADS);
  assert_int_equal(geom_threads_clamp(0, 0), 1);
  assert_int_equal(geom_threads_clamp(0, -4), 1);
}

/* got_solve: refused with the message, nothing allocated; 0 and 2 run. */
static void test_got(void **state) {
  (void)state;
  const geom_point p[5] = {{0, 0}, {2, 0}, {3, 1}, {1, 3}, {-1, 1}};
  rule r = tth_rule("P_1");
  got_result res;
  char err[256];
  for (size_t i = 0; i < TTH_NBAD; i++) {
    got_options o = {tth_bad[i], RULE_DEFAULT_TIE_EPS};
    err[0] = '\0';
    assert_int_equal(got_solve(p, 5, &r, &o, &res, err, sizeof err), -1);
    assert_non_null(strstr(err, "threads:"));
    assert_null(res.tri);
  }
  double key = 0;
  for (int t = 0; t <= 2; t += 2) {
    got_options o = {t, RULE_DEFAULT_TIE_EPS};
    assert_int_equal(got_solve(p, 5, &r, &o, &res, err, sizeof err), 0);
    assert_true(res.threads >= 1 && res.threads <= GEOM_MAX_THREADS);
    if (t == 0) key = res.key;
    assert_true(res.key == key);
    got_result_free(&res);
  }
}

/* flipgraph_tally: -1 with the counts untouched; classify_n (no error
** channel for threads) runs clamped, with the same graphs as one thread. */
static void test_flipgraph(void **state) {
  (void)state;
  rule r = tth_rule("R_1");
  flipgraph_counts c;
  for (size_t i = 0; i < TTH_NBAD; i++) {
    memset(&c, 0xab, sizeof c);
    assert_int_equal(flipgraph_tally(&r, 1, 1, 0, 100, RULE_DEFAULT_TIE_EPS, tth_bad[i], &c,
                                     NULL, NULL), -1);
    for (size_t k = 0; k < sizeof c; k++) assert_int_equal(((unsigned char *)&c)[k], 0xab);
  }
  memset(&c, 0, sizeof c);
  assert_int_equal(flipgraph_tally(&r, 1, 1, 0, 100, RULE_DEFAULT_TIE_EPS, 2, &c, NULL, NULL), 0);
  geom_point v[2][40];
  flipgraph g[2][8];
  for (int k = 0; k < 8; k++) sampler_pentagon(3, (uint64_t)k, &v[0][5 * k]);
  memcpy(v[1], v[0], sizeof v[0]);
  geom_polyerr e;
  size_t bad;
  assert_int_equal(flipgraph_classify_n(v[0], 8, &r, 1, RULE_DEFAULT_TIE_EPS, 100000, g[0], &e,
                                        &bad), 8);
  assert_int_equal(flipgraph_classify_n(v[1], 8, &r, 1, RULE_DEFAULT_TIE_EPS, 1, g[1], &e, &bad),
                   8);
  for (int k = 0; k < 8; k++) {
    assert_int_equal(g[0][k].type, g[1][k].type);
    assert_int_equal(g[0][k].nsinks, g[1][k].nsinks);
  }
}

/* siteflip_census: -1 with geom_threads_check's message. */
static void test_siteflip(void **state) {
  (void)state;
  rule r = tth_rule("DT");
  siteflip_counts c;
  char err[256];
  for (size_t i = 0; i < TTH_NBAD; i++) {
    memset(&c, 0, sizeof c);
    err[0] = '\0';
    assert_int_equal(siteflip_census(&r, 1, SAMPLER_SITES_DISC, 5, 1, 0, 10,
                                     RULE_DEFAULT_TIE_EPS, tth_bad[i], 0, &c, NULL, NULL, NULL,
                                     err, sizeof err), -1);
    assert_non_null(strstr(err, "threads: expected"));
    assert_int_equal(c.samples, 0);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_check_and_clamp),
    cmocka_unit_test(test_got),
    cmocka_unit_test(test_flipgraph),
    cmocka_unit_test(test_siteflip),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
