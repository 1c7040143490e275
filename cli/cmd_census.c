/*
** cmd_census.c: `fliplab census`: table 3.4 generalised from convex
** pentagons to random sets of N sites (convex N-gons, or N independent
** points from a disc, a square, a normal distribution): per rule, how many
** directed flip graphs have one sink, one sink that is DT, several sinks,
** none, a tie; the mean and largest number of sinks; the mean gap between
** the worst sink and the GOT.  Or a shard of it, for `fliplab merge`.
*/
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "joint.h"
#include "measure.h"
#include "report.h"
#include "rule.h"
#include "sampler.h"
#include "siteflip.h"

#define CMD "census"
#define CLI_CENSUS_MAX_SAMPLES 1000000000000ull   /* 1e12 */

static const cli_option cli_census_help[] = {
  {"--sites", "N", "6", "sites per set, 3 to 12"},
  {"--sampler", "S", "convex",
   "convex: convex N-gons by the thesis's iteration method (for\n"
   "                     N = 5 the very pentagons of table34); disc, square, normal:\n"
   "                     N independent points (most sets have interior sites)"},
  {"--samples", "S", "10000", "site sets, at most 1e12"},
  {"--seed", "S", "1", "sampler seed; same seed, same table"},
  {"--measures", "M", "table34",
   "table34, all, or a comma list of measures: every measure x\n"
   "                     joint rule of them, then DT"},
  {"--rules", "R", "none", "instead of --measures: a comma list of rules (e.g. R_1,DT)"},
  {"--threads", "T", "all cores", "threads; the table does not depend on T"},
  {"--shard", "K/N", "none",
   "only samples [floor((K-1)S/N), floor(KS/N)); fliplab merge\n"
   "                     sums the shards' CSVs into the unsharded CSV, byte for byte"},
  {"--tie-eps", "E", "1e-12", "relative tie tolerance of the rules"},
  {"--format", "F", "--out's extension, else text", "text, md, or csv (docs/sitesets.md)"},
  {"--out", "FILE", "stdout", "write the table to FILE"},
};

static void cli_census_usage(void) {
  cli_help(stdout, "usage: fliplab census --sites N [--sampler convex|disc|square|normal] [options]",
           "Table 3.4 for any small site set: enumerate every triangulation of random sets\n"
           "of N sites, direct their flip graphs by each rule and count one sink, sink = DT,\n"
           "two or more sinks, no sink, tie; the mean and largest number of sinks; the mean\n"
           "gap of the worst sink to the GOT (triangle-based rules; docs/sitesets.md).\n",
           cli_census_help, CLI_NOPTS(cli_census_help));
}

typedef struct cli_census_opts {
  uint64_t sites, samples, seed, threads, shard_k, shard_n;
  int sampler;
  double tie_eps;
  report_format format;
  const char *out, *measures, *rules;
} cli_census_opts;

static int cli_census_option(int argc, char **argv, int *i, cli_census_opts *o) {
  const char *a = argv[*i], *v;
  static const struct { const char *name; uint64_t lo, hi; size_t off; } nums[] = {
    {"--sites", 3, SITEFLIP_MAX_SITES, offsetof(cli_census_opts, sites)},
    {"--samples", 1, CLI_CENSUS_MAX_SAMPLES, offsetof(cli_census_opts, samples)},
    {"--seed", 0, UINT64_MAX, offsetof(cli_census_opts, seed)},
    {"--threads", 1, 1024, offsetof(cli_census_opts, threads)},
  };
  for (size_t k = 0; k < sizeof nums / sizeof nums[0]; k++)
    if (strcmp(a, nums[k].name) == 0) {
      uint64_t *dst = (uint64_t *)((char *)o + nums[k].off);
      if ((v = cli_optarg(CMD, argc, argv, i)) == NULL) return -1;
      if (cli_parse_u64(CMD, a, v, 0, UINT64_MAX, dst) != 0) return -1;   /* said why */
      if (*dst >= nums[k].lo && *dst <= nums[k].hi) return 0;
      if (strcmp(a, "--sites") != 0) return cli_parse_u64(CMD, a, v, nums[k].lo, nums[k].hi, dst);
      cli_error(CMD, "--sites %s: the census enumerates every triangulation, so it takes "
                     "3 to %d sites", v, SITEFLIP_MAX_SITES);
      return -1;
    }
  if ((v = cli_optarg(CMD, argc, argv, i)) == NULL) return -1;
  if (strcmp(a, "--sampler") == 0) {
    if ((o->sampler = sampler_sites_find(v)) < 0)
      return cli_error(CMD, "--sampler: unknown sampler '%s' (valid: convex, disc, square, "
                            "normal)", v), -1;
  } else if (strcmp(a, "--tie-eps") == 0) {
    return cli_parse_double(CMD, a, v, 0, 1, &o->tie_eps);
  } else if (strcmp(a, "--format") == 0) {
    if (report_format_parse(v, &o->format) != 0)
      return cli_error(CMD, "--format must be text, md or csv, got '%s'", v), -1;
  } else if (strcmp(a, "--shard") == 0) {
    return cli_parse_shard(CMD, v, &o->shard_k, &o->shard_n);
  } else if (strcmp(a, "--measures") == 0) {
    o->measures = v;
  } else if (strcmp(a, "--rules") == 0) {
    o->rules = v;
  } else if (strcmp(a, "--out") == 0) {
    o->out = v;
  }
  return 0;
}

static int cli_census_parse(int argc, char **argv, cli_census_opts *o) {
  *o = (cli_census_opts){.sites = 6, .samples = 10000, .seed = 1, .sampler = SAMPLER_SITES_CONVEX,
                         .tie_eps = RULE_DEFAULT_TIE_EPS, .format = REPORT_TEXT,
                         .measures = "table34"};
  int have_measures = 0, have_format = 0;
  for (int i = 1; i < argc; i++) {
    if (cli_is_help(argv[i])) {
      cli_census_usage();
      return 1;
    }
    if (cli_option_find(argv[i], cli_census_help, CLI_NOPTS(cli_census_help)) == NULL) {
      cli_unknown_option(CMD, argv[i], cli_census_help, CLI_NOPTS(cli_census_help));
      return -1;
    }
    have_measures |= strcmp(argv[i], "--measures") == 0;
    have_format |= strcmp(argv[i], "--format") == 0;
    if (cli_census_option(argc, argv, &i, o) != 0) return -1;
  }
  if (!have_format && o->out != NULL) {   /* the table format --out's name asks for */
    const char *f = cli_format_of_path(o->out);
    if (f != NULL) report_format_parse(f, &o->format);
  }
  if (have_measures && o->rules != NULL) {
    cli_error(CMD, "--measures and --rules exclude each other");
    return -1;
  }
  return 0;
}

/* --rules A,B,C or the measures' (measure x joint) rules then DT; count
** or -1 (*rules malloc'ed). */
static int cli_census_rules(const cli_census_opts *o, rule **rules) {
  if (o->rules == NULL) {
    int ids[MEASURE_MAX];
    int nm = cli_measure_list(CMD, o->measures, ids);
    if (nm < 0) return -1;
    int cap = nm * JOINT_COUNT + 1;
    if ((*rules = malloc((size_t)cap * sizeof **rules)) == NULL) return cli_error(CMD, "out of memory"), -1;
    int n = rule_list_triangle(ids, nm, *rules, cap - 1);
    (*rules)[n++] = rule_delaunay();
    return n;
  }
  int cap = 1;
  for (const char *c = o->rules; *c; c++) cap += *c == ',';
  if ((*rules = malloc((size_t)cap * sizeof **rules)) == NULL) return cli_error(CMD, "out of memory"), -1;
  int n = 0;
  if (cli_parse_rule_list(CMD, o->rules, *rules, &n, cap) != 0) {
    free(*rules);
    return -1;
  }
  return n;
}

int cli_cmd_census(int argc, char **argv) {
  cli_census_opts o;
  int st = cli_census_parse(argc, argv, &o);
  if (st != 0) return st > 0 ? 0 : 2;
  uint64_t first = 0, count = o.samples;
  if (o.shard_n > 0) census_shard_range(o.samples, o.shard_k, o.shard_n, &first, &count);
  rule *rules;
  int nrules = cli_census_rules(&o, &rules);
  if (nrules < 0) return 2;
  siteflip_counts *counts = calloc((size_t)nrules, sizeof *counts);
  report_census_row *rows = calloc((size_t)nrules, sizeof *rows);
  FILE *out = NULL;
  int rc = 2;
  char err[256];
  if (counts == NULL || rows == NULL) {
    cli_error(CMD, "out of memory");
    goto done;
  }
  if ((out = cli_open_out(CMD, o.out)) == NULL) goto done;   /* before a long run */
  if (count > 0) {
    cli_progress prog;
    cli_progress_start(&prog, CMD);
    int t = siteflip_census(rules, nrules, o.sampler, (int)o.sites, o.seed, first, count,
                            o.tie_eps, (int)o.threads, counts, cli_progress_update, &prog,
                            err, sizeof err);
    cli_progress_finish(&prog);
    rc = 1;
    if (t != 0) {
      cli_error(CMD, "%s", err);
      goto done;
    }
    if (cli_userdefs_failed(CMD)) goto done;
  }
  for (int r = 0; r < nrules; r++) {
    counts[r].samples = count;
    report_census_row_from_rule(&rows[r], &rules[r], (int)o.sites, sampler_sites_name(o.sampler),
                                &counts[r]);
  }
  report_census_meta meta = {1, o.seed, 1, o.tie_eps, o.shard_k, o.shard_n};
  /* A failed write sets the stream's error flag; cli_close_out reports it. */
  report_census_write(out, o.format, &meta, rows, nrules);
  rc = cli_close_out(out) != 0 ? 1 : 0;
  out = NULL;
done:
  cli_abort_out(out);     /* only on an early exit: nothing to keep */
  free(counts);
  free(rows);
  free(rules);
  return rc;
}
