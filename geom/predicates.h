/*
** predicates.h: the exact orientation and incircle tests, and the point
** type they work on.
**
** geom_orient: +1 if a, b, c turn anticlockwise, -1 clockwise, 0 collinear.
** geom_incircle: for anticlockwise a, b, c: +1 if d is strictly inside
** their circumcircle, -1 strictly outside, 0 on it.
** Each evaluates its determinant in floating point and accepts the sign
** when it clears a proven bound on the rounding error, else recomputes it
** exactly (geom_orient_exact; geom/predicates.c): in integers when the
** coordinate differences are integer multiples of one power of two within
** 62 bits of it (grids, integer coordinates), else in floating-point
** expansions, else in GMP rationals.  The bounds are Shewchuk's "stage A"
** bounds (Adaptive Precision Floating-Point Arithmetic and Fast Robust
** Geometric Predicates, 1997), which cover the rounding of the input
** differences too.  NaN and infinite coordinates give 0; callers validate
** input first.
**
** Depends on nothing but <math.h> (fabs) and fliplab_config.h (the
** floating-point contract the error bounds assume); geom.h builds on it.
*/
#ifndef FLIPLAB_PREDICATES_H
#define FLIPLAB_PREDICATES_H

#include <math.h>
#include "fliplab_config.h"

typedef struct geom_point {
  double x, y;
} geom_point;

int geom_orient_exact(geom_point a, geom_point b, geom_point c);
/* |orientation determinant| exactly, rounded toward zero (input within the
** coordinate contract of geom.h; geom_twice_area's slow path).  Computed
** with floating-point expansions, not GMP (predicates.c). */
double geom_twice_area_exact(geom_point a, geom_point b, geom_point c);
int geom_incircle_exact(geom_point a, geom_point b, geom_point c, geom_point d);

/* eps = 2^-53, half an ulp of 1: the relative error of one rounded operation. */
#define GEOM_EPS 0x1p-53

/* Shewchuk's stage-A bound of the orientation determinant (his
** ccwerrboundA).  Write det = (bx-ax)(cy-ay) - (by-ay)(cx-ax) and let
** l = fl(fl(bx-ax) fl(cy-ay)), r likewise, so fl(det) = fl(l - r).
** Each of the four differences carries a relative error of at most eps,
** each product one more rounding, and the final subtraction one more; the
** sum of these error terms, bounded against |l| + |r| instead of the
** unknown exact products (which costs the second-order terms), is
**   |fl(det) - det| <= (3 + 16 eps) eps (|l| + |r|)
** (Shewchuk 1997, section 4).  So whenever |fl(det)| exceeds
** GEOM_CCW_ERRBOUND_A (|l| + |r|), fl(det) has the sign of det.  The
** bound is relative: it assumes no underflow (geom_filter_tiny below) and
** no overflow (which turns the comparisons false).  Its users:
** geom_orient_filtered here, lot/'s walk (the same determinant written
** with differences to the third point), and the area filters of geom/
** (geom_twice_area_inline, geom_edges_make), which accept a value only
** 2^40 times above it.  3 + 16 eps = 3 + 2^-49 is exact, so the constant is
** one double, and multiplying it by 2^40 is exact too. */
#define GEOM_CCW_ERRBOUND_A ((3.0 + 16.0 * GEOM_EPS) * GEOM_EPS)

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
  return (d != 0) & (fabs(d) < 0x1p-200);
}

/* det = (bx-ax)(cy-ay) - (by-ay)(cx-ax).  With l, r the two products,
** |fl(det) - det| <= GEOM_CCW_ERRBOUND_A (|l| + |r|) (above), so a larger
** |fl(det)| has the true sign.  Inline: hot loops (hull updates, polygon
** checks) decide nearly every test here without a call.  `tiny` = 0 skips
** the tiny-difference test (geom_orient_valid below says when that is safe);
** it is a constant at every call, so each caller gets one specialised copy. */
static inline int geom_orient_filtered(geom_point a, geom_point b, geom_point c, int tiny) {
  double bax = b.x - a.x, bay = b.y - a.y, cax = c.x - a.x, cay = c.y - a.y;
  double l = bax * cay, r = bay * cax;
  double det = l - r;
  double bound = GEOM_CCW_ERRBOUND_A * (fabs(l) + fabs(r));
  if (!tiny || !(geom_filter_tiny(bax) | geom_filter_tiny(bay) | geom_filter_tiny(cax)
                 | geom_filter_tiny(cay))) {
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  return geom_orient_exact(a, b, c);
}

static inline int geom_orient(geom_point a, geom_point b, geom_point c) {
  return geom_orient_filtered(a, b, c, 1);
}

/* The incircle determinant of a, b, c, d translated so that d is the origin:
**   | adx ady adx^2+ady^2 |
**   | bdx bdy bdx^2+bdy^2 |
**   | cdx cdy cdx^2+cdy^2 |   (positive when d is inside circle abc, abc anticlockwise)
** With permanent = sum of |lift_i| (|x_j y_k| + |x_k y_j|), |fl(det) - det|
** <= (10 + 96 eps) eps permanent (Shewchuk's iccerrboundA, which covers the
** rounding of the six input differences), so a larger |fl(det)| has the true
** sign; tiny differences and overflow go to the exact path as for
** geom_orient.  Inline: the Delaunay triangulation of a million points makes
** millions of these tests, nearly all decided here without a call.  The
** tiny tests are combined with | rather than ||: six cheap comparisons beat
** six unpredictable branches. */
static inline int geom_incircle_filtered(geom_point a, geom_point b, geom_point c, geom_point d,
                                         int tiny) {
  double adx = a.x - d.x, ady = a.y - d.y;
  double bdx = b.x - d.x, bdy = b.y - d.y;
  double cdx = c.x - d.x, cdy = c.y - d.y;
  double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  double cdxady = cdx * ady, adxcdy = adx * cdy;
  double adxbdy = adx * bdy, bdxady = bdx * ady;
  double alift = adx * adx + ady * ady;
  double blift = bdx * bdx + bdy * bdy;
  double clift = cdx * cdx + cdy * cdy;
  double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy)
             + clift * (adxbdy - bdxady);
  double permanent = (fabs(bdxcdy) + fabs(cdxbdy)) * alift
                   + (fabs(cdxady) + fabs(adxcdy)) * blift
                   + (fabs(adxbdy) + fabs(bdxady)) * clift;
  double bound = (10.0 + 96.0 * GEOM_EPS) * GEOM_EPS * permanent;
  if (!tiny || !(geom_filter_tiny(adx) | geom_filter_tiny(ady) | geom_filter_tiny(bdx)
                 | geom_filter_tiny(bdy) | geom_filter_tiny(cdx) | geom_filter_tiny(cdy))) {
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  return geom_incircle_exact(a, b, c, d);
}

static inline int geom_incircle(geom_point a, geom_point b, geom_point c, geom_point d) {
  return geom_incircle_filtered(a, b, c, d, 1);
}

/* The same predicates for points known to obey the coordinate contract
** (every coordinate 0 or of magnitude in [1e-30, 1e30]; geom_coord_check in
** geom.h), as lot/ knows after validating its input: there the tiny test
** cannot fire.  1e-30 > 2^-100, so two distinct coordinates are multiples of
** 2^-152 and differ by at least 2^-152 > 2^-200 (a difference with 0 is the
** other coordinate, at least 2^-100); and no difference, product or lift of
** such points over- or underflows (docs/scale.md), so the bounds above hold
** as they stand.  The tiny test is a tenth of the instructions of a
** Delaunay triangulation, which is why these exist. */
static inline int geom_orient_valid(geom_point a, geom_point b, geom_point c) {
  return geom_orient_filtered(a, b, c, 0);
}

static inline int geom_incircle_valid(geom_point a, geom_point b, geom_point c, geom_point d) {
  return geom_incircle_filtered(a, b, c, d, 0);
}

/* 1 when the segments ab and cd cross at one point interior to both: the
** ends of each strictly on opposite sides of the other's line.  Touching,
** an end on the other segment, overlapping and shared ends are no crossing.
** Exact; the second pair of tests only when the first separates.  The one
** crossing test of the library: `tiny` as for geom_orient_filtered, _valid
** for points known to obey the contract; ops_segments_cross counts it. */
static inline int geom_segments_cross_filtered(geom_point a, geom_point b, geom_point c,
                                               geom_point d, int tiny) {
  return geom_orient_filtered(a, b, c, tiny) * geom_orient_filtered(a, b, d, tiny) < 0 &&
         geom_orient_filtered(c, d, a, tiny) * geom_orient_filtered(c, d, b, tiny) < 0;
}

static inline int geom_segments_cross(geom_point a, geom_point b, geom_point c, geom_point d) {
  return geom_segments_cross_filtered(a, b, c, d, 1);
}

static inline int geom_segments_cross_valid(geom_point a, geom_point b, geom_point c,
                                            geom_point d) {
  return geom_segments_cross_filtered(a, b, c, d, 0);
}

/* The sign of |ab|^2 - |cd|^2: +1 when segment ab is strictly longer than
** cd, -1 strictly shorter, 0 equal; exact for finite inputs (a filter, then
** floating-point expansions or GMP rationals; predicates.c has the bound).
** The minimum-weight triangulation's flip decision (got/got_skel.c). */
int geom_dist2_cmp(geom_point a, geom_point b, geom_point c, geom_point d);

/* The power test of weighted points (the regular triangulation's
** incircle test): the sign of the lifted determinant of a, b, c, d with
** weights w[0..3], each point lifted to x^2 + y^2 - w.  For anticlockwise
** a, b, c: +1 when d's lifted point lies strictly below the plane through
** the others' (d has negative power against the orthogonal circle of a,
** b, c: the edge between them is not regular), -1 strictly above, 0 on it.
** All weights equal: geom_incircle's answer.  Exact for finite inputs
** (filter, then the exact stages of geom_incircle; predicates.c has the
** bound). */
int geom_power(geom_point a, geom_point b, geom_point c, geom_point d, const double w[4]);
int geom_power_exact(geom_point a, geom_point b, geom_point c, geom_point d, const double w[4]);

/* Counts of predicate calls that needed the exact fallback (diagnostics). */
unsigned long geom_exact_calls(void);

/* The exact fallback's calls broken down by predicate and by the stage that
** decided (predicates.c): integers (128-bit, and 256-bit sums for the
** lifted determinant) when the coordinate differences are exact integer
** multiples of one power of two within 62 bits of it, floating-point
** expansions, GMP rationals (the last resort).  Summed over all threads
** since the start; geom_exact_calls is the total. */
typedef enum geom_pred {
  GEOM_PRED_ORIENT, GEOM_PRED_INCIRCLE, GEOM_PRED_POWER, GEOM_PRED_AREA, GEOM_PRED_COUNT
} geom_pred;
typedef enum geom_stage {
  GEOM_STAGE_INT, GEOM_STAGE_EXPANSION, GEOM_STAGE_GMP, GEOM_STAGE_COUNT
} geom_stage;
unsigned long geom_exact_stage_calls(geom_pred p, geom_stage s);
/* on != 0: every exact fallback goes straight to GMP, skipping the faster
** stages (process-wide; the purely exact mode the tests and bench_grid
** compare the fast stages with).  Returns the previous setting. */
int geom_exact_gmp_only(int on);

#endif
