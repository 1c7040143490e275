/*
** divide_polygon.c: divide and conquer for the constrained Delaunay
** triangulation of a simple polygon (section 2.6.3, "dc-polygon"), and of
** a convex one (2.6.5).
**
** The polygon is split at a diagonal that leaves at least n/3 of its
** vertices on each side, each side is triangulated recursively (the
** diagonal a wall between them, a constraint while they are solved), and
** the two constrained Delaunay triangulations are merged across the
** diagonal: the wall is lifted and the edges that are no longer locally
** Delaunay are flipped, starting from the diagonal.  Every test is lot's
** (paradigm_inshape, its tie-break a symbolic perturbation of the lifts),
** so the result is lot's constrained Delaunay triangulation of the polygon
** restricted to its inside, ties included.
**
** Finding the diagonals.  As 2.6.3 suggests, any triangulation of the
** polygon holds them all: here one made once by cutting ears.  Each piece
** of the recursion is a subtree of that triangulation's dual tree (a split
** at one of its edges leaves each side's triangles where they are), and a
** piece of m vertices has m - 2 triangles.  An edge of a triangle bounds an
** arc of the piece's boundary of (triangles beyond it) + 1 sides; a
** triangle's three arcs add up to m.  Existence: start at any triangle and
** step across its arc of more than m/2 sides, if it has one; the arcs
** beyond shrink, so the walk ends at a triangle whose arcs are all at most
** m/2 (the dual tree's centroid).  Its largest arc e >= m/3 is no side (m
** >= 4 gives e >= 2), so that edge is a diagonal; it leaves e + 1 >= m/3 +
** 1 vertices beyond it and m - e + 1 >= m/2 + 1 on the near side.  Found by
** one breadth-first pass over the piece's triangles with their subtree
** sizes: O(m).
**
** The merge.  Two constrained Delaunay triangulations joined at a lifted
** wall are locally Delaunay everywhere but at the diagonal, and Lawson's
** flips from there end at the constrained Delaunay triangulation of the
** union (locally Delaunay everywhere implies it; the perturbed lifts make
** it unique).  Each flip lowers the lifted surface, so no edge comes back,
** and an edge of the union's triangulation is never flipped (it is locally
** Delaunay in any triangulation that holds it): a merge flips edges the
** union does not keep, each once.
**
** Cost.  Ears: each test looks at the reflex and flat vertices in the
** grid cells (about one such vertex a cell) that the ear's bounding box
** meets, so O(n) tests of O(1) cells when the walk finds small ears near it
** (convex, star-shaped, monotone polygons of spread vertices); at worst
** O(n) tests an ear of O(r) vertices each, O(n^2 r) for r reflex ones; a
** linear-time triangulation (Chazelle's, which 2.6.3 cites) is what would
** bring it to O(n).  Splits: the pieces shrink by a factor 2/3 at least,
** so log_{3/2} n levels of O(n) passes, O(n log n).  Merges: the flips,
** O(m^2) for a piece of m at worst (each pair of vertices an edge once);
** measured about half a flip a vertex a level (bench_paradigm_dc: 6.8 a
** vertex in all on a convex polygon of 20,000, 0.5 on a star-shaped one).
** Memory: 79 bytes a vertex plus the flip stack and the ears' grid.
**
** ES:SHAPE is refused: a rule's flips need not end at lot's LOT (2.6.6).
*/
#include <stdio.h>
#include <stdlib.h>
#include "geom_key_internal.h"
#include "geom_mem_internal.h"
#include "paradigm_internal.h"
#include "cpdt.h"

typedef struct dp_run {
  geom_point *q;        /* the vertices in anticlockwise boundary order */
  uint32_t *ord;        /* q[v] = in->p[ord[v]] */
  uint32_t n;
  uint32_t *tri;        /* n - 2 triangles, 3 vertices each, anticlockwise */
  int32_t *nb;          /* nb[3t + k]: across the edge opposite tri[3t + k] */
  uint8_t *wall;        /* per corner: the opposite edge is a diagonal being split at */
  uint32_t *vt;         /* a triangle at each vertex */
  uint32_t *seen, *list, *size;   /* a piece's breadth-first pass */
  int32_t *up;          /* its parent triangle */
  uint32_t stamp;
  uint32_t *stack;      /* the merge's edges to check, triangle and corner */
  size_t cap;
  const rule *r;
  ops_counts *c;
} dp_run;

#define DP_AT(t, k) (3 * (t) + ((k) % 3))

/* ---- ears: the first triangulation ---- */

/* w in the closed triangle a, b, c (anticlockwise). */
static int dp_in_triangle(dp_run *R, uint32_t a, uint32_t b, uint32_t c, uint32_t w) {
  const geom_point *q = R->q;
  return ops_orient(R->c, q[a], q[b], q[w]) >= 0 && ops_orient(R->c, q[b], q[c], q[w]) >= 0
         && ops_orient(R->c, q[c], q[a], q[w]) >= 0;
}

/* The ear cutting's state: the remaining polygon as a ring, and a grid of
** cells over the bounding box listing the reflex and flat vertices (bent).
** The grid only filters: a cell's index is monotone in the coordinate
** (a difference, a product by a positive scale, a clamp and a truncation,
** each monotone in IEEE arithmetic), so a vertex inside a triangle lies in
** a cell between those of the triangle's extreme coordinates, and the
** exact orientation tests decide. */
typedef struct dp_ears {
  uint32_t *next, *prev, *cell, *off;   /* cell: the bent vertices, cell by cell */
  uint8_t *bent;
  double x0, y0, sx, sy;
  uint32_t w;           /* cells a side */
} dp_ears;

static uint32_t dp_cell(double v, double v0, double s, uint32_t w) {
  double c = (v - v0) * s;
  return c <= 0 ? 0 : c >= (double)(w - 1) ? w - 1 : (uint32_t)c;
}

/* The grid cell of vertex v (row-major). */
static size_t dp_vertex_cell(const dp_run *R, const dp_ears *E, uint32_t v) {
  return (size_t)dp_cell(R->q[v].y, E->y0, E->sy, E->w) * E->w
         + dp_cell(R->q[v].x, E->x0, E->sx, E->w);
}

/* The cell of bent vertex v, GEOM_CSR_NONE for the others: geom_csr_build's key. */
typedef struct dp_grid { const dp_run *R; const dp_ears *E; } dp_grid;

static size_t dp_bent_cell(const void *ctx, size_t v) {
  const dp_grid *g = ctx;
  return g->E->bent[v] ? dp_vertex_cell(g->R, g->E, (uint32_t)v) : GEOM_CSR_NONE;
}

/* Is v an ear of the remaining polygon?  Strictly convex, and no reflex or
** flat vertex in its closed triangle (if any vertex lies in it, one of
** those does: the one farthest from the cut does). */
static int dp_is_ear(dp_run *R, const dp_ears *E, uint32_t v) {
  uint32_t a = E->prev[v], b = E->next[v];
  if (E->bent[v]) return 0;
  geom_point pa = R->q[a], pv = R->q[v], pb = R->q[b];
  double lx = pa.x < pv.x ? pa.x : pv.x, hx = pa.x > pv.x ? pa.x : pv.x;
  double ly = pa.y < pv.y ? pa.y : pv.y, hy = pa.y > pv.y ? pa.y : pv.y;
  lx = pb.x < lx ? pb.x : lx, hx = pb.x > hx ? pb.x : hx;
  ly = pb.y < ly ? pb.y : ly, hy = pb.y > hy ? pb.y : hy;
  uint32_t cx0 = dp_cell(lx, E->x0, E->sx, E->w), cx1 = dp_cell(hx, E->x0, E->sx, E->w);
  uint32_t cy1 = dp_cell(hy, E->y0, E->sy, E->w);
  for (uint32_t cy = dp_cell(ly, E->y0, E->sy, E->w); cy <= cy1; cy++)
    for (uint32_t cx = cx0; cx <= cx1; cx++)
      for (uint32_t k = E->off[cy * E->w + cx]; k < E->off[cy * E->w + cx + 1]; k++) {
        uint32_t w = E->cell[k];
        if (E->bent[w] && w != a && w != b && dp_in_triangle(R, a, v, b, w)) return 0;
      }
  return 1;
}

static void dp_bend(dp_run *R, dp_ears *E, uint32_t v) {
  E->bent[v] = ops_orient(R->c, R->q[E->prev[v]], R->q[v], R->q[E->next[v]]) <= 0;
}

/* The ring, the bent vertices and their grid of about one cell each. */
static int dp_ears_begin(dp_run *R, dp_ears *E, uint32_t *lst) {
  uint32_t n = R->n, r = 0;
  E->next = lst, E->prev = lst + n, E->cell = lst + 2 * n, E->bent = (uint8_t *)(lst + 3 * n);
  double x1 = R->q[0].x, y1 = R->q[0].y;
  E->x0 = x1, E->y0 = y1;
  for (uint32_t v = 0; v < n; v++) {
    E->next[v] = (v + 1) % n, E->prev[v] = (v + n - 1) % n;
    geom_point p = R->q[v];
    E->x0 = p.x < E->x0 ? p.x : E->x0, x1 = p.x > x1 ? p.x : x1;
    E->y0 = p.y < E->y0 ? p.y : E->y0, y1 = p.y > y1 ? p.y : y1;
  }
  for (uint32_t v = 0; v < n; v++) dp_bend(R, E, v), r += E->bent[v];
  for (E->w = 1; (E->w + 1) * (E->w + 1) <= r; E->w++) {}
  E->sx = E->w / (x1 - E->x0), E->sy = E->w / (y1 - E->y0);   /* ranges > 0: no line */
  size_t cells = (size_t)E->w * E->w;
  E->off = malloc((cells + 1) * sizeof *E->off);
  if (E->off == NULL) return -1;
  ops_memory(R->c, (int64_t)(cells + 1) * 4);
  /* a counting sort by cell; an earlier linked-list insertion (link[v] = head[c], head[c]
  ** = v) came out of clang 14 at -O3 -march=native vectorised (AVX-512 gathers and
  ** scatters) and lost vertices that shared a cell: ears were cut over reflex vertices
  ** (test_dc_polygon caught it) */
  geom_csr_build(E->off, cells, E->cell, n, dp_bent_cell, &(dp_grid){R, E});
  return 0;
}

/* Cut ears walking round the polygon (cost above): the n - 2 triangles
** into R->tri.  lst holds 4n words of scratch.  0, -1 out of memory, -2
** when the walk went round without an ear (not simple: the check refused
** that). */
static int dp_ears_cut(dp_run *R, uint32_t *lst) {
  dp_ears E;
  if (dp_ears_begin(R, &E, lst) != 0) return -1;
  uint32_t v = 0, left = R->n, miss = 0, t = 0;
  while (left > 3 && miss <= left) {
    if (!dp_is_ear(R, &E, v)) {
      v = E.next[v], miss++;
      continue;
    }
    uint32_t a = E.prev[v], b = E.next[v];
    R->tri[3 * t] = a, R->tri[3 * t + 1] = v, R->tri[3 * t + 2] = b, t++;
    E.next[a] = b, E.prev[b] = a, E.bent[v] = 0, left--, miss = 0;
    if (E.bent[a]) dp_bend(R, &E, a);
    if (E.bent[b]) dp_bend(R, &E, b);
    v = a;
  }
  R->tri[3 * t] = E.prev[v], R->tri[3 * t + 1] = v, R->tri[3 * t + 2] = E.next[v];
  ops_add(R->c, OPS_EDGES_MADE, 2 * (uint64_t)R->n - 3);   /* n sides, n - 3 diagonals */
  ops_memory(R->c, -(int64_t)E.w * E.w * 4);
  free(E.off);
  return left > 3 ? -2 : 0;
}

/* ---- the splits ---- */

/* The piece of m vertices holding triangle t0 (walls and the outside bound
** it) in breadth-first order into R->list, parents and subtree sizes. */
static void dp_piece(dp_run *R, uint32_t t0, uint32_t m) {
  uint32_t head = 0, tail = 0, stamp = ++R->stamp;
  R->list[tail++] = t0, R->seen[t0] = stamp, R->up[t0] = -1;
  while (head < tail) {
    uint32_t t = R->list[head++];
    for (int k = 0; k < 3; k++) {
      int32_t u = R->nb[3 * t + k];
      if (u < 0 || R->wall[3 * t + k] || R->seen[u] == stamp) continue;
      R->seen[u] = stamp, R->up[u] = (int32_t)t, R->list[tail++] = (uint32_t)u;
    }
  }
  for (uint32_t i = 0; i < m - 2; i++) R->size[R->list[i]] = 1;
  for (uint32_t i = m - 2; i-- > 1;) R->size[R->up[R->list[i]]] += R->size[R->list[i]];
}

/* The sides of the piece's boundary beyond edge k of t (piece of m). */
static uint32_t dp_arc(const dp_run *R, uint32_t t, int k, uint32_t m) {
  int32_t u = R->nb[3 * t + k];
  if (u < 0 || R->wall[3 * t + k]) return 1;
  if (u == R->up[t]) return m - 1 - R->size[t];
  return R->size[u] + 1;
}

/* The split of the piece of m >= 4 vertices at t0: the centroid triangle's
** largest arc (existence and bounds above), as triangle *t and corner *k;
** returns the arc. */
static uint32_t dp_diagonal(dp_run *R, uint32_t t0, uint32_t m, uint32_t *t, int *k) {
  dp_piece(R, t0, m);
  for (uint32_t i = 0; i < m - 2; i++) {
    uint32_t s = R->list[i], best = 0;
    int bk = 0;
    for (int j = 0; j < 3; j++) {
      uint32_t e = dp_arc(R, s, j, m);
      if (e > best) best = e, bk = j;
    }
    if (2 * best <= m) {
      *t = s, *k = bk;
      return best;
    }
  }
  return 0;   /* unreachable: the centroid exists */
}

/* ---- the merges: Lawson's flips ---- */

static void dp_set(dp_run *R, uint32_t t, const uint32_t v[3], const int32_t nb[3],
                   const uint8_t w[3]) {
  for (int i = 0; i < 3; i++)
    R->tri[3 * t + i] = v[i], R->nb[3 * t + i] = nb[i], R->wall[3 * t + i] = w[i];
  for (int i = 0; i < 3; i++) R->vt[v[i]] = t;
}

/* Flip the edge b-c of t = (a, b, c) (a at corner k) and u = (d, c, b) (d at
** corner j) into t = (a, b, d), u = (d, c, a). */
static void dp_flip(dp_run *R, uint32_t t, int k, uint32_t u, int j) {
  uint32_t a = R->tri[DP_AT(t, k)], b = R->tri[DP_AT(t, k + 1)], c = R->tri[DP_AT(t, k + 2)];
  uint32_t d = R->tri[DP_AT(u, j)];
  int32_t na = R->nb[DP_AT(t, k + 1)], nB = R->nb[DP_AT(t, k + 2)];
  int32_t nc = R->nb[DP_AT(u, j + 1)], nd = R->nb[DP_AT(u, j + 2)];
  uint8_t wa = R->wall[DP_AT(t, k + 1)], wb = R->wall[DP_AT(t, k + 2)];
  uint8_t wc = R->wall[DP_AT(u, j + 1)], wd = R->wall[DP_AT(u, j + 2)];
  paradigm_nb_relink(R->nb, na, t, u);
  paradigm_nb_relink(R->nb, nc, u, t);
  dp_set(R, t, (uint32_t[3]){a, b, d}, (int32_t[3]){nc, (int32_t)u, nB},
         (uint8_t[3]){wc, 0, wb});
  dp_set(R, u, (uint32_t[3]){d, c, a}, (int32_t[3]){na, (int32_t)t, nd},
         (uint8_t[3]){wa, 0, wd});
  ops_add(R->c, OPS_FLIPS, 1);
  ops_add(R->c, OPS_EDGES_MADE, 1);
  ops_add(R->c, OPS_EDGES_DELETED, 1);
}

static int dp_push(dp_run *R, size_t *top, uint32_t t, int k) {
  size_t old = R->cap;
  if (geom_grow((void **)&R->stack, &R->cap, *top + 1, sizeof *R->stack) != 0) return -1;
  ops_memory(R->c, (int64_t)((R->cap - old) * sizeof *R->stack));   /* the peak counts it */
  R->stack[(*top)++] = 3 * t + (uint32_t)k;
  return 0;
}

/* Flip from edge k of t until every edge is locally Delaunay (the merge;
** an entry made stale by a later flip names another edge of a triangle
** that flip rewrote, whose edges it pushed again).  0, or -1 (memory). */
static int dp_lawson(dp_run *R, uint32_t t0, int k0) {
  size_t top = 0;
  if (dp_push(R, &top, t0, k0) != 0) return -1;
  while (top > 0) {
    uint32_t e = R->stack[--top], t = e / 3;
    int k = (int)(e % 3);
    int32_t u = R->nb[e];
    if (u < 0 || R->wall[e]) continue;
    int j = paradigm_nb_corner(R->nb, (uint32_t)u, t);
    const geom_point *q = R->q;
    if (paradigm_inshape(R->r, R->c, q[R->tri[e]], q[R->tri[DP_AT(t, k + 1)]],
                         q[R->tri[DP_AT(t, k + 2)]], q[R->tri[DP_AT(u, j)]]) <= 0)
      continue;
    dp_flip(R, t, k, (uint32_t)u, j);
    if (dp_push(R, &top, t, 0) || dp_push(R, &top, t, 2) || dp_push(R, &top, (uint32_t)u, 0)
        || dp_push(R, &top, (uint32_t)u, 2))
      return -1;
  }
  return 0;
}

/* The triangle and corner of the edge a-b, turning round a from R->vt[a]
** one way, then the other (the outside stops a turn).  O(degree of a). */
static void dp_find(const dp_run *R, uint32_t a, uint32_t b, uint32_t *t, int *k) {
  for (int way = 1; way <= 2; way++) {
    int32_t s = (int32_t)R->vt[a];
    while (s >= 0) {
      uint32_t u = (uint32_t)s;
      int i = R->tri[3 * u] == a ? 0 : R->tri[3 * u + 1] == a ? 1 : 2;
      if (R->tri[DP_AT(u, i + 1)] == b) { *t = u, *k = (i + 2) % 3; return; }
      if (R->tri[DP_AT(u, i + 2)] == b) { *t = u, *k = (i + 1) % 3; return; }
      s = R->nb[DP_AT(u, i + way)];
    }
  }
}

/* The piece of m vertices holding triangle t0: split, solve both sides,
** merge.  T(m) = T(e + 1) + T(m - e + 1) + O(m) + flips, m/3 <= e <= m/2. */
static int dp_solve(dp_run *R, uint32_t t0, uint32_t m) {
  if (m <= 3) return 0;
  uint32_t t = t0;
  int k = 0;
  uint32_t e = dp_diagonal(R, t0, m, &t, &k);
  uint32_t u = (uint32_t)R->nb[3 * t + k], a = R->tri[DP_AT(t, k + 1)];
  uint32_t b = R->tri[DP_AT(t, k + 2)];
  R->wall[3 * t + k] = R->wall[3 * u + paradigm_nb_corner(R->nb, u, t)] = 1;
  if (dp_solve(R, t, m - e + 1) != 0 || dp_solve(R, u, e + 1) != 0) return -1;
  dp_find(R, a, b, &t, &k);
  u = (uint32_t)R->nb[3 * t + k];
  R->wall[3 * t + k] = R->wall[3 * u + paradigm_nb_corner(R->nb, u, t)] = 0;
  return dp_lawson(R, t, k);
}

/* ---- the run ---- */

/* The vertices anticlockwise: a polygon checked as simple (any way round),
** a convex one as strictly convex and anticlockwise.  0, or -1 (err). */
static int dp_order(const paradigm_input *in, dp_run *R, char *err, size_t errlen) {
  int ccw = 1;
  if (in->problem == PARADIGM_CONVEX) {
    size_t bad = 0;
    int e = cpdt_check(in->p, in->n, &bad);
    if (e != 0) {
      snprintf(err, errlen, "convex polygon: vertex %zu: %s", bad + 1, cpdt_check_str(e));
      return -1;
    }
  } else {
    uint32_t *seg;
    if (paradigm_polygon_sides(in, &seg, &ccw, err, errlen) != 0) return -1;
    free(seg);
  }
  for (uint32_t v = 0; v < R->n; v++) {
    R->ord[v] = ccw ? v : R->n - 1 - v;
    R->q[v] = in->p[R->ord[v]];
  }
  return 0;
}

/* 79 bytes a vertex: points 16, order 4, triangles 12, neighbours 12,
** walls 3, a triangle per vertex 4, the breadth-first pass 12 (marks,
** sizes, parents) and its list, also the ears' scratch, 16. */
static size_t dp_bytes(uint32_t n) {
  return (size_t)n * (sizeof(geom_point) + 15 * sizeof(uint32_t) + 3) + 64 * sizeof(uint32_t);
}

static int dp_alloc(dp_run *R, uint32_t n) {
  size_t t = n;   /* n - 2 triangles, rounded up */
  R->q = malloc(n * sizeof *R->q);
  R->ord = malloc(n * sizeof *R->ord);
  R->tri = malloc(3 * t * sizeof *R->tri);
  R->nb = malloc(3 * t * sizeof *R->nb);
  R->wall = calloc(3 * t, 1);
  R->vt = malloc(n * sizeof *R->vt);
  R->seen = calloc(t, sizeof *R->seen);
  R->list = malloc(4 * t * sizeof *R->list);   /* also the ears' scratch */
  R->size = malloc(t * sizeof *R->size);
  R->up = malloc(t * sizeof *R->up);
  R->cap = 64;
  R->stack = malloc(R->cap * sizeof *R->stack);
  ops_memory(R->c, (int64_t)dp_bytes(n));
  return R->q && R->ord && R->tri && R->nb && R->wall && R->vt && R->seen && R->list
         && R->size && R->up && R->stack ? 0 : -1;
}

static void dp_free(dp_run *R) {
  ops_memory(R->c, -(int64_t)dp_bytes(R->n) - (int64_t)((R->cap - 64) * sizeof *R->stack));
  free(R->q), free(R->ord), free(R->tri), free(R->nb), free(R->wall), free(R->vt);
  free(R->seen), free(R->list), free(R->size), free(R->up), free(R->stack);
}

/* Ears, neighbours, then the recursion from triangle 0; the triangles out
** in input indices. */
static int dp_mesh(dp_run *R, paradigm_output *out, char *err, size_t errlen) {
  uint32_t n = R->n, nt = n - 2;
  int rc = dp_ears_cut(R, R->list);
  if (rc != 0) {
    if (rc == -1) snprintf(err, errlen, "out of memory for a polygon of %u vertices", n);
    else snprintf(err, errlen, "dc-polygon: no ear among %u vertices (a bug: please report it)",
                  n);
    return -1;
  }
  for (uint32_t i = 0; i < 3 * nt; i++) R->vt[R->tri[i]] = i / 3;
  if (lot_neighbors(R->tri, nt, n, R->nb) != 0 || dp_solve(R, 0, n) != 0) {
    snprintf(err, errlen, "out of memory for a polygon of %u vertices", n);
    return -1;
  }
  out->tri = malloc(3 * (size_t)nt * sizeof *out->tri);
  if (out->tri == NULL) {
    snprintf(err, errlen, "out of memory for the triangles of %u vertices", n);
    return -1;
  }
  for (size_t i = 0; i < 3 * (size_t)nt; i++) out->tri[i] = R->ord[R->tri[i]];
  out->ntri = nt;
  return 0;
}

int paradigm_dc_polygon(const paradigm_input *in, paradigm_output *out, char *err,
                        size_t errlen) {
  if (in->n >= 0x7fffffffu / 3) {
    snprintf(err, errlen, "dc-polygon: %zu vertices, at most %u", in->n, 0x7fffffffu / 3 - 1);
    return -1;
  }
  dp_run R = {.n = (uint32_t)in->n, .r = in->r, .c = &out->ops};
  int rc = dp_alloc(&R, R.n);
  if (rc != 0) snprintf(err, errlen, "out of memory for a polygon of %zu vertices", in->n);
  if (rc == 0) rc = dp_order(in, &R, err, errlen);
  if (rc == 0) rc = dp_mesh(&R, out, err, errlen);
  dp_free(&R);
  return rc;
}
