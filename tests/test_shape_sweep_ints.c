/*
** test_shape_sweep_ints.c: the sweep on grids and integer coordinates
** (issue 35): its exact keys in integers, its triangles on sites in
** special position, and what it costs there.
**
** 1. Every integer comparison of the circle's keys (key_cmp, whose integer
**    stage decides first, and a run's frame keys, ikey and ikey_cmp)
**    equals GMP's: the ellipse arithmetic with the circle's form x^2 +
**    y^2, which has no integer stage.  Triangles: random small-integer
**    ones, translates (equal keys), triangles of one circle through many
**    integer points (equal keys with other centres' formulas), circles of
**    different centres and radii with equal keys, against sites' x, all
**    scaled by powers of two, by 3, and moved far from the origin.  A
**    polygon's integer records (keys for K with integer corners, translates
**    for every K) against its key_cmp.
** 2. The sweep's triangles equal the incremental algorithm's, index for
**    index, for DT and a shape of every kind (square, diamond, hexagon,
**    triangle, pentagon, rectangle, ellipse): many small seeded sets
**    (grids, scaled lattices, integer points on circles, collinear rows,
**    duplicate-heavy draws from small grids) and a few medium ones.
** 3. Guards: the DT sweep of the 100 x 100 grid makes no GMP call (neither
**    the sweep's primitives nor the predicates) and no flip after the
**    sweep, nor do the sweeps of six polygons (square, diamond, triangle,
**    a rectangle, hexagon, octagon) on the 30 x 30 grid; the CDT of a
**    rotated grid (sampler_pslg_grid) makes no GMP call.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lot.h"
#include "rule.h"
#include "sampler.h"
#include "shape.h"
#include "shape_sweep_internal.h"
#include "testutil.h"

static const shape_sweep_conic ti_form = {1, 0, 1};

/* ---- 1. the integer keys against GMP ----------------------------------- */

static size_t ti_frame_cmps, ti_int_cmps;

/* key(t) against key(u) (t or u NULL: the site's x), by the circle's
** table and by its frame keys when the six points fit one, against GMP. */
static void ti_cmp(const geom_point *t, double tx, const geom_point *u, double ux) {
  const shape_sweep *s = &shape_sweep_circle;
  int want = shape_sweep_conic_key_cmp(&ti_form, t, tx, u, ux);
  int got = s->key_cmp(s->ctx, t, tx, u, ux);
  if (got != want) fail_msg("key_cmp %d, GMP %d", got, want);
  ti_int_cmps++;
  if (s->frame == NULL) return;
  geom_point pts[6];
  size_t n = 0;
  for (int k = 0; k < 2; k++) {
    const geom_point *p = k ? u : t;
    for (int i = 0; i < 3 && p != NULL; i++) pts[n++] = p[i];
    if (p == NULL) pts[n++] = (geom_point){k ? ux : tx, 0};
  }
  shape_sweep_frame f;
  if (!s->frame(s->ctx, pts, n, &f)) return;
  shape_sweep_ikey a, b;
  s->ikey(s->ctx, &f, t, tx, &a);
  s->ikey(s->ctx, &f, u, ux, &b);
  int c = s->ikey_cmp(&a, &b);
  if (c != 2 && c != want) fail_msg("ikey_cmp %d, GMP %d", c, want);
  ti_frame_cmps += c != 2;
}

/* Both orders, and t against the sites around its key. */
static void ti_pair(const geom_point t[3], const geom_point u[3]) {
  ti_cmp(t, 0, u, 0);
  ti_cmp(u, 0, t, 0);
  ti_cmp(t, 0, t, 0);
  double lo, hi;
  shape_sweep_circle.key_bounds(NULL, t, &lo, &hi);
  const double xs[3] = {floor(lo), ceil(hi), t[0].x};
  for (int i = 0; i < 3; i++) {
    ti_cmp(t, 0, NULL, xs[i]);
    ti_cmp(NULL, xs[i], t, 0);
  }
}

/* p scaled by s and moved by o: exact for the magnitudes used here. */
static void ti_map(const geom_point *p, geom_point *q, double s, double o) {
  for (int i = 0; i < 3; i++) q[i] = (geom_point){p[i].x * s + o, p[i].y * s - o};
}

static void ti_pair_scaled(const geom_point t[3], const geom_point u[3]) {
  static const double sc[][2] = {{1, 0}, {0x1p-20, 0}, {0x1p30, 0}, {3, 0}, {1, 0x1p40},
                                 {0.5, 1e6}};
  for (size_t k = 0; k < sizeof sc / sizeof *sc; k++) {
    geom_point a[3], b[3];
    ti_map(t, a, sc[k][0], sc[k][1]);
    ti_map(u, b, sc[k][0], sc[k][1]);
    if (geom_orient(a[0], a[1], a[2]) != 0 && geom_orient(b[0], b[1], b[2]) != 0) ti_pair(a, b);
  }
}

static double ti_int(sampler_rng *g, int64_t r) {
  return (double)((int64_t)(sampler_next(g) % (uint64_t)(2 * r + 1)) - r);
}

/* Random triangles of integers within r, with a translate of each. */
static void test_random_keys(void **state) {
  (void)state;
  sampler_rng g;
  sampler_seed(&g, 35, 0);
  static const int64_t rs[] = {2, 5, 50, 1000, 1 << 19, (int64_t)1 << 30};
  for (size_t i = 0; i < sizeof rs / sizeof *rs; i++)
    for (int k = 0; k < 300; k++) {
      geom_point t[3], u[3];
      for (int j = 0; j < 3; j++) {
        t[j] = (geom_point){ti_int(&g, rs[i]), ti_int(&g, rs[i])};
        u[j] = (geom_point){ti_int(&g, rs[i]), ti_int(&g, rs[i])};
      }
      if (geom_orient(t[0], t[1], t[2]) == 0 || geom_orient(u[0], u[1], u[2]) == 0) continue;
      ti_pair_scaled(t, u);
      double dy = ti_int(&g, rs[i]);
      for (int j = 0; j < 3; j++) u[j] = (geom_point){t[j].x, t[j].y + dy};
      ti_pair_scaled(t, u);
    }
  printf("integer comparisons %zu, decided by frame keys %zu\n", ti_int_cmps, ti_frame_cmps);
  assert_true(ti_frame_cmps > ti_int_cmps / 4);
}

/* The twelve integer points of x^2 + y^2 = 25 around (cx, cy): every pair
** of their triangles has equal keys; and circles of other centres and
** radii whose keys are equal all the same (radius 5 about 0, radius 4
** about (1, 0), radius 1 about (4, 0): key 5). */
static void test_equal_keys(void **state) {
  (void)state;
  static const int c25[12][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3},
                                 {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  geom_point t[3], u[3];
  for (int a = 0; a < 12; a++)
    for (int b = 0; b < 12; b += 5)
      for (int c = 1; c < 12; c += 3) {
        int k[3] = {a, (a + b + 1) % 12, (a + c + 6) % 12};
        int l[3] = {(a + 2) % 12, (a + 5) % 12, (a + 9) % 12};
        for (int j = 0; j < 3; j++) {
          t[j] = (geom_point){c25[k[j]][0] + 7, c25[k[j]][1] - 2};
          u[j] = (geom_point){c25[l[j]][0] + 7, c25[l[j]][1] - 2};
        }
        if (geom_orient(t[0], t[1], t[2]) == 0) continue;
        assert_int_equal(shape_sweep_conic_key_cmp(&ti_form, t, 0, u, 0), 0);
        ti_pair_scaled(t, u);
      }
  const geom_point r5[3] = {{5, 0}, {0, -5}, {-5, 0}}, r4[3] = {{5, 0}, {1, -4}, {-3, 0}};
  const geom_point r1[3] = {{5, 0}, {4, -1}, {3, 0}};
  assert_int_equal(shape_sweep_conic_key_cmp(&ti_form, r5, 0, r4, 0), 0);
  ti_pair_scaled(r5, r4);
  ti_pair_scaled(r4, r1);
  ti_pair_scaled(r5, r1);
}

/* A polygon's integer records (integer keys of homothets of K with
** corners of few fraction bits, translate records of the other keys, over
** the frame of the six sites) against its key_cmp (GMP), on random integer
** triangles and their translates, for seven polygons: for each, most pairs
** must be compared in integers (the hexagon's, octagon's and pentagon's
** corners have 20 fraction bits, their keys reduced N / D); one triangle in
** seven spans the whole frame, where reduced keys may not fit. */
static void test_polygon_keys(void **state) {
  (void)state;
  static const char *const specs[] = {"square", "diamond", "triangle", "poly:0 0;2 0;2 1;0 1",
                                      "hexagon", "ngon:5", "octagon"};
  sampler_rng g;
  sampler_seed(&g, 36, 0);
  for (size_t i = 0; i < sizeof specs / sizeof *specs; i++) {
    size_t known = 0, all = 0;
    shape *k;
    char err[256];
    if (shape_parse(specs[i], &k, err, sizeof err) != 0) fail_msg("%s: %s", specs[i], err);
    shape_sweep_ctx c;
    size_t special = 0;
    shape_sweep s;
    shape_sweep_make(k, &c, &special, &s);
    assert_non_null(s.frame);
    for (int n = 0; n < 2000; n++) {
      geom_point pts[6];
      int64_t r = n % 7 == 6 ? (1 << 19) - 1 : n % 2 ? 3 : 40;   /* the frame's edge too */
      for (int j = 0; j < 6; j++) pts[j] = (geom_point){ti_int(&g, r), ti_int(&g, r)};
      if (n % 3 == 0)
        for (int j = 3; j < 6; j++) pts[j] = (geom_point){pts[j - 3].x, pts[j - 3].y + 5};
      if (!s.closes(s.ctx, pts[0], pts[1], pts[2]) || !s.closes(s.ctx, pts[3], pts[4], pts[5]))
        continue;
      shape_sweep_frame f;
      assert_true(s.frame(s.ctx, pts, 6, &f));
      shape_sweep_ikey a, b;
      s.ikey(s.ctx, &f, pts, 0, &a);
      s.ikey(s.ctx, &f, pts + 3, 0, &b);
      int want = s.key_cmp(s.ctx, pts, 0, pts + 3, 0), got = s.ikey_cmp(&a, &b);
      all++;
      if (got == 2) continue;
      known++;
      if (got != want) fail_msg("%s: ikey_cmp %d, key_cmp %d", specs[i], got, want);
      s.ikey(s.ctx, &f, NULL, pts[4].x, &b);
      got = s.ikey_cmp(&a, &b);
      if (got != 2) assert_int_equal(got, s.key_cmp(s.ctx, pts, 0, NULL, pts[4].x));
    }
    shape_free(k);
    printf("%s keys: %zu of %zu pairs compared in integers\n", specs[i], known, all);
    assert_true(known > all / 2);
  }
}

/* ---- 2. the sweep against the incremental algorithm -------------------- */

static const char *const ti_rules[] = {
  "DT", "ES:square", "ES:diamond", "ES:hexagon", "ES:triangle", "ES:ngon:5",
  "ES:poly:0 0;2 0;2 1;0 1", "ES:ellipse:2 1"};
#define TI_RULES (sizeof ti_rules / sizeof *ti_rules)

/* The sorted triangles of the LOT of p under name by algorithm a (and its
** flips into *flips). */
static uint32_t *ti_build(const char *name, const geom_point *p, size_t n, lot_algorithm a,
                          size_t *nt, uint64_t *flips) {
  rule r;
  char err[256];
  if (rule_parse(name, &r, err, sizeof err) != 0) fail_msg("rule %s: %s", name, err);
  lot_options o;
  lot_options_init(&o, &r);
  o.algorithm = a;
  lot *L;
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) fail_msg("lot_build %s: %s", name, err);
  const lot_stats *st = lot_get_stats(L);
  *nt = st->triangles;
  if (flips != NULL) *flips = st->flips;
  uint32_t *tri = malloc((3 * *nt + 1) * sizeof *tri);
  assert_non_null(tri);
  lot_get_triangles(L, tri);
  assert_int_equal(st->status, LOT_CONVERGED);
  lot_free(L);
  return tri;
}

static void ti_agree(const geom_point *p, size_t n, const char *what, size_t rules) {
  for (size_t r = 0; r < rules; r++) {
    size_t ns, ni;
    uint32_t *s = ti_build(ti_rules[r], p, n, LOT_SWEEP, &ns, NULL);
    uint32_t *i = ti_build(ti_rules[r], p, n, LOT_INCREMENTAL, &ni, NULL);
    if (ns != ni || memcmp(s, i, 3 * ns * sizeof *s) != 0)
      fail_msg("%s, %s, %zu points: the sweep differs from the incremental algorithm",
               ti_rules[r], what, n);
    free(s);
    free(i);
  }
}

/* Sets of n sites from the seed: a grid scaled by s, integer points on
** circles about one centre, collinear rows, and draws from a 5 x 5 grid
** (duplicates). */
static size_t ti_set(int kind, uint64_t seed, geom_point *p) {
  sampler_rng g;
  sampler_seed(&g, seed, 1);
  size_t n = 6 + sampler_next(&g) % 40;
  static const double sc[] = {1, 0x1p-30, 0x1p20, 3, 0.25};
  switch (kind) {
  case 0: {
    double s = sc[seed % 5];
    sampler_points(SAMPLER_GRID, seed, n, p);
    for (size_t k = 0; k < n; k++) p[k] = (geom_point){p[k].x * s, p[k].y * s + 1e6 * s};
    return n;
  }
  case 1: {   /* x^2 + y^2 in {25, 50, 65, 85}: 12, 12, 16, 16 integer points */
    size_t m = 0;
    static const int r2[] = {25, 50, 65, 85};
    for (int x = -10; x <= 10 && m < 60; x++)
      for (int y = -10; y <= 10 && m < 60; y++)
        for (int i = 0; i < 4; i++)
          if (x * x + y * y == r2[i] && sampler_next(&g) % 3 != 0)
            p[m++] = (geom_point){x + 100.0, y};
    return m;
  }
  case 2:   /* rows of 2 to 6 collinear sites */
    for (size_t k = 0; k < n; k++) {
      double row = (double)(k / 5), col = ti_int(&g, 6);
      p[k] = (geom_point){col + (double)(seed % 3) * row, 2 * row};
    }
    return n;
  default:
    for (size_t k = 0; k < n; k++) p[k] = (geom_point){ti_int(&g, 2), ti_int(&g, 2)};
    return n;
  }
}

static int ti_degenerate(const geom_point *p, size_t n) {
  for (size_t k = 2; k < n; k++)
    for (size_t j = 1; j < k; j++)
      if (geom_orient(p[0], p[j], p[k]) != 0) return 0;
  return 1;
}

static void test_small_sets(void **state) {
  (void)state;
  static const char *const kinds[] = {"a scaled grid", "integer points on circles",
                                      "collinear rows", "a draw from a 5 x 5 grid"};
  geom_point p[64];
  for (int kind = 0; kind < 4; kind++)
    for (uint64_t seed = 1; seed <= (uint64_t)testutil_reps(12); seed++) {
      size_t n = ti_set(kind, seed, p);
      if (n >= 3 && !ti_degenerate(p, n)) ti_agree(p, n, kinds[kind], TI_RULES);
    }
}

/* A 900-point grid for every rule, a 10^4-point one for DT. */
static void test_medium_sets(void **state) {
  (void)state;
  geom_point *p = malloc(10000 * sizeof *p);
  assert_non_null(p);
  sampler_points(SAMPLER_GRID, 1, 900, p);
  ti_agree(p, 900, "a 30 x 30 grid", TI_RULES);
  sampler_points(SAMPLER_GRID, 1, 10000, p);
  ti_agree(p, 10000, "a 100 x 100 grid", 1);
  free(p);
}

/* ---- 3. guards --------------------------------------------------------- */

static unsigned long ti_gmp(void) {
  unsigned long n = shape_sweep_gmp_calls();
  for (int p = 0; p < GEOM_PRED_COUNT; p++) n += geom_exact_stage_calls(p, GEOM_STAGE_GMP);
  return n;
}

/* The 100 x 100 grid's DT sweep: no GMP call, no flip after the sweep
** (the sweep's ties need none for DT: flips are of cocircular edges only,
** and the events already made the tie-broken choice here; a change that
** makes either non-zero is a regression of issue 35). */
static void test_grid_guard(void **state) {
  (void)state;
  geom_point *p = malloc(10000 * sizeof *p);
  assert_non_null(p);
  sampler_points(SAMPLER_GRID, 1, 10000, p);
  unsigned long g0 = ti_gmp();
  size_t nt;
  uint64_t flips;
  free(ti_build("DT", p, 10000, LOT_SWEEP, &nt, &flips));
  printf("100 x 100 grid, DT sweep: %lu GMP calls, %llu flips after the sweep\n",
         ti_gmp() - g0, (unsigned long long)flips);
  assert_int_equal(ti_gmp() - g0, 0);
  assert_int_equal(flips, 0);
  assert_int_equal(nt, 2 * 99 * 99);
  free(p);
}

/* Polygons with corners of few fraction bits on the 30 x 30 grid: the
** sweep's own primitives (keys, "above" tests) make no GMP call (the
** shapes' contact tests are shapes/'s, not counted here), and the sweep's
** ties, decided by a fixed order, need no repair flip (docs/lot.md: the
** pentagon's do, one per cell, and is not held to it). */
static void test_polygon_guard(void **state) {
  (void)state;
  geom_point p[900];
  sampler_points(SAMPLER_GRID, 1, 900, p);
  static const char *const names[] = {"ES:square", "ES:diamond", "ES:triangle",
                                      "ES:poly:0 0;2 0;2 1;0 1", "ES:hexagon", "ES:octagon"};
  for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
    unsigned long g0 = shape_sweep_gmp_calls();
    size_t nt;
    uint64_t flips;
    free(ti_build(names[i], p, 900, LOT_SWEEP, &nt, &flips));
    printf("30 x 30 grid, %s sweep: %lu GMP calls of the sweep, %llu repair flips\n", names[i],
           shape_sweep_gmp_calls() - g0, (unsigned long long)flips);
    assert_int_equal(shape_sweep_gmp_calls() - g0, 0);
    assert_int_equal(flips, 0);
  }
}

/* The CDT of a rotated grid with segments along its rows and columns: no
** GMP call either (the predicates' integer stage decides). */
static void test_cdt_grid_guard(void **state) {
  (void)state;
  rule dt;
  char err[256];
  assert_int_equal(rule_parse("DT", &dt, err, sizeof err), 0);
  for (int a = 0; a < 2; a++) {
    sampler_rng g;
    sampler_seed(&g, 3, 0);
    geom_pslg G;
    assert_int_equal(sampler_pslg_grid(&g, 2500, &G), 0);
    lot_options o;
    lot_options_init(&o, &dt);
    o.algorithm = a ? LOT_SWEEP : LOT_INCREMENTAL;
    o.segments = G.seg;
    o.nsegments = G.nseg;
    unsigned long g0 = ti_gmp();
    lot *L;
    if (lot_build(&L, G.pts, G.npts, &o, err, sizeof err) != 0) fail_msg("lot_build: %s", err);
    assert_int_equal(ti_gmp() - g0, 0);
    lot_free(L);
    geom_pslg_free(&G);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_random_keys),  cmocka_unit_test(test_equal_keys),
    cmocka_unit_test(test_polygon_keys),
    cmocka_unit_test(test_small_sets),   cmocka_unit_test(test_medium_sets),
    cmocka_unit_test(test_grid_guard),   cmocka_unit_test(test_polygon_guard),
    cmocka_unit_test(test_cdt_grid_guard),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
