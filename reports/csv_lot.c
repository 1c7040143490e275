/*
** csv_lot.c: CSV for `fliplab lot`: reading a point set (rows "x,y", an
** optional header "x,y") and writing a triangulation's triangles, both
** through libcsv (report_csv_each, report_csv_field).
*/
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"

typedef struct report_lot_reader {
  geom_point *pts;
  size_t n, cap;
  int records;
  char *err;
  size_t errlen;
  const char *path;
} report_lot_reader;

static int report_lot_record(char **f, int nf, uint64_t line, void *data) {
  report_lot_reader *r = data;
  unsigned long long ln = (unsigned long long)line;
  if (r->records++ == 0 && nf == 2 && strcmp(f[0], "x") == 0 && strcmp(f[1], "y") == 0)
    return 0;   /* header */
  if (nf != 2) {
    snprintf(r->err, r->errlen, "%s line %llu: expected 2 fields x,y, got %d", r->path, ln, nf);
    return -1;
  }
  double xy[2];
  for (int q = 0; q < 2; q++) {
    geom_coorderr e = geom_coord_parse(f[q], &xy[q]);
    if (e != GEOM_COORD_OK) {
      snprintf(r->err, r->errlen, "%s line %llu: '%.40s' %s", r->path, ln, f[q],
               geom_coorderr_str(e));
      return -1;
    }
  }
  if (r->n == r->cap) {
    size_t cap = r->cap ? 2 * r->cap : 256;
    geom_point *np = realloc(r->pts, cap * sizeof *np);
    if (np == NULL) {
      snprintf(r->err, r->errlen, "%s: out of memory after %zu points", r->path, r->n);
      return -1;
    }
    r->pts = np;
    r->cap = cap;
  }
  r->pts[r->n++] = (geom_point){xy[0], xy[1]};
  return 0;
}

int report_lot_read_points(const char *path, geom_point **out, size_t *n, char *err,
                           size_t errlen) {
  *out = NULL;
  *n = 0;
  FILE *f = fopen(path, "rb");
  if (f == NULL) {
    snprintf(err, errlen, "cannot read '%s': %s", path, strerror(errno));
    return -1;
  }
  report_lot_reader r = {0};
  r.err = err;
  r.errlen = errlen;
  r.path = path;
  err[0] = '\0';
  char perr[256] = "";
  int rc = report_csv_each(f, report_lot_record, &r, perr, sizeof perr);
  fclose(f);
  if (rc == 0 && r.n == 0) {
    snprintf(err, errlen, "%s: no points (expected rows x,y)", path);
    rc = -1;
  }
  if (rc != 0) {
    if (err[0] == '\0') snprintf(err, errlen, "%s %s", path, perr);
    free(r.pts);
    return -1;
  }
  *out = r.pts;
  *n = r.n;
  return 0;
}

int report_lot_csv(FILE *f, const uint32_t *tri, size_t ntri, const double *badness) {
  static const char *const head[4] = {"i", "j", "k", "badness"};
  for (int q = 0; q < 4; q++) {
    if (q) fputc(',', f);
    report_csv_field(f, head[q]);
  }
  fputc('\n', f);
  char buf[40];
  for (size_t t = 0; t < ntri && !ferror(f); t++) {
    for (int a = 0; a < 3; a++) {
      snprintf(buf, sizeof buf, "%u", (unsigned)tri[3 * t + a]);
      report_csv_field(f, buf);
      fputc(',', f);
    }
    if (badness && !isnan(badness[t])) {
      snprintf(buf, sizeof buf, "%.17g", badness[t]);
      report_csv_field(f, buf);
    }
    fputc('\n', f);
  }
  return ferror(f) ? -1 : 0;
}
