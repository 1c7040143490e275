/*
** bench_select.c: the selection algorithms of 2.4 (paradigms/select.c)
** beside the incremental row, on uniform sites, for DT or an empty-shape
** rule.
**
**   bench_select [RUNS [SEED [P [RULE]]]]   (defaults 3, 1, 1, DT)
**
** For n = 10^4 and 10^5, RUNS rounds, each running every algorithm once
** on the same points (so all see the same load); prints per algorithm the
** median wall and CPU seconds, the median of the paired ratios to the
** incremental row's wall time, and the counts of its last run per site:
** orientation and in-circle (in-shape) tests, buckets examined per
** triangle (beside the thesis's 2/p + 3/sqrt(p) + 1), the peak boundary in
** edges.  The two
** scans (select-stack, select-queue) are O(n^2) and run at 10^4 only, and
** for DT only (an empty-shape rule's in-shape test is slower).
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "benchutil.h"
#include "paradigm.h"
#include "splitmix.h"

static const char *const bs_rows[] = {"incremental", "select-stack", "select-queue",
                                      "select-strip", "select-buckets"};
#define BS_ROWS (sizeof bs_rows / sizeof bs_rows[0])
#define BS_MAX_RUNS 16

static void bs_run(const char *name, const paradigm_input *in, double *wall, double *cpu,
                   ops_counts *ops, size_t *ntri) {
  paradigm_result res;
  char err[256];
  double c0 = bench_cpu(), t0 = bench_wall();
  if (paradigm_run(paradigm_find(name), in, &res, err, sizeof err) != 0) {
    fprintf(stderr, "bench_select: %s: %s\n", name, err);
    exit(1);
  }
  *wall = bench_wall() - t0;
  *cpu = bench_cpu() - c0;
  *ops = res.ops;
  *ntri = res.ntri;
  paradigm_result_free(&res);
}

/* The scans, O(n^2): run at 10^4 only, for DT. */
static int bs_skip(size_t a, size_t n, const rule *r) {
  return (n > 20000 || !rule_is_delaunay(r))
         && (strcmp(bs_rows[a], "select-stack") == 0 || strcmp(bs_rows[a], "select-queue") == 0);
}

static void bs_size(size_t n, int runs, uint64_t seed, double p, const rule *dt) {
  geom_point *pt = malloc(n * sizeof *pt);
  if (pt == NULL) {
    fprintf(stderr, "bench_select: out of memory for %zu points\n", n);
    exit(1);
  }
  uint64_t s = seed;
  for (size_t i = 0; i < n; i++)
    pt[i].x = geom_unit53(geom_splitmix64(&s)), pt[i].y = geom_unit53(geom_splitmix64(&s));
  paradigm_input in = {.p = pt, .n = n, .r = dt, .problem = PARADIGM_DELAUNAY, .seed = seed,
                       .threads = 1, .param = p};
  double wall[BS_ROWS][BS_MAX_RUNS], cpu[BS_ROWS][BS_MAX_RUNS], ratio[BS_ROWS][BS_MAX_RUNS];
  ops_counts ops[BS_ROWS];
  size_t ntri[BS_ROWS];
  for (int k = 0; k < runs; k++)
    for (size_t a = 0; a < BS_ROWS; a++) {
      if (bs_skip(a, n, dt)) continue;
      bs_run(bs_rows[a], &in, &wall[a][k], &cpu[a][k], &ops[a], &ntri[a]);
      ratio[a][k] = wall[a][k] / wall[0][k];
    }
  for (size_t a = 0; a < BS_ROWS; a++) {
    if (bs_skip(a, n, dt)) {
      printf("| %zu | %s | (O(n^2): not run) | | | | | | |\n", n, bs_rows[a]);
      continue;
    }
    double t = (double)ntri[a], nn = (double)n;
    double tests = (double)(ops[a].v[OPS_INCIRCLE] + ops[a].v[OPS_INSHAPE]);
    printf("| %zu | %s | %.4f | %.4f | %.2f | %.1f | %.1f | %.3f | %llu |\n", n, bs_rows[a],
           bench_median(wall[a], runs), bench_median(cpu[a], runs), bench_median(ratio[a], runs),
           (double)ops[a].v[OPS_ORIENT] / nn, tests / nn, (double)ops[a].v[OPS_BUCKETS] / t,
           (unsigned long long)ops[a].v[OPS_PEAK_BYTES] / 8);
  }
  fflush(stdout);
  free(pt);
}

int main(int argc, char **argv) {
  int runs = argc > 1 ? atoi(argv[1]) : 3;
  uint64_t seed = argc > 2 ? strtoull(argv[2], NULL, 10) : 1;
  double p = argc > 3 ? strtod(argv[3], NULL) : 1;
  rule r;
  char err[256];
  if (rule_parse(argc > 4 ? argv[4] : "DT", &r, err, sizeof err) != 0) {
    fprintf(stderr, "bench_select: %s\n", err);
    return 1;
  }
  if (runs < 1 || runs > BS_MAX_RUNS || !(p >= 0.0625 && p <= 1e6)) {
    fprintf(stderr, "bench_select: RUNS must be 1 .. %d and P in [0.0625, 1e6]\n", BS_MAX_RUNS);
    return 1;
  }
  printf("bench_select: uniform sites, %s, %d runs, seed %llu, p = %g (b(p) = %.3f); "
         "load %.2f\n", rule_name(&r), runs, (unsigned long long)seed, p,
         2 / p + 3 / sqrt(p) + 1, bench_load());
  printf("| n | algorithm | wall s | CPU s | / incremental | orient/site | in-shape/site | "
         "buckets/triangle | peak boundary |\n|---|---|---|---|---|---|---|---|---|\n");
  bs_size(10000, runs, seed, p, &r);
  bs_size(100000, runs, seed, p, &r);
  printf("load after: %.2f\n", bench_load());
  return 0;
}
