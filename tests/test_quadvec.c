/*
** test_quadvec.c: the lane decision engine shared by table34 and the census
** (classify/quadvec_internal.h) against its oracle, joint_compare (what
** rule_eval_tris decides), quadrilateral by quadrilateral, on random
** batches whose values include the cases its rewrites must get right:
** ties, near ties, zeros, the least subnormal, magnitudes near 2^+-1000
** (products and squares under- and overflow), +inf and NaN; with the
** vector engine and the portable one; and a harmonic case built so that
** 1/(1/y) != y decides the answer (an argument +inf must give y exactly).
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "joint.h"
#include "quadvec_internal.h"
#include "testutil.h"

#define TQV_ROWS 8
#define TQV_QUADS 6
#define TQV_STRIDE 16

typedef struct tqv_batch {
  ptrdiff_t qoff[TQV_QUADS][4];
  int used[JOINT_COUNT];
  unsigned long long bw[TQV_QUADS], tw[TQV_QUADS], code[JOINT_COUNT * TQV_STRIDE];
  long long tie[JOINT_COUNT * TQV_STRIDE], flags[TQV_STRIDE];
  double sign[TQV_STRIDE], val[TQV_ROWS * TQV_STRIDE], mag[TQV_ROWS * TQV_STRIDE],
      h[TQV_ROWS * TQV_STRIDE];
} tqv_batch;

/* A magnitude: mostly ordinary, sometimes one of the hard cases. */
static double tqv_magnitude(testutil_rng *g, double prev) {
  double u = testutil_uniform(g), m = 0.1 + 10 * testutil_uniform(g);
  if (u < 0.10) return prev;                                   /* exact ties */
  if (u < 0.15) return prev * (1 + 1e-13 * testutil_uniform(g));   /* near ties */
  if (u < 0.18) return 0.0;
  if (u < 0.20) return 0x1p-1074;
  if (u < 0.25) return ldexp(m, 1000 - (int)(testutil_next(g) % 40));
  if (u < 0.30) return ldexp(m, -1000 + (int)(testutil_next(g) % 40));
  if (u < 0.33) return INFINITY;
  if (u < 0.34) return NAN;
  return m;
}

/* Runs b through quadvec (engine `scalar`) and checks every used joint,
** slot and quadrilateral against joint_compare. */
static void tqv_check(tqv_batch *t, int nslots, int ntris, int nquads, double eps, int scalar) {
  const quadvec_batch b = {nslots, TQV_STRIDE, ntris, nquads, (const ptrdiff_t (*)[4])t->qoff, t->bw,
                           t->tw, t->sign, eps, t->used, t->val, t->mag, t->h, t->flags,
                           t->code, t->tie};
  quadvec_use_scalar(scalar);
  quadvec_run(&b);
  quadvec_use_scalar(0);
  for (int j = 0; j < JOINT_COUNT; j++)
    for (int s = 0; s < nslots && t->used[j]; s++) {
      unsigned long long code = 0;
      int tied = 0;
      for (int q = 0; q < nquads; q++) {
        const ptrdiff_t *o = t->qoff[q];
        int c = joint_compare((joint_id)j, t->sign[s] < 0 ? -1 : 1, t->val[o[0] + s],
                              t->val[o[1] + s], t->val[o[2] + s], t->val[o[3] + s], eps);
        code += c < 0 ? 0 : c > 0 ? t->bw[q] : t->tw[q];
        tied |= c == 0;
      }
      if (t->code[j * TQV_STRIDE + s] != code || (t->tie[j * TQV_STRIDE + s] != 0) != tied)
        fail_msg("%s engine, joint %s, slot %d (sign %g), tie_eps %g: code %llu tie %d, "
                 "joint_compare %llu tie %d", scalar ? "scalar" : "vector",
                 joint_get((joint_id)j)->name, s, t->sign[s], eps,
                 t->code[j * TQV_STRIDE + s], t->tie[j * TQV_STRIDE + s] != 0, code, tied);
    }
}

static void tqv_random(testutil_rng *g, tqv_batch *t, int nslots, int ntris, int nquads) {
  for (int j = 0; j < JOINT_COUNT; j++) t->used[j] = 1;
  for (int q = 0, w = 1; q < nquads; q++, w *= 3) {
    for (int k = 0; k < 4; k++) t->qoff[q][k] = (ptrdiff_t)(testutil_next(g) % (uint64_t)ntris) * TQV_STRIDE;
    t->bw[q] = (unsigned long long)w;
    t->tw[q] = 2 * (unsigned long long)w;
  }
  for (int s = 0; s < TQV_STRIDE; s++) t->sign[s] = s < nslots && testutil_next(g) % 3 == 0 ? -1.0 : 1.0;
  for (int r = 0; r < ntris; r++)
    for (int s = 0; s < TQV_STRIDE; s++) {
      double prev = r > 0 ? fabs(t->val[(r - 1) * TQV_STRIDE + s]) : 1.0;
      t->val[r * TQV_STRIDE + s] = s < nslots ? t->sign[s] * tqv_magnitude(g, prev) : 1.0;
    }
}

static void test_random_batches(void **state) {
  (void)state;
  testutil_rng g = {20261201};
  static tqv_batch t;
  const double eps[] = {1e-12, 0, 1e-4, 0.05};
  for (int trial = 0; trial < 20000; trial++) {
    int nslots = 1 + (int)(testutil_next(&g) % 9), ntris = 2 + (int)(testutil_next(&g) % 7);
    int nquads = 1 + (int)(testutil_next(&g) % TQV_QUADS);
    tqv_random(&g, &t, nslots, ntris, nquads);
    double e = eps[trial % 4];
    tqv_check(&t, nslots, ntris, nquads, e, 0);
    tqv_check(&t, nslots, ntris, nquads, e, 1);
  }
}

/* harmonic(+inf, y) is y exactly; the shared-reciprocal form would give
** fl(1/fl(1/y)), which differs from y for some y.  With z = fl(1/fl(1/y))
** a round trip's fixed point, AC = harmonic(inf, y) = y and BD =
** harmonic(z, inf) = z differ (no tie at tie_eps 0), while the
** reciprocal form would see z twice: a tie. */
static void test_harmonic_infinity(void **state) {
  (void)state;
  testutil_rng g = {7};
  static tqv_batch t;
  int found = 0;
  for (int k = 0; k < 100000 && found < 4; k++) {
    double y = 1 + testutil_uniform(&g), z = 1.0 / (1.0 / y);
    if (z == y || 1.0 / (1.0 / z) != z) continue;
    found++;
    memset(&t, 0, sizeof t);
    t.used[JOINT_HARMONIC] = 1;
    int row[4] = {0, 1, 2, 3};
    for (int i = 0; i < 4; i++) t.qoff[0][i] = row[i] * TQV_STRIDE;
    t.bw[0] = 1;
    t.tw[0] = 2;
    for (int s = 0; s < TQV_STRIDE; s++) {
      t.sign[s] = 1.0;
      for (int r = 0; r < 4; r++) t.val[r * TQV_STRIDE + s] = 1.0;
    }
    t.val[0] = INFINITY;
    t.val[1 * TQV_STRIDE] = y;
    t.val[2 * TQV_STRIDE] = z;
    t.val[3 * TQV_STRIDE] = INFINITY;
    assert_int_not_equal(joint_compare(JOINT_HARMONIC, 1, INFINITY, y, z, INFINITY, 0), 0);
    tqv_check(&t, 1, 4, 1, 0, 0);
    tqv_check(&t, 1, 4, 1, 0, 1);
  }
  assert_true(found > 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_random_batches),
    cmocka_unit_test(test_harmonic_infinity),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
