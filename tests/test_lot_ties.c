/*
** test_lot_ties.c: lot's tie-break (docs/lot.md, Ties): for DT and the
** empty-shape rules every point set has ONE triangulation, the one every
** algorithm returns.
**
** - Brute force: every triangulation of small grids, cocircular, collinear
**   and random grid sets (classify/siteflip.h enumerates them) is tested
**   for local optimality under the rule with the tie-break; exactly one
**   passes, and it is lot's, for every algorithm and insertion order.  For
**   DT the decisions come from an independent oracle: the in-circle
**   determinant of the perturbed lifting z = x^2 + y^2 + eps^(n - rank)
**   with a finite eps small enough to give the infinitesimal one's signs,
**   in GMP integers (tt_dt_oracle).  For the empty-shape rules:
**   shape_decide, and the tie-break as docs/lot.md states it.
** - Agreement: flip == incremental (spatial with two seeds, random, input)
**   == sweep (where the sweep takes the rule), triangle for triangle, on
**   every sampler, collinear-heavy and duplicate-heavy sets; the same
**   triangles (as points) for the rows shuffled; every edge of lot's
**   triangulation of integer sets passes the oracle.
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

#include "lot.h"
#include "rule.h"
#include "sampler.h"
#include "shape.h"
#include "siteflip.h"
#include "testutil.h"

#define TT_NRULES 8
static const char *const tt_rules[TT_NRULES] = {
  "DT", "ES:square", "ES:diamond", "ES:hexagon", "ES:triangle", "ES:ellipse:2 1",
  "ES:poly:0 0;3 1;4 4;1 3", "ES:octagon"};
/* The rules run on the larger sets: all but the octagon (the slowest shape
** to decide), which the brute force covers. */
#define TT_NLARGE (TT_NRULES - 1)

static rule tt_rule(const char *name) {
  rule r;
  char err[4096];
  if (rule_parse(name, &r, err, sizeof err) != 0) fail_msg("%s: %s", name, err);
  return r;
}

static int tt_lex_less(geom_point p, geom_point q) {
  return p.x < q.x || (p.x == q.x && p.y < q.y);
}

/* ---- the oracles --------------------------------------------------------- */

/* What the oracles need of a site set: the shape (NULL: DT), and for DT
** each site's lexicographic rank among the distinct sites, the power of two
** 2^s that makes every coordinate an integer and the lifting's eps = 2^-E. */
typedef struct tt_oracle {
  const shape *k;
  const geom_point *p;
  size_t n;
  size_t *rank;
  int s;
  unsigned long E;
  long ties;            /* quadrilaterals found tied (exactly) */
} tt_oracle;

static const geom_point *tt_sort_base;

static int tt_index_cmp(const void *x, const void *y) {
  geom_point a = tt_sort_base[*(const size_t *)x], b = tt_sort_base[*(const size_t *)y];
  return tt_lex_less(a, b) ? -1 : tt_lex_less(b, a);
}

/* Sites scaled by 2^s to integers X, Y of magnitude < 2^B; the lifting with
** eps = 2^-E, E = 2B + 8, scaled by 2^(E n): z_i = (X^2 + Y^2) 2^(E n) +
** 2^(E rank_i).  The in-circle determinant's cofactors along its z column
** are orientations, below 2^(2B + 3) in magnitude, so a non-zero exact
** value (at least 2^(E n)) outweighs every perturbation term, and each
** perturbation term all smaller ones together: the signs are those of an
** infinitesimal eps.  So they depend only on the order of the four sites'
** ranks, and tt_dt_oracle lifts by their ranks among the four (n = 4),
** which keeps the numbers short. */
static tt_oracle tt_oracle_make(const shape *k, const geom_point *p, size_t n) {
  tt_oracle o = {k, p, n, malloc((n + 1) * sizeof(size_t)), 0, 0, 0};
  size_t *idx = malloc((n + 1) * sizeof *idx);
  assert_true(o.rank && idx);
  double big = 0;
  for (size_t i = 0; i < n; i++) {
    idx[i] = i;
    big = fmax(big, fmax(fabs(p[i].x), fabs(p[i].y)));
    for (int c = 0; c < 2; c++) {
      double v = c ? p[i].y : p[i].x;
      while (ldexp(v, o.s) != floor(ldexp(v, o.s))) o.s++;
    }
  }
  tt_sort_base = p;
  qsort(idx, n, sizeof *idx, tt_index_cmp);
  for (size_t i = 0, r = 0; i < n; i++) {   /* equal sites share a rank */
    if (i > 0 && tt_lex_less(p[idx[i - 1]], p[idx[i]])) r++;
    o.rank[idx[i]] = r;
  }
  free(idx);
  int e;
  frexp(ldexp(big, o.s), &e);
  o.E = 2 * (unsigned long)(e > 0 ? e : 1) + 8;
  return o;
}

/* DT on the anticlockwise strictly convex quadrilateral p[q0..q3] under the
** perturbed lifting: RULE_AC when q3 is outside the perturbed circle of
** q0 q1 q2, RULE_BD when inside (the determinant of the rows
** (X - X_d, Y - Y_d, z - z_d), expanded along its z column). */
static rule_choice tt_dt_oracle(tt_oracle *o, const size_t q[4]) {
  const geom_point *p = o->p;
  mpz_t x[4], y[4], z[4], m[3][2], cof, det, t;
  mpz_inits(det, t, cof, NULL);
  for (int k = 0; k < 4; k++) {
    mpz_inits(x[k], y[k], z[k], NULL);
    mpz_set_d(x[k], ldexp(p[q[k]].x, o->s));
    mpz_set_d(y[k], ldexp(p[q[k]].y, o->s));
    mpz_mul(z[k], x[k], x[k]);
    mpz_addmul(z[k], y[k], y[k]);
    mpz_mul_2exp(z[k], z[k], o->E * 4);
    unsigned long r = 0;   /* the rank among the four: the signs depend on no more */
    for (int j = 0; j < 4; j++) r += o->rank[q[j]] < o->rank[q[k]];
    mpz_set_ui(t, 1);
    mpz_mul_2exp(t, t, o->E * r);
    mpz_add(z[k], z[k], t);
  }
  for (int r = 0; r < 3; r++) {
    mpz_inits(m[r][0], m[r][1], NULL);
    mpz_sub(m[r][0], x[r], x[3]);
    mpz_sub(m[r][1], y[r], y[3]);
  }
  for (int r = 0; r < 3; r++) {   /* cofactor r: (-1)^r (m[i] x m[j]), i < j the other rows */
    int i = r == 0 ? 1 : 0, j = r == 2 ? 1 : 2;
    mpz_mul(cof, m[i][0], m[j][1]);
    mpz_submul(cof, m[i][1], m[j][0]);
    if (r == 1) mpz_neg(cof, cof);
    mpz_sub(t, z[r], z[3]);
    mpz_addmul(det, t, cof);
  }
  o->ties += geom_incircle(p[q[0]], p[q[1]], p[q[2]], p[q[3]]) == 0;
  int sign = mpz_sgn(det);
  for (int k = 0; k < 4; k++) mpz_clears(x[k], y[k], z[k], NULL);
  for (int r = 0; r < 3; r++) mpz_clears(m[r][0], m[r][1], NULL);
  mpz_clears(det, t, cof, NULL);
  if (sign == 0) fail_msg("perturbed lifts coplanar: the oracle's eps is too large");
  return sign > 0 ? RULE_BD : RULE_AC;
}

/* An empty-shape rule with the tie-break as docs/lot.md states it: at a
** tie the greatest vertex is outside, the diagonal not incident to it kept. */
static rule_choice tt_es_oracle(tt_oracle *o, const size_t q[4]) {
  const geom_point *p = o->p;
  shape_choice c = shape_decide(o->k, p[q[0]], p[q[1]], p[q[2]], p[q[3]], NULL);
  if (c != SHAPE_EITHER) return c == SHAPE_AC ? RULE_AC : RULE_BD;
  o->ties++;
  int g = 0;
  for (int i = 1; i < 4; i++)
    if (tt_lex_less(p[q[g]], p[q[i]])) g = i;
  return g % 2 == 0 ? RULE_BD : RULE_AC;   /* greatest A or C: keep BD */
}

static rule_choice tt_decide(tt_oracle *o, const size_t q[4]) {
  return o->k ? tt_es_oracle(o, q) : tt_dt_oracle(o, q);
}

/* The shape of an empty-shape rule (NULL for DT), or of a shape spec. */
static shape *tt_shape(const char *name) {
  if (strcmp(name, "DT") == 0) return NULL;
  shape *k;
  char err[256];
  const char *spec = strncmp(name, "ES:", 3) == 0 ? name + 3 : name;
  if (shape_parse(spec, &k, err, sizeof err) != 0) fail_msg("%s: %s", name, err);
  return k;
}

/* ---- lot's triangulations -------------------------------------------------- */

typedef struct tt_tris {
  uint32_t *tri;        /* rows, as lot_get_triangles gives them */
  size_t n;
  uint64_t flips;
} tt_tris;

/* lot of p under rule `name` with algorithm a (order, seed for the
** incremental one).  Returns 0, or 1 when the sweep refuses the rule. */
static int tt_lot(const geom_point *p, size_t n, const char *name, lot_algorithm a,
                  lot_order order, uint64_t seed, tt_tris *out) {
  rule r = tt_rule(name);
  lot_options o;
  lot_options_init(&o, &r);
  o.algorithm = a;
  o.order = order;
  o.seed = seed;
  lot *L;
  char err[512];
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) {
    if (a == LOT_SWEEP && strstr(err, "sweep algorithm") != NULL) return 1;
    fail_msg("lot_build %s: %s", name, err);
  }
  const lot_stats *st = lot_get_stats(L);
  assert_int_equal(st->status, LOT_CONVERGED);
  out->n = st->triangles;
  out->flips = st->flips;
  out->tri = malloc(3 * (out->n + 1) * sizeof *out->tri);
  assert_non_null(out->tri);
  lot_get_triangles(L, out->tri);
  lot_free(L);
  return 0;
}

/* The runs compared: the flip algorithm, the incremental one in four
** orders, the sweep. */
#define TT_RUNS 6
static const struct {
  lot_algorithm a;
  lot_order order;
  uint64_t seed;
} tt_run[TT_RUNS] = {
  {LOT_FLIP, LOT_ORDER_SPATIAL, 1},        {LOT_INCREMENTAL, LOT_ORDER_SPATIAL, 1},
  {LOT_INCREMENTAL, LOT_ORDER_SPATIAL, 7}, {LOT_INCREMENTAL, LOT_ORDER_RANDOM, 3},
  {LOT_INCREMENTAL, LOT_ORDER_INPUT, 1},   {LOT_SWEEP, LOT_ORDER_SPATIAL, 1},
};

/* Every run of rule `name` on p gives the same triangles; the flip
** algorithm's are returned (the caller frees them). */
static tt_tris tt_agree(const geom_point *p, size_t n, const char *name) {
  tt_tris ref;
  tt_lot(p, n, name, tt_run[0].a, tt_run[0].order, tt_run[0].seed, &ref);
  for (int k = 1; k < TT_RUNS; k++) {
    tt_tris t;
    if (tt_lot(p, n, name, tt_run[k].a, tt_run[k].order, tt_run[k].seed, &t) != 0) continue;
    if (t.n != ref.n || memcmp(t.tri, ref.tri, 3 * ref.n * sizeof *ref.tri) != 0)
      fail_msg("%s, %zu points: run %d differs from the flip algorithm", name, n, k);
    free(t.tri);
  }
  return ref;
}

/* ---- brute force ------------------------------------------------------------ */

static int tt_u32_cmp(const void *x, const void *y) {
  uint32_t a = *(const uint32_t *)x, b = *(const uint32_t *)y;
  return a < b ? -1 : a > b;
}

static int tt_tri_cmp(const void *x, const void *y) {
  const uint32_t *a = x, *b = y;
  for (int i = 0; i < 3; i++)
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  return 0;
}

/* Triangles with their vertices ascending, the list sorted. */
static void tt_normalise(uint32_t *tri, size_t n) {
  for (size_t t = 0; t < n; t++) qsort(tri + 3 * t, 3, sizeof *tri, tt_u32_cmp);
  qsort(tri, n, 3 * sizeof *tri, tt_tri_cmp);
}

/* The triangulations of g with no flip away under the oracle (sinks);
** the first into *sink. */
static int tt_sinks(const siteflip_graph *g, tt_oracle *o, int *sink) {
  rule_choice *dec = malloc((size_t)(g->nquads + 1) * sizeof *dec);
  assert_non_null(dec);
  for (int q = 0; q < g->nquads; q++) {
    const size_t v[4] = {g->quad[q].v[0], g->quad[q].v[1], g->quad[q].v[2], g->quad[q].v[3]};
    dec[q] = tt_decide(o, v);
  }
  int count = 0;
  for (int u = 0; u < g->nnodes; u++) {
    int ok = 1;
    for (int j = g->adj_off[u]; j < g->adj_off[u + 1] && ok; j++) {
      const siteflip_edge *e = &g->edge[g->adj[j]];
      ok = dec[e->quad] == RULE_AC ? e->ac == u : e->bd == u;
    }
    if (ok && count++ == 0) *sink = u;
  }
  free(dec);
  return count;
}

/* Tied quadrilaterals met by the brute force, per rule. */
static long tt_brute_ties[TT_NRULES];

/* The brute-force check of one site set under every rule. */
static void tt_brute(const geom_point *p, int n) {
  char err[256];
  siteflip_graph *g = siteflip_build(p, n, err, sizeof err);
  if (g == NULL) fail_msg("siteflip_build: %s", err);
  for (int r = 0; r < TT_NRULES; r++) {
    shape *k = tt_shape(tt_rules[r]);
    tt_oracle o = tt_oracle_make(k, g->p, (size_t)n);
    int sink = -1, count = tt_sinks(g, &o, &sink);
    tt_brute_ties[r] += o.ties;
    if (count != 1)
      fail_msg("%s, %d sites (%d triangulations): %d locally optimal", tt_rules[r], n,
               g->nnodes, count);
    tt_tris t = tt_agree(p, (size_t)n, tt_rules[r]);
    assert_int_equal(t.n, g->per);
    uint32_t *want = malloc(3 * (size_t)g->per * sizeof *want);
    assert_non_null(want);
    for (int i = 0; i < g->per; i++)
      for (int j = 0; j < 3; j++) want[3 * i + j] = g->tri_v[g->node_tri[sink * g->per + i]][j];
    tt_normalise(want, t.n);
    tt_normalise(t.tri, t.n);
    if (memcmp(want, t.tri, 3 * t.n * sizeof *want) != 0)
      fail_msg("%s, %d sites: lot is not the locally optimal triangulation", tt_rules[r], n);
    free(want);
    free(t.tri);
    free(o.rank);
    shape_free(k);
  }
  siteflip_free(g);
}

static void tt_grid(int w, int h, int x0, int y0, geom_point *p) {
  for (int i = 0; i < w * h; i++) p[i] = (geom_point){x0 + i % w, y0 + i / w};
}

/* Full grids (every unit square a tie for DT and the square), the twelve
** integer points of x^2 + y^2 = 25 with and without centre, the diamond's
** boundary |x| + |y| = 2 with its centre, rows of collinear sites. */
static void test_brute_structured(void **state) {
  (void)state;
  geom_point p[16];
  static const int grids[][4] = {{3, 3, 0, 0}, {4, 3, -2, 1}, {3, 4, 0, -2}, {2, 6, 0, 0},
                                 {6, 2, 1, 1}, {2, 5, -1, -1}};
  for (size_t i = 0; i < sizeof grids / sizeof grids[0]; i++) {
    tt_grid(grids[i][0], grids[i][1], grids[i][2], grids[i][3], p);
    tt_brute(p, grids[i][0] * grids[i][1]);
  }
  static const geom_point c25[12] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3},
                                     {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  memcpy(p, c25, sizeof c25);
  tt_brute(p, 12);
  p[12] = (geom_point){0, 0};
  tt_brute(p + 4, 9);   /* eight on the circle and the centre */
  static const geom_point dia[9] = {{2, 0}, {1, 1}, {0, 2}, {-1, 1}, {-2, 0},
                                    {-1, -1}, {0, -2}, {1, -1}, {0, 0}};
  tt_brute(dia, 9);
  /* corners of two homothets of the polygons (their own doubles, times 4
  ** and 8: exact): ties for each shape */
  static const char *const polys[] = {"square", "diamond", "hexagon", "octagon"};
  for (size_t i = 0; i < sizeof polys / sizeof *polys; i++) {
    shape *k = tt_shape(polys[i]);
    int n = 0;
    for (int v = 0; v < k->n; v++) p[n++] = (geom_point){4 * k->v[v].x, 4 * k->v[v].y};
    for (int v = 0; v < 3; v++) p[n++] = (geom_point){8 * k->v[v].x, 8 * k->v[v].y};
    tt_brute(p, n);
    shape_free(k);
  }
  static const geom_point rows[11] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0},
                                      {2, 1}, {0, 2}, {1, 2}, {3, 2}, {5, 2}};
  tt_brute(rows, 11);
  /* every rule met ties, but the triangle: its ties are all settled by the
  ** turn of the shape (docs/emptyshape.md) */
  for (int r = 0; r < TT_NRULES; r++)
    if (strcmp(tt_rules[r], "ES:triangle") != 0 && tt_brute_ties[r] == 0)
      fail_msg("%s: no tie in the structured sets", tt_rules[r]);
}

/* Random sets of 4 to 11 distinct sites of a 5 x 5 grid (collinear and
** cocircular everywhere). */
static void test_brute_random(void **state) {
  (void)state;
  testutil_rng g = {20261202};
  for (int trial = 0; trial < 60; trial++) {
    int n = 4 + (int)(testutil_next(&g) % 8), m = 0;
    geom_point p[16];
    while (m < n) {
      geom_point q = {(double)(testutil_next(&g) % 5), (double)(testutil_next(&g) % 5)};
      int dup = 0;
      for (int i = 0; i < m; i++) dup |= p[i].x == q.x && p[i].y == q.y;
      if (!dup) p[m++] = q;
    }
    char err[256];
    if (siteflip_check(p, n, err, sizeof err) == 0) tt_brute(p, n);
  }
}

/* ---- agreement on larger sets --------------------------------------------- */

typedef struct tt_dedge {
  uint64_t key;         /* u << 32 | v: the edge u -> v of a triangle */
  uint32_t apex;        /* that triangle's third vertex */
} tt_dedge;

static int tt_dedge_cmp(const void *x, const void *y) {
  uint64_t a = ((const tt_dedge *)x)->key, b = ((const tt_dedge *)y)->key;
  return a < b ? -1 : a > b;
}

/* Every interior edge of t (rows of o->p) in a strictly convex
** quadrilateral passes the oracle: the triangulation is locally optimal
** under the rule with the tie-break (for DT: the regular triangulation of
** the perturbed lifting). */
static void tt_optimal(tt_oracle *o, const tt_tris *t) {
  size_t ne = 3 * t->n;
  tt_dedge *e = malloc((ne + 1) * sizeof *e);
  assert_non_null(e);
  for (size_t i = 0; i < t->n; i++)
    for (int j = 0; j < 3; j++)
      e[3 * i + j] = (tt_dedge){(uint64_t)t->tri[3 * i + j] << 32 | t->tri[3 * i + (j + 1) % 3],
                                t->tri[3 * i + (j + 2) % 3]};
  qsort(e, ne, sizeof *e, tt_dedge_cmp);
  const geom_point *p = o->p;
  for (size_t i = 0; i < ne; i++) {
    size_t u = e[i].key >> 32, v = e[i].key & 0xffffffffu;
    if (u > v) continue;   /* each interior edge once */
    tt_dedge want = {(uint64_t)v << 32 | u, 0}, *twin = bsearch(&want, e, ne, sizeof *e, tt_dedge_cmp);
    if (twin == NULL) continue;   /* a hull edge */
    const size_t q[4] = {u, twin->apex, v, e[i].apex};   /* anticlockwise, diagonal u-v */
    int convex = 1;
    for (int k = 0; k < 4; k++)
      convex &= geom_orient(p[q[k]], p[q[(k + 1) % 4]], p[q[(k + 2) % 4]]) > 0;
    if (convex && tt_decide(o, q) != RULE_AC)
      fail_msg("edge %zu-%zu is not locally optimal under the tie-break", u, v);
  }
  free(e);
}

/* All runs agree on p under rules first .. end - 1, and the result is
** locally optimal under the oracle. */
static void tt_agree_all(const geom_point *p, size_t n, int first, int end) {
  for (int r = first; r < end; r++) {
    shape *k = tt_shape(tt_rules[r]);
    tt_tris t = tt_agree(p, n, tt_rules[r]);
    tt_oracle o = tt_oracle_make(k, p, n);
    tt_optimal(&o, &t);
    free(o.rank);
    free(t.tri);
    shape_free(k);
  }
}

/* Every sampler of lot; DT on more points than the empty-shape rules. */
static void test_samplers(void **state) {
  (void)state;
  geom_point *p = malloc(600 * sizeof *p);
  assert_non_null(p);
  for (int kind = 0; kind < SAMPLER_POINTS_COUNT; kind++)
    for (uint64_t seed = 1; seed <= 2; seed++) {
      sampler_points((sampler_points_kind)kind, seed, 600, p);
      tt_agree_all(p, 600, 0, 1);
      sampler_points((sampler_points_kind)kind, seed, 40 * seed, p);
      tt_agree_all(p, 40 * seed, 1, TT_NLARGE);
    }
  free(p);
}

/* Collinear-heavy sets: integer sites on a few horizontal, vertical and
** diagonal lines (many collinear, duplicates among them); duplicate-heavy
** ones: a small pool of sites drawn again and again. */
static void test_collinear_duplicates(void **state) {
  (void)state;
  testutil_rng g = {77};
  geom_point p[600];
  for (int trial = 0; trial < 4; trial++) {
    size_t n = trial < 2 ? 400 : 100;
    for (size_t i = 0; i < n; i++) {
      double c = (double)(testutil_next(&g) % 4), t = (double)(testutil_next(&g) % 40);
      int line = (int)(testutil_next(&g) % 3);
      p[i] = line == 0 ? (geom_point){3 * c, t} : line == 1 ? (geom_point){t, 5 * c}
                       : (geom_point){t, t - 7 * c};
    }
    tt_agree_all(p, n, 0, n > 200 ? 1 : TT_NLARGE);
    for (size_t i = 0; i < n; i++)
      p[i] = (geom_point){(double)(testutil_next(&g) % 6), (double)(testutil_next(&g) % 6) / 2};
    tt_agree_all(p, n, 0, n > 200 ? 1 : TT_NLARGE);
  }
}

/* Triangles as points: each vertex triple sorted, the list sorted. */
static int tt_ptri_cmp(const void *x, const void *y) {
  const geom_point *a = x, *b = y;
  for (int i = 0; i < 3; i++) {
    if (tt_lex_less(a[i], b[i])) return -1;
    if (tt_lex_less(b[i], a[i])) return 1;
  }
  return 0;
}

static int tt_pt_cmp(const void *x, const void *y) {
  const geom_point *a = x, *b = y;
  return tt_lex_less(*a, *b) ? -1 : tt_lex_less(*b, *a);
}

static geom_point *tt_as_points(const geom_point *p, const tt_tris *t) {
  geom_point *q = malloc((3 * t->n + 1) * sizeof *q);
  assert_non_null(q);
  for (size_t i = 0; i < 3 * t->n; i++) q[i] = p[t->tri[i]];
  for (size_t i = 0; i < t->n; i++) qsort(q + 3 * i, 3, sizeof *q, tt_pt_cmp);
  qsort(q, t->n, 3 * sizeof *q, tt_ptri_cmp);
  return q;
}

/* The triangles depend on the point set only: the rows shuffled (and the
** first occurrences of duplicates with them) give the same triangles as
** points, for every rule, on a grid with duplicates and on a circle. */
static void test_shuffled(void **state) {
  (void)state;
  testutil_rng g = {5};
  geom_point p[100], q[100];
  for (int set = 0; set < 2; set++) {
    sampler_points(set ? SAMPLER_CIRCLE : SAMPLER_GRID, 4, 80, p);
    for (int i = 80; i < 100; i++) p[i] = p[testutil_next(&g) % 80];
    for (int r = 0; r < TT_NLARGE; r++) {
      memcpy(q, p, sizeof p);
      for (int i = 99; i > 0; i--) {
        int j = (int)(testutil_next(&g) % (uint64_t)(i + 1));
        geom_point t = q[i];
        q[i] = q[j];
        q[j] = t;
      }
      tt_tris a = tt_agree(p, 100, tt_rules[r]), b = tt_agree(q, 100, tt_rules[r]);
      assert_int_equal(a.n, b.n);
      geom_point *pa = tt_as_points(p, &a), *pb = tt_as_points(q, &b);
      if (memcmp(pa, pb, 3 * a.n * sizeof *pa) != 0)
        fail_msg("%s: the shuffled rows give other triangles", tt_rules[r]);
      free(pa);
      free(pb);
      free(a.tri);
      free(b.tri);
    }
  }
}

/* ---- lot_check's tie-break check -------------------------------------------- */

/* Turn the first tied edge of t (a strictly convex quadrilateral on which
** rule r answers EITHER) to its other diagonal; 1 when there was one, its
** new diagonal in e[]. */
static int tt_flip_tie(const geom_point *p, tt_tris *t, const rule *r, uint32_t e[2]) {
  for (size_t i = 0; i < t->n; i++)
    for (size_t j = 0; j < t->n; j++)
      for (int x = 0; x < 3; x++)
        for (int y = 0; y < 3; y++) {
          uint32_t *t1 = t->tri + 3 * i, *t2 = t->tri + 3 * j;
          uint32_t u = t1[x], v = t1[(x + 1) % 3], a = t1[(x + 2) % 3], d = t2[(y + 2) % 3];
          if (i == j || t2[y] != v || t2[(y + 1) % 3] != u) continue;
          const geom_point q[4] = {p[u], p[d], p[v], p[a]};
          int convex = 1;
          for (int k = 0; k < 4; k++) convex &= geom_orient(q[k], q[(k + 1) % 4], q[(k + 2) % 4]) > 0;
          if (!convex || rule_eval(r, q, NULL, NULL) != RULE_EITHER) continue;
          t1[0] = u; t1[1] = d; t1[2] = a;   /* u d v a anticlockwise: u d a and d v a */
          t2[0] = d; t2[1] = v; t2[2] = a;
          e[0] = a < d ? a : d;
          e[1] = a < d ? d : a;
          return 1;
        }
  return 0;
}

/* lot_check finds every LOT of DT and of the shape rules tie-broken (and
** counts its ties), and catches one tied edge turned to the other
** diagonal: still valid and locally optimal (a tie), but not the
** tie-break's triangulation. */
static void test_check_tiebreak(void **state) {
  (void)state;
  geom_point p[25];
  tt_grid(5, 5, 0, 0, p);
  for (int k = 0; k < TT_NLARGE; k++) {
    rule r = tt_rule(tt_rules[k]);
    tt_tris t = {0};
    for (int run = 0; run < TT_RUNS; run++) {
      assert_int_equal(tt_lot(p, 25, tt_rules[k], tt_run[run].a, tt_run[run].order,
                              tt_run[run].seed, &t), 0);
      lot_check_result c;
      lot_tie_result tie;
      assert_int_equal(lot_check_ties(p, 25, t.tri, t.n, &r, &c, &tie), 0);
      assert_true(c.valid);
      assert_int_equal(c.not_optimal, 0);
      assert_int_equal(tie.not_tie_broken, 0);
      uint32_t e[2];
      if (run > 0 || !tt_flip_tie(p, &t, &r, e)) {
        free(t.tri);
        continue;
      }
      assert_true(tie.ties > 0);
      assert_int_equal(lot_check_ties(p, 25, t.tri, t.n, &r, &c, &tie), 0);
      assert_true(c.valid);
      if (tie.not_tie_broken == 0) fail_msg("%s: a wrong tie not caught", tt_rules[k]);
      if (c.not_optimal == 0) {   /* the tie alone is wrong: it is the one named */
        assert_int_equal(tie.not_tie_broken, 1);
        assert_int_equal(tie.tie_edge[0], e[0]);
        assert_int_equal(tie.tie_edge[1], e[1]);
      }
      free(t.tri);
    }
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_brute_structured),
    cmocka_unit_test(test_brute_random),
    cmocka_unit_test(test_samplers),
    cmocka_unit_test(test_collinear_duplicates),
    cmocka_unit_test(test_shuffled),
    cmocka_unit_test(test_check_tiebreak),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
