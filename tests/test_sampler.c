/*
** test_sampler.c: the generator streams and the iteration sampler.
**
** - sample i depends only on (seed, i): generated forwards, backwards and
**   on two threads it is the same, bit for bit; different seeds or indices
**   give different pentagons;
** - every pentagon is strictly convex, anticlockwise, inside the unit disc,
**   starts at its lexicographically smallest vertex;
** - it IS the iteration method: replaying the same stream of disc points
**   and recomputing the hull from scratch (monotone chain, exact orient)
**   after every draw, the first hull with five vertices is the sample;
** - the incremental hull on degenerate input (duplicates, collinear points,
**   points on an edge, points extending an edge);
** - uniform and normal deviates have the right first two moments.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>

#include "geom.h"
#include "sampler.h"
#include "testutil.h"

/* Exposed by pentagon.c for this test only. */
int sampler_hull_add(geom_point *h, int n, geom_point p);

#define TS_N 20000

static int ts_same(const geom_point *a, const geom_point *b, int n) {
  for (int i = 0; i < n; i++)
    if (memcmp(&a[i].x, &b[i].x, sizeof(double)) != 0 || memcmp(&a[i].y, &b[i].y, sizeof(double)) != 0)
      return 0;
  return 1;
}

static void test_determinism(void **state) {
  (void)state;
  geom_point *fw = malloc(TS_N * 5 * sizeof *fw), *bw = malloc(TS_N * 5 * sizeof *bw),
             *par = malloc(TS_N * 5 * sizeof *par);
  assert_non_null(fw);
  assert_non_null(bw);
  assert_non_null(par);
  for (int i = 0; i < TS_N; i++) sampler_pentagon(42, (uint64_t)i, fw + 5 * i);
  for (int i = TS_N - 1; i >= 0; i--) sampler_pentagon(42, (uint64_t)i, bw + 5 * i);
#pragma omp parallel for num_threads(2) schedule(dynamic, 7)
  for (int i = 0; i < TS_N; i++) sampler_pentagon(42, (uint64_t)i, par + 5 * i);
  assert_true(ts_same(fw, bw, 5 * TS_N));
  assert_true(ts_same(fw, par, 5 * TS_N));
  /* Neighbouring indices and seeds differ. */
  geom_point a[5], b[5];
  for (int i = 0; i < 1000; i++) {
    sampler_pentagon(42, (uint64_t)i, a);
    sampler_pentagon(43, (uint64_t)i, b);
    assert_false(ts_same(a, b, 5));
    assert_false(ts_same(a, fw + 5 * (i + 1), 5));
  }
  /* Streams of the raw generator too. */
  sampler_rng g1, g2;
  sampler_seed(&g1, 1, 0);
  sampler_seed(&g2, 1, 0);
  for (int i = 0; i < 100; i++) assert_true(sampler_next(&g1) == sampler_next(&g2));
  sampler_seed(&g2, 1, 1);
  int same = 0;
  for (int i = 0; i < 100; i++) same += sampler_next(&g1) == sampler_next(&g2);
  assert_int_equal(same, 0);
  free(fw);
  free(bw);
  free(par);
}

static int ts_lexless(geom_point a, geom_point b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

static void test_convex_anticlockwise(void **state) {
  (void)state;
  for (uint64_t i = 0; i < TS_N; i++) {
    geom_point v[5];
    sampler_pentagon(5, i, v);
    for (int k = 0; k < 5; k++) {
      assert_true(geom_orient(v[k], v[(k + 1) % 5], v[(k + 2) % 5]) > 0);
      assert_true(v[k].x * v[k].x + v[k].y * v[k].y < 1);
      if (k > 0) assert_true(ts_lexless(v[0], v[k]));
    }
    /* Winding once (no pentagram), no duplicates: the project's validator. */
    size_t bad;
    int rev;
    assert_int_equal(geom_polygon_check(v, 5, &bad, &rev), GEOM_OK);
    assert_int_equal(rev, 0);
  }
}

static int ts_cmp_point(const void *a, const void *b) {
  const geom_point *p = a, *q = b;
  return ts_lexless(*p, *q) ? -1 : ts_lexless(*q, *p) ? 1 : 0;
}

/* Andrew's monotone chain with exact orient; collinear and duplicate
** points are not vertices.  Returns the size, hull anticlockwise in h. */
static int ts_hull(const geom_point *pts, int n, geom_point *h) {
  geom_point s[64];
  memcpy(s, pts, (size_t)n * sizeof *s);
  qsort(s, (size_t)n, sizeof *s, ts_cmp_point);
  int m = 0;
  for (int i = 0; i < n; i++)
    if (m == 0 || ts_cmp_point(&s[i], &s[m - 1]) != 0) s[m++] = s[i];
  n = m;
  if (n <= 2) {
    memcpy(h, s, (size_t)n * sizeof *h);
    return n;
  }
  int k = 0;
  for (int i = 0; i < n; i++) {
    while (k >= 2 && geom_orient(h[k - 2], h[k - 1], s[i]) <= 0) k--;
    h[k++] = s[i];
  }
  for (int i = n - 2, t = k + 1; i >= 0; i--) {
    while (k >= t && geom_orient(h[k - 2], h[k - 1], s[i]) <= 0) k--;
    h[k++] = s[i];
  }
  return k - 1;
}

/* The spec's iteration method, from scratch: the same generator stream
** (sampler_seed(seed, index)), points uniform in the unit disc by
** rejection from the square, full hull after every draw. */
static void test_is_iteration_method(void **state) {
  (void)state;
  long draws = 0;
  const int n = 3000;
  for (int i = 0; i < n; i++) {
    sampler_rng g;
    sampler_seed(&g, 77, (uint64_t)i);
    geom_point pts[64], h[64];
    int np = 0, nh = 0;
    while (nh != 5) {
      assert_true(np < 64);
      double x, y;
      do {
        x = 2 * sampler_uniform(&g) - 1;
        y = 2 * sampler_uniform(&g) - 1;
      } while (!(x * x + y * y < 1));
      pts[np++] = (geom_point){x, y};
      int before = nh;
      nh = ts_hull(pts, np, h);
      assert_true(nh <= before + 1);   /* the hull grows by at most one */
    }
    draws += np;
    geom_point v[5];
    sampler_pentagon(77, (uint64_t)i, v);
    /* h starts at the lexicographically smallest point too. */
    assert_true(ts_same(v, h, 5));
  }
  /* Sanity: a pentagon needs a handful of draws on average. */
  double mean = (double)draws / n;
  assert_true(mean > 5 && mean < 30);
}

static geom_point P(double x, double y) {
  return (geom_point){x, y};
}

static void ts_expect(const geom_point *h, int n, const geom_point *want, int nw) {
  assert_int_equal(n, nw);
  /* Same cyclic sequence, anticlockwise. */
  int start = -1;
  for (int k = 0; k < n; k++)
    if (h[k].x == want[0].x && h[k].y == want[0].y) start = k;
  assert_true(start >= 0);
  for (int k = 0; k < n; k++) {
    assert_true(h[(start + k) % n].x == want[k].x);
    assert_true(h[(start + k) % n].y == want[k].y);
  }
}

static void test_hull_degenerate(void **state) {
  (void)state;
  geom_point h[8];
  int n = 0;
  n = sampler_hull_add(h, n, P(0, 0));
  n = sampler_hull_add(h, n, P(0, 0));           /* duplicate */
  assert_int_equal(n, 1);
  n = sampler_hull_add(h, n, P(2, 0));
  n = sampler_hull_add(h, n, P(1, 0));           /* between: not a vertex */
  n = sampler_hull_add(h, n, P(2, 0));           /* duplicate */
  assert_int_equal(n, 2);
  n = sampler_hull_add(h, n, P(3, 0));           /* extends the segment */
  ts_expect(h, n, (geom_point[]){P(0, 0), P(3, 0)}, 2);
  n = sampler_hull_add(h, n, P(-1, 0));
  ts_expect(h, n, (geom_point[]){P(-1, 0), P(3, 0)}, 2);
  n = sampler_hull_add(h, n, P(1, -2));          /* clockwise third point */
  ts_expect(h, n, (geom_point[]){P(-1, 0), P(1, -2), P(3, 0)}, 3);
  n = sampler_hull_add(h, n, P(1, 0));           /* on an edge */
  n = sampler_hull_add(h, n, P(0, -1));          /* on an edge */
  n = sampler_hull_add(h, n, P(1, -1));          /* inside */
  n = sampler_hull_add(h, n, P(3, 0));           /* a vertex again */
  assert_int_equal(n, 3);
  n = sampler_hull_add(h, n, P(5, 2));           /* extends edge (1,-2)-(3,0): (3,0) drops */
  ts_expect(h, n, (geom_point[]){P(-1, 0), P(1, -2), P(5, 2)}, 3);
  n = sampler_hull_add(h, n, P(1, 4));           /* a fourth vertex */
  ts_expect(h, n, (geom_point[]){P(-1, 0), P(1, -2), P(5, 2), P(1, 4)}, 4);
  n = sampler_hull_add(h, n, P(-3, -2));         /* sees both edges at (-1,0): it drops */
  ts_expect(h, n, (geom_point[]){P(-3, -2), P(1, -2), P(5, 2), P(1, 4)}, 4);
  n = sampler_hull_add(h, n, P(3, -2));          /* on the line of edge (-3,-2)-(1,-2), beyond (1,-2) */
  ts_expect(h, n, (geom_point[]){P(-3, -2), P(3, -2), P(5, 2), P(1, 4)}, 4);
  n = sampler_hull_add(h, n, P(-4, 3));
  ts_expect(h, n, (geom_point[]){P(-3, -2), P(3, -2), P(5, 2), P(1, 4), P(-4, 3)}, 5);
  n = sampler_hull_add(h, n, P(20, 1));          /* replaces (5,2) */
  ts_expect(h, n, (geom_point[]){P(-3, -2), P(3, -2), P(20, 1), P(1, 4), P(-4, 3)}, 5);
  n = sampler_hull_add(h, n, P(0, 100));         /* replaces (1,4) */
  ts_expect(h, n, (geom_point[]){P(-3, -2), P(3, -2), P(20, 1), P(0, 100), P(-4, 3)}, 5);
  n = sampler_hull_add(h, n, P(-1, -2));         /* on an edge of a pentagon */
  assert_int_equal(n, 5);
  /* Random points against the monotone chain, including grid duplicates
  ** and collinear triples. */
  testutil_rng g = {3};
  for (int trial = 0; trial < 20000; trial++) {
    geom_point pts[7], ref[16];
    n = 0;
    for (int k = 0; k < 7; k++) {
      pts[k] = P((double)(testutil_next(&g) % 4), (double)(testutil_next(&g) % 4));
      n = sampler_hull_add(h, n, pts[k]);
      int nr = ts_hull(pts, k + 1, ref);
      if (n >= 3 || nr >= 3) ts_expect(h, n, ref, nr);
      else assert_int_equal(n, nr);
      if (n == 5) break;   /* the sampler never goes past five */
    }
  }
}

/* The registry of streams (geom/splitmix.h): the tags spell what their
** comments say, the fixed values stay what every recorded output was drawn
** with, and no two tags coincide. */
static void test_stream_registry(void **state) {
  (void)state;
  static const struct { uint64_t tag; const char *ascii; } tags[] = {
    {GEOM_STREAM_POINTS, "points"}, {GEOM_STREAM_BRIO, "brio"},
    {GEOM_STREAM_RANDOM_ORDER, "rand"}, {GEOM_STREAM_PSLG, "pslgraph"},
    {GEOM_STREAM_SEGMENTS, "segments"}};
  for (size_t k = 0; k < sizeof tags / sizeof tags[0]; k++) {
    uint64_t v = 0;
    for (const char *c = tags[k].ascii; *c; c++) v = v << 8 | (unsigned char)*c;
    assert_true(v == tags[k].tag);
    assert_true(tags[k].tag != GEOM_STREAM_GOT_POLYGON);
    for (size_t j = 0; j < k; j++) assert_true(tags[j].tag != tags[k].tag);
  }
  assert_true(GEOM_STREAM_GOT_POLYGON == 0);
  assert_true(GEOM_SALT_QUAD == 0x51A7C0DE5EEDF00Dull);
  assert_true(GEOM_STATE_FORMULA_SIGNS == 0x5EED5167ull);
  assert_true(GEOM_STATE_LOT_WALK == 0x9e3779b97f4a7c15ull);
  assert_true(GEOM_STREAM_SAMPLE(12345) == 12345);
}

static void test_deviates(void **state) {
  (void)state;
  sampler_rng g;
  sampler_seed(&g, 9, 0);
  const int n = 400000;
  double s1 = 0, s2 = 0, n1 = 0, n2 = 0;
  for (int i = 0; i < n; i++) {
    double u = sampler_uniform(&g);
    assert_true(u >= 0 && u < 1);
    s1 += u;
    s2 += u * u;
    double z = sampler_normal(&g);
    n1 += z;
    n2 += z * z;
  }
  /* Uniform: mean 1/2 (sd 0.289/sqrt n = 4.6e-4), E u^2 = 1/3 (sd 0.298/sqrt n
  ** = 4.7e-4); normal: mean 0 (sd 1/sqrt n = 1.6e-3), E z^2 = 1 (sd
  ** sqrt 2/sqrt n = 2.2e-3).  Tolerances are 5 standard errors. */
  assert_true(fabs(s1 / n - 0.5) < 5 * 4.6e-4);
  assert_true(fabs(s2 / n - 1.0 / 3) < 5 * 4.7e-4);
  assert_true(fabs(n1 / n) < 5 * 1.6e-3);
  assert_true(fabs(n2 / n - 1) < 5 * 2.2e-3);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_determinism),
    cmocka_unit_test(test_convex_anticlockwise),
    cmocka_unit_test(test_is_iteration_method),
    cmocka_unit_test(test_hull_degenerate),
    cmocka_unit_test(test_deviates),
    cmocka_unit_test(test_stream_registry),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
