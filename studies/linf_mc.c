/*
** linf_mc.c: the Monte Carlo of section 4.2.1: d + 1 points uniform in the
** unit cube of R^d, and how many l_inf circumcubes they have; the exact
** law beside it (linf_rank_law).
*/
#include <omp.h>
#include <stdio.h>
#include <string.h>
#include "sampler.h"
#include "study_linf.h"

/* Trial t: its points from stream GEOM_STREAM_SAMPLE(t), point by point,
** coordinate by coordinate; the count of their circumcubes. */
static int study_linf_trial(int d, uint64_t seed, uint64_t t) {
  sampler_rng g;
  double pts[(LINF_DIM_MAX + 1) * LINF_DIM_MAX];
  linf_cube cubes[LINF_CUBES_MAX];
  sampler_seed(&g, seed, GEOM_STREAM_SAMPLE(t));
  for (int k = 0; k < (d + 1) * d; k++) pts[k] = sampler_uniform(&g);
  return linf_circumcubes(pts, d, cubes);
}

/* Cost: O(trials 2^d d^2), split among the threads; the counts are sums,
** the same for any split. */
int study_linf_montecarlo(int d, uint64_t trials, uint64_t seed, int threads, study_linf_mc *mc,
                          char *err, size_t errlen) {
  memset(mc, 0, sizeof *mc);
  if (d < LINF_DIM_MIN || d > LINF_DIM_MAX)
    return snprintf(err, errlen, "dimension %d is out of range (%d .. %d)", d, LINF_DIM_MIN,
                    LINF_DIM_MAX), -1;
  if (trials == 0 || trials > STUDY_LINF_TRIALS_MAX)
    return snprintf(err, errlen, "trials must be 1 .. 2^40"), -1;
  if (geom_threads_check(threads, err, errlen) != 0) return -1;
  mc->d = d;
  mc->trials = trials;
  mc->seed = seed;
  int nt = geom_threads_clamp(threads, omp_get_max_threads());
#pragma omp parallel num_threads(nt)
  {
    uint64_t mine[LINF_CUBES_MAX + 2] = {0};
#pragma omp for schedule(static)
    for (uint64_t t = 0; t < trials; t++) {
      int c = study_linf_trial(d, seed, t);
      mine[c == LINF_INFINITE ? LINF_CUBES_MAX + 1 : c]++;
    }
#pragma omp critical(study_linf_mc)
    {
      for (int k = 0; k <= LINF_CUBES_MAX; k++) mc->count[k] += mine[k];
      mc->infinite += mine[LINF_CUBES_MAX + 1];
    }
  }
  mc->law_total = linf_rank_law(d, mc->law);
  return 0;
}
