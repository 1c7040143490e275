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

typedef struct cli_census_opts {
  uint64_t sites, samples, seed, threads, memory;
  cli_shard shard;
  int sampler;
  double tie_eps;
  report_format format;
  const char *out, *measures, *rules;
} cli_census_opts;

#define CLI_CENSUS_STR(x) CLI_CENSUS_STR2(x)
#define CLI_CENSUS_STR2(x) #x
#define T cli_census_opts
static const cli_option cli_census_help[] = {
  {.name = "--sites", .arg = "N", .help = "sites per set, 3 to 16", .kind = CLI_U64,
   .off = CLI_AT(T, sites, uint64_t), .lo = 3, .hi = SITEFLIP_MAX_SITES, .def = 6,
   .bad = "--sites %s: the census enumerates every triangulation, so it takes 3 to "
          CLI_CENSUS_STR(SITEFLIP_MAX_SITES) " sites"},
  {.name = "--sampler", .arg = "S", .dflt = "convex",
   .help = "convex: convex N-gons by the thesis's iteration method (for\n"
           "                     N = 5 the very pentagons of table34); disc, square, normal:\n"
           "                     N independent points (most sets have interior sites)",
   .kind = CLI_CHOICE, .off = CLI_AT(T, sampler, int), .find = sampler_sites_find,
   .idef = SAMPLER_SITES_CONVEX,
   .bad = "--sampler: unknown sampler '%s' (valid: convex, disc, square, normal)"},
  CLI_OPT_U64("--samples", "S", "site sets, at most 1e12", T, samples, 1, CLI_CENSUS_MAX_SAMPLES,
              10000),
  CLI_OPT_SEED("sampler seed; same seed, same table", T, seed),
  CLI_OPT_STRING("--measures", "M", "table34",
                 "table34, all, or a comma list of measures: every measure x\n"
                 "                     joint rule of them, then DT", T, measures),
  CLI_OPT_STRING("--rules", "R", "none",
                 "instead of --measures: a comma list of rules (e.g. R_1,DT)", T, rules),
  CLI_OPT_THREADS("threads; the table does not depend on T", T, threads),
  CLI_OPT_MEMORY("1G", SITEFLIP_MEMORY_DEFAULT,
                 "memory budget of each set's flip graph (K, M, G: KiB, MiB,\n"
                 "                     GiB; each thread holds one graph)", T, memory),
  CLI_OPT_SHARD("only samples [floor((K-1)S/N), floor(KS/N)); fliplab merge\n"
                "                     sums the shards' CSVs into the unsharded CSV, byte for byte",
                T, shard),
  CLI_OPT_TIE_EPS("relative tie tolerance of the rules", 1, T, tie_eps),
  CLI_OPT_FORMAT("--out's extension, else text", "text, md, or csv (docs/sitesets.md)",
                 REPORT_TEXT, "--format must be text, md or csv, got '%s'", T, format),
  CLI_OPT_OUT("FILE", "stdout", NULL, "write the table to FILE", T, out),
};
#undef T

static const cli_spec cli_census_spec = {
  CMD, "usage: fliplab census --sites N [--sampler convex|disc|square|normal] [options]",
  "Table 3.4 for any small site set: enumerate every triangulation of random sets\n"
  "of N sites, direct their flip graphs by each rule and count one sink, sink = DT,\n"
  "two or more sinks, no sink, tie; the mean and largest number of sinks; the mean\n"
  "gap of the worst sink to the GOT (triangle-based rules; docs/sitesets.md).\n"
  "A set whose flip graph outgrows --memory stops the run (exit 2).\n",
  cli_census_help, CLI_NOPTS(cli_census_help), NULL};

/* 0, 1 after --help, 2 after an error.  --measures table34 unless given. */
static int cli_census_parse(int argc, char **argv, cli_census_opts *o) {
  uint64_t given;
  int st = cli_options_parse(&cli_census_spec, argc, argv, o, &given);
  if (st != 0) return st;
  int have_measures = cli_option_given(&cli_census_spec, given, "--measures");
  if (!cli_option_given(&cli_census_spec, given, "--format") && o->out != NULL) {
    const char *f = cli_format_of_path(o->out);   /* the format --out's name asks for */
    if (f != NULL) report_format_parse(f, &o->format);
  }
  if (have_measures && o->rules != NULL)
    return cli_error(CMD, "--measures and --rules exclude each other");
  if (!have_measures) o->measures = "table34";
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
  return cli_rule_list_new(CMD, o->rules, rules);
}

int cli_cmd_census(int argc, char **argv) {
  cli_census_opts o;
  int st = cli_census_parse(argc, argv, &o);
  if (st != 0) return st == 1 ? 0 : st;
  uint64_t first = 0, count = o.samples;
  if (o.shard.n > 0) census_shard_range(o.samples, o.shard.k, o.shard.n, &first, &count);
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
    int over;
    int t = siteflip_census(rules, nrules, o.sampler, (int)o.sites, o.seed, first, count,
                            o.tie_eps, (int)o.threads, (size_t)o.memory, counts,
                            cli_progress_update, &prog, &over, err, sizeof err);
    cli_progress_finish(&prog);
    rc = t != 0 && over ? 2 : 1;
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
  report_census_meta meta = {1, o.seed, 1, o.tie_eps, o.shard.k, o.shard.n};
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
