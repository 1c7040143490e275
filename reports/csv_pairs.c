/*
** csv_pairs.c: the reader of files of two-field rows (points "x,y",
** segments "i,j") and of one-field rows (weights "w"), through libcsv (report_csv_file): the optional header,
** the field count, the growing arrays of rows and their lines, and the
** messages about them.  What a row means is its caller's (csv_points.c,
** csv_segments.c).
*/
#include <stdlib.h>
#include <string.h>
#include "report_internal.h"

typedef struct report_pairs_run {
  const report_pairs *r;
  unsigned char *rows;
  uint64_t *line;       /* line of each row */
  size_t n, cap;
  int records;
} report_pairs_run;

/* Room for one more row (and its line). */
static int report_pairs_grow(report_pairs_run *u) {
  if (u->n < u->cap) return 0;
  size_t cap = u->cap ? 2 * u->cap : 256;
  unsigned char *nr = realloc(u->rows, cap * u->r->size);
  if (nr != NULL) u->rows = nr;
  uint64_t *nl = realloc(u->line, cap * sizeof *nl);
  if (nl != NULL) u->line = nl;
  if (nr == NULL || nl == NULL) {
    snprintf(u->r->err, u->r->errlen, "%s: out of memory after %zu %s", u->r->path, u->n,
             u->r->what);
    return -1;
  }
  u->cap = cap;
  return 0;
}

void report_pairs_shown(const char *f, size_t len, char out[41]) {
  size_t k = 0;
  for (; k < len && k < 40; k++) out[k] = (unsigned char)f[k] < 0x20 || f[k] == 0x7f ? '?' : f[k];
  out[k] = '\0';
}

/* The columns as a reader names them: "x,y", or "w". */
static const char *report_pairs_cols(const report_pairs *r, char *buf, size_t len) {
  if (r->fields == 1) return r->head[0];
  snprintf(buf, len, "%s,%s", r->head[0], r->head[1]);
  return buf;
}

static int report_pairs_record(char **f, const size_t *len, int nf, uint64_t line, void *data) {
  report_pairs_run *u = data;
  const report_pairs *r = u->r;
  unsigned long long ln = (unsigned long long)line;
  int want = r->fields == 1 ? 1 : 2;
  if (u->records++ == 0 && nf == want && strcmp(f[0], r->head[0]) == 0 &&
      (want == 1 || strcmp(f[1], r->head[1]) == 0))
    return 0;   /* header */
  if (nf != want) {
    char cols[64];
    snprintf(r->err, r->errlen, "%s line %llu: expected %d field%s %s, got %d", r->path, ln,
             want, want == 1 ? "" : "s", report_pairs_cols(r, cols, sizeof cols), nf);
    return -1;
  }
  unsigned char row[16];   /* r->size bytes, at most 16 (report_internal.h) */
  if (r->row(r, f, len, ln, row) != 0 || report_pairs_grow(u) != 0) return -1;
  u->line[u->n] = line;
  memcpy(u->rows + u->n++ * r->size, row, r->size);
  return 0;
}

int report_pairs_read(const report_pairs *r, void **rows, uint64_t **lines, size_t *n) {
  *rows = NULL;
  if (lines) *lines = NULL;
  *n = 0;
  report_pairs_run u = {.r = r};
  int rc = report_csv_file(r->path, report_pairs_record, &u, r->err, r->errlen);
  if (rc == 0 && u.n == 0) {
    char cols[64];
    snprintf(r->err, r->errlen, "%s: no %s (expected rows %s)", r->path, r->what,
             report_pairs_cols(r, cols, sizeof cols));
    rc = -1;
  }
  if (rc != 0) {
    free(u.rows);
    free(u.line);
    return -1;
  }
  *rows = u.rows;
  *n = u.n;
  if (lines)
    *lines = u.line;
  else
    free(u.line);
  return 0;
}
