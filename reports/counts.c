/*
** counts.c: the counts table behind both CSV kinds that `merge` sums, the
** table-3.4 counts of table34 (csvio.c) and the census of site sets
** (census.c).  A kind is described by its table (report_internal.h): the
** integer columns with where each lives in a row and how shards combine
** (sum or maximum), the consistency checks as rows, and the kind's own
** fields (names, means, run columns).  Reading (field count, row bound,
** counts, the kind's fields, checks, one sample count per file), adding and
** writing the integer columns are done here once for both kinds.
*/
#include <stdlib.h>
#include <string.h>
#include "report_internal.h"

static uint64_t *report_table_cell(const report_countcol *c, void *row) {
  return (uint64_t *)((char *)row + c->off);
}

static uint64_t report_table_value(const report_countcol *c, const void *row) {
  uint64_t v;
  memcpy(&v, (const char *)row + c->off, sizeof v);
  return v;
}

/* The integer columns of one record; 0, or -1 with the message. */
static int report_table_counts(report_tableread *r, char **f, void *row, unsigned long long ln) {
  const report_table *t = r->t;
  for (int k = 0; k < t->ncounts; k++) {
    const report_countcol *c = &t->counts[k];
    if (c->col < 0) continue;   /* derived by the kind (a mean's sum) */
    if (geom_count_parse(f[c->col], r->len[c->col], report_table_cell(c, row)) != 0) {
      snprintf(r->err, r->errlen, "%s line %llu: %s '%.40s' is not a count", r->name, ln,
               t->header[c->col], f[c->col]);
      return -1;
    }
  }
  return 0;
}

/* Every check row of the table; 0, or -1 naming them all. */
static int report_table_checks(report_tableread *r, const void *row, unsigned long long ln) {
  const report_table *t = r->t;
  int ok = 1;
  for (int k = 0; k < t->nchecks; k++) ok = ok && t->checks[k].holds(row);
  if (ok) return 0;
  char what[400] = "";
  for (int k = 0; k < t->nchecks; k++)
    snprintf(what + strlen(what), sizeof what - strlen(what), "%s%s", k ? ", " : "",
             t->checks[k].rule);
  snprintf(r->err, r->errlen, "%s line %llu: inconsistent counts (%s)", r->name, ln, what);
  return -1;
}

/* Room for one more row; NULL after the message. */
static void *report_table_grow(report_tableread *r, unsigned long long ln) {
  const report_table *t = r->t;
  if (r->n >= t->max_rows) {
    snprintf(r->err, r->errlen, "%s line %llu: more than %d rules", r->name, ln, t->max_rows);
    return NULL;
  }
  if (r->n == r->cap) {
    int cap = r->cap ? 2 * r->cap : 64;
    char *rows = realloc(r->rows, (size_t)cap * t->row_size);
    if (rows == NULL) {
      snprintf(r->err, r->errlen, "%s line %llu: out of memory", r->name, ln);
      return NULL;
    }
    r->rows = rows;
    r->cap = cap;
  }
  char *row = r->rows + (size_t)r->n * t->row_size;
  memset(row, 0, t->row_size);
  return row;
}

int report_table_record(report_tableread *r, char **f, const size_t *len, int nf,
                        uint64_t line) {
  const report_table *t = r->t;
  unsigned long long ln = (unsigned long long)line;
  r->len = len;
  if (nf != r->ncols) {
    snprintf(r->err, r->errlen, "%s line %llu: expected %d fields, got %d", r->name, ln,
             r->ncols, nf);
    return -1;
  }
  for (int k = 0; k < t->nnames; k++)
    if (memchr(f[t->names[k]], '\0', len[t->names[k]]) != NULL) {
      snprintf(r->err, r->errlen, "%s line %llu: %s '%.40s' has a NUL byte inside", r->name, ln,
               t->header[t->names[k]], f[t->names[k]]);
      return -1;
    }
  char *row = report_table_grow(r, ln);
  if (row == NULL || report_table_counts(r, f, row, ln) != 0 ||
      t->fields(r, f, row, ln) != 0 || report_table_checks(r, row, ln) != 0)
    return -1;
  uint64_t s = report_table_value(&t->counts[0], row);
  if (r->n > 0 && s != report_table_value(&t->counts[0], r->rows)) {
    snprintf(r->err, r->errlen, "%s line %llu: samples %llu differs from the first row's %llu",
             r->name, ln, (unsigned long long)s,
             (unsigned long long)report_table_value(&t->counts[0], r->rows));
    return -1;
  }
  r->n++;
  return 0;
}

int report_table_add(const report_table *t, void *acc, int nacc, const void *add, int nadd,
                     const char *what, char *err, size_t errlen) {
  if (nacc != nadd) {
    snprintf(err, errlen, "%s has %d rules, the first file %d", what, nadd, nacc);
    return -1;
  }
  for (int i = 0; i < nacc; i++)
    if (t->same((const char *)acc + (size_t)i * t->row_size,
                (const char *)add + (size_t)i * t->row_size, i, what, err, errlen) != 0)
      return -1;
  for (int i = 0; i < nacc; i++) {
    char *a = (char *)acc + (size_t)i * t->row_size;
    const char *b = (const char *)add + (size_t)i * t->row_size;
    for (int k = 0; k < t->ncounts; k++)
      if (t->counts[k].op == REPORT_ADD_SUM &&
          report_table_value(&t->counts[k], a) > UINT64_MAX - report_table_value(&t->counts[k], b)) {
        snprintf(err, errlen, "%s: counts overflow", what);
        return -1;
      }
    for (int k = 0; k < t->ncounts; k++) {
      uint64_t *x = report_table_cell(&t->counts[k], a), y = report_table_value(&t->counts[k], b);
      *x = t->counts[k].op == REPORT_ADD_SUM ? *x + y : *x > y ? *x : y;
    }
  }
  return 0;
}

void report_table_format(const report_table *t, const void *row, char num[][32],
                         const char **field) {
  for (int k = 0; k < t->ncounts; k++) {
    const report_countcol *c = &t->counts[k];
    if (c->col < 0) continue;
    snprintf(num[c->col], 32, "%llu", (unsigned long long)report_table_value(c, row));
    field[c->col] = num[c->col];
  }
}
