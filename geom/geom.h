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

typedef struct geom_point {
  double x, y;
} geom_point;

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

/* Exact predicates for double inputs.
** geom_orient: +1 if a, b, c turn anticlockwise, -1 clockwise, 0 collinear.
** geom_incircle: for anticlockwise a, b, c: +1 if d is strictly inside
** their circumcircle, -1 strictly outside, 0 on it.
** Each evaluates its determinant in floating point and accepts the sign
** when it clears a proven bound on the rounding error, else recomputes it
** exactly with GMP rationals (geom_orient_exact; geom/predicates.c).  The
** bounds are Shewchuk's "stage A" bounds (Adaptive Precision
** Floating-Point Arithmetic and Fast Robust Geometric Predicates, 1997),
** which cover the rounding of the input differences too.  NaN and infinite
** coordinates give 0; callers validate input first. */
int geom_incircle(geom_point a, geom_point b, geom_point c, geom_point d);
int geom_orient_exact(geom_point a, geom_point b, geom_point c);

/* eps = 2^-53, half an ulp of 1: the relative error of one rounded operation. */
#define GEOM_EPS 0x1p-53

/* Shewchuk's bounds are relative, which assumes nothing underflows: a
** result in the subnormal range has an absolute error of up to 2^-1075
** whatever its size.  When every non-zero coordinate difference is at least
** 2^-200 in magnitude, every non-zero term of a determinant's permanent
** (degree 4 at most) is at least 2^-800, so the few absolute errors of
** 2^-1075 that can still occur (a final product or a cancelling sum in the
** subnormal range) are below 2^-270 of eps * permanent and the bound holds.
** Smaller differences go to the exact path.  Overflow needs no test: it
** makes the determinant or the bound infinite or NaN, the comparisons fail,
** and the exact path decides. */
static inline int geom_filter_tiny(double d) {
  return d != 0 && (d < 0 ? -d : d) < 0x1p-200;
}

/* det = (bx-ax)(cy-ay) - (by-ay)(cx-ax).  With l, r the two products,
** |fl(det) - det| <= (3 + 16 eps) eps (|l| + |r|) (ccwerrboundA), so a larger
** |fl(det)| has the true sign.  Inline: hot loops (hull updates, polygon
** checks) decide nearly every test here without a call. */
static inline int geom_orient(geom_point a, geom_point b, geom_point c) {
  double bax = b.x - a.x, bay = b.y - a.y, cax = c.x - a.x, cay = c.y - a.y;
  double l = bax * cay, r = bay * cax;
  double det = l - r;
  double bound = (3.0 + 16.0 * GEOM_EPS) * GEOM_EPS * ((l < 0 ? -l : l) + (r < 0 ? -r : r));
  if (!(geom_filter_tiny(bax) || geom_filter_tiny(bay) || geom_filter_tiny(cax)
        || geom_filter_tiny(cay))) {
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  return geom_orient_exact(a, b, c);
}

/* Counts of predicate calls that needed the exact fallback (diagnostics). */
unsigned long geom_exact_calls(void);

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
  GEOM_OUT_OF_SCALE    /* |coordinate| > GEOM_MAX_COORD or an edge < GEOM_MIN_EDGE */
} geom_polyerr;

/* The scales fliplab accepts.  Measures are products of up to six lengths
** (abc, joined by a product) evaluated in double precision: beyond these
** bounds they would overflow or underflow and decide nothing. */
#define GEOM_MAX_COORD 1e50
#define GEOM_MIN_EDGE 1e-50

geom_polyerr geom_polygon_check(geom_point *p, size_t n, size_t *bad, int *reversed);
const char *geom_polyerr_str(geom_polyerr e);

#endif
