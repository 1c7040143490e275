/*
** simplepoly.c: random simple (non-convex) polygons for `fliplab got
** --random N --sampler star|monotone`.
**
** Star.  n angles uniform in [0, 2 pi), sorted, each with a radius uniform
** in [0.2, 1]; the vertices (r cos t, r sin t) in angle order.  When every
** angular gap is below pi the polygon is star-shaped from the origin, hence
** simple; rounding can still spoil that for nearly equal angles, so every
** draw is checked exactly (geom_simple_polygon_check) and redrawn (rarely).
** Typically about half the vertices are reflex.
**
** Monotone.  The second family, far less star-like: n points uniform in the
** unit square, sorted by x; the leftmost L and the rightmost R split the
** others by the line LR (exact geom_orient): those strictly above form the
** upper chain, the rest the lower chain.  L, the lower chain left to right,
** R, the upper chain right to left is an x-monotone simple polygon,
** anticlockwise (the chains meet only at L and R), with long reflex
** "valleys" that block most diagonals.  Draws with two equal x are redrawn.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "sampler.h"

#define SAMPLER_SIMPLE_TRIES 100
#define SAMPLER_SIMPLE_2PI 6.28318530717958647693

static int sampler_double_cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static int sampler_point_x_cmp(const void *a, const void *b) {
  const geom_point *p = a, *q = b;
  if (p->x != q->x) return p->x < q->x ? -1 : 1;
  return (p->y > q->y) - (p->y < q->y);
}

/* Exactly simple and anticlockwise as drawn (a copy is checked, since the
** check may reverse). */
static int sampler_simple_ok(const geom_point *p, size_t n, geom_point *scratch) {
  memcpy(scratch, p, n * sizeof *p);
  int rev = 0;
  return geom_simple_polygon_check(scratch, n, NULL, NULL, &rev) == GEOM_OK && !rev;
}

int sampler_star(sampler_rng *g, size_t n, geom_point *out) {
  if (n < 3) return -1;
  double *t = malloc(n * sizeof *t);
  geom_point *scratch = malloc(n * sizeof *scratch);
  int rc = t != NULL && scratch != NULL ? -1 : SAMPLER_ENOMEM;
  for (int tries = 0; t && scratch && tries < SAMPLER_SIMPLE_TRIES && rc != 0; tries++) {
    for (size_t i = 0; i < n; i++) t[i] = SAMPLER_SIMPLE_2PI * sampler_uniform(g);
    qsort(t, n, sizeof *t, sampler_double_cmp);
    for (size_t i = 0; i < n; i++) {
      double r = 0.2 + 0.8 * sampler_uniform(g);
      out[i] = (geom_point){r * cos(t[i]), r * sin(t[i])};
    }
    if (sampler_simple_ok(out, n, scratch)) rc = 0;
  }
  free(t);
  free(scratch);
  return rc;
}

int sampler_monotone(sampler_rng *g, size_t n, geom_point *out) {
  if (n < 3) return -1;
  geom_point *q = malloc(n * sizeof *q), *scratch = malloc(n * sizeof *scratch);
  int rc = q != NULL && scratch != NULL ? -1 : SAMPLER_ENOMEM;
  for (int tries = 0; q && scratch && tries < SAMPLER_SIMPLE_TRIES && rc != 0; tries++) {
    for (size_t i = 0; i < n; i++) {
      double x = sampler_uniform(g);
      q[i] = (geom_point){x, sampler_uniform(g)};
    }
    qsort(q, n, sizeof *q, sampler_point_x_cmp);
    int distinct = 1;
    for (size_t i = 1; i < n; i++) distinct &= q[i].x != q[i - 1].x;
    if (!distinct) continue;
    geom_point L = q[0], R = q[n - 1];
    size_t m = 0;
    out[m++] = L;
    for (size_t i = 1; i + 1 < n; i++)
      if (geom_orient(L, R, q[i]) <= 0) out[m++] = q[i];
    out[m++] = R;
    for (size_t i = n - 1; i-- > 1;)
      if (geom_orient(L, R, q[i]) > 0) out[m++] = q[i];
    if (sampler_simple_ok(out, n, scratch)) rc = 0;
  }
  free(q);
  free(scratch);
  return rc;
}
