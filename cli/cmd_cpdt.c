/*
** cmd_cpdt.c: `fliplab cpdt`: the thesis's chapter-5 experiment, random
** convex polygons of several sizes triangulated by the workbench's
** Delaunay algorithms, counted (studies/cpdt_study.c); a CSV table and a
** log-log plot with the fitted slopes.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "report.h"
#include "sampler.h"
#include "study_cpdt.h"

#define CMD "cpdt"
#define CLI_CPDT_MAX_SIZES 64

typedef struct cli_cpdt_opts {
  const char *sizes, *algorithms, *out, *plot;
  uint64_t trials, seed, law;
  int sampler, region, measure;
} cli_cpdt_opts;

#define T cli_cpdt_opts
static const cli_option cli_cpdt_table[] = {
  CLI_OPT_STRING("--sizes", "N,N,...", "31,62,124,248,496,992",
                 "polygon sizes (3 .. 2^29 vertices each, at most 64 sizes)", T, sizes),
  CLI_OPT_U64("--trials", "K", "polygons per size", T, trials, 1, 1000000000, 70),
  {.name = "--sampler", .arg = "S", .dflt = "vector",
   .help = "a random convex n-gon sampler of `fliplab convex` (not the\n"
           "                     weighted rejection: valtr draws its law unweighted)",
   .kind = CLI_CHOICE, .off = CLI_AT(T, sampler, int), .find = study_cpdt_sampler_find,
   .idef = -1, .bad = "unknown sampler '%s' (fliplab convex --help lists them)"},
  {.name = "--region", .arg = "R", .dflt = "square",
   .help = "the region of the samplers that draw points: square, disc, triangle",
   .kind = CLI_CHOICE, .off = CLI_AT(T, region, int), .find = sampler_region_find,
   .idef = -1, .bad = "unknown region '%s' (valid: square, disc, triangle)"},
  CLI_OPT_U64("--law", "L", "the sampler's variant (as fliplab convex --law)", T, law, 0, 1, 0),
  CLI_OPT_STRING("--algorithms", "A,A,...", "all",
                 "circum, circum-random, circum-walk, divide, incremental,\n"
                 "                     random, flip, corners", T, algorithms),
  CLI_OPT_SEED("polygons and the randomised algorithms' choices", T, seed),
  CLI_OPT_FILE("--out", "FILE.csv", "none", "csv",
               "the table: each size and algorithm, every count's mean and interval", T, out),
  CLI_OPT_FILE("--plot", "FILE.svg", "none", "svg", "log-log plot of --measure, slopes fitted",
               T, plot),
  {.name = "--measure", .arg = "M", .dflt = "incircle",
   .help = "plotted and fitted: scanned, incircle, orient, flips, cross,\n"
           "                     cross_max, depth, memory, index_length, seconds",
   .kind = CLI_CHOICE, .off = CLI_AT(T, measure, int), .find = study_cpdt_count_find,
   .idef = STUDY_CPDT_INCIRCLE, .bad = "unknown measure '%s' (fliplab cpdt --help lists them)"},
};
#undef T

static const cli_spec cli_cpdt_spec = {
  CMD, "usage: fliplab cpdt [options]",
  "Chapter 5's experiment: random convex polygons of each size (--trials of\n"
  "them) triangulated by each algorithm for the Delaunay triangulation of a\n"
  "convex polygon, exactly (every algorithm's triangles are compared), with\n"
  "its operations counted.  Prints the mean of --measure per size and the\n"
  "slope of its log-log least-squares line per algorithm; --out writes every\n"
  "count's mean and 95% interval, --plot the log-log plot (docs/cpdt.md).\n",
  cli_cpdt_table, CLI_NOPTS(cli_cpdt_table), NULL};

/* "31,62,..." into sizes[]: the count, or -1 after the error. */
static int cli_cpdt_sizes(const char *s, uint64_t *sizes) {
  int n = 0;
  for (const char *p = s;; p++) {
    const char *e = strchr(p, ',');
    size_t len = e ? (size_t)(e - p) : strlen(p);
    char item[32];
    if (n == CLI_CPDT_MAX_SIZES) return cli_error(CMD, "--sizes: at most %d sizes", n), -1;
    snprintf(item, sizeof item, "%.*s", (int)(len < 31 ? len : 31), p);
    if (len >= 31 || cli_parse_u64(CMD, "--sizes", item, 3, CPDT_MAX_N, &sizes[n]) != 0) {
      if (len >= 31) cli_error(CMD, "--sizes: '%.40s' is not a size", p);
      return -1;
    }
    n++;
    if (e == NULL) return n;
    p = e;
  }
}

/* "all" or names into algorithms[]: the count, or -1 after the error. */
static int cli_cpdt_algorithms(const char *s, int *alg) {
  if (strcmp(s, "all") == 0) {
    for (int a = 0; a < CPDT_ALGORITHM_COUNT; a++) alg[a] = a;
    return CPDT_ALGORITHM_COUNT;
  }
  int n = 0;
  for (const char *p = s;; p++) {
    const char *e = strchr(p, ',');
    size_t len = e ? (size_t)(e - p) : strlen(p);
    char name[32];
    snprintf(name, sizeof name, "%.*s", (int)(len < 31 ? len : 31), p);
    int a = len < 31 ? cpdt_algorithm_find(name) : -1;
    if (a < 0)
      return cli_error(CMD, "--algorithms: unknown algorithm '%.40s' (valid: circum, "
                            "circum-random, circum-walk, divide, incremental, random, flip, "
                            "corners)", name), -1;
    for (int k = 0; k < n; k++)
      if (alg[k] == a) return cli_error(CMD, "--algorithms: '%s' given twice", name), -1;
    alg[n++] = a;
    if (e == NULL) return n;
    p = e;
  }
}

/* The sizes and algorithms of a run. */
typedef struct cli_cpdt_run {
  const uint64_t *sizes;
  size_t nsizes;
  const int *algorithms;
  size_t nalgorithms;
} cli_cpdt_run;

/* The summary: the mean of the measure per size and algorithm, slopes. */
static void cli_cpdt_print(const cli_cpdt_opts *o, const cli_cpdt_run *s,
                           const study_cpdt_cell *cells) {
  printf("# fliplab cpdt: sampler %s, %zu sizes, %llu trials each, seed %llu; mean %s\n",
         study_cpdt_sampler_name(o->sampler), s->nsizes, (unsigned long long)o->trials,
         (unsigned long long)o->seed, study_cpdt_count_name(o->measure));
  printf("%8s", "n");
  for (size_t a = 0; a < s->nalgorithms; a++)
    printf(" %14s", cpdt_algorithm_name(s->algorithms[a]));
  printf("\n");
  for (size_t i = 0; i < s->nsizes; i++) {
    printf("%8llu", (unsigned long long)s->sizes[i]);
    for (size_t a = 0; a < s->nalgorithms; a++)
      printf(" %14.6g", cells[i * s->nalgorithms + a].mean[o->measure]);
    printf("\n");
  }
  printf("%8s", "slope");
  size_t nc = s->nsizes * s->nalgorithms;
  for (size_t a = 0; a < s->nalgorithms; a++) {
    double sl = study_cpdt_slope(cells, nc, s->algorithms[a], o->measure);
    if (isnan(sl)) printf(" %14s", "-");
    else printf(" %14.3f", sl);
  }
  printf("\n");
}

static int cli_cpdt_write(const cli_cpdt_opts *o, const cli_cpdt_run *s,
                          const study_cpdt_cell *cells) {
  size_t nc = s->nsizes * s->nalgorithms;
  if (o->out != NULL) {
    FILE *f = cli_open_out(CMD, o->out);
    if (f == NULL) return 2;
    int w = report_cpdt_csv(f, study_cpdt_sampler_name(o->sampler), o->trials, cells, nc);
    if (cli_finish_out(CMD, f, w) != 0) return 1;
  }
  if (o->plot != NULL) {
    FILE *f = cli_open_out(CMD, o->plot);
    if (f == NULL) return 2;
    char title[160];
    snprintf(title, sizeof title, "Delaunay triangulation of convex polygons (%s, %llu trials)",
             study_cpdt_sampler_name(o->sampler), (unsigned long long)o->trials);
    int w = report_cpdt_svg(f, title, cells, nc, s->algorithms, s->nalgorithms, o->measure);
    if (cli_finish_out(CMD, f, w) != 0) return 1;
  }
  return 0;
}

int cli_cmd_cpdt(int argc, char **argv) {
  cli_cpdt_opts o;
  int st = cli_options_parse(&cli_cpdt_spec, argc, argv, &o, NULL);
  if (st != 0) return st == 1 ? 0 : st;
  uint64_t sizes[CLI_CPDT_MAX_SIZES];
  int alg[CPDT_ALGORITHM_COUNT];
  int ns = cli_cpdt_sizes(o.sizes != NULL ? o.sizes : "31,62,124,248,496,992", sizes);
  if (ns < 0) return 2;
  int na = cli_cpdt_algorithms(o.algorithms != NULL ? o.algorithms : "all", alg);
  if (na < 0) return 2;
  if (o.sampler < 0) o.sampler = study_cpdt_sampler_find("vector");
  char why[200];
  for (int i = 0; i < ns; i++)
    if (study_cpdt_sampler_check(o.sampler, o.region, (int)o.law, (size_t)sizes[i], why,
                                 sizeof why) != 0)
      return cli_error(CMD, "--sizes: %llu: %s", (unsigned long long)sizes[i], why);
  cli_cpdt_run s = {sizes, (size_t)ns, alg, (size_t)na};
  study_cpdt_cell *cells = malloc((size_t)ns * (size_t)na * sizeof *cells);
  if (cells == NULL) return cli_error(CMD, "out of memory"), 1;
  char err[256];
  int rc = study_cpdt_run(sizes, s.nsizes, alg, s.nalgorithms, o.trials, o.seed, o.sampler,
                          o.region, (int)o.law, cells, err, sizeof err);
  if (rc != 0) {
    free(cells);
    return cli_error(CMD, "%s", err), rc == -1 ? 2 : 1;
  }
  cli_cpdt_print(&o, &s, cells);
  rc = cli_cpdt_write(&o, &s, cells);
  free(cells);
  return rc;
}
