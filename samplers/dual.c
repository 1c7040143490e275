/*
** dual.c: the dual methods (thesis section 6.7): the polar dual of another
** sampler's polygon, and Dual Rejection.
**
** Polar dual.  About a point c strictly inside a convex polygon, the edge
** from p_i to p_{i+1} lies on the line {x : (x - c) . q_i = 1} with
**   q_i = (b.y - a.y, a.x - b.x) / cross(a, b),  a = p_i - c, b = p_{i+1} - c
** (cross(a, b) > 0 because c is inside), and the q_i, in order, are the
** vertices of the dual polygon (about the origin): a convex n-gon again,
** vertices for edges.  Computed as cross(a, Q - P) and Q - P from the
** vertices themselves: a and b are nearly parallel when the edge is short
** (a 10^6-gon's edges are 10^-6 of its size), and cross(a, b) would lose
** six digits to cancellation, more than the dual's turns can spare.  The
** centre is the mean of the vertices, strictly inside any strictly convex
** polygon in exact arithmetic; each cross(a, b) is checked positive
** exactly (geom_orient(c, p_i, p_{i+1})), and the result by
** sampler_gon_canon.  A draw that rounding spoils is drawn again, at most
** 10 times (the dual of a vector 10^6-gon fails about half the time: its
** shortest edges become turns too small for doubles).  O(n) beyond the
** inner sampler.
**
** Dual Rejection.  n half-planes {x : x . u < r}, u a uniform direction and
** r uniform in (0, 1] (so the boundary line meets the unit disc and the
** half-plane contains the origin); their intersection is an n-gon exactly
** when the dual points q = u / r, sorted by angle about the origin, form a
** strictly convex polygon with the origin strictly inside (then each is a
** hull vertex and the intersection is bounded): that is checked exactly,
** and the intersection is the polar dual of those points about the origin.
** Otherwise all n half-planes are drawn again.  O(n log n) a draw (the
** sort); the acceptance rate falls fast with n (docs/sampling.md), so the
** sampler gives up (-1) after SAMPLER_DUALREJ_DRAWS half-planes.
*/
#include <math.h>
#include <stdlib.h>
#include "sampler.h"

#define DUAL_TRIES 10
#define DUAL_2PI 6.28318530717958647693

/* out = the polar dual of p about c; 0, or -1 when c is not strictly inside
** or rounding spoilt the result. */
static int dual_polar(const geom_point *p, size_t n, geom_point c, geom_point *out) {
  for (size_t i = 0; i < n; i++) {
    geom_point P = p[i], Q = p[(i + 1) % n];
    if (geom_orient(c, P, Q) <= 0) return -1;
    double ax = P.x - c.x, ay = P.y - c.y, ex = Q.x - P.x, ey = Q.y - P.y;
    double d = ax * ey - ay * ex;   /* cross(a, b) = cross(a, Q - P): no cancellation */
    out[i] = (geom_point){ey / d, -ex / d};
  }
  return sampler_gon_canon(out, n, NULL);
}

int sampler_gon_polar(const geom_point *p, size_t n, geom_point *out) {
  geom_point c = {0, 0};
  if (n < 3) return -1;
  for (size_t i = 0; i < n; i++) c.x += p[i].x, c.y += p[i].y;
  c.x /= (double)n;
  c.y /= (double)n;
  return dual_polar(p, n, c, out);
}

int sampler_gon_dual(sampler_rng *g, size_t n, const sampler_gon_params *p, geom_point *out,
                     sampler_gon_info *info) {
  const sampler_gon *inner = sampler_gon_inner(p != NULL ? p->inner : NULL);
  if (inner == NULL || n < 3) return -1;
  geom_point *q = malloc(n * sizeof *q);
  if (q == NULL) return SAMPLER_ENOMEM;
  int rc = -1;
  for (int t = 0; t < DUAL_TRIES && rc == -1; t++) {
    rc = inner->draw(g, n, p, q, info);
    if (rc == 0) rc = sampler_gon_polar(q, n, out);
  }
  free(q);
  return rc;
}

typedef struct dual_pt { double angle; geom_point q; } dual_pt;

static int dual_pt_cmp(const void *a, const void *b) {
  double x = ((const dual_pt *)a)->angle, y = ((const dual_pt *)b)->angle;
  return x < y ? -1 : x > y;
}

/* One draw of n half-planes; 0 when their intersection is an n-gon (into
** out), else -1. */
static int dual_rej_once(sampler_rng *g, size_t n, dual_pt *d, geom_point *q, geom_point *out) {
  for (size_t i = 0; i < n; i++) {
    double th = DUAL_2PI * sampler_uniform(g), r = 1 - sampler_uniform(g);   /* (0, 1] */
    d[i].q = (geom_point){cos(th) / r, sin(th) / r};
    d[i].angle = atan2(d[i].q.y, d[i].q.x);
  }
  qsort(d, n, sizeof *d, dual_pt_cmp);
  for (size_t i = 0; i < n; i++) q[i] = d[i].q;
  size_t bad;
  int rev;
  if (geom_polygon_check(q, n, &bad, &rev) != GEOM_OK || rev) return -1;
  return dual_polar(q, n, (geom_point){0, 0}, out);
}

int sampler_gon_dualrej(sampler_rng *g, size_t n, const sampler_gon_params *p, geom_point *out,
                        sampler_gon_info *info) {
  (void)p;
  if (info != NULL) *info = (sampler_gon_info){0, 0, 0};
  if (n < 3) return -1;
  dual_pt *d = malloc(n * sizeof *d);
  geom_point *q = malloc(n * sizeof *q);
  int rc = d != NULL && q != NULL ? -1 : SAMPLER_ENOMEM;
  uint64_t drawn = 0;
  while (rc == -1 && drawn + n <= SAMPLER_DUALREJ_DRAWS) {
    rc = dual_rej_once(g, n, d, q, out);
    drawn += n;
  }
  if (info != NULL) info->draws = drawn;
  free(d);
  free(q);
  return rc;
}
