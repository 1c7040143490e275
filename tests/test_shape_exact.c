/*
** test_shape_exact.c: the shape predicates' cheap exact paths against the
** purely exact decision.  The expansion stage (shapes/shape_xp.c), the
** answers kept per thread and asked again (shapes/shape_seen.c), the
** square's and the diamond's decisions of special position
** (shapes/shape_square.c) and the hint's triple in the general path must
** each give what every predicate taken exactly on GMP rationals gives
** (shape_set_exact_only with geom_exact_gmp_only): on grids, integer sets,
** scaled lattices (powers of two from 2^-90 to 2^90, inside and outside
** the expansions' range), sites on one homothet or one ellipse (the
** rule's genuine ties) and pairs parallel to edges, for every kind of
** shape.  And a regression guard on counts, not time: the LOT of a
** 100 x 100 grid takes no GMP run for any rule, and the square's takes
** almost no exact run at all.
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

#include "geom.h"
#include "lot.h"
#include "rule.h"
#include "sampler.h"
#include "shape.h"
#include "shape_internal.h"   /* the reference modes, the stages' counters, the programs */
#include "testutil.h"

static const char *const texact_specs[] = {
  "square", "diamond", "triangle", "hexagon", "octagon", "ngon:5", "ngon:7",
  "poly:1 0;0.309 0.951;-0.809 0.588;-0.809 -0.588;0.309 -0.951", "poly:0 0;3 1;4 4;1 3",
  "poly:3 0;0 3;-3 0;0 -3", "ellipse:2 1", "ellipse:2 1 0.5", "ellipse:1 1"};
#define TEXACT_NSPECS (sizeof texact_specs / sizeof texact_specs[0])

static shape *texact_shape(const char *spec) {
  shape *k = NULL;
  char err[256];
  if (shape_parse(spec, &k, err, sizeof err) != 0) fail_msg("shape '%s': %s", spec, err);
  return k;
}

static int texact_convex(const geom_point q[4]) {
  for (int i = 0; i < 4; i++)
    if (geom_orient(q[i], q[(i + 1) % 4], q[(i + 2) % 4]) <= 0) return 0;
  return 1;
}

/* p[0..3] put in convex anticlockwise order into q, or 0 if they are not
** in strictly convex position. */
static int texact_order(const geom_point p[4], geom_point q[4]) {
  static const int perm[6][3] = {{1, 2, 3}, {1, 3, 2}, {2, 1, 3}, {2, 3, 1}, {3, 1, 2}, {3, 2, 1}};
  for (int i = 0; i < 6; i++) {
    q[0] = p[0], q[1] = p[perm[i][0]], q[2] = p[perm[i][1]], q[3] = p[perm[i][2]];
    if (texact_convex(q)) return 1;
  }
  return 0;
}

/* The purely exact decision: no filter, no kept answer, every exact run on GMP. */
static shape_choice texact_reference(const shape *k, const geom_point q[4], shape_trace *tr) {
  int was = geom_exact_gmp_only(1);
  shape_set_exact_only(1);
  shape_choice c = shape_decide(k, q[0], q[1], q[2], q[3], tr);
  shape_set_exact_only(0);
  geom_exact_gmp_only(was);
  return c;
}

static long texact_checked;

/* Every way of asking (plain, traced, valid, hinted twice: the second with
** the hint the first left) against the reference, in all four rotations;
** the trace against the reference's trace too. */
static void texact_same(const shape *k, const geom_point q[4]) {
  for (int r = 0; r < 4; r++) {
    geom_point a = q[r], b = q[(r + 1) % 4], c = q[(r + 2) % 4], d = q[(r + 3) % 4];
    const geom_point p[4] = {a, b, c, d};
    shape_trace t1, t2;
    shape_choice want = texact_reference(k, p, &t2);
    shape_hint h = {0};
    shape_choice got[5] = {shape_decide(k, a, b, c, d, NULL), shape_decide(k, a, b, c, d, &t1),
                           shape_decide_valid(k, a, b, c, d),
                           shape_decide_hinted(k, a, b, c, d, &h),
                           shape_decide_hinted(k, a, b, c, d, &h)};
    for (int i = 0; i < 5; i++)
      if (got[i] != want)
        fail_msg("way %d: %d, exact %d on (%a,%a) (%a,%a) (%a,%a) (%a,%a)", i, got[i], want,
                 a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y);
    if (t1.level != t2.level || t1.rounding != t2.rounding || t1.corner != t2.corner ||
        memcmp(t1.contact, t2.contact, sizeof t1.contact) != 0)
      fail_msg("trace differs from the exact one on (%a,%a) (%a,%a) (%a,%a) (%a,%a)", a.x, a.y,
               b.x, b.y, c.x, c.y, d.x, d.y);
    texact_checked++;
  }
}

/* q scaled by s and shifted by (ox, oy), then checked, if still convex. */
static void texact_scaled(const shape *k, const geom_point q[4], double s, double ox, double oy) {
  geom_point r[4];
  for (int i = 0; i < 4; i++) r[i] = (geom_point){ox + s * q[i].x, oy + s * q[i].y};
  if (texact_convex(r)) texact_same(k, r);
}

/* Four points of a g x g integer grid in convex position. */
static int texact_grid_quad(testutil_rng *rng, int g, geom_point q[4]) {
  geom_point p[4];
  for (int i = 0; i < 4; i++)
    p[i] = (geom_point){(double)(testutil_next(rng) % (uint64_t)g),
                        (double)(testutil_next(rng) % (uint64_t)g)};
  return texact_order(p, q);
}

/* Four sites on one homothet t + sK of a polygon (its corners and the
** midpoints of its edges: exact for s a power of two and t an integer),
** or on one homothet of an ellipse's axis-aligned rectangle family: sites
** (+-a, +-b) about an integer centre, on one ellipse of every form whose
** axes are the coordinate axes (ellipse:2 1, ellipse:1 1). */
static int texact_on_shape(testutil_rng *rng, const shape *k, geom_point q[4]) {
  geom_point p[4];
  double s = ldexp(1, (int)(testutil_next(rng) % 6)), tx = (double)(testutil_next(rng) % 9);
  double ty = (double)(testutil_next(rng) % 9);
  if (k->kind == SHAPE_ELLIPSE) {
    double a = (double)(1 + testutil_next(rng) % 5), b = (double)(1 + testutil_next(rng) % 5);
    const double sx[4] = {1, -1, -1, 1}, sy[4] = {1, 1, -1, -1};
    for (int i = 0; i < 4; i++) p[i] = (geom_point){tx + sx[i] * a, ty + sy[i] * b};
    return texact_order(p, q);
  }
  for (int i = 0; i < 4; i++) {
    int v = (int)(testutil_next(rng) % (uint64_t)k->n), mid = testutil_next(rng) % 2 == 0;
    geom_point a = k->v[v], b = k->v[(v + 1) % k->n];
    geom_point at = mid ? (geom_point){(a.x + b.x) / 2, (a.y + b.y) / 2} : a;
    p[i] = (geom_point){tx + s * at.x, ty + s * at.y};
  }
  return texact_order(p, q);
}

/* ---- decisions -------------------------------------------------------------
**
** Each shape on grid quadrilaterals (3 to 17 wide: pairs parallel to the
** square's and the diamond's sides, sites on a corner's cone, four on one
** square), at scales 2^-90 to 2^90 (2^+-90 lie beyond the expansions'
** [2^-80, 2^80]: GMP decides there, in the fast mode too) and shifted by
** integers times the scale (the same differences at other places: the
** kept answers answer them), and on sites on one homothet. */
static void test_decisions(void **state) {
  (void)state;
  static const double scale[] = {1, 0x1p-90, 0x1p-40, 0x1p30, 0x1p90, 0.75};
  testutil_rng rng = {3501};
  texact_checked = 0;
  for (size_t si = 0; si < TEXACT_NSPECS; si++) {
    shape *k = texact_shape(texact_specs[si]);
    geom_point q[4];
    for (int it = 0; it < testutil_reps(60); it++) {
      if (texact_grid_quad(&rng, 3 + (it % 4) * 5, q)) {
        texact_same(k, q);
        double s = scale[it % 6], o = (double)(testutil_next(&rng) % 1000);
        texact_scaled(k, q, s, o * s, 3 * o * s);
      }
      if (texact_on_shape(&rng, k, q)) {
        texact_same(k, q);
        texact_scaled(k, q, 1, 1000, -7);
      }
    }
    shape_free(k);
  }
  printf("decisions checked: %ld\n", texact_checked);
  assert_true(texact_checked > testutil_reps(60) * 4 * (int)TEXACT_NSPECS);
}

/* ---- programs ----------------------------------------------------------------
**
** Each program's exact sign (the value's and its eps coefficient's) on
** the expansions against GMP, for random edges and corners of every
** polygon and grid sites, lattice sites scaled by 2^-80 and 2^80 (the
** expansions' range ends), and sites with 53-bit coordinates: the stage
** itself, with no filter and nothing kept in front of it. */
static int texact_sign(shape_prog p, const shape_args *g, int gmp) {
  int was = geom_exact_gmp_only(gmp);
  shape_set_exact_only(1);
  int s = shape_sign(p, g);
  shape_set_exact_only(0);
  geom_exact_gmp_only(was);
  return s;
}

static void texact_args(testutil_rng *rng, const shape *k, int kind, shape_args *g) {
  static const double scale[4] = {1, 0x1p-80, 0x1p80, 0};
  double s = scale[kind];
  for (int r = 0; r < 4; r++) {
    g->e[r] = k->n > 0 ? (int)(testutil_next(rng) % (uint64_t)k->n) : 0;
    double x = (double)(testutil_next(rng) % 7), y = (double)(testutil_next(rng) % 7);
    g->p[r] = s != 0 ? (geom_point){x * s, y * s}
                     : (geom_point){testutil_uniform(rng), testutil_uniform(rng)};
  }
  g->o = g->p[testutil_next(rng) % 4];
  g->corner = g->e[3];
}

static void test_programs(void **state) {
  (void)state;
  testutil_rng rng = {3502};
  long zeros = 0, asked = 0;
  for (size_t si = 0; si < TEXACT_NSPECS; si++) {
    shape *k = texact_shape(texact_specs[si]);
    for (int it = 0; it < testutil_reps(400); it++) {
      shape_args g = {.K = k};
      texact_args(&rng, k, it % 4, &g);
      for (int p = 0; p < SHAPE_PROG_COUNT; p++) {
        if ((p == SHAPE_PROG_ELLIPSE) != (k->kind == SHAPE_ELLIPSE)) continue;
        for (g.deriv = 0; g.deriv < 2; g.deriv++) {
          int fast = texact_sign(p, &g, 0), want = texact_sign(p, &g, 1);
          if (fast != want) fail_msg("%s: program %d deriv %d: %d, GMP %d", texact_specs[si], p,
                                     g.deriv, fast, want);
          zeros += want == 0;
          asked++;
        }
      }
    }
    shape_free(k);
  }
  printf("program signs: %ld, of them 0: %ld\n", asked, zeros);
  assert_true(zeros > asked / 20);   /* the exact zeros, the stage's reason to be, are there */
}

/* ---- the kept answers ---------------------------------------------------------
**
** Sites on one homothet (or ellipse) asked at ten places each: every
** answer is the reference's, and the kept answers are found (the counters
** move; not for the triangle, whose such quadrilaterals are seldom
** strictly convex, nor the turned ellipse, on which the sites are not). */
static unsigned long texact_hits(void) {
  unsigned long n = 0;
  for (int w = 0; w < SHAPE_SEEN_WHATS; w++) n += shape_seen_hits(w);
  return n;
}

static void test_kept(void **state) {
  (void)state;
  testutil_rng rng = {3503};
  unsigned long all = texact_hits();
  for (size_t si = 0; si < TEXACT_NSPECS; si++) {
    shape *k = texact_shape(texact_specs[si]);
    geom_point q[4];
    unsigned long before = texact_hits();
    for (int it = 0; it < testutil_reps(20); it++) {
      if (!texact_on_shape(&rng, k, q)) continue;
      for (int at = 0; at < 10; at++)
        texact_scaled(k, q, 1, (double)(at * 37), (double)(at * -11));
    }
    printf("%-20.20s kept answers found: %lu\n", texact_specs[si], texact_hits() - before);
    shape_free(k);
  }
  assert_true(texact_hits() - all > (unsigned long)testutil_reps(20) * 100);
}

/* ---- the square's and the diamond's own decisions -----------------------------
**
** A diamond is a variant of its own only when its frame (x + y, y - x) is
** exact and square; its own answers, where it gives them, are the
** reference's, on grids (where special position is everywhere) and on
** sites on one homothet (four on one square: either); on random sites,
** whose frames are seldom exact, it gives up and the general path's answer
** is still the reference's. */
static void test_own(void **state) {
  (void)state;
  static const char *const diamonds[] = {"diamond", "poly:3 0;0 3;-3 0;0 -3",
                                         "poly:0.1 0;0 0.1;-0.1 0;0 -0.1"};
  static const char *const not_diamonds[] = {"square", "poly:1 0;0 1;-1 0;0 -1.0000000000000002",
                                             "poly:2 0;0 1;-2 0;0 -1"};
  for (size_t i = 0; i < 3; i++) {
    shape *k = texact_shape(not_diamonds[i]);
    assert_int_not_equal(shape_variant_of(k), SHAPE_V_DIAMOND);
    shape_free(k);
  }
  testutil_rng rng = {3504};
  long answered = 0, asked = 0;
  for (size_t i = 0; i < 4; i++) {
    const char *spec = i < 3 ? diamonds[i] : "square";
    shape *k = texact_shape(spec);
    assert_int_equal(shape_variant_of(k), i < 3 ? SHAPE_V_DIAMOND : SHAPE_V_SQUARE);
    geom_point q[4];
    for (int it = 0; it < testutil_reps(500); it++) {
      if (it % 2 ? !texact_grid_quad(&rng, 2 + it % 9, q) : !texact_on_shape(&rng, k, q))
        continue;
      int own = i < 3 ? shape_diamond_decide(q) : shape_square_decide(q);
      int want = (int)texact_reference(k, q, NULL);
      if (own >= 0 && own != want)
        fail_msg("%s: own %d, exact %d on (%a,%a) (%a,%a) (%a,%a) (%a,%a)", spec, own, want,
                 q[0].x, q[0].y, q[1].x, q[1].y, q[2].x, q[2].y, q[3].x, q[3].y);
      answered += own >= 0;
      asked++;
      texact_same(k, q);
    }
    for (int it = 0; it < testutil_reps(100); it++) {   /* frames seldom exact: it gives up */
      testutil_convex_quad(&rng, q);
      texact_same(k, q);
    }
    shape_free(k);
  }
  printf("own decisions: %ld of %ld special-position quadrilaterals\n", answered, asked);
  /* special position no longer gives up: only staircases (a corner's
  ** rounding shape, a quarter of these) go to the general path */
  assert_true(answered > asked * 6 / 10);
}

/* ---- the count guard --------------------------------------------------------
**
** The incremental LOT of the 100 x 100 grid for each rule: no exact run
** falls to GMP (every grid coordinate is an integer below 2^80: the
** expansions take every run, and a degree-8 program of integers below 2^8
** stays far inside their pool), and the square's own decision leaves only
** staircases (corners' rounding shapes) and second-order ties to the
** exact runs: at most 50 (4 when written) where there were 163,598. */
static void test_counts(void **state) {
  (void)state;
  static const char *const rules[] = {
    "ES:square", "ES:diamond", "ES:hexagon",
    "ES:poly:1 0;0.309 0.951;-0.809 0.588;-0.809 -0.588;0.309 -0.951", "ES:ellipse:2 1"};
  enum { N = 10000 };
  geom_point *p = malloc(N * sizeof *p);
  assert_non_null(p);
  sampler_points(SAMPLER_GRID, 1, N, p);
  for (size_t i = 0; i < sizeof rules / sizeof rules[0]; i++) {
    rule r;
    char err[256];
    assert_int_equal(rule_parse(rules[i], &r, err, sizeof err), 0);
    unsigned long gmp = 0, runs = 0;
    for (int q = 0; q < SHAPE_PROG_COUNT; q++) {
      gmp -= shape_exact_stage_calls(q, GEOM_STAGE_GMP);
      runs -= shape_exact_stage_calls(q, GEOM_STAGE_EXPANSION);
    }
    lot_options o;
    lot_options_init(&o, &r);
    lot *L = NULL;
    assert_int_equal(lot_build(&L, p, N, &o, err, sizeof err), 0);
    lot_free(L);
    for (int q = 0; q < SHAPE_PROG_COUNT; q++) {
      gmp += shape_exact_stage_calls(q, GEOM_STAGE_GMP);
      runs += shape_exact_stage_calls(q, GEOM_STAGE_EXPANSION);
    }
    printf("%-12.12s exact runs: %lu on expansions, %lu on GMP\n", rules[i], runs, gmp);
    assert_int_equal(gmp, 0);
    if (i == 0) assert_true(runs <= 50);
  }
  free(p);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_programs), cmocka_unit_test(test_decisions),
    cmocka_unit_test(test_kept),     cmocka_unit_test(test_own),
    cmocka_unit_test(test_counts),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
