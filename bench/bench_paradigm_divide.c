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
** Then the empty-shape rules (2.6.6), on the first min(N, 10^5) points:
** for ES:square, ES:hexagon, ES:triangle and an ellipse, lot's incremental
** ES triangulation (lot_build) beside dc-vertical, dc-alternating on one
** and two threads and Watson's insertion (quaternary order), each checked
** equal to the incremental row's triangles first; medians of RUNS rounds,
** and the counts per site of one counted run.
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

/* ---- the empty-shape rules ---- */

enum { BE_INCR, BE_VERT, BE_ALT1, BE_ALT2, BE_WATSON, BE_ROWS };
static const char *const be_rows[BE_ROWS] = {"incremental", "dc-vertical", "dc-alternating",
                                             "dc-alternating", "watson"};

/* Row k of be_rows through the runner (two threads for BE_ALT2): its
** result, checked equal to ref's triangles when ref is given; exits on
** failure or a difference. */
static paradigm_result be_run(const paradigm_input *in0, int k, const paradigm_result *ref) {
  paradigm_input in = *in0;
  in.threads = k == BE_ALT2 ? 2 : 1;
  paradigm_result res;
  char err[256];
  if (paradigm_run(paradigm_find(be_rows[k]), &in, &res, err, sizeof err) != 0) {
    fprintf(stderr, "bench_paradigm_divide: %s: %s\n", be_rows[k], err);
    exit(1);
  }
  if (ref != NULL && (res.ntri != ref->ntri
                      || memcmp(res.tri, ref->tri, 3 * res.ntri * sizeof *res.tri) != 0)) {
    fprintf(stderr, "bench_paradigm_divide: %s under %s: NOT the incremental triangles\n",
            be_rows[k], in.r->name);
    exit(1);
  }
  return res;
}

/* One round for rule r: every row once, in turn (divide and conquer
** directly, without the runner's checks and canonical sort, as above). */
static void be_round(const paradigm_input *in, bench_time *t) {
  size_t ntri;
  paradigm_input in2 = *in;
  in2.threads = 2;
  t[BE_INCR] = bench_lot_time("bench_paradigm_divide", in->r, in->p, in->n, NULL);
  t[BE_VERT] = bd_divide(in, 0, 0, &ntri);
  t[BE_ALT1] = bd_divide(in, 1, 0, &ntri);
  t[BE_ALT2] = bd_divide(&in2, 1, 0, &ntri);
  double w = bench_wall(), c = bench_cpu();
  paradigm_result res = be_run(in, BE_WATSON, NULL);
  t[BE_WATSON] = (bench_time){bench_wall() - w, bench_cpu() - c};
  paradigm_result_free(&res);
}

/* Rule `spec` on the points of in: check, time, count, print its rows. */
static void be_rule(const paradigm_input *in0, const char *spec, int runs) {
  rule r;
  char err[256];
  if (rule_parse(spec, &r, err, sizeof err) != 0) {
    fprintf(stderr, "bench_paradigm_divide: %s\n", err);
    exit(1);
  }
  paradigm_input in = *in0;
  in.r = &r;
  paradigm_result res[BE_ROWS];
  for (int k = 0; k < BE_ROWS; k++) res[k] = be_run(&in, k, k ? &res[0] : NULL);
  bench_time t[16][BE_ROWS], m[BE_ROWS];
  for (int k = 0; k < runs; k++) be_round(&in, t[k]);
  for (int k = 0; k < BE_ROWS; k++) {
    bench_time v[16];
    for (int j = 0; j < runs; j++) v[j] = t[j][k];
    m[k] = bench_median_time(v, runs);
  }
  double n = (double)in.n;
  for (int k = 0; k < BE_ROWS; k++) {
    const uint64_t *c = res[k].ops.v;
    printf("| %s | %s%s | %.3f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", spec, be_rows[k],
           k == BE_ALT2 ? ", 2 threads" : k == BE_INCR ? " (lot_build)" : "", m[k].wall,
           m[k].wall / m[BE_INCR].wall, (double)c[OPS_ORIENT] / n, (double)c[OPS_INSHAPE] / n,
           (double)c[OPS_EDGES_MADE] / n, (double)c[OPS_LOCATE] / n);
  }
  for (int k = 0; k < BE_ROWS; k++) paradigm_result_free(&res[k]);
}

static void be_table(const geom_point *p, size_t n, uint64_t seed, int runs) {
  static const char *const shapes[] = {"ES:square", "ES:hexagon", "ES:triangle",
                                       "ES:ellipse:2 1"};
  paradigm_input in = {.p = p, .n = n, .problem = PARADIGM_DELAUNAY, .seed = seed,
                       .threads = 1};
  printf("\n# empty-shape rules: the first %zu points, median of %d rounds; counts per site "
         "of one counted run\n", n, runs);
  printf("\n| rule | algorithm | time (s) | / incremental | orient/site | inshape/site "
         "| edges made/site | locate/site |\n|---|---|---:|---:|---:|---:|---:|---:|\n");
  for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; k++) be_rule(&in, shapes[k], runs);
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
  be_table(p, n < 100000 ? n : 100000, seed, runs);
  printf("(load average at the end: %.2f)\n", bench_load());
  free(p);
  return 0;
}
