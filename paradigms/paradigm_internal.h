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

/* The incremental variants of 2.3 (paradigms/incremental.c): lot's
** insertion in the bucket orders of figure 2.8; Watson's cavity insertion
** located by a walk, and by the history DAG. */
FLIPLAB_INTERNAL
int paradigm_incr_serpentine(const paradigm_input *in, paradigm_output *out, char *err,
                             size_t errlen);
FLIPLAB_INTERNAL
int paradigm_incr_spiral(const paradigm_input *in, paradigm_output *out, char *err,
                         size_t errlen);
FLIPLAB_INTERNAL
int paradigm_incr_quaternary(const paradigm_input *in, paradigm_output *out, char *err,
                             size_t errlen);
FLIPLAB_INTERNAL
int paradigm_watson(const paradigm_input *in, paradigm_output *out, char *err, size_t errlen);
FLIPLAB_INTERNAL
int paradigm_incr_dag(const paradigm_input *in, paradigm_output *out, char *err,
                      size_t errlen);

#endif
