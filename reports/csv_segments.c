/*
** csv_segments.c: the reader of segment files (`lot --segments`): rows
** "i,j" of 0-based indices into a point file already read, with an optional
** header line "i,j", read through the two-field reader (csv_pairs.c).
**
** Every error is one line naming the file and line: a wrong field count, an
** index that is not a non-negative integer, an index beyond the points, a
** segment from a point to itself, no segments at all, memory.  Whether the
** segments cross, overlap or pass through points is the triangulation's
** business (lot_build), not the reader's.  The path "-" is standard input.
*/
#include <stdlib.h>
#include <string.h>
#include "report_internal.h"

/* Field q of a record as a point index: digits only, below npoints. */
static int report_segments_index(const report_pairs *r, const char *f, size_t len, int q,
                                 unsigned long long ln, uint32_t *out) {
  size_t npoints = *(const size_t *)r->ctx;
  const char *name = q ? "j" : "i";
  uint64_t v;
  if (geom_count_parse(f, len, &v) != 0) {
    int neg = len > 1 && f[0] == '-' && geom_count_parse(f + 1, len - 1, &v) == 0;
    char shown[41];
    report_pairs_shown(f, len, shown);
    snprintf(r->err, r->errlen, "%s line %llu: %s '%s' is %s", r->path, ln, name, shown,
             neg ? "negative (point indices are 0-based rows of the points file)"
                 : "not a non-negative integer");
    return -1;
  }
  if (v >= npoints) {
    snprintf(r->err, r->errlen, "%s line %llu: %s %llu is out of range (%zu points)", r->path, ln,
             name, (unsigned long long)v, npoints);
    return -1;
  }
  *out = (uint32_t)v;
  return 0;
}

static int report_segments_row(const report_pairs *r, char **f, const size_t *len,
                               unsigned long long ln, void *out) {
  uint32_t ij[2];
  for (int q = 0; q < 2; q++)
    if (report_segments_index(r, f[q], len[q], q, ln, &ij[q]) != 0) return -1;
  if (ij[0] == ij[1]) {
    snprintf(r->err, r->errlen, "%s line %llu: both ends are point %u (a segment needs two "
             "different points)", r->path, ln, ij[0]);
    return -1;
  }
  memcpy(out, ij, sizeof ij);
  return 0;
}

int report_segments_read(const char *path, size_t npoints, uint32_t **seg, uint64_t **lines,
                         size_t *nseg, char *err, size_t errlen) {
  report_pairs r = {.path = path, .what = "segments", .head = {"i", "j"},
                    .size = 2 * sizeof **seg, .row = report_segments_row, .ctx = &npoints,
                    .err = err, .errlen = errlen};
  void *rows;
  int rc = report_pairs_read(&r, &rows, lines, nseg);
  *seg = rows;
  return rc;
}
