/*
** cdt.c: constrained triangulations (thesis 2.3.2): segments inserted into
** a triangulation of the points, exactly, and the removal of holes and of
** the outside.  docs/lot.md ("Constrained triangulations") states the
** definitions and the decisions.
**
** A segment a-b is inserted piece by piece.  From vertex a the triangles
** around a are searched for the one whose wedge holds the direction of b;
** when an edge a-x runs along ab (x on the segment), a-x is a piece and
** the search goes on from x.  Otherwise the open segment crosses edges:
** the walk collects the triangles it crosses until it reaches a vertex z
** on ab (b itself, or a point inside the segment, which splits it).  The
** crossed triangles are deleted, the edge a-z is made, and the two
** pseudo-polygons on its sides are triangulated by the Delaunay rule
** (each edge u-w takes the chain vertex c whose circle u w c holds no
** other chain vertex; Anglada 1997).  Every test is exact (geom_orient,
** geom_incircle), so "x lies on ab" and "the edge is crossed" are facts,
** not tolerances.  The caller then flips the new triangles' edges with its
** rule, never flipping a constrained edge: for DT that is the CDT with the
** tie-break of lot.c (Lawson's flips converge to it), for any other rule a
** constrained LOT.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cdt.h"
#include "geom_key_internal.h"

/* ---- the set of constrained edges -------------------------------------- */

/* The set's key of edge uv: its edge key + 1, so that 0 marks an empty slot. */
static uint64_t lot_cons_key(uint32_t u, uint32_t v) {
  return geom_edge_key(u, v) + 1;
}

static size_t lot_cons_slot(const lot_cons *s, uint64_t key) {
  uint64_t h = key * 0x9e3779b97f4a7c15u;
  size_t i = (size_t)(h >> 17) & (s->cap - 1);
  while (s->key[i] != 0 && s->key[i] != key) i = (i + 1) & (s->cap - 1);
  return i;
}

int lot_cons_has(const lot_cons *s, uint32_t u, uint32_t v) {
  if (s == NULL || s->cap == 0) return 0;
  uint64_t key = lot_cons_key(u, v);
  return s->key[lot_cons_slot(s, key)] == key;
}

/* The segment that owns u-v, or UINT32_MAX. */
static uint32_t lot_cons_owner(const lot_cons *s, uint32_t u, uint32_t v) {
  if (s->cap == 0) return UINT32_MAX;
  uint64_t key = lot_cons_key(u, v);
  size_t i = lot_cons_slot(s, key);
  return s->key[i] == key ? s->seg[i] : UINT32_MAX;
}

static int lot_cons_grow(lot_cons *s) {
  size_t cap = s->cap ? 2 * s->cap : 1024;
  lot_cons t = {calloc(cap, sizeof *t.key), malloc(cap * sizeof *t.seg), cap, s->count};
  if (t.key == NULL || t.seg == NULL) {
    free(t.key);
    free(t.seg);
    return -1;
  }
  for (size_t i = 0; i < s->cap; i++)
    if (s->key[i] != 0) {
      size_t j = lot_cons_slot(&t, s->key[i]);
      t.key[j] = s->key[i];
      t.seg[j] = s->seg[i];
    }
  free(s->key);
  free(s->seg);
  *s = t;
  return 0;
}

/* Add u-v for segment k: 1 when it was new, 0 when already there, -1 (memory). */
static int lot_cons_add(lot_cons *s, uint32_t u, uint32_t v, uint32_t k) {
  if (2 * (s->count + 1) > s->cap && lot_cons_grow(s) != 0) return -1;
  uint64_t key = lot_cons_key(u, v);
  size_t i = lot_cons_slot(s, key);
  if (s->key[i] == key) return 0;
  s->key[i] = key;
  s->seg[i] = k;
  s->count++;
  return 1;
}

/* ---- buffers of one piece ---------------------------------------------- */

typedef struct lot_half {
  uint64_t key;         /* lot_cons_key of the edge */
  uint32_t corner;      /* the corner opposite it */
} lot_half;

typedef struct lot_task {
  uint32_t u, w, lo, hi;   /* triangulate u-w with chain[lo .. hi) left of u -> w */
} lot_task;

typedef struct lot_cdt_work {
  uint32_t *dead;  size_t ndead, deadcap;     /* crossed triangles */
  uint32_t *left;  size_t nleft, leftcap;     /* chain left of a -> z, from a */
  uint32_t *right; size_t nright, rightcap;   /* chain right of it, from a */
  uint32_t *made;  size_t nmade, madecap;     /* new triangles, 3 vertices each */
  lot_task *task;  size_t ntask, taskcap;
  lot_half *half;  size_t nhalf, halfcap;
} lot_cdt_work;

/* Make room for one more element of size sz in *a (count n, capacity *cap). */
static int lot_room(void **a, size_t n, size_t *cap, size_t sz) {
  if (n < *cap) return 0;
  size_t c = *cap ? 2 * *cap : 64;
  void *x = realloc(*a, c * sz);
  if (x == NULL) return -1;
  *a = x;
  *cap = c;
  return 0;
}

#define LOT_PUSH(arr, n, cap, val) \
  (lot_room((void **)&(arr), (n), &(cap), sizeof *(arr)) != 0 ? -1 : ((arr)[(n)++] = (val), 0))

/* ---- starting ---------------------------------------------------------- */

int lot_cdt_begin(lot_cdt *C, lot_mesh *m, const uint32_t *ord, size_t n) {
  C->rep = malloc((n ? n : 1) * sizeof *C->rep);
  C->vc = malloc((size_t)m->np * sizeof *C->vc);
  C->work = calloc(1, sizeof(lot_cdt_work));
  if (C->rep == NULL || C->vc == NULL || C->work == NULL) return -1;
  for (uint32_t k = 0; k < m->np; k++) C->vc[k] = LOT_NONE;
  for (uint32_t c = 0; c < LOT_CORNER(m->nt, 0); c++)
    if (lot_slot(c) < 3 && m->tv[c] != LOT_GHOST) C->vc[m->tv[c]] = c;
  for (size_t k = 0; k < n; k++) C->rep[ord[k]] = (uint32_t)k;
  return 0;
}

/* The mesh vertex of input point i: itself, or for a merged duplicate the
** vertex at its place (located once, then remembered).  The walk starts at
** a vertex just before it in the insertion order, which is spatial, so
** near it: from the mesh's last triangle, anywhere, the walks of n / 10
** random segments' ends took time quadratic in n (27.8 s of a 10^6-point
** CDT with three duplicates a point, bench_families). */
static uint32_t lot_cdt_vertex(lot_cdt *C, lot_mesh *m, uint32_t i) {
  uint32_t k = C->rep[i], c;
  if (C->vc[k] != LOT_NONE) return k;
  for (uint32_t j = k; j-- > 0 && k - j <= 64;)
    if (C->vc[j] != LOT_NONE && C->vc[j] < LOT_CORNER(m->nt, 0)) {
      m->last = lot_tri_of(C->vc[j]);
      break;
    }
  if (lot_mesh_locate(m, m->p[k], &c) != LOT_ON_VERTEX) return LOT_NONE;
  C->rep[i] = m->tv[c];
  return m->tv[c];
}

/* A corner of vertex a, found again when a flip has moved it: a flip
** keeps the triangle of the old corner next to a, so the walk starts there
** (from the mesh's last triangle it would cross the whole mesh). */
static uint32_t lot_cdt_corner(lot_cdt *C, lot_mesh *m, uint32_t a) {
  uint32_t c = C->vc[a];
  if (c != LOT_NONE && c < LOT_CORNER(m->nt, 0) && m->tv[c] == a) return c;
  if (c != LOT_NONE && c < LOT_CORNER(m->nt, 0)) m->last = lot_tri_of(c);
  if (lot_mesh_locate(m, m->p[a], &c) != LOT_ON_VERTEX) return LOT_NONE;
  C->vc[a] = c;
  return c;
}

/* Around vertex a (corner c), the first step toward b: returns the vertex x
** when the edge a-x runs along ab (x == b or x inside the segment), else
** LOT_NONE with *cross the corner opposite the edge that ab crosses first
** (its triangle (a, r, l), r right of ab and l left). */
static uint32_t lot_cdt_first(const lot_mesh *m, uint32_t c0, uint32_t b, uint32_t *cross) {
  uint32_t a = m->tv[c0], c = c0;
  geom_point pa = m->p[a], pb = m->p[b];
  do {
    uint32_t x = m->tv[lot_next3(c)], y = m->tv[lot_prev3(c)];
    if (x != LOT_GHOST && y != LOT_GHOST) {
      if (x == b || y == b) return b;
      int ox = geom_orient_valid(pa, pb, m->p[x]), oy = geom_orient_valid(pa, pb, m->p[y]);
      if (ox == 0 && geom_ahead(pa, pb, m->p[x])) return x;
      if (oy == 0 && geom_ahead(pa, pb, m->p[y])) return y;
      if (ox < 0 && oy > 0) {
        *cross = c;
        return LOT_NONE;
      }
    }
    c = lot_next3(m->tn[lot_next3(c)]);   /* the next triangle anticlockwise around a */
  } while (c != c0);
  *cross = LOT_NONE;
  return LOT_NONE;
}

static void lot_cross_message(const lot_options *o, size_t k, uint32_t j, char *err,
                              size_t errlen) {
  snprintf(err, errlen, "segments %zu (%u-%u) and %u (%u-%u) cross", k, o->segments[2 * k],
           o->segments[2 * k + 1], j, o->segments[2 * (size_t)j], o->segments[2 * (size_t)j + 1]);
}

/* The walk from the crossing at corner c (triangle (a, r, l)) to the first
** vertex z on ab: the crossed triangles go to W->dead, the chains to
** W->left and W->right.  z, or LOT_NONE with the message (a crossed
** segment). */
static uint32_t lot_cdt_walk(lot_cdt *C, lot_mesh *m, uint32_t c, uint32_t b,
                             const lot_options *o, size_t k, char *err, size_t errlen,
                             int *oom) {
  lot_cdt_work *W = C->work;
  uint32_t a = m->tv[c], r = m->tv[lot_next3(c)], l = m->tv[lot_prev3(c)];
  geom_point pa = m->p[a], pb = m->p[b];
  W->ndead = W->nleft = W->nright = 0;
  *oom = LOT_PUSH(W->dead, W->ndead, W->deadcap, lot_tri_of(c)) != 0 ||
         LOT_PUSH(W->left, W->nleft, W->leftcap, l) != 0 ||
         LOT_PUSH(W->right, W->nright, W->rightcap, r) != 0;
  for (;;) {
    uint32_t owner = lot_cons_owner(&C->cons, r, l);
    if (owner != UINT32_MAX) {
      lot_cross_message(o, k, owner, err, errlen);
      return LOT_NONE;
    }
    uint32_t j = m->tn[c], z = m->tv[j];   /* the triangle (l, r, z) beyond */
    if (*oom || z == LOT_GHOST) {
      if (!*oom) snprintf(err, errlen, "segment %zu leaves the convex hull (internal error)", k);
      return LOT_NONE;
    }
    *oom = LOT_PUSH(W->dead, W->ndead, W->deadcap, lot_tri_of(j)) != 0;
    int oz = z == b ? 0 : geom_orient_valid(pa, pb, m->p[z]);
    if (oz == 0) return z;
    if (oz > 0) {
      c = lot_next3(j);   /* opposite l: the edge r-z */
      l = z;
      *oom |= LOT_PUSH(W->left, W->nleft, W->leftcap, z) != 0;
    } else {
      c = lot_prev3(j);   /* opposite r: the edge z-l */
      r = z;
      *oom |= LOT_PUSH(W->right, W->nright, W->rightcap, z) != 0;
    }
  }
}

/* Triangulate the pseudo-polygon u, chain[0 .. n), w (the chain left of
** u -> w, in order from u) by the Delaunay rule into W->made. */
static int lot_cdt_fill(lot_cdt_work *W, const lot_mesh *m, const uint32_t *chain, size_t n,
                        uint32_t u, uint32_t w) {
  W->ntask = 0;
  if (LOT_PUSH(W->task, W->ntask, W->taskcap, ((lot_task){u, w, 0, (uint32_t)n})) != 0) return -1;
  while (W->ntask > 0) {
    lot_task t = W->task[--W->ntask];
    if (t.lo >= t.hi) continue;
    uint32_t ci = t.lo;
    for (uint32_t i = t.lo + 1; i < t.hi; i++)
      if (geom_incircle(m->p[t.u], m->p[t.w], m->p[chain[ci]], m->p[chain[i]]) > 0) ci = i;
    uint32_t c = chain[ci];
    if (LOT_PUSH(W->made, W->nmade, W->madecap, t.u) != 0 ||
        LOT_PUSH(W->made, W->nmade, W->madecap, t.w) != 0 ||
        LOT_PUSH(W->made, W->nmade, W->madecap, c) != 0)
      return -1;
    if (LOT_PUSH(W->task, W->ntask, W->taskcap, ((lot_task){t.u, c, t.lo, ci})) != 0 ||
        LOT_PUSH(W->task, W->ntask, W->taskcap, ((lot_task){c, t.w, ci + 1, t.hi})) != 0)
      return -1;
  }
  return 0;
}

static int lot_half_cmp(const void *x, const void *y) {
  const lot_half *a = x, *b = y;
  return a->key < b->key ? -1 : a->key > b->key;
}

/* Replace the dead triangles by the made ones (as many: k crossed edges,
** k + 1 triangles either way) and link them: each edge of a made triangle
** meets either another made triangle or the outside of the dead region,
** whose corners are recorded first.  The new corners go to *cand. */
static int lot_cdt_replace(lot_cdt *C, lot_mesh *m, uint32_t **cand, size_t *nc,
                           size_t *candcap) {
  lot_cdt_work *W = C->work;
  W->nhalf = 0;
  for (size_t i = 0; i < W->ndead; i++) C->mark[W->dead[i]] = 1;
  for (size_t i = 0; i < W->ndead; i++)
    for (uint32_t s = 0; s < 3; s++) {
      uint32_t c = LOT_CORNER(W->dead[i], s), o = m->tn[c];
      if (C->mark[lot_tri_of(o)]) continue;
      lot_half h = {lot_cons_key(m->tv[lot_next3(c)], m->tv[lot_prev3(c)]), o};
      if (LOT_PUSH(W->half, W->nhalf, W->halfcap, h) != 0) return -1;
    }
  for (size_t i = 0; i < W->ndead; i++) {
    uint32_t t = W->dead[i], *v = W->made + 3 * i;
    C->mark[t] = 0;
    lot_mesh_set(m, t, v[0], v[1], v[2]);
    for (uint32_t s = 0; s < 3; s++) {
      uint32_t c = LOT_CORNER(t, s);
      C->vc[m->tv[c]] = c;
      lot_half h = {lot_cons_key(m->tv[lot_next3(c)], m->tv[lot_prev3(c)]), c};
      if (LOT_PUSH(W->half, W->nhalf, W->halfcap, h) != 0 || LOT_PUSH(*cand, *nc, *candcap, c) != 0)
        return -1;
    }
  }
  qsort(W->half, W->nhalf, sizeof *W->half, lot_half_cmp);
  for (size_t i = 0; i + 1 < W->nhalf; i += 2) lot_mesh_link(m, W->half[i].corner, W->half[i + 1].corner);
  return 0;
}

/* Record vertex v as the next of segment k's chain. */
static int lot_cdt_chain(lot_cdt *C, uint32_t v) {
  return LOT_PUSH(C->chain, C->nchain, C->chaincap, v);
}

/* One piece from a: the next vertex on the segment (made an edge), or
** LOT_NONE with *fail set (-1 memory, -2 message). */
static uint32_t lot_cdt_piece(lot_cdt *C, lot_mesh *m, uint32_t a, uint32_t b,
                              const lot_options *o, size_t k, uint32_t **cand, size_t *nc,
                              size_t *candcap, char *err, size_t errlen, int *fail) {
  lot_cdt_work *W = C->work;
  uint32_t c0 = lot_cdt_corner(C, m, a), cross;
  if (c0 == LOT_NONE) {
    snprintf(err, errlen, "segment %zu: a vertex is missing from the mesh (internal error)", k);
    *fail = -2;
    return LOT_NONE;
  }
  uint32_t z = lot_cdt_first(m, c0, b, &cross);
  if (z != LOT_NONE) return z;
  if (cross == LOT_NONE) {
    snprintf(err, errlen, "segment %zu: no triangle around its first end (internal error)", k);
    *fail = -2;
    return LOT_NONE;
  }
  int oom = 0;
  z = lot_cdt_walk(C, m, cross, b, o, k, err, errlen, &oom);
  if (z == LOT_NONE) {
    *fail = oom ? -1 : -2;
    return LOT_NONE;
  }
  W->nmade = 0;
  for (size_t i = 0, j = W->nright - 1; i < j; i++, j--) {   /* right chain from z to a */
    uint32_t s = W->right[i];
    W->right[i] = W->right[j];
    W->right[j] = s;
  }
  if (lot_cdt_fill(W, m, W->left, W->nleft, a, z) != 0 ||
      lot_cdt_fill(W, m, W->right, W->nright, z, a) != 0 ||
      lot_cdt_replace(C, m, cand, nc, candcap) != 0) {
    *fail = -1;
    return LOT_NONE;
  }
  return z;
}

static int lot_cdt_ends(lot_cdt *C, lot_mesh *m, const lot_options *o, const lot_stats *st,
                        size_t k, uint32_t *a, uint32_t *b, char *err, size_t errlen) {
  uint32_t i = o->segments[2 * k], j = o->segments[2 * k + 1];
  if (i >= st->n || j >= st->n) {
    snprintf(err, errlen, "segment %zu: point index %u out of range (%zu points)", k,
             i >= st->n ? i : j, st->n);
    return -2;
  }
  *a = lot_cdt_vertex(C, m, i);
  *b = lot_cdt_vertex(C, m, j);
  if (*a == LOT_NONE || *b == LOT_NONE) {
    snprintf(err, errlen, "segment %zu: an end is missing from the mesh (internal error)", k);
    return -2;
  }
  if (*a == *b) {
    snprintf(err, errlen, "segment %zu: both ends are point %u%s", k, i,
             i == j ? "" : " (equal points)");
    return -2;
  }
  return 0;
}

long lot_cdt_segment(lot_cdt *C, lot_mesh *m, const lot_options *o, lot_stats *st, size_t k,
                     uint32_t **cand, size_t *candcap, char *err, size_t errlen) {
  if (C->mark == NULL && (C->mark = calloc(m->cap, 1)) == NULL) return -1;
  if (C->chain_at == NULL && (C->chain_at = calloc(o->nsegments + 1, sizeof *C->chain_at)) == NULL)
    return -1;
  uint32_t a, b;
  int rc = lot_cdt_ends(C, m, o, st, k, &a, &b, err, errlen);
  if (rc != 0) return rc;
  size_t nc = 0, pieces = 0, old = 0;
  if (lot_cdt_chain(C, a) != 0) return -1;
  while (a != b) {
    int fail = 0;
    uint32_t z = lot_cdt_piece(C, m, a, b, o, k, cand, &nc, candcap, err, errlen, &fail);
    if (z == LOT_NONE) return fail;
    int added = lot_cons_add(&C->cons, a, z, (uint32_t)k);
    if (added < 0 || lot_cdt_chain(C, z) != 0) return -1;
    old += added == 0;
    pieces++;
    a = z;
  }
  C->chain_at[k + 1] = C->nchain;
  st->segments_split += pieces > 1;
  st->segments_merged += old > 0;
  return (long)nc;
}

/* ---- holes and the outside --------------------------------------------- */

/* Remove every triangle reachable from t without crossing a constrained
** edge (or the hull); returns how many, or -1 when out of memory. */
static long lot_cdt_flood(lot_cdt *C, const lot_mesh *m, uint32_t t, uint8_t why) {
  lot_cdt_work *W = C->work;
  long count = 0;
  W->ndead = 0;
  if (C->gone[t]) return 0;
  if (LOT_PUSH(W->dead, W->ndead, W->deadcap, t) != 0) return -1;
  C->gone[t] = why;
  while (W->ndead > 0) {
    uint32_t s = W->dead[--W->ndead];
    count++;
    for (uint32_t i = 0; i < 3; i++) {
      uint32_t c = LOT_CORNER(s, i), u = lot_tri_of(m->tn[c]);
      if (C->gone[u] || lot_is_ghost(m, u) ||
          lot_cons_has(&C->cons, m->tv[lot_next3(c)], m->tv[lot_prev3(c)]))
        continue;
      C->gone[u] = why;
      if (LOT_PUSH(W->dead, W->ndead, W->deadcap, u) != 0) return -1;
    }
  }
  return count;
}

/* The triangles outside the outermost segment-bounded region: those
** reachable from the hull's edges without crossing a segment. */
static long lot_cdt_outside(lot_cdt *C, const lot_mesh *m) {
  long count = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!lot_is_ghost(m, t)) continue;
    for (uint32_t i = 0; i < 3; i++) {
      uint32_t c = LOT_CORNER(t, i);
      if (m->tv[c] != LOT_GHOST) continue;   /* the ghost corner faces the hull edge */
      uint32_t u = lot_tri_of(m->tn[c]);
      if (lot_cons_has(&C->cons, m->tv[lot_next3(c)], m->tv[lot_prev3(c)])) continue;
      long n = lot_cdt_flood(C, m, u, 1);
      if (n < 0) return -1;
      count += n;
    }
  }
  return count;
}

/* Hole h: its triangle, or LOT_NONE with the message. */
static uint32_t lot_cdt_hole_tri(lot_cdt *C, lot_mesh *m, const lot_options *o, size_t h,
                                 char *err, size_t errlen) {
  geom_point q = o->holes[h];
  geom_coorderr e = geom_coord_check(q.x);
  if (e == GEOM_COORD_OK) e = geom_coord_check(q.y);
  if (e != GEOM_COORD_OK) {
    snprintf(err, errlen, "hole %zu (%g, %g): a coordinate %s", h, q.x, q.y, geom_coorderr_str(e));
    return LOT_NONE;
  }
  uint32_t c;
  lot_where w = lot_mesh_locate(m, q, &c);
  if (w == LOT_OUTSIDE) {
    snprintf(err, errlen, "hole %zu (%g, %g) is outside the convex hull of the points", h, q.x, q.y);
    return LOT_NONE;
  }
  if (w == LOT_ON_VERTEX) {
    snprintf(err, errlen, "hole %zu (%g, %g) is point %u: a hole point must lie inside a region",
             h, q.x, q.y, m->inp[m->tv[c]]);
    return LOT_NONE;
  }
  uint32_t t = lot_tri_of(c);
  if (w == LOT_ON_EDGE) {
    uint32_t u = m->tv[lot_next3(c)], v = m->tv[lot_prev3(c)], s = lot_cons_owner(&C->cons, u, v);
    if (s != UINT32_MAX) {
      snprintf(err, errlen, "hole %zu (%g, %g) lies on segment %u (%u-%u)", h, q.x, q.y, s,
               o->segments[2 * (size_t)s], o->segments[2 * (size_t)s + 1]);
      return LOT_NONE;
    }
    if (lot_is_ghost(m, t)) t = lot_tri_of(m->tn[c]);
  }
  if (C->gone[t] == 1) {
    snprintf(err, errlen, "hole %zu (%g, %g) lies outside every region bounded by segments", h,
             q.x, q.y);
    return LOT_NONE;
  }
  return t;
}

static int lot_key_cmp64(const void *x, const void *y) {
  uint64_t a = *(const uint64_t *)x, b = *(const uint64_t *)y;
  return a < b ? -1 : a > b;
}

/* Segments with a piece in no kept triangle. */
static int lot_cdt_count_removed(lot_cdt *C, const lot_mesh *m, const lot_options *o,
                                 lot_stats *st) {
  size_t ne = lot_cdt_edges(C, m, NULL);
  uint64_t *key = malloc((ne ? ne : 1) * sizeof *key);
  uint32_t *e = malloc((2 * ne + 1) * sizeof *e);
  if (key == NULL || e == NULL) {
    free(key);
    free(e);
    return -1;
  }
  lot_cdt_edges(C, m, e);
  for (size_t i = 0; i < ne; i++) key[i] = (uint64_t)e[2 * i] << 32 | e[2 * i + 1];
  st->constrained = ne;
  for (size_t k = 0; k < o->nsegments && C->chain_at; k++) {
    int lost = 0;
    for (size_t i = C->chain_at[k]; i + 1 < C->chain_at[k + 1] && !lost; i++) {
      uint32_t u = m->inp[C->chain[i]], v = m->inp[C->chain[i + 1]];
      uint64_t q = geom_edge_key(u, v);
      lost = bsearch(&q, key, ne, sizeof *key, lot_key_cmp64) == NULL;
    }
    st->segments_removed += lost;
  }
  free(key);
  free(e);
  return 0;
}

int lot_cdt_remove(lot_cdt *C, lot_mesh *m, const lot_options *o, lot_stats *st, char *err,
                   size_t errlen) {
  st->segments = o->nsegments;
  st->holes = o->nholes;
  if (C->work == NULL && (C->work = calloc(1, sizeof(lot_cdt_work))) == NULL) return -1;
  if ((C->gone = calloc(m->cap, 1)) == NULL) return -1;
  long removed = 0;
  if (!o->keep_hull && o->nsegments > 0 && (removed = lot_cdt_outside(C, m)) < 0) return -1;
  for (size_t h = 0; h < o->nholes; h++) {
    uint32_t t = lot_cdt_hole_tri(C, m, o, h, err, errlen);
    if (t == LOT_NONE) return -2;
    long n = lot_cdt_flood(C, m, t, 2);
    if (n < 0) return -1;
    removed += n;
  }
  st->removed = (size_t)removed;
  C->removed = st->removed;
  if (removed == 0) {   /* every piece is in a kept triangle */
    st->constrained = C->cons.count;
    return 0;
  }
  return lot_cdt_count_removed(C, m, o, st);
}

/* ---- output ------------------------------------------------------------ */

static int lot_pair_cmp(const void *x, const void *y) {
  const uint32_t *a = x, *b = y;
  if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
  return a[1] < b[1] ? -1 : a[1] > b[1];
}

/* The pieces straight from the set, when no triangle was removed. */
static size_t lot_cdt_all_edges(const lot_cdt *C, const lot_mesh *m, uint32_t *out) {
  size_t w = 0;
  for (size_t i = 0; i < C->cons.cap; i++) {
    uint64_t key = C->cons.key[i];
    if (key == 0) continue;
    if (out) {
      uint32_t x = m->inp[(uint32_t)((key - 1) >> 32)], y = m->inp[(uint32_t)(key - 1)];
      out[2 * w] = x < y ? x : y;
      out[2 * w + 1] = x < y ? y : x;
    }
    w++;
  }
  if (out) qsort(out, w, 2 * sizeof *out, lot_pair_cmp);
  return w;
}

size_t lot_cdt_edges(const lot_cdt *C, const lot_mesh *m, uint32_t *out) {
  if (C->removed == 0) return lot_cdt_all_edges(C, m, out);
  size_t w = 0;
  for (uint32_t c = 0; c < LOT_CORNER(m->nt, 0); c++) {
    uint32_t t = lot_tri_of(c), o = m->tn[c], u = lot_tri_of(o);
    if (lot_slot(c) == 3 || lot_is_ghost(m, t) || lot_cdt_gone(C, t)) continue;
    uint32_t a = m->tv[lot_next3(c)], b = m->tv[lot_prev3(c)];
    int other = !lot_is_ghost(m, u) && !lot_cdt_gone(C, u);
    if ((other && c > o) || !lot_cons_has(&C->cons, a, b)) continue;
    if (out) {
      uint32_t x = m->inp[a], y = m->inp[b];
      out[2 * w] = x < y ? x : y;
      out[2 * w + 1] = x < y ? y : x;
    }
    w++;
  }
  if (out) qsort(out, w, 2 * sizeof *out, lot_pair_cmp);
  return w;
}

void lot_cdt_free(lot_cdt *C) {
  lot_cdt_work *W = C->work;
  if (W) {
    free(W->dead);
    free(W->left);
    free(W->right);
    free(W->made);
    free(W->task);
    free(W->half);
    free(W);
  }
  free(C->cons.key);
  free(C->cons.seg);
  free(C->rep);
  free(C->vc);
  free(C->mark);
  free(C->gone);
  free(C->chain);
  free(C->chain_at);
  memset(C, 0, sizeof *C);
}
