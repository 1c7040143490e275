/*
** sweep_constrained.c: the constrained sweepline of section 2.5.2 (rows
** sweep-constrained and, through sweep_monotone.c, sweep-monotone).
**
** A vertical line sweeps the sites in the lexicographic order (x, then y).
** Its status is the boundary of the part of the constrained triangulation
** that is certain whatever lies to the right, as in 2.5.1 (lot/sweep.c):
** sites whose arcs meet the sweepline, bottom to top, a site possibly
** several times; each pair of consecutive sites has a breakpoint, the
** contact point of the circle through them tangent to the sweepline.  The
** active constraints (a site swept, the other not) cut it into pieces: the
** constraint tree of the thesis is here two skip lists of the same cost,
** one of the active constraints in their order along the sweepline (an
** entry knows the piece above it; S->bottom is the lowest piece), and one
** per piece of its sites (a head node of full height starts each).
**
** Site event C, in three stages (the thesis's, generalised below):
**   incoming: the constraints through C (found by one search of the
**     constraint list, orientation tests: each is adjacent to the next)
**     end there; one that runs on past C is cut at C, its rest becoming an
**     outgoing constraint of C (a site inside a segment cuts it, as lot/
**     cuts it);
**   locate: in each of the i + 1 pieces around C (one when i = 0), the arc
**     whose breakpoints hold C (the breakpoint search of 2.5.1 within the
**     piece) gets C as B C B; a piece is then cut at C.  The thesis joins
**     C to the constraint's other end without a search; that arc is the
**     one found whenever the end's arc reaches C's height, but a steep or
**     vertical constraint leaves it below C (the arc's breakpoint is that
**     of a circle through the end and a site behind it), and C's edge then
**     goes to the arc found, the sites between closing a pocket;
**   outgoing: the pieces between consecutive constraints at C close into
**     pockets (closed lists, first and last node C: no site can reach them
**     again), the piece below the lowest and above the highest incoming
**     constraint join at C, and the j outgoing constraints (sorted round C,
**     overlapping collinear ones cut at the nearer end) cut it into j + 1.
** Circle event (a, b, c consecutive in a piece or pocket, c right of a ->
** b, keyed by the rightmost point of their circumcircle): triangle a c b.
**
** Why the unmodified circle is safe (the thesis's argument, 2.5.2): the
** circle of a, b, c may hold a site d behind a constraint, which a
** visibility-restricted circle would not; d's site event comes before the
** event.  It could cancel the event only by joining d to a, b or c, i.e.
** by finding one of their arcs in d's piece; but a constraint separates d
** from the triangle, so d lies in another piece, whose lists hold other
** nodes.  So the event waits for its key, when the breakpoints of a b and
** b c meet (both are circles through b tangent to the sweepline, whatever
** the constraints), and the order of every piece's breakpoints is kept.
**
** The order of equal keys is fixed (creation order); the triangles are
** then handed to sweep_finish.c, which checks them exactly and settles the
** ties with lot's tie-break (Lawson's flips with paradigm_inshape's
** perturbation), as lot's own sweep ends.  A pocket goes on in the key
** order of the piece it came from, so its breakpoints stay ordered; no
** proof here that this order is Delaunay inside a pocket, but the check
** would stop a corner cut over a site, the pass would flip a non-Delaunay
** edge (and counts it), and on generic sites it flips none
** (bench_paradigm_sweep, tests/test_paradigm_sweep.c).
**
** Cost: O(n log n) expected for n sites and e segment pieces: every event
** is one search or update of a skip list, O(log n) expected, and a heap
** operation; a site with i incoming and j outgoing constraints costs
** O((i + j + 1) log n); there are n site events and one circle event per
** triangle.  Plus the tie pass: O(n) with no ties.  Crossing segments are
** found as Shamos and Hoey find them: each pair of constraints that
** become neighbours in the constraint list is tested once.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "geom_mem_internal.h"
#include "splitmix.h"
#include "order.h"
#include "paradigm_internal.h"
#include "shape_sweep_internal.h"

#define CS_LEVELS 12        /* towers of at most 12 levels, p = 1/4 */
#define CS_NONE UINT32_MAX

/* A skip list's tower (both lists: sites, constraints); heights from a
** fixed generator (GEOM_STATE_LOT_SWEEP, lot's sweep's), so every run
** builds the same lists. */
typedef struct cs_tower {
  uint32_t h;
  uint32_t nx[CS_LEVELS], pv[CS_LEVELS];
} cs_tower;

typedef struct cs_node {
  geom_point pt;            /* its site's point (CS_NONE site: a list's head) */
  uint32_t site;
} cs_node;

/* A waiting circle event: its triple is its node's predecessor, the node
** and its successor, which do not change while it waits. */
typedef struct cs_event {
  double lo, hi;            /* lo <= key <= hi */
  uint32_t node, seq;       /* the middle node; creation order */
} cs_event;

/* An active constraint, u swept and v not; above: the head of the piece
** above it. */
typedef struct cs_con {
  uint32_t u, v, seg, above;
} cs_con;

/* A constraint piece waiting to start at its site (a list per site). */
typedef struct cs_out {
  uint32_t v, seg, next;
} cs_out;

typedef struct cs_state {
  const geom_point *p;
  size_t n;
  ops_counts *c;
  const shape_sweep *s;
  cs_node *nd;
  cs_tower *nt;             /* the nodes' towers */
  size_t nnd, ndcap, ntcap;
  uint32_t freed;
  cs_event *hp;
  size_t nh, hcap;
  uint32_t *hpos;           /* per node: its event's place in hp (CS_NONE: none) */
  size_t hposcap;
  cs_con *cn;               /* cn[0]: the constraint list's head */
  cs_tower *ct;             /* their towers */
  size_t ncn, cncap, ctcap;
  uint32_t cnfree;
  cs_out *out;
  size_t nout, outcap;
  uint32_t *outhead;        /* per site: its first waiting piece */
  uint32_t bottom;          /* the head of the lowest piece */
  uint32_t *tri;            /* the triangles made, 3 per triangle */
  size_t ntri, tricap;
  uint32_t *made;           /* the constraint pieces made, 2 per piece */
  size_t nmade, madecap;
  uint32_t *thru;           /* a site event's constraints through its site */
  size_t thrucap;
  uint32_t *part;           /* per piece around it: the C node, the head above */
  size_t partcap;
  uint32_t *touch;          /* the nodes it made (their events anew) */
  size_t ntouch, touchcap;
  uint32_t *drop;           /* the heads of the empty pockets it made (freed) */
  size_t ndrop, dropcap;
  cs_out *og;               /* its outgoing constraints, sorted round it */
  size_t ogcap;
  uint32_t seq;
  uint64_t rng;
  size_t pockets;           /* pockets closed with sites in them */
  char *err;
  size_t errlen;
} cs_state;

/* A tower of random height for entry x of towers t (1 to CS_LEVELS, p =
** 1/4), or of full height (a list's head), unlinked. */
static void cs_tower_init(cs_state *S, cs_tower *t, int head) {
  uint64_t r = geom_splitmix64(&S->rng);
  t->h = 1;
  while (t->h < CS_LEVELS && (r & 3) == 0) t->h++, r >>= 2;
  if (head) t->h = CS_LEVELS;
  for (int l = 0; l < CS_LEVELS; l++) t->nx[l] = t->pv[l] = CS_NONE;
}

/* A new node for site v (CS_NONE when out of memory); v == CS_NONE makes a
** head. */
static uint32_t cs_node_new(cs_state *S, uint32_t v) {
  uint32_t x = S->freed;
  if (x != CS_NONE) {
    S->freed = S->nt[x].nx[0];
  } else {
    size_t need = S->nnd + 1;
    if (geom_grow((void **)&S->nd, &S->ndcap, need, sizeof *S->nd) != 0
        || geom_grow((void **)&S->nt, &S->ntcap, need, sizeof *S->nt) != 0
        || geom_grow((void **)&S->hpos, &S->hposcap, need, sizeof *S->hpos) != 0)
      return CS_NONE;
    x = (uint32_t)S->nnd++;
  }
  cs_tower_init(S, &S->nt[x], v == CS_NONE);
  S->nd[x].pt = v != CS_NONE ? S->p[v] : (geom_point){0, 0};
  S->nd[x].site = v;
  S->hpos[x] = CS_NONE;
  return x;
}

static void cs_node_free(cs_state *S, uint32_t x) {
  S->nt[x].nx[0] = S->freed;
  S->freed = x;
}

/* ---- skip lists (the pieces' sites, the active constraints) ------------- */

/* Link x after b: at level l the predecessor is the nearest entry at or
** before b whose tower reaches l (a head reaches every level). */
static void cs_link_after(cs_tower *t, uint32_t b, uint32_t x) {
  uint32_t p = b;
  for (uint32_t l = 0; l < t[x].h; l++) {
    while (t[p].h <= l) p = t[p].pv[l - 1];
    uint32_t q = t[p].nx[l];
    t[x].pv[l] = p, t[x].nx[l] = q, t[p].nx[l] = x;
    if (q != CS_NONE) t[q].pv[l] = x;
  }
}

static void cs_unlink(cs_tower *t, uint32_t x) {
  for (uint32_t l = 0; l < t[x].h; l++) {
    uint32_t p = t[x].pv[l], q = t[x].nx[l];
    t[p].nx[l] = q;
    if (q != CS_NONE) t[q].pv[l] = p;
  }
}

/* Cut the list after x: the entries after it move to the list of head H
** (empty before).  O(log n) expected. */
static void cs_split(cs_tower *t, uint32_t x, uint32_t H) {
  uint32_t p = x;
  for (uint32_t l = 0; l < CS_LEVELS; l++) {
    while (t[p].h <= l) p = t[p].pv[l - 1];
    uint32_t q = t[p].nx[l];
    t[H].nx[l] = q, t[p].nx[l] = CS_NONE;
    if (q != CS_NONE) t[q].pv[l] = H;
  }
}

/* The last entry of the list of head h (h itself when empty). */
static uint32_t cs_last(const cs_tower *t, uint32_t h) {
  uint32_t p = h;
  for (int l = CS_LEVELS - 1; l >= 0; l--)
    while (t[p].nx[l] != CS_NONE) p = t[p].nx[l];
  return p;
}

/* Append the list of head B to the list of head A (B is left empty).
** O(log n) expected. */
static void cs_join(cs_tower *t, uint32_t A, uint32_t B) {
  uint32_t p = A;
  for (int l = CS_LEVELS - 1; l >= 0; l--) {
    while (t[p].nx[l] != CS_NONE) p = t[p].nx[l];
    uint32_t q = t[B].nx[l];
    t[p].nx[l] = q, t[B].nx[l] = CS_NONE;
    if (q != CS_NONE) t[q].pv[l] = p;
  }
}

/* The node whose arc meets the sweepline at X in the list of head h: the
** last one whose breakpoint with its predecessor lies below X (the first
** node has none); h when the list is empty.  Each breakpoint test counts as
** a location step. */
static uint32_t cs_locate(cs_state *S, uint32_t h, geom_point X) {
  const cs_node *nd = S->nd;
  const cs_tower *t = S->nt;
  uint32_t cur = h;
  for (int l = CS_LEVELS - 1; l >= 0; l--)
    for (;;) {
      uint32_t q = t[cur].nx[l];
      if (q == CS_NONE) break;
      uint32_t a = t[q].pv[0];
      if (a != h) {
        ops_add(S->c, OPS_LOCATE, 1);
        if (!S->s->above(S->s->ctx, nd[a].pt, nd[q].pt, X)) break;
      }
      cur = q;
    }
  return cur;
}

/* ---- the event heap ------------------------------------------------------ */

static void cs_points(const cs_state *S, uint32_t b, geom_point t[3]) {
  const cs_node *nd = S->nd;
  t[0] = nd[S->nt[b].pv[0]].pt, t[1] = nd[b].pt, t[2] = nd[S->nt[b].nx[0]].pt;
}

/* Do the events of nodes a and b have one triangle (a pocket's last
** triangle has one event from each end)?  Their keys are then equal. */
static int cs_same_triangle(const cs_state *S, uint32_t a, uint32_t b) {
  const cs_tower *t = S->nt;
  uint32_t u[3] = {t[a].pv[0], a, t[a].nx[0]}, v[3] = {t[b].pv[0], b, t[b].nx[0]};
  int shared = 0;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) shared += S->nd[u[i]].site == S->nd[v[j]].site;
  return shared == 3;
}

/* Does event a come before b?  Disjoint bounds, else the exact keys, else
** creation order. */
static int cs_before(const cs_state *S, const cs_event *a, const cs_event *b) {
  if (a->hi < b->lo) return 1;
  if (b->hi < a->lo) return 0;
  if (cs_same_triangle(S, a->node, b->node)) return a->seq < b->seq;
  geom_point ta[3], tb[3];
  cs_points(S, a->node, ta);
  cs_points(S, b->node, tb);
  int c = S->s->key_cmp(S->s->ctx, ta, 0, tb, 0);
  return c != 0 ? c < 0 : a->seq < b->seq;
}

/* Does event e come before the site event at x?  Ties: the circle first. */
static int cs_before_site(const cs_state *S, const cs_event *e, double x) {
  if (e->hi < x) return 1;
  if (e->lo > x) return 0;
  geom_point t[3];
  cs_points(S, e->node, t);
  return S->s->key_cmp(S->s->ctx, t, 0, NULL, x) <= 0;
}

static void cs_heap_put(cs_state *S, size_t i, const cs_event *e) {
  S->hp[i] = *e;
  S->hpos[e->node] = (uint32_t)i;
}

/* e into the hole at i: up while it comes before its parent, else down. */
static void cs_sift(cs_state *S, size_t i, const cs_event *e) {
  while (i > 0 && cs_before(S, e, &S->hp[(i - 1) / 2])) {
    cs_heap_put(S, i, &S->hp[(i - 1) / 2]);
    i = (i - 1) / 2;
  }
  for (;;) {
    size_t c = 2 * i + 1;
    if (c >= S->nh) break;
    if (c + 1 < S->nh) c += (size_t)cs_before(S, &S->hp[c + 1], &S->hp[c]);
    if (!cs_before(S, &S->hp[c], e)) break;
    cs_heap_put(S, i, &S->hp[c]);
    i = c;
  }
  cs_heap_put(S, i, e);
}

/* Take node b's event, if any, out of the heap (before b's neighbours
** change: the comparisons read its triple from them). */
static void cs_cancel(cs_state *S, uint32_t b) {
  size_t i = S->hpos[b];
  if (i == CS_NONE) return;
  S->hpos[b] = CS_NONE;
  cs_event last = S->hp[--S->nh];
  if (i < S->nh) cs_sift(S, i, &last);
}

/* Node b's event anew: cancelled, then scheduled if its predecessor, b and
** its successor close one (the closing test: an orientation).  0, or -1
** when out of memory. */
static int cs_schedule(cs_state *S, uint32_t b) {
  if (b == CS_NONE || S->nd[b].site == CS_NONE) return 0;
  cs_cancel(S, b);
  uint32_t a = S->nt[b].pv[0], c = S->nt[b].nx[0];
  if (S->nd[a].site == CS_NONE || c == CS_NONE) return 0;
  cs_event e = {0, 0, b, S->seq++};
  geom_point t[3];
  cs_points(S, b, t);
  ops_add(S->c, OPS_ORIENT, 1);
  if (!S->s->closes(S->s->ctx, t[0], t[1], t[2])) return 0;
  S->s->key_bounds(S->s->ctx, t, &e.lo, &e.hi);
  if (geom_grow((void **)&S->hp, &S->hcap, S->nh + 1, sizeof *S->hp) != 0) return -1;
  S->nh++;
  cs_sift(S, S->nh - 1, &e);
  return 0;
}

/* Node x and its two neighbours anew. */
static int cs_touch(cs_state *S, uint32_t x) {
  if (cs_schedule(S, S->nt[x].pv[0]) != 0 || cs_schedule(S, x) != 0) return -1;
  return cs_schedule(S, S->nt[x].nx[0]);
}

/* Free the list of head h, events and all (a pocket done, or empty). */
static void cs_drop(cs_state *S, uint32_t h) {
  for (uint32_t x = S->nt[h].nx[0], y; x != CS_NONE; x = y) {
    y = S->nt[x].nx[0];
    cs_cancel(S, x);
    cs_node_free(S, x);
  }
  cs_node_free(S, h);
}

/* The head of x's list. */
static uint32_t cs_head(const cs_state *S, uint32_t x) {
  while (S->nd[x].site != CS_NONE) x = S->nt[x].pv[0];
  return x;
}

/* ---- circle events --------------------------------------------------------- */

static int cs_emit(cs_state *S, uint32_t a, uint32_t b, uint32_t c) {
  if (geom_grow((void **)&S->tri, &S->tricap, 3 * (S->ntri + 1), sizeof *S->tri) != 0)
    return -1;
  uint32_t *t = S->tri + 3 * S->ntri++;
  t[0] = a, t[1] = b, t[2] = c;
  return 0;
}

/* The event of node b (a, b, c consecutive): triangle a c b, b leaves its
** list and a c is a new edge, unless it closes a pocket (a c a' or c' a c:
** the edge was there, a constraint or the pocket's first edge). */
static int cs_circle(cs_state *S, uint32_t b) {
  const cs_node *nd = S->nd;
  uint32_t a = S->nt[b].pv[0], c = S->nt[b].nx[0], an = S->nt[c].nx[0], cp = S->nt[a].pv[0];
  if (cs_emit(S, nd[a].site, nd[c].site, nd[b].site) != 0) return -1;
  int closes = (an != CS_NONE && nd[an].site == nd[a].site)
               || (nd[cp].site != CS_NONE && nd[cp].site == nd[c].site);
  ops_add(S->c, OPS_EDGES_MADE, (uint64_t)!closes);
  cs_cancel(S, a);
  cs_cancel(S, c);
  cs_unlink(S->nt, b);
  cs_node_free(S, b);
  if (closes) {   /* the pocket's last triangle: what is left is the edge a c */
    cs_drop(S, cs_head(S, a));
    return 0;
  }
  if (cs_schedule(S, a) != 0) return -1;
  return cs_schedule(S, c);
}

/* ---- the constraint list ------------------------------------------------ */

/* A new active constraint u -> v (input row seg), unlinked; CS_NONE when
** out of memory. */
static uint32_t cs_con_new(cs_state *S, uint32_t u, uint32_t v, uint32_t seg) {
  uint32_t x = S->cnfree;
  if (x != CS_NONE) {
    S->cnfree = S->ct[x].nx[0];
  } else {
    if (geom_grow((void **)&S->cn, &S->cncap, S->ncn + 1, sizeof *S->cn) != 0
        || geom_grow((void **)&S->ct, &S->ctcap, S->ncn + 1, sizeof *S->ct) != 0)
      return CS_NONE;
    x = (uint32_t)S->ncn++;
  }
  cs_tower_init(S, &S->ct[x], x == 0);
  S->cn[x] = (cs_con){u, v, seg, CS_NONE};
  return x;
}

/* Is C strictly above the active constraint e (left of u -> v)? */
static int cs_con_side(cs_state *S, uint32_t e, geom_point C) {
  return ops_orient(S->c, S->p[S->cn[e].u], S->p[S->cn[e].v], C);
}

/* The last active constraint C lies strictly above (0: the list's head).
** Orientation tests: the constraints crossing the sweepline never cross
** each other (a crossing is refused before the sweep reaches it), so the
** order along the sweepline is the order of the list.  O(log n). */
static uint32_t cs_con_find(cs_state *S, geom_point C) {
  const cs_tower *t = S->ct;
  uint32_t cur = 0;
  for (int l = CS_LEVELS - 1; l >= 0; l--)
    while (t[cur].nx[l] != CS_NONE && cs_con_side(S, t[cur].nx[l], C) > 0) cur = t[cur].nx[l];
  return cur;
}

/* The head of the piece above entry e (0: the lowest piece). */
static uint32_t cs_piece_above(const cs_state *S, uint32_t e) {
  return e == 0 ? S->bottom : S->cn[e].above;
}

/* Do the active constraints e and f (neighbours now) cross at a point
** inside both?  Then the one-line refusal.  An end of one inside the
** other is no crossing: the sweep cuts the other there. */
static int cs_con_cross(cs_state *S, uint32_t e, uint32_t f) {
  if (e == 0 || f == CS_NONE) return 0;
  const geom_point *p = S->p;
  if (!ops_segments_cross(S->c, p[S->cn[e].u], p[S->cn[e].v], p[S->cn[f].u], p[S->cn[f].v]))
    return 0;
  uint32_t s = S->cn[e].seg, r = S->cn[f].seg;
  snprintf(S->err, S->errlen, "segments %u and %u cross", s < r ? s : r, s < r ? r : s);
  return -1;
}

/* A waiting piece k -> v of input row seg: 0, or -1 out of memory. */
static int cs_out_push(cs_state *S, uint32_t k, uint32_t v, uint32_t seg) {
  if (geom_grow((void **)&S->out, &S->outcap, S->nout + 1, sizeof *S->out) != 0) return -1;
  S->out[S->nout] = (cs_out){v, seg, S->outhead[k]};
  S->outhead[k] = (uint32_t)S->nout++;
  return 0;
}

/* ---- site events ------------------------------------------------------- */

/* Stage 1: the constraints through site k, in S->thru (bottom to top,
** *ni of them; *lo the entry below them).  They are neighbours in the list
** after the entry below C; one that runs on past C is cut there (its rest
** waits as an outgoing piece of C).  0, or -1 out of memory. */
static int cs_incoming(cs_state *S, uint32_t k, uint32_t *lo, size_t *ni) {
  geom_point C = S->p[k];
  *lo = cs_con_find(S, C);
  *ni = 0;
  for (uint32_t e = S->ct[*lo].nx[0]; e != CS_NONE && cs_con_side(S, e, C) == 0;
       e = S->ct[e].nx[0]) {
    if (S->cn[e].v != k && cs_out_push(S, k, S->cn[e].v, S->cn[e].seg) != 0) return -1;
    S->cn[e].v = k;
    if (geom_grow((void **)&S->thru, &S->thrucap, *ni + 1, sizeof *S->thru) != 0) return -1;
    S->thru[(*ni)++] = e;
  }
  return 0;
}

/* Remember the head of an empty pocket, freed at the site event's end. */
static int cs_dropped(cs_state *S, uint32_t h) {
  if (geom_grow((void **)&S->drop, &S->dropcap, S->ndrop + 1, sizeof *S->drop) != 0) return -1;
  S->drop[S->ndrop++] = h;
  return 0;
}

static int cs_touched(cs_state *S, uint32_t x) {
  if (geom_grow((void **)&S->touch, &S->touchcap, S->ntouch + 1, sizeof *S->touch) != 0)
    return -1;
  S->touch[S->ntouch++] = x;
  return 0;
}

/* A new node of site v linked after b (and remembered for its event). */
static uint32_t cs_add(cs_state *S, uint32_t b, uint32_t v) {
  uint32_t x = cs_node_new(S, v);
  if (x == CS_NONE || cs_touched(S, x) != 0) return CS_NONE;
  cs_link_after(S->nt, b, x);
  return x;
}

/* Stage 2 in the piece of head h: the arc w holding C gets C as w C w
** (only w C when w lies on the sweepline too: w is then the top of a
** column and has no successor in the piece), and the piece is cut after
** C: *up the head of the part above.  w C is a new edge unless w is the
** far end of the constraint (lo_u or hi_u) below or above the piece; *xp
** the C node.  0,
** -1 out of memory, -2 the structure broke. */
static int cs_place(cs_state *S, uint32_t h, uint32_t k, uint32_t lo_u, uint32_t hi_u,
                    uint32_t *xp, uint32_t *up) {
  uint32_t w = cs_locate(S, h, S->p[k]), x, w2 = CS_NONE;
  *up = cs_node_new(S, CS_NONE);
  if (*up == CS_NONE) return -1;
  int column = w != h && S->nd[w].pt.x == S->p[k].x;
  if (column && S->nt[w].nx[0] != CS_NONE) return -2;
  if (w != h) cs_cancel(S, w);
  if ((x = cs_add(S, w, k)) == CS_NONE) return -1;
  if (w != h && !column && (w2 = cs_add(S, x, S->nd[w].site)) == CS_NONE) return -1;
  uint32_t ws = S->nd[w].site;
  ops_add(S->c, OPS_EDGES_MADE, (uint64_t)(w != h && ws != lo_u && ws != hi_u));
  cs_split(S->nt, x, *up);
  *xp = x;
  return 0;
}

/* Is the list of head h the degenerate pocket of one node of site u (its
** nodes after `from`, CS_NONE: all, end exclusive)? */
static int cs_lone(const cs_state *S, uint32_t h, uint32_t u, uint32_t end) {
  uint32_t f = S->nt[h].nx[0];
  return f == CS_NONE || (S->nd[f].site == u && S->nt[f].nx[0] == end);
}

/* Stage 3a: the pieces between consecutive constraints through C close
** into pockets (C first and last): the part above C of the piece below
** constraint m, the part below C of the piece above it.  part[2m] is the
** C node of piece m, part[2m + 1] the head of its part above C.  A pocket
** of one node between two C's is the constraint itself: dropped. */
static int cs_pockets(cs_state *S, uint32_t k, size_t ni) {
  for (size_t m = 1; m <= ni; m++) {
    uint32_t u = S->cn[S->thru[m - 1]].u, upper = S->part[2 * (m - 1) + 1];
    uint32_t lower = S->cn[S->thru[m - 1]].above;
    if (cs_lone(S, upper, u, CS_NONE)) {
      if (cs_dropped(S, upper) != 0) return -1;
    } else {
      S->pockets++;
      if (cs_add(S, upper, k) == CS_NONE || cs_add(S, cs_last(S->nt, upper), k) == CS_NONE)
        return -1;
    }
    if (cs_lone(S, lower, u, S->part[2 * m])) {
      if (cs_dropped(S, lower) != 0) return -1;
    } else {
      S->pockets++;
      if (cs_add(S, lower, k) == CS_NONE) return -1;
    }
  }
  return 0;
}

/* Sort a[0 .. n - 1] round C, bottom to top (v before w when w lies left
** of C -> v: every piece leaving C points into the open right half-plane or
** straight up, so this order is total up to collinear pieces).  Merge
** sort, O(n log n) orientation tests. */
static void cs_sort_round(cs_state *S, geom_point C, cs_out *a, cs_out *tmp, size_t n) {
  if (n < 2) return;
  size_t h = n / 2, i = 0, j = h, o = 0;
  cs_sort_round(S, C, a, tmp, h);
  cs_sort_round(S, C, a + h, tmp, n - h);
  while (i < h || j < n) {
    int left = j == n || (i < h && ops_orient(S->c, C, S->p[a[j].v], S->p[a[i].v]) <= 0);
    tmp[o++] = left ? a[i++] : a[j++];
  }
  memcpy(a, tmp, n * sizeof *a);
}

/* Stage 3b: the pieces leaving site k, sorted round it into S->og (*nj of
** them).  Collinear pieces overlap: the nearest end keeps the piece, each
** longer one waits at that end for its rest (equal ones merge, as lot/
** merges them).  0, or -1 out of memory. */
static int cs_outgoing(cs_state *S, uint32_t k, size_t *nj) {
  size_t n = 0;
  for (uint32_t o = S->outhead[k]; o != CS_NONE; o = S->out[o].next) n++;
  if (geom_grow((void **)&S->og, &S->ogcap, 2 * n + 2, sizeof *S->og) != 0) return -1;
  n = 0;
  for (uint32_t o = S->outhead[k]; o != CS_NONE; o = S->out[o].next) S->og[n++] = S->out[o];
  geom_point C = S->p[k];
  cs_sort_round(S, C, S->og, S->og + n, n);
  *nj = 0;
  for (size_t i = 0; i < n; i++) {
    cs_out *q = &S->og[*nj - (*nj > 0)];
    if (*nj > 0 && ops_orient(S->c, C, S->p[q->v], S->p[S->og[i].v]) == 0) {
      cs_out far = S->og[i];
      if (geom_lexless(S->p[far.v], S->p[q->v])) far = *q, *q = S->og[i];
      if (far.v != q->v && cs_out_push(S, q->v, far.v, far.seg) != 0) return -1;
      continue;
    }
    S->og[(*nj)++] = S->og[i];
  }
  return 0;
}

/* Record constraint piece u v (the tie pass never flips it). */
static int cs_made(cs_state *S, uint32_t u, uint32_t v) {
  if (geom_grow((void **)&S->made, &S->madecap, 2 * S->nmade + 2, sizeof *S->made) != 0)
    return -1;
  S->made[2 * S->nmade] = u, S->made[2 * S->nmade++ + 1] = v;
  return 0;
}

/* Stage 3c: the constraints through C leave the list; the piece below the
** lowest (head h0) and the part above C of the piece above the highest
** (head top) join at C when nothing leaves C, else the j pieces leaving C
** enter the list there, with a piece [C] between each two.  The new
** neighbours in the list are tested for a crossing. */
static int cs_restructure(cs_state *S, uint32_t k, uint32_t lo, size_t ni, size_t nj) {
  uint32_t h0 = cs_piece_above(S, lo), top = S->part[2 * ni + 1], prev = lo;
  for (size_t m = 0; m < ni; m++) {
    uint32_t e = S->thru[m];
    if (cs_made(S, S->cn[e].u, k) != 0) return -1;
    cs_unlink(S->ct, e);
    S->ct[e].nx[0] = S->cnfree, S->cnfree = e;
  }
  if (nj == 0) {
    cs_join(S->nt, h0, top);
    cs_node_free(S, top);
    return cs_con_cross(S, lo, S->ct[lo].nx[0]);
  }
  for (size_t q = 0; q < nj; q++) {
    uint32_t h = q + 1 < nj ? cs_node_new(S, CS_NONE) : top;
    if (h == CS_NONE || cs_add(S, h, k) == CS_NONE) return -1;
    uint32_t e = cs_con_new(S, k, S->og[q].v, S->og[q].seg);
    if (e == CS_NONE) return -1;
    S->cn[e].above = h;
    cs_link_after(S->ct, prev, e);
    ops_add(S->c, OPS_EDGES_MADE, 1);
    prev = e;
  }
  if (cs_con_cross(S, lo, S->ct[lo].nx[0]) != 0) return -1;
  return cs_con_cross(S, prev, S->ct[prev].nx[0]);
}

/* The site event of site k: 0, -1 (out of memory, or a refusal in
** S->err), -2 the structure broke. */
static int cs_site(cs_state *S, uint32_t k) {
  uint32_t lo;
  size_t ni, nj;
  S->ntouch = S->ndrop = 0;
  if (cs_incoming(S, k, &lo, &ni) != 0) return -1;
  if (geom_grow((void **)&S->part, &S->partcap, 2 * ni + 2, sizeof *S->part) != 0) return -1;
  for (size_t m = 0; m <= ni; m++) {
    uint32_t h = cs_piece_above(S, m == 0 ? lo : S->thru[m - 1]);
    uint32_t lo_u = m > 0 ? S->cn[S->thru[m - 1]].u : CS_NONE;
    uint32_t hi_u = m < ni ? S->cn[S->thru[m]].u : CS_NONE;
    int rc = cs_place(S, h, k, lo_u, hi_u, &S->part[2 * m], &S->part[2 * m + 1]);
    if (rc != 0) return rc;
  }
  if (cs_pockets(S, k, ni) != 0 || cs_outgoing(S, k, &nj) != 0) return -1;
  if (cs_restructure(S, k, lo, ni, nj) != 0) return -1;
  for (size_t t = 0; t < S->ntouch; t++)
    if (cs_touch(S, S->touch[t]) != 0) return -1;
  for (size_t d = 0; d < S->ndrop; d++) cs_drop(S, S->drop[d]);
  return 0;
}

/* ---- the run ------------------------------------------------------------ */

/* Every event in order: the sites in the lexicographic order (ord), the
** circle events between them.  0, -1 (S->err), -2 the structure broke. */
static int cs_events(cs_state *S, const uint32_t *ord) {
  size_t k = 0;
  for (;;) {
    if (k == S->n && S->nh == 0) return 0;
    int rc;
    if (S->nh > 0 && (k == S->n || cs_before_site(S, &S->hp[0], S->p[ord[k]].x))) {
      uint32_t b = S->hp[0].node;
      cs_cancel(S, b);
      rc = cs_circle(S, b);
    } else {
      rc = cs_site(S, ord[k++]);
    }
    ops_add(S->c, OPS_EVENTS, 1);
    if (rc != 0) return rc;
  }
}

/* The sites' order and their waiting pieces (each segment from its first
** end in that order); a segment from a point to itself is refused.  0, or
** -1 (S->err). */
static int cs_prepare(cs_state *S, const paradigm_input *in, uint32_t **ord) {
  size_t n = S->n;
  *ord = malloc((n ? n : 1) * sizeof **ord);
  S->outhead = malloc((n ? n : 1) * sizeof *S->outhead);
  int rc = *ord && S->outhead ? lot_order_lexicographic(S->p, (uint32_t)n, *ord) : -1;
  for (size_t i = 0; i < n && rc == 0; i++) S->outhead[i] = CS_NONE;
  for (size_t s = 0; s < in->nsegments && rc == 0; s++) {
    uint32_t u = in->segments[2 * s], v = in->segments[2 * s + 1];
    if (u == v) {
      snprintf(S->err, S->errlen, "segment %zu: both ends are point %u", s, u);
      return -1;
    }
    if (geom_lexless(S->p[v], S->p[u])) u = in->segments[2 * s + 1], v = in->segments[2 * s];
    rc = cs_out_push(S, u, v, (uint32_t)s);
  }
  if (rc != 0) snprintf(S->err, S->errlen, "out of memory for %zu segments", in->nsegments);
  return rc;
}

/* The arrays only grow: their final sizes are the sweep's peak, held on
** top of the triangles for the run's length. */
static void cs_memory(const cs_state *S) {
  int64_t b = (int64_t)(S->ndcap * sizeof *S->nd + S->ntcap * sizeof *S->nt
                        + S->hcap * sizeof *S->hp + S->hposcap * sizeof *S->hpos
                        + S->cncap * sizeof *S->cn + S->ctcap * sizeof *S->ct
                        + S->outcap * sizeof *S->out + S->n * sizeof *S->outhead
                        + S->tricap * sizeof *S->tri + S->madecap * sizeof *S->made
                        + S->ogcap * sizeof *S->og + S->n * sizeof(uint32_t));
  ops_memory(S->c, b);
  ops_memory(S->c, -b);
}

static void cs_free(cs_state *S) {
  free(S->nd), free(S->nt), free(S->hp), free(S->hpos), free(S->cn), free(S->ct);
  free(S->out), free(S->outhead), free(S->tri), free(S->made), free(S->thru);
  free(S->part), free(S->touch), free(S->og), free(S->drop);
}

/* The sweep on in (distinct sites, in->nsegments segments), then the
** check and the tie pass: 0, or -1 with a one-line message.  *pockets (may
** be NULL): the pockets closed with sites in them. */
static int cs_run(const paradigm_input *in, paradigm_output *out, size_t *pockets, char *err,
                  size_t errlen) {
  cs_state S;
  memset(&S, 0, sizeof S);
  S.p = in->p, S.n = in->n, S.c = &out->ops, S.s = &shape_sweep_circle;
  S.freed = S.cnfree = CS_NONE, S.rng = GEOM_STATE_LOT_SWEEP, S.err = err, S.errlen = errlen;
  err[0] = '\0';
  uint32_t *ord = NULL;
  int rc = cs_prepare(&S, in, &ord);
  if (rc == 0 && (cs_con_new(&S, 0, 0, 0) != 0 || (S.bottom = cs_node_new(&S, CS_NONE)) == CS_NONE))
    rc = -1;
  if (rc == 0) rc = cs_events(&S, ord);
  cs_memory(&S);
  if (rc == -2)
    snprintf(err, errlen, "the sweep's boundary broke (a site on the sweepline below another's "
             "arc): a bug, please report the input");
  else if (rc != 0 && err[0] == '\0')
    snprintf(err, errlen, "out of memory for the sweep of %zu sites", in->n);
  if (rc == 0) rc = paradigm_sweep_finish(in, S.tri, S.ntri, S.made, S.nmade, S.c, err, errlen);
  if (rc == 0) out->tri = S.tri, out->ntri = S.ntri, S.tri = NULL;
  if (pockets != NULL) *pockets = S.pockets;
  cs_free(&S);
  free(ord);
  return rc == 0 ? 0 : -1;
}

/* A polygon (simple; convex for PARADIGM_CONVEX, checked as the convex
** rows check it; x-monotone for sweep-monotone): its sides as segments,
** the triangles outside dropped.  Any other problem as it is. */
int paradigm_sweep_run(const paradigm_input *in, int monotone, paradigm_output *out,
                       size_t *pockets, char *err, size_t errlen) {
  paradigm_input sub = *in;
  if (in->problem == PARADIGM_DELAUNAY) sub.nsegments = 0;
  if (in->problem != PARADIGM_POLYGON && in->problem != PARADIGM_CONVEX)
    return cs_run(&sub, out, pockets, err, errlen);
  uint32_t *seg;
  int ccw;
  if (paradigm_polygon_sides(in, &seg, &ccw, err, errlen) != 0) return -1;
  if (paradigm_polygon_kind(in, monotone, err, errlen) != 0) {
    free(seg);
    return -1;
  }
  sub.problem = PARADIGM_CONSTRAINED, sub.segments = seg, sub.nsegments = in->n;
  int rc = cs_run(&sub, out, pockets, err, errlen);
  if (rc == 0) rc = paradigm_polygon_inside(out, in->n, ccw, err, errlen);
  free(seg);
  return rc;
}

int paradigm_sweep_constrained(const paradigm_input *in, paradigm_output *out, char *err,
                               size_t errlen) {
  return paradigm_sweep_run(in, 0, out, NULL, err, errlen);
}
