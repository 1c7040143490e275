/*
** csv_lot.c: CSV for `fliplab lot`: writing a triangulation's triangles
** through libcsv (report_csv_field); the points are read by
** report_points_read (csv_points.c).
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"

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
