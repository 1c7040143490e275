/*
** test_cpdt_hypothesis.c: chapter 5's hypothesis tested.  The closed forms
** of studies/triavg.h average over the C_n triangulations of the
** (n+2)-gon taken as equally likely; the `triangulation` sampler draws
** polygons whose Delaunay triangulation is uniform over them.  So:
**   - exactly, polygon by polygon (any sampler): the workbench's counts are
**     the closed forms' quantities of its own result: `circum`'s scans are
**     study_tri_measure's tc, the first (top) merge of `divide` adds its
**     cross count (the same cut), the reported L(D) is its len_sum / (N-3);
**   - statistically, on `triangulation` polygons started at a uniformly
**     random vertex: the means of those counts and of one vertex's
**     interior degree lie within 99.99% normal intervals (z = 3.891, from
**     the sample variance) of T_c, A, L_a and DEGREE, at (n+2) = 12, 20, 40
**     (fixed seed).  As the registry draws them (from the lexicographically
**     smallest vertex, a start that depends on the triangulation) the
**     labelled counts are biased: the degree of p_n at 12 vertices and T_c
**     at 40 lie far outside (asserted); L(D), which no labelling changes,
**     lies within;
**   - on the thesis's generated polygons (Valtr's uniform convex polygons in
**     the square) the same means are far from the closed forms, in the
**     direction the thesis found (docs/cpdt.md gives the ratios).
** T_i is not tested against its closed form: it assumes every prefix
** polygon's triangulation uniform, which a uniform triangulation of the
** whole polygon does not give (its prefixes' Delaunay triangulations are
** not uniform); what is exact about the flips is in test_cpdt.c.
*/
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "cpdt.h"
#include "sampler.h"
#include "splitmix.h"
#include "study_cpdt.h"
#include "testutil.h"
#include "triavg.h"

/* The quantities compared with a closed form, in this order. */
enum { TH_TC, TH_CROSS, TH_LA, TH_DEGREE, TH_COUNT };
static const int th_kind[TH_COUNT] = {STUDY_AVG_TC, STUDY_AVG_CROSS, STUDY_AVG_LA,
                                      STUDY_AVG_DEGREE};
static const char *const th_name[TH_COUNT] = {"Tc", "A", "L_a", "degree"};

/* Two-sided 99.99% normal quantile. */
#define TH_Z 3.891

/* The cross edges of the top merge of `divide` on p[0..n): its cross_sum
** less the cross sums of its two halves triangulated alone (the recursion
** below the top merge is theirs: halves by index, the same rule). */
static uint64_t th_top_cross(const geom_point *p, size_t n, uint32_t *tri) {
  size_t k = (n - 2) / 2;   /* the halves 0..k and k+1..n-1 */
  cpdt_counts c;
  assert_int_equal(cpdt_triangulate(p, n, CPDT_DIVIDE, 1, tri, &c), 0);
  uint64_t a = c.cross_sum;
  const size_t lo[2] = {0, k + 1}, len[2] = {k + 1, n - k - 1};
  for (int h = 0; h < 2; h++)
    if (len[h] >= 3) {
      assert_int_equal(cpdt_triangulate(p + lo[h], len[h], CPDT_DIVIDE, 1, tri, &c), 0);
      a -= c.cross_sum;
    }
  return a;
}

/* Reverse p[lo..hi); three of them start p at vertex r. */
static void th_reverse(geom_point *p, size_t lo, size_t hi) {
  for (; lo + 1 < hi; lo++, hi--) {
    geom_point t = p[lo];
    p[lo] = p[hi - 1];
    p[hi - 1] = t;
  }
}

/* Polygon `trial` of n vertices from sampler s (rotate: started at a vertex
** uniform from a stream of its own): its counts checked exactly against
** study_tri_measure of the workbench's own triangles, and the four
** quantities into x[]. */
static void th_polygon(int s, int rotate, uint64_t seed, size_t n, uint64_t trial,
                       geom_point *p, uint32_t *tri, uint32_t *deg, double x[TH_COUNT]) {
  assert_int_equal(study_cpdt_polygon(s, -1, 0, seed, n, trial, p), 0);
  if (rotate) {
    sampler_rng g;
    sampler_seed(&g, seed + 1, GEOM_STREAM_SAMPLE(trial));
    size_t r = (size_t)sampler_below(&g, n);
    th_reverse(p, 0, r), th_reverse(p, r, n), th_reverse(p, 0, n);
  }
  uint64_t cross = th_top_cross(p, n, tri);
  cpdt_counts c;
  assert_int_equal(cpdt_triangulate(p, n, CPDT_CIRCUM, 1, tri, &c), 0);
  study_tri_stats st;
  char err[200];
  if (study_tri_measure(tri, n - 2, (uint32_t)n, &st, deg, err, sizeof err) != 0)
    fail_msg("%s", err);
  if (c.scanned != st.tc || cross != st.cross)
    fail_msg("n %zu trial %llu: scanned %llu tc %llu, top cross %llu cross %llu", n,
             (unsigned long long)trial, (unsigned long long)c.scanned,
             (unsigned long long)st.tc, (unsigned long long)cross,
             (unsigned long long)st.cross);
  double la = n > 3 ? (double)st.len_sum / (double)(n - 3) : 0;
  TESTUTIL_NEAR(c.index_length, la, 1e-12, 0);
  x[TH_TC] = (double)st.tc, x[TH_CROSS] = (double)cross, x[TH_LA] = la;
  x[TH_DEGREE] = (double)deg[n - 2];   /* p_n of p_0 .. p_{n+1} */
}

/* Means and standard errors of the quantities over `trials` polygons. */
static void th_sample(int s, int rotate, uint64_t seed, size_t n, uint64_t trials,
                      double mean[TH_COUNT], double se[TH_COUNT]) {
  geom_point *p = malloc(n * sizeof *p);
  uint32_t *tri = malloc(3 * n * sizeof *tri), *deg = malloc(n * sizeof *deg);
  assert_true(p != NULL && tri != NULL && deg != NULL);
  double sum[TH_COUNT] = {0}, sq[TH_COUNT] = {0};
  for (uint64_t t = 0; t < trials; t++) {
    double x[TH_COUNT];
    th_polygon(s, rotate, seed, n, t, p, tri, deg, x);
    for (int k = 0; k < TH_COUNT; k++) sum[k] += x[k], sq[k] += x[k] * x[k];
  }
  for (int k = 0; k < TH_COUNT; k++) {
    mean[k] = sum[k] / (double)trials;
    double var = (sq[k] - (double)trials * mean[k] * mean[k]) / (double)(trials - 1);
    se[k] = sqrt(var > 0 ? var : 0) / sqrt((double)trials);
  }
  free(p);
  free(tri);
  free(deg);
}

/* The closed forms of the N-gon (n = N - 2), as doubles. */
static void th_closed(size_t N, double want[TH_COUNT]) {
  char err[200];
  study_avg *a = study_avg_new((int)N - 2, 0, err, sizeof err);
  if (a == NULL) fail_msg("%s", err);
  for (int k = 0; k < TH_COUNT; k++) want[k] = study_avg_double(a, th_kind[k], 0);
  study_avg_delete(a);
}

static int th_sampler(const char *name) {
  int s = study_cpdt_sampler_find(name);
  if (s < 0) fail_msg("no sampler %s in the registry", name);
  return s;
}

/* Exact, polygon by polygon, on several samplers and sizes. */
static void test_counts_are_the_closed_forms_quantities(void **state) {
  (void)state;
  static const char *const names[] = {"triangulation", "vector", "circle", "valtr"};
  for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
    for (size_t n = 3; n <= 41; n += 19) {
      double m[TH_COUNT], se[TH_COUNT];
      th_sample(th_sampler(names[i]), (int)(n % 2), 3, n, 40, m, se);
    }
}

static void th_within(size_t n, const double *m, const double *se, const double *want, int k,
                      int within) {
  double z = fabs(m[k] - want[k]) / se[k];
  if ((z <= TH_Z) != within)
    fail_msg("N = %zu, %s: mean %.6g, closed form %.6g, |z| = %.2f, expected %s %.3f", n,
             th_name[k], m[k], want[k], z, within ? "<=" : ">", TH_Z);
}

/* The hypothesis: on uniform triangulations the means are the closed forms. */
static void test_uniform_means_are_the_closed_forms(void **state) {
  (void)state;
  static const size_t sizes[] = {12, 20, 40};
  for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
    double m[TH_COUNT], se[TH_COUNT], want[TH_COUNT];
    th_closed(sizes[i], want);
    th_sample(th_sampler("triangulation"), 1, 1, sizes[i], 3000, m, se);
    for (int k = 0; k < TH_COUNT; k++) th_within(sizes[i], m, se, want, k, 1);
    th_sample(th_sampler("triangulation"), 0, 1, sizes[i], 3000, m, se);
    th_within(sizes[i], m, se, want, TH_LA, 1);
    if (sizes[i] == 12) th_within(sizes[i], m, se, want, TH_DEGREE, 0);
    if (sizes[i] == 40) th_within(sizes[i], m, se, want, TH_TC, 0);
  }
}

/* The thesis's finding: generated polygons are not uniform triangulations.
** Measured at seed 1 (docs/cpdt.md): T_c's mean over 1000 polygons of 40
** vertices is 1.07 T_c(38) on Valtr's polygons (9 standard errors above)
** and 1.16 T_c(38) on vector polygons; the other quantities are printed.
** Only T_c's direction is asserted, beyond the same 99.99% interval. */
static void test_generated_polygons_are_far(void **state) {
  (void)state;
  const size_t n = 40;
  static const char *const names[] = {"valtr", "vector"};
  double want[TH_COUNT];
  th_closed(n, want);
  for (size_t i = 0; i < 2; i++) {
    double m[TH_COUNT], se[TH_COUNT];
    th_sample(th_sampler(names[i]), 0, 1, n, 1000, m, se);
    for (int k = 0; k < TH_COUNT; k++)
      print_message("%s N = %zu %s: mean %.6g +- %.3g, closed form %.6g, ratio %.4f\n",
                    names[i], n, th_name[k], m[k], TH_Z * se[k], want[k], m[k] / want[k]);
    assert_true(m[TH_TC] - want[TH_TC] > TH_Z * se[TH_TC]);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_counts_are_the_closed_forms_quantities),
    cmocka_unit_test(test_uniform_means_are_the_closed_forms),
    cmocka_unit_test(test_generated_polygons_are_far),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
