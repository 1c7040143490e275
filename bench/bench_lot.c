/*
** bench_lot.c: locally optimal triangulations of many points.
**
**   bench_lot [N [RUNS [SEED [RULE_RUNS]]]]      (defaults 1000000, 3, 1, 1)
**
** On N uniform random points in the unit square (sampler "uniform"):
**   1. the Delaunay triangulation (default algorithm: incremental, BRIO +
**      Hilbert order), median wall time of RUNS runs, and the same points
**      through CGAL's Delaunay_triangulation_2 with the
**      Exact_predicates_inexact_constructions_kernel (bench_lot_cgal, built
**      when CGAL is found, run as a child process so both see the same
**      machine state), and the ratio;
**   2. peak memory: a child process builds the DT and reports its peak
**      resident set (getrusage), input points included, in bytes per point;
**   3. every built-in triangle-based rule with joint l_1: time (median of
**      RULE_RUNS), ratio to fliplab's DT time, flips per point, status.
** Times cover the triangulation only (input validation, ordering,
** insertion, flips), not sampling or output.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "lot.h"
#include "measure.h"
#include "sampler.h"

static double bench_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int bench_cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

/* Median time of `runs` builds; *flips of the last one. */
static double bench_rule(const geom_point *p, size_t n, const rule *r, int runs,
                         uint64_t *flips, lot_status *status) {
  double t[16];
  for (int k = 0; k < runs; k++) {
    lot_options o;
    lot_options_init(&o, r);
    lot *L;
    char err[256];
    double t0 = bench_now();
    if (lot_build(&L, p, n, &o, err, sizeof err) != 0) {
      fprintf(stderr, "bench_lot: %s\n", err);
      exit(1);
    }
    t[k] = bench_now() - t0;
    *flips = lot_get_stats(L)->flips;
    *status = lot_get_stats(L)->status;
    lot_free(L);
  }
  qsort(t, (size_t)runs, sizeof *t, bench_cmp);
  return t[runs / 2];
}

/* Peak resident memory of a child that builds the DT, in bytes. */
static double bench_peak_rss(const geom_point *p, size_t n) {
  pid_t pid = fork();
  if (pid == 0) {
    rule dt = rule_delaunay();
    lot_options o;
    lot_options_init(&o, &dt);
    lot *L;
    char err[256];
    _exit(lot_build(&L, p, n, &o, err, sizeof err) == 0 ? 0 : 1);
  }
  int st;
  struct rusage ru;
  if (pid < 0 || wait4(pid, &st, 0, &ru) < 0 || !WIFEXITED(st) || WEXITSTATUS(st) != 0)
    return NAN;
  return 1024.0 * (double)ru.ru_maxrss;
}

/* CGAL's time from bench_lot_cgal next to this program, or NAN. */
static double bench_cgal(const char *argv0, size_t n, int runs, uint64_t seed) {
  char cmd[4200];
  const char *slash = strrchr(argv0, '/');
  int dir = slash ? (int)(slash - argv0 + 1) : 0;
  snprintf(cmd, sizeof cmd, "%.*sbench_lot_cgal %zu %d %llu 2>/dev/null", dir, argv0, n, runs,
           (unsigned long long)seed);
  FILE *f = popen(cmd, "r");
  if (f == NULL) return NAN;
  double s = NAN;
  char line[256];
  while (fgets(line, sizeof line, f))
    if (sscanf(line, "cgal_seconds %lf", &s) == 1) break;
  pclose(f);
  return s;
}

int main(int argc, char **argv) {
  size_t n = argc > 1 ? (size_t)strtod(argv[1], NULL) : 1000000;
  int runs = argc > 2 ? atoi(argv[2]) : 3;
  uint64_t seed = argc > 3 ? strtoull(argv[3], NULL, 10) : 1;
  int rule_runs = argc > 4 ? atoi(argv[4]) : 1;
  if (n < 3 || runs < 1 || runs > 15 || rule_runs < 1 || rule_runs > 15) {
    fprintf(stderr, "usage: bench_lot [N >= 3 [RUNS 1..15 [SEED [RULE_RUNS 1..15]]]]\n");
    return 2;
  }
  geom_point *p = malloc(n * sizeof *p);
  if (p == NULL) return 1;
  sampler_points(SAMPLER_UNIFORM, seed, n, p);
  printf("# bench_lot: %zu uniform points (seed %llu), DT and CGAL median of %d runs, "
         "rules median of %d\n", n, (unsigned long long)seed, runs, rule_runs);
  double rss = bench_peak_rss(p, n);
  rule dt = rule_delaunay();
  uint64_t flips;
  lot_status status;
  double tdt = bench_rule(p, n, &dt, runs, &flips, &status);
  double tcgal = bench_cgal(argv[0], n, runs, seed);
  printf("| rule | algorithm | time (s) | vs fliplab DT | flips/point | status |\n");
  printf("|---|---|---|---|---|---|\n");
  printf("| DT | incremental, spatial | %.3f | 1.00 | %.3f | %s |\n", tdt,
         (double)flips / (double)n, status == LOT_CONVERGED ? "converged" : "NOT converged");
  if (isnan(tcgal))
    printf("| CGAL Delaunay_triangulation_2 (Epick) | - | not built | - | - | - |\n");
  else
    printf("| CGAL Delaunay_triangulation_2 (Epick) | insert(range) | %.3f | %.2f | - | - |\n",
           tcgal, tcgal / tdt);
  for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++) {
    rule r;
    char err[256];
    if (rule_triangle(m, JOINT_SUM, &r, err, sizeof err) != 0) continue;
    double t = bench_rule(p, n, &r, rule_runs, &flips, &status);
    printf("| %s | incremental, spatial | %.3f | %.2f | %.3f | %s |\n", r.name, t, t / tdt,
           (double)flips / (double)n,
           status == LOT_CONVERGED ? "converged" : status == LOT_CYCLE ? "cycle" : "budget");
    fflush(stdout);
  }
  printf("\nfliplab DT / CGAL time ratio: %.3f (<= 1 means fliplab is as fast or faster)\n",
         tcgal / tdt > 0 ? tdt / tcgal : NAN);
  printf("peak memory (DT, input included): %.1f bytes/point (%.1f MB)\n", rss / (double)n,
         rss / 1e6);
  free(p);
  return 0;
}
