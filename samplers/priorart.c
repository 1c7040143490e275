/*
** priorart.c: the two generators of convex n-gons that the thesis measures
** its own against (section 6.1): XYZ GeoBench's radius moves and Roussille
** and Dufour's angles.
**
** GeoBench.  Corners in polar coordinates (r_i, theta_i): n angles uniform
** on [0, 2 pi), sorted, all r_i = 1 (a cyclic polygon); then n times, a
** corner i chosen uniformly gets a new radius uniform on (r_min, r_max),
** the radii along its ray at which it stays convex and keeps its two
** neighbours convex: beyond the chord p_{i-1} p_{i+1}, and within the
** lines p_{i-2} p_{i-1} and p_{i+1} p_{i+2} (thesis figure 6.1).  A line
** the ray does not cross bounds nothing; with no upper bound (a triangle,
** or a neighbour's wide angle) r_max is twice the largest radius.  The new
** corner is checked exactly against its three triples (geom_orient) and
** the move is not made when rounding spoils one.  A corner is chosen
** Binomial(n, 1/n) times, about Poisson(1): a fraction (1 - 1/n)^n ~ 1/e ~
** 37% of the corners are never moved and stay on the unit circle.  O(n log
** n) for the sort, O(1) a move.
**
** Angles (Roussille and Dufour).  Walking round the boundary, the turning
** angle at corner i is uniform on the range that leaves the remaining
** corners a total they can still take: with R of the 2 pi left and m
** corners after this one, on (max(0, R - m pi), min(pi, R)); the last
** corner takes the rest.  As the thesis says, the first few corners take
** most of the turn, and the later ones are nearly straight.  Edge lengths
** are uniform on [1/2, 1), and the two edges whose directions bracket the
** closing vector are lengthened to close the polygon (the published
** method leaves lengths open; a least-squares correction of all lengths
** goes negative from n of about 100 on, because the nearly parallel later
** edges must be balanced by the first few).  A draw spoilt by rounding
** (sampler_gon_canon) is drawn again, at most 100 times.  O(n).
*/
#include <math.h>
#include <stdlib.h>
#include "sampler.h"

#define PRIOR_PI 3.14159265358979323846
#define PRIOR_TRIES 100

static int prior_cmp_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

/* The radius at which the ray from the origin in direction u meets the
** line through P and Q, or INFINITY when it does not at a positive radius. */
static double prior_ray(geom_point u, geom_point P, geom_point Q) {
  double ex = Q.x - P.x, ey = Q.y - P.y;
  double den = ex * u.y - ey * u.x, num = ex * P.y - ey * P.x;
  double r = den != 0 ? num / den : INFINITY;
  return r > 0 ? r : INFINITY;
}

/* One radius move of corner i of p (radii r, unit directions u). */
static void prior_move(sampler_rng *g, geom_point *p, double *r, const geom_point *u, size_t n,
                       size_t i, double rbig) {
  size_t a = (i + n - 1) % n, c = (i + 1) % n, aa = (i + n - 2) % n, cc = (i + 2) % n;
  double lo = prior_ray(u[i], p[a], p[c]);
  if (!isfinite(lo)) lo = 0;
  double hi = n > 3 ? fmin(prior_ray(u[i], p[aa], p[a]), prior_ray(u[i], p[cc], p[c])) : INFINITY;
  if (!isfinite(hi)) hi = 2 * rbig;
  if (!(hi > lo)) return;
  double nr = lo + (hi - lo) * sampler_uniform(g);
  geom_point np = {nr * u[i].x, nr * u[i].y};
  if (!(nr > lo) || geom_orient(p[a], np, p[c]) <= 0) return;
  if (n > 3 && (geom_orient(p[aa], p[a], np) <= 0 || geom_orient(np, p[c], p[cc]) <= 0)) return;
  p[i] = np;
  r[i] = nr;
}

/* The cyclic polygon, then n moves.  r and th: n radii and angles. */
static int prior_geobench(sampler_rng *g, size_t n, geom_point *out, double *r, double *th,
                          geom_point *u) {
  double rbig = 1;
  for (size_t i = 0; i < n; i++) th[i] = 2 * PRIOR_PI * sampler_uniform(g);
  qsort(th, n, sizeof *th, prior_cmp_double);
  for (size_t i = 0; i < n; i++) {
    u[i] = (geom_point){cos(th[i]), sin(th[i])};
    out[i] = u[i];
    r[i] = 1;
  }
  for (size_t k = 0; k < n; k++) {
    size_t i = (size_t)sampler_below(g, n);
    prior_move(g, out, r, u, n, i, rbig);
    rbig = fmax(rbig, r[i]);
  }
  return sampler_gon_canon(out, n, NULL);
}

int sampler_gon_geobench(sampler_rng *g, size_t n, const sampler_gon_params *prm,
                         geom_point *out, sampler_gon_info *info) {
  (void)prm;
  if (info != NULL) *info = (sampler_gon_info){0, 0, n};
  if (n < 3) return -1;
  double *r = malloc(2 * n * sizeof *r);
  geom_point *u = malloc(n * sizeof *u);
  int rc = r != NULL && u != NULL ? prior_geobench(g, n, out, r, r + n, u) : SAMPLER_ENOMEM;
  free(r);
  free(u);
  return rc;
}

/* The turning angles: the exterior angle at corner i, t[i], in (0, pi),
** summing to 2 pi. */
static void prior_turns(sampler_rng *g, size_t n, double *t) {
  double left = 2 * PRIOR_PI;
  for (size_t i = 0; i + 1 < n; i++) {
    double m = (double)(n - 1 - i);
    double lo = fmax(0, left - m * PRIOR_PI), hi = fmin(PRIOR_PI, left);
    t[i] = lo + (hi - lo) * sampler_uniform(g);
    left -= t[i];
  }
  t[n - 1] = left;
}

/* Lengths for the edge directions e (anticlockwise, each turn in (0, pi),
** one full turn): uniform on [1/2, 1); then the closing vector v = -sum L_i
** e_i lies between two consecutive directions e_a, e_{a+1} (they turn by
** less than pi, all the way round), and v = alpha e_a + beta e_{a+1} with
** alpha, beta >= 0 lengthens those two edges to close the polygon.  0, or
** -1 when rounding found no such pair. */
static int prior_lengths(sampler_rng *g, size_t n, const geom_point *e, double *len) {
  double vx = 0, vy = 0;
  for (size_t i = 0; i < n; i++) {
    len[i] = 0.5 + 0.5 * sampler_uniform(g);
    vx -= len[i] * e[i].x, vy -= len[i] * e[i].y;
  }
  for (size_t a = 0; a < n; a++) {
    geom_point p = e[a], q = e[(a + 1) % n];
    double ca = p.x * vy - p.y * vx, cb = vx * q.y - vy * q.x, d = p.x * q.y - p.y * q.x;
    if (ca >= 0 && cb >= 0 && d > 0) {
      len[a] += cb / d;
      len[(a + 1) % n] += ca / d;
      return 0;
    }
  }
  return -1;
}

static int prior_angles_once(sampler_rng *g, size_t n, geom_point *out, double *t, geom_point *e) {
  double dir = 0;
  prior_turns(g, n, t);
  for (size_t i = 0; i < n; i++) {
    dir += t[i];
    e[i] = (geom_point){cos(dir), sin(dir)};
  }
  if (prior_lengths(g, n, e, t) != 0) return -1;
  geom_point at = {0, 0};
  for (size_t i = 0; i < n; i++) {
    out[i] = at;
    at.x += t[i] * e[i].x;
    at.y += t[i] * e[i].y;
  }
  return sampler_gon_canon(out, n, NULL);
}

int sampler_gon_angles(sampler_rng *g, size_t n, const sampler_gon_params *prm, geom_point *out,
                       sampler_gon_info *info) {
  (void)prm;
  if (info != NULL) *info = (sampler_gon_info){0, 0, 0};
  if (n < 3) return -1;
  double *t = malloc(n * sizeof *t);
  geom_point *e = malloc(n * sizeof *e);
  int rc = t != NULL && e != NULL ? -1 : SAMPLER_ENOMEM;
  int tries = 0;
  while (rc == -1 && tries++ < PRIOR_TRIES) rc = prior_angles_once(g, n, out, t, e);
  if (info != NULL) info->draws = (uint64_t)tries;
  free(t);
  free(e);
  return rc;
}
