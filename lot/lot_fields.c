/*
** lot_fields.c: lot_stats and lot_check_result read by the names of their
** fields (lot.h), for callers that do not compile against lot.h: one table
** per structure, its rows in declaration order, read by the one reader of
** geom_field_internal.h.  A field added to either structure needs its row
** here; python/tests/test_layout.py compares the tables with what the
** compiler made of lot.h.
*/
#include <stdlib.h>
#include "lot.h"
#include "geom_field_internal.h"

_Static_assert(sizeof(lot_status) == sizeof(int), "lot_status is read as an int");

#define S(M, T) GEOM_FIELD(lot_stats, M, GEOM_FIELD_##T)
static const geom_field lot_stats_fields[] = {
  S(n, SIZE), S(distinct, SIZE), S(duplicates, SIZE), S(hull, SIZE), S(triangles, SIZE),
  S(flips, U64), S(status, INT), S(cycle_length, U64), S(cycle_quads, SIZE),
  S(cycle_quad, U32), S(max_flips, U64), S(seconds_init, DOUBLE), S(seconds_flip, DOUBLE),
  S(segments, SIZE), S(constrained, SIZE), S(segments_merged, SIZE), S(segments_split, SIZE),
  S(segments_removed, SIZE), S(holes, SIZE), S(removed, SIZE), S(redundant, SIZE),
  S(rounds, SIZE)};
#undef S

#define C(M, T) GEOM_FIELD(lot_check_result, M, GEOM_FIELD_##T)
static const geom_field lot_check_result_fields[] = {
  C(interior_edges, SIZE), C(boundary_edges, SIZE), C(decided, SIZE), C(not_optimal, SIZE),
  C(bad_edge, U32), C(valid, INT), C(segments_missing, SIZE), C(missing_segment, SIZE)};
#undef C

#define LOT_NFIELDS(t) (sizeof t / sizeof *t)

const char *lot_stats_field(size_t i) {
  return i < LOT_NFIELDS(lot_stats_fields) ? lot_stats_fields[i].name : NULL;
}

int lot_stats_get_u64(const lot_stats *s, const char *name, size_t i, uint64_t *out) {
  return geom_field_u64(s, geom_field_find(lot_stats_fields, LOT_NFIELDS(lot_stats_fields),
                                           name), i, out);
}

int lot_stats_get_double(const lot_stats *s, const char *name, double *out) {
  return geom_field_double(s, geom_field_find(lot_stats_fields,
                                              LOT_NFIELDS(lot_stats_fields), name), out);
}

lot_check_result *lot_check_result_new(void) {
  return calloc(1, sizeof(lot_check_result));
}

void lot_check_result_free(lot_check_result *c) {
  free(c);
}

const char *lot_check_result_field(size_t i) {
  return i < LOT_NFIELDS(lot_check_result_fields) ? lot_check_result_fields[i].name : NULL;
}

int lot_check_result_get_u64(const lot_check_result *c, const char *name, size_t i,
                             uint64_t *out) {
  return geom_field_u64(c, geom_field_find(lot_check_result_fields,
                                           LOT_NFIELDS(lot_check_result_fields), name), i, out);
}
