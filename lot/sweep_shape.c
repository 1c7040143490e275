/*
** sweep_shape.c: the shape primitives the sweepline algorithm uses for a
** rule (sweep_internal.h): the circle for DT, the ellipse's or the
** polygon's for ES:SHAPE; a one-line refusal for every other rule.
*/
#include <stdio.h>
#include <string.h>
#include "sweep_internal.h"

int lot_sweep_pick_rule(const rule *r, lot_sweep_pick *pk, char *err, size_t errlen) {
  memset(pk, 0, sizeof *pk);
  if (rule_is_delaunay(r)) {
    pk->s = lot_sweep_circle;
    return 0;
  }
  const char *name = rule_name(r);
  if (strncmp(name, "ES:", 3) != 0) {
    snprintf(err, errlen, "the sweep algorithm makes the Delaunay triangulation or an "
             "empty-shape one: it needs rule DT or ES:SHAPE (got %s)", name);
    return -1;
  }
  if (shape_parse(name + 3, &pk->k, err, errlen) != 0) return -1;
  if (pk->k->kind == SHAPE_ELLIPSE) {
    pk->q = (lot_sweep_conic){pk->k->q11, pk->k->q12, pk->k->q22};
    lot_sweep_ellipse(&pk->q, &pk->s);
    return 0;
  }
  lot_sweep_polygon(&pk->poly, pk->k, &pk->special, &pk->s);
  return 0;
}

void lot_sweep_pick_free(lot_sweep_pick *pk) {
  shape_free(pk->k);
  pk->k = NULL;
}
