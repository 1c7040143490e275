/*
** benchutil.c: clocks, medians, the load average and polygons for bench/ (see
** benchutil.h).
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "benchutil.h"
#include "lot.h"

static double bench_clock(clockid_t id) {
  struct timespec ts;
  clock_gettime(id, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double bench_wall(void) { return bench_clock(CLOCK_MONOTONIC); }

double bench_cpu(void) { return bench_clock(CLOCK_PROCESS_CPUTIME_ID); }

static int bench_cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

double bench_median(double *v, int n) {
  qsort(v, (size_t)n, sizeof *v, bench_cmp);
  return v[n / 2];
}

static int bench_cmp_time(const void *a, const void *b) {
  return bench_cmp(&((const bench_time *)a)->wall, &((const bench_time *)b)->wall);
}

bench_time bench_median_time(bench_time *t, int n) {
  qsort(t, (size_t)n, sizeof *t, bench_cmp_time);
  return t[n / 2];
}

geom_point *bench_polygon(const char *prog, bench_sampler fn, size_t n) {
  geom_point *p = malloc(n * sizeof *p);
  sampler_rng g;
  sampler_seed(&g, 1, 0);
  if (p == NULL || fn(&g, n, p) != 0) {
    fprintf(stderr, "%s: sampler failed for n = %zu\n", prog, n);
    exit(1);
  }
  return p;
}

double bench_load(void) {
  double l = NAN;
  FILE *f = fopen("/proc/loadavg", "r");
  if (f != NULL) {
    if (fscanf(f, "%lf", &l) != 1) l = NAN;
    fclose(f);
  }
  return l;
}

void bench_sibling(const char *argv0, const char *name, const char *args, double *wall,
                   double *cpu) {
  char cmd[4400];
  const char *slash = strrchr(argv0, '/');
  int dir = slash ? (int)(slash - argv0 + 1) : 0;
  snprintf(cmd, sizeof cmd, "%.*s%s %s 2>/dev/null", dir, argv0, name, args);
  *wall = *cpu = NAN;
  FILE *f = popen(cmd, "r");
  if (f == NULL) return;
  char line[256];
  while (fgets(line, sizeof line, f)) {
    sscanf(line, "cgal_seconds %lf", wall);
    sscanf(line, "cgal_cpu_seconds %lf", cpu);
  }
  pclose(f);
}

bench_time bench_lot_time(const char *prog, const struct rule *r, const geom_point *p, size_t n,
                          struct lot_stats *stats) {
  lot_options o;
  lot_options_init(&o, r);
  lot *L;
  char err[256];
  double c0 = bench_cpu(), t0 = bench_wall();
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) {
    fprintf(stderr, "%s: %s\n", prog, err);
    exit(1);
  }
  bench_time t = {bench_wall() - t0, bench_cpu() - c0};
  if (stats != NULL) *stats = *lot_get_stats(L);
  lot_free(L);
  return t;
}
