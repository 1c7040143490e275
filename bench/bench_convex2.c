/*
** bench_convex2.c: the chapter-6 convex n-gon samplers of samplers/tridt.c,
** bounce.c, dual.c and priorart.c, timed for n = 10^3 .. MAX (10^6 by
** default): the median CPU time of RUNS draws (3; draw r is stream r of
** seed 1), how many of them doubles realised (the others returned -1),
** and the exponent of n fitted by least squares to log time over the sizes
** whose draws all succeeded, beside the thesis's cost (triangulation O(n),
** bounce O(n log n) for 2n events, dual O(n log n) with the vector
** method inside, GeoBench O(n log n)).  Then, with --limit, the share of
** triangulation draws refused at n = 1, 1.5, 2, 3 x 10^6 (where doubles
** stop realising the drawn triangulation).  CPU time (the samplers are
** single-threaded) and the load average are printed: the machine is
** shared.  Usage: bench_convex2 [MAX [RUNS]] [--limit]
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "benchutil.h"
#include "sampler.h"

typedef struct bc2_sampler {
  const char *name, *cost;
  sampler_gon_fn fn;
  int law;
  const char *inner;
} bc2_sampler;

static const bc2_sampler bc2_samplers[] = {
  {"triangulation", "n", sampler_gon_triangulation, 0, NULL},
  {"bounce law 0", "n log n", sampler_gon_bounce, 0, NULL},
  {"bounce law 1", "n log n", sampler_gon_bounce, 1, NULL},
  {"dual (of vector)", "n log n", sampler_gon_dual, 0, NULL},
  {"dual (of triangulation)", "n", sampler_gon_dual, 0, "triangulation"},
  {"geobench", "n log n", sampler_gon_geobench, 0, NULL},
};
#define BC2_COUNT (sizeof bc2_samplers / sizeof bc2_samplers[0])

/* Median CPU seconds of runs draws of size n; *ok gets how many succeeded. */
static double bc2_time(const bc2_sampler *s, size_t n, int runs, geom_point *p, int *ok) {
  double t[16];
  *ok = 0;
  for (int r = 0; r < runs; r++) {
    sampler_rng g;
    sampler_gon_params prm = {SAMPLER_REGION_DISC, s->law, s->inner};
    sampler_seed(&g, 1, (uint64_t)r);
    double c0 = bench_cpu();
    int rc = s->fn(&g, n, &prm, p, NULL);
    t[r] = bench_cpu() - c0;
    if (rc == SAMPLER_ENOMEM) {
      fprintf(stderr, "bench_convex2: out of memory at n = %zu\n", n);
      exit(1);
    }
    *ok += rc == 0;
  }
  return bench_median(t, runs);
}

/* The least-squares slope of log y against log x over m points. */
static double bc2_slope(const double *x, const double *y, int m) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < m; i++) {
    double lx = log(x[i]), ly = log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  return m > 1 ? (m * sxy - sx * sy) / (m * sxx - sx * sx) : NAN;
}

static void bc2_row(const bc2_sampler *s, size_t max, int runs, geom_point *p) {
  double xs[8], ys[8];
  int m = 0;
  printf("| %s |", s->name);
  for (size_t n = 1000; n <= max; n *= 10) {
    int ok;
    double t = bc2_time(s, n, runs, p, &ok);
    printf(" %.4f (%d/%d) |", t, ok, runs);
    if (ok == runs && t > 0) xs[m] = (double)n, ys[m++] = t;
    fflush(stdout);
  }
  printf(" %.2f | %s |\n", bc2_slope(xs, ys, m), s->cost);
}

static void bc2_limit(geom_point *p) {
  static const size_t ns[] = {1000000, 1500000, 2000000, 3000000};
  printf("\n| n | triangulation draws refused |\n|---:|---:|\n");
  for (size_t k = 0; k < sizeof ns / sizeof ns[0]; k++) {
    int ok;
    (void)bc2_time(&bc2_samplers[0], ns[k], 5, p, &ok);
    printf("| %zu | %d of 5 |\n", ns[k], 5 - ok);
    fflush(stdout);
  }
}

int main(int argc, char **argv) {
  size_t max = 1000000;
  int runs = 3, limit = 0, pos = 0;
  for (int i = 1; i < argc; i++) {
    if (strcmp(argv[i], "--limit") == 0) limit = 1;
    else if (pos++ == 0) max = (size_t)strtoull(argv[i], NULL, 10);
    else runs = atoi(argv[i]);
  }
  if (max < 1000 || runs < 1 || runs > 15) {
    fprintf(stderr, "usage: bench_convex2 [MAX >= 1000 [RUNS 1..15]] [--limit]\n");
    return 2;
  }
  geom_point *p = malloc((limit && max < 3000000 ? 3000000 : max) * sizeof *p);
  if (p == NULL) return 1;
  printf("# bench_convex2: median CPU seconds of %d draws (realised/drawn), seed 1\n", runs);
  printf("(load average at start: %.2f)\n\n| sampler |", bench_load());
  for (size_t n = 1000; n <= max; n *= 10) printf(" n = %zu |", n);
  printf(" fitted exponent | thesis |\n|---|");
  for (size_t n = 1000; n <= max; n *= 10) printf("---:|");
  printf("---:|---|\n");
  for (size_t k = 0; k < BC2_COUNT; k++) bc2_row(&bc2_samplers[k], max, runs, p);
  if (limit) bc2_limit(p);
  free(p);
  return 0;
}
