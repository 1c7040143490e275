/*
** shape_ellipse.c: the empty-shape decision of an ellipse, its variant
** (shape_internal.h): one determinant, exact (shape_arith.c's program).
*/
#include "shape.h"
#include "shape_internal.h"

/* The ellipse: D inside the ellipse homothet through A, B, C when the
** determinant is positive (as the incircle test: Q = L^T L with det L > 0
** maps the ellipse to the unit circle).  The boundary case answers either,
** as DT does for cocircular sites: a smooth shape has no support ties, and
** four sites on one ellipse are the rule's genuine ties. */
static shape_choice shape_ellipse_decide(const shape *k, const geom_point p[4], shape_trace *tr) {
  shape_args g = {.K = k, .p = {p[0], p[1], p[2]}, .o = p[3]};
  int s = shape_sign(SHAPE_PROG_ELLIPSE, &g);
  if (tr) tr->level = s == 0 ? 2 : 0;
  return s > 0 ? SHAPE_BD : s < 0 ? SHAPE_AC : SHAPE_EITHER;
}

/* ---- the ellipse's variant (shape_internal.h) ---------------------------- */

static shape_choice shape_ellipse_variant_decide(const shape *k, geom_point a, geom_point b,
                                                 geom_point c, geom_point d, shape_trace *tr) {
  const geom_point p[4] = {a, b, c, d};
  return shape_ellipse_decide(k, p, tr);
}

/* An ellipse's decision is one determinant: nothing to hint. */
static shape_choice shape_ellipse_hinted(const shape *k, geom_point a, geom_point b,
                                         geom_point c, geom_point d, shape_hint *h) {
  (void)h;
  const geom_point p[4] = {a, b, c, d};
  return shape_ellipse_decide(k, p, NULL);
}

static int shape_ellipse_wants_hints(const shape *k) {
  (void)k;
  return 0;
}

const shape_ops shape_ops_ellipse = {shape_ellipse_variant_decide, shape_ellipse_hinted,
                                     shape_ellipse_wants_hints};
