/*
** bench_paradigm_sweep.c: the constrained sweepline of 2.5.2 (row
** sweep-constrained) beside lot's constrained triangulation (the row
** incremental: the points, then the segments inserted), on uniform sites
** with random segments.
**
**   bench_paradigm_sweep [RUNS [SEED]]   (defaults 5, 1)
**
** n = 10^5 uniform sites in the unit square; the square is cut into
** 100 x 100 cells and E of them (10^3, 10^4) get a segment between two of
** their sites (segments in different cells cannot cross; about 10 sites
** per cell, so a segment crosses a few Delaunay edges).  RUNS rounds, each
** running both rows once on the same input (so both see the same load);
** prints per row the median wall and CPU seconds, the median of the paired
** ratios to incremental's wall time, and its counts per site (orientation
** and in-circle tests, location steps, flips, events, edges made, peak
** bytes), and checks that both give the same triangles.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "benchutil.h"
#include "paradigm.h"
#include "splitmix.h"

#define BPS_MAX_RUNS 16
#define BPS_CELLS 100

static const char *const bps_rows[] = {"incremental", "sweep-constrained"};

/* Segments in e random cells of the grid: two sites of the cell each. */
static size_t bps_segments(const geom_point *p, size_t n, size_t e, uint64_t seed,
                           uint32_t *seg) {
  const size_t cells = BPS_CELLS * BPS_CELLS;
  uint32_t *first = malloc(cells * sizeof *first), *second = malloc(cells * sizeof *second);
  if (first == NULL || second == NULL) exit(1);
  for (size_t c = 0; c < cells; c++) first[c] = second[c] = UINT32_MAX;
  for (size_t i = 0; i < n; i++) {
    size_t c = (size_t)(p[i].x * BPS_CELLS) + BPS_CELLS * (size_t)(p[i].y * BPS_CELLS);
    if (first[c] == UINT32_MAX) first[c] = (uint32_t)i;
    else if (second[c] == UINT32_MAX) second[c] = (uint32_t)i;
  }
  size_t ns = 0;
  uint64_t s = seed ^ 0x5e6;
  for (size_t c = 0; c < cells && ns < e; c++) {
    uint64_t left = cells - c, want = e - ns;   /* each cell kept with chance want / left */
    if (geom_splitmix64(&s) % left >= want || second[c] == UINT32_MAX) continue;
    seg[2 * ns] = first[c], seg[2 * ns + 1] = second[c], ns++;
  }
  free(first), free(second);
  return ns;
}

static paradigm_result bps_run(const char *name, const paradigm_input *in, double *wall,
                               double *cpu) {
  paradigm_result res;
  char err[256];
  double c0 = bench_cpu(), t0 = bench_wall();
  if (paradigm_run(paradigm_find(name), in, &res, err, sizeof err) != 0) {
    fprintf(stderr, "bench_paradigm_sweep: %s: %s\n", name, err);
    exit(1);
  }
  *wall = bench_wall() - t0;
  *cpu = bench_cpu() - c0;
  return res;
}

static void bps_print(size_t ns, const char *row, const double *wall, const double *cpu,
                      double *ratio, int runs, const ops_counts *o, double n) {
  printf("| %zu | %s | %.4f | %.4f | %.2f | %.2f | %.2f | %.2f | %.3f | %.2f | %.2f | %.0f |\n",
         ns, row, bench_median((double *)wall, runs), bench_median((double *)cpu, runs),
         bench_median(ratio, runs), (double)o->v[OPS_ORIENT] / n,
         (double)o->v[OPS_INCIRCLE] / n, (double)o->v[OPS_LOCATE] / n,
         (double)o->v[OPS_FLIPS] / n, (double)o->v[OPS_EVENTS] / n,
         (double)o->v[OPS_EDGES_MADE] / n, (double)o->v[OPS_PEAK_BYTES] / n);
}

static void bps_case(const geom_point *p, size_t n, size_t e, int runs, uint64_t seed,
                     const rule *dt) {
  uint32_t *seg = malloc(2 * e * sizeof *seg);
  if (seg == NULL) exit(1);
  size_t ns = bps_segments(p, n, e, seed, seg);
  paradigm_input in = {.p = p, .n = n, .r = dt, .problem = PARADIGM_CONSTRAINED,
                       .segments = seg, .nsegments = ns, .seed = seed, .threads = 1};
  double wall[2][BPS_MAX_RUNS], cpu[2][BPS_MAX_RUNS], ratio[2][BPS_MAX_RUNS];
  ops_counts ops[2];
  for (int k = 0; k < runs; k++) {
    paradigm_result r[2];
    for (int a = 0; a < 2; a++) {
      r[a] = bps_run(bps_rows[a], &in, &wall[a][k], &cpu[a][k]);
      ops[a] = r[a].ops;
      ratio[a][k] = wall[a][k] / wall[0][k];
    }
    if (r[0].ntri != r[1].ntri || memcmp(r[0].tri, r[1].tri, 3 * r[0].ntri * sizeof *r[0].tri)) {
      fprintf(stderr, "bench_paradigm_sweep: the rows' triangles differ\n");
      exit(1);
    }
    paradigm_result_free(&r[0]), paradigm_result_free(&r[1]);
  }
  for (int a = 0; a < 2; a++) bps_print(ns, bps_rows[a], wall[a], cpu[a], ratio[a], runs,
                                        &ops[a], (double)n);
  fflush(stdout);
  free(seg);
}

int main(int argc, char **argv) {
  int runs = argc > 1 ? atoi(argv[1]) : 5;
  uint64_t seed = argc > 2 ? strtoull(argv[2], NULL, 10) : 1;
  rule dt;
  char err[256];
  if (runs < 1 || runs > BPS_MAX_RUNS || rule_parse("DT", &dt, err, sizeof err) != 0) {
    fprintf(stderr, "bench_paradigm_sweep: RUNS must be 1 .. %d\n", BPS_MAX_RUNS);
    return 1;
  }
  const size_t n = 100000;
  geom_point *p = malloc(n * sizeof *p);
  if (p == NULL) return 1;
  uint64_t s = seed;
  for (size_t i = 0; i < n; i++)
    p[i].x = geom_unit53(geom_splitmix64(&s)), p[i].y = geom_unit53(geom_splitmix64(&s));
  printf("bench_paradigm_sweep: %zu uniform sites, DT, %d runs, seed %llu; load %.2f\n", n,
         runs, (unsigned long long)seed, bench_load());
  printf("| segments | algorithm | wall s | CPU s | / incremental | orient/site | "
         "incircle/site | locate/site | flips/site | events/site | edges made/site | "
         "peak bytes/site |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  bps_case(p, n, 1000, runs, seed, &dt);
  bps_case(p, n, 10000, runs, seed, &dt);
  printf("load after: %.2f\n", bench_load());
  free(p);
  return 0;
}
