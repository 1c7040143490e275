/*
** csv_weights.c: the reader of weight files (`lot --rule WDT --weights`):
** one row "w" per point of the points file, with an optional header line
** "w", read through the rows reader (csv_pairs.c).  Every weight is held
** to the weight contract of geom.h; every error is one line naming the file
** and line (or, for a wrong count, the file).
*/
#include <stdlib.h>
#include <string.h>
#include "report_internal.h"

static int report_weights_row(const report_pairs *r, char **f, const size_t *len,
                              unsigned long long ln, void *out) {
  double w = 0;
  geom_numerr ne = geom_number_parse(f[0], len[0], &w);
  geom_coorderr e = ne == GEOM_NUM_OK ? geom_weight_check(w)
                  : ne == GEOM_NUM_NOT_FINITE ? GEOM_COORD_NOT_FINITE
                  : ne == GEOM_NUM_OUT_OF_RANGE ? GEOM_COORD_OUT_OF_RANGE : GEOM_COORD_NOT_NUMBER;
  if (e != GEOM_COORD_OK) {
    char shown[41];
    report_pairs_shown(f[0], len[0], shown);
    snprintf(r->err, r->errlen, "%s line %llu: weight '%s' %s", r->path, ln, shown,
             geom_weighterr_str(e));
    return -1;
  }
  memcpy(out, &w, sizeof w);
  return 0;
}

int report_weights_read(const char *path, size_t npoints, double **w, char *err,
                        size_t errlen) {
  report_pairs r = {.path = path, .what = "weights", .head = {"w", ""}, .fields = 1,
                    .size = sizeof **w, .row = report_weights_row, .err = err,
                    .errlen = errlen};
  void *rows;
  size_t n;
  *w = NULL;
  if (report_pairs_read(&r, &rows, NULL, &n) != 0) return -1;
  if (n != npoints) {
    snprintf(err, errlen, "%s: %zu weights for %zu points (one row per row of the points "
             "file)", path, n, npoints);
    free(rows);
    return -1;
  }
  *w = rows;
  return 0;
}
