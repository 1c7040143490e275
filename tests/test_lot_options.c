/*
** test_lot_options.c: lot_options, lot_stats and lot_check_result through
** their verbs (lot.h; lot/lot_options.c, lot/lot_fields.c), the way a
** binding reaches them without their layout.
**
** The oracle is the structure itself, read by its members: a heap
** lot_options is lot_options_init's, each setter writes its member or
** refuses and leaves the structure as it was, and every field read by name
** equals the member of that name, on a constrained run with a duplicate, a
** split and a merged segment, and on a check that fails (bad_edge set).
** lot_options_check refuses the combinations a run would silently ignore,
** in one line that names the fields and no flag of the program.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lot.h"
#include "rule.h"
#include "testutil.h"

static void test_options_new_and_setters(void **state) {
  (void)state;
  rule r = rule_delaunay();
  lot_options want, *o = lot_options_new(&r);
  assert_non_null(o);
  lot_options_init(&want, &r);
  assert_memory_equal(o, &want, sizeof want);
  assert_int_equal(lot_options_set_algorithm(o, LOT_SWEEP + 1), -1);
  assert_int_equal(lot_options_set_algorithm(o, -1), -1);
  assert_int_equal(lot_options_set_order(o, LOT_ORDER_RANDOM + 1), -1);
  assert_int_equal(lot_options_set_tie_eps(o, NAN), -1);
  assert_int_equal(lot_options_set_tie_eps(o, -1e-3), -1);
  assert_int_equal(lot_options_set_tie_eps(o, INFINITY), -1);
  assert_memory_equal(o, &want, sizeof want);           /* refusals change nothing */
  uint32_t seg[2] = {0, 1};
  geom_point hole = {0.5, 0.5};
  assert_int_equal(lot_options_set_algorithm(o, LOT_FLIP), 0);
  assert_int_equal(lot_options_set_order(o, LOT_ORDER_INPUT), 0);
  assert_int_equal(lot_options_set_tie_eps(o, 0.25), 0);
  lot_options_set_seed(o, 99);
  lot_options_set_max_flips(o, UINT64_MAX);
  lot_options_set_segments(o, seg, 1);
  lot_options_set_holes(o, &hole, 1);
  lot_options_set_keep_hull(o, 5);
  assert_true(o->algorithm == LOT_FLIP && o->order == LOT_ORDER_INPUT && o->tie_eps == 0.25);
  assert_true(o->seed == 99 && o->max_flips == UINT64_MAX && o->keep_hull == 1);
  assert_true(o->segments == seg && o->nsegments == 1 && o->holes == &hole && o->nholes == 1);
  lot_options_free(o);
  lot_options_free(NULL);
}

/* lot_options_check on o: 0, or the message's first words must be want. */
static void tlo_check(const lot_options *o, const char *want) {
  char err[256];
  int rc = lot_options_check(o, err, sizeof err);
  if (want == NULL) {
    assert_int_equal(rc, 0);
    return;
  }
  assert_int_equal(rc, -1);
  if (strncmp(err, want, strlen(want)) != 0) fail_msg("got '%s', want '%s'", err, want);
  assert_null(strstr(err, "--"));
  assert_null(strchr(err, '\n'));
}

static void test_options_check(void **state) {
  (void)state;
  rule r = rule_delaunay();
  lot_options o;
  lot_options_init(&o, &r);
  tlo_check(&o, NULL);
  o.algorithm = LOT_FLIP;
  tlo_check(&o, NULL);                                  /* the default order: no refusal */
  o.order = LOT_ORDER_RANDOM;
  tlo_check(&o, "order applies to algorithm 'incremental' only");
  o.algorithm = LOT_INCREMENTAL;
  tlo_check(&o, NULL);
  o.keep_hull = 1;
  tlo_check(&o, "keep_hull applies to constrained runs");
  geom_point hole = {0, 0};
  o.holes = &hole;                                      /* an empty array is given */
  tlo_check(&o, NULL);
  o.tie_eps = NAN;
  tlo_check(&o, "tie_eps: expected a finite number >= 0");
  o.tie_eps = 0;
  o.order = (lot_order)7;
  tlo_check(&o, "order: no such order");
}

/* A field of lot_stats read by name against the member. */
#define TLO_U(s, M)                                                                        \
  do {                                                                                     \
    uint64_t v;                                                                            \
    assert_int_equal(lot_stats_get_u64(s, #M, 0, &v), 0);                                  \
    assert_true(v == (uint64_t)(s)->M);                                                    \
    seen++;                                                                                \
  } while (0)

/* Every lot_stats field by name equals its member; returns how many. */
static size_t tlo_stats_fields(const lot_stats *s) {
  size_t seen = 0;
  TLO_U(s, n); TLO_U(s, distinct); TLO_U(s, duplicates); TLO_U(s, hull); TLO_U(s, triangles);
  TLO_U(s, flips); TLO_U(s, status); TLO_U(s, cycle_length); TLO_U(s, cycle_quads);
  TLO_U(s, max_flips); TLO_U(s, segments); TLO_U(s, constrained); TLO_U(s, segments_merged);
  TLO_U(s, segments_split); TLO_U(s, segments_removed); TLO_U(s, holes); TLO_U(s, removed);
  TLO_U(s, redundant); TLO_U(s, rounds);
  for (size_t i = 0; i < 4 * LOT_CYCLE_QUADS; i++) {
    uint64_t v;
    assert_int_equal(lot_stats_get_u64(s, "cycle_quad", i, &v), 0);
    assert_true(v == s->cycle_quad[i / 4][i % 4]);
  }
  double d;
  assert_int_equal(lot_stats_get_double(s, "seconds_init", &d), 0);
  assert_true(d == s->seconds_init);
  assert_int_equal(lot_stats_get_double(s, "seconds_flip", &d), 0);
  assert_true(d == s->seconds_flip);
  return seen + 3;
}

static void test_stats_by_name(void **state) {
  (void)state;
  /* a square with a square hole and a segment through a point, one duplicate */
  geom_point p[] = {{0, 0}, {8, 0}, {8, 8}, {0, 8}, {3, 3}, {5, 3}, {5, 5}, {3, 5},
                    {1, 1}, {7, 7}, {4, 1}, {2, 1}, {1, 1}};
  uint32_t seg[] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 8, 10, 0, 1};
  geom_point hole = {4, 4};
  rule r;
  char err[256];
  assert_int_equal(rule_parse("P_1", &r, err, sizeof err), 0);
  lot_options *o = lot_options_new(&r);
  lot_options_set_segments(o, seg, 10);
  lot_options_set_holes(o, &hole, 1);
  lot *L;
  assert_int_equal(lot_build(&L, p, 13, o, err, sizeof err), 0);
  const lot_stats *s = lot_get_stats(L);
  assert_true(s->duplicates == 1 && s->segments_split == 1 && s->segments_merged == 1);
  size_t k = 0;
  while (lot_stats_field(k) != NULL) k++;
  assert_int_equal(tlo_stats_fields(s), k);       /* every name, and no other */
  uint64_t v;
  double d;
  assert_int_equal(lot_stats_get_u64(s, "seconds_init", 0, &v), -1);   /* a time */
  assert_int_equal(lot_stats_get_double(s, "flips", &d), -1);          /* a count */
  assert_int_equal(lot_stats_get_u64(s, "n", 1, &v), -1);              /* no element 1 */
  assert_int_equal(lot_stats_get_u64(s, "cycle_quad", 4 * LOT_CYCLE_QUADS, &v), -1);
  assert_int_equal(lot_stats_get_u64(s, "nope", 0, &v), -1);
  assert_int_equal(lot_stats_get_u64(s, NULL, 0, &v), -1);
  lot_free(L);
  lot_options_free(o);
}

static void test_check_result_by_name(void **state) {
  (void)state;
  /* a square's two triangles on the diagonal DT does not keep: not optimal */
  geom_point p[] = {{0, 0}, {4, 0}, {5, 3}, {0, 1}};
  uint32_t tri[] = {0, 1, 2, 0, 2, 3};
  rule r = rule_delaunay();
  lot_check_result *c = lot_check_result_new();
  assert_non_null(c);
  assert_int_equal(lot_check(p, 4, tri, 2, &r, c), 0);
  assert_true(c->valid && c->not_optimal == 1);
  const uint64_t want[] = {c->interior_edges, c->boundary_edges, c->decided, c->not_optimal,
                           c->bad_edge[0], c->bad_edge[1], (uint64_t)c->valid,
                           c->segments_missing, c->missing_segment};
  const char *name[] = {"interior_edges", "boundary_edges", "decided", "not_optimal",
                        "bad_edge", "bad_edge", "valid", "segments_missing", "missing_segment"};
  for (size_t i = 0, e = 0; i < sizeof want / sizeof *want; i++) {
    uint64_t v;
    e = i == 5;                                         /* bad_edge's second end */
    assert_int_equal(lot_check_result_get_u64(c, name[i], e, &v), 0);
    assert_true(v == want[i]);
  }
  size_t k = 0;
  while (lot_check_result_field(k) != NULL) k++;
  assert_int_equal(k, 8);
  lot_check_result_free(c);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_options_new_and_setters),
    cmocka_unit_test(test_options_check),
    cmocka_unit_test(test_stats_by_name),
    cmocka_unit_test(test_check_result_by_name),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
