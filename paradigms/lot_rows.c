/*
** lot_rows.c: lot/'s incremental, flip and sweep algorithms as rows of the
** registry, so that every new algorithm is compared with them on equal
** terms.  lot/ counts its own operations through ops.h (lot_options.ops).
*/
#include <stdio.h>
#include <stdlib.h>
#include "paradigm_internal.h"
#include "lot.h"

/* Build with lot, then copy its triangles and statistics.  A simple
** polygon: its sides as segments, the outside removed (keep_hull 0). */
static int paradigm_lot_run(const paradigm_input *in, lot_algorithm alg, paradigm_output *out,
                            char *err, size_t errlen) {
  lot_options o;
  lot_options_init(&o, in->r);
  o.algorithm = alg;
  o.seed = in->seed;
  o.ops = &out->ops;
  if (in->problem == PARADIGM_CONSTRAINED) {
    o.segments = in->segments;
    o.nsegments = in->nsegments;
    o.keep_hull = 1;
  }
  uint32_t *sides = NULL;
  int ccw;
  if (in->problem == PARADIGM_POLYGON) {
    if (paradigm_polygon_sides(in, &sides, &ccw, err, errlen) != 0) return -1;
    o.segments = sides, o.nsegments = in->n, o.keep_hull = 0;
  }
  lot *L = NULL;
  int rc = lot_build(&L, in->p, in->n, &o, err, errlen);
  free(sides);
  return rc != 0 ? -1 : paradigm_lot_take(L, out, err, errlen);
}

/* A lot that did not converge is no LOT: for DT and ES only the flip budget
** stops the flips (an order that makes about n^2 of them, section 2.3). */
int paradigm_lot_take(lot *L, paradigm_output *out, char *err, size_t errlen) {
  const lot_stats *st = lot_get_stats(L);
  if (st->status != LOT_CONVERGED) {
    snprintf(err, errlen, "the flip budget (%llu flips) ran out: this order makes about n^2 "
             "flips on these points (section 2.3)", (unsigned long long)st->max_flips);
    lot_free(L);
    return -1;
  }
  out->ntri = st->triangles;
  out->tri = malloc((out->ntri ? out->ntri : 1) * 3 * sizeof *out->tri);
  if (out->tri == NULL) {
    snprintf(err, errlen, "out of memory for %zu triangles", st->triangles);
    lot_free(L);
    return -1;
  }
  lot_get_triangles(L, out->tri);
  lot_free(L);
  return 0;
}

int paradigm_lot_incremental(const paradigm_input *in, paradigm_output *out, char *err,
                             size_t errlen) {
  return paradigm_lot_run(in, LOT_INCREMENTAL, out, err, errlen);
}

int paradigm_lot_flip(const paradigm_input *in, paradigm_output *out, char *err,
                      size_t errlen) {
  return paradigm_lot_run(in, LOT_FLIP, out, err, errlen);
}

int paradigm_lot_sweep(const paradigm_input *in, paradigm_output *out, char *err,
                       size_t errlen) {
  return paradigm_lot_run(in, LOT_SWEEP, out, err, errlen);
}
