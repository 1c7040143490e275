/*
** test_convex.c: the random convex n-gons of chapter 6 (samplers/gon.c,
** samplers/gon_hull.c, samplers/valtr.c) and their statistics
** (studies/convex.c), against what is known of their laws:
**  - every sampler, region and size gives a strictly convex polygon,
**    anticlockwise from its lexicographically smallest vertex (exact);
**    the wrapped samplers are the old ones draw for draw;
**  - naive rejection keeps n points of the square, the triangle and the
**    disc at the exact rates of the literature (Valtr 1995, 1996; the disc:
**    Sylvester's 1 - 35/(12 pi^2), Marckert's 1 - 305/(48 pi^2)), and for
**    the disc at n = 5 it is the `disc-hull` pentagon sampler;
**  - weighted rejection has the law of naive rejection (n = 4, 5, 6, three
**    regions) and of Valtr's sampler (square, n = 10, 20): weighted means of
**    area and perimeter agree within their intervals, and a two-sample
**    z-test on P(area < t) does not reject;
**  - the iteration's O(h log n) path has the law of sampler_convex's loop,
**    and h >= n;
**  - statistics: hand-checked polygons; the same output for any threads.
** Each comparison is a two-sided test at level 1e-4 (|z| < 3.89); there are
** about 60 of them, so a correct sampler fails one with probability below
** 0.6%; the seeds are fixed, so the outcome is reproducible.
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

#include "sampler.h"
#include "study.h"
#include "testutil.h"

#define TC_Z 3.89   /* two-sided 1e-4 */
#define TC_PI 3.14159265358979323846

/* count polygons of a sampler; their statistics accumulated, and *draws
** (when not NULL) the points drawn in all. */
static void tc_run(const char *sampler, int region, int law, size_t n, uint64_t count,
                   uint64_t seed, double thresh, study_convex_acc *acc, uint64_t *draws) {
  const sampler_gon *s = sampler_gon_find(sampler);
  assert_non_null(s);
  sampler_gon_params p = {(sampler_region)region, law, NULL};
  geom_point *v = malloc(n * sizeof *v);
  study_convex_acc_init(acc);
  for (uint64_t i = 0; i < count; i++) {
    sampler_gon_info info;
    assert_int_equal(sampler_gon_draw(s, &p, seed, i, n, v, &info), 0);
    double st[STUDY_CONVEX_NSTATS];
    study_convex_measure(v, n, info.hull_changes, st);
    st[STUDY_CONVEX_UNIMODAL] = st[STUDY_CONVEX_AREA] < thresh;   /* the two-sample statistic */
    study_convex_acc_add(acc, info.log_weight, st);
    if (draws != NULL) *draws += info.draws;
  }
  free(v);
}

/* |mean_a - mean_b| within TC_Z combined standard errors, for statistic k. */
static void tc_agree(const study_convex_acc *a, const study_convex_acc *b, int k,
                     const char *what) {
  double ma, ha, mb, hb;
  study_convex_acc_mean(a, k, &ma, &ha);
  study_convex_acc_mean(b, k, &mb, &hb);
  double se = sqrt(ha * ha + hb * hb) / 1.96;
  if (!(fabs(ma - mb) <= TC_Z * se))
    fail_msg("%s, %s: %.6g against %.6g, z = %.2f", what, study_convex_stat_names[k], ma, mb,
             (ma - mb) / se);
}

static void tc_compare(const char *sa, const char *sb, int region, size_t n, uint64_t ca,
                       uint64_t cb, double thresh) {
  study_convex_acc a, b;
  char what[96];
  tc_run(sa, region, 0, n, ca, 11, thresh, &a, NULL);
  tc_run(sb, region, 0, n, cb, 12, thresh, &b, NULL);
  snprintf(what, sizeof what, "%s/%s, %s, n = %zu", sa, sb, sampler_region_name(region), n);
  tc_agree(&a, &b, STUDY_CONVEX_AREA, what);
  tc_agree(&a, &b, STUDY_CONVEX_PERIMETER, what);
  tc_agree(&a, &b, STUDY_CONVEX_UNIMODAL, what);   /* P(area < thresh) */
}

/* The median area of naive (or valtr) draws: the two-sample threshold. */
static double tc_median_area(const char *s, int region, size_t n) {
  enum { M = 2001 };
  double *a = malloc(M * sizeof *a);
  geom_point v[32];
  sampler_gon_params p = {(sampler_region)region, 0, NULL};
  for (int i = 0; i < M; i++) {
    sampler_gon_info info;
    assert_int_equal(sampler_gon_draw(sampler_gon_find(s), &p, 99, (uint64_t)i, n, v, &info), 0);
    double st[STUDY_CONVEX_NSTATS];
    study_convex_measure(v, n, 0, st);
    a[i] = st[STUDY_CONVEX_AREA];
  }
  for (int i = 1; i < M; i++)   /* insertion sort: small */
    for (int j = i; j > 0 && a[j] < a[j - 1]; j--) {
      double t = a[j];
      a[j] = a[j - 1];
      a[j - 1] = t;
    }
  double m = a[M / 2];
  free(a);
  return m;
}

static void test_rejection_naive(void **state) {
  (void)state;
  uint64_t c = (uint64_t)testutil_reps(20000);
  for (int r = 0; r < SAMPLER_REGION_COUNT; r++)
    for (size_t n = 4; n <= 6; n++)
      tc_compare("rejection", "naive", r, n, c, c, tc_median_area("naive", r, n));
}

static void test_rejection_valtr(void **state) {
  (void)state;
  uint64_t c = (uint64_t)testutil_reps(20000);
  tc_compare("rejection", "valtr", SAMPLER_REGION_SQUARE, 10, c, c,
             tc_median_area("valtr", SAMPLER_REGION_SQUARE, 10));
  /* At n = 20 the weights are very uneven (effective sample size about
  ** 1e-4 of the count): five times the polygons. */
  tc_compare("rejection", "valtr", SAMPLER_REGION_SQUARE, 20, 5 * c, c,
             tc_median_area("valtr", SAMPLER_REGION_SQUARE, 20));
}

/* Naive rejection's acceptance rate: polygons / attempts (draws / n),
** against the closed form p, with the negative binomial's standard error
** p sqrt((1 - p) / polygons). */
static void tc_rate(int region, size_t n, double p, const char *source) {
  study_convex_acc acc;
  uint64_t c = (uint64_t)testutil_reps(40000), draws = 0;
  tc_run("naive", region, 0, n, c, 5, 0, &acc, &draws);
  double rate = (double)c / ((double)draws / (double)n), se = p * sqrt((1 - p) / (double)c);
  if (!(fabs(rate - p) <= TC_Z * se))
    fail_msg("%s, n = %zu: rate %.5f, %s %.5f, z = %.2f", sampler_region_name(region), n, rate,
             source, p, (rate - p) / se);
}

static void test_naive_rates(void **state) {
  (void)state;
  /* Valtr: (C(2n-2, n-1) / n!)^2 in a parallelogram; 2^n (3n-3)! /
  ** ((n-1)!^3 (2n)!) in a triangle. */
  tc_rate(SAMPLER_REGION_SQUARE, 4, 25.0 / 36, "Valtr");
  tc_rate(SAMPLER_REGION_SQUARE, 5, 49.0 / 144, "Valtr");
  tc_rate(SAMPLER_REGION_TRIANGLE, 4, 2.0 / 3, "Valtr");
  tc_rate(SAMPLER_REGION_TRIANGLE, 5, 11.0 / 36, "Valtr");
  tc_rate(SAMPLER_REGION_DISC, 4, 1 - 35 / (12 * TC_PI * TC_PI), "Sylvester");
  tc_rate(SAMPLER_REGION_DISC, 5, 1 - 305 / (48 * TC_PI * TC_PI), "Marckert");
}

/* Naive rejection of five disc points is the disc-hull pentagon sampler,
** draw for draw: the rate above is that sampler's (35.62%, not 38%). */
static void test_dischull_is_naive(void **state) {
  (void)state;
  const sampler_pentagons *dh = sampler_pentagons_find("disc-hull");
  sampler_gon_params p = {SAMPLER_REGION_DISC, 0, NULL};
  for (uint64_t i = 0; i < 2000; i++) {
    geom_point a[5], b[5];
    sampler_gon_info info;
    assert_int_equal(dh->draw(7, i, a), 0);
    assert_int_equal(sampler_gon_draw(sampler_gon_find("naive"), &p, 7, i, 5, b, &info), 0);
    assert_memory_equal(a, b, sizeof a);
  }
}

/* Five polygons of s with parameters p: strictly convex, anticlockwise,
** lexicographically first vertex first (exact); or refused (-1) when the
** registry says s does not take them (region, nmax). */
static void tc_convex_five(const sampler_gon *s, const sampler_gon_params *p, size_t n,
                           geom_point *v) {
  int ok = (s->regions == 0 || (s->regions & (1u << p->region))) && (!s->nmax || n <= s->nmax);
  for (uint64_t i = 0; i < 5; i++) {
    sampler_gon_info info;
    int rc = sampler_gon_draw(s, p, 3, i, n, v, &info);
    if (!ok) {
      assert_int_equal(rc, -1);
      continue;
    }
    if (rc != 0) fail_msg("%s (law %d, inner %s), %s, n = %zu, polygon %llu: %d", s->name,
                          p->law, p->inner ? p->inner : "-", sampler_region_name(p->region), n,
                          (unsigned long long)i, rc);
    size_t bad;
    int rev;
    assert_int_equal(geom_polygon_check(v, n, &bad, &rev), GEOM_OK);
    assert_int_equal(rev, 0);
    for (size_t j = 1; j < n; j++) assert_true(geom_lexless(v[0], v[j]));
  }
}

/* Does doubles' reach stop s before n (measured, docs/sampling.md)?  The
** iteration in the square and triangle near 150, angles near 50. */
static int tc_beyond_doubles(const sampler_gon *s, int region, size_t n) {
  if (strcmp(s->name, "iteration") == 0) return region != SAMPLER_REGION_DISC && n > 40;
  return strcmp(s->name, "angles") == 0 && n > 40;
}

/* tc_convex_five for every row of the registry, each law it takes, each
** inner method of the dual, each region (the region-free samplers: one)
** and a range of n. */
static void test_all_convex(void **state) {
  (void)state;
  static const size_t ns[] = {3, 4, 7, 10, 16, 17, 40, 300};
  geom_point v[300];
  for (size_t k = 0; k < sampler_gons_count; k++)
    for (size_t m = 0; m < (sampler_gons[k].inner ? sampler_gons_count : 1); m++) {
      const sampler_gon *s = &sampler_gons[k], *t = s;
      sampler_gon_params p = {SAMPLER_REGION_SQUARE, 0, NULL};
      if (s->inner && (t = sampler_gon_inner(sampler_gons[m].name)) == NULL) continue;
      if (s->inner) p.inner = t->name;
      for (p.law = 0; p.law < t->laws; p.law++)
        for (int r = 0; r < (s->regions ? SAMPLER_REGION_COUNT : 1); r++)
          for (size_t j = 0; j < sizeof ns / sizeof ns[0]; j++) {
            p.region = (sampler_region)r;
            if (!tc_beyond_doubles(t, r, ns[j]) && (!t->nmax || ns[j] <= t->nmax))
              tc_convex_five(s, &p, ns[j], v);
          }
    }
}

/* The registry's limits are refused, not attempted. */
static void test_registry_limits(void **state) {
  (void)state;
  char err[256];
  geom_point v[16];
  sampler_gon_info info;
  sampler_gon_params p = {SAMPLER_REGION_SQUARE, 0, NULL};
  for (size_t k = 0; k < sampler_gons_count; k++) {
    const sampler_gon *s = &sampler_gons[k];
    if (s->nmax != 0) {
      assert_int_equal(sampler_gon_check(s->name, -1, s->nmax + 1, err, sizeof err), -1);
      assert_int_equal(sampler_gon_draw(s, &p, 1, 0, s->nmax + 1, v, &info), -1);
    }
    assert_int_equal(sampler_gon_check_variant(s->name, s->laws, NULL, 5, err, sizeof err), -1);
    assert_int_equal(sampler_gon_check_variant(s->name, 0, "vector", 5, err, sizeof err),
                     s->inner ? 0 : -1);
  }
  assert_int_equal(sampler_gon_check_variant("dual", 0, "dual", 5, err, sizeof err), -1);
  assert_int_equal(sampler_gon_check_variant("dual", 0, "rejection", 5, err, sizeof err), -1);
  assert_int_equal(sampler_gon_check_variant("dual", 1, "bounce", 5, err, sizeof err), 0);
  assert_int_equal(sampler_gon_check_variant("dual", 0, "dual-rejection", 11, err, sizeof err),
                   -1);
}

/* The wrapped samplers are the old ones, draw for draw. */
static void test_wrapped(void **state) {
  (void)state;
  sampler_gon_params p = {SAMPLER_REGION_DISC, 0, NULL};
  for (int n = 3; n < SAMPLER_HULL_MAX; n++)
    for (uint64_t i = 0; i < 50; i++) {
      geom_point a[SAMPLER_HULL_MAX], b[SAMPLER_HULL_MAX];
      sampler_gon_info info;
      sampler_convex(4, i, n, a);
      assert_int_equal(sampler_gon_draw(sampler_gon_find("iteration"), &p, 4, i, (size_t)n, b,
                                        &info), 0);
      assert_memory_equal(a, b, (size_t)n * sizeof *a);
      assert_true(info.hull_changes >= (uint64_t)n);
    }
  for (uint64_t i = 0; i < 50; i++) {
    geom_point a[64], b[64];
    sampler_rng g;
    sampler_gon_info info;
    sampler_seed(&g, 4, GEOM_STREAM_SAMPLE(i));
    assert_int_equal(sampler_vector(&g, 64, a), 0);
    assert_int_equal(sampler_gon_draw(sampler_gon_find("vector"), &p, 4, i, 64, b, &info), 0);
    size_t s = 0;   /* b is a rotated to its lexicographically smallest vertex */
    for (size_t k = 1; k < 64; k++)
      if (geom_lexless(a[k], a[s])) s = k;
    for (size_t k = 0; k < 64; k++) assert_memory_equal(&a[(s + k) % 64], &b[k], sizeof *a);
  }
}

/* The exterior-region path (law 1) against sampler_convex's loop on the
** disc: mean area, perimeter and h agree; h >= n always. */
static void test_iteration_paths(void **state) {
  (void)state;
  uint64_t c = (uint64_t)testutil_reps(20000);
  for (size_t n = 5; n <= 12; n += 7) {
    study_convex_acc a, b;
    tc_run("iteration", SAMPLER_REGION_DISC, 0, n, c, 21, 0, &a, NULL);
    tc_run("iteration", SAMPLER_REGION_DISC, 1, n, c, 22, 0, &b, NULL);
    tc_agree(&a, &b, STUDY_CONVEX_AREA, "iteration paths");
    tc_agree(&a, &b, STUDY_CONVEX_PERIMETER, "iteration paths");
    tc_agree(&a, &b, STUDY_CONVEX_H, "iteration paths");
  }
}

/* Hand-checked statistics: the unit square (area 1, perimeter 4, unimodal,
** one rectangle), and a convex hexagon whose distances from (0, 0) rise,
** fall and rise again (not unimodal). */
static void test_stats_hand(void **state) {
  (void)state;
  geom_point sq[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  geom_point hx[6] = {{0, 0}, {10, -1}, {11, 0}, {10, 1}, {2, 8}, {0, 9}};
  double st[STUDY_CONVEX_NSTATS];
  study_convex_measure(sq, 4, 7, st);
  assert_true(st[STUDY_CONVEX_AREA] == 1 && st[STUDY_CONVEX_PERIMETER] == 4);
  assert_true(st[STUDY_CONVEX_H] == 7 && st[STUDY_CONVEX_UNIMODAL] == 1);
  assert_true(st[STUDY_CONVEX_RECT_DIFFER] == 0);
  study_convex_measure(hx, 6, 0, st);
  assert_true(st[STUDY_CONVEX_UNIMODAL] == 0);
}

/* The enclosing rectangles by brute force: for each edge, every vertex
** projected (O(n^2)); differ when no edge is optimal for both. */
static int tc_rect_differ(const geom_point *v, size_t n) {
  double ra[64], rp[64], ma = INFINITY, mp = INFINITY;
  for (size_t e = 0; e < n; e++) {
    geom_point a = v[e], b = v[(e + 1) % n];
    double ux = b.x - a.x, uy = b.y - a.y, l = hypot(ux, uy), lo = 0, hi = 0, far = 0;
    for (size_t j = 0; j < n; j++) {
      double d = (ux * (v[j].x - a.x) + uy * (v[j].y - a.y)) / l;
      double c = (ux * (v[j].y - a.y) - uy * (v[j].x - a.x)) / l;
      lo = d < lo ? d : lo;
      hi = d > hi ? d : hi;
      far = c > far ? c : far;
    }
    ra[e] = (hi - lo) * far;
    rp[e] = 2 * (hi - lo + far);
    ma = ra[e] < ma ? ra[e] : ma;
    mp = rp[e] < mp ? rp[e] : mp;
  }
  for (size_t e = 0; e < n; e++)
    if (ra[e] <= ma * (1 + 1e-9) && rp[e] <= mp * (1 + 1e-9)) return 0;
  return 1;
}

static void test_rect_oracle(void **state) {
  (void)state;
  sampler_gon_params p = {SAMPLER_REGION_SQUARE, 0, NULL};
  int differ = 0;
  for (uint64_t i = 0; i < 3000; i++) {
    geom_point v[64];
    sampler_gon_info info;
    size_t n = 3 + (size_t)(i % 30);
    assert_int_equal(sampler_gon_draw(sampler_gon_find("valtr"), &p, 8, i, n, v, &info), 0);
    double st[STUDY_CONVEX_NSTATS];
    study_convex_measure(v, n, 0, st);
    assert_true(st[STUDY_CONVEX_RECT_DIFFER] == tc_rect_differ(v, n));
    differ += st[STUDY_CONVEX_RECT_DIFFER] == 1;
  }
  assert_true(differ > 0 && differ < 3000);   /* both outcomes occur */
}

/* The same polygons, weights, h and statistics for 1 and 2 threads. */
static void test_threads(void **state) {
  (void)state;
  enum { C = 64, N = 30 };
  static geom_point xy[2][C * N];
  static double lw[2][C], st[2][C * STUDY_CONVEX_NSTATS];
  static uint64_t h[2][C];
  for (size_t s = 0; s < sampler_gons_count; s++)
    for (int t = 0; t < 2; t++) {
      size_t n = sampler_gons[s].nmax ? 6 : N;   /* 6: a few hundred draws a polygon */
      study_convex_run run = {sampler_gons[s].name, SAMPLER_REGION_SQUARE, 0, t + 1, n, 9,
                              NULL};
      uint64_t failed;
      assert_int_equal(study_convex_draw(&run, 100, C, xy[t], lw[t], h[t], st[t], &failed), 0);
      if (t == 1) {
        assert_memory_equal(xy[0], xy[1], sizeof xy[0]);
        assert_memory_equal(lw[0], lw[1], sizeof lw[0]);
        assert_memory_equal(h[0], h[1], sizeof h[0]);
        assert_memory_equal(st[0], st[1], sizeof st[0]);
      }
    }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_all_convex),
    cmocka_unit_test(test_registry_limits),
    cmocka_unit_test(test_wrapped),
    cmocka_unit_test(test_dischull_is_naive),
    cmocka_unit_test(test_naive_rates),
    cmocka_unit_test(test_rejection_naive),
    cmocka_unit_test(test_rejection_valtr),
    cmocka_unit_test(test_iteration_paths),
    cmocka_unit_test(test_stats_hand),
    cmocka_unit_test(test_rect_oracle),
    cmocka_unit_test(test_threads),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
