/*
** bench_lot_sweep.c: the sweepline algorithm against the incremental one,
** for DT and empty-shape rules.
**
**   bench_lot_sweep [N [RUNS [SEED [SAMPLER [RULE,RULE,...]]]]]
**       (defaults 1000000, 5, 1, uniform, DT)
**
** For each rule, RUNS paired runs on the same N points: the incremental
** algorithm (spatial order), then the sweep, one after the other so that
** both see the same machine load.  Prints each algorithm's median wall and
** CPU time and the medians of the pairs' ratios sweep / incremental (on a
** shared machine the paired ratios, and the CPU ones above all, are the
** steady figures).  Times cover lot_build only (validation, ordering,
** triangulation, flips).  Rules are separated by commas, so a shape's
** numbers take blanks (ES:ellipse:2 1 0.3).  With a sampler other than
** uniform, each pair is joined by the sweep of N uniform points (the same
** seed), and a third row gives the sweep's time on the sampler's points
** over its time on uniform ones (paired, median): issue 35's measure of
** special position (a grid within 3 times uniform).
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "benchutil.h"
#include "lot.h"
#include "rule.h"
#include "sampler.h"

static void bench_build(const geom_point *p, size_t n, const rule *r, lot_algorithm a,
                        double *wall, double *cpu) {
  lot_options o;
  lot_options_init(&o, r);
  o.algorithm = a;
  lot *L;
  char err[256];
  double c0 = bench_cpu(), t0 = bench_wall();
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) {
    fprintf(stderr, "bench_lot_sweep: %s\n", err);
    exit(1);
  }
  *wall = bench_wall() - t0;
  *cpu = bench_cpu() - c0;
  lot_free(L);
}

/* RUNS paired runs of rule r on p; one table row per algorithm, and one
** for the sweep on the uniform points u (NULL: none). */
static void bench_rule(const geom_point *p, const geom_point *u, size_t n, const rule *r,
                       int runs) {
  double iw[16], ic[16], sw[16], sc[16], rw[16], rc[16], uw[16], uc[16], vw[16], vc[16];
  for (int k = 0; k < runs; k++) {
    bench_build(p, n, r, LOT_INCREMENTAL, &iw[k], &ic[k]);
    bench_build(p, n, r, LOT_SWEEP, &sw[k], &sc[k]);
    if (u != NULL) {
      bench_build(u, n, r, LOT_SWEEP, &uw[k], &uc[k]);
      vw[k] = sw[k] / uw[k];
      vc[k] = sc[k] / uc[k];
    }
    rw[k] = sw[k] / iw[k];
    rc[k] = sc[k] / ic[k];
  }
  printf("| %s | incremental (spatial order) | %.3f | %.3f | 1.00 |\n", rule_name(r),
         bench_median(iw, runs), bench_median(ic, runs));
  printf("| %s | sweep | %.3f | %.3f | wall %.2f, CPU %.2f |\n", rule_name(r),
         bench_median(sw, runs), bench_median(sc, runs), bench_median(rw, runs),
         bench_median(rc, runs));
  if (u != NULL)   /* the sweep on uniform points, and these points' time over it */
    printf("| %s | sweep, uniform points | %.3f | %.3f | these points / uniform: wall %.2f, "
           "CPU %.2f |\n", rule_name(r), bench_median(uw, runs), bench_median(uc, runs),
           bench_median(vw, runs), bench_median(vc, runs));
  fflush(stdout);
}

int main(int argc, char **argv) {
  size_t n = argc > 1 ? (size_t)strtod(argv[1], NULL) : 1000000;
  int runs = argc > 2 ? atoi(argv[2]) : 5;
  uint64_t seed = argc > 3 ? strtoull(argv[3], NULL, 10) : 1;
  int kind = argc > 4 ? sampler_points_find(argv[4]) : SAMPLER_UNIFORM;
  const char *rules = argc > 5 ? argv[5] : "DT";
  if (n < 3 || runs < 1 || runs > 15 || kind < 0) {
    fprintf(stderr, "usage: bench_lot_sweep [N >= 3 [RUNS 1..15 [SEED [SAMPLER [RULES]]]]]\n");
    return 2;
  }
  geom_point *p = malloc(n * sizeof *p), *u = NULL;
  if (p == NULL) return 1;
  sampler_points((sampler_points_kind)kind, seed, n, p);
  if (kind != SAMPLER_UNIFORM) {
    if ((u = malloc(n * sizeof *u)) == NULL) return 1;
    sampler_points(SAMPLER_UNIFORM, seed, n, u);
  }
  printf("# bench_lot_sweep: %zu %s points (seed %llu), %d paired runs\n", n,
         sampler_points_name((sampler_points_kind)kind), (unsigned long long)seed, runs);
  printf("(load average at start: %.2f on %ld cores)\n\n", bench_load(),
         sysconf(_SC_NPROCESSORS_ONLN));
  printf("| rule | algorithm | time (s) | CPU (s) | sweep / incremental (paired, median) |\n");
  printf("|---|---|---:|---:|---:|\n");
  for (const char *s = rules; *s != '\0';) {
    const char *comma = strchr(s, ',');
    size_t len = comma ? (size_t)(comma - s) : strlen(s);
    char name[128], err[256];
    rule r;
    snprintf(name, sizeof name, "%.*s", (int)len, s);
    if (rule_parse(name, &r, err, sizeof err) != 0) {
      fprintf(stderr, "bench_lot_sweep: %s\n", err);
      return 2;
    }
    bench_rule(p, u, n, &r, runs);
    s += len + (comma != NULL);
  }
  printf("(load average at end: %.2f)\n", bench_load());
  free(p);
  free(u);
  return 0;
}
