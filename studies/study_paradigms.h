/*
** study_paradigms.h: table 2.4 anew (docs/paradigms.md, "Table 2.4
** anew"): every algorithm of the registry (paradigm.h) on the point
** families of `lot --random` (sampler_points) at several sizes, for
** several rules: the median time, every operation count per site, and
** the growth exponent of each (the log-log least-squares slope of the
** totals against n, study_slope_add).  An algorithm that refuses a rule
** gets its cell marked refused with its reason, one that fails (a flip
** budget run out) marked failed with its message, never skipped.
**
** The matrix is made for one problem of chapter 2 (paradigm_problem), on
** that problem's input families (study_paradigms_family_find):
**   delaunay     the point families of `lot --random` (sampler_points);
**   constrained  the same points and up to n/4 non-crossing segments on them
**                (sampler_segments, stream GEOM_STREAM_SEGMENTS: the graph of
**                `sample --sampler segments --point-sampler F --points n
**                --segments n/4`);
**   polygon      star, monotone: a simple polygon of n vertices (sampler_star,
**                sampler_monotone, stream GEOM_STREAM_GOT_POLYGON: `got
**                --random n --sampler F`'s);
**   convex       the convex n-gon samplers of chapter 6 by name (polygon 0 of
**                `convex --sampler F --n n`, study_cpdt_polygon).
** The points of (family, n) depend on (seed, family, n) alone, and the
** counts of a run on its input alone, so every count is the same on any
** machine (times are not).  Every algorithm's triangles are compared with
** those of the first that serves the rule: a disagreement is an error.
*/
#ifndef FLIPLAB_STUDY_PARADIGMS_H
#define FLIPLAB_STUDY_PARADIGMS_H

#include <stddef.h>
#include <stdint.h>
#include "ops.h"
#include "paradigm.h"
#include "rule.h"

#define STUDY_PARADIGMS_WHY 200

/* One algorithm, rule, family and size. */
typedef struct study_paradigms_cell {
  size_t algorithm;           /* its index in the registry (paradigm_get) */
  size_t rule;                /* the index of its rule in the run's rules */
  int family;                 /* an input family of the plan's problem */
  uint64_t n;                 /* points drawn (duplicates included) */
  int refused;                /* 1: the algorithm does not serve the rule; 2: it failed
                                 (its flip budget ran out ...); why says it */
  char why[STUDY_PARADIGMS_WHY];
  size_t distinct, triangles;
  double seconds;             /* the median over the runs */
  double per_site[OPS_COUNT]; /* each count over n */
} study_paradigms_cell;

/* The cell of (a, r, f, s): cells[((a * nrules + r) * nfamilies + f) * nsizes + s]. */
typedef struct study_paradigms_plan {
  const size_t *algorithms;   /* registry indices */
  size_t nalgorithms;
  const rule *rules;
  size_t nrules;
  const int *families;        /* input families of `problem` (study_paradigms_family_find) */
  size_t nfamilies;
  const uint64_t *sizes;      /* each >= 3 */
  size_t nsizes;
  int runs;                   /* timed runs per cell, 1 .. 99 */
  uint64_t seed;
  paradigm_problem problem;
} study_paradigms_plan;

/* The input family of problem pb named name, or -1; family f's name (NULL
** when there is none); every name, comma-separated, into buf (for
** messages). */
int study_paradigms_family_find(paradigm_problem pb, const char *name);
const char *study_paradigms_family_name(paradigm_problem pb, int f);
void study_paradigms_family_names(paradigm_problem pb, char *buf, size_t len);

/* Can family f of problem pb make an input of n points?  0, or -1 with a
** one-line message (a convex sampler that takes no n-gon of that size). */
int study_paradigms_family_check(paradigm_problem pb, int f, uint64_t n, char *err,
                                 size_t errlen);

size_t study_paradigms_cells(const study_paradigms_plan *pl);

/* Fill cells (study_paradigms_cells(pl) of them).  0; -1 with a one-line
** message (a bad plan, two algorithms that disagree); -2 out of memory. */
int study_paradigms_run(const study_paradigms_plan *pl, study_paradigms_cell *cells, char *err,
                        size_t errlen);

/* The growth exponent of (algorithm a, rule r, family f) over the sizes:
** the log-log slope of count k's total (k = OPS_COUNT: the time) against
** n; NAN when refused, or fewer than two positive values. */
double study_paradigms_growth(const study_paradigms_plan *pl, const study_paradigms_cell *cells,
                              size_t a, size_t r, size_t f, int k);

#endif
