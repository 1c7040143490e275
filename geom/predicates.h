/*
** predicates.h: the exact orientation and incircle tests, and the point
** type they work on.
**
** geom_orient: +1 if a, b, c turn anticlockwise, -1 clockwise, 0 collinear.
** geom_incircle: for anticlockwise a, b, c: +1 if d is strictly inside
** their circumcircle, -1 strictly outside, 0 on it.
** Each evaluates its determinant in floating point and accepts the sign
** when it clears a proven bound on the rounding error, else recomputes it
** exactly with GMP rationals (geom_orient_exact; geom/predicates.c).  The
** bounds are Shewchuk's "stage A" bounds (Adaptive Precision
** Floating-Point Arithmetic and Fast Robust Geometric Predicates, 1997),
** which cover the rounding of the input differences too.  NaN and infinite
** coordinates give 0; callers validate input first.
**
** Depends on nothing but fliplab_config.h (the floating-point contract the
** error bounds assume); geom.h builds on it.
*/
#ifndef FLIPLAB_PREDICATES_H
#define FLIPLAB_PREDICATES_H

#include "fliplab_config.h"

typedef struct geom_point {
  double x, y;
} geom_point;

int geom_incircle(geom_point a, geom_point b, geom_point c, geom_point d);
int geom_orient_exact(geom_point a, geom_point b, geom_point c);
/* |orientation determinant| exactly, rounded toward zero (finite input;
** geom_twice_area's slow path). */
double geom_twice_area_exact(geom_point a, geom_point b, geom_point c);

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

#endif
