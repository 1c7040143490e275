/*
** test_lot_order.c: the lexicographic order of lot/ (lot_order_lexicographic,
** lot/order.h), the sweep's and the flip algorithm's site order, made by a
** radix sort on the coordinates' integer keys.
**
** The oracle is the definition, written here with qsort and geom_lexless
** (x, then y, then input index; -0.0 equals 0.0 under ==).  The order is
** total, so the two must agree index for index.  Inputs: uniform points,
** both signs, -0.0 against 0.0, duplicates, columns and rows of equal
** coordinates (the path that sorts by y), the contract's extreme
** magnitudes, and points that differ in their lowest bits only.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "order.h"
#include "testutil.h"

typedef struct to_item {
  geom_point p;
  uint32_t i;
} to_item;

static int to_cmp(const void *x, const void *y) {
  const to_item *a = x, *b = y;
  if (geom_lexless(a->p, b->p)) return -1;
  if (geom_lexless(b->p, a->p)) return 1;
  return a->i < b->i ? -1 : a->i > b->i;
}

/* lot_order_lexicographic(p) equals the qsort of the definition. */
static void to_agree(const geom_point *p, uint32_t n) {
  to_item *s = malloc((n + 1) * sizeof *s);
  uint32_t *ord = malloc((n + 1) * sizeof *ord);
  assert_non_null(s);
  assert_non_null(ord);
  for (uint32_t i = 0; i < n; i++) s[i] = (to_item){p[i], i};
  qsort(s, n, sizeof *s, to_cmp);
  assert_int_equal(lot_order_lexicographic(p, n, ord), 0);
  for (uint32_t k = 0; k < n; k++)
    if (ord[k] != s[k].i) fail_msg("position %u: %u, want %u", k, ord[k], s[k].i);
  free(s);
  free(ord);
}

/* A coordinate drawn from a small set when `few` (many ties), else uniform
** in [-1, 1); zeros of both signs among the few. */
static double to_coord(testutil_rng *g, int few) {
  static const double set[] = {-0.0, 0.0, 1.0, -1.0, 0.5, 1e-30, -1e-30, 1e30, -1e30, 3.0};
  if (few) return set[testutil_next(g) % (sizeof set / sizeof set[0])];
  return 2 * testutil_uniform(g) - 1;
}

static void test_order_random(void **state) {
  (void)state;
  testutil_rng g = {7};
  for (uint32_t n = 1; n < 300; n += 1 + n / 4)
    for (int mode = 0; mode < 4; mode++) {
      geom_point *p = malloc((n + 1) * sizeof *p);
      assert_non_null(p);
      for (uint32_t i = 0; i < n; i++) p[i] = (geom_point){to_coord(&g, mode & 1),
                                                           to_coord(&g, mode & 2)};
      to_agree(p, n);
      free(p);
    }
}

static void test_order_zeros_and_duplicates(void **state) {
  (void)state;
  const geom_point p[] = {{0.0, 0.0}, {-0.0, -0.0}, {-0.0, 0.0}, {0.0, -0.0}, {0.0, 1.0},
                          {-0.0, -1.0}, {1.0, -0.0}, {1.0, 0.0}, {-0.0, 0.0}, {0.0, 0.0}};
  to_agree(p, sizeof p / sizeof p[0]);
  geom_point q[64];
  for (uint32_t i = 0; i < 64; i++) q[i] = (geom_point){i % 2 ? -0.0 : 0.0, i % 3 ? 0.0 : -0.0};
  to_agree(q, 64);
}

/* Columns and rows of a grid, in a scrambled input order; points apart by
** one ulp; the contract's magnitudes (every binade of the keys' digits). */
static void test_order_adversarial(void **state) {
  (void)state;
  enum { N = 4096 };
  geom_point *p = malloc(N * sizeof *p);
  assert_non_null(p);
  testutil_rng g = {11};
  for (uint32_t i = 0; i < N; i++) {
    uint32_t k = (uint32_t)(testutil_next(&g) % N);
    p[i] = (geom_point){(double)(k % 64) - 32, (double)(k / 64) - 32};
  }
  to_agree(p, N);
  for (uint32_t i = 0; i < N; i++) {
    double x = 1.0, y = -1.0;
    for (uint64_t k = testutil_next(&g) % 8; k > 0; k--) x = nextafter(x, 2.0);
    for (uint64_t k = testutil_next(&g) % 8; k > 0; k--) y = nextafter(y, 0.0);
    p[i] = (geom_point){x, y};
  }
  to_agree(p, N);
  for (uint32_t i = 0; i < N; i++) {
    double m = ldexp(1.0, (int)(testutil_next(&g) % 199) - 99);   /* 2^-99 .. 2^99 */
    p[i] = (geom_point){testutil_next(&g) % 2 ? m : -m, testutil_uniform(&g) * m};
  }
  to_agree(p, N);
  free(p);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_order_random),
    cmocka_unit_test(test_order_zeros_and_duplicates),
    cmocka_unit_test(test_order_adversarial),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
