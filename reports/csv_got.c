/*
** csv_got.c: CSV for `fliplab got`: reading a polygon (the point file of
** report_points_read, then checked) and writing its GOT's triangles through
** libcsv (report_csv_row).
**
** Every input error names its line: those of report_points_read, and what
** geom_simple_polygon_check rejects: a duplicate vertex (its line), two edges that cross or touch
** (both edges with their lines); too few has no line.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "report_internal.h"

int report_got_read_polygon(const char *path, geom_point **out, size_t *n, int *reversed,
                            char *err, size_t errlen) {
  if (reversed) *reversed = 0;
  geom_point *p;
  uint64_t *line;
  size_t np, bad = 0, bad2 = 0;
  if (report_points_read(path, &p, &line, &np, err, errlen) != 0) return -1;
  int rev = 0;
  geom_polyerr e = geom_simple_polygon_check(p, np, &bad, &bad2, &rev);
  if (e == GEOM_TOO_FEW)
    snprintf(err, errlen, "%s: %zu vertices; a polygon needs at least 3", path, np);
  else if (e == GEOM_CROSSING)
    snprintf(err, errlen, "%s: polygon is not simple: edge %zu-%zu (lines %llu-%llu) and "
             "edge %zu-%zu (lines %llu-%llu) cross or touch", path, bad, (bad + 1) % np,
             (unsigned long long)line[bad], (unsigned long long)line[(bad + 1) % np],
             bad2, (bad2 + 1) % np, (unsigned long long)line[bad2],
             (unsigned long long)line[(bad2 + 1) % np]);
  else if (e != GEOM_OK)
    snprintf(err, errlen, "%s line %llu: %s (vertex %zu)", path,
             (unsigned long long)line[bad], geom_polyerr_str(e), bad);
  free(line);
  if (e != GEOM_OK) {
    free(p);
    return -1;
  }
  *out = p;
  *n = np;
  if (reversed) *reversed = rev;
  return 0;
}

int report_got_csv(FILE *f, const got_triangle *t, size_t ntri, const size_t *map) {
  static const char *const head[4] = {"i", "j", "k", "badness"};
  report_csv_row(f, head, 4);
  for (size_t q = 0; q < ntri; q++) {
    size_t v[3] = {(size_t)t[q].i, (size_t)t[q].k, (size_t)t[q].j};
    for (int a = 0; a < 3; a++)
      if (map) v[a] = map[v[a]];
    for (int a = 0; a < 2; a++)
      for (int b = 0; b < 2 - a; b++)
        if (v[b] > v[b + 1]) { size_t s = v[b]; v[b] = v[b + 1]; v[b + 1] = s; }
    char num[4][40];
    const char *field[4] = {num[0], num[1], num[2], num[3]};
    for (int a = 0; a < 3; a++) snprintf(num[a], sizeof num[a], "%zu", v[a]);
    snprintf(num[3], sizeof num[3], "%.17g", t[q].badness);
    report_csv_row(f, field, 4);
  }
  return ferror(f) ? -1 : 0;
}

