/*
** bench_paradigm_divide.c: the speed targets of divide and conquer
** (paradigms/divide.c, docs/paradigms.md), side by side in one run on the
** same N uniform points:
**   - dc-alternating on one thread against lot's incremental DT (lot_build,
**     the present default: target at most 1.00);
**   - dc-alternating on two threads against CGAL's single-thread
**     Delaunay_triangulation_2 (bench_lot_cgal, the child program bench_lot
**     runs: target at most 0.35);
**   - dc-vertical on one thread, and dc-alternating with the counting layer
**     on against off (the cost of counting);
**   - dc-alternating on two threads through the registry's runner
**     (paradigm_run: duplicates merged, indices mapped back, triangles in
**     canonical order), whose time beyond the algorithm's own is the
**     runner's overhead, printed apart: the targets time the algorithm.
** Each round runs every contender once, in turn, so that all see the same
** load; the figures are medians of RUNS rounds.  On a loaded machine two
** threads rarely get two cores at once, so the two-thread run also reports
** the CPU time of its busier thread (its critical path, which is its wall
** time on two idle cores): run with OMP_WAIT_POLICY=passive, so that a
** waiting thread sleeps instead of spinning into its CPU time.  Sorting is part of every
** time.  Before timing, dc-alternating's triangles (one and two threads)
** are checked equal to the incremental algorithm's.
**
**   bench_paradigm_divide [N [RUNS [SEED]]]     (defaults 1000000 5 1)
*/
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <time.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "benchutil.h"
#include "lot.h"
#include "paradigm_internal.h"

enum { BD_INCR, BD_VERT, BD_ALT1, BD_ALT1_COUNT, BD_ALT2, BD_RUN2, BD_CGAL, BD_ROWS };

static const char *const bd_names[BD_ROWS] = {
  "lot incremental (lot_build, 1 thread)", "dc-vertical, 1 thread",
  "dc-alternating, 1 thread", "dc-alternating, 1 thread, counting on",
  "dc-alternating, 2 threads", "dc-alternating, 2 threads, through paradigm_run",
  "CGAL Delaunay_triangulation_2 (Epick, 1 thread)"};

/* The CPU time of each of the team's first two threads into cpu[2]. */
static void bd_thread_cpu(double cpu[2]) {
#pragma omp parallel num_threads(2)
  {
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    cpu[omp_get_thread_num()] = (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
  }
}

/* One run of paradigm_divide, timed; exits on failure. */
static bench_time bd_divide(const paradigm_input *in, int alternating, int counting,
                            size_t *ntri) {
  paradigm_output out = {0};
  char err[256];
  double w = bench_wall(), c = bench_cpu();
  int rc = paradigm_divide(in, alternating, counting ? &out.ops : NULL, &out, err, sizeof err);
  bench_time t = {bench_wall() - w, bench_cpu() - c};
  if (rc != 0) {
    fprintf(stderr, "bench_paradigm_divide: %s\n", err);
    exit(1);
  }
  *ntri = out.ntri;
  free(out.tri);
  return t;
}

/* dc-alternating through the runner, timed whole; *alone gets the
** algorithm's own time (the runner's clock). */
static bench_time bd_runner(const paradigm_input *in, double *alone) {
  paradigm_result res;
  char err[256];
  double w = bench_wall(), c = bench_cpu();
  int rc = paradigm_run(paradigm_find("dc-alternating"), in, &res, err, sizeof err);
  bench_time t = {bench_wall() - w, bench_cpu() - c};
  if (rc != 0) {
    fprintf(stderr, "bench_paradigm_divide: %s\n", err);
    exit(1);
  }
  *alone = res.seconds;
  paradigm_result_free(&res);
  return t;
}

/* dc-alternating on `threads` threads gives the incremental row's triangles. */
static void bd_check(const paradigm_input *in0, int threads) {
  paradigm_input in = *in0;
  in.threads = threads;
  paradigm_result a, b;
  char err[256];
  if (paradigm_run(paradigm_find("incremental"), &in, &a, err, sizeof err) != 0
      || paradigm_run(paradigm_find("dc-alternating"), &in, &b, err, sizeof err) != 0) {
    fprintf(stderr, "bench_paradigm_divide: %s\n", err);
    exit(1);
  }
  int same = a.ntri == b.ntri && memcmp(a.tri, b.tri, 3 * a.ntri * sizeof *a.tri) == 0;
  printf("dc-alternating on %d thread%s: %zu triangles, %s the incremental algorithm's\n",
         threads, threads > 1 ? "s" : "", b.ntri, same ? "exactly" : "NOT");
  paradigm_result_free(&a), paradigm_result_free(&b);
  if (!same) exit(1);
}

/* One round: every contender once, in turn. */
static void bd_round(const char *argv0, const paradigm_input *in, uint64_t seed,
                     bench_time *t, double *overhead, double *busier) {
  rule dt = rule_delaunay();
  size_t ntri;
  paradigm_input in2 = *in;
  in2.threads = 2;
  t[BD_INCR] = bench_lot_time("bench_paradigm_divide", &dt, in->p, in->n, NULL);
  t[BD_VERT] = bd_divide(in, 0, 0, &ntri);
  t[BD_ALT1] = bd_divide(in, 1, 0, &ntri);
  t[BD_ALT1_COUNT] = bd_divide(in, 1, 1, &ntri);
  double c0[2] = {0, 0}, c1[2] = {0, 0};
  bd_thread_cpu(c0);
  t[BD_ALT2] = bd_divide(&in2, 1, 0, &ntri);
  bd_thread_cpu(c1);
  *busier = c1[0] - c0[0] > c1[1] - c0[1] ? c1[0] - c0[0] : c1[1] - c0[1];
  double alone;
  t[BD_RUN2] = bd_runner(&in2, &alone);
  *overhead = t[BD_RUN2].wall - alone;
  char args[128];
  snprintf(args, sizeof args, "%zu 1 %llu", in->n, (unsigned long long)seed);
  bench_sibling(argv0, "bench_lot_cgal", args, &t[BD_CGAL].wall, &t[BD_CGAL].cpu);
}

static int bd_dcmp(const void *x, const void *y) {
  double a = *(const double *)x, b = *(const double *)y;
  return (a > b) - (a < b);
}

static void bd_table(bench_time t[][BD_ROWS], double *overhead, double *busier, int runs) {
  bench_time m[BD_ROWS];
  for (int r = 0; r < BD_ROWS; r++) {
    bench_time v[16];
    for (int k = 0; k < runs; k++) v[k] = t[k][r];
    m[r] = bench_median_time(v, runs);
  }
  printf("\n| algorithm | time (s) | CPU (s) | / incremental | / CGAL |\n");
  printf("|---|---:|---:|---:|---:|\n");
  for (int r = 0; r < BD_ROWS; r++)
    printf("| %s | %.3f | %.3f | %.2f | %.2f |\n", bd_names[r], m[r].wall, m[r].cpu,
           m[r].wall / m[BD_INCR].wall, m[r].wall / m[BD_CGAL].wall);
  printf("\ntarget dc-alternating 1 thread / incremental <= 1.00: %.2f (CPU %.2f)\n",
         m[BD_ALT1].wall / m[BD_INCR].wall, m[BD_ALT1].cpu / m[BD_INCR].cpu);
  printf("target dc-alternating 2 threads / CGAL <= 0.35: %.2f%s\n",
         m[BD_ALT2].wall / m[BD_CGAL].wall, isnan(m[BD_CGAL].wall) ? " (CGAL not built)" : "");
  printf("counting on / off (dc-alternating, 1 thread): %.3f (CPU %.3f)\n",
         m[BD_ALT1_COUNT].wall / m[BD_ALT1].wall, m[BD_ALT1_COUNT].cpu / m[BD_ALT1].cpu);
  qsort(busier, (size_t)runs, sizeof *busier, bd_dcmp);
  printf("dc-alternating 2 threads, the busier thread's CPU: %.3f s, %.2f of CGAL's CPU "
         "(%.2f of one thread's)\n", busier[runs / 2], busier[runs / 2] / m[BD_CGAL].cpu,
         busier[runs / 2] / m[BD_ALT1].cpu);
  qsort(overhead, (size_t)runs, sizeof *overhead, bd_dcmp);
  printf("the runner's overhead (paradigm_run's time beyond the algorithm's, 2 threads): "
         "%.3f s\n", overhead[runs / 2]);
}

int main(int argc, char **argv) {
  size_t n = argc > 1 ? (size_t)strtod(argv[1], NULL) : 1000000;
  int runs = argc > 2 ? atoi(argv[2]) : 5;
  uint64_t seed = argc > 3 ? strtoull(argv[3], NULL, 10) : 1;
  if (n < 3 || n > 100000000 || runs < 1 || runs > 15) {
    fprintf(stderr, "usage: bench_paradigm_divide [N 3..1e8 [RUNS 1..15 [SEED]]]\n");
    return 2;
  }
  geom_point *p = malloc(n * sizeof *p);
  uint32_t *first = malloc(n * sizeof *first);
  if (p == NULL || first == NULL) return 1;
  sampler_points(SAMPLER_UNIFORM, seed, n, p);
  if (lot_distinct(p, n, first) != (long)n) {
    fprintf(stderr, "bench_paradigm_divide: the sample has duplicates; try another seed\n");
    return 1;
  }
  free(first);
  rule dt = rule_delaunay();
  paradigm_input in = {.p = p, .n = n, .r = &dt, .problem = PARADIGM_DELAUNAY, .seed = seed,
                       .threads = 1};
  printf("# bench_paradigm_divide: %zu uniform points (seed %llu), median of %d rounds\n", n,
         (unsigned long long)seed, runs);
  printf("(load average at start: %.2f on %ld cores)\n", bench_load(),
         sysconf(_SC_NPROCESSORS_ONLN));
  bd_check(&in, 1);
  bd_check(&in, 2);
  bench_time t[16][BD_ROWS];
  double overhead[16], busier[16];
  for (int k = 0; k < runs; k++) bd_round(argv[0], &in, seed, t[k], &overhead[k], &busier[k]);
  bd_table(t, overhead, busier, runs);
  printf("(load average at the end: %.2f)\n", bench_load());
  free(p);
  return 0;
}
