/*
** shape_internal.h: the filtered arithmetic behind the shape predicates
** (geom/shape_arith.c): one program per predicate, run first on doubles with a
** proven error bound, then, when the bound cannot tell the sign, on exact
** GMP rationals.  Private to geom/ (not installed: shape.c and shape_arith.c include it).
*/
#ifndef FLIPLAB_SHAPE_INTERNAL_H
#define FLIPLAB_SHAPE_INTERNAL_H

#include "fliplab_config.h"
#include "shape.h"

/* What a predicate reads: the shape, up to four rows (a polygon edge and a
** site each), the point o every site is taken relative to (the
** predicates are translation-invariant: differences to o keep the double
** run accurate), and whether the value or its perturbation coefficient is
** wanted (docs/emptyshape.md: the shape turned by an infinitesimal angle,
** computed as the sites turned the other way). */
typedef struct shape_args {
  const shape *K;
  int e[4];             /* polygon edges (edge i joins vertices i and i+1) */
  geom_point p[4];      /* the rows' sites */
  geom_point o;         /* the origin of the site differences */
  int corner;           /* shape_prog_corner: the corner's vertex */
  int deriv;            /* 0: the value; 1: the coefficient of eps */
} shape_args;

struct shape_ar;
typedef int (*shape_prog)(struct shape_ar *a, const shape_args *g);

/* The exact sign of a program's value (filter, then GMP). */
FLIPLAB_INTERNAL int shape_sign(shape_prog f, const shape_args *g);
/* The sign under the perturbation: the value's sign, or when it is 0 the
** sign of the eps coefficient; *level (may be NULL) gets 0 or 1, or 2
** when both are 0. */
FLIPLAB_INTERNAL int shape_eps_sign(shape_prog f, shape_args g, int *level);

/* The contact edges t (of A, B, C = p[0..2]) of the circumscribing
** homothet of the anticlockwise triangle p whose supports s_AB, s_BC, s_CA
** (sup) differ, and det3's sign; 0 when none is found (shape.c). */
FLIPLAB_INTERNAL int shape_contacts(const shape *k, const int sup[3], const geom_point p[3], int t[3]);

/* The programs.  cross: cross(e_{e[0]}, p[1] - p[0]) (deriv: -e.(p[1] - p[0]));
** det3h: rows (e_x, e_y, h) of edges e[0..2], h = cross(k_i, k_{i+1});
** det3w: rows (e_x, e_y, w) of (e[r], p[r]), w = cross(p - o, e) (deriv: e.(p - o));
** det4: rows (e_x, e_y, h, w) of (e[r], p[r]), r < 4;
** corner: the rounding-shape determinant of p[0..2] about o (shape.c);
** ellipse: rows (x, y, Q(x, y)) of p[r] - o, r < 3. */
FLIPLAB_INTERNAL int shape_prog_cross(struct shape_ar *a, const shape_args *g);
FLIPLAB_INTERNAL int shape_prog_det3h(struct shape_ar *a, const shape_args *g);
FLIPLAB_INTERNAL int shape_prog_det3w(struct shape_ar *a, const shape_args *g);
FLIPLAB_INTERNAL int shape_prog_det4(struct shape_ar *a, const shape_args *g);
FLIPLAB_INTERNAL int shape_prog_corner(struct shape_ar *a, const shape_args *g);
FLIPLAB_INTERNAL int shape_prog_ellipse(struct shape_ar *a, const shape_args *g);

#endif
