/*
** bench_formula.c: what a formula-defined measure costs next to the same
** measure built in.
**
** Classifies the same pentagons under abc_f for the six joints (built-in
** abc) and under q_f with q defined as the formula a*b*c, through
** flipgraph_tally on one thread (the fast path evaluates each measure once
** per triangle, ten triangles per pentagon).  Prints ns per pentagon for
** each, the ratio; then the same for classification alone (pre-sampled
** pentagons, where the formula's share is largest); then one evaluation of
** each measure alone.  Median of 5 runs each.
** The budget: the formula run at most 3x the built-in one.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "benchutil.h"
#include "formula.h"
#include "measure.h"
#include "flipgraph.h"
#include "rule.h"
#include "sampler.h"

#define BENCH_RUNS 5

/* ns per pentagon of flipgraph_tally over the six joints of measure m. */
static double bench_tally(int m, uint64_t n) {
  rule rules[JOINT_COUNT];
  char err[256];
  for (int j = 0; j < JOINT_COUNT; j++)
    if (rule_triangle(m, (joint_id)j, &rules[j], err, sizeof err) != 0) {
      fprintf(stderr, "bench_formula: %s\n", err);
      exit(1);
    }
  double t[BENCH_RUNS];
  for (int k = -1; k < BENCH_RUNS; k++) {   /* k = -1: warm-up, not timed */
    flipgraph_counts c[JOINT_COUNT];
    memset(c, 0, sizeof c);
    double t0 = bench_wall();
    flipgraph_tally(rules, JOINT_COUNT, 1, 0, n, RULE_DEFAULT_TIE_EPS, 1, c, NULL, NULL);
    if (k >= 0) t[k] = (bench_wall() - t0) * 1e9 / (double)n;
  }
  return bench_median(t, BENCH_RUNS);
}

/* ns per pentagon of classification alone (pentagons sampled and their
** triangles made beforehand): flipgraph_plan_run over the six joints. */
static double bench_plan(int m, const flipgraph_pentagon *pent, int npent, int reps) {
  rule rules[JOINT_COUNT];
  char err[256];
  for (int j = 0; j < JOINT_COUNT; j++) rule_triangle(m, (joint_id)j, &rules[j], err, sizeof err);
  flipgraph_plan *pl = flipgraph_plan_new(rules, JOINT_COUNT, RULE_DEFAULT_TIE_EPS);
  if (pl == NULL) exit(1);
  double t[BENCH_RUNS];
  volatile int sink = 0;
  for (int k = 0; k < BENCH_RUNS; k++) {
    flipgraph g[JOINT_COUNT];
    double t0 = bench_wall();
    for (int r = 0; r < reps; r++)
      for (int i = 0; i < npent; i++) {
        flipgraph_plan_run(pl, &pent[i], g);
        sink += g[0].type;
      }
    t[k] = (bench_wall() - t0) * 1e9 / ((double)reps * npent);
  }
  (void)sink;
  flipgraph_plan_free(pl);
  return bench_median(t, BENCH_RUNS);
}

/* ns per evaluation of measure m alone, over a fixed set of triangles. */
static double bench_eval(int m, const geom_tri *tri, int ntri, int reps) {
  double t[BENCH_RUNS];
  volatile double sink = 0;
  for (int k = 0; k < BENCH_RUNS; k++) {
    double t0 = bench_wall(), s = 0;
    for (int r = 0; r < reps; r++)
      for (int i = 0; i < ntri; i++) s += measure_eval(m, &tri[i]);
    sink += s;
    t[k] = (bench_wall() - t0) * 1e9 / ((double)reps * ntri);
  }
  (void)sink;
  return bench_median(t, BENCH_RUNS);
}

int main(int argc, char **argv) {
  uint64_t n = argc > 1 ? strtoull(argv[1], NULL, 10) : 200000;
  if (n == 0) n = 200000;
  char err[512];
  int q = formula_define("q = a*b*c", err, sizeof err);
  if (q < 0) {
    fprintf(stderr, "bench_formula: %s\n", err);
    return 1;
  }
  enum { NTRI = 4096 };
  static geom_tri tri[NTRI];
  uint64_t s = 12345;
  for (int i = 0; i < NTRI; i++) {
    geom_point p[3];
    for (int k = 0; k < 3; k++) {
      s = s * 6364136223846793005ull + 1442695040888963407ull;
      double x = (double)(s >> 11) * 0x1.0p-53;
      s = s * 6364136223846793005ull + 1442695040888963407ull;
      p[k] = (geom_point){x, (double)(s >> 11) * 0x1.0p-53};
    }
    geom_tri_make(&tri[i], p[0], p[1], p[2]);
  }
  enum { NPENT = 8192 };
  static flipgraph_pentagon pent[NPENT];
  for (int i = 0; i < NPENT; i++) {
    geom_point v[5];
    sampler_pentagon(99, (uint64_t)i, v);
    flipgraph_prepare(&pent[i], v);
  }
  double tb = bench_tally(MEASURE_ABC, n), tf = bench_tally(q, n);
  double cb = bench_plan(MEASURE_ABC, pent, NPENT, 20), cf = bench_plan(q, pent, NPENT, 20);
  double eb = bench_eval(MEASURE_ABC, tri, NTRI, 200), ef = bench_eval(q, tri, NTRI, 200);
  printf("bench_formula: %llu pentagons, 6 rules (joints -inf..inf), 1 thread, median of %d\n",
         (unsigned long long)n, BENCH_RUNS);
  printf("%-34s %12s\n", "", "ns");
  printf("%-34s %12.1f\n", "abc_f built in, per pentagon", tb);
  printf("%-34s %12.1f\n", "q_f formula a*b*c, per pentagon", tf);
  printf("%-34s %12.2f   (budget: <= 3)\n", "ratio formula / built-in", tf / tb);
  printf("%-34s %12.1f\n", "abc_f classification only", cb);
  printf("%-34s %12.1f\n", "q_f classification only", cf);
  printf("%-34s %12.2f   (without sampling)\n", "ratio formula / built-in", cf / cb);
  printf("%-34s %12.1f\n", "abc alone, per evaluation", eb);
  printf("%-34s %12.1f\n", "q alone, per evaluation", ef);
  char msg[512];
  if (formula_check_errors(msg, sizeof msg)) {
    fprintf(stderr, "bench_formula: %s\n", msg);
    return 1;
  }
  return 0;
}
