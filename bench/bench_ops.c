/*
** bench_ops.c: what the counting layer (geom/ops.h, lot_options.ops) costs.
**
**   bench_ops [N [RUNS [SEED [PEER]]]]      (defaults 1000000, 5, 1)
**   bench_ops --one off|on N SEED           (one run: prints its seconds)
**
** The Delaunay triangulation of N uniform points (lot's incremental, the
** default options) with counting off (ops NULL) and on, and, with PEER,
** the same run of another build: PEER is a bench_ops program of that
** build, run as `PEER --one off N SEED` (for a tree whose lot/ cannot
** count, this file compiled with -DBENCH_OPS_PEER, which leaves the
** counting out).  Every run is a child process (same start for all three),
** and the three alternate run by run, so that they see the same machine
** load; the table gives the median wall and CPU times of RUNS and their
** ratios to the run with counting off (on a shared machine the CPU time
** is the steadier figure).  The target: off within 2% of the peer.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "benchutil.h"
#include "lot.h"
#include "sampler.h"

/* One DT of n uniform points (seed), counting when `on`: prints the
** wall seconds of lot_build alone, and with counting the counts. */
static int bench_ops_one(int on, size_t n, uint64_t seed) {
  geom_point *p = malloc((n ? n : 1) * sizeof *p);
  if (p == NULL) return 1;
  sampler_points(SAMPLER_UNIFORM, seed, n, p);
  rule dt = rule_delaunay();
  lot_options o;
  lot_options_init(&o, &dt);
#ifndef BENCH_OPS_PEER
  ops_counts c;
  ops_clear(&c);
  if (on) o.ops = &c;
#else
  if (on) return 2;
#endif
  lot *L;
  char err[256];
  double t0 = bench_wall(), c0 = bench_cpu();
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) {
    fprintf(stderr, "bench_ops: %s\n", err);
    return 1;
  }
  printf("peer_seconds %.6f\npeer_cpu %.6f\n", bench_wall() - t0, bench_cpu() - c0);
#ifndef BENCH_OPS_PEER
  for (int k = 0; on && k < OPS_COUNT; k++)
    printf("count %s %.3f\n", ops_name(k), (double)c.v[k] / (double)n);
#endif
  lot_free(L);
  free(p);
  return 0;
}

/* Run `prog --one mode n seed` and read its wall seconds (NAN on
** failure) and CPU seconds (*cpu). */
static double bench_ops_child(const char *prog, const char *mode, size_t n, uint64_t seed,
                              int show_counts, double *cpu) {
  char cmd[4400], line[256];
  snprintf(cmd, sizeof cmd, "%s --one %s %zu %llu", prog, mode, n, (unsigned long long)seed);
  FILE *f = popen(cmd, "r");
  double s = NAN;
  *cpu = NAN;
  if (f == NULL) return s;
  while (fgets(line, sizeof line, f)) {
    sscanf(line, "peer_seconds %lf", &s);
    sscanf(line, "peer_cpu %lf", cpu);
    if (show_counts && strncmp(line, "count ", 6) == 0) printf("  %s", line + 6);
  }
  return pclose(f) == 0 ? s : NAN;
}

int main(int argc, char **argv) {
  if (argc == 5 && strcmp(argv[1], "--one") == 0)
    return bench_ops_one(strcmp(argv[2], "on") == 0, strtoull(argv[3], NULL, 10),
                         strtoull(argv[4], NULL, 10));
  size_t n = argc > 1 ? strtoull(argv[1], NULL, 10) : 1000000;
  int runs = argc > 2 ? atoi(argv[2]) : 5;
  uint64_t seed = argc > 3 ? strtoull(argv[3], NULL, 10) : 1;
  const char *peer = argc > 4 ? argv[4] : NULL;
  if (n < 3 || runs < 1 || runs > 15) {
    fprintf(stderr, "usage: bench_ops [N >= 3 [RUNS 1..15 [SEED [PEER]]]]\n");
    return 2;
  }
  printf("# bench_ops: DT of %zu uniform points (seed %llu), median of %d runs\n", n,
         (unsigned long long)seed, runs);
  printf("(load average at start: %.2f on %ld cores)\n", bench_load(),
         sysconf(_SC_NPROCESSORS_ONLN));
  printf("counts per point (counting on):\n");
  double w[3][16], c[3][16], mw[3], mc[3];
  for (int k = 0; k < runs; k++) {
    w[0][k] = bench_ops_child(argv[0], "off", n, seed, 0, &c[0][k]);
    w[1][k] = bench_ops_child(argv[0], "on", n, seed, k == 0, &c[1][k]);
    w[2][k] = peer ? bench_ops_child(peer, "off", n, seed, 0, &c[2][k]) : NAN;
  }
  for (int i = 0; i < 3; i++) mw[i] = bench_median(w[i], runs), mc[i] = bench_median(c[i], runs);
  static const char *const what[3] = {"counting off", "counting on", "peer build"};
  printf("\n| run | wall (s) | / off | CPU (s) | / off |\n|---|---:|---:|---:|---:|\n");
  for (int i = 0; i < (peer ? 3 : 2); i++)
    printf("| %s | %.3f | %.3f | %.3f | %.3f |\n", what[i], mw[i], mw[i] / mw[0], mc[i],
           mc[i] / mc[0]);
  double toff = mw[0], ton = mw[1];
  printf("(load average at end: %.2f)\n", bench_load());
  return isnan(toff) || isnan(ton) ? 1 : 0;
}
