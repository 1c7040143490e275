/*
** got_result.c: got_options and got_result through verbs (got.h), for
** callers that do not compile against got.h (the Python package: no
** mirror of either layout, docs/python.md "How the package talks to the
** library").  got_result is read by the names of its fields, from a table
** in declaration order and the one reader of geom_field_internal.h.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "got.h"
#include "geom_field_internal.h"

_Static_assert(sizeof(joint_id) == sizeof(int), "joint_id is read as an int");

#define G(M, T) GEOM_FIELD(got_result, M, GEOM_FIELD_##T)
static const geom_field got_result_fields[] = {
  G(n, SIZE), G(measure, INT), G(joint, INT), G(sign, INT), G(key, DOUBLE), G(total, DOUBLE),
  G(has_runner_up, INT), G(key2, DOUBLE), G(total2, DOUBLE), G(gap, DOUBLE),
  G(rel_gap, DOUBLE), G(unique, INT), G(tie_eps, DOUBLE),
  G(tri, OTHER),       /* got_result_get_triangles */
  G(ntri, SIZE), G(simple, INT), G(cert_err, DOUBLE), G(cert_err2, DOUBLE),
  G(cert_gap, DOUBLE), G(cert_bound, DOUBLE), G(cert_unique, INT),
  G(cert_why, OTHER),  /* got_result_get_text */
  G(cert_rho, DOUBLE), G(cert_alpha, DOUBLE), G(seconds, DOUBLE), G(threads, INT),
  G(points, INT), G(skeleton, INT), G(candidates, SIZE), G(edges, SIZE), G(certain, SIZE),
  G(rounds, SIZE),
  G(faces, SIZE), G(faces_left, SIZE), G(faces_general, SIZE), G(largest_face, SIZE),
  G(face_states, SIZE), G(seconds_candidates, DOUBLE), G(seconds_lmt, DOUBLE),
  G(seconds_faces, DOUBLE), G(seconds_solve, DOUBLE), G(seconds_delaunay, DOUBLE)};
#undef G
#define GOT_NFIELDS (sizeof got_result_fields / sizeof *got_result_fields)

got_options *got_options_new(void) {
  got_options *o = malloc(sizeof *o);
  if (o != NULL) *o = (got_options){0, RULE_DEFAULT_TIE_EPS};
  return o;
}

void got_options_free(got_options *o) {
  free(o);
}

int got_options_set_threads(got_options *o, int threads) {
  if (geom_threads_check(threads, NULL, 0) != 0) return -1;
  o->threads = threads;
  return 0;
}

int got_options_set_tie_eps(got_options *o, double tie_eps) {
  if (!(isfinite(tie_eps) && tie_eps >= 0)) return -1;
  o->tie_eps = tie_eps;
  return 0;
}

got_result *got_result_new(void) {
  return calloc(1, sizeof(got_result));
}

void got_result_delete(got_result *res) {
  got_result_free(res);
  free(res);
}

const char *got_result_field(size_t i) {
  return i < GOT_NFIELDS ? got_result_fields[i].name : NULL;
}

static const geom_field *got_result_row(const char *name) {
  return geom_field_find(got_result_fields, GOT_NFIELDS, name);
}

int got_result_get_i64(const got_result *res, const char *name, int64_t *out) {
  return geom_field_i64(res, got_result_row(name), 0, out);
}

int got_result_get_double(const got_result *res, const char *name, double *out) {
  return geom_field_double(res, got_result_row(name), out);
}

const char *got_result_get_text(const got_result *res, const char *name) {
  return name != NULL && strcmp(name, "cert_why") == 0 ? res->cert_why : NULL;
}

size_t got_result_get_triangles(const got_result *res, int32_t *ijk, double *bad) {
  for (size_t q = 0; q < res->ntri; q++) {
    ijk[3 * q] = res->tri[q].i;
    ijk[3 * q + 1] = res->tri[q].k;
    ijk[3 * q + 2] = res->tri[q].j;
    bad[q] = res->tri[q].badness;
  }
  return res->ntri;
}
