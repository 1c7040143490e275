/*
** csv_points.c: the one reader of point files: rows "x,y" with an optional
** header line "x,y", read through libcsv (report_csv_each).  `got` reads a
** polygon with it, `lot` a point set, `flipgraph` a site set; each then
** checks what its own input must be (simple polygon, enough points, ...).
**
** Every error is one line naming the file and line: a wrong field count, a
** coordinate outside the contract (geom_coord_parse_n: not a number, out of
** range), no points at all, memory.  The path "-" is standard input.
*/
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"

typedef struct report_points_reader {
  geom_point *pts;
  uint64_t *line;       /* line of each point */
  size_t n, cap;
  int records;
  char *err;
  size_t errlen;
  const char *path;
} report_points_reader;

/* Room for one more point (and its line). */
static int report_points_grow(report_points_reader *r) {
  if (r->n < r->cap) return 0;
  size_t cap = r->cap ? 2 * r->cap : 256;
  geom_point *np = realloc(r->pts, cap * sizeof *np);
  if (np != NULL) r->pts = np;
  uint64_t *nl = realloc(r->line, cap * sizeof *nl);
  if (nl != NULL) r->line = nl;
  if (np == NULL || nl == NULL) {
    snprintf(r->err, r->errlen, "%s: out of memory after %zu points", r->path, r->n);
    return -1;
  }
  r->cap = cap;
  return 0;
}

static int report_points_record(char **f, const size_t *len, int nf, uint64_t line,
                                void *data) {
  report_points_reader *r = data;
  unsigned long long ln = (unsigned long long)line;
  if (r->records++ == 0 && nf == 2 && strcmp(f[0], "x") == 0 && strcmp(f[1], "y") == 0)
    return 0;   /* header */
  if (nf != 2) {
    snprintf(r->err, r->errlen, "%s line %llu: expected 2 fields x,y, got %d", r->path, ln, nf);
    return -1;
  }
  double xy[2];
  for (int q = 0; q < 2; q++) {
    geom_coorderr ce = geom_coord_parse_n(f[q], len[q], &xy[q]);   /* the coordinate contract */
    if (ce != GEOM_COORD_OK) {
      snprintf(r->err, r->errlen, "%s line %llu: %s '%.40s' %s", r->path, ln, q ? "y" : "x",
               f[q], geom_coorderr_str(ce));
      return -1;
    }
  }
  if (report_points_grow(r) != 0) return -1;
  r->line[r->n] = line;
  r->pts[r->n++] = (geom_point){xy[0], xy[1]};
  return 0;
}

int report_points_read(const char *path, geom_point **out, uint64_t **lines, size_t *n,
                       char *err, size_t errlen) {
  *out = NULL;
  if (lines) *lines = NULL;
  *n = 0;
  report_points_reader r = {0};
  r.err = err;
  r.errlen = errlen;
  r.path = path;
  int rc = report_csv_file(path, report_points_record, &r, err, errlen);
  if (rc == 0 && r.n == 0) {
    snprintf(err, errlen, "%s: no points (expected rows x,y)", path);
    rc = -1;
  }
  if (rc != 0) {
    free(r.pts);
    free(r.line);
    return -1;
  }
  *out = r.pts;
  *n = r.n;
  if (lines)
    *lines = r.line;
  else
    free(r.line);
  return 0;
}
