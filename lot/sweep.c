/*
** sweep.c: the sweepline algorithm (thesis sections 2.5.1 and 4.1.1) for
** lot --algorithm sweep, written against the primitives of a shape
** (shapes/shape_sweep_internal.h; the circle's give the Delaunay
** triangulation).
**
** A vertical line sweeps the sites from left to right.  Its status is the
** boundary of the part of the triangulation that is certain whatever lies
** to the right: the sites whose arcs meet the sweepline, from bottom to
** top, a site possibly several times.  Two consecutive sites A, B form a
** boundary edge; its breakpoint is the contact point of the shape through
** A and B tangent to the sweepline, and breakpoints increase along the
** boundary.  Events, in the order of their keys:
**   site X (key X.x): find the arc B the sweepline meets at X.y (the last
**     boundary site whose breakpoint with its predecessor lies below X, by
**     the shape's "above" test), and replace B by B X B: the edge BX now
**     lies on the boundary twice, once per side;
**   circumshape A, B, C (consecutive, closing: C right of AB; key the
**     rightmost point of the shape through them, for a circle cx + R):
**     triangle A C B is certain; B leaves the boundary, A C becomes a
**     boundary edge.
** Every change of the boundary reschedules the triples around it.  The
** boundary is a skip list (expected O(log n) search, insertion and
** deletion by handle; tower heights from a fixed generator, so runs are
** reproducible); circumshape events sit in a binary heap, at most one per
** boundary node (its triple's), and an event is taken out of the heap as
** soon as its triple is about to change (sw_cancel: each node knows its
** event's place).  Left in the heap until they came up, such stale events
** were nine in ten of its entries for uniform points, and the heap's time
** went in cache misses; a waiting event reads its sites from its node's
** neighbours, so an entry is 24 bytes, not 40.  Site events come in the
** sorted order of the input (x, then y, then index) and are merged with
** the heap.
**
** Exactness.  The heap is ordered by exact keys: each event carries
** certified bounds lo <= key <= hi (the shape's key_bounds), disjoint
** bounds decide, and overlapping ones go to the shape's exact comparison.
** A circumshape event comes before a site event of the same key, equal
** circumshape keys in the order the events were made; every order of
** equal keys is a valid sweep (at that key each of the configurations is
** a true status), and this one is fixed, so cocircular sites give one
** reproducible valid triangulation.  The "above" test and the closing test
** are exact (shapes/shape_sweep_*.c), so every decision is the exact one.
** Grids make most keys that meet in the heap exactly equal: when the shape
** has integer keys and every site fits its frame (integers in one unit,
** found in O(n) at the start), each event's key is also made once as an
** integer record (ik, per node beside hpos) and records are compared
** before points, so those comparisons never reach GMP.
**
** Adjacency: every edge made (by a site event, or as the new edge AC of a
** circumshape event) has a record with two slots, one per side; a boundary
** node points at the record and side of the edge to its successor.  A
** triangle fills the slots of its three edges; when both slots of a record
** are filled the two corners are linked.  At the end, the records with one
** slot filled are the hull edges: each gets its ghost triangle, and the
** ghosts are linked around the hull (mesh.h's convention).
*/
#include <stdlib.h>
#include <string.h>
#include "geom_mem_internal.h"
#include "splitmix.h"
#include "sweep_internal.h"

#define SW_LEVELS 12        /* towers of at most 12 levels, p = 1/4: 4^12 = 1.7e7 */
#define SW_NONE UINT32_MAX
#define SW_HEAD 0u          /* the skip list's head node (no site) */
/* A polygon sweep through ties it could not order (sites in special
** position, sweep_polygon.c) has no proof behind it: should it make more
** triangles than a triangulation has, or a hull that is no cycle, it stops
** with this code (lot.c then starts again from the circle's sweep).  The
** circle's and the ellipses' sweeps never return it. */
#define SW_BROKEN (-3)

typedef struct sw_node {
  geom_point pt;            /* its point (a copy: the search reads it without m->p) */
  uint32_t site;            /* the mesh vertex */
  uint32_t edge;            /* the record of the edge to the successor (SW_NONE: last) */
  uint32_t life;            /* counts the node's lives (a hint names one) */
  uint8_t side, h;          /* edge's slot on this side; tower height */
  uint32_t nx[SW_LEVELS], pv[SW_LEVELS];
} sw_node;

/* An event waiting in the heap: its triple is its node's predecessor, the
** node and its successor, which do not change while it waits. */
typedef struct sw_event {
  double lo, hi;            /* lo <= key <= hi */
  uint32_t node, seq;       /* the middle node; creation order */
} sw_event;

typedef struct sw_hint {
  uint32_t node, life;      /* valid while the node lives that life */
} sw_hint;

typedef struct lot_sweep {
  lot_mesh *m;
  const shape_sweep *s;
  sw_node *nd;
  uint32_t nnd, ndcap, freed;
  uint32_t *ec;             /* two corners per edge record (SW_NONE: empty) */
  size_t ne, ecap;
  sw_event *hp;
  size_t nh, hcap;
  uint32_t *hpos;           /* per node: its event's place in hp (SW_NONE: none) */
  size_t hposcap;
  shape_sweep_ikey *ik;     /* per node: its event's integer key (framed runs) */
  size_t ikcap;
  shape_sweep_frame fr;
  int framed;               /* every site fits the shape's integer frame */
  uint32_t seq;
  uint64_t rng;
  sw_hint *hint;            /* per band of y: a node lately seen there */
  uint32_t nhint;
  double y0, yscale;        /* band of y: (y - y0) * yscale */
} lot_sweep;

/* Arrays grow by geom_grow (geom/geom_mem_internal.h). */

/* A new node for site v (SW_NONE when out of memory). */
static uint32_t sw_node_new(lot_sweep *S, uint32_t v) {
  uint32_t x = S->freed;
  if (x != SW_NONE) {
    S->freed = S->nd[x].nx[0];
  } else {
    size_t cap = S->ndcap;
    if (geom_grow((void **)&S->nd, &cap, (size_t)S->nnd + 1, sizeof *S->nd) != 0
        || geom_grow((void **)&S->hpos, &S->hposcap, (size_t)S->nnd + 1, sizeof *S->hpos) != 0
        || (S->framed &&
            geom_grow((void **)&S->ik, &S->ikcap, (size_t)S->nnd + 1, sizeof *S->ik)))
      return SW_NONE;
    S->ndcap = (uint32_t)cap;
    x = S->nnd++;
    S->nd[x].life = 0;
  }
  uint64_t r = geom_splitmix64(&S->rng);
  uint8_t h = 1;
  while (h < SW_LEVELS && (r & 3) == 0) {
    h++;
    r >>= 2;
  }
  sw_node *n = &S->nd[x];
  n->pt = v != SW_NONE ? S->m->p[v] : (geom_point){0, 0};
  n->site = v;
  n->edge = SW_NONE;
  n->side = 0;
  n->h = h;
  n->life++;
  S->hpos[x] = SW_NONE;
  return x;
}

/* A new edge record, both slots empty (SW_NONE when out of memory). */
static uint32_t sw_edge_new(lot_sweep *S) {
  if (geom_grow((void **)&S->ec, &S->ecap, 2 * (S->ne + 1), sizeof *S->ec) != 0)
    return SW_NONE;
  S->ec[2 * S->ne] = S->ec[2 * S->ne + 1] = SW_NONE;
  ops_add(S->m->ops, OPS_EDGES_MADE, 1);
  return (uint32_t)S->ne++;
}

/* ---- the skip list ----------------------------------------------------- */

/* Link x after b: at level l the predecessor is the nearest node at or
** before b whose tower reaches l, found walking back along level l - 1. */
static void sw_link_after(lot_sweep *S, uint32_t b, uint32_t x) {
  sw_node *nd = S->nd;
  uint32_t p = b;
  for (uint32_t l = 0; l < nd[x].h; l++) {
    while (nd[p].h <= l) p = nd[p].pv[l - 1];
    uint32_t q = nd[p].nx[l];
    nd[x].pv[l] = p;
    nd[x].nx[l] = q;
    nd[p].nx[l] = x;
    if (q != SW_NONE) nd[q].pv[l] = x;
  }
}

static void sw_unlink(lot_sweep *S, uint32_t x) {
  sw_node *nd = S->nd;
  for (uint32_t l = 0; l < nd[x].h; l++) {
    uint32_t p = nd[x].pv[l], q = nd[x].nx[l];
    nd[p].nx[l] = q;
    if (q != SW_NONE) nd[q].pv[l] = p;
  }
  nd[x].life++;   /* hints to it die with it */
  nd[x].nx[0] = S->freed;
  S->freed = x;
}

/* The node whose arc the sweepline meets at X: the last one whose
** breakpoint with its predecessor lies below X (the first node has none). */
static uint32_t sw_locate(const lot_sweep *S, geom_point X) {
  const sw_node *nd = S->nd;
  uint32_t cur = SW_HEAD;
  for (int l = SW_LEVELS - 1; l >= 0; l--)
    for (;;) {
      uint32_t q = nd[cur].nx[l];
      if (q == SW_NONE) break;
      uint32_t a = nd[q].pv[0];
      if (a != SW_HEAD && !S->s->above(S->s->ctx, nd[a].pt, nd[q].pt, X)) break;
      cur = q;
    }
  return cur;
}

/* From node h, walk along the boundary to X's node (sw_locate's answer:
** every breakpoint is monotone along the boundary, so the steps down and
** up never alternate); SW_NONE after SW_WALK steps. */
#define SW_WALK 8
static uint32_t sw_walk(const lot_sweep *S, uint32_t h, geom_point X) {
  const sw_node *nd = S->nd;
  for (int k = 0; k < SW_WALK; k++) {
    uint32_t a = nd[h].pv[0], c = nd[h].nx[0];
    if (a != SW_HEAD && !S->s->above(S->s->ctx, nd[a].pt, nd[h].pt, X)) {
      h = a;
    } else if (c != SW_NONE && S->s->above(S->s->ctx, nd[h].pt, nd[c].pt, X)) {
      h = c;
    } else {
      return h;
    }
  }
  return SW_NONE;
}

/* The band of height y. */
static uint32_t sw_band(const lot_sweep *S, double y) {
  double f = (y - S->y0) * S->yscale;
  return f > 0 ? (f < S->nhint - 1 ? (uint32_t)f : S->nhint - 1) : 0;
}

/* X's node: a short walk from the node last seen in X's band of y, or
** when that node has left the boundary (three site events in ten for
** uniform points, each then paying a search of the skip list) from the
** nearest band around whose node still lives (hints are a speed-up only:
** the walk's answer is exact), else the skip list's search, O(log n)
** expected. */
#define SW_BANDS 4
static uint32_t sw_find(const lot_sweep *S, geom_point X) {
  uint32_t k = sw_band(S, X.y);
  for (uint32_t d = 0; d <= SW_BANDS; d++)
    for (int side = 0; side < 2 - (d == 0); side++) {
      uint32_t j = side ? k - d : k + d;   /* k - d wraps below 0: too large */
      if (j >= S->nhint) continue;
      sw_hint h = S->hint[j];
      if (h.node == SW_NONE || S->nd[h.node].life != h.life) continue;
      uint32_t b = sw_walk(S, h.node, X);
      return b != SW_NONE ? b : sw_locate(S, X);
    }
  return sw_locate(S, X);
}

static void sw_hint_set(lot_sweep *S, double y, uint32_t x) {
  S->hint[sw_band(S, y)] = (sw_hint){x, S->nd[x].life};
}

/* ---- the event heap ---------------------------------------------------- */

static void sw_points(const lot_sweep *S, const sw_event *e, geom_point t[3]) {
  const sw_node *nd = S->nd;
  uint32_t b = e->node;
  t[0] = nd[nd[b].pv[0]].pt;
  t[1] = nd[b].pt;
  t[2] = nd[nd[b].nx[0]].pt;
}

/* The sites events a and b share: 2 for neighbouring triples. */
static int sw_shared(const lot_sweep *S, const sw_event *a, const sw_event *b) {
  const sw_node *nd = S->nd;
  uint32_t u[3] = {nd[nd[a->node].pv[0]].site, nd[a->node].site, nd[nd[a->node].nx[0]].site};
  uint32_t v[3] = {nd[nd[b->node].pv[0]].site, nd[b->node].site, nd[nd[b->node].nx[0]].site};
  int n = 0;
  for (int i = 0; i < 3; i++) n += u[i] == v[0] || u[i] == v[1] || u[i] == v[2];
  return n;
}

/* Does event a come before b, their bounds overlapping?  Exact keys (the
** integer keys made when the events were, in a framed run, else the
** shape's comparison), then creation order. */
static int sw_before_exact(const lot_sweep *S, const sw_event *a, const sw_event *b) {
  int c = S->framed ? S->s->ikey_cmp(&S->ik[a->node], &S->ik[b->node]) : 2;
  if (c == 2) {
    geom_point ta[3], tb[3];
    sw_points(S, a, ta);
    sw_points(S, b, tb);
    c = S->s->key_cmp(S->s->ctx, ta, 0, tb, 0);
  }
  if (c == 0 && S->s->ties != NULL && sw_shared(S, a, b) == 2) ++*S->s->ties;
  return c != 0 ? c < 0 : a->seq < b->seq;
}

/* Does event a come before b?  Disjoint bounds decide, else the exact keys. */
static int sw_before(const lot_sweep *S, const sw_event *a, const sw_event *b) {
  if (a->hi < b->lo) return 1;
  if (b->hi < a->lo) return 0;
  return sw_before_exact(S, a, b);
}

/* Does event e come before the site event of x?  Ties: the circumshape. */
static int sw_before_site(const lot_sweep *S, const sw_event *e, double x) {
  if (e->hi < x) return 1;
  if (e->lo > x) return 0;
  if (S->framed) {
    shape_sweep_ikey k;
    S->s->ikey(S->s->ctx, &S->fr, NULL, x, &k);
    int c = S->s->ikey_cmp(&S->ik[e->node], &k);
    if (c != 2) return c <= 0;
  }
  geom_point t[3];
  sw_points(S, e, t);
  return S->s->key_cmp(S->s->ctx, t, 0, NULL, x) <= 0;
}

static void sw_heap_put(lot_sweep *S, size_t i, const sw_event *e) {
  S->hp[i] = *e;
  S->hpos[e->node] = (uint32_t)i;
}

/* e into the hole at i, moving it up as far as it goes. */
static void sw_sift_up(lot_sweep *S, size_t i, const sw_event *e) {
  while (i > 0 && sw_before(S, e, &S->hp[(i - 1) / 2])) {
    sw_heap_put(S, i, &S->hp[(i - 1) / 2]);
    i = (i - 1) / 2;
  }
  sw_heap_put(S, i, e);
}

/* e into the hole at i, moving it down as far as it goes. */
static void sw_sift_down(lot_sweep *S, size_t i, const sw_event *e) {
  size_t n = S->nh;
  for (;;) {
    size_t c = 2 * i + 1;
    if (c >= n) break;
    if (c + 1 < n) c += (size_t)sw_before(S, &S->hp[c + 1], &S->hp[c]);
    if (!sw_before(S, &S->hp[c], e)) break;
    sw_heap_put(S, i, &S->hp[c]);
    i = c;
  }
  sw_heap_put(S, i, e);
}

static int sw_push(lot_sweep *S, const sw_event *e) {
  if (geom_grow((void **)&S->hp, &S->hcap, S->nh + 1, sizeof *S->hp) != 0) return -1;
  sw_sift_up(S, S->nh++, e);
  return 0;
}

/* Take the event at i out of the heap: the last entry fills its place. */
static void sw_remove(lot_sweep *S, size_t i) {
  S->hpos[S->hp[i].node] = SW_NONE;
  sw_event last = S->hp[--S->nh];
  if (i == S->nh) return;
  if (i > 0 && sw_before(S, &last, &S->hp[(i - 1) / 2])) sw_sift_up(S, i, &last);
  else sw_sift_down(S, i, &last);
}

/* Node b's triple is about to change: its event, if any, leaves the heap
** (every entry's triple must be its node's neighbours, which the exact
** comparisons read). */
static void sw_cancel(lot_sweep *S, uint32_t b) {
  if (S->hpos[b] != SW_NONE) sw_remove(S, S->hpos[b]);
}

/* Node b's triple changed (its event cancelled): schedule the new one if
** its predecessor, b and its successor close one. */
static int sw_schedule(lot_sweep *S, uint32_t b) {
  sw_node *nd = S->nd;
  uint32_t a = nd[b].pv[0], c = nd[b].nx[0];
  if (a == SW_HEAD || c == SW_NONE) return 0;
  sw_event e = {0, 0, b, S->seq++};
  const geom_point t[3] = {nd[a].pt, nd[b].pt, nd[c].pt};
  ops_add(S->m->ops, OPS_ORIENT, 1);   /* the closing test: c right of a b */
  if (!S->s->closes(S->s->ctx, t[0], t[1], t[2])) return 0;
  S->s->key_bounds(S->s->ctx, t, &e.lo, &e.hi);
  if (S->framed) S->s->ikey(S->s->ctx, &S->fr, t, 0, &S->ik[b]);
  return sw_push(S, &e);
}

/* ---- events ------------------------------------------------------------ */

/* Corner c of a new triangle takes the slot (edge, side); linked to the
** corner on the other side once both are there. */
static void sw_fill(lot_sweep *S, uint32_t edge, uint8_t side, uint32_t c) {
  S->ec[2 * (size_t)edge + side] = c;
  uint32_t o = S->ec[2 * (size_t)edge + (1 - side)];
  if (o != SW_NONE) {
    S->m->tn[c] = o;
    S->m->tn[o] = c;
  }
}

/* The site event of vertex k: 0, -1 when out of memory, or SW_BROKEN. */
static int sw_site(lot_sweep *S, uint32_t k) {
  geom_point X = S->m->p[k];
  uint32_t b = sw_find(S, X), x = sw_node_new(S, k);
  if (x == SW_NONE) return -1;
  sw_hint_set(S, X.y, x);
  if (b == SW_HEAD) {   /* the first site */
    sw_link_after(S, SW_HEAD, x);
    return 0;
  }
  uint32_t e = sw_edge_new(S);
  if (e == SW_NONE) return -1;
  sw_cancel(S, b);   /* b's successor becomes x */
  if (S->nd[b].pt.x == X.x) {
    /* b lies on the sweepline too: it is the top of the first column of
    ** sites (every breakpoint of a site on the sweepline is at its height),
    ** and X goes above it, once.  A b with a successor would mean that a
    ** shape's "above" test broke that invariant: stop, never corrupt. */
    if (S->nd[b].nx[0] != SW_NONE) return SW_BROKEN;
    S->nd[b].edge = e;
    S->nd[b].side = 0;
    sw_link_after(S, b, x);
    return sw_schedule(S, b);
  }
  uint32_t b2 = sw_node_new(S, S->nd[b].site);
  if (b2 == SW_NONE) return -1;
  sw_node *nd = S->nd;
  nd[b2].edge = nd[b].edge;
  nd[b2].side = nd[b].side;
  nd[b].edge = e;
  nd[b].side = 0;
  nd[x].edge = e;
  nd[x].side = 1;
  sw_link_after(S, b, x);
  sw_link_after(S, x, b2);
  if (sw_schedule(S, b) != 0) return -1;   /* in this order: events are numbered */
  return sw_schedule(S, b2);
}

/* Roughly the height where b's arc vanishes, the circumcentre's (a hint:
** any value will do). */
static double sw_centre_y(geom_point a, geom_point b, geom_point c) {
  double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  double d = 2 * (bx * cy - by * cx);
  return a.y + ((cx * cx + cy * cy) * bx - (bx * bx + by * by) * cx) / d;
}

/* The circumshape event of node b (a, b, c consecutive): triangle a c b,
** anticlockwise (a, b, c turn clockwise); 0, -1 when out of memory, -3
** when the mesh is full (SW_BROKEN). */
static int sw_circle(lot_sweep *S, uint32_t b) {
  lot_mesh *m = S->m;
  if (m->nt >= m->cap) return SW_BROKEN;
  uint32_t e = sw_edge_new(S);
  if (e == SW_NONE) return -1;
  sw_node *nd = S->nd;
  uint32_t a = nd[b].pv[0], c = nd[b].nx[0], t = m->nt++;
  lot_mesh_set(m, t, nd[a].site, nd[c].site, nd[b].site);
  sw_fill(S, nd[a].edge, nd[a].side, LOT_CORNER(t, 1));   /* edge b-a, opposite c */
  sw_fill(S, nd[b].edge, nd[b].side, LOT_CORNER(t, 0));   /* edge c-b, opposite a */
  sw_fill(S, e, 1, LOT_CORNER(t, 2));                     /* edge a-c, opposite b */
  nd[a].edge = e;
  nd[a].side = 0;
  sw_hint_set(S, sw_centre_y(nd[a].pt, nd[b].pt, nd[c].pt), a);
  sw_cancel(S, a);   /* a and c become neighbours */
  sw_cancel(S, c);
  sw_unlink(S, b);
  if (sw_schedule(S, a) != 0) return -1;
  return sw_schedule(S, c);
}

/* ---- the run ----------------------------------------------------------- */

/* A ghost for every hull edge (a record with one slot filled), linked to
** its triangle and to the ghosts of the hull edges around it. */
static int sw_ghosts(lot_sweep *S) {
  lot_mesh *m = S->m;
  uint32_t *first = malloc((size_t)m->np * sizeof *first), g0 = m->nt;
  if (first == NULL) return -1;
  for (uint32_t k = 0; k < m->np; k++) first[k] = SW_NONE;
  int rc = 0;
  for (size_t e = 0; e < S->ne && rc == 0; e++) {
    uint32_t c0 = S->ec[2 * e], c1 = S->ec[2 * e + 1];
    if ((c0 == SW_NONE) == (c1 == SW_NONE)) continue;
    uint32_t c = c0 != SW_NONE ? c0 : c1, g = m->nt;
    uint32_t u = m->tv[lot_next3(c)], w = m->tv[lot_prev3(c)];
    if (g >= m->cap || first[w] != SW_NONE) {   /* never in a valid sweep */
      rc = SW_BROKEN;
      break;
    }
    m->nt++;
    lot_mesh_set(m, g, w, u, LOT_GHOST);   /* the ghost (w, u, G): the outside left of w -> u */
    m->tn[c] = LOT_CORNER(g, 2);
    m->tn[LOT_CORNER(g, 2)] = c;
    first[w] = g;
  }
  for (uint32_t g = g0; g < m->nt && rc == 0; g++) {   /* (w, u, G) meets (u, ., G) across u-G */
    uint32_t h = first[m->tv[LOT_CORNER(g, 1)]];
    if (h == SW_NONE) {
      rc = SW_BROKEN;
      break;
    }
    m->tn[LOT_CORNER(g, 0)] = LOT_CORNER(h, 1);
    m->tn[LOT_CORNER(h, 1)] = LOT_CORNER(g, 0);
  }
  free(first);
  return rc;
}

/* Every event in order: 0, -1 when out of memory, or SW_BROKEN. */
static int sw_events(lot_sweep *S, size_t *duplicates) {
  const geom_point *p = S->m->p;
  uint32_t np = S->m->np, k = 0;
  for (;;) {
    if (k == np && S->nh == 0) return 0;
    if (S->nh > 0 && (k == np || sw_before_site(S, &S->hp[0], p[k].x))) {
      uint32_t b = S->hp[0].node;
      sw_remove(S, 0);
      ops_add(S->m->ops, OPS_EVENTS, 1);
      int rc = sw_circle(S, b);
      if (rc != 0) return rc;
    } else if (k > 0 && p[k].x == p[k - 1].x && p[k].y == p[k - 1].y) {
      ++*duplicates;   /* sorted: the first of equal points has the smallest index */
      k++;
    } else {
      ops_add(S->m->ops, OPS_EVENTS, 1);
      int rc = sw_site(S, k++);
      if (rc != 0) return rc;
    }
  }
}

/* Bands of y for the hints: about 2 sqrt(n) over the points' range, as
** many as the boundary has nodes for uniform points. */
static int sw_hints_init(lot_sweep *S) {
  const lot_mesh *m = S->m;
  double lo = m->p[0].y, hi = lo;
  for (uint32_t k = 1; k < m->np; k++) {
    lo = m->p[k].y < lo ? m->p[k].y : lo;
    hi = m->p[k].y > hi ? m->p[k].y : hi;
  }
  uint32_t b = 16;
  while ((double)b * b < 4.0 * m->np && b < (1u << 24)) b *= 2;
  S->hint = malloc((size_t)b * sizeof *S->hint);
  if (S->hint == NULL) return -1;
  for (uint32_t i = 0; i < b; i++) S->hint[i] = (sw_hint){SW_NONE, 0};
  S->nhint = b;
  S->y0 = lo;
  S->yscale = hi > lo ? b / (hi - lo) : 0;
  return 0;
}

/* The sweep's arrays only grow: their final sizes are its peak, held on
** top of the mesh's for the run's length. */
static void sw_memory(const lot_sweep *S) {
  int64_t b = (int64_t)(S->ndcap * sizeof *S->nd + S->ecap * sizeof *S->ec
                        + S->hcap * sizeof *S->hp + S->hposcap * sizeof *S->hpos
                        + S->ikcap * sizeof *S->ik + S->nhint * sizeof *S->hint);
  ops_memory(S->m->ops, b);
  ops_memory(S->m->ops, -b);
}

int lot_sweep_run(lot_mesh *m, const shape_sweep *s, size_t *duplicates) {
  lot_sweep S;
  memset(&S, 0, sizeof S);
  S.m = m;
  S.s = s;
  S.freed = SW_NONE;
  S.rng = GEOM_STATE_LOT_SWEEP;
  *duplicates = 0;
  m->nt = 0;
  S.framed = s->frame != NULL && s->frame(s->ctx, m->p, m->np, &S.fr);
  int rc = -1;
  if (sw_hints_init(&S) != 0 || sw_node_new(&S, SW_NONE) != SW_HEAD) goto done;
  S.nd[SW_HEAD].h = SW_LEVELS;
  for (int l = 0; l < SW_LEVELS; l++) S.nd[SW_HEAD].nx[l] = SW_NONE;
  rc = sw_events(&S, duplicates);
  if (rc != 0) goto done;
  rc = -2;
  if (m->nt == 0) goto done;
  rc = sw_ghosts(&S);
  m->last = 0;
done:
  sw_memory(&S);
  free(S.nd);
  free(S.ec);
  free(S.hp);
  free(S.hpos);
  free(S.ik);
  free(S.hint);
  return rc;
}
