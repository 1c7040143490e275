/*
** csv_lot.c: CSV for `fliplab lot`: writing a triangulation's triangles
** and its convex-distance Delaunay graph through libcsv (report_csv_row);
** the points are read by
** report_points_read (csv_points.c).
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "report_internal.h"

int report_lot_csv(FILE *f, const uint32_t *tri, size_t ntri, const double *badness) {
  static const char *const head[4] = {"i", "j", "k", "badness"};
  report_csv_row(f, head, 4);
  char num[4][40];
  const char *field[4] = {num[0], num[1], num[2], num[3]};
  for (size_t t = 0; t < ntri && !ferror(f); t++) {
    for (int a = 0; a < 3; a++) snprintf(num[a], sizeof num[a], "%u", (unsigned)tri[3 * t + a]);
    num[3][0] = '\0';   /* empty: no badness */
    if (badness && !isnan(badness[t])) snprintf(num[3], sizeof num[3], "%.17g", badness[t]);
    report_csv_row(f, field, 4);
  }
  return ferror(f) ? -1 : 0;
}

int report_lot_cdf_csv(FILE *f, const lot_cdf *g) {
  static const char *const head[3] = {"i", "j", "k"};
  report_csv_row(f, head, 3);
  char num[3][16];
  const char *field[3] = {num[0], num[1], num[2]};
  for (size_t t = 0; t < g->triangles && !ferror(f); t++) {
    for (int a = 0; a < 3; a++) snprintf(num[a], sizeof num[a], "%u", (unsigned)g->tri[3 * t + a]);
    report_csv_row(f, field, 3);
  }
  num[2][0] = '\0';   /* an edge: k empty */
  for (size_t e = 0; e < g->edges && !ferror(f); e++) {
    for (int a = 0; a < 2; a++) snprintf(num[a], sizeof num[a], "%u", (unsigned)g->edge[2 * e + a]);
    report_csv_row(f, field, 3);
  }
  return ferror(f) ? -1 : 0;
}
