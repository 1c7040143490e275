/*
** study_cpdt.h: chapter 5's experiment (docs/cpdt.md): random convex
** polygons of several sizes triangulated by the workbench's algorithms
** (cpdt.h), each count's mean over the trials with its 95% interval, and
** the slope of a count against n on log-log axes (figures 5.4-5.13).
**
** Polygon (n, trial) of seed S depends on (S, n, trial) alone; the
** randomised algorithms draw from a stream of the same triple; so every
** count is the same on any machine and thread count (times are not).
*/
#ifndef FLIPLAB_STUDY_CPDT_H
#define FLIPLAB_STUDY_CPDT_H

#include <stddef.h>
#include <stdint.h>
#include "cpdt.h"
#include "geom.h"

/* The polygon samplers the experiment draws from are the rows of the
** registry of random convex n-gons (sampler_gons, docs/sampling.md), by
** index in its order; region is a sampler_region (-1: none given, the
** square for the samplers that draw from one) and law a method's variant
** (sampler_gon_params).  study_cpdt_sampler_check: 0, or -1 with a one-line
** err (an unknown sampler, region or size, a weighted sampler: the means
** are unweighted).  study_cpdt_polygon is the one place a polygon is
** drawn: polygon `trial` of n vertices of stream `seed`, the registry's
** polygon `trial` (sampler_gon_draw, the same as `fliplab convex --sampler
** NAME --n n --seed seed` draws); 0; -1 when the sampler cannot make the
** n-gon; -2 out of memory. */
int study_cpdt_sampler_count(void);
const char *study_cpdt_sampler_name(int sampler);
int study_cpdt_sampler_find(const char *name);   /* -1 if unknown */
int study_cpdt_sampler_check(int sampler, int region, int law, size_t n, char *err,
                             size_t errlen);
int study_cpdt_polygon(int sampler, int region, int law, uint64_t seed, size_t n, uint64_t trial,
                       geom_point *out);

/* The quantities of one run: cpdt_counts' fields, then its time. */
typedef enum study_cpdt_count {
  STUDY_CPDT_SCANNED, STUDY_CPDT_INCIRCLE, STUDY_CPDT_ORIENT, STUDY_CPDT_FLIPS,
  STUDY_CPDT_CROSS, STUDY_CPDT_CROSS_MAX, STUDY_CPDT_DEPTH, STUDY_CPDT_MEMORY,
  STUDY_CPDT_INDEX_LENGTH, STUDY_CPDT_SECONDS, STUDY_CPDT_NCOUNTS
} study_cpdt_count;
const char *study_cpdt_count_name(int count);    /* "scanned", ..., "seconds" */
int study_cpdt_count_find(const char *name);     /* -1 if unknown */

/* One size and algorithm: each quantity's mean over the trials and the
** half-width of its 95% interval (1.96 s / sqrt(trials), s the sample
** standard deviation; 0 for one trial). */
typedef struct study_cpdt_cell {
  uint64_t n;
  int algorithm;
  double mean[STUDY_CPDT_NCOUNTS], half[STUDY_CPDT_NCOUNTS];
} study_cpdt_cell;

/* cells[s * nalgorithms + a] for sizes[s] and algorithms[a], over trials
** polygons of each size from `sampler` (with region and law).  Every polygon is checked
** (cpdt_check) and its triangulation by each algorithm compared with the
** first algorithm's.  0; -1 with a one-line message in err for bad
** arguments, a sampler's failure or a disagreement; -2 out of memory. */
int study_cpdt_run(const uint64_t *sizes, size_t nsizes, const int *algorithms,
                   size_t nalgorithms, uint64_t trials, uint64_t seed, int sampler,
                   int region, int law, study_cpdt_cell *cells, char *err, size_t errlen);

/* For bindings: cells on the heap (zeroed; NULL when memory ran out), and
** cell i's mean and half-width of one quantity (0, or -1 for a bad count). */
study_cpdt_cell *study_cpdt_cells_new(size_t ncells);
void study_cpdt_cells_delete(study_cpdt_cell *cells);
int study_cpdt_cell_get(const study_cpdt_cell *cells, size_t i, int count, double *mean,
                        double *half);

/* The least-squares slope of log(mean[count]) against log(n) over the cells
** of `algorithm` whose mean is positive; NaN with fewer than two. */
double study_cpdt_slope(const study_cpdt_cell *cells, size_t ncells, int algorithm, int count);
/* A least-squares slope of log y against log x, point by point (also the
** benchmarks'): start from a zeroed study_slope, add positive (x, y), read
** the slope (NAN with fewer than two points or all x equal). */
typedef struct study_slope { double sx, sy, sxx, sxy; size_t k; } study_slope;
void study_slope_add(study_slope *s, double x, double y);
double study_slope_get(const study_slope *s);

#endif
