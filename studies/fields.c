/*
** fields.c: the studies' results through verbs (study.h), for callers that
** do not compile against study.h (the Python package: no mirror of any
** layout).  Each result is read by the names of its fields, from one table
** per structure and the one reader of geom_field_internal.h, as lot_stats
** and got_result are; what no table row can say (the intervals, the
** witnesses, the sites, the texts, the GOT) has a verb of its own.
*/
#include <stdlib.h>
#include <string.h>
#include "study.h"
#include "geom_field_internal.h"

_Static_assert(sizeof(rule_choice) == sizeof(int), "rule_choice is read as an int");

/* A row named N for member M of structure S (N: the caller's name for a
** nested member), of elements of type T. */
#define STUDY_ROW(S, N, M, T) \
  {N, offsetof(S, M), GEOM_FIELD_##T, sizeof(((S *)0)->M) / GEOM_FIELD_BYTES(GEOM_FIELD_##T)}
#define STUDY_NROWS(t) (sizeof t / sizeof *t)

#define V(N, M, T) STUDY_ROW(study_verdict, N, M, T)
static const geom_field study_verdict_fields[] = {
  V("samples", counts.samples, U64), V("type", counts.type, U64), V("dt", counts.dt, U64),
  V("lo", lo, OTHER), V("hi", hi, OTHER),   /* study_verdict_interval */
  V("decided", decided, U64), V("systematic", systematic, INT), V("local", local, INT),
  V("sink_bug", sink_bug, INT), V("always_delaunay", always_delaunay, INT),
  V("witness", witness, OTHER)};            /* study_verdict_witness */
#undef V

#define Q(N, M, T) STUDY_ROW(study_quadcheck, N, M, T)
static const geom_field study_quadcheck_fields[] = {
  Q("tested", tested, U64), Q("disagree", disagree, U64), Q("ties", ties, U64),
  Q("cocircular", cocircular, U64), Q("decided", decided, U64),
  Q("equivalent", equivalent, INT), Q("first", first, U64), Q("q", q, OTHER),
  Q("choice", choice, INT), Q("dt", dt, INT), Q("ac", ac, DOUBLE), Q("bd", bd, DOUBLE)};
#undef Q

#define S(N, M, T) STUDY_ROW(study_sitecheck, N, M, T)
static const geom_field study_sitecheck_fields[] = {
  S("sampler", sampler, INT), S("n", n, INT), S("samples", counts.samples, U64),
  S("tie", counts.tie, U64), S("no_sink", counts.no_sink, U64),
  S("one_sink", counts.one_sink, U64), S("multi_sink", counts.multi_sink, U64),
  S("sink_dt", counts.sink_dt, U64), S("sinks", counts.sinks, U64),
  S("max_sinks", counts.max_sinks, U64), S("gap_units", counts.gap_units, U64),
  S("decided", decided, U64), S("systematic", systematic, INT),
  S("has_witness", has_witness, INT), S("witness", witness, U64),
  S("sites", sites, OTHER)};                /* study_sitecheck_sites */
#undef S

#define G(N, M, T) STUDY_ROW(study_gotcheck, N, M, T)
static const geom_field study_gotcheck_fields[] = {
  G("got", got, OTHER),                     /* study_gotcheck_got */
  G("ring", ring, INT), G("n", n, SIZE),
  G("tri", tri, OTHER),                     /* study_gotcheck_triangles */
  G("lot_key", lot_key, DOUBLE), G("lot_total", lot_total, DOUBLE),
  G("lot_text", lot_text, OTHER), G("got_text", got_text, OTHER),   /* _get_text */
  G("rel", rel, DOUBLE), G("certified", certified, INT),
  G("uncertified", uncertified, OTHER),     /* study_gotcheck_get_text */
  G("equal", equal, INT), G("below", below, INT),
  G("edges_lot", diff.edges_a, SIZE), G("edges_got", diff.edges_b, SIZE),
  G("edges_shared", diff.edges_common, SIZE), G("triangles_lot", diff.triangles_a, SIZE),
  G("triangles_got", diff.triangles_b, SIZE), G("triangles_shared", diff.triangles_common, SIZE),
  G("same", same, INT), G("got_is_cdt", got_is_cdt, INT), G("failed", failed, INT)};
#undef G

/* ---- verdicts ---- */

study_verdict *study_verdict_new(void) {
  return calloc(1, sizeof(study_verdict));
}

void study_verdict_delete(study_verdict *v) {
  free(v);
}

const char *study_verdict_field(size_t i) {
  return i < STUDY_NROWS(study_verdict_fields) ? study_verdict_fields[i].name : NULL;
}

int study_verdict_get_u64(const study_verdict *v, const char *name, size_t i, uint64_t *out) {
  return geom_field_u64(v, geom_field_find(study_verdict_fields,
                                           STUDY_NROWS(study_verdict_fields), name), i, out);
}

int study_verdict_interval(const study_verdict *v, int row, double *lo, double *hi) {
  if (row < 0 || row >= STUDY_ROWS) return -1;
  *lo = v->lo[row];
  *hi = v->hi[row];
  return 0;
}

int64_t study_verdict_witness(const study_verdict *v, int t, int k) {
  if (t < 0 || t >= FLIPGRAPH_NTYPES || k < 0 || k >= v->witness[t].n) return -1;
  return (int64_t)v->witness[t].idx[k];
}

/* ---- quadrilaterals ---- */

study_quadcheck *study_quadcheck_new(void) {
  return calloc(1, sizeof(study_quadcheck));
}

void study_quadcheck_delete(study_quadcheck *q) {
  free(q);
}

const char *study_quadcheck_field(size_t i) {
  return i < STUDY_NROWS(study_quadcheck_fields) ? study_quadcheck_fields[i].name : NULL;
}

int study_quadcheck_get_u64(const study_quadcheck *q, const char *name, size_t i,
                            uint64_t *out) {
  return geom_field_u64(q, geom_field_find(study_quadcheck_fields,
                                           STUDY_NROWS(study_quadcheck_fields), name), i, out);
}

int study_quadcheck_get_double(const study_quadcheck *q, const char *name, double *out) {
  return geom_field_double(q, geom_field_find(study_quadcheck_fields,
                                              STUDY_NROWS(study_quadcheck_fields), name), out);
}

/* ---- site sets ---- */

study_sitecheck *study_sitecheck_new(void) {
  return calloc(1, sizeof(study_sitecheck));
}

void study_sitecheck_delete(study_sitecheck *s) {
  free(s);
}

const char *study_sitecheck_field(size_t i) {
  return i < STUDY_NROWS(study_sitecheck_fields) ? study_sitecheck_fields[i].name : NULL;
}

int study_sitecheck_get_u64(const study_sitecheck *s, const char *name, size_t i,
                            uint64_t *out) {
  return geom_field_u64(s, geom_field_find(study_sitecheck_fields,
                                           STUDY_NROWS(study_sitecheck_fields), name), i, out);
}

int study_sitecheck_sites(const study_sitecheck *s, geom_point *out) {
  if (!s->has_witness || s->n < 0 || s->n > SITEFLIP_MAX_SITES) return 0;
  memcpy(out, s->sites, (size_t)s->n * sizeof *out);
  return s->n;
}

/* ---- a LOT against the GOT ---- */

study_gotcheck *study_gotcheck_new(void) {
  return calloc(1, sizeof(study_gotcheck));
}

void study_gotcheck_delete(study_gotcheck *c) {
  if (c != NULL) study_gotcheck_free(c);
  free(c);
}

const char *study_gotcheck_field(size_t i) {
  return i < STUDY_NROWS(study_gotcheck_fields) ? study_gotcheck_fields[i].name : NULL;
}

int study_gotcheck_get_u64(const study_gotcheck *c, const char *name, size_t i, uint64_t *out) {
  return geom_field_u64(c, geom_field_find(study_gotcheck_fields,
                                           STUDY_NROWS(study_gotcheck_fields), name), i, out);
}

int study_gotcheck_get_double(const study_gotcheck *c, const char *name, double *out) {
  return geom_field_double(c, geom_field_find(study_gotcheck_fields,
                                              STUDY_NROWS(study_gotcheck_fields), name), out);
}

const char *study_gotcheck_get_text(const study_gotcheck *c, const char *name) {
  if (name == NULL) return NULL;
  if (strcmp(name, "lot_text") == 0) return c->lot_text;
  if (strcmp(name, "got_text") == 0) return c->got_text;
  if (strcmp(name, "uncertified") == 0) return c->uncertified ? c->uncertified : "";
  return NULL;
}

const uint32_t *study_gotcheck_triangles(const study_gotcheck *c) {
  return c->tri;
}

const got_result *study_gotcheck_got(const study_gotcheck *c) {
  return &c->got;
}
