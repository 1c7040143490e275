/*
** census.c: what `fliplab census` prints and `fliplab merge` reads back:
** the census CSV (through libcsv), and a table with one row per rule as
** text or Markdown.
**
** Exact merging.  The CSV carries two means; merge turns them back into
** the integer sums they were divided from: sinks = round(mean_sinks x
** (samples - tie)) and gap units = round(mean_worst_gap x (one_sink +
** multi_sink) / SITEFLIP_GAP_UNIT).  A mean is one correctly rounded
** quotient printed with %.17g, which reads back to the same double, so the
** product is the sum within a relative 2^-52: exact after rounding while
** the sum stays below 2^50 (gap units: at most 2^22 per sample, so up to
** 2^28 samples per file).  Shards therefore merge into the very bytes of
** the unsharded run.
*/
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "report_internal.h"
#include "measure.h"
#include "joint.h"

const char *const report_census_header[REPORT_CENSUS_NCOLS] = {
  "measure", "joint", "rule", "sites", "sampler", "samples", "tie", "no_sink",
  "one_sink", "multi_sink", "sink_dt", "mean_sinks", "max_sinks", "mean_worst_gap"};

void report_census_row_from_rule(report_census_row *row, const rule *r, int sites,
                                 const char *sampler, const siteflip_counts *c) {
  memset(row, 0, sizeof *row);
  snprintf(row->measure, sizeof row->measure, "%s", rule_measure_name(r));
  snprintf(row->joint, sizeof row->joint, "%s", rule_joint_name(r));
  snprintf(row->rule, sizeof row->rule, "%s", rule_name(r));
  snprintf(row->sampler, sizeof row->sampler, "%s", sampler);
  row->sites = sites;
  if (c != NULL) row->c = *c;
}

static uint64_t report_census_with_sink(const siteflip_counts *c) {
  return c->one_sink + c->multi_sink;
}

/* The two means; NAN when there is nothing to average (printed empty). */
static double report_census_mean_sinks(const siteflip_counts *c) {
  uint64_t d = c->samples - c->tie;
  return d > 0 ? (double)c->sinks / (double)d : NAN;
}

static double report_census_mean_gap(const report_census_row *r) {
  uint64_t d = report_census_with_sink(&r->c);
  if (r->measure[0] == '\0' || d == 0) return NAN;
  return (double)r->c.gap_units * SITEFLIP_GAP_UNIT / (double)d;
}

/* The counts table of census CSVs (below, with the reader). */
static const report_table report_census_kind;

static int report_census_csv(FILE *f, const report_census_row *rows, int nrows) {
  report_csv_row(f, report_census_header, REPORT_CENSUS_NCOLS);
  for (int r = 0; r < nrows; r++) {
    const report_census_row *w = &rows[r];
    const siteflip_counts *c = &w->c;
    char num[REPORT_CENSUS_NCOLS][32];
    double ms = report_census_mean_sinks(c), mg = report_census_mean_gap(w);
    snprintf(num[3], 32, "%d", w->sites);
    const char *field[REPORT_CENSUS_NCOLS] = {w->measure, w->joint, w->rule, num[3], w->sampler};
    report_table_format(&report_census_kind, w, num, field);   /* the integer columns */
    num[11][0] = num[13][0] = '\0';   /* empty: nothing to average */
    if (!isnan(ms)) snprintf(num[11], 32, "%.17g", ms);
    if (!isnan(mg)) snprintf(num[13], 32, "%.17g", mg);
    field[11] = num[11];
    field[13] = num[13];
    report_csv_row(f, field, REPORT_CENSUS_NCOLS);
  }
  return ferror(f) ? -1 : 0;
}

static void report_census_pct(char *buf, size_t len, uint64_t k, uint64_t n) {
  if (n == 0) snprintf(buf, len, "-");
  else snprintf(buf, len, "%.3f", 100.0 * (double)k / (double)n);
}

static const char *const report_census_cols[9] = {
  "rule", "one sink %", "sink=DT %", "2+ sinks %", "no sink %", "tie %",
  "mean sinks", "max sinks", "mean worst gap"};

/* The cells of one row, as strings (the rule's whole name fits). */
#define REPORT_CELL RULE_NAME_MAX
static void report_census_cells(const report_census_row *w, char cell[9][REPORT_CELL]) {
  const siteflip_counts *c = &w->c;
  snprintf(cell[0], REPORT_CELL, "%s", w->rule);
  report_census_pct(cell[1], 100, c->one_sink, c->samples);
  report_census_pct(cell[2], 100, c->sink_dt, c->samples);
  report_census_pct(cell[3], 100, c->multi_sink, c->samples);
  report_census_pct(cell[4], 100, c->no_sink, c->samples);
  report_census_pct(cell[5], 100, c->tie, c->samples);
  double ms = report_census_mean_sinks(c), mg = report_census_mean_gap(w);
  snprintf(cell[6], 100, "%.4f", ms);
  if (isnan(ms)) snprintf(cell[6], 100, "-");
  snprintf(cell[7], 100, "%llu", (unsigned long long)c->max_sinks);
  snprintf(cell[8], 100, "%.3g", mg);
  if (isnan(mg)) snprintf(cell[8], 100, "-");
}

static void report_census_title(FILE *f, const report_census_meta *m,
                                 const report_census_row *w, int md) {
  fprintf(f, "%sCensus of directed flip graphs: %d sites, sampler %s, %llu samples\n%s",
          md ? "### " : "", w->sites, w->sampler, (unsigned long long)w->c.samples,
          md ? "\n" : "");
  const char *sep = "";
  if (m->has_seed) {
    fprintf(f, "seed %llu", (unsigned long long)m->seed);
    sep = ", ";
  }
  if (m->has_tie_eps) {
    fprintf(f, "%stie eps %g", sep, m->tie_eps);
    sep = ", ";
  }
  if (m->shard_n > 0)
    fprintf(f, "%sshard %llu/%llu", sep, (unsigned long long)m->shard_k,
            (unsigned long long)m->shard_n);
  fprintf(f, "%s%% of site sets with one sink (one LOT), whose sink is DT, with two or\n"
             "more sinks (not systematic), no sink, a tie (counted only there); worst gap:\n"
             "the worst sink's total badness relative to the GOT's (triangle-based rules)\n\n",
          m->has_seed || m->has_tie_eps || m->shard_n > 0 ? "\n" : "");
}

static int report_census_table(FILE *f, const report_census_meta *m,
                               const report_census_row *rows, int nrows, int md) {
  if (nrows == 0) return 0;
  report_census_title(f, m, &rows[0], md);
  int width[9];
  for (int k = 0; k < 9; k++) width[k] = (int)strlen(report_census_cols[k]);
  char cell[9][REPORT_CELL];
  for (int r = 0; r < nrows; r++) {
    report_census_cells(&rows[r], cell);
    for (int k = 0; k < 9; k++)
      if ((int)strlen(cell[k]) > width[k]) width[k] = (int)strlen(cell[k]);
  }
  for (int k = 0; k < 9; k++) {
    if (md) fprintf(f, "| %s ", report_census_cols[k]);
    else fprintf(f, k ? "  %*s" : "%-*s", width[k], report_census_cols[k]);
  }
  fprintf(f, md ? "|\n|:--|--:|--:|--:|--:|--:|--:|--:|--:|\n" : "\n");
  for (int r = 0; r < nrows; r++) {
    report_census_cells(&rows[r], cell);
    for (int k = 0; k < 9; k++) {
      if (md) {
        fputs("| ", f);
        for (const char *s = cell[k]; *s; s++) {   /* Markdown: escape | and * */
          if (*s == '|' || *s == '*' || *s == '_') fputc('\\', f);
          fputc(*s, f);
        }
        fputc(' ', f);
      } else {
        fprintf(f, k ? "  %*s" : "%-*s", width[k], cell[k]);
      }
    }
    fputs(md ? "|\n" : "\n", f);
  }
  return ferror(f) ? -1 : 0;
}

int report_census_write(FILE *f, report_format fmt, const report_census_meta *m,
                        const report_census_row *rows, int nrows) {
  if (fmt == REPORT_CSV) return report_census_csv(f, rows, nrows);
  return report_census_table(f, m, rows, nrows, fmt == REPORT_MD);
}

/* ---- reading ---------------------------------------------------------------- */

typedef struct report_census_reader {
  report_tableread tr;
  int header_seen;
} report_census_reader;

static int report_census_mean(const char *s, size_t len, uint64_t denom, double scale,
                              uint64_t *out) {
  if (len == 0) {
    *out = 0;
    return 0;   /* nothing averaged (or no gap for this rule) */
  }
  double v = 0;
  if (geom_number_parse(s, len, &v) != GEOM_NUM_OK || !(v >= 0)) return -1;
  double x = v * (double)denom / scale;
  if (x >= 0x1p52) return -1;
  *out = (uint64_t)llround(x);
  return 0;
}

/* A triangle-based row's rule is MEASURE_JOINT; a quadrilateral rule's row
** has neither measure nor joint, and no gap (it has no GOT).  Anything else
** would not survive being written back (the writer derives the gap column
** from the measure). */
static int report_census_named(const report_census_row *row, const char *gap) {
  if (row->measure[0] == '\0') return row->joint[0] == '\0' && gap[0] == '\0';
  return rule_name_is(row->rule, row->measure, row->joint);
}

static int report_census_names(report_tableread *r, report_census_row *row, char **f,
                               unsigned long long ln) {
  if (strlen(f[0]) >= sizeof row->measure || strlen(f[1]) >= sizeof row->joint ||
      strlen(f[2]) >= sizeof row->rule || f[2][0] == '\0' || strlen(f[4]) >= sizeof row->sampler) {
    snprintf(r->err, r->errlen, "%s line %llu: rule or sampler name empty or too long",
             r->name, ln);
    return -1;
  }
  strcpy(row->measure, f[0]);
  strcpy(row->joint, f[1]);
  strcpy(row->rule, f[2]);
  strcpy(row->sampler, f[4]);
  if (!report_census_named(row, f[13])) {
    snprintf(r->err, r->errlen, "%s line %llu: rule '%.40s' does not match measure '%.40s' "
             "and joint '%.16s' (or has a gap without a measure)", r->name, ln, row->rule,
             row->measure, row->joint);
    return -1;
  }
  return 0;
}

/* The kind's fields of a census row (report_table.fields): names, sites,
** and the two means read back into their sums (the integer columns are
** read: the means' denominators). */
static int report_census_fields(report_tableread *r, char **f, void *p, unsigned long long ln) {
  report_census_row *row = p;
  siteflip_counts *c = &row->c;
  uint64_t sites;
  if (report_census_names(r, row, f, ln) != 0) return -1;
  if (geom_count_parse(f[3], r->len[3], &sites) != 0 || sites < 3 || sites > SITEFLIP_MAX_SITES) {
    snprintf(r->err, r->errlen, "%s line %llu: sites '%.40s' is not a site count 3..%d",
             r->name, ln, f[3], SITEFLIP_MAX_SITES);
    return -1;
  }
  row->sites = (int)sites;
  uint64_t untied = c->samples - (c->tie <= c->samples ? c->tie : 0);
  if (report_census_mean(f[11], r->len[11], untied, 1.0, &c->sinks) != 0 ||
      report_census_mean(f[13], r->len[13], c->one_sink + c->multi_sink, SITEFLIP_GAP_UNIT,
                         &c->gap_units) != 0) {
    snprintf(r->err, r->errlen, "%s line %llu: bad mean_sinks or mean_worst_gap", r->name, ln);
    return -1;
  }
  return 0;
}

/* The check rows of a census row.  The untied samples have no sink, one
** (one_sink) or 2 to max_sinks (multi_sink) sinks each, so one_sink + 2
** multi_sink <= sinks <= one_sink + max_sinks multi_sink, and max_sinks is
** 0 without a sink, 1 without a multi-sink sample, at least 2 with one (a
** row whose mean_sinks exceeds its max_sinks fails the upper bound). */
static int report_census_parts_sum(const void *p) {
  const siteflip_counts *c = &((const report_census_row *)p)->c;
  uint64_t parts[4] = {c->tie, c->no_sink, c->one_sink, c->multi_sink}, sum = 0;
  for (int k = 0; k < 4; k++) {
    if (parts[k] > c->samples - sum) return 0;
    sum += parts[k];
  }
  return sum == c->samples;
}

static int report_census_dt_le(const void *p) {
  const siteflip_counts *c = &((const report_census_row *)p)->c;
  return c->sink_dt <= c->one_sink;
}

static int report_census_sinks_fit(const void *p) {
  const siteflip_counts *c = &((const report_census_row *)p)->c;
  uint64_t one = c->one_sink, multi = c->multi_sink;
  if (one + multi == 0) return c->max_sinks == 0 && c->sinks == 0;
  if (multi == 0) return c->max_sinks == 1 && c->sinks == one;
  if (c->max_sinks < 2 || c->sinks < one || (c->sinks - one) / 2 < multi) return 0;
  uint64_t extra = c->sinks - one;   /* at most max_sinks x multi */
  return extra / multi + (extra % multi != 0) <= c->max_sinks;
}

static int report_census_same(const void *pa, const void *pb, int i, const char *what,
                              char *err, size_t errlen) {
  const report_census_row *a = pa, *b = pb;
  if (strcmp(a->rule, b->rule) == 0 && strcmp(a->measure, b->measure) == 0 &&
      strcmp(a->joint, b->joint) == 0 && a->sites == b->sites &&
      strcmp(a->sampler, b->sampler) == 0)
    return 0;
  snprintf(err, errlen, "%s row %d is '%s' (%d sites, %s), the first file has '%s' (%d sites, %s)",
           what, i + 1, b->rule, b->sites, b->sampler, a->rule, a->sites, a->sampler);
  return -1;
}

#define REPORT_CENSUS_COL(col, field, op) {col, offsetof(report_census_row, c.field), op}
static const report_countcol report_census_intcols[9] = {
  REPORT_CENSUS_COL(5, samples, REPORT_ADD_SUM), REPORT_CENSUS_COL(6, tie, REPORT_ADD_SUM),
  REPORT_CENSUS_COL(7, no_sink, REPORT_ADD_SUM), REPORT_CENSUS_COL(8, one_sink, REPORT_ADD_SUM),
  REPORT_CENSUS_COL(9, multi_sink, REPORT_ADD_SUM),
  REPORT_CENSUS_COL(10, sink_dt, REPORT_ADD_SUM),
  REPORT_CENSUS_COL(12, max_sinks, REPORT_ADD_MAX),
  REPORT_CENSUS_COL(-1, sinks, REPORT_ADD_SUM),       /* from mean_sinks */
  REPORT_CENSUS_COL(-1, gap_units, REPORT_ADD_SUM)};  /* from mean_worst_gap */
static const report_countcheck report_census_checks[3] = {
  {"tie + no_sink + one_sink + multi_sink must be samples", report_census_parts_sum},
  {"sink_dt <= one_sink", report_census_dt_le},
  {"mean_sinks within what one_sink, multi_sink and max_sinks allow", report_census_sinks_fit}};
static const int report_census_names_cols[4] = {0, 1, 2, 4};
static const report_table report_census_kind = {
  report_census_header, sizeof(report_census_row), REPORT_CENSUS_MAX_ROWS, report_census_intcols, 9,
  report_census_checks, 3, report_census_names_cols, 4, report_census_fields,
  report_census_same};

static int report_census_record(char **f, const size_t *len, int nf, uint64_t line,
                                void *data) {
  report_census_reader *cr = data;
  if (cr->header_seen) return report_table_record(&cr->tr, f, len, nf, line);
  int ok = nf == REPORT_CENSUS_NCOLS;
  for (int i = 0; ok && i < nf; i++) ok = strcmp(f[i], report_census_header[i]) == 0;
  if (!ok) {
    snprintf(cr->tr.err, cr->tr.errlen, "%s line %llu: not a census CSV (bad header)",
             cr->tr.name, (unsigned long long)line);
    return -1;
  }
  cr->header_seen = 1;
  cr->tr.ncols = nf;
  return 0;
}

int report_census_read(FILE *in, const char *path, report_census_row **rows, int *nrows,
                       char *err, size_t errlen) {
  report_census_reader cr = {.tr = {.t = &report_census_kind, .name = path, .err = err,
                                    .errlen = errlen}};
  char perr[256] = "";
  err[0] = '\0';
  int rc = report_csv_each(in, report_census_record, &cr, perr, sizeof perr);
  if (rc != 0 && err[0] == '\0') snprintf(err, errlen, "%s: %s", path, perr);
  if (rc == 0 && cr.tr.n == 0) {
    snprintf(err, errlen, "%s: no rows after the header", path);
    rc = -1;
  }
  if (rc != 0) {
    free(cr.tr.rows);
    return -1;
  }
  *rows = (report_census_row *)(void *)cr.tr.rows;
  *nrows = cr.tr.n;
  return 0;
}

int report_census_add(report_census_row *acc, int nacc, const report_census_row *add,
                      int nadd, const char *what, char *err, size_t errlen) {
  return report_table_add(&report_census_kind, acc, nacc, add, nadd, what, err, errlen);
}
