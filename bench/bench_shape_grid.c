/*
** bench_shape_grid.c: each empty-shape rule's LOT on the integer grid
** beside uniform points of the same size, and which exact stages its
** predicates fall to.
**
**   bench_shape_grid [N [RUNS [RULES [gmp]]]]
**   (defaults 99856, 3, ES:square,ES:diamond,ES:hexagon,PENTAGON,ES:ellipse:2 1;
**    PENTAGON is ES:poly:1 0;0.309 0.951;-0.809 0.588;-0.809 -0.588;0.309 -0.951)
**
** For each rule of the comma list: the run of median wall time of RUNS
** incremental LOTs (lot_build, default options, seed 1) of the uniform and
** of the grid sampler, its CPU time beside it (steadier on loaded cores),
** their ratios (the target: 3 at most), and for the grid
** the exact signs of one LOT per predicate program: runs by deciding stage
** (expansions, GMP: shape_exact_stage_calls) and signs found kept
** (shape_seen_hits), and the supports and decisions found kept; with
** `gmp`, the grid's LOT once more with every exact run sent to GMP
** (geom_exact_gmp_only: no expansions and nothing kept, CPU seconds):
** what those save.  docs/performance.md, "Empty-shape rules on grids",
** has the table and the command.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "benchutil.h"
#include "lot.h"
#include "rule.h"
#include "sampler.h"
#include "shape_internal.h"

#define BENCH_PENTAGON "ES:poly:1 0;0.309 0.951;-0.809 0.588;-0.809 -0.588;0.309 -0.951"

/* One LOT of rule r on p: wall and CPU seconds. */
static bench_time bench_sg_lot(const rule *r, const geom_point *p, size_t n) {
  return bench_lot_time("bench_shape_grid", r, p, n, NULL);
}

/* The run of median wall time of runs. */
static bench_time bench_sg_median(const rule *r, const geom_point *p, size_t n, int runs) {
  bench_time t[16];
  for (int i = 0; i < runs; i++) t[i] = bench_sg_lot(r, p, n);
  return bench_median_time(t, runs);
}

static void bench_sg_snapshot(unsigned long c[SHAPE_SEEN_WHATS][3]) {
  for (int q = 0; q < SHAPE_SEEN_WHATS; q++) {
    c[q][0] = q < SHAPE_PROG_COUNT ? shape_exact_stage_calls(q, GEOM_STAGE_EXPANSION) : 0;
    c[q][1] = q < SHAPE_PROG_COUNT ? shape_exact_stage_calls(q, GEOM_STAGE_GMP) : 0;
    c[q][2] = shape_seen_hits(q);
  }
}

/* The exact signs since `since`, "expansions/GMP/reused" per program that
** had any. */
static void bench_sg_counts(unsigned long since[SHAPE_SEEN_WHATS][3], char *out,
                            size_t size) {
  static const char *const names[SHAPE_SEEN_WHATS] = {"cross", "det3h", "det3w", "det4",
                                                      "corner", "ellipse", "support",
                                                      "search", "decision"};
  unsigned long now[SHAPE_SEEN_WHATS][3];
  bench_sg_snapshot(now);
  size_t used = 0;
  out[0] = 0;
  for (int q = 0; q < SHAPE_SEEN_WHATS && used < size; q++) {
    unsigned long x = now[q][0] - since[q][0], g = now[q][1] - since[q][1];
    unsigned long re = now[q][2] - since[q][2];
    if (x + g + re > 0)
      used += (size_t)snprintf(out + used, size - used, "%s%s %lu/%lu/%lu", used ? ", " : "",
                               names[q], x, g, re);
  }
  if (used == 0) snprintf(out, size, "none");
}

/* One table row: rule `name` on uniform and grid points. */
static int bench_sg_row(const char *name, const geom_point *u, const geom_point *g, size_t n,
                        int runs, int gmp) {
  rule r;
  char err[256], counts[512], slow[32] = "";
  if (rule_parse(name, &r, err, sizeof err) != 0) {
    fprintf(stderr, "bench_shape_grid: %s\n", err);
    return 1;
  }
  bench_time tu = bench_sg_median(&r, u, n, runs);
  unsigned long since[SHAPE_SEEN_WHATS][3];
  bench_sg_snapshot(since);
  bench_sg_lot(&r, g, n);
  bench_sg_counts(since, counts, sizeof counts);
  bench_time tg = bench_sg_median(&r, g, n, runs);
  if (gmp) {
    int was = geom_exact_gmp_only(1);
    snprintf(slow, sizeof slow, " %.3f |", bench_sg_lot(&r, g, n).cpu);
    geom_exact_gmp_only(was);
  }
  printf("| %s | %.3f (CPU %.3f) | %.3f (CPU %.3f) | %.2f (CPU %.2f) | %s |%s\n", name, tu.wall,
         tu.cpu, tg.wall, tg.cpu, tg.wall / tu.wall, tg.cpu / tu.cpu, counts, slow);
  fflush(stdout);
  return 0;
}

int main(int argc, char **argv) {
  size_t n = argc > 1 ? (size_t)strtod(argv[1], NULL) : 99856;
  int runs = argc > 2 ? atoi(argv[2]) : 3;
  const char *rules = argc > 3 ? argv[3]
                               : "ES:square,ES:diamond,ES:hexagon," BENCH_PENTAGON
                                 ",ES:ellipse:2 1";
  int gmp = argc > 4 && strcmp(argv[4], "gmp") == 0;
  if (n < 3 || n > 20000000 || runs < 1 || runs > 15) {
    fprintf(stderr, "usage: bench_shape_grid [N 3..2e7 [RUNS 1..15 [RULES [gmp]]]]\n");
    return 2;
  }
  geom_point *u = malloc(n * sizeof *u), *g = malloc(n * sizeof *g);
  char *list = strdup(rules);
  if (u == NULL || g == NULL || list == NULL) return 1;
  sampler_points(SAMPLER_UNIFORM, 1, n, u);
  sampler_points(SAMPLER_GRID, 1, n, g);
  printf("# bench_shape_grid: %zu points (seed 1), medians of %d runs; load average %.2f\n\n"
         "| rule | uniform (s) | grid (s) | grid / uniform | grid's exact signs: "
         "expansions/GMP/reused |%s\n|---|---:|---:|---:|---|%s\n",
         n, runs, bench_load(), gmp ? " grid, GMP only (CPU s) |" : "", gmp ? "---:|" : "");
  int rc = 0;
  char *save = NULL;
  for (char *s = strtok_r(list, ",", &save); s && rc == 0; s = strtok_r(NULL, ",", &save))
    rc = bench_sg_row(s, u, g, n, runs, gmp);
  printf("\n(load average at end: %.2f)\n", bench_load());
  free(list);
  free(u);
  free(g);
  return rc;
}
