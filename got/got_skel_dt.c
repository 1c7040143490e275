/*
** got_skel_dt.c: the skeleton of a point set's GOT for the rules whose GOT is a Delaunay
** triangulation (rule_got_cdt_theorem), built from a triangulation the caller claims is
** Delaunay and certified here exactly (got_skel.h; docs/got.md, "Point sets: rules whose
** GOT is Delaunay").  got/ does not triangulate: the caller brings the triangulation
** (lot's exact Delaunay triangulation, through studies/), and nothing it brings is trusted.
**
** Why the candidates are sound.  Each rule rule_got_cdt_theorem names decides every strictly
** convex quadrilateral as Delaunay's rule does, strictly when the four points are not
** cocircular (a theorem of the thesis's appendix A, not an observation on samples),
** and its joint's keys add (a strictly monotone sum).  A GOT is weakly locally optimal (no
** flip lowers its total strictly: got_points.c), so at each of its edges whose quadrilateral
** is strictly convex the fourth point is not strictly inside the circle of the other three;
** an edge whose quadrilateral is not strictly convex has that property anyway (a point
** strictly inside the circle, beyond the chord, makes the quadrilateral strictly convex).
** By Delaunay's lemma a triangulation whose every edge is locally Delaunay is a Delaunay
** triangulation: a triangulation of the Delaunay subdivision, whose cells are the convex
** hulls of the points on an empty circle.  So every GOT holds every edge of the subdivision
** (CERTAIN) and its other edges are diagonals of cells with four points or more (POSSIBLE).
**
** The certificate (exact: geom_orient, geom_incircle; each failure one line):
**   - every triangle has three distinct vertices below n and turns anticlockwise;
**   - no directed edge is used twice; the unmatched directed edges (each interior edge is
**     matched by its reverse in the triangle on its other side) form one closed cycle that
**     turns left or goes straight at every vertex and winds once.  The number of triangles
**     over a point off the edges is the winding number of that cycle around it (the
**     boundary of a sum of anticlockwise triangles): 1 inside, 0 outside, so the triangles
**     tile the convex region the cycle bounds;
**   - every point is a vertex (a point inside a triangle or an edge would be covered twice
**     near it), so the triangles triangulate the point set and the cycle is its hull;
**     Euler's 2n - h - 2 triangles is checked as well;
**   - every interior edge is locally Delaunay (geom_incircle <= 0): a Delaunay
**     triangulation, by the lemma.  Edges with geom_incircle == 0 join the cells.
** Cost: O(n) exact tests, plus sorting each point's outgoing edges by their heads (O(n) for
** bounded degree, O(n log n) at worst) and O(k^2 log k) for the diagonals of a cell of k
** points (k = 3 in general position, 4 for a grid's squares).
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "got_skel.h"
#include "geom_key_internal.h"
#include "geom_mem_internal.h"

#define DT_NONE UINT32_MAX

/* The claimed triangulation and what the certificate learns: directed edge h = 3 t + k
** runs from tri[3 t + k] to tri[3 t + (k + 1) % 3]. */
typedef struct dtc {
  const geom_point *p;
  size_t n, nt;
  const uint32_t *tri;
  uint32_t *off;        /* n + 1: point v's outgoing edges are out[off[v] .. off[v + 1]) */
  uint64_t *out;        /* head << 32 | h, ascending */
  uint32_t *twin;       /* per directed edge: its reverse, or DT_NONE (the boundary) */
  uint32_t *cell;       /* per triangle: its cell (cocircular neighbours joined) */
  size_t nbound;        /* boundary edges = hull points h */
} dtc;

static void dtc_free(dtc *d) {
  free(d->off), free(d->out), free(d->twin), free(d->cell);
}

static int dtc_err(char *err, size_t errlen, const char *what) {
  snprintf(err, errlen, "delaunay certificate: %s", what);
  return -1;
}

static uint32_t dtc_tail(const dtc *d, size_t h) { return d->tri[h]; }
static uint32_t dtc_head(const dtc *d, size_t h) { return d->tri[h - h % 3 + (h + 1) % 3]; }
static uint32_t dtc_third(const dtc *d, size_t h) { return d->tri[h - h % 3 + (h + 2) % 3]; }

/* Triangles: vertices below n, distinct, anticlockwise.  O(t). */
static int dtc_triangles(const dtc *d, char *err, size_t errlen) {
  for (size_t t = 0; t < d->nt; t++) {
    const uint32_t *v = d->tri + 3 * t;
    if (v[0] >= d->n || v[1] >= d->n || v[2] >= d->n) {
      snprintf(err, errlen, "delaunay certificate: triangle %zu names a point beyond the %zu "
               "given", t, d->n);
      return -1;
    }
    if (geom_orient(d->p[v[0]], d->p[v[1]], d->p[v[2]]) <= 0) {
      snprintf(err, errlen, "delaunay certificate: triangle %zu (points %u, %u, %u) does not "
               "turn anticlockwise", t, v[0], v[1], v[2]);
      return -1;
    }
  }
  return 0;
}

/* Sorts v[0..k-1] ascending: insertion for the few edges of most points, qsort beyond. */
static void dtc_sort(uint64_t *v, size_t k) {
  if (k > 16) {
    qsort(v, k, sizeof *v, geom_u64_cmp);
    return;
  }
  for (size_t i = 1; i < k; i++) {
    uint64_t x = v[i];
    size_t j = i;
    for (; j > 0 && v[j - 1] > x; j--) v[j] = v[j - 1];
    v[j] = x;
  }
}

/* geom_csr_build's keys: a directed edge's tail, a triangle's cell. */
static size_t dtc_tail_key(const void *ctx, size_t h) { return dtc_tail(ctx, h); }
static size_t dtc_cell_key(const void *ctx, size_t t) { return ((const dtc *)ctx)->cell[t]; }

/* Outgoing edges of each point, sorted by head; an edge used twice in one direction means
** overlapping triangles; a point on no triangle is missing.  O(t) and the sorts. */
static int dtc_outgoing(dtc *d, char *err, size_t errlen) {
  size_t m = 3 * d->nt;
  uint32_t *by = malloc((m + 1) * sizeof *by);   /* the directed edges by tail */
  d->off = malloc((d->n + 1) * sizeof *d->off);
  d->out = malloc((m + 1) * sizeof *d->out);
  if (!by || !d->off || !d->out) return free(by), dtc_err(err, errlen, "out of memory");
  geom_csr_build(d->off, d->n, by, m, dtc_tail_key, d);
  for (size_t k = 0; k < m; k++) d->out[k] = (uint64_t)dtc_head(d, by[k]) << 32 | by[k];
  free(by);
  for (size_t v = 0; v < d->n; v++) {
    size_t a = d->off[v], b = d->off[v + 1];
    if (a == b) {
      snprintf(err, errlen, "delaunay certificate: point %zu is a vertex of no triangle", v);
      return -1;
    }
    dtc_sort(d->out + a, b - a);
    for (size_t k = a + 1; k < b; k++)
      if (d->out[k] >> 32 == d->out[k - 1] >> 32) {
        snprintf(err, errlen, "delaunay certificate: edge %zu -> %u is used by two triangles "
                 "on the same side: they overlap", v, (unsigned)(d->out[k] >> 32));
        return -1;
      }
  }
  return 0;
}

/* The directed edge u -> v, or DT_NONE: a binary search among u's outgoing edges. */
static uint32_t dtc_find(const dtc *d, uint32_t u, uint32_t v) {
  size_t lo = d->off[u], hi = d->off[u + 1];
  while (lo < hi) {
    size_t mid = lo + (hi - lo) / 2;
    uint32_t w = (uint32_t)(d->out[mid] >> 32);
    if (w == v) return (uint32_t)d->out[mid];
    if (w < v) lo = mid + 1;
    else hi = mid;
  }
  return DT_NONE;
}

/* Which half of the directions holds a -> b: 0 for angles in [0, pi), 1 for [pi, 2 pi).
** Exact: coordinates compared. */
static int dtc_half(geom_point a, geom_point b) {
  return b.y < a.y || (b.y == a.y && b.x < a.x);
}

/* The turn a -> b -> c of the boundary: 0 when left, or straight on (b strictly between a
** and c, compared by coordinates), else -1. */
static int dtc_turn_ok(geom_point a, geom_point b, geom_point c) {
  int o = geom_orient(a, b, c);
  if (o != 0) return o > 0 ? 0 : -1;
  int fwd = a.x != b.x ? (a.x < b.x) == (b.x < c.x) : (a.y < b.y) == (b.y < c.y);
  return fwd ? 0 : -1;
}

/* The unmatched edges: one cycle, left turns only, winding once.  O(h). */
static int dtc_boundary(dtc *d, uint32_t *bnext, char *err, size_t errlen) {
  size_t m = 3 * d->nt, start = m;
  for (size_t v = 0; v < d->n; v++) bnext[v] = DT_NONE;
  for (size_t h = 0; h < m; h++) {
    if (d->twin[h] != DT_NONE) continue;
    uint32_t a = dtc_tail(d, h);
    if (bnext[a] != DT_NONE) {
      snprintf(err, errlen, "delaunay certificate: point %u has two boundary edges leaving "
               "it: the triangles do not cover a convex region", a);
      return -1;
    }
    bnext[a] = (uint32_t)h, d->nbound++, start = start < h ? start : h;
  }
  if (start == m) return dtc_err(err, errlen, "the triangles have no boundary");
  size_t h = start, steps = 0, wind = 0;
  do {
    uint32_t a = dtc_tail(d, h), b = dtc_head(d, h), g = bnext[b];
    if (g == DT_NONE || ++steps > d->nbound)
      return dtc_err(err, errlen, "the boundary edges do not close into one cycle");
    uint32_t c = dtc_head(d, g);
    if (dtc_turn_ok(d->p[a], d->p[b], d->p[c]) != 0) {
      snprintf(err, errlen, "delaunay certificate: the boundary turns right or back at point "
               "%u: the triangles do not cover the convex hull", b);
      return -1;
    }
    wind += dtc_half(d->p[a], d->p[b]) == 1 && dtc_half(d->p[b], d->p[c]) == 0;
    h = g;
  } while (h != start);
  if (steps != d->nbound)
    return dtc_err(err, errlen, "the boundary edges form more than one cycle");
  if (wind != 1) return dtc_err(err, errlen, "the boundary winds round more than once");
  return 0;
}

/* Twins, the boundary, Euler's count and the in-circle test of every interior edge.  A
** cocircular edge (geom_incircle == 0) is marked in cocirc (per directed edge). */
static int dtc_certify(dtc *d, unsigned char *cocirc, char *err, size_t errlen) {
  size_t m = 3 * d->nt;
  uint32_t *bnext = malloc((d->n + 1) * sizeof *bnext);
  d->twin = malloc((m + 1) * sizeof *d->twin);
  if (!bnext || !d->twin) return free(bnext), dtc_err(err, errlen, "out of memory");
  for (size_t h = 0; h < m; h++) d->twin[h] = dtc_find(d, dtc_head(d, h), dtc_tail(d, h));
  int rc = dtc_boundary(d, bnext, err, errlen);
  free(bnext);
  if (rc == 0 && d->nt != 2 * d->n - d->nbound - 2) {
    snprintf(err, errlen, "delaunay certificate: %zu triangles, but a triangulation of %zu "
             "points with %zu on the hull has %zu", d->nt, d->n, d->nbound,
             2 * d->n - d->nbound - 2);
    rc = -1;
  }
  for (size_t h = 0; rc == 0 && h < m; h++) {
    uint32_t g = d->twin[h];
    cocirc[h] = g != DT_NONE && g < h && cocirc[g];   /* each edge tested once, at h < g */
    if (g == DT_NONE || g < h) continue;
    uint32_t a = dtc_tail(d, h), b = dtc_head(d, h), c = dtc_third(d, h), e = dtc_third(d, g);
    int s = geom_incircle(d->p[a], d->p[b], d->p[c], d->p[e]);
    if (s > 0) {
      snprintf(err, errlen, "delaunay certificate: edge %u-%u is not locally Delaunay (point "
               "%u is inside the circle of %u, %u, %u)", a, b, e, a, b, c);
      rc = -1;
    }
    cocirc[h] = s == 0;
  }
  return rc;
}

/* Cells: triangles joined across cocircular edges, numbered by their first triangle (a
** flood fill with a stack).  O(t). */
static int dtc_cells(dtc *d, const unsigned char *cocirc, size_t *ncell) {
  uint32_t *stack = malloc((d->nt + 1) * sizeof *stack);
  d->cell = malloc((d->nt + 1) * sizeof *d->cell);
  if (!stack || !d->cell) return free(stack), -1;
  for (size_t t = 0; t < d->nt; t++) d->cell[t] = DT_NONE;
  *ncell = 0;
  for (size_t t0 = 0; t0 < d->nt; t0++) {
    if (d->cell[t0] != DT_NONE) continue;
    size_t top = 0;
    d->cell[t0] = (uint32_t)*ncell, stack[top++] = (uint32_t)t0;
    while (top > 0) {
      uint32_t t = stack[--top];
      for (uint32_t h = 3 * t; h < 3 * t + 3; h++) {
        if (!cocirc[h] || d->cell[d->twin[h] / 3] != DT_NONE) continue;
        d->cell[d->twin[h] / 3] = (uint32_t)*ncell, stack[top++] = d->twin[h] / 3;
      }
    }
    (*ncell)++;
  }
  free(stack);
  return 0;
}

/* Appends edge ab with its state: two arrays grown by geom_grow's one rule from the same
** capacity, so they keep the same capacity. */
static int dtc_push(got_skel *s, size_t *cap, uint32_t a, uint32_t b, int state) {
  size_t c = *cap;
  if (geom_grow((void **)&s->edge, cap, s->nedges + 1, 2 * sizeof *s->edge) != 0 ||
      geom_grow((void **)&s->state, &c, s->nedges + 1, 1) != 0)
    return -1;
  s->edge[2 * s->nedges] = a < b ? a : b, s->edge[2 * s->nedges + 1] = a < b ? b : a;
  s->state[s->nedges++] = (unsigned char)state;
  return 0;
}

/* The diagonals of one cell (its triangles tl[0..k-1]) that are no edge of the given
** triangulation: POSSIBLE.  vs: room for the cell's points. */
static int dtc_cell_diagonals(const dtc *d, const uint32_t *tl, size_t k, uint32_t *vs,
                              uint32_t *stamp, got_skel *s, size_t *cap) {
  size_t nv = 0;
  for (size_t i = 0; i < k; i++)
    for (int j = 0; j < 3; j++) {
      uint32_t v = d->tri[3 * tl[i] + j];
      if (stamp[v] != tl[0] + 1) stamp[v] = tl[0] + 1, vs[nv++] = v;
    }
  for (size_t i = 0; i < nv; i++)
    for (size_t j = i + 1; j < nv; j++)
      if (dtc_find(d, vs[i], vs[j]) == DT_NONE && dtc_find(d, vs[j], vs[i]) == DT_NONE &&
          dtc_push(s, cap, vs[i], vs[j], GOT_EDGE_POSSIBLE) != 0)
        return -1;
  return 0;
}

/* The skeleton: each edge once, CERTAIN between cells and on the hull, POSSIBLE inside a
** cell; then the cells' other diagonals. */
static int dtc_output(const dtc *d, size_t ncell, got_skel *s) {
  size_t m = 3 * d->nt, cap = 0;
  for (size_t h = 0; h < m; h++) {
    uint32_t g = d->twin[h];
    if (g != DT_NONE && g < h) continue;
    int inside = g != DT_NONE && d->cell[g / 3] == d->cell[h / 3];
    if (dtc_push(s, &cap, dtc_tail(d, h), dtc_head(d, h),
                 inside ? GOT_EDGE_POSSIBLE : GOT_EDGE_CERTAIN) != 0)
      return -1;
  }
  uint32_t *coff = malloc((ncell + 1) * sizeof *coff);   /* the triangles by cell */
  uint32_t *tl = malloc((d->nt + 1) * sizeof *tl), *vs = malloc((d->nt + 3) * sizeof *vs);
  uint32_t *stamp = calloc(d->n + 1, sizeof *stamp);
  int rc = coff && tl && vs && stamp ? 0 : -1;
  if (rc == 0) geom_csr_build(coff, ncell, tl, d->nt, dtc_cell_key, d);
  for (size_t c = 0; rc == 0 && c < ncell; c++)
    if (coff[c + 1] - coff[c] > 1)
      rc = dtc_cell_diagonals(d, tl + coff[c], coff[c + 1] - coff[c], vs, stamp, s, &cap);
  free(coff), free(tl), free(vs), free(stamp);
  return rc;
}

int got_skel_delaunay(const geom_point *p, size_t n, const uint32_t *tri, size_t ntri,
                      got_skel *out, char *err, size_t errlen) {
  memset(out, 0, sizeof *out);
  out->n = n;
  if (n < 3 || n > UINT32_MAX / 8 || ntri == 0 || ntri > UINT32_MAX / 4)
    return dtc_err(err, errlen, "no triangles, or too many points or triangles");
  double t0 = omp_get_wtime();
  dtc d = {.p = p, .n = n, .nt = ntri, .tri = tri};
  unsigned char *cocirc = malloc(3 * ntri + 1);
  size_t ncell = 0;
  int rc = cocirc ? 0 : dtc_err(err, errlen, "out of memory");
  if (rc == 0) rc = dtc_triangles(&d, err, errlen);
  if (rc == 0) rc = dtc_outgoing(&d, err, errlen);
  if (rc == 0) rc = dtc_certify(&d, cocirc, err, errlen);
  if (rc == 0 && (dtc_cells(&d, cocirc, &ncell) != 0 || dtc_output(&d, ncell, out) != 0))
    rc = dtc_err(err, errlen, "out of memory");
  free(cocirc);
  dtc_free(&d);
  out->candidates = out->nedges;
  out->seconds_candidates = omp_get_wtime() - t0;
  if (rc != 0) got_skel_free(out);
  return rc;
}
