/*
** test_cdf.c: the convex-distance Delaunay graph read off an empty-shape
** triangulation (lot_cdf_extract) against the definition, computed here
** independently in exact rationals: PQ is CDF-Delaunay iff some homothet
** t + sK has P and Q on its boundary and no site in its interior.
**
** The oracle enumerates the edges i, j of K that P and Q lie on.  With
** c_m = n_m.t + s h_m the support value of edge m, "P on edge i" is the
** linear equation n_i.t + s h_i = n_i.P and "P in the closed homothet" the
** inequalities n_m.P <= c_m: for i != j the homothets with P on edge i and
** Q on edge j form a segment (or ray) x0 + lambda d of (t, s) space.  A site
** R lies inside for lambda in an interval (open: the interior; closed: the
** closed shape), so the edge is CDF-Delaunay iff the segment is not covered
** by the sites' open intervals, which is decided on the intervals' endpoints
** and the midpoints between them.  "Strongly" CDF-Delaunay: some homothet
** through P and Q has every other site strictly outside (the closed
** intervals).  Strong implies weak; in general position they agree.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom.h"
#include "lot.h"
#include "rule.h"
#include "shape.h"
#include "testutil.h"

#define TCDF_MAXN 12
#define TCDF_MAXK 16

/* ---- the exact oracle ---------------------------------------------------- */

typedef struct tcdf_shape {   /* K in rationals: outward normals and h_m = n_m.k_m */
  int m;
  mpq_t nx[TCDF_MAXK], ny[TCDF_MAXK], h[TCDF_MAXK];
} tcdf_shape;

typedef struct tcdf_iv {      /* {lambda : a_k lambda >= g_k for all k}, and its open version */
  int closed_empty, open_empty, has_lo, has_hi;
  mpq_t lo, hi;
} tcdf_iv;

/* K's vertices turned by the rotation ((1-t^2)/(1+t^2), 2t/(1+t^2)), t = num/den
** (num = 0: not turned). */
static void tcdf_shape_init(tcdf_shape *s, const shape *k, long num, long den) {
  mpq_t c, sn, t, vx[TCDF_MAXK], vy[TCDF_MAXK], a, b;
  mpq_inits(c, sn, t, a, b, NULL);
  mpq_set_si(t, num, (unsigned long)den);
  mpq_mul(a, t, t);                       /* t^2 */
  mpq_set_ui(b, 1, 1);
  mpq_add(b, b, a);                       /* 1 + t^2 */
  mpq_set_ui(c, 1, 1);
  mpq_sub(c, c, a);
  mpq_div(c, c, b);
  mpq_add(sn, t, t);
  mpq_div(sn, sn, b);
  assert_true(k->n <= TCDF_MAXK);
  s->m = k->n;
  for (int i = 0; i < k->n; i++) {
    mpq_inits(vx[i], vy[i], NULL);
    mpq_set_d(a, k->v[i].x), mpq_set_d(b, k->v[i].y);
    mpq_mul(vx[i], c, a), mpq_mul(t, sn, b), mpq_sub(vx[i], vx[i], t);
    mpq_mul(vy[i], sn, a), mpq_mul(t, c, b), mpq_add(vy[i], vy[i], t);
  }
  for (int i = 0; i < k->n; i++) {
    int j = (i + 1) % k->n;
    mpq_inits(s->nx[i], s->ny[i], s->h[i], NULL);
    mpq_sub(s->nx[i], vy[j], vy[i]);      /* n = (e_y, -e_x) */
    mpq_sub(s->ny[i], vx[i], vx[j]);
    mpq_mul(s->h[i], s->nx[i], vx[i]), mpq_mul(t, s->ny[i], vy[i]), mpq_add(s->h[i], s->h[i], t);
  }
  for (int i = 0; i < k->n; i++) mpq_clears(vx[i], vy[i], NULL);
  mpq_clears(c, sn, t, a, b, NULL);
}

static void tcdf_shape_clear(tcdf_shape *s) {
  for (int i = 0; i < s->m; i++) mpq_clears(s->nx[i], s->ny[i], s->h[i], NULL);
}

static void tcdf_dot(mpq_t out, const mpq_t ax, const mpq_t ay, const mpq_t bx, const mpq_t by) {
  mpq_t t;
  mpq_init(t);
  mpq_mul(out, ax, bx), mpq_mul(t, ay, by), mpq_add(out, out, t);
  mpq_clear(t);
}

typedef struct tcdf_line {    /* x0 + lambda d in (t_x, t_y, s) */
  mpq_t x0[3], d[3];
} tcdf_line;

/* The line of homothets with P on edge i and Q on edge j (i != j). */
static void tcdf_line_make(const tcdf_shape *s, int i, int j, mpq_t P[2], mpq_t Q[2],
                           tcdf_line *L) {
  mpq_t r1[3], r2[3], d1, d2, det, t;
  for (int c = 0; c < 3; c++) mpq_inits(r1[c], r2[c], L->x0[c], L->d[c], NULL);
  mpq_inits(d1, d2, det, t, NULL);
  mpq_set(r1[0], s->nx[i]), mpq_set(r1[1], s->ny[i]), mpq_set(r1[2], s->h[i]);
  mpq_set(r2[0], s->nx[j]), mpq_set(r2[1], s->ny[j]), mpq_set(r2[2], s->h[j]);
  tcdf_dot(d1, s->nx[i], s->ny[i], P[0], P[1]);
  tcdf_dot(d2, s->nx[j], s->ny[j], Q[0], Q[1]);
  for (int c = 0; c < 3; c++) {          /* d = r1 x r2 */
    int a = (c + 1) % 3, b = (c + 2) % 3;
    mpq_mul(L->d[c], r1[a], r2[b]), mpq_mul(t, r1[b], r2[a]), mpq_sub(L->d[c], L->d[c], t);
  }
  /* A particular solution: the minor of columns a, b that is not 0 (d[c]), x_c = 0. */
  int c = mpq_sgn(L->d[2]) ? 2 : mpq_sgn(L->d[0]) ? 0 : 1;
  int a = (c + 1) % 3, b = (c + 2) % 3;
  assert_true(mpq_sgn(L->d[c]) != 0);
  mpq_set(det, L->d[c]);                 /* r1[a] r2[b] - r1[b] r2[a] */
  mpq_mul(L->x0[a], d1, r2[b]), mpq_mul(t, d2, r1[b]), mpq_sub(L->x0[a], L->x0[a], t);
  mpq_div(L->x0[a], L->x0[a], det);
  mpq_mul(L->x0[b], r1[a], d2), mpq_mul(t, r2[a], d1), mpq_sub(L->x0[b], L->x0[b], t);
  mpq_div(L->x0[b], L->x0[b], det);
  for (int k = 0; k < 3; k++) mpq_clears(r1[k], r2[k], NULL);
  mpq_clears(d1, d2, det, t, NULL);
}

static void tcdf_line_clear(tcdf_line *L) {
  for (int c = 0; c < 3; c++) mpq_clears(L->x0[c], L->d[c], NULL);
}

static void tcdf_iv_init(tcdf_iv *v) {
  memset(v, 0, sizeof *v);
  mpq_inits(v->lo, v->hi, NULL);
}

static void tcdf_iv_clear(tcdf_iv *v) { mpq_clears(v->lo, v->hi, NULL); }

/* Intersect v with the constraint "R in the closed homothet's edge-m half-plane"
** along L: (n_m, h_m).x(lambda) >= n_m.R, i.e. a lambda >= g. */
static void tcdf_iv_edge(tcdf_iv *v, const tcdf_shape *s, int m, const tcdf_line *L,
                         mpq_t R[2]) {
  mpq_t a, g, t;
  mpq_inits(a, g, t, NULL);
  mpq_mul(a, s->nx[m], L->d[0]), mpq_mul(t, s->ny[m], L->d[1]), mpq_add(a, a, t);
  mpq_mul(t, s->h[m], L->d[2]), mpq_add(a, a, t);
  tcdf_dot(g, s->nx[m], s->ny[m], R[0], R[1]);
  mpq_mul(t, s->nx[m], L->x0[0]), mpq_sub(g, g, t);
  mpq_mul(t, s->ny[m], L->x0[1]), mpq_sub(g, g, t);
  mpq_mul(t, s->h[m], L->x0[2]), mpq_sub(g, g, t);
  int sa = mpq_sgn(a);
  if (sa == 0) {
    if (mpq_sgn(g) > 0) v->closed_empty = 1;
    if (mpq_sgn(g) >= 0) v->open_empty = 1;
  } else {
    mpq_div(t, g, a);
    if (sa > 0 && (!v->has_lo || mpq_cmp(t, v->lo) > 0)) mpq_set(v->lo, t), v->has_lo = 1;
    if (sa < 0 && (!v->has_hi || mpq_cmp(t, v->hi) < 0)) mpq_set(v->hi, t), v->has_hi = 1;
  }
  mpq_clears(a, g, t, NULL);
}

static void tcdf_iv_point(tcdf_iv *v, const tcdf_shape *s, const tcdf_line *L, mpq_t R[2]) {
  for (int m = 0; m < s->m; m++) tcdf_iv_edge(v, s, m, L, R);
}

static int tcdf_in_closed(const tcdf_iv *v, const mpq_t x) {
  return !v->closed_empty && (!v->has_lo || mpq_cmp(x, v->lo) >= 0) &&
         (!v->has_hi || mpq_cmp(x, v->hi) <= 0);
}

static int tcdf_in_open(const tcdf_iv *v, const mpq_t x) {
  return !v->open_empty && (!v->has_lo || mpq_cmp(x, v->lo) > 0) &&
         (!v->has_hi || mpq_cmp(x, v->hi) < 0);
}

static int tcdf_mpq_cmp(const void *a, const void *b) {
  return mpq_cmp(*(const mpq_t *)a, *(const mpq_t *)b);
}

/* Is some lambda of F in no site's interval?  res[0]: open intervals (weak),
** res[1]: closed ones (strong). */
static void tcdf_uncovered(const tcdf_iv *F, const tcdf_iv *site, int ns, int res[2]) {
  mpq_t pts[4 * TCDF_MAXN + 8];
  int np = 0;
  const tcdf_iv *all[TCDF_MAXN + 1];
  all[0] = F;
  for (int r = 0; r < ns; r++) all[r + 1] = site + r;
  for (int r = 0; r <= ns; r++) {
    if (all[r]->has_lo) mpq_init(pts[np]), mpq_set(pts[np++], all[r]->lo);
    if (all[r]->has_hi) mpq_init(pts[np]), mpq_set(pts[np++], all[r]->hi);
  }
  if (np == 0) mpq_init(pts[np++]);
  qsort(pts, (size_t)np, sizeof pts[0], tcdf_mpq_cmp);
  int base = np;
  for (int i = 0; i + 1 < base; i++) {
    mpq_init(pts[np]);
    mpq_add(pts[np], pts[i], pts[i + 1]);
    mpq_div_2exp(pts[np], pts[np], 1);
    np++;
  }
  mpq_t one;
  mpq_init(one);
  mpq_set_ui(one, 1, 1);
  mpq_init(pts[np]), mpq_sub(pts[np], pts[0], one), np++;
  mpq_init(pts[np]), mpq_add(pts[np], pts[base - 1], one), np++;
  for (int i = 0; i < np; i++) {
    if (!tcdf_in_closed(F, pts[i])) continue;
    int in_open = 0, in_closed = 0;
    for (int r = 0; r < ns; r++) {
      in_open |= tcdf_in_open(site + r, pts[i]);
      in_closed |= tcdf_in_closed(site + r, pts[i]);
    }
    res[0] |= !in_open;
    res[1] |= !in_closed;
  }
  for (int i = 0; i < np; i++) mpq_clear(pts[i]);
  mpq_clear(one);
}

/* PQ by the definition: res[0] weak, res[1] strong.  Counts in *parallel the
** edges i with P and Q on one line parallel to edge i (not enumerated). */
static void tcdf_oracle(const tcdf_shape *s, mpq_t (*pt)[2], int n, int P, int Q, int res[2],
                        int *parallel) {
  res[0] = res[1] = 0;
  for (int i = 0; i < s->m; i++) {
    mpq_t a, b;
    mpq_inits(a, b, NULL);
    tcdf_dot(a, s->nx[i], s->ny[i], pt[P][0], pt[P][1]);
    tcdf_dot(b, s->nx[i], s->ny[i], pt[Q][0], pt[Q][1]);
    *parallel += mpq_equal(a, b) != 0;
    mpq_clears(a, b, NULL);
  }
  for (int i = 0; i < s->m; i++)
    for (int j = 0; j < s->m; j++) {
      if (i == j) continue;
      tcdf_line L;
      tcdf_iv F, site[TCDF_MAXN];
      tcdf_line_make(s, i, j, pt[P], pt[Q], &L);
      tcdf_iv_init(&F);
      tcdf_iv_point(&F, s, &L, pt[P]);
      tcdf_iv_point(&F, s, &L, pt[Q]);
      int ns = 0;
      if (!F.closed_empty && !(F.has_lo && F.has_hi && mpq_cmp(F.lo, F.hi) > 0)) {
        for (int r = 0; r < n; r++) {
          if (r == P || r == Q) continue;
          tcdf_iv_init(&site[ns]);
          tcdf_iv_point(&site[ns++], s, &L, pt[r]);
        }
        tcdf_uncovered(&F, site, ns, res);
      }
      for (int r = 0; r < ns; r++) tcdf_iv_clear(&site[r]);
      tcdf_iv_clear(&F);
      tcdf_line_clear(&L);
    }
}

/* ---- the triangulation and the extraction -------------------------------- */

static rule_choice tcdf_rule_fn(const geom_point q[4], void *ctx) {
  return (rule_choice)shape_decide((const shape *)ctx, q[0], q[1], q[2], q[3], NULL);
}

typedef struct tcdf_case {
  shape *k;
  rule r;
} tcdf_case;

static void tcdf_case_make(tcdf_case *c, const char *spec, const char *name_in) {
  static char names[RULE_QUAD_MAX][32];   /* the registry keeps the name's pointer */
  static int used;
  char err[256], *name = names[used++ % RULE_QUAD_MAX];
  snprintf(name, sizeof names[0], "%s", name_in);
  assert_int_equal(shape_parse(spec, &c->k, err, sizeof err), 0);
  rule_quad q = {name, "empty-shape rule of the test", tcdf_rule_fn, c->k};
  assert_true(rule_quad_register(&q) >= 0);
  assert_int_equal(rule_parse(name, &c->r, err, sizeof err), 0);
}

/* The empty-shape triangulation of p; returns the triangle count. */
static size_t tcdf_triangulate(const tcdf_case *c, const geom_point *p, size_t n, uint32_t *tri) {
  lot_options o;
  lot_options_init(&o, &c->r);
  lot *L = NULL;
  char err[256];
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) fail_msg("lot_build: %s", err);
  const lot_stats *st = lot_get_stats(L);
  assert_int_equal(st->status, LOT_CONVERGED);
  assert_int_equal(st->duplicates, 0);
  size_t nt = st->triangles;
  lot_get_triangles(L, tri);
  lot_free(L);
  return nt;
}

typedef struct tcdf_tally {
  long sets, edges, cdf, extra, dropped, hull_dropped, shared_nonedge, strong_only;
} tcdf_tally;

/* The extraction's CDF edges as an n x n table (1: in a kept triangle or extra). */
static void tcdf_extract(const tcdf_case *c, const geom_point *p, const uint32_t *tri, size_t nt,
                         unsigned char in[TCDF_MAXN][TCDF_MAXN], tcdf_tally *tl) {
  lot_cdf g;
  assert_int_equal(lot_cdf_extract(p, tri, nt, c->k, &g), 0);
  assert_int_equal(g.conflicts, 0);
  assert_int_equal(g.triangles + g.rounded, nt);
  memset(in, 0, TCDF_MAXN * TCDF_MAXN);
  for (size_t t = 0; t < g.triangles; t++)
    for (int e = 0; e < 3; e++) {
      uint32_t u = g.tri[3 * t + (size_t)e], v = g.tri[3 * t + (size_t)(e + 1) % 3];
      in[u][v] = in[v][u] = 1;
    }
  for (size_t e = 0; e < g.edges; e++) {
    uint32_t u = g.edge[2 * e], v = g.edge[2 * e + 1];
    assert_true(u < v);
    assert_int_equal(in[u][v], 0);   /* in no kept triangle, listed once */
    in[u][v] = in[v][u] = 2;
  }
  tl->extra += (long)g.edges;
  tl->dropped += (long)g.rounded;
  lot_cdf_free(&g);
}

/* The thesis's shortcut read literally ("the two other edges of a dropped
** triangle are CDF-Delaunay") fails when the edge is its neighbour's
** non-edge: count those edges, which the oracle must reject. */
static void tcdf_tally_shared(const tcdf_case *c, const geom_point *p, const uint32_t *tri,
                              size_t nt, unsigned char in[TCDF_MAXN][TCDF_MAXN], tcdf_tally *tl) {
  for (size_t t = 0; t < nt; t++) {
    const uint32_t *v = tri + 3 * t;
    int bad = lot_cdf_nonedge(c->k, p[v[0]], p[v[1]], p[v[2]]);
    if (bad < 0) continue;
    for (int e = 0; e < 3; e++) {
      uint32_t a = v[e], b = v[(e + 1) % 3];
      int hull = 1;
      for (size_t u = 0; u < nt; u++)
        for (int f = 0; f < 3; f++)
          if (tri[3 * u + (size_t)f] == b && tri[3 * u + (size_t)(f + 1) % 3] == a) hull = 0;
      tl->hull_dropped += hull && e == bad;   /* outside the support hull */
      if (e != bad && !in[a][b]) tl->shared_nonedge++;
    }
  }
}

/* Extraction and oracle agree on p: exactly (general position) or
** strong <= extracted <= weak (special position, oracle on K turned). */
static void tcdf_compare(const tcdf_case *c, const tcdf_shape *s, const geom_point *p, int n,
                         int exact, tcdf_tally *tl) {
  uint32_t tri[6 * TCDF_MAXN];
  size_t nt = tcdf_triangulate(c, p, (size_t)n, tri);
  unsigned char in[TCDF_MAXN][TCDF_MAXN];
  tcdf_extract(c, p, tri, nt, in, tl);
  tcdf_tally_shared(c, p, tri, nt, in, tl);
  mpq_t pt[TCDF_MAXN][2];
  for (int i = 0; i < n; i++) {
    mpq_inits(pt[i][0], pt[i][1], NULL);
    mpq_set_d(pt[i][0], p[i].x), mpq_set_d(pt[i][1], p[i].y);
  }
  int parallel = 0;
  for (int a = 0; a < n; a++)
    for (int b = a + 1; b < n; b++) {
      int res[2];
      tcdf_oracle(s, pt, n, a, b, res, &parallel);
      tl->edges++;
      tl->cdf += res[0];
      tl->strong_only += res[1] && !res[0];
      assert_false(res[1] && !res[0]);           /* strong implies weak */
      if ((exact && (res[0] != res[1] || res[0] != (in[a][b] != 0))) ||
          (!exact && ((res[1] && !in[a][b]) || (in[a][b] && !res[0]))))
        fail_msg("edge %d-%d of %d sites: extracted %d, weak %d, strong %d", a, b, n, in[a][b],
                 res[0], res[1]);
    }
  assert_int_equal(parallel, 0);   /* the oracle enumerates i != j only */
  for (int i = 0; i < n; i++) mpq_clears(pt[i][0], pt[i][1], NULL);
  tl->sets++;
}

/* ---- the tests ----------------------------------------------------------- */

static const char *const tcdf_specs[] = {
    "square", "diamond", "triangle", "hexagon", "poly:0,0;3,-1;5,0.5;4.5,3;1,2.5",
};
#define TCDF_NSPECS (sizeof tcdf_specs / sizeof tcdf_specs[0])

/* A random convex polygon: the hull of 7 random points (at least a triangle). */
static void tcdf_random_poly(testutil_rng *g, char *buf, size_t len) {
  for (;;) {
    geom_point q[7], h[8];
    for (int i = 0; i < 7; i++) q[i] = (geom_point){testutil_uniform(g), testutil_uniform(g)};
    int nh = 0;   /* gift wrapping from the lowest point */
    int lo = 0;
    for (int i = 1; i < 7; i++)
      if (q[i].y < q[lo].y) lo = i;
    int cur = lo;
    do {
      h[nh++] = q[cur];
      int nx = (cur + 1) % 7;
      for (int i = 0; i < 7; i++)
        if (geom_orient(q[cur], q[nx], q[i]) < 0) nx = i;
      cur = nx;
    } while (cur != lo && nh < 8);
    if (nh < 3 || nh > 7) continue;
    size_t off = (size_t)snprintf(buf, len, "poly:");
    for (int i = 0; i < nh; i++)
      off += (size_t)snprintf(buf + off, len - off, "%s%.17g,%.17g", i ? ";" : "", h[i].x, h[i].y);
    return;
  }
}

static void tcdf_report(const char *what, const char *spec, const tcdf_tally *t) {
  printf("cdf %s %s: %ld sets, %ld of %ld pairs CDF-Delaunay, %ld extra edges, %ld dropped "
         "triangles, %ld hull edges not CDF-Delaunay, %ld edges of a dropped triangle rejected by the neighbour\n",
         what, spec, t->sets, t->cdf, t->edges, t->extra, t->dropped, t->hull_dropped,
         t->shared_nonedge);
}

static void tcdf_random_sets(const char *spec, const char *name, testutil_rng *g, int sets,
                             tcdf_tally *tl) {
  tcdf_case c;
  tcdf_case_make(&c, spec, name);
  tcdf_shape s;
  tcdf_shape_init(&s, c.k, 0, 1);
  for (int t = 0; t < sets; t++) {
    geom_point p[TCDF_MAXN];
    int n = 4 + (int)(testutil_next(g) % (TCDF_MAXN - 3));
    for (int i = 0; i < n; i++) p[i] = (geom_point){testutil_uniform(g), testutil_uniform(g)};
    tcdf_compare(&c, &s, p, n, 1, tl);
  }
  tcdf_shape_clear(&s);
  shape_free(c.k);
}

static void test_cdf_general_position(void **state) {
  (void)state;
  testutil_rng g = {20261202};
  char spec[512], name[32];
  long extra = 0, shared = 0, hull = 0;
  for (size_t i = 0; i <= TCDF_NSPECS + 2; i++) {
    tcdf_tally tl = {0};
    if (i < TCDF_NSPECS) snprintf(spec, sizeof spec, "%s", tcdf_specs[i]);
    else tcdf_random_poly(&g, spec, sizeof spec);
    snprintf(name, sizeof name, "tcdf%zu", i);
    tcdf_random_sets(spec, name, &g, testutil_reps(50), &tl);
    tcdf_report("random", i < TCDF_NSPECS ? spec : "polygon", &tl);
    assert_true(tl.dropped > 0);
    extra += tl.extra, shared += tl.shared_nonedge, hull += tl.hull_dropped;
  }
  assert_true(extra > 0);     /* figure 4.6's edges in no triangle do occur */
  assert_true(shared > 0);    /* and so do candidates a neighbour rejects */
  assert_true(hull > 0);      /* and hull edges outside the graph */
  rule_quad_unregister_user();
}

/* Integer grids, full of sites in special position: the extraction is the
** CDF graph of K turned by an infinitesimal angle (the tie-break of
** docs/emptyshape.md); the oracle turns K by the finite angle of
** tan(theta/2) = 2^-24 and checks strong <= extracted <= weak. */
static void test_cdf_grids(void **state) {
  (void)state;
  testutil_rng g = {77};
  const char *specs[] = {"square", "diamond", "triangle", "hexagon"};
  for (size_t i = 0; i < 4; i++) {
    tcdf_case c;
    char name[32];
    snprintf(name, sizeof name, "tcdfgrid%zu", i);
    tcdf_case_make(&c, specs[i], name);
    tcdf_shape s;
    tcdf_shape_init(&s, c.k, 1, 1L << 24);
    tcdf_tally tl = {0};
    for (int t = 0; t < testutil_reps(40); t++) {
      geom_point p[TCDF_MAXN];
      int n = 0, want = 5 + (int)(testutil_next(&g) % (TCDF_MAXN - 4)), side = t % 2 ? 4 : 5;
      unsigned char used[25] = {0};
      while (n < want) {
        int cell = (int)(testutil_next(&g) % (uint64_t)(side * side));
        if (used[cell]) continue;
        used[cell] = 1;
        p[n++] = (geom_point){(double)(cell % side), (double)(cell / side)};
      }
      int collinear = 1;
      for (int k = 2; k < n; k++) collinear &= geom_orient(p[0], p[1], p[k]) == 0;
      if (!collinear) tcdf_compare(&c, &s, p, n, 0, &tl);
    }
    tcdf_report("grid", specs[i], &tl);
    tcdf_shape_clear(&s);
    shape_free(c.k);
  }
  rule_quad_unregister_user();
}

/* An ellipse is smooth: every triangle is kept, no extra edge. */
static void test_cdf_ellipse(void **state) {
  (void)state;
  tcdf_case c;
  tcdf_case_make(&c, "ellipse:2,1,0.5", "tcdfell");
  testutil_rng g = {5};
  geom_point p[200];
  for (int i = 0; i < 200; i++) p[i] = (geom_point){testutil_uniform(&g), testutil_uniform(&g)};
  uint32_t *tri = malloc(6 * 200 * sizeof *tri);
  assert_non_null(tri);
  size_t nt = tcdf_triangulate(&c, p, 200, tri);
  lot_cdf cd;
  assert_int_equal(lot_cdf_extract(p, tri, nt, c.k, &cd), 0);
  assert_int_equal(cd.triangles, nt);
  assert_int_equal(cd.edges, 0);
  assert_int_equal(cd.rounded, 0);
  assert_memory_equal(cd.tri, tri, 3 * nt * sizeof *tri);
  lot_cdf_free(&cd);
  free(tri);
  shape_free(c.k);
  rule_quad_unregister_user();
}

/* lot_cdf_nonedge by hand on the square, in its three rotations. */
static void test_cdf_nonedge(void **state) {
  (void)state;
  shape *k = NULL;
  char err[256];
  assert_int_equal(shape_parse("square", &k, err, sizeof err), 0);
  /* A=(0,0) B=(2,1) C=(3,3): s_AB = s_BC = (1,-1); every square through A
  ** and C contains B, so CA is the non-edge. */
  geom_point a = {0, 0}, b = {2, 1}, c = {3, 3};
  assert_int_equal(lot_cdf_nonedge(k, a, b, c), 2);
  assert_int_equal(lot_cdf_nonedge(k, b, c, a), 1);
  assert_int_equal(lot_cdf_nonedge(k, c, a, b), 0);
  geom_point d = {0, 0}, e = {2, -1}, f = {1, 2};   /* a square through all three */
  assert_int_equal(lot_cdf_nonedge(k, d, e, f), -1);
  lot_cdf empty;
  assert_int_equal(lot_cdf_extract(&a, NULL, 0, k, &empty), 0);
  assert_int_equal(empty.triangles + empty.edges, 0);
  lot_cdf_free(&empty);
  shape_free(k);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_cdf_nonedge),
      cmocka_unit_test(test_cdf_ellipse),
      cmocka_unit_test(test_cdf_general_position),
      cmocka_unit_test(test_cdf_grids),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
