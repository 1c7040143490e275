/*
** bench_census.c: the census of site sets (`fliplab census`) against its
** speed targets, sampling included:
**   convex hexagons, 120 rules + DT, 10^6 samples:   < 6 s on 2 cores
**   seven-point disc sets, 120 rules + DT, 10^5:      < 10 s on 2 cores
**   convex 10-gons (1430 triangulations), one rule:   >= 10^4 samples/s
** Usage: bench_census [SCALE].  Each workload runs SCALE times its target
** sample count (default 0.1) BENCH_RUNS times on all threads; the line is
** the run of median wall time, extrapolated to the target count, with the
** CPU seconds the process got (the per-core speed even when other
** processes share the machine).
*/
#include <stdio.h>
#include <stdlib.h>
#include <omp.h>
#include "benchutil.h"
#include "measure.h"
#include "sampler.h"
#include "siteflip.h"

#define BENCH_RUNS 3

static bench_time bench_run(const rule *rules, int nrules, int sampler, int n, uint64_t count) {
  siteflip_counts *c = calloc((size_t)nrules, sizeof *c);
  char err[256];
  if (c == NULL) exit(1);
  double t0 = bench_wall(), c0 = bench_cpu();
  if (siteflip_census(rules, nrules, sampler, n, 1, 0, count, 1e-12, 0, 0, c, NULL, NULL, NULL, err,
                      sizeof err) != 0 || c[0].samples != count) {
    fprintf(stderr, "bench_census: %s\n", err);
    exit(1);
  }
  bench_time t = {bench_wall() - t0, bench_cpu() - c0};
  free(c);
  return t;
}

static void bench_line(const char *what, const rule *rules, int nrules, int sampler, int n,
                       uint64_t target, double scale, const char *goal) {
  uint64_t count = (uint64_t)((double)target * scale);
  if (count < 100) count = 100;
  bench_time t[BENCH_RUNS];
  for (int k = 0; k < BENCH_RUNS; k++) t[k] = bench_run(rules, nrules, sampler, n, count);
  bench_time m = bench_median_time(t, BENCH_RUNS);
  double f = (double)target / (double)count;
  printf("%-44s %9llu samples: %7.2f s wall, %7.2f cpu-s (%.0f samples/s; target %s)\n", what,
         (unsigned long long)target, m.wall * f, m.cpu * f, (double)count / m.wall, goal);
}

int main(int argc, char **argv) {
  double scale = argc > 1 ? atof(argv[1]) : 0.1;
  if (!(scale > 0)) {
    fprintf(stderr, "usage: bench_census [SCALE > 0]\n");
    return 2;
  }
  int ids[MEASURE_TABLE34_COUNT];
  for (int i = 0; i < MEASURE_TABLE34_COUNT; i++) ids[i] = measure_table34[i];
  rule rules[MEASURE_TABLE34_COUNT * JOINT_COUNT + 1];
  int nr = rule_list_triangle(ids, MEASURE_TABLE34_COUNT, rules, MEASURE_TABLE34_COUNT * JOINT_COUNT);
  rules[nr++] = rule_delaunay();
  rule one;
  char err[256];
  if (rule_parse("R_1", &one, err, sizeof err) != 0) return 1;
  printf("bench_census: %d threads, median of %d runs, scale %g (times extrapolated)\n",
         omp_get_max_threads(), BENCH_RUNS, scale);
  bench_line("convex hexagons, 120 rules + DT", rules, nr, SAMPLER_SITES_CONVEX, 6, 1000000, scale,
             "< 6 s");
  bench_line("7-point disc sets, 120 rules + DT", rules, nr, SAMPLER_SITES_DISC, 7, 100000, scale,
             "< 10 s");
  bench_line("convex 10-gons, R_1", &one, 1, SAMPLER_SITES_CONVEX, 10, 10000, scale * 10,
             ">= 10^4 samples/s");
  return 0;
}
