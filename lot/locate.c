/*
** locate.c: exact point location in a triangulation given as a triangle
** list and its neighbours (lot_locate, lot.h): for every query point the
** index of a triangle holding it, or -1, as scipy.spatial.Delaunay's
** find_simplex answers, but decided by geom_orient (exact) instead of a
** tolerance.
**
** How.  The queries are put in a spatial order (lot_order_spatial: Hilbert
** curve rounds) and each walks from the triangle where the previous one
** stopped: the remembering stochastic walk (Devillers, Pion and Teillaud,
** Walking in a triangulation, 2002): from triangle t, the edges are tried
** from a random one, the edge just crossed skipped, and the walk crosses
** the first edge that has q strictly on its other side; when none has, t
** holds q.  The random start is what ends the walk in any triangulation (a
** fixed order can cycle in one that is not Delaunay, and a LOT of another
** rule is not), and the generator is seeded, so every run is the same.
**
** Fallbacks.  A walk that reaches a boundary edge with q beyond it proves q
** outside only when the triangles cover their convex hull
** (LOT_LOCATE_CONVEX: an unconstrained run, or one that removed nothing);
** otherwise (holes, a non-convex region) the triangles are scanned.  A walk
** longer than the number of triangles is also given up for the scan.
**
** The answer does not depend on the walk: a point inside a triangle has
** one, a point on an edge gets the smaller of its two triangles, a point on
** a vertex the smallest triangle incident to the vertex (vmin, made on the
** first such query), and the scan returns the smallest triangle holding
** the point.  Non-finite queries get -1.
*/
#include <stdint.h>
#include <stdlib.h>
#include "lot.h"
#include "order.h"
#include "splitmix.h"

/* Queries ordered and walked per block, whose indices fit lot_order_spatial. */
#define LOT_LOCATE_BLOCK ((size_t)1 << 24)

typedef struct lot_loc {
  const geom_point *p;
  const uint32_t *tri;
  const int32_t *nb;
  size_t n, ntri;
  int flags;
  int32_t *vmin;        /* per vertex, the smallest triangle holding it; NULL until needed */
  uint64_t rng;         /* the walk's generator state */
} lot_loc;

/* The side of q to the edge of triangle t opposite its vertex k: +1 on t's
** side (the edge runs anticlockwise), 0 on the edge's line, -1 beyond it. */
static int lot_loc_side(const lot_loc *X, size_t t, int k, geom_point q) {
  const uint32_t *v = X->tri + 3 * t;
  return geom_orient(X->p[v[(k + 1) % 3]], X->p[v[(k + 2) % 3]], q);
}

/* The edge of triangle u shared with t (its index 0..2), -1 if none. */
static int lot_loc_back(const lot_loc *X, size_t u, size_t t) {
  for (int k = 0; k < 3; k++)
    if (X->nb[3 * u + (size_t)k] == (int32_t)t) return k;
  return -1;
}

/* Walk from *tp towards q: 1 when *tp holds q (closed), 0 when the walk
** left through a boundary edge of *tp with q beyond it, -1 when it took
** more steps than there are triangles.  O(triangles crossed). */
static int lot_loc_walk(lot_loc *X, size_t *tp, geom_point q) {
  size_t t = *tp;
  int came = -1;
  for (size_t step = 0; step <= X->ntri; step++) {
    int k0 = (int)(geom_splitmix64(&X->rng) % 3), k = 0, beyond = 0;
    for (int j = 0; j < 3 && !beyond; j++) {
      k = (k0 + j) % 3;
      beyond = k != came && lot_loc_side(X, t, k, q) < 0;
    }
    *tp = t;
    if (!beyond) return 1;
    int32_t u = X->nb[3 * t + (size_t)k];
    if (u < 0) return 0;
    came = lot_loc_back(X, (size_t)u, t);
    t = (size_t)u;
  }
  return -1;
}

/* The smallest triangle holding q, or -1: every triangle tried, O(ntri). */
static int32_t lot_loc_scan(const lot_loc *X, geom_point q) {
  for (size_t t = 0; t < X->ntri; t++)
    if (lot_loc_side(X, t, 0, q) >= 0 && lot_loc_side(X, t, 1, q) >= 0
        && lot_loc_side(X, t, 2, q) >= 0)
      return (int32_t)t;
  return -1;
}

/* vmin[v]: the smallest triangle with vertex v.  O(n + ntri); 0 or -1. */
static int lot_loc_vmin(lot_loc *X) {
  X->vmin = malloc((X->n ? X->n : 1) * sizeof *X->vmin);
  if (X->vmin == NULL) return -1;
  for (size_t v = 0; v < X->n; v++) X->vmin[v] = -1;
  for (size_t t = X->ntri; t > 0; t--)   /* downwards: the smallest writes last */
    for (int k = 0; k < 3; k++) X->vmin[X->tri[3 * (t - 1) + (size_t)k]] = (int32_t)(t - 1);
  return 0;
}

/* Triangle t holds q: the smallest triangle that does (t alone inside it,
** t and its neighbour on an edge, the vertex's smallest on a vertex);
** -2 when vmin cannot be made (out of memory). */
static int32_t lot_loc_canonical(lot_loc *X, size_t t, geom_point q) {
  int zeros = 0, kz[3] = {0, 0, 0};
  for (int k = 0; k < 3; k++)
    if (lot_loc_side(X, t, k, q) == 0) kz[zeros++] = k;
  if (zeros == 0) return (int32_t)t;
  if (zeros == 1) {
    int32_t u = X->nb[3 * t + (size_t)kz[0]];
    return u >= 0 && (size_t)u < t ? u : (int32_t)t;
  }
  if (X->vmin == NULL && lot_loc_vmin(X) != 0) return -2;
  return X->vmin[X->tri[3 * t + (size_t)(3 - kz[0] - kz[1])]];   /* the edges' common vertex */
}

/* One query from the walk's current triangle *t; -2 out of memory. */
static int32_t lot_loc_one(lot_loc *X, size_t *t, geom_point q) {
  if (!geom_point_finite(q)) return -1;
  if (X->flags & LOT_LOCATE_SCAN) return lot_loc_scan(X, q);
  int w = lot_loc_walk(X, t, q);
  if (w == 1) return lot_loc_canonical(X, *t, q);
  if (w == 0 && (X->flags & LOT_LOCATE_CONVEX)) return -1;
  return lot_loc_scan(X, q);
}

/* A block of queries q[0 .. k-1] walked in spatial order.  The order is
** made on a copy whose non-finite points stand at the first finite one
** (they are answered -1 wherever they stand); without memory for it the
** block is walked in input order: the answers are the same, only slower. */
static int lot_loc_block(lot_loc *X, size_t *t, const geom_point *q, uint32_t k,
                         int32_t *out) {
  uint32_t *ord = malloc((k ? k : 1) * sizeof *ord);
  geom_point *qq = malloc((k ? k : 1) * sizeof *qq);
  int ordered = ord != NULL && qq != NULL && k > 1;
  geom_point stand = {0, 0};
  for (uint32_t i = k; ordered && i > 0; i--)
    if (geom_point_finite(q[i - 1])) stand = q[i - 1];
  for (uint32_t i = 0; ordered && i < k; i++) qq[i] = geom_point_finite(q[i]) ? q[i] : stand;
  ordered = ordered && lot_order_spatial(qq, k, 1, ord) == 0;
  free(qq);
  int rc = 0;
  for (uint32_t i = 0; i < k && rc == 0; i++) {
    uint32_t j = ordered ? ord[i] : i;
    out[j] = lot_loc_one(X, t, q[j]);
    rc = out[j] == -2 ? -1 : 0;
  }
  free(ord);
  return rc;
}

int lot_locate(const geom_point *p, size_t n, const uint32_t *tri, const int32_t *nb,
               size_t ntri, int flags, const geom_point *q, size_t nq, int32_t *out) {
  lot_loc X = {p, tri, nb, n, ntri, flags, NULL, 0x6c6f636174650000ull};
  size_t t = ntri / 2;
  int rc = 0;
  if (ntri == 0) flags |= LOT_LOCATE_SCAN;   /* every answer -1, no walk */
  X.flags = flags;
  for (size_t b = 0; b < nq && rc == 0; b += LOT_LOCATE_BLOCK) {
    size_t k = nq - b < LOT_LOCATE_BLOCK ? nq - b : LOT_LOCATE_BLOCK;
    rc = lot_loc_block(&X, &t, q + b, (uint32_t)k, out + b);
  }
  free(X.vmin);
  return rc;
}
