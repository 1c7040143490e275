/*
** shape_sweep_internal.h: what the sweepline algorithm (lot/sweep.c, lot
** --algorithm sweep) asks of a shape, exactly: the two primitives of the
** thesis's section 4.1 (the key of a circumshape event, the rightmost point
** of the shape through three sites, and the "above" test of a site against
** the contact point of the shape through two boundary sites tangent to the
** sweepline), plus the test that three consecutive boundary sites close an
** event.  The sweep knows nothing of circles: it reads a shape's table of
** primitives (shape_sweep), the circle's (shape_sweep_circle.c: the
** Delaunay triangulation), an ellipse's (shape_sweep_ellipse.c) or a
** polygon's (shape_sweep_polygon.c), each made by shape_sweep_make
** (shape_sweep.c).  Every primitive is exact for points within geom.h's
** coordinate contract: certified floating-point intervals (below) decide
** when they can, GMP rationals (shape_internal.h's pool) when they cannot.
** Private to shapes/ and the sweep of lot/ (not installed).
*/
#ifndef FLIPLAB_SHAPE_SWEEP_INTERNAL_H
#define FLIPLAB_SHAPE_SWEEP_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <gmp.h>
#include "fliplab_config.h"
#include "predicates.h"
#include "shape.h"

/* An event's key in exact integers, made once when the event is scheduled
** and compared many times (the circle's, shape_sweep_circle.c: grids and
** integer inputs send most heap comparisons here): a.x, d, s nx and N =
** nlo + 2^64 nhi over the run's frame, the unit and origin in which every
** site is a small integer. */
typedef struct shape_sweep_ikey {
  int64_t ax, d, snx;       /* a polygon's integer key: a.x, D, 0 (shape_sweep_polygon.c) */
  uint64_t nlo, nhi;        /* a polygon's integer key: its numerator, two's complement */
  int known;                /* 1; a polygon's translate record 2 (d, snx, nlo: its words) */
} shape_sweep_ikey;

typedef struct shape_sweep_frame {
  double scale;             /* 1/u0: every coordinate times it is an integer */
  int64_t lo[2];            /* the smallest of those integers, x and y */
  int shift;                /* the unit is 2^shift u0 */
} shape_sweep_frame;

typedef struct shape_sweep {
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
  /* Optional (NULL: none): the integer keys.  frame: 1 and *f when every
  ** one of the n sites fits one; ikey: the key of t (t == NULL: the site
  ** key x) in frame f; ikey_cmp: the exact sign of key(a) - key(b), or 2
  ** when key_cmp must decide. */
  int (*frame)(const void *ctx, const geom_point *p, size_t n, shape_sweep_frame *f);
  void (*ikey)(const void *ctx, const shape_sweep_frame *f, const geom_point *t, double x,
               shape_sweep_ikey *k);
  int (*ikey_cmp)(const shape_sweep_ikey *a, const shape_sweep_ikey *b);
} shape_sweep;

/* The circle: the sweepline Delaunay triangulation (ctx unused). */
FLIPLAB_INTERNAL const shape_sweep shape_sweep_circle;

/* A conic {p : q11 x^2 + 2 q12 x y + q22 y^2 <= 1} (q11, q22 > 0,
** q11 q22 > q12^2): an ellipse's form (shape.h's), or the circle's
** (1, 0, 1), whose exact arithmetic is the ellipse's. */
typedef struct shape_sweep_conic {
  double q11, q12, q22;
} shape_sweep_conic;

/* A convex polygon K: its rightmost corner (the tie-break's) and that
** corner's x, and where every tie the sweep would need the rule's
** tie-break for is counted. */
/* The last triangle a polygon's table classified (its circumscribing
** shape: kind, contact edges or corner), which the next primitive on the
** same triangle reuses: scheduling an event asks for its key bounds and
** its integer key in a row, and each classification costs exact tests of
** the shape in special position. */
typedef struct shape_sweep_poly_memo {
  geom_point t[3];
  int ok, kind, e[3], corner;
} shape_sweep_poly_memo;

typedef struct shape_sweep_poly {
  const shape *k;
  int right;
  double xr;
  size_t *special;
  double kscale;            /* 2^p: K's corners times it are integers within 2^20 (then
                            ** integer keys), or 0 */
  shape_sweep_poly_memo *memo, last;   /* memo = &last */
} shape_sweep_poly;

/* The tables of an ellipse (shape_sweep_ellipse.c), reading *q, and of a
** polygon K (shape_sweep_polygon.c), reading *P, which it fills: into *s.
** What they read must outlive the run. */
FLIPLAB_INTERNAL void shape_sweep_ellipse(const shape_sweep_conic *q, shape_sweep *s);
FLIPLAB_INTERNAL void shape_sweep_polygon(shape_sweep_poly *P, const shape *k, size_t *special,
                                          shape_sweep *s);

/* What the table of a shape reads: one of these, by its kind. */
typedef struct shape_sweep_ctx {
  shape_sweep_conic q;
  shape_sweep_poly poly;
} shape_sweep_ctx;

/* The table of shape K into *s, its ctx pointing into *c: c must not
** move, and c, K and *special must outlive the run.  A polygon's ties
** decided by a fixed rule are counted in *special (shape_sweep_polygon.c);
** an ellipse has none (*special is left alone).  shape_sweep.c. */
FLIPLAB_INTERNAL void shape_sweep_make(const shape *k, shape_sweep_ctx *c, size_t *special,
                                       shape_sweep *s);

/* ---- shared by the shapes' primitives -------------------------------- */

/* The frame of the n sites p (the frame primitive of every table that has
** integer keys, ctx unused): 1 and *f when every site is an integer in
** [0, 2^20) in one unit (a power of two) relative to the smallest
** coordinates, else 0.  O(n).  shape_sweep_in_frame: site p's integers
** (p one of those sites, or (x, 0) for a site's x: z[0] only). */
FLIPLAB_INTERNAL int shape_sweep_frame_make(const void *ctx, const geom_point *p, size_t n,
                                            shape_sweep_frame *f);
FLIPLAB_INTERNAL void shape_sweep_in_frame(const shape_sweep_frame *f, geom_point p,
                                           int64_t z[2]);

/* Calls of the sweep's primitives that GMP decided, over the process (the
** tests' guard on grids: none there for the circle); shape_sweep.c. */
FLIPLAB_INTERNAL unsigned long shape_sweep_gmp_calls(void);
FLIPLAB_INTERNAL void shape_sweep_note_gmp(void);

/* Consecutive a, b, c (bottom to top) close an event when c is strictly
** right of a -> b: then the arcs' breakpoints converge (the circumscribing
** shape lies behind b).  The same for every shape. */
FLIPLAB_INTERNAL int shape_sweep_closes(const void *ctx, geom_point a, geom_point b,
                                        geom_point c);

/* sign((q1 + sqrt r1) - (q2 + sqrt r2)) exactly, r1, r2 >= 0 (q1, q2 may
** be overwritten); sign(e + 2 sqrt f) exactly, f >= 0 (e, f may be
** overwritten): the step both squarings of square roots end in. */
FLIPLAB_INTERNAL int shape_sweep_sqrt_cmp(mpq_ptr q1, mpq_srcptr r1, mpq_ptr q2, mpq_srcptr r2);
FLIPLAB_INTERNAL int shape_sweep_root_sign(mpq_ptr e, mpq_ptr f);

/* The conics' exact arithmetic (shape_sweep_ellipse.c), the circle's with
** the form (1, 0, 1): key_cmp of the table of form q (ctx: a
** shape_sweep_conic); the exact sign of a.x Q(b) - b.x Q(a), a = A - X,
** b = B - X (the lift sign of the "above" test); and for A.x = B.x the
** exact sign of q22 (2 X.y - A.y - B.y) + 2 q12 (X.x - A.x) (the column's). */
FLIPLAB_INTERNAL int shape_sweep_conic_key_cmp(const void *ctx, const geom_point *t, double tx,
                                               const geom_point *u, double ux);
FLIPLAB_INTERNAL int shape_sweep_conic_lift(const shape_sweep_conic *q, geom_point A,
                                            geom_point B, geom_point X);
FLIPLAB_INTERNAL int shape_sweep_conic_column(const shape_sweep_conic *q, geom_point A,
                                              geom_point B, geom_point X);

/* The conics' "above" test for A.x != B.x (shape_sweep_circle.c has the
** argument), up to the lift sign: 1 or 0, or 2 when X is above exactly
** when lift * *oab < 0 (lift: the sign of shape_sweep_conic_lift, oab =
** orient(A, B, X)). */
static inline int shape_sweep_conic_side(geom_point A, geom_point B, geom_point X, int *oab) {
  int lower = A.x < B.x;
  *oab = geom_orient_valid(A, B, X);   /* = orient(X, A, B) */
  int o = lower ? *oab : -*oab;
  if (o == 0) return lower;
  if (o > 0 && lower) return 1;
  if (o < 0 && !lower) return 0;
  return 2;
}

/* The trailing zero bits of x != 0 (the integer stages' common unit). */
static inline int shape_sweep_ctz(uint64_t x) {
#if defined(__GNUC__)
  return __builtin_ctzll(x);
#else
  int m = 0;
  for (; (x & 1) == 0; x >>= 1) m++;
  return m;
#endif
}

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
** at most, each shrinking it by a factor (1 - eps) at worst: shape_iv_fix's
** factor 1 + 2^-40 outweighs them all, and its 2^-1000 the absolute error
** of any term that underflows.  A NaN or infinite v or e (overflow, a
** division by an interval holding 0) makes the final bounds infinite, and
** the exact path decides. */
typedef struct shape_iv {
  double v, e;
} shape_iv;

static inline double shape_iv_fix(double e) {
  return e * (1.0 + 0x1p-40) + 0x1p-1000;
}

static inline shape_iv shape_iv_diff(double a, double b) {   /* a - b of two doubles */
  double v = a - b;
  return (shape_iv){v, shape_iv_fix(2 * GEOM_EPS * fabs(v))};
}

static inline shape_iv shape_iv_add(shape_iv x, shape_iv y) {
  double v = x.v + y.v;
  return (shape_iv){v, shape_iv_fix(x.e + y.e + 2 * GEOM_EPS * fabs(v))};
}

static inline shape_iv shape_iv_neg(shape_iv x) {
  return (shape_iv){-x.v, x.e};
}

static inline shape_iv shape_iv_sub(shape_iv x, shape_iv y) {
  return shape_iv_add(x, shape_iv_neg(y));
}

static inline shape_iv shape_iv_mul(shape_iv x, shape_iv y) {
  double v = x.v * y.v;
  return (shape_iv){v, shape_iv_fix(fabs(x.v) * y.e + fabs(y.v) * x.e + x.e * y.e
                                    + 2 * GEOM_EPS * fabs(v))};
}

static inline shape_iv shape_iv_div(shape_iv x, shape_iv y) {
  double v = x.v / y.v, ay = fabs(y.v);
  if (!(ay > y.e)) return (shape_iv){v, INFINITY};
  return (shape_iv){v, shape_iv_fix((ay * x.e + fabs(x.v) * y.e) / ((ay - y.e) * ay)
                                    + 2 * GEOM_EPS * fabs(v))};
}

static inline shape_iv shape_iv_sqrt(shape_iv x) {
  double v = sqrt(x.v > 0 ? x.v : 0);
  if (x.v <= x.e) return (shape_iv){v, shape_iv_fix(sqrt(x.v + x.e) + 2 * GEOM_EPS * v)};
  return (shape_iv){v, shape_iv_fix(x.e / v + 2 * GEOM_EPS * v)};
}

/* The certain sign of x: 1 or -1 when its interval excludes 0, else 2. */
static inline int shape_iv_sign(shape_iv x) {
  return x.v > x.e ? 1 : -x.v > x.e ? -1 : 2;
}

/* The final bounds v -+ E of k, E = fix(e + 4 eps |v|), are rounded too:
** fl(v - E) <= v - E + eps (|v| + E), which stays below v - e because
** E (1 - eps) - e >= 3 eps |v|; likewise above.  Both infinite when k is
** not finite. */
static inline void shape_iv_bounds(shape_iv k, double *lo, double *hi) {
  double E = shape_iv_fix(k.e + 4 * GEOM_EPS * fabs(k.v));
  *lo = k.v - E;
  *hi = k.v + E;
  if (!isfinite(*lo) || !isfinite(*hi)) {
    *lo = -INFINITY;
    *hi = INFINITY;
  }
}

#endif
