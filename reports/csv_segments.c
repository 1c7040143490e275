/*
** csv_segments.c: the reader of segment files (`lot --segments`): rows
** "i,j" of 0-based indices into a point file already read, with an optional
** header line "i,j", read through libcsv (report_csv_each) in the manner of
** csv_points.c.
**
** Every error is one line naming the file and line: a wrong field count, an
** index that is not a non-negative integer, an index beyond the points, a
** segment from a point to itself, no segments at all, memory.  Whether the
** segments cross, overlap or pass through points is the triangulation's
** business (lot_build), not the reader's.  The path "-" is standard input.
*/
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"

typedef struct report_segments_reader {
  uint32_t *seg;        /* 2 per segment */
  uint64_t *line;       /* line of each segment */
  size_t n, cap;
  size_t npoints;
  int records;
  char *err;
  size_t errlen;
  const char *path;
} report_segments_reader;

/* Room for one more segment (and its line). */
static int report_segments_grow(report_segments_reader *r) {
  if (r->n < r->cap) return 0;
  size_t cap = r->cap ? 2 * r->cap : 256;
  uint32_t *ns = realloc(r->seg, 2 * cap * sizeof *ns);
  if (ns != NULL) r->seg = ns;
  uint64_t *nl = realloc(r->line, cap * sizeof *nl);
  if (nl != NULL) r->line = nl;
  if (ns == NULL || nl == NULL) {
    snprintf(r->err, r->errlen, "%s: out of memory after %zu segments", r->path, r->n);
    return -1;
  }
  r->cap = cap;
  return 0;
}

/* At most 40 bytes of a field for a message, control bytes (a quoted
** field may hold line breaks) shown as '?', so the message stays one line. */
static void report_segments_shown(const char *f, size_t len, char out[41]) {
  size_t k = 0;
  for (; k < len && k < 40; k++) out[k] = (unsigned char)f[k] < 0x20 || f[k] == 0x7f ? '?' : f[k];
  out[k] = '\0';
}

/* Field q of a record as a point index: digits only, below npoints. */
static int report_segments_index(report_segments_reader *r, const char *f, size_t len, int q,
                                 unsigned long long ln, uint32_t *out) {
  const char *name = q ? "j" : "i";
  uint64_t v;
  if (geom_count_parse(f, len, &v) != 0) {
    int neg = len > 1 && f[0] == '-' && geom_count_parse(f + 1, len - 1, &v) == 0;
    char shown[41];
    report_segments_shown(f, len, shown);
    snprintf(r->err, r->errlen, "%s line %llu: %s '%s' is %s", r->path, ln, name, shown,
             neg ? "negative (point indices are 0-based rows of the points file)"
                 : "not a non-negative integer");
    return -1;
  }
  if (v >= r->npoints) {
    snprintf(r->err, r->errlen, "%s line %llu: %s %llu is out of range (%zu points)", r->path, ln,
             name, (unsigned long long)v, r->npoints);
    return -1;
  }
  *out = (uint32_t)v;
  return 0;
}

static int report_segments_record(char **f, const size_t *len, int nf, uint64_t line,
                                  void *data) {
  report_segments_reader *r = data;
  unsigned long long ln = (unsigned long long)line;
  if (r->records++ == 0 && nf == 2 && strcmp(f[0], "i") == 0 && strcmp(f[1], "j") == 0)
    return 0;   /* header */
  if (nf != 2) {
    snprintf(r->err, r->errlen, "%s line %llu: expected 2 fields i,j, got %d", r->path, ln, nf);
    return -1;
  }
  uint32_t ij[2];
  for (int q = 0; q < 2; q++)
    if (report_segments_index(r, f[q], len[q], q, ln, &ij[q]) != 0) return -1;
  if (ij[0] == ij[1]) {
    snprintf(r->err, r->errlen, "%s line %llu: both ends are point %u (a segment needs two "
             "different points)", r->path, ln, ij[0]);
    return -1;
  }
  if (report_segments_grow(r) != 0) return -1;
  r->line[r->n] = line;
  r->seg[2 * r->n] = ij[0];
  r->seg[2 * r->n + 1] = ij[1];
  r->n++;
  return 0;
}

int report_segments_read(const char *path, size_t npoints, uint32_t **seg, uint64_t **lines,
                         size_t *nseg, char *err, size_t errlen) {
  *seg = NULL;
  if (lines) *lines = NULL;
  *nseg = 0;
  report_segments_reader r = {.npoints = npoints, .err = err, .errlen = errlen, .path = path};
  int rc = report_csv_file(path, report_segments_record, &r, err, errlen);
  if (rc == 0 && r.n == 0) {
    snprintf(err, errlen, "%s: no segments (expected rows i,j)", path);
    rc = -1;
  }
  if (rc != 0) {
    free(r.seg);
    free(r.line);
    return -1;
  }
  *seg = r.seg;
  *nseg = r.n;
  if (lines)
    *lines = r.line;
  else
    free(r.line);
  return 0;
}
