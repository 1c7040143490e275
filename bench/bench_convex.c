/*
** bench_convex.c: the cost of every random convex n-gon sampler of the
** registry (samplers/gon.c; thesis chapter 6) as n grows, and its fitted
** exponent beside the registry's stated cost.
**
**   bench_convex [MAXN [RUNS [SAMPLERS]]] [--limit]   (defaults 1000000, 3, all)
**
** One row per sampler, law (bounce, iteration) and inner method (dual), and
** per region for the point-based ones (square and disc; the triangle costs
** as the square): for n = 10^3, 10^4, ... MAXN the median CPU time of RUNS
** polygons (polygon r of seed 1, one thread: on the shared machine CPU time
** is the steady figure) and, when not all were realised, how many were
** (the others returned -1: doubles could not realise them, and their time
** is the time to find that out).  A row stops after a size where none was
** realised or a polygon took over 10 CPU seconds.  The exponent is the
** least-squares slope of log time against log n over the sizes realised in
** full (1 for O(n), about 1.1 for O(n log n) over these sizes).  Samplers
** limited to small n (naive, dual-rejection) are left out.  --limit adds
** the share of triangulation draws refused at n = 1, 1.5, 2, 3 x 10^6.
** docs/performance.md, "Random convex polygons", has the table.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "benchutil.h"
#include "sampler.h"
#include "study_cpdt.h"

#define BENCH_SIZES 8
#define BENCH_RUNS 16
#define BENCH_BUDGET 10.0   /* CPU seconds for one polygon: larger sizes skipped */

/* One row: a sampler with its region, law and inner method. */
typedef struct bench_convex_case {
  const sampler_gon *s;
  sampler_gon_params p;
} bench_convex_case;

/* runs polygons of size n: their median CPU time; *ok gets how many were
** realised, *slow whether one exceeded the budget (the rest then skipped). */
static double bench_convex_size(const bench_convex_case *c, size_t n, int runs, geom_point *v,
                                int *ok, int *slow) {
  double t[BENCH_RUNS];
  int r = 0;
  *ok = *slow = 0;
  for (; r < runs && !*slow; r++) {
    sampler_gon_info info;
    double c0 = bench_cpu();
    int rc = sampler_gon_draw(c->s, &c->p, 1, (uint64_t)r, n, v, &info);
    t[r] = bench_cpu() - c0;
    if (rc == SAMPLER_ENOMEM) {
      fprintf(stderr, "bench_convex: out of memory at n = %zu\n", n);
      exit(1);
    }
    *ok += rc == 0;
    *slow = t[r] > BENCH_BUDGET;
  }
  return bench_median(t, r);
}

static void bench_convex_row(const bench_convex_case *c, size_t maxn, int runs, geom_point *v) {
  study_slope fit = {0};
  int k = 0, ok = 1, slow = 0;
  size_t n = 1000;
  char name[64];
  snprintf(name, sizeof name, "%s%s%s", c->s->name, c->p.inner ? " of " : "",
           c->p.inner ? c->p.inner : "");
  if (c->s->laws > 1 || (c->p.inner && sampler_gon_inner(c->p.inner)->laws > 1))
    snprintf(name + strlen(name), sizeof name - strlen(name), ", law %d", c->p.law);
  printf("| `%s` | %s |", name, c->s->regions ? sampler_region_name(c->p.region) : "-");
  for (; n <= maxn && ok > 0 && !slow && k < BENCH_SIZES; n *= 10) {
    double t = bench_convex_size(c, n, runs, v, &ok, &slow);
    if (slow) printf(" slow |");
    else if (ok == runs) printf(" %.4f |", t);
    else printf(" %.4f (%d/%d) |", t, ok, runs);
    if (ok == runs && !slow && t > 0) study_slope_add(&fit, (double)n, t), k++;
    fflush(stdout);
  }
  for (; n <= maxn; n *= 10) printf(" |");
  double e = study_slope_get(&fit);
  if (isnan(e)) printf(" - |");
  else printf(" %.2f |", e);
  printf(" %s |\n", c->s->cost);
}

/* The rows of registry entry s: each region it takes (the triangle left
** out), law and, for the dual, inner method. */
static void bench_convex_entry(const sampler_gon *s, size_t maxn, int runs, geom_point *v) {
  for (size_t m = 0; m < (s->inner ? sampler_gons_count : 1); m++) {
    bench_convex_case c = {s, {SAMPLER_REGION_SQUARE, 0, NULL}};
    const sampler_gon *t = s->inner ? sampler_gon_inner(sampler_gons[m].name) : s;
    if (t == NULL || (t->nmax != 0 && t->nmax < 1000)) continue;
    if (s->inner) c.p.inner = t->name;
    for (c.p.law = 0; c.p.law < t->laws; c.p.law++)
      for (int r = 0; r < SAMPLER_REGION_TRIANGLE; r++) {
        c.p.region = (sampler_region)r;
        if (s->regions == 0 ? r == 0 : (s->regions & (1u << r)) != 0)
          bench_convex_row(&c, maxn, runs, v);
      }
  }
}

static void bench_convex_limit(geom_point *v) {
  static const size_t ns[] = {1000000, 1500000, 2000000, 3000000};
  bench_convex_case c = {sampler_gon_find("triangulation"), {SAMPLER_REGION_SQUARE, 0, NULL}};
  printf("\n| n | triangulation draws refused |\n|---:|---:|\n");
  for (size_t k = 0; k < sizeof ns / sizeof ns[0]; k++) {
    int ok, slow;
    (void)bench_convex_size(&c, ns[k], 5, v, &ok, &slow);
    printf("| %zu | %d of 5 |\n", ns[k], 5 - ok);
    fflush(stdout);
  }
}

int main(int argc, char **argv) {
  size_t maxn = 1000000;
  int runs = 3, limit = 0, pos = 0;
  const char *only = NULL;
  for (int i = 1; i < argc; i++)
    if (strcmp(argv[i], "--limit") == 0) limit = 1;
    else if (pos++ == 0) maxn = (size_t)strtod(argv[i], NULL);
    else if (pos == 2) runs = atoi(argv[i]);
    else only = argv[i];
  if (maxn < 1000 || runs < 1 || runs > BENCH_RUNS) {
    fprintf(stderr, "usage: bench_convex [MAXN >= 1000 [RUNS 1..16 [SAMPLERS]]] [--limit]\n");
    return 2;
  }
  geom_point *v = malloc((limit && maxn < 3000000 ? 3000000 : maxn) * sizeof *v);
  if (v == NULL) return 1;
  printf("# bench_convex: median CPU seconds of %d polygons (realised/drawn when not all),"
         " one thread, seed 1; load %.2f\n\n| sampler | region |", runs, bench_load());
  for (size_t n = 1000; n <= maxn; n *= 10) printf(" %.0e |", (double)n);
  printf(" exponent | cost |\n|---|---|");
  for (size_t n = 1000; n <= maxn; n *= 10) printf("--:|");
  printf("--:|---|\n");
  for (size_t i = 0; i < sampler_gons_count; i++)
    if (only == NULL || strstr(only, sampler_gons[i].name) != NULL)
      bench_convex_entry(&sampler_gons[i], maxn, runs, v);
  if (limit) bench_convex_limit(v);
  printf("\n(load average at the end: %.2f)\n", bench_load());
  free(v);
  return 0;
}
