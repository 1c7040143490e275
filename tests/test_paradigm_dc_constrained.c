/*
** test_paradigm_dc_constrained.c: the row dc-constrained (2.6.2 as far as
** it is built: the vertical strips with no virtual site).  On uniform
** sets, grid sets with duplicates and ties, and integer points on two
** concentric circles (cocircular ties): with segments drawn among the
** Delaunay edges (many sharing endpoints) it gives exactly lot's
** constrained triangulation; with random segments it serves the set
** exactly when every segment is an edge of lot's Delaunay triangulation
** (then with lot's constrained triangulation), and otherwise refuses on
** one line naming the segment and what is missing.  Euler's count holds
** on every run; the other refusals are one line.
*/
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "paradigm.h"
#include "lot.h"
#include "testutil.h"

#define TDC_MAXN 48

/* A small set: uniform, a grid with duplicates, or circle points. */
static size_t tdc_points(int f, testutil_rng *g, geom_point *p) {
  size_t n = 4 + testutil_next(g) % (TDC_MAXN - 4), k = 0;
  if (f == 0)
    for (; k < n; k++) p[k] = (geom_point){testutil_uniform(g), testutil_uniform(g)};
  if (f == 1)
    for (; k < n; k++)
      p[k] = (geom_point){(double)(testutil_next(g) % 5), (double)(testutil_next(g) % 5)};
  for (int x = -7; f == 2 && x <= 7; x++)
    for (int y = -7; y <= 7; y++)
      if ((x * x + y * y == 25 || x * x + y * y == 50) && k < TDC_MAXN)
        p[k++] = (geom_point){x, y};
  return k;
}

static int tdc_run(const char *row, const geom_point *p, size_t n, const uint32_t *seg,
                   size_t ns, paradigm_result *res, char *err, size_t errlen) {
  rule dt = rule_delaunay();
  paradigm_input in = {.p = p, .n = n, .r = &dt, .problem = PARADIGM_CONSTRAINED,
                       .segments = seg, .nsegments = ns, .seed = 3, .threads = 1};
  return paradigm_run(paradigm_find(row), &in, res, err, errlen);
}

/* Is u-v (input indices, mapped to first occurrences) an edge of tri? */
static int tdc_edge(const paradigm_result *dt, const uint32_t *first, uint32_t u, uint32_t v) {
  u = first[u], v = first[v];
  for (size_t t = 0; t < dt->ntri; t++)
    for (int k = 0; k < 3; k++) {
      uint32_t a = dt->tri[3 * t + k], b = dt->tri[3 * t + (k + 1) % 3];
      if ((a == u && b == v) || (a == v && b == u)) return 1;
    }
  return 0;
}

/* One set with its segments: dc-constrained against lot (the incremental
** row) and lot's Delaunay triangulation; returns 1 when it served. */
static int tdc_compare(const geom_point *p, size_t n, const uint32_t *seg, size_t ns,
                       const paradigm_result *dt, const uint32_t *first) {
  char err[512], err2[512];
  paradigm_result ref, res;
  if (tdc_run("incremental", p, n, seg, ns, &ref, err, sizeof err) != 0) return 0;
  int edges = 1;
  for (size_t s = 0; s < ns; s++) edges &= tdc_edge(dt, first, seg[2 * s], seg[2 * s + 1]);
  int rc = tdc_run("dc-constrained", p, n, seg, ns, &res, err2, sizeof err2);
  if (rc != 0) {
    if (edges || strstr(err2, "virtual sites") == NULL || strchr(err2, '\n') != NULL)
      fail_msg("n %zu, %zu segments (edges %d): refused: %s", n, ns, edges, err2);
    paradigm_result_free(&ref);
    return 0;
  }
  if (!edges || res.ntri != ref.ntri
      || memcmp(res.tri, ref.tri, 3 * ref.ntri * sizeof *ref.tri) != 0)
    fail_msg("n %zu, %zu segments: differs from lot's constrained triangulation", n, ns);
  size_t m = res.distinct, h = 2 * m - 2 - res.ntri;
  assert_int_equal(res.ops.v[OPS_EDGES_MADE] - res.ops.v[OPS_EDGES_DELETED], 3 * m - 3 - h);
  paradigm_result_free(&res), paradigm_result_free(&ref);
  return 1;
}

static void tdc_set(int f, testutil_rng *g, int *served, int *refused) {
  geom_point p[TDC_MAXN];
  uint32_t first[TDC_MAXN], seg[2 * 3 * TDC_MAXN];
  size_t n = tdc_points(f, g, p);
  rule dt = rule_delaunay();
  char err[256];
  paradigm_input in = {.p = p, .n = n, .r = &dt, .problem = PARADIGM_DELAUNAY, .threads = 1};
  paradigm_result del;
  if (paradigm_run(paradigm_find("incremental"), &in, &del, err, sizeof err) != 0) return;
  assert_true(lot_distinct(p, n, first) >= 0);
  size_t ns = 0;   /* Delaunay edges, by input index (a duplicate's too) */
  for (size_t t = 0; t < del.ntri; t++)
    if (testutil_next(g) % 3 == 0) {
      int k = (int)(testutil_next(g) % 3);
      seg[2 * ns] = del.tri[3 * t + k], seg[2 * ns + 1] = del.tri[3 * t + (k + 1) % 3], ns++;
    }
  *served += tdc_compare(p, n, seg, ns, &del, first);
  for (size_t s = 0; s < 2; s++) {   /* one or two random segments */
    for (size_t k = 0; k < 2 * (s + 1); k++) seg[k] = (uint32_t)(testutil_next(g) % n);
    if (seg[0] == seg[1] || (s && seg[2] == seg[3])) continue;
    int ok = tdc_compare(p, n, seg, s + 1, &del, first);
    *served += ok, *refused += !ok;
  }
  paradigm_result_free(&del);
}

static void test_sets(void **state) {
  (void)state;
  testutil_rng g = {262};
  int sets = testutil_reps(1500), served = 0, refused = 0;
  for (int s = 0; s < sets; s++) tdc_set(s % 3, &g, &served, &refused);
  print_message("dc-constrained: %d runs served, %d refused\n", served, refused);
  assert_true(served > sets && refused > sets / 4);
}

static void test_refusals(void **state) {
  (void)state;
  const geom_point sq[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.2}};
  const uint32_t self[] = {1, 1}, diag[] = {0, 2}, side[] = {0, 1};
  char err[512];
  paradigm_result res;
  assert_int_equal(tdc_run("dc-constrained", sq, 5, self, 1, &res, err, sizeof err), -1);
  assert_non_null(strstr(err, "segment 0 joins a point to itself"));
  assert_int_equal(tdc_run("dc-constrained", sq, 5, diag, 1, &res, err, sizeof err), -1);
  assert_non_null(strstr(err, "segment 0 is no edge"));
  assert_null(strchr(err, '\n'));
  assert_int_equal(tdc_run("dc-constrained", sq, 5, side, 1, &res, err, sizeof err), 0);
  paradigm_result_free(&res);
  rule es;
  assert_int_equal(rule_parse("ES:square", &es, err, sizeof err), 0);
  paradigm_input in = {.p = sq, .n = 5, .r = &es, .problem = PARADIGM_CONSTRAINED,
                       .segments = side, .nsegments = 1, .threads = 1};
  assert_int_equal(paradigm_run(paradigm_find("dc-constrained"), &in, &res, err, sizeof err),
                   -1);
  assert_non_null(strstr(err, "needs the rule DT"));
  rule dt = rule_delaunay();
  in.r = &dt, in.problem = PARADIGM_DELAUNAY;
  assert_int_equal(paradigm_run(paradigm_find("dc-constrained"), &in, &res, err, sizeof err),
                   -1);
  assert_non_null(strstr(err, "dc-vertical"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_sets),
    cmocka_unit_test(test_refusals),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
