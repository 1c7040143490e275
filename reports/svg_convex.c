/*
** svg_convex.c: an SVG sheet of a few random convex polygons (`fliplab
** convex --svg`): one panel each, in a row of up to four, all at one scale
** (the bounding box of them all), so that sizes compare; each panel is
** titled with its index and, for a weighted sampler, its log weight.
*/
#include <math.h>
#include <stdio.h>
#include "report_internal.h"

#define REPORT_CONVEX_PANEL 240.0
#define REPORT_CONVEX_PAD 10.0
#define REPORT_CONVEX_TOP 24.0
#define REPORT_CONVEX_PER_ROW 4

/* One panel's outline as one path, y upwards. */
static void report_convex_panel(FILE *f, const geom_point *v, size_t n, double x0, double y0,
                                const report_svg_box *b, double s) {
  fprintf(f, "<path fill='#fdeccd' stroke='#333333' stroke-width='1' d='");
  for (size_t i = 0; i < n; i++)
    fprintf(f, "%s%.2f,%.2f", i ? " L" : "M", x0 + (v[i].x - b->minx) * s,
            y0 + (b->maxy - v[i].y) * s);
  fprintf(f, " Z'/>\n");
}

int report_convex_svg(FILE *f, const geom_point *xy, size_t n, size_t count,
                      const uint64_t *index, const double *log_weight) {
  if (count == 0) return -1;
  report_svg_box b = report_svg_bbox(xy, n * count);
  double s = report_svg_fit_scale(&b, REPORT_CONVEX_PANEL);
  size_t cols = count < REPORT_CONVEX_PER_ROW ? count : REPORT_CONVEX_PER_ROW;
  size_t rows = (count + cols - 1) / cols;
  double cw = REPORT_CONVEX_PANEL + 2 * REPORT_CONVEX_PAD, ch = cw + REPORT_CONVEX_TOP;
  report_svg_graph_open(f, cw * (double)cols, ch * (double)rows);
  for (size_t k = 0; k < count; k++) {
    double x0 = cw * (double)(k % cols), y0 = ch * (double)(k / cols);
    char title[96];
    if (log_weight != NULL)
      snprintf(title, sizeof title, "polygon %llu, ln w = %.6g", (unsigned long long)index[k],
               log_weight[k]);
    else
      snprintf(title, sizeof title, "polygon %llu", (unsigned long long)index[k]);
    report_svg_text(f, x0 + REPORT_CONVEX_PAD, y0 + 16, 12, title);
    report_convex_panel(f, xy + k * n, n, x0 + REPORT_CONVEX_PAD,
                        y0 + REPORT_CONVEX_TOP + REPORT_CONVEX_PAD, &b, s);
  }
  fprintf(f, "</svg>\n");
  return ferror(f) ? -1 : 0;
}
