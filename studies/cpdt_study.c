/*
** cpdt_study.c: chapter 5's experiment (study_cpdt.h): polygons drawn by
** one sampler, triangulated by each chosen algorithm, the counts' means and
** intervals per size, and the log-log slopes of figures 5.4-5.13.
*/
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "sampler.h"
#include "study_cpdt.h"

/* A run's arguments (study_cpdt_run). */
typedef struct study_cpdt_opts {
  const uint64_t *sizes;
  size_t nsizes;
  const int *algorithms;
  size_t nalgorithms;
  uint64_t trials, seed;
  int sampler, region, law;
} study_cpdt_opts;

static const char *const study_cpdt_counts[STUDY_CPDT_NCOUNTS] = {
  "scanned", "incircle", "orient", "flips", "cross", "cross_max", "depth", "memory",
  "index_length", "seconds",
};

/* The experiment's samplers are the registry's rows (samplers/gon.c), in
** its order: one name, one home. */
int study_cpdt_sampler_count(void) { return (int)sampler_gons_count; }

const char *study_cpdt_sampler_name(int s) {
  return s >= 0 && (size_t)s < sampler_gons_count ? sampler_gons[s].name : NULL;
}

int study_cpdt_sampler_find(const char *name) {
  const sampler_gon *g = name != NULL ? sampler_gon_find(name) : NULL;
  return g != NULL ? (int)(g - sampler_gons) : -1;
}

int study_cpdt_sampler_check(int s, int region, int law, size_t n, char *err, size_t errlen) {
  const char *name = study_cpdt_sampler_name(s);
  if (name == NULL) {
    snprintf(err, errlen, "unknown sampler %d (valid: %s)", s, sampler_gon_names());
    return -1;
  }
  if (sampler_gon_check(name, region, n, err, errlen) != 0) return -1;
  if (n > CPDT_MAX_N)
    snprintf(err, errlen, "n = %zu: too many vertices (at most 2^29)", n);
  else if (sampler_gons[s].weighted)
    snprintf(err, errlen, "sampler %s weights its polygons and the experiment's means are "
             "unweighted: use valtr (the same law in the square) or naive", name);
  else
    return sampler_gon_check_variant(name, law, NULL, n, err, errlen);
  return -1;
}

const char *study_cpdt_count_name(int k) {
  return k >= 0 && k < STUDY_CPDT_NCOUNTS ? study_cpdt_counts[k] : NULL;
}

int study_cpdt_count_find(const char *name) {
  for (int k = 0; name != NULL && k < STUDY_CPDT_NCOUNTS; k++)
    if (strcmp(name, study_cpdt_counts[k]) == 0) return k;
  return -1;
}

/* The one place the experiment draws a polygon: the registry's draw of
** polygon `trial` of stream `seed`, so the same polygon as `fliplab convex
** --sampler NAME --n n --seed S` draws as its polygon `trial` (region -1:
** the square for the samplers that take one). */
int study_cpdt_polygon(int s, int region, int law, uint64_t seed, size_t n, uint64_t trial,
                       geom_point *out) {
  char err[160];
  if (study_cpdt_sampler_check(s, region, law, n, err, sizeof err) != 0) return -1;
  sampler_gon_params p = {region < 0 ? SAMPLER_REGION_SQUARE : (sampler_region)region, law,
                          NULL};
  sampler_gon_info info;
  int rc = sampler_gon_draw(&sampler_gons[s], &p, seed, trial, n, out, &info);
  return rc == SAMPLER_ENOMEM ? -2 : rc != 0 ? -1 : 0;
}

/* One run's quantities, in study_cpdt_count order. */
static void study_cpdt_values(const cpdt_counts *c, double seconds, double v[]) {
  const double x[STUDY_CPDT_NCOUNTS] = {
    (double)c->scanned, (double)c->incircle, (double)c->orient, (double)c->flips,
    (double)c->cross_sum, (double)c->cross_max, (double)c->depth, (double)c->memory,
    c->index_length, seconds,
  };
  memcpy(v, x, sizeof x);
}

/* Sums of x and x^2 into the cell, turned into means and half-widths. */
static void study_cpdt_finish(study_cpdt_cell *c, const double *sq, uint64_t trials) {
  for (int k = 0; k < STUDY_CPDT_NCOUNTS; k++) {
    double m = c->mean[k] / (double)trials;
    double var = trials > 1 ? (sq[k] - (double)trials * m * m) / (double)(trials - 1) : 0;
    c->mean[k] = m;
    c->half[k] = trials > 1 && var > 0 ? 1.96 * sqrt(var / (double)trials) : 0;
  }
}

static int study_cpdt_check_opts(const study_cpdt_opts *o, char *err, size_t errlen) {
  if (o->nsizes == 0 || o->nalgorithms == 0 || o->trials == 0) {
    snprintf(err, errlen, "no sizes, algorithms or trials");
    return -1;
  }
  for (size_t a = 0; a < o->nalgorithms; a++)
    if (cpdt_algorithm_name(o->algorithms[a]) == NULL) {
      snprintf(err, errlen, "unknown algorithm %d", o->algorithms[a]);
      return -1;
    }
  for (size_t s = 0; s < o->nsizes; s++) {
    char why[200];
    if (study_cpdt_sampler_check(o->sampler, o->region, o->law, (size_t)o->sizes[s], why,
                                 sizeof why) != 0) {
      snprintf(err, errlen, "size %llu: %s", (unsigned long long)o->sizes[s], why);
      return -1;
    }
  }
  return 0;
}

/* Polygon `trial` of size n through every algorithm into the cells' sums
** (sq: the sums of squares); tri holds 2 x 3n words. */
static int study_cpdt_trial(const study_cpdt_opts *o, size_t n, uint64_t trial, geom_point *p,
                            uint32_t *tri, study_cpdt_cell *cells, double *sq, char *err,
                            size_t errlen) {
  int rc = study_cpdt_polygon(o->sampler, o->region, o->law, o->seed, n, trial, p);
  size_t bad = 0;
  if (rc == 0) rc = cpdt_check(p, n, &bad);
  if (rc != 0) {
    snprintf(err, errlen, "polygon %llu of size %zu: %s", (unsigned long long)trial, n,
             rc == -2 ? "out of memory" : rc == -1 ? "the sampler failed" : cpdt_check_str(rc));
    return rc == -2 ? -2 : -1;
  }
  uint64_t seed = o->seed ^ GEOM_STREAM_CPDT_GON(n, trial);
  for (size_t a = 0; a < o->nalgorithms; a++) {
    cpdt_counts c;
    uint32_t *t = tri + (a > 0 ? 3 * n : 0);
    double t0 = omp_get_wtime();
    if (cpdt_triangulate(p, n, o->algorithms[a], seed, t, &c) != 0) {
      snprintf(err, errlen, "out of memory");
      return -2;
    }
    double v[STUDY_CPDT_NCOUNTS];
    study_cpdt_values(&c, omp_get_wtime() - t0, v);
    if (a > 0 && memcmp(t, tri, 3 * (n - 2) * sizeof *t) != 0) {
      snprintf(err, errlen, "%s and %s disagree on polygon %llu of size %zu",
               cpdt_algorithm_name(o->algorithms[a]), cpdt_algorithm_name(o->algorithms[0]),
               (unsigned long long)trial, n);
      return -1;
    }
    for (int k = 0; k < STUDY_CPDT_NCOUNTS; k++) {
      cells[a].mean[k] += v[k];
      sq[a * STUDY_CPDT_NCOUNTS + k] += v[k] * v[k];
    }
  }
  return 0;
}

/* Cost: for each size n, trials x (the sampler + each algorithm's cost). */
int study_cpdt_run(const uint64_t *sizes, size_t nsizes, const int *algorithms,
                   size_t nalgorithms, uint64_t trials, uint64_t seed, int sampler,
                   int region, int law, study_cpdt_cell *cells, char *err, size_t errlen) {
  const study_cpdt_opts opts = {sizes, nsizes, algorithms, nalgorithms, trials,
                                seed, sampler, region, law};
  const study_cpdt_opts *o = &opts;
  if (study_cpdt_check_opts(o, err, errlen) != 0) return -1;
  int rc = 0;
  for (size_t s = 0; s < o->nsizes && rc == 0; s++) {
    size_t n = (size_t)o->sizes[s];
    study_cpdt_cell *row = cells + s * o->nalgorithms;
    geom_point *p = malloc(n * sizeof *p);
    uint32_t *tri = malloc(6 * n * sizeof *tri);
    double *sq = calloc(o->nalgorithms * STUDY_CPDT_NCOUNTS, sizeof *sq);
    if (p == NULL || tri == NULL || sq == NULL) {
      snprintf(err, errlen, "out of memory");
      rc = -2;
    }
    for (size_t a = 0; a < o->nalgorithms; a++)
      row[a] = (study_cpdt_cell){.n = n, .algorithm = o->algorithms[a]};
    for (uint64_t t = 0; t < o->trials && rc == 0; t++)
      rc = study_cpdt_trial(o, n, t, p, tri, row, sq, err, errlen);
    for (size_t a = 0; a < o->nalgorithms && rc == 0; a++)
      study_cpdt_finish(&row[a], sq + a * STUDY_CPDT_NCOUNTS, o->trials);
    free(p);
    free(tri);
    free(sq);
  }
  return rc;
}

void study_slope_add(study_slope *s, double x, double y) {
  double a = log(x), b = log(y);
  s->sx += a, s->sy += b, s->sxx += a * a, s->sxy += a * b;
  s->k++;
}

double study_slope_get(const study_slope *s) {
  double k = (double)s->k, d = k * s->sxx - s->sx * s->sx;
  return s->k >= 2 && d > 0 ? (k * s->sxy - s->sx * s->sy) / d : NAN;
}

double study_cpdt_slope(const study_cpdt_cell *cells, size_t ncells, int algorithm, int count) {
  if (count < 0 || count >= STUDY_CPDT_NCOUNTS) return NAN;
  study_slope s = {0};
  for (size_t i = 0; i < ncells; i++)
    if (cells[i].algorithm == algorithm && cells[i].mean[count] > 0)
      study_slope_add(&s, (double)cells[i].n, cells[i].mean[count]);
  return study_slope_get(&s);
}

study_cpdt_cell *study_cpdt_cells_new(size_t ncells) {
  return calloc(ncells > 0 ? ncells : 1, sizeof(study_cpdt_cell));
}

void study_cpdt_cells_delete(study_cpdt_cell *cells) { free(cells); }

int study_cpdt_cell_get(const study_cpdt_cell *cells, size_t i, int count, double *mean,
                        double *half) {
  if (count < 0 || count >= STUDY_CPDT_NCOUNTS) return -1;
  *mean = cells[i].mean[count];
  *half = cells[i].half[count];
  return 0;
}
