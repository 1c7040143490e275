/*
** bench_got_skel.c: the skeleton of a point set's GOT (got/got_skel.c, issue 38): for
** uniform random points in the unit square (sampler_points "uniform", seed 1) and P_1,
** the candidate edges the diamond test leaves, the edges the LMT loop keeps, the share of
** them that is certain, the rounds, and the time of the two stages (median of 3 runs by
** wall time, with the CPU time of that run, all threads); then another rule (-alpha_1,
** all pairs) at its largest size.  Every run is checked to give the same edges and states
** with 1 thread and with 2 (a hash).
**
** Target (issue 38): the exact MWT of 10^6 points in under a minute on 2 cores, of which
** the skeleton is a part.  Usage: bench_got_skel [--quick] (up to 10^5 points) [N ...].
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "benchutil.h"
#include "rule.h"
#include "sampler.h"
#include "got_skel.h"

#define BENCH_RUNS 3

static uint64_t bench_hash(const got_skel *s) {
  uint64_t h = 1469598103934665603ULL;
  for (size_t e = 0; e < s->nedges; e++) {
    h = (h ^ s->edge[2 * e]) * 1099511628211ULL;
    h = (h ^ s->edge[2 * e + 1]) * 1099511628211ULL;
    h = (h ^ s->state[e]) * 1099511628211ULL;
  }
  return h;
}

static void bench_build(const geom_point *p, size_t n, const rule *r, int threads,
                        got_skel *s, bench_time *t) {
  char err[256];
  double c0 = bench_cpu(), t0 = bench_wall();
  if (got_skel_build(p, n, r, threads, s, err, sizeof err) != 0) {
    fprintf(stderr, "bench_got_skel: %s\n", err);
    exit(1);
  }
  t->wall = bench_wall() - t0;
  t->cpu = bench_cpu() - c0;
}

static void bench_one(const char *rname, size_t n) {
  rule r;
  char err[256];
  if (rule_parse(rname, &r, err, sizeof err) != 0) exit(1);
  geom_point *p = malloc(n * sizeof *p);
  if (!p) exit(1);
  sampler_points(SAMPLER_UNIFORM, 1, n, p);
  bench_time t[BENCH_RUNS], t1;
  double cand[BENCH_RUNS], lmt[BENCH_RUNS];
  got_skel s;
  uint64_t h2 = 0;
  for (int k = 0; k < BENCH_RUNS; k++) {
    bench_build(p, n, &r, 2, &s, &t[k]);
    cand[k] = s.seconds_candidates, lmt[k] = s.seconds_lmt;
    h2 = bench_hash(&s);
    if (k + 1 < BENCH_RUNS) got_skel_free(&s);
  }
  got_skel s1;
  bench_build(p, n, &r, 1, &s1, &t1);
  size_t cert = 0;
  for (size_t e = 0; e < s.nedges; e++) cert += s.state[e] == GOT_EDGE_CERTAIN;
  bench_time m = bench_median_time(t, BENCH_RUNS);
  printf("%-9s %8zu %7.2f n %6.3f n %6.1f%% %3zu  %7.3f %7.3f %7.3f %7.3f  %7.3f  %s %016llx\n",
         rname,
         n, (double)s.candidates / (double)n, (double)s.nedges / (double)n,
         100.0 * (double)cert / (double)s.nedges, s.rounds, bench_median(cand, BENCH_RUNS),
         bench_median(lmt, BENCH_RUNS), m.wall, m.cpu, t1.wall,
         bench_hash(&s1) == h2 ? "same" : "DIFFERENT", (unsigned long long)h2);
  got_skel_free(&s);
  got_skel_free(&s1);
  free(p);
}

int main(int argc, char **argv) {
  size_t sizes[16] = {10000, 100000, 1000000}, ns = 3;
  int quick = argc > 1 && strcmp(argv[1], "--quick") == 0, first = 1 + quick;
  if (quick) ns = 2;
  if (argc > first) ns = 0;
  for (int i = first; i < argc && ns < 16; i++) sizes[ns++] = strtoull(argv[i], NULL, 10);
  printf("# bench_got_skel: uniform points in the unit square, median of %d runs on 2 threads;"
         " load average %.2f\n", BENCH_RUNS, bench_load());
  printf("# rule          n  candid.    kept  certain rnd  cand(s)  lmt(s)  wall(s)  cpu(s)"
         "  1 thr(s)  1 vs 2 threads, hash\n");
  for (size_t k = 0; k < ns; k++) bench_one("P_1", sizes[k]);
  bench_one("-alpha_1", 200);
  return 0;
}
