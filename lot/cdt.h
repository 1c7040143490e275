/*
** cdt.h: constrained triangulations inside lot/ (private, not installed;
** lot/cdt.c): the set of constrained edges, the insertion of segments into
** a mesh, and the removal of holes and of the outside.
**
** Constrained edges are kept as a hash set of mesh vertex pairs, so they
** survive every flip elsewhere (the mesh moves edges between corners, the
** pair stays).  lot.c's flip loop asks lot_cons_has before examining an
** edge; nothing else of lot.c knows about constraints.
*/
#ifndef FLIPLAB_LOT_CDT_H
#define FLIPLAB_LOT_CDT_H

#include "mesh.h"

typedef struct lot_cons {
  uint64_t *key;        /* min << 32 | max + 1; 0: empty slot */
  uint32_t *seg;        /* the input segment that made the edge first */
  size_t cap, count;    /* cap a power of two, or 0 */
} lot_cons;

/* 1 when u-v (mesh vertices) is constrained (s may be NULL: none). */
FLIPLAB_INTERNAL int lot_cons_has(const lot_cons *s, uint32_t u, uint32_t v);

typedef struct lot_cdt {
  lot_cons cons;
  uint32_t *rep;        /* rep[i]: the mesh vertex of input point i */
  uint32_t *vc;         /* a corner of each vertex (checked before use) */
  uint8_t *mark;        /* per triangle: deleted by the current segment */
  uint8_t *gone;        /* per triangle: 1 removed as outside, 2 by a hole */
  size_t removed;       /* how many are gone */
  uint32_t *chain;      /* the vertices of each segment's pieces, in order */
  size_t *chain_at;     /* segment k's vertices: chain[chain_at[k] .. chain_at[k + 1]) */
  size_t nchain, chaincap;
  void *work;           /* lot_cdt_work: the current segment's buffers */
} lot_cdt;

/* Map the input's points to the mesh's vertices after triangulation
** (m->inp before merging is ord); 0, or -1 when out of memory. */
FLIPLAB_INTERNAL int lot_cdt_begin(lot_cdt *C, lot_mesh *m, const uint32_t *ord, size_t n);
/* Insert input segment k (o->segments[2k], [2k + 1]) exactly: its pieces
** (split at the vertices on it) become constrained edges, each piece by
** deleting the triangles it crosses and retriangulating the two
** pseudo-polygons beside it.  The corners of the new triangles go to
** *cand (grown); returns how many, -1 when out of memory, -2 with the
** message in err (crossing segments, bad indices). */
FLIPLAB_INTERNAL long lot_cdt_segment(lot_cdt *C, lot_mesh *m, const lot_options *o,
                                      lot_stats *st, size_t k, uint32_t **cand,
                                      size_t *candcap, char *err, size_t errlen);
/* Remove the outside (unless o->keep_hull or no segments) and the holes;
** fill the stats.  0, -1 when out of memory, -2 with the message. */
FLIPLAB_INTERNAL int lot_cdt_remove(lot_cdt *C, lot_mesh *m, const lot_options *o,
                                    lot_stats *st, char *err, size_t errlen);
/* 1 when triangle t is removed (C may be NULL). */
static inline int lot_cdt_gone(const lot_cdt *C, uint32_t t) {
  return C != NULL && C->gone != NULL && C->gone[t] != 0;
}
/* The constrained edges of kept triangles as sorted input-index pairs
** (out NULL: only count them). */
FLIPLAB_INTERNAL size_t lot_cdt_edges(const lot_cdt *C, const lot_mesh *m, uint32_t *out);
FLIPLAB_INTERNAL void lot_cdt_free(lot_cdt *C);

#endif
