/*
** lot_options.c: lot_options made, set and checked by verbs (lot.h), for
** callers that do not compile against lot.h and so cannot be trusted with
** its layout: the Python package sets a run's options through these and
** asks lot_options_check which options go together, instead of mirroring
** the structure and restating the program's rules (docs/python.md, "How
** the package talks to the library").
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "lot.h"

lot_options *lot_options_new(const rule *r) {
  lot_options *o = malloc(sizeof *o);
  if (o != NULL) lot_options_init(o, r);
  return o;
}

void lot_options_free(lot_options *o) {
  free(o);
}

int lot_options_set_algorithm(lot_options *o, int algorithm) {
  if (algorithm < LOT_INCREMENTAL || algorithm > LOT_SWEEP) return -1;
  o->algorithm = (lot_algorithm)algorithm;
  return 0;
}

int lot_options_set_order(lot_options *o, int order) {
  if (order < LOT_ORDER_SPATIAL || order > LOT_ORDER_RANDOM) return -1;
  o->order = (lot_order)order;
  return 0;
}

void lot_options_set_seed(lot_options *o, uint64_t seed) {
  o->seed = seed;
}

void lot_options_set_max_flips(lot_options *o, uint64_t max_flips) {
  o->max_flips = max_flips;
}

int lot_options_set_tie_eps(lot_options *o, double tie_eps) {
  if (!(isfinite(tie_eps) && tie_eps >= 0)) return -1;
  o->tie_eps = tie_eps;
  return 0;
}

void lot_options_set_segments(lot_options *o, const uint32_t *segments, size_t nsegments) {
  o->segments = segments;
  o->nsegments = nsegments;
}

void lot_options_set_holes(lot_options *o, const geom_point *holes, size_t nholes) {
  o->holes = holes;
  o->nholes = nholes;
}

void lot_options_set_keep_hull(lot_options *o, int keep_hull) {
  o->keep_hull = keep_hull != 0;
}

void lot_options_set_weights(lot_options *o, const double *weights) {
  o->weights = weights;
}

void lot_options_set_ops(lot_options *o, ops_counts *ops) {
  o->ops = ops;
}

int lot_options_check(const lot_options *o, char *err, size_t errlen) {
  const char *why = NULL;
  if ((int)o->algorithm < LOT_INCREMENTAL || (int)o->algorithm > LOT_SWEEP)
    why = "algorithm: no such algorithm";
  else if ((int)o->order < LOT_ORDER_SPATIAL || (int)o->order > LOT_ORDER_RANDOM)
    why = "order: no such order";
  else if (!(isfinite(o->tie_eps) && o->tie_eps >= 0))
    why = "tie_eps: expected a finite number >= 0";
  else if (o->order != LOT_ORDER_SPATIAL && o->algorithm != LOT_INCREMENTAL)
    why = "order applies to algorithm 'incremental' only (the others order the points "
          "themselves)";
  else if (o->keep_hull && o->segments == NULL && o->holes == NULL)
    why = "keep_hull applies to constrained runs (segments, holes)";
  if (why == NULL) return 0;
  snprintf(err, errlen, "%s", why);
  return -1;
}
