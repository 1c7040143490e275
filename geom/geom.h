/*
** geom.h: points, triangles and exact predicates.
**
** A geom_tri holds every quantity of a triangle that a badness measure may
** need, computed once.  The three vertices are put in a canonical order
** (lexicographic by x, then y) before anything is computed, so the same
** triangle gets bit-identical values however its vertices are listed; the
** flip rules rely on that to be independent of the quadrilateral's first
** vertex bit for bit.
*/
#ifndef FLIPLAB_GEOM_H
#define FLIPLAB_GEOM_H

#include <stddef.h>
#include "fliplab_config.h"

#include "predicates.h"   /* geom_point, geom_orient, geom_incircle */

typedef struct geom_tri {
  geom_point v[3];            /* vertices in canonical (lexicographic) order */
  double a, b, c;             /* side lengths, a >= b >= c */
  double alpha, beta, gamma;  /* angles in radians, alpha <= beta <= gamma */
  double area;                /* A > 0 for a proper triangle */
  double P;                   /* perimeter a + b + c */
  double R;                   /* circumradius abc / (4A) */
  double r;                   /* inradius 2A / P */
  double h;                   /* shortest altitude a' = 2A / a */
  double rx, ry;              /* coordinate ranges of the vertices */
} geom_tri;

/* Fill *t from three points, in any order. */
void geom_tri_make(geom_tri *t, geom_point p, geom_point q, geom_point r);

/* The lexicographic order of points (by x, then y): a triangle's canonical
** vertex order, the samplers' collinear tie-break, the plugin rotation. */
static inline int geom_lexless(geom_point a, geom_point b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

double geom_dist(geom_point p, geom_point q);
int geom_point_finite(geom_point p);

/* Convex polygon validation, used for every polygon a user hands us.
** geom_polygon_check reverses a clockwise polygon in place (the documented
** normalisation: fliplab works anticlockwise) and returns GEOM_OK, or an
** error code with *bad set to the 0-based index of the offending vertex. */
typedef enum geom_polyerr {
  GEOM_OK = 0,
  GEOM_TOO_FEW,        /* fewer than 3 vertices */
  GEOM_NOT_FINITE,     /* NaN or infinite coordinate */
  GEOM_DUPLICATE,      /* two equal vertices */
  GEOM_COLLINEAR,      /* three consecutive vertices on a line */
  GEOM_NOT_CONVEX,     /* a reflex vertex, or the boundary winds more than once */
  GEOM_OUT_OF_SCALE,   /* |coordinate| > GEOM_MAX_COORD or an edge < GEOM_MIN_EDGE */
  GEOM_CROSSING        /* two edges cross, touch or overlap (simple polygons) */
} geom_polyerr;

/* The scales fliplab accepts.  Measures are products of up to six lengths
** (abc, joined by a product) evaluated in double precision: beyond these
** bounds they would overflow or underflow and decide nothing. */
#define GEOM_MAX_COORD 1e50
#define GEOM_MIN_EDGE 1e-50

geom_polyerr geom_polygon_check(geom_point *p, size_t n, size_t *bad, int *reversed);

/* Simple polygon validation, exact (geom_orient only): finite coordinates
** within GEOM_MAX_COORD, no repeated vertex, edges at least GEOM_MIN_EDGE,
** and no two edges meeting except adjacent edges at their shared vertex
** (crossing, touching and overlapping are all refused; an adjacent pair
** that folds back onto itself overlaps).  Consecutive collinear vertices
** are allowed.  Edge e joins vertices e and e+1 (mod n).  On GEOM_CROSSING
** *bad < *bad2 are the two offending edges; on the other errors *bad is the
** vertex, as for geom_polygon_check.  A clockwise polygon is reversed in
** place keeping vertex 0 (the same convention).  O(n log n) to sort the
** edges plus one exact test per pair of edges whose x-ranges overlap
** (O(n^2) at worst). */
geom_polyerr geom_simple_polygon_check(geom_point *p, size_t n, size_t *bad, size_t *bad2,
                                       int *reversed);
/* 1 if the closed segments ab and cd have a point in common (exact). */
int geom_segments_meet(geom_point a, geom_point b, geom_point c, geom_point d);
const char *geom_polyerr_str(geom_polyerr e);

#endif
