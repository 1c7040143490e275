/*
** cpdt_internal.h: what the files of cpdt/ share: a run's state, the exact
** incircle test with lot's tie-break, and the half-edge mesh the merging and
** flipping algorithms work on.
*/
#ifndef FLIPLAB_CPDT_INTERNAL_H
#define FLIPLAB_CPDT_INTERNAL_H

#include "cpdt.h"
#include "fliplab_config.h"

#define CPDT_NONE 0xffffffffu

/* One run: the polygon, the counters, the random state, the output. */
typedef struct cpdt_run {
  const geom_point *p;
  size_t n;
  cpdt_counts *c;
  uint64_t rng;          /* splitmix64 counter (GEOM_STREAM_CPDT) */
  uint32_t *tri;         /* 3 (n - 2) words, filled by cpdt_emit */
} cpdt_run;

/* d inside the circle of anticlockwise a, b, c: +1, else -1; never 0. */
FLIPLAB_INTERNAL int cpdt_incircle(cpdt_run *r, uint32_t a, uint32_t b, uint32_t c, uint32_t d);
/* Triangle a b c (any rotation) into its slot (its middle vertex). */
FLIPLAB_INTERNAL void cpdt_emit(cpdt_run *r, uint32_t a, uint32_t b, uint32_t c);
/* A uniform integer in [0, m). */
FLIPLAB_INTERNAL uint32_t cpdt_random(cpdt_run *r, uint32_t m);
/* Working memory allocated (counted, every run holds it to its end). */
FLIPLAB_INTERNAL void cpdt_memory(cpdt_run *r, uint64_t bytes);

/* The algorithms (cpdt_circum.c, cpdt_divide.c, cpdt_insert.c): 0 or -2. */
FLIPLAB_INTERNAL int cpdt_circum(cpdt_run *r);
FLIPLAB_INTERNAL int cpdt_circum_random(cpdt_run *r);
FLIPLAB_INTERNAL int cpdt_circum_walk(cpdt_run *r);
FLIPLAB_INTERNAL int cpdt_divide(cpdt_run *r);
FLIPLAB_INTERNAL int cpdt_incremental(cpdt_run *r);
FLIPLAB_INTERNAL int cpdt_random_incremental(cpdt_run *r);
FLIPLAB_INTERNAL int cpdt_flip(cpdt_run *r);
FLIPLAB_INTERNAL int cpdt_corners(cpdt_run *r);

/* ---- the half-edge mesh (cpdt_mesh.c) -----------------------------------
**
** Edge e is the half-edges 2e and 2e + 1 (twins: h ^ 1); to[h] is the head
** of h, its origin to[h ^ 1].  The half-edges out of a vertex form a ring
** in anticlockwise order (nx: next anticlockwise, pv: previous); first[v]
** is one of them.  Round vertex v of an anticlockwise convex polygon the
** others lie anticlockwise in the order v+1, v+2, ..., v-1, so a ring is
** sorted by (u - v) mod n; the face left of h = a->b is the triangle
** a b to[nx[h]], the face right of it b a to[pv[h]]. */
typedef struct cpdt_mesh {
  uint32_t *to, *nx, *pv, *first;
  uint32_t free;         /* a free edge list through to[2e] */
  uint32_t used, cap;    /* edges handed out, capacity */
} cpdt_mesh;

FLIPLAB_INTERNAL int cpdt_mesh_init(cpdt_mesh *m, cpdt_run *r, size_t edges);
FLIPLAB_INTERNAL void cpdt_mesh_free(cpdt_mesh *m);
/* A new edge a-b: a->b put in a's ring after half-edge pa (CPDT_NONE: a's
** ring is empty), b->a in b's after pb.  Returns a->b. */
FLIPLAB_INTERNAL uint32_t cpdt_mesh_add(cpdt_mesh *m, uint32_t a, uint32_t b, uint32_t pa,
                                        uint32_t pb);
FLIPLAB_INTERNAL void cpdt_mesh_delete(cpdt_mesh *m, uint32_t h);
/* Flip the edge of h = a->b (faces a b c and b a d) into c->d, returned. */
FLIPLAB_INTERNAL uint32_t cpdt_mesh_flip(cpdt_mesh *m, uint32_t h);
/* The half-edge a->b, or CPDT_NONE (a walk round a's ring). */
FLIPLAB_INTERNAL uint32_t cpdt_mesh_find(const cpdt_mesh *m, uint32_t a, uint32_t b);
/* Lawson's flips with cpdt_incircle until every diagonal is locally
** Delaunay, starting from every diagonal of m (queue: 2n edges, queued:
** 2n zeroed flags); counts the flips. */
FLIPLAB_INTERNAL void cpdt_lawson(cpdt_mesh *m, cpdt_run *r, uint32_t *queue,
                                  unsigned char *queued);
/* Every face into r's output. */
FLIPLAB_INTERNAL void cpdt_mesh_emit(const cpdt_mesh *m, cpdt_run *r);

#endif
