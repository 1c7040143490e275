/*
** mesh.c: the triangle-neighbour structure of mesh.h: the first
** triangle, point location by a walk, insertion (inside a triangle, on an
** edge, outside the hull), the flip, and the per-triangle badness cache
** (exact values, or enclosures made exact on demand).
**
** All geometric decisions are exact (geom_orient_valid: lot_build has
** checked every point against the coordinate contract).  The walk is the
** "remembering stochastic" visibility walk (Devillers, Pion and Teillaud,
** Walking in a triangulation, 2002): from the current triangle it crosses
** an edge that separates it from the point, trying the edges from a
** pseudo-random one; in a triangulation that is not Delaunay a fixed order
** can cycle, a random start cannot forever.  The generator is seeded per
** mesh, so runs are reproducible; after far more steps than triangles the
** walk gives way to a scan of every triangle, so it always ends.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "mesh.h"
#include "measure.h"
#include "splitmix.h"

/* The cache's array for its kind (the other one freed): 0, or -1. */
static int lot_cache_alloc(lot_mesh *m, lot_cache cache) {
  free(m->bad);
  free(m->enc);
  m->bad = NULL;
  m->enc = NULL;
  if (cache == LOT_CACHE_EXACT) m->bad = malloc((size_t)m->cap * sizeof *m->bad);
  if (cache == LOT_CACHE_ENCLOSED) m->enc = malloc((size_t)m->cap * sizeof *m->enc);
  return cache == LOT_CACHE_NONE || m->bad || m->enc ? 0 : -1;
}

int lot_mesh_alloc(lot_mesh *m, uint32_t np, lot_cache cache) {
  memset(m, 0, sizeof *m);
  m->np = np;
  m->cap = 2 * np + 4;
  m->p = malloc((size_t)np * sizeof *m->p);
  m->inp = malloc((size_t)np * sizeof *m->inp);
  m->tv = calloc(LOT_CORNER((size_t)m->cap, 0), sizeof *m->tv);   /* slot 3: no hint */
  m->tn = malloc(LOT_CORNER((size_t)m->cap, 0) * sizeof *m->tn);
  m->walk = GEOM_STATE_LOT_WALK;
  if (!m->p || !m->inp || !m->tv || !m->tn || lot_cache_alloc(m, cache) != 0) {
    lot_mesh_free(m);
    return -1;
  }
  return 0;
}

size_t lot_mesh_bytes(const lot_mesh *m) {
  size_t cache = m->bad ? sizeof *m->bad : m->enc ? sizeof *m->enc : 0;
  return (size_t)m->np * (sizeof *m->p + sizeof *m->inp)
       + (size_t)m->cap * (2 * LOT_CORNER(sizeof *m->tv, 0) + cache);
}

void lot_mesh_free(lot_mesh *m) {
  free(m->p);
  free(m->inp);
  free(m->tv);
  free(m->tn);
  free(m->bad);
  free(m->enc);
  memset(m, 0, sizeof *m);
}

double lot_mesh_badness(const lot_mesh *m, uint32_t a, uint32_t b, uint32_t c) {
  if (m->pts) return m->pts(m->p[a], m->p[b], m->p[c]);   /* built-in: inline kernel */
  geom_tri t;
  geom_tri_make_fields(&t, m->p[a], m->p[b], m->p[c], m->fields);
  return m->meas->fn(&t, m->meas->ctx);
}

lot_enc lot_mesh_enclose(const lot_mesh *m, uint32_t a, uint32_t b, uint32_t c) {
  lot_enc e;
  if (!measure_bounds(rule_measure(m->r), m->p[a], m->p[b], m->p[c], &e.lo, &e.hi))
    e.lo = e.hi = lot_mesh_badness(m, a, b, c);
  return e;
}

void lot_mesh_exact(lot_mesh *m, uint32_t t) {
  lot_enc *e = &m->enc[t];
  if (e->lo == e->hi) return;
  const uint32_t *v = m->tv + LOT_CORNER((size_t)t, 0);
  e->lo = e->hi = lot_mesh_badness(m, v[0], v[1], v[2]);
}

/* Triangle t's cache entry from its vertices (0 for a ghost). */
static void lot_cache_set(lot_mesh *m, uint32_t t) {
  const uint32_t *v = m->tv + LOT_CORNER((size_t)t, 0);
  int ghost = v[0] == LOT_GHOST || v[1] == LOT_GHOST || v[2] == LOT_GHOST;
  if (m->bad) m->bad[t] = ghost ? 0 : lot_mesh_badness(m, v[0], v[1], v[2]);
  else if (m->enc) m->enc[t] = ghost ? (lot_enc){0, 0} : lot_mesh_enclose(m, v[0], v[1], v[2]);
}

int lot_mesh_recache(lot_mesh *m, lot_cache cache) {
  if (lot_cache_alloc(m, cache) != 0) return -1;
  for (uint32_t t = 0; t < m->nt; t++) lot_cache_set(m, t);
  return 0;
}

void lot_mesh_link(lot_mesh *m, uint32_t c1, uint32_t c2) {
  m->tn[c1] = c2;
  m->tn[c2] = c1;
}

void lot_mesh_set(lot_mesh *m, uint32_t t, uint32_t a, uint32_t b, uint32_t c) {
  uint32_t *v = m->tv + LOT_CORNER((size_t)t, 0);
  v[0] = a;
  v[1] = b;
  v[2] = c;
  v[3] = 0;   /* no hint */
  if (m->bad || m->enc) lot_cache_set(m, t);
}

void lot_mesh_first(lot_mesh *m, uint32_t a, uint32_t b, uint32_t c) {
  /* t0 = abc; ghosts g1 = (b, a, G), g2 = (c, b, G), g3 = (a, c, G). */
  lot_mesh_set(m, 0, a, b, c);
  lot_mesh_set(m, 1, b, a, LOT_GHOST);
  lot_mesh_set(m, 2, c, b, LOT_GHOST);
  lot_mesh_set(m, 3, a, c, LOT_GHOST);
  lot_mesh_link(m, 0, LOT_CORNER(2, 2));       /* opposite a: bc */
  lot_mesh_link(m, 1, LOT_CORNER(3, 2));       /* opposite b: ca */
  lot_mesh_link(m, 2, LOT_CORNER(1, 2));       /* opposite c: ab */
  lot_mesh_link(m, LOT_CORNER(1, 0), LOT_CORNER(3, 1));
  lot_mesh_link(m, LOT_CORNER(1, 1), LOT_CORNER(2, 0));
  lot_mesh_link(m, LOT_CORNER(2, 1), LOT_CORNER(3, 0));
  m->nt = 4;
  m->last = 0;
  ops_add(m->ops, OPS_EDGES_MADE, 3);
}

/* i mod 3 for i < 6, by table: the first step's and lot_scan's edge
** arithmetic without divisions. */
static const uint8_t lot_mod3[6] = {0, 1, 2, 0, 1, 2};

/* A random edge 0, 1 or 2 (xorshift64 on the state *s; the high word
** times 3, >> 32). */
static inline uint32_t lot_walk_rand3(uint64_t *s) {
  uint64_t x = *s;
  x ^= x << 13;
  x ^= x >> 7;
  x ^= x << 17;
  *s = x;
  return (uint32_t)(((x >> 32) * 3) >> 32);
}

/* Classify q against the real triangle t whose three orientations are o[]
** (none negative). */
static lot_where lot_classify(uint32_t t, const int o[3], uint32_t *c) {
  int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
  if (zeros == 0) {
    *c = LOT_CORNER(t, 0);
    return LOT_IN_TRIANGLE;
  }
  if (zeros == 1) {
    *c = LOT_CORNER(t, o[0] == 0 ? 0u : o[1] == 0 ? 1u : 2u);
    return LOT_ON_EDGE;
  }
  *c = LOT_CORNER(t, o[0] != 0 ? 0u : o[1] != 0 ? 1u : 2u);   /* on both other edges: that vertex */
  return LOT_ON_VERTEX;
}

/* The last resort of the walk: look at every triangle. */
static lot_where lot_scan(const lot_mesh *m, geom_point q, uint32_t *c) {
  for (uint32_t t = 0; t < m->nt; t++) {
    if (lot_is_ghost(m, t)) continue;
    const uint32_t *v = m->tv + LOT_CORNER((size_t)t, 0);
    int o[3];
    for (int e = 0; e < 3; e++)
      o[e] = geom_orient_valid(m->p[v[lot_mod3[e + 1]]], m->p[v[lot_mod3[e + 2]]], q);
    if (o[0] >= 0 && o[1] >= 0 && o[2] >= 0) return lot_classify(t, o, c);
  }
  for (uint32_t t = 0; t < m->nt; t++) {
    const uint32_t *v = m->tv + LOT_CORNER((size_t)t, 0);
    for (int g = 0; g < 3; g++)
      if (v[g] == LOT_GHOST &&
          geom_orient_valid(m->p[v[lot_mod3[g + 1]]], m->p[v[lot_mod3[g + 2]]], q) > 0) {
        *c = LOT_CORNER(t, g);
        return LOT_OUTSIDE;
      }
  }
  *c = 0;
  return LOT_ON_VERTEX;   /* unreachable for a valid mesh */
}

/* The walk inside a triangle it has entered: nc is the corner opposite the
** edge it came through, a = tv[nc] its apex and pa a's point (when a is
** not LOT_GHOST); that edge runs from L = tv[next(nc)] to R =
** tv[prev(nc)].  The two ways on are exit 0, the edge opposite L
** (R -> A), which makes A the next triangle's L, and exit 1, the edge
** opposite R (A -> L), which makes A its R.  nx[x] = tn[corner of L or R]
** is the corner beyond exit x, loaded a step ahead.  Beside this struct
** the walk keeps d[0] = L - q and d[1] = R - q, carried over from the
** triangle before (exit x replaces d[x] by A - q); apart, because that
** store by index keeps its array in memory, and would keep the struct
** there too. */
typedef struct lot_walk {
  uint32_t nc, a, nx[2];
  geom_point pa;
  geom_point dg;        /* the guide point minus q (lot_mesh_locate) */
  unsigned guided;      /* 1 while the exit is chosen by the guide, 0 by the draw */
} lot_walk;

/* The triangles beyond both exits, loaded (lot_walk_step): their entry
** corners, apexes, apex points and the corners beyond their own exits,
** one array per field so that the step's choice reads each with one
** indexed load. */
typedef struct lot_walk_ahead {
  uint32_t nc[2], a[2], nx0[2], nx1[2];
  geom_point pa[2];
} lot_walk_ahead;

/* The arrays the step reads, copied out of the mesh: the step's rare
** out-of-line calls (lot_walk_settle) could change *m as far as the
** compiler knows, so read through m the pointers would be reloaded on
** every step; these copies stay in registers. */
typedef struct lot_walk_view {
  const uint32_t *tv, *tn;
  const geom_point *p;
} lot_walk_view;

/* Load the triangle entered at corner nc as candidate x of *h. */
static inline void lot_walk_load(lot_walk_view v, uint32_t nc, lot_walk_ahead *h, int x) {
  uint32_t a = v.tv[nc];
  h->nc[x] = nc;
  h->a[x] = a;
  h->pa[x] = v.p[a != LOT_GHOST ? a : 0];   /* a ghost's point is never read */
  h->nx0[x] = v.tn[lot_next3(nc)];
  h->nx1[x] = v.tn[lot_prev3(nc)];
}

/* Move the walk into candidate x of *h. */
static inline void lot_walk_take(lot_walk *w, const lot_walk_ahead *h, unsigned x) {
  w->nc = h->nc[x];
  w->a = h->a[x];
  w->pa = h->pa[x];
  w->nx[0] = h->nx0[x];
  w->nx[1] = h->nx1[x];
}

static inline geom_point lot_walk_diff(geom_point a, geom_point q) {
  return (geom_point){a.x - q.x, a.y - q.y};
}

/* q's side of the directed line a -> b from da = a - q and db = b - q:
** orient(a, b, q) = orient(q, a, b) = da.x db.y - da.y db.x.  That is
** Shewchuk's orient2d(a, b, q) in his own form (differences to the third
** point), and his bound GEOM_CCW_ERRBOUND_A (geom/predicates.h),
** |fl(det) - det| <= GEOM_CCW_ERRBOUND_A (|l| + |r|) with l, r the two
** products, covers the rounding of da, db and
** of the products, as for geom_orient_filtered (which takes differences to
** a instead); within the coordinate contract nothing under- or overflows
** (geom_orient_valid).  So when |fl(det)| is larger, fl(det) has the exact
** sign (and is not 0); otherwise *unsure is set and the step asks
** geom_orient_valid.  Either way the walk sees the exact sign. */
static inline double lot_walk_det(geom_point da, geom_point db, int *unsure) {
  double l = da.x * db.y, r = da.y * db.x, det = l - r;
  double bound = GEOM_CCW_ERRBOUND_A * (fabs(l) + fabs(r));
  *unsure |= fabs(det) <= bound;
  return det;
}

/* The filter could not tell a side: decide the exit with geom_orient_valid
** instead, reading the edges in the step's order (r_first: the edge
** opposite R first) and the second only when q is not beyond the first.
** Returns bit 0 for the edge opposite L, bit 1 for the edge opposite R,
** 0 when q is beyond neither. */
static unsigned lot_walk_settle(const lot_mesh *m, uint32_t nc, geom_point q, unsigned r_first) {
  geom_point pa = m->p[m->tv[nc]], pl = m->p[m->tv[lot_next3(nc)]];
  geom_point pr = m->p[m->tv[lot_prev3(nc)]];
  for (unsigned k = 0; k < 2; k++) {
    unsigned right = (k == 0) == (r_first != 0);
    if ((right ? geom_orient_valid(pa, pl, q) : geom_orient_valid(pr, pa, q)) < 0)
      return right ? 2u : 1u;
  }
  return 0;
}

/* The walk ends in the real triangle of corner nc, q strictly on the inner
** side of the edge opposite nc and not beyond the other two: where in it. */
static lot_where lot_walk_stop(const lot_mesh *m, uint32_t nc, geom_point q, uint32_t *c) {
  uint32_t t = lot_tri_of(nc);
  const uint32_t *v = m->tv + LOT_CORNER((size_t)t, 0);
  int o[3];
  for (uint32_t e = 0; e < 3; e++)
    o[e] = e == lot_slot(nc)
               ? 1 : geom_orient_valid(m->p[v[lot_mod3[e + 1]]], m->p[v[lot_mod3[e + 2]]], q);
  return lot_classify(t, o, c);
}

/* The exit (0: the edge opposite L, 1: the edge opposite R) is bit i of
** LOT_WALK_EXIT, i = [q beyond the edge opposite L] + 2 [beyond the edge
** opposite R] + 4 [the edge opposite R is tried first]: the edge tried
** first if q is beyond it, else the other. */
#define LOT_WALK_EXIT 0xC4u

/* One step from the real triangle of w->nc: cross an edge q is strictly
** beyond, or return 1 when there is none.  The edge tried first is the
** first after a drawn edge e0 in the order e0, e0 + 1, e0 + 2, skipping
** the way in: the edge opposite R when e0 is R's slot, else the edge
** opposite L.
** Why it is written this way: which exit q lies beyond is a coin toss, so
** a branch on it would be mispredicted every other step; and the
** triangles around a point were made at scattered times, so their entries
** lie far apart in memory.  So both orientations are computed and the
** exit picked by selects (on the sign bits, read as integers so that the
** compiler does not turn them into branches), and while they are computed
** the step loads, for both triangles it may enter, the apex, its point
** and the corners beyond their exits: the next step's data is then one
** select away rather than three dependent loads. */
static inline int lot_walk_step(const lot_mesh *m, lot_walk_view v, lot_walk *w, geom_point d[2],
                                geom_point q, uint64_t *s) {
  lot_walk_ahead h;
  lot_walk_load(v, w->nx[0], &h, 0);
  lot_walk_load(v, w->nx[1], &h, 1);
  unsigned r_first = lot_walk_rand3(s) == lot_slot(lot_prev3(w->nc)), i;
  int unsure = 0;
  geom_point da = lot_walk_diff(w->pa, q);
  /* Guided: the edge opposite R first when the apex is (weakly) left of
  ** the line from the guide point g to q, i.e. when that line passes on
  ** the side of R.  Plain arithmetic: only a choice between two exits that
  ** are both correct, which rounding may make either way. */
  unsigned g_first = w->dg.x * da.y - w->dg.y * da.x >= 0;
  r_first = w->guided ? g_first : r_first;
  double detl = lot_walk_det(d[1], da, &unsure), detr = lot_walk_det(da, d[0], &unsure);
  if (unsure) {
    if ((i = lot_walk_settle(m, w->nc, q, r_first)) == 0) return 1;
  } else {
    uint64_t bl, br;   /* past the filter det != 0: its sign bit says det < 0 */
    memcpy(&bl, &detl, sizeof bl);
    memcpy(&br, &detr, sizeof br);
    if ((bl | br) >> 63 == 0) return 1;
    i = (unsigned)(bl >> 63 | br >> 63 << 1);
  }
  unsigned x = (LOT_WALK_EXIT >> (i | r_first << 2)) & 1;
  d[x] = da;
  lot_walk_take(w, &h, x);
  return 0;
}

/* The first step, in the real triangle t: the edges in the order e0,
** e0 + 1, e0 + 2 from a drawn e0, crossing the first that q is strictly
** beyond.  Returns 1 (*where and *c set) when there is none, else 0 with
** *w and d in the triangle beyond. */
static int lot_walk_first(const lot_mesh *m, uint32_t t, geom_point q, uint64_t *s,
                          lot_walk *w, geom_point d[2], uint32_t *c, lot_where *where) {
  const uint32_t *v = m->tv + LOT_CORNER((size_t)t, 0);
  uint32_t e0 = lot_walk_rand3(s);
  int o[3] = {1, 1, 1};
  for (uint32_t k = 0; k < 3; k++) {
    uint32_t e = lot_mod3[e0 + k];
    geom_point pr = m->p[v[lot_mod3[e + 1]]], pl = m->p[v[lot_mod3[e + 2]]];
    o[e] = geom_orient_valid(pr, pl, q);
    ops_add(m->ops, OPS_ORIENT, 1);
    if (o[e] < 0) {   /* the triangle beyond sees this edge from pl to pr */
      lot_walk_ahead h;
      lot_walk_load((lot_walk_view){m->tv, m->tn, m->p}, m->tn[LOT_CORNER(t, e)], &h, 0);
      lot_walk_take(w, &h, 0);
      d[0] = lot_walk_diff(pl, q);
      d[1] = lot_walk_diff(pr, q);
      return 0;
    }
  }
  *where = lot_classify(t, o, c);
  return 1;
}

/* Where the walk starts: m->last, or the real triangle next to it if it
** is a ghost. */
static uint32_t lot_walk_start(const lot_mesh *m) {
  uint32_t t = m->last;
  const uint32_t *v = m->tv + LOT_CORNER((size_t)t, 0);
  for (uint32_t g = 0; g < 3; g++)
    if (v[g] == LOT_GHOST) return lot_tri_of(m->tn[LOT_CORNER(t, g)]);
  return t;
}

/* Steps of the guided phase (lot_mesh_locate). */
#define LOT_WALK_GUIDED 2048u

/* The remembering stochastic walk (file comment), guided.  Where q is
** beyond both exits of a step, the walk takes the one that the line from
** a guide point g (the start triangle's centroid) to q passes through
** rather than a random one: in the needle-filled LOTs of beta, -A or -c a
** random choice wanders along the needles, and the guided walk crosses
** about a third fewer triangles (beta_1 on 3 10^5 points: 30 steps per
** point instead of 49).  Like every visibility walk it only ever crosses
** an edge that q is strictly beyond, so wherever it stops it is right.
** Why it ends: in a
** Delaunay triangulation any visibility walk does (Edelsbrunner), but in
** the needle-filled LOTs of other rules a fixed choice of exit edge can
** cycle for ever; with each step's first edge drawn at random, both exits
** have a probability of at least 1/3 whenever q is beyond both, so the
** walk leaves any cycle with probability 1 (Devillers, Pion and Teillaud,
** 2002).  The guided choice is fixed, so it could cycle in principle:
** after LOT_WALK_GUIDED steps the drawn choice takes over, and that
** argument applies to the rest.  For a guarantee rather than a
** probability, after 4 nt + 64 steps lot_scan decides.  A ghost triangle is recognised by its apex: a real
** triangle's neighbour across an edge is a ghost exactly when the vertex
** opposite that edge is LOT_GHOST, which the step loads anyway.
** Each step draws one number whether or not it uses it.  The path, and so
** the side of an edge from which it reaches a point on that edge (which
** decides the triangles' numbering and the flips' order), is a fixed
** function of the mesh, q and the generator's state: the same on every
** machine (plain arithmetic, no FMA). */
lot_where lot_mesh_locate(lot_mesh *m, geom_point q, uint32_t *c) {
  uint64_t s = m->walk, limit = 4 * (uint64_t)m->nt + 64;
  lot_walk_view v = {m->tv, m->tn, m->p};
  lot_walk w;
  geom_point d[2];
  lot_where where;
  uint32_t t0 = lot_walk_start(m);
  const uint32_t *tv0 = m->tv + LOT_CORNER((size_t)t0, 0);
  geom_point p0 = m->p[tv0[0]], p1 = m->p[tv0[1]], p2 = m->p[tv0[2]];
  w.dg = (geom_point){(p0.x + p1.x + p2.x) / 3 - q.x, (p0.y + p1.y + p2.y) / 3 - q.y};
  w.guided = 1;
  uint64_t step = 0;
  if (!lot_walk_first(m, t0, q, &s, &w, d, c, &where)) {
    for (step = 1;; step++) {
      if (step == LOT_WALK_GUIDED) w.guided = 0;
      if (w.a == LOT_GHOST) {   /* crossed the hull: the ghost's ghost corner */
        *c = w.nc;
        where = LOT_OUTSIDE;
        break;
      }
      if (step == limit) {
        where = lot_scan(m, q, c);
        break;
      }
      if (lot_walk_step(m, v, &w, d, q, &s)) {
        where = lot_walk_stop(m, w.nc, q, c);
        break;
      }
    }
  }
  m->walk = s;
  /* Counted once per location, off the walk's loop: its steps (triangles
  ** entered), two orientations per step, and the last triangle's two. */
  ops_add(m->ops, OPS_LOCATE, step + 1);
  ops_add(m->ops, OPS_ORIENT, 2 * step);
  return where;
}

/* Split triangle t = (a, b, c) at k: (a, b, k), (b, c, k), (c, a, k). */
static void lot_split_triangle(lot_mesh *m, uint32_t t, uint32_t k, uint32_t out[3]) {
  uint32_t a = m->tv[LOT_CORNER(t, 0)], b = m->tv[LOT_CORNER(t, 1)], c = m->tv[LOT_CORNER(t, 2)];
  uint32_t na = m->tn[LOT_CORNER(t, 0)], nb = m->tn[LOT_CORNER(t, 1)];
  uint32_t t1 = m->nt++, t2 = m->nt++;
  lot_mesh_set(m, t, a, b, k);
  lot_mesh_set(m, t1, b, c, k);
  lot_mesh_set(m, t2, c, a, k);
  lot_mesh_link(m, LOT_CORNER(t, 0), LOT_CORNER(t1, 1));
  lot_mesh_link(m, LOT_CORNER(t, 1), LOT_CORNER(t2, 0));
  lot_mesh_link(m, LOT_CORNER(t1, 0), LOT_CORNER(t2, 1));
  lot_mesh_link(m, LOT_CORNER(t1, 2), na);
  lot_mesh_link(m, LOT_CORNER(t2, 2), nb);
  out[0] = LOT_CORNER(t, 2);
  out[1] = LOT_CORNER(t1, 2);
  out[2] = LOT_CORNER(t2, 2);
}

/* Split the edge opposite corner c (of t = (a, b, c0), the other side
** t' = (d, c0, b), possibly a ghost) at k: (a, b, k), (a, k, c0),
** (d, c0, k), (d, k, b).  out: the corners of k in the four triangles. */
static void lot_split_edge(lot_mesh *m, uint32_t c, uint32_t k, uint32_t out[4]) {
  uint32_t t = lot_tri_of(c), cb = lot_next3(c), cc = lot_next3(cb);
  uint32_t cd = m->tn[c], u = lot_tri_of(cd), ud = cd, uc = lot_next3(cd), ub = lot_next3(uc);
  uint32_t a = m->tv[c], b = m->tv[cb], c0 = m->tv[cc], d = m->tv[ud];
  uint32_t n_ca = m->tn[cb], n_ab = m->tn[cc], n_bd = m->tn[uc], n_dc = m->tn[ub];
  uint32_t t1 = m->nt++, t2 = m->nt++;
  lot_mesh_set(m, t, a, b, k);
  lot_mesh_set(m, t1, a, k, c0);
  lot_mesh_set(m, u, d, c0, k);
  lot_mesh_set(m, t2, d, k, b);
  lot_mesh_link(m, LOT_CORNER(t, 0), LOT_CORNER(t2, 0));
  lot_mesh_link(m, LOT_CORNER(t, 1), LOT_CORNER(t1, 2));
  lot_mesh_link(m, LOT_CORNER(t, 2), n_ab);
  lot_mesh_link(m, LOT_CORNER(t1, 0), LOT_CORNER(u, 0));
  lot_mesh_link(m, LOT_CORNER(t1, 1), n_ca);
  lot_mesh_link(m, LOT_CORNER(u, 1), LOT_CORNER(t2, 2));
  lot_mesh_link(m, LOT_CORNER(u, 2), n_dc);
  lot_mesh_link(m, LOT_CORNER(t2, 1), n_bd);
  out[0] = LOT_CORNER(t, 2);
  out[1] = LOT_CORNER(t1, 1);
  out[2] = LOT_CORNER(u, 2);
  out[3] = LOT_CORNER(t2, 1);
}

/* k outside the hull, seeing the edge of ghost g (ghost corner gc): every
** ghost whose edge k sees becomes a real triangle with k in place of the
** ghost vertex; two new ghosts close the hull at both ends of that chain. */
static long lot_insert_outside(lot_mesh *m, uint32_t gc, uint32_t k, uint32_t **cand,
                               size_t *candcap) {
  geom_point q = m->p[k];
  /* Walk back to the first visible ghost.  Ghost corner x: edge
  ** (tv[next(x)], tv[prev(x)]); the previous ghost is across the edge
  ** opposite prev(x), the next one across the edge opposite next(x). */
  uint32_t first = gc;
  for (uint32_t guard = 0; guard < m->nt; guard++) {
    /* The previous ghost (z, u, G) faces edge (u, G) with z's corner pc. */
    uint32_t pc = m->tn[lot_prev3(first)];
    uint32_t pg = lot_prev3(pc);
    ops_add(m->ops, OPS_ORIENT, pg != gc);
    if (pg == gc ||
        geom_orient_valid(m->p[m->tv[lot_next3(pg)]], m->p[m->tv[lot_prev3(pg)]], q) <= 0)
      break;
    first = pg;
  }
  size_t nc = 0;
  uint32_t x = first, last = first;
  for (uint32_t guard = 0; guard < m->nt; guard++) {
    if (nc == *candcap) {
      size_t cap = *candcap * 2 + 16;
      uint32_t *nw = realloc(*cand, cap * sizeof *nw);
      if (nw == NULL) return -1;
      *cand = nw;
      *candcap = cap;
    }
    uint32_t t = lot_tri_of(x);
    m->tv[x] = k;
    m->tv[LOT_CORNER(t, 3)] = 0;
    if (m->bad || m->enc) lot_cache_set(m, t);
    (*cand)[nc++] = x;
    last = x;
    /* The next ghost (v, w, G) faces edge (G, v) with w's corner. */
    uint32_t ng = lot_next3(m->tn[lot_next3(x)]);
    if (m->tv[ng] != LOT_GHOST) break;       /* it was converted already: wrapped around */
    ops_add(m->ops, OPS_ORIENT, 1);
    if (geom_orient_valid(m->p[m->tv[lot_next3(ng)]], m->p[m->tv[lot_prev3(ng)]], q) <= 0)
      break;
    x = ng;
  }
  /* Close: first = (u0, v0, k) at corners next, prev of k; last = (um, vm, k). */
  uint32_t A = m->nt++, B = m->nt++;
  uint32_t u0 = m->tv[lot_next3(first)], vm = m->tv[lot_prev3(last)];
  uint32_t prev_in = m->tn[lot_prev3(first)];   /* previous ghost's corner facing edge (u0, G) */
  uint32_t next_in = m->tn[lot_next3(last)];    /* next ghost's corner facing edge (vm, G) */
  lot_mesh_set(m, A, u0, k, LOT_GHOST);
  lot_mesh_set(m, B, k, vm, LOT_GHOST);
  lot_mesh_link(m, LOT_CORNER(A, 2), lot_prev3(first));    /* edge u0-k */
  lot_mesh_link(m, LOT_CORNER(A, 1), prev_in);              /* edge G-u0 */
  lot_mesh_link(m, LOT_CORNER(B, 2), lot_next3(last));      /* edge k-vm */
  lot_mesh_link(m, LOT_CORNER(B, 0), next_in);              /* edge vm-G */
  lot_mesh_link(m, LOT_CORNER(A, 0), LOT_CORNER(B, 1));            /* edge k-G */
  return (long)nc;
}

long lot_mesh_insert(lot_mesh *m, uint32_t k, lot_where w, uint32_t c, uint32_t **cand,
                     size_t *candcap) {
  if (*candcap < 6) {
    uint32_t *nw = realloc(*cand, 16 * sizeof *nw);
    if (nw == NULL) return -1;
    *cand = nw;
    *candcap = 16;
  }
  uint32_t out[4];
  long n = 0;
  /* A split hull edge has a ghost beyond it: its edge to k is no edge. */
  int far_real = w == LOT_ON_EDGE && m->tv[m->tn[c]] != LOT_GHOST;
  if (w == LOT_OUTSIDE) {
    n = lot_insert_outside(m, c, k, cand, candcap);
  } else if (w == LOT_IN_TRIANGLE) {
    lot_split_triangle(m, lot_tri_of(c), k, out);
    for (int i = 0; i < 3; i++) (*cand)[n++] = out[i];
  } else {
    /* The halves b-k and k-c0 of the split edge are candidates too: their
    ** quadrilaterals (a, b, d, k) and (a, k, d, c0) can be strictly convex
    ** (k-a and k-d are not: b, k, c0 are collinear).  DT never flips them
    ** (an edge's halves keep its empty circle); other rules may. */
    lot_split_edge(m, c, k, out);
    for (int i = 0; i < 4; i++) (*cand)[n++] = out[i];
    (*cand)[n++] = lot_prev3(lot_prev3(out[0]));   /* a's corner in (a, b, k): edge b-k */
    (*cand)[n++] = lot_prev3(out[1]);              /* a's corner in (a, k, c0): edge k-c0 */
  }
  if (n < 0) return -1;
  /* Edges made: k's to the triangle's corners, to a split edge's ends and
  ** apexes (the edge itself deleted), or to the hull chain it sees. */
  ops_add(m->ops, OPS_EDGES_MADE, w == LOT_IN_TRIANGLE ? 3u : w == LOT_ON_EDGE ? 3u + far_real
                                   : (uint64_t)n + 1);
  if (w == LOT_ON_EDGE) ops_add(m->ops, OPS_EDGES_DELETED, 1);
  m->last = lot_tri_of((*cand)[0]);
  /* Keep only edges with a real triangle on both sides. */
  long kept = 0;
  for (long i = 0; i < n; i++) {
    uint32_t x = (*cand)[i];
    if (!lot_is_ghost(m, lot_tri_of(x)) && !lot_is_ghost(m, lot_tri_of(m->tn[x])))
      (*cand)[kept++] = x;
  }
  return kept;
}

void lot_mesh_flip(lot_mesh *m, uint32_t c, double bad_t, double bad_u) {
  uint32_t t = lot_tri_of(c), i1 = lot_next3(c), i2 = lot_next3(i1);
  uint32_t j0 = m->tn[c], u = lot_tri_of(j0), j1 = lot_next3(j0), j2 = lot_next3(j1);
  uint32_t a = m->tv[c], d = m->tv[j0];
  uint32_t n_ca = m->tn[i1], n_bd = m->tn[j1];
  ops_add(m->ops, OPS_FLIPS, 1);
  ops_add(m->ops, OPS_EDGES_MADE, 1);
  ops_add(m->ops, OPS_EDGES_DELETED, 1);
  m->tv[i2] = d;
  m->tv[j2] = a;
  m->tv[LOT_CORNER(t, 3)] = m->tv[LOT_CORNER(u, 3)] = 0;   /* no hints */
  lot_mesh_link(m, c, n_bd);
  lot_mesh_link(m, j0, n_ca);
  lot_mesh_link(m, i1, j1);
  if (m->bad) {
    m->bad[t] = bad_t;
    m->bad[u] = bad_u;
  }
}

/* ---- validity (the polygon sweep's special position, lot.c) ------------
**
** lot_mesh_valid decides whether the triangles and ghosts of m are a
** triangulation of m's `distinct` points, from local exact tests:
**   (a) every corner's neighbour link is an involution across the same
**       edge, reversed (tn[tn[c]] == c, the edge's ends swapped);
**   (b) every real triangle is strictly anticlockwise (geom_orient_valid);
**   (c) the ghosts' edges, read as the real side's edges u -> w, give each
**       boundary vertex one successor, and following them is one cycle
**       through all of them;
**   (d) that cycle turns left or goes straight on at every vertex (never
**       back), and its direction passes the positive x direction exactly
**       once: it is a convex polygon traversed once anticlockwise;
**   (e) every distinct point is a vertex of a real triangle.
** Why that suffices.  By (a) the interior edges cancel in the sum of the
** real triangles' boundaries, which is therefore the cycle C of (c).  For
** a point q on no edge, the number of real triangles holding q, each
** counted +1 by (b), is the winding number of that sum about q, i.e. of C:
** by (d) 1 inside the hull polygon C and 0 outside.  So the triangles'
** interiors are disjoint and cover the polygon, whose corners are points,
** so it is the convex hull.  A vertex p inside another triangle, or inside
** an edge not its own, would have a wedge of its own triangles covered
** twice (or lying outside C), so none is; with (e) the triangles are a
** triangulation of the points.  (d) is exact: a direction's half-plane
** class (angle in [0, pi) or [pi, 2 pi)) is read off comparisons of
** coordinates, and with every turn in [0, pi) the angle crosses 2 pi once
** per step from class 1 to class 0.  O(T) with one orientation per
** triangle and per hull vertex. */

/* The half of direction a -> b: 0 for angles in [0, pi), 1 in [pi, 2 pi). */
static int lot_valid_half(geom_point a, geom_point b) {
  return !(b.y > a.y || (b.y == a.y && b.x > a.x));
}

/* (a), (b), and (c)'s successors into nxt (LOT_NONE: not on the boundary),
** the points used into used[]; the ghost count, or -1. */
static long lot_valid_local(const lot_mesh *m, uint32_t *nxt, unsigned char *used) {
  long ghosts = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    const uint32_t *v = m->tv + LOT_CORNER((size_t)t, 0);
    int g = (v[0] == LOT_GHOST) + (v[1] == LOT_GHOST) + (v[2] == LOT_GHOST);
    for (uint32_t i = 0; i < 3; i++) {
      uint32_t c = LOT_CORNER(t, i), d = m->tn[c];
      if ((v[i] >= m->np && v[i] != LOT_GHOST) || d >= LOT_CORNER(m->nt, 0) || lot_slot(d) > 2 ||
          m->tn[d] != c || m->tv[lot_next3(c)] != m->tv[lot_prev3(d)] ||
          m->tv[lot_prev3(c)] != m->tv[lot_next3(d)])
        return -1;
    }
    if (g > 1 || (g == 1 && v[2] != LOT_GHOST)) return -1;   /* the sweep's ghosts: (w, u, G) */
    if (g == 1) {
      if (nxt[v[1]] != LOT_NONE) return -1;
      nxt[v[1]] = v[0];
      ghosts++;
      continue;
    }
    if (geom_orient_valid(m->p[v[0]], m->p[v[1]], m->p[v[2]]) <= 0) return -1;
    used[v[0]] = used[v[1]] = used[v[2]] = 1;
  }
  return ghosts;
}

/* (c) and (d): the successors form one convex cycle of h vertices from s. */
static int lot_valid_hull(const lot_mesh *m, const uint32_t *nxt, uint32_t s, long h) {
  uint32_t a = s, b = nxt[s];
  long steps = 0, wraps = 0;
  do {
    if (b == LOT_NONE || nxt[b] == LOT_NONE || nxt[b] == b || ++steps > h) return 0;
    geom_point pa = m->p[a], pb = m->p[b], pc = m->p[nxt[b]];
    int o = geom_orient_valid(pa, pb, pc);
    if (o < 0 || (o == 0 && geom_ahead(pb, pc, pa))) return 0;
    wraps += lot_valid_half(pa, pb) == 1 && lot_valid_half(pb, pc) == 0;
    a = b;
    b = nxt[b];
  } while (a != s);
  return steps == h && wraps == 1;
}

int lot_mesh_valid(const lot_mesh *m, uint32_t distinct) {
  uint32_t *nxt = malloc(((size_t)m->np + 1) * sizeof *nxt);
  unsigned char *used = calloc((size_t)m->np + 1, 1);
  int ok = -1;
  if (nxt == NULL || used == NULL) goto done;
  for (uint32_t k = 0; k < m->np; k++) nxt[k] = LOT_NONE;
  long h = lot_valid_local(m, nxt, used);
  uint32_t s = 0, n = 0;
  for (uint32_t k = 0; k < m->np; k++) {
    n += used[k];
    if (nxt[k] != LOT_NONE) s = k;
  }
  ok = h >= 3 && n == distinct && lot_valid_hull(m, nxt, s, h);
done:
  free(nxt);
  free(used);
  return ok;
}
