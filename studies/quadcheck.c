/*
** quadcheck.c: is a rule Delaunay-equivalent?  Its decisions against the
** exact DT on random convex quadrilaterals (docs/rules.md): quadrilateral i
** is sampler_quad(seed, i), so the counts and the first disagreement are
** the same for any thread count.
*/
#include <math.h>
#include <omp.h>
#include <string.h>
#include "sampler.h"
#include "study.h"

/* The first disagreement, decided again on its own. */
static void study_quad_first(const rule *r, uint64_t seed, study_quadcheck *out) {
  rule dt = rule_delaunay();
  out->ac = out->bd = NAN;
  sampler_quad(seed, out->first, out->q);
  out->choice = rule_eval(r, out->q, &out->ac, &out->bd);
  out->dt = rule_eval(&dt, out->q, NULL, NULL);
  if (!rule_is_triangle(r)) out->ac = out->bd = NAN;
}

int study_quads(const rule *r, uint64_t seed, uint64_t tested, int threads,
                study_quadcheck *out, char *err, size_t errlen) {
  if (geom_threads_check(threads, err, errlen) != 0) return -1;
  rule dt = rule_delaunay();
  uint64_t dis = 0, ties = 0, coc = 0, first = UINT64_MAX;
  int nt = geom_threads_clamp(threads, omp_get_max_threads());
#pragma omp parallel for schedule(dynamic, 4096) num_threads(nt) \
    reduction(+ : dis, ties, coc) reduction(min : first)
  for (uint64_t i = 0; i < tested; i++) {
    geom_point q[4];
    sampler_quad(seed, i, q);
    rule_choice d = rule_eval(&dt, q, NULL, NULL);
    if (d == RULE_EITHER) {
      coc++;
      continue;
    }
    rule_choice c = rule_eval(r, q, NULL, NULL);
    if (c == RULE_EITHER) {
      ties++;
    } else if (c != d) {
      dis++;
      if (i < first) first = i;
    }
  }
  memset(out, 0, sizeof *out);   /* padding too: results compare whole */
  out->tested = tested;
  out->disagree = dis;
  out->ties = ties;
  out->cocircular = coc;
  out->decided = tested - coc;
  out->equivalent = dis == 0 && ties == 0;
  out->first = dis ? first : 0;
  out->choice = out->dt = RULE_EITHER;
  out->ac = out->bd = NAN;
  if (dis) study_quad_first(r, seed, out);
  return 0;
}
