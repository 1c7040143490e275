/*
** csvio.c: every CSV file fliplab reads or writes, through libcsv: the
** table-3.4 counts (written by table34, summed by merge) and pentagon lists
** (written by sample, read by classify).
**
** Reading: csv_parse in strict mode, with CSV_REPALL_NL so that every LF
** reaches us and error messages can name the line (a CRLF file yields an
** empty record for the CR/LF pair, which is skipped like any blank line).
*/
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <csv.h>
#include "fliplab_config.h"
#include "joint.h"
#include "measure.h"
#include "report_internal.h"

/* Bounds on what a reader accepts (a crafted file must not take all memory
** or time): fields per record, bytes per field, rules per counts file (every
** measure of the registry under every joint, and room for whole-
** quadrilateral rules). */
#define REPORT_CSV_MAXFIELDS 256
#define REPORT_CSV_FIELD_MAX 4096
#define REPORT_CSV_MAXROWS (MEASURE_MAX * JOINT_COUNT + 64)

const char *const report_csv_header[REPORT_CSV_NCOLS] = {
  "measure", "joint", "rule", "samples", "type_I", "type_II", "type_III",
  "type_IV", "type_V", "dt", "seed", "tie_eps", "first", "end", "total", "rules"
};

static void report_errf(char *err, size_t errlen, const char *fmt, ...) FLIPLAB_PRINTF(3, 4);

static void report_errf(char *err, size_t errlen, const char *fmt, ...) {
  va_list ap;
  if (err == NULL || errlen == 0) return;
  va_start(ap, fmt);
  vsnprintf(err, errlen, fmt, ap);
  va_end(ap);
}

/* The counts table of table34 CSVs (below, with the reader). */
static const report_table report_counts_table;

/* ---------------------------------------------------------------- writing */

int report_csv_field(FILE *f, const char *s) {
  size_t n = strlen(s);
  int plain = 1;
  /* libcsv trims unquoted blanks at either end, so those need quotes too. */
  if (n > 0 && (s[0] == ' ' || s[0] == '\t' || s[n - 1] == ' ' || s[n - 1] == '\t'))
    plain = 0;
  for (size_t i = 0; plain && i < n; i++)
    if (s[i] == ',' || s[i] == '"' || s[i] == '\r' || s[i] == '\n') plain = 0;
  if (plain) return fwrite(s, 1, n, f) == n ? 0 : -1;
  return csv_fwrite(f, s, n) == 0 ? 0 : -1;
}

int report_csv_write(FILE *f, const report_row *rows, int nrows) {
  return report_csv_write_run(f, rows, nrows, NULL);
}

int report_csv_row(FILE *f, const char *const *fields, int n) {
  for (int i = 0; i < n; i++) {
    if (i > 0) fputc(',', f);
    report_csv_field(f, fields[i]);
  }
  fputc('\n', f);
  return ferror(f) ? -1 : 0;
}

/* tie_eps in the fewest digits that read back bit for bit, so merge
** compares it exactly. */
static void report_shortest(char *buf, size_t len, double x) {
  for (int d = 1; d <= 17; d++) {
    snprintf(buf, len, "%.*g", d, x);
    if (strtod(buf, NULL) == x) break;
  }
}

/* The fields of one counts row (what report_csv_header names); their count. */
static int report_counts_format(const report_row *row, const report_run *run, int nrows,
                                char num[REPORT_CSV_NCOLS][32], const char **field) {
  field[0] = row->measure;
  field[1] = row->joint;
  field[2] = row->rule;
  report_table_format(&report_counts_table, row, num, field);
  if (run == NULL) return 10;
  const uint64_t w[6] = {run->seed, 0, run->first, run->end, run->total, (uint64_t)nrows};
  for (int k = 0; k < 6; k++) snprintf(num[10 + k], 32, "%llu", (unsigned long long)w[k]);
  report_shortest(num[11], 32, run->tie_eps);
  return REPORT_CSV_NCOLS;
}

int report_csv_write_run(FILE *f, const report_row *rows, int nrows, const report_run *run) {
  const char *field[REPORT_CSV_NCOLS + 1];
  char num[REPORT_CSV_NCOLS][32];
  int ncols = run != NULL ? REPORT_CSV_NCOLS : 10;
  for (int i = 0; i < ncols; i++) field[i] = report_csv_header[i];
  int sampler = run != NULL && run->sampler != NULL;
  if (sampler) field[ncols] = "sampler";
  report_csv_row(f, field, ncols + sampler);
  for (int i = 3; i < REPORT_CSV_NCOLS; i++) field[i] = num[i];
  for (int r = 0; r < nrows; r++) {
    int n = report_counts_format(&rows[r], run, nrows, num, field);
    if (sampler) field[n++] = run->sampler;
    report_csv_row(f, field, n);
  }
  return ferror(f) ? -1 : 0;
}

int report_pentagon_header(FILE *f) {
  static const char *const names[10] = {"x1", "y1", "x2", "y2", "x3",
                                        "y3", "x4", "y4", "x5", "y5"};
  return report_csv_row(f, names, 10);
}

int report_pentagon_write(FILE *f, const geom_point v[5]) {
  /* %.17g round-trips every double exactly (17 significant digits). */
  char num[10][32];
  const char *field[10];
  for (int i = 0; i < 10; i++) {
    snprintf(num[i], 32, "%.17g", i % 2 ? v[i / 2].y : v[i / 2].x);
    field[i] = num[i];
  }
  return report_csv_row(f, field, 10);
}

/* ---------------------------------------------------------------- reading */

/* libcsv grows its field buffer without limit; a reader must not (a
** crafted file with one huge field would take all memory).  Its buffer
** is grown through this function, which refuses past REPORT_CSV_FIELD_MAX
** bytes and says so in a per-thread flag, so the error can tell "field too
** long" from "out of memory". */
static _Thread_local int report_csv_field_refused;

static void *report_csv_realloc(void *p, size_t n) {
  if (n > REPORT_CSV_FIELD_MAX + 1) {
    report_csv_field_refused = 1;
    return NULL;
  }
  return realloc(p, n);
}

typedef struct report_csvstate {
  char *fields[REPORT_CSV_MAXFIELDS];
  size_t len[REPORT_CSV_MAXFIELDS];
  int nfields;       /* fields seen in the current record */
  uint64_t line;
  int after_cr;      /* the last record ended with a CR (a CRLF's LF is no new line) */
  int stop;          /* non-zero: the callback's verdict, ignore the rest */
  int oom, toomany;
  report_record_fn fn;
  void *ctx;
} report_csvstate;

static void report_csv_clear(report_csvstate *st) {
  for (int i = 0; i < st->nfields; i++) free(st->fields[i]);
  st->nfields = 0;
}

static void report_csv_cb_field(void *s, size_t len, void *data) {
  report_csvstate *st = data;
  if (st->stop) return;
  if (st->nfields == REPORT_CSV_MAXFIELDS) {
    st->toomany = 1;
    st->stop = -1;
    return;
  }
  char *copy = malloc(len + 1);
  if (copy == NULL) {
    st->oom = 1;
    st->stop = -1;
    return;
  }
  if (len > 0) memcpy(copy, s, len);
  copy[len] = '\0';
  st->len[st->nfields] = len;
  st->fields[st->nfields++] = copy;
}

static void report_csv_cb_record(int c, void *data) {
  report_csvstate *st = data;
  if (!st->stop) {
    /* A blank line is no record: none or one empty field. */
    int blank = st->nfields == 0 || (st->nfields == 1 && st->fields[0][0] == '\0');
    if (!blank) st->stop = st->fn(st->fields, st->len, st->nfields, st->line, st->ctx);
  }
  /* Lines end with LF, CRLF or a lone CR (libcsv ends a record at each);
  ** the LF of a CRLF arrives as an empty record of its own. */
  int crlf = c == '\n' && st->after_cr && st->nfields == 0;
  if ((c == '\n' && !crlf) || c == '\r') st->line++;
  st->after_cr = c == '\r';
  report_csv_clear(st);
}

/* The message for a libcsv failure at the current line. */
static void report_csv_parse_err(struct csv_parser *p, const report_csvstate *st,
                                 char *err, size_t errlen) {
  unsigned long long ln = (unsigned long long)st->line;
  if (report_csv_field_refused)
    report_errf(err, errlen, "line %llu: a field is longer than %d bytes", ln,
                REPORT_CSV_FIELD_MAX);
  else if (csv_error(p) == CSV_ENOMEM || csv_error(p) == CSV_ETOOBIG)
    report_errf(err, errlen, "line %llu: out of memory", ln);
  else
    report_errf(err, errlen, "line %llu: malformed CSV (%s)", ln, csv_strerror(csv_error(p)));
}

/* A UTF-8 byte order mark (which spreadsheet programs write) is not data:
** skipped at the start of the input, so it never shows up as an invisible
** character inside a "not a number" error. */
static size_t report_csv_bom(const char *buf, size_t n) {
  return n >= 3 && (unsigned char)buf[0] == 0xEF && (unsigned char)buf[1] == 0xBB &&
                 (unsigned char)buf[2] == 0xBF
           ? 3
           : 0;
}

int report_csv_each(FILE *in, report_record_fn fn, void *ctx, char *err, size_t errlen) {
  struct csv_parser p;
  report_csvstate st;
  char buf[65536];
  memset(&st, 0, sizeof st);
  st.line = 1;
  st.fn = fn;
  st.ctx = ctx;
  report_csv_field_refused = 0;
  if (csv_init(&p, CSV_STRICT | CSV_STRICT_FINI | CSV_REPALL_NL) != 0) {
    report_errf(err, errlen, "out of memory");
    return -1;
  }
  csv_set_realloc_func(&p, report_csv_realloc);
  csv_set_blk_size(&p, 4096);
  int rc = 0, first = 1;
  size_t n;
  while (!st.stop && (n = fread(buf, 1, sizeof buf, in)) > 0) {
    size_t skip = first ? report_csv_bom(buf, n) : 0;
    first = 0;
    if (csv_parse(&p, buf + skip, n - skip, report_csv_cb_field, report_csv_cb_record, &st) !=
            n - skip && !st.stop) {
      report_csv_parse_err(&p, &st, err, errlen);
      rc = -1;
      break;
    }
  }
  if (rc == 0 && !st.stop && ferror(in)) {
    report_errf(err, errlen, "read error: %s", strerror(errno));
    rc = -1;
  }
  if (rc == 0 && !st.stop &&
      csv_fini(&p, report_csv_cb_field, report_csv_cb_record, &st) != 0 && !st.stop) {
    report_csv_parse_err(&p, &st, err, errlen);
    rc = -1;
  }
  report_csv_clear(&st);
  csv_free(&p);
  if (st.oom) {
    report_errf(err, errlen, "line %llu: out of memory", (unsigned long long)st.line);
    return -1;
  }
  if (st.toomany) {
    report_errf(err, errlen, "line %llu: more than %d fields", (unsigned long long)st.line,
                REPORT_CSV_MAXFIELDS);
    return -1;
  }
  return rc != 0 ? rc : st.stop;
}

int report_csv_file(const char *path, report_record_fn fn, void *ctx, char *err, size_t errlen) {
  FILE *f = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
  if (f == NULL) {
    snprintf(err, errlen, "cannot read '%s': %s", path, strerror(errno));
    return -1;
  }
  err[0] = '\0';
  char perr[256] = "";
  int rc = report_csv_each(f, fn, ctx, perr, sizeof perr);
  if (f != stdin) fclose(f);
  if (rc != 0 && err[0] == '\0') snprintf(err, errlen, "%s %s", path, perr);
  return rc != 0 ? -1 : 0;
}

/* A parse error of report_csv_each ("line N: ...") gets the file's name. */
static void report_prefix_err(char *err, size_t errlen, const char *name, const char *perr) {
  if (perr[0] == '\0') return;
  report_errf(err, errlen, strncmp(perr, "line ", 5) == 0 ? "%s %s" : "%s: %s", name, perr);
}

/* ------------------------------------------------------- counts files */

typedef struct report_countsread {
  report_tableread tr;
  int header_seen;
  report_run run;
} report_countsread;

static int report_counts_header(report_countsread *cr, char **f, int nf, uint64_t line) {
  const char *name = cr->tr.name;
  if (nf == REPORT_CSV_NCOLS + 1 && strcmp(f[nf - 1], "sampler") == 0) {
    report_errf(cr->tr.err, cr->tr.errlen,
                "%s: made by table34 --sampler other than iteration; merge sums only "
                "iteration-method runs (docs/merge.md)", name);
    return -1;
  }
  int ok = nf == 10 || nf == REPORT_CSV_NCOLS;
  for (int i = 0; ok && i < nf; i++) ok = strcmp(f[i], report_csv_header[i]) == 0;
  if (!ok) {
    report_errf(cr->tr.err, cr->tr.errlen,
                "%s line %llu: not a table34 CSV (the header must be "
                "measure,joint,rule,samples,type_I,type_II,type_III,type_IV,type_V,dt"
                "[,seed,tie_eps,first,end,total,rules])",
                name, (unsigned long long)line);
    return -1;
  }
  cr->header_seen = 1;
  cr->tr.ncols = nf;
  cr->run.known = nf == REPORT_CSV_NCOLS;
  return 0;
}

/* The row's names: a known joint, rule = MEASURE_JOINT (or a whole-
** quadrilateral rule such as DT, measure and joint empty). */
static int report_counts_names(report_tableread *r, char **f, report_row *row,
                               unsigned long long ln) {
  if (strlen(f[0]) >= sizeof row->measure || strlen(f[1]) >= sizeof row->joint ||
      strlen(f[2]) >= sizeof row->rule || f[2][0] == '\0') {
    report_errf(r->err, r->errlen, "%s line %llu: rule name empty or too long", r->name, ln);
    return -1;
  }
  strcpy(row->measure, f[0]);
  strcpy(row->joint, f[1]);
  strcpy(row->rule, f[2]);
  if (row->measure[0] == '\0' && row->joint[0] == '\0') return 0;
  if (row->measure[0] == '\0' || joint_find(row->joint) < 0 ||
      !rule_name_is(row->rule, row->measure, row->joint)) {
    char joints[64];
    joint_names(joints, sizeof joints);
    report_errf(r->err, r->errlen,
                "%s line %llu: rule '%.40s' does not match its measure '%.40s' and joint "
                "'%.16s' (expected MEASURE_JOINT with a joint in {%s} or a real p)",
                r->name, ln, row->rule, row->measure, row->joint, joints);
    return -1;
  }
  return 0;
}

/* The check rows of a counts row: the five types sum to samples, dt <= type_I. */
static int report_counts_types_sum(const void *p) {
  const flipgraph_counts *c = &((const report_row *)p)->c;
  uint64_t sum = 0;
  for (int t = 0; t < FLIPGRAPH_NTYPES; t++) {
    if (c->type[t] > c->samples - sum) return 0;
    sum += c->type[t];
  }
  return sum == c->samples;
}

static int report_counts_dt_le(const void *p) {
  const flipgraph_counts *c = &((const report_row *)p)->c;
  return c->dt <= c->type[FLIPGRAPH_I];
}

/* The run columns: the same on every row, samples = end - first, first <
** end <= total; rules is checked against the row count at the end. */
static int report_counts_run(report_countsread *cr, char **f, const report_row *row,
                             unsigned long long ln) {
  const report_tableread *tr = &cr->tr;
  report_run r = {.known = 1};
  uint64_t *dst[5] = {&r.seed, &r.first, &r.end, &r.total, &r.rules};
  const int col[5] = {10, 12, 13, 14, 15};
  for (int i = 0; i < 5; i++)
    if (geom_count_parse(f[col[i]], tr->len[col[i]], dst[i]) != 0) {
      report_errf(tr->err, tr->errlen, "%s line %llu: %s '%.40s' is not a count", tr->name,
                  ln, report_csv_header[col[i]], f[col[i]]);
      return -1;
    }
  if (geom_number_parse(f[11], tr->len[11], &r.tie_eps) != GEOM_NUM_OK &&
      strcmp(f[11], "0") != 0) {
    report_errf(tr->err, tr->errlen, "%s line %llu: tie_eps '%.40s' is not a number",
                tr->name, ln, f[11]);
    return -1;
  }
  if (strcmp(f[11], "0") == 0) r.tie_eps = 0;
  if (!(r.first <= r.end && r.end <= r.total) || row->c.samples != r.end - r.first ||
      r.rules == 0 || r.rules > REPORT_CSV_MAXROWS) {
    report_errf(tr->err, tr->errlen,
                "%s line %llu: inconsistent run columns (need first <= end <= total, "
                "samples = end - first, 1 <= rules <= %d)", tr->name, ln, REPORT_CSV_MAXROWS);
    return -1;
  }
  if (tr->n == 0) {
    cr->run = r;
  } else if (memcmp(&r, &cr->run, sizeof r) != 0) {
    report_errf(tr->err, tr->errlen,
                "%s line %llu: run columns (seed,tie_eps,first,end,total,rules) differ from "
                "the first row's", tr->name, ln);
    return -1;
  }
  return 0;
}

/* The kind's fields of a counts row (report_table.fields): names, run
** columns, a rule named once. */
static int report_counts_fields(report_tableread *r, char **f, void *p, unsigned long long ln) {
  report_countsread *cr = r->ctx;
  report_row *row = p;
  if (report_counts_names(r, f, row, ln) != 0) return -1;
  if (cr->run.known && report_counts_run(cr, f, row, ln) != 0) return -1;
  const report_row *rows = (const report_row *)(const void *)r->rows;
  for (int i = 0; i < r->n; i++)
    if (strcmp(rows[i].rule, row->rule) == 0) {
      report_errf(r->err, r->errlen, "%s line %llu: rule '%.40s' appears twice", r->name, ln,
                  row->rule);
      return -1;
    }
  return 0;
}

static int report_counts_same(const void *pa, const void *pb, int i, const char *what,
                              char *err, size_t errlen) {
  const report_row *a = pa, *b = pb;
  if (strcmp(a->measure, b->measure) == 0 && strcmp(a->joint, b->joint) == 0 &&
      strcmp(a->rule, b->rule) == 0)
    return 0;
  report_errf(err, errlen, "%s row %d is rule '%s', the first file has '%s' there", what, i + 1,
              b->rule, a->rule);
  return -1;
}

#define REPORT_COUNT(col, field) {col, offsetof(report_row, c.field), REPORT_ADD_SUM}
static const report_countcol report_counts_cols[7] = {
  REPORT_COUNT(3, samples), REPORT_COUNT(4, type[0]), REPORT_COUNT(5, type[1]),
  REPORT_COUNT(6, type[2]), REPORT_COUNT(7, type[3]), REPORT_COUNT(8, type[4]),
  REPORT_COUNT(9, dt)};
static const report_countcheck report_counts_checks[2] = {
  {"types must sum to samples", report_counts_types_sum},
  {"dt <= type_I", report_counts_dt_le}};
static const int report_counts_names_cols[3] = {0, 1, 2};
static const report_table report_counts_table = {
  report_csv_header, sizeof(report_row), REPORT_CSV_MAXROWS, report_counts_cols, 7,
  report_counts_checks, 2, report_counts_names_cols, 3, report_counts_fields,
  report_counts_same};

static int report_counts_record(char **f, const size_t *len, int nf, uint64_t line,
                                void *data) {
  report_countsread *cr = data;
  if (!cr->header_seen) return report_counts_header(cr, f, nf, line);
  return report_table_record(&cr->tr, f, len, nf, line);
}

int report_counts_read(FILE *in, const char *name, report_row **rows, int *nrows,
                       report_run *run, char *err, size_t errlen) {
  report_countsread cr = {.tr = {.t = &report_counts_table, .name = name, .err = err,
                                 .errlen = errlen}};
  cr.tr.ctx = &cr;
  char perr[256] = "";
  err[0] = '\0';
  int rc = report_csv_each(in, report_counts_record, &cr, perr, sizeof perr) != 0 ? -1 : 0;
  report_prefix_err(err, errlen, name, perr);
  int n = cr.tr.n;
  if (rc == 0 && !cr.header_seen) {
    report_errf(err, errlen, "%s: empty file (no header)", name);
    rc = -1;
  } else if (rc == 0 && n == 0) {
    report_errf(err, errlen, "%s: no rows after the header", name);
    rc = -1;
  } else if (rc == 0 && cr.run.known && cr.run.rules != (uint64_t)n) {
    /* A file cut at a row boundary parses cleanly: only this count shows it. */
    report_errf(err, errlen, "%s: %d rules, but its rows say %llu: the file is truncated "
                "or has extra rows", name, n, (unsigned long long)cr.run.rules);
    rc = -1;
  }
  if (rc != 0) {
    free(cr.tr.rows);
    return -1;
  }
  *rows = (report_row *)(void *)cr.tr.rows;
  *nrows = n;
  if (run != NULL) *run = cr.run;
  return 0;
}

int report_csv_read(const char *path, report_row **rows, int *nrows,
                    char *err, size_t errlen) {
  int is_stdin = strcmp(path, "-") == 0;
  FILE *in = is_stdin ? stdin : fopen(path, "rb");
  if (in == NULL) {
    report_errf(err, errlen, "cannot read '%s': %s", path, strerror(errno));
    return -1;
  }
  int rc = report_counts_read(in, path, rows, nrows, NULL, err, errlen);
  if (!is_stdin) fclose(in);
  return rc;
}

int report_rows_add(report_row *acc, int nacc, const report_row *add, int nadd,
                    const char *what, char *err, size_t errlen) {
  return report_table_add(&report_counts_table, acc, nacc, add, nadd, what, err, errlen);
}

/* ------------------------------------------------------------- pentagons */

typedef struct report_pentread {
  const char *name;
  report_pentagon_fn fn;
  void *ctx;
  uint64_t n;
  int first;
  char *err;
  size_t errlen;
} report_pentread;

static int report_is_pentagon_header(char **f, int nf) {
  static const char *const names[10] = {"x1", "y1", "x2", "y2", "x3",
                                        "y3", "x4", "y4", "x5", "y5"};
  if (nf != 10) return 0;
  for (int i = 0; i < 10; i++)
    if ((f[i][0] | 0x20) != names[i][0] || strcmp(f[i] + 1, names[i] + 1) != 0) return 0;
  return 1;
}

static int report_pent_record(char **f, const size_t *len, int nf, uint64_t line,
                              void *data) {
  report_pentread *pr = data;
  unsigned long long ln = (unsigned long long)line;
  int first = pr->first;
  pr->first = 0;
  if (first && report_is_pentagon_header(f, nf)) return 0;
  if (nf != 10) {
    report_errf(pr->err, pr->errlen,
                "%s line %llu: expected 10 numbers x1,y1,...,x5,y5, got %d fields",
                pr->name, ln, nf);
    return -1;
  }
  geom_point p[5];
  for (int i = 0; i < 10; i++) {
    const char *s = f[i];
    double x = 0;
    geom_coorderr ce = geom_coord_parse_n(s, len[i], &x);   /* the coordinate contract */
    if (ce != GEOM_COORD_OK) {
      report_errf(pr->err, pr->errlen, "%s line %llu: %s%d '%.40s' %s", pr->name, ln,
                  i % 2 ? "y" : "x", i / 2 + 1, s, geom_coorderr_str(ce));
      return -1;
    }
    if (i % 2) p[i / 2].y = x;
    else p[i / 2].x = x;
  }
  size_t bad = 0;
  int rev = 0;
  geom_polyerr e = geom_polygon_check(p, 5, &bad, &rev);
  if (e != GEOM_OK) {
    /* bad is the offending vertex in the row's order, as got names it. */
    report_errf(pr->err, pr->errlen, "%s line %llu: point %zu (x%zu,y%zu): %s", pr->name,
                ln, bad + 1, bad + 1, bad + 1, geom_polyerr_str(e));
    return -1;
  }
  pr->n++;
  return pr->fn(p, pr->n, line, rev, pr->ctx);
}

int report_pentagon_each(FILE *in, const char *name, report_pentagon_fn fn, void *ctx,
                         char *err, size_t errlen) {
  report_pentread pr = {.name = name, .fn = fn, .ctx = ctx, .first = 1, .err = err,
                        .errlen = errlen};
  char perr[256] = "";
  err[0] = '\0';
  int rc = report_csv_each(in, report_pent_record, &pr, perr, sizeof perr);
  report_prefix_err(err, errlen, name, perr);
  if (rc == 0 && pr.n == 0) {
    report_errf(err, errlen, "%s: no pentagons", name);
    rc = -1;
  }
  return rc;
}

/* report_pentagon_read collects what report_pentagon_each streams. */
typedef struct report_pentbuf {
  const char *name;
  geom_point *v;
  size_t n, cap, reversed;
  char *err;
  size_t errlen;
} report_pentbuf;

static int report_pent_collect(const geom_point v[5], uint64_t id, uint64_t line, int rev,
                               void *ctx) {
  report_pentbuf *b = ctx;
  (void)id;
  if (b->n == b->cap) {
    size_t cap = b->cap ? 2 * b->cap : 1024;
    geom_point *nv = realloc(b->v, cap * 5 * sizeof *nv);
    if (nv == NULL) {
      report_errf(b->err, b->errlen, "%s line %llu: out of memory", b->name,
                  (unsigned long long)line);
      return -1;
    }
    b->v = nv;
    b->cap = cap;
  }
  memcpy(b->v + 5 * b->n, v, 5 * sizeof *v);
  b->n++;
  b->reversed += rev != 0;
  return 0;
}

int report_pentagon_read(FILE *in, const char *name, geom_point **v, size_t *count,
                         size_t *reversed, char *err, size_t errlen) {
  report_pentbuf b = {.name = name, .err = err, .errlen = errlen};
  if (report_pentagon_each(in, name, report_pent_collect, &b, err, errlen) != 0) {
    free(b.v);
    return -1;
  }
  *v = b.v;
  *count = b.n;
  if (reversed) *reversed = b.reversed;
  return 0;
}
