/*
** test_got_result.c: got_options and got_result through their verbs
** (got.h, got/got_result.c), the way a binding reaches them without their
** layout.  The oracle is the structure itself: a heap got_options is the
** documented defaults, its setters write their member or refuse without
** change, and every field of a solved got_result read by name equals the
** member of that name (integers by got_result_get_i64, doubles by
** got_result_get_double, each refusing the other's, cert_why by
** got_result_get_text), the triangles by got_result_get_triangles.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "got.h"
#include "rule.h"
#include "testutil.h"

static void test_options(void **state) {
  (void)state;
  got_options *o = got_options_new();
  assert_non_null(o);
  assert_true(o->threads == 0 && o->tie_eps == RULE_DEFAULT_TIE_EPS);
  assert_int_equal(got_options_set_threads(o, -1), -1);
  assert_int_equal(got_options_set_threads(o, GEOM_MAX_THREADS + 1), -1);
  assert_int_equal(got_options_set_tie_eps(o, NAN), -1);
  assert_int_equal(got_options_set_tie_eps(o, -1), -1);
  assert_true(o->threads == 0 && o->tie_eps == RULE_DEFAULT_TIE_EPS);
  assert_int_equal(got_options_set_threads(o, GEOM_MAX_THREADS), 0);
  assert_int_equal(got_options_set_tie_eps(o, 0), 0);
  assert_true(o->threads == GEOM_MAX_THREADS && o->tie_eps == 0);
  got_options_free(o);
  got_options_free(NULL);
}

/* An integer field read by name against the member, refused as a double. */
#define TGR_I(r, M)                                                                        \
  do {                                                                                     \
    int64_t v;                                                                             \
    double d;                                                                              \
    assert_int_equal(got_result_get_i64(r, #M, &v), 0);                                    \
    assert_true(v == (int64_t)(r)->M);                                                     \
    assert_int_equal(got_result_get_double(r, #M, &d), -1);                                \
    seen++;                                                                                \
  } while (0)
#define TGR_D(r, M)                                                                        \
  do {                                                                                     \
    int64_t v;                                                                             \
    double d;                                                                              \
    assert_int_equal(got_result_get_double(r, #M, &d), 0);                                 \
    assert_true(memcmp(&d, &(r)->M, sizeof d) == 0);   /* NaN and INFINITY too */          \
    assert_int_equal(got_result_get_i64(r, #M, &v), -1);                                   \
    seen++;                                                                                \
  } while (0)

/* Every field of r by name; returns how many names were read. */
static size_t tgr_fields(const got_result *r) {
  size_t seen = 0;
  TGR_I(r, n); TGR_I(r, measure); TGR_I(r, joint); TGR_I(r, sign); TGR_D(r, key);
  TGR_D(r, total); TGR_I(r, has_runner_up); TGR_D(r, key2); TGR_D(r, total2); TGR_D(r, gap);
  TGR_D(r, rel_gap); TGR_I(r, unique); TGR_D(r, tie_eps); TGR_I(r, ntri); TGR_I(r, simple);
  TGR_D(r, cert_err); TGR_D(r, cert_err2); TGR_D(r, cert_gap); TGR_D(r, cert_bound);
  TGR_I(r, cert_unique); TGR_D(r, cert_rho); TGR_D(r, cert_alpha); TGR_D(r, seconds);
  TGR_I(r, threads);
  TGR_I(r, points); TGR_I(r, skeleton); TGR_I(r, candidates); TGR_I(r, edges);
  TGR_I(r, certain); TGR_I(r, rounds); TGR_I(r, faces); TGR_I(r, faces_left);
  TGR_I(r, faces_general); TGR_I(r, largest_face); TGR_I(r, face_states);
  TGR_D(r, seconds_candidates); TGR_D(r, seconds_lmt); TGR_D(r, seconds_faces);
  TGR_D(r, seconds_solve); TGR_D(r, seconds_delaunay);
  assert_true(got_result_get_text(r, "cert_why") == r->cert_why);
  assert_null(got_result_get_text(r, "total"));
  return seen + 2;                               /* and tri, cert_why: read by their verbs */
}

static void test_result_by_name(void **state) {
  (void)state;
  geom_point hexagon[6] = {{0, 0}, {2, 0}, {3, 1}, {2, 3}, {0, 2}, {-1, 1}};
  rule r;
  char err[256];
  assert_int_equal(rule_parse("P_1", &r, err, sizeof err), 0);
  got_options *o = got_options_new();
  got_result *res = got_result_new();
  assert_true(o != NULL && res != NULL);
  assert_int_equal(got_options_set_threads(o, 1), 0);
  assert_int_equal(got_solve(hexagon, 6, &r, o, res, err, sizeof err), 0);
  size_t k = 0;
  while (got_result_field(k) != NULL) k++;
  assert_int_equal(tgr_fields(res), k);          /* every name, and no other */
  got_result *pts = got_result_new();            /* a point set's: its statistics too */
  geom_point seven[7] = {{0, 0}, {2, 0}, {3, 1}, {2, 3}, {0, 2}, {-1, 1}, {1, 1.2}};
  assert_int_equal(got_points_solve(seven, 7, &r, o, GOT_SKELETON_ALL, pts, err, sizeof err), 0);
  assert_true(pts->points == 1 && pts->skeleton == GOT_SKELETON_ALL && pts->ntri == 6);
  assert_int_equal(tgr_fields(pts), k);
  got_result_delete(pts);
  int32_t ijk[12];
  double bad[4];
  assert_int_equal(got_result_get_triangles(res, ijk, bad), 4);
  for (size_t q = 0; q < 4; q++) {
    assert_true(ijk[3 * q] == res->tri[q].i && ijk[3 * q + 1] == res->tri[q].k);
    assert_true(ijk[3 * q + 2] == res->tri[q].j && bad[q] == res->tri[q].badness);
  }
  int64_t v;
  assert_int_equal(got_result_get_i64(res, "tri", &v), -1);
  assert_int_equal(got_result_get_i64(res, "nope", &v), -1);
  got_result_delete(res);
  got_result_delete(NULL);
  got_options_free(o);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_options),
    cmocka_unit_test(test_result_by_name),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
