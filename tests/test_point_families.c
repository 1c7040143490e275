/*
** test_point_families.c: the laws of the benchmark families of
** sampler_points (samplers/sampler.h): clustered, jittered, lines, dups.
**
** - every family is a function of (kind, seed, n): drawn twice, and on two
**   threads at once, the same bits; another seed, other points;
** - clustered: the centres are the stream's first uniforms (as stated);
**   every point lies within 8 sigma of a centre; around well-separated
**   centres the offsets have mean 0 and variance sigma^2, and the cluster
**   sizes are Binomial(n, 1 / K) (5 standard errors);
** - jittered: every point within J of its grid point; the offsets have mean
**   0 and second moment J^2 / 3 (5 standard errors);
** - lines: integer coordinates of magnitude at most 128 m; the points of
**   each line exactly collinear (exact orientation), distinct and in order
**   along it; no set of three or more points all on one line;
** - dups: the pool is the uniform family's first m points, bit for bit;
**   every other point is a copy of a pool point; exactly m distinct points;
**   the pool points repeated once, twice, three times in the shares of
**   1 + Poisson(3) (5 standard errors).
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom.h"
#include "sampler.h"
#include "splitmix.h"
#include "testutil.h"

static const sampler_points_kind tpf_kinds[] = {SAMPLER_CLUSTERED, SAMPLER_JITTERED,
                                                SAMPLER_LINES, SAMPLER_DUPS};
#define TPF_NKINDS (sizeof tpf_kinds / sizeof tpf_kinds[0])

static geom_point *tpf_draw(sampler_points_kind k, uint64_t seed, size_t n) {
  geom_point *p = malloc((n + 1) * sizeof *p);
  assert_non_null(p);
  sampler_points(k, seed, n, p);
  return p;
}

static void test_reproducible(void **state) {
  (void)state;
  const size_t n = 5000;
  for (size_t k = 0; k < TPF_NKINDS; k++) {
    geom_point *a = tpf_draw(tpf_kinds[k], 3, n), *b[2];
    assert_non_null(sampler_points_name(tpf_kinds[k]));
    assert_int_equal(sampler_points_find(sampler_points_name(tpf_kinds[k])), (int)tpf_kinds[k]);
#pragma omp parallel for num_threads(2)
    for (int t = 0; t < 2; t++) b[t] = tpf_draw(tpf_kinds[k], 3, n);
    for (int t = 0; t < 2; t++) {
      assert_memory_equal(a, b[t], n * sizeof *a);
      free(b[t]);
    }
    geom_point *c = tpf_draw(tpf_kinds[k], 4, n);
    assert_true(memcmp(a, c, n * sizeof *a) != 0);
    free(a);
    free(c);
  }
}

/* The index of the centre nearest to p, and its squared distance. */
static int tpf_nearest(const geom_point *c, int nc, geom_point p, double *d2) {
  int best = 0;
  *d2 = INFINITY;
  for (int k = 0; k < nc; k++) {
    double dx = p.x - c[k].x, dy = p.y - c[k].y;
    if (dx * dx + dy * dy < *d2) {
      *d2 = dx * dx + dy * dy;
      best = k;
    }
  }
  return best;
}

/* Whether centre k is at least 12 sigma from every other: then a point of
** another cluster comes as near to it as to its own only past 6 sigma. */
static int tpf_isolated(const geom_point *c, int nc, int k) {
  for (int j = 0; j < nc; j++)
    if (j != k && hypot(c[j].x - c[k].x, c[j].y - c[k].y) < 12 * SAMPLER_CLUSTER_SIGMA) return 0;
  return 1;
}

/* Offsets around isolated centres: mean 0 (sd sigma / sqrt N), variance
** sigma^2 (sd sigma^2 sqrt(2 / N)); cluster sizes Binomial(n, 1 / K). */
static void tpf_check_clusters(const geom_point *p, size_t n, const geom_point *c) {
  const int nc = SAMPLER_CLUSTER_COUNT;
  const double s = SAMPLER_CLUSTER_SIGMA;
  double sum = 0, sum2 = 0, count[SAMPLER_CLUSTER_COUNT] = {0};
  size_t used = 0;
  for (size_t i = 0; i < n; i++) {
    double d2;
    int k = tpf_nearest(c, nc, p[i], &d2);
    assert_true(d2 < 64 * s * s);   /* P(chi^2_2 > 64) = e^-32 */
    count[k]++;
    if (!tpf_isolated(c, nc, k)) continue;
    double o[2] = {p[i].x - c[k].x, p[i].y - c[k].y};
    for (int a = 0; a < 2; a++) sum += o[a], sum2 += o[a] * o[a];
    used += 2;
  }
  assert_true(used > n / 2);
  double m = sum / (double)used, v = sum2 / (double)used;
  assert_true(fabs(m) < 5 * s / sqrt((double)used));
  assert_true(fabs(v - s * s) < 5 * s * s * sqrt(2.0 / (double)used));
  double q = 1.0 / nc, sd = sqrt((double)n * q * (1 - q));
  for (int k = 0; k < nc; k++)
    if (tpf_isolated(c, nc, k)) assert_true(fabs(count[k] - (double)n * q) < 5 * sd);
}

static void test_clustered(void **state) {
  (void)state;
  const size_t n = 20000;
  for (uint64_t seed = 1; seed <= (uint64_t)testutil_reps(4); seed++) {
    geom_point *p = tpf_draw(SAMPLER_CLUSTERED, seed, n), c[SAMPLER_CLUSTER_COUNT];
    sampler_rng g;
    sampler_seed(&g, seed, GEOM_STREAM_POINTS);
    for (int k = 0; k < SAMPLER_CLUSTER_COUNT; k++) {
      c[k].x = sampler_uniform(&g);
      c[k].y = sampler_uniform(&g);
    }
    tpf_check_clusters(p, n, c);
    free(p);
  }
}

/* Offsets (exact: x and its grid value are within a factor 2, or the grid
** value is 0) within J; mean 0 (sd J / sqrt(3N)), second moment J^2 / 3
** (sd J^2 sqrt(4 / (45 N)): E u^4 - (E u^2)^2 = J^4 / 5 - J^4 / 9). */
static void test_jittered(void **state) {
  (void)state;
  const size_t n = 40000, side = 200;
  const double J = SAMPLER_JITTER;
  geom_point *p = tpf_draw(SAMPLER_JITTERED, 2, n);
  double sum = 0, sum2 = 0;
  for (size_t i = 0; i < n; i++) {
    double o[2] = {p[i].x - (double)(i % side), p[i].y - (double)(i / side)};
    for (int a = 0; a < 2; a++) {
      assert_true(fabs(o[a]) <= J);
      sum += o[a];
      sum2 += o[a] * o[a];
    }
  }
  double N = 2.0 * (double)n;
  assert_true(fabs(sum / N) < 5 * J / sqrt(3 * N));
  assert_true(fabs(sum2 / N - J * J / 3) < 5 * J * J * sqrt(4 / (45 * N)));
  free(p);
}

/* The points of line k (i = k, k + L, ...): integers, collinear with its
** first two, each step along the line in the same direction. */
static void tpf_check_line(const geom_point *p, size_t n, size_t k, double bound) {
  const size_t L = SAMPLER_LINE_COUNT;
  for (size_t i = k; i < n; i += L) {
    assert_true(p[i].x == floor(p[i].x) && p[i].y == floor(p[i].y));
    assert_true(fabs(p[i].x) <= bound && fabs(p[i].y) <= bound);
    if (i < k + 2 * L) continue;
    geom_point a = p[i - 2 * L], b = p[i - L];
    assert_int_equal(geom_orient(p[k], p[k + L], p[i]), 0);
    assert_true((b.x - a.x) * (p[i].x - b.x) + (b.y - a.y) * (p[i].y - b.y) > 0);
  }
}

/* Whether the points are all on one line (or all equal), exactly. */
static int tpf_flat(const geom_point *p, size_t n) {
  for (size_t j = 1; j < n; j++)
    if (p[j].x != p[0].x || p[j].y != p[0].y) {
      for (size_t i = j + 1; i < n; i++)
        if (geom_orient(p[0], p[j], p[i]) != 0) return 0;
      return 1;
    }
  return 1;
}

static void test_lines(void **state) {
  (void)state;
  static const size_t ns[] = {3, 4, 5, 8, 9, 17, 100, 10000};
  for (size_t s = 0; s < sizeof ns / sizeof *ns; s++)
    for (uint64_t seed = 1; seed <= 300; seed++) {
      size_t n = ns[s], m = (n + SAMPLER_LINE_COUNT - 1) / SAMPLER_LINE_COUNT;
      if (n > 100 && seed > 3) break;
      geom_point *p = tpf_draw(SAMPLER_LINES, seed, n);
      for (size_t k = 0; k < SAMPLER_LINE_COUNT && k < n; k++)
        tpf_check_line(p, n, k, 128.0 * (double)m);
      assert_false(tpf_flat(p, n));
      free(p);
    }
}

static int tpf_lexcmp(const void *a, const void *b) {
  const geom_point *p = a, *q = b;
  if (p->x != q->x) return p->x < q->x ? -1 : 1;
  return (p->y > q->y) - (p->y < q->y);
}

/* Multiplicities of the pool points: how many are repeated 1, 2, 3 times,
** against 1 + Poisson(3) (the binomial's limit; (1 - 1/m)^(n-m) differs
** from e^-3 by 1e-4 here), 5 binomial standard errors each. */
static void tpf_check_multiplicity(geom_point *p, size_t n, size_t m) {
  qsort(p, n, sizeof *p, tpf_lexcmp);
  size_t distinct = 0, times[4] = {0};
  for (size_t i = 0, j; i < n; i = j) {
    for (j = i; j < n && p[j].x == p[i].x && p[j].y == p[i].y;) j++;
    distinct++;
    if (j - i <= 3) times[j - i]++;
  }
  assert_int_equal(distinct, m);
  double lambda = (double)(n - m) / (double)m, pk = exp(-lambda);
  for (size_t r = 1; r <= 3; r++) {
    double sd = sqrt((double)m * pk * (1 - pk));
    assert_true(fabs((double)times[r] - (double)m * pk) < 5 * sd);
    pk *= lambda / (double)r;
  }
}

static void test_dups(void **state) {
  (void)state;
  const size_t n = 40000, m = n / SAMPLER_DUPS_SHARE;
  geom_point *p = tpf_draw(SAMPLER_DUPS, 5, n), *u = tpf_draw(SAMPLER_UNIFORM, 5, m);
  assert_memory_equal(p, u, m * sizeof *p);
  qsort(u, m, sizeof *u, tpf_lexcmp);
  for (size_t i = m; i < n; i++) assert_non_null(bsearch(&p[i], u, m, sizeof *u, tpf_lexcmp));
  tpf_check_multiplicity(p, n, m);
  free(u);
  free(p);
  /* Small sets keep three distinct points (a triangle, almost surely). */
  for (size_t k = 3; k < 13; k++) {
    geom_point *q = tpf_draw(SAMPLER_DUPS, 1, k);
    assert_true(geom_orient(q[0], q[1], q[2]) != 0);
    free(q);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_reproducible), cmocka_unit_test(test_clustered),
    cmocka_unit_test(test_jittered),     cmocka_unit_test(test_lines),
    cmocka_unit_test(test_dups),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
