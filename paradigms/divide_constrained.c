/*
** divide_constrained.c: the row dc-constrained, divide and conquer for the
** constrained Delaunay triangulation (section 2.6.2).
**
** The sites are cut at the middle rank, recursively: by vertical cuts
** (parameter 1: Chew's strips) or by cuts alternating between vertical and
** horizontal (0, the default: Dwyer's, whose pieces stay square).  A cut
** between ranks k - 1 and k of its frame's order is a line turned by an
** infinitesimal angle, so equal coordinates need no case of their own.  A
** piece's triangulation is the constrained Delaunay triangulation of its
** sites with the segments that have both ends in it (a site on a segment
** ranks between its ends in any frame, so it is in the piece too).  Two
** pieces, L before R in the frame of their cut, are merged in three steps:
**
**   1. Guibas and Stolfi's zipper from the lower common tangent, with two
**      changes in its candidates (dcc_candidate): a segment is never
**      deleted, and an edge is deleted only when the face beyond it is a
**      triangle.  No segment crosses the cut, so the union's triangulation
**      crosses it in a chain of triangles, and its edges inside L are edges
**      of L's; the zipper finds that chain (docs/paradigms.md argues it).
**   2. Lawson's check of every edge of every triangle the zipper made, with
**      lot's in-circle test (paradigm_inshape: its tie-break a symbolic
**      perturbation of the lifts), flipping strictly convex quadrilaterals
**      only.  It flips nothing on every set tested; it makes the union's
**      triangulation locally constrained Delaunay whatever step 1 did.
**   3. The segments joining L to R, each inserted by flips as Sloan does:
**      the edges it crosses are queued; one whose quadrilateral is strictly
**      convex is flipped, and queued again while its new diagonal still
**      crosses the segment (Sloan proves this ends); a site on the segment
**      ends a piece there.  Lawson's flips then run from every edge the
**      insertion rewrote.  An edge it crosses that is a segment is a
**      crossing: refused, naming both.
**
** Every edge off Lawson's stack is locally Delaunay or a segment (an edge
** whose triangles did not change stays so), and the result is certified a
** triangulation (dcc_triangles), so it is the constrained Delaunay
** triangulation, unique under the perturbation: lot's exactly, grids and
** cocircular sets included.  A certificate that fails is reported as a bug.
**
** What is not as Chew has it.  Chew keeps in each strip also the segments
** that cross it (the regions they cut, and virtual sites where they cross
** the strip's borders, infinitely far for the in-circle tests), so that a
** merge zips each pair of facing regions and inserts nothing.  Here a
** piece sees only its own segments; those joining two pieces are inserted
** by flips at their merge.  docs/paradigms.md says what the virtual sites
** need.
**
** Cost.  The cuts, O(n log n) expected (a selection a level); log n levels
** of merges, each linear in the edges the zipper makes and deletes (as
** Guibas and Stolfi's), with Lawson's check of them; each segment inserted
** once, at the merge of the pieces of its two ends, in O(k) flips for k
** crossed edges when they come convex (Sloan's queue can take O(k^2)), with
** Lawson's flips after it.  Memory: 12 bytes a half-edge, 6n of them, 36 a
** site for the sites, ranks and marks, and the segments' buckets.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "geom_key_internal.h"
#include "geom_mem_internal.h"
#include "paradigm_internal.h"
#include "splitmix.h"

#define DCC_NONE UINT32_MAX
#define DCC_FREE INT32_MIN    /* con[]: no segment on this edge */

typedef struct dcc_run {
  geom_point *s;          /* the sites, in the order of the cuts */
  uint32_t *id;           /* s[k] = in->p[id[k]] */
  uint32_t *pos;          /* pos[id[k]] = k */
  paradigm_half *h;       /* 2 per edge; at most 3n edges */
  int32_t *con;           /* per edge: the segment on it, or DCC_FREE */
  uint32_t *out;          /* a half-edge out of each site */
  uint32_t nedges, free;   /* edges made; a deleted one to reuse (DCC_NONE: none) */
  uint32_t *at, *list;    /* the segments of each merge (by key, dcc_key) */
  uint32_t *stack;        /* Lawson's edges to check */
  size_t top, scap;
  uint32_t *queue;        /* Sloan's crossed edges, in the order they wait */
  size_t qcap;
  const paradigm_input *in;
  int alternating;        /* cuts alternate vertical and horizontal (Dwyer) */
  ops_counts *c;
  char *err;
  size_t errlen;
} dcc_run;

typedef struct dcc_hull {
  uint32_t l, r;          /* ccw hull edge out of the leftmost site, cw out of the rightmost */
} dcc_hull;

static inline geom_point dcc_p(const dcc_run *R, uint32_t v) {
  return R->s[v];
}

static inline uint32_t dcc_dest(const dcc_run *R, uint32_t e) {
  return paradigm_he_dest(R->h, e);
}

static uint32_t dcc_make_edge(dcc_run *R, uint32_t a, uint32_t b) {
  paradigm_half *h = R->h;
  uint32_t e = R->free;
  if (e != DCC_NONE) R->free = h[e].next;
  else e = 2 * R->nedges++;
  h[e] = (paradigm_half){e, e, a};
  h[e + 1] = (paradigm_half){e + 1, e + 1, b};
  R->con[e / 2] = DCC_FREE;
  R->out[a] = e, R->out[b] = e + 1;
  ops_add(R->c, OPS_EDGES_MADE, 1);
  return e;
}

/* A new edge from Dest(a) to Org(b), a's left face split off by it. */
static uint32_t dcc_connect(dcc_run *R, uint32_t a, uint32_t b) {
  uint32_t e = dcc_make_edge(R, dcc_dest(R, a), R->h[b].org);
  paradigm_he_splice(R->h, e, paradigm_he_lnext(R->h, a));
  paradigm_he_splice(R->h, e ^ 1, b);
  return e;
}

/* Edge e out of both rings (each end keeps another edge), its origins
** DCC_NONE, onto the free list. */
static void dcc_delete(dcc_run *R, uint32_t e) {
  paradigm_half *h = R->h;
  uint32_t a = h[e].org, b = paradigm_he_dest(h, e);
  if (R->out[a] == e) R->out[a] = h[e].next;
  if (R->out[b] == (e ^ 1)) R->out[b] = h[e ^ 1].next;
  paradigm_he_splice(h, e, h[e].prev);
  paradigm_he_splice(h, e ^ 1, h[e ^ 1].prev);
  h[e].org = h[e ^ 1].org = DCC_NONE;
  h[e & ~1u].next = R->free, R->free = e & ~1u;
  ops_add(R->c, OPS_EDGES_DELETED, 1);
}

/* Edge e (a -> b, triangles a b c on its left and b a d on its right)
** becomes d -> c (Guibas and Stolfi's swap on the origin rings). */
static void dcc_flip(dcc_run *R, uint32_t e) {
  paradigm_half *h = R->h;
  uint32_t a = h[e].prev, b = h[e ^ 1].prev;   /* a -> d, b -> c */
  paradigm_he_splice(h, e, a);
  paradigm_he_splice(h, e ^ 1, b);
  paradigm_he_splice(h, e, paradigm_he_lnext(h, a));
  paradigm_he_splice(h, e ^ 1, paradigm_he_lnext(h, b));
  R->out[h[a].org] = a, R->out[h[b].org] = b;
  h[e].org = dcc_dest(R, a), h[e ^ 1].org = dcc_dest(R, b);
  ops_add(R->c, OPS_FLIPS, 1);
  ops_add(R->c, OPS_EDGES_MADE, 1);
  ops_add(R->c, OPS_EDGES_DELETED, 1);
}

static int dcc_orient(dcc_run *R, uint32_t a, uint32_t b, uint32_t d) {
  return ops_orient(R->c, dcc_p(R, a), dcc_p(R, b), dcc_p(R, d));
}

/* Site x strictly right of (left of) the directed edge e. */
static int dcc_right_of(dcc_run *R, uint32_t x, uint32_t e) {
  return dcc_orient(R, x, dcc_dest(R, e), R->h[e].org) > 0;
}

static int dcc_left_of(dcc_run *R, uint32_t x, uint32_t e) {
  return dcc_orient(R, x, R->h[e].org, dcc_dest(R, e)) > 0;
}

/* d strictly inside the circle through anticlockwise a, b, c: lot's test. */
static int dcc_incircle(dcc_run *R, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  return paradigm_inshape(R->in->r, R->c, dcc_p(R, a), dcc_p(R, b), dcc_p(R, c),
                          dcc_p(R, d)) > 0;
}

static int dcc_push(dcc_run *R, uint32_t e) {
  size_t old = R->scap;
  if (geom_grow((void **)&R->stack, &R->scap, R->top + 1, sizeof *R->stack) != 0) return -1;
  ops_memory(R->c, (int64_t)((R->scap - old) * sizeof *R->stack));
  R->stack[R->top++] = e >> 1;
  return 0;
}

/* The apex of the face left of e when that face is a triangle (three
** half-edges round), else DCC_NONE; the outer face of a three-site hull
** is a round of three too, told apart by the flip's orientation tests. */
static uint32_t dcc_apex(const dcc_run *R, uint32_t e) {
  const paradigm_half *h = R->h;
  uint32_t l1 = paradigm_he_lnext(h, e), l2 = paradigm_he_lnext(h, l1);
  return paradigm_he_lnext(h, l2) == e ? h[l2].org : DCC_NONE;
}

/* Flip edge e (a -> b) when it is no segment, both its faces are
** triangles a b c and b a d, and d lies strictly inside the circle of a b
** c: then the quadrilateral is strictly convex (the two orientation tests
** only tell a hull's outer round of three from a triangle); the four
** sides are pushed.  0, or -1 out of memory. */
static int dcc_check(dcc_run *R, uint32_t e) {
  if (R->h[e].org == DCC_NONE) return 0;   /* deleted since it was pushed */
  uint32_t a = R->h[e].org, b = dcc_dest(R, e), c = dcc_apex(R, e), d = dcc_apex(R, e ^ 1);
  if (R->con[e / 2] != DCC_FREE || c == DCC_NONE || d == DCC_NONE) return 0;
  if (!dcc_incircle(R, a, b, c, d)) return 0;
  if (dcc_orient(R, a, b, c) <= 0 || dcc_orient(R, b, a, d) <= 0) return 0;
  const paradigm_half *h = R->h;
  uint32_t l1 = paradigm_he_lnext(h, e), r1 = paradigm_he_lnext(h, e ^ 1);
  uint32_t l2 = paradigm_he_lnext(h, l1), r2 = paradigm_he_lnext(h, r1);
  dcc_flip(R, e);
  return dcc_push(R, l1) || dcc_push(R, l2) || dcc_push(R, r1) || dcc_push(R, r2) ? -1 : 0;
}

/* Lawson's flips until the stack is empty.  0, or -1 out of memory. */
static int dcc_lawson(dcc_run *R) {
  while (R->top > 0)
    if (dcc_check(R, 2 * R->stack[--R->top]) != 0) return -1;
  return 0;
}

/* Two or three sites, lexicographically sorted. */
static dcc_hull dcc_base(dcc_run *R, uint32_t lo, uint32_t n) {
  uint32_t a = dcc_make_edge(R, lo, lo + 1);
  if (n == 2) return (dcc_hull){a, a ^ 1};
  uint32_t b = dcc_make_edge(R, lo + 1, lo + 2);
  paradigm_he_splice(R->h, a ^ 1, b);
  int o = dcc_orient(R, lo, lo + 1, lo + 2);
  if (o > 0) {
    dcc_connect(R, b, a);
    return (dcc_hull){a, b ^ 1};
  }
  if (o < 0) {
    uint32_t t = dcc_connect(R, b, a);
    return (dcc_hull){t ^ 1, t};
  }
  return (dcc_hull){a, b ^ 1};
}

/* The left (right) candidate of basel: Guibas and Stolfi's, with two
** changes.  The first neighbour of basel's left (right) end anticlockwise
** (clockwise) from basel and above it; while the next neighbour lies inside
** the circle through basel and it, their edge is deleted, but only when it
** is no segment and the face between the two edges is a triangle: then the
** next neighbour is seen from the edge through that triangle, and basel's
** far end from its points near basel, so every circle through the edge
** holds a site seen from it and the union's triangulation has no such edge.
** Else the candidate stays (docs/paradigms.md: why it is the apex when the
** apex lies on its side).  DCC_NONE when no neighbour lies above. */
static uint32_t dcc_candidate(dcc_run *R, uint32_t basel, int right) {
  paradigm_half *h = R->h;
  uint32_t bo = h[basel].org, bd = dcc_dest(R, basel), stop = right ? bd : bo;
  uint32_t e = right ? h[basel].prev : h[basel ^ 1].next;
  if (!dcc_right_of(R, dcc_dest(R, e), basel)) return DCC_NONE;
  for (int deleted = 0;; deleted = 1) {
    uint32_t t = right ? h[e].prev : h[e].next, far = dcc_dest(R, t), g = right ? e ^ 1 : e;
    if (R->con[e / 2] != DCC_FREE || far == stop || dcc_apex(R, g) != far
        || dcc_orient(R, h[g].org, dcc_dest(R, g), far) <= 0
        || !dcc_incircle(R, bd, bo, dcc_dest(R, e), far))
      return !deleted || dcc_right_of(R, dcc_dest(R, e), basel) ? e : DCC_NONE;
    dcc_delete(R, e);
    e = t;
  }
}

/* Guibas and Stolfi's zipper from basel upwards, with dcc_candidate's
** candidates: of the two, the right one when it lies inside the circle
** through basel and the left one.  Pushes its edges for Lawson's check.
** O(edges made and deleted).  0, or -1 out of memory. */
static int dcc_zip(dcc_run *R, uint32_t basel) {
  paradigm_half *h = R->h;
  int rc = dcc_push(R, basel);
  for (;;) {
    uint32_t lc = dcc_candidate(R, basel, 0), rc_ = dcc_candidate(R, basel, 1);
    if (lc == DCC_NONE && rc_ == DCC_NONE) return rc;
    int right = lc == DCC_NONE
                || (rc_ != DCC_NONE && dcc_incircle(R, dcc_dest(R, lc), dcc_dest(R, basel),
                                                    h[basel].org, dcc_dest(R, rc_)));
    rc |= dcc_push(R, right ? rc_ : lc);
    basel = right ? dcc_connect(R, rc_, basel ^ 1) : dcc_connect(R, basel ^ 1, lc ^ 1);
    rc |= dcc_push(R, basel);
  }
}

/* Merge left (ldo, ldi: cw hull edge out of its rightmost site) and right
** (rdi: ccw hull edge out of its leftmost site, rdo): steps 1 and 2. */
static int dcc_merge(dcc_run *R, dcc_hull a, dcc_hull b, dcc_hull *m) {
  paradigm_half *h = R->h;
  uint32_t ldo = a.l, ldi = a.r, rdi = b.l, rdo = b.r;
  for (;;) {   /* the lower common tangent */
    if (dcc_left_of(R, h[rdi].org, ldi)) ldi = paradigm_he_lnext(h, ldi);
    else if (dcc_right_of(R, h[ldi].org, rdi)) rdi = paradigm_he_rprev(h, rdi);
    else break;
  }
  uint32_t basel = dcc_connect(R, rdi ^ 1, ldi);
  if (h[ldi].org == h[ldo].org) ldo = basel ^ 1;
  if (h[rdi].org == h[rdo].org) rdo = basel;
  *m = (dcc_hull){ldo, rdo};
  return dcc_zip(R, basel) != 0 || dcc_lawson(R) != 0 ? -1 : 0;
}

/* ---- step 3: a segment joining the two pieces, inserted by flips ---- */

/* Mark the edge u -> w (a ring neighbour of u) as segment sg. */
static void dcc_mark(dcc_run *R, uint32_t e, uint32_t sg) {
  R->con[e / 2] = (int32_t)sg;
}

/* The first step of segment u -> v round u: the edge u -> w when w is v
** or on the open segment (returned, *first DCC_NONE), or else the half-edge
** x -> y of the triangle u x y whose open wedge at u holds v (in *first;
** returns DCC_NONE).  O(degree of u). */
static uint32_t dcc_start(dcc_run *R, uint32_t u, uint32_t v, uint32_t *first) {
  const paradigm_half *h = R->h;
  uint32_t e0 = R->out[u], e = e0;
  *first = DCC_NONE;
  do {
    uint32_t x = dcc_dest(R, e);
    ops_add(R->c, OPS_LOCATE, 1);
    if (x == v || ops_on_segment(R->c, dcc_p(R, u), dcc_p(R, v), dcc_p(R, x))) return e;
    uint32_t f = h[e].next, y = dcc_dest(R, f);
    if (f != e && dcc_apex(R, e) == y && dcc_orient(R, u, x, v) > 0
        && dcc_orient(R, u, v, y) > 0)
      *first = paradigm_he_lnext(h, e);
    e = f;
  } while (e != e0 && *first == DCC_NONE);
  return DCC_NONE;
}

static int dcc_enqueue(dcc_run *R, size_t *tail, uint32_t e) {
  size_t old = R->qcap;
  if (geom_grow((void **)&R->queue, &R->qcap, *tail + 1, sizeof *R->queue) != 0) return -1;
  ops_memory(R->c, (int64_t)((R->qcap - old) * sizeof *R->queue));
  R->queue[(*tail)++] = e >> 1;
  return 0;
}

/* The edges the open segment u -> t crosses, walked from the half-edge
** g (x -> y, x right of u -> v) into the queue, up to t: v or the first
** site on the segment.  -1 when one is a segment (a crossing: both named)
** or memory runs out. */
static int dcc_walk(dcc_run *R, uint32_t sg, uint32_t u, uint32_t v, uint32_t g,
                    uint32_t *t, size_t *n) {
  for (;;) {
    if (R->con[g / 2] != DCC_FREE) {
      uint32_t o = (uint32_t)R->con[g / 2];
      snprintf(R->err, R->errlen, "segments %u and %u cross", o < sg ? o : sg, o < sg ? sg : o);
      return -1;
    }
    if (dcc_enqueue(R, n, g) != 0) return -1;
    uint32_t z = dcc_apex(R, g ^ 1);
    ops_add(R->c, OPS_LOCATE, 1);
    int o = z == v ? 0 : dcc_orient(R, u, v, z);
    if (o == 0) {
      *t = z;
      return 0;
    }
    /* the far triangle y x z: leave by x -> z (z left of u -> v) or z -> y */
    uint32_t zx = paradigm_he_lnext(R->h, g ^ 1), yz = paradigm_he_lnext(R->h, zx);
    g = o > 0 ? zx : yz;
  }
}

/* Does the edge e cross the open segment u -> t (its ends strictly on
** both sides of the line)? */
static int dcc_crosses(dcc_run *R, uint32_t u, uint32_t t, uint32_t e) {
  int a = dcc_orient(R, u, t, R->h[e].org), b = dcc_orient(R, u, t, dcc_dest(R, e));
  return a * b < 0;
}

/* Sloan's flips: a queued edge whose quadrilateral is strictly convex is
** flipped, and queued again while it crosses u -> t; else it waits its
** turn again (at the queue's end).  0, or -1. */
static int dcc_sloan(dcc_run *R, uint32_t u, uint32_t t, size_t tail) {
  for (size_t head = 0; head < tail; head++) {
    uint32_t e = 2 * R->queue[head], a = R->h[e].org, b = dcc_dest(R, e);
    uint32_t c = dcc_apex(R, e), d = dcc_apex(R, e ^ 1);
    if (dcc_orient(R, c, d, a) * dcc_orient(R, c, d, b) >= 0) {
      if (dcc_enqueue(R, &tail, e) != 0) return -1;
      continue;
    }
    const paradigm_half *h = R->h;
    uint32_t l1 = paradigm_he_lnext(h, e), r1 = paradigm_he_lnext(h, e ^ 1);
    uint32_t l2 = paradigm_he_lnext(h, l1), r2 = paradigm_he_lnext(h, r1);
    dcc_flip(R, e);
    if (dcc_push(R, l1) || dcc_push(R, l2) || dcc_push(R, r1) || dcc_push(R, r2)) return -1;
    if (dcc_crosses(R, u, t, e) ? dcc_enqueue(R, &tail, e) : dcc_push(R, e)) return -1;
  }
  return 0;
}

/* The edge u -> w, found round u (it exists). */
static uint32_t dcc_find(const dcc_run *R, uint32_t u, uint32_t w) {
  uint32_t e = R->out[u];
  while (dcc_dest(R, e) != w) e = R->h[e].next;
  return e;
}

/* Segment sg from u to v: piece by piece (a site on it ends a piece), each
** made an edge by Sloan's flips and marked, then Lawson's flips.  0, or -1
** with the message. */
static int dcc_insert(dcc_run *R, uint32_t sg, uint32_t u, uint32_t v) {
  while (u != v) {
    uint32_t g, t, e = dcc_start(R, u, v, &g);
    if (e == DCC_NONE) {
      size_t n = 0;
      if (g == DCC_NONE) {
        snprintf(R->err, R->errlen, "segment %u: no triangle round its end (a bug)", sg);
        return -1;
      }
      if (dcc_walk(R, sg, u, v, g, &t, &n) != 0 || dcc_sloan(R, u, t, n) != 0) goto fail;
      e = dcc_find(R, u, t);
    }
    dcc_mark(R, e, sg);
    u = dcc_dest(R, e);
    if (dcc_lawson(R) != 0) goto fail;
  }
  return 0;
fail:
  if (R->err[0] == '\0') snprintf(R->err, R->errlen, "out of memory for segment %u", sg);
  return -1;
}

/* ---- the recursion ---- */

/* Where segment a-b (ranks a < b) is inserted: at the merge whose cut
** separates them (key 2 mid), or in the base piece holding both (key
** 2 lo + 1); the halving is dcc_solve's.  O(log n). */
static uint32_t dcc_key(uint32_t n, uint32_t a, uint32_t b) {
  for (uint32_t lo = 0, hi = n;;) {
    if (hi - lo <= 3) return 2 * lo + 1;
    uint32_t mid = lo + (hi - lo) / 2;
    if (b < mid) hi = mid;
    else if (a >= mid) lo = mid;
    else return 2 * mid;
  }
}

/* The segments inserted at key k: list[at[k] .. at[k + 1]). */
static int dcc_segments_at(dcc_run *R, uint32_t k) {
  const uint32_t *sg = R->in->segments;
  for (uint32_t j = R->at[k]; j < R->at[k + 1]; j++) {
    uint32_t s = R->list[j];
    if (dcc_insert(R, s, R->pos[sg[2 * s]], R->pos[sg[2 * s + 1]]) != 0) return -1;
  }
  return 0;
}

/* Merge two pieces split by the cut of frame 1 (horizontal): their ends
** in that frame found, merged, and the union's given back in frame 0. */
static int dcc_merge_across(dcc_run *R, dcc_hull a, dcc_hull b, int frame, dcc_hull *m) {
  if (frame == 0) return dcc_merge(R, a, b, m);
  const paradigm_half *h = R->h;
  dcc_hull a1 = {paradigm_he_extreme(h, R->s, a.l, 1, 0),
                 h[paradigm_he_extreme(h, R->s, a.l, 1, 1)].prev};
  dcc_hull b1 = {paradigm_he_extreme(h, R->s, b.l, 1, 0),
                 h[paradigm_he_extreme(h, R->s, b.l, 1, 1)].prev};
  if (dcc_merge(R, a1, b1, m) != 0) return -1;
  *m = (dcc_hull){paradigm_he_extreme(R->h, R->s, m->l, 0, 0),
                  R->h[paradigm_he_extreme(R->h, R->s, m->l, 0, 1)].prev};
  return 0;
}

/* Sites [lo, hi) at depth `depth`: T(n) = 2 T(n/2) + merge.  0, or -1
** with the message. */
static int dcc_solve(dcc_run *R, uint32_t lo, uint32_t hi, int depth, dcc_hull *out) {
  if (hi - lo <= 3) {
    *out = dcc_base(R, lo, hi - lo);
    return dcc_segments_at(R, 2 * lo + 1);
  }
  uint32_t mid = lo + (hi - lo) / 2;
  dcc_hull a, b;
  if (dcc_solve(R, lo, mid, depth + 1, &a) != 0 || dcc_solve(R, mid, hi, depth + 1, &b) != 0)
    return -1;
  if (dcc_merge_across(R, a, b, R->alternating ? depth & 1 : 0, out) != 0) {
    snprintf(R->err, R->errlen, "out of memory for the merge of %u sites", hi - lo);
    return -1;
  }
  return dcc_segments_at(R, 2 * mid);
}

/* ---- the run ---- */

typedef struct dcc_site {
  geom_point p;
  uint32_t id;
} dcc_site;

static int dcc_cmp0(const void *x, const void *y) {
  const dcc_site *a = x, *b = y;
  return paradigm_frame_before(a->p, b->p, 0) ? -1 : paradigm_frame_before(b->p, a->p, 0);
}

static int dcc_cmp1(const void *x, const void *y) {
  const dcc_site *a = x, *b = y;
  return paradigm_frame_before(a->p, b->p, 1) ? -1 : paradigm_frame_before(b->p, a->p, 1);
}

/* a[0 .. n) reordered so that a[k] is the element of rank k in the
** frame's order, the smaller before it and the larger after: Hoare's
** selection with pseudo-random pivots, O(n) expected; past its budget of
** rounds, a sort (no input makes it quadratic).  The points are distinct. */
static void dcc_select(dcc_site *a, uint32_t n, uint32_t k, int frame) {
  uint64_t g = n;
  uint32_t lo = 0, hi = n;
  for (int budget = 64; hi - lo > 1; budget--) {
    if (budget == 0) {
      qsort(a + lo, hi - lo, sizeof *a, frame ? dcc_cmp1 : dcc_cmp0);
      return;
    }
    uint32_t q = lo + (uint32_t)(geom_splitmix64(&g) % (hi - lo)), i = lo, j = hi - 1;
    dcc_site piv = a[q], t;
    a[q] = a[j], a[j] = piv;
    while (i < j) {
      if (paradigm_frame_before(a[i].p, piv.p, frame)) i++;
      else t = a[i], a[i] = a[--j], a[j] = t;
    }
    a[hi - 1] = a[i], a[i] = piv;
    if (k == i) return;
    if (k < i) hi = i;
    else lo = i + 1;
  }
}

/* The cuts of dcc_solve, made beforehand: piece [lo, hi) at depth `depth`
** split at its middle rank in the frame of its cut, the pieces of three
** sites or fewer sorted in frame 0.  O(n log n) expected. */
static void dcc_cut(dcc_site *t, uint32_t lo, uint32_t hi, int depth, int alternating) {
  if (hi - lo <= 3) {
    qsort(t + lo, hi - lo, sizeof *t, dcc_cmp0);
    return;
  }
  uint32_t mid = lo + (hi - lo) / 2;
  dcc_select(t + lo, hi - lo, mid - lo, alternating ? depth & 1 : 0);
  dcc_cut(t, lo, mid, depth + 1, alternating);
  dcc_cut(t, mid, hi, depth + 1, alternating);
}

/* geom_csr_build's key of segment i: its merge's, computed beforehand. */
static size_t dcc_segment_key(const void *key, size_t i) {
  return ((const uint32_t *)key)[i];
}

/* The cuts made (the sites' ranks), the segments listed by the key of
** their merge, a segment joining a site to itself refused.  0, or -1. */
static int dcc_prepare(dcc_run *R) {
  const paradigm_input *in = R->in;
  uint32_t n = (uint32_t)in->n, keys = 2 * n + 2;
  dcc_site *t = malloc((n ? n : 1) * sizeof *t);
  if (t == NULL) {
    snprintf(R->err, R->errlen, "out of memory for the sort of %u sites", n);
    return -1;
  }
  for (uint32_t k = 0; k < n; k++) t[k] = (dcc_site){in->p[k], k};
  dcc_cut(t, 0, n, 0, R->alternating);
  for (uint32_t k = 0; k < n; k++) R->s[k] = t[k].p, R->id[k] = t[k].id, R->pos[t[k].id] = k;
  free(t);
  uint32_t *key = R->list + in->nsegments;
  for (size_t s = 0; s < in->nsegments; s++) {
    uint32_t a = R->pos[in->segments[2 * s]], b = R->pos[in->segments[2 * s + 1]];
    if (a == b) {
      snprintf(R->err, R->errlen, "segment %zu joins a point to itself", s);
      return -1;
    }
    key[s] = dcc_key(n, a < b ? a : b, a < b ? b : a);
  }
  geom_csr_build(R->at, keys, R->list, in->nsegments, dcc_segment_key, key);
  return 0;
}

/* Is the outer face's round from e0 the hull, once round?  Every turn
** clockwise or straight (the outer face on the left), and the x-direction
** of its edges changing sign twice (a convex polygon once round; a
** pentagram turns the same way throughout and changes four times).  Its
** length into *hull.  O(h); exact tests, not counted (a check of the
** result, as the runner's of the input). */
static int dcc_hull_ok(const dcc_run *R, uint32_t e0, uint32_t *hull) {
  const paradigm_half *h = R->h;
  uint32_t e = e0, changes = 0;
  int first = 0, last = 0;
  *hull = 0;
  do {
    uint32_t f = paradigm_he_lnext(h, e);
    geom_point a = R->s[h[e].org], b = R->s[h[f].org], c = R->s[paradigm_he_dest(h, f)];
    if (geom_orient(a, b, c) > 0) return 0;
    int dx = (b.x > a.x) - (b.x < a.x);
    if (dx != 0 && first == 0) first = dx;
    else if (dx != 0 && dx != last) changes++;
    last = dx != 0 ? dx : last;
    ++*hull;
    e = f;
  } while (e != e0 && *hull <= 2 * R->in->n);
  return e == e0 && changes + (first != last) == 2;
}

/* The triangles: each face that is a round of three half-edges, written
** once from its smallest, but the outer face (a three-site hull's is a
** round of three too).  The certificate that the mesh is a triangulation
** (got's, docs/got.md): every triangle anticlockwise, the outer face the
** hull once round (dcc_hull_ok), and Euler's count 2n - 2 - h; a half-edge
** mesh uses each directed edge once.  O(n); -2 when it fails (a bug). */
static int dcc_triangles(dcc_run *R, dcc_hull top, paradigm_output *out) {
  uint32_t n = (uint32_t)R->in->n, e0 = top.l ^ 1, e = e0, hull, skip = e0;
  if (!dcc_hull_ok(R, e0, &hull)) return -2;
  do {
    skip = e < skip ? e : skip;
    e = paradigm_he_lnext(R->h, e);
  } while (e != e0);
  size_t want = n >= 3 && hull < 2 * n - 2 ? 2 * (size_t)n - 2 - hull : 0, k = 0;
  out->tri = malloc(3 * (want ? want : 1) * sizeof *out->tri);
  if (out->tri == NULL) return -1;
  for (uint32_t a = 0; a < 2 * R->nedges; a++) {
    const paradigm_half *h = R->h;
    uint32_t b = paradigm_he_lnext(h, a), c = paradigm_he_lnext(h, b);
    if (h[a].org == DCC_NONE || paradigm_he_lnext(h, c) != a || b < a || c < a
        || (hull == 3 && a == skip))
      continue;
    if (geom_orient(R->s[h[a].org], R->s[h[b].org], R->s[h[c].org]) <= 0) return -2;
    if (k < want) {
      uint32_t *t = out->tri + 3 * k;
      t[0] = R->id[h[a].org], t[1] = R->id[h[b].org], t[2] = R->id[h[c].org];
    }
    k++;
  }
  out->ntri = k;
  return k == want ? 0 : -2;
}

/* Bytes a site: the site, its rank, position and ring end (28), three
** edges of two half-edges (72) and a segment mark each (12). */
#define DCC_SITE_BYTES (sizeof(geom_point) + 3 * sizeof(uint32_t) \
                        + 6 * sizeof(paradigm_half) + 3 * sizeof(int32_t))

/* The bytes dcc_alloc holds, for the peak's count. */
static size_t dcc_bytes(const dcc_run *R) {
  size_t n = R->in->n ? R->in->n : 1;
  return n * DCC_SITE_BYTES + (2 * n + 3 + 2 * R->in->nsegments) * sizeof(uint32_t);
}

static int dcc_alloc(dcc_run *R) {
  size_t n = R->in->n ? R->in->n : 1, ns = R->in->nsegments;
  R->s = malloc(n * sizeof *R->s);
  R->id = malloc(n * sizeof *R->id);
  R->pos = malloc(n * sizeof *R->pos);
  R->out = malloc(n * sizeof *R->out);
  R->h = malloc(6 * n * sizeof *R->h);
  R->con = malloc(3 * n * sizeof *R->con);
  R->at = calloc(2 * n + 3, sizeof *R->at);
  R->list = malloc((2 * ns + 1) * sizeof *R->list);
  ops_memory(R->c, (int64_t)dcc_bytes(R));
  return R->s && R->id && R->pos && R->out && R->h && R->con && R->at && R->list ? 0 : -1;
}

static void dcc_free(dcc_run *R) {
  ops_memory(R->c, -(int64_t)dcc_bytes(R));
  ops_memory(R->c, -(int64_t)(R->scap * sizeof *R->stack + R->qcap * sizeof *R->queue));
  free(R->s), free(R->id), free(R->pos), free(R->out), free(R->h), free(R->con);
  free(R->at), free(R->list), free(R->stack), free(R->queue);
}

/* Cost as above the file: O(n log n) for the cuts and the zipper's merges,
** plus the segments' insertions. */
int paradigm_dc_constrained(const paradigm_input *in, paradigm_output *out, char *err,
                            size_t errlen) {
  if (in->n > UINT32_MAX / 8) {
    snprintf(err, errlen, "dc-constrained: %zu points, at most %u", in->n, UINT32_MAX / 8);
    return -1;
  }
  if (in->param != 0 && in->param != 1) {
    snprintf(err, errlen, "dc-constrained: parameter %g: 0 (cuts alternating between "
             "vertical and horizontal) or 1 (vertical strips)", in->param);
    return -1;
  }
  dcc_run R = {.in = in, .c = &out->ops, .err = err, .errlen = errlen, .free = DCC_NONE,
               .alternating = in->param == 0};
  err[0] = '\0';
  int rc = dcc_alloc(&R);
  if (rc != 0) snprintf(err, errlen, "out of memory for the mesh of %zu points", in->n);
  if (rc == 0) rc = dcc_prepare(&R);
  dcc_hull top = {0, 0};
  if (rc == 0 && in->n >= 2) rc = dcc_solve(&R, 0, (uint32_t)in->n, 0, &top);
  if (rc == 0 && in->n >= 2) rc = dcc_triangles(&R, top, out);
  if (rc == -1 && err[0] == '\0') snprintf(err, errlen, "out of memory for the triangles");
  if (rc == -2) snprintf(err, errlen, "dc-constrained: the mesh of %zu points is not a "
                         "triangulation (a bug: please report it)", in->n);
  dcc_free(&R);
  return rc == 0 ? 0 : -1;
}
