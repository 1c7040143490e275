/*
** fields.c: a study's results read by name, for front ends that read no C
** layout (python/): one table per result kind, each row a field's name,
** its place in the struct and its type, so a field added here reaches
** every front end without a mirrored structure to keep in step.
*/
#include <math.h>
#include <stddef.h>
#include <string.h>
#include "study.h"

/* The types of fields: an unsigned count, a signed integer, a flag (0 or
** 1), a real, a text (a char array, or a const char * that may be NULL). */
typedef enum study_ftype {
  STUDY_F_U64, STUDY_F_SIZE, STUDY_F_I64, STUDY_F_INT, STUDY_F_CHOICE, STUDY_F_FLAG,
  STUDY_F_DOUBLE, STUDY_F_CHARS, STUDY_F_STRING
} study_ftype;

typedef struct study_frow {
  const char *name;
  size_t off;
  study_ftype type;
} study_frow;

/* offsetof(T, F), refused by the compiler unless field F has type CT. */
#define STUDY_AT(T, F, CT) (offsetof(T, F) + 0 * sizeof(&((T *)0)->F == (CT *)0))
#define STUDY_U64(T, N, F) {N, STUDY_AT(T, F, uint64_t), STUDY_F_U64}
#define STUDY_SIZE(T, N, F) {N, STUDY_AT(T, F, size_t), STUDY_F_SIZE}
#define STUDY_I64(T, N, F) {N, STUDY_AT(T, F, int64_t), STUDY_F_I64}
#define STUDY_INT(T, N, F) {N, STUDY_AT(T, F, int), STUDY_F_INT}
#define STUDY_CHOICE(T, N, F) {N, STUDY_AT(T, F, rule_choice), STUDY_F_CHOICE}
#define STUDY_FLAG(T, N, F) {N, STUDY_AT(T, F, int), STUDY_F_FLAG}
#define STUDY_DOUBLE(T, N, F) {N, STUDY_AT(T, F, double), STUDY_F_DOUBLE}
#define STUDY_CHARS(T, N, F) {N, STUDY_AT(T, F[0], char), STUDY_F_CHARS}
#define STUDY_STRING(T, N, F) {N, STUDY_AT(T, F, const char *), STUDY_F_STRING}

#define V study_verdict
static const study_frow study_verdict_rows[] = {
  STUDY_U64(V, "samples", counts.samples),
  STUDY_U64(V, "type_I", counts.type[FLIPGRAPH_I]),
  STUDY_U64(V, "type_II", counts.type[FLIPGRAPH_II]),
  STUDY_U64(V, "type_III", counts.type[FLIPGRAPH_III]),
  STUDY_U64(V, "type_IV", counts.type[FLIPGRAPH_IV]),
  STUDY_U64(V, "type_V", counts.type[FLIPGRAPH_V]),
  STUDY_U64(V, "dt", counts.dt),
  STUDY_DOUBLE(V, "lo_I", lo[FLIPGRAPH_I]), STUDY_DOUBLE(V, "hi_I", hi[FLIPGRAPH_I]),
  STUDY_DOUBLE(V, "lo_II", lo[FLIPGRAPH_II]), STUDY_DOUBLE(V, "hi_II", hi[FLIPGRAPH_II]),
  STUDY_DOUBLE(V, "lo_III", lo[FLIPGRAPH_III]), STUDY_DOUBLE(V, "hi_III", hi[FLIPGRAPH_III]),
  STUDY_DOUBLE(V, "lo_IV", lo[FLIPGRAPH_IV]), STUDY_DOUBLE(V, "hi_IV", hi[FLIPGRAPH_IV]),
  STUDY_DOUBLE(V, "lo_V", lo[FLIPGRAPH_V]), STUDY_DOUBLE(V, "hi_V", hi[FLIPGRAPH_V]),
  STUDY_DOUBLE(V, "lo_DT", lo[STUDY_ROW_DT]), STUDY_DOUBLE(V, "hi_DT", hi[STUDY_ROW_DT]),
  STUDY_U64(V, "decided", decided),
  STUDY_FLAG(V, "systematic", systematic),
  STUDY_FLAG(V, "local", local),
  STUDY_FLAG(V, "sink_bug", sink_bug),
  STUDY_FLAG(V, "always_delaunay", always_delaunay),
  {NULL, 0, STUDY_F_INT}};
#undef V

#define Q study_quadcheck
static const study_frow study_quadcheck_rows[] = {
  STUDY_U64(Q, "tested", tested), STUDY_U64(Q, "disagree", disagree),
  STUDY_U64(Q, "ties", ties), STUDY_U64(Q, "cocircular", cocircular),
  STUDY_U64(Q, "decided", decided), STUDY_FLAG(Q, "equivalent", equivalent),
  STUDY_I64(Q, "first", first), STUDY_CHOICE(Q, "choice", choice), STUDY_CHOICE(Q, "dt", dt),
  STUDY_DOUBLE(Q, "ac", ac), STUDY_DOUBLE(Q, "bd", bd),
  {NULL, 0, STUDY_F_INT}};
#undef Q

#define S study_sitecheck
static const study_frow study_sitecheck_rows[] = {
  STUDY_INT(S, "sampler", sampler), STUDY_INT(S, "sites", n),
  STUDY_U64(S, "samples", counts.samples), STUDY_U64(S, "tie", counts.tie),
  STUDY_U64(S, "no_sink", counts.no_sink), STUDY_U64(S, "one_sink", counts.one_sink),
  STUDY_U64(S, "multi_sink", counts.multi_sink), STUDY_U64(S, "sink_dt", counts.sink_dt),
  STUDY_U64(S, "decided", decided), STUDY_FLAG(S, "systematic", systematic),
  STUDY_I64(S, "witness", witness),
  {NULL, 0, STUDY_F_INT}};
#undef S

#define G study_gotcheck
static const study_frow study_gotcheck_rows[] = {
  STUDY_FLAG(G, "ring", ring), STUDY_SIZE(G, "n", n),
  STUDY_DOUBLE(G, "lot_key", lot_key), STUDY_DOUBLE(G, "got_key", got.key),
  STUDY_DOUBLE(G, "lot_total", lot_total), STUDY_DOUBLE(G, "got_total", got.total),
  STUDY_CHARS(G, "lot_text", lot_text), STUDY_CHARS(G, "got_text", got_text),
  STUDY_DOUBLE(G, "rel", rel), STUDY_FLAG(G, "certified", certified),
  STUDY_STRING(G, "uncertified", uncertified), STUDY_FLAG(G, "equal", equal),
  STUDY_FLAG(G, "below", below), STUDY_SIZE(G, "triangles_lot", diff.triangles_a),
  STUDY_SIZE(G, "triangles_got", diff.triangles_b),
  STUDY_SIZE(G, "triangles_shared", diff.triangles_common),
  STUDY_SIZE(G, "edges_lot", diff.edges_a), STUDY_SIZE(G, "edges_got", diff.edges_b),
  STUDY_SIZE(G, "edges_shared", diff.edges_common), STUDY_FLAG(G, "same", same),
  STUDY_FLAG(G, "got_is_cdt", got_is_cdt), STUDY_FLAG(G, "failed", failed),
  {NULL, 0, STUDY_F_INT}};
#undef G

static const struct {
  const char *kind;
  size_t size;
  const study_frow *rows;
} study_kinds[] = {
  {"verdict", sizeof(study_verdict), study_verdict_rows},
  {"quadcheck", sizeof(study_quadcheck), study_quadcheck_rows},
  {"sitecheck", sizeof(study_sitecheck), study_sitecheck_rows},
  {"gotcheck", sizeof(study_gotcheck), study_gotcheck_rows},
};
#define STUDY_NKINDS (sizeof study_kinds / sizeof *study_kinds)

/* Row i of kind, or NULL (an unknown kind, or past the last row). */
static const study_frow *study_row(const char *kind, int i, size_t *size) {
  for (size_t k = 0; kind != NULL && k < STUDY_NKINDS; k++) {
    if (strcmp(kind, study_kinds[k].kind) != 0) continue;
    if (size != NULL) *size = study_kinds[k].size;
    for (int j = 0; j >= 0 && j <= i; j++)
      if (study_kinds[k].rows[j].name == NULL) return NULL;
    return i >= 0 ? &study_kinds[k].rows[i] : NULL;
  }
  return NULL;
}

size_t study_size(const char *kind) {
  size_t size = 0;
  study_row(kind, -1, &size);
  return size;
}

const char *study_field_name(const char *kind, int i) {
  const study_frow *f = study_row(kind, i, NULL);
  return f ? f->name : NULL;
}

/* The letter of each type: unsigned, signed, flag, real, text. */
int study_field_type(const char *kind, int i) {
  static const char letter[] = {
    [STUDY_F_U64] = 'u', [STUDY_F_SIZE] = 'u', [STUDY_F_I64] = 'i', [STUDY_F_INT] = 'i',
    [STUDY_F_CHOICE] = 'i', [STUDY_F_FLAG] = 'b', [STUDY_F_DOUBLE] = 'd',
    [STUDY_F_CHARS] = 's', [STUDY_F_STRING] = 's'};
  const study_frow *f = study_row(kind, i, NULL);
  return f ? letter[f->type] : 0;
}

double study_field(const char *kind, const void *res, int i) {
  const study_frow *f = study_row(kind, i, NULL);
  const char *at = f ? (const char *)res + f->off : NULL;
  switch (f ? f->type : STUDY_F_CHARS) {
    case STUDY_F_U64: return (double)*(const uint64_t *)(const void *)at;
    case STUDY_F_SIZE: return (double)*(const size_t *)(const void *)at;
    case STUDY_F_I64: return (double)*(const int64_t *)(const void *)at;
    case STUDY_F_INT: case STUDY_F_FLAG: return *(const int *)(const void *)at;
    case STUDY_F_CHOICE: return (double)*(const rule_choice *)(const void *)at;
    case STUDY_F_DOUBLE: return *(const double *)(const void *)at;
    case STUDY_F_CHARS: case STUDY_F_STRING: return NAN;
  }
  return NAN;
}

const char *study_field_text(const char *kind, const void *res, int i) {
  const study_frow *f = study_row(kind, i, NULL);
  const char *at = f ? (const char *)res + f->off : NULL;
  if (f != NULL && f->type == STUDY_F_CHARS) return at;
  if (f != NULL && f->type == STUDY_F_STRING) {
    const char *s = *(const char *const *)(const void *)at;
    return s ? s : "";
  }
  return NULL;
}

int64_t study_witness(const study_verdict *v, int t, int k) {
  if (t < 0 || t >= FLIPGRAPH_NTYPES || k < 0 || k >= v->witness[t].n) return -1;
  return (int64_t)v->witness[t].idx[k];
}

int study_witness_sites(const study_sitecheck *s, geom_point *out) {
  if (s->witness < 0 || s->n < 0 || s->n > SITEFLIP_MAX_SITES) return 0;
  memcpy(out, s->sites, (size_t)s->n * sizeof *out);
  return s->n;
}

const uint32_t *study_got_triangles(const study_gotcheck *c) {
  return c->tri;
}
