/*
** valtr.c: Valtr's uniform random convex n-gon in the square (P. Valtr,
** "Probability that n random points are in convex position", Discrete
** Comput. Geom. 13, 1995), drawn directly: the law of n independent uniform
** points of [0, 1]^2 conditioned on convex position, the law the thesis's
** weighted rejection reaches by weights (docs/sampling.md).
**
** Valtr's proof is a measure-preserving correspondence, and it is the
** algorithm: draw n x-coordinates, sorted; the smallest and largest are the
** polygon's leftmost and rightmost x; every other one goes to the upper or
** the lower chain with probability 1/2, and the chains' successive
** differences (positive along one, negative along the other) are the x
** components of the n edge vectors; the same for y, independently; pair the
** x components with a uniformly random permutation of the y components;
** sort the n vectors by direction and chain them head to tail (a convex
** polygon whose width and height are those of the drawn coordinates);
** translate it to the drawn smallest x and y.
**
** Exactness.  The coordinates are drawn on the grid 2^-53 Z in [0, 1), so
** every difference and every partial sum of them (all in (-1, 1)) is
** exact: the vectors sum to zero exactly and the vertices are the exact
** partial sums.  Directions are compared exactly (geom_orient against the
** origin), so the polygon is convex whatever n; two parallel vectors (a
** chance of about n^2 2^-54) make it not strictly convex and are drawn
** again.  O(n log n): two sorts of numbers and one of vectors.
*/
#include <stdlib.h>
#include "gon_internal.h"

static int valtr_cmp_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

/* The upper half-plane (y > 0, or y = 0 and x > 0) comes first; within a
** half, anticlockwise order by the exact sign of the cross product. */
static int valtr_half(geom_point v) {
  return v.y > 0 || (v.y == 0 && v.x > 0) ? 0 : 1;
}

static int valtr_cmp_dir(const void *a, const void *b) {
  geom_point u = *(const geom_point *)a, v = *(const geom_point *)b;
  int hu = valtr_half(u), hv = valtr_half(v);
  if (hu != hv) return hu - hv;
  return -geom_orient((geom_point){0, 0}, u, v);
}

/* n sorted uniforms of the 2^-53 grid into c, then the components of the
** two chains from c[0] to c[n-1] into d; returns c[0]. */
static double valtr_components(sampler_rng *g, size_t n, double *c, double *d) {
  for (size_t i = 0; i < n; i++) c[i] = sampler_uniform(g);
  qsort(c, n, sizeof *c, valtr_cmp_double);
  double top = c[0], bot = c[0];
  size_t m = 0;
  for (size_t i = 1; i + 1 < n; i++) {
    if (sampler_next(g) >> 63) {
      d[m++] = c[i] - top;
      top = c[i];
    } else {
      d[m++] = bot - c[i];
      bot = c[i];
    }
  }
  d[m++] = c[n - 1] - top;
  d[m++] = bot - c[n - 1];
  return c[0];
}

/* Fisher-Yates with exactly uniform indices (sampler_below). */
static void valtr_shuffle(sampler_rng *g, double *d, size_t n) {
  for (size_t i = n - 1; i > 0; i--) {
    size_t j = (size_t)sampler_below(g, i + 1);
    double t = d[i];
    d[i] = d[j];
    d[j] = t;
  }
}

static int valtr_once(sampler_rng *g, size_t n, geom_point *out, double *c, double *dx,
                      double *dy) {
  double x0 = valtr_components(g, n, c, dx);
  double y0 = valtr_components(g, n, c, dy);
  valtr_shuffle(g, dy, n);
  for (size_t i = 0; i < n; i++) out[i] = (geom_point){dx[i], dy[i]};
  qsort(out, n, sizeof *out, valtr_cmp_dir);
  double x = 0, y = 0, mx = 0, my = 0;
  for (size_t i = 0; i < n; i++) {
    geom_point e = out[i];
    out[i] = (geom_point){x, y};
    mx = x < mx ? x : mx;
    my = y < my ? y : my;
    x += e.x;
    y += e.y;
  }
  for (size_t i = 0; i < n; i++) out[i] = (geom_point){out[i].x - mx + x0, out[i].y - my + y0};
  for (size_t i = 0; i < n; i++)
    if (geom_orient(out[i], out[(i + 1) % n], out[(i + 2) % n]) <= 0) return -1;
  sampler_lexfirst(out, n);
  return 0;
}

#define VALTR_TRIES 100

int sampler_gon_valtr(sampler_rng *g, size_t n, const sampler_gon_params *p, geom_point *out,
                      sampler_gon_info *info) {
  if (n < 3 || p->region != SAMPLER_REGION_SQUARE) return -1;
  double *c = malloc(n * sizeof *c), *dx = malloc(n * sizeof *dx), *dy = malloc(n * sizeof *dy);
  int rc = c && dx && dy ? -1 : SAMPLER_ENOMEM;
  for (int t = 0; t < VALTR_TRIES && rc == -1; t++) {
    rc = valtr_once(g, n, out, c, dx, dy);
    info->draws += 2 * n;
  }
  free(c);
  free(dx);
  free(dy);
  return rc;
}
