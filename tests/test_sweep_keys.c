/*
** test_sweep_keys.c: the circle's event keys of the sweep (lot/sweep_circle.c,
** through the table lot_sweep_circle of sweep_internal.h): the certified
** bounds lo <= key <= hi that order the event heap, from the fast path
** (one error bound) or the interval path (near-collinear triangles), hold
** against the exact key, compared in rationals with the sites' keys lo
** and hi.  Triangles: uniform, near collinear, thin, at the contract's
** magnitudes, and points one ulp apart.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>

#include "sweep_internal.h"
#include "testutil.h"

/* The bounds of t's key hold, when t closes an event. */
static int tk_check(geom_point t[3]) {
  const lot_sweep_shape *s = &lot_sweep_circle;
  if (!s->closes(s->ctx, t[0], t[1], t[2])) return 0;
  double lo, hi;
  s->key_bounds(s->ctx, t, &lo, &hi);
  assert_true(lo <= hi);
  if (isfinite(lo)) assert_true(s->key_cmp(s->ctx, t, 0, NULL, lo) >= 0);
  if (isfinite(hi)) assert_true(s->key_cmp(s->ctx, t, 0, NULL, hi) <= 0);
  return 1;
}

static void test_keys_hold(void **state) {
  (void)state;
  testutil_rng g = {5};
  int checked = 0;
  for (int k = 0; k < 20000; k++) {
    double m = ldexp(1.0, (int)(testutil_next(&g) % 161) - 80);
    geom_point t[3];
    for (int i = 0; i < 3; i++)
      t[i] = (geom_point){m * testutil_uniform(&g), m * testutil_uniform(&g)};
    int mode = k % 4;
    if (mode == 1) {   /* c near the line a b */
      double f = testutil_uniform(&g), d = ldexp(m, -(int)(testutil_next(&g) % 60));
      t[2] = (geom_point){t[0].x + f * (t[1].x - t[0].x), t[0].y + f * (t[1].y - t[0].y) + d};
    } else if (mode == 2) {   /* one ulp apart */
      t[1] = (geom_point){nextafter(t[0].x, INFINITY), t[0].y};
      t[2] = (geom_point){t[0].x, nextafter(t[0].y, -INFINITY)};
    } else if (mode == 3) {   /* thin and tall */
      t[1].x = t[0].x + (t[1].x - t[0].x) * 1e-9;
    }
    checked += tk_check(t);
    geom_point u[3] = {t[0], t[2], t[1]};   /* the other orientation */
    checked += tk_check(u);
  }
  assert_true(checked > 15000);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_keys_hold),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
