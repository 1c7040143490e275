/*
** test_convex2_sampler.c: the chapter-6 convex n-gon samplers of
** samplers/tridt.c, bounce.c, dual.c and priorart.c.
**
** - every output is strictly convex, anticlockwise, from its lexicographically
**   smallest vertex (exact check), and the same (seed, stream) gives the
**   same bits while another stream does not;
** - triangulation: the drawn triangles are a triangulation of the output
**   (n - 2 anticlockwise triangles of distinct vertices, n - 3 distinct
**   diagonals) and its exact Delaunay triangulation by the definition (no
**   vertex on or inside any triangle's circumcircle, brute force over all
**   vertices); over 200 C_{n-2} draws at n = 5, 6, 7 every one of the 5, 14,
**   42 triangulations appears, with frequencies passing a chi-square test at
**   significance 1e-4 (fixed seed, so the verdict is reproducible), the
**   drawn labels read back from the output (the drawn vertex 0 is the one
**   at the origin);
** - bounce: both laws give strictly convex output after 2n events (and the
**   events do run to 2n from n = 50 on);
** - dual: the polar dual of the square and the regular hexagon by hand; Dual
**   Rejection's edges lie on lines within distance 1 of the origin, which is
**   strictly inside;
** - prior art: GeoBench leaves 1/e of the corners unmoved (within 0.01 over
**   10^5 corners); Roussille-Dufour's angles are refused where doubles
**   cannot hold them.
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
#include "testutil.h"

/* Strictly convex, anticlockwise, first vertex lexicographically smallest. */
static void tc2_check_canon(const geom_point *p, size_t n) {
  testutil_check_convex(p, n);
  for (size_t k = 1; k < n; k++) assert_true(geom_lexless(p[0], p[k]));
}

/* The diagonals of tri as a bit mask over vertex pairs (n <= 11), after
** checking it is a triangulation of the n-gon: n - 2 anticlockwise
** triangles whose n - 3 diagonals are distinct. */
static uint64_t tc2_diagonals(const uint32_t *tri, size_t n) {
  uint64_t mask = 0;
  int count = 0;
  for (size_t t = 0; t + 2 < n; t++)
    for (int c = 0; c < 3; c++) {
      uint32_t a = tri[3 * t + c], b = tri[3 * t + (c + 1) % 3];
      assert_true(a < n && b < n && a != b);
      uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
      if (hi - lo == 1 || (lo == 0 && hi == n - 1)) continue;   /* a side */
      uint64_t bit = 1ull << (hi * (hi - 1) / 2 + lo);   /* < 55 pairs */
      if (!(mask & bit)) count++;
      mask |= bit;
    }
  assert_int_equal(count, (int)n - 3);
  return mask;
}

/* The definition of the Delaunay triangulation, by brute force. */
static void tc2_check_delaunay(const geom_point *p, size_t n, const uint32_t *tri) {
  for (size_t t = 0; t + 2 < n; t++) {
    geom_point a = p[tri[3 * t]], b = p[tri[3 * t + 1]], c = p[tri[3 * t + 2]];
    assert_int_equal(geom_orient(a, b, c), 1);
    for (size_t v = 0; v < n; v++)
      if (v != tri[3 * t] && v != tri[3 * t + 1] && v != tri[3 * t + 2])
        assert_int_equal(geom_incircle(a, b, c, p[v]), -1);
  }
}

static void test_tridt_delaunay(void **state) {
  (void)state;
  static const size_t sizes[] = {3, 4, 5, 7, 10, 11, 40, 300};
  geom_point p[300];
  uint32_t tri[3 * 300];
  for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
    for (uint64_t i = 0; i < (sizes[s] < 100 ? 50u : 5u); i++) {
      sampler_rng g;
      sampler_seed(&g, 5, i);
      assert_int_equal(sampler_gon_tridt(&g, sizes[s], p, tri, NULL), 0);
      tc2_check_canon(p, sizes[s]);
      for (size_t t = 0; t + 2 < sizes[s]; t++) {
        geom_point a = p[tri[3 * t]], b = p[tri[3 * t + 1]], c = p[tri[3 * t + 2]];
        assert_int_equal(geom_orient(a, b, c), 1);
      }
      if (sizes[s] <= 11) (void)tc2_diagonals(tri, sizes[s]);
      tc2_check_delaunay(p, sizes[s], tri);
    }
  sampler_rng g;
  sampler_seed(&g, 5, 0);
  assert_int_equal(sampler_gon_tridt(&g, 2, p, tri, NULL), -1);
}

/* Chi-square upper quantiles at 1e-4 for 4, 13 and 41 degrees of freedom
** (scipy.stats.chi2.isf(1e-4, df)). */
static void test_tridt_uniform(void **state) {
  (void)state;
  static const size_t ns[] = {5, 6, 7};
  static const int catalan[] = {5, 14, 42};
  static const double crit[] = {23.5127, 40.8707, 83.4733};
  for (int c = 0; c < 3; c++) {
    uint64_t key[42];
    long cnt[42] = {0};
    int kinds = 0;
    long draws = 200L * catalan[c];
    for (long i = 0; i < draws; i++) {
      sampler_rng g;
      geom_point p[7];
      uint32_t tri[15];
      sampler_seed(&g, 11, (uint64_t)i);
      assert_int_equal(sampler_gon_tridt(&g, ns[c], p, tri, NULL), 0);
      /* Back to the drawn labels: the drawn vertex 0 is the one at the origin. */
      uint32_t r = 0;
      while (p[r].x != 0 || p[r].y != 0) r++;
      for (int v = 0; v < 3 * ((int)ns[c] - 2); v++)
        tri[v] = (tri[v] + (uint32_t)ns[c] - r) % (uint32_t)ns[c];
      uint64_t m = tc2_diagonals(tri, ns[c]);
      int k = 0;
      while (k < kinds && key[k] != m) k++;
      assert_true(k < catalan[c]);   /* never more kinds than triangulations */
      if (k == kinds) key[kinds++] = m;
      cnt[k]++;
    }
    assert_int_equal(kinds, catalan[c]);
    double e = (double)draws / catalan[c], x2 = 0;
    for (int k = 0; k < kinds; k++) x2 += (cnt[k] - e) * (cnt[k] - e) / e;
    print_message("n = %zu: chi-square %.2f on %d df (1e-4 critical %.2f)\n", ns[c], x2,
                  catalan[c] - 1, crit[c]);
    assert_true(x2 < crit[c]);
  }
}

typedef int (*tc2_fn)(sampler_rng *g, size_t n, const sampler_gon_params *p, geom_point *out,
                      sampler_gon_info *info);
typedef struct tc2_sampler {
  const char *name;
  tc2_fn fn;
  int law;
  const char *inner;
  size_t maxn;
} tc2_sampler;
static const tc2_sampler tc2_samplers[] = {
  {"triangulation", sampler_gon_triangulation, 0, NULL, 100000},
  {"bounce law 0", sampler_gon_bounce, 0, NULL, 100000},
  {"bounce law 1", sampler_gon_bounce, 1, NULL, 100000},
  {"dual of vector", sampler_gon_dual, 0, NULL, 100000},
  {"dual of triangulation", sampler_gon_dual, 0, "triangulation", 100000},
  {"dual of geobench", sampler_gon_dual, 0, "geobench", 1000},
  {"dual of bounce", sampler_gon_dual, 1, "bounce", 1000},
  {"geobench", sampler_gon_geobench, 0, NULL, 100000},
  {"angles", sampler_gon_angles, 0, NULL, 10},
  {"dual-rejection", sampler_gon_dualrej, 0, NULL, 6},
};
#define TC2_SAMPLERS (sizeof tc2_samplers / sizeof tc2_samplers[0])

static void test_convex_reproducible(void **state) {
  (void)state;
  static const size_t sizes[] = {3, 4, 5, 6, 10, 100, 1000, 100000};
  geom_point *a = malloc(100000 * sizeof *a), *b = malloc(100000 * sizeof *b);
  for (size_t f = 0; f < TC2_SAMPLERS; f++)
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
      size_t n = sizes[s];
      if (n > tc2_samplers[f].maxn) continue;
      sampler_gon_params prm = {SAMPLER_REGION_DISC, tc2_samplers[f].law,
                                tc2_samplers[f].inner};
      for (uint64_t i = 0; i < (n <= 1000 ? 10u : 1u); i++) {
        sampler_rng g1, g2;
        sampler_seed(&g1, 3, i);
        sampler_seed(&g2, 3, i);
        assert_int_equal(tc2_samplers[f].fn(&g1, n, &prm, a, NULL), 0);
        tc2_check_canon(a, n);
        assert_int_equal(tc2_samplers[f].fn(&g2, n, &prm, b, NULL), 0);
        assert_memory_equal(a, b, n * sizeof *a);
        sampler_seed(&g2, 3, i + 1000);
        if (n >= 100 && tc2_samplers[f].fn(&g2, n, &prm, b, NULL) == 0)
          assert_true(memcmp(a, b, n * sizeof *a) != 0);
      }
      sampler_rng g;
      sampler_seed(&g, 3, 0);
      assert_int_equal(tc2_samplers[f].fn(&g, 2, &prm, a, NULL), -1);
    }
  free(a);
  free(b);
}

/* Both bounce laws keep the polygon strictly convex over 2n events and
** more: the output passes the exact check, and the events run to 2n unless
** none is left (the polygon then only grows). */
static void test_bounce_events(void **state) {
  (void)state;
  static const size_t sizes[] = {3, 4, 5, 8, 50, 2000};
  static geom_point p[2000];
  for (int law = 0; law < 2; law++)
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
      uint64_t total = 0;
      for (uint64_t i = 0; i < 40; i++) {
        sampler_rng g;
        sampler_gon_info info;
        sampler_gon_params prm = {SAMPLER_REGION_DISC, law, NULL};
        sampler_seed(&g, 9, i);
        assert_int_equal(sampler_gon_bounce(&g, sizes[s], &prm, p, &info), 0);
        tc2_check_canon(p, sizes[s]);
        total += info.draws;
      }
      if (sizes[s] >= 50) assert_true(total >= 40 * 2 * (uint64_t)sizes[s]);
      sampler_gon_params bad = {SAMPLER_REGION_DISC, 2, NULL};
      sampler_rng g;
      sampler_seed(&g, 9, 0);
      assert_int_equal(sampler_gon_bounce(&g, sizes[s], &bad, p, NULL), -1);   /* no law 2 */
      print_message("law %d n %zu: %.1f events a polygon\n", law, sizes[s], (double)total / 40);
    }
}

/* The polar dual about the centre of a polygon symmetric about the origin:
** the square (+-1, +-1) has the diamond of (+-1, 0), (0, +-1) (edge x = 1 is
** the point (1, 0)); the regular hexagon of circumradius 2 has the hexagon
** of inradius 1/2 turned by 30 degrees, vertices at distance 1/sqrt(3). */
static void test_polar(void **state) {
  (void)state;
  const geom_point sq[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  geom_point d[6];
  assert_int_equal(sampler_gon_polar(sq, 4, d), 0);
  const geom_point want[4] = {{-1, 0}, {0, -1}, {1, 0}, {0, 1}};
  for (int k = 0; k < 4; k++) {
    assert_true(d[k].x == want[k].x && d[k].y == want[k].y);
  }
  geom_point hex[6];
  for (int k = 0; k < 6; k++)
    hex[k] = (geom_point){2 * cos(k * M_PI / 3), 2 * sin(k * M_PI / 3)};
  assert_int_equal(sampler_gon_polar(hex, 6, d), 0);
  tc2_check_canon(d, 6);
  for (int k = 0; k < 6; k++) TESTUTIL_NEAR(hypot(d[k].x, d[k].y), 1 / sqrt(3.0), 1e-14, 0);
  const geom_point cw[4] = {{-1, -1}, {-1, 1}, {1, 1}, {1, -1}};
  assert_int_equal(sampler_gon_polar(cw, 4, d), -1);   /* clockwise: centre not left of edges */
}

/* Dual Rejection's polygon is the intersection of half-planes x . u < r with
** r <= 1: every edge's line passes within distance 1 of the origin, which
** is strictly inside. */
static void test_dualrej(void **state) {
  (void)state;
  geom_point p[6];
  for (size_t n = 3; n <= 6; n++)
    for (uint64_t i = 0; i < 30; i++) {
      sampler_rng g;
      sampler_gon_info info;
      sampler_seed(&g, 2, i);
      assert_int_equal(sampler_gon_dualrej(&g, n, NULL, p, &info), 0);
      assert_true(info.draws >= n && info.draws % n == 0);
      for (size_t k = 0; k < n; k++) {
        geom_point a = p[k], b = p[(k + 1) % n];
        assert_int_equal(geom_orient(a, b, (geom_point){0, 0}), 1);
        double dist = (a.x * b.y - a.y * b.x) / hypot(b.x - a.x, b.y - a.y);
        assert_true(dist > 0 && dist <= 1 + 1e-12);
      }
    }
}

/* GeoBench: a corner never chosen keeps radius 1; the chance is (1 - 1/n)^n
** (0.36786 at n = 10^4, ~1/e).  Over 10 polygons of 10^4 corners the share's
** standard deviation is below 0.0016 (never-chosen counts are negatively
** correlated), so +-0.01 is over six of them.  An unmoved corner is (cos t,
** sin t), at distance 1 within 2 ulps; a moved one lands within 1e-15 of 1
** with chance about 1e-15 / 1e-7 (its range: the chord's sagitta at gaps
** of 2 pi / n), so the count is exact in practice.  Angles: refused (-1) where doubles
** cannot hold its ever smaller turns (n = 200). */
static void test_prior_art(void **state) {
  (void)state;
  enum { N = 10000, REPS = 10 };
  geom_point *p = malloc(N * sizeof *p);
  long unmoved = 0;
  for (uint64_t i = 0; i < REPS; i++) {
    sampler_rng g;
    sampler_seed(&g, 4, i);
    assert_int_equal(sampler_gon_geobench(&g, N, NULL, p, NULL), 0);
    for (size_t k = 0; k < N; k++) unmoved += fabs(hypot(p[k].x, p[k].y) - 1) < 1e-15;
  }
  double share = (double)unmoved / (N * REPS);
  print_message("geobench: %.4f of the corners unmoved (1/e = %.4f)\n", share, exp(-1.0));
  assert_true(fabs(share - exp(-1.0)) < 0.01);
  sampler_rng g;
  sampler_seed(&g, 4, 0);
  assert_int_equal(sampler_gon_angles(&g, 200, NULL, p, NULL), -1);
  free(p);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_tridt_delaunay),
    cmocka_unit_test(test_tridt_uniform),
    cmocka_unit_test(test_convex_reproducible),
    cmocka_unit_test(test_bounce_events),
    cmocka_unit_test(test_polar),
    cmocka_unit_test(test_dualrej),
    cmocka_unit_test(test_prior_art),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
