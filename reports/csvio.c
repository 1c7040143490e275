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
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <csv.h>
#include "fliplab_config.h"
#include "report.h"

#define REPORT_CSV_MAXFIELDS 256   /* fields kept per record; more are only counted */

const char *const report_csv_header[10] = {
  "measure", "joint", "rule", "samples", "type_I", "type_II", "type_III",
  "type_IV", "type_V", "dt"
};

static void report_errf(char *err, size_t errlen, const char *fmt, ...) FLIPLAB_PRINTF(3, 4);

static void report_errf(char *err, size_t errlen, const char *fmt, ...) {
  va_list ap;
  if (err == NULL || errlen == 0) return;
  va_start(ap, fmt);
  vsnprintf(err, errlen, fmt, ap);
  va_end(ap);
}

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
  for (int i = 0; i < 10; i++) {
    if (i > 0) fputc(',', f);
    report_csv_field(f, report_csv_header[i]);
  }
  fputc('\n', f);
  for (int r = 0; r < nrows; r++) {
    const flipgraph_counts *c = &rows[r].c;
    report_csv_field(f, rows[r].measure);
    fputc(',', f);
    report_csv_field(f, rows[r].joint);
    fputc(',', f);
    report_csv_field(f, rows[r].rule);
    fprintf(f, ",%llu", (unsigned long long)c->samples);
    for (int t = 0; t < FLIPGRAPH_NTYPES; t++)
      fprintf(f, ",%llu", (unsigned long long)c->type[t]);
    fprintf(f, ",%llu\n", (unsigned long long)c->dt);
  }
  return ferror(f) ? -1 : 0;
}

int report_pentagon_header(FILE *f) {
  static const char *const names[10] = {"x1", "y1", "x2", "y2", "x3",
                                        "y3", "x4", "y4", "x5", "y5"};
  for (int i = 0; i < 10; i++) {
    if (i > 0) fputc(',', f);
    report_csv_field(f, names[i]);
  }
  fputc('\n', f);
  return ferror(f) ? -1 : 0;
}

int report_pentagon_write(FILE *f, const geom_point v[5]) {
  /* %.17g round-trips every double exactly (17 significant digits). */
  for (int i = 0; i < 5; i++)
    fprintf(f, "%s%.17g,%.17g", i ? "," : "", v[i].x, v[i].y);
  fputc('\n', f);
  return ferror(f) ? -1 : 0;
}

/* ---------------------------------------------------------------- reading */

typedef struct report_csvstate {
  char *fields[REPORT_CSV_MAXFIELDS];
  int nfields;       /* fields seen in the current record (may exceed the kept ones) */
  int kept;
  uint64_t line;
  int stop;          /* non-zero: the callback's verdict, ignore the rest */
  int oom;
  report_record_fn fn;
  void *ctx;
} report_csvstate;

static void report_csv_clear(report_csvstate *st) {
  for (int i = 0; i < st->kept; i++) free(st->fields[i]);
  st->nfields = st->kept = 0;
}

static void report_csv_cb_field(void *s, size_t len, void *data) {
  report_csvstate *st = data;
  if (st->stop) return;
  if (st->kept < REPORT_CSV_MAXFIELDS) {
    char *copy = malloc(len + 1);
    if (copy == NULL) {
      st->oom = 1;
      st->stop = -1;
      return;
    }
    if (len > 0) memcpy(copy, s, len);
    copy[len] = '\0';
    st->fields[st->kept++] = copy;
  }
  st->nfields++;
}

static void report_csv_cb_record(int c, void *data) {
  report_csvstate *st = data;
  if (!st->stop) {
    /* A blank line is no record: none or one empty field. */
    int blank = st->nfields == 0 || (st->nfields == 1 && st->fields[0][0] == '\0');
    if (!blank) st->stop = st->fn(st->fields, st->nfields, st->line, st->ctx);
  }
  report_csv_clear(st);
  if (c == '\n') st->line++;
}

int report_csv_each(FILE *in, report_record_fn fn, void *ctx, char *err, size_t errlen) {
  struct csv_parser p;
  report_csvstate st;
  char buf[65536];
  memset(&st, 0, sizeof st);
  st.line = 1;
  st.fn = fn;
  st.ctx = ctx;
  if (csv_init(&p, CSV_STRICT | CSV_STRICT_FINI | CSV_REPALL_NL) != 0) {
    report_errf(err, errlen, "out of memory");
    return -1;
  }
  int rc = 0;
  size_t n;
  while (!st.stop && (n = fread(buf, 1, sizeof buf, in)) > 0) {
    if (csv_parse(&p, buf, n, report_csv_cb_field, report_csv_cb_record, &st) != n &&
        !st.stop) {
      report_errf(err, errlen, "line %llu: malformed CSV (%s)",
                  (unsigned long long)st.line, csv_strerror(csv_error(&p)));
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
    report_errf(err, errlen, "line %llu: malformed CSV (%s)",
                (unsigned long long)st.line, csv_strerror(csv_error(&p)));
    rc = -1;
  }
  report_csv_clear(&st);
  csv_free(&p);
  if (st.oom) {
    report_errf(err, errlen, "out of memory");
    return -1;
  }
  return rc != 0 ? rc : st.stop;
}

/* A parse error of report_csv_each ("line N: ...") gets the file's name. */
static void report_prefix_err(char *err, size_t errlen, const char *name, const char *perr) {
  if (perr[0] == '\0') return;
  report_errf(err, errlen, strncmp(perr, "line ", 5) == 0 ? "%s %s" : "%s: %s", name, perr);
}

/* Strict decimal count: digits only, no sign, no overflow. */
static int report_parse_count(const char *s, uint64_t *out) {
  uint64_t v = 0;
  if (*s == '\0') return -1;
  for (; *s; s++) {
    if (*s < '0' || *s > '9') return -1;
    unsigned d = (unsigned)(*s - '0');
    if (v > (UINT64_MAX - d) / 10) return -1;
    v = v * 10 + d;
  }
  *out = v;
  return 0;
}

typedef struct report_countsread {
  const char *name;
  report_row *rows;
  int n, cap;
  int header_seen;
  char *err;
  size_t errlen;
} report_countsread;

static int report_counts_record(char **f, int nf, uint64_t line, void *data) {
  report_countsread *cr = data;
  unsigned long long ln = (unsigned long long)line;
  if (!cr->header_seen) {
    int ok = nf == 10;
    for (int i = 0; ok && i < 10; i++) ok = strcmp(f[i], report_csv_header[i]) == 0;
    if (!ok) {
      report_errf(cr->err, cr->errlen,
                  "%s line %llu: not a table34 CSV (the header must be "
                  "measure,joint,rule,samples,type_I,type_II,type_III,type_IV,type_V,dt)",
                  cr->name, ln);
      return -1;
    }
    cr->header_seen = 1;
    return 0;
  }
  if (nf != 10) {
    report_errf(cr->err, cr->errlen, "%s line %llu: expected 10 fields, got %d",
                cr->name, ln, nf);
    return -1;
  }
  if (cr->n == cr->cap) {
    int cap = cr->cap ? 2 * cr->cap : 64;
    report_row *r = realloc(cr->rows, (size_t)cap * sizeof *r);
    if (r == NULL) {
      report_errf(cr->err, cr->errlen, "%s: out of memory", cr->name);
      return -1;
    }
    cr->rows = r;
    cr->cap = cap;
  }
  report_row *row = &cr->rows[cr->n];
  memset(row, 0, sizeof *row);
  if (strlen(f[0]) >= sizeof row->measure || strlen(f[1]) >= sizeof row->joint ||
      strlen(f[2]) >= sizeof row->rule || f[2][0] == '\0') {
    report_errf(cr->err, cr->errlen, "%s line %llu: rule name empty or too long",
                cr->name, ln);
    return -1;
  }
  strcpy(row->measure, f[0]);
  strcpy(row->joint, f[1]);
  strcpy(row->rule, f[2]);
  uint64_t *dst[8] = {&row->c.samples, &row->c.type[0], &row->c.type[1], &row->c.type[2],
                      &row->c.type[3], &row->c.type[4], &row->c.dt, NULL};
  for (int i = 0; i < 7; i++)
    if (report_parse_count(f[3 + i], dst[i]) != 0) {
      report_errf(cr->err, cr->errlen, "%s line %llu: %s '%s' is not a count",
                  cr->name, ln, report_csv_header[3 + i], f[3 + i]);
      return -1;
    }
  uint64_t sum = 0;
  for (int t = 0; t < FLIPGRAPH_NTYPES; t++) {
    if (row->c.type[t] > row->c.samples - sum || sum > row->c.samples) {
      sum = UINT64_MAX;
      break;
    }
    sum += row->c.type[t];
  }
  if (sum != row->c.samples || row->c.dt > row->c.type[FLIPGRAPH_I]) {
    report_errf(cr->err, cr->errlen,
                "%s line %llu: inconsistent counts (types must sum to samples, dt <= type_I)",
                cr->name, ln);
    return -1;
  }
  if (cr->n > 0 && row->c.samples != cr->rows[0].c.samples) {
    report_errf(cr->err, cr->errlen,
                "%s line %llu: samples %llu differs from the first row's %llu",
                cr->name, ln, (unsigned long long)row->c.samples,
                (unsigned long long)cr->rows[0].c.samples);
    return -1;
  }
  cr->n++;
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
  report_countsread cr = {.name = path, .err = err, .errlen = errlen};
  char perr[256] = "";
  int rc = report_csv_each(in, report_counts_record, &cr, perr, sizeof perr);
  if (!is_stdin) fclose(in);
  if (rc != 0) rc = -1;
  report_prefix_err(err, errlen, path, perr);
  if (rc == 0 && !cr.header_seen) {
    report_errf(err, errlen, "%s: empty file (no header)", path);
    rc = -1;
  } else if (rc == 0 && cr.n == 0) {
    report_errf(err, errlen, "%s: no rows after the header", path);
    rc = -1;
  }
  if (rc != 0) {
    free(cr.rows);
    return -1;
  }
  *rows = cr.rows;
  *nrows = cr.n;
  return 0;
}

int report_rows_add(report_row *acc, int nacc, const report_row *add, int nadd,
                    const char *what, char *err, size_t errlen) {
  if (nacc != nadd) {
    report_errf(err, errlen, "%s has %d rules, the first file %d", what, nadd, nacc);
    return -1;
  }
  for (int i = 0; i < nacc; i++) {
    if (strcmp(acc[i].measure, add[i].measure) != 0 || strcmp(acc[i].joint, add[i].joint) != 0 ||
        strcmp(acc[i].rule, add[i].rule) != 0) {
      report_errf(err, errlen, "%s row %d is rule '%s', the first file has '%s' there",
                  what, i + 1, add[i].rule, acc[i].rule);
      return -1;
    }
  }
  for (int i = 0; i < nacc; i++) {
    uint64_t *a[7] = {&acc[i].c.samples, &acc[i].c.type[0], &acc[i].c.type[1],
                      &acc[i].c.type[2], &acc[i].c.type[3], &acc[i].c.type[4], &acc[i].c.dt};
    const uint64_t b[7] = {add[i].c.samples, add[i].c.type[0], add[i].c.type[1],
                           add[i].c.type[2], add[i].c.type[3], add[i].c.type[4], add[i].c.dt};
    for (int k = 0; k < 7; k++)
      if (*a[k] > UINT64_MAX - b[k]) {
        report_errf(err, errlen, "%s: counts overflow", what);
        return -1;
      }
    for (int k = 0; k < 7; k++) *a[k] += b[k];
  }
  return 0;
}

/* ------------------------------------------------------------- pentagons */

typedef struct report_pentread {
  const char *name;
  geom_point *v;
  size_t n, cap;
  size_t reversed;
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

static int report_pent_record(char **f, int nf, uint64_t line, void *data) {
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
    char *end;
    const char *s = f[i];
    double x = strtod(s, &end);
    const char *coord = i % 2 ? "y" : "x";
    if (*s == '\0' || end == s || *end != '\0') {
      report_errf(pr->err, pr->errlen, "%s line %llu: %s%d '%.40s' is not a number",
                  pr->name, ln, coord, i / 2 + 1, s);
      return -1;
    }
    if (!isfinite(x)) {
      report_errf(pr->err, pr->errlen, "%s line %llu: %s%d '%.40s' is not finite",
                  pr->name, ln, coord, i / 2 + 1, s);
      return -1;
    }
    if (i % 2) p[i / 2].y = x;
    else p[i / 2].x = x;
  }
  size_t bad = 0;
  int rev = 0;
  geom_polyerr e = geom_polygon_check(p, 5, &bad, &rev);
  if (e != GEOM_OK) {
    if (e == GEOM_DUPLICATE || e == GEOM_COLLINEAR)
      report_errf(pr->err, pr->errlen, "%s line %llu: point %zu (x%zu,y%zu): %s", pr->name,
                  ln, bad + 1, bad + 1, bad + 1, geom_polyerr_str(e));
    else
      report_errf(pr->err, pr->errlen, "%s line %llu: %s", pr->name, ln, geom_polyerr_str(e));
    return -1;
  }
  if (pr->n == pr->cap) {
    size_t cap = pr->cap ? 2 * pr->cap : 1024;
    geom_point *nv = realloc(pr->v, cap * 5 * sizeof *nv);
    if (nv == NULL) {
      report_errf(pr->err, pr->errlen, "%s: out of memory", pr->name);
      return -1;
    }
    pr->v = nv;
    pr->cap = cap;
  }
  memcpy(pr->v + 5 * pr->n, p, sizeof p);
  pr->n++;
  pr->reversed += rev != 0;
  return 0;
}

int report_pentagon_read(FILE *in, const char *name, geom_point **v, size_t *count,
                         size_t *reversed, char *err, size_t errlen) {
  report_pentread pr = {.name = name, .first = 1, .err = err, .errlen = errlen};
  char perr[256] = "";
  int rc = report_csv_each(in, report_pent_record, &pr, perr, sizeof perr);
  report_prefix_err(err, errlen, name, perr);
  if (rc == 0 && pr.n == 0) {
    report_errf(err, errlen, "%s: no pentagons", name);
    rc = -1;
  }
  if (rc != 0) {
    free(pr.v);
    return -1;
  }
  *v = pr.v;
  *count = pr.n;
  if (reversed) *reversed = pr.reversed;
  return 0;
}
