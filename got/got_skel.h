/* got_skel.h: the edges every GOT of a sum rule must contain, and the edges none can
** (private to got/, its tests and benchmarks; docs/got.md, "Point sets: the skeleton").
** got_skel_build and got_skel_free: got/got_skel.c; got_skel_all: got/got_skel_all.c;
** got_skel_delaunay: got/got_skel_dt.c. */
#ifndef FLIPLAB_GOT_SKEL_H
#define FLIPLAB_GOT_SKEL_H

#include <stddef.h>
#include <stdint.h>
#include "geom.h"
#include "rule.h"

typedef enum got_edge_state { GOT_EDGE_POSSIBLE = 0, GOT_EDGE_CERTAIN = 1 } got_edge_state;
typedef struct got_skel {
  size_t n;            /* points (distinct, validated by the caller) */
  size_t nedges;       /* candidate edges kept: every edge of every GOT is among them */
  uint32_t *edge;      /* 2 per edge, a < b (point indices) */
  unsigned char *state;/* got_edge_state per edge: CERTAIN edges are in every GOT */
  /* statistics */
  size_t candidates;   /* edges after the exclusion test, before the LMT loop */
  size_t rounds;       /* LMT iterations until nothing changed */
  double seconds_candidates, seconds_lmt;
} got_skel;
/* Every edge that can be in a GOT of the sum rule r for p[0..n-1] (distinct points, not all
** collinear): 0, or -1 with a one-line message (a non-sum rule, out of memory, n too large for
** the rule's exclusion test, a coordinate outside the contract of geom_coord_check).  threads
** as in got_options. */
FLIPLAB_INTERNAL
int got_skel_build(const geom_point *p, size_t n, const rule *r, int threads, got_skel *out,
                   char *err, size_t errlen);
/* The rules of rule_got_cdt_theorem: every GOT is a Delaunay triangulation.  tri[0..3 ntri-1]
** is a triangulation claimed to be Delaunay (anticlockwise triples of point indices); it is
** certified exactly, then the Delaunay subdivision's edges are CERTAIN and every diagonal
** of a cocircular cell POSSIBLE.  0, or -1 with a one-line message naming what fails
** (got/got_skel_dt.c). */
FLIPLAB_INTERNAL
int got_skel_delaunay(const geom_point *p, size_t n, const uint32_t *tri, size_t ntri,
                      got_skel *out, char *err, size_t errlen);
/* All edges (no segment through a third point is an edge), hull edges CERTAIN: the trivial
** skeleton, for tests and tiny inputs (got/got_skel_all.c). */
FLIPLAB_INTERNAL
int got_skel_all(const geom_point *p, size_t n, got_skel *out, char *err, size_t errlen);
FLIPLAB_INTERNAL void got_skel_free(got_skel *s);

#endif
