/*
** test_table34_stats.c: the thesis's statements about table 3.4, checked on
** 20,000 pentagons of the iteration sampler (flipgraph_tally, the 120
** rules of the table plus DT), with tolerances from the binomial standard
** error SE = sqrt(p (1 - p) / n), n = 20,000:
**
** - R_f (all six joints), -alpha_inf, -r_1, abc_1, -r/R_1, -r2/A_0 and DT
**   are 100% Delaunay.  These are theorems (thesis section 3.4, appendix
**   A): SE is 0 at p = 1 and no exception is allowed.
** - A_1, a_inf, -c_inf, Rinf_inf are 100% type V (thesis section 3.5:
**   A_1 ties always; a_inf ties on every pentagon because the pentagon's
**   longest segment is a side of some quadrilateral; likewise the others).
** - -c with the other five joints is about 84% type V and Pinf_inf about
**   11%.  The thesis's figures are whole percentages of 5,000 samples; we
**   allow 5 SE of our estimate (84%: SE = 0.26%, 11%: SE = 0.22%) plus half
**   a percentage point for the thesis's rounding.  (Measured on 2,000,000
**   samples: see the report; both agree with the thesis.)
** - No other rule of the table gives type V (ties have probability zero
**   unless structural), and no triangle-based rule gives type IV.
** - -A_inf and -A_-inf have identical type counts: with A_ABC + A_ACD =
**   A_ABD + A_BCD, maximising the smaller area is minimising the larger,
**   so one rule's graph is the other's reversed, and reversal maps types
**   I, II, III onto themselves (sinks and sources swap; their distance on
**   the cycle is kept).
** - The counts are identical for one and two threads and for any split
**   into shards.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "measure.h"
#include "flipgraph.h"
#include "rule.h"

#define TS34_N 20000
#define TS34_SEED 20260523

static rule ts34_rules[128];
static int ts34_n;
static flipgraph_counts ts34_c[128];

static int ts34_setup(void **state) {
  (void)state;
  ts34_n = rule_list_triangle(measure_table34, MEASURE_TABLE34_COUNT, ts34_rules, 127);
  ts34_rules[ts34_n++] = rule_delaunay();
  memset(ts34_c, 0, sizeof ts34_c);
  return flipgraph_tally(ts34_rules, ts34_n, TS34_SEED, 0, TS34_N, RULE_DEFAULT_TIE_EPS, 0,
                         ts34_c, NULL, NULL);
}

static const flipgraph_counts *ts34_get(const char *name) {
  for (int r = 0; r < ts34_n; r++)
    if (strcmp(ts34_rules[r].name, name) == 0) return &ts34_c[r];
  print_error("rule %s not in the table\n", name);
  fail();
  return NULL;
}

static void test_table_shape(void **state) {
  (void)state;
  assert_int_equal(ts34_n, 121);
  for (int r = 0; r < ts34_n; r++) {
    uint64_t sum = 0;
    for (int t = 0; t < FLIPGRAPH_NTYPES; t++) sum += ts34_c[r].type[t];
    assert_int_equal(ts34_c[r].samples, TS34_N);
    assert_int_equal(sum, TS34_N);
    assert_true(ts34_c[r].dt <= ts34_c[r].type[FLIPGRAPH_I]);
    assert_int_equal(ts34_c[r].type[FLIPGRAPH_IV], 0);
  }
}

static void test_always_delaunay(void **state) {
  (void)state;
  const char *dt[] = {"R_-inf", "R_-1", "R_0", "R_1", "R_2", "R_inf", "-alpha_inf",
                      "-r_1", "abc_1", "-r/R_1", "-r2/A_0", "DT"};
  for (size_t i = 0; i < sizeof dt / sizeof dt[0]; i++) {
    const flipgraph_counts *c = ts34_get(dt[i]);
    if (c->dt != TS34_N) {
      print_error("%s: %llu of %d Delaunay\n", dt[i], (unsigned long long)c->dt, TS34_N);
      fail();
    }
  }
}

static void ts34_rate(const char *name, double want, double slack) {
  const flipgraph_counts *c = ts34_get(name);
  double p = (double)c->type[FLIPGRAPH_V] / TS34_N;
  double se = sqrt(want * (1 - want) / TS34_N);
  double tol = 5 * se + slack;
  if (!(fabs(p - want) <= tol)) {
    print_error("%s: type V %.4f, thesis %.2f, tolerance %.4f\n", name, p, want, tol);
    fail();
  }
}

static void test_type_five(void **state) {
  (void)state;
  const char *always[] = {"-A_1", "a_inf", "-c_inf", "Rinf_inf"};
  for (size_t i = 0; i < 4; i++)
    assert_int_equal(ts34_get(always[i])->type[FLIPGRAPH_V], TS34_N);
  const char *c84[] = {"-c_-inf", "-c_-1", "-c_0", "-c_1", "-c_2"};
  for (size_t i = 0; i < 5; i++) ts34_rate(c84[i], 0.84, 0.005);
  ts34_rate("Pinf_inf", 0.11, 0.005);
  /* Nobody else. */
  const char *any[] = {"-A_1", "a_inf", "-c_inf", "Rinf_inf", "-c_-inf", "-c_-1", "-c_0",
                       "-c_1", "-c_2", "Pinf_inf"};
  for (int r = 0; r < ts34_n; r++) {
    int listed = 0;
    for (size_t i = 0; i < sizeof any / sizeof any[0]; i++)
      listed |= strcmp(ts34_rules[r].name, any[i]) == 0;
    if (!listed && ts34_c[r].type[FLIPGRAPH_V] != 0) {
      print_error("%s: unexpected type V (%llu)\n", ts34_rules[r].name,
                  (unsigned long long)ts34_c[r].type[FLIPGRAPH_V]);
      fail();
    }
  }
}

static void test_area_min_max_mirror(void **state) {
  (void)state;
  const flipgraph_counts *a = ts34_get("-A_inf"), *b = ts34_get("-A_-inf");
  for (int t = 0; t < FLIPGRAPH_NTYPES; t++) assert_int_equal(a->type[t], b->type[t]);
  /* Not a trivial equality: the two rules do pick different triangulations
  ** (reversal moves the sink), so their Delaunay counts differ. */
  assert_true(a->type[FLIPGRAPH_III] > 0);
  assert_int_not_equal(a->dt, b->dt);
}

static void test_threads_and_shards(void **state) {
  (void)state;
  flipgraph_counts one[128], shards[128];
  memset(one, 0, sizeof one);
  memset(shards, 0, sizeof shards);
  assert_int_equal(flipgraph_tally(ts34_rules, ts34_n, TS34_SEED, 0, TS34_N,
                                   RULE_DEFAULT_TIE_EPS, 1, one, NULL, NULL), 0);
  assert_memory_equal(one, ts34_c, (size_t)ts34_n * sizeof one[0]);
  /* Three uneven shards, two threads, added up. */
  const uint64_t cut[4] = {0, 1234, 13000, TS34_N};
  for (int s = 0; s < 3; s++)
    assert_int_equal(flipgraph_tally(ts34_rules, ts34_n, TS34_SEED, cut[s], cut[s + 1] - cut[s],
                                     RULE_DEFAULT_TIE_EPS, 2, shards, NULL, NULL), 0);
  assert_memory_equal(shards, ts34_c, (size_t)ts34_n * sizeof one[0]);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_table_shape),
    cmocka_unit_test(test_always_delaunay),
    cmocka_unit_test(test_type_five),
    cmocka_unit_test(test_area_min_max_mirror),
    cmocka_unit_test(test_threads_and_shards),
  };
  return cmocka_run_group_tests(tests, ts34_setup, NULL);
}
