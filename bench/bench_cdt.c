/*
** bench_cdt.c: constrained triangulations at scale (the targets of
** docs/performance.md): the exact CDT of N uniform points (the "uniform" sampler)
** with M non-crossing segments (sampler_segments, the stream of `fliplab
** sample --sampler segments`), next to
**   - fliplab's unconstrained DT of the same points (what the segments cost),
**   - CGAL's Constrained_Delaunay_triangulation_2 (Epick, Exact_predicates_tag)
**     on the same points and segments (bench_cdt_cgal, built when CGAL is
**     found), run alternately with fliplab so both see the same load,
**   - the constrained LOT of each rule of a comma list (default P_1).
** Every figure is the median of RUNS runs; wall and CPU seconds.
**
**   bench_cdt [N [M [RUNS [SEED [RULES]]]]]   (defaults 10^6 10^5 3 1 P_1)
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "benchutil.h"
#include "lot.h"
#include "rule.h"
#include "sampler.h"

/* One lot_build: wall and CPU seconds; exits on failure. */
static bench_time bench_build(const geom_point *p, size_t n, const rule *r, const uint32_t *seg,
                              size_t nseg, lot_stats *st) {
  lot_options o;
  lot_options_init(&o, r);
  o.segments = seg;
  o.nsegments = nseg;
  o.keep_hull = 1;
  char err[512];
  lot *L;
  double w = bench_wall(), c = bench_cpu();
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) {
    fprintf(stderr, "bench_cdt: %s: %s\n", r->name, err);
    exit(1);
  }
  bench_time t = {bench_wall() - w, bench_cpu() - c};
  *st = *lot_get_stats(L);
  lot_free(L);
  return t;
}

static void bench_row(const char *what, bench_time t, bench_time ref) {
  printf("| %s | %.3f | %.3f | %.2f (CPU %.2f) |\n", what, t.wall, t.cpu, t.wall / ref.wall,
         t.cpu / ref.cpu);
  fflush(stdout);
}

/* The median of RUNS timings of rule r with the segments. */
static bench_time bench_rule(const geom_point *p, size_t n, const rule *r, const uint32_t *seg,
                             size_t nseg, int runs, lot_stats *st) {
  bench_time t[16];
  for (int k = 0; k < runs; k++) t[k] = bench_build(p, n, r, seg, nseg, st);
  return bench_median_time(t, runs);
}

int main(int argc, char **argv) {
  size_t n = argc > 1 ? (size_t)strtod(argv[1], NULL) : 1000000;
  size_t m = argc > 2 ? (size_t)strtod(argv[2], NULL) : 100000;
  int runs = argc > 3 ? atoi(argv[3]) : 3;
  uint64_t seed = argc > 4 ? strtoull(argv[4], NULL, 10) : 1;
  const char *rules = argc > 5 ? argv[5] : "P_1";
  if (n < 3 || runs < 1 || runs > 15) {
    fprintf(stderr, "usage: bench_cdt [N >= 3 [M [RUNS 1..15 [SEED [RULES]]]]]\n");
    return 2;
  }
  geom_point *p = malloc(n * sizeof *p);
  uint32_t *seg = malloc((2 * m + 2) * sizeof *seg);
  size_t nseg;
  sampler_rng g;
  if (p == NULL || seg == NULL) return 1;
  sampler_points(SAMPLER_UNIFORM, seed, n, p);
  sampler_seed(&g, seed, GEOM_STREAM_SEGMENTS);
  if (sampler_segments(&g, p, n, m, seg, &nseg) != 0) return 1;
  printf("bench_cdt: %zu uniform points, %zu segments (seed %llu), median of %d\n", n, nseg,
         (unsigned long long)seed, runs);
  printf("(load average at start: %.2f on %ld cores)\n\n", bench_load(),
         sysconf(_SC_NPROCESSORS_ONLN));
  rule dt = rule_delaunay();
  lot_stats st;
  bench_time tc[16], td[16];
  double cw[16], cc[16];
  int have_cgal = 1;
  char args[160];
  snprintf(args, sizeof args, "%zu %zu 1 %llu", n, m, (unsigned long long)seed);
  for (int k = 0; k < runs; k++) {   /* alternating, so all see the same load */
    td[k] = bench_build(p, n, &dt, NULL, 0, &st);
    tc[k] = bench_build(p, n, &dt, seg, nseg, &st);
    bench_sibling(argv[0], "bench_cdt_cgal", args, &cw[k], &cc[k]);
    have_cgal &= !isnan(cw[k]);
  }
  bench_time cdt = bench_median_time(tc, runs), dtt = bench_median_time(td, runs);
  printf("CDT: %zu triangles, %zu constrained edges (%zu segments split at points on them)\n\n",
         st.triangles, st.constrained, st.segments_split);
  printf("| triangulation | time (s) | CPU (s) | / fliplab CDT |\n|---|---:|---:|---:|\n");
  bench_row("fliplab CDT (DT + segments)", cdt, cdt);
  bench_row("fliplab DT, no segments", dtt, cdt);
  if (have_cgal)
    bench_row("CGAL Constrained_Delaunay_triangulation_2",
              (bench_time){bench_median(cw, runs), bench_median(cc, runs)}, cdt);
  else
    printf("| CGAL Constrained_Delaunay_triangulation_2 | not built | | |\n");
  char name[256];
  for (const char *s = rules; *s;) {
    size_t len = strcspn(s, ",");
    snprintf(name, sizeof name, "%.*s", (int)len, s);
    rule r;
    char err[512];
    if (rule_parse(name, &r, err, sizeof err) != 0) {
      fprintf(stderr, "bench_cdt: %s\n", err);
      return 2;
    }
    char what[300];
    snprintf(what, sizeof what, "constrained LOT %s", name);
    bench_row(what, bench_rule(p, n, &r, seg, nseg, runs, &st), cdt);
    s += len + (s[len] == ',');
  }
  free(p);
  free(seg);
  return 0;
}
