/*
** test_polygon_sampler.c: the large-n convex polygon samplers of
** samplers/polygon.c (vector method, thesis 6.4; points on a circle).
**
** - every sample is strictly convex and anticlockwise (exact check), for
**   n from 3 to 20000; n < 3 is refused;
** - same seed and stream give bit-identical polygons, another seed not;
** - it IS the vector method: the edges, read as vectors, have strictly
**   increasing directions (one turn around), and their x components form
**   a point uniform in the unit ball of the hyperplane sum = 0: the norm
**   r satisfies r <= 1 and r^(n-1) is uniform on [0, 1] (mean 1/2, checked
**   over 3000 polygons within 5 standard errors);
** - the circle sampler's points are on the unit circle to rounding, in
**   increasing angle, and the angles are uniform (share in the upper half
**   plane is 1/2 within 5 standard errors).
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

typedef int (*tps_fn)(sampler_rng *g, size_t n, geom_point *out);

static void test_convex_anticlockwise(void **state) {
  (void)state;
  static const size_t sizes[] = {3, 4, 5, 7, 10, 100, 1000, 20000};
  tps_fn fns[2] = {sampler_vector, sampler_circle};
  geom_point *p = malloc(20000 * sizeof *p);
  for (int f = 0; f < 2; f++)
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
      for (uint64_t seed = 1; seed <= (sizes[s] < 1000 ? 20u : 2u); seed++) {
        sampler_rng g;
        sampler_seed(&g, seed, 3);
        assert_int_equal(fns[f](&g, sizes[s], p), 0);
        testutil_check_convex(p, sizes[s]);
      }
  sampler_rng g;
  sampler_seed(&g, 1, 1);
  assert_int_equal(sampler_vector(&g, 2, p), -1);
  assert_int_equal(sampler_circle(&g, 2, p), -1);
  free(p);
}

static void test_reproducible(void **state) {
  (void)state;
  enum { N = 500 };
  static geom_point a[N], b[N];
  tps_fn fns[2] = {sampler_vector, sampler_circle};
  for (int f = 0; f < 2; f++) {
    sampler_rng g1, g2;
    sampler_seed(&g1, 42, 7);
    sampler_seed(&g2, 42, 7);
    assert_int_equal(fns[f](&g1, N, a), 0);
    assert_int_equal(fns[f](&g2, N, b), 0);
    assert_memory_equal(a, b, sizeof a);
    sampler_seed(&g2, 43, 7);
    assert_int_equal(fns[f](&g2, N, b), 0);
    assert_true(memcmp(a, b, sizeof a) != 0);
  }
}

static void test_vector_method(void **state) {
  (void)state;
  enum { N = 10, DRAWS = 3000 };
  geom_point p[N];
  double sum = 0;
  for (int d = 0; d < DRAWS; d++) {
    sampler_rng g;
    sampler_seed(&g, 1000 + (uint64_t)d, 0);
    assert_int_equal(sampler_vector(&g, N, p), 0);
    double r2 = 0;
    int descents = 0;
    double prev = 0;
    for (size_t i = 0; i < N; i++) {
      double ex = p[(i + 1) % N].x - p[i].x, ey = p[(i + 1) % N].y - p[i].y;
      double th = atan2(ey, ex);
      if (i > 0 && th <= prev) descents++;
      prev = th;
      r2 += ex * ex;
    }
    assert_true(descents <= 1);          /* directions go round once */
    assert_true(r2 <= 1 + 1e-12);        /* inside the unit ball */
    sum += pow(sqrt(r2), N - 1);         /* uniform on [0, 1] */
  }
  double mean = sum / DRAWS, se = sqrt(1.0 / 12 / DRAWS);
  if (fabs(mean - 0.5) > 5 * se) fail_msg("mean of r^(n-1) = %g, want 0.5 +- %g", mean, 5 * se);
}

static void test_circle(void **state) {
  (void)state;
  enum { N = 20000 };
  static geom_point p[N];
  sampler_rng g;
  sampler_seed(&g, 8, 8);
  assert_int_equal(sampler_circle(&g, N, p), 0);
  size_t upper = 0;
  double prev = -1;
  for (size_t i = 0; i < N; i++) {
    assert_true(fabs(hypot(p[i].x, p[i].y) - 1) <= 4e-16);
    double th = atan2(p[i].y, p[i].x);
    if (th < 0) th += 2 * M_PI;
    assert_true(th > prev);
    prev = th;
    upper += p[i].y > 0;
  }
  double share = (double)upper / N, se = 0.5 / sqrt((double)N);
  assert_true(fabs(share - 0.5) <= 5 * se);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_convex_anticlockwise),
    cmocka_unit_test(test_reproducible),
    cmocka_unit_test(test_vector_method),
    cmocka_unit_test(test_circle),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
