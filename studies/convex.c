/*
** convex.c: what the lab measures on random convex polygons (thesis
** section 6.8, docs/sampling.md): per polygon its area, perimeter, the
** iteration method's hull changes h, whether it is unimodal, whether its
** minimum-area and minimum-perimeter enclosing rectangles differ; over many
** polygons their weighted means with 95% intervals (rejection's weights);
** and the drawing of many polygons on all cores, each from its own stream.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "study.h"
#include "sampler.h"
#include <omp.h>

const char *const study_convex_stat_names[STUDY_CONVEX_NSTATS] = {
  "area", "perimeter", "h", "unimodal", "rect_differ"};

/* Relative tolerance of the two floating-point decisions below: squared
** distances (unimodality) and rectangle areas and perimeters (rotating
** calipers) that agree to within it count as equal.  Every quantity is a
** sum or product of a few rounded terms of the coordinates' magnitude, so
** its relative error is a small multiple of 2^-53 ~ 1.1e-16; 1e-12 leaves
** a margin of 10^3 and treats closer values as the tie they may be. */
#define STUDY_CONVEX_TOL 1e-12

static double study_dist2(geom_point a, geom_point b) {
  double dx = a.x - b.x, dy = a.y - b.y;
  return dx * dx + dy * dy;
}

/* Unimodal at vertex i: the distances from v_i to v_{i+1}, ..., v_{i-1}
** rise, then fall (one maximum, a plateau allowed; steps within the
** tolerance are flat).  O(n). */
static int study_unimodal_at(const geom_point *v, size_t n, size_t i) {
  int falling = 0;
  double prev = study_dist2(v[i], v[(i + 1) % n]);
  for (size_t j = 2; j < n; j++) {
    double d = study_dist2(v[i], v[(i + j) % n]);
    double tol = STUDY_CONVEX_TOL * (d > prev ? d : prev);
    if (d < prev - tol) falling = 1;
    else if (d > prev + tol && falling) return 0;
    prev = d;
  }
  return 1;
}

/* O(n^2): refused (NaN) above STUDY_CONVEX_UNIMODAL_MAX vertices. */
static double study_unimodal(const geom_point *v, size_t n) {
  if (n > STUDY_CONVEX_UNIMODAL_MAX) return NAN;
  for (size_t i = 0; i < n; i++)
    if (!study_unimodal_at(v, n, i)) return 0;
  return 1;
}

/* The calipers' three functions of a vertex p for the edge from a along
** u: how far ahead along u, how far behind, how far from the edge's line. */
enum { STUDY_AHEAD, STUDY_BEHIND, STUDY_AWAY };
static double study_caliper(int kind, geom_point u, geom_point a, geom_point p) {
  double dx = p.x - a.x, dy = p.y - a.y;
  return kind == STUDY_AHEAD ? u.x * dx + u.y * dy
         : kind == STUDY_BEHIND ? -(u.x * dx + u.y * dy) : u.x * dy - u.y * dx;
}

/* Move k forward while the next vertex is at least as extreme (each
** function is unimodal round a strictly convex polygon); at most n steps. */
static size_t study_advance(const geom_point *v, size_t n, size_t k, int kind, geom_point u,
                            geom_point a) {
  for (size_t t = 0; t < n; t++) {
    size_t j = (k + 1) % n;
    if (study_caliper(kind, u, a, v[j]) < study_caliper(kind, u, a, v[k])) break;
    k = j;
  }
  return k;
}

/* Rotating calipers: for each edge e (an optimal enclosing rectangle of
** either kind has a side on an edge: Freeman and Shapira for the area, the
** same argument for the perimeter) the rectangle with a side on e, its area
** and perimeter into ra[e], rp[e].  The extreme vertices move forward only
** as e does: O(n) after the first edge's O(n) scan. */
static void study_calipers(const geom_point *v, size_t n, double *ra, double *rp) {
  size_t k[3] = {0, 0, 0};
  for (size_t e = 0; e < n; e++) {
    geom_point a = v[e], b = v[(e + 1) % n], u = {b.x - a.x, b.y - a.y};
    for (int kind = 0; kind < 3; kind++) {
      if (e == 0) {   /* the first edge's extremes by a scan */
        for (size_t j = 1; j < n; j++)
          if (study_caliper(kind, u, a, v[j]) > study_caliper(kind, u, a, v[k[kind]])) k[kind] = j;
      }
      k[kind] = study_advance(v, n, k[kind], kind, u, a);
    }
    double len2 = u.x * u.x + u.y * u.y;
    double w = (study_caliper(STUDY_AHEAD, u, a, v[k[0]]) +
                study_caliper(STUDY_BEHIND, u, a, v[k[1]])) / sqrt(len2);
    double h = study_caliper(STUDY_AWAY, u, a, v[k[2]]) / sqrt(len2);
    ra[e] = w * h;
    rp[e] = 2 * (w + h);
  }
}

/* Do the two optimal rectangles differ: is no edge's rectangle optimal for
** both (within the tolerance)?  NaN when memory runs out. */
static double study_rect_differ(const geom_point *v, size_t n) {
  double *ra = malloc(2 * n * sizeof *ra);
  if (ra == NULL) return NAN;
  double *rp = ra + n, ma = INFINITY, mp = INFINITY;
  study_calipers(v, n, ra, rp);
  for (size_t e = 0; e < n; e++) {
    ma = ra[e] < ma ? ra[e] : ma;
    mp = rp[e] < mp ? rp[e] : mp;
  }
  int both = 0;
  for (size_t e = 0; e < n && !both; e++)
    both = ra[e] <= ma * (1 + STUDY_CONVEX_TOL) && rp[e] <= mp * (1 + STUDY_CONVEX_TOL);
  free(ra);
  return both ? 0 : 1;
}

void study_convex_measure(const geom_point *v, size_t n, uint64_t h,
                          double out[STUDY_CONVEX_NSTATS]) {
  double a2 = 0, per = 0;
  for (size_t i = 0; i < n; i++) {
    geom_point p = v[i], q = v[(i + 1) % n];
    a2 += (p.x - v[0].x) * (q.y - v[0].y) - (p.y - v[0].y) * (q.x - v[0].x);
    per += hypot(q.x - p.x, q.y - p.y);
  }
  out[STUDY_CONVEX_AREA] = a2 / 2;
  out[STUDY_CONVEX_PERIMETER] = per;
  out[STUDY_CONVEX_H] = (double)h;
  out[STUDY_CONVEX_UNIMODAL] = study_unimodal(v, n);
  out[STUDY_CONVEX_RECT_DIFFER] = study_rect_differ(v, n);
}

/* ---- weighted means ------------------------------------------------------
** Self-normalised importance sampling: with weights w_i (exp of the log
** weights, taken relative to the largest seen so far so that nothing
** overflows; the sums are rescaled when a larger one arrives), the mean of
** x is sum w x / sum w and its standard error is estimated by
** sqrt(sum w^2 (x - mean)^2) / sum w (the delta method; for equal weights
** the usual s / sqrt(N) up to N / (N - 1)); the interval is mean +- 1.96 se.
** The effective sample size (sum w)^2 / sum w^2 says how many equally
** weighted polygons the weights are worth.  Polygons are added in index
** order, so the sums are the same for any thread count. */
void study_convex_acc_init(study_convex_acc *a) {
  memset(a, 0, sizeof *a);
  a->ref = -INFINITY;
}

static void study_acc_rescale(study_convex_acc *a, double lw) {
  double f = exp(a->ref - lw), f2 = f * f;
  a->w *= f;
  a->w2 *= f2;
  for (int k = 0; k < STUDY_CONVEX_NSTATS; k++) {
    a->wx[k] *= f;
    a->w2x[k] *= f2;
    a->w2xx[k] *= f2;
  }
  a->ref = lw;
}

void study_convex_acc_add(study_convex_acc *a, double log_weight,
                          const double x[STUDY_CONVEX_NSTATS]) {
  if (log_weight > a->ref) study_acc_rescale(a, log_weight);
  double w = exp(log_weight - a->ref);
  a->count++;
  a->w += w;
  a->w2 += w * w;
  for (int k = 0; k < STUDY_CONVEX_NSTATS; k++) {
    if (isnan(x[k])) {
      a->missing[k]++;
      continue;
    }
    a->wx[k] += w * x[k];
    a->w2x[k] += w * w * x[k];
    a->w2xx[k] += w * w * x[k] * x[k];
  }
}

/* Statistic k's weighted mean and the half-width of its 95% interval (NaN
** when some polygon has no value, as unimodality beyond its size). */
void study_convex_acc_mean(const study_convex_acc *a, int k, double *mean, double *half) {
  if (a->count == 0 || a->missing[k] > 0 || !(a->w > 0)) {
    *mean = *half = NAN;
    return;
  }
  double m = a->wx[k] / a->w;
  double v = a->w2xx[k] - 2 * m * a->w2x[k] + m * m * a->w2;
  *mean = m;
  *half = 1.96 * sqrt(v > 0 ? v : 0) / a->w;
}

double study_convex_acc_ess(const study_convex_acc *a) {
  return a->w2 > 0 ? a->w * a->w / a->w2 : 0;
}

void study_convex_summary(const double *stats, const double *log_weight, size_t count,
                          double *mean, double *half, double *ess) {
  study_convex_acc a;
  study_convex_acc_init(&a);
  for (size_t i = 0; i < count; i++)
    study_convex_acc_add(&a, log_weight != NULL ? log_weight[i] : 0,
                         stats + i * STUDY_CONVEX_NSTATS);
  for (int k = 0; k < STUDY_CONVEX_NSTATS; k++) study_convex_acc_mean(&a, k, &mean[k], &half[k]);
  *ess = study_convex_acc_ess(&a);
}

const char *study_convex_stat_name(int k) {
  return k >= 0 && k < STUDY_CONVEX_NSTATS ? study_convex_stat_names[k] : NULL;
}

/* ---- drawing many polygons ---------------------------------------------- */

int study_convex_draw(const study_convex_run *run, uint64_t first, uint64_t count,
                      geom_point *xy, double *log_weight, uint64_t *h, double *stats,
                      uint64_t *failed) {
  const sampler_gon *s = sampler_gon_find(run->sampler);
  if (s == NULL || run->n < 3) return -1;
  sampler_gon_params p = {run->region, run->law, run->inner};
  int threads = geom_threads_clamp(run->threads, omp_get_max_threads());
  uint64_t bad = UINT64_MAX;
  int badrc = 0;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int64_t i = 0; i < (int64_t)count; i++) {
    sampler_gon_info info;
    int rc = sampler_gon_draw(s, &p, run->seed, first + (uint64_t)i, run->n,
                              xy + (size_t)i * run->n, &info);
    if (log_weight != NULL) log_weight[i] = info.log_weight;
    if (h != NULL) h[i] = info.hull_changes;
    if (stats != NULL && rc == 0)
      study_convex_measure(xy + (size_t)i * run->n, run->n, info.hull_changes,
                           stats + (size_t)i * STUDY_CONVEX_NSTATS);
#pragma omp critical(study_convex_fail)
    if (rc != 0 && (uint64_t)i < bad) {
      bad = (uint64_t)i;
      badrc = rc;
    }
  }
  if (failed != NULL) *failed = bad == UINT64_MAX ? 0 : first + bad;
  return badrc;
}
