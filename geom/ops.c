/*
** ops.c: the names of the operation counts (ops.h) and their arithmetic.
*/
#include <string.h>
#include "ops.h"

/* One row per ops_kind, in its order: the name a table's column carries. */
static const struct {
  const char *name, *about;
} ops_rows[OPS_COUNT] = {
  {"orient", "orientation tests"},
  {"incircle", "in-circle tests"},
  {"inshape", "in-shape tests of an empty-shape rule"},
  {"exact", "tests the floating-point filter left to exact arithmetic"},
  {"flips", "edge flips"},
  {"locate", "point-location steps"},
  {"edges_made", "edges created"},
  {"edges_deleted", "edges deleted"},
  {"events", "sweep events"},
  {"buckets", "buckets examined"},
  {"peak_bytes", "most bytes of working memory held at once"},
};

void ops_clear(ops_counts *c) {
  memset(c, 0, sizeof *c);
}

void ops_merge(ops_counts *into, const ops_counts *from) {
  for (int k = 0; k < OPS_COUNT; k++) into->v[k] += from->v[k];
  into->bytes += from->bytes;
}

const char *ops_name(int k) {
  return k >= 0 && k < OPS_COUNT ? ops_rows[k].name : NULL;
}

const char *ops_about(int k) {
  return k >= 0 && k < OPS_COUNT ? ops_rows[k].about : NULL;
}

int ops_find(const char *name) {
  for (int k = 0; k < OPS_COUNT; k++)
    if (strcmp(ops_rows[k].name, name) == 0) return k;
  return -1;
}
