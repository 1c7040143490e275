/*
** test_gon_region.c: the regions rejection and iteration draw in
** (samplers/gon_region.c), against an identity: the exterior regions of a
** convex polygon P inside the domain D (right of edge i, left of the line of
** edge i - 1) partition D minus P, so their masses sum to 1 - area(P) /
** area(D) exactly; each acceptance region lies in its edge's exterior
** region.  Hulls from the samplers of each domain, and for the disc
** polygons with vertices exactly on the circle (the cap's chord ends: the
** disc area once came out 0 there when the crossings were found from the
** roots alone, and iteration stopped).
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "gon_internal.h"
#include "testutil.h"

static double tg_area(const geom_point *v, size_t n) {
  double a = 0;
  for (size_t i = 0; i < n; i++)
    a += v[i].x * v[(i + 1) % n].y - v[i].y * v[(i + 1) % n].x;
  return a / 2;
}

/* The exterior masses sum to 1 - area / domain area; acceptance <= exterior. */
static void tg_check(sampler_region r, const geom_point *v, size_t n) {
  static const double domain[SAMPLER_REGION_COUNT] = {1, 3.14159265358979323846, 0.5};
  double sum = 0;
  for (size_t i = 0; i < n; i++) {
    geom_point z = v[(i + n - 1) % n], a = v[i], b = v[(i + 1) % n], c = v[(i + 2) % n];
    geom_point left[2][2] = {{z, a}, {b, c}};
    sampler_clip clip;
    double ext = sampler_region_mass(r, a, b, (const geom_point (*)[2])left, 1, &clip);
    double acc = sampler_region_mass(r, a, b, (const geom_point (*)[2])left, 2, &clip);
    assert_true(acc <= ext * (1 + 1e-12) + 1e-300);
    sum += ext;
  }
  TESTUTIL_NEAR(sum, 1 - tg_area(v, n) / domain[r], 1e-9, 1e-12);
}

static void test_partition(void **state) {
  (void)state;
  static const char *const by[SAMPLER_REGION_COUNT] = {"valtr", "iteration", "rejection"};
  geom_point v[200];
  for (int r = 0; r < SAMPLER_REGION_COUNT; r++)
    for (uint64_t i = 0; i < 200; i++) {
      size_t n = 3 + (size_t)(i % 60);
      sampler_gon_params p = {(sampler_region)r, 0, NULL};
      sampler_gon_info info;
      assert_int_equal(sampler_gon_draw(sampler_gon_find(by[r]), &p, 2, i, n, v, &info), 0);
      tg_check((sampler_region)r, v, n);
    }
}

static void test_disc_on_circle(void **state) {
  (void)state;
  geom_point diamond[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  geom_point tri[3] = {{1, 0}, {-0.5, 0.8660254037844386}, {-0.5, -0.8660254037844386}};
  geom_point inner[4] = {{0.6, 0}, {0, 0.6}, {-0.6, 0}, {0, -0.6}};
  tg_check(SAMPLER_REGION_DISC, diamond, 4);
  tg_check(SAMPLER_REGION_DISC, tri, 3);
  tg_check(SAMPLER_REGION_DISC, inner, 4);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_partition),
    cmocka_unit_test(test_disc_on_circle),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
