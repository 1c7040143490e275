/*
** bench_got_poly.c: GOT of simple (non-convex) polygons: wall time of a
** whole got_solve (exact validation, valid diagonals, the masked
** programme, runner-up, certification) on random star-shaped and
** x-monotone polygons, with the validation and diagonal phases timed on
** their own; the cost of the certified verdict against the whole run; and
** the masked programme against the convex path on convex input.
**
** Targets (issue 12): a star-shaped 1000-gon under P_1 and sigma_2 in
** under 1 s on 2 cores, a 2000-gon in under 4 s; certification at most 20%
** over an uncertified run.  Medians of 3 runs (of 51 for the verdict).  The
** machine's load average is printed: on a shared machine wall times grow
** with it, so the CPU time of the whole run (all threads) is printed too:
** on 2 idle cores the wall time would be about half of it.  Usage: bench_got_poly [--quick] (n <= 1000).
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "benchutil.h"
#include "got.h"
#include "got_internal.h"
#include "sampler.h"

#define BENCH_RUNS 3


static double bench_last_cpu;

static double bench_solve(const geom_point *p, size_t n, const char *rname, int mask,
                          got_result *keep) {
  rule r;
  char err[256];
  if (rule_parse(rname, &r, err, sizeof err) != 0) exit(1);
  got_options o = {2, RULE_DEFAULT_TIE_EPS};
  got_result res;
  double c0 = bench_cpu(), t0 = bench_wall();
  if (got_solve_ex(p, n, &r, &o, mask, &res, err, sizeof err) != 0) {
    fprintf(stderr, "bench_got_poly: %s\n", err);
    exit(1);
  }
  double t = bench_wall() - t0;
  bench_last_cpu = bench_cpu() - c0;
  if (keep) *keep = res;
  else got_result_free(&res);
  return t;
}

/* Validation and diagonals alone (2 threads for the diagonals). */
static void bench_phases(const geom_point *p, size_t n, double *tval, double *tdiag) {
  double a[BENCH_RUNS], b[BENCH_RUNS];
  geom_point *q = malloc(n * sizeof *q);
  unsigned char *V = malloc(n * n);
  for (int r = 0; r < BENCH_RUNS; r++) {
    memcpy(q, p, n * sizeof *q);
    double t0 = bench_wall();
    geom_simple_polygon_check(q, n, NULL, NULL, NULL);
    double t1 = bench_wall();
    got_valid_diagonals(p, n, V, 2);
    a[r] = t1 - t0;
    b[r] = bench_wall() - t1;
  }
  *tval = bench_median(a, BENCH_RUNS);
  *tdiag = bench_median(b, BENCH_RUNS);
  free(q);
  free(V);
}

static void bench_table_simple(int quick) {
  static const struct { const char *name; bench_sampler fn; } S[] = {
    {"star", sampler_star}, {"monotone", sampler_monotone}};
  static const size_t N[] = {500, 1000, 2000};
  static const char *R[] = {"P_1", "sigma_2"};
  printf("| polygon | n | valid diagonals | validation | diagonals | rule | got total (2 threads) | CPU | target | verdict |\n");
  printf("|---|---:|---:|---:|---:|---|---:|---:|---:|---|\n");
  for (size_t s = 0; s < 2; s++)
    for (size_t a = 0; a < 3; a++) {
      size_t n = N[a];
      if (quick && n > 1000) continue;
      geom_point *p = bench_polygon("bench_got_poly", S[s].fn, n);
      double tv, td;
      bench_phases(p, n, &tv, &td);
      unsigned char *V = malloc(n * n);
      got_valid_diagonals(p, n, V, 2);
      size_t cnt = 0;
      for (size_t i = 0; i < n; i++)
        for (size_t j = i + 2; j < n; j++) cnt += V[i * n + j] && !(i == 0 && j == n - 1);
      free(V);
      for (int r = 0; r < 2; r++) {
        double t[BENCH_RUNS], cpu[BENCH_RUNS];
        got_result res;
        for (int k = 0; k < BENCH_RUNS; k++) {
          t[k] = bench_solve(p, n, R[r], 0, k == 0 ? &res : NULL);
          cpu[k] = bench_last_cpu;
        }
        double med = bench_median(t, BENCH_RUNS), target = n <= 1000 ? 1.0 : 4.0;
        double cmed = bench_median(cpu, BENCH_RUNS);
        char tg[16] = "-";
        if (s == 0 && n >= 1000) snprintf(tg, sizeof tg, "< %.0f s", target);
        printf("| %s | %zu | %zu (%.1f%%) | %.4f s | %.4f s | %s | %.3f s | %.3f s | %s | %s |\n",
               S[s].name, n, cnt, 200.0 * (double)cnt / ((double)n * (double)(n - 3)), tv, td,
               R[r], med, cmed, tg, res.cert_unique ? "unique" : "tie not excluded");
        got_result_free(&res);
      }
      free(p);
    }
}

/* The verdict's own cost: got_certify on a finished result, median of 51,
** against the median whole run. */
static void bench_table_cert(int quick) {
  printf("\n| polygon | n | rule | got total | certification | share |\n|---|---:|---|---:|---:|---:|\n");
  static const size_t N[] = {1000, 2000};
  static const char *R[] = {"P_1", "sigma_2"};
  for (size_t a = 0; a < 2; a++) {
    size_t n = N[a];
    if (quick && n > 1000) continue;
    geom_point *p = bench_polygon("bench_got_poly", sampler_star, n);
    for (int r = 0; r < 2; r++) {
      double t[BENCH_RUNS], c[51];
      got_result res;
      for (int k = 0; k < BENCH_RUNS; k++) t[k] = bench_solve(p, n, R[r], 0, k == 0 ? &res : NULL);
      got_keyfn kf = r == 0 ? GOT_KEY_IDENT : GOT_KEY_FROM_SQ_IDENT;
      for (int k = 0; k < 51; k++) {
        double t0 = bench_wall();
        got_certify(&res, p, n, kf, JOINT_KEY_ADD);
        c[k] = bench_wall() - t0;
      }
      double tm = bench_median(t, BENCH_RUNS), cm = bench_median(c, 51);
      printf("| star | %zu | %s | %.3f s | %.2g s | %.4f%% |\n", n, R[r], tm, cm, 100 * cm / tm);
      got_result_free(&res);
    }
    free(p);
  }
}

/* Convex input: the convex path (tiled, unmasked) against the masked
** programme on the same polygon (results identical; tests check that). */
static void bench_table_convex(void) {
  printf("\n| convex n | rule | convex path | masked path |\n|---:|---|---:|---:|\n");
  geom_point *p = bench_polygon("bench_got_poly", sampler_vector, 1000);
  static const char *R[] = {"P_1", "sigma_2"};
  for (int r = 0; r < 2; r++) {
    double a[BENCH_RUNS], b[BENCH_RUNS];
    for (int k = 0; k < BENCH_RUNS; k++) {
      a[k] = bench_solve(p, 1000, R[r], 0, NULL);
      b[k] = bench_solve(p, 1000, R[r], 1, NULL);
    }
    printf("| 1000 | %s | %.3f s | %.3f s |\n", R[r], bench_median(a, BENCH_RUNS),
           bench_median(b, BENCH_RUNS));
  }
  free(p);
}

int main(int argc, char **argv) {
  int quick = argc > 1 && strcmp(argv[1], "--quick") == 0;
  printf("# bench_got_poly: 2 threads, medians of %d runs; load average %.2f at start\n\n",
         BENCH_RUNS, bench_load());
  bench_table_simple(quick);
  bench_table_cert(quick);
  if (!quick) bench_table_convex();
  printf("\n# load average %.2f at the end\n", bench_load());
  return 0;
}
