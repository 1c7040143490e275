/*
** mesh.h: the triangulation structure behind lot.h (private to lot/, not
** installed; lot/mesh.c).
**
** Triangle-neighbour arrays.  Triangle t has vertices tv[4t..4t+2],
** anticlockwise; corner c = 4t + i (i < 3) names vertex tv[c] and the edge
** opposite it, and tn[c] is the corner of the neighbouring triangle opposite
** the same edge, so tn[tn[c]] == c.  The convex hull is closed by "ghost"
** triangles (u, v, LOT_GHOST), one per hull edge, the outside lying to the
** left of u -> v (Shewchuk's ghost triangles): every triangle then has three
** neighbours, a point outside the hull is "in" the ghost triangles whose
** edges it sees, and inserting it replaces their ghost vertex by the point.
** Why a stride of 4: corner arithmetic is then shifts and masks; with 3t +
** i every step of the walk and every examined edge paid several divisions
** by 3, a tenth of the Delaunay triangulation's instructions.  Slot 3 of
** tv holds no vertex: an empty-shape rule keeps a triangle's hint there
** (lot.c), on the cache line its vertices are read from; every write of a
** triangle's vertices sets it to 0 (no hint), and tn's slot 3 is unused.
** 16 bytes of indices per corner slot pair, 2n - 2 triangles (ghosts
** included) for n vertices: 64 bytes per point, plus 8 per triangle for the
** badness cache of triangle-based rules, or 16 for its enclosures.
**
** The badness cache.  A triangle-based rule keeps each triangle's badness
** (bad[], exact, computed whenever a triangle is made).  The angle
** measures with a joint that has enclosures (measure_has_bounds,
** joint_has_bounds) keep an enclosure [lo, hi] instead (enc[]), from
** measure_bounds, without atan2; the exact value replaces it (lo == hi)
** only when a decision needs it (lot.c).  lo == hi always means exact: an
** enclosure that wide holds only the exact value.
**
** Vertices are numbered in insertion order (p[] is the input permuted),
** which keeps neighbouring triangles' points close in memory.
*/
#ifndef FLIPLAB_LOT_MESH_H
#define FLIPLAB_LOT_MESH_H

#include <stdint.h>
#include "lot.h"
#include "measure.h"

#define LOT_GHOST UINT32_MAX
#define LOT_NONE UINT32_MAX

/* An enclosure lo <= badness <= hi of a triangle; lo == hi: the exact value. */
typedef struct lot_enc {
  double lo, hi;
} lot_enc;

/* What a mesh caches per triangle: nothing (DT, quadrilateral rules, a
** decision hook), the exact badness, or enclosures of it. */
typedef enum lot_cache { LOT_CACHE_NONE, LOT_CACHE_EXACT, LOT_CACHE_ENCLOSED } lot_cache;

typedef struct lot_mesh {
  geom_point *p;        /* vertex k's point (k in insertion order) */
  uint32_t *inp;        /* vertex k's input index (first occurrence after merging) */
  uint32_t np;          /* slots in p (input points, duplicates included) */
  uint32_t *tv, *tn;    /* 4 per triangle (LOT_CORNER): tv's last a hint, tn's unused */
  double *bad;          /* per-triangle badness (triangle-based rules) or NULL */
  lot_enc *enc;         /* per-triangle enclosures of it instead (LOT_CACHE_ENCLOSED) */
  uint32_t nt, cap;     /* triangles used, allocated */
  uint32_t last;        /* a triangle near the last insertion: the walk's start */
  uint64_t walk;        /* the walk's generator state (deterministic) */
  const rule *r;        /* for the badness cache */
  const measure *meas;  /* r's measure, looked up once (triangle-based rules) */
  unsigned fields;      /* the geom_tri fields the measure reads (measure_fields) */
  measure_points_fn pts;   /* its evaluation from points (built-ins), or NULL */
  ops_counts *ops;      /* the run's counts (lot_options.ops), or NULL */
} lot_mesh;

/* Corner i of triangle t, the triangle of corner c, and the next and
** previous corners of the same triangle (anticlockwise). */
#define LOT_CORNER(t, i) (4 * (t) + (i))
static inline uint32_t lot_tri_of(uint32_t c) { return c >> 2; }
static inline uint32_t lot_slot(uint32_t c) { return c & 3; }
/* By a table of steps rather than a test on the slot, which the compiler
** makes a branch: in the walk and the flip loop the slot is a coin toss. */
static const int8_t lot_dnext[4] = {1, 1, -2, 0}, lot_dprev[4] = {2, -1, -1, 0};
static inline uint32_t lot_next3(uint32_t c) { return c + (uint32_t)lot_dnext[c & 3]; }
static inline uint32_t lot_prev3(uint32_t c) { return c + (uint32_t)lot_dprev[c & 3]; }
static inline int lot_is_ghost(const lot_mesh *m, uint32_t t) {
  const uint32_t *v = m->tv + LOT_CORNER((size_t)t, 0);
  return v[0] == LOT_GHOST || v[1] == LOT_GHOST || v[2] == LOT_GHOST;
}

/* Where a point lies (lot_mesh_locate). */
typedef enum lot_where { LOT_IN_TRIANGLE, LOT_ON_EDGE, LOT_ON_VERTEX, LOT_OUTSIDE } lot_where;

FLIPLAB_INTERNAL int lot_mesh_alloc(lot_mesh *m, uint32_t np, lot_cache cache);
/* Switch the cache to another kind and fill it for every triangle (reflip);
** 0, or -1 when out of memory. */
FLIPLAB_INTERNAL int lot_mesh_recache(lot_mesh *m, lot_cache cache);
FLIPLAB_INTERNAL void lot_mesh_free(lot_mesh *m);
/* The bytes m holds (points, indices, triangles, cache): for OPS_PEAK_BYTES. */
FLIPLAB_INTERNAL size_t lot_mesh_bytes(const lot_mesh *m);
/* The first triangle a, b, c (anticlockwise) and its three ghosts. */
/* Link corners c1 and c2 as neighbours across their opposite edge. */
FLIPLAB_INTERNAL void lot_mesh_link(lot_mesh *m, uint32_t c1, uint32_t c2);
/* Triangle t's vertices a, b, c (anticlockwise), its cache entry made. */
FLIPLAB_INTERNAL void lot_mesh_set(lot_mesh *m, uint32_t t, uint32_t a, uint32_t b, uint32_t c);
FLIPLAB_INTERNAL void lot_mesh_first(lot_mesh *m, uint32_t a, uint32_t b, uint32_t c);
/* Locate vertex k's point: *c is a triangle's corner (IN_TRIANGLE: 3t;
** ON_EDGE: the corner opposite the edge; ON_VERTEX: the vertex's corner;
** OUTSIDE: a ghost triangle's ghost corner, the point seeing its edge). */
FLIPLAB_INTERNAL lot_where lot_mesh_locate(lot_mesh *m, geom_point q, uint32_t *c);
/* Insert vertex k at a located place.  The corners whose opposite edge
** is now a candidate for flipping (the edges opposite k, and the halves of
** a split edge, with a real triangle on both sides) are stored in *cand
** (grown as needed); returns how many, or -1 when out of memory. */
FLIPLAB_INTERNAL
long lot_mesh_insert(lot_mesh *m, uint32_t k, lot_where w, uint32_t c, uint32_t **cand,
                     size_t *candcap);
/* Flip the edge opposite corner c (both triangles real): t = (a, b, c0)
** and t' = (d, c0, b) become (a, b, d) and (d, c0, a), keeping a at its
** corner in t and d at its corner in t'.  bad_t and bad_u go to an exact
** cache; an enclosed one is the caller's to update (lot.c). */
FLIPLAB_INTERNAL void lot_mesh_flip(lot_mesh *m, uint32_t c, double bad_t, double bad_u);
/* The badness of triangle (a, b, c) for m->r (triangle-based rules). */
FLIPLAB_INTERNAL double lot_mesh_badness(const lot_mesh *m, uint32_t a, uint32_t b, uint32_t c);
/* An enclosure of it (measure_bounds), or the exact value where there is none. */
FLIPLAB_INTERNAL lot_enc lot_mesh_enclose(const lot_mesh *m, uint32_t a, uint32_t b, uint32_t c);
/* Triangle t's enclosure made exact (computed once, then cached). */
FLIPLAB_INTERNAL void lot_mesh_exact(lot_mesh *m, uint32_t t);
/* 1 when m's triangles and ghosts (ghost vertex last, as the sweep makes
** them) are a triangulation of its `distinct` points, by exact local tests
** (the argument is in mesh.c); 0 when not; -1 out of memory. */
FLIPLAB_INTERNAL int lot_mesh_valid(const lot_mesh *m, uint32_t distinct);

#endif
