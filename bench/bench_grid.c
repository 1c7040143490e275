/*
** bench_grid.c: the Delaunay triangulation on inputs whose predicates fall
** to the exact path (the integer grid, a parabola, a circle) beside uniform
** points of the same size, and what one exact call costs.
**
**   bench_grid [N [RUNS [SAMPLERS]]]   (defaults 1000000, 3, uniform,grid,parabola,circle)
**
** For each sampler of the comma list (samplers/sampler.h, seed 1):
**   1. fliplab's DT (lot_build, default options), median wall and CPU time
**      of RUNS runs, alternating with CGAL's Delaunay_triangulation_2 on the
**      same points (bench_lot_cgal N 1 1 SAMPLER, a child process, built
**      when CGAL is found), and the ratio;
**   2. the exact fallback calls of one DT run, per predicate (orient,
**      incircle) and per deciding stage (128-bit integers, expansions,
**      GMP: geom_exact_stage_calls);
**   3. the same DT with every fallback sent to GMP (geom_exact_gmp_only),
**      median of RUNS: what the faster stages save.
** Then the cost of one exact call (geom_orient_exact, geom_incircle_exact)
** in nanoseconds, by stage, on the degenerate tuples of each input: three
** consecutive grid points of a row, the four corners of a grid square
** (exactly collinear, cocircular), consecutive points of the parabola and
** of the circle sorted by angle.  docs/performance.md, "Grids and integer
** coordinates", has the table and the command.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "benchutil.h"
#include "lot.h"
#include "sampler.h"

/* One DT build: wall and CPU seconds. */
static bench_time bench_grid_dt(const geom_point *p, size_t n) {
  rule dt = rule_delaunay();
  return bench_lot_time("bench_grid", &dt, p, n, NULL);
}

/* The exact calls of predicate q since `since` (a snapshot), by stage. */
static void bench_grid_counts(geom_pred q, const unsigned long since[GEOM_STAGE_COUNT],
                              char *out, size_t size) {
  unsigned long c[GEOM_STAGE_COUNT];
  for (int s = 0; s < GEOM_STAGE_COUNT; s++) c[s] = geom_exact_stage_calls(q, s) - since[s];
  snprintf(out, size, "%lu / %lu / %lu", c[GEOM_STAGE_INT], c[GEOM_STAGE_EXPANSION],
           c[GEOM_STAGE_GMP]);
}

static void bench_grid_snapshot(unsigned long snap[GEOM_PRED_COUNT][GEOM_STAGE_COUNT]) {
  for (int q = 0; q < GEOM_PRED_COUNT; q++)
    for (int s = 0; s < GEOM_STAGE_COUNT; s++) snap[q][s] = geom_exact_stage_calls(q, s);
}

/* One table row: the timings and counts of one sampler. */
static void bench_grid_row(const char *argv0, sampler_points_kind k, size_t n, int runs) {
  geom_point *p = malloc(n * sizeof *p);
  if (p == NULL) exit(1);
  sampler_points(k, 1, n, p);
  bench_time f[16], g[16], c[16];
  char args[128];
  snprintf(args, sizeof args, "%zu 1 1 %s", n, sampler_points_name(k));
  int have_cgal = 1;
  unsigned long snap[GEOM_PRED_COUNT][GEOM_STAGE_COUNT];
  char co[96], ci[96];
  for (int r = 0; r < runs; r++) {
    bench_grid_snapshot(snap);
    f[r] = bench_grid_dt(p, n);
    if (r == 0) {
      bench_grid_counts(GEOM_PRED_ORIENT, snap[GEOM_PRED_ORIENT], co, sizeof co);
      bench_grid_counts(GEOM_PRED_INCIRCLE, snap[GEOM_PRED_INCIRCLE], ci, sizeof ci);
    }
    bench_sibling(argv0, "bench_lot_cgal", args, &c[r].wall, &c[r].cpu);
    have_cgal &= !isnan(c[r].wall);
    int was = geom_exact_gmp_only(1);
    g[r] = bench_grid_dt(p, n);
    geom_exact_gmp_only(was);
  }
  bench_time tf = bench_median_time(f, runs), tg = bench_median_time(g, runs);
  bench_time tc = have_cgal ? bench_median_time(c, runs) : (bench_time){NAN, NAN};
  printf("| %s | %zu | %.3f (CPU %.3f) | %.3f (CPU %.3f) | %.2f | %s | %s | %.3f |\n",
         sampler_points_name(k), n, tf.wall, tf.cpu, tc.wall, tc.cpu, tf.wall / tc.wall, co, ci,
         tg.wall);
  fflush(stdout);
  free(p);
}

/* Nanoseconds per exact call on m tuples of t points each (t = 3: orient,
** 4: incircle), taken from p in steps of `step`, repeated until 0.2 s. */
static double bench_grid_ns(const geom_point *p, size_t m, size_t step, int t) {
  volatile int sink = 0;
  size_t calls = 0;
  double t0 = bench_wall(), dt;
  do {
    for (size_t i = 0; i < m; i++) {
      const geom_point *q = p + i * step;
      sink += t == 3 ? geom_orient_exact(q[0], q[1], q[2])
                     : geom_incircle_exact(q[0], q[1], q[2], q[3]);
    }
    calls += m;
    dt = bench_wall() - t0;
  } while (dt < 0.2);
  (void)sink;
  return 1e9 * dt / (double)calls;
}

static int bench_grid_angle_cmp(const void *a, const void *b) {
  double x = atan2(((const geom_point *)a)->y, ((const geom_point *)a)->x);
  double y = atan2(((const geom_point *)b)->y, ((const geom_point *)b)->x);
  return (x > y) - (x < y);
}

/* One line of the per-call table: orient and incircle, default and GMP. */
static void bench_grid_calls_row(const char *what, const geom_point *o, size_t om, size_t ostep,
                                 const geom_point *c, size_t cm, size_t cstep) {
  double ns[4];
  for (int gmp = 0; gmp < 2; gmp++) {
    int was = geom_exact_gmp_only(gmp);
    ns[gmp] = bench_grid_ns(o, om, ostep, 3);
    ns[2 + gmp] = bench_grid_ns(c, cm, cstep, 4);
    geom_exact_gmp_only(was);
  }
  printf("| %s | %.0f | %.0f | %.0f | %.0f |\n", what, ns[0], ns[1], ns[2], ns[3]);
}

/* The per-call table: degenerate tuples of the grid, parabola and circle. */
static void bench_grid_calls(void) {
  enum { M = 4096 };
  static geom_point g[M + 4], sq[4 * M], pa[M + 4], ci[M + 4];
  for (size_t i = 0; i < M + 4; i++) {
    g[i] = (geom_point){(double)i, 17};   /* a row of the grid: collinear */
    pa[i] = (geom_point){(double)(50000 + i), (double)(50000 + i) * (double)(50000 + i)};
  }
  for (size_t i = 0; i < M; i++) {   /* squares, anticlockwise corners */
    double x = (double)(i % 64), y = (double)(i / 64);
    sq[4 * i] = (geom_point){x, y};
    sq[4 * i + 1] = (geom_point){x + 1, y};
    sq[4 * i + 2] = (geom_point){x + 1, y + 1};
    sq[4 * i + 3] = (geom_point){x, y + 1};
  }
  sampler_points(SAMPLER_CIRCLE, 1, M + 4, ci);
  qsort(ci, M + 4, sizeof *ci, bench_grid_angle_cmp);
  printf("\n| tuples | orient (ns) | orient, GMP only (ns) | incircle (ns) "
         "| incircle, GMP only (ns) |\n|---|---:|---:|---:|---:|\n");
  bench_grid_calls_row("grid row / grid square", g, M, 1, sq, M, 4);
  bench_grid_calls_row("parabola, consecutive", pa, M, 1, pa, M, 1);
  bench_grid_calls_row("circle, consecutive", ci, M, 1, ci, M, 1);
}

int main(int argc, char **argv) {
  size_t n = argc > 1 ? (size_t)strtod(argv[1], NULL) : 1000000;
  int runs = argc > 2 ? atoi(argv[2]) : 3;
  const char *list = argc > 3 ? argv[3] : "uniform,grid,parabola,circle";
  if (n < 3 || runs < 1 || runs > 15) {
    fprintf(stderr, "usage: bench_grid [N >= 3 [RUNS 1..15 [SAMPLERS]]]\n");
    return 2;
  }
  printf("# bench_grid: %zu points (seed 1), medians of %d runs; load average %.2f\n\n", n, runs,
         bench_load());
  printf("| points | n | fliplab DT (s) | CGAL (s) | DT / CGAL | exact orient: int / exp / GMP "
         "| exact incircle: int / exp / GMP | DT, GMP only (s) |\n"
         "|---|---:|---:|---:|---:|---:|---:|---:|\n");
  char name[64];
  for (const char *s = list; *s;) {
    size_t len = strcspn(s, ",");
    snprintf(name, sizeof name, "%.*s", (int)len, s);
    int k = sampler_points_find(name);
    if (k < 0) {
      fprintf(stderr, "bench_grid: unknown sampler '%s' (%s)\n", name, sampler_points_names);
      return 2;
    }
    bench_grid_row(argv[0], (sampler_points_kind)k, n, runs);
    s += len + (s[len] == ',');
  }
  bench_grid_calls();
  printf("\n(load average at end: %.2f)\n", bench_load());
  return 0;
}
