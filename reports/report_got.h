/*
** report_got.h: input and output of `fliplab got`: the polygon CSV reader,
** the triangles as CSV, and the SVG picture of a polygon and its GOT.
*/
#ifndef FLIPLAB_REPORT_GOT_H
#define FLIPLAB_REPORT_GOT_H

#include <stddef.h>
#include <stdio.h>
#include "geom/geom.h"
#include "got/got.h"

/* Read a polygon from CSV: one vertex per row "x,y", an optional header
** line "x,y".  The polygon is validated (geom_polygon_check) and made
** anticlockwise; *reversed is 1 when the input was clockwise (it is
** reversed keeping vertex 0: vertex v is then input vertex (n - v) mod n).
** Errors are one line, "FILE line N: problem", naming the offending row.
** 0 on success (free *out), -1 on error. */
int report_got_read_polygon(const char *path, geom_point **out, size_t *n, int *reversed,
                            char *err, size_t errlen);

/* Triangles as CSV: header "i,j,k,badness", one row per triangle, vertex
** indices ascending.  map[v] (may be NULL) renumbers vertices, e.g. back
** to the input's order.  Fields go through report_csv_field (libcsv). */
int report_got_csv(FILE *f, const got_triangle *t, size_t ntri, const size_t *map);

typedef struct report_got_svg_opts {
  int shade;            /* fill triangles by badness (light = good, dark = bad) */
  const char *title;    /* one line above the picture, or NULL */
} report_got_svg_opts;

/* The polygon, its triangulation and (small) vertices, scaled to about
** 1000 px with thin strokes so that n = 1000 stays readable. */
int report_got_svg(FILE *f, const geom_point *p, size_t n, const got_triangle *t,
                   size_t ntri, const report_got_svg_opts *o);

#endif
