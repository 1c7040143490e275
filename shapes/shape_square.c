/*
** shape_square.c: the empty-square (L_inf) rule decided by bounding boxes.
** For an axis-parallel square K the circumscribing homothet of a triangle
** is read off the triangle's bounding box, and D's test is comparisons of
** coordinates and of differences of coordinates: no product, no filter.
** Where a comparison ties it gives up, and shape_polygon.c's quick and exact paths
** decide (so every answer is theirs).
*/
#include <math.h>
#include "shape_internal.h"

/* ---- why the bounding box gives the circumscribing square --------------
**
** Let A, B, C have x-extent W (max x - min x) and y-extent H, and say
** W > H.  A homothet of the square containing the three has side at least
** W; one with all three on its boundary has side exactly W when the two
** x-extremes are on its left and right sides: then the third point Q must
** touch the top or the bottom, so Q is the topmost or the bottommost of the
** three, and the square is [xmin, xmax] x [yQ - W, yQ] (or [yQ, yQ + W]); it
** holds the other two (their y is within H < W of yQ) and has the three on
** its boundary, so it is THE circumscribing homothet (docs/emptyshape.md:
** it is unique when it exists).  When Q's y is strictly between the others'
** no homothet passes through the three (the triangle is a staircase, whose
** circumscribing shape is a corner's rounding shape): left to shape_polygon.c.  A
** side longer than W would need a third side touched on the x-slab's
** behalf, impossible with one point per side and the x-extremes strictly
** inside the slab's two sides.  Two of A, B, C with one x or one y (two
** sites on a line parallel to a side), or W = H (a site on a corner's
** cone), are special position, left to shape_polygon.c (its perturbation decides);
** so below the three x and the three y are different.  H > W is the same
** with x and y swapped.
**
** Exactness.  D is inside the open square when xmin < xD < xmax, yD < yQ and
** yQ - yD < W (top case), and outside when one of them fails strictly.
** Plain comparisons of doubles are exact.  A comparison of two rounded
** differences, fl(a - b) < fl(c - d), implies a - b < c - d: rounding is
** monotone, so a - b >= c - d would give fl(a - b) >= fl(c - d); equal
** rounded values say nothing, and the comparison is a tie.  W > H is such a
** comparison too.  No difference overflows inside the coordinate contract
** (docs/scale.md).  So every strict outcome below is the exact one, the
** perturbed one too (the perturbation only ever decides exact ties), and
** each tie gives up. */

/* Which of A, B, C is where is a coin toss, so below the choices are
** made by tables and flags, and a branch is taken on rare cases and on the
** answer only.  The least and the greatest of three different values, by
** (v0 < v1) | (v0 < v2) << 1 | (v1 < v2) << 2 (2 and 5 cannot occur). */
static const unsigned char shape_sq_least[8] = {2, 2, 0, 0, 1, 0, 1, 0};
static const unsigned char shape_sq_most[8] = {0, 1, 0, 1, 0, 0, 2, 2};

static inline int shape_sq_order(const double v[4]) {
  return (v[0] < v[1]) | (v[0] < v[2]) << 1 | (v[1] < v[2]) << 2;
}

int shape_square_decide(const geom_point p[4]) {
  /* xy[0]: the x, xy[1]: the y (selected by index: a select would be a branch) */
  double xy[2][4] = {{p[0].x, p[1].x, p[2].x, p[3].x}, {p[0].y, p[1].y, p[2].y, p[3].y}};
  const double *x = xy[0], *y = xy[1];
  if ((x[0] == x[1]) | (x[0] == x[2]) | (x[1] == x[2]) | (y[0] == y[1]) | (y[0] == y[2]) |
      (y[1] == y[2]))
    return -1;   /* two sites on a line parallel to a side: special position */
  int o[2] = {shape_sq_order(x), shape_sq_order(y)};
  double ext[2] = {x[shape_sq_most[o[0]]] - x[shape_sq_least[o[0]]],
                   y[shape_sq_most[o[1]]] - y[shape_sq_least[o[1]]]};
  if (ext[0] == ext[1]) return -1;   /* a site on a corner's cone */
  /* u: the coordinate of the larger extent (its slab holds two of the
  ** three on its sides), v the other */
  int iu = ext[1] > ext[0], iv = !iu;
  const double *u = xy[iu], *v = xy[iv];
  int ulo = shape_sq_least[o[iu]], uhi = shape_sq_most[o[iu]], q = 3 - ulo - uhi;
  /* s: +1 when Q is on the top side, -1 on the bottom, 0 when Q's v is
  ** between the others' (a staircase: a corner's rounding shape) */
  int s = (q == shape_sq_most[o[iv]]) - (q == shape_sq_least[o[iv]]);
  if (s == 0) return -1;
  /* the inside of the square across the slab is s (vQ - vD) in (0, e):
  ** a, b, c exact signs (differences of two doubles); d: the extent
  ** against the rounded difference c, a tie when 0 */
  double a = u[3] - u[ulo], b = u[uhi] - u[3], c = s * (v[q] - v[3]), d = ext[iu] - c;
  if ((a < 0) | (b < 0) | (c < 0) | (d < 0)) return SHAPE_AC;
  if ((a > 0) & (b > 0) & (c > 0) & (d > 0)) return SHAPE_BD;
  return -1;
}

int shape_square_is(const shape *k) {
  if (k->n != 4) return 0;
  const geom_point *v = k->v;
  for (int i = 0; i < 4; i++) {
    geom_point a = v[i], b = v[(i + 1) & 3];
    if ((a.x == b.x) == (a.y == b.y)) return 0;   /* not axis-parallel */
  }
  /* a convex quadrilateral with axis-parallel sides is a rectangle: a
  ** square when two adjacent sides are equally long, exactly (sides that
  ** are no exact difference of doubles are not taken) */
  int horizontal = v[0].y == v[1].y;
  double s0a = horizontal ? v[1].x : v[1].y, s0b = horizontal ? v[0].x : v[0].y;
  double s1a = horizontal ? v[2].y : v[2].x, s1b = horizontal ? v[1].y : v[1].x;
  double d0, d1;
  return shape_exact_diff(s0a, s0b, &d0) && shape_exact_diff(s1a, s1b, &d1) && fabs(d0) == fabs(d1);
}

/* ---- the square's variant (shape_internal.h) ------------------------------ */

/* The bounding boxes need no hint and leave none. */
static int shape_square_own(const shape *k, const geom_point p[4], shape_hint *h) {
  (void)k;
  (void)h;
  return shape_square_decide(p);
}

/* Without hints lot's square takes 12% fewer instructions. */
static int shape_square_wants_hints(const shape *k) {
  (void)k;
  return 0;
}

SHAPE_VARIANT_OPS(square, shape_square_own, NULL, shape_square_wants_hints);
