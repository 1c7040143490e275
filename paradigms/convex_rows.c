/*
** convex_rows.c: chapter 5's algorithms for the Delaunay triangulation of
** a convex polygon (cpdt/) as rows of the registry (PARADIGM_CONVEX), each
** counted through cpdt_counts and reported in ops.h's terms.
*/
#include <stdio.h>
#include <stdlib.h>
#include "paradigm_internal.h"
#include "cpdt.h"

/* cpdt's counts in ops.h's terms: what both name alike. */
static void paradigm_convex_ops(const cpdt_counts *c, ops_counts *o) {
  o->v[OPS_INCIRCLE] += c->incircle;
  o->v[OPS_ORIENT] += c->orient;
  o->v[OPS_FLIPS] += c->flips;
  o->v[OPS_EDGES_MADE] += c->added;
  o->v[OPS_EDGES_DELETED] += c->deleted;
  if (c->memory > o->v[OPS_PEAK_BYTES]) o->v[OPS_PEAK_BYTES] = c->memory;
}

/* Check the polygon (strictly convex, anticlockwise: cpdt_check, O(n log
** n)), then triangulate by `alg` (its cost in cpdt.h). */
static int paradigm_convex_run(const paradigm_input *in, int alg, paradigm_output *out,
                               char *err, size_t errlen) {
  size_t bad = 0;
  int e = cpdt_check(in->p, in->n, &bad);
  if (e != 0) {
    snprintf(err, errlen, "convex polygon: vertex %zu: %s", bad + 1, cpdt_check_str(e));
    return -1;
  }
  cpdt_counts c = {0};
  out->ntri = in->n - 2;
  out->tri = malloc(3 * out->ntri * sizeof *out->tri);
  if (out->tri == NULL || cpdt_triangulate(in->p, in->n, alg, in->seed, out->tri, &c) != 0) {
    snprintf(err, errlen, "out of memory for a convex polygon of %zu vertices", in->n);
    return -1;
  }
  paradigm_convex_ops(&c, &out->ops);
  return 0;
}

#define PARADIGM_CONVEX_ROW(fn, alg)                                                       \
  int fn(const paradigm_input *in, paradigm_output *out, char *err, size_t errlen) {       \
    return paradigm_convex_run(in, alg, out, err, errlen);                                 \
  }
PARADIGM_CONVEX_ROW(paradigm_convex_circum, CPDT_CIRCUM)
PARADIGM_CONVEX_ROW(paradigm_convex_circum_random, CPDT_CIRCUM_RANDOM)
PARADIGM_CONVEX_ROW(paradigm_convex_circum_walk, CPDT_CIRCUM_WALK)
PARADIGM_CONVEX_ROW(paradigm_convex_divide, CPDT_DIVIDE)
PARADIGM_CONVEX_ROW(paradigm_convex_incremental, CPDT_INCREMENTAL)
PARADIGM_CONVEX_ROW(paradigm_convex_random, CPDT_RANDOM)
PARADIGM_CONVEX_ROW(paradigm_convex_flip, CPDT_FLIP)
PARADIGM_CONVEX_ROW(paradigm_convex_corners, CPDT_CORNERS)
