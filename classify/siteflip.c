/*
** siteflip.c: every triangulation of a small site set and its flip graph.
**
** Segments.  A segment i-j may be an edge of a triangulation iff no site
** lies in its relative interior ("valid").  Two valid segments without a
** common endpoint can share a point only by crossing properly (touching
** would put an endpoint of one in the interior of the other), and two with
** a common endpoint only meet there (overlapping would too).  So a set of
** valid segments is non-crossing iff no two of them cross properly: two
** strict orientation tests each, exact.  A maximal non-crossing set of
** valid segments is a triangulation; the first one is built greedily.
**
** Faces.  A triangle with no site inside or on its sides ("empty") whose
** three sides are edges of a triangulation T is a face of T: an edge of T
** entering it would cross a side, and no site is there to end one.  So the
** faces of T are the empty triangles whose side masks lie in T's mask.
**
** Flips.  An edge i-j shared by faces ijk and jil is flippable iff ikjl is
** strictly convex, i.e. iff k-l crosses i-j properly; the flip swaps i-j
** for k-l.  The flip graph of a planar point set is connected (Lawson), so
** breadth-first search from the first triangulation, with the edge mask as
** the canonical key, finds all of them.  Each flip is recorded once, from
** the triangulation that holds the quadrilateral's diagonal AC.
**
** Memory.  Every array the build grows is counted (its capacity in bytes)
** with what the finished graph will still need per triangulation and per
** flip (SITEFLIP_NODE_RESERVE, SITEFLIP_EDGE_RESERVE); a growth that would
** pass the budget is cut to what is left, and when nothing is left the
** build stops (siteflip_build_within).  The capacities do not change the
** result: node numbers, edges and quadrilaterals come out in the same
** order whatever the budget.
*/
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "siteflip_internal.h"
#include "measure.h"
#include "joint.h"

#define SITEFLIP_NSEG (SITEFLIP_MAX_SITES * (SITEFLIP_MAX_SITES - 1) / 2)
#define SITEFLIP_NTRIPLE (SITEFLIP_MAX_SITES * (SITEFLIP_MAX_SITES - 1) * (SITEFLIP_MAX_SITES - 2) / 6)

int siteflip_seg(int n, int i, int j) {
  if (i > j) {
    int t = i;
    i = j;
    j = t;
  }
  return i * n - i * (i + 1) / 2 + (j - i - 1);
}

static void siteflip_mask_set(siteflip_mask *m, int b) {
  if (b < 64) m->lo |= 1ull << b;
  else m->hi |= 1ull << (b - 64);
}

static void siteflip_mask_clear(siteflip_mask *m, int b) {
  if (b < 64) m->lo &= ~(1ull << b);
  else m->hi &= ~(1ull << (b - 64));
}

static int siteflip_mask_has(const siteflip_mask *m, int b) {
  return (int)(b < 64 ? (m->lo >> b) & 1 : (m->hi >> (b - 64)) & 1);
}

static int siteflip_mask_meets(siteflip_mask a, siteflip_mask b) {
  return ((a.lo & b.lo) | (a.hi & b.hi)) != 0;
}

static int siteflip_mask_within(siteflip_mask a, siteflip_mask b) {
  return (a.lo & ~b.lo) == 0 && (a.hi & ~b.hi) == 0;
}

int siteflip_has_edge(const siteflip_graph *g, int u, int i, int j) {
  return siteflip_mask_has(&g->node[u], siteflip_seg(g->n, i, j));
}

/* ---- checking the sites -------------------------------------------------- */

int siteflip_check(const geom_point *p, int n, char *err, size_t errlen) {
  if (n < 3) {
    snprintf(err, errlen, "%d site%s: a triangulation needs at least 3", n, n == 1 ? "" : "s");
    return -1;
  }
  if (n > SITEFLIP_MAX_SITES) {
    snprintf(err, errlen,
             "%d sites: enumeration takes at most %d sites (the edge masks hold 120 segments)",
             n, SITEFLIP_MAX_SITES);
    return -1;
  }
  for (int i = 0; i < n; i++) {
    geom_coorderr e = geom_coord_check(p[i].x);
    if (e == GEOM_COORD_OK) e = geom_coord_check(p[i].y);
    if (e != GEOM_COORD_OK) {
      snprintf(err, errlen, "site %d: a coordinate %s", i + 1, geom_coorderr_str(e));
      return -1;
    }
  }
  for (int i = 0; i < n; i++)
    for (int j = 0; j < i; j++)
      if (p[i].x == p[j].x && p[i].y == p[j].y) {
        snprintf(err, errlen, "sites %d and %d are equal (%.17g, %.17g)", j + 1, i + 1,
                 p[i].x, p[i].y);
        return -1;
      }
  for (int k = 2; k < n; k++)
    if (geom_orient(p[0], p[1], p[k]) != 0) return 0;
  snprintf(err, errlen, "all %d sites are collinear: there is no triangulation", n);
  return -1;
}

/* ---- the build ----------------------------------------------------------- */

typedef struct siteflip_ctx {
  int n, nseg;
  unsigned char seg_i[SITEFLIP_NSEG], seg_j[SITEFLIP_NSEG];
  int valid[SITEFLIP_NSEG];
  siteflip_mask cross[SITEFLIP_NSEG];    /* segments crossing s properly */
  int ntri;
  unsigned char tri_v[SITEFLIP_NTRIPLE][3];
  siteflip_mask tri_mask[SITEFLIP_NTRIPLE];
  short tri_id[SITEFLIP_MAX_SITES][SITEFLIP_MAX_SITES][SITEFLIP_MAX_SITES];
  int *qmap;                             /* [1 << n]: site set -> quadrilateral, -1 */
  int *table;                            /* hash: node index + 1, 0 empty */
  size_t tcap;
  size_t ncap, ecap, qcap, tricap;       /* capacities of node, edge, quad, node_tri rows */
  size_t budget, used;                   /* bytes: the budget, what is counted against it */
  int over;                              /* the budget ran out */
  int cap;                               /* stop past cap triangulations; 0: never */
  census_progress_fn progress;
  void *pctx;
} siteflip_ctx;

/* Counts `bytes` more against the budget: 0, or -1 (and over) past it. */
static int siteflip_spend(siteflip_ctx *c, size_t bytes) {
  if (bytes > c->budget - c->used) {
    c->over = 1;
    return -1;
  }
  c->used += bytes;
  return 0;
}

/* Room for `need` elements of `size` bytes in *p (capacity *cap): doubled,
** but never past the budget.  0, or -1 (over set when the budget ran out). */
static int siteflip_grow(siteflip_ctx *c, void **p, size_t *cap, size_t need, size_t size) {
  if (need <= *cap) return 0;
  size_t left = (c->budget - c->used) / size, want = *cap ? *cap * 2 : 64;
  if (want < need) want = need;
  if (want - *cap > left) want = *cap + left;
  if (want < need) {
    c->over = 1;
    return -1;
  }
  void *q = realloc(*p, want * size);
  if (q == NULL) return -1;
  c->used += (want - *cap) * size;
  *p = q;
  *cap = want;
  return 0;
}

/* Is site k in the relative interior of segment i-j? (exact) */
static int siteflip_between(const geom_point *p, int i, int j, int k) {
  geom_point a = p[i], b = p[j], c = p[k];
  if (geom_orient(a, b, c) != 0) return 0;
  return fmin(a.x, b.x) <= c.x && c.x <= fmax(a.x, b.x) && fmin(a.y, b.y) <= c.y &&
         c.y <= fmax(a.y, b.y);
}

static int siteflip_crosses(const geom_point *p, int a, int b, int c, int d) {
  if (a == c || a == d || b == c || b == d) return 0;
  return geom_segments_cross(p[a], p[b], p[c], p[d]);
}

/* Is the triangle ijk proper and free of other sites (inside or on a side)? */
static int siteflip_empty(const geom_point *p, int n, int i, int j, int k) {
  int o = geom_orient(p[i], p[j], p[k]);
  if (o == 0) return 0;
  for (int m = 0; m < n; m++) {
    if (m == i || m == j || m == k) continue;
    if (o * geom_orient(p[i], p[j], p[m]) >= 0 && o * geom_orient(p[j], p[k], p[m]) >= 0 &&
        o * geom_orient(p[k], p[i], p[m]) >= 0)
      return 0;
  }
  return 1;
}

static void siteflip_segments(siteflip_ctx *c, const geom_point *p) {
  int n = c->n;
  c->nseg = n * (n - 1) / 2;
  for (int i = 0; i < n; i++)
    for (int j = i + 1; j < n; j++) {
      int s = siteflip_seg(n, i, j), ok = 1;
      c->seg_i[s] = (unsigned char)i;
      c->seg_j[s] = (unsigned char)j;
      for (int k = 0; k < n && ok; k++)
        if (k != i && k != j && siteflip_between(p, i, j, k)) ok = 0;
      c->valid[s] = ok;
    }
  for (int s = 0; s < c->nseg; s++) {
    c->cross[s] = (siteflip_mask){0, 0};
    for (int t = 0; t < c->nseg; t++)
      if (c->valid[t] && siteflip_crosses(p, c->seg_i[s], c->seg_j[s], c->seg_i[t], c->seg_j[t]))
        siteflip_mask_set(&c->cross[s], t);
  }
  c->ntri = 0;
  for (int i = 0; i < n; i++)
    for (int j = i + 1; j < n; j++)
      for (int k = j + 1; k < n; k++) {
        c->tri_id[i][j][k] = -1;
        if (!siteflip_empty(p, n, i, j, k)) continue;
        int t = c->ntri++;
        c->tri_id[i][j][k] = (short)t;
        c->tri_v[t][0] = (unsigned char)i;
        c->tri_v[t][1] = (unsigned char)j;
        c->tri_v[t][2] = (unsigned char)k;
        c->tri_mask[t] = (siteflip_mask){0, 0};
        siteflip_mask_set(&c->tri_mask[t], siteflip_seg(n, i, j));
        siteflip_mask_set(&c->tri_mask[t], siteflip_seg(n, j, k));
        siteflip_mask_set(&c->tri_mask[t], siteflip_seg(n, i, k));
      }
}

static int siteflip_tri_of(const siteflip_ctx *c, int a, int b, int d) {
  int v[3] = {a, b, d};
  for (int x = 0; x < 2; x++)
    for (int y = 0; y < 2 - x; y++)
      if (v[y] > v[y + 1]) {
        int t = v[y];
        v[y] = v[y + 1];
        v[y + 1] = t;
      }
  return c->tri_id[v[0]][v[1]][v[2]];
}

/* Every bit of the mask reaches the low bits the table uses (a product
** alone carries low bits only upwards; neighbouring triangulations differ
** in two bits).  The hash orders nothing the graph keeps: nodes are
** numbered in discovery order. */
static uint64_t siteflip_hash(siteflip_mask m) {
  uint64_t h = m.lo * 0x9E3779B97F4A7C15ull;
  h ^= h >> 32;
  h += m.hi * 0xC2B2AE3D27D4EB4Full;
  h ^= h >> 29;
  h *= 0xBF58476D1CE4E5B9ull;
  return h ^ (h >> 32);
}

/* Node index of mask m, adding it when new (-1 when out of memory). */
static int siteflip_node_of(siteflip_ctx *c, siteflip_graph *g, siteflip_mask m) {
  if ((size_t)g->nnodes * 2 >= c->tcap) {
    size_t cap = c->tcap ? c->tcap * 2 : 1024;
    if (siteflip_spend(c, (cap - c->tcap) * sizeof *c->table) != 0) return -1;
    int *t = calloc(cap, sizeof *t);
    if (t == NULL) return -1;
    for (int u = 0; u < g->nnodes; u++) {
      size_t h = siteflip_hash(g->node[u]) & (cap - 1);
      while (t[h] != 0) h = (h + 1) & (cap - 1);
      t[h] = u + 1;
    }
    free(c->table);
    c->table = t;
    c->tcap = cap;
  }
  size_t h = siteflip_hash(m) & (c->tcap - 1);
  for (; c->table[h] != 0; h = (h + 1) & (c->tcap - 1)) {
    siteflip_mask o = g->node[c->table[h] - 1];
    if (o.lo == m.lo && o.hi == m.hi) return c->table[h] - 1;
  }
  if (g->nnodes == INT_MAX - 1 || siteflip_spend(c, SITEFLIP_NODE_RESERVE) != 0 ||
      siteflip_grow(c, (void **)&g->node, &c->ncap, (size_t)g->nnodes + 1, sizeof *g->node) != 0)
    return -1;
  g->node[g->nnodes] = m;
  c->table[h] = g->nnodes + 1;
  return g->nnodes++;
}

/* The quadrilateral of the flip i-j <-> k-l, added when new; *is_ac says
** whether i-j is its diagonal AC.  -1 when out of memory. */
static int siteflip_quad_of(siteflip_ctx *c, siteflip_graph *g, int i, int j, int k, int l,
                            int *is_ac) {
  const geom_point *p = g->p;
  int cyc[4] = {i, k, j, l};
  if (geom_orient(p[i], p[k], p[j]) < 0) {
    cyc[1] = l;
    cyc[3] = k;
  }
  int m = 0;
  for (int t = 1; t < 4; t++)
    if (cyc[t] < cyc[m]) m = t;
  unsigned char v[4];
  for (int t = 0; t < 4; t++) v[t] = (unsigned char)cyc[(m + t) % 4];
  *is_ac = (v[0] == i && v[2] == j) || (v[0] == j && v[2] == i);
  int key = (1 << i) | (1 << j) | (1 << k) | (1 << l);
  if (c->qmap[key] >= 0) return c->qmap[key];
  if (siteflip_grow(c, (void **)&g->quad, &c->qcap, (size_t)g->nquads + 1, sizeof *g->quad) != 0)
    return -1;
  siteflip_quad *q = &g->quad[g->nquads];
  memcpy(q->v, v, 4);
  q->tri[0] = siteflip_tri_of(c, v[0], v[1], v[2]);
  q->tri[1] = siteflip_tri_of(c, v[0], v[2], v[3]);
  q->tri[2] = siteflip_tri_of(c, v[0], v[1], v[3]);
  q->tri[3] = siteflip_tri_of(c, v[1], v[2], v[3]);
  return c->qmap[key] = g->nquads++;
}

static int siteflip_add_edge(siteflip_ctx *c, siteflip_graph *g, int ac, int bd, int q) {
  /* 2 nedges + 1 adjacency entries must stay an int count */
  if (g->nedges >= INT_MAX / 2 - 1 || siteflip_spend(c, SITEFLIP_EDGE_RESERVE) != 0 ||
      siteflip_grow(c, (void **)&g->edge, &c->ecap, (size_t)g->nedges + 1, sizeof *g->edge) != 0)
    return -1;
  g->edge[g->nedges++] = (siteflip_edge){ac, bd, q};
  return 0;
}

/* Faces of node u into g->node_tri (grown by the caller), and every flip
** out of u; new triangulations join the queue (the node array). */
static int siteflip_expand(siteflip_ctx *c, siteflip_graph *g, int u, int *faces) {
  siteflip_mask T = g->node[u];
  int nf = 0, face_of[SITEFLIP_NSEG][2], nfo[SITEFLIP_NSEG];
  for (int t = 0; t < c->ntri; t++)
    if (siteflip_mask_within(c->tri_mask[t], T)) faces[nf++] = t;
  if (nf != g->per) return -2;   /* cannot happen: every triangulation has per faces */
  memset(nfo, 0, sizeof nfo);
  for (int f = 0; f < nf; f++) {
    const unsigned char *v = c->tri_v[faces[f]];
    int s[3] = {siteflip_seg(c->n, v[0], v[1]), siteflip_seg(c->n, v[1], v[2]),
                siteflip_seg(c->n, v[0], v[2])};
    for (int e = 0; e < 3; e++) face_of[s[e]][nfo[s[e]]++] = faces[f];
  }
  for (int s = 0; s < c->nseg; s++) {
    if (nfo[s] != 2) continue;
    int i = c->seg_i[s], j = c->seg_j[s], k = -1, l = -1;
    for (int e = 0; e < 3; e++) {
      int a = c->tri_v[face_of[s][0]][e], b = c->tri_v[face_of[s][1]][e];
      if (a != i && a != j) k = a;
      if (b != i && b != j) l = b;
    }
    int s2 = siteflip_seg(c->n, k, l);
    if (!siteflip_mask_has(&c->cross[s], s2)) continue;   /* not strictly convex */
    siteflip_mask T2 = T;
    siteflip_mask_clear(&T2, s);
    siteflip_mask_set(&T2, s2);
    int w = siteflip_node_of(c, g, T2), is_ac;
    if (w < 0) return -1;
    int q = siteflip_quad_of(c, g, i, j, k, l, &is_ac);
    if (q < 0) return -1;
    if (is_ac && siteflip_add_edge(c, g, u, w, q) != 0) return -1;
  }
  return 0;
}

static int siteflip_adjacency(siteflip_graph *g) {
  g->adj_off = calloc((size_t)g->nnodes + 1, sizeof *g->adj_off);
  g->adj = malloc(((size_t)g->nedges * 2 + 1) * sizeof *g->adj);
  if (g->adj_off == NULL || g->adj == NULL) return -1;
  for (int e = 0; e < g->nedges; e++) {
    g->adj_off[g->edge[e].ac + 1]++;
    g->adj_off[g->edge[e].bd + 1]++;
  }
  for (int u = 0; u < g->nnodes; u++) g->adj_off[u + 1] += g->adj_off[u];
  int *fill = malloc(((size_t)g->nnodes + 1) * sizeof *fill);
  if (fill == NULL) return -1;
  memcpy(fill, g->adj_off, (size_t)g->nnodes * sizeof *fill);
  for (int e = 0; e < g->nedges; e++) {
    g->adj[fill[g->edge[e].ac]++] = e;
    g->adj[fill[g->edge[e].bd]++] = e;
  }
  free(fill);
  return 0;
}

void siteflip_dt_decisions(const siteflip_graph *g, rule_choice *d) {
  for (int q = 0; q < g->nquads; q++) {
    const unsigned char *v = g->quad[q].v;
    d[q] = rule_delaunay_eval(g->p[v[0]], g->p[v[1]], g->p[v[2]], g->p[v[3]]);
  }
}

/* The triangulation all of whose flippable edges are locally Delaunay:
** the nodes no flip leaves under DT; -1 unless unique. */
int siteflip_delaunay_of(const siteflip_graph *g, const rule_choice *d) {
  int found = -1, count = 0;
  for (int u = 0; u < g->nnodes && count < 2; u++) {
    int out = 0;
    for (int a = g->adj_off[u]; a < g->adj_off[u + 1] && !out; a++) {
      const siteflip_edge *e = &g->edge[g->adj[a]];
      out = (d[e->quad] == RULE_AC && e->bd == u) || (d[e->quad] == RULE_BD && e->ac == u);
    }
    if (!out) {
      found = u;
      count++;
    }
  }
  return count == 1 ? found : -1;
}

void siteflip_move_tris(siteflip_graph *g, const geom_point *p) {
  memcpy(g->p, p, (size_t)g->n * sizeof *p);
  for (int t = 0; t < g->ntris; t++)
    geom_tri_make(&g->tri[t], p[g->tri_v[t][0]], p[g->tri_v[t][1]], p[g->tri_v[t][2]]);
}

int siteflip_move(siteflip_graph *g, const geom_point *p) {
  siteflip_move_tris(g, p);
  rule_choice *d = malloc(((size_t)g->nquads + 1) * sizeof *d);
  g->delaunay = -1;
  if (d == NULL) return -1;   /* never "as if DT were not unique": that is another answer */
  siteflip_dt_decisions(g, d);
  g->delaunay = siteflip_delaunay_of(g, d);
  free(d);
  return 0;
}

static int siteflip_first(siteflip_ctx *c, siteflip_graph *g) {
  siteflip_mask T = {0, 0};
  for (int s = 0; s < c->nseg; s++)
    if (c->valid[s] && !siteflip_mask_meets(c->cross[s], T)) siteflip_mask_set(&T, s);
  int nf = 0;
  for (int t = 0; t < c->ntri; t++) nf += siteflip_mask_within(c->tri_mask[t], T);
  g->per = nf;
  return siteflip_node_of(c, g, T);
}

/* Breadth-first: node u's faces into its row of node_tri, its flips; the
** progress every 4096 nodes (expanded out of found).  0, -1, or 1 when more
** than c->cap triangulations are found (c->cap > 0): the search stops. */
static int siteflip_enumerate(siteflip_ctx *c, siteflip_graph *g) {
  if (siteflip_first(c, g) != 0) return -1;
  size_t row = (size_t)g->per * sizeof *g->node_tri;
  for (int u = 0; u < g->nnodes; u++) {
    if (siteflip_grow(c, (void **)&g->node_tri, &c->tricap, (size_t)u + 1, row) != 0) return -1;
    if (siteflip_expand(c, g, u, g->node_tri + (size_t)u * (size_t)g->per) != 0) return -1;
    if (c->cap > 0 && g->nnodes > c->cap) return 1;
    if (c->progress != NULL && (u & 4095) == 4095)
      c->progress((uint64_t)u + 1, (uint64_t)g->nnodes, c->pctx);
  }
  if (c->progress != NULL) c->progress((uint64_t)g->nnodes, (uint64_t)g->nnodes, c->pctx);
  return 0;
}

/* "1 GiB", "512 MiB", "1000 bytes": the largest unit that divides. */
static void siteflip_bytes_str(char *buf, size_t len, size_t bytes) {
  static const char *const unit[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
  int k = 0;
  while (k < 4 && bytes >= 1024 && bytes % 1024 == 0) {
    bytes /= 1024;
    k++;
  }
  snprintf(buf, len, "%zu %s", bytes, unit[k]);
}

/* A fresh context for n sites within lim, its own bytes counted; NULL
** when out of memory. */
static siteflip_ctx *siteflip_ctx_new(int n, const siteflip_limits *lim) {
  siteflip_ctx *c = malloc(sizeof *c);
  if (c == NULL) return NULL;
  memset(c, 0, sizeof *c);
  size_t nq = (size_t)1 << n;
  if ((c->qmap = malloc(nq * sizeof *c->qmap)) == NULL) {
    free(c);
    return NULL;
  }
  memset(c->qmap, 0xff, nq * sizeof *c->qmap);
  c->n = n;
  c->budget = lim->memory ? lim->memory : SITEFLIP_MEMORY_DEFAULT;
  c->progress = lim->progress;
  c->pctx = lim->ctx;
  siteflip_spend(c, sizeof *c + nq * sizeof *c->qmap);
  return c;
}

static void siteflip_ctx_free(siteflip_ctx *c) {
  if (c == NULL) return;
  free(c->table);
  free(c->qmap);
  free(c);
}

/* The enumeration and the arrays made from it: 0, or -1. */
static int siteflip_fill(siteflip_ctx *c, siteflip_graph *g) {
  if (c->over || siteflip_enumerate(c, g) != 0) return -1;
  g->ntris = c->ntri;
  g->tri_v = malloc((size_t)c->ntri * sizeof *g->tri_v + 1);
  g->tri = malloc((size_t)c->ntri * sizeof *g->tri + 1);
  if (g->tri_v == NULL || g->tri == NULL || siteflip_adjacency(g) != 0) return -1;
  memcpy(g->tri_v, c->tri_v, (size_t)c->ntri * sizeof *g->tri_v);
  return 0;
}

siteflip_graph *siteflip_build_within(const geom_point *p, int n, const siteflip_limits *lim,
                                      int *over, char *err, size_t errlen) {
  if (over != NULL) *over = 0;
  if (siteflip_check(p, n, err, errlen) != 0) return NULL;
  siteflip_graph *g = calloc(1, sizeof *g);
  siteflip_ctx *c = siteflip_ctx_new(n, lim);
  if (g != NULL && c != NULL) {
    g->n = n;
    memcpy(g->p, p, (size_t)n * sizeof *p);
    siteflip_segments(c, p);
    if (siteflip_fill(c, g) == 0 && siteflip_move(g, p) == 0) {
      siteflip_ctx_free(c);
      return g;
    }
  }
  if (c != NULL && c->over) {
    char b[32];
    siteflip_bytes_str(b, sizeof b, c->budget);
    snprintf(err, errlen, "the flip graph of %d sites outgrows the memory budget of %s: "
             "%d triangulations found before it ran out", n, b, g != NULL ? g->nnodes : 0);
    if (over != NULL) *over = 1;
  } else {
    snprintf(err, errlen, "out of memory enumerating the triangulations of %d sites", n);
  }
  siteflip_ctx_free(c);
  siteflip_free(g);
  return NULL;
}

/* Cost: the breadth-first search up to the first cap + 1 triangulations,
** O(min(N, cap + 1) n^3) for N triangulations (each expansion looks at the
** O(n^2) segments and the O(n^3) empty triangles' masks), and the memory of
** as many nodes; never the whole graph's when N > cap. */
int siteflip_count_upto(const geom_point *p, int n, int cap, int *count, char *err,
                        size_t errlen) {
  if (cap < 1) {
    snprintf(err, errlen, "siteflip_count_upto: cap %d; expected at least 1", cap);
    return -1;
  }
  if (siteflip_check(p, n, err, errlen) != 0) return -1;
  const siteflip_limits lim = {SITEFLIP_MEMORY_DEFAULT, NULL, NULL};
  siteflip_graph *g = calloc(1, sizeof *g);
  siteflip_ctx *c = siteflip_ctx_new(n, &lim);
  int rc = -1;
  if (g != NULL && c != NULL) {
    g->n = n;
    c->cap = cap;
    siteflip_segments(c, p);
    rc = siteflip_enumerate(c, g);
    *count = rc == 1 ? cap + 1 : g->nnodes;
  }
  if (rc < 0)
    snprintf(err, errlen, "out of memory (or past the memory budget) counting the "
             "triangulations of %d sites", n);
  siteflip_ctx_free(c);
  siteflip_free(g);
  return rc;
}

siteflip_graph *siteflip_build(const geom_point *p, int n, char *err, size_t errlen) {
  const siteflip_limits lim = {SITEFLIP_MEMORY_DEFAULT, NULL, NULL};
  return siteflip_build_within(p, n, &lim, NULL, err, errlen);
}

void siteflip_free(siteflip_graph *g) {
  if (g == NULL) return;
  free(g->node);
  free(g->node_tri);
  free(g->tri_v);
  free(g->tri);
  free(g->quad);
  free(g->edge);
  free(g->adj_off);
  free(g->adj);
  free(g);
}

/* ---- one rule ------------------------------------------------------------- */

static rule_choice siteflip_decide(const siteflip_graph *g, const rule *r, const double *w,
                                   int q) {
  const siteflip_quad *Q = &g->quad[q];
  if (!rule_is_triangle(r)) {
    geom_point pts[4] = {g->p[Q->v[0]], g->p[Q->v[1]], g->p[Q->v[2]], g->p[Q->v[3]]};
    if (w == NULL) return rule_eval(r, pts, NULL, NULL);
    const double wq[4] = {w[Q->v[0]], w[Q->v[1]], w[Q->v[2]], w[Q->v[3]]};
    return rule_eval_weighted(r, pts, wq, NULL, NULL);
  }
  return rule_eval_tris(r, &g->tri[Q->tri[0]], &g->tri[Q->tri[1]], &g->tri[Q->tri[2]],
                        &g->tri[Q->tri[3]], NULL, NULL);
}

double siteflip_node_key(const siteflip_graph *g, const rule *r, int u) {
  const measure *M = measure_get(rule_measure(r));
  double k = rule_key_identity(r);
  for (int f = 0; f < g->per; f++) {
    const geom_tri *t = &g->tri[g->node_tri[(size_t)u * (size_t)g->per + f]];
    k = rule_key_add(r, k, rule_key(r, M->fn(t, M->ctx)));
  }
  return k;
}

/* Kahn's algorithm on the strict edges: peel sinks until none is left. */
static int siteflip_has_cycle(const siteflip_graph *g, const rule_choice *dec, int *outdeg,
                              int *queue) {
  int head = 0, tail = 0;
  for (int u = 0; u < g->nnodes; u++)
    if (outdeg[u] == 0) queue[tail++] = u;
  while (head < tail) {
    int u = queue[head++];
    for (int a = g->adj_off[u]; a < g->adj_off[u + 1]; a++) {
      const siteflip_edge *e = &g->edge[g->adj[a]];
      rule_choice d = dec[e->quad];
      int from = d == RULE_AC ? e->bd : d == RULE_BD ? e->ac : -1;
      int to = d == RULE_AC ? e->ac : e->bd;
      if (from >= 0 && to == u && --outdeg[from] == 0) queue[tail++] = from;
    }
  }
  return tail < g->nnodes;
}

static void siteflip_got(const siteflip_graph *g, const rule *r, const int *sinkv, int nsinks,
                         siteflip_result *res) {
  double best = 0, worst = 0;
  for (int u = 0; u < g->nnodes; u++) {
    double k = siteflip_node_key(g, r, u);
    if (u == 0 || k < best) {
      best = k;
      res->got_node = u;
    }
  }
  res->worst_sink = -1;
  for (int s = 0; s < nsinks; s++) {
    double k = siteflip_node_key(g, r, sinkv[s]);
    if (res->worst_sink < 0 || k > worst) {
      worst = k;
      res->worst_sink = sinkv[s];
    }
  }
  res->has_got = 1;
  res->got_total = rule_unkey(r, best);
  res->worst_gap = res->worst_sink >= 0 ? rule_gap(r, best, worst) : 0;
}

int siteflip_direct(const siteflip_graph *g, const rule *r, double tie_eps,
                    rule_choice *dec, int *sinks, siteflip_result *res) {
  return siteflip_direct_weighted(g, r, NULL, tie_eps, dec, sinks, res);
}

int siteflip_direct_weighted(const siteflip_graph *g, const rule *r, const double *w,
                             double tie_eps, rule_choice *dec, int *sinks,
                             siteflip_result *res) {
  memset(res, 0, sizeof *res);
  rule re = *r;
  rule_set_tie_eps(&re, tie_eps);
  size_t nn = (size_t)g->nnodes;
  int *outdeg = calloc(nn, sizeof *outdeg), *indeg = calloc(nn, sizeof *indeg);
  int *queue = malloc(nn * sizeof *queue);
  if (outdeg == NULL || indeg == NULL || queue == NULL) {
    free(outdeg);
    free(indeg);
    free(queue);
    return -1;
  }
  for (int q = 0; q < g->nquads; q++) {
    dec[q] = siteflip_decide(g, &re, w, q);
    res->ties |= dec[q] == RULE_EITHER;
  }
  for (int e = 0; e < g->nedges; e++) {
    rule_choice d = dec[g->edge[e].quad];
    if (d == RULE_EITHER) continue;
    int to = d == RULE_AC ? g->edge[e].ac : g->edge[e].bd;
    int from = d == RULE_AC ? g->edge[e].bd : g->edge[e].ac;
    outdeg[from]++;
    indeg[to]++;
  }
  for (int u = 0; u < g->nnodes; u++) {
    if (outdeg[u] == 0) {
      if (sinks != NULL) sinks[res->nsinks] = u;
      queue[res->nsinks++] = u;
    }
    res->nsources += indeg[u] == 0;
  }
  res->sink_dt = res->nsinks == 1 && g->delaunay >= 0 ? queue[0] == g->delaunay : -1;
  if (rule_is_triangle(r)) siteflip_got(g, r, queue, res->nsinks, res);
  res->cycle = siteflip_has_cycle(g, dec, outdeg, queue);
  free(outdeg);
  free(indeg);
  free(queue);
  return 0;
}
