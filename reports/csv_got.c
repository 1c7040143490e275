/*
** csv_got.c: CSV for `fliplab got`: reading a polygon (rows "x,y", an
** optional header "x,y") and writing its GOT's triangles, both through
** libcsv (report_csv_each, report_csv_field).
**
** Every input error names its line: a wrong field count, a field that is
** not a finite number, and, after reading, what geom_simple_polygon_check
** rejects: a duplicate vertex (its line), two edges that cross or touch
** (both edges with their lines); too few has no line.
*/
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"

typedef struct report_got_reader {
  geom_point *pts;
  uint64_t *line;       /* line of each vertex */
  size_t n, cap;
  int records;
  char *err;
  size_t errlen;
  const char *path;
} report_got_reader;

static int report_got_record(char **f, int nf, uint64_t line, void *data) {
  report_got_reader *r = data;
  unsigned long long ln = (unsigned long long)line;
  if (r->records++ == 0 && nf == 2 && strcmp(f[0], "x") == 0 && strcmp(f[1], "y") == 0)
    return 0;   /* header */
  if (nf != 2) {
    snprintf(r->err, r->errlen, "%s line %llu: expected 2 fields x,y, got %d", r->path, ln, nf);
    return -1;
  }
  double xy[2];
  for (int q = 0; q < 2; q++) {
    geom_coorderr ce = geom_coord_parse(f[q], &xy[q]);   /* the coordinate contract */
    if (ce != GEOM_COORD_OK) {
      snprintf(r->err, r->errlen, "%s line %llu: %s '%.40s' %s", r->path, ln, q ? "y" : "x",
               f[q], geom_coorderr_str(ce));
      return -1;
    }
  }
  if (r->n == r->cap) {
    size_t cap = r->cap ? 2 * r->cap : 64;
    geom_point *np = realloc(r->pts, cap * sizeof *np);
    if (np != NULL) r->pts = np;
    uint64_t *nl = realloc(r->line, cap * sizeof *nl);
    if (nl != NULL) r->line = nl;
    if (np == NULL || nl == NULL) {
      snprintf(r->err, r->errlen, "%s: out of memory", r->path);
      return -1;
    }
    r->cap = cap;
  }
  r->line[r->n] = line;
  r->pts[r->n++] = (geom_point){xy[0], xy[1]};
  return 0;
}

int report_got_read_polygon(const char *path, geom_point **out, size_t *n, int *reversed,
                            char *err, size_t errlen) {
  *out = NULL;
  *n = 0;
  if (reversed) *reversed = 0;
  FILE *f = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");   /* "-": standard input */
  if (f == NULL) {
    snprintf(err, errlen, "cannot read '%s': %s", path, strerror(errno));
    return -1;
  }
  report_got_reader r = {0};
  r.err = err;
  r.errlen = errlen;
  r.path = path;
  err[0] = '\0';
  char perr[256] = "";
  int rc = report_csv_each(f, report_got_record, &r, perr, sizeof perr);
  if (f != stdin) fclose(f);
  if (rc != 0) {
    if (err[0] == '\0') snprintf(err, errlen, "%s %s", path, perr);
    free(r.pts);
    free(r.line);
    return -1;
  }
  size_t bad = 0, bad2 = 0;
  int rev = 0;
  geom_polyerr e = geom_simple_polygon_check(r.pts, r.n, &bad, &bad2, &rev);
  if (e == GEOM_TOO_FEW)
    snprintf(err, errlen, "%s: %zu vertices; a polygon needs at least 3", path, r.n);
  else if (e == GEOM_CROSSING)
    snprintf(err, errlen, "%s: polygon is not simple: edge %zu-%zu (lines %llu-%llu) and "
             "edge %zu-%zu (lines %llu-%llu) cross or touch", path, bad, (bad + 1) % r.n,
             (unsigned long long)r.line[bad], (unsigned long long)r.line[(bad + 1) % r.n],
             bad2, (bad2 + 1) % r.n, (unsigned long long)r.line[bad2],
             (unsigned long long)r.line[(bad2 + 1) % r.n]);
  else if (e != GEOM_OK)
    snprintf(err, errlen, "%s line %llu: %s (vertex %zu)", path,
             (unsigned long long)r.line[bad], geom_polyerr_str(e), bad);
  free(r.line);
  if (e != GEOM_OK) {
    free(r.pts);
    return -1;
  }
  *out = r.pts;
  *n = r.n;
  if (reversed) *reversed = rev;
  return 0;
}

int report_got_csv(FILE *f, const got_triangle *t, size_t ntri, const size_t *map) {
  static const char *const head[4] = {"i", "j", "k", "badness"};
  for (int q = 0; q < 4; q++) {
    if (q) fputc(',', f);
    report_csv_field(f, head[q]);
  }
  fputc('\n', f);
  for (size_t q = 0; q < ntri; q++) {
    size_t v[3] = {(size_t)t[q].i, (size_t)t[q].k, (size_t)t[q].j};
    for (int a = 0; a < 3; a++)
      if (map) v[a] = map[v[a]];
    for (int a = 0; a < 2; a++)
      for (int b = 0; b < 2 - a; b++)
        if (v[b] > v[b + 1]) { size_t s = v[b]; v[b] = v[b + 1]; v[b + 1] = s; }
    char buf[40];
    for (int a = 0; a < 3; a++) {
      snprintf(buf, sizeof buf, "%zu", v[a]);
      report_csv_field(f, buf);
      fputc(',', f);
    }
    snprintf(buf, sizeof buf, "%.17g", t[q].badness);
    report_csv_field(f, buf);
    fputc('\n', f);
  }
  return ferror(f) ? -1 : 0;
}

/* The same rows as a polygon, unchecked: a site set for `fliplab flipgraph`. */
int report_sites_read(const char *path, geom_point **out, size_t *n, char *err, size_t errlen) {
  *out = NULL;
  *n = 0;
  FILE *f = fopen(path, "rb");
  if (f == NULL) {
    snprintf(err, errlen, "cannot read '%s': %s", path, strerror(errno));
    return -1;
  }
  report_got_reader r = {0};
  r.err = err;
  r.errlen = errlen;
  r.path = path;
  err[0] = '\0';
  char perr[256] = "";
  int rc = report_csv_each(f, report_got_record, &r, perr, sizeof perr);
  fclose(f);
  free(r.line);
  if (rc != 0) {
    if (err[0] == '\0') snprintf(err, errlen, "%s %s", path, perr);
    free(r.pts);
    return -1;
  }
  *out = r.pts;
  *n = r.n;
  return 0;
}
