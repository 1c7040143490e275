/*
** bench_lot.c: locally optimal triangulations of many points.
**
**   bench_lot [N [RUNS [SEED [RULE_RUNS [RULES]]]]]   (defaults 1000000, 3, 1, 1)
**
** On N uniform random points in the unit square (sampler "uniform"):
**   1. the Delaunay triangulation (default algorithm: incremental, BRIO +
**      Hilbert order), median wall time of RUNS runs, and the same points
**      through CGAL's Delaunay_triangulation_2 with the
**      Exact_predicates_inexact_constructions_kernel (bench_lot_cgal, built
**      when CGAL is found, run as a child process), and the ratio; the two
**      alternate run by run so that both see the same machine load, and
**      both wall and process CPU time are reported (on a shared machine
**      the CPU time is the steadier figure);
**   2. peak memory: a child process builds the DT and reports its peak
**      resident set (getrusage), input points included, in bytes per point;
**   3. every built-in triangle-based rule with joint l_1: time (median of
**      RULE_RUNS), ratio to fliplab's DT time (each rule run is paired
**      with a DT run just before it; the median of the pairs' ratios),
**      flips per point, status; or, with RULES (a comma list of rule
**      names: "ES:square,ES:hexagon,ES:ellipse:2 1"), those rules instead,
**      each paired with DT the same way (docs/performance.md, empty shapes:
**      bench_lot 1000000 3 1 5 'ES:square,ES:hexagon,...').
** Times cover the triangulation only (input validation, ordering,
** insertion, flips), not sampling or output.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include "benchutil.h"
#include "lot.h"
#include "measure.h"
#include "sampler.h"

/* One build: wall and CPU seconds, flips, status. */
static void bench_once(const geom_point *p, size_t n, const rule *r, double *wall, double *cpu,
                       uint64_t *flips, lot_status *status) {
  lot_stats st;
  bench_time t = bench_lot_time("bench_lot", r, p, n, &st);
  *wall = t.wall;
  *cpu = t.cpu;
  *flips = st.flips;
  *status = st.status;
}

/* Median wall time of `runs` builds of rule r (*cpu: median CPU time),
** each run next to a DT run: *ratio is the median of the per-pair ratios
** of wall times (*cratio: of CPU times), which the machine's drift from
** minute to minute hardly moves, since both members of a pair see the
** same load. */
static double bench_rule(const geom_point *p, size_t n, const rule *r, int runs, double *cpu,
                         double *ratio, double *cratio, uint64_t *flips, lot_status *status) {
  double t[16], c[16], q[16], cq[16], dw, dc;
  rule dt = rule_delaunay();
  uint64_t dflips;
  lot_status dstatus;
  for (int k = 0; k < runs; k++) {
    bench_once(p, n, &dt, &dw, &dc, &dflips, &dstatus);
    bench_once(p, n, r, &t[k], &c[k], flips, status);
    q[k] = t[k] / dw;
    cq[k] = c[k] / dc;
  }
  *ratio = bench_median(q, runs);
  *cratio = bench_median(cq, runs);
  *cpu = bench_median(c, runs);
  return bench_median(t, runs);
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

/* One run of bench_lot_cgal next to this program (bench_sibling). */
static void bench_cgal(const char *argv0, size_t n, uint64_t seed, double *wall, double *cpu) {
  char args[128];
  snprintf(args, sizeof args, "%zu 1 %llu", n, (unsigned long long)seed);
  bench_sibling(argv0, "bench_lot_cgal", args, wall, cpu);
}

/* One table row: rule r timed next to DT (bench_rule). */
static void bench_row(const geom_point *p, size_t n, const rule *r, int runs) {
  uint64_t flips;
  lot_status status;
  double c, q, cq, t = bench_rule(p, n, r, runs, &c, &q, &cq, &flips, &status);
  printf("| %s | %.3f | %.3f | %.2f (CPU %.2f) | %.3f | %s |\n", r->name, t, c, q, cq,
         (double)flips / (double)n,
         status == LOT_CONVERGED ? "converged" : status == LOT_CYCLE ? "cycle" : "budget");
  fflush(stdout);
}

/* A row for each rule of the comma list; -1 (message printed) on a bad name. */
static int bench_rule_list(const geom_point *p, size_t n, const char *list, int runs) {
  char name[256];
  for (const char *s = list; *s;) {
    size_t len = strcspn(s, ",");
    snprintf(name, sizeof name, "%.*s", (int)len, s);
    rule r;
    char err[512];
    if (rule_parse(name, &r, err, sizeof err) != 0) {
      fprintf(stderr, "bench_lot: %s\n", err);
      return -1;
    }
    bench_row(p, n, &r, runs);
    s += len + (s[len] == ',');
  }
  return 0;
}

int main(int argc, char **argv) {
  size_t n = argc > 1 ? (size_t)strtod(argv[1], NULL) : 1000000;
  int runs = argc > 2 ? atoi(argv[2]) : 3;
  uint64_t seed = argc > 3 ? strtoull(argv[3], NULL, 10) : 1;
  int rule_runs = argc > 4 ? atoi(argv[4]) : 1;
  if (n < 3 || runs < 1 || runs > 15 || rule_runs < 1 || rule_runs > 15) {
    fprintf(stderr, "usage: bench_lot [N >= 3 [RUNS 1..15 [SEED [RULE_RUNS 1..15 [RULES]]]]]\n");
    return 2;
  }
  geom_point *p = malloc(n * sizeof *p);
  if (p == NULL) return 1;
  sampler_points(SAMPLER_UNIFORM, seed, n, p);
  printf("# bench_lot: %zu uniform points (seed %llu), DT and CGAL median of %d runs, "
         "rules median of %d\n", n, (unsigned long long)seed, runs, rule_runs);
  printf("(load average at start: %.2f on %ld cores)\n\n", bench_load(),
         sysconf(_SC_NPROCESSORS_ONLN));
  double rss = bench_peak_rss(p, n);
  rule dt = rule_delaunay();
  uint64_t flips;
  lot_status status;
  /* DT and CGAL alternate, so both see the same machine load. */
  double tw[16], tc[16], cw[16], cc[16];
  int have_cgal = 1;
  for (int k = 0; k < runs; k++) {
    bench_once(p, n, &dt, &tw[k], &tc[k], &flips, &status);
    bench_cgal(argv[0], n, seed, &cw[k], &cc[k]);
    have_cgal &= !isnan(cw[k]);
  }
  double tdt = bench_median(tw, runs), cdt = bench_median(tc, runs);
  double tcg = have_cgal ? bench_median(cw, runs) : NAN, ccg = have_cgal ? bench_median(cc, runs) : NAN;
  printf("| rule | time (s) | CPU (s) | time / fliplab DT (paired runs) | flips/point | status |\n");
  printf("|---|---:|---:|---:|---:|---|\n");
  printf("| DT (fliplab, incremental, spatial order) | %.3f | %.3f | 1.00 | %.3f | %s |\n", tdt,
         cdt, (double)flips / (double)n, status == LOT_CONVERGED ? "converged" : "NOT converged");
  if (!have_cgal)
    printf("| CGAL Delaunay_triangulation_2 (Epick) | not built | | | | |\n");
  else
    printf("| CGAL Delaunay_triangulation_2 (Epick) | %.3f | %.3f | %.2f | - | - |\n", tcg, ccg,
           tcg / tdt);
  fflush(stdout);
  if (argc > 5) {
    if (bench_rule_list(p, n, argv[5], rule_runs) != 0) return 2;
  } else {
    for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++) {
      rule r;
      char err[256];
      if (rule_triangle(m, JOINT_SUM, &r, err, sizeof err) != 0) continue;
      bench_row(p, n, &r, rule_runs);
    }
  }
  printf("\nfliplab DT / CGAL: wall %.3f, CPU %.3f (<= 1: fliplab as fast or faster)\n",
         tdt / tcg, cdt / ccg);
  printf("peak memory (DT, input included): %.1f bytes/point (%.1f MB)\n", rss / (double)n,
         rss / 1e6);
  printf("(load average at end: %.2f)\n", bench_load());
  free(p);
  return 0;
}
