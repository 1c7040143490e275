/*
** incremental.c: the incremental variants of section 2.3 as rows of the
** registry (docs/paradigms.md, "Incremental variants"):
**
**   incremental-serpentine, -spiral, -quaternary   lot's Lawson insertion
**       (locate by a walk, connect, flip) with the points in the bucket
**       orders of figure 2.8 instead of lot's BRIO;
**   watson            Watson's cavity insertion: the triangles whose
**       circumcircle holds the new site are deleted and the star-shaped
**       cavity is joined to it; located by a walk;
**   incremental-dag   the same insertion located through the history DAG
**       of every triangle ever made (Guibas, Knuth and Sharir; the Delaunay
**       tree of Boissonnat and Teillaud), the points in random order.
**
** Every one gives lot's triangles exactly: lot's insertion has one answer
** whatever the order (the rule's tie-broken LOT), and Watson's cavity is
** decided by paradigm_inregion, the rule's region test with lot's
** tie-break as a symbolic perturbation, under which no four sites are on
** one region, so the perturbed triangulation is unique and is what any
** correct algorithm builds (for DT and every ES:SHAPE: the argument is
** above wat_conflict).
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "paradigm_internal.h"
#include "lot.h"
#include "order.h"

/* ---- the bucket orders of figure 2.8 ----------------------------------- */

typedef enum incr_order { INCR_SERPENTINE, INCR_SPIRAL, INCR_QUATERNARY } incr_order;

/* The bucket grid's side: about sqrt(n) buckets for serpentine and spiral
** (Lee and Schachter), n for quaternary (Ohya, Iri and Murota), a power of
** two there (its cells are numbered by interleaving bits); `buckets` > 0
** asks for that many instead. */
static uint32_t incr_side(incr_order k, size_t n, double buckets) {
  double want = buckets > 0 ? buckets : k == INCR_QUATERNARY ? (double)n : sqrt((double)n);
  double most = 4.0 * (double)n + 16;   /* never more buckets than this: memory */
  uint32_t s = 1;
  while ((double)s * s < want && 4.0 * s * s <= most) s = k == INCR_QUATERNARY ? 2 * s : s + 1;
  return s;
}

/* Cell (i, j) (column i, row j) of an s x s spiral, numbered from the
** outer ring inwards: each ring's bottom row left to right, right column
** up, top row right to left, left column down. */
static uint64_t incr_spiral_key(uint32_t i, uint32_t j, uint32_t s) {
  uint32_t k = i < j ? i : j, a = s - 1 - i, b = s - 1 - j;
  k = k < a ? k : a;
  k = k < b ? k : b;
  uint64_t before = (uint64_t)s * s - (uint64_t)(s - 2 * k) * (s - 2 * k);
  uint32_t L = s - 2 * k - 1, x = i - k, y = j - k;   /* L: the ring's side less one */
  if (L == 0) return before;
  if (y == 0) return before + x;
  if (x == L) return before + L + y;
  if (y == L) return before + 2 * (uint64_t)L + (L - x);
  return before + 3 * (uint64_t)L + (L - y);
}

/* Bits of i and j interleaved (the base-4 digits of figure 2.8). */
static uint64_t incr_morton(uint32_t i, uint32_t j) {
  uint64_t z = 0;
  for (int b = 0; b < 16; b++)
    z |= (uint64_t)(i >> b & 1) << (2 * b) | (uint64_t)(j >> b & 1) << (2 * b + 1);
  return z;
}

static uint64_t incr_key(incr_order k, uint32_t i, uint32_t j, uint32_t s) {
  switch (k) {
    case INCR_SERPENTINE: return (uint64_t)j * s + (j % 2 == 0 ? i : s - 1 - i);
    case INCR_SPIRAL: return incr_spiral_key(i, j, s);
    case INCR_QUATERNARY: return incr_morton(i, j);
  }
  return 0;
}

/* The cell of coordinate v in [lo, hi] on a side of s cells. */
static uint32_t incr_cell(double v, double lo, double hi, uint32_t s) {
  double f = hi > lo ? (v - lo) / (hi - lo) * s : 0;
  uint32_t c = f > 0 ? (uint32_t)f : 0;
  return c < s ? c : s - 1;
}

/* ord[0..n-1]: the points by bucket in order k, input order within a
** bucket (a counting sort, stable).  0, or -1 out of memory.  O(n + s^2). */
static int incr_bucket_order(const geom_point *p, size_t n, incr_order k, double buckets,
                             uint32_t *ord, ops_counts *c) {
  uint32_t s = incr_side(k, n, buckets);
  size_t cells = (size_t)(k == INCR_QUATERNARY ? incr_morton(s - 1, s - 1) + 1 : (uint64_t)s * s);
  uint32_t *key = malloc((n ? n : 1) * sizeof *key), *start = calloc(cells + 1, sizeof *start);
  if (key == NULL || start == NULL) {
    free(key), free(start);
    return -1;
  }
  ops_memory(c, (int64_t)(n * sizeof *key + (cells + 1) * sizeof *start));
  double x0 = p[0].x, x1 = p[0].x, y0 = p[0].y, y1 = p[0].y;
  for (size_t i = 1; i < n; i++) {
    x0 = fmin(x0, p[i].x), x1 = fmax(x1, p[i].x);
    y0 = fmin(y0, p[i].y), y1 = fmax(y1, p[i].y);
  }
  for (size_t i = 0; i < n; i++) {
    key[i] = (uint32_t)incr_key(k, incr_cell(p[i].x, x0, x1, s), incr_cell(p[i].y, y0, y1, s), s);
    start[key[i] + 1]++;
  }
  for (size_t b = 0; b < cells; b++) start[b + 1] += start[b];
  for (size_t i = 0; i < n; i++) ord[start[key[i]]++] = (uint32_t)i;
  ops_add(c, OPS_BUCKETS, cells);
  ops_memory(c, -(int64_t)(n * sizeof *key + (cells + 1) * sizeof *start));
  free(key), free(start);
  return 0;
}

/* lot's incremental algorithm on the points in the order ord (its input
** order), the triangles mapped back to in's indices.  0, or -1 with the
** message. */
static int incr_lot_ordered(const paradigm_input *in, const uint32_t *ord, paradigm_output *out,
                            char *err, size_t errlen) {
  geom_point *q = malloc(in->n * sizeof *q);
  if (q == NULL) {
    snprintf(err, errlen, "out of memory for %zu points", in->n);
    return -1;
  }
  for (size_t i = 0; i < in->n; i++) q[i] = in->p[ord[i]];
  lot_options o;
  lot_options_init(&o, in->r);
  o.order = LOT_ORDER_INPUT;
  o.ops = &out->ops;
  lot *L = NULL;
  int rc = lot_build(&L, q, in->n, &o, err, errlen);
  free(q);
  if (rc != 0 || paradigm_lot_take(L, out, err, errlen) != 0) return -1;
  for (size_t k = 0; k < 3 * out->ntri; k++) out->tri[k] = ord[out->tri[k]];
  return 0;
}

/* Cost: the bucket sort O(n + buckets), then lot's insertion: a walk from
** the last point's triangle (O(sqrt(n)) steps per point for sqrt(n)
** buckets of uniform sites, O(1) for n buckets) and the flips, O(1)
** expected per point for uniform sites, O(n) worst (a half-parabola). */
static int incr_bucketed(const paradigm_input *in, incr_order k, paradigm_output *out,
                         char *err, size_t errlen) {
  uint32_t *ord = malloc(in->n * sizeof *ord);
  if (ord == NULL || incr_bucket_order(in->p, in->n, k, in->param, ord, &out->ops) != 0) {
    free(ord);
    snprintf(err, errlen, "out of memory for %zu points", in->n);
    return -1;
  }
  int rc = incr_lot_ordered(in, ord, out, err, errlen);
  free(ord);
  return rc;
}

int paradigm_incr_serpentine(const paradigm_input *in, paradigm_output *out, char *err,
                             size_t errlen) {
  return incr_bucketed(in, INCR_SERPENTINE, out, err, errlen);
}

int paradigm_incr_spiral(const paradigm_input *in, paradigm_output *out, char *err,
                         size_t errlen) {
  return incr_bucketed(in, INCR_SPIRAL, out, err, errlen);
}

int paradigm_incr_quaternary(const paradigm_input *in, paradigm_output *out, char *err,
                             size_t errlen) {
  return incr_bucketed(in, INCR_QUATERNARY, out, err, errlen);
}

/* ---- Watson's insertion ------------------------------------------------
**
** The triangulation is closed by ghost triangles (u, v, G), one per hull
** edge, the outside to the left of u -> v (as lot/mesh.h).  A ghost's
** "circumcircle" is the open half-plane beyond its edge together with the
** open edge itself (Shewchuk): a site outside the hull conflicts with the
** ghosts of the edges it sees, a site on a hull edge with that edge's
** ghost.  The conflicting triangles form a connected region (it holds the
** triangle or ghost holding the site, and with the perturbed test no site
** is cocircular with a triangle), star-shaped from the new site, so
** joining the site to its boundary edges triangulates it: k triangles
** deleted, k + 2 made (a disc of k triangles has k + 2 boundary edges), 2
** more per site, whatever the cavity.  Corner c = 3t + i names vertex
** tv[c] and the edge opposite it; tn[c] is the corner across that edge. */

#define WAT_GHOST UINT32_MAX

typedef struct wat_edge {
  uint32_t a, b, oc;    /* a cavity boundary edge a -> b (cavity on its left), the corner beyond */
} wat_edge;

typedef struct wat {
  const geom_point *p;
  uint32_t n;           /* points; vertex ids are indices into p, the ghost WAT_GHOST */
  const rule *r;
  ops_counts *ops;
  int dag;              /* 1: keep every triangle for the history DAG */
  uint32_t *tv, *tn, *mark;
  uint32_t *kid0, *kidn, *kidp, *kidc;   /* DAG: fan first, size; children's start, count */
  uint8_t *dead;
  size_t nt, cap;
  uint32_t *freel, *cav, *cavc, *stk, *start;   /* cavc: the corner toward the cavity's root */
  size_t nfree, ncav, nstk;
  wat_edge *bd;
  size_t nbd;
  uint32_t last;        /* a live triangle near the last insertion */
} wat;

/* A vertex's slot in per-vertex arrays (the ghost's is n). */
static uint32_t wat_slot(const wat *W, uint32_t v) {
  return v == WAT_GHOST ? W->n : v;
}

static int wat_is_ghost(const wat *W, uint32_t t) {
  const uint32_t *v = W->tv + 3 * (size_t)t;
  return v[0] == WAT_GHOST || v[1] == WAT_GHOST || v[2] == WAT_GHOST;
}

static int wat_lex_less(geom_point p, geom_point q) {
  return p.x < q.x || (p.x == q.x && p.y < q.y);
}

/* The ghost's real edge a -> b (its vertices after G), or 0 for a real
** triangle. */
static int wat_ghost_edge(const wat *W, uint32_t t, geom_point *a, geom_point *b) {
  const uint32_t *v = W->tv + 3 * (size_t)t;
  int g = v[0] == WAT_GHOST ? 0 : v[1] == WAT_GHOST ? 1 : v[2] == WAT_GHOST ? 2 : -1;
  if (g < 0) return 0;
  *a = W->p[v[(g + 1) % 3]];
  *b = W->p[v[(g + 2) % 3]];
  return 1;
}

/* Does q conflict with triangle t (lie inside its perturbed region: the
** circumcircle, or for ES:SHAPE the circumscribing homothet or rounding
** shape; or beyond or on a ghost's open edge)?
**
** Why the cavity is right for ES as for DT (section 2.3.6 leaves it
** open): the argument needs only that the regions through two sites a, b
** are nested on each side of ab, oppositely on the two sides (true of the
** circumscribing shapes with their rounding shapes, docs/emptyshape.md;
** the perturbation makes the order strict), and that the triangulation
** has empty regions.  (1) Connected, from the triangle holding q: if q is
** in the region of abc and beyond ab, the region of the neighbour abd is
** larger than abc's on d's side (d is outside abc's), so it holds q too; a
** hull edge's ghost conflicts.  (2) Star-shaped: a boundary edge ab of the
** cavity, abc inside, has q strictly on c's side (beyond it, q would be in
** abd's region; on its line but off the closed edge, outside abc's, a, b
** would be inside a region they bound; on the open edge, in both).  (3)
** The new triangles are right: q's region through a, b is smaller than
** abc's on c's side (q is in abc's) and than abd's on the other (q is not
** in abd's, on the side away from d), and those hold no old site.  A
** walk in such a triangulation may cycle (no acyclicity theorem for
** convex distances): wat_walk's scan is then its way out. */
static int wat_conflict(wat *W, uint32_t t, geom_point q) {
  geom_point a, b;
  if (!wat_ghost_edge(W, t, &a, &b)) {
    const uint32_t *v = W->tv + 3 * (size_t)t;
    return paradigm_inregion(W->r, W->ops, W->p[v[0]], W->p[v[1]], W->p[v[2]], q);
  }
  int o = ops_orient(W->ops, a, b, q);
  return o > 0 || (o == 0 && wat_lex_less(a, q) != wat_lex_less(b, q));
}

/* Does t hold q: a real triangle closed, a ghost's open half-plane? */
static int wat_holds(wat *W, uint32_t t, geom_point q) {
  geom_point a, b;
  if (wat_ghost_edge(W, t, &a, &b)) return ops_orient(W->ops, a, b, q) > 0;
  const uint32_t *v = W->tv + 3 * (size_t)t;
  for (int e = 0; e < 3; e++)
    if (ops_orient(W->ops, W->p[v[(e + 1) % 3]], W->p[v[(e + 2) % 3]], q) < 0) return 0;
  return 1;
}

/* Room for `more` triangles: 0, or -1 out of memory. */
static int wat_reserve(wat *W, size_t more) {
  if (W->nt + more <= W->cap) return 0;
  size_t cap = W->cap, old = W->cap;
  while (cap < W->nt + more) cap = cap ? 2 * cap : 1024;
  uint32_t **arr[11] = {&W->tv,    &W->tn,  &W->mark, &W->kid0, &W->kidn, &W->kidp,
                        &W->kidc,  &W->freel, &W->cav, &W->cavc, &W->stk};
  size_t width[11] = {3, 3, 1, 1, 1, 1, 1, 1, 1, 1, 1};
  for (int k = 0; k < 11; k++) {   /* the scratch lists hold a cavity: at most every triangle */
    uint32_t *x = realloc(*arr[k], (cap + 4) * width[k] * sizeof *x);
    if (x == NULL) return -1;
    *arr[k] = x;
  }
  uint8_t *d = realloc(W->dead, cap);
  wat_edge *bd = realloc(W->bd, (cap + 4) * sizeof *bd);
  if (d != NULL) W->dead = d;
  if (bd != NULL) W->bd = bd;
  if (d == NULL || bd == NULL) return -1;
  memset(W->mark + old, 0, (cap - old) * sizeof *W->mark);
  ops_memory(W->ops, (int64_t)((cap - old) * (15 * sizeof(uint32_t) + sizeof(wat_edge) + 1)));
  W->cap = cap;
  return 0;
}

/* A new triangle a, b, c (a freed slot in walk mode). */
static uint32_t wat_new(wat *W, uint32_t a, uint32_t b, uint32_t c) {
  uint32_t t = !W->dag && W->nfree > 0 ? W->freel[--W->nfree] : (uint32_t)W->nt++;
  uint32_t *v = W->tv + 3 * (size_t)t;
  v[0] = a, v[1] = b, v[2] = c;
  W->dead[t] = 0;
  W->kidn[t] = 0;
  W->mark[t] = 0;
  return t;
}

static void wat_link(wat *W, uint32_t c1, uint32_t c2) {
  W->tn[c1] = c2;
  W->tn[c2] = c1;
}

/* The first triangle a, b, c (anticlockwise) and its three ghosts. */
static void wat_first(wat *W, uint32_t a, uint32_t b, uint32_t c) {
  uint32_t t = wat_new(W, a, b, c), g0 = wat_new(W, b, a, WAT_GHOST);
  uint32_t g1 = wat_new(W, c, b, WAT_GHOST), g2 = wat_new(W, a, c, WAT_GHOST);
  wat_link(W, 3 * t + 0, 3 * g1 + 2);   /* b-c */
  wat_link(W, 3 * t + 1, 3 * g2 + 2);   /* c-a */
  wat_link(W, 3 * t + 2, 3 * g0 + 2);   /* a-b */
  wat_link(W, 3 * g0 + 0, 3 * g2 + 1);  /* a-G */
  wat_link(W, 3 * g0 + 1, 3 * g1 + 0);  /* b-G */
  wat_link(W, 3 * g2 + 0, 3 * g1 + 1);  /* c-G */
  ops_add(W->ops, OPS_EDGES_MADE, 3);
  W->last = t;
}

/* A live triangle conflicting with q, by a visibility walk from t: cross
** an edge q lies strictly beyond (tried from a rotating first edge) until
** there is none (t holds q) or a ghost is entered (q sees its edge).  In
** a Delaunay triangulation such a walk never cycles (Edelsbrunner); past
** 4 nt + 64 steps every triangle is scanned anyway. */
static uint32_t wat_walk(wat *W, uint32_t t, geom_point q) {
  const uint32_t *v = W->tv + 3 * (size_t)t;
  for (int g = 0; g < 3; g++)   /* from a ghost, into the real triangle across its edge */
    if (v[g] == WAT_GHOST) t = W->tn[3 * (size_t)t + (size_t)g] / 3;
  uint64_t limit = 4 * (uint64_t)W->nt + 64;
  for (uint64_t step = 0; step < limit; step++) {
    ops_add(W->ops, OPS_LOCATE, 1);
    if (wat_is_ghost(W, t)) return t;
    v = W->tv + 3 * (size_t)t;
    int crossed = 0;
    for (uint32_t j = 0; j < 3 && !crossed; j++) {
      uint32_t e = (uint32_t)(step + j) % 3;
      if (ops_orient(W->ops, W->p[v[(e + 1) % 3]], W->p[v[(e + 2) % 3]], q) < 0) {
        t = W->tn[3 * (size_t)t + e] / 3;
        crossed = 1;
      }
    }
    if (!crossed) return t;
  }
  for (uint32_t u = 0; u < W->nt; u++)
    if (!W->dead[u] && wat_holds(W, u, q)) return u;
  return W->last;   /* unreachable: the live triangles and ghosts cover the plane */
}

/* The history DAG: from the first four triangles (which cover the plane),
** into the child that holds q, until a live triangle.  The children of a
** dead triangle are the triangles of the fan that replaced its cavity
** which overlap it (wat_children: an arc of the fan); a ghost's half-plane
** may reach past them, and then the first child is taken and the walk
** finishes the job.  Counted: each node tested is a step. */
static uint32_t wat_descend(wat *W, geom_point q) {
  uint32_t base = 0, span = 4, from = 0, cnt = 4;
  for (;;) {
    uint32_t pick = base + from;
    for (uint32_t i = 0; i < cnt; i++) {
      uint32_t t = base + (from + i) % span;
      ops_add(W->ops, OPS_LOCATE, 1);
      if (wat_holds(W, t, q)) {
        pick = t;
        break;
      }
    }
    if (!W->dead[pick]) return pick;
    base = W->kid0[pick], span = W->kidn[pick], from = W->kidp[pick], cnt = W->kidc[pick];
  }
}

/* The cavity of q from the conflicting triangle t0: its triangles (cav,
** marked) and its boundary edges (bd).  Stamp s marks a triangle in
** (2s + 1) or tested out (2s). */
static void wat_cavity(wat *W, uint32_t t0, geom_point q, uint32_t s) {
  W->ncav = W->nbd = W->nstk = 0;
  W->mark[t0] = 2 * s + 1;
  W->cavc[W->ncav] = WAT_GHOST;   /* the root holds q */
  W->cav[W->ncav++] = W->stk[W->nstk++] = t0;
  while (W->nstk > 0) {
    uint32_t t = W->stk[--W->nstk];
    for (uint32_t e = 0; e < 3; e++) {
      uint32_t c = 3 * t + e, oc = W->tn[c], u = oc / 3;
      if (W->mark[u] == 2 * s + 1) continue;
      if (W->mark[u] != 2 * s && wat_conflict(W, u, q)) {
        W->mark[u] = 2 * s + 1;
        W->cavc[W->ncav] = oc;
        W->cav[W->ncav++] = W->stk[W->nstk++] = u;
        continue;
      }
      W->mark[u] = 2 * s;
      W->bd[W->nbd++] = (wat_edge){W->tv[3 * t + (e + 1) % 3], W->tv[3 * t + (e + 2) % 3], oc};
    }
  }
}

/* The real edges inside the cavity (each once): the edges deleted. */
static uint64_t wat_inner_edges(const wat *W, uint32_t s) {
  uint64_t k = 0;
  for (size_t i = 0; i < W->ncav; i++) {
    uint32_t t = W->cav[i];
    for (uint32_t e = 0; e < 3; e++) {
      uint32_t c = 3 * t + e, oc = W->tn[c];
      k += c < oc && W->mark[oc / 3] == 2 * s + 1 && W->tv[3 * t + (e + 1) % 3] != WAT_GHOST
           && W->tv[3 * t + (e + 2) % 3] != WAT_GHOST;
    }
  }
  return k;
}

/* The boundary edges in their cycle around k, into stk (edge indices);
** start[v] then says where the edge from v stands in it. */
static void wat_cycle(wat *W) {
  size_t m = W->nbd;
  for (size_t i = 0; i < m; i++) W->start[wat_slot(W, W->bd[i].a)] = (uint32_t)i;
  uint32_t e = 0;
  for (size_t j = 0; j < m; j++) {
    W->stk[j] = e;
    e = W->start[wat_slot(W, W->bd[e].b)];
  }
  for (size_t j = 0; j < m; j++) {
    W->start[wat_slot(W, W->bd[W->stk[j]].a)] = (uint32_t)j;
  }
}

/* The DAG's children of the cavity's triangles.  The cavity is a polygon
** triangulated without inner vertices, star-shaped from k, its dual a tree
** rooted at the triangle that holds k.  A triangle t reached from its
** parent across edge x -> y (t on its left) lies beyond that chord from k:
** the segments from k to the boundary edges on the arc from y round to x
** (anticlockwise, through t's third vertex) cross the chord into t, those
** of the other arc stay on k's side.  So t's children are the fan
** triangles of that arc; the root's, a ghost's, or any when k lies outside
** the hull (the root is a ghost), the whole fan. */
static void wat_children(wat *W, uint32_t first) {
  uint32_t m = (uint32_t)W->nbd;
  int outside = wat_is_ghost(W, W->cav[0]);
  for (size_t i = 0; i < W->ncav; i++) {
    uint32_t t = W->cav[i], c = W->cavc[i], from = 0, cnt = m;
    if (!outside && c != WAT_GHOST && !wat_is_ghost(W, t)) {
      uint32_t x = W->tv[3 * (c / 3) + (c % 3 + 1) % 3], y = W->tv[3 * (c / 3) + (c % 3 + 2) % 3];
      from = W->start[y];
      cnt = (W->start[x] + m - from) % m;
    }
    W->kid0[t] = first, W->kidn[t] = m, W->kidp[t] = from, W->kidc[t] = cnt;
  }
}

/* Join vertex k to every boundary edge, in their cycle; link the fan. */
static void wat_fan(wat *W, uint32_t k) {
  for (size_t i = 0; i < W->ncav; i++) W->dead[W->cav[i]] = 1;
  if (!W->dag)
    for (size_t i = 0; i < W->ncav; i++) W->freel[W->nfree++] = W->cav[i];
  wat_cycle(W);
  uint32_t first = (uint32_t)W->nt;
  for (size_t j = 0; j < W->nbd; j++) {
    const wat_edge *e = &W->bd[W->stk[j]];
    uint32_t t = wat_new(W, e->a, e->b, k);
    wat_link(W, 3 * t + 2, e->oc);
    ops_add(W->ops, OPS_EDGES_MADE, e->a != WAT_GHOST);
    W->stk[j] = t;
  }
  for (size_t j = 0; j < W->nbd; j++)   /* (a, b, k) meets the next, (b, c, k), across b-k */
    wat_link(W, 3 * W->stk[j] + 0, 3 * W->stk[(j + 1) % W->nbd] + 1);
  if (W->dag) wat_children(W, first);
  W->last = W->stk[0];
}

static void wat_free(wat *W) {
  free(W->tv), free(W->tn), free(W->mark), free(W->kid0), free(W->kidn), free(W->freel);
  free(W->kidp), free(W->kidc), free(W->cav), free(W->cavc), free(W->stk), free(W->dead);
  free(W->bd), free(W->start);
}

/* Insert vertex k: locate, carve the cavity, fill it.  0, or -1 (memory). */
static int wat_insert(wat *W, uint32_t k, uint32_t stamp) {
  geom_point q = W->p[k];
  uint32_t t0 = wat_walk(W, W->dag ? wat_descend(W, q) : W->last, q);
  wat_cavity(W, t0, q, stamp);
  ops_add(W->ops, OPS_EDGES_DELETED, wat_inner_edges(W, stamp));
  if (wat_reserve(W, W->nbd) != 0) return -1;
  wat_fan(W, k);
  return 0;
}

/* The first triangle in the order ord: ord[0], ord[1] and the first point
** off their line (the runner made sure there is one), then every other
** point.  0, or -1 out of memory. */
static int wat_run(wat *W, const uint32_t *ord) {
  uint32_t a = ord[0], b = ord[1], c = 2;
  while (ops_orient(W->ops, W->p[a], W->p[b], W->p[ord[c]]) == 0) c++;
  if (wat_reserve(W, 4) != 0) return -1;
  if (geom_orient_valid(W->p[a], W->p[b], W->p[ord[c]]) > 0) wat_first(W, a, b, ord[c]);
  else wat_first(W, a, ord[c], b);
  for (uint32_t i = 2, s = 1; i < W->n; i++)
    if (i != c && wat_insert(W, ord[i], s++) != 0) return -1;
  return 0;
}

/* The live real triangles into out. */
static int wat_output(const wat *W, paradigm_output *out) {
  size_t m = 0;
  out->tri = malloc((2 * (size_t)W->n + 1) * 3 * sizeof *out->tri);
  if (out->tri == NULL) return -1;
  for (uint32_t t = 0; t < W->nt; t++) {
    if (W->dead[t] || wat_is_ghost(W, t)) continue;
    memcpy(out->tri + 3 * m++, W->tv + 3 * (size_t)t, 3 * sizeof *out->tri);
  }
  out->ntri = m;
  return 0;
}

/* Watson's algorithm in the order ord (walk or DAG). */
static int wat_build(const paradigm_input *in, const uint32_t *ord, int dag,
                     paradigm_output *out, char *err, size_t errlen) {
  wat W;
  memset(&W, 0, sizeof W);
  W.p = in->p, W.n = (uint32_t)in->n, W.r = in->r, W.ops = &out->ops, W.dag = dag;
  W.start = malloc(((size_t)W.n + 1) * sizeof *W.start);
  int rc = W.start == NULL || wat_reserve(&W, 2 * (size_t)W.n + 4) != 0 ? -1 : wat_run(&W, ord);
  if (rc == 0) rc = wat_output(&W, out);
  ops_memory(W.ops, -(int64_t)(W.cap * (15 * sizeof(uint32_t) + sizeof(wat_edge) + 1)));
  wat_free(&W);
  if (rc != 0) snprintf(err, errlen, "out of memory for %zu points", in->n);
  return rc;
}

/* The insertion order: random (lot's --order random: the same seed, the
** same order) or the quaternary buckets. */
static int wat_order(const paradigm_input *in, int random, uint32_t *ord, ops_counts *c) {
  if (random) {
    lot_order_random((uint32_t)in->n, in->seed, ord);
    return 0;
  }
  return incr_bucket_order(in->p, in->n, INCR_QUATERNARY, 0, ord, c);
}

static int wat_rows(const paradigm_input *in, int dag, paradigm_output *out, char *err,
                    size_t errlen) {
  uint32_t *ord = malloc(in->n * sizeof *ord);
  int random = dag ? in->param != 1 : in->param == 1;
  if (ord == NULL || wat_order(in, random, ord, &out->ops) != 0) {
    free(ord);
    snprintf(err, errlen, "out of memory for %zu points", in->n);
    return -1;
  }
  int rc = wat_build(in, ord, dag, out, err, errlen);
  free(ord);
  return rc;
}

/* Cost: the cavity of each site, O(its degree) expected for uniform
** sites, found by a walk of O(1) steps in the quaternary order (O(sqrt n)
** in random order, param 1): O(n) expected for uniform sites after the
** O(n) bucket sort; O(n^2) worst (every cavity large). */
int paradigm_watson(const paradigm_input *in, paradigm_output *out, char *err, size_t errlen) {
  return wat_rows(in, 0, out, err, errlen);
}

/* Cost: random order (param 1: quaternary buckets), each site located
** through the DAG in O(log n) expected steps (Guibas, Knuth and Sharir's
** analysis over random orders), cavities O(1) expected: O(n log n)
** expected time, O(n) expected memory (every triangle ever made is kept:
** about 6 per site). */
int paradigm_incr_dag(const paradigm_input *in, paradigm_output *out, char *err,
                      size_t errlen) {
  return wat_rows(in, 1, out, err, errlen);
}
