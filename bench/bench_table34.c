/*
** bench_table34.c: pentagons per second for table 3.4's full workload: the
** 120 triangle-based rules (20 measures x 6 joints) plus DT, through
** flipgraph_tally (sampling included), on one thread and on all threads.
**
** Usage: bench_table34 [SAMPLES [SEED]].  Without SAMPLES the count is
** calibrated so that one single-thread run takes about one second.  Each
** line is the run of median wall time out of 5; "pentagons/cpu-s" divides
** by the CPU time the process got, the per-core speed even when other
** processes share the machine.
*/
#include <stdio.h>
#include <stdlib.h>
#include <omp.h>
#include "benchutil.h"
#include "measure.h"
#include "flipgraph.h"

#define BENCH_RUNS 5

/* Seconds for one tally of n pentagons; the counts are checked so the
** work cannot be optimised away or silently fail. */
static bench_time bench_run(const rule *rules, int nrules, uint64_t seed, uint64_t n, int threads) {
  flipgraph_counts *c = calloc((size_t)nrules, sizeof *c);
  if (c == NULL) exit(1);
  double t0 = bench_wall(), c0 = bench_cpu();
  if (flipgraph_tally(rules, nrules, seed, 0, n, 1e-12, threads, c, NULL, NULL) != 0
      || c[0].samples != n) {
    fprintf(stderr, "bench_table34: tally failed\n");
    exit(1);
  }
  bench_time t = {bench_wall() - t0, bench_cpu() - c0};
  free(c);
  return t;
}

/* The run of median wall time. */
static bench_time bench_repeat(const rule *rules, int nrules, uint64_t seed, uint64_t n, int threads) {
  bench_time t[BENCH_RUNS];
  for (int k = 0; k < BENCH_RUNS; k++) t[k] = bench_run(rules, nrules, seed, n, threads);
  return bench_median_time(t, BENCH_RUNS);
}

int main(int argc, char **argv) {
  uint64_t seed = argc > 2 ? strtoull(argv[2], NULL, 10) : 1;
  rule rules[128];
  int n = rule_list_triangle(measure_table34, MEASURE_TABLE34_COUNT, rules, 127);
  rules[n++] = rule_delaunay();

  uint64_t samples = argc > 1 ? strtoull(argv[1], NULL, 10) : 0;
  if (samples == 0) {   /* calibrate: about one second on one thread */
    uint64_t probe = 20000;
    double t = bench_run(rules, n, seed, probe, 1).wall;
    samples = (uint64_t)((double)probe / t);
    samples = samples < 1000 ? 1000 : samples / 1000 * 1000;
  }
  int all = omp_get_max_threads();
  printf("bench_table34: %d rules (120 triangle-based + DT), seed %llu, %llu samples per run,"
         " median of %d runs\n", n, (unsigned long long)seed, (unsigned long long)samples,
         BENCH_RUNS);
  printf("%-8s %9s %9s %13s %19s %17s %20s\n", "threads", "wall s", "cpu s", "pentagons/s",
         "pentagons/s/thread", "pentagons/cpu-s", "wall s / 1e6 pent.");
  int tcount[2] = {1, all};
  for (int k = 0; k < (all > 1 ? 2 : 1); k++) {
    bench_time t = bench_repeat(rules, n, seed, samples, tcount[k]);
    double rate = (double)samples / t.wall;
    printf("%-8d %9.3f %9.3f %13.0f %19.0f %17.0f %20.3f\n", tcount[k], t.wall, t.cpu, rate,
           rate / tcount[k], (double)samples / t.cpu, 1e6 / rate);
  }
  return 0;
}
