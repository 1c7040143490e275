/*
** cmd_table34.c: `fliplab table34`: regenerate the thesis's table 3.4, the
** % of directed flip graphs of each type for the 120 (measure x joint)
** rules over random pentagons, with DT alongside; or a shard of it, to be
** summed by `fliplab merge`.  --sampler picks the pentagons
** (sampler_pentagons_table; docs/sampling.md).
*/
#include <stdlib.h>
#include <string.h>
#include "measure.h"
#include "flipgraph.h"
#include "cli.h"
#include "rule.h"
#include "joint.h"
#include "report.h"
#include "sampler.h"

#define CMD "table34"
#define CLI_MAX_SAMPLES 1000000000000ull   /* 1e12 */

typedef struct cli_table34_opts {
  uint64_t samples, seed, threads, columns;
  cli_shard shard;
  double tie_eps;
  report_format format;
  const char *out, *plot, *measures, *rules;
  int has_measures;
  int sampler;                   /* index in sampler_pentagons_table */
} cli_table34_opts;

static int cli_table34_sampler(const char *cmd, const cli_option *o, const char *v, void *dst);

#define T cli_table34_opts
static const cli_option cli_table34_help[] = {
  CLI_OPT_U64("--samples", "N", "pentagons, at most 1e12", T, samples, 1, CLI_MAX_SAMPLES, 5000),
  CLI_OPT_SEED("sampler seed; same seed, same table", T, seed),
  {.name = "--sampler", .arg = "NAME", .dflt = "iteration",
   .help = "the pentagons: iteration (the thesis's), vector, circle or\n"
           "                     disc-hull (docs/sampling.md); merge refuses all but iteration",
   .kind = CLI_CALL, .off = CLI_AT(T, sampler, int), .call = cli_table34_sampler},
  CLI_OPT_THREADS("threads; the table does not depend on T", T, threads),
  {.name = "--measures", .arg = "M", .sdef = "table34", .kind = CLI_STRING,
   .help = "table34 (the thesis's 20 columns), all (those, then beta, d,\n"
           "                     sigma and user measures) or a comma list of measure names,\n"
           "                     e.g. R,-alpha,mymeasure",
   .off = CLI_AT(T, measures, const char *)},
  CLI_OPT_STRING("--rules", "R", "none",
                 "instead of --measures: a comma list of rules (e.g. R_1,P_3,DT)", T, rules),
  CLI_OPT_TIE_EPS("relative tie tolerance of the rules", 1, T, tie_eps),
  CLI_OPT_FORMAT("--out's extension, else text",
                 "text, md, or csv (one row per rule, DT last; docs/formats.md)", REPORT_TEXT,
                 "--format must be text, md or csv, got '%s'", T, format),
  {.name = "--columns", .arg = "C", .dflt = "fit the terminal; no limit off a terminal",
   .help = "text: at most C measures per block", .kind = CLI_U64,
   .off = CLI_AT(T, columns, uint64_t), .lo = 1, .hi = MEASURE_MAX},
  CLI_OPT_OUT("FILE", "stdout", NULL, "write the table to FILE", T, out),
  CLI_OPT_SHARD("only samples [floor((K-1)S/N), floor(KS/N)) of the S samples;\n"
                "                     sum the shards' CSVs with fliplab merge", T, shard),
  CLI_OPT_FILE("--plot", "FILE.svg", "none", "svg",
               "also draw type-I % against DT % (thesis figure 3.9)", T, plot),
};
#undef T

static const cli_spec cli_table34_spec = {
  CMD, "usage: fliplab table34 [options]",
  "Classify the directed flip graphs of random convex pentagons (the thesis's\n"
  "iteration method in the unit disc) under every (measure x joint) rule and DT:\n"
  "types I-V and agreement with Delaunay (docs/classification.md, docs/sampling.md).\n",
  cli_table34_help, CLI_NOPTS(cli_table34_help), NULL};

/* The format: --format, else the one --out's extension names, else text;
** a --format contradicting the extension is refused. */
static int cli_table34_format(cli_table34_opts *o, int has_format) {
  const char *ext = o->out ? cli_format_of_path(o->out) : NULL;
  report_format f;
  if (ext == NULL || report_format_parse(ext, &f) != 0) return 0;
  if (!has_format) {
    o->format = f;
    return 0;
  }
  if (f != o->format) {
    cli_error(CMD, "--out '%s' names a .%s file but --format is another format", o->out,
              strrchr(o->out, '.') + 1);
    return -1;
  }
  return 0;
}

/* --sampler NAME: one of sampler_pentagons_table (its index), else a
** one-line error with the closest name. */
static int cli_table34_sampler(const char *cmd, const cli_option *o, const char *v, void *dst) {
  (void)o;
  const sampler_pentagons *s = v != NULL ? sampler_pentagons_find(v) : sampler_pentagons_table;
  if (s != NULL) {
    *(int *)dst = (int)(s - sampler_pentagons_table);
    return 0;
  }
  const char *names[SAMPLER_PENTAGONS_COUNT];
  for (int k = 0; k < SAMPLER_PENTAGONS_COUNT; k++) names[k] = sampler_pentagons_table[k].name;
  const char *near = cli_closest(v, names, SAMPLER_PENTAGONS_COUNT);
  if (near != NULL)
    return cli_error(cmd, "--sampler: unknown sampler '%s': did you mean '%s'?", v, near);
  return cli_error(cmd, "--sampler: unknown sampler '%s' (valid: iteration, vector, circle, "
                        "disc-hull)", v);
}

/* 0, 1 after --help, 2 after an error. */
static int cli_table34_parse(int argc, char **argv, cli_table34_opts *o) {
  uint64_t given;
  int st = cli_options_parse(&cli_table34_spec, argc, argv, o, &given);
  if (st != 0) return st;
  if (cli_table34_format(o, cli_option_given(&cli_table34_spec, given, "--format")) != 0)
    return 2;
  o->has_measures = cli_option_given(&cli_table34_spec, given, "--measures");
  if (!cli_option_given(&cli_table34_spec, given, "--columns") && o->format == REPORT_TEXT &&
      (o->out == NULL || strcmp(o->out, "-") == 0))
    o->columns = cli_terminal_columns(20, 8);
  return 0;
}

/* The rules: --rules as given, else every (measure x joint) of the chosen
** measures, table order, then DT.  *rules is malloc'ed; count or -1. */
static int cli_table34_rules(const cli_table34_opts *o, rule **rules) {
  const char *measures = o->measures;
  if (o->has_measures && o->rules != NULL)
    return cli_error(CMD, "--measures and --rules exclude each other"), -1;
  if (o->rules != NULL) return cli_rule_list_new(CMD, o->rules, rules);
  int ids[MEASURE_MAX];
  int nm = cli_measure_list(CMD, measures, ids);
  if (nm < 0) return -1;
  int cap = nm * JOINT_COUNT + 1;
  *rules = malloc((size_t)cap * sizeof **rules);
  if (*rules == NULL) {
    cli_error(CMD, "out of memory");
    return -1;
  }
  int n = rule_list_triangle(ids, nm, *rules, cap - 1);
  if (n <= 0) {
    free(*rules);
    cli_error(CMD, "--measures %s gives no triangle-based rules", measures);
    return -1;
  }
  (*rules)[n++] = rule_delaunay();
  return n;
}

/* Count samples [first, first + count) under every rule, with progress;
** 0, or -1 after a one-line error. */
static int cli_table34_tally(const cli_table34_opts *o, const rule *rules, int nrules,
                             uint64_t first, uint64_t count, flipgraph_counts *counts) {
  cli_progress prog;
  cli_progress_start(&prog, "table34");
  /* The iteration method is the tally's own default (sampler NULL). */
  flipgraph_run run = {.seed = o->seed, .first = first, .count = count, .tie_eps = o->tie_eps,
                       .threads = (int)o->threads, .progress = cli_progress_update,
                       .progress_ctx = &prog,
                       .sampler = o->sampler == 0 ? NULL
                                                  : sampler_pentagons_table[o->sampler].draw};
  int t = flipgraph_tally_run(rules, nrules, &run, counts);
  cli_progress_finish(&prog);
  if (t != 0) {
    cli_error(CMD, "out of memory");   /* the tally fails only to allocate */
    return -1;
  }
  return cli_userdefs_failed(CMD) ? -1 : 0;
}

/* The table into out and the scatter plot into plot (if not NULL), which
** are closed or discarded; the exit status. */
static int cli_table34_write(const cli_table34_opts *o, const report_row *rows, int nrules,
                             uint64_t first, uint64_t count, FILE *out, FILE *plot) {
  const char *sampler = o->sampler == 0 ? NULL : sampler_pentagons_table[o->sampler].name;
  report_run run = {.known = 1, .seed = o->seed, .tie_eps = o->tie_eps, .first = first,
                    .end = first + count, .total = o->samples, .rules = (uint64_t)nrules,
                    .sampler = sampler};
  report_meta meta = {.samples = count, .has_seed = 1, .seed = o->seed, .has_tie_eps = 1,
                      .tie_eps = o->tie_eps, .shard_k = o->shard.k, .shard_n = o->shard.n,
                      .shard_first = first, .shard_total = o->samples,
                      .text_columns = (int)o->columns, .run = &run, .sampler = sampler};
  uint64_t iv = report_type_iv(rows, nrules);
  if (iv > 0)
    fprintf(stderr, "fliplab table34: WARNING: %llu type-IV flip graphs from triangle-based "
                    "rules, which theorem 1 rules out: this is a bug\n",
            (unsigned long long)iv);
  /* A failed write sets the stream's error flag, which cli_close_out
  ** reports (once, naming the file). */
  int rc = cli_finish_out(CMD, out, report_write(out, o->format, &meta, rows, nrules));
  if (rc == 0 && plot != NULL)
    rc = cli_finish_out(CMD, plot, report_scatter_svg(plot, &meta, rows, nrules));
  else
    cli_abort_out(plot);
  return rc;
}

int cli_cmd_table34(int argc, char **argv) {
  cli_table34_opts o;
  int st = cli_table34_parse(argc, argv, &o);
  if (st != 0) return st == 1 ? 0 : st;

  uint64_t first = 0, count = o.samples;
  if (o.shard.n > 0) census_shard_range(o.samples, o.shard.k, o.shard.n, &first, &count);
  rule *rules;
  int nrules = cli_table34_rules(&o, &rules);
  if (nrules < 0) return 2;
  flipgraph_counts *counts = calloc((size_t)nrules, sizeof *counts);
  report_row *rows = calloc((size_t)nrules, sizeof *rows);
  FILE *out = NULL, *plot = NULL;
  int rc = 2;
  if (counts == NULL || rows == NULL) {
    cli_error(CMD, "out of memory");
    goto done;
  }
  /* Open the outputs first: a bad path should not cost a long run. */
  if ((out = cli_open_out(CMD, o.out)) == NULL) goto done;
  if (o.plot != NULL && (plot = cli_open_out(CMD, o.plot)) == NULL) goto done;

  if (count > 0 && cli_table34_tally(&o, rules, nrules, first, count, counts) != 0) {
    rc = 1;
    goto done;
  }
  for (int r = 0; r < nrules; r++) {
    counts[r].samples = count;
    report_row_from_rule(&rows[r], &rules[r], &counts[r]);
  }
  rc = cli_table34_write(&o, rows, nrules, first, count, out, plot);
  out = plot = NULL;
done:
  cli_abort_out(out);     /* only on an early exit: nothing to keep */
  cli_abort_out(plot);
  free(counts);
  free(rows);
  free(rules);
  return rc;
}
