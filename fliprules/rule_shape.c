/*
** rule_shape.c: empty-shape rules, named "ES:SPEC" (SPEC a shape of
** shapes/shape.h, docs/emptyshape.md): a whole-quadrilateral rule whose
** context is the parsed shape, registered the first time rule_parse meets
** the name and found in the registry afterwards.  The rule owns its shape,
** parsed once here: every other part asks rule_shape for it.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rule.h"
#include "shape.h"

/* The registry keeps pointers: each rule's name, description and shape
** live as long as the process (a handful per run). */
typedef struct rule_shape_entry {
  char name[RULE_NAME_MAX];
  char desc[128];
  shape *k;
} rule_shape_entry;

static const rule_choice rule_shape_choice[3] = {
  [SHAPE_AC] = RULE_AC, [SHAPE_BD] = RULE_BD, [SHAPE_EITHER] = RULE_EITHER};

static rule_choice rule_shape_eval(const geom_point q[4], void *ctx) {
  const rule_shape_entry *e = ctx;
  return rule_shape_choice[shape_decide(e->k, q[0], q[1], q[2], q[3], NULL)];
}

int rule_shape_make(const char *name, rule *out, char *err, size_t errlen) {
  rule_shape_entry *e = calloc(1, sizeof *e);
  if (e == NULL) {
    snprintf(err, errlen, "rule '%.60s': out of memory", name);
    return -1;
  }
  if (strlen(name) >= sizeof e->name) {
    snprintf(err, errlen, "rule '%.60s...': an empty-shape rule name has at most %zu characters",
             name, sizeof e->name - 1);
    free(e);
    return -1;
  }
  if (shape_parse(name + 3, &e->k, err, errlen) != 0) {
    /* A comma list of rules (--rule a,b) cuts "ellipse:2,1" at its comma. */
    if (strstr(err, "needs two coordinates") || strstr(err, "expects ellipse")) {
      size_t used = strlen(err);
      snprintf(err + used, errlen - used, " (in a comma list of rules, separate a shape's "
               "numbers by blanks: ES:ellipse:2 1)");
    }
    free(e);
    return -1;
  }
  snprintf(e->name, sizeof e->name, "%s", name);
  snprintf(e->desc, sizeof e->desc, "empty-shape rule of the shape %.90s", name + 3);
  rule_quad Q = {e->name, e->desc, rule_shape_eval, e};
  int id = rule_quad_register(&Q);
  if (id < 0) {
    snprintf(err, errlen, "rule '%.60s': no room for another quadrilateral rule (at most %d)",
             name, RULE_QUAD_MAX);
    shape_free(e->k);
    free(e);
    return -1;
  }
  /* Systematic and acyclic (docs/emptyshape.md): lot takes DT's path. */
  rule_quad_set_systematic(id);
  *out = (rule){.kind = RULE_QUAD, .measure = -1, .quad = id, .tie_eps = RULE_DEFAULT_TIE_EPS};
  snprintf(out->name, sizeof out->name, "%s", e->name);
  return 0;
}

int rule_is_shape(const rule *r) {
  const rule_quad *q = rule_quad_of(r);
  return q != NULL && q->fn == rule_shape_eval;
}

const shape *rule_shape(const rule *r) {
  return rule_is_shape(r) ? ((const rule_shape_entry *)rule_quad_of(r)->ctx)->k : NULL;
}
