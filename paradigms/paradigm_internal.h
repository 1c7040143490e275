/*
** paradigm_internal.h: the algorithms the registry of paradigm.c lists,
** one paradigm_fn each (private to paradigms/).  A new algorithm adds its
** function here and its row to paradigm_algorithms in paradigm.c.
*/
#ifndef FLIPLAB_PARADIGM_INTERNAL_H
#define FLIPLAB_PARADIGM_INTERNAL_H

#include "lot.h"
#include "paradigm.h"

/* lot/'s algorithms as rows (paradigms/lot_rows.c). */
FLIPLAB_INTERNAL
int paradigm_lot_incremental(const paradigm_input *in, paradigm_output *out, char *err,
                             size_t errlen);
FLIPLAB_INTERNAL
int paradigm_lot_flip(const paradigm_input *in, paradigm_output *out, char *err,
                      size_t errlen);
FLIPLAB_INTERNAL
int paradigm_lot_sweep(const paradigm_input *in, paradigm_output *out, char *err,
                       size_t errlen);

/* lot's triangles into out and L freed (paradigms/lot_rows.c), or -1 with a
** one-line message when L did not converge (the flip budget ran out) or
** memory ran out; L is freed either way. */
FLIPLAB_INTERNAL
int paradigm_lot_take(lot *L, paradigm_output *out, char *err, size_t errlen);

/* The rule's in-shape decision for the registry's in-shape algorithms: for
** anticlockwise a, b, c, +1 when d lies strictly inside the rule's empty
** region through a, b, c (the circumcircle for DT, the circumscribing
** homothet for ES:SHAPE), -1 strictly outside, 0 on it (then the rule's
** tie-break decides, as lot/ does).  Counted as OPS_INCIRCLE or
** OPS_INSHAPE. */
FLIPLAB_INTERNAL
int paradigm_inshape(const rule *r, ops_counts *c, geom_point a, geom_point b, geom_point d,
                     geom_point e);

/* The order of the regions through a and b on the left of ab: for c and d
** strictly left of ab, 1 when d lies strictly inside the rule's region
** through a, b, c (lot's tie-break included), which is a strict order there
** (docs/paradigms.md, "Selection").  Counted as paradigm_inshape, with the
** orientation tests ES needs to place c and d. */
FLIPLAB_INTERNAL
int paradigm_beats(const rule *r, ops_counts *c, geom_point a, geom_point b, geom_point pc,
                   geom_point d);
/* 1 when q (not a, b or c) lies strictly inside the rule's region through
** anticlockwise a, b, c: paradigm_beats from a side q lies left of. */
FLIPLAB_INTERNAL
int paradigm_inregion(const rule *r, ops_counts *c, geom_point a, geom_point b,
                      geom_point pc, geom_point q);

/* Divide and conquer (paradigms/divide.c), Guibas and Stolfi's merge with
** vertical or alternating cuts; paradigm_divide counts into c (NULL: not
** counting, for the benchmark of the counting layer's cost). */
FLIPLAB_INTERNAL
int paradigm_divide(const paradigm_input *in, int alternating, ops_counts *c,
                    paradigm_output *out, char *err, size_t errlen);
FLIPLAB_INTERNAL
int paradigm_dc_vertical(const paradigm_input *in, paradigm_output *out, char *err,
                         size_t errlen);
FLIPLAB_INTERNAL
int paradigm_dc_alternating(const paradigm_input *in, paradigm_output *out, char *err,
                            size_t errlen);
#define PARADIGM_DC_REFUSAL \
  "constraints: the row dc-constrained (2.6.2); simple and convex polygons: " \
  "dc-polygon (2.6.3)"
/* 2.6.2 (paradigms/divide_constrained.c): pieces, each with its own
** segments, merged by Guibas and Stolfi's zipper; the segments joining two
** pieces inserted there by flips. */
FLIPLAB_INTERNAL
int paradigm_dc_constrained(const paradigm_input *in, paradigm_output *out, char *err,
                            size_t errlen);
/* 2.6.3 (paradigms/divide_polygon.c): a simple or convex polygon split at a
** diagonal with n/3 vertices on each side, the sides merged by flips. */
FLIPLAB_INTERNAL
int paradigm_dc_polygon(const paradigm_input *in, paradigm_output *out, char *err,
                        size_t errlen);
/* The selection algorithms of 2.4 (paradigms/select.c): the boundary of
** unfinished edges as a stack or a queue, and the apex search by a scan of
** every site, an x-sorted strip, or a bucket grid; with constraints. */
FLIPLAB_INTERNAL int paradigm_select_stack(const paradigm_input *in, paradigm_output *out,
                                           char *err, size_t errlen);
FLIPLAB_INTERNAL int paradigm_select_queue(const paradigm_input *in, paradigm_output *out,
                                           char *err, size_t errlen);
FLIPLAB_INTERNAL int paradigm_select_strip(const paradigm_input *in, paradigm_output *out,
                                           char *err, size_t errlen);
FLIPLAB_INTERNAL int paradigm_select_buckets(const paradigm_input *in, paradigm_output *out,
                                             char *err, size_t errlen);
/* 2.4.2: the stack and the scan, each apex seen across no constraint. */
FLIPLAB_INTERNAL int paradigm_select_constrained(const paradigm_input *in, paradigm_output *out,
                                                 char *err, size_t errlen);

/* How a selection run keeps its boundary and searches for an apex. */
typedef enum paradigm_select_order { PARADIGM_SELECT_STACK, PARADIGM_SELECT_QUEUE }
  paradigm_select_order;
typedef enum paradigm_select_search {
  PARADIGM_SELECT_SCAN, PARADIGM_SELECT_STRIP, PARADIGM_SELECT_BUCKETS
} paradigm_select_search;

/* What figures 2.9-2.11 and the bucket count of 2.4.1 measure: the
** boundary's size after each triangle (its mean) and its peak, the hull's
** sites, the grid's buckets; and the sites the apex searches tried. */
typedef struct paradigm_select_stats {
  double mean_boundary;
  size_t peak_boundary;
  size_t hull;
  size_t buckets;
  uint64_t examined;
} paradigm_select_stats;

/* One selection run on distinct points (as the runner hands them over),
** with in->segments when in->problem is PARADIGM_CONSTRAINED; st may be
** NULL.  0, or -1 with a one-line message (out of memory, a bucket size
** out of range, crossing segments, a segment from a point to itself). */
FLIPLAB_INTERNAL int paradigm_select_run(const paradigm_input *in, paradigm_select_order order,
                                         paradigm_select_search search, paradigm_output *out,
                                         paradigm_select_stats *st, char *err, size_t errlen);
/* The incremental variants of 2.3 (paradigms/incremental.c): lot's
** insertion in the bucket orders of figure 2.8; Watson's cavity insertion
** located by a walk, and by the history DAG. */
FLIPLAB_INTERNAL
int paradigm_incr_serpentine(const paradigm_input *in, paradigm_output *out, char *err,
                             size_t errlen);
FLIPLAB_INTERNAL
int paradigm_incr_spiral(const paradigm_input *in, paradigm_output *out, char *err,
                         size_t errlen);
FLIPLAB_INTERNAL
int paradigm_incr_quaternary(const paradigm_input *in, paradigm_output *out, char *err,
                             size_t errlen);
FLIPLAB_INTERNAL
int paradigm_watson(const paradigm_input *in, paradigm_output *out, char *err, size_t errlen);
FLIPLAB_INTERNAL
int paradigm_incr_dag(const paradigm_input *in, paradigm_output *out, char *err,
                      size_t errlen);

/* The simple polygon problem (paradigms/polygon_rows.c): the polygon
** checked and its sides as segments (*ccw its orientation); out's triangles
** outside it dropped; select-constrained serving it too. */
FLIPLAB_INTERNAL int paradigm_polygon_sides(const paradigm_input *in, uint32_t **seg, int *ccw,
                                            char *err, size_t errlen);
FLIPLAB_INTERNAL int paradigm_polygon_inside(paradigm_output *out, size_t n, int ccw, char *err,
                                             size_t errlen);
FLIPLAB_INTERNAL int paradigm_select_polygon(const paradigm_input *in, paradigm_output *out,
                                             char *err, size_t errlen);
/* The constrained sweepline of 2.5.2 (paradigms/sweep_constrained.c) and
** its monotone-polygon form of 2.5.4 (paradigms/sweep_monotone.c), DT only.
** paradigm_sweep_run serves both: monotone 1 refuses a polygon that is not
** x-monotone; *pockets (may be NULL) counts the pockets closed with sites
** in them.  paradigm_polygon_kind: a convex polygon as the convex rows
** check it, or with monotone an x-monotone one; 0 or -1 naming the vertex.
** paradigm_sweep_finish: the sweep's ntri triangles checked to be a
** triangulation of the hull, then Lawson's flips with paradigm_inshape over
** every edge but the ncons pieces cons (2 per piece): lot's tie-broken
** triangulation; 0, or -1 with a one-line message. */
FLIPLAB_INTERNAL int paradigm_sweep_constrained(const paradigm_input *in, paradigm_output *out,
                                                char *err, size_t errlen);
FLIPLAB_INTERNAL int paradigm_sweep_monotone(const paradigm_input *in, paradigm_output *out,
                                             char *err, size_t errlen);
FLIPLAB_INTERNAL int paradigm_sweep_run(const paradigm_input *in, int monotone,
                                        paradigm_output *out, size_t *pockets, char *err,
                                        size_t errlen);
FLIPLAB_INTERNAL int paradigm_polygon_kind(const paradigm_input *in, int monotone, char *err,
                                           size_t errlen);
FLIPLAB_INTERNAL int paradigm_sweep_finish(const paradigm_input *in, uint32_t *tri, size_t ntri,
                                           const uint32_t *cons, size_t ncons, ops_counts *c,
                                           char *err, size_t errlen);
#define PARADIGM_SWEEP_REFUSAL \
  "DT only: the breakpoints and the unmodified-circle argument are the circle's; a " \
  "polygon's homothets are neither smooth nor strictly convex (2.5.6)"
/* Chapter 5's convex polygon algorithms (paradigms/convex_rows.c), one per
** cpdt_algorithm. */
#define PARADIGM_CONVEX_FN(fn) \
  FLIPLAB_INTERNAL int fn(const paradigm_input *in, paradigm_output *out, char *err, \
                          size_t errlen);
PARADIGM_CONVEX_FN(paradigm_convex_circum)
PARADIGM_CONVEX_FN(paradigm_convex_circum_random)
PARADIGM_CONVEX_FN(paradigm_convex_circum_walk)
PARADIGM_CONVEX_FN(paradigm_convex_divide)
PARADIGM_CONVEX_FN(paradigm_convex_incremental)
PARADIGM_CONVEX_FN(paradigm_convex_random)
PARADIGM_CONVEX_FN(paradigm_convex_flip)
PARADIGM_CONVEX_FN(paradigm_convex_corners)

/* The half-edge mesh of the divide-and-conquer rows (divide.c,
** divide_constrained.c): half-edges 2k and 2k + 1 are one edge's two
** directions, each on the ring of its origin's half-edges in anticlockwise
** order (next, prev), so Lnext(e) = Oprev(Sym e) and Rprev(e) = Onext(Sym
** e); Guibas and Stolfi's splice swaps two ring successors (the faces
** follow: no face records). */
typedef struct paradigm_half {
  uint32_t next, prev;    /* the origin's ring, anticlockwise */
  uint32_t org;           /* origin site */
} paradigm_half;

static inline uint32_t paradigm_he_dest(const paradigm_half *h, uint32_t e) {
  return h[e ^ 1].org;
}

static inline uint32_t paradigm_he_lnext(const paradigm_half *h, uint32_t e) {
  return h[e ^ 1].prev;
}

static inline uint32_t paradigm_he_rprev(const paradigm_half *h, uint32_t e) {
  return h[e ^ 1].next;
}

static inline void paradigm_he_splice(paradigm_half *h, uint32_t a, uint32_t b) {
  uint32_t alpha = h[a].next, beta = h[b].next;
  h[a].next = beta, h[b].next = alpha;
  h[beta].prev = a, h[alpha].prev = b;
}

/* u before v in the frame of a cut: (x, y) for a vertical cut, (y, -x)
** for a horizontal one (the frame turned a quarter clockwise). */
static inline int paradigm_frame_before(geom_point u, geom_point v, int frame) {
  if (frame == 0) return (u.x < v.x) | ((u.x == v.x) & (u.y < v.y));   /* no branches: */
  return (u.y < v.y) | ((u.y == v.y) & (u.x > v.x));   /* the partitions' answers are coins */
}

/* From ccw hull edge e of a mesh of sites s, the ccw hull edge out of the
** first (last) site of the frame: the order is unimodal along a convex
** hull, so walk the way it improves.  O(hull). */
static inline uint32_t paradigm_he_extreme(const paradigm_half *h, const geom_point *s,
                                           uint32_t e, int frame, int last) {
#define PARADIGM_BETTER(u, v) \
  (last ? paradigm_frame_before(s[v], s[u], frame) : paradigm_frame_before(s[u], s[v], frame))
  while (PARADIGM_BETTER(paradigm_he_dest(h, e), h[e].org)) e = paradigm_he_rprev(h, e);
  for (uint32_t b = h[e].prev ^ 1; PARADIGM_BETTER(h[b].org, h[e].org); b = h[e].prev ^ 1)
    e = b;
#undef PARADIGM_BETTER
  return e;
}

/* The triangle meshes of the rows that flip edges (sweep_finish.c, divide_polygon.c):
** nb[3 t + k] is the triangle across the side of t opposite its corner k, -1 outside.
** The corner of triangle u whose side borders triangle t, or -1 when none does. */
static inline int paradigm_nb_corner(const int32_t *nb, size_t u, size_t t) {
  for (int k = 0; k < 3; k++)
    if (nb[3 * u + (size_t)k] == (int32_t)t) return k;
  return -1;
}

/* Neighbour x's link to triangle `from` pointed at `to` instead (x < 0: the outside). */
static inline void paradigm_nb_relink(int32_t *nb, int32_t x, size_t from, size_t to) {
  if (x >= 0) nb[3 * (size_t)x + (size_t)paradigm_nb_corner(nb, (size_t)x, from)] = (int32_t)to;
}

#endif
