/*
** test_lot_sweep_shape.c: the sweepline algorithm for empty-shape rules
** (lot --algorithm sweep --rule ES:SHAPE).
**
** The sweep shares no decision code with the other two algorithms: they
** flip by shape_decide, the sweep orders events by the exact keys of the
** circumscribing shapes' rightmost points and locates sites by its own
** "above" test.  So the checks are: sweep == incremental == flip as sets
** of triangles on inputs where the rule's triangulation is unique (no four
** sites on one homothet), and lot_check (structure, Euler's count, the
** rule on every interior edge, from scratch) on all of them.  Inputs: the
** samplers of lot, rotated ellipses on grids and circles (no four sites
** on one ellipse there), polygons on generic sites, columns of equal x,
** tiny and huge coordinates, and polygons on sites in special position
** (grids, turned grids, collinear rows, duplicates, corners of homothets),
** where the sweep's ties are repaired by flips with the tie-break (and
** lot_mesh_valid, which vouches for the sweep's mesh there).
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
#include "mesh.h"
#include "rule.h"
#include "sampler.h"
#include "shape.h"
#include "splitmix.h"
#include "testutil.h"

typedef struct tss_result {
  uint32_t *tri;
  size_t ntri;
} tss_result;

/* What the sweeps met, over the whole run (printed at the end), and the
** input being run (for the failure messages). */
static size_t tss_runs, tss_tied, tss_restarts;
static uint64_t tss_repairs;
static const char *tss_input = "";
/* Set while inputs run whose ties the sweep's count may miss (lot.c,
** lot_sweep_mesh: two sites on a line parallel to a side of K): the
** repair flips are then not asserted to be none. */
static int tss_uncounted;

static rule tss_rule(const char *name) {
  rule r;
  char err[256];
  if (rule_parse(name, &r, err, sizeof err) != 0) fail_msg("rule_parse %s: %s", name, err);
  return r;
}

/* Build the LOT of p for rule name with algorithm a; its sorted triangles. */
static tss_result tss_build(const char *name, const geom_point *p, size_t n, lot_algorithm a) {
  rule r = tss_rule(name);
  lot_options o;
  lot_options_init(&o, &r);
  o.algorithm = a;
  lot *L;
  char err[256];
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) fail_msg("lot_build %s: %s", name, err);
  const lot_stats *st = lot_get_stats(L);
  int restarted;
  size_t ties = lot_get_sweep_ties(L, &restarted);
  if (a == LOT_SWEEP) {
    tss_runs++;
    tss_tied += ties > 0;
    tss_restarts += (size_t)restarted;
    tss_repairs += st->flips;
  }
  tss_result res = {malloc(3 * (st->triangles + 1) * sizeof *res.tri), st->triangles};
  assert_non_null(res.tri);
  lot_get_triangles(L, res.tri);
  if (a == LOT_SWEEP && ties == 0 && !tss_uncounted) assert_int_equal(st->flips, 0);
  assert_int_equal(st->status, LOT_CONVERGED);
  lot_free(L);
  return res;
}

/* The sweep's triangulation is one of the rule (lot_check_ties), and the
** tie-broken one where the rule is unique under the tie-break (every
** polygon, and ellipses where no four sites lie on one homothet); then the
** incremental and flip algorithms give the very same triangles. */
static void tss_agree(const char *name, const geom_point *p, size_t n, int unique) {
  tss_result s = tss_build(name, p, n, LOT_SWEEP);
  rule r = tss_rule(name);
  lot_check_result c;
  lot_tie_result tie;
  assert_int_equal(lot_check_ties(p, n, s.tri, s.ntri, &r, &c, &tie), 0);
  assert_true(c.valid);
  if (c.not_optimal != 0) fail_msg("%s, %zu points: %zu edges not optimal", name, n, c.not_optimal);
  if (unique && tie.not_tie_broken != 0)
    fail_msg("%s, %zu points%s%s: %zu ties not tie-broken", name, n, *tss_input ? " of " : "",
             tss_input, tie.not_tie_broken);
  for (int a = 0; a < 2 && unique; a++) {
    tss_result o = tss_build(name, p, n, a == 0 ? LOT_INCREMENTAL : LOT_FLIP);
    if (o.ntri != s.ntri || memcmp(o.tri, s.tri, 3 * s.ntri * sizeof *s.tri) != 0)
      fail_msg("%s, %zu points%s%s: the sweep differs from %s", name, n, *tss_input ? " of " : "",
               tss_input, a == 0 ? "incremental" : "flip");
    free(o.tri);
  }
  free(s.tri);
}

/* Rotated ellipses: no four sites of a grid or of the circle sampler lie
** on one of their homothets, so the triangulation is unique there too. */
static const char *const tss_ellipses[] = {"ES:ellipse:2 1 0.3", "ES:ellipse:3 0.5 1.1",
                                           "ES:ellipse:1 4 -0.7"};

static void test_ellipse_samplers(void **state) {
  (void)state;
  static const size_t ns[] = {3, 4, 7, 30, 500};
  for (size_t e = 0; e < sizeof tss_ellipses / sizeof *tss_ellipses; e++)
    for (int k = 0; k < SAMPLER_POINTS_COUNT; k++)
      for (size_t i = 0; i < sizeof ns / sizeof *ns; i++) {
        geom_point *p = malloc(ns[i] * sizeof *p);
        assert_non_null(p);
        sampler_points((sampler_points_kind)k, 1 + i, ns[i], p);
        tss_agree(tss_ellipses[e], p, ns[i], 1);
        free(p);
      }
}

/* Axis-aligned ellipses and the unit circle on grids: four sites on one
** homothet everywhere (the triangulation is not unique), so only
** lot_check; on uniform points they agree. */
static void test_ellipse_special(void **state) {
  (void)state;
  geom_point p[900];
  const char *names[] = {"ES:ellipse:2 1", "ES:ellipse:1 1", "ES:ellipse:1 3"};
  for (int e = 0; e < 3; e++) {
    sampler_points(SAMPLER_GRID, 1, 900, p);
    tss_agree(names[e], p, 900, 0);
    sampler_points(SAMPLER_UNIFORM, 5, 900, p);
    tss_agree(names[e], p, 900, 1);
  }
}

/* Columns of equal x (the sweep's first-column case and later columns),
** tiny and huge coordinates (the exact fallbacks). */
static void test_ellipse_adversarial(void **state) {
  (void)state;
  geom_point a[40];
  for (int i = 0; i < 20; i++) {
    a[i] = (geom_point){0, i * 0.37};
    a[20 + i] = (geom_point){1, i * 0.41 + 0.05};
  }
  for (size_t e = 0; e < sizeof tss_ellipses / sizeof *tss_ellipses; e++)
    tss_agree(tss_ellipses[e], a, 40, 1);
  const double sc[] = {1e-28, 1e-20, 1e20, 1e28};   /* coordinates within 2^-100 .. 2^100 */
  geom_point p[300];
  for (size_t s = 0; s < sizeof sc / sizeof *sc; s++) {
    sampler_points(SAMPLER_NORMAL, 3, 300, p);
    for (int i = 0; i < 300; i++)
      p[i] = (geom_point){(10 + p[i].x) * sc[s], (10 + p[i].y) * sc[s]};
    tss_agree("ES:ellipse:2 1 0.3", p, 300, 1);
  }
}

/* Polygons: the named ones, a regular heptagon, a quadrilateral and a
** triangle with a vertical right edge (the tie-break's rightmost corner is
** its lower end, and the upper end's rounding shape has the smallest
** infinite keys), a thin slanted quadrilateral. */
static const char *const tss_polygons[] = {
  "ES:square", "ES:diamond", "ES:triangle", "ES:hexagon", "ES:ngon:7",
  "ES:poly:0 0;3 1;2 3;-1 2", "ES:poly:0 0;1 0;1 1", "ES:poly:0 0;5 1;5.5 1.5;0.2 0.3"};

/* Generic sites (no two on a line parallel to a side of K, no four on one
** homothet): the triangles of the incremental and flip algorithms, index
** for index, from 3 sites up. */
static void test_polygon_samplers(void **state) {
  (void)state;
  static const size_t ns[] = {3, 4, 5, 9, 31, 150};
  const sampler_points_kind ks[] = {SAMPLER_UNIFORM, SAMPLER_NORMAL, SAMPLER_DISC,
                                    SAMPLER_CIRCLE};
  for (size_t e = 0; e < sizeof tss_polygons / sizeof *tss_polygons; e++)
    for (size_t k = 0; k < sizeof ks / sizeof *ks; k++)
      for (size_t i = 0; i < sizeof ns / sizeof *ns; i++)
        for (uint64_t seed = 1; seed <= (ns[i] < 100 ? 2u : 1u); seed++) {
          geom_point *p = malloc(ns[i] * sizeof *p);
          assert_non_null(p);
          sampler_points(ks[k], seed, ns[i], p);
          tss_agree(tss_polygons[e], p, ns[i], 1);
          free(p);
        }
}

/* Columns of equal x (no other tie for a shape without vertical edges),
** and tiny and huge coordinates. */
static void test_polygon_adversarial(void **state) {
  (void)state;
  geom_point a[40];
  for (int i = 0; i < 20; i++) {
    a[i] = (geom_point){0, i * 0.37};
    a[20 + i] = (geom_point){1, i * 0.41 + 0.05};
  }
  tss_agree("ES:hexagon", a, 40, 1);   /* no vertical side (ngon:7 has one on the left) */
  tss_agree("ES:poly:0 0;3 1;2 3;-1 2", a, 40, 1);
  const double sc[] = {1e-28, 1e-20, 1e20, 1e28};
  geom_point p[300];
  for (size_t s = 0; s < sizeof sc / sizeof *sc; s++) {
    sampler_points(SAMPLER_NORMAL, 3, 300, p);
    for (int i = 0; i < 300; i++)
      p[i] = (geom_point){(10 + p[i].x) * sc[s], (10 + p[i].y) * sc[s]};
    for (size_t e = 0; e < 4; e += 3) tss_agree(tss_polygons[e], p, 300, 1);
  }
}

/* Sites in special position for a polygon (a grid for the square: equal
** keys, sites on lines parallel to its sides), once refused: the sweep
** counts its ties and, after the rule's flips with the tie-break, gives
** the other algorithms' triangles (test_grids and the others below have
** many more such inputs). */
static void test_polygon_special(void **state) {
  (void)state;
  geom_point p[100];
  sampler_points(SAMPLER_GRID, 1, 100, p);
  rule r = tss_rule("ES:square");
  lot_options o;
  lot_options_init(&o, &r);
  o.algorithm = LOT_SWEEP;
  lot *L;
  char err[256];
  assert_int_equal(lot_build(&L, p, 100, &o, err, sizeof err), 0);
  assert_true(lot_get_sweep_ties(L, NULL) > 0);
  lot_free(L);
  for (size_t e = 0; e < sizeof tss_polygons / sizeof *tss_polygons; e++)
    tss_agree(tss_polygons[e], p, 100, 1);
}

/* Do p[0 .. n-1] span a triangle (three sites not on one line)? */
static int tss_has_triangle(const geom_point *p, size_t n) {
  for (size_t i = 1; i < n; i++)
    for (size_t j = i + 1; j < n; j++)
      if (geom_orient_exact(p[0], p[i], p[j]) != 0 || geom_orient_exact(p[1], p[i], p[j]) != 0)
        return 1;
  return 0;
}

/* Sites on the sweepline that are no top of the first column (found from
** outside: the sweep of ES:square wrote through a missing edge record on
** (0,0), (10,6), (10,4), (30,20), and on 10 of 1,500 random sets of 4-9
** integer points).  A site on the sweepline is its own contact point: the
** polygons' "above" test answers so before any contact test, whose tie
** located (10,6) at (10,4) while (10,4) had a successor.  Here: that set,
** then small integer sets, most with several sites on one vertical line,
** under the square, two axis-parallel rectangles, the diamond and a
** triangle, each against the incremental algorithm. */
static void test_sweepline_sites(void **state) {
  (void)state;
  static const char *const rules[] = {"ES:square", "ES:poly:0,0;3,0;3,1;0,1",
                                      "ES:poly:0 0;1 0;1 2;0 2", "ES:diamond", "ES:triangle"};
  const geom_point first[4] = {{0, 0}, {10, 6}, {10, 4}, {30, 20}};
  for (size_t r = 0; r < sizeof rules / sizeof *rules; r++) tss_agree(rules[r], first, 4, 1);
  uint64_t s = 0x5eedu;
  static const int range[4] = {3, 5, 10, 30};
  int sets = testutil_reps(1500);
  tss_uncounted = 1;
  for (int k = 0; k < sets; k++) {
    geom_point p[9];
    size_t n = 4 + geom_splitmix64(&s) % 6;
    int R = range[geom_splitmix64(&s) % 4];
    for (size_t i = 0; i < n; i++)
      p[i] = (geom_point){(double)(geom_splitmix64(&s) % (uint64_t)(R + 1)),
                          (double)(geom_splitmix64(&s) % (uint64_t)(R + 1))};
    if (!tss_has_triangle(p, n)) continue;
    for (size_t r = 0; r < sizeof rules / sizeof *rules; r++) tss_agree(rules[r], p, n, 1);
  }
  tss_uncounted = 0;
}

/* lot_mesh_valid on a first triangle and its ghosts (mesh.c's own
** layout): valid; clockwise (its ghosts' hull then winds the wrong way):
** not; a fourth point inside left out: not. */
static void test_mesh_valid(void **state) {
  (void)state;
  lot_mesh m;
  assert_int_equal(lot_mesh_alloc(&m, 4, LOT_CACHE_NONE), 0);
  const geom_point p[4] = {{0, 0}, {4, 0}, {0, 4}, {1, 1}};
  for (uint32_t k = 0; k < 4; k++) {
    m.p[k] = p[k];
    m.inp[k] = k;
  }
  lot_mesh_first(&m, 0, 1, 2);
  assert_int_equal(lot_mesh_valid(&m, 3), 1);
  assert_int_equal(lot_mesh_valid(&m, 4), 0);
  lot_mesh_first(&m, 0, 2, 1);
  assert_int_equal(lot_mesh_valid(&m, 3), 0);
  lot_mesh_free(&m);
}

/* ---- sites in special position for a polygon ----------------------------
** Grids, turned grids, collinear rows, duplicates, small-integer clouds and
** corners of homothets (sites on lines parallel to the sides, four on one
** homothet), for seven polygons.  The sweep decides their ties by a fixed
** order, its mesh is checked (lot_mesh_valid) and, when it is no
** triangulation, replaced by the circle's; the rule's flips with the
** tie-break then end at the one tie-broken LOT (docs/lot.md): the
** triangles of the incremental and flip algorithms, index for index. */

static const char *const tss_sp_shapes[] = {
  "ES:square", "ES:diamond", "ES:triangle", "ES:hexagon", "ES:ngon:5",
  "ES:poly:0 0;3 1;2 3;-1 2", "ES:poly:0 0;2 0;2 1;0 1"};
#define TSS_SP_SHAPES (sizeof tss_sp_shapes / sizeof *tss_sp_shapes)

static void tss_sp_all(const geom_point *p, size_t n, const char *what) {
  tss_input = what;
  for (size_t e = 0; e < TSS_SP_SHAPES; e++) tss_agree(tss_sp_shapes[e], p, n, 1);
  tss_input = "";
}

/* Grids (the sampler's rows), and the same grid turned by 45 degrees
** (x + y, x - y) and by atan(1/2) with scale sqrt 5 (2x - y, x + 2y). */
static void test_grids(void **state) {
  (void)state;
  static const size_t ns[] = {4, 9, 16, 30, 100, 225};
  geom_point p[225], q[225];
  for (size_t i = 0; i < sizeof ns / sizeof *ns; i++) {
    sampler_points(SAMPLER_GRID, 1, ns[i], p);
    tss_sp_all(p, ns[i], "a grid");
    for (size_t k = 0; k < ns[i]; k++) q[k] = (geom_point){p[k].x + p[k].y, p[k].x - p[k].y};
    tss_sp_all(q, ns[i], "a grid turned by 45 degrees");
    for (size_t k = 0; k < ns[i]; k++)
      q[k] = (geom_point){2 * p[k].x - p[k].y, p[k].x + 2 * p[k].y};
    tss_sp_all(q, ns[i], "a grid turned by atan(1/2)");
  }
}

/* Collinear rows: horizontal rows of equal spacing, shifted rows, a
** column, and one row alone plus one point off it. */
static void test_rows(void **state) {
  (void)state;
  geom_point p[64];
  size_t n = 0;
  for (int r = 0; r < 3; r++)
    for (int i = 0; i < 12; i++) p[n++] = (geom_point){i * 0.5 + (r == 1 ? 0.25 : 0), r * 1.25};
  tss_sp_all(p, n, "three rows");
  for (int i = 0; i < 10; i++) p[n++] = (geom_point){7, i * 0.5};
  tss_sp_all(p, n, "three rows and a column");
  for (int i = 0; i < 20; i++) p[i] = (geom_point){i, 0};
  p[20] = (geom_point){9.5, 3};
  tss_sp_all(p, 21, "a row and a point");
  p[20] = (geom_point){9, -1};
  p[21] = (geom_point){9, 2};
  tss_sp_all(p, 22, "a row and a column crossing it");
}

/* Duplicates and small-integer clouds: draws from an m x m grid. */
static void test_clouds(void **state) {
  (void)state;
  geom_point p[300];
  for (uint64_t seed = 1; seed <= 6; seed++) {
    uint64_t s = seed;
    size_t n = seed <= 3 ? 300 : 60, m = seed <= 3 ? 6 : 9;
    for (size_t k = 0; k < n; k++) {
      uint64_t r = geom_splitmix64(&s);
      p[k] = (geom_point){(double)(r % m), (double)((r >> 20) % m)};
    }
    tss_sp_all(p, n, seed <= 3 ? "300 draws from a 6 x 6 grid" : "60 draws from a 9 x 9 grid");
  }
}

/* Corners of homothets 2^j K about one centre and about a corner: pairs of
** corners on lines parallel to K's sides, four on one homothet. */
static void test_homothets(void **state) {
  (void)state;
  for (size_t e = 0; e < TSS_SP_SHAPES; e++) {
    shape *k;
    char err[256];
    if (shape_parse(tss_sp_shapes[e] + 3, &k, err, sizeof err) != 0) fail_msg("%s", err);
    geom_point p[64];
    size_t n = 0;
    for (int j = 0; j < 3; j++)
      for (int i = 0; i < k->n && n < 64; i++)
        p[n++] = (geom_point){k->v[i].x * (1 << j), k->v[i].y * (1 << j)};
    tss_agree(tss_sp_shapes[e], p, n, 1);
    for (int i = 0; i < k->n && n < 64; i++)   /* 4K + 2 v_0 - 2 v_0 + ... : corners of 2K at 2 v_0 */
      p[n++] = (geom_point){2 * k->v[0].x + 2 * k->v[i].x, 2 * k->v[0].y + 2 * k->v[i].y};
    tss_agree(tss_sp_shapes[e], p, n, 1);
    shape_free(k);
  }
  print_message("sweeps so far: %zu, %zu with ties in special position, %zu "
                "restarted from the circle's sweep, %llu repair flips in all\n", tss_runs,
                tss_tied, tss_restarts, (unsigned long long)tss_repairs);
}

/* The sweep takes DT and empty-shape rules only, in one line. */
static void test_errors(void **state) {
  (void)state;
  rule r = tss_rule("P_1");
  lot_options o;
  lot_options_init(&o, &r);
  o.algorithm = LOT_SWEEP;
  lot *L;
  char err[256];
  geom_point t[] = {{0, 0}, {1, 0}, {0, 1}};
  assert_int_equal(lot_build(&L, t, 3, &o, err, sizeof err), -1);
  assert_non_null(strstr(err, "it needs rule DT or ES:SHAPE (got P_1)"));
  assert_null(strchr(err, '\n'));
}

/* A LOT reflipped with another rule gets that rule's own triangles: the
** empty-shape rules keep hints in the mesh's triangles (lot.c), and the
** first rule's must not answer for the second's decisions.  From every
** rule's LOT of the same points to every other's (two hexagons, so that a
** stale hint's edges would exist, other edge counts, and the square, which
** keeps none), each result equal to the second rule's LOT built afresh. */
static void test_reflip_hints(void **state) {
  (void)state;
  static const char *const names[] = {"ES:square", "ES:hexagon", "ES:poly:0 0;2 0;3 1;2 2;0 2;-1 1",
                                      "ES:ngon:5", "ES:ngon:7"};
  enum { N = 600, K = sizeof names / sizeof *names };
  geom_point *p = malloc(N * sizeof *p);
  assert_non_null(p);
  sampler_points(SAMPLER_UNIFORM, 11, N, p);
  tss_result fresh[K];
  for (int j = 0; j < K; j++) fresh[j] = tss_build(names[j], p, N, LOT_INCREMENTAL);
  for (int i = 0; i < K; i++)
    for (int j = 0; j < K; j++) {
      if (i == j) continue;
      rule r1 = tss_rule(names[i]), r2 = tss_rule(names[j]);
      lot_options o;
      lot_options_init(&o, &r1);
      lot *L;
      char err[256];
      if (lot_build(&L, p, N, &o, err, sizeof err) != 0) fail_msg("%s: %s", names[i], err);
      lot_options_init(&o, &r2);
      assert_int_equal(lot_reflip(L, &o), 0);
      assert_true(lot_get_stats(L)->flips > 0);
      size_t nt = lot_get_stats(L)->triangles;
      uint32_t *tri = malloc(3 * nt * sizeof *tri);
      assert_non_null(tri);
      lot_get_triangles(L, tri);
      if (nt != fresh[j].ntri || memcmp(tri, fresh[j].tri, 3 * nt * sizeof *tri) != 0)
        fail_msg("%s reflipped with %s differs from %s built afresh", names[i], names[j],
                 names[j]);
      free(tri);
      lot_free(L);
    }
  for (int j = 0; j < K; j++) free(fresh[j].tri);
  free(p);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_reflip_hints),
    cmocka_unit_test(test_ellipse_samplers),
    cmocka_unit_test(test_ellipse_special),
    cmocka_unit_test(test_ellipse_adversarial),
    cmocka_unit_test(test_polygon_samplers),
    cmocka_unit_test(test_polygon_adversarial),
    cmocka_unit_test(test_polygon_special),
    cmocka_unit_test(test_mesh_valid),
    cmocka_unit_test(test_grids),
    cmocka_unit_test(test_rows),
    cmocka_unit_test(test_clouds),
    cmocka_unit_test(test_homothets),
    cmocka_unit_test(test_errors),
    cmocka_unit_test(test_sweepline_sites),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
