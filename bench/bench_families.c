/*
** bench_families.c: every rule on every input family (samplers/sampler.h:
** uniform, normal, clustered, grid, jittered, circle, lines, dups), its
** time beside its own time on uniform points of the same size, and CGAL
** beside it where CGAL solves the same problem.
**
**   bench_families [--n N[,N...]] [--runs K] [--seed S] [--families LIST]
**                  [--rules LIST] [--cap SECONDS] [--cpu] [--markdown]
**
** Defaults: --n 100000 --runs 3 --seed 1, the eight families above, the
** rules DT, P_1 (a triangle-based rule that flips), ES:square, ES:hexagon
** and CDT: DT with the segments of `sample --sampler segments` on the
** family's points (sampler_segments, N / 10 asked, stream "segments").
** For each size, family and rule: the median of K lot_build runs (default
** options; the CDT keeps the hull, as bench_cdt), the ratio to the same
** rule on the uniform family of the same size (uniform is run first, added
** when the list lacks it; each run is paired with a uniform run just
** before it, and the ratio is the median of the pairs'), and the exact
** fallbacks of the first run
** (geom_exact_calls: orientation, incircle and area determinants the
** filters left; shape_exact_calls: empty-shape decisions sent to GMP).
** Beside DT, CGAL's Delaunay_triangulation_2 (bench_lot_cgal N 1 SEED
** FAMILY); beside the CDT, CGAL's Constrained_Delaunay_triangulation_2
** (bench_cdt_cgal N M 1 SEED FAMILY), each run alternating with fliplab's
** (the ratio: the median of the pairs'); built when CGAL is found.  A run longer
** than --cap seconds (default 120) is not repeated: its cell is marked *.
** A cell whose time t at the previous size n' predicts more than the cap
** at n, by t (n / n')^1.5, is not run: "skipped" (sizes run in the order
** given, so list them ascending).
** --cpu reports process CPU seconds instead of wall seconds; --markdown
** prints Markdown tables (docs/performance.md, "Input families").
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "benchutil.h"
#include "lot.h"
#include "rule.h"
#include "sampler.h"
#include "shape.h"

#define FAM_MAX_RULES 8
#define FAM_MAX_RUNS 15
#define FAM_MAX_SIZES 4

typedef struct fam_args {
  size_t n[FAM_MAX_SIZES];
  int nsizes, runs, cpu, markdown;
  uint64_t seed;
  double cap;
  char families[512], rules[512];
} fam_args;

/* One cell: the median time and the median ratio to uniform points (paired
** runs), whether it was capped, failed or skipped, the exact fallbacks of
** its first run, CGAL's median time and the median ratio to it (NAN: none). */
typedef struct fam_cell {
  double t, ratio, cgal, cgal_ratio;
  int capped, failed, skipped;
  unsigned long geom_exact, shape_exact;
} fam_cell;

/* The points of one family and the segments of its CDT. */
typedef struct fam_input {
  const char *family;
  geom_point *p;
  size_t n;
  uint32_t *seg;
  size_t nseg, asked;
} fam_input;

static const char *fam_usage =
  "usage: bench_families [--n N[,N...]] [--runs 1..15] [--seed S] [--families LIST]\n"
  "                      [--rules LIST] [--cap SECONDS] [--cpu] [--markdown]\n";

static int fam_sizes(const char *s, fam_args *a) {
  a->nsizes = 0;
  while (*s && a->nsizes < FAM_MAX_SIZES) {
    char *end;
    double v = strtod(s, &end);
    if (end == s || v < 3 || v > 1e9) return -1;
    a->n[a->nsizes++] = (size_t)v;
    s = *end == ',' ? end + 1 : end;
    if (*end != ',' && *end != '\0') return -1;
  }
  return a->nsizes > 0 && *s == '\0' ? 0 : -1;
}

static int fam_parse(int argc, char **argv, fam_args *a) {
  *a = (fam_args){{100000}, 1, 3, 0, 0, 1, 120, "", "DT,P_1,ES:square,ES:hexagon,CDT"};
  snprintf(a->families, sizeof a->families, "uniform,normal,clustered,grid,jittered,circle,"
           "lines,dups");
  for (int i = 1; i < argc; i++) {
    const char *o = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
    int takes = strcmp(o, "--cpu") != 0 && strcmp(o, "--markdown") != 0;
    if (takes && v == NULL) return -1;
    if (strcmp(o, "--n") == 0 && fam_sizes(v, a) != 0) return -1;
    else if (strcmp(o, "--runs") == 0) a->runs = atoi(v);
    else if (strcmp(o, "--seed") == 0) a->seed = strtoull(v, NULL, 10);
    else if (strcmp(o, "--cap") == 0) a->cap = strtod(v, NULL);
    else if (strcmp(o, "--families") == 0) snprintf(a->families, sizeof a->families, "%s", v);
    else if (strcmp(o, "--rules") == 0) snprintf(a->rules, sizeof a->rules, "%s", v);
    else if (strcmp(o, "--cpu") == 0) a->cpu = 1;
    else if (strcmp(o, "--markdown") == 0) a->markdown = 1;
    else if (strcmp(o, "--n") != 0) return -1;
    i += takes;
  }
  return a->runs >= 1 && a->runs <= FAM_MAX_RUNS && a->cap > 0 ? 0 : -1;
}

/* Splits the comma list s into at most max names (pointers into buf). */
static int fam_split(const char *s, char *buf, size_t size, const char **names, int max) {
  snprintf(buf, size, "%s", s);
  int k = 0;
  for (char *t = strtok(buf, ","); t != NULL && k < max; t = strtok(NULL, ",")) names[k++] = t;
  return k;
}

static int fam_is_cdt(const char *name) { return strcmp(name, "CDT") == 0; }

/* The family's points and, when a CDT is asked, its segments. */
static void fam_input_make(fam_input *in, const char *family, size_t n, uint64_t seed) {
  *in = (fam_input){family, malloc(n * sizeof *in->p), n, NULL, 0, n / 10};
  in->seg = malloc((2 * in->asked + 2) * sizeof *in->seg);
  int k = sampler_points_find(family);
  if (in->p == NULL || in->seg == NULL || k < 0) {
    fprintf(stderr, "bench_families: %s\n", k < 0 ? "unknown family" : "out of memory");
    exit(2);
  }
  sampler_points((sampler_points_kind)k, seed, n, in->p);
  sampler_rng g;
  sampler_seed(&g, seed, GEOM_STREAM_SEGMENTS);
  if (sampler_segments(&g, in->p, n, in->asked, in->seg, &in->nseg) != 0) exit(1);
}

static void fam_input_free(fam_input *in) {
  free(in->p);
  free(in->seg);
}

/* One lot_build of rule r (CDT: DT with the segments): wall or CPU
** seconds, or NAN with the error on stderr. */
static double fam_build(const fam_input *in, const char *name, const rule *r, int cpu) {
  lot_options o;
  lot_options_init(&o, r);
  if (fam_is_cdt(name)) {
    o.segments = in->seg;
    o.nsegments = in->nseg;
    o.keep_hull = 1;
  }
  lot *L;
  char err[512];
  double w = bench_wall(), c = bench_cpu();
  int rc = lot_build(&L, in->p, in->n, &o, err, sizeof err);
  double t = cpu ? bench_cpu() - c : bench_wall() - w;
  if (rc != 0) {
    fprintf(stderr, "bench_families: %s, %s: %s\n", in->family, name, err);
    return NAN;
  }
  lot_free(L);
  return t;
}

/* CGAL's time for the same problem (DT or CDT), one run; NAN if none. */
static double fam_cgal(const char *argv0, const fam_input *in, const char *name, uint64_t seed,
                       int cpu) {
  char args[256];
  double w, c;
  if (strcmp(name, "DT") == 0) {
    snprintf(args, sizeof args, "%zu 1 %llu %s", in->n, (unsigned long long)seed, in->family);
    bench_sibling(argv0, "bench_lot_cgal", args, &w, &c);
  } else if (fam_is_cdt(name)) {
    snprintf(args, sizeof args, "%zu %zu 1 %llu %s", in->n, in->asked, (unsigned long long)seed,
             in->family);
    bench_sibling(argv0, "bench_cdt_cgal", args, &w, &c);
  } else {
    return NAN;
  }
  return cpu ? c : w;
}

/* Runs one cell: K runs (one past the cap); before each, the same rule on
** the uniform points ref (NULL: in is uniform), after each, CGAL's run.
** The ratios are the medians of the runs' pairs, which the load's drift
** from minute to minute hardly moves (both members see the same load). */
static fam_cell fam_measure(const char *argv0, const fam_input *in, const fam_input *ref,
                            const char *name, const rule *r, const fam_args *a) {
  fam_cell cell = {NAN, NAN, NAN, NAN, 0, 0, 0, 0, 0};
  double t[FAM_MAX_RUNS], c[FAM_MAX_RUNS], qu[FAM_MAX_RUNS], qc[FAM_MAX_RUNS];
  int runs = 0, cgal_runs = 0;
  while (runs < a->runs) {
    double tu = ref != NULL ? fam_build(ref, name, r, a->cpu) : NAN;
    unsigned long g0 = geom_exact_calls(), s0 = shape_exact_calls();
    t[runs] = fam_build(in, name, r, a->cpu);
    if (runs == 0) {
      cell.geom_exact = geom_exact_calls() - g0;
      cell.shape_exact = shape_exact_calls() - s0;
    }
    if (isnan(t[runs])) return cell.failed = 1, cell;
    qu[runs] = ref != NULL ? t[runs] / tu : 1;
    c[cgal_runs] = fam_cgal(argv0, in, name, a->seed, a->cpu);
    if (!isnan(c[cgal_runs])) qc[cgal_runs] = t[runs] / c[cgal_runs], cgal_runs++;
    if (t[runs++] > a->cap) {
      cell.capped = 1;
      break;
    }
  }
  cell.t = bench_median(t, runs);
  cell.ratio = bench_median(qu, runs);
  if (cgal_runs > 0) {
    cell.cgal = bench_median(c, cgal_runs);
    cell.cgal_ratio = bench_median(qc, cgal_runs);
  }
  return cell;
}

/* Writes one row: cells separated by " | " (Markdown) or padded. */
static void fam_row(int markdown, const char *const *cells, int n) {
  for (int k = 0; k < n; k++) {
    if (markdown) printf("| %s ", cells[k]);
    else printf(k == 0 ? "%-10s" : k == 1 ? " %8s" : " %22s", cells[k]);
  }
  printf(markdown ? "|\n" : "\n");
}

/* The header of the time table and of the exact-call table. */
static void fam_headers(const fam_args *a, const char **rules, int nr, int exact) {
  static char h[2 * FAM_MAX_RULES + 2][96];
  const char *cells[2 * FAM_MAX_RULES + 2] = {"family", "n"};
  int k = 2;
  const char *unit = a->cpu ? "CPU s" : "s";
  for (int j = 0; j < nr; j++) {
    if (exact) snprintf(h[k], sizeof h[k], "%s: geom / shape", rules[j]);
    else snprintf(h[k], sizeof h[k], "%s %s (x uniform)", rules[j], unit);
    cells[k] = h[k], k++;
    if (exact || (strcmp(rules[j], "DT") != 0 && !fam_is_cdt(rules[j]))) continue;
    snprintf(h[k], sizeof h[k], "CGAL %s %s (%s / CGAL)", rules[j], unit, rules[j]);
    cells[k] = h[k], k++;
  }
  fam_row(a->markdown, cells, k);
  if (!a->markdown) return;
  printf("|---|---:|");
  for (int j = 2; j < k; j++) printf("---:|");
  printf("\n");
}

/* "0.123 (1.05)": the time and its ratio to ref. */
static void fam_fmt(char *out, size_t size, double t, int capped, double ratio) {
  snprintf(out, size, "%.3f%s (%.2f)", t, capped ? "*" : "", ratio);
}

/* One family's row of the time table. */
static void fam_time_row(const fam_args *a, const char *family, size_t n, const char **rules,
                         int nr, const fam_cell *c) {
  static char buf[2 * FAM_MAX_RULES + 2][64];
  const char *cells[2 * FAM_MAX_RULES + 2] = {family, buf[0]};
  snprintf(buf[0], sizeof buf[0], "%zu", n);
  int k = 2;
  for (int j = 0; j < nr; j++) {
    if (c[j].failed) snprintf(buf[k], sizeof buf[k], "error");
    else if (c[j].skipped) snprintf(buf[k], sizeof buf[k], "skipped");
    else fam_fmt(buf[k], sizeof buf[k], c[j].t, c[j].capped, c[j].ratio);
    cells[k] = buf[k], k++;
    if (strcmp(rules[j], "DT") != 0 && !fam_is_cdt(rules[j])) continue;
    if (isnan(c[j].cgal)) snprintf(buf[k], sizeof buf[k], "n/a");
    else fam_fmt(buf[k], sizeof buf[k], c[j].cgal, 0, c[j].cgal_ratio);
    cells[k] = buf[k], k++;
  }
  fam_row(a->markdown, cells, k);
}

static void fam_exact_row(const fam_args *a, const char *family, size_t n, int nr,
                          const fam_cell *c) {
  static char buf[FAM_MAX_RULES + 1][64];
  const char *cells[FAM_MAX_RULES + 2] = {family, buf[0]};
  snprintf(buf[0], sizeof buf[0], "%zu", n);
  for (int j = 0; j < nr; j++) {
    if (c[j].skipped || c[j].failed) snprintf(buf[j + 1], sizeof buf[j + 1], "-");
    else snprintf(buf[j + 1], sizeof buf[j + 1], "%lu / %lu", c[j].geom_exact, c[j].shape_exact);
    cells[j + 2] = buf[j + 1];
  }
  fam_row(a->markdown, cells, nr + 2);
}

/* The families with uniform first (added when missing). */
static int fam_families(const fam_args *a, char *buf, size_t size, const char **names, int max) {
  int k = fam_split(a->families, buf, size, names + 1, max - 1), m = 1;
  names[0] = "uniform";
  for (int j = 1; j <= k; j++)
    if (strcmp(names[j], "uniform") != 0) names[m++] = names[j];
  return m;
}

/* Whether the previous size's cell predicts more than the cap at n. */
static int fam_hopeless(const fam_cell *prev, size_t nprev, size_t n, double cap) {
  if (prev == NULL) return 0;
  if (prev->skipped) return 1;
  return !isnan(prev->t) && prev->t * pow((double)n / (double)nprev, 1.5) > cap;
}

/* Every family and rule at size n (prev: the cells of the previous size
** nprev, or NULL), then the two tables; c gets the cells. */
static void fam_size(const char *argv0, const fam_args *a, size_t n, const char **fams, int nf,
                     const char **names, const rule *rules, int nr,
                     fam_cell (*c)[FAM_MAX_RULES], fam_cell (*prev)[FAM_MAX_RULES],
                     size_t nprev) {
  fam_input uni, in;
  fam_input_make(&uni, fams[0], n, a->seed);   /* uniform, the reference */
  for (int f = 0; f < nf; f++) {
    if (f > 0) fam_input_make(&in, fams[f], n, a->seed);
    for (int j = 0; j < nr; j++) {
      if (fam_hopeless(prev ? &prev[f][j] : NULL, nprev, n, a->cap)) {
        c[f][j] = (fam_cell){NAN, NAN, NAN, NAN, 0, 0, 1, 0, 0};
        continue;
      }
      c[f][j] = fam_measure(argv0, f ? &in : &uni, f ? &uni : NULL, names[j], &rules[j], a);
      fprintf(stderr, "bench_families: %s, %zu, %s: %.3f s\n", fams[f], n, names[j], c[f][j].t);
    }
    if (f > 0) fam_input_free(&in);
  }
  fam_input_free(&uni);
  printf("\n");
  fam_headers(a, names, nr, 0);
  for (int f = 0; f < nf; f++) fam_time_row(a, fams[f], n, names, nr, c[f]);
  printf("\nExact fallbacks of one run (geom_exact_calls / shape_exact_calls):\n\n");
  fam_headers(a, names, nr, 1);
  for (int f = 0; f < nf; f++) fam_exact_row(a, fams[f], n, nr, c[f]);
  fflush(stdout);
}

int main(int argc, char **argv) {
  fam_args a;
  if (fam_parse(argc, argv, &a) != 0) return fprintf(stderr, "%s", fam_usage), 2;
  char fbuf[512], rbuf[512], err[512];
  const char *fams[32], *names[FAM_MAX_RULES];
  int nf = fam_families(&a, fbuf, sizeof fbuf, fams, 32);
  int nr = fam_split(a.rules, rbuf, sizeof rbuf, names, FAM_MAX_RULES);
  rule rules[FAM_MAX_RULES];
  for (int j = 0; j < nr; j++)
    if (rule_parse(fam_is_cdt(names[j]) ? "DT" : names[j], &rules[j], err, sizeof err) != 0)
      return fprintf(stderr, "bench_families: %s\n", err), 2;
  for (int f = 0; f < nf; f++)
    if (sampler_points_find(fams[f]) < 0)
      return fprintf(stderr, "bench_families: unknown family '%s' (%s)\n", fams[f],
                     sampler_points_names), 2;
  printf("bench_families: seed %llu, medians of %d runs (%s), CDT with n / 10 segments "
         "asked; load average %.2f\n", (unsigned long long)a.seed, a.runs,
         a.cpu ? "CPU seconds" : "wall seconds", bench_load());
  fam_cell(*c)[32][FAM_MAX_RULES] = malloc((size_t)a.nsizes * sizeof *c);
  if (c == NULL) return 1;
  for (int s = 0; s < a.nsizes; s++)
    fam_size(argv[0], &a, a.n[s], fams, nf, names, rules, nr, c[s], s ? c[s - 1] : NULL,
             s ? a.n[s - 1] : 0);
  printf("\n(load average at the end: %.2f; * one run, over the cap of %.0f s; skipped: "
         "predicted over the cap)\n", bench_load(), a.cap);
  free(c);
  return 0;
}
