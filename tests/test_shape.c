/*
** test_shape.c: shapes (parsing, named shapes, refusals) and the exact
** empty-shape decision: the four triangle choices agree, exact relations
** (square and diamond, axis-aligned ellipses and DT), homothety and scale
** invariance, a brute-force rational oracle, the rounding shapes' branch,
** regular n-gons approaching DT, and the drawn circumscribing shapes.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <gmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom.h"
#include "shape.h"
#include "shape_internal.h"   /* shape_set_exact_only: the filters against the exact runs */
#include "testutil.h"

static shape *tshape_get(const char *spec) {
  shape *k = NULL;
  char err[256];
  if (shape_parse(spec, &k, err, sizeof err) != 0) fail_msg("shape '%s': %s", spec, err);
  return k;
}

/* The decision of ABCD read through the triangle starting at vertex r:
** rotating by one vertex swaps the names of the diagonals. */
static shape_choice tshape_rot(const shape *k, const geom_point q[4], int r, shape_trace *tr) {
  shape_choice c = shape_decide(k, q[r], q[(r + 1) % 4], q[(r + 2) % 4], q[(r + 3) % 4], tr);
  if ((r & 1) && c != SHAPE_EITHER) c = c == SHAPE_AC ? SHAPE_BD : SHAPE_AC;
  return c;
}

/* Is q strictly convex and anticlockwise? */
static int tshape_convex(const geom_point q[4]) {
  for (int i = 0; i < 4; i++)
    if (geom_orient(q[i], q[(i + 1) % 4], q[(i + 2) % 4]) <= 0) return 0;
  return 1;
}

/* Four distinct points of a g x g integer grid (scaled by s, shifted by o)
** in strictly convex position, anticlockwise; 0 if the draw is not. */
static int tshape_grid_quad(testutil_rng *rng, int g, double s, double o, geom_point q[4]) {
  geom_point p[4];
  for (int i = 0; i < 4; i++)
    p[i] = (geom_point){o + s * (double)(testutil_next(rng) % (uint64_t)g),
                        o + s * (double)(testutil_next(rng) % (uint64_t)g)};
  /* Try the orders of p[1..3] after p[0]: one is the hull's, if convex. */
  static const int perm[6][3] = {{1, 2, 3}, {1, 3, 2}, {2, 1, 3}, {2, 3, 1}, {3, 1, 2}, {3, 2, 1}};
  for (int i = 0; i < 6; i++) {
    q[0] = p[0], q[1] = p[perm[i][0]], q[2] = p[perm[i][1]], q[3] = p[perm[i][2]];
    if (tshape_convex(q)) return 1;
  }
  return 0;
}

typedef struct tshape_counts {
  long quads, rounding, perturbed, either, failed;
} tshape_counts;

/* The four triangle choices agree on q; counts what the first needed. */
static void tshape_check4(const shape *k, const geom_point q[4], tshape_counts *n) {
  shape_trace tr;
  shape_choice c0 = tshape_rot(k, q, 0, &tr);
  n->quads++;
  n->rounding += tr.rounding;
  n->perturbed += tr.level == 1;
  n->either += c0 == SHAPE_EITHER;
  n->failed += tr.failed;
  for (int r = 1; r < 4; r++) {
    shape_trace t2;
    shape_choice c = tshape_rot(k, q, r, &t2);
    n->failed += t2.failed;
    if (c != c0) {
      fail_msg("rotations disagree: %d vs %d (r=%d) on (%a,%a) (%a,%a) (%a,%a) (%a,%a)", c0, c,
               r, q[0].x, q[0].y, q[1].x, q[1].y, q[2].x, q[2].y, q[3].x, q[3].y);
    }
  }
}

static const char *const tshape_specs[] = {
  "square", "diamond", "triangle", "hexagon", "octagon", "ngon:5", "ngon:12",
  "poly:0 0;3 1;4 4;1 3", "poly:0,0;5,1;6,2;2,5;-1,3", "ellipse:2 1", "ellipse:2,1,0.5",
};
#define TSHAPE_NSPECS (sizeof tshape_specs / sizeof tshape_specs[0])

static void test_rotations_random(void **state) {
  (void)state;
  testutil_rng rng = {18};
  for (size_t s = 0; s < TSHAPE_NSPECS; s++) {
    shape *k = tshape_get(tshape_specs[s]);
    tshape_counts n = {0};
    for (int i = 0; i < 4000; i++) {
      geom_point q[4];
      testutil_convex_quad(&rng, q);
      tshape_check4(k, q, &n);
    }
    printf("random  %-26s quads %ld rounding %ld perturbed %ld either %ld\n", tshape_specs[s],
           n.quads, n.rounding, n.perturbed, n.either);
    assert_int_equal(n.failed, 0);
    if (k->kind == SHAPE_POLYGON) assert_true(n.rounding > 0);
    assert_true(n.either == 0);
    shape_free(k);
  }
}

/* Grids and equal coordinates (every special position at once), at
** several scales within the coordinate contract. */
static void test_rotations_grid(void **state) {
  (void)state;
  testutil_rng rng = {1994};
  unsigned long exact0 = shape_exact_calls();
  static const double scale[][2] = {{1, 0}, {0x1p-90, 0}, {0x1p90, 0}, {1, 1e6}, {0.25, -3}};
  for (size_t s = 0; s < TSHAPE_NSPECS; s++) {
    shape *k = tshape_get(tshape_specs[s]);
    tshape_counts n = {0};
    for (size_t sc = 0; sc < sizeof scale / sizeof scale[0]; sc++)
      for (int i = 0; i < 3000; i++) {
        geom_point q[4];
        if (tshape_grid_quad(&rng, i % 2 ? 4 : 7, scale[sc][0], scale[sc][1], q))
          tshape_check4(k, q, &n);
      }
    printf("grid    %-26s quads %ld rounding %ld perturbed %ld either %ld\n", tshape_specs[s],
           n.quads, n.rounding, n.perturbed, n.either);
    assert_int_equal(n.failed, 0);
    if (k->kind == SHAPE_POLYGON) assert_true(n.perturbed > 0);
    shape_free(k);
  }
  /* the double runs cannot decide exact zeros: the exact path ran */
  printf("exact runs: %lu\n", shape_exact_calls() - exact0);
  assert_true(shape_exact_calls() > exact0);
}


/* ---- a brute-force rational oracle ------------------------------------------
**
** Independent of shape_polygon.c: supports by comparing every vertex, the
** circumscribing homothet by trying every triple of edges (any edges, not
** the ranges) with Cramer's rule in rationals, and for a problem corner the
** hyperbola through the mapped A, B, C solved as a linear system.  Only for
** sites in general position (a support tie makes the oracle give up). */

typedef struct toracle {
  const shape *k;
  mpq_t nx[SHAPE_MAX_VERTICES > 64 ? 64 : SHAPE_MAX_VERTICES], ny[64], h[64];
} toracle;

static void toracle_init(toracle *o, const shape *k) {
  o->k = k;
  for (int i = 0; i < k->n; i++) {
    geom_point p = k->v[i], q = k->v[(i + 1) % k->n];
    mpq_t t;
    mpq_inits(o->nx[i], o->ny[i], o->h[i], t, NULL);
    mpq_set_d(o->nx[i], q.y), mpq_set_d(t, p.y), mpq_sub(o->nx[i], o->nx[i], t);  /* e_y */
    mpq_set_d(o->ny[i], p.x), mpq_set_d(t, q.x), mpq_sub(o->ny[i], o->ny[i], t);  /* -e_x */
    mpq_set_d(t, p.x), mpq_mul(o->h[i], o->nx[i], t);
    mpq_set_d(t, p.y), mpq_mul(t, o->ny[i], t), mpq_add(o->h[i], o->h[i], t);     /* n.k_i */
    mpq_clear(t);
  }
}

static void toracle_clear(toracle *o) {
  for (int i = 0; i < o->k->n; i++) mpq_clears(o->nx[i], o->ny[i], o->h[i], NULL);
}

/* r = n_i . p */
static void toracle_dot(toracle *o, mpq_t r, int i, geom_point p) {
  mpq_t t;
  mpq_init(t);
  mpq_set_d(t, p.x), mpq_mul(r, o->nx[i], t);
  mpq_set_d(t, p.y), mpq_mul(t, o->ny[i], t), mpq_add(r, r, t);
  mpq_clear(t);
}

/* det of a 3x3 rational matrix (row-major). */
static void toracle_det3(mpq_t r, mpq_t *m) {
  mpq_t a, b;
  mpq_inits(a, b, NULL);
  mpq_set_ui(r, 0, 1);
  for (int c = 0; c < 3; c++) {
    int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
    mpq_mul(a, m[3 + c1], m[6 + c2]), mpq_mul(b, m[3 + c2], m[6 + c1]), mpq_sub(a, a, b);
    mpq_mul(a, a, m[c]), mpq_add(r, r, a);
  }
  mpq_clears(a, b, NULL);
}

/* Solve M x = rhs (3x3, rationals) by Cramer; 0 if singular. */
static int toracle_solve3(mpq_t *m, mpq_t *rhs, mpq_t *x) {
  mpq_t d, t[9];
  mpq_init(d);
  toracle_det3(d, m);
  int ok = mpq_sgn(d) != 0;
  for (int i = 0; i < 9; i++) mpq_init(t[i]);
  for (int c = 0; ok && c < 3; c++) {
    for (int i = 0; i < 9; i++) mpq_set(t[i], i % 3 == c ? rhs[i / 3] : m[i]);
    toracle_det3(x[c], t);
    mpq_div(x[c], x[c], d);
  }
  for (int i = 0; i < 9; i++) mpq_clear(t[i]);
  mpq_clear(d);
  return ok;
}

/* max_m (n_m.p - c_m) for the homothet (tx, ty, s): its sign. */
static int toracle_side(toracle *o, mpq_t *ts, geom_point p) {
  mpq_t best, v, t;
  mpq_inits(best, v, t, NULL);
  for (int m = 0; m < o->k->n; m++) {
    toracle_dot(o, v, m, p);
    mpq_mul(t, o->nx[m], ts[0]), mpq_sub(v, v, t);
    mpq_mul(t, o->ny[m], ts[1]), mpq_sub(v, v, t);
    mpq_mul(t, o->h[m], ts[2]), mpq_sub(v, v, t);
    if (m == 0 || mpq_cmp(v, best) > 0) mpq_set(best, v);
  }
  int s = mpq_sgn(best);
  mpq_clears(best, v, t, NULL);
  return s;
}

/* The circumscribing homothet of p[0..2] by trying every edge triple: 1 and
** ts set, or 0 when there is none. */
static int toracle_homothet(toracle *o, const geom_point p[3], mpq_t *ts) {
  int n = o->k->n, found = 0;
  mpq_t m[9], rhs[3];
  for (int i = 0; i < 9; i++) mpq_init(m[i]);
  for (int i = 0; i < 3; i++) mpq_init(rhs[i]);
  for (int a = 0; a < n && !found; a++)
    for (int b = 0; b < n && !found; b++)
      for (int c = 0; c < n && !found; c++) {
        int e[3] = {a, b, c};
        for (int r = 0; r < 3; r++) {
          mpq_set(m[3 * r], o->nx[e[r]]), mpq_set(m[3 * r + 1], o->ny[e[r]]);
          mpq_set(m[3 * r + 2], o->h[e[r]]);
          toracle_dot(o, rhs[r], e[r], p[r]);
        }
        if (!toracle_solve3(m, rhs, ts) || mpq_sgn(ts[2]) <= 0) continue;
        found = toracle_side(o, ts, p[0]) == 0 && toracle_side(o, ts, p[1]) == 0
             && toracle_side(o, ts, p[2]) == 0;
      }
  for (int i = 0; i < 9; i++) mpq_clear(m[i]);
  for (int i = 0; i < 3; i++) mpq_clear(rhs[i]);
  return found;
}

/* The support vertex of PQ by comparing every vertex; -1 on a tie. */
static int toracle_support(const shape *k, geom_point p, geom_point q) {
  long double dx = (long double)q.y - p.y, dy = (long double)p.x - q.x;   /* right normal */
  int best = -1, tie = 0;
  long double bv = 0;
  for (int i = 0; i < k->n; i++) {
    long double v = dx * k->v[i].x + dy * k->v[i].y;   /* exact: small integers in tests */
    if (best < 0 || v > bv) best = i, bv = v, tie = 0;
    else if (v == bv) tie = 1;
  }
  return tie ? -1 : best;
}

/* The rounding shape of corner c through p[0..2]: D inside?  Asserts the
** mapped A, B, C on the branch x > h_x, y decreasing as x increases.
** Returns 1 inside, -1 outside, 0 on it. */
static int toracle_corner(const shape *k, int c, const geom_point p[4]) {
  geom_point v0 = k->v[c], un = k->v[(c + 1) % k->n], vp = k->v[(c + k->n - 1) % k->n];
  /* L = [u v]^-1 in exact rationals: x = (v_y p_x - v_x p_y) / d, y = (u_x p_y - u_y p_x) / d */
  mpq_t ux, uy, vx, vy, d, t, X[4], Y[4], m[9], rhs[3], sol[3];
  mpq_inits(ux, uy, vx, vy, d, t, NULL);
  mpq_set_d(ux, un.x), mpq_set_d(t, v0.x), mpq_sub(ux, ux, t);
  mpq_set_d(uy, un.y), mpq_set_d(t, v0.y), mpq_sub(uy, uy, t);
  mpq_set_d(vx, vp.x), mpq_set_d(t, v0.x), mpq_sub(vx, vx, t);
  mpq_set_d(vy, vp.y), mpq_set_d(t, v0.y), mpq_sub(vy, vy, t);
  mpq_mul(d, ux, vy), mpq_mul(t, uy, vx), mpq_sub(d, d, t);
  for (int i = 0; i < 4; i++) {
    mpq_t px, py;
    mpq_inits(X[i], Y[i], px, py, NULL);
    mpq_set_d(px, p[i].x), mpq_set_d(py, p[i].y);
    mpq_mul(X[i], vy, px), mpq_mul(t, vx, py), mpq_sub(X[i], X[i], t), mpq_div(X[i], X[i], d);
    mpq_mul(Y[i], ux, py), mpq_mul(t, uy, px), mpq_sub(Y[i], Y[i], t), mpq_div(Y[i], Y[i], d);
    mpq_clears(px, py, NULL);
  }
  /* x y + alpha x + beta y + gamma = 0 through the three: unknowns (alpha, beta, gamma). */
  for (int i = 0; i < 9; i++) mpq_init(m[i]);
  for (int i = 0; i < 3; i++) {
    mpq_inits(rhs[i], sol[i], NULL);
    mpq_set(m[3 * i], X[i]), mpq_set(m[3 * i + 1], Y[i]), mpq_set_ui(m[3 * i + 2], 1, 1);
    mpq_mul(rhs[i], X[i], Y[i]), mpq_neg(rhs[i], rhs[i]);
  }
  assert_true(toracle_solve3(m, rhs, sol));
  /* h_x = -beta, h_y = -alpha */
  mpq_t hx, hy, r, rd;
  mpq_inits(hx, hy, r, rd, NULL);
  mpq_neg(hx, sol[1]), mpq_neg(hy, sol[0]);
  for (int i = 0; i < 3; i++) assert_true(mpq_cmp(X[i], hx) > 0);   /* the branch x > h_x */
  int ord[3] = {0, 1, 2};
  for (int i = 0; i < 3; i++)
    for (int j = i + 1; j < 3; j++)
      if (mpq_cmp(X[ord[j]], X[ord[i]]) < 0) { int s = ord[i]; ord[i] = ord[j]; ord[j] = s; }
  assert_true(mpq_cmp(X[ord[0]], X[ord[1]]) < 0 && mpq_cmp(X[ord[1]], X[ord[2]]) < 0);
  assert_true(mpq_cmp(Y[ord[0]], Y[ord[1]]) > 0 && mpq_cmp(Y[ord[1]], Y[ord[2]]) > 0);
  mpq_sub(r, X[0], hx), mpq_sub(t, Y[0], hy), mpq_mul(r, r, t);
  assert_true(mpq_sgn(r) > 0);
  mpq_sub(rd, X[3], hx), mpq_sub(t, Y[3], hy), mpq_mul(rd, rd, t);
  int side = mpq_cmp(X[3], hx) > 0 ? mpq_cmp(rd, r) : -1;
  mpq_clears(hx, hy, r, rd, ux, uy, vx, vy, d, t, NULL);
  for (int i = 0; i < 4; i++) mpq_clears(X[i], Y[i], NULL);
  for (int i = 0; i < 9; i++) mpq_clear(m[i]);
  for (int i = 0; i < 3; i++) mpq_clears(rhs[i], sol[i], NULL);
  return side > 0 ? 1 : side < 0 ? -1 : 0;
}

/* The oracle's decision, or -1 when it gives up (a support tie). */
static int toracle_decide(toracle *o, const geom_point q[4], int *rounding) {
  int s[3] = {toracle_support(o->k, q[0], q[1]), toracle_support(o->k, q[1], q[2]),
              toracle_support(o->k, q[2], q[0])};
  if (s[0] < 0 || s[1] < 0 || s[2] < 0) return -1;
  *rounding = s[0] == s[1] || s[1] == s[2] || s[2] == s[0];
  if (*rounding) {
    int c = s[0] == s[1] || s[0] == s[2] ? s[0] : s[1];
    int in = toracle_corner(o->k, c, q);
    return in > 0 ? SHAPE_BD : in < 0 ? SHAPE_AC : SHAPE_EITHER;
  }
  mpq_t ts[3];
  mpq_inits(ts[0], ts[1], ts[2], NULL);
  assert_true(toracle_homothet(o, q, ts));
  int side = toracle_side(o, ts, q[3]);
  mpq_clears(ts[0], ts[1], ts[2], NULL);
  return side < 0 ? SHAPE_BD : side > 0 ? SHAPE_AC : SHAPE_EITHER;
}

/* Random quadrilaterals with coordinates of a 2^-10 grid (exact long
** double support values) against the oracle. */
static void test_oracle(void **state) {
  (void)state;
  static const char *const specs[] = {"square", "diamond", "triangle", "hexagon", "ngon:7",
                                      "poly:0 0;3 1;4 4;1 3", "poly:0,0;5,1;6,2;2,5;-1,3"};
  testutil_rng rng = {4};
  for (size_t s = 0; s < sizeof specs / sizeof specs[0]; s++) {
    shape *k = tshape_get(specs[s]);
    toracle o;
    toracle_init(&o, k);
    long checked = 0, rounded = 0;
    for (int i = 0; i < 600; i++) {
      geom_point q[4];
      testutil_convex_quad(&rng, q);
      for (int j = 0; j < 4; j++)
        q[j] = (geom_point){round(q[j].x * 1024) / 1024, round(q[j].y * 1024) / 1024};
      if (!tshape_convex(q)) continue;
      int rounding = 0, want = toracle_decide(&o, q, &rounding);
      if (want < 0) continue;
      shape_trace tr;
      assert_int_equal(shape_decide(k, q[0], q[1], q[2], q[3], &tr), want);
      assert_int_equal(tr.rounding, rounding);
      checked++;
      rounded += rounding;
    }
    printf("oracle  %-26s checked %ld (rounding %ld)\n", specs[s], checked, rounded);
    assert_true(checked > 300 && rounded > 0);
    toracle_clear(&o);
    shape_free(k);
  }
}

/* ---- exact relations ---------------------------------------------------- */

/* (x, y) -> (x - y, x + y) is a rotation times a scale that maps the square
** onto a homothet of the diamond; it commutes with the shape's
** perturbation, so the rules agree on every input, grids included.  The
** map of the issue, (x + y, x - y), also reverses orientation: it mirrors
** the perturbation too, so it is checked on sites in general position. */
static void test_square_diamond(void **state) {
  (void)state;
  shape *sq = tshape_get("square"), *di = tshape_get("diamond");
  testutil_rng rng = {7};
  long n = 0;
  for (int i = 0; i < 20000; i++) {
    geom_point q[4], r[4];
    if (!tshape_grid_quad(&rng, 9, 1, -4, q)) continue;
    for (int j = 0; j < 4; j++) r[j] = (geom_point){q[j].x - q[j].y, q[j].x + q[j].y};
    assert_int_equal(shape_decide(sq, q[0], q[1], q[2], q[3], NULL),
                     shape_decide(di, r[0], r[1], r[2], r[3], NULL));
    n++;
  }
  for (int i = 0; i < 20000; i++) {
    geom_point q[4], r[4];
    testutil_convex_quad(&rng, q);
    for (int j = 0; j < 4; j++) q[j] = (geom_point){round(q[j].x * 0x1p30), round(q[j].y * 0x1p30)};
    /* mirrored: the anticlockwise order of the images is A D C B */
    for (int j = 0; j < 4; j++) r[(4 - j) % 4] = (geom_point){q[j].x + q[j].y, q[j].x - q[j].y};
    if (!tshape_convex(q) || !tshape_convex(r)) continue;
    assert_int_equal(shape_decide(sq, q[0], q[1], q[2], q[3], NULL),
                     shape_decide(di, r[0], r[1], r[2], r[3], NULL));
    n++;
  }
  assert_true(n > 25000);
  shape_free(sq);
  shape_free(di);
}

static shape_choice tshape_dt(geom_point a, geom_point b, geom_point c, geom_point d) {
  int s = geom_incircle(a, b, c, d);
  return s > 0 ? SHAPE_BD : s < 0 ? SHAPE_AC : SHAPE_EITHER;
}

/* An axis-aligned ellipse (a, b), a and b powers of two, is DT on
** (x / a, y / b): the division is exact. */
static void test_ellipse_dt(void **state) {
  (void)state;
  static const double ab[][2] = {{2, 1}, {1, 4}, {0.5, 8}, {1, 1}};
  testutil_rng rng = {11};
  for (size_t e = 0; e < sizeof ab / sizeof ab[0]; e++) {
    char spec[64];
    snprintf(spec, sizeof spec, "ellipse:%g %g", ab[e][0], ab[e][1]);
    shape *k = tshape_get(spec);
    assert_true(k->q12 == 0);
    for (int i = 0; i < 20000; i++) {
      geom_point q[4], r[4];
      if (i % 2) testutil_convex_quad(&rng, q);
      else if (!tshape_grid_quad(&rng, 6, 0.5, 1, q)) continue;
      for (int j = 0; j < 4; j++) r[j] = (geom_point){q[j].x / ab[e][0], q[j].y / ab[e][1]};
      assert_int_equal(shape_decide(k, q[0], q[1], q[2], q[3], NULL),
                       tshape_dt(r[0], r[1], r[2], r[3]));
    }
    shape_free(k);
  }
  /* ellipse:1 1 is the circle: DT itself. */
}

/* Homothety: the shape scaled by powers of two and translated by exact
** offsets, and the sites scaled by powers of two (and shifted on grids),
** give the same decisions, special positions included. */
static void test_homothety(void **state) {
  (void)state;
  static const char *const specs[] = {"square", "triangle", "hexagon", "poly:0 0;3 1;4 4;1 3"};
  testutil_rng rng = {5};
  for (size_t s = 0; s < sizeof specs / sizeof specs[0]; s++) {
    shape *k = tshape_get(specs[s]);
    char spec[4096] = "poly:";
    for (int i = 0; i < k->n; i++)
      snprintf(spec + strlen(spec), sizeof spec - strlen(spec), "%s%a %a", i ? ";" : "",
               k->v[i].x * 0x1p-7 + 3.5, k->v[i].y * 0x1p-7 - 1024);
    shape *k2 = tshape_get(spec);
    for (int i = 0; i < 6000; i++) {
      geom_point q[4], r[4];
      if (i % 2) testutil_convex_quad(&rng, q);
      else if (!tshape_grid_quad(&rng, 5, 1, 0, q)) continue;
      double sc = i % 3 == 0 ? 0x1p-60 : i % 3 == 1 ? 0x1p60 : 0.5;
      for (int j = 0; j < 4; j++) r[j] = (geom_point){q[j].x * sc, q[j].y * sc};
      shape_choice c = shape_decide(k, q[0], q[1], q[2], q[3], NULL);
      assert_int_equal(shape_decide(k2, q[0], q[1], q[2], q[3], NULL), c);
      assert_int_equal(shape_decide(k, r[0], r[1], r[2], r[3], NULL), c);
      if (i % 2 == 0) {
        for (int j = 0; j < 4; j++) r[j] = (geom_point){q[j].x + 17, q[j].y - 5};
        assert_int_equal(shape_decide(k, r[0], r[1], r[2], r[3], NULL), c);
      }
    }
    shape_free(k2);
    shape_free(k);
  }
}

/* The least signed distance of P to the sides of the anticlockwise polygon
** out[0..n-1] (>= 0 inside, 0 on it), for the drawn homothets. */
static double tshape_side_dist(const geom_point *out, int n, geom_point p) {
  double best = INFINITY;
  for (int i = 0; i < n; i++) {
    geom_point u = out[i], w = out[(i + 1) % n];
    double dx = w.x - u.x, dy = w.y - u.y;
    best = fmin(best, (dx * (p.y - u.y) - dy * (p.x - u.x)) / hypot(dx, dy));
  }
  return best;
}

/* shape_circumscribe_draw: A, B and C lie on the drawn shape (to rounding),
** and a D far enough from it is inside exactly when the exact decision of
** ABCD says BD (D inside the circumscribing shape of ABC); a corner's
** rounding shape draws nothing and names shape_circumscribe's corner.  The
** ellipse's 256 points are a polygon inscribed in it, so that check is on
** D's side only beyond the chord error (1 - cos(pi/256) of its size). */
static void test_circumscribe_draw(void **state) {
  (void)state;
  static const char *const specs[] = {"square", "triangle", "hexagon", "ngon:7",
                                      "poly:0 0;3 1;4 4;1 3", "ellipse:2 1 0.5"};
  testutil_rng rng = {11};
  geom_point out[256];
  for (size_t s = 0; s < sizeof specs / sizeof specs[0]; s++) {
    shape *k = tshape_get(specs[s]);
    int drawn = 0;
    for (int i = 0; i < 3000; i++) {
      geom_point q[4];
      testutil_convex_quad(&rng, q);
      int corner = -1, e[3], c2 = -1;
      int n = shape_circumscribe_draw(k, q[0], q[1], q[2], out, 256, &corner);
      if (k->kind == SHAPE_POLYGON) {
        int r = shape_circumscribe(k, q[0], q[1], q[2], e, &c2);
        assert_int_equal(n == 0, r == 0);
        if (r == 0) assert_int_equal(corner, c2);
      }
      if (n <= 0) continue;
      drawn++;
      double size = fabs(out[0].x - out[n / 2].x) + fabs(out[0].y - out[n / 2].y);
      double tol = 1e-9 * size + (n == 256 ? size * 1e-4 : 0);
      for (int j = 0; j < 3; j++) assert_true(fabs(tshape_side_dist(out, n, q[j])) <= tol);
      double dd = tshape_side_dist(out, n, q[3]);
      shape_choice c = shape_decide(k, q[0], q[1], q[2], q[3], NULL);
      if (dd > tol) assert_int_equal(c, SHAPE_BD);
      if (dd < -tol) assert_int_equal(c, SHAPE_AC);
    }
    assert_true(drawn > 1000);
    shape_free(k);
  }
  shape *k = tshape_get("square");
  assert_int_equal(shape_circumscribe_draw(k, (geom_point){0, 0}, (geom_point){1, 1},
                                           (geom_point){2, 2}, out, 256, NULL), -1);
  shape_free(k);
  k = tshape_get("ellipse:2 1");
  assert_int_equal(shape_circumscribe_draw(k, (geom_point){0, 0}, (geom_point){1, 0},
                                           (geom_point){0, 1}, out, 2, NULL), -1);
  shape_free(k);
}

/* Regular n-gons approach the circle: their rules disagree with DT on
** fewer random quadrilaterals as n grows.  With 20000 quadrilaterals a
** count's standard deviation is below 70; the steps asserted are larger
** than 4 of them (the measured counts are printed). */
static void test_ngon_to_dt(void **state) {
  (void)state;
  static const int ns[] = {4, 6, 12, 24, 64};
  long prev = 1L << 30;
  for (size_t i = 0; i < sizeof ns / sizeof ns[0]; i++) {
    char spec[32];
    snprintf(spec, sizeof spec, "ngon:%d", ns[i]);
    shape *k = tshape_get(spec);
    testutil_rng rng = {99};
    long dis = 0;
    for (int j = 0; j < 20000; j++) {
      geom_point q[4];
      testutil_convex_quad(&rng, q);
      dis += shape_decide(k, q[0], q[1], q[2], q[3], NULL) != tshape_dt(q[0], q[1], q[2], q[3]);
    }
    printf("ngon:%-3d disagrees with DT on %ld of 20000\n", ns[i], dis);
    assert_true(dis < prev - 250 || (i > 0 && dis < 300 && dis < prev));
    prev = dis;
    shape_free(k);
  }
}

/* ---- parsing ------------------------------------------------------------- */

static void test_named(void **state) {
  (void)state;
  shape *k = tshape_get("square");
  assert_int_equal(k->n, 4);
  assert_true(k->v[0].x == -1 && k->v[0].y == -1 && k->v[2].x == 1 && k->v[2].y == 1);
  shape_free(k);
  k = tshape_get("triangle");
  assert_true(k->n == 3 && k->v[1].x == 1 && k->v[1].y == 0 && k->v[2].x == 0 && k->v[2].y == 1);
  shape_free(k);
  k = tshape_get("hexagon");
  assert_int_equal(k->n, 6);
  assert_true(k->v[1].x == 0.5 && k->v[1].y == 908093 * 0x1p-20 && k->v[3].x == -1);
  shape_free(k);
  k = tshape_get("octagon");
  assert_true(k->n == 8 && k->v[1].x == 741455 * 0x1p-20 && k->v[2].x == 0 && k->v[2].y == 1);
  shape_free(k);
  /* clockwise input is reversed, keeping the first vertex */
  k = tshape_get("poly:0 0;0 1;1 0");
  assert_true(k->v[0].x == 0 && k->v[1].x == 1 && k->v[1].y == 0);
  shape_free(k);
  k = tshape_get("poly: 0, 0 ; 2,0;0 2");   /* blanks around numbers */
  assert_int_equal(k->n, 3);
  shape_free(k);
  k = tshape_get("ellipse:2,1,0.5");
  assert_true(k->kind == SHAPE_ELLIPSE && k->q12 != 0);
  shape_free(k);
  k = tshape_get("ngon:1024");
  assert_int_equal(k->n, 1024);
  shape_free(k);
}

/* Support points, ties included: an edge parallel to PQ with PQ's direction
** counts as turned clockwise from it, so the support is its start vertex. */
static void test_support(void **state) {
  (void)state;
  shape *k = tshape_get("square");   /* (-1,-1) (1,-1) (1,1) (-1,1) */
  geom_point o = {0, 0};
  assert_int_equal(shape_support(k, o, (geom_point){1, 0}), 0);    /* bottom edge, tie */
  assert_int_equal(shape_support(k, o, (geom_point){0, 1}), 1);    /* right edge, tie */
  assert_int_equal(shape_support(k, o, (geom_point){-1, 0}), 2);   /* top edge, tie */
  assert_int_equal(shape_support(k, o, (geom_point){0, -1}), 3);   /* left edge, tie */
  assert_int_equal(shape_support(k, o, (geom_point){1, 1}), 1);    /* normal (1,-1) */
  assert_int_equal(shape_support(k, o, (geom_point){1, -1}), 0);   /* normal (-1,-1) */
  assert_int_equal(shape_support(k, o, (geom_point){-1, 1}), 2);
  assert_int_equal(shape_support(k, o, (geom_point){-1, -1}), 3);
  shape_free(k);
  k = tshape_get("ngon:100");
  for (int i = 0; i < 100; i++) {   /* PQ along edge i: its start vertex */
    geom_point p = k->v[i], q = k->v[(i + 1) % 100];
    assert_int_equal(shape_support(k, (geom_point){0, 0}, (geom_point){q.x - p.x, q.y - p.y}), i);
  }
  shape_free(k);
}

static void test_bad_specs(void **state) {
  (void)state;
  static const struct { const char *spec, *why; } bad[] = {
    {"", "unknown shape"}, {"circle", "unknown shape"}, {"poly:", "vertex 1"},
    {"poly:0 0;1 0", "too few"}, {"poly:0 0;1 0;1 1;0 1;0.5 0.5", "convex"},
    {"poly:0 0;1 0;0 0;0 1", "duplicate"}, {"poly:0 0;1 0;2 0;0 1", "collinear"},
    {"poly:0 0;1 0;0 1;", "vertex 4"}, {"poly:0 0;1 nan;0 1", "not finite"},
    {"poly:0 0;1 0;0 1e31", "out of range"}, {"poly:0 0;1 0;0", "two coordinates"},
    {"poly:0 0 0;1 0;0 1", "too many"}, {"poly:0,,0;1 0;0 1", "missing"},
    {"poly:0 0;1 x;0 1", "missing"}, {"ngon:2", "3 to"}, {"ngon:x", "3 to"},
    {"ngon:1025", "3 to"}, {"ellipse:", "missing"}, {"ellipse:1", "expects"},
    {"ellipse:0 1", "semi-axes"}, {"ellipse:1 1e9", "semi-axes"}, {"ellipse:1 2 inf", "finite"},
    {"ellipse:1 2 3 4", "too many"},
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    shape *k = NULL;
    char err[512];
    err[0] = '\0';
    assert_int_equal(shape_parse(bad[i].spec, &k, err, sizeof err), -1);
    if (strstr(err, bad[i].why) == NULL || strchr(err, '\n') != NULL)
      fail_msg("'%s': got '%s', expected it to mention '%s'", bad[i].spec, err, bad[i].why);
  }
}


/* ---- the filters against the exact runs ------------------------------------
**
** A predicate's double run answers only when its error bound proves the sign
** (shapes/shape_arith.c), reads kept shape-only determinants, and evaluates
** det4 along its last column; none of that may change a decision.  So the
** decision with the filters must be, trace and all, the decision with every
** predicate taken exactly (shape_set_exact_only).  The quadrilaterals are
** where a filter is most likely to be wrong: grid points (sites on lines
** parallel to the edges, on a corner's cone, four on one homothet), sites
** displaced by small multiples of two edge directions of the shape (every
** site pair parallel to some edge), near-degenerate random quadrilaterals
** far from the origin, and tiny and huge scales within the coordinate
** contract (2^-90 .. 2^90 of the unit). */

static long tshape_fallbacks;

static void tshape_same_exact(const shape *k, const geom_point q[4]) {
  shape_trace t1, t2;
  unsigned long before = shape_exact_calls();
  shape_choice c1 = shape_decide(k, q[0], q[1], q[2], q[3], &t1);
  tshape_fallbacks += shape_exact_calls() > before;
  shape_set_exact_only(1);
  shape_choice c2 = shape_decide(k, q[0], q[1], q[2], q[3], &t2);
  shape_set_exact_only(0);
  if (c1 != c2 || t1.rounding != t2.rounding || t1.corner != t2.corner ||
      t1.level != t2.level || t1.failed != t2.failed ||
      memcmp(t1.contact, t2.contact, sizeof t1.contact) != 0)
    fail_msg("filtered %d (level %d) vs exact %d (level %d) on (%a,%a) (%a,%a) (%a,%a) (%a,%a)",
             c1, t1.level, c2, t2.level, q[0].x, q[0].y, q[1].x, q[1].y, q[2].x, q[2].y,
             q[3].x, q[3].y);
}

/* Four sites base + a_i u + b_i w (small integers a_i, b_i; u, w two edge
** directions of k, or the axes for an ellipse) in strictly convex position,
** anticlockwise: 0 if the draw is not. */
static int tshape_edge_quad(testutil_rng *rng, const shape *k, geom_point q[4]) {
  geom_point u = {1, 0}, w = {0, 1};
  if (k->kind == SHAPE_POLYGON) {
    int i = (int)(testutil_next(rng) % (uint64_t)k->n), j = (int)(testutil_next(rng) % (uint64_t)k->n);
    u = (geom_point){k->v[(i + 1) % k->n].x - k->v[i].x, k->v[(i + 1) % k->n].y - k->v[i].y};
    w = (geom_point){k->v[(j + 1) % k->n].x - k->v[j].x, k->v[(j + 1) % k->n].y - k->v[j].y};
  }
  geom_point p[4];
  for (int r = 0; r < 4; r++) {
    double a = (double)(testutil_next(rng) % 7) - 3, b = (double)(testutil_next(rng) % 7) - 3;
    p[r] = (geom_point){3 + a * u.x + b * w.x, 5 + a * u.y + b * w.y};
  }
  static const int perm[6][3] = {{1, 2, 3}, {1, 3, 2}, {2, 1, 3}, {2, 3, 1}, {3, 1, 2}, {3, 2, 1}};
  for (int i = 0; i < 6; i++) {
    q[0] = p[0], q[1] = p[perm[i][0]], q[2] = p[perm[i][1]], q[3] = p[perm[i][2]];
    if (tshape_convex(q)) return 1;
  }
  return 0;
}

static void tshape_scaled(const shape *k, const geom_point q[4], double s, double o) {
  geom_point r[4];
  for (int i = 0; i < 4; i++) r[i] = (geom_point){o + s * q[i].x, o + s * q[i].y};
  if (tshape_convex(r)) tshape_same_exact(k, r);
}

static void test_filter_exact(void **state) {
  (void)state;
  static const char *const specs[] = {"square", "diamond", "triangle", "hexagon", "octagon",
                                      "ngon:7", "poly:0 0;3 1;4 4;1 3", "ngon:24", "ellipse:2 1",
                                      "ellipse:2 1 0.5"};
  static const double scale[] = {1, 0x1p-90, 0x1p90, 0.1};
  testutil_rng rng = {2026};
  tshape_fallbacks = 0;
  for (size_t si = 0; si < sizeof specs / sizeof specs[0]; si++) {
    shape *k = tshape_get(specs[si]);
    geom_point q[4];
    for (int it = 0; it < 80; it++) {
      if (tshape_grid_quad(&rng, 4 + it % 5, 1, 0, q))
        for (size_t j = 0; j < 4; j++) tshape_scaled(k, q, scale[j], 0);
      if (tshape_edge_quad(&rng, k, q)) {
        tshape_same_exact(k, q);
        tshape_scaled(k, q, 0x1p-60, 0x1p-40);
      }
      testutil_convex_quad(&rng, q);
      tshape_same_exact(k, q);
      tshape_scaled(k, q, 0x1p-30, 1e6);   /* nearly equal coordinates: cancellation */
    }
    shape_free(k);
  }
  /* The inputs reach the exact runs (else the comparison proves little). */
  assert_true(tshape_fallbacks > 300);
}

/* ---- the quick path against the exact runs ----------------------------------
**
** shapes/shape_quick.c answers a decision only when every sign it rests on is
** certain, and claims that answer (and its supports and contact triple) is
** the filtered-exact path's.  Checked against the purely exact decision on
** random quadrilaterals (where it must answer most of the time, else it
** saves nothing) and where it is most likely to be wrong: four sites on one
** homothet (exactly, at its corners, or nudged by an ulp), grid points,
** sites displaced along the shape's edge directions (pairs parallel to
** sides), and tiny and huge scales. */

static long tquick_answers, tquick_tries;

static void tquick_same1(const shape *k, const geom_point q[4]) {
  shape_trace tr;
  shape_set_exact_only(1);
  shape_choice ce = shape_decide(k, q[0], q[1], q[2], q[3], &tr);
  int se[3] = {shape_support(k, q[0], q[1]), shape_support(k, q[1], q[2]),
               shape_support(k, q[2], q[0])}, sup[3], t[3];
  assert_int_equal(shape_quick_ready(k, q), 0);   /* the exact-only mode takes no quick answer */
  shape_set_exact_only(0);
  if (!shape_quick_ready(k, q)) return;
  if (shape_quick_supports(k, q, sup) == 0)
    for (int r = 0; r < 3; r++) assert_int_equal(sup[r], se[r]);
  tquick_tries++;
  if (se[0] == se[1] || se[1] == se[2] || se[2] == se[0]) {   /* a corner's rounding shape */
    int corner = se[0] == se[1] || se[0] == se[2] ? se[0] : se[1];
    int s = shape_quick_corner(k, corner, q);
    if (s == 2) return;
    tquick_answers++;
    if ((s < 0 ? SHAPE_BD : SHAPE_AC) != (int)ce || !tr.rounding || tr.corner != corner)
      fail_msg("quick corner %d vs exact %d on (%a,%a) (%a,%a) (%a,%a) (%a,%a)", s, ce, q[0].x,
               q[0].y, q[1].x, q[1].y, q[2].x, q[2].y, q[3].x, q[3].y);
    return;
  }
  int c = shape_quick_homothet(k, se, q, t);
  if (c < 0) return;
  tquick_answers++;
  if (c != (int)ce || tr.rounding || memcmp(t, tr.contact, sizeof t) != 0)
    fail_msg("quick %d vs exact %d on (%a,%a) (%a,%a) (%a,%a) (%a,%a)", c, ce, q[0].x, q[0].y,
             q[1].x, q[1].y, q[2].x, q[2].y, q[3].x, q[3].y);
}

/* Every rotation of q (each is a decision of its own). */
static void tquick_same(const shape *k, const geom_point q[4]) {
  for (int r = 0; r < 4; r++) {
    geom_point p[4] = {q[r], q[(r + 1) % 4], q[(r + 2) % 4], q[(r + 3) % 4]};
    tquick_same1(k, p);
  }
}

/* x moved by k ulps, up for k > 0, down for k < 0. */
static double tquick_ulps(double x, int k) {
  for (; k > 0; k--) x = nextafter(x, 1e300);
  for (; k < 0; k++) x = nextafter(x, -1e300);
  return x;
}

/* Four sites on the homothet c + s k at boundary parameters u (edge floor(u),
** fraction u - floor(u), a corner when 0), sorted: anticlockwise; the last
** nudged by `nudge` ulps in x.  0 when they are not strictly convex. */
static int tquick_on_homothet(testutil_rng *rng, const shape *k, geom_point q[4], int nudge) {
  double u[4], c = testutil_uniform(rng) * 8 - 4, s = 0.5 + testutil_uniform(rng) * 4;
  for (int r = 0; r < 4; r++) {
    u[r] = testutil_uniform(rng) * k->n;
    if (testutil_next(rng) % 3 == 0) u[r] = floor(u[r]);   /* a corner of the homothet */
  }
  for (int i = 1; i < 4; i++)
    for (int j = i; j > 0 && u[j - 1] > u[j]; j--) {
      double x = u[j];
      u[j] = u[j - 1], u[j - 1] = x;
    }
  for (int r = 0; r < 4; r++) {
    int i = (int)u[r];
    double f = u[r] - i;
    geom_point a = k->v[i], b = k->v[(i + 1) % k->n];
    q[r] = (geom_point){c + s * (a.x + f * (b.x - a.x)), c * 0.5 + s * (a.y + f * (b.y - a.y))};
  }
  q[3].x = tquick_ulps(q[3].x, nudge);
  return tshape_convex(q);
}

static void test_quick_exact(void **state) {
  (void)state;
  static const char *const specs[] = {"square", "diamond", "triangle", "hexagon", "octagon",
                                      "ngon:7", "ngon:16", "poly:0 0;3 1;4 4;1 3",
                                      "poly:0.1 0.2;3.3 1.1;4 4.7;0.9 3.9;-0.7 1.3"};
  testutil_rng rng = {2027};
  for (size_t si = 0; si < sizeof specs / sizeof specs[0]; si++) {
    shape *k = tshape_get(specs[si]);
    geom_point q[4];
    tquick_answers = tquick_tries = 0;
    for (int it = 0; it < testutil_reps(400); it++) {
      testutil_convex_quad(&rng, q);
      tquick_same(k, q);
    }
    /* Random quadrilaterals are the quick path's case. */
    assert_true(tquick_answers > tquick_tries * 9 / 10);
    long a0 = tquick_answers, t0 = tquick_tries;
    for (int it = 0; it < testutil_reps(400); it++) {
      if (tquick_on_homothet(&rng, k, q, it % 5 - 2)) tquick_same(k, q);
      if (tshape_grid_quad(&rng, 3 + it % 6, it % 2 ? 0x1p-90 : 0x1p90, 0, q)) tquick_same(k, q);
      if (tshape_edge_quad(&rng, k, q)) tquick_same(k, q);
      testutil_convex_quad(&rng, q);
      for (int r = 0; r < 4; r++) q[r] = (geom_point){1e6 + 0x1p-30 * q[r].x, 1e6 + 0x1p-30 * q[r].y};
      if (tshape_convex(q)) tquick_same(k, q);
    }
    printf("quick   %-26s random: answered %ld of %ld; adversarial: %ld of %ld\n", specs[si], a0,
           t0, tquick_answers - a0, tquick_tries - t0);
    shape_free(k);
  }
}

/* A hint (shape_decide_hinted) answers as a fresh decision: one triangle
** ABC, its hint kept, against many D (beyond CA, near its shape's boundary
** and far from it), on random triangles and on triangles with sites on a
** homothet's corners; both kinds of hint, homothet and rounding corner,
** must occur, and the hinted call in the exact-only mode too. */
static void test_hint(void **state) {
  (void)state;
  static const char *const specs[] = {"square", "triangle", "hexagon", "ngon:7",
                                      "poly:0.1 0.2;3.3 1.1;4 4.7;0.9 3.9;-0.7 1.3"};
  testutil_rng rng = {2028};
  long kinds[3] = {0, 0, 0}, asked = 0, rotated = 0;   /* kinds by how: none, homothet, corner */
  for (size_t si = 0; si < sizeof specs / sizeof specs[0]; si++) {
    shape *k = tshape_get(specs[si]);
    for (int it = 0; it < testutil_reps(400); it++) {
      geom_point q[4];
      if (it % 2 ? !tquick_on_homothet(&rng, k, q, 0) : (testutil_convex_quad(&rng, q), 0))
        continue;
      shape_hint h = {0};
      for (int j = 0; j < 12; j++) {
        geom_point p[4] = {q[0], q[1], q[2], q[3]};
        double w = j < 6 ? 0x1p-20 * (j + 1) : 0.2 * (j - 5);
        if (j > 0)
          p[3] = (geom_point){q[3].x + w * (testutil_uniform(&rng) - 0.5),
                              q[3].y + w * (testutil_uniform(&rng) - 0.5)};
        if (!tshape_convex(p)) continue;
        int exact = j % 3 == 2;
        shape_set_exact_only(exact);
        shape_choice got = shape_decide_hinted(k, p[0], p[1], p[2], p[3], &h);
        shape_set_exact_only(0);
        shape_choice want = shape_decide(k, p[0], p[1], p[2], p[3], NULL);
        if (got != want)
          fail_msg("%s: hinted %d, fresh %d (hint %d, exact-only %d) on (%a,%a) (%a,%a) (%a,%a) "
                   "(%a,%a)", specs[si], got, want, h.how, exact, p[0].x, p[0].y, p[1].x, p[1].y,
                   p[2].x, p[2].y, p[3].x, p[3].y);
        /* the square's bounding-box decisions need no hint */
        assert_true(h.how == SHAPE_HINT_HOMOTHET || h.how == SHAPE_HINT_CORNER ||
                    (h.how == SHAPE_HINT_NONE && !shape_wants_hints(k)));
        kinds[h.how]++;
        asked++;
        /* lot reads a triangle's hint through any rotation: B C A, its
        ** contact edges rotated, against D' beyond AB */
        if (h.how != SHAPE_HINT_HOMOTHET) continue;
        shape_hint hr = {SHAPE_HINT_HOMOTHET, {h.e[1], h.e[2], h.e[0]}};
        geom_point r[4] = {p[1], p[2], p[0], {p[0].x + p[1].x - p[2].x, p[0].y + p[1].y - p[2].y}};
        if (!tshape_convex(r)) continue;
        got = shape_decide_hinted(k, r[0], r[1], r[2], r[3], &hr);
        want = shape_decide(k, r[0], r[1], r[2], r[3], NULL);
        if (got != want)
          fail_msg("%s: rotated hint %d, fresh %d", specs[si], got, want);
        rotated++;
      }
    }
    shape_free(k);
  }
  printf("hint: %ld decisions, %ld with a homothet's hint, %ld with a corner's, %ld rotated\n",
         asked, kinds[SHAPE_HINT_HOMOTHET], kinds[SHAPE_HINT_CORNER], rotated);
  assert_true(kinds[SHAPE_HINT_HOMOTHET] > 0 && kinds[SHAPE_HINT_CORNER] > 0 && rotated > 0);
}

/* ---- the square's and the hexagon's own decisions ----------------------
**
** shapes/shape_square.c (bounding boxes) and shapes/shape_hex.c (slab
** coordinates) answer only when every comparison is certain, and claim the
** general path's answer.  Each is checked against the purely exact decision
** on the shapes that take it: on random quadrilaterals at scales 2^-60 to
** 2^60 it must answer at least the share given, and on grid points (sites
** with one x or one y everywhere), on four sites of one homothet (exactly,
** at its corners, or an ulp off) and through every rotation it may only
** answer what the exact run answers; shapes near them must not take it. */

typedef struct tfast {
  const char *name;
  int (*decide)(const shape *k, const geom_point p[4]);
  int (*takes)(const shape *k);
  const char *const *yes, *const *no;   /* NULL-terminated spec lists */
  long share;                           /* random: answered > asked * share / 10 */
} tfast;

static int tfast_square(const shape *k, const geom_point p[4]) {
  (void)k;
  return shape_square_decide(p);
}

static int tfast_square_takes(const shape *k) {
  return shape_variant_of(k) == SHAPE_V_SQUARE;
}

static int tfast_hex(const shape *k, const geom_point p[4]) {
  return shape_hex_decide(k, p, NULL);
}

static int tfast_hex_takes(const shape *k) {
  return shape_variant_of(k) == SHAPE_V_HEXAGON;
}

static void tfast_same(const tfast *f, const shape *k, const geom_point q[4], long *asked,
                       long *answered) {
  for (int r = 0; r < 4; r++) {
    geom_point p[4] = {q[r], q[(r + 1) % 4], q[(r + 2) % 4], q[(r + 3) % 4]};
    if (!shape_quick_ready(k, p)) continue;
    shape_set_exact_only(1);
    shape_choice want = shape_decide(k, p[0], p[1], p[2], p[3], NULL);
    shape_set_exact_only(0);
    int got = f->decide(k, p);
    shape_choice whole = shape_decide_valid(k, p[0], p[1], p[2], p[3]);
    (*asked)++;
    *answered += got >= 0;
    if ((got >= 0 && got != (int)want) || whole != want)
      fail_msg("%s %d (whole %d) vs exact %d on (%a,%a) (%a,%a) (%a,%a) (%a,%a)", f->name, got,
               whole, want, p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y, p[3].x, p[3].y);
  }
}

static void tfast_check(const tfast *f, testutil_rng *rng) {
  for (const char *const *spec = f->no; *spec != NULL; spec++) {
    shape *k = tshape_get(*spec);
    assert_int_equal(f->takes(k), 0);
    shape_free(k);
  }
  for (const char *const *spec = f->yes; *spec != NULL; spec++) {
    shape *k = tshape_get(*spec);
    assert_int_equal(f->takes(k), 1);
    long asked = 0, answered = 0;
    geom_point q[4];
    for (int it = 0; it < testutil_reps(600); it++) {
      testutil_convex_quad(rng, q);
      double scale = ldexp(1, 60 * (it % 3 - 1));
      for (int r = 0; r < 4; r++) q[r] = (geom_point){q[r].x * scale, q[r].y * scale};
      tfast_same(f, k, q, &asked, &answered);
    }
    assert_true(answered > asked * f->share / 10);
    long random = asked;
    for (int it = 0; it < testutil_reps(300); it++)
      if (tshape_grid_quad(rng, 5, 1, 0, q)) tfast_same(f, k, q, &asked, &answered);
    for (int it = 0; it < testutil_reps(900); it++)
      if (tquick_on_homothet(rng, k, q, it % 3 - 1)) tfast_same(f, k, q, &asked, &answered);
    printf("%-7s %-30s %ld of %ld answered (%ld random)\n", f->name, *spec, answered, asked,
           random);
    shape_free(k);
  }
}

/* Squares of any size, either orientation; a rectangle an ulp from square
** does not take it, nor a diamond.  Random quadrilaterals leave only
** staircases (a corner's rounding shape) to the general path. */
static const char *const tfast_squares[] = {"square", "poly:1 1;1.5 1;1.5 1.5;1 1.5",
                                            "poly:3 -1;-2 -1;-2 4;3 4", NULL};
static const char *const tfast_not_squares[] = {
    "diamond", "hexagon", "poly:0 0;2 0;2 2.0000000000000004;0 2",
    "poly:0 0;2 0;2 2;0 2.0000000000000004", NULL};
static const tfast tfast_square_case = {"square", tfast_square, tfast_square_takes,
                                        tfast_squares, tfast_not_squares, 5};

/* Affinely regular hexagons (the named one, a sheared one with exact
** edges, either orientation) answer nearly every random quadrilateral,
** corners' rounding shapes included; a centrally symmetric hexagon that is
** not affinely regular, the octagon, the square and a hexagon an ulp off do
** not take it. */
static const char *const tfast_hexes[] = {"hexagon", "poly:2 0;3 1;2 2;0 2;-1 1;0 0",
                                          "poly:0 0;-1 1;0 2;2 2;3 1;2 0", NULL};
static const char *const tfast_not_hexes[] = {
    "poly:2 0;3 2;1 3;-2 0;-3 -2;-1 -3", "octagon", "square",
    "poly:2 0;3 1;2 2;0 2;-1 1;0 0.0000000000000002", NULL};
static const tfast tfast_hex_case = {"hexagon", tfast_hex, tfast_hex_takes, tfast_hexes,
                                     tfast_not_hexes, 9};

/* The hexagon's decision from a known contact triple (shape_hex_at, as
** lot's hints ask it): the triple is the exact run's own, so wherever the
** exact run finds a homothet the answer must be its; a rounding shape is
** not asked (its hint is a corner's). */
static int tfast_hex_at(const shape *k, const geom_point p[4]) {
  shape_trace tr;
  shape_set_exact_only(1);
  shape_decide(k, p[0], p[1], p[2], p[3], &tr);
  shape_set_exact_only(0);
  return tr.rounding || tr.contact[0] < 0 ? -1 : shape_hex_at(k, tr.contact, p);
}

static const tfast tfast_hex_at_case = {"hex-at", tfast_hex_at, tfast_hex_takes, tfast_hexes,
                                        tfast_not_hexes, 7};

/* The state: the tfast to check. */
static void test_fast_exact(void **state) {
  testutil_rng rng = {2029};
  tfast_check(*state, &rng);
}

/* shape_hex_at's equations, for each of the 216 contact triples: three
** sites on the named sides of a random homothet c + s K and D inside it
** (c + s l X, X in K, l <= 0.9) or outside (l >= 1.1).  Three different
** sides fix the homothet (two parallel ones and a third, or one side of
** each slab), so the answer must be given and be right; a side named twice
** leaves a family of homothets, and the answer must be -1. */
static void test_hex_at(void **state) {
  (void)state;
  static const char *const specs[] = {"hexagon", "poly:2 0;3 1;2 2;0 2;-1 1;0 0"};
  testutil_rng rng = {2031};
  for (size_t si = 0; si < sizeof specs / sizeof specs[0]; si++) {
    shape *k = tshape_get(specs[si]);
    long answered = 0, refused = 0;
    for (int t = 0; t < 216; t++) {
      int tt[3] = {t % 6, t / 6 % 6, t / 36};
      int fixed = tt[0] != tt[1] && tt[1] != tt[2] && tt[0] != tt[2];
      for (int it = 0; it < testutil_reps(20); it++) {
        geom_point c = {testutil_uniform(&rng) * 8 - 4, testutil_uniform(&rng) * 8 - 4}, p[4];
        double sc = 0.25 + testutil_uniform(&rng) * 4;
        for (int j = 0; j < 3; j++) {
          geom_point a = k->v[tt[j]], b = k->v[(tt[j] + 1) % 6];
          double f = 0.05 + 0.9 * testutil_uniform(&rng);
          p[j] = (geom_point){c.x + sc * (a.x + f * (b.x - a.x)), c.y + sc * (a.y + f * (b.y - a.y))};
        }
        /* D = c + s (o + l (Y - o)): Y on the boundary of K, o its centre */
        int i0 = (int)(testutil_next(&rng) % 6), i1 = (i0 + 1) % 6, inside = it % 2;
        double f = testutil_uniform(&rng), g = testutil_uniform(&rng);
        double l = inside ? 0.9 * g : 1.1 + g;
        geom_point o = {0, 0}, y = {k->v[i0].x + f * (k->v[i1].x - k->v[i0].x),
                                    k->v[i0].y + f * (k->v[i1].y - k->v[i0].y)};
        for (int j = 0; j < 6; j++) o = (geom_point){o.x + k->v[j].x / 6, o.y + k->v[j].y / 6};
        p[3] = (geom_point){c.x + sc * (o.x + l * (y.x - o.x)), c.y + sc * (o.y + l * (y.y - o.y))};
        int got = shape_hex_at(k, tt, p);
        if (!fixed) {
          if (got != -1) fail_msg("%s: triple %d %d %d answered %d", specs[si], tt[0], tt[1], tt[2], got);
          refused++;
          continue;
        }
        if (got != (inside ? SHAPE_BD : SHAPE_AC))
          fail_msg("%s: triple %d %d %d, D %s: answered %d", specs[si], tt[0], tt[1], tt[2],
                   inside ? "inside" : "outside", got);
        answered++;
      }
    }
    printf("hex-at  %-30s %ld answered, %ld refused\n", specs[si], answered, refused);
    shape_free(k);
  }
}

/* The octant windows (shapes/shape_quick.c): each open octant fixes the
** signs of the edges outside it, so the supports of directions on and next
** to an octant's boundary rays (the axes and diagonals) and to each edge's
** own direction, nudged by ulps, are where a wrong table would show; every
** certain support must be shape_support's, and random directions must be
** answered.  The last shapes have edges an ulp off a diagonal and an axis,
** and two edges whose rounded directions are exact opposites, (2, 1) and
** fl(-2 - 2^-59, -1), though the edges are not (one cross product answers
** for both: the directions between the two are probed from the points). */
static void tquick_points(const shape *k, const geom_point q[3], long *answered) {
  int sup[3];
  if (shape_quick_supports(k, q, sup) != 0) return;
  (*answered)++;
  for (int r = 0; r < 3; r++)
    if (sup[r] != shape_support(k, q[r], q[(r + 1) % 3]))
      fail_msg("quick support %d of (%a,%a) -> (%a,%a): %d, exact %d", r, q[r].x, q[r].y,
               q[(r + 1) % 3].x, q[(r + 1) % 3].y, sup[r], shape_support(k, q[r], q[(r + 1) % 3]));
}

static void tquick_dir(const shape *k, geom_point d, long *answered) {
  /* supports of d, of (-d.y - d.x, d.x - d.y) and of -(-d.y, d.x) */
  geom_point q[3] = {{0, 0}, d, {-d.y, d.x}};
  tquick_points(k, q, answered);
}

static void tquick_opposite(const shape *k, long *answered) {
  /* Q - P = (2 + nud 2^-61, 1), on both sides of and between the two
  ** exact directions, and reversed directions nudged by ulps */
  for (int nud = -4; nud <= 4; nud++)
    for (int way = -1; way <= 1; way += 2) {
      geom_point q[3] = {{-nud * 0x1p-61, 0}, {2, 1}, {-1, 3}};
      if (way < 0) q[0] = (geom_point){2 + 4 * nud * 0x1p-52, 1}, q[1] = (geom_point){0, 0};
      tquick_points(k, q, answered);
    }
}

static void test_quick_octants(void **state) {
  (void)state;
  static const char *const specs[] = {"square", "diamond", "triangle", "hexagon", "octagon",
                                      "ngon:7", "ngon:16", "poly:0 0;1 1.0000000000000002;0 3",
                                      "poly:0 0;1 -0.0000000000000001;1 1;0 1",
                                      "poly:0 0;2 1;2 3;1.7347234759768071e-18 3;-2 2"};
  testutil_rng rng = {2028};
  for (size_t si = 0; si < sizeof specs / sizeof specs[0]; si++) {
    shape *k = tshape_get(specs[si]);
    long answered = 0, tried = 0;
    for (int it = 0; it < 4000; it++, tried++) {
      double a = testutil_uniform(&rng) * 2 - 1, b = testutil_uniform(&rng) * 2 - 1;
      tquick_dir(k, (geom_point){a, b}, &answered);
    }
    assert_true(answered > tried * 99 / 100);
    for (int sx = -1; sx <= 1; sx += 2)
      for (int sy = -1; sy <= 1; sy += 2)
        for (int nud = -3; nud <= 3; nud++) {
          double one = tquick_ulps(1, nud), tiny = nud * 0x1p-60;
          tquick_dir(k, (geom_point){sx * 1.0, sy * one}, &answered);    /* diagonals */
          tquick_dir(k, (geom_point){sx * one, sy * 1.0}, &answered);
          tquick_dir(k, (geom_point){sx * 1.0, tiny}, &answered);        /* axes */
          tquick_dir(k, (geom_point){tiny, sy * 1.0}, &answered);
        }
    for (int j = 0; j < k->n; j++) {   /* each edge's direction, both ways, nudged */
      geom_point a = k->v[j], b = k->v[(j + 1) % k->n];
      for (int nud = -3; nud <= 3; nud++) {
        geom_point d = {b.x - a.x, tquick_ulps(b.y - a.y, nud)};
        tquick_dir(k, d, &answered);
        tquick_dir(k, (geom_point){-d.x, -d.y}, &answered);
      }
    }
    tquick_opposite(k, &answered);
    shape_free(k);
  }
}

/* Every shape is one variant, chosen when it is made, and the public verbs
** answer through its table: each spec below is the variant named, wants
** hints as shape.h says (polygons of 3 to 255 vertices but the
** axis-parallel square; no ellipse) and gives through the table, with a
** trace, hinted (an empty hint, then the one it left) or not, the purely
** exact decision of the general path, in every rotation. */
typedef struct tvariant {
  const char *spec;
  shape_variant v;
  int hints;
} tvariant;

static const tvariant tvariants[] = {
    {"square", SHAPE_V_SQUARE, 0},    {"poly:3 -1;-2 -1;-2 4;3 4", SHAPE_V_SQUARE, 0},
    {"hexagon", SHAPE_V_HEXAGON, 1},  {"poly:0 0;-1 1;0 2;2 2;3 1;2 0", SHAPE_V_HEXAGON, 1},
    {"diamond", SHAPE_V_DIAMOND, 1},  {"triangle", SHAPE_V_POLYGON, 1},
    {"octagon", SHAPE_V_POLYGON, 1},  {"ngon:255", SHAPE_V_POLYGON, 1},
    {"ngon:256", SHAPE_V_POLYGON, 0}, {"ellipse:2 1 0.5", SHAPE_V_ELLIPSE, 0},
    {"ellipse:1 1", SHAPE_V_ELLIPSE, 0}};

static void tvariant_same(const shape *k, const geom_point q[4]) {
  for (int r = 0; r < 4; r++) {
    geom_point a = q[r], b = q[(r + 1) % 4], c = q[(r + 2) % 4], d = q[(r + 3) % 4];
    shape_set_exact_only(1);
    shape_choice want = shape_decide(k, a, b, c, d, NULL);
    shape_set_exact_only(0);
    shape_trace tr;
    shape_hint h = {0};
    assert_int_equal(shape_decide(k, a, b, c, d, NULL), want);
    assert_int_equal(shape_decide(k, a, b, c, d, &tr), want);
    assert_int_equal(shape_decide_valid(k, a, b, c, d), want);
    assert_int_equal(shape_decide_hinted(k, a, b, c, d, &h), want);
    assert_int_equal(shape_decide_hinted(k, a, b, c, d, &h), want);
  }
}

static void test_variants(void **state) {
  (void)state;
  testutil_rng rng = {41};
  for (size_t i = 0; i < sizeof tvariants / sizeof tvariants[0]; i++) {
    const tvariant *t = &tvariants[i];
    shape *k = tshape_get(t->spec);
    assert_int_equal(shape_variant_of(k), t->v);
    assert_int_equal(shape_wants_hints(k), t->hints);
    geom_point q[4];
    for (int it = 0; it < testutil_reps(200); it++) {
      testutil_convex_quad(&rng, q);
      tvariant_same(k, q);
      if (tshape_grid_quad(&rng, 4, 1, 0, q)) tvariant_same(k, q);
    }
    shape_free(k);
  }
}

/* Two groups, so that ctest runs them side by side (tests/CMakeLists.txt):
** "quick" (the quick path against the exact one, the slowest) and "rest";
** no argument runs both. */
int main(int argc, char **argv) {
  const struct CMUnitTest quick[] = {
    cmocka_unit_test(test_filter_exact),
    cmocka_unit_test(test_quick_exact),
    cmocka_unit_test(test_quick_octants),
    cmocka_unit_test(test_hint),
    cmocka_unit_test_prestate(test_fast_exact, (void *)&tfast_square_case),
    cmocka_unit_test_prestate(test_fast_exact, (void *)&tfast_hex_case),
    cmocka_unit_test_prestate(test_fast_exact, (void *)&tfast_hex_at_case),
    cmocka_unit_test(test_hex_at),
  };
  const struct CMUnitTest rest[] = {
    cmocka_unit_test(test_rotations_random),
    cmocka_unit_test(test_rotations_grid),
    cmocka_unit_test(test_oracle),
    cmocka_unit_test(test_square_diamond),
    cmocka_unit_test(test_ellipse_dt),
    cmocka_unit_test(test_homothety),
    cmocka_unit_test(test_circumscribe_draw),
    cmocka_unit_test(test_ngon_to_dt),
    cmocka_unit_test(test_named),
    cmocka_unit_test(test_support),
    cmocka_unit_test(test_bad_specs),
    cmocka_unit_test(test_variants),
  };
  const char *part = argc > 1 ? argv[1] : "";
  if (*part != '\0' && strcmp(part, "quick") != 0 && strcmp(part, "rest") != 0) {
    fprintf(stderr, "test_shape: unknown group '%s' (quick or rest)\n", part);
    return 2;
  }
  int rc = 0;
  if (strcmp(part, "rest") != 0) rc |= cmocka_run_group_tests_name("quick", quick, NULL, NULL);
  if (strcmp(part, "quick") != 0) rc |= cmocka_run_group_tests_name("rest", rest, NULL, NULL);
  return rc;
}
