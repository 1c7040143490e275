/*
** paradigm_internal.h: the algorithms the registry of paradigm.c lists,
** one paradigm_fn each (private to paradigms/).  A new algorithm adds its
** function here and its row to paradigm_algorithms in paradigm.c.
*/
#ifndef FLIPLAB_PARADIGM_INTERNAL_H
#define FLIPLAB_PARADIGM_INTERNAL_H

#include "paradigm.h"

/* lot/'s algorithms as rows (paradigms/lot_rows.c). */
FLIPLAB_INTERNAL
int paradigm_lot_incremental(const paradigm_input *in, paradigm_output *out, char *err,
                             size_t errlen);
FLIPLAB_INTERNAL
int paradigm_lot_flip(const paradigm_input *in, paradigm_output *out, char *err,
                      size_t errlen);
FLIPLAB_INTERNAL
int paradigm_lot_sweep(const paradigm_input *in, paradigm_output *out, char *err,
                       size_t errlen);

/* The rule's in-shape decision for the registry's in-shape algorithms: for
** anticlockwise a, b, c, +1 when d lies strictly inside the rule's empty
** region through a, b, c (the circumcircle for DT, the circumscribing
** homothet for ES:SHAPE), -1 strictly outside, 0 on it (then the rule's
** tie-break decides, as lot/ does).  Counted as OPS_INCIRCLE or
** OPS_INSHAPE. */
FLIPLAB_INTERNAL
int paradigm_inshape(const rule *r, ops_counts *c, geom_point a, geom_point b, geom_point d,
                     geom_point e);

/* Divide and conquer (paradigms/divide.c), Guibas and Stolfi's merge with
** vertical or alternating cuts; paradigm_divide counts into c (NULL: not
** counting, for the benchmark of the counting layer's cost). */
FLIPLAB_INTERNAL
int paradigm_divide(const paradigm_input *in, int alternating, ops_counts *c,
                    paradigm_output *out, char *err, size_t errlen);
FLIPLAB_INTERNAL
int paradigm_dc_vertical(const paradigm_input *in, paradigm_output *out, char *err,
                         size_t errlen);
FLIPLAB_INTERNAL
int paradigm_dc_alternating(const paradigm_input *in, paradigm_output *out, char *err,
                            size_t errlen);
#define PARADIGM_DC_REFUSAL \
  "ES:SHAPE: a merge trusts empty circles through its cross edges, but a polygon's LOT " \
  "has triangles with non-empty homothets, and merges would start at support-hull edges " \
  "(2.6.6); constraints: not yet (Chew's virtual sites, 2.6.2)"

#endif
