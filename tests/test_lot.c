/*
** test_lot.c: locally optimal triangulations of point sets (lot/).
**
** Every result is re-verified by lot_check, which shares nothing with the
** algorithms: the Delaunay rule by the exact empty-circle test on every
** interior edge, the other rules by rule_eval on each strictly convex
** quadrilateral, the structure by orientation and Euler's count
** T = 2n - h - 2.  The thesis's theorems 6 and 7 give exact flip counts and
** bounds; GOT (an independent dynamic programme) and the convex-polygon
** Delaunay triangulation check DT-equivalent rules in convex position.
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

#include "got.h"
#include "lot.h"
#include "measure.h"
#include "rule.h"
#include "sampler.h"
#include "testutil.h"

static int tu_tri_cmp(const void *x, const void *y) {
  const uint32_t *a = x, *b = y;
  for (int i = 0; i < 3; i++)
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  return 0;
}

static rule tl_rule(const char *name) {
  rule r;
  char err[256];
  if (rule_parse(name, &r, err, sizeof err) != 0) fail_msg("rule %s: %s", name, err);
  return r;
}

static geom_point *tl_points(sampler_points_kind k, uint64_t seed, size_t n) {
  geom_point *p = malloc(n * sizeof *p);
  assert_non_null(p);
  sampler_points(k, seed, n, p);
  return p;
}

/* Build, check structure and local optimality, return the triangles. */
static lot *tl_build(const geom_point *p, size_t n, const lot_options *o, uint32_t **tri) {
  lot *L;
  char err[256];
  if (lot_build(&L, p, n, o, err, sizeof err) != 0) fail_msg("lot_build: %s", err);
  const lot_stats *st = lot_get_stats(L);
  *tri = malloc(3 * st->triangles * sizeof **tri);
  assert_non_null(*tri);
  lot_get_triangles(L, *tri);
  return L;
}

static void tl_assert_lot(const geom_point *p, size_t n, const lot *L, const uint32_t *tri,
                          const rule *r, const char *what) {
  const lot_stats *st = lot_get_stats(L);
  lot_check_result c;
  assert_int_equal(lot_check(p, n, tri, st->triangles, r, &c), 0);
  if (!c.valid || c.not_optimal != 0 || st->status != LOT_CONVERGED)
    fail_msg("%s, rule %s: valid %d, %zu of %zu interior edges not optimal (first %u-%u), "
             "status %d", what, r->name, c.valid, c.not_optimal, c.interior_edges,
             c.bad_edge[0], c.bad_edge[1], (int)st->status);
  /* Euler with every distinct point a vertex: T = 2n - h - 2. */
  assert_int_equal(st->triangles, 2 * st->distinct - st->hull - 2);
  assert_int_equal(c.boundary_edges, st->hull);
}

static void test_dt_random_sets(void **state) {
  (void)state;
  rule dt = rule_delaunay();
  static const sampler_points_kind kinds[] = {SAMPLER_UNIFORM, SAMPLER_NORMAL, SAMPLER_DISC};
  static const lot_order orders[] = {LOT_ORDER_SPATIAL, LOT_ORDER_RANDOM, LOT_ORDER_INPUT};
  for (int k = 0; k < 3; k++)
    for (uint64_t seed = 1; seed <= 3; seed++) {
      size_t n = 500 + 700 * (size_t)seed;
      geom_point *p = tl_points(kinds[k], seed, n);
      for (int alg = 0; alg < 4; alg++) {
        lot_options o;
        lot_options_init(&o, &dt);
        if (alg < 3) o.order = orders[alg];
        else o.algorithm = LOT_FLIP;
        uint32_t *tri;
        lot *L = tl_build(p, n, &o, &tri);
        assert_int_equal(lot_get_stats(L)->duplicates, 0);
        tl_assert_lot(p, n, L, tri, &dt, sampler_points_name(kinds[k]));
        free(tri);
        lot_free(L);
      }
      free(p);
    }
}

static void test_dt_grid_and_circle(void **state) {
  (void)state;
  rule dt = rule_delaunay();
  static const sampler_points_kind kinds[] = {SAMPLER_GRID, SAMPLER_CIRCLE};
  for (int k = 0; k < 2; k++)
    for (int alg = 0; alg < 2; alg++) {
      size_t n = 900;
      geom_point *p = tl_points(kinds[k], 7, n);
      lot_options o;
      lot_options_init(&o, &dt);
      o.algorithm = alg ? LOT_FLIP : LOT_INCREMENTAL;
      uint32_t *tri;
      lot *L = tl_build(p, n, &o, &tri);
      tl_assert_lot(p, n, L, tri, &dt, sampler_points_name(kinds[k]));
      if (kinds[k] == SAMPLER_GRID) assert_int_equal(lot_get_stats(L)->hull, 4 * 29);
      free(tri);
      lot_free(L);
      free(p);
    }
}

/* Theorem 6: inserting (i, i^2), i = n .. 1, in that order takes exactly
** (n-2)(n-3)/2 Delaunay flips. */
static void test_theorem6_parabola(void **state) {
  (void)state;
  rule dt = rule_delaunay();
  for (size_t n = 3; n <= 120; n += 9) {
    geom_point *p = tl_points(SAMPLER_PARABOLA, 1, n);
    lot_options o;
    lot_options_init(&o, &dt);
    o.order = LOT_ORDER_INPUT;
    uint32_t *tri;
    lot *L = tl_build(p, n, &o, &tri);
    assert_int_equal(lot_get_stats(L)->flips, (n - 2) * (n - 3) / 2);
    tl_assert_lot(p, n, L, tri, &dt, "parabola");
    free(tri);
    lot_free(L);
    free(p);
  }
}

/* Theorem 7: the flip algorithm for DT from any triangulation needs at
** most (n-2)(n-3)/2 flips: from the sweep, and from the LOTs of other
** rules (lot_reflip). */
static void test_theorem7_bound(void **state) {
  (void)state;
  rule dt = rule_delaunay();
  static const char *const starts[] = {"P_1", "-alpha_-inf", "a_inf", "-A_1"};
  for (uint64_t seed = 1; seed <= 4; seed++) {
    size_t n = 60 * (size_t)seed;
    geom_point *p = tl_points(seed % 2 ? SAMPLER_UNIFORM : SAMPLER_PARABOLA, seed, n);
    uint64_t bound = (uint64_t)(n - 2) * (n - 3) / 2;
    lot_options o;
    lot_options_init(&o, &dt);
    o.algorithm = LOT_FLIP;
    uint32_t *tri;
    lot *L = tl_build(p, n, &o, &tri);
    assert_true(lot_get_stats(L)->flips <= bound);
    tl_assert_lot(p, n, L, tri, &dt, "flip from the sweep");
    free(tri);
    lot_free(L);
    for (int s = 0; s < 4; s++) {
      rule r = tl_rule(starts[s]);
      lot_options os;
      lot_options_init(&os, &r);
      L = tl_build(p, n, &os, &tri);
      free(tri);
      assert_int_equal(lot_reflip(L, &o), 0);
      const lot_stats *st = lot_get_stats(L);
      assert_true(st->flips <= bound);
      tri = malloc(3 * st->triangles * sizeof *tri);
      lot_get_triangles(L, tri);
      tl_assert_lot(p, n, L, tri, &dt, starts[s]);
      free(tri);
      lot_free(L);
    }
    free(p);
  }
}

/* measure_fields is right both ways: a triangle made with only the fields
** a measure is said to read gives the same value bit for bit (the others
** are NaN), and leaving out any one of them changes it, on random
** triangles of every shape. */
static int tlot_fields_agree(int m, unsigned fields, testutil_rng *g) {
  for (int k = 0; k < 2000; k++) {
    geom_point p[3];
    for (int i = 0; i < 3; i++)
      p[i] = (geom_point){testutil_uniform(g), (k % 3 ? 1e-3 : 1) * testutil_uniform(g)};
    if (geom_orient(p[0], p[1], p[2]) == 0) continue;
    geom_tri a, b;
    geom_tri_make(&a, p[0], p[1], p[2]);
    geom_tri_make_fields(&b, p[0], p[1], p[2], fields);
    double va = measure_eval(m, &a), vb = measure_eval(m, &b);
    if (memcmp(&va, &vb, sizeof va) != 0) return 0;
  }
  return 1;
}

static void test_fields_list(void **state) {
  (void)state;
  testutil_rng g = {77};
  for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++) {
    unsigned f = measure_fields(m);
    if (!tlot_fields_agree(m, f, &g))
      fail_msg("measure %s: values differ with fields %#x only", measure_get(m)->name, f);
    for (unsigned bit = 1; bit < GEOM_F_ALL; bit <<= 1)
      if ((f & bit) && tlot_fields_agree(m, f & ~bit, &g))
        fail_msg("measure %s: field group %#x is listed but not read", measure_get(m)->name, bit);
  }
  assert_int_equal(measure_fields(MEASURE_BUILTIN_COUNT), GEOM_F_ALL);   /* user measures */
}

/* Every built-in measure with every joint it admits, both algorithms, on
** small sets: random points, and a grid (exactly collinear points: points
** inserted on an edge, whose halves a rule may flip; a bug once left
** them unexamined).  The result is locally optimal. */
static void test_every_rule_locally_optimal(void **state) {
  (void)state;
  for (int set = 0; set < 2; set++) {
  size_t n = set ? 64 : 90;
  geom_point *p = tl_points(set ? SAMPLER_GRID : SAMPLER_DISC, 11, n);
  if (set)   /* shear the grid: no longer cocircular, still collinear rows */
    for (size_t i = 0; i < n; i++) p[i].x += 0.25 * p[i].y + 0.001 * p[i].y * p[i].y;
  int rules = 0;
  for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++)
    for (int j = 0; j < JOINT_COUNT; j++) {
      rule r;
      char err[256];
      if (rule_triangle(m, (joint_id)j, &r, err, sizeof err) != 0) continue;
      for (int alg = 0; alg < 2; alg++) {
        lot_options o;
        lot_options_init(&o, &r);
        o.algorithm = alg ? LOT_FLIP : LOT_INCREMENTAL;
        uint32_t *tri;
        lot *L = tl_build(p, n, &o, &tri);
        tl_assert_lot(p, n, L, tri, &r, alg ? "flip" : "incremental");
        free(tri);
        lot_free(L);
      }
      rules++;
    }
  assert_true(rules >= 100);
  free(p);
  }
}

/* Points in convex position: the LOT of each rule proved equal to DT on
** convex quadrilaterals is the Delaunay triangulation, and GOT. */
static void test_convex_dt_equivalent(void **state) {
  (void)state;
  static const char *const names[] = {"R_-inf", "R_-1", "R_0", "R_1", "R_2", "R_inf",
                                      "-alpha_inf", "-r_1", "abc_1", "-r/R_1", "-r2/A_0"};
  rule dt = rule_delaunay();
  for (uint64_t seed = 1; seed <= 6; seed++) {
    size_t n = 8 + 4 * (size_t)seed;
    geom_point *p = malloc(n * sizeof *p);
    sampler_rng g;
    sampler_seed(&g, seed, 99);
    assert_int_equal(sampler_vector(&g, n, p), 0);
    got_triangle *gd = malloc(n * sizeof *gd);
    int unique;
    assert_int_equal(got_delaunay(p, n, gd, &unique), 0);
    assert_true(unique);
    uint32_t *dtri = malloc(3 * n * sizeof *dtri);
    for (size_t t = 0; t < n - 2; t++) {
      dtri[3 * t] = (uint32_t)gd[t].i;
      dtri[3 * t + 1] = (uint32_t)gd[t].k;
      dtri[3 * t + 2] = (uint32_t)gd[t].j;
    }
    for (size_t s = 0; s <= sizeof names / sizeof names[0]; s++) {
      rule r = s == 0 ? dt : tl_rule(names[s - 1]);
      lot_options o;
      lot_options_init(&o, &r);
      uint32_t *tri;
      lot *L = tl_build(p, n, &o, &tri);
      assert_int_equal(lot_get_stats(L)->triangles, n - 2);
      lot_diff d;
      assert_int_equal(lot_compare(tri, n - 2, dtri, n - 2, &d), 0);
      if (d.triangles_common != n - 2) fail_msg("%s: LOT != DT (seed %llu)", r.name,
                                                (unsigned long long)seed);
      if (r.kind == RULE_TRIANGLE) {
        got_result res;
        got_options go = {1, RULE_DEFAULT_TIE_EPS};
        char err[256];
        assert_int_equal(got_solve(p, n, &r, &go, &res, err, sizeof err), 0);
        uint32_t *gt = malloc(3 * n * sizeof *gt);
        for (size_t t = 0; t < n - 2; t++) {
          gt[3 * t] = (uint32_t)res.tri[t].i;
          gt[3 * t + 1] = (uint32_t)res.tri[t].k;
          gt[3 * t + 2] = (uint32_t)res.tri[t].j;
        }
        assert_int_equal(lot_compare(tri, n - 2, gt, n - 2, &d), 0);
        /* A unique GOT is the LOT; a tied one (min and max joints) has the
        ** LOT's total, the LOT being one of the optimal triangulations. */
        if (res.unique && d.triangles_common != n - 2) fail_msg("%s: LOT != GOT", r.name);
        double *b = malloc((n - 2) * sizeof *b);
        lot_get_badness(p, tri, n - 2, &r, b);
        int sg = measure_get(r.measure)->sign;
        double total = joint_identity(r.joint, sg);
        for (size_t t = 0; t < n - 2; t++) total = joint_apply(r.joint, sg, total, b[t]);
        TESTUTIL_NEAR(total, res.total, 1e-12, 0);
        free(b);
        free(gt);
        got_result_free(&res);
      }
      free(tri);
      lot_free(L);
    }
    free(dtri);
    free(gd);
    free(p);
  }
}

/* A rule that always wants the other diagonal: a cycle, found at once. */
static rule_choice tl_always_flip(const geom_point q[4], rule_choice current, void *ctx) {
  (void)q;
  (void)ctx;
  return current == RULE_AC ? RULE_BD : RULE_AC;
}

static void test_always_flip_is_a_cycle(void **state) {
  (void)state;
  size_t n = 200;
  geom_point *p = tl_points(SAMPLER_UNIFORM, 3, n);
  rule dt = rule_delaunay();
  for (int alg = 0; alg < 2; alg++) {
    lot_options o;
    lot_options_init(&o, &dt);
    o.decide = tl_always_flip;
    o.algorithm = alg ? LOT_FLIP : LOT_INCREMENTAL;
    lot *L;
    char err[256];
    assert_int_equal(lot_build(&L, p, n, &o, err, sizeof err), 0);
    const lot_stats *st = lot_get_stats(L);
    assert_int_equal(st->status, LOT_CYCLE);
    assert_int_equal(st->cycle_length, 2);
    assert_true(st->flips <= 2);
    assert_int_equal(st->cycle_quads, 2);
    /* the cycle flips one quadrilateral and back: the same four points */
    uint32_t sum0 = 0, sum1 = 0, x0 = 0, x1 = 0;
    for (int j = 0; j < 4; j++) {
      sum0 += st->cycle_quad[0][j];
      sum1 += st->cycle_quad[1][j];
      x0 ^= st->cycle_quad[0][j] * 2654435761u;
      x1 ^= st->cycle_quad[1][j] * 2654435761u;
    }
    assert_int_equal(sum0, sum1);
    assert_int_equal(x0, x1);
    /* still a triangulation of every point */
    uint32_t *tri = malloc(3 * st->triangles * sizeof *tri);
    lot_get_triangles(L, tri);
    lot_check_result c;
    assert_int_equal(lot_check(p, n, tri, st->triangles, &dt, &c), 0);
    assert_true(c.valid);
    free(tri);
    lot_free(L);
  }
  free(p);
}

/* The budget stops a run and still leaves a triangulation. */
static void test_budget(void **state) {
  (void)state;
  size_t n = 100;
  geom_point *p = tl_points(SAMPLER_PARABOLA, 1, n);
  rule dt = rule_delaunay();
  lot_options o;
  lot_options_init(&o, &dt);
  o.order = LOT_ORDER_INPUT;
  o.max_flips = 50;
  lot *L;
  char err[256];
  assert_int_equal(lot_build(&L, p, n, &o, err, sizeof err), 0);
  const lot_stats *st = lot_get_stats(L);
  assert_int_equal(st->status, LOT_BUDGET);
  assert_int_equal(st->flips, 50);
  uint32_t *tri = malloc(3 * st->triangles * sizeof *tri);
  lot_get_triangles(L, tri);
  lot_check_result c;
  assert_int_equal(lot_check(p, n, tri, st->triangles, &dt, &c), 0);
  assert_true(c.valid);
  assert_true(c.not_optimal > 0);
  free(tri);
  lot_free(L);
  free(p);
}

/* Rotating the input by 90 degrees ((x, y) -> (-y, x), exact) gives the
** same triangles by index: DT with the default order (unique for random
** points), and a triangle rule in input and random order. */
static void test_rotation(void **state) {
  (void)state;
  size_t n = 3000;
  geom_point *p = tl_points(SAMPLER_NORMAL, 5, n), *q = malloc(n * sizeof *q);
  for (size_t i = 0; i < n; i++) q[i] = (geom_point){-p[i].y, p[i].x};
  static const char *const names[] = {"DT", "P_1", "-alpha_-inf", "R_inf"};
  for (int s = 0; s < 4; s++) {
    rule r = tl_rule(names[s]);
    lot_options o;
    lot_options_init(&o, &r);
    if (s == 1) o.order = LOT_ORDER_INPUT;
    if (s >= 2) o.order = LOT_ORDER_RANDOM;
    uint32_t *ta, *tb;
    lot *A = tl_build(p, n, &o, &ta), *B = tl_build(q, n, &o, &tb);
    size_t nt = lot_get_stats(A)->triangles;
    assert_int_equal(nt, lot_get_stats(B)->triangles);
    assert_memory_equal(ta, tb, 3 * nt * sizeof *ta);
    free(ta);
    free(tb);
    lot_free(A);
    lot_free(B);
  }
  free(p);
  free(q);
}

/* Duplicates merged (indices of the first occurrence), collinear points
** on the hull and inside kept as vertices. */
static void test_duplicates_and_collinear(void **state) {
  (void)state;
  geom_point p[] = {{1, 1}, {0, 0}, {2, 0}, {1, 1}, {4, 0}, {0, 0}, {2, 2}, {3, 0}, {2, 0},
                    {1, 0}, {1, 1}};
  size_t n = sizeof p / sizeof p[0];
  rule dt = rule_delaunay();
  for (int alg = 0; alg < 2; alg++)
    for (int ord = 0; ord < 3; ord++) {
      lot_options o;
      lot_options_init(&o, &dt);
      o.algorithm = alg ? LOT_FLIP : LOT_INCREMENTAL;
      o.order = (lot_order)ord;
      uint32_t *tri;
      lot *L = tl_build(p, n, &o, &tri);
      const lot_stats *st = lot_get_stats(L);
      assert_int_equal(st->duplicates, 4);
      assert_int_equal(st->distinct, 7);
      /* all on the boundary: (0,0) (1,0) (2,0) (3,0) (4,0) (2,2) (1,1) */
      assert_int_equal(st->hull, 7);
      assert_int_equal(st->triangles, 2 * 7 - 7 - 2);
      for (size_t i = 0; i < 3 * st->triangles; i++) {
        uint32_t v = tri[i];
        assert_true(v != 3 && v != 5 && v != 8 && v != 10);   /* later copies */
      }
      tl_assert_lot(p, n, L, tri, &dt, "duplicates");
      free(tri);
      lot_free(L);
    }
}

/* lot_get_triangles' order is qsort's (sorted, each triangle from its
** smallest index), and lot_neighbors agrees with a brute force over all
** pairs of triangles: across the edge opposite vertex k lies the one other
** triangle holding both its ends, or none on the hull (one per hull edge).
** Sets with a vertex of high degree (parabola, circle: the sort's qsort
** buckets) and duplicates included. */
static void test_triangle_order_and_neighbors(void **state) {
  (void)state;
  const sampler_points_kind kinds[] = {SAMPLER_UNIFORM, SAMPLER_PARABOLA, SAMPLER_CIRCLE,
                                       SAMPLER_GRID};
  for (size_t q = 0; q < sizeof kinds / sizeof *kinds; q++) {
    size_t n = 150;
    geom_point *p = tl_points(kinds[q], 3, n);
    p[7] = p[3];   /* a duplicate */
    rule r = rule_delaunay();
    lot_options o;
    lot_options_init(&o, &r);
    uint32_t *tri;
    lot *L = tl_build(p, n, &o, &tri);
    size_t m = lot_get_stats(L)->triangles, hull = lot_get_stats(L)->hull;
    uint32_t *sorted = malloc(3 * m * sizeof *sorted);
    int32_t *nb = malloc(3 * m * sizeof *nb);
    assert_non_null(sorted);
    assert_non_null(nb);
    memcpy(sorted, tri, 3 * m * sizeof *tri);
    qsort(sorted, m, 3 * sizeof *sorted, tu_tri_cmp);
    assert_memory_equal(sorted, tri, 3 * m * sizeof *tri);
    assert_int_equal(lot_neighbors(tri, m, n, nb), 0);
    size_t boundary = 0;
    for (size_t t = 0; t < m; t++)
      for (int k = 0; k < 3; k++) {
        uint32_t u = tri[3 * t + (k + 1) % 3], v = tri[3 * t + (k + 2) % 3];
        int32_t want = -1;
        for (size_t s = 0; s < m; s++) {
          int hu = 0, hv = 0;
          for (int c = 0; c < 3; c++) hu |= tri[3 * s + c] == u, hv |= tri[3 * s + c] == v;
          if (s != t && hu && hv) want = (int32_t)s;
        }
        assert_int_equal(nb[3 * t + k], want);
        boundary += want < 0;
      }
    assert_int_equal(boundary, hull);
    lot_free(L);
    free(tri);
    free(sorted);
    free(nb);
    free(p);
  }
}

static void test_bad_input(void **state) {
  (void)state;
  rule dt = rule_delaunay();
  lot_options o;
  lot_options_init(&o, &dt);
  lot *L;
  char err[256];
  geom_point two[] = {{0, 0}, {1, 1}};
  assert_int_equal(lot_build(&L, two, 2, &o, err, sizeof err), -1);
  assert_non_null(strstr(err, "2 points"));
  geom_point line[] = {{0, 0}, {1, 1}, {2, 2}, {3, 3}, {0, 0}};
  assert_int_equal(lot_build(&L, line, 5, &o, err, sizeof err), -1);
  assert_non_null(strstr(err, "collinear"));
  geom_point same[] = {{1, 2}, {1, 2}, {1, 2}};
  assert_int_equal(lot_build(&L, same, 3, &o, err, sizeof err), -1);
  assert_non_null(strstr(err, "equal"));
  geom_point nan[] = {{0, 0}, {1, 0}, {NAN, 1}};
  assert_int_equal(lot_build(&L, nan, 3, &o, err, sizeof err), -1);
  assert_non_null(strstr(err, "point 2"));
  geom_point big[] = {{0, 0}, {1, 0}, {0, 10 * GEOM_COORD_MAX}};
  assert_int_equal(lot_build(&L, big, 3, &o, err, sizeof err), -1);
  assert_non_null(strstr(err, "out of range"));
  geom_point tiny[] = {{0, 0}, {1, 0}, {0, GEOM_COORD_MIN / 10}};
  assert_int_equal(lot_build(&L, tiny, 3, &o, err, sizeof err), -1);
  assert_non_null(strstr(err, "point 2"));
  assert_true(testutil_one_line(err) || strchr(err, '\n') == NULL);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_dt_random_sets),
    cmocka_unit_test(test_dt_grid_and_circle),
    cmocka_unit_test(test_theorem6_parabola),
    cmocka_unit_test(test_theorem7_bound),
    cmocka_unit_test(test_fields_list),
    cmocka_unit_test(test_every_rule_locally_optimal),
    cmocka_unit_test(test_convex_dt_equivalent),
    cmocka_unit_test(test_always_flip_is_a_cycle),
    cmocka_unit_test(test_budget),
    cmocka_unit_test(test_rotation),
    cmocka_unit_test(test_duplicates_and_collinear),
    cmocka_unit_test(test_triangle_order_and_neighbors),
    cmocka_unit_test(test_bad_input),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
