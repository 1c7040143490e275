/*
** paradigms.c: the matrix of study_paradigms.h, table 2.4 anew: every
** chosen algorithm x rule x point family x size, timed and counted.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "study_paradigms.h"
#include "study_cpdt.h"
#include "paradigm.h"
#include "sampler.h"
#include "splitmix.h"

/* The simple polygon families (the polygon problem), as `got --random`
** draws them. */
static const struct {
  const char *name;
  int (*draw)(sampler_rng *g, size_t n, geom_point *out);
} study_par_polygons[] = {{"star", sampler_star}, {"monotone", sampler_monotone}};
#define STUDY_PAR_POLYGONS (int)(sizeof study_par_polygons / sizeof *study_par_polygons)

const char *study_paradigms_family_name(paradigm_problem pb, int f) {
  switch (pb) {
    case PARADIGM_DELAUNAY:
    case PARADIGM_CONSTRAINED:
      return f >= 0 && f < SAMPLER_POINTS_COUNT ? sampler_points_name((sampler_points_kind)f)
                                                : NULL;
    case PARADIGM_POLYGON: return f >= 0 && f < STUDY_PAR_POLYGONS ? study_par_polygons[f].name
                                                                   : NULL;
    case PARADIGM_CONVEX: return study_cpdt_sampler_name(f);
  }
  return NULL;
}

int study_paradigms_family_find(paradigm_problem pb, const char *name) {
  for (int f = 0; study_paradigms_family_name(pb, f) != NULL; f++)
    if (strcmp(study_paradigms_family_name(pb, f), name) == 0) return f;
  return -1;
}

void study_paradigms_family_names(paradigm_problem pb, char *buf, size_t len) {
  size_t at = 0;
  buf[0] = '\0';
  for (int f = 0; study_paradigms_family_name(pb, f) != NULL && at < len; f++)
    at += (size_t)snprintf(buf + at, len - at, "%s%s", f ? ", " : "",
                           study_paradigms_family_name(pb, f));
}

int study_paradigms_family_check(paradigm_problem pb, int f, uint64_t n, char *err,
                                 size_t errlen) {
  if (study_paradigms_family_name(pb, f) == NULL) {
    snprintf(err, errlen, "families: no family %d of the %s problem", f,
             paradigm_problem_name(pb));
    return -1;
  }
  if (pb != PARADIGM_CONVEX || study_cpdt_sampler_check(f, -1, 0, (size_t)n, err, errlen) == 0)
    return 0;
  size_t u = strlen(err);   /* name the family and the size in front of the reason */
  char why[200];
  snprintf(why, sizeof why, "%.*s", (int)(u < sizeof why ? u : sizeof why - 1), err);
  snprintf(err, errlen, "family %s, n = %llu: %s", study_cpdt_sampler_name(f),
           (unsigned long long)n, why);
  return -1;
}

size_t study_paradigms_cells(const study_paradigms_plan *pl) {
  return pl->nalgorithms * pl->nrules * pl->nfamilies * pl->nsizes;
}

static size_t study_par_at(const study_paradigms_plan *pl, size_t a, size_t r, size_t f,
                           size_t s) {
  return ((a * pl->nrules + r) * pl->nfamilies + f) * pl->nsizes + s;
}

static int study_par_dcmp(const void *x, const void *y) {
  double a = *(const double *)x, b = *(const double *)y;
  return (a > b) - (a < b);
}

static int study_par_check(const study_paradigms_plan *pl, char *err, size_t errlen) {
  const char *why = pl->runs < 1 || pl->runs > 99 ? "runs: 1 .. 99" : NULL;
  for (size_t a = 0; why == NULL && a < pl->nalgorithms; a++)
    if (paradigm_get(pl->algorithms[a]) == NULL) why = "algorithms: an index past the registry";
  if (paradigm_problem_name(pl->problem)[0] == '?') why = "problem: unknown";
  for (size_t s = 0; why == NULL && s < pl->nsizes; s++)
    if (pl->sizes[s] < 3 || pl->sizes[s] > 100000000u) why = "sizes: 3 .. 10^8 points each";
  if (why != NULL) {
    snprintf(err, errlen, "%s", why);
    return -1;
  }
  for (size_t f = 0; f < pl->nfamilies; f++)
    for (size_t s = 0; s < pl->nsizes; s++)
      if (study_paradigms_family_check(pl->problem, pl->families[f], pl->sizes[s], err, errlen))
        return -1;
  return 0;
}

/* The input of family f with n points for the plan's problem into in:
** the points into p, and for the constrained problem up to n/4 segments
** into seg (room for 2 (n/4 + 1) indices).  0; -1 with the message (no
** polygon came out); -2 out of memory. */
static int study_par_input(const study_paradigms_plan *pl, int f, size_t n, geom_point *p,
                           uint32_t *seg, paradigm_input *in, char *err, size_t errlen) {
  sampler_rng g;
  int rc = 0;
  switch (pl->problem) {
    case PARADIGM_DELAUNAY: sampler_points((sampler_points_kind)f, pl->seed, n, p); return 0;
    case PARADIGM_CONSTRAINED:
      sampler_points((sampler_points_kind)f, pl->seed, n, p);
      sampler_seed(&g, pl->seed, GEOM_STREAM_SEGMENTS);
      in->segments = seg;
      return sampler_segments(&g, p, n, n / 4, seg, &in->nsegments) == 0 ? 0 : -2;
    case PARADIGM_POLYGON:
      sampler_seed(&g, pl->seed, GEOM_STREAM_GOT_POLYGON);
      rc = study_par_polygons[f].draw(&g, n, p);
      break;
    case PARADIGM_CONVEX: rc = study_cpdt_polygon(f, -1, 0, pl->seed, n, 0, p); break;
  }
  if (rc == SAMPLER_ENOMEM || rc == -2) return -2;
  if (rc != 0)
    snprintf(err, errlen, "family %s: no %s polygon of %zu vertices came out (seed %llu)",
             study_paradigms_family_name(pl->problem, f), paradigm_problem_name(pl->problem),
             n, (unsigned long long)pl->seed);
  return rc != 0 ? -1 : 0;
}

/* Does alg serve the rule of in (the runner's test of paradigm.c)? */
static int study_par_serves(const paradigm_algorithm *alg, const paradigm_input *in) {
  unsigned want = rule_is_shape(in->r) ? PARADIGM_RULE_ES
                : rule_is_delaunay(in->r) ? PARADIGM_RULE_DT : 0;
  return (alg->problems & (unsigned)in->problem) && (alg->rules & want);
}

/* One cell: `runs` runs of algorithm alg on in, the median time, the
** counts of the first (the same every run); its triangles compared with
** *ref (taken when it has none).  A refusal is the runner's message.  0,
** or -1 (err). */
static int study_par_cell(const study_paradigms_plan *pl, const paradigm_algorithm *alg,
                          const paradigm_input *in, study_paradigms_cell *c,
                          paradigm_result *ref, const char **refname, char *err, size_t errlen) {
  double t[99];
  paradigm_result res;
  if (!study_par_serves(alg, in)) {
    c->refused = 1;
    if (paradigm_run(alg, in, &res, c->why, sizeof c->why) == 0) paradigm_result_free(&res);
    return 0;
  }
  for (int k = 0; k < pl->runs; k++) {
    if (paradigm_run(alg, in, &res, c->why, sizeof c->why) != 0) {
      c->refused = 2;
      return 0;
    }
    t[k] = res.seconds;
    if (k == 0) {
      c->distinct = res.distinct, c->triangles = res.ntri;
      for (int o = 0; o < OPS_COUNT; o++) c->per_site[o] = (double)res.ops.v[o] / (double)in->n;
    }
    if (k == 0 && ref->tri == NULL) {
      *ref = res, *refname = alg->name;
      continue;
    }
    int same = k > 0 || (res.ntri == ref->ntri
                         && memcmp(res.tri, ref->tri, 3 * res.ntri * sizeof *res.tri) == 0);
    paradigm_result_free(&res);
    if (!same) {
      snprintf(err, errlen, "%s and %s give different triangles on %zu points", alg->name,
               *refname, in->n);
      return -1;
    }
  }
  qsort(t, (size_t)pl->runs, sizeof *t, study_par_dcmp);
  c->seconds = t[pl->runs / 2];
  return 0;
}

/* Every algorithm on one rule, family and size. */
static int study_par_column(const study_paradigms_plan *pl, study_paradigms_cell *cells,
                            size_t r, size_t f, size_t s, geom_point *p, uint32_t *seg,
                            char *err, size_t errlen) {
  paradigm_input in = {.p = p, .n = (size_t)pl->sizes[s], .r = &pl->rules[r],
                       .problem = pl->problem, .seed = pl->seed, .threads = 1};
  int rc = study_par_input(pl, pl->families[f], in.n, p, seg, &in, err, errlen);
  if (rc != 0) return rc;
  paradigm_result ref = {0};
  const char *refname = NULL;
  for (size_t a = 0; a < pl->nalgorithms && rc == 0; a++) {
    study_paradigms_cell *c = &cells[study_par_at(pl, a, r, f, s)];
    memset(c, 0, sizeof *c);
    c->algorithm = pl->algorithms[a], c->rule = r, c->family = pl->families[f];
    c->n = pl->sizes[s];
    rc = study_par_cell(pl, paradigm_get(pl->algorithms[a]), &in, c, &ref, &refname, err,
                        errlen);
  }
  paradigm_result_free(&ref);
  return rc;
}

/* Cost: every cell's runs; memory one input (points, segments) of the
** largest size. */
int study_paradigms_run(const study_paradigms_plan *pl, study_paradigms_cell *cells, char *err,
                        size_t errlen) {
  if (study_par_check(pl, err, errlen) != 0) return -1;
  uint64_t most = 3;
  for (size_t s = 0; s < pl->nsizes; s++) most = pl->sizes[s] > most ? pl->sizes[s] : most;
  geom_point *p = malloc((size_t)most * sizeof *p);
  uint32_t *seg = malloc(2 * ((size_t)most / 4 + 1) * sizeof *seg);
  int rc = p != NULL && seg != NULL ? 0 : -2;
  for (size_t r = 0; r < pl->nrules && rc == 0; r++)
    for (size_t f = 0; f < pl->nfamilies && rc == 0; f++)
      for (size_t s = 0; s < pl->nsizes && rc == 0; s++)
        rc = study_par_column(pl, cells, r, f, s, p, seg, err, errlen);
  free(p), free(seg);
  return rc;
}

double study_paradigms_growth(const study_paradigms_plan *pl, const study_paradigms_cell *cells,
                              size_t a, size_t r, size_t f, int k) {
  study_slope sl = {0};
  for (size_t s = 0; s < pl->nsizes; s++) {
    const study_paradigms_cell *c = &cells[study_par_at(pl, a, r, f, s)];
    double v = c->refused ? 0 : k == OPS_COUNT ? c->seconds : c->per_site[k] * (double)c->n;
    if (v > 0) study_slope_add(&sl, (double)c->n, v);
  }
  return study_slope_get(&sl);
}
