/*
** sweep_internal.h: the sweepline algorithm of lot (--algorithm sweep) and
** the geometric primitives it is written against.
**
** The sweep (lot/sweep.c) knows nothing of circles: it asks a shape for the
** two primitives of the thesis's section 4.1 (the key of a circumshape
** event, and the "above" test of a site against the contact point of the
** shape through two boundary sites tangent to the sweepline), plus the
** test that three consecutive boundary sites close an event.  The circle's
** primitives (the Delaunay triangulation) are in lot/sweep_circle.c; an
** empty-shape rule plugs in by giving its own table.  Every primitive must
** be exact for points within geom.h's coordinate contract.
*/
#ifndef FLIPLAB_SWEEP_INTERNAL_H
#define FLIPLAB_SWEEP_INTERNAL_H

#include <stddef.h>
#include "mesh.h"

typedef struct lot_sweep_shape {
  const char *name;
  /* 1 when a, b, c, consecutive on the boundary from bottom to top, close
  ** an event (for the circle: c strictly right of the line a -> b). */
  int (*closes)(geom_point a, geom_point b, geom_point c);
  /* lo <= key <= hi, the key of the event of t (for the circle: cx + R),
  ** or lo = -inf, hi = +inf when no bound is known. */
  void (*key_bounds)(const geom_point t[3], double *lo, double *hi);
  /* The exact sign of key(t) - key(u), where t == NULL stands for the
  ** site key tx (an x coordinate), u == NULL for ux. */
  int (*key_cmp)(const geom_point *t, double tx, const geom_point *u, double ux);
  /* 1 when x lies strictly above the contact point of the shape through a
  ** and b (a's arc below b's on the boundary) tangent to the sweepline
  ** through x; a.x, b.x <= x.x. */
  int (*above)(geom_point a, geom_point b, geom_point x);
} lot_sweep_shape;

/* The circle: the sweepline Delaunay triangulation. */
FLIPLAB_INTERNAL const lot_sweep_shape lot_sweep_circle;

/* Triangulate m->p[0 .. m->np - 1], sorted by x, then y (then input
** index), with s: triangles and ghosts into m (allocated by
** lot_mesh_alloc, no cache).  Equal consecutive points are merged into
** the first (*duplicates counts them, m->inp takes the smaller index).
** 0; -1 out of memory; -2 no triangle (all points equal or collinear). */
FLIPLAB_INTERNAL int lot_sweep_run(lot_mesh *m, const lot_sweep_shape *s, size_t *duplicates);

#endif
