/*
** bench_convex.c: the cost of each random convex n-gon sampler of the
** registry (samplers/gon.c) as n grows, and its fitted exponent.
**
**   bench_convex [MAXN [RUNS [SAMPLERS]]]   (defaults 1000000, 3, all)
**
** For each sampler (and region: square, and the disc for the point-based
** ones) and n = 10^3, 10^4, ... MAXN: the median CPU time of RUNS polygons
** (polygon i of seed 1, one thread: on the shared machine CPU time is the
** steady figure, the wall time of an idle core); a sampler that fails at
** some n (iteration in the square, circle: no strictly convex n-gon in
** doubles) or exceeds 10 CPU seconds stops there.  The exponent is the least-squares slope of
** log time against log n over the sizes measured (1 for O(n), about 1.1
** for O(n log n) over these sizes).  docs/performance.md, "Random convex
** polygons", has the table and the command.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "benchutil.h"
#include "sampler.h"

#define BENCH_SIZES 8
#define BENCH_BUDGET 10.0   /* seconds for one polygon: larger sizes skipped */

/* One polygon's wall and CPU time, or a negative wall time on failure. */
static bench_time bench_convex_one(const sampler_gon *s, int region, size_t n, uint64_t i,
                                   geom_point *v) {
  sampler_gon_params p = {(sampler_region)region, 0, NULL};
  sampler_gon_info info;
  double c0 = bench_cpu(), t0 = bench_wall();
  int rc = sampler_gon_draw(s, &p, 1, i, n, v, &info);
  bench_time t = {bench_wall() - t0, bench_cpu() - c0};
  if (rc != 0) t.wall = -1;
  return t;
}

/* The least-squares slope of log y against log x. */
static double bench_slope(const double *x, const double *y, int k) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < k; i++) {
    double a = log(x[i]), b = log(y[i]);
    sx += a;
    sy += b;
    sxx += a * a;
    sxy += a * b;
  }
  double d = k * sxx - sx * sx;
  return k >= 2 && d > 0 ? (k * sxy - sx * sy) / d : NAN;
}

static void bench_convex_row(const sampler_gon *s, int region, size_t maxn, int runs) {
  double xs[BENCH_SIZES], ys[BENCH_SIZES];
  int k = 0;
  printf("%-10s %-8s", s->name, s->regions ? sampler_region_name(region) : "-");
  geom_point *v = malloc(maxn * sizeof *v);
  for (size_t n = 1000; n <= maxn && v != NULL && k < BENCH_SIZES; n *= 10) {
    bench_time t[16];
    int ok = 1, failed = 0;
    for (int r = 0; r < runs && ok; r++) {
      t[r] = bench_convex_one(s, region, n, (uint64_t)r, v);
      failed = t[r].wall < 0;
      ok = !failed && t[r].cpu < BENCH_BUDGET;
      t[r].wall = t[r].cpu;   /* the median of CPU times */
    }
    if (!ok) {
      printf("  %8s", failed ? "fails" : "slow");
      break;
    }
    bench_time m = bench_median_time(t, runs);   /* sorted by CPU time */
    printf("  %8.4f", m.cpu);
    xs[k] = (double)n;
    ys[k++] = m.cpu;
  }
  free(v);
  printf("   exponent %.2f\n", bench_slope(xs, ys, k));
}

int main(int argc, char **argv) {
  size_t maxn = argc > 1 ? (size_t)strtod(argv[1], NULL) : 1000000;
  int runs = argc > 2 ? atoi(argv[2]) : 3;
  const char *only = argc > 3 ? argv[3] : NULL;
  if (maxn < 1000 || runs < 1 || runs > 16) {
    fprintf(stderr, "usage: bench_convex [MAXN >= 1000 [RUNS 1..16 [SAMPLERS]]]\n");
    return 2;
  }
  printf("random convex n-gons: median CPU seconds of %d polygons, one thread; load %.2f\n",
         runs, bench_load());
  printf("%-10s %-8s", "sampler", "region");
  for (size_t n = 1000; n <= maxn; n *= 10) printf("  %8.0e", (double)n);
  printf("\n");
  for (size_t i = 0; i < sampler_gons_count; i++) {
    const sampler_gon *s = &sampler_gons[i];
    if (only != NULL && strstr(only, s->name) == NULL) continue;
    if (strcmp(s->name, "naive") == 0) continue;   /* n <= 10 */
    for (int r = 0; r < SAMPLER_REGION_COUNT; r++) {
      if (s->regions == 0 ? r != 0 : !(s->regions & (1u << r))) continue;
      if (r == SAMPLER_REGION_TRIANGLE) continue;   /* as the square */
      bench_convex_row(s, r, maxn, runs);
    }
  }
  return 0;
}
