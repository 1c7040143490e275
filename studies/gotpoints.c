/*
** gotpoints.c: how far a rule's local optimum is from its global one on point sets
** (study.h, "how far local is from global"; docs/got.md, "Point sets"): the LOT's
** total against the GOT's (got_points_solve), one set or a table over random sets.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "sampler.h"
#include "study.h"

int study_lot_key(const geom_point *p, size_t n, const rule *r, double *key, char *err,
                  size_t errlen) {
  lot_options o;
  lot_options_init(&o, r);
  lot *L = NULL;
  if (lot_build(&L, p, n, &o, err, errlen) != 0) return -1;
  size_t nt = lot_get_stats(L)->triangles;
  uint32_t *tri = malloc((3 * nt + 1) * sizeof *tri);
  double *bad = malloc((nt + 1) * sizeof *bad);
  int rc = tri && bad ? 0 : -1;
  if (rc == 0) {
    lot_get_triangles(L, tri);
    lot_get_badness(p, tri, nt, r, bad);
    *key = rule_total_key(r, bad, nt);
  } else {
    snprintf(err, errlen, "out of memory for the LOT's %zu triangles", nt);
  }
  free(tri);
  free(bad);
  lot_free(L);
  return rc;
}

/* lot's exact Delaunay triangulation (the rule DT, spatial incremental order) of p, its
** triangles into *tri (anticlockwise); 0, or -1 with err. */
static int study_delaunay(const geom_point *p, size_t n, uint32_t **tri, size_t *nt,
                          char *err, size_t errlen) {
  lot_options o;
  rule dt = rule_delaunay();
  lot_options_init(&o, &dt);
  lot *L = NULL;
  if (lot_check_memory(n, err, errlen) != 0 || lot_build(&L, p, n, &o, err, errlen) != 0)
    return -1;
  *nt = lot_get_stats(L)->triangles;
  *tri = malloc((3 * *nt + 1) * sizeof **tri);
  if (*tri != NULL) lot_get_triangles(L, *tri);
  else snprintf(err, errlen, "out of memory for the Delaunay triangulation's %zu triangles", *nt);
  lot_free(L);
  return *tri != NULL ? 0 : -1;
}

int study_got_points(const geom_point *p, size_t n, const rule *r, const got_options *opt,
                     got_skeleton sk, got_result *out, char *err, size_t errlen) {
  if ((sk != GOT_SKELETON_AUTO && sk != GOT_SKELETON_DELAUNAY) || rule_got_cdt_theorem(r) == 0)
    return got_points_solve(p, n, r, opt, sk, out, err, errlen);
  memset(out, 0, sizeof *out);
  /* got's own checks first, once: its one-line errors (equal points, collinear sets) stand */
  if (got_points_check(p, n, r, err, errlen) != 0 ||
      got_points_check_memory(n, err, errlen) != 0)
    return -1;
  double t0 = omp_get_wtime();
  uint32_t *tri = NULL;
  size_t nt = 0;
  if (study_delaunay(p, n, &tri, &nt, err, errlen) != 0) return -1;
  double t1 = omp_get_wtime();
  int rc = got_points_solve_checked(p, n, r, opt, sk, tri, nt, out, err, errlen);
  free(tri);
  if (rc == 0) out->seconds_delaunay = t1 - t0, out->seconds += t1 - t0;
  return rc;
}

/* One set: its gap, whether the LOT is a GOT, whether the GOT is certified unique. */
typedef struct study_gap_one {
  double gap;
  int equal, certified, failed;
} study_gap_one;

static void study_gap_set(const rule *r, int kind, size_t n, uint64_t seed, got_skeleton sk,
                          geom_point *p, study_gap_one *o, char *err, size_t errlen) {
  got_options go = {1, rule_tie_eps(r)};
  got_result g;
  double lk;
  sampler_points((sampler_points_kind)kind, seed, n, p);
  o->failed = study_got_points(p, n, r, &go, sk, &g, err, errlen) != 0;
  if (!o->failed && study_lot_key(p, n, r, &lk, err, errlen) != 0) o->failed = 1;
  if (o->failed) return;
  /* a LOT is a triangulation: its total certainly below the GOT's would be a wrong GOT */
  double bound = g.cert_err + got_cert_err_of(&g, lk);
  if (lk < g.key - bound) {
    snprintf(err, errlen, "the LOT's total %.17g is below the GOT's %.17g beyond the error "
             "bound %.3g (a wrong GOT)", lk, g.key, bound);
    o->failed = 1;
    got_result_free(&g);
    return;
  }
  o->gap = rule_gap(r, lk, g.key);
  o->equal = o->gap <= rule_tie_eps(r);
  o->certified = g.cert_unique;
  got_result_free(&g);
}

/* Sum in set order: mean, normal interval, max, counts. */
static void study_gap_sum(const study_gap_one *one, uint64_t sets, study_gap_row *out) {
  double s = 0, s2 = 0;
  out->max = 0;
  for (uint64_t i = 0; i < sets; i++) {
    s += one[i].gap;
    out->max = fmax(out->max, one[i].gap);
    out->equal += (uint64_t)one[i].equal;
    out->certified += (uint64_t)one[i].certified;
  }
  out->mean = s / (double)sets;
  for (uint64_t i = 0; i < sets; i++) s2 += (one[i].gap - out->mean) * (one[i].gap - out->mean);
  double sd = sets > 1 ? sqrt(s2 / (double)(sets - 1)) : 0, h = 1.959963984540054 * sd /
                                                                  sqrt((double)sets);
  out->lo = out->mean - h;
  out->hi = out->mean + h;
  study_wilson(out->equal, sets, &out->equal_lo, &out->equal_hi);
}

int study_lot_got_gaps(const rule *r, int kind, size_t n, uint64_t sets, uint64_t seed,
                       int threads, got_skeleton sk, study_gap_row *out, char *err,
                       size_t errlen) {
  memset(out, 0, sizeof *out);
  out->sets = sets;
  double t0 = omp_get_wtime();
  int nt = geom_threads_clamp(threads, omp_get_max_threads());
  study_gap_one *one = sets ? calloc(sets, sizeof *one) : NULL;
  geom_point *pts = malloc((size_t)nt * n * sizeof *pts);
  if (one == NULL || pts == NULL) {
    free(one), free(pts);
    snprintf(err, errlen, "out of memory for %llu sets of %zu points", (unsigned long long)sets,
             n);
    return -1;
  }
  long long first = -1, m = (long long)sets;
#pragma omp parallel for schedule(dynamic, 1) num_threads(nt)
  for (long long i = 0; i < m; i++) {
    char e[512];
    study_gap_set(r, kind, n, seed + (uint64_t)i, sk, pts + (size_t)omp_get_thread_num() * n,
                  &one[i], e, sizeof e);
#pragma omp critical(study_gap_fail)
    if (one[i].failed && (first < 0 || i < first)) {
      first = i;
      snprintf(err, errlen, "set %lld: %s", i, e);
    }
  }
  if (first < 0) study_gap_sum(one, sets, out);
  out->seconds = omp_get_wtime() - t0;
  free(one), free(pts);
  return first < 0 ? 0 : -1;
}
