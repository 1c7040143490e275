/*
** cmd_merge.c: `fliplab merge`: sum CSV shards into one table.  The CSV
** output is written by the same code as table34's, so merging the shards
** 1/N .. N/N of a run reproduces the unsharded CSV byte for byte.
**
** A sum is only meaningful over disjoint pieces of one run, so merge checks
** what each table34 CSV records on every row (docs/merge.md): the same
** seed, tie tolerance, total samples and rules (so the same --measures),
** sample ranges [first, end) that tile without gap or overlap, a row count
** equal to the recorded one (a file cut at a row boundary), and no file
** given twice, also under another name (device and inode).
**
** Each kind of CSV merge accepts is one entry of cli_merge_kinds, found by
** the first file's header; a new kind adds its entry and its own function.
*/
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "cli.h"
#include "measure.h"
#include "report.h"

#define CMD "merge"

typedef struct cli_merge_opts {
  const char *out, *plot;
  report_format fmt;
  uint64_t columns;
  const char **files;
  int nfiles;
} cli_merge_opts;

#define T cli_merge_opts
static const cli_option cli_merge_help[] = {
  CLI_OPT_OUT("FILE", "stdout", NULL, "write the merged table to FILE", T, out),
  CLI_OPT_FORMAT("csv", "csv, text or md: the table as table34 prints it", REPORT_CSV,
                 "--format must be csv, text or md, got '%s'", T, fmt),
  {.name = "--columns", .arg = "C", .dflt = "all in one block",
   .help = "text: at most C measures per block", .kind = CLI_U64,
   .off = CLI_AT(T, columns, uint64_t), .lo = 1, .hi = MEASURE_MAX},
  CLI_OPT_FILE("--plot", "FILE.svg", "none", "svg",
               "also draw type-I % against DT % (thesis figure 3.9)", T, plot),
};
#undef T

/* A file to merge ('-': standard input); other names starting with '-'
** are unknown options. */
static int cli_merge_positional(const char *cmd, const char *arg, void *dst) {
  cli_merge_opts *o = dst;
  if (arg[0] == '-' && arg[1] != '\0')
    return cli_unknown_option(cmd, arg, cli_merge_help, CLI_NOPTS(cli_merge_help));
  o->files[o->nfiles++] = arg;
  return 0;
}

static const cli_spec cli_merge_spec = {
  CMD, "usage: fliplab merge A.csv B.csv ... [options]",
  "Sum table34 CSV files (the shards of `fliplab table34 --shard K/N --format csv`),\n"
  "or census CSV files (`fliplab census --shard K/N --format csv`; no --plot).\n"
  "They must come from one run: same seed, tie tolerance, samples and measures,\n"
  "sample ranges that tile without gap or overlap, no file twice (docs/merge.md).\n"
  "A file name '-' reads standard input.\n",
  cli_merge_help, CLI_NOPTS(cli_merge_help), cli_merge_positional};

/* 0, 1 after --help, or 2 after a usage error (printed). */
static int cli_merge_parse(int argc, char **argv, cli_merge_opts *o) {
  int st = cli_options_parse(&cli_merge_spec, argc, argv, o, NULL);
  if (st != 0) return st;
  if (o->nfiles == 0) return cli_error(CMD, "no input files (try: fliplab merge --help)");
  return 0;
}

/* ---- the inputs: open once, each file once ------------------------------ */

typedef struct cli_merge_input {
  const char *name;
  FILE *f;
  report_row *rows;
  int nrows;
  report_run run;
} cli_merge_input;

/* Open every input, refusing one file named twice (by its device and inode,
** so also under two paths or through a link): its samples would count twice. */
static int cli_merge_open(cli_merge_input *in, const char **files, int n) {
  struct stat *st = calloc((size_t)n, sizeof *st);
  if (st == NULL) return cli_error(CMD, "out of memory");
  int rc = 0;
  for (int k = 0; k < n && rc == 0; k++) {
    in[k].name = files[k];
    in[k].f = strcmp(files[k], "-") == 0 ? stdin : fopen(files[k], "rb");
    if (in[k].f == NULL || fstat(fileno(in[k].f), &st[k]) != 0) {
      rc = cli_error(CMD, "cannot read '%s': %s", files[k], strerror(errno));
      break;
    }
    for (int j = 0; j < k; j++)
      if (st[j].st_dev == st[k].st_dev && st[j].st_ino == st[k].st_ino)
        rc = cli_error(CMD, "'%s' and '%s' are the same file: its samples would count twice",
                       files[j], files[k]);
  }
  free(st);
  return rc;
}

static void cli_merge_close(cli_merge_input *in, int n) {
  for (int k = 0; k < n; k++) {
    if (in[k].f != NULL && in[k].f != stdin) fclose(in[k].f);
    free(in[k].rows);
  }
}

/* ---- table34 counts ----------------------------------------------------- */

/* Read one shard and check that it belongs to the same run as the first. */
static int cli_merge_read34(cli_merge_input *in, const cli_merge_input *first) {
  char err[512];
  if (report_counts_read(in->f, in->name, &in->rows, &in->nrows, &in->run, err, sizeof err) != 0)
    return cli_error(CMD, "%s", err);
  if (!in->run.known)
    return cli_error(CMD, "%s has no run columns (seed,tie_eps,first,end,total,rules): "
                     "rerun its table34 with this fliplab", in->name);
  if (first == NULL) return 0;
  const report_run *a = &first->run, *b = &in->run;
  if (a->seed != b->seed)
    return cli_error(CMD, "%s is seed %llu, %s seed %llu: not shards of one run", in->name,
                     (unsigned long long)b->seed, first->name, (unsigned long long)a->seed);
  if (a->tie_eps != b->tie_eps)
    return cli_error(CMD, "%s has tie_eps %.17g, %s %.17g: not shards of one run", in->name,
                     b->tie_eps, first->name, a->tie_eps);
  if (a->total != b->total)
    return cli_error(CMD, "%s is a run of %llu samples, %s of %llu: not shards of one run",
                     in->name, (unsigned long long)b->total, first->name,
                     (unsigned long long)a->total);
  if (in->nrows != first->nrows)
    return cli_error(CMD, "%s has %d rules, %s %d: different --measures", in->name, in->nrows,
                     first->name, first->nrows);
  return 0;
}

static int cli_merge_by_first(const void *pa, const void *pb) {
  const cli_merge_input *a = pa, *b = pb;
  if (a->run.first != b->run.first) return a->run.first < b->run.first ? -1 : 1;
  return a->run.end < b->run.end ? -1 : a->run.end > b->run.end;
}

/* The ranges [first, end), sorted, must follow each other exactly. */
static int cli_merge_tiles(cli_merge_input *in, int n) {
  qsort(in, (size_t)n, sizeof *in, cli_merge_by_first);
  for (int k = 1; k < n; k++) {
    const report_run *a = &in[k - 1].run, *b = &in[k].run;
    if (a->end < b->first)
      return cli_error(CMD, "samples [%llu, %llu) are missing between %s and %s (a shard "
                       "not given?)", (unsigned long long)a->end, (unsigned long long)b->first,
                       in[k - 1].name, in[k].name);
    if (a->end > b->first)
      return cli_error(CMD, "%s and %s overlap: both count samples [%llu, %llu)",
                       in[k - 1].name, in[k].name, (unsigned long long)b->first,
                       (unsigned long long)(a->end < b->end ? a->end : b->end));
  }
  return 0;
}

static int cli_merge_write34(const cli_merge_opts *o, const report_row *rows, int nrows,
                             const report_run *run) {
  FILE *out = cli_open_out(CMD, o->out), *plot = NULL;
  if (out == NULL) return 2;
  if (o->plot != NULL && (plot = cli_open_out(CMD, o->plot)) == NULL) return 2;
  char note[160];
  int n = snprintf(note, sizeof note, "merged from %d CSV file%s", o->nfiles,
                   o->nfiles > 1 ? "s" : "");
  if (run->first != 0 || run->end != run->total)
    snprintf(note + n, sizeof note - (size_t)n, ": samples [%llu, %llu) of %llu",
             (unsigned long long)run->first, (unsigned long long)run->end,
             (unsigned long long)run->total);
  report_meta meta = {.samples = run->end - run->first, .has_seed = 1, .seed = run->seed,
                      .has_tie_eps = 1, .tie_eps = run->tie_eps, .note = note,
                      .text_columns = (int)o->columns, .run = run};
  int rc = cli_finish_out(CMD, out, report_write(out, o->fmt, &meta, rows, nrows));
  if (rc == 0 && plot != NULL)
    rc = cli_finish_out(CMD, plot, report_scatter_svg(plot, &meta, rows, nrows));
  return rc;
}

static int cli_merge_table34(const cli_merge_opts *o, cli_merge_input *in) {
  for (int k = 0; k < o->nfiles; k++)
    if (cli_merge_read34(&in[k], k > 0 ? &in[0] : NULL) != 0) return 2;
  char err[512];
  for (int k = 1; k < o->nfiles; k++)
    if (report_rows_add(in[0].rows, in[0].nrows, in[k].rows, in[k].nrows, in[k].name, err,
                        sizeof err) != 0)
      return cli_error(CMD, "%s", err);
  report_row *sum = in[0].rows;         /* tiles() reorders in[]: keep the sum */
  in[0].rows = NULL;
  int rc = cli_merge_tiles(in, o->nfiles);
  if (rc == 0) {
    report_run run = in[0].run;
    run.end = in[o->nfiles - 1].run.end;
    rc = cli_merge_write34(o, sum, in[0].nrows, &run);
  }
  free(sum);
  return rc;
}

/* ---- census CSVs ----------------------------------------------------------- */

/* `fliplab census --format csv` files: same rules, sites and sampler in the
** same order, summed and written by census's own writer (the means read
** back into exact sums: reports/census.c).  The census CSV records no
** seed or sample range, so tiling cannot be checked; --plot does not
** apply. */
static int cli_merge_census(const cli_merge_opts *o, cli_merge_input *in) {
  if (o->plot != NULL)
    return cli_error(CMD, "--plot draws table34 CSVs only; '%s' is a census CSV", in[0].name);
  report_census_row *acc = NULL, *add = NULL;
  int nacc = 0, nadd = 0, rc = 2;
  char err[512];
  if (report_census_read(in[0].f, in[0].name, &acc, &nacc, err, sizeof err) != 0)
    return cli_error(CMD, "%s", err);
  for (int k = 1; k < o->nfiles; k++) {
    int bad = report_census_read(in[k].f, in[k].name, &add, &nadd, err, sizeof err) != 0 ||
              report_census_add(acc, nacc, add, nadd, in[k].name, err, sizeof err) != 0;
    free(add);
    add = NULL;
    if (bad) {
      cli_error(CMD, "%s", err);
      goto done;
    }
  }
  FILE *out = cli_open_out(CMD, o->out);
  if (out == NULL) goto done;
  report_census_meta meta = {0};
  report_census_write(out, o->fmt, &meta, acc, nacc);   /* errors: cli_close_out */
  rc = cli_close_out(out) != 0 ? 1 : 0;
done:
  free(acc);
  return rc;
}

/* ---- kinds -------------------------------------------------------------- */

typedef struct cli_merge_kind {
  const char *header;     /* the first line starts with this */
  int (*run)(const cli_merge_opts *o, cli_merge_input *in);
} cli_merge_kind;

static const cli_merge_kind cli_merge_kinds[] = {
  {"measure,joint,rule,samples,", cli_merge_table34},
  {"measure,joint,rule,sites,sampler,", cli_merge_census},
};
#define CLI_MERGE_NKINDS (sizeof cli_merge_kinds / sizeof cli_merge_kinds[0])

/* The kind of the first input that is a file (standard input cannot be
** read twice): the entry whose header it starts with; else the first kind,
** whose reader then names the problem. */
static const cli_merge_kind *cli_merge_kind_of(const cli_merge_opts *o) {
  for (int k = 0; k < o->nfiles; k++) {
    if (strcmp(o->files[k], "-") == 0) continue;
    FILE *f = fopen(o->files[k], "rb");
    char line[256] = "";
    if (f == NULL) break;
    if (fgets(line, sizeof line, f) == NULL) line[0] = '\0';
    fclose(f);
    const char *h = strncmp(line, "\xEF\xBB\xBF", 3) == 0 ? line + 3 : line;
    for (size_t i = 0; i < CLI_MERGE_NKINDS; i++)
      if (strncmp(h, cli_merge_kinds[i].header, strlen(cli_merge_kinds[i].header)) == 0)
        return &cli_merge_kinds[i];
    break;
  }
  return &cli_merge_kinds[0];
}

int cli_cmd_merge(int argc, char **argv) {
  cli_merge_opts o = {0};
  o.files = calloc((size_t)argc, sizeof *o.files);
  if (o.files == NULL) return cli_error(CMD, "out of memory");
  int rc = cli_merge_parse(argc, argv, &o);
  if (rc != 0) {
    free(o.files);
    return rc == 1 ? 0 : rc;
  }
  cli_merge_input *in = calloc((size_t)o.nfiles, sizeof *in);
  if (in == NULL) rc = cli_error(CMD, "out of memory");
  if (rc == 0) rc = cli_merge_open(in, o.files, o.nfiles);
  if (rc == 0) rc = cli_merge_kind_of(&o)->run(&o, in);
  if (in != NULL) cli_merge_close(in, o.nfiles);
  free(in);
  free(o.files);
  return rc;
}
