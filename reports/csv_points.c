/*
** csv_points.c: the one reader of point files: rows "x,y" with an optional
** header line "x,y", read through the two-field reader (csv_pairs.c).
** `got` reads a polygon with it, `lot` a point set, `flipgraph` a site set;
** each then checks what its own input must be (simple polygon, enough
** points, ...).
**
** Every error is one line naming the file and line: a wrong field count, a
** coordinate outside the contract (geom_coord_parse_n: not a number, out of
** range), no points at all, memory.  The path "-" is standard input.
*/
#include <stdlib.h>
#include <string.h>
#include "report_internal.h"

static int report_points_row(const report_pairs *r, char **f, const size_t *len,
                             unsigned long long ln, void *out) {
  double xy[2];
  for (int q = 0; q < 2; q++) {
    geom_coorderr ce = geom_coord_parse_n(f[q], len[q], &xy[q]);   /* the coordinate contract */
    if (ce != GEOM_COORD_OK) {
      char shown[41];
      report_pairs_shown(f[q], len[q], shown);
      snprintf(r->err, r->errlen, "%s line %llu: %s '%s' %s", r->path, ln, q ? "y" : "x",
               shown, geom_coorderr_str(ce));
      return -1;
    }
  }
  geom_point pt = {xy[0], xy[1]};
  memcpy(out, &pt, sizeof pt);
  return 0;
}

int report_points_read(const char *path, geom_point **out, uint64_t **lines, size_t *n,
                       char *err, size_t errlen) {
  report_pairs r = {.path = path, .what = "points", .head = {"x", "y"},
                    .size = sizeof **out, .row = report_points_row, .err = err, .errlen = errlen};
  void *rows;
  int rc = report_pairs_read(&r, &rows, lines, n);
  *out = rows;
  return rc;
}
