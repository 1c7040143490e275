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

#include <math.h>
#include <stddef.h>
#include <gmp.h>
#include "mesh.h"
#include "rule.h"
#include "shape.h"

typedef struct lot_sweep_shape {
  const char *name;
  const void *ctx;          /* the shape's parameters, passed to every primitive */
  /* 1 when a, b, c, consecutive on the boundary from bottom to top, close
  ** an event (c strictly right of the line a -> b). */
  int (*closes)(const void *ctx, geom_point a, geom_point b, geom_point c);
  /* lo <= key <= hi, the key of the event of t (for the circle: cx + R),
  ** or lo = -inf, hi = +inf when no bound is known.  A shape may also give
  ** infinite keys (unbounded to the right) bounds in bands above every
  ** finite key's: disjoint bounds must order as the keys do. */
  void (*key_bounds)(const void *ctx, const geom_point t[3], double *lo, double *hi);
  /* The exact sign of key(t) - key(u), where t == NULL stands for the
  ** site key tx (an x coordinate), u == NULL for ux. */
  int (*key_cmp)(const void *ctx, const geom_point *t, double tx, const geom_point *u,
                 double ux);
  /* 1 when x lies strictly above the contact point of the shape through a
  ** and b (a's arc below b's on the boundary) tangent to the sweepline
  ** through x; a.x, b.x <= x.x. */
  int (*above)(const void *ctx, geom_point a, geom_point b, geom_point x);
  /* NULL when every order of equal keys is a valid sweep (the circle,
  ** ellipses: four sites on one shape); else the sweep counts here the
  ** equal keys of events that share two sites, which only a tie-break
  ** could order. */
  size_t *ties;
} lot_sweep_shape;

/* The circle: the sweepline Delaunay triangulation (ctx unused). */
FLIPLAB_INTERNAL const lot_sweep_shape lot_sweep_circle;

/* An ellipse {p : q11 x^2 + 2 q12 x y + q22 y^2 <= 1} (shape.h's form,
** q11, q22 > 0, q11 q22 > q12^2): the table in *s, reading *q, which must
** outlive the run (lot/sweep_ellipse.c). */
typedef struct lot_sweep_conic {
  double q11, q12, q22;
} lot_sweep_conic;
FLIPLAB_INTERNAL void lot_sweep_ellipse(const lot_sweep_conic *q, lot_sweep_shape *s);

/* A convex polygon K (lot/sweep_polygon.c): the table in *s, reading *P
** (which must outlive the run, as must k); every tie the sweep would need
** the rule's tie-break for is counted in *special. */
typedef struct lot_sweep_poly {
  const shape *k;
  int right;                /* K's rightmost corner (the tie-break's) */
  double xr;                /* its x */
  size_t *special;
} lot_sweep_poly;
FLIPLAB_INTERNAL void lot_sweep_polygon(lot_sweep_poly *P, const shape *k, size_t *special,
                                        lot_sweep_shape *s);

/* Triangulate m->p[0 .. m->np - 1], sorted by x, then y (then input
** index), with s: triangles and ghosts into m (allocated by
** lot_mesh_alloc, no cache).  Equal consecutive points are merged into
** the first (*duplicates counts them, m->inp takes the smaller index).
** 0; -1 out of memory; -2 no triangle (all points equal or collinear); -3
** the structure broke (more triangles than the mesh holds, a hull that is
** no cycle): only a polygon's sweep after ties it counted in *ties. */
FLIPLAB_INTERNAL int lot_sweep_run(lot_mesh *m, const lot_sweep_shape *s, size_t *duplicates);

/* The primitives the sweep uses for a rule (lot/sweep_shape.c): s, whose
** ctx points into the pick itself (so it must not move), and the parsed
** shape k (NULL for DT).  0, or -1 with a one-line message when the sweep
** cannot make the rule's triangulation; free with lot_sweep_pick_free. */
typedef struct lot_sweep_pick {
  lot_sweep_shape s;
  lot_sweep_conic q;
  lot_sweep_poly poly;
  size_t special;           /* polygons: ties decided by the fixed rule (lot_sweep_mesh) */
  shape *k;
} lot_sweep_pick;
FLIPLAB_INTERNAL int lot_sweep_pick_rule(const rule *r, lot_sweep_pick *pk, char *err,
                                         size_t errlen);
FLIPLAB_INTERNAL void lot_sweep_pick_free(lot_sweep_pick *pk);

/* ---- shared by the shapes' primitives -------------------------------- */

/* Consecutive a, b, c (bottom to top) close an event when c is strictly
** right of a -> b: then the arcs' breakpoints converge (the circumscribing
** shape lies behind b).  The same for every shape. */
FLIPLAB_INTERNAL int lot_sweep_closes(const void *ctx, geom_point a, geom_point b, geom_point c);

/* sign((q1 + sqrt r1) - (q2 + sqrt r2)) exactly, r1, r2 >= 0. */
FLIPLAB_INTERNAL int lot_sweep_sqrt_cmp(mpq_t q1, mpq_t r1, mpq_t q2, mpq_t r2);

/* ---- certified floating-point intervals -------------------------------- */

/* A value v with a bound e on its distance to the exact quantity.  Each
** operation below returns v = fl(op(x.v, y.v)) and an e that bounds
** |op(X, Y) - v| for every X within x.e of x.v and Y within y.e of y.v:
**   add: |X + Y - (x.v + y.v)| <= x.e + y.e;
**   mul: |XY - x.v y.v| <= |x.v| y.e + |y.v| x.e + x.e y.e;
**   div: |X/Y - x.v/y.v| = |(X - x.v) y.v - x.v (Y - y.v)| / |Y y.v|
**        <= (|y.v| x.e + |x.v| y.e) / ((|y.v| - y.e) |y.v|), when |y.v| > y.e;
**   sqrt: |sqrt X - sqrt x.v| = |X - x.v| / (sqrt X + sqrt x.v) <= x.e / sqrt x.v,
**        or, when x.v <= x.e, sqrt X and sqrt x.v both lie in [0, sqrt(x.v + x.e)];
** plus the rounding of v itself, at most eps |op| <= 2 eps |v|.  The bound
** is evaluated in floating point from non-negative terms, a dozen roundings
** at most, each shrinking it by a factor (1 - eps) at worst: lot_iv_fix's
** factor 1 + 2^-40 outweighs them all, and its 2^-1000 the absolute error
** of any term that underflows.  A NaN or infinite v or e (overflow, a
** division by an interval holding 0) makes the final bounds infinite, and
** the exact path decides. */
typedef struct lot_iv {
  double v, e;
} lot_iv;

static inline double lot_iv_fix(double e) {
  return e * (1.0 + 0x1p-40) + 0x1p-1000;
}

static inline lot_iv lot_iv_diff(double a, double b) {   /* a - b of two doubles */
  double v = a - b;
  return (lot_iv){v, lot_iv_fix(2 * GEOM_EPS * fabs(v))};
}

static inline lot_iv lot_iv_add(lot_iv x, lot_iv y) {
  double v = x.v + y.v;
  return (lot_iv){v, lot_iv_fix(x.e + y.e + 2 * GEOM_EPS * fabs(v))};
}

static inline lot_iv lot_iv_neg(lot_iv x) {
  return (lot_iv){-x.v, x.e};
}

static inline lot_iv lot_iv_mul(lot_iv x, lot_iv y) {
  double v = x.v * y.v;
  return (lot_iv){v, lot_iv_fix(fabs(x.v) * y.e + fabs(y.v) * x.e + x.e * y.e
                                + 2 * GEOM_EPS * fabs(v))};
}

static inline lot_iv lot_iv_div(lot_iv x, lot_iv y) {
  double v = x.v / y.v, ay = fabs(y.v);
  if (!(ay > y.e)) return (lot_iv){v, INFINITY};
  return (lot_iv){v, lot_iv_fix((ay * x.e + fabs(x.v) * y.e) / ((ay - y.e) * ay)
                                + 2 * GEOM_EPS * fabs(v))};
}

static inline lot_iv lot_iv_sqrt(lot_iv x) {
  double v = sqrt(x.v > 0 ? x.v : 0);
  if (x.v <= x.e) return (lot_iv){v, lot_iv_fix(sqrt(x.v + x.e) + 2 * GEOM_EPS * v)};
  return (lot_iv){v, lot_iv_fix(x.e / v + 2 * GEOM_EPS * v)};
}

/* The final bounds v -+ E of k, E = fix(e + 4 eps |v|), are rounded too:
** fl(v - E) <= v - E + eps (|v| + E), which stays below v - e because
** E (1 - eps) - e >= 3 eps |v|; likewise above.  Both infinite when k is
** not finite. */
static inline void lot_iv_bounds(lot_iv k, double *lo, double *hi) {
  double E = lot_iv_fix(k.e + 4 * GEOM_EPS * fabs(k.v));
  *lo = k.v - E;
  *hi = k.v + E;
  if (!isfinite(*lo) || !isfinite(*hi)) {
    *lo = -INFINITY;
    *hi = INFINITY;
  }
}

#endif
