/*
** lot.c: locally optimal triangulations: the incremental and flip
** algorithms over the structure of mesh.c, the edge queue, the decisions,
** cycle detection and the flip budget.
**
** Why the flip loop ends.
** - DT: each flip lowers the lifted surface (points lifted to the paraboloid
**   z = x^2 + y^2), and the decision is exact, so no triangulation repeats
**   (thesis 2.2.1).
** - A triangle-based rule b_f: each triangle's badness v(t) is a fixed
**   number (geom_tri_make is canonical, so the same triangle always gets the
**   same double), and a flip happens only when rule_compare finds
**   fl(f(v1', v2')) < fl(f(v1, v2)) strictly.  Rounding is monotone, so the
**   exact value of the computed formula decreases too, and a potential over
**   the whole triangulation strictly decreases, so no triangulation repeats
**   and there are finitely many:
**     l_1:  sum of v(t)                 (fl(x'+y') < fl(x+y) => x'+y' < x+y);
**     l_2:  sum of fl(v(t)^2)            (sqrt and the sum are monotone);
**     l_-1: minus sum of fl(1/v(t))      (1/s is decreasing);
**     l_0:  sum of log v(t)              (the product is monotone);
**     l_inf: the values sorted decreasingly, lexicographically (both new
**            triangles are below the larger removed one);
**     l_-inf: the values sorted increasingly, lexicographically (the new
**            smaller triangle is below both removed ones).
**   The angle measures under l_1, l_inf and l_-inf keep enclosures of v(t)
**   and compute v(t) only when they cannot decide (lot_prefers_lazy): the
**   decisions, and so the argument, are those of the exact values.
**   Measures of sign <= 0 use |v| and the mirror potentials.  Two cases are
**   subtle: a value 0 under l_0 or l_-1 (log 0 and 1/0 are infinite; the
**   joint then ties or decides by the other triangles only) and values that
**   overflow in the joint (inf ties with inf).  We believe the potentials
**   extend to them (count of zero or infinite terms first), but rely on the
**   flip budget there rather than on that argument.
** - Empty-shape rules (ES:SHAPE, marked systematic by
**   rule_quad_set_systematic): acyclic and systematic as DT is
**   (docs/emptyshape.md), so they take DT's path: incremental insertion
**   flips only the new point's link (star_only), and nothing watches for
**   cycles; the flip budget still bounds every run.
** - Other quadrilateral rules (plugins) have no such potential: a flip sequence
**   can return to an earlier triangulation (a type-V flip graph, or a
**   rounding-inconsistent DT as in thesis 7.5).  For them the sum of 64-bit
**   hashes of the edges is kept up to date at each flip; when it repeats
**   within a flip phase, the flips in between are checked to cancel exactly
**   (every edge added as often as removed), and the run stops with status
**   cycle.  Cycles longer than LOT_CYCLE_WINDOW flips are caught by the
**   budget instead.
** Every run stops after max_flips flips in any case (status budget
** exhausted); the remaining points are still inserted, without flips, so
** the output is always a triangulation of every point.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "mesh.h"
#include "cdt.h"
#include "order.h"
#include "weighted.h"
#include "sweep_internal.h"
#include "measure.h"
#include "splitmix.h"
#include "geom_key_internal.h"

#define LOT_CYCLE_WINDOW (1u << 20)

/* r is lot's one copy of its rule, the options' tolerance in it: the mesh
** (its badness cache) and the run (its decisions) both read this one. */
struct lot {
  lot_mesh m;
  lot_stats st;
  rule r;
  lot_cdt cdt;          /* constraints (cdt.c); all zero when there are none */
  int constrained;
  size_t sweep_ties;    /* a polygon's sweep: ties decided by its fixed order */
  int sweep_restarted;  /* 1: its mesh was replaced by the circle's sweep */
  uint32_t *redundant;  /* WDT: input indices of the sites left out (sorted) */
};

/* How lot_examine decides: DT's incircle, a triangle-based rule (its
** cache), an empty-shape rule's shape (straight to the shape's decision:
** the sites are validated and its answer is the same for every rotation
** of the quadrilateral, so rule_eval's checks and rotation are skipped),
** another quadrilateral rule, WDT's power test with the run's weights, or
** a decision hook. */
typedef enum lot_kind {
  LOT_K_DT, LOT_K_TRI, LOT_K_SHAPE, LOT_K_QUAD, LOT_K_POWER, LOT_K_HOOK
} lot_kind;

typedef struct lot_entry {
  uint32_t c, u, v;     /* the edge opposite corner c, from u to v when pushed */
} lot_entry;

enum { LOT_FIRST_SUM = 1, LOT_FIRST_MAX = 2 };

typedef struct lot_run {
  lot_mesh *m;
  const lot_options *o;
  const rule *r;        /* the lot's rule (struct lot) */
  lot_stats *st;
  const lot_cons *cons; /* constrained edges, never flipped; NULL: none */
  lot_kind kind;
  const shape *shape;   /* LOT_K_SHAPE: the rule's shape */
  const double *w;      /* LOT_K_POWER: the weights, by input index (m->inp) */
  int hints;            /* 1: its decisions keep hints in the triangles (lot_run_hints) */
  int star_only;        /* DT insertion: only edges opposite the new point */
  int stopped;          /* cycle or budget: no more flips */
  int settle_ties;      /* an empty-shape rule: its EITHER goes to lot_tie_flips */
  lot_enc any;          /* encloses every value of the measure (measure_floor) */
  int one_first;        /* exact cache: the first new triangle may decide (lot_prefers_exact):
                           0, or LOT_FIRST_SUM / LOT_FIRST_MAX, the joint's form */
  lot_entry *stk;
  size_t ns, cap;
  /* cycle detection (quadrilateral rules) */
  int track;
  uint64_t H;
  uint64_t *hkey;
  uint32_t *hval;
  size_t hcap, hcount;
  uint32_t (*log)[4];   /* quadrilateral of each flip of the window: a, b, d, c */
  size_t nlog, logcap;
} lot_run;

static double lot_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

uint64_t lot_default_max_flips(size_t n) {
  return 1000 * (uint64_t)n + 10000000u;
}

void lot_options_init(lot_options *o, const rule *r) {
  memset(o, 0, sizeof *o);
  o->r = *r;
  o->algorithm = LOT_INCREMENTAL;
  o->order = LOT_ORDER_SPATIAL;
  o->seed = 1;
  o->tie_eps = rule_tie_eps(r);
}

/* ---- the edge queue ---------------------------------------------------- */

static int lot_push(lot_run *R, uint32_t c) {
  if (R->ns == R->cap) {
    size_t cap = R->cap ? 2 * R->cap : 1024;
    lot_entry *s = realloc(R->stk, cap * sizeof *s);
    if (s == NULL) return -1;
    ops_memory(R->o->ops, (int64_t)((cap - R->cap) * sizeof *s));
    R->stk = s;
    R->cap = cap;
  }
  R->stk[R->ns++] = (lot_entry){c, R->m->tv[lot_next3(c)], R->m->tv[lot_prev3(c)]};
  return 0;
}

/* ---- cycle detection --------------------------------------------------- */

static uint64_t lot_edge_hash(uint32_t u, uint32_t v) {
  uint64_t x = geom_edge_key(u, v);
  return geom_splitmix64(&x);   /* a bijection of the key, well mixed */
}

/* Find or add H -> index; returns the earlier index, or UINT32_MAX if new. */
static uint32_t lot_hash_put(lot_run *R, uint64_t H, uint32_t index) {
  if (2 * (R->hcount + 1) > R->hcap) {
    size_t cap = R->hcap ? 2 * R->hcap : 1024;
    uint64_t *k = malloc(cap * sizeof *k);
    uint32_t *v = malloc(cap * sizeof *v);
    if (!k || !v) {
      free(k);
      free(v);
      return UINT32_MAX - 1;
    }
    for (size_t i = 0; i < cap; i++) v[i] = UINT32_MAX;
    for (size_t i = 0; i < R->hcap; i++)
      if (R->hval[i] != UINT32_MAX) {
        size_t j = R->hkey[i] & (cap - 1);
        while (v[j] != UINT32_MAX) j = (j + 1) & (cap - 1);
        k[j] = R->hkey[i];
        v[j] = R->hval[i];
      }
    free(R->hkey);
    free(R->hval);
    R->hkey = k;
    R->hval = v;
    R->hcap = cap;
  }
  size_t j = H & (R->hcap - 1);
  while (R->hval[j] != UINT32_MAX) {
    if (R->hkey[j] == H) return R->hval[j];
    j = (j + 1) & (R->hcap - 1);
  }
  R->hkey[j] = H;
  R->hval[j] = index;
  R->hcount++;
  return UINT32_MAX;
}

static void lot_window_reset(lot_run *R) {
  for (size_t i = 0; i < R->hcap; i++) R->hval[i] = UINT32_MAX;
  R->hcount = 0;
  R->nlog = 0;
  R->H = 0;
  lot_hash_put(R, 0, 0);
}

static int lot_key_cmp(const void *x, const void *y) {
  uint64_t a = *(const uint64_t *)x, b = *(const uint64_t *)y;
  return a < b ? -1 : a > b;
}

/* Do the flips of log (k0, k1] cancel exactly?  Each flip removes b-c and
** adds a-d; as keys with the low bit marking additions, sorted, every edge
** must be added as often as it is removed. */
static int lot_cancels(const lot_run *R, size_t k0, size_t k1) {
  size_t n = 2 * (k1 - k0);
  uint64_t *e = malloc(n * sizeof *e);
  if (e == NULL) return 0;
  size_t w = 0;
  for (size_t k = k0; k < k1; k++) {
    const uint32_t *q = R->log[k];
    e[w++] = geom_edge_key(q[0], q[2]) << 1 | 1;   /* keys < 2^63: ids < 2^31 */
    e[w++] = geom_edge_key(q[1], q[3]) << 1;
  }
  qsort(e, n, sizeof *e, lot_key_cmp);
  int ok = 1;
  for (size_t i = 0; i < n && ok;) {
    size_t j = i;
    long bal = 0;
    while (j < n && e[j] >> 1 == e[i] >> 1) bal += (e[j++] & 1) ? 1 : -1;
    ok = bal == 0;
    i = j;
  }
  free(e);
  return ok;
}

/* Record a flip of quadrilateral (a, b, d, c): 1 when it closes a cycle. */
static int lot_track(lot_run *R, uint32_t a, uint32_t b, uint32_t d, uint32_t c) {
  if (R->nlog == LOT_CYCLE_WINDOW) lot_window_reset(R);
  if (R->nlog == R->logcap) {
    size_t cap = R->logcap ? 2 * R->logcap : 1024;
    void *nl = realloc(R->log, cap * sizeof *R->log);
    if (nl == NULL) return 0;
    R->log = nl;
    R->logcap = cap;
  }
  uint32_t *q = R->log[R->nlog++];
  q[0] = a; q[1] = b; q[2] = d; q[3] = c;
  R->H += lot_edge_hash(a, d) - lot_edge_hash(b, c);
  uint32_t k0 = lot_hash_put(R, R->H, (uint32_t)R->nlog);
  if (k0 >= UINT32_MAX - 1 || !lot_cancels(R, k0, R->nlog)) return 0;
  lot_stats *st = R->st;
  st->status = LOT_CYCLE;
  st->cycle_length = R->nlog - k0;
  st->cycle_quads = st->cycle_length < LOT_CYCLE_QUADS ? st->cycle_length : LOT_CYCLE_QUADS;
  for (size_t i = 0; i < st->cycle_quads; i++)
    for (int j = 0; j < 4; j++) st->cycle_quad[i][j] = R->m->inp[R->log[k0 + i][j]];
  return 1;
}

/* ---- decisions and the flip loop --------------------------------------- */

/* A triangle rule's decision with an exact cache: the new pair (AC)
** against the cached current one (BD), as rule_eval_badness decides,
** without its lookups.  *n1, *n2: the new triangles' values.
** R->one_first (l_1 with a built-in measure that has a floor F, or l_inf):
** the first new triangle alone may rule the flip out.  The flip needs
** fl(x1 + x2) < fl(y1 + y2) strictly; x2 >= F (measure_floor holds for
** every computed value), so x1 + x2 >= x1 + F exactly and, rounding being
** monotone, fl(x1 + x2) >= fl(x1 + F): when fl(x1 + F) >= fl(y1 + y2)
** there is no flip, the decision the second triangle would confirm.  Under
** l_inf, max(x1, x2) >= x1, so x1 >= max(y1, y2) suffices.  That settles a
** fifth to two fifths of the examined edges of R, abc, lambda, d, a-c,
** -r/R and -r2/A, which then make one triangle instead of two. */
static int lot_prefers_exact(const lot_run *R, uint32_t a, uint32_t b, uint32_t c0, uint32_t d,
                             uint32_t t, uint32_t u, lot_enc *n1, lot_enc *n2) {
  const lot_mesh *m = R->m;
  double x1 = lot_mesh_badness(m, a, b, d), y1 = m->bad[t], y2 = m->bad[u];
  *n1 = (lot_enc){x1, x1};
  if (R->one_first && (R->one_first == LOT_FIRST_SUM ? x1 + R->any.lo >= y1 + y2
                                                     : x1 >= (y1 > y2 ? y1 : y2)))
    return 0;
  double x2 = lot_mesh_badness(m, a, d, c0);
  *n2 = (lot_enc){x2, x2};
  return rule_decide(R->r, x1, x2, y1, y2) == RULE_AC;
}

static joint_verdict lot_verdict(const lot_run *R, lot_enc n1, lot_enc n2, lot_enc o1,
                                 lot_enc o2) {
  const double lo[4] = {n1.lo, n2.lo, o1.lo, o2.lo}, hi[4] = {n1.hi, n2.hi, o1.hi, o2.hi};
  return rule_decide_bounds(R->r, lo, hi);
}

/* The same decision with an enclosed cache (mesh.h), exact values
** made lazily.  The rule flips when joint_compare(J, s, x1, x2, y1, y2,
** eps) < 0, x1, x2 the new triangles' exact values (lot_mesh_badness), y1,
** y2 the current ones'.  Each of them lies in its enclosure: measure_bounds
** encloses the very double lot_mesh_badness returns (measure_fields makes
** that double measure_eval's on geom_tri_make's triangle, bit for bit, in
** any vertex order), and an exact entry is that double.
** joint_compare_bounds certifies a verdict only when every choice of values
** inside the enclosures gives it (joints/joint.c has the argument, rounding
** of the joint and of the tie test included), so a certified verdict is
** the exact one.  When it cannot tell: the current triangles are made
** exact (they stay so in the cache: they meet more decisions), then, if
** still unsure, the new ones, and joint_compare decides on exact values
** exactly as the exact cache does.  So every flip, and with it the
** sequence of triangulations, is the exact cache's, bit for bit; the
** termination argument at the top of this file holds as it stands (it is
** about the exact values, which are the same).  Enclosures are about 2e-6
** wide and the compared joints rarely that close, so most decisions, and
** most triangles, never need atan2. */
static int lot_prefers_lazy(const lot_run *R, uint32_t a, uint32_t b, uint32_t c0, uint32_t d,
                            uint32_t t, uint32_t u, lot_enc *n1, lot_enc *n2) {
  lot_mesh *m = R->m;
  *n1 = lot_mesh_enclose(m, a, b, d);
  joint_verdict v = lot_verdict(R, *n1, R->any, m->enc[t], m->enc[u]);
  if (v == JOINT_NOT_LESS) return 0;
  *n2 = lot_mesh_enclose(m, a, d, c0);
  v = lot_verdict(R, *n1, *n2, m->enc[t], m->enc[u]);
  if (v == JOINT_UNSURE && (m->enc[t].lo != m->enc[t].hi || m->enc[u].lo != m->enc[u].hi)) {
    lot_mesh_exact(m, t);
    lot_mesh_exact(m, u);
    v = lot_verdict(R, *n1, *n2, m->enc[t], m->enc[u]);
  }
  if (v != JOINT_UNSURE) return v == JOINT_LESS;
  n1->lo = n1->hi = lot_mesh_badness(m, a, b, d);
  n2->lo = n2->hi = lot_mesh_badness(m, a, d, c0);
  return rule_decide(R->r, n1->lo, n2->lo, m->enc[t].lo, m->enc[u].lo) == RULE_AC;
}

/* ---- the tie-break ------------------------------------------------------
**
** DT and the empty-shape rules answer EITHER when the four sites of a
** strictly convex quadrilateral lie on one circle (one homothet of the
** shape, for every small turn of it: geom/shape.c).  lot settles such a tie
** by one rule, whatever the algorithm: the vertex greatest in the
** lexicographic order of the plane (larger x, then larger y) counts as
** outside the circle of the other three, so the diagonal NOT incident to it
** is kept.  For DT this is the symbolic perturbation of the lifting
** z = x^2 + y^2 + eps^(n - r), r the point's rank in that order (eps -> 0):
** the in-circle determinant is linear in the z column, so it becomes
** value + sum over the four of eps^(n - r) (+-) the orientation of the
** other three; when the value is 0 the greatest vertex's term decides (in a
** strictly convex quadrilateral no three are collinear), and it lifts that
** vertex above the plane of the other three, whose lower hull is the two
** triangles on the other diagonal.  No four perturbed lifts lie on a
** non-vertical plane (a point's coefficient is 0 only when the other three
** are collinear), so the lower hull projects to one triangulation, every
** point a vertex: the unique triangulation whose every edge is locally
** optimal under the perturbed rule, which Lawson's flips reach from any
** triangulation (each flip lowers the perturbed surface) and which
** incremental insertion keeps (an edge not locally optimal still has a
** strictly convex quadrilateral: its four sites are cocircular or the exact
** test already fails).  The order is one of the points, not of the input:
** the result depends on the point set only (duplicates, insertion order and
** algorithm do not matter), as with CGAL's Delaunay triangulation, which
** perturbs the same way.  For the empty-shape rules the same last resort is
** the first-order effect of additive weights eps^(n - r) on the sites; the
** uniqueness of its LOT is checked by brute force (tests/test_lot_ties.c).
** Triangle-based rules' ties (within tie_eps) and plugin rules' EITHER are
** left alone. */

/* The empty-shape decision of a b d c0 (a at corner c of t = (a, b, c0), d
** at corner cd of the far triangle u = (d, c0, b)).  A triangle's
** circumscribing shape depends on its three sites alone, so a decision
** keeps what it found of it (its hint, shape.h) in the triangle's unused
** slot 3 (mesh.h: cleared whenever its vertices change), by vertex slot:
** bits 8 s .. 8 s + 7 the contact edge of the vertex in slot s (a corner
** hint: its corner in bits 0-7), how in bits 24-25.  Any rotation of the
** triangle reads it, rotated.  When u has one, the quadrilateral is asked
** of u with a as D (the rotation b d c0 a, answers with AC and BD swapped:
** shape.h), and only D's test is left.  Otherwise it is asked of t with d
** as D (the rotation c0 a b d, the same answers as b d c0 a), and t keeps
** what it found: t is new (a's insertion made it), so unlike u it has
** its whole life ahead, and the later points that arrive beside it read
** the hint (docs/emptyshape.md, "Hints", has the counts). */
static uint32_t lot_hint_pack(uint32_t c, shape_hint h) {
  uint32_t s[3] = {lot_slot(lot_prev3(c)), lot_slot(c), lot_slot(lot_next3(c))};
  if (h.how == SHAPE_HINT_CORNER) return (uint32_t)h.how << 24 | h.e[0];
  return (uint32_t)h.how << 24 | (uint32_t)h.e[0] << 8 * s[0] | (uint32_t)h.e[1] << 8 * s[1] |
         (uint32_t)h.e[2] << 8 * s[2];
}

/* The hint of word w for the rotation (prev, at, next) of corner c. */
static shape_hint lot_hint_unpack(uint32_t c, uint32_t w) {
  shape_hint h = {.how = (unsigned char)(w >> 24 & 3)};
  if (h.how == SHAPE_HINT_CORNER) {
    h.e[0] = (unsigned char)w;
    return h;
  }
  h.e[0] = (unsigned char)(w >> 8 * lot_slot(lot_prev3(c)));
  h.e[1] = (unsigned char)(w >> 8 * lot_slot(c));
  h.e[2] = (unsigned char)(w >> 8 * lot_slot(lot_next3(c)));
  return h;
}

static rule_choice lot_shape_choice(lot_run *R, uint32_t c, uint32_t cd, geom_point pa,
                                    geom_point pb, geom_point pd, geom_point pc) {
  shape_choice s;
  if (!R->hints) {
    s = shape_decide_valid(R->shape, pb, pd, pc, pa);
  } else {
    uint32_t wu = R->m->tv[LOT_CORNER(lot_tri_of(cd), 3)];
    if (wu >> 24 & 3) {
      shape_hint h = lot_hint_unpack(cd, wu);
      s = shape_decide_hinted(R->shape, pb, pd, pc, pa, &h);
    } else {
      shape_hint h = {0};
      s = shape_decide_hinted(R->shape, pc, pa, pb, pd, &h);
      R->m->tv[LOT_CORNER(lot_tri_of(c), 3)] = lot_hint_pack(c, h);
    }
  }
  return s == SHAPE_EITHER ? RULE_EITHER : s == SHAPE_BD ? RULE_AC : RULE_BD;
}

static int lot_lex_less(geom_point p, geom_point q) {
  return p.x < q.x || (p.x == q.x && p.y < q.y);
}

/* A tie at quadrilateral a b d c0 (diagonal b-c0): 1 when the tie-break
** flips it to a-d, i.e. when the greatest of the four is b or c0. */
static int lot_tie_flips(geom_point pa, geom_point pb, geom_point pc, geom_point pd) {
  geom_point keep = lot_lex_less(pa, pd) ? pd : pa, drop = lot_lex_less(pb, pc) ? pc : pb;
  return lot_lex_less(keep, drop);
}

/* Examine the edge opposite corner c; flip it when the rule prefers the
** other diagonal.  With t = (a, b, c0) and t' = (d, c0, b) the
** quadrilateral is a b d c0 (anticlockwise), its current diagonal b-c0
** (RULE_BD), the other a-d (RULE_AC). */
static int lot_examine(lot_run *R, uint32_t c) {
  lot_mesh *m = R->m;
  /* Queued corners are in real triangles; the other side is a ghost when
  ** its apex d is the ghost vertex (b and c0 are real). */
  uint32_t cd = m->tn[c], t = lot_tri_of(c), u = lot_tri_of(cd), d = m->tv[cd];
  if (d == LOT_GHOST) return 0;
  uint32_t a = m->tv[c], b = m->tv[lot_next3(c)], c0 = m->tv[lot_prev3(c)];
  if (R->cons != NULL && lot_cons_has(R->cons, b, c0)) return 0;
  geom_point pa = m->p[a], pb = m->p[b], pc = m->p[c0], pd = m->p[d];
  lot_enc n1, n2;
  if (R->kind == LOT_K_DT) {
    /* d strictly inside circle abc makes abdc strictly convex (a and d on
    ** opposite sides of bc, and the line ab meets the circle only at a and
    ** b, so b is not on segment ad; likewise c), so no orientation test.
    ** d on it (a tie) makes four distinct cocircular sites, a and d apart:
    ** strictly convex too. */
    int in = ops_incircle(R->o->ops, pa, pb, pc, pd);
    if (in < 0 || (in == 0 && !lot_tie_flips(pa, pb, pc, pd))) return 0;
    n1 = n2 = (lot_enc){0, 0};
  } else {
    n1 = n2 = (lot_enc){0, 0};
    if (ops_orient(R->o->ops, pa, pb, pd) <= 0 || ops_orient(R->o->ops, pa, pd, pc) <= 0)
      return 0;
    rule_choice ch;
    if (R->kind == LOT_K_TRI) {
      int flip = m->enc ? lot_prefers_lazy(R, a, b, c0, d, t, u, &n1, &n2)
                        : lot_prefers_exact(R, a, b, c0, d, t, u, &n1, &n2);
      ch = flip ? RULE_AC : RULE_EITHER;
    } else if (R->kind == LOT_K_SHAPE) {
      ops_add(R->o->ops, OPS_INSHAPE, 1);
      ch = lot_shape_choice(R, c, cd, pa, pb, pd, pc);
    } else if (R->kind == LOT_K_POWER) {
      const uint32_t *in = m->inp;
      const double w[4] = {R->w[in[a]], R->w[in[b]], R->w[in[c0]], R->w[in[d]]};
      int s = geom_power(pa, pb, pc, pd, w);   /* d's lifted point below plane a b c0 */
      ch = s > 0 || (s == 0 && lot_tie_flips(pa, pb, pc, pd)) ? RULE_AC : RULE_BD;
    } else {
      const geom_point q[4] = {pa, pb, pd, pc};
      ch = R->kind == LOT_K_QUAD ? rule_eval(R->r, q, NULL, NULL)
                                 : R->o->decide(q, RULE_BD, R->o->decide_ctx);
    }
    if (ch == RULE_EITHER && R->settle_ties) ch = lot_tie_flips(pa, pb, pc, pd) ? RULE_AC : RULE_BD;
    if (ch != RULE_AC) return 0;
  }
  if (R->st->flips >= R->st->max_flips) {
    R->st->status = LOT_BUDGET;
    R->stopped = 1;
    return 0;
  }
  lot_mesh_flip(m, c, n1.lo, n2.lo);
  if (m->enc) {   /* t and u keep their numbers: (a, b, d) and (d, c0, a) */
    m->enc[t] = n1;
    m->enc[u] = n2;
  }
  R->st->flips++;
  if (R->track && lot_track(R, a, b, d, c0)) R->stopped = 1;
  return 1;
}

/* After the flip at corner c (t = (a, b, d) with a at c, t' = (d, c0, a)):
** queue the edges whose quadrilateral changed. */
static int lot_push_after(lot_run *R, uint32_t c) {
  uint32_t j1 = R->m->tn[lot_next3(c)];   /* t's b corner faces t' across a-d: c0's corner */
  int rc = lot_push(R, c) | lot_push(R, lot_next3(j1));   /* b-d, d-c0: opposite a */
  if (!R->star_only) rc |= lot_push(R, lot_prev3(c)) | lot_push(R, lot_prev3(j1));   /* a-b, c0-a */
  if (R->track) rc |= lot_push(R, lot_next3(c));   /* a-d, for a rule not systematic */
  return rc;
}

static int lot_drain(lot_run *R) {
  if (R->track) lot_window_reset(R);
  while (R->ns > 0 && !R->stopped) {
    lot_entry e = R->stk[--R->ns];
    const lot_mesh *m = R->m;
    if (m->tv[lot_next3(e.c)] != e.u || m->tv[lot_prev3(e.c)] != e.v) continue;   /* stale */
    if (lot_examine(R, e.c) && lot_push_after(R, e.c) != 0) return -1;
  }
  R->ns = 0;
  return 0;
}

static int lot_push_all(lot_run *R) {
  const lot_mesh *m = R->m;
  for (uint32_t c = 0; c < LOT_CORNER(m->nt, 0); c++)
    if (lot_slot(c) < 3 && c < m->tn[c] && !lot_is_ghost(m, lot_tri_of(c)) &&
        !lot_is_ghost(m, lot_tri_of(m->tn[c])))
      if (lot_push(R, c) != 0) return -1;
  return 0;
}

/* The flip phase over every interior edge: the flip algorithm's second
** half (and lot_reflip's), every edge queued at once. */
static int lot_flip_all(lot_run *R) {
  return lot_push_all(R) != 0 || lot_drain(R) != 0 ? -1 : 0;
}

/* The pass that finishes every sweep.  The sweep decides each tie by the
** order of its events, so its triangulation is one LOT of the rule, not
** always the tie-broken one; Lawson's flips with the tie-break
** (lot_tie_flips) turn it into that one.  For DT only tied edges flip: the
** sweep's triangulation refines the Delaunay subdivision (convex faces of
** cocircular sites), a flip inside a face keeps the faces, and an edge
** between two faces has its far apex strictly outside its circle whatever
** the near apex, so it never flips.  The edges are examined in a scan
** rather than queued first (the stack of 3n entries cost more than the
** examinations); each flip queues the edges it changes and drains them
** before the scan goes on, so every edge is examined after its last
** change, by the scan or from the queue, and the result is a LOT with the
** tie-break: the one triangulation, whatever the order of the flips.  An
** empty-shape sweep (same table of primitives, shapes/shape_sweep_internal.h)
** goes through the same pass; after a polygon's ties in special position
** (lot_sweep_mesh) edges that are no tie flip too, as any flip pass
** would: the examination is the full rule's. */
static int lot_settle_ties(lot_run *R) {
  const lot_mesh *m = R->m;
  for (uint32_t c = 0; c < LOT_CORNER(m->nt, 0) && !R->stopped; c++)
    if (lot_slot(c) < 3 && c < m->tn[c] && !lot_is_ghost(m, lot_tri_of(c)) &&
        !lot_is_ghost(m, lot_tri_of(m->tn[c])) && lot_examine(R, c))
      if (lot_push_after(R, c) != 0 || lot_drain(R) != 0) return -1;
  return 0;
}

/* What the mesh caches for rule r and options o (mesh.h). */
static lot_cache lot_cache_of(const rule *r, const lot_options *o) {
  if (!rule_is_triangle(r) || o->decide) return LOT_CACHE_NONE;
  return measure_has_bounds(rule_measure(r)) && joint_has_bounds(rule_joint(r)) ? LOT_CACHE_ENCLOSED
                                                                                : LOT_CACHE_EXACT;
}

static void lot_run_init(lot_run *R, lot *L, const lot_options *o) {
  const rule *r = &L->r;
  memset(R, 0, sizeof *R);
  R->m = &L->m;
  R->o = o;
  R->r = r;
  R->st = &L->st;
  R->cons = L->constrained ? &L->cdt.cons : NULL;
  R->shape = rule_shape(r);
  R->w = o->weights;
  /* WDT without weights is DT exactly: DT's path. */
  R->kind = o->decide ? LOT_K_HOOK
          : rule_is_triangle(r) ? LOT_K_TRI
          : rule_wants_weights(r) && o->weights ? LOT_K_POWER
          : rule_is_delaunay(r) || rule_wants_weights(r) ? LOT_K_DT
          : R->shape ? LOT_K_SHAPE : LOT_K_QUAD;
  /* A decision hook, or a quadrilateral rule not known to be systematic
  ** (rule_quad_set_systematic), may cycle. */
  R->track = R->kind == LOT_K_HOOK || (R->kind == LOT_K_QUAD && !rule_is_systematic(r));
  R->settle_ties = R->kind == LOT_K_SHAPE;
  if (R->kind == LOT_K_TRI) R->any = (lot_enc){measure_floor(rule_measure(r)), INFINITY};
  /* Built-in measures only: their floors hold for every value they give
  ** (a user's formula or plugin promises its sign, but nothing checks it). */
  /* The joint table's form says whether f is x + y or max(x, y). */
  joint_vec v = joint_get(rule_joint(r))->vec;
  R->one_first = R->kind != LOT_K_TRI || rule_measure(r) >= MEASURE_BUILTIN_COUNT ? 0
               : v == JOINT_VEC_SUM && R->any.lo > -INFINITY ? LOT_FIRST_SUM
               : v == JOINT_VEC_MAX ? LOT_FIRST_MAX : 0;
  L->st.max_flips = o->max_flips ? o->max_flips : lot_default_max_flips(L->st.n);
  L->m.ops = o->ops;   /* the mesh counts too, for this run (lot_run_free forgets it) */
  ops_memory(o->ops, (int64_t)lot_mesh_bytes(&L->m));
}

/* An empty-shape rule keeps hints where its shape wants them
** (shape_wants_hints: polygons, but the axis-parallel square, which takes
** 12% fewer instructions without them).  A new mesh's triangles start
** without (every write of their vertices clears slot 3); a mesh reflipped
** (`forget`) may hold another rule's, which are cleared. */
static void lot_run_hints(lot_run *R, int forget) {
  R->hints = R->kind == LOT_K_SHAPE && shape_wants_hints(R->shape);
  if (!R->hints || !forget) return;
  for (uint32_t t = 0; t < R->m->nt; t++) R->m->tv[LOT_CORNER((size_t)t, 3)] = 0;
}

static void lot_run_free(lot_run *R) {
  ops_memory(R->o->ops, -(int64_t)(R->cap * sizeof *R->stk));
  R->m->ops = NULL;   /* the caller's counts are not kept past the run */
  free(R->stk);
  free(R->hkey);
  free(R->hval);
  free(R->log);
}

/* ---- building ---------------------------------------------------------- */

/* Weights: WDT's alone, with the incremental or flip algorithm, no
** constraints, every one within the weight contract (geom.h). */
static int lot_validate_weights(size_t n, const lot_options *o, char *err, size_t errlen) {
  const char *no = !rule_wants_weights(&o->r) ? "weights apply to the weighted Delaunay rule WDT"
                 : o->algorithm == LOT_SWEEP ? "the sweep takes no weights (WDT: use the "
                                               "incremental or flip algorithm)"
                 : o->nsegments > 0 || o->nholes > 0 ? "weights take no segments or holes"
                 : o->decide ? "weights take no decision hook" : NULL;
  if (no != NULL) {
    snprintf(err, errlen, "%s%s%s", no, rule_wants_weights(&o->r) ? "" : ", not ",
             rule_wants_weights(&o->r) ? "" : rule_name(&o->r));
    return -1;
  }
  for (size_t i = 0; i < n; i++) {
    geom_coorderr e = geom_weight_check(o->weights[i]);
    if (e != GEOM_COORD_OK) {
      snprintf(err, errlen, "point %zu: weight %g %s", i, o->weights[i], geom_weighterr_str(e));
      return -1;
    }
  }
  return 0;
}

static int lot_validate(const geom_point *p, size_t n, const lot_options *o, char *err,
                        size_t errlen) {
  if (o->algorithm == LOT_SWEEP) {
    lot_sweep_pick pk;
    if (o->decide) {
      snprintf(err, errlen, "the sweep algorithm decides by its rule's shape: it takes no "
               "decision hook");
      return -1;
    }
    if (lot_sweep_pick_rule(&o->r, &pk, err, errlen) != 0) return -1;
  }
  if ((o->nsegments > 0 && o->segments == NULL) || (o->nholes > 0 && o->holes == NULL)) {
    snprintf(err, errlen, "constraints: a count without its array");
    return -1;
  }
  if (n > LOT_MAX_POINTS) {
    snprintf(err, errlen, "%zu points: at most %u are supported", n, (unsigned)LOT_MAX_POINTS);
    return -1;
  }
  for (size_t i = 0; i < n; i++) {
    geom_coorderr e = geom_coord_check(p[i].x);
    if (e == GEOM_COORD_OK) e = geom_coord_check(p[i].y);
    if (e != GEOM_COORD_OK) {
      snprintf(err, errlen, "point %zu (%g, %g): a coordinate %s", i, p[i].x, p[i].y,
               geom_coorderr_str(e));
      return -1;
    }
  }
  return o->weights != NULL ? lot_validate_weights(n, o, err, errlen) : 0;
}

/* The insertion order: ord[k] = input index of the k-th point. */
static int lot_make_order(const geom_point *p, uint32_t n, const lot_options *o, uint32_t *ord) {
  if (o->algorithm != LOT_INCREMENTAL) return lot_order_lexicographic(p, n, ord);
  if (o->order == LOT_ORDER_SPATIAL) return lot_order_spatial(p, n, o->seed, ord);
  if (o->order == LOT_ORDER_RANDOM) lot_order_random(n, o->seed, ord);
  else for (uint32_t i = 0; i < n; i++) ord[i] = i;
  return 0;
}

/* The message for n points with no triangle: all equal, or all collinear. */
static void lot_degenerate(uint32_t n, int equal, char *err, size_t errlen) {
  snprintf(err, errlen, "all %u points are %s: a triangulation needs three non-collinear "
           "points", n, equal ? "equal" : "collinear");
}

/* The first triangle: vertex 0, the first point different from it, the
** first point off their line.  0, or -1 with the message. */
static int lot_first(lot_mesh *m, uint32_t *kb, uint32_t *kc, char *err, size_t errlen) {
  uint32_t n = m->np, b = 1, c;
  while (b < n && m->p[b].x == m->p[0].x && m->p[b].y == m->p[0].y) b++;
  for (c = b + 1; c < n && b < n; c++)
    if (geom_orient_valid(m->p[0], m->p[b], m->p[c]) != 0) break;
  if (b >= n || c >= n) {
    lot_degenerate(n, b >= n, err, errlen);
    return -1;
  }
  if (geom_orient_valid(m->p[0], m->p[b], m->p[c]) > 0) lot_mesh_first(m, 0, b, c);
  else lot_mesh_first(m, 0, c, b);
  *kb = b;
  *kc = c;
  return 0;
}

/* Insert every point (flipping after each when `flip`); 0 or -1 (memory). */
static int lot_insert_all(lot *L, lot_run *R, uint32_t kb, uint32_t kc, int flip) {
  lot_mesh *m = &L->m;
  uint32_t *cand = NULL;
  size_t candcap = 0;
  for (uint32_t k = 1; k < m->np; k++) {
    if (k == kb || k == kc) continue;
    uint32_t c;
    lot_where w = lot_mesh_locate(m, m->p[k], &c);
    if (w == LOT_ON_VERTEX) {   /* a duplicate: merged into the vertex already there */
      uint32_t v = m->tv[c];
      if (m->inp[k] < m->inp[v]) m->inp[v] = m->inp[k];
      L->st.duplicates++;
      continue;
    }
    long nc = lot_mesh_insert(m, k, w, c, &cand, &candcap);
    if (nc < 0) goto oom;
    if (!flip || R->stopped) continue;
    for (long i = 0; i < nc; i++)
      if (lot_push(R, cand[i]) != 0) goto oom;
    if (lot_drain(R) != 0) goto oom;
  }
  free(cand);
  return 0;
oom:
  free(cand);
  return -1;
}

static void lot_finish_stats(lot *L) {
  lot_mesh *m = &L->m;
  size_t ghosts = 0;
  for (uint32_t t = 0; t < m->nt; t++) ghosts += lot_is_ghost(m, t);
  L->st.hull = ghosts;
  L->st.triangles = m->nt - ghosts - L->st.removed;
  L->st.distinct = L->st.n - L->st.duplicates;
}

/* Take o's rule, with o's tolerance, as L's one copy (lot_build and
** lot_reflip, before the mesh's cache is made for it). */
static void lot_take_rule(lot *L, const lot_options *o) {
  L->r = o->r;
  rule_set_tie_eps(&L->r, o->tie_eps);
}

/* Point the mesh at L's rule: its measure, the fields it reads and its
** evaluation from points (triangle rules). */
static void lot_use_rule(lot *L) {
  int tri = rule_is_triangle(&L->r), mi = rule_measure(&L->r);
  L->m.r = &L->r;
  L->m.meas = tri ? measure_get(mi) : NULL;
  L->m.fields = tri ? measure_fields(mi) : GEOM_F_ALL;
  L->m.pts = tri ? measure_points(mi) : NULL;
}

/* The sweep's triangulation (lot_triangulate).  A polygon's sweep decides
** the ties of sites in special position (equal keys of neighbouring
** events, a zero "above" sign, shapes/shape_sweep_polygon.c) by a fixed rule (equal
** keys in creation order, a zero sign as "not above") and counts those it
** meets (pk.special), and nothing proves that this gives a triangulation.
** So its mesh is checked (lot_mesh_valid, exact), every time: the count
** depends on which comparisons the event heap happens to make, and may
** miss a tie; when the mesh is none, or the sweep's structure broke (-3),
** the circle's sweep makes the Delaunay triangulation instead, which is
** valid on every input.  Either way the pass after it (lot_settle_ties,
** Lawson's flips with the rule and its tie-break) ends at the rule's one
** tie-broken LOT (docs/lot.md, Ties), the triangles of the other
** algorithms.  0, -1 (memory), -2 (err). */
static int lot_sweep_mesh(lot *L, char *err, size_t errlen) {
  lot_sweep_pick pk;
  if (lot_sweep_pick_rule(&L->r, &pk, err, errlen) != 0) return -2;
  int rc = lot_sweep_run(&L->m, &pk.s, &L->st.duplicates);
  L->sweep_ties = pk.special;
  int poly = pk.s.ties != NULL;
  if (rc == 0 && poly) {
    int v = lot_mesh_valid(&L->m, L->m.np - (uint32_t)L->st.duplicates);
    if (v < 0) return -1;
    rc = v ? 0 : -3;
  }
  if (rc == -2 && poly) rc = -3;   /* no triangle from a polygon's sweep: the circle's says why */
  if (rc == -3) {
    L->sweep_restarted = 1;
    rc = lot_sweep_run(&L->m, &shape_sweep_circle, &L->st.duplicates);
  }
  if (rc == -2) lot_degenerate(L->m.np, L->st.duplicates + 1 == L->m.np, err, errlen);
  if (rc == -3) snprintf(err, errlen, "internal error: the circle's sweep broke");
  return rc == -3 ? -2 : rc;
}

/* The triangulation of L's points in their order: the sweep, or the first
** triangle and every insertion (flipping after each, incremental).  0; -1
** out of memory; -2 with the message in err (no triangle). */
static int lot_triangulate(lot *L, lot_run *R, const lot_options *o, char *err, size_t errlen) {
  if (o->algorithm == LOT_SWEEP) return lot_sweep_mesh(L, err, errlen);
  uint32_t kb, kc;
  if (lot_first(&L->m, &kb, &kc, err, errlen) != 0) return -2;
  return lot_insert_all(L, R, kb, kc, o->algorithm == LOT_INCREMENTAL);
}

/* The segments, inserted into the triangulation one by one (cdt.c); after
** each, the new triangles' edges are flipped with the rule (not for the
** flip algorithm, whose one flip phase follows).  0, -1 (memory), -2 (err). */
static int lot_constrain(lot *L, lot_run *R, const lot_options *o, const uint32_t *ord,
                         char *err, size_t errlen) {
  if (lot_cdt_begin(&L->cdt, &L->m, ord, L->st.n) != 0) return -1;
  R->cons = &L->cdt.cons;
  R->star_only = 0;   /* a new triangle is no star of a new point */
  uint32_t *cand = NULL;
  size_t candcap = 0;
  int rc = 0;
  for (size_t k = 0; k < o->nsegments && rc == 0; k++) {
    long nc = lot_cdt_segment(&L->cdt, &L->m, o, &L->st, k, &cand, &candcap, err, errlen);
    if (nc < 0) rc = (int)nc;
    for (long i = 0; rc == 0 && o->algorithm != LOT_FLIP && i < nc && !R->stopped; i++)
      rc = lot_push(R, cand[i]);
    if (rc == 0 && o->algorithm != LOT_FLIP) rc = lot_drain(R);
  }
  free(cand);
  return rc;
}

/* The flip algorithm's flip phase, and the times (started at t0, the
** order made at tord).  0, or -1 when out of memory. */
static int lot_flip_phase(lot *L, lot_run *R, const lot_options *o, double t0, double tord) {
  double t1 = lot_now();
  if (o->algorithm == LOT_FLIP) {
    L->st.seconds_init = t1 - t0;
    if (lot_flip_all(R) != 0) return -1;
    L->st.seconds_flip = lot_now() - t1;
  } else {   /* the split is ordering | the rest (insertion or sweep, with their flips) */
    L->st.seconds_init = tord - t0;
    L->st.seconds_flip = t1 - tord;
  }
  return 0;
}

/* 1 with the message when the constraints removed every triangle. */
static int lot_none_left(const lot *L, const lot_options *o, char *err, size_t errlen) {
  if (!L->constrained || L->st.triangles > 0) return 0;
  /* No flag named: the Python package shows the same words (keep_hull=True). */
  snprintf(err, errlen, "no triangle is left: the %s every triangle (keeping the hull keeps "
           "the convex hull's)", o->nholes > 0 ? "holes and segments remove"
                                               : "segments bound no region and the outside takes");
  return 1;
}

/* One triangulation of all of p (lot_build without weights' rounds). */
static int lot_build_once(lot **out, const geom_point *p, size_t n, const lot_options *o,
                          char *err, size_t errlen) {
  *out = NULL;
  if (n < 3) {
    snprintf(err, errlen, "%zu point%s: a triangulation needs at least three non-collinear "
             "points", n, n == 1 ? "" : "s");
    return -1;
  }
  if (lot_validate(p, n, o, err, errlen) != 0) return -1;
  lot *L = calloc(1, sizeof *L);
  uint32_t *ord = malloc(n * sizeof *ord);
  lot_run R;
  if (L == NULL || ord == NULL) goto oom;
  lot_take_rule(L, o);
  if (lot_mesh_alloc(&L->m, (uint32_t)n, lot_cache_of(&L->r, o)) != 0) goto oom;
  lot_use_rule(L);
  L->st.n = n;
  L->constrained = o->nsegments > 0 || o->nholes > 0;
  lot_run_init(&R, L, o);
  /* Not for weights: a new site can hide old ones, whose edges are not
  ** in its star (lot_weighted.c). */
  R.star_only = rule_is_systematic(&L->r) && !o->decide && o->algorithm == LOT_INCREMENTAL &&
                R.kind != LOT_K_POWER;
  lot_run_hints(&R, 0);
  double t0 = lot_now();
  if (lot_make_order(p, (uint32_t)n, o, ord) != 0) goto oom_run;
  double tord = lot_now();
  for (size_t k = 0; k < n; k++) {
    L->m.p[k] = p[ord[k]];
    L->m.inp[k] = ord[k];
  }
  int rc = lot_triangulate(L, &R, o, err, errlen);
  if (rc == 0 && o->algorithm == LOT_SWEEP) rc = lot_settle_ties(&R);
  if (rc == 0 && L->constrained) rc = lot_constrain(L, &R, o, ord, err, errlen);
  free(ord);
  ord = NULL;
  if (rc == -2) goto refused;
  if (rc != 0) goto oom_run;
  if (lot_flip_phase(L, &R, o, t0, tord) != 0) goto oom_run;
  if (L->constrained && (rc = lot_cdt_remove(&L->cdt, &L->m, o, &L->st, err, errlen)) != 0) {
    if (rc == -1) goto oom_run;
    goto refused;
  }
  lot_run_free(&R);
  lot_finish_stats(L);
  if (lot_none_left(L, o, err, errlen)) {
    lot_free(L);
    return -1;
  }
  *out = L;
  return 0;
refused:
  lot_run_free(&R);
  lot_free(L);
  return -1;
oom_run:
  lot_run_free(&R);
oom:
  free(ord);
  lot_free(L);
  snprintf(err, errlen, "out of memory for %zu points", n);
  return -1;
}

/* ---- the weighted rule's rounds (weighted.c has the argument) ---------- */

/* What happens to each site of a weighted run (keep[]). */
enum { LOT_W_HIDDEN = 0, LOT_W_KEPT = 1, LOT_W_DUPLICATE = 2 };

/* Exact duplicates: all but the heaviest of each group (the first of the
** heaviest), which alone can have a non-empty power cell, are marked
** LOT_W_DUPLICATE; how many, or -1 out of memory.  O(n log n). */
static long lot_weighted_dedupe(const geom_point *p, const double *w, uint32_t n,
                                unsigned char *keep, uint32_t *ord) {
  if (lot_order_lexicographic(p, n, ord) != 0) return -1;   /* x, y, then index */
  long dropped = 0;
  for (uint32_t i = 0, j; i < n; i = j) {
    uint32_t best = ord[i];
    for (j = i + 1; j < n && p[ord[j]].x == p[ord[i]].x && p[ord[j]].y == p[ord[i]].y; j++) {
      uint32_t drop = w[ord[j]] > w[best] ? best : ord[j];
      best = drop == best ? ord[j] : best;
      keep[drop] = LOT_W_DUPLICATE;
      dropped++;
    }
  }
  return dropped;
}

/* The sites kept, in input order: their points, weights and input indices. */
static uint32_t lot_weighted_subset(const geom_point *p, const double *w, uint32_t n,
                                    const unsigned char *keep, geom_point *q, double *wq,
                                    uint32_t *map) {
  uint32_t m = 0;
  for (uint32_t i = 0; i < n; i++)
    if (keep[i] == LOT_W_KEPT) {
      q[m] = p[i];
      wq[m] = w[i];
      map[m++] = i;
    }
  return m;
}

/* The final round's lot speaks of the whole input: input indices, the
** sites left out, the flips, times and number of every round (in acc). */
static int lot_weighted_finish(lot *L, const unsigned char *keep, const uint32_t *map, size_t n,
                               long dups, const lot_stats *acc) {
  for (uint32_t v = 0; v < L->m.np; v++) L->m.inp[v] = map[L->m.inp[v]];
  size_t out = 0;
  for (size_t i = 0; i < n; i++) out += keep[i] == LOT_W_HIDDEN;
  L->redundant = malloc((out > 0 ? out : 1) * sizeof *L->redundant);
  if (L->redundant == NULL) return -1;
  out = 0;
  for (size_t i = 0; i < n; i++)
    if (keep[i] == LOT_W_HIDDEN) L->redundant[out++] = (uint32_t)i;
  L->st.n = n;
  L->st.duplicates = (size_t)dups;
  L->st.distinct = n - (size_t)dups;
  L->st.redundant = out;
  L->st.flips = acc->flips;
  L->st.rounds = acc->rounds;
  L->st.seconds_init = acc->seconds_init;
  L->st.seconds_flip = acc->seconds_flip;
  return 0;
}

/* WDT with weights: triangulate the sites kept, drop those a concave edge
** certifies redundant, again until none is: the regular triangulation.
** Cost: a LOT per round; a round drops at least one site, and random
** weights need two or three rounds. */
static int lot_build_weighted(lot **out, const geom_point *p, size_t n, const lot_options *o,
                              char *err, size_t errlen) {
  if (lot_validate(p, n, o, err, errlen) != 0) return -1;
  unsigned char *keep = malloc(n), *mark = NULL;
  uint32_t *map = malloc(n * sizeof *map);
  geom_point *q = malloc(n * sizeof *q);
  double *wq = malloc(n * sizeof *wq);
  lot *L = NULL;
  long dups = keep && map && q && wq ? (memset(keep, LOT_W_KEPT, n), 0) : -1;
  if (dups == 0) dups = lot_weighted_dedupe(p, o->weights, (uint32_t)n, keep, map);
  lot_stats acc = {0};
  int rc = dups < 0 ? -2 : 0;
  while (rc == 0) {
    uint32_t m = lot_weighted_subset(p, o->weights, (uint32_t)n, keep, q, wq, map);
    lot_options oo = *o;
    oo.weights = wq;
    if ((rc = lot_build_once(&L, q, m, &oo, err, errlen)) != 0) break;
    acc.flips += L->st.flips;
    acc.rounds++;
    acc.seconds_init += L->st.seconds_init;
    acc.seconds_flip += L->st.seconds_flip;
    if (L->st.status != LOT_CONVERGED) break;   /* unfinished: no LOT to read */
    free(mark);
    if ((mark = calloc(m, 1)) == NULL) rc = -2;
    else if (lot_weighted_hidden(&L->m, wq, mark) == 0) break;
    for (uint32_t k = 0; rc == 0 && k < m; k++)
      if (mark[k]) keep[map[k]] = LOT_W_HIDDEN;
    lot_free(L);
    L = NULL;
  }
  if (rc == 0 && lot_weighted_finish(L, keep, map, n, dups, &acc) != 0) rc = -2;
  if (rc == -2) snprintf(err, errlen, "out of memory for %zu points", n);
  if (rc != 0) lot_free(L);
  *out = rc == 0 ? L : NULL;
  free(keep);
  free(mark);
  free(map);
  free(q);
  free(wq);
  return rc == 0 ? 0 : -1;
}

int lot_build(lot **out, const geom_point *p, size_t n, const lot_options *o, char *err,
              size_t errlen) {
  if (o->weights != NULL && n >= 3) return lot_build_weighted(out, p, n, o, err, errlen);
  return lot_build_once(out, p, n, o, err, errlen);
}

size_t lot_get_redundant(const lot *L, uint32_t *out) {
  if (L->redundant != NULL && L->st.redundant > 0)
    memcpy(out, L->redundant, L->st.redundant * sizeof *out);
  return L->st.redundant;
}

int lot_reflip(lot *L, const lot_options *o) {
  lot_mesh *m = &L->m;
  lot_take_rule(L, o);
  lot_use_rule(L);
  if (lot_mesh_recache(m, lot_cache_of(&L->r, o)) != 0) return -1;
  lot_run R;
  L->st.flips = 0;
  L->st.status = LOT_CONVERGED;
  L->st.cycle_length = 0;
  L->st.cycle_quads = 0;
  lot_run_init(&R, L, o);
  lot_run_hints(&R, 1);
  double t0 = lot_now();
  int rc = lot_flip_all(&R);
  L->st.seconds_init = 0;
  L->st.seconds_flip = lot_now() - t0;
  lot_run_free(&R);
  return rc;
}

/* Bytes per point: input copy in insertion order (16) and its index (4),
** the order (4, transient), 2 triangles of 32 bytes of indices and up to
** 16 of badness (an enclosure), and a caller's input and output
** (16 + 2 * 12 + 2 * 8). */
#define LOT_BYTES_PER_POINT 184u

int lot_check_memory(size_t n, char *err, size_t errlen) {
  long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  double have = pages > 0 && page > 0 ? (double)pages * (double)page : 0;
  double need = (double)n * LOT_BYTES_PER_POINT;
  if (n > LOT_MAX_POINTS || (have > 0 && need > 0.75 * have)) {
    snprintf(err, errlen, "%zu points need about %.3g GB of memory%s", n, need / 1e9,
             n > LOT_MAX_POINTS ? " and more than the supported maximum number of points"
                                : " (more than 3/4 of this machine's memory)");
    return -1;
  }
  return 0;
}

size_t lot_get_hull(const lot *L, uint32_t *out) {
  const lot_mesh *m = &L->m;
  uint32_t x = LOT_NONE;
  for (uint32_t c = 0; c < LOT_CORNER(m->nt, 0) && x == LOT_NONE; c++)
    if (lot_slot(c) < 3 && m->tv[c] == LOT_GHOST) x = c;
  size_t h = L->st.hull;
  for (size_t k = 0; k < h; k++) {   /* ghost edges u -> v run clockwise */
    out[h - 1 - k] = m->inp[m->tv[lot_next3(x)]];
    x = lot_next3(m->tn[lot_next3(x)]);
  }
  return h;
}

const lot_stats *lot_get_stats(const lot *L) {
  return &L->st;
}

size_t lot_get_sweep_ties(const lot *L, int *restarted) {
  if (restarted != NULL) *restarted = L->sweep_restarted;
  return L->sweep_ties;
}

size_t lot_get_constrained(const lot *L, uint32_t *out) {
  return L->constrained ? lot_cdt_edges(&L->cdt, &L->m, out) : 0;
}

static int lot_tri_cmp(const void *x, const void *y) {
  const uint32_t *a = x, *b = y;
  for (int i = 0; i < 3; i++)
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  return 0;
}

/* Insertion sort of a few rows of stride (3 or 4) words by their first
** three (a bucket of lot_rows_sort). */
static FLIPLAB_ALWAYS_INLINE void lot_rows_insertion(uint32_t *r, size_t k, size_t stride) {
  for (size_t i = 1; i < k; i++) {
    uint32_t x[4];
    memcpy(x, r + stride * i, stride * sizeof *r);
    size_t j = i;
    for (; j > 0 && lot_tri_cmp(r + stride * (j - 1), x) > 0; j--)
      memcpy(r + stride * j, r + stride * (j - 1), stride * sizeof *r);
    memcpy(r + stride * j, x, stride * sizeof *r);
  }
}

/* The w rows of stride words (3: a triangle; 4: a triangle and its mesh
** triangle) of src into dst, in the order of qsort with lot_tri_cmp on
** their first three words, in linear time for bounded degree: a counting
** sort on the first word (below n; start: n + 1 zeroed counts), then each
** bucket (the rows whose smallest vertex is v: a handful) by insertion, or
** by qsort when large (a vertex of high degree).  The one sort of
** lot_get_triangles and lot_get_neighbors, inlined into each so that the
** stride is a constant there. */
static FLIPLAB_ALWAYS_INLINE void lot_rows_sort(uint32_t *dst, const uint32_t *src, size_t w,
                                               size_t stride, size_t n, size_t *start) {
  for (size_t t = 0; t < w; t++) start[src[stride * t] + 1]++;
  for (size_t v = 0; v < n; v++) start[v + 1] += start[v];
  for (size_t t = 0; t < w; t++)
    memcpy(dst + stride * start[src[stride * t]]++, src + stride * t, stride * sizeof *src);
  for (size_t v = 0, b = 0; v < n; b = start[v++]) {   /* bucket v is [b, start[v]) */
    size_t k = start[v] - b;
    if (k > 32) qsort(dst + stride * b, k, stride * sizeof *dst, lot_tri_cmp);
    else lot_rows_insertion(dst + stride * b, k, stride);
  }
}

/* The order of qsort with lot_tri_cmp (a total order: the triangles are
** distinct), by lot_rows_sort from a copy; qsort alone when the copy
** cannot be made.  For 2 10^6 triangles about ten times faster than qsort,
** which cost as much as the triangulation. */
static void lot_sort_triangles(uint32_t *tri, size_t w, size_t n) {
  size_t *start = calloc(n + 1, sizeof *start);
  uint32_t *copy = malloc((w ? 3 * w : 1) * sizeof *copy);
  if (start == NULL || copy == NULL) {
    free(start);
    free(copy);
    qsort(tri, w, 3 * sizeof *tri, lot_tri_cmp);
    return;
  }
  memcpy(copy, tri, 3 * w * sizeof *tri);
  lot_rows_sort(tri, copy, w, 3, n, start);
  free(start);
  free(copy);
}

void lot_get_triangles(const lot *L, uint32_t *tri) {
  const lot_mesh *m = &L->m;
  size_t w = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (lot_is_ghost(m, t) || lot_cdt_gone(&L->cdt, t)) continue;
    uint32_t v[3];
    for (int i = 0; i < 3; i++) v[i] = m->inp[m->tv[LOT_CORNER(t, i)]];
    int s = v[0] < v[1] ? (v[0] < v[2] ? 0 : 2) : (v[1] < v[2] ? 1 : 2);
    for (int i = 0; i < 3; i++) tri[3 * w + i] = v[(s + i) % 3];
    w++;
  }
  lot_sort_triangles(tri, w, L->st.n);
}

void lot_free(lot *L) {
  if (L == NULL) return;
  free(L->redundant);
  lot_mesh_free(&L->m);
  lot_cdt_free(&L->cdt);
  free(L);
}

/* ---- neighbours from the mesh (lot_get_neighbors) ---- */

/* Insertion sort of a few 4-word records (v0, v1, v2, mesh triangle) by
** their first three words: a bucket of lot_rank_triangles. */

/* Triangle t's vertices as lot_get_triangles writes them (input indices,
** the smallest first) into v; returns the slot of the mesh corner that
** became v[0]. */
static int lot_tri_rotated(const lot_mesh *m, uint32_t t, uint32_t v[3]) {
  uint32_t w[3];
  for (int i = 0; i < 3; i++) w[i] = m->inp[m->tv[LOT_CORNER(t, i)]];
  int s = w[0] < w[1] ? (w[0] < w[2] ? 0 : 2) : (w[1] < w[2] ? 1 : 2);
  for (int i = 0; i < 3; i++) v[i] = w[(s + i) % 3];
  return s;
}

/* The rows of lot_get_triangles as records rec[4i..4i+3] = (v0, v1, v2, mesh
** triangle), in its order, found by the same sort (lot_rows_sort, into
** rec); rot[t] =
** the mesh corner slot that became v0.  One pass over the mesh reads its
** vertices (into tmp, in mesh order); the others read arrays in order.
** O(n + T) time for bounded degree.  0, or -1 when out of memory. */
static int lot_rows(const lot *L, uint32_t *rec, uint8_t *rot) {
  const lot_mesh *m = &L->m;
  size_t n = L->st.n, w = 0;
  size_t *start = calloc(n + 1, sizeof *start);
  uint32_t *tmp = malloc((L->st.triangles ? 4 * L->st.triangles : 1) * sizeof *tmp);
  if (start == NULL || tmp == NULL) {
    free(start);
    free(tmp);
    return -1;
  }
  for (uint32_t t = 0; t < m->nt; t++) {
    if (lot_is_ghost(m, t) || lot_cdt_gone(&L->cdt, t)) continue;
    rot[t] = (uint8_t)lot_tri_rotated(m, t, tmp + 4 * w);
    tmp[4 * w++ + 3] = t;
  }
  lot_rows_sort(rec, tmp, w, 4, n, start);
  free(start);
  free(tmp);
  return 0;
}

/* Row i is mesh triangle t = rec[4i + 3]; its vertex k is mesh corner
** (rot[t] + k) % 3, and the triangle across the edge opposite it is the
** one of the twin corner tn[], whose row is rank[] (-1 for a ghost or a
** removed triangle).  Scratch: 36 bytes per triangle, 8 per point. */
int lot_get_neighbors(const lot *L, int32_t *nb) {
  const lot_mesh *m = &L->m;
  size_t w = L->st.triangles, nt = m->nt ? m->nt : 1;
  uint32_t *rec = malloc((w ? 4 * w : 1) * sizeof *rec);
  int32_t *rank = malloc(nt * sizeof *rank);
  uint8_t *rot = malloc(nt);
  int rc = rec != NULL && rank != NULL && rot != NULL ? lot_rows(L, rec, rot) : -1;
  if (rc == 0) {
    for (uint32_t t = 0; t < m->nt; t++) rank[t] = -1;
    for (size_t i = 0; i < w; i++) rank[rec[4 * i + 3]] = (int32_t)i;
    for (uint32_t t = 0; t < m->nt; t++) {   /* mesh order: tn is read in order */
      if (rank[t] < 0) continue;
      int32_t *row = nb + 3 * (size_t)rank[t];
      for (uint32_t k = 0; k < 3; k++)
        row[k] = rank[lot_tri_of(m->tn[LOT_CORNER(t, (rot[t] + k) % 3)])];
    }
  }
  free(rec);
  free(rank);
  free(rot);
  return rc;
}
