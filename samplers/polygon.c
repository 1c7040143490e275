/*
** polygon.c: random convex n-gons for large n (thesis sections 6.4 and a
** circle), used by `fliplab got --random N`.
**
** Vector method (section 6.4).  The edges of a convex polygon, read as
** vectors, sum to zero and are sorted by direction; conversely n vectors
** summing to zero, no two of the same direction, sorted by direction and
** chained head to tail, form a strictly convex polygon, anticlockwise.  The
** thesis draws the x components (and independently the y components) from
** the uniform distribution on the (n-1)-dimensional unit ball of the
** hyperplane sum = 0; we get the same distribution by projecting n normal
** variates onto the hyperplane (subtract their mean: an isotropic Gaussian
** stays isotropic), normalising to the sphere and scaling by u^(1/(n-1)),
** instead of the thesis's explicit orthonormal rotation.  O(n log n) for
** the sort.  In floating point the projected components sum to zero only
** up to rounding, so the last edge is the one closing the polygon; the
** result is checked exactly with geom_polygon_check and redrawn (rarely)
** when rounding spoils strict convexity, as it is for equal directions.
**
** Circle.  n random angles, sorted, on the unit circle: every triangulation
** is Delaunay in exact arithmetic.  cos and sin round, so the points are
** only cocircular up to about 1e-16: exact predicates still see a unique
** Delaunay triangulation, chosen by the rounding, while every measure ties
** to ~1e-15 (a stress case for tie handling).  Very close angles can make
** three points non-convex after rounding (the gap g needs g^2 >> 1e-16,
** so n of a few tens of thousands at most); those draws are redrawn too.
*/
#include <math.h>
#include <stdlib.h>
#include "sampler.h"

#define SAMPLER_TRIES 100
#define SAMPLER_2PI 6.28318530717958647693

typedef struct sampler_dir {
  double angle;
  double x, y;
} sampler_dir;

static int sampler_dir_cmp(const void *a, const void *b) {
  double x = ((const sampler_dir *)a)->angle, y = ((const sampler_dir *)b)->angle;
  return x < y ? -1 : x > y;
}

/* n components uniform in the unit ball of {sum = 0}. */
static int sampler_hyperplane(sampler_rng *g, size_t n, double *v) {
  double mean = 0, norm = 0;
  for (size_t i = 0; i < n; i++) mean += (v[i] = sampler_normal(g));
  mean /= (double)n;
  for (size_t i = 0; i < n; i++) {
    v[i] -= mean;
    norm += v[i] * v[i];
  }
  if (!(norm > 0)) return -1;
  double scale = pow(sampler_uniform(g), 1.0 / (double)(n - 1)) / sqrt(norm);
  for (size_t i = 0; i < n; i++) v[i] *= scale;
  return 0;
}

static int sampler_vector_once(sampler_rng *g, size_t n, geom_point *out,
                               sampler_dir *d, double *tmp) {
  if (sampler_hyperplane(g, n, tmp) != 0) return -1;
  for (size_t i = 0; i < n; i++) d[i].x = tmp[i];
  if (sampler_hyperplane(g, n, tmp) != 0) return -1;
  for (size_t i = 0; i < n; i++) {
    d[i].y = tmp[i];
    if (d[i].x == 0 && d[i].y == 0) return -1;
    d[i].angle = atan2(d[i].y, d[i].x);
  }
  qsort(d, n, sizeof *d, sampler_dir_cmp);
  for (size_t i = 1; i < n; i++)
    if (d[i].angle == d[i - 1].angle) return -1;   /* parallel edges */
  /* Chain the edges; centre the vertices on their mean. */
  double x = 0, y = 0, cx = 0, cy = 0;
  for (size_t i = 0; i < n; i++) {
    out[i] = (geom_point){x, y};
    cx += x;
    cy += y;
    x += d[i].x;
    y += d[i].y;
  }
  cx /= (double)n;
  cy /= (double)n;
  for (size_t i = 0; i < n; i++) {
    out[i].x -= cx;
    out[i].y -= cy;
  }
  size_t bad;
  int rev;
  return geom_polygon_check(out, n, &bad, &rev) == GEOM_OK && !rev ? 0 : -1;
}

int sampler_vector(sampler_rng *g, size_t n, geom_point *out) {
  if (n < 3) return -1;
  sampler_dir *d = malloc(n * sizeof *d);
  double *tmp = malloc(n * sizeof *tmp);
  int rc = d != NULL && tmp != NULL ? -1 : SAMPLER_ENOMEM;
  if (rc == -1)
    for (int t = 0; t < SAMPLER_TRIES && rc != 0; t++) rc = sampler_vector_once(g, n, out, d, tmp);
  free(d);
  free(tmp);
  return rc;
}

static int sampler_cmp_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

int sampler_circle(sampler_rng *g, size_t n, geom_point *out) {
  if (n < 3) return -1;
  double *th = malloc(n * sizeof *th);
  if (th == NULL) return SAMPLER_ENOMEM;
  int rc = -1;
  for (int t = 0; t < SAMPLER_TRIES && rc != 0; t++) {
    for (size_t i = 0; i < n; i++) th[i] = SAMPLER_2PI * sampler_uniform(g);
    qsort(th, n, sizeof *th, sampler_cmp_double);
    int dup = 0;
    for (size_t i = 1; i < n && !dup; i++) dup = th[i] == th[i - 1];
    if (dup) continue;
    for (size_t i = 0; i < n; i++) out[i] = (geom_point){cos(th[i]), sin(th[i])};
    size_t bad;
    int rev;
    rc = geom_polygon_check(out, n, &bad, &rev) == GEOM_OK && !rev ? 0 : -1;
  }
  free(th);
  return rc;
}
