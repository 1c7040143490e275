/*
** shape.h: convex shapes (balls of convex distance functions) and the exact
** empty-shape decision of a convex quadrilateral.
**
** A shape K is a strictly convex polygon (its vertices, anticlockwise, as
** doubles: the shape IS those doubles) or an ellipse (a quadratic form
** rounded to doubles once: the shape IS that rounded form).  Its homothets
** t + sK (s > 0) play the part circles play for the Delaunay rule; a
** polygon's corners add their rounding shapes (hyperbolic regions) so that
** every triangle has exactly one circumscribing shape.  docs/emptyshape.md
** has the definitions, the special-position rule and the exactness argument.
*/
#ifndef FLIPLAB_SHAPE_H
#define FLIPLAB_SHAPE_H

#include <stddef.h>
#include "predicates.h"   /* geom_point */

typedef enum shape_kind { SHAPE_POLYGON, SHAPE_ELLIPSE } shape_kind;

/* The answers of shape_decide, numbered as fliprules/' rule_choice. */
typedef enum shape_choice { SHAPE_AC = 0, SHAPE_BD = 1, SHAPE_EITHER = 2 } shape_choice;

#define SHAPE_MAX_VERTICES 1024
#define SHAPE_NGON_MAX 1024

/* What a user reads of a shape; the rest (its variant, its decision and the
** tables that speed it up, chosen once when the shape is made) is private to
** shapes/ (shape_internal.h). */
typedef struct shape {
  shape_kind kind;
  int n;                  /* polygon: vertex count (>= 3) */
  geom_point *v;          /* polygon: the vertices, anticlockwise (owned) */
  double q11, q12, q22;   /* ellipse: {x : q11 x^2 + 2 q12 x y + q22 y^2 <= 1} */
  struct shape_impl *impl;   /* private */
} shape;

/* Parse a shape spec (docs/emptyshape.md has the grammar): "square",
** "diamond", "triangle", "hexagon", "octagon", "ngon:K",
** "poly:X Y;X Y;..." (a vertex's two numbers separated by ',' or blanks),
** "ellipse:A B[ THETA]" (',' or blanks).  0 and *out (free it with
** shape_free), or -1 and a one-line reason in err. */
int shape_parse(const char *spec, shape **out, char *err, size_t errlen);
void shape_free(shape *k);

/* How a decision was reached (diagnostics and tests). */
typedef struct shape_trace {
  int rounding;       /* 1: the circumscribing shape was a corner's rounding shape */
  int corner;         /* its corner (vertex index), else -1 */
  int contact[3];     /* polygon homothet: the contact edges of A, B, C */
  int level;          /* 0: decided by the value, 1: by the perturbation, 2: neither (either) */
  int failed;         /* 1: no contact triple found (answered either; never expected) */
} shape_trace;

/* The empty-shape rule of K on the strictly convex anticlockwise
** quadrilateral ABCD: SHAPE_BD when D is inside the circumscribing shape of
** ABC, SHAPE_AC when outside, SHAPE_EITHER when on it after the tie-break
** (docs/emptyshape.md).  Exact for finite double inputs; the same answer
** for ABCD, BCDA, CDAB and DABC (with AC and BD swapped for the odd ones).
** tr may be NULL. */
shape_choice shape_decide(const shape *k, geom_point a, geom_point b, geom_point c, geom_point d,
                          shape_trace *tr);

/* shape_decide for sites known to obey the coordinate contract of geom.h
** (every coordinate 0 or of magnitude in [1e-30, 1e30]: lot's validated
** sites), without a trace: the same answer, without the checks. */
shape_choice shape_decide_valid(const shape *k, geom_point a, geom_point b, geom_point c,
                                geom_point d);

/* What a decision learned of the circumscribing shape of its A, B, C (in
** that order): the homothet's contact edges, or the corner whose rounding
** shape it is.  Kept with a triangle (lot keeps one per mesh triangle), it
** lets the next quadrilateral on the same A, B, C skip finding the shape
** again; {0} is the empty hint.  Polygons of at most 255 vertices. */
enum { SHAPE_HINT_NONE = 0, SHAPE_HINT_HOMOTHET = 1, SHAPE_HINT_CORNER = 2 };
typedef struct shape_hint {
  unsigned char how;    /* SHAPE_HINT_* */
  unsigned char e[3];   /* HOMOTHET: the contact edges of A, B, C; CORNER: e[0] */
} shape_hint;
/* shape_decide_valid reading and filling *h: it must be empty or have been
** filled by a call with the same K, A, B and C, or with the same triangle
** in another rotation and its edges rotated alike (B, C, A take e[1], e[2],
** e[0]; a corner's hint stays).  The same answer as without it; h may be
** NULL.  A decision that needs no hint (the square's, shape_wants_hints)
** may leave *h empty. */
shape_choice shape_decide_hinted(const shape *k, geom_point a, geom_point b, geom_point c,
                                 geom_point d, shape_hint *h);
/* 1 when keeping hints saves K's decisions work: polygons of 3 to 255
** vertices, but for an axis-parallel square, whose bounding-box decision
** (shapes/shape_square.c) needs none and leaves *h as it is; else 0. */
int shape_wants_hints(const shape *k);
/* The vertex of polygon K extremal in the right-hand normal direction of
** PQ (P != Q), ties (PQ parallel to an edge) broken by the perturbation:
** the start vertex of an edge of the same direction as PQ. */
int shape_support(const shape *k, geom_point p, geom_point q);

/* The circumscribing shape of the anticlockwise triangle ABC (with the
** tie-break, docs/emptyshape.md): 1 when it is a homothet of polygon K, its
** contact edges (edge i joins vertices i and i + 1) of A, B, C in
** contact[]; 0 when it is the rounding shape of the corner *corner; -1 when
** no contact triple was found (never expected).  shapes/shape_sweep.c. */
int shape_circumscribe(const shape *k, geom_point a, geom_point b, geom_point c, int contact[3],
                       int *corner);

/* Calls that needed the exact (GMP) fallback, over the process (diagnostics). */
unsigned long shape_exact_calls(void);

#endif
