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
#define CLI_MAX_THREADS 1024

static const cli_option cli_table34_help[] = {
  {"--samples", "N", "5000", "pentagons, at most 1e12"},
  {"--seed", "S", "1", "sampler seed; same seed, same table"},
  {"--sampler", "NAME", "iteration",
   "the pentagons: iteration (the thesis's), vector, circle or\n"
   "                     disc-hull (docs/sampling.md); merge refuses all but iteration"},
  {"--threads", "T", "all cores", "threads; the table does not depend on T"},
  {"--measures", "M", "table34",
   "table34 (the thesis's 20 columns), all (those, then beta, d,\n"
   "                     sigma and user measures) or a comma list of measure names,\n"
   "                     e.g. R,-alpha,mymeasure"},
  {"--tie-eps", "E", "1e-12", "relative tie tolerance of the rules"},
  {"--format", "F", "--out's extension, else text",
   "text, md, or csv (one row per rule, DT last; docs/formats.md)"},
  {"--columns", "C", "fit the terminal; no limit off a terminal",
   "text: at most C measures per block"},
  {"--out", "FILE", "stdout", "write the table to FILE"},
  {"--shard", "K/N", "none",
   "only samples [floor((K-1)S/N), floor(KS/N)) of the S samples;\n"
   "                     sum the shards' CSVs with fliplab merge"},
  {"--plot", "FILE.svg", "none", "also draw type-I % against DT % (thesis figure 3.9)"},
};

static void cli_table34_usage(void) {
  cli_help(stdout, "usage: fliplab table34 [options]",
           "Classify the directed flip graphs of random convex pentagons (the thesis's\n"
           "iteration method in the unit disc) under every (measure x joint) rule and DT:\n"
           "types I-V and agreement with Delaunay (docs/classification.md, docs/sampling.md).\n",
           cli_table34_help, CLI_NOPTS(cli_table34_help));
}

typedef struct cli_table34_opts {
  uint64_t samples, seed, threads, shard_k, shard_n, columns;
  double tie_eps;
  report_format format;
  int has_format, has_columns;
  const char *out, *plot, *measures;
  const sampler_pentagons *sampler;
} cli_table34_opts;

/* The format: --format, else the one --out's extension names, else text;
** a --format contradicting the extension is refused. */
static int cli_table34_format(cli_table34_opts *o) {
  const char *ext = o->out ? cli_format_of_path(o->out) : NULL;
  report_format f;
  if (ext == NULL || report_format_parse(ext, &f) != 0) return 0;
  if (!o->has_format) {
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

/* --sampler NAME: one of sampler_pentagons_table, else a one-line error
** with the closest name. */
static int cli_table34_sampler(const char *v, cli_table34_opts *o) {
  if ((o->sampler = sampler_pentagons_find(v)) != NULL) return 0;
  const char *names[SAMPLER_PENTAGONS_COUNT];
  for (int k = 0; k < SAMPLER_PENTAGONS_COUNT; k++) names[k] = sampler_pentagons_table[k].name;
  const char *near = cli_closest(v, names, SAMPLER_PENTAGONS_COUNT);
  if (near != NULL)
    cli_error(CMD, "--sampler: unknown sampler '%s': did you mean '%s'?", v, near);
  else
    cli_error(CMD, "--sampler: unknown sampler '%s' (valid: iteration, vector, circle, "
                   "disc-hull)", v);
  return -1;
}

static int cli_table34_parse(int argc, char **argv, cli_table34_opts *o) {
  *o = (cli_table34_opts){.samples = 5000, .seed = 1, .tie_eps = RULE_DEFAULT_TIE_EPS,
                          .format = REPORT_TEXT, .measures = "table34",
                          .sampler = &sampler_pentagons_table[0]};
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i], *v;
    if (cli_is_help(a)) {
      cli_table34_usage();
      return 1;
    }
    if (strcmp(a, "--samples") == 0) {
      if ((v = cli_optarg(CMD, argc, argv, &i)) == NULL ||
          cli_parse_u64(CMD, a, v, 1, CLI_MAX_SAMPLES, &o->samples) != 0)
        return -1;
    } else if (strcmp(a, "--seed") == 0) {
      if ((v = cli_optarg(CMD, argc, argv, &i)) == NULL ||
          cli_parse_u64(CMD, a, v, 0, UINT64_MAX, &o->seed) != 0)
        return -1;
    } else if (strcmp(a, "--threads") == 0) {
      if ((v = cli_optarg(CMD, argc, argv, &i)) == NULL ||
          cli_parse_u64(CMD, a, v, 1, CLI_MAX_THREADS, &o->threads) != 0)
        return -1;
    } else if (strcmp(a, "--tie-eps") == 0) {
      if ((v = cli_optarg(CMD, argc, argv, &i)) == NULL ||
          cli_parse_double(CMD, a, v, 0, 1, &o->tie_eps) != 0)
        return -1;
    } else if (strcmp(a, "--format") == 0) {
      if ((v = cli_optarg(CMD, argc, argv, &i)) == NULL) return -1;
      if (report_format_parse(v, &o->format) != 0) {
        cli_error(CMD, "--format must be text, md or csv, got '%s'", v);
        return -1;
      }
      o->has_format = 1;
    } else if (strcmp(a, "--columns") == 0) {
      if ((v = cli_optarg(CMD, argc, argv, &i)) == NULL ||
          cli_parse_u64(CMD, a, v, 1, MEASURE_MAX, &o->columns) != 0)
        return -1;
      o->has_columns = 1;
    } else if (strcmp(a, "--shard") == 0) {
      if ((v = cli_optarg(CMD, argc, argv, &i)) == NULL ||
          cli_parse_shard(CMD, v, &o->shard_k, &o->shard_n) != 0)
        return -1;
    } else if (strcmp(a, "--sampler") == 0) {
      if ((v = cli_optarg(CMD, argc, argv, &i)) == NULL || cli_table34_sampler(v, o) != 0)
        return -1;
    } else if (strcmp(a, "--measures") == 0) {
      if ((o->measures = cli_optarg(CMD, argc, argv, &i)) == NULL) return -1;
    } else if (strcmp(a, "--out") == 0) {
      if ((o->out = cli_optarg(CMD, argc, argv, &i)) == NULL) return -1;
    } else if (strcmp(a, "--plot") == 0) {
      if ((o->plot = cli_optarg(CMD, argc, argv, &i)) == NULL ||
          cli_check_out_ext(CMD, a, o->plot, "svg") != 0)
        return -1;
    } else {
      cli_unknown_option(CMD, a, cli_table34_help, CLI_NOPTS(cli_table34_help));
      return -1;
    }
  }
  if (cli_table34_format(o) != 0) return -1;
  if (!o->has_columns && o->format == REPORT_TEXT && (o->out == NULL || strcmp(o->out, "-") == 0))
    o->columns = cli_terminal_columns(20, 8);
  return 0;
}

/* The rules: every (measure x joint) of the chosen measures, table order,
** then DT.  *rules is malloc'ed; count or -1. */
static int cli_table34_rules(const char *measures, rule **rules) {
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
                       .sampler = o->sampler == &sampler_pentagons_table[0] ? NULL
                                                                            : o->sampler->draw};
  int t = flipgraph_tally_run(rules, nrules, &run, counts);
  cli_progress_finish(&prog);
  if (t != 0) {
    cli_error(CMD, "out of memory");   /* the tally fails only to allocate */
    return -1;
  }
  return cli_userdefs_failed(CMD) ? -1 : 0;
}

int cli_cmd_table34(int argc, char **argv) {
  cli_table34_opts o;
  int st = cli_table34_parse(argc, argv, &o);
  if (st != 0) return st > 0 ? 0 : 2;

  uint64_t first = 0, count = o.samples;
  if (o.shard_n > 0) census_shard_range(o.samples, o.shard_k, o.shard_n, &first, &count);
  rule *rules;
  int nrules = cli_table34_rules(o.measures, &rules);
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
  const char *sampler = o.sampler == &sampler_pentagons_table[0] ? NULL : o.sampler->name;
  report_run run = {.known = 1, .seed = o.seed, .tie_eps = o.tie_eps, .first = first,
                    .end = first + count, .total = o.samples, .rules = (uint64_t)nrules,
                    .sampler = sampler};
  report_meta meta = {.samples = count, .has_seed = 1, .seed = o.seed, .has_tie_eps = 1,
                      .tie_eps = o.tie_eps, .shard_k = o.shard_k, .shard_n = o.shard_n,
                      .shard_first = first, .shard_total = o.samples,
                      .text_columns = (int)o.columns, .run = &run, .sampler = sampler};
  uint64_t iv = report_type_iv(rows, nrules);
  if (iv > 0)
    fprintf(stderr, "fliplab table34: WARNING: %llu type-IV flip graphs from triangle-based "
                    "rules, which theorem 1 rules out: this is a bug\n",
            (unsigned long long)iv);
  /* A failed write sets the stream's error flag, which cli_close_out
  ** reports (once, naming the file). */
  int w = report_write(out, o.format, &meta, rows, nrules);
  rc = cli_finish_out(CMD, out, w);
  if (rc == 0 && plot != NULL)
    rc = cli_finish_out(CMD, plot, report_scatter_svg(plot, &meta, rows, nrules));
  else
    cli_abort_out(plot);
  out = plot = NULL;
done:
  cli_abort_out(out);     /* only on an early exit: nothing to keep */
  cli_abort_out(plot);
  free(counts);
  free(rows);
  free(rules);
  return rc;
}
