/*
** sweep_shape.c: the shape primitives the sweepline algorithm uses for a
** rule (sweep_internal.h): the circle for DT, the rule's own shape's for
** ES:SHAPE (the rule owns its shape: rule_shape); a one-line refusal for
** every other rule.
*/
#include <stdio.h>
#include <string.h>
#include "sweep_internal.h"

int lot_sweep_pick_rule(const rule *r, lot_sweep_pick *pk, char *err, size_t errlen) {
  memset(pk, 0, sizeof *pk);
  const shape *k = rule_shape(r);
  if (rule_is_delaunay(r)) {
    pk->s = shape_sweep_circle;
  } else if (k != NULL) {
    shape_sweep_make(k, &pk->ctx, &pk->special, &pk->s);
  } else {
    snprintf(err, errlen, "the sweep algorithm makes the Delaunay triangulation or an "
             "empty-shape one: it needs rule DT or ES:SHAPE (got %s)", rule_name(r));
    return -1;
  }
  return 0;
}
