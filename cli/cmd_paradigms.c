/*
** cmd_paradigms.c: `fliplab paradigms`: chapter 2's algorithms behind the
** registry (paradigms/), listed, and run as a matrix of algorithms x rules
** x point families x sizes (studies/paradigms.c): table 2.4 anew, as a
** Markdown table on stdout, a CSV file and a log-log plot.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "paradigm.h"
#include "report.h"
#include "rule.h"
#include "sampler.h"
#include "study_paradigms.h"

#define CMD "paradigms"
/* Small enough that the quadratic rows (the selection scans) finish in
** seconds by default; larger sizes are asked for. */
#define CLI_PAR_SIZES "1000,4000"
#define CLI_PAR_MAX_SIZES 16
#define CLI_PAR_MAX_FAMILIES 16

typedef struct cli_par_opts {
  int list, measure, problem;   /* problem: an index of cli_par_problems */
  const char *algorithms, *rules, *families, *sizes, *csv, *svg;
  uint64_t runs, seed;
} cli_par_opts;

/* The plotted quantity: a count's name (ops_find) or "seconds" (OPS_COUNT). */
static int cli_par_measure_find(const char *v) {
  return strcmp(v, "seconds") == 0 ? OPS_COUNT : ops_find(v);
}

/* --problem's values, paradigm_problem 1 << k for value k; each with the
** family it draws when --families is not given. */
static const char *const cli_par_problem_names[] = {"delaunay", "constrained", "polygon",
                                                    "convex", NULL};
static const char *const cli_par_default_family[] = {"uniform", "uniform", "star", "valtr"};

#define T cli_par_opts
static const cli_option cli_par_table[] = {
  CLI_OPT_FLAG("--list", "list the algorithms: name, paradigm, section, problems, cost,\n"
               "                     refusal", T, list),
  CLI_OPT_STRING("--algorithms", "A,A,...", "all", "algorithms of --list, or all", T,
                 algorithms),
  CLI_OPT_STRING("--rules", "R,R,...", "DT", "DT or empty-shape rules ES:SHAPE", T, rules),
  {.name = "--problem", .arg = "P", .dflt = "delaunay",
   .help = "delaunay, constrained (n/4 random segments), polygon (simple)\n"
           "                     or convex", .kind = CLI_CHOICE, .off = CLI_AT(T, problem, int),
   .names = cli_par_problem_names, .idef = 0,
   .bad = "unknown problem '%s' (delaunay, constrained, polygon, convex)"},
  CLI_OPT_STRING("--families", "F,F,...", "uniform, star (polygon), valtr (convex)",
                 "delaunay, constrained: point families of lot --random\n"
                 "                     (uniform, grid, clustered, lines, dups, ...); polygon:\n"
                 "                     star, monotone; convex: the samplers of fliplab convex",
                 T, families),
  CLI_OPT_STRING("--sizes", "N,N,...", CLI_PAR_SIZES,
                 "points per set (3 .. 10^8 each, at most 16 sizes)", T, sizes),
  CLI_OPT_U64("--runs", "K", "timed runs per cell (the median is shown)", T, runs, 1, 99, 3),
  CLI_OPT_SEED("the point sets and randomised algorithms", T, seed),
  CLI_OPT_FILE("--csv", "FILE.csv", "none", "csv",
               "every cell: time, counts per site, growth exponents", T, csv),
  CLI_OPT_FILE("--svg", "FILE.svg", "none", "svg",
               "--measure against n, log axes, first rule and family", T, svg),
  {.name = "--measure", .arg = "M", .dflt = "seconds",
   .help = "plotted: seconds, or a count per site (orient, incircle,\n"
           "                     inshape, exact, flips, locate, edges_made, ...)",
   .kind = CLI_CHOICE, .off = CLI_AT(T, measure, int), .find = cli_par_measure_find,
   .idef = OPS_COUNT, .bad = "unknown measure '%s' (seconds, orient, incircle, inshape, exact, "
                             "flips, locate, edges_made, edges_deleted, events, buckets, "
                             "peak_bytes)"},
};
#undef T

static const cli_spec cli_par_spec = {
  CMD, "usage: fliplab paradigms [--list] [options]",
  "Chapter 2's triangulation algorithms (flip, incremental, sweepline, ...)\n"
  "behind one registry.  --list shows them; otherwise each chosen algorithm\n"
  "triangulates each input family of --problem at each size, for each rule,\n"
  "--runs times: a Markdown table (table 2.4 anew: median times, the growth\n"
  "exponent of the time, counts per site at the largest size) on stdout;\n"
  "--csv every cell, --svg a plot.  Every algorithm's triangles are compared;\n"
  "one that refuses a problem or rule gets a row saying why (docs/paradigms.md).\n",
  cli_par_table, CLI_NOPTS(cli_par_table), NULL};

/* The next comma-separated item of *s into item (cut at len - 1): its
** length, or -1 at the end. */
static long cli_par_item(const char **s, char *item, size_t len) {
  if (*s == NULL) return -1;
  const char *e = strchr(*s, ',');
  size_t n = e ? (size_t)(e - *s) : strlen(*s);
  snprintf(item, len, "%.*s", (int)(n < len ? n : len - 1), *s);
  *s = e ? e + 1 : NULL;
  return (long)n;
}

/* Algorithm names, or all: the count, or -1 after the error. */
static int cli_par_algorithms(const char *s, size_t *alg) {
  size_t n = 0;
  char name[64];
  if (strcmp(s, "all") == 0) {
    for (; n < paradigm_count(); n++) alg[n] = n;
    return (int)n;
  }
  for (long len; (len = cli_par_item(&s, name, sizeof name)) >= 0;) {
    const paradigm_algorithm *a = (size_t)len < sizeof name ? paradigm_find(name) : NULL;
    if (a == NULL)
      return cli_error(CMD, "--algorithms: unknown algorithm '%.40s' (fliplab paradigms "
                            "--list shows them)", name), -1;
    size_t i = (size_t)(a - paradigm_get(0));
    for (size_t k = 0; k < n; k++)
      if (alg[k] == i) return cli_error(CMD, "--algorithms: '%s' given twice", name), -1;
    alg[n++] = i;
  }
  return (int)n;
}

static int cli_par_families(const char *s, paradigm_problem pb, int *fam) {
  int n = 0;
  char name[64], names[512];
  for (long len; (len = cli_par_item(&s, name, sizeof name)) >= 0;) {
    int k = (size_t)len < sizeof name ? study_paradigms_family_find(pb, name) : -1;
    if (k < 0) {
      study_paradigms_family_names(pb, names, sizeof names);
      return cli_error(CMD, "--families: unknown family '%.40s' of the %s problem (valid: %s)",
                       name, paradigm_problem_name(pb), names), -1;
    }
    for (int j = 0; j < n; j++)
      if (fam[j] == k) return cli_error(CMD, "--families: '%s' given twice", name), -1;
    if (n == CLI_PAR_MAX_FAMILIES) return cli_error(CMD, "--families: at most %d", n), -1;
    fam[n++] = k;
  }
  return n;
}

static int cli_par_sizes(const char *s, uint64_t *sizes) {
  int n = 0;
  char item[32];
  for (long len; (len = cli_par_item(&s, item, sizeof item)) >= 0;) {
    if (n == CLI_PAR_MAX_SIZES) return cli_error(CMD, "--sizes: at most %d sizes", n), -1;
    if ((size_t)len >= sizeof item)
      return cli_error(CMD, "--sizes: '%.31s...' is no size", item), -1;
    if (cli_parse_u64(CMD, "--sizes", item, 3, 100000000u, &sizes[n]) != 0) return -1;
    n++;
  }
  return n;
}

/* The problems bit set as names: "delaunay, constrained". */
static void cli_par_problems(unsigned bits, char *buf, size_t len) {
  buf[0] = '\0';
  for (unsigned b = PARADIGM_DELAUNAY; b <= PARADIGM_CONVEX; b <<= 1)
    if (bits & b) {
      size_t u = strlen(buf);
      snprintf(buf + u, len - u, "%s%s", u ? ", " : "", paradigm_problem_name((paradigm_problem)b));
    }
}

static int cli_par_list(void) {
  printf("| algorithm | paradigm | section | problems | rules | cost | refuses |\n"
         "|---|---|---|---|---|---|---|\n");
  for (size_t i = 0; i < paradigm_count(); i++) {
    const paradigm_algorithm *a = paradigm_get(i);
    char pb[96];
    cli_par_problems(a->problems, pb, sizeof pb);
    printf("| %s | %s | %s | %s | %s | %s | %s |\n", a->name, a->paradigm, a->section, pb,
           a->rules & PARADIGM_RULE_ES ? "DT, ES:SHAPE" : "DT", a->cost, a->refusal);
  }
  return 0;
}

static int cli_par_write(const cli_par_opts *o, const study_paradigms_plan *pl,
                         const study_paradigms_cell *cells) {
  if (o->csv != NULL) {
    FILE *f = cli_open_out(CMD, o->csv);
    if (f == NULL) return 2;
    if (cli_finish_out(CMD, f, report_paradigms_csv(f, pl, cells)) != 0) return 1;
  }
  if (o->svg != NULL) {
    FILE *f = cli_open_out(CMD, o->svg);
    if (f == NULL) return 2;
    char title[160];
    snprintf(title, sizeof title, "%.60s, %s, %s (seed %llu)", pl->rules[0].name,
             paradigm_problem_name(pl->problem),
             study_paradigms_family_name(pl->problem, pl->families[0]),
             (unsigned long long)pl->seed);
    if (cli_finish_out(CMD, f, report_paradigms_svg(f, title, pl, cells, o->measure)) != 0)
      return 1;
  }
  return 0;
}

/* Run the matrix of pl, print it, write the files. */
static int cli_par_matrix(const cli_par_opts *o, const study_paradigms_plan *pl) {
  study_paradigms_cell *cells = malloc(study_paradigms_cells(pl) * sizeof *cells);
  if (cells == NULL) return cli_error(CMD, "out of memory"), 1;
  char err[256];
  int rc = study_paradigms_run(pl, cells, err, sizeof err);
  if (rc != 0) {
    free(cells);
    return rc == -2 ? (cli_error(CMD, "out of memory"), 1) : (cli_error(CMD, "%s", err), 1);
  }
  printf("# fliplab paradigms: %s problem, %zu algorithms, %zu rules, %zu families, %zu sizes, "
         "median of %d runs, seed %llu\n\n", paradigm_problem_name(pl->problem),
         pl->nalgorithms, pl->nrules, pl->nfamilies, pl->nsizes, pl->runs,
         (unsigned long long)pl->seed);
  report_paradigms_md(stdout, pl, cells);
  rc = cli_par_write(o, pl, cells);
  free(cells);
  return rc;
}

int cli_cmd_paradigms(int argc, char **argv) {
  cli_par_opts o;
  int st = cli_options_parse(&cli_par_spec, argc, argv, &o, NULL);
  if (st != 0) return st == 1 ? 0 : st;
  if (o.list) return cli_par_list();
  size_t *alg = malloc(paradigm_count() * sizeof *alg);
  if (alg == NULL) return cli_error(CMD, "out of memory"), 1;
  int fam[CLI_PAR_MAX_FAMILIES];
  uint64_t sizes[CLI_PAR_MAX_SIZES];
  rule *rules = NULL;
  int na = cli_par_algorithms(o.algorithms ? o.algorithms : "all", alg);
  paradigm_problem pb = (paradigm_problem)(1 << o.problem);
  int nf = na < 0 ? -1 : cli_par_families(o.families ? o.families
                                                    : cli_par_default_family[o.problem], pb, fam);
  int ns = nf < 0 ? -1 : cli_par_sizes(o.sizes ? o.sizes : CLI_PAR_SIZES, sizes);
  char err[256];
  for (int f = 0; f < nf && ns > 0; f++)   /* a convex sampler's sizes */
    for (int k = 0; k < ns && ns > 0; k++)
      if (study_paradigms_family_check(pb, fam[f], sizes[k], err, sizeof err) != 0)
        ns = -1, cli_error(CMD, "--families: %s", err);
  int nr = ns < 0 ? -1 : cli_rule_list_new(CMD, o.rules ? o.rules : "DT", &rules);
  if (nr < 0) rules = NULL;   /* freed by cli_rule_list_new */
  int rc = 2;
  if (nr > 0) {
    study_paradigms_plan pl = {alg, (size_t)na, rules, (size_t)nr, fam, (size_t)nf, sizes,
                               (size_t)ns, (int)o.runs, o.seed, pb};
    rc = cli_par_matrix(&o, &pl);
  }
  free(rules);
  free(alg);
  return rc;
}
