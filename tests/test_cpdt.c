/*
** test_cpdt.c: the convex-polygon Delaunay workbench (cpdt/) against the
** library's general Delaunay triangulation (lot, rule DT) and chapter 5's
** theorems: every algorithm gives exactly lot's triangles on random convex
** polygons (vector, circle), regular polygons and integer points on one
** circle (every four cocircular: lot's tie-break throughout); the
** circumcircle algorithm scans sum (k - i - 1) vertices of its result; the
** incremental algorithm in input order flips each vertex in as often as
** its interior degree in D_i; each merge of divide and conquer makes a
** additions and a - 1 deletions; the counts repeat with the seed.
*/
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "cpdt.h"
#include "lot.h"
#include "rule.h"
#include "sampler.h"
#include "testutil.h"

/* lot's DT of p, in cpdt's layout (each triangle sorted, at its middle). */
static uint32_t *tc_lot(const geom_point *p, size_t n) {
  rule r;
  char err[256];
  if (rule_parse("DT", &r, err, sizeof err) != 0) fail_msg("%s", err);
  lot_options o;
  lot_options_init(&o, &r);
  lot *L;
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) fail_msg("lot_build: %s", err);
  size_t nt = lot_get_stats(L)->triangles;
  assert_int_equal(nt, n - 2);
  uint32_t *raw = malloc(3 * nt * sizeof *raw), *out = malloc(3 * nt * sizeof *out);
  assert_non_null(raw);
  assert_non_null(out);
  lot_get_triangles(L, raw);
  lot_free(L);
  for (size_t t = 0; t < nt; t++) {
    uint32_t v[3] = {raw[3 * t], raw[3 * t + 1], raw[3 * t + 2]};
    for (int a = 0; a < 2; a++)
      for (int b = 0; b < 2 - a; b++)
        if (v[b] > v[b + 1]) { uint32_t s = v[b]; v[b] = v[b + 1]; v[b + 1] = s; }
    assert_true(v[1] >= 1 && v[1] <= n - 2);
    memcpy(out + 3 * (v[1] - 1), v, sizeof v);
  }
  free(raw);
  return out;
}

/* Every algorithm on p: the same triangles as lot's; the theorems. */
static void tc_all_flips(const geom_point *p, size_t n, uint64_t seed,
                         uint64_t *corner_flips) {
  assert_int_equal(cpdt_check(p, n, NULL), 0);
  uint32_t *want = tc_lot(p, n), *got = malloc(3 * (n - 2) * sizeof *got);
  assert_non_null(got);
  for (int a = 0; a < CPDT_ALGORITHM_COUNT; a++) {
    if (a == CPDT_CIRCUM_WALK && n > 600) continue;   /* Theta(n^2) */
    cpdt_counts c;
    memset(got, 0xff, 3 * (n - 2) * sizeof *got);
    assert_int_equal(cpdt_triangulate(p, n, a, seed, got, &c), 0);
    if (memcmp(got, want, 3 * (n - 2) * sizeof *got) != 0)
      fail_msg("%s differs from lot's DT (n = %zu, seed %llu)", cpdt_algorithm_name(a), n,
               (unsigned long long)seed);
    if (a == CPDT_CIRCUM) assert_int_equal(c.scanned, cpdt_circum_cost(want, n));
    if (a == CPDT_CORNERS) *corner_flips = c.flips;
    if (a == CPDT_CIRCUM_WALK) assert_true(c.scanned >= cpdt_circum_cost(want, n));
    if (a == CPDT_DIVIDE && n > 3) {
      assert_int_equal(c.added, c.cross_sum);
      assert_int_equal(c.added + c.deleted, 2 * c.cross_sum - c.merges);
      assert_true(c.cross_max <= c.cross_sum);
    }
    assert_true(fabs(c.index_length - cpdt_index_length(want, n)) == 0);
  }
  free(want);
  free(got);
}

static void tc_all(const geom_point *p, size_t n, uint64_t seed) {
  uint64_t f;
  tc_all_flips(p, n, seed, &f);
}

static geom_point *tc_vector(uint64_t seed, size_t n, int circle) {
  geom_point *p = malloc(n * sizeof *p);
  assert_non_null(p);
  sampler_rng g;
  sampler_seed(&g, seed, 77);
  int rc = circle ? sampler_circle(&g, n, p) : sampler_vector(&g, n, p);
  assert_int_equal(rc, 0);
  return p;
}

/* Points on a circle are nearly cocircular: most of their incircle tests
** take the exact stages, so they stop at 257 vertices.  On the vector
** polygons corner cutting, smallest circle first, needs no repair. */
static void test_random_polygons(void **state) {
  (void)state;
  static const size_t sizes[] = {3, 4, 5, 6, 7, 8, 10, 13, 20, 31, 64, 100, 257, 1000, 3000};
  for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
    int seeds = sizes[s] < 100 ? 40 : sizes[s] < 1000 ? 6 : 1;
    for (int k = 0; k < seeds; k++)
      for (int circle = 0; circle < (sizes[s] <= 257 ? 2 : 1); circle++) {
        geom_point *p = tc_vector(1000 * s + (uint64_t)k, sizes[s], circle);
        uint64_t repairs;
        tc_all_flips(p, sizes[s], (uint64_t)k, &repairs);
        if (!circle && repairs != 0)
          fail_msg("corners repaired %llu edges (n = %zu, k = %d)", (unsigned long long)repairs,
                   sizes[s], k);
        free(p);
      }
  }
}

/* Regular polygons from cos and sin: nearly cocircular, and for n divisible
** by 4 four vertices exactly so (the axes). */
static void test_regular(void **state) {
  (void)state;
  for (size_t n = 3; n <= 200; n += (n < 40 ? 1 : 37)) {
    geom_point *p = malloc(n * sizeof *p);
    assert_non_null(p);
    for (size_t i = 0; i < n; i++) {
      double t = 2 * M_PI * (double)i / (double)n;
      p[i] = (geom_point){cos(t), sin(t)};
    }
    if (n % 4 == 0)
      for (size_t i = 0; i < n; i += n / 4) p[i] = (geom_point){i == n / 2 ? -1 : i == 0,
                                                              i == n / 4 ? 1 : -(i > n / 2)};
    tc_all(p, n, n);
    free(p);
  }
  geom_point sq[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  tc_all(sq, 4, 1);
}

static int tc_angle_cmp(const void *x, const void *y) {
  const geom_point *a = x, *b = y;
  double s = atan2(a->y, a->x), t = atan2(b->y, b->x);
  return s < t ? -1 : s > t;
}

/* Every integer point of x^2 + y^2 = R^2 (R = 1105 = 5 13 17: 108 points),
** anticlockwise, and random subsets of them: every four exactly cocircular. */
static void test_pythagorean(void **state) {
  (void)state;
  const long R = 1105;
  geom_point *all = malloc(512 * sizeof *all);
  assert_non_null(all);
  size_t m = 0;
  for (long x = -R; x <= R; x++) {
    long y = (long)llround(sqrt((double)(R * R - x * x)));
    if (y * y + x * x != R * R) continue;
    all[m++] = (geom_point){(double)x, (double)y};
    if (y != 0) all[m++] = (geom_point){(double)x, (double)-y};
  }
  assert_int_equal(m, 108);
  qsort(all, m, sizeof *all, tc_angle_cmp);
  tc_all(all, m, 1);
  testutil_rng g = {12345};
  geom_point *sub = malloc(m * sizeof *sub);
  assert_non_null(sub);
  for (int trial = 0; trial < 200; trial++) {
    size_t k = 0;
    double keep = 0.1 + 0.8 * testutil_uniform(&g);
    for (size_t i = 0; i < m; i++)
      if (testutil_uniform(&g) < keep) sub[k++] = all[i];
    if (k >= 3) tc_all(sub, k, (uint64_t)trial);
  }
  free(sub);
  free(all);
}

/* Interior degree of vertex v in a triangulation of n vertices (layout of
** cpdt.h): the triangles at v less one. */
static size_t tc_degree(const uint32_t *tri, size_t n, uint32_t v) {
  size_t d = 0;
  for (size_t t = 0; t + 2 < n; t++)
    d += tri[3 * t] == v || tri[3 * t + 1] == v || tri[3 * t + 2] == v;
  return d - 1;
}

/* 5.4.3: adding p_i to D_{i-1} takes as many flips as p_i's interior degree
** in D_i, so the flips are the sum of those degrees. */
static void test_incremental_degrees(void **state) {
  (void)state;
  for (uint64_t seed = 1; seed <= 30; seed++) {
    size_t n = 3 + (size_t)(seed * 7 % 120);
    geom_point *p = tc_vector(seed, n, seed % 2 == 0);
    uint32_t *tri = malloc(3 * n * sizeof *tri);
    assert_non_null(tri);
    uint64_t want = 0;
    for (size_t i = 3; i < n; i++) {
      assert_int_equal(cpdt_triangulate(p, i + 1, CPDT_DIVIDE, 0, tri, NULL), 0);
      want += tc_degree(tri, i + 1, (uint32_t)i);
    }
    cpdt_counts c;
    assert_int_equal(cpdt_triangulate(p, n, CPDT_INCREMENTAL, 0, tri, &c), 0);
    assert_int_equal(c.flips, want);
    free(tri);
    free(p);
  }
}

/* Same seed, same counts; the randomised algorithms linear in expectation:
** Chew's flips below 4n (the expected degree of a random vertex is below 4),
** checked on polygons whose input-order flips are quadratic-ish. */
static void test_counts_repeat(void **state) {
  (void)state;
  size_t n = 4000;
  geom_point *p = tc_vector(99, n, 0);
  uint32_t *tri = malloc(3 * n * sizeof *tri);
  assert_non_null(tri);
  for (int a = 0; a < CPDT_ALGORITHM_COUNT; a++) {
    if (a == CPDT_CIRCUM_WALK) continue;
    cpdt_counts c1, c2;
    assert_int_equal(cpdt_triangulate(p, n, a, 7, tri, &c1), 0);
    assert_int_equal(cpdt_triangulate(p, n, a, 7, tri, &c2), 0);
    assert_memory_equal(&c1, &c2, sizeof c1);
    if (a == CPDT_RANDOM) assert_true(c1.flips < 4 * n);
  }
  free(tri);
  free(p);
}

static void test_bad_input(void **state) {
  (void)state;
  geom_point sq[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  geom_point cw[4] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  geom_point dent[5] = {{0, 0}, {2, 0}, {2, 2}, {1, 0.5}, {0, 2}};
  geom_point dup[4] = {{0, 0}, {1, 0}, {1, 0}, {0, 1}};
  size_t bad;
  assert_int_equal(cpdt_check(sq, 4, &bad), 0);
  assert_int_equal(cpdt_check(cw, 4, &bad), CPDT_CLOCKWISE);
  assert_int_equal(cpdt_check(dent, 5, &bad), GEOM_NOT_CONVEX);
  assert_int_equal(cpdt_check(dup, 4, &bad), GEOM_DUPLICATE);
  assert_int_equal(cpdt_check(sq, 2, &bad), GEOM_TOO_FEW);
  for (int e = 1; e <= CPDT_TOO_MANY; e += (e < 8 ? 1 : 92)) assert_non_null(cpdt_check_str(e));
  uint32_t tri[6];
  assert_int_equal(cpdt_triangulate(sq, 4, CPDT_ALGORITHM_COUNT, 0, tri, NULL), -1);
  assert_int_equal(cpdt_triangulate(sq, 2, CPDT_CIRCUM, 0, tri, NULL), -1);
  for (int a = 0; a < CPDT_ALGORITHM_COUNT; a++)
    assert_int_equal(cpdt_algorithm_find(cpdt_algorithm_name(a)), a);
  assert_int_equal(cpdt_algorithm_find("circumcircle"), -1);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_random_polygons), cmocka_unit_test(test_regular),
    cmocka_unit_test(test_pythagorean),     cmocka_unit_test(test_incremental_degrees),
    cmocka_unit_test(test_counts_repeat),   cmocka_unit_test(test_bad_input),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
