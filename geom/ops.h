/*
** ops.h: what a triangulation algorithm did, counted (docs/paradigms.md).
**
** One layout for every algorithm of chapter 2 (and chapter 5's workbench),
** so that a table of counts compares like with like whatever the machine:
** the number of orientation and in-circle / in-shape tests, the exact
** fallbacks among them, flips, point-location steps, edges made and
** deleted, events of a sweep, buckets visited, and the peak working memory.
**
** Counting costs nothing worth measuring when it is off: an algorithm holds
** an `ops_counts *` that is NULL when nobody asked, and every count is
** `if (c) c->v[k] += d`, one well-predicted branch on a register beside a
** predicate that costs tens of instructions.  Counts are plain integers of
** one run on one thread; a parallel algorithm counts per thread and adds
** the threads' counts in a fixed order (ops_merge), so the totals do not
** depend on the thread count's scheduling.
*/
#ifndef FLIPLAB_OPS_H
#define FLIPLAB_OPS_H

#include <stddef.h>
#include <stdint.h>
#include "geom.h"
#include "predicates.h"

typedef enum ops_kind {
  OPS_ORIENT,         /* orientation tests */
  OPS_INCIRCLE,       /* in-circle tests (DT) */
  OPS_INSHAPE,        /* in-shape tests (an empty-shape rule's decision) */
  OPS_EXACT,          /* of those, the ones the floating-point filter could not decide */
  OPS_FLIPS,          /* edge flips */
  OPS_LOCATE,         /* point-location steps (triangles or edges walked, DAG nodes visited) */
  OPS_EDGES_MADE,     /* edges created */
  OPS_EDGES_DELETED,  /* edges deleted */
  OPS_EVENTS,         /* sweep events (site and circle/shape events) */
  OPS_BUCKETS,        /* buckets (grid cells, strips) examined */
  OPS_PEAK_BYTES,     /* the most bytes of working memory held at once */
  OPS_COUNT
} ops_kind;

typedef struct ops_counts {
  uint64_t v[OPS_COUNT];
  uint64_t bytes;     /* working memory held now (for OPS_PEAK_BYTES) */
} ops_counts;

/* Count d operations of kind k, when counting. */
static inline void ops_add(ops_counts *c, ops_kind k, uint64_t d) {
  if (c) c->v[k] += d;
}

/* Working memory taken (d > 0) or given back (d < 0); the peak follows. */
static inline void ops_memory(ops_counts *c, int64_t d) {
  if (!c) return;
  c->bytes = (uint64_t)((int64_t)c->bytes + d);
  if (c->bytes > c->v[OPS_PEAK_BYTES]) c->v[OPS_PEAK_BYTES] = c->bytes;
}

/* The exact predicates of predicates.h for valid input (geom_coord_check),
** counted.  The exact fallbacks are counted by the runner from
** geom_exact_calls (predicates.c counts them per stage), not here: the
** filter's verdict is not visible from outside. */
static inline int ops_orient(ops_counts *c, geom_point a, geom_point b, geom_point d) {
  ops_add(c, OPS_ORIENT, 1);
  return geom_orient_valid(a, b, d);
}

static inline int ops_incircle(ops_counts *c, geom_point a, geom_point b, geom_point d,
                               geom_point e) {
  ops_add(c, OPS_INCIRCLE, 1);
  return geom_incircle_valid(a, b, d, e);
}

/* geom_segments_cross, counted: the orientation tests it makes. */
static inline int ops_segments_cross(ops_counts *c, geom_point a, geom_point b, geom_point d,
                                     geom_point e) {
  return ops_orient(c, a, b, d) * ops_orient(c, a, b, e) < 0 &&
         ops_orient(c, d, e, a) * ops_orient(c, d, e, b) < 0;
}

/* geom_on_segment, counted: the coordinate comparisons first (q between a
** and b along the line's main axis is needed), then the orientation test. */
static inline int ops_on_segment(ops_counts *c, geom_point a, geom_point b, geom_point q) {
  return geom_ahead(a, b, q) && geom_ahead(b, a, q) && ops_orient(c, a, b, q) == 0;
}

void ops_clear(ops_counts *c);
/* into += from, kind by kind; the peaks add too (parallel halves hold their
** memory at the same time, so the sum bounds the true peak from above). */
void ops_merge(ops_counts *into, const ops_counts *from);
/* The name of kind k ("orient", "incircle", ...; NULL past the last), a line
** about it, and back (-1 if unknown). */
const char *ops_name(int k);
const char *ops_about(int k);
int ops_find(const char *name);

#endif
