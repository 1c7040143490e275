/*
** bench_cpdt.c: the workbench's Delaunay algorithms for convex polygons
** (cpdt/) on polygons of 10^3 .. 10^6 vertices: CPU seconds (median of
** several runs) and incircle tests per size, the fitted exponent of each
** (least squares on log-log, study_cpdt_slope), and the fastest beside
** lot's general Delaunay triangulation of the same 10^6 points.  Results:
** docs/performance.md.
**   bench_cpdt [vector|circle] [MAX_N] [RUNS]
** The quadratic algorithms stop early (circum-walk at 10^4; circum,
** circum-random and incremental at 10^5): their cost at 10^6 is hours.
** On circle polygons every limit is ten times lower: their vertices are
** nearly cocircular, so most incircle tests take the exact stages.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "benchutil.h"
#include "cpdt.h"
#include "lot.h"
#include "rule.h"
#include "study_cpdt.h"

static const size_t bc_cap[CPDT_ALGORITHM_COUNT] = {
  [CPDT_CIRCUM] = 100000, [CPDT_CIRCUM_RANDOM] = 100000, [CPDT_CIRCUM_WALK] = 10000,
  [CPDT_DIVIDE] = 0, [CPDT_INCREMENTAL] = 100000, [CPDT_RANDOM] = 0, [CPDT_FLIP] = 0,
};

/* Median CPU seconds of `runs` runs of algorithm a on p; its counts. */
static double bc_time(const geom_point *p, size_t n, int a, int runs, uint32_t *tri,
                      cpdt_counts *c) {
  double t[16];
  for (int r = 0; r < runs; r++) {
    double t0 = bench_cpu();
    if (cpdt_triangulate(p, n, a, 1, tri, c) != 0) {
      fprintf(stderr, "bench_cpdt: out of memory\n");
      exit(1);
    }
    t[r] = bench_cpu() - t0;
  }
  return bench_median(t, runs);
}

/* lot's DT of the same points, median CPU seconds. */
static double bc_lot(const geom_point *p, size_t n, int runs) {
  rule r;
  char err[256];
  if (rule_parse("DT", &r, err, sizeof err) != 0) exit(1);
  lot_options o;
  lot_options_init(&o, &r);
  double t[16];
  for (int k = 0; k < runs; k++) {
    lot *L;
    double t0 = bench_cpu();
    if (lot_build(&L, p, n, &o, err, sizeof err) != 0) {
      fprintf(stderr, "bench_cpdt: lot: %s\n", err);
      exit(1);
    }
    t[k] = bench_cpu() - t0;
    lot_free(L);
  }
  return bench_median(t, runs);
}

static void bc_row(study_cpdt_cell *cells, size_t n, const geom_point *p, int runs,
                   uint32_t *tri, size_t cap_div) {
  printf("%8zu", n);
  for (int a = 0; a < CPDT_ALGORITHM_COUNT; a++) {
    study_cpdt_cell *c = &cells[a];
    *c = (study_cpdt_cell){.n = n, .algorithm = a};
    if (bc_cap[a] != 0 && n > bc_cap[a] / cap_div) {
      printf(" %21s", "-");
      continue;
    }
    cpdt_counts k;
    c->mean[STUDY_CPDT_SECONDS] = bc_time(p, n, a, runs, tri, &k);
    c->mean[STUDY_CPDT_INCIRCLE] = (double)k.incircle;
    printf(" %9.4f %11.4g", c->mean[STUDY_CPDT_SECONDS], (double)k.incircle);
  }
  printf("\n");
}

int main(int argc, char **argv) {
  int circle = argc > 1 && strcmp(argv[1], "circle") == 0;
  size_t max_n = argc > 2 ? (size_t)atof(argv[2]) : 1000000;
  int runs = argc > 3 ? atoi(argv[3]) : 3;
  if (runs < 1 || runs > 16) runs = 3;
  printf("# bench_cpdt: %s polygons, CPU seconds (median of %d) and incircle tests; load %.2f\n",
         circle ? "circle" : "vector", runs, bench_load());
  printf("%8s", "n");
  for (int a = 0; a < CPDT_ALGORITHM_COUNT; a++) printf(" %21s", cpdt_algorithm_name(a));
  printf("\n");
  study_cpdt_cell cells[16 * CPDT_ALGORITHM_COUNT];
  size_t nc = 0, last = 0;
  for (size_t n = 1000; n <= max_n && nc + CPDT_ALGORITHM_COUNT <= 16 * CPDT_ALGORITHM_COUNT;
       n = n % 3 == 1 ? n * 3 : n / 3 * 10) {
    geom_point *p = bench_polygon("bench_cpdt", circle ? sampler_circle : sampler_vector, n);
    uint32_t *tri = malloc(3 * n * sizeof *tri);
    if (tri == NULL) return 1;
    bc_row(cells + nc, n, p, runs, tri, circle ? 10 : 1);
    nc += CPDT_ALGORITHM_COUNT;
    last = n;
    free(tri);
    free(p);
  }
  printf("%8s", "exponent");
  for (int a = 0; a < CPDT_ALGORITHM_COUNT; a++)
    printf(" %9.2f %11.2f", study_cpdt_slope(cells, nc, a, STUDY_CPDT_SECONDS),
           study_cpdt_slope(cells, nc, a, STUDY_CPDT_INCIRCLE));
  printf("\n");
  int best = CPDT_DIVIDE;
  const study_cpdt_cell *row = cells + nc - CPDT_ALGORITHM_COUNT;
  for (int a = 0; a < CPDT_ALGORITHM_COUNT; a++)
    if (row[a].mean[STUDY_CPDT_SECONDS] > 0 &&
        row[a].mean[STUDY_CPDT_SECONDS] < row[best].mean[STUDY_CPDT_SECONDS])
      best = a;
  geom_point *p = bench_polygon("bench_cpdt", circle ? sampler_circle : sampler_vector, last);
  double tl = bc_lot(p, last, runs);
  printf("fastest at n = %zu: %s %.4f s; lot's DT of the same points %.4f s (%.2fx)\n", last,
         cpdt_algorithm_name(best), row[best].mean[STUDY_CPDT_SECONDS], tl,
         tl / row[best].mean[STUDY_CPDT_SECONDS]);
  free(p);
  return 0;
}
