/*
** test_shape_sweep_keys.c: the exact keys of the sweep
** (shapes/shape_sweep_*.c, through the tables of shape_sweep_internal.h).
** The certified bounds lo <= key <= hi that order the event heap, from the
** circle's fast path (one error bound) or its interval path
** (near-collinear triangles), from an ellipse's intervals and from a
** polygon's (finite keys; infinite ones in bands above every site), hold
** against the exact key, compared in rationals with the sites' keys lo
** and hi.  Triangles: uniform, near collinear, thin, at the contract's
** magnitudes, and points one ulp apart.  The circle is the ellipse of
** the form x^2 + y^2: the two tables order every pair of keys and answer
** every "above" test alike.  The comparison of square roots both key
** comparisons end in, against rationals whose roots are rational.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>

#include "shape.h"
#include "shape_sweep_internal.h"
#include "testutil.h"

/* The bounds of t's key in table s hold, when t closes an event: 0 (no
** event), 1, or 2 for an infinite key.  A polygon's finite keys are
** bounded by at most 2^140 from below; above that lie the bands of its
** infinite keys (shape_sweep_polygon.c), beyond every site's key. */
static int tk_check_in(const shape_sweep *s, geom_point t[3]) {
  if (!s->closes(s->ctx, t[0], t[1], t[2])) return 0;
  double lo, hi;
  s->key_bounds(s->ctx, t, &lo, &hi);
  assert_true(lo <= hi);
  if (lo > 0x1p140) {
    assert_true(s->ties != NULL);
    assert_true(s->key_cmp(s->ctx, t, 0, NULL, 0x1p1000) > 0);
    return 2;
  }
  if (isfinite(lo)) assert_true(s->key_cmp(s->ctx, t, 0, NULL, lo) >= 0);
  if (isfinite(hi)) assert_true(s->key_cmp(s->ctx, t, 0, NULL, hi) <= 0);
  return 1;
}

static int tk_check(geom_point t[3]) {
  return tk_check_in(&shape_sweep_circle, t) != 0;
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

/* The table of shape spec into s, reading c and counting in *special. */
static shape *tk_table(const char *spec, shape_sweep_ctx *c, size_t *special, shape_sweep *s) {
  shape *k = NULL;
  char err[256];
  if (shape_parse(spec, &k, err, sizeof err) != 0) fail_msg("shape '%s': %s", spec, err);
  shape_sweep_make(k, c, special, s);
  return k;
}

/* A triangle of sites at magnitude m, sometimes on a small grid (special
** position for the polygons: sites on lines parallel to their sides). */
static void tk_triangle(testutil_rng *g, int k, geom_point t[3]) {
  double m = ldexp(1.0, (int)(testutil_next(g) % 81) - 40);
  for (int i = 0; i < 3; i++) {
    double x = testutil_uniform(g), y = testutil_uniform(g);
    if (k % 3 == 2) {
      x = (double)(testutil_next(g) % 5);
      y = (double)(testutil_next(g) % 5);
    }
    t[i] = (geom_point){m * x, m * y};
  }
}

static void test_shape_keys_hold(void **state) {
  (void)state;
  static const char *const specs[] = {"ellipse:2 1 0.5", "ellipse:1 3", "square", "hexagon",
                                      "diamond", "triangle", "poly:0 0;3 0;4 1;1 2"};
  for (size_t i = 0; i < sizeof specs / sizeof specs[0]; i++) {
    shape_sweep_ctx c;
    shape_sweep s;
    size_t special = 0;
    shape *k = tk_table(specs[i], &c, &special, &s);
    testutil_rng g = {7 + i};
    int checked[3] = {0, 0, 0};
    for (int it = 0; it < testutil_reps(3000); it++) {
      geom_point t[3];
      tk_triangle(&g, it, t);
      checked[tk_check_in(&s, t)]++;
      geom_point u[3] = {t[0], t[2], t[1]};
      checked[tk_check_in(&s, u)]++;
    }
    printf("%-22s %d finite keys checked, %d infinite, %zu ties counted\n", specs[i],
           checked[1], checked[2], special);
    assert_true(checked[1] + checked[2] > testutil_reps(3000) / 2);
    assert_true(k->kind == SHAPE_ELLIPSE ? checked[2] == 0 : checked[2] > 0);
    shape_free(k);
  }
}

/* The circle and the ellipse of the form x^2 + y^2 (ellipse:1 1: its form
** is (1, 0, 1) exactly) order every pair of event keys, and of an event's
** key and a site's, alike, and answer every "above" test alike, on
** random sites and on small grids (cocircular sites, equal keys, columns). */
static void test_circle_is_conic(void **state) {
  (void)state;
  shape_sweep_ctx c;
  shape_sweep e;
  size_t special = 0;
  shape *k = tk_table("ellipse:1 1", &c, &special, &e);
  assert_true(c.q.q11 == 1 && c.q.q12 == 0 && c.q.q22 == 1);
  const shape_sweep *o = &shape_sweep_circle;
  testutil_rng g = {11};
  for (int it = 0; it < testutil_reps(4000); it++) {
    geom_point t[3], u[3], x;
    tk_triangle(&g, it, t);
    tk_triangle(&g, it, u);
    x = u[0];
    if (o->closes(o->ctx, t[0], t[1], t[2]) && o->closes(o->ctx, u[0], u[1], u[2]))
      assert_int_equal(o->key_cmp(o->ctx, t, 0, u, 0), e.key_cmp(e.ctx, t, 0, u, 0));
    if (o->closes(o->ctx, t[0], t[1], t[2]))
      assert_int_equal(o->key_cmp(o->ctx, t, 0, NULL, x.x), e.key_cmp(e.ctx, t, 0, NULL, x.x));
    if (t[0].x <= x.x && t[1].x <= x.x)
      assert_int_equal(o->above(o->ctx, t[0], t[1], x), e.above(e.ctx, t[0], t[1], x));
  }
  shape_free(k);
}

/* a / b as a rational. */
static void tk_q(mpq_ptr out, long a, unsigned long b) {
  mpq_set_si(out, a, b);
  mpq_canonicalize(out);
}

/* shape_sweep_sqrt_cmp and shape_sweep_root_sign against rationals whose
** square roots are rational (r = s^2), where the sign is a comparison of
** rationals: small numerators and denominators, so that ties are common. */
static void test_sqrt_cmp(void **state) {
  (void)state;
  static const unsigned long den[3] = {1, 2, 3};
  testutil_rng g = {13};
  mpq_t q1, r1, s1, q2, r2, s2, x, y;
  mpq_inits(q1, r1, s1, q2, r2, s2, x, y, NULL);
  int ties = 0;
  for (int it = 0; it < 20000; it++) {
    tk_q(q1, (long)(testutil_next(&g) % 9) - 4, den[testutil_next(&g) % 3]);
    tk_q(q2, (long)(testutil_next(&g) % 9) - 4, den[testutil_next(&g) % 3]);
    tk_q(s1, (long)(testutil_next(&g) % 5), den[testutil_next(&g) % 3]);
    tk_q(s2, (long)(testutil_next(&g) % 5), den[testutil_next(&g) % 3]);
    mpq_mul(r1, s1, s1);
    mpq_mul(r2, s2, s2);
    mpq_add(x, q1, s1);   /* (q1 + s1) - (q2 + s2) */
    mpq_sub(x, x, q2);
    mpq_sub(x, x, s2);
    int want = mpq_sgn(x);
    ties += want == 0;
    mpq_add(y, s1, s1);   /* q2 + 2 s1, for the root sign of e = q2, f = s1^2 */
    mpq_add(y, y, q2);
    int want_root = mpq_sgn(y);
    mpq_set(x, q2);
    assert_int_equal(shape_sweep_sqrt_cmp(q1, r1, q2, r2), want);
    mpq_set(y, r1);
    assert_int_equal(shape_sweep_root_sign(x, y), want_root);
  }
  assert_true(ties > 200);
  mpq_clears(q1, r1, s1, q2, r2, s2, x, y, NULL);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_keys_hold),
    cmocka_unit_test(test_shape_keys_hold),
    cmocka_unit_test(test_circle_is_conic),
    cmocka_unit_test(test_sqrt_cmp),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
