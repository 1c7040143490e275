/*
** test_census.c: the census engine against the one-graph path and against
** table 3.4's engine.  Sample by sample, siteflip_census must count what
** siteflip_direct (brute force GOT over every triangulation, rule_eval_tris
** decisions) sees, for every rule and sampler, so the packed decisions and
** the GOT shortcut change nothing; for convex pentagons its counts must be
** table34's (one sink = I + II, several = III, none = IV, tie = V); thread
** counts change nothing; the vector and the portable decision engines
** (quadvec) count the same, also on measures with extreme values.
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

#include "census.h"
#include "flipgraph.h"
#include "measure.h"
#include "rule.h"
#include "sampler.h"
#include "siteflip.h"
#include "testutil.h"

static int tc_all_rules(rule **rules) {
  int ids[MEASURE_BUILTIN_COUNT];
  for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++) ids[m] = m;
  int cap = MEASURE_BUILTIN_COUNT * JOINT_COUNT + 1;
  *rules = malloc((size_t)cap * sizeof **rules);
  int n = rule_list_triangle(ids, MEASURE_BUILTIN_COUNT, *rules, cap - 1);
  (*rules)[n++] = rule_delaunay();
  return n;
}

/* The rules of the three extreme test measures (testutil), then DT. */
static int tc_extreme_rules(rule **rules) {
  int ids[3];
  assert_int_equal(testutil_extreme_measures(ids), 0);
  int cap = 3 * JOINT_COUNT + 1;
  *rules = malloc((size_t)cap * sizeof **rules);
  int n = rule_list_triangle(ids, 3, *rules, cap - 1);
  (*rules)[n++] = rule_delaunay();
  return n;
}

static void tc_census_eps(const rule *rules, int nr, int kind, int n, uint64_t first,
                          uint64_t count, int threads, double eps, siteflip_counts *c) {
  char err[256];
  memset(c, 0, (size_t)nr * sizeof *c);
  if (siteflip_census(rules, nr, kind, n, 3, first, count, eps, threads, 0, c, NULL, NULL, NULL, err,
                      sizeof err) != 0)
    fail_msg("siteflip_census: %s", err);
}

static void tc_census(const rule *rules, int nr, int kind, int n, uint64_t first,
                      uint64_t count, int threads, siteflip_counts *c) {
  tc_census_eps(rules, nr, kind, n, first, count, threads, RULE_DEFAULT_TIE_EPS, c);
}

/* Census against siteflip_direct on samples 0..per-1 of every sampler and
** n = 4..7; adds the several-sink graphs and positive gaps seen. */
static void tc_against_direct(const rule *rules, int nr, double eps, uint64_t per,
                              int *multi_seen, int *gaps_seen) {
  siteflip_counts *c = malloc((size_t)nr * sizeof *c);
  for (int kind = 0; kind < SAMPLER_SITES_COUNT; kind++)
    for (int n = 4; n <= 7; n++)
      for (uint64_t i = 0; i < per; i++) {
        tc_census_eps(rules, nr, kind, n, i, 1, 1, eps, c);
        geom_point p[7];
        sampler_sites(kind, 3, i, n, p);
        char err[256];
        siteflip_graph *g = siteflip_build(p, n, err, sizeof err);
        assert_non_null(g);
        rule_choice *dec = malloc((size_t)(g->nquads + 1) * sizeof *dec);
        for (int r = 0; r < nr; r++) {
          siteflip_result res;
          assert_int_equal(siteflip_direct(g, &rules[r], eps, dec, NULL, &res), 0);
          assert_int_equal(c[r].samples, 1);
          assert_int_equal(c[r].tie, res.ties);
          if (res.ties) continue;
          assert_int_equal(c[r].sinks, res.nsinks);
          assert_int_equal(c[r].no_sink, res.nsinks == 0);
          assert_int_equal(c[r].one_sink, res.nsinks == 1);
          assert_int_equal(c[r].multi_sink, res.nsinks > 1);
          assert_int_equal(c[r].sink_dt, res.sink_dt == 1);
          *multi_seen += res.nsinks > 1;
          if (res.has_got) {
            uint64_t want = (uint64_t)llround(res.worst_gap / SITEFLIP_GAP_UNIT);
            if (c[r].gap_units != want)
              fail_msg("%s, %s %d/%llu: census gap %llu units, brute force %llu", rules[r].name,
                       sampler_sites_name(kind), n, (unsigned long long)i,
                       (unsigned long long)c[r].gap_units, (unsigned long long)want);
            *gaps_seen += want > 0;
          }
        }
        free(dec);
        siteflip_free(g);
      }
  free(c);
}

static void test_census_equals_direct(void **state) {
  (void)state;
  rule *rules;
  int nr = tc_all_rules(&rules), multi_seen = 0, gaps_seen = 0;
  tc_against_direct(rules, nr, RULE_DEFAULT_TIE_EPS, 8, &multi_seen, &gaps_seen);
  print_message("%d several-sink graphs, %d positive gaps compared\n", multi_seen, gaps_seen);
  assert_true(multi_seen > 100);
  assert_true(gaps_seen > 100);
  /* Coarse tolerances make near-ties common; 0 leaves exact equality. */
  const double eps[] = {0, 1e-4, 0.05};
  for (size_t e = 0; e < sizeof eps / sizeof eps[0]; e++)
    tc_against_direct(rules, nr, eps[e], 3, &multi_seen, &gaps_seen);
  free(rules);
}

/* Products and squares that under- or overflow, +inf and 0 values: the
** slots quadvec hands to joint_compare. */
static void test_census_extremes_equal_direct(void **state) {
  (void)state;
  rule *rules;
  int nr = tc_extreme_rules(&rules), multi_seen = 0, gaps_seen = 0;
  const double eps[] = {RULE_DEFAULT_TIE_EPS, 0, 1e-4};
  for (size_t e = 0; e < sizeof eps / sizeof eps[0]; e++)
    tc_against_direct(rules, nr, eps[e], 8, &multi_seen, &gaps_seen);
  print_message("%d several-sink graphs, %d positive gaps compared\n", multi_seen, gaps_seen);
  assert_true(multi_seen > 10);
  free(rules);
  measure_unregister_user();
}

/* The vector engine and the portable one count the same, for every sampler,
** tie tolerance, built-in and extreme measure (so the census CSVs are
** byte-identical), on packed graphs (n <= 7) and the others (n = 8). */
static void test_census_vector_equals_scalar(void **state) {
  (void)state;
  rule *b, *x;
  int nb = tc_all_rules(&b), nx = tc_extreme_rules(&x), nr = nb + nx;
  rule *rules = malloc((size_t)nr * sizeof *rules);
  memcpy(rules, b, (size_t)nb * sizeof *b);
  memcpy(rules + nb, x, (size_t)nx * sizeof *x);
  siteflip_counts *v = malloc((size_t)nr * sizeof *v), *s = malloc((size_t)nr * sizeof *s);
  const double eps[] = {RULE_DEFAULT_TIE_EPS, 0, 1e-4, 0.05};
  for (size_t e = 0; e < sizeof eps / sizeof eps[0]; e++)
    for (int kind = 0; kind < SAMPLER_SITES_COUNT; kind++)
      for (int n = 5; n <= 8; n++) {
        uint64_t count = n == 8 ? 20 : 150;
        flipgraph_use_portable(0);
        tc_census_eps(rules, nr, kind, n, 0, count, 2, eps[e], v);
        flipgraph_use_portable(1);
        tc_census_eps(rules, nr, kind, n, 0, count, 2, eps[e], s);
        flipgraph_use_portable(0);
        for (int r = 0; r < nr; r++)
          if (memcmp(&v[r], &s[r], sizeof v[r]) != 0)
            fail_msg("%s, %s %d sites, tie_eps %g: vector and scalar engines differ", rules[r].name,
                     sampler_sites_name(kind), n, eps[e]);
      }
  free(v);
  free(s);
  free(rules);
  free(b);
  free(x);
  measure_unregister_user();
}

static void test_census_pentagons_are_table34(void **state) {
  (void)state;
  rule *rules;
  int nr = tc_all_rules(&rules);
  siteflip_counts *c = malloc((size_t)nr * sizeof *c);
  flipgraph_counts *f = calloc((size_t)nr, sizeof *f);
  const uint64_t S = 20000;
  tc_census(rules, nr, SAMPLER_SITES_CONVEX, 5, 0, S, 2, c);
  assert_int_equal(flipgraph_tally(rules, nr, 3, 0, S, RULE_DEFAULT_TIE_EPS, 2, f, NULL, NULL), 0);
  uint64_t multi = 0;
  for (int r = 0; r < nr; r++) {
    assert_int_equal(c[r].samples, S);
    assert_int_equal(c[r].one_sink, f[r].type[FLIPGRAPH_I] + f[r].type[FLIPGRAPH_II]);
    assert_int_equal(c[r].multi_sink, f[r].type[FLIPGRAPH_III]);
    assert_int_equal(c[r].no_sink, f[r].type[FLIPGRAPH_IV]);
    assert_int_equal(c[r].tie, f[r].type[FLIPGRAPH_V]);
    /* table34's DT column also asks for type I; ours any single sink */
    assert_true(c[r].sink_dt >= f[r].dt);
    assert_true(c[r].max_sinks <= 2);
    multi += c[r].multi_sink;
  }
  assert_true(multi > 0);
  free(c);
  free(f);
  free(rules);
}

static void test_census_threads(void **state) {
  (void)state;
  rule *rules;
  int nr = tc_all_rules(&rules);
  siteflip_counts *a = malloc((size_t)nr * sizeof *a), *b = malloc((size_t)nr * sizeof *b);
  siteflip_counts *s = calloc((size_t)nr, sizeof *s);
  for (int kind = 0; kind < SAMPLER_SITES_COUNT; kind++) {
    tc_census(rules, nr, kind, 6, 0, 1500, 1, a);
    tc_census(rules, nr, kind, 6, 0, 1500, 3, b);
    assert_memory_equal(a, b, (size_t)nr * sizeof *a);
    /* two pieces add up to the whole */
    memset(s, 0, (size_t)nr * sizeof *s);
    tc_census(rules, nr, kind, 6, 0, 700, 2, b);
    for (int r = 0; r < nr; r++) s[r] = b[r];
    tc_census(rules, nr, kind, 6, 700, 800, 2, b);
    for (int r = 0; r < nr; r++) {
      assert_int_equal(s[r].tie + b[r].tie, a[r].tie);
      assert_int_equal(s[r].multi_sink + b[r].multi_sink, a[r].multi_sink);
      assert_int_equal(s[r].gap_units + b[r].gap_units, a[r].gap_units);
      assert_int_equal(s[r].sinks + b[r].sinks, a[r].sinks);
    }
  }
  free(a);
  free(b);
  free(s);
  free(rules);
}

/* The rules' order changes no rule's counts: the census gives each used
** measure a slot in measure order and copies runs of consecutive
** measures, so a reversed list, and a subset with gaps between its
** measures listed out of order, must count as the full list does.  And a
** census adds to what out already holds. */
static void test_census_rule_order(void **state) {
  (void)state;
  rule *rules;
  int nr = tc_all_rules(&rules);
  rule *perm = malloc((size_t)nr * sizeof *perm);
  int *from = malloc((size_t)nr * sizeof *from);
  siteflip_counts *a = malloc((size_t)nr * sizeof *a), *b = malloc((size_t)nr * sizeof *b);
  assert_true(nr % 37 != 0);
  for (int kind = 0; kind < SAMPLER_SITES_COUNT; kind++) {
    tc_census(rules, nr, kind, 6, 0, 400, 1, a);
    for (int variant = 0; variant < 2; variant++) {
      int np = 0;
      for (int r = 0; r < nr; r++) {
        /* reversed; or scrambled (nr is prime to 37), without the measures 1, 4, 7, ... */
        int k = variant == 0 ? nr - 1 - r : (int)((r * 37L) % nr);
        if (variant == 1 && rules[k].kind == RULE_TRIANGLE && rules[k].measure % 3 == 1) continue;
        from[np] = k;
        perm[np++] = rules[k];
      }
      assert_true(np > 5);
      tc_census(perm, np, kind, 6, 0, 400, 2, b);
      for (int i = 0; i < np; i++)
        assert_memory_equal(&b[i], &a[from[i]], sizeof *b);
    }
    /* Adding 400 more samples to a's counts gives the census of 800. */
    char err[256];
    assert_int_equal(siteflip_census(rules, nr, kind, 6, 3, 400, 400, RULE_DEFAULT_TIE_EPS, 1,
                                     0, a, NULL, NULL, NULL, err, sizeof err), 0);
    tc_census(rules, nr, kind, 6, 0, 800, 2, b);
    for (int r = 0; r < nr; r++) {
      assert_int_equal(a[r].samples, 800);
      assert_memory_equal(&a[r], &b[r], sizeof *a);
    }
  }
  free(a);
  free(b);
  free(from);
  free(perm);
  free(rules);
}

/* Sets of 13 and 14 sites (random 16-site sets often have millions of
** triangulations): the same counts for one thread and two, each
** set within the budget; a budget too small for them stops the census with
** the set named and *over. */
static void test_census_large_sets(void **state) {
  (void)state;
  rule rs[3];
  char err[4096];
  rs[0] = rule_delaunay();
  assert_int_equal(rule_parse("R_1", &rs[1], err, sizeof err), 0);
  assert_int_equal(rule_parse("P_inf", &rs[2], err, sizeof err), 0);
  for (int n = 13; n <= 14; n++) {
    siteflip_counts a[3], b[3];
    uint64_t count = 3;
    memset(a, 0, sizeof a);
    memset(b, 0, sizeof b);
    int over = -1;
    if (siteflip_census(rs, 3, SAMPLER_SITES_DISC, n, 5, 0, count, 1e-12, 1, 0, a, NULL, NULL,
                        &over, err, sizeof err) != 0)
      fail_msg("%d sites: %s", n, err);
    assert_int_equal(over, 0);
    assert_int_equal(siteflip_census(rs, 3, SAMPLER_SITES_DISC, n, 5, 0, count, 1e-12, 2, 0, b,
                                     NULL, NULL, NULL, err, sizeof err), 0);
    assert_memory_equal(a, b, sizeof a);
    assert_int_equal(a[0].samples, count);
    assert_int_equal(a[0].one_sink + a[0].tie, count);   /* DT: one sink */
  }
  siteflip_counts c[3] = {{0}};
  int over = 0;
  assert_int_not_equal(siteflip_census(rs, 3, SAMPLER_SITES_DISC, 14, 5, 0, 8, 1e-12, 2, 65536,
                                       c, NULL, NULL, &over, err, sizeof err), 0);
  assert_int_equal(over, 1);
  assert_non_null(strstr(err, "set #"));
  assert_non_null(strstr(err, "memory budget of 64 KiB"));
}

static void test_census_bad_args(void **state) {
  (void)state;
  rule r = rule_delaunay();
  siteflip_counts c = {0};
  char err[256];
  assert_int_not_equal(siteflip_census(&r, 1, 17, 6, 1, 0, 10, 1e-12, 1, 0, &c, NULL, NULL, NULL, err, sizeof err), 0);
  assert_non_null(strstr(err, "unknown sampler"));
  assert_int_not_equal(siteflip_census(&r, 1, SAMPLER_SITES_DISC, 17, 1, 0, 10, 1e-12, 1, 0, &c, NULL, NULL, NULL, err, sizeof err), 0);
  assert_non_null(strstr(err, "3 to 16"));
  assert_int_equal(c.samples, 0);
}

/* Shard k of n of total: [first, end), checked against the plain formula
** wherever (k-1) total and k total fit in 64 bits. */
static void tc_shard(uint64_t total, uint64_t k, uint64_t n, uint64_t *first, uint64_t *end) {
  uint64_t count;
  assert_int_equal(census_shard_range(total, k, n, first, &count), 0);
  *end = *first + count;
  assert_true(*first <= *end && *end <= total);
  if (total <= UINT64_MAX / n) {
    assert_int_equal(*first, (k - 1) * total / n);
    assert_int_equal(*end, k * total / n);
  }
}

/* census_shard_range: the shards 1/n .. n/n tile [0, total) in order, also
** where (k-1) total overflows 64 bits (all shards for small n, the seams at
** 1, n/3 and n-1 for large n); a bad k/n is refused. */
static void test_census_shard_range(void **state) {
  (void)state;
  static const uint64_t totals[] = {0, 1, 7, 1000, 999983, 1000000000000ull, UINT64_MAX};
  static const uint64_t ns[] = {1, 2, 3, 7, 1000, 1000000, 4294967296ull};
  for (size_t a = 0; a < sizeof totals / sizeof totals[0]; a++)
    for (size_t b = 0; b < sizeof ns / sizeof ns[0]; b++) {
      uint64_t total = totals[a], n = ns[b], f, e, f2, e2;
      tc_shard(total, 1, n, &f, &e);
      assert_int_equal(f, 0);
      tc_shard(total, n, n, &f, &e);
      assert_int_equal(e, total);
      const uint64_t seams[3] = {1, n / 3 > 0 ? n / 3 : 1, n > 1 ? n - 1 : 1};
      for (uint64_t i = 0, k = 1; n > 1000 ? i < 3 : k < n; i++, k++) {
        if (n > 1000) k = seams[i];
        tc_shard(total, k, n, &f, &e);
        tc_shard(total, k + 1, n, &f2, &e2);
        assert_int_equal(e, f2);
      }
    }
  uint64_t f, c;
  assert_int_equal(census_shard_range(10, 0, 3, &f, &c), -1);
  assert_int_equal(census_shard_range(10, 4, 3, &f, &c), -1);
  assert_int_equal(census_shard_range(10, 1, 0, &f, &c), -1);
  assert_int_equal(census_shard_range(10, 1, (1ull << 32) + 1, &f, &c), -1);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_census_equals_direct),
    cmocka_unit_test(test_census_extremes_equal_direct),
    cmocka_unit_test(test_census_vector_equals_scalar),
    cmocka_unit_test(test_census_pentagons_are_table34),
    cmocka_unit_test(test_census_threads),
    cmocka_unit_test(test_census_rule_order),
    cmocka_unit_test(test_census_large_sets),
    cmocka_unit_test(test_census_bad_args),
    cmocka_unit_test(test_census_shard_range),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
