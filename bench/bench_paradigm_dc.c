/*
** bench_paradigm_dc.c: divide and conquer with constraints (rows
** dc-constrained and dc-polygon, docs/paradigms.md) beside lot's
** constrained triangulation (the row incremental), side by side in one run:
**   - N uniform sites with S segments drawn among their Delaunay edges, and
**     with one long segment from site 0 to site N - 1;
**   - the same sites with 10^3 and 10^4 random non-crossing segments
**     (sampler_segments, short and long ones in cells; the share that are
**     Delaunay edges printed): lot, dc-constrained and sweep-constrained;
**   - a star-shaped polygon of P vertices: dc-polygon beside incremental
**     (lot's polygon insertion is slow on it: P smaller than N by default);
**     a convex one: dc-polygon beside convex-divide (cpdt's 5.4.2).
** dc-constrained runs with its cuts alternating (its default) and, as
** "dc-constrained:1" (its parameter 1), in vertical strips.
** Each round runs every contender once, in turn; the figures are medians of
** RUNS rounds: wall and CPU seconds, the ratio to lot's, and counts per
** site.  Before timing, every contender's triangles are checked equal.
**
**   bench_paradigm_dc [N [S [P [RUNS [SEED]]]]]    (defaults 100000 1000 20000 5 1)
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "benchutil.h"
#include "lot.h"
#include "paradigm.h"
#include "sampler.h"
#include "splitmix.h"

#define BDC_MAX 4   /* contenders per case */
/* The constrained cases' contenders (the first three for Delaunay edges). */
#define BDC_CONSTRAINED {"incremental", "dc-constrained", "dc-constrained:1", "sweep-constrained"}

typedef struct bdc_case {
  const char *title;
  paradigm_input in;
  const char *rows[BDC_MAX];
  int nrows;
} bdc_case;

/* A contender: a row of the registry, "ROW:PARAM" for its parameter. */
static paradigm_result bdc_run(const char *row, const paradigm_input *in0, bench_time *t) {
  paradigm_result res;
  paradigm_input in = *in0;
  char err[512], name[64];
  const char *colon = strchr(row, ':');
  snprintf(name, sizeof name, "%.*s", colon ? (int)(colon - row) : (int)strlen(row), row);
  in.param = colon ? atof(colon + 1) : 0;
  double w = bench_wall(), c = bench_cpu();
  if (paradigm_run(paradigm_find(name), &in, &res, err, sizeof err) != 0) {
    fprintf(stderr, "bench_paradigm_dc: %s: %s\n", row, err);
    exit(1);
  }
  if (t != NULL) *t = (bench_time){bench_wall() - w, bench_cpu() - c};
  return res;
}

/* Every contender gives the first one's triangles; exits if not. */
static void bdc_check(const bdc_case *k) {
  paradigm_result ref = bdc_run(k->rows[0], &k->in, NULL);
  for (int r = 1; r < k->nrows; r++) {
    paradigm_result res = bdc_run(k->rows[r], &k->in, NULL);
    int same = res.ntri == ref.ntri
               && memcmp(res.tri, ref.tri, 3 * ref.ntri * sizeof *ref.tri) == 0;
    printf("%s: %s gives %zu triangles, %s %s's\n", k->title, k->rows[r], res.ntri,
           same ? "exactly" : "NOT", k->rows[0]);
    paradigm_result_free(&res);
    if (!same) exit(1);
  }
  paradigm_result_free(&ref);
}

/* RUNS rounds of every contender, then the table of medians. */
static void bdc_time(const bdc_case *k, int runs) {
  bench_time t[BDC_MAX][16], m[BDC_MAX];
  ops_counts ops[BDC_MAX];
  for (int i = 0; i < runs; i++)
    for (int r = 0; r < k->nrows; r++) {
      paradigm_result res = bdc_run(k->rows[r], &k->in, &t[r][i]);
      ops[r] = res.ops;
      paradigm_result_free(&res);
    }
  printf("\n%s\n\n| algorithm | time (s) | CPU (s) | / %s | orient/site | incircle/site "
         "| flips/site | edges made/site | peak bytes/site |\n|---|---:|---:|---:|---:|---:"
         "|---:|---:|---:|\n", k->title, k->rows[0]);
  for (int r = 0; r < k->nrows; r++) m[r] = bench_median_time(t[r], runs);
  for (int r = 0; r < k->nrows; r++) {
    const uint64_t *v = ops[r].v;
    double n = (double)k->in.n;
    printf("| %s | %.4f | %.4f | %.2f | %.2f | %.2f | %.2f | %.2f | %.1f |\n", k->rows[r],
           m[r].wall, m[r].cpu, m[r].wall / m[0].wall, (double)v[OPS_ORIENT] / n,
           (double)v[OPS_INCIRCLE] / n, (double)v[OPS_FLIPS] / n,
           (double)v[OPS_EDGES_MADE] / n, (double)v[OPS_PEAK_BYTES] / n);
  }
}

/* s segments among the Delaunay edges of p, spread over its triangles. */
static uint32_t *bdc_segments(const paradigm_input *in, size_t s) {
  paradigm_input d = *in;
  d.problem = PARADIGM_DELAUNAY;
  paradigm_result dt = bdc_run("incremental", &d, NULL);
  uint32_t *seg = malloc(2 * s * sizeof *seg);
  if (seg == NULL || dt.ntri < s) exit(1);
  for (size_t k = 0; k < s; k++) {
    const uint32_t *v = dt.tri + 3 * (k * (dt.ntri / s));
    seg[2 * k] = v[k % 3], seg[2 * k + 1] = v[(k + 1) % 3];
  }
  paradigm_result_free(&dt);
  return seg;
}

/* One segment from site 0 to site N - 1 (a long one, crossing about
** sqrt(N) triangles and most strips), timed as the other cases. */
static void bdc_long(const paradigm_input *in0, int runs) {
  char title[128];
  bdc_case k = {title, *in0, BDC_CONSTRAINED, 4};
  uint32_t far[2] = {0, (uint32_t)(in0->n - 1)};
  k.in.segments = far, k.in.nsegments = 1;
  snprintf(title, sizeof title, "%zu uniform sites, one segment from site 0 to site %zu",
           in0->n, in0->n - 1);
  bdc_check(&k);
  bdc_time(&k, runs);
}

/* How many of the ns segments seg are edges of the Delaunay triangulation
** of in's sites: each site's neighbours listed (a counting sort of the
** triangles' sides by first end), then each segment looked up among its
** first end's. */
static size_t bdc_delaunay_edges(const paradigm_input *in, const uint32_t *seg, size_t ns) {
  paradigm_input d = *in;
  d.problem = PARADIGM_DELAUNAY, d.segments = NULL, d.nsegments = 0;
  paradigm_result dt = bdc_run("incremental", &d, NULL);
  size_t m = 3 * dt.ntri, hits = 0, *at = calloc(in->n + 1, sizeof *at);
  uint32_t *nb = malloc(m * sizeof *nb);
  if (at == NULL || nb == NULL) exit(1);
  for (size_t k = 0; k < m; k++) at[dt.tri[k] + 1]++;
  for (size_t v = 0; v < in->n; v++) at[v + 1] += at[v];
  for (size_t k = 0; k < m; k++) nb[at[dt.tri[k]]++] = dt.tri[k - k % 3 + (k + 1) % 3];
  for (size_t v = in->n; v > 0; v--) at[v] = at[v - 1];   /* back to the starts */
  at[0] = 0;
  for (size_t s = 0; s < ns; s++) {
    uint32_t u = seg[2 * s], v = seg[2 * s + 1], hit = 0;
    for (size_t j = at[u]; j < at[u + 1]; j++) hit |= nb[j] == v;
    for (size_t j = at[v]; j < at[v + 1]; j++) hit |= nb[j] == u;   /* hull sides: one way */
    hits += hit;
  }
  free(at), free(nb);
  paradigm_result_free(&dt);
  return hits;
}

/* in's sites with up to m random non-crossing segments (sampler_segments):
** lot's constrained triangulation, dc-constrained and the constrained
** sweep, checked and timed. */
static void bdc_random(const paradigm_input *base, size_t m, int runs) {
  char title[160];
  bdc_case k = {title, *base, BDC_CONSTRAINED, 4};
  uint32_t *seg = malloc(2 * m * sizeof *seg);
  size_t ns;
  sampler_rng g;
  sampler_seed(&g, base->seed, GEOM_STREAM_SEGMENTS);
  if (seg == NULL || sampler_segments(&g, base->p, base->n, m, seg, &ns) != 0) exit(1);
  k.in.segments = seg, k.in.nsegments = ns;
  size_t del = bdc_delaunay_edges(&k.in, seg, ns);
  snprintf(title, sizeof title, "%zu uniform sites, %zu random non-crossing segments "
           "(%zu of them Delaunay edges)", base->n, ns, del);
  bdc_check(&k);
  bdc_time(&k, runs);
  free(seg);
}

/* One polygon case: N vertices of `fn` as problem pb, rows a and b. */
static void bdc_polygon(const char *what, bench_sampler fn, paradigm_problem pb,
                        const char *a, const char *b, int runs, const paradigm_input *base) {
  char title[128];
  bdc_case k = {title, *base, {a, b}, 2};
  snprintf(title, sizeof title, "%s polygon of %zu vertices", what, base->n);
  k.in.p = bench_polygon("bench_paradigm_dc", fn, base->n);
  k.in.problem = pb, k.in.segments = NULL, k.in.nsegments = 0;
  bdc_check(&k);
  bdc_time(&k, runs);
  free((void *)k.in.p);
}

int main(int argc, char **argv) {
  size_t n = argc > 1 ? (size_t)strtod(argv[1], NULL) : 100000;
  size_t s = argc > 2 ? (size_t)strtod(argv[2], NULL) : 1000;
  size_t np = argc > 3 ? (size_t)strtod(argv[3], NULL) : 20000;
  int runs = argc > 4 ? atoi(argv[4]) : 5;
  uint64_t seed = argc > 5 ? strtoull(argv[5], NULL, 10) : 1;
  if (n < 16 || n > 10000000 || s < 1 || s > n / 4 || np < 3 || np > 10000000 || runs < 1
      || runs > 15) {
    fprintf(stderr, "usage: bench_paradigm_dc [N 16..1e7 [S 1..N/4 [P 3..1e7 [RUNS 1..15 "
            "[SEED]]]]]\n");
    return 2;
  }
  geom_point *p = malloc(n * sizeof *p);
  if (p == NULL) return 1;
  sampler_points(SAMPLER_UNIFORM, seed, n, p);
  rule dt = rule_delaunay();
  char title[128];
  snprintf(title, sizeof title, "%zu uniform sites (seed %llu), %zu segments among their "
           "Delaunay edges", n, (unsigned long long)seed, s);
  bdc_case cdt = {title, {.p = p, .n = n, .r = &dt, .problem = PARADIGM_CONSTRAINED,
                          .seed = seed, .threads = 1}, BDC_CONSTRAINED, 3};
  printf("# bench_paradigm_dc: median of %d rounds\n(load average at start: %.2f on %ld "
         "cores)\n", runs, bench_load(), sysconf(_SC_NPROCESSORS_ONLN));
  uint32_t *seg = bdc_segments(&cdt.in, s);
  cdt.in.segments = seg, cdt.in.nsegments = s;
  bdc_check(&cdt);
  bdc_time(&cdt, runs);
  bdc_long(&cdt.in, runs);
  for (size_t m = 1000; m <= 10000 && m <= n / 4; m *= 10) bdc_random(&cdt.in, m, runs);
  cdt.in.n = np;
  bdc_polygon("star-shaped", sampler_star, PARADIGM_POLYGON, "incremental", "dc-polygon",
              runs, &cdt.in);
  bdc_polygon("convex", sampler_vector, PARADIGM_CONVEX, "convex-divide", "dc-polygon", runs,
              &cdt.in);
  printf("(load average at the end: %.2f)\n", bench_load());
  free(seg), free(p);
  return 0;
}
