/*
** sweep_internal.h: the sweepline algorithm of lot (--algorithm sweep).
**
** The sweep (lot/sweep.c) knows nothing of circles: it is written against
** a shape's table of exact primitives (shapes/shape_sweep_internal.h: the
** key of a circumshape event, the "above" test, the closing test), the
** circle's for the Delaunay triangulation, the shape of an empty-shape
** rule's for that rule (lot/sweep_shape.c picks it).
*/
#ifndef FLIPLAB_SWEEP_INTERNAL_H
#define FLIPLAB_SWEEP_INTERNAL_H

#include <stddef.h>
#include "mesh.h"
#include "rule.h"
#include "shape_sweep_internal.h"

/* Triangulate m->p[0 .. m->np - 1], sorted by x, then y (then input
** index), with s: triangles and ghosts into m (allocated by
** lot_mesh_alloc, no cache).  Equal consecutive points are merged into
** the first (*duplicates counts them, m->inp takes the smaller index).
** 0; -1 out of memory; -2 no triangle (all points equal or collinear); -3
** the structure broke (more triangles than the mesh holds, a hull that is
** no cycle): only a polygon's sweep after ties it counted in *ties. */
FLIPLAB_INTERNAL int lot_sweep_run(lot_mesh *m, const shape_sweep *s, size_t *duplicates);

/* The primitives the sweep uses for a rule (lot/sweep_shape.c): s, whose
** ctx points into the pick itself (so it must not move), read off the
** rule's shape (rule_shape; the circle for DT).  0, or -1 with a one-line
** message when the sweep cannot make the rule's triangulation. */
typedef struct lot_sweep_pick {
  shape_sweep s;
  shape_sweep_ctx ctx;
  size_t special;           /* polygons: ties decided by the fixed rule (lot_sweep_mesh) */
} lot_sweep_pick;
FLIPLAB_INTERNAL int lot_sweep_pick_rule(const rule *r, lot_sweep_pick *pk, char *err,
                                         size_t errlen);

#endif
