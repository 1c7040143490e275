/*
** svg_lot.c: an SVG picture of triangulations of one point set side by
** side (`fliplab lot --svg`, with --compare DT the LOT next to the
** Delaunay triangulation; `--rule A,B,...` one panel per rule, in rows of
** a grid beyond three panels).  Edges are hairlines in one <path> per panel
** (each interior edge drawn twice, which an SVG viewer does not show);
** shading fills triangles by badness on one scale for all panels; a
** convex-distance Delaunay graph (`lot --cdf`) is drawn in bold red over its
** panel's triangulation; the constrained edges of a constrained run (`lot
** --segments`, `--poly`) in a thick near-black stroke over everything but
** the points.  A panel without them draws exactly what it drew before.
*/
#include <math.h>
#include <stdio.h>
#include "report_internal.h"

#define REPORT_LOT_SIZE 600.0
#define REPORT_LOT_GRID_SIZE 400.0   /* a panel's side beyond three panels */
#define REPORT_LOT_MARGIN 14.0
#define REPORT_LOT_TOP 34.0
#define REPORT_LOT_CAPTION 22.0

/* Where a panel goes: the data box's corner, the scale, and the panel's
** left edge and top (its caption's band starts at y0). */
typedef struct report_lot_view {
  double minx, maxy, s, x0, y0;
} report_lot_view;

static double report_lot_px(const report_lot_view *v, double x) {
  return v->x0 + (x - v->minx) * v->s;
}
static double report_lot_py(const report_lot_view *v, double y) {
  return v->y0 + REPORT_LOT_CAPTION + (v->maxy - y) * v->s;
}

static void report_lot_range(const report_lot_panel *panels, int np, double *lo, double *hi) {
  *lo = INFINITY;
  *hi = -INFINITY;
  for (int k = 0; k < np; k++)
    for (size_t t = 0; panels[k].badness && t < panels[k].ntri; t++) {
      double b = panels[k].badness[t];
      if (isfinite(b) && b < *lo) *lo = b;
      if (isfinite(b) && b > *hi) *hi = b;
    }
}

/* The moves of one closed triangle or one open edge (k = 2) of a path. */
static void report_lot_moves(FILE *f, const geom_point *p, const uint32_t *w, int k,
                             const report_lot_view *v) {
  for (int a = 0; a < k; a++)
    fprintf(f, "%c%.2f %.2f", a ? 'L' : 'M', report_lot_px(v, p[w[a]].x),
            report_lot_py(v, p[w[a]].y));
  if (k == 3) fputc('Z', f);
}

static void report_lot_cdf_draw(FILE *f, const geom_point *p, const lot_cdf *g,
                                const report_lot_view *v, double width) {
  fprintf(f, "<path fill=\"none\" stroke=\"#c0392b\" stroke-width=\"%.2f\" "
             "stroke-linejoin=\"round\" d=\"", width);
  for (size_t t = 0; t < g->triangles; t++) report_lot_moves(f, p, g->tri + 3 * t, 3, v);
  for (size_t e = 0; e < g->edges; e++) report_lot_moves(f, p, g->edge + 2 * e, 2, v);
  fprintf(f, "\"/>\n");
}

/* The constrained edges, pairs of point indices, in one thick path. */
static void report_lot_seg_draw(FILE *f, const geom_point *p, const uint32_t *seg, size_t nseg,
                                const report_lot_view *v, double width) {
  fprintf(f, "<path fill=\"none\" stroke=\"#111111\" stroke-width=\"%.2f\" "
             "stroke-linecap=\"round\" d=\"", width);
  for (size_t e = 0; e < nseg; e++) report_lot_moves(f, p, seg + 2 * e, 2, v);
  fprintf(f, "\"/>\n");
}

static void report_lot_panel_draw(FILE *f, const geom_point *p, size_t n,
                                  const report_lot_panel *pn, const report_lot_view *v,
                                  int shade, double lo, double hi) {
  double hair = n > 2000 ? 0.2 : n > 300 ? 0.4 : 0.8;
  double dot = n > 2000 ? 0.5 : n > 300 ? 1.0 : 2.0;
  if (pn->caption) report_svg_text(f, v->x0, v->y0 + 12, 13, pn->caption);
  for (size_t t = 0; shade && pn->badness && t < pn->ntri; t++) {
    char col[16] = "#dddddd";
    double b = pn->badness[t];
    if (isfinite(b)) report_svg_colour(hi > lo ? (b - lo) / (hi - lo) : 0, col, sizeof col);
    const uint32_t *w = pn->tri + 3 * t;
    fprintf(f, "<polygon fill=\"%s\" points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f\"/>\n", col,
            report_lot_px(v, p[w[0]].x), report_lot_py(v, p[w[0]].y),
            report_lot_px(v, p[w[1]].x), report_lot_py(v, p[w[1]].y),
            report_lot_px(v, p[w[2]].x), report_lot_py(v, p[w[2]].y));
  }
  fprintf(f, "<path fill=\"none\" stroke=\"#1f4e79\" stroke-width=\"%.2f\" d=\"", hair);
  for (size_t t = 0; t < pn->ntri; t++) report_lot_moves(f, p, pn->tri + 3 * t, 3, v);
  fprintf(f, "\"/>\n");
  if (pn->cdf) report_lot_cdf_draw(f, p, pn->cdf, v, 3 * hair);
  if (pn->nseg) report_lot_seg_draw(f, p, pn->seg, pn->nseg, v, 3 * hair);
  fprintf(f, "<g fill=\"black\">\n");
  for (size_t q = 0; q < n; q++)
    fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.1f\"/>\n", report_lot_px(v, p[q].x),
            report_lot_py(v, p[q].y), dot);
  fprintf(f, "</g>\n");
}

/* Panels per row: all of them up to three, then the smallest square grid
** (four in 2 x 2, five and six in 3 x 2, up to nine in 3 x 3). */
static int report_lot_columns(int npanels) {
  int c = 1;
  if (npanels <= 3) return npanels;
  while (c * c < npanels) c++;
  return c;
}

int report_lot_svg(FILE *f, const geom_point *p, size_t n, const report_lot_panel *panels,
                   int npanels, int shade, const char *title) {
  report_svg_box b = report_svg_bbox(p, n);
  int cols = report_lot_columns(npanels), rows = (npanels + cols - 1) / cols;
  double size = npanels > 3 ? REPORT_LOT_GRID_SIZE : REPORT_LOT_SIZE;
  report_lot_view v = {b.minx, b.maxy, report_svg_fit_scale(&b, size), REPORT_LOT_MARGIN,
                       REPORT_LOT_TOP};
  double w = b.maxx - b.minx, h = b.maxy - b.miny;
  double pw = w * v.s + 2 * REPORT_LOT_MARGIN;
  double ph = h * v.s + REPORT_LOT_CAPTION + REPORT_LOT_MARGIN;
  double width = pw * cols, height = ph * rows + REPORT_LOT_TOP + (shade ? 26 : 0);
  if (width < 420) width = 420;
  fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
             "viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\">\n"
             "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
          width, height, width, height);
  if (title) report_svg_text(f, REPORT_LOT_MARGIN, 20, 14, title);
  double lo, hi;
  report_lot_range(panels, npanels, &lo, &hi);
  for (int k = 0; k < npanels; k++) {
    v.x0 = REPORT_LOT_MARGIN + (k % cols) * pw;
    v.y0 = REPORT_LOT_TOP + (k / cols) * ph;
    report_lot_panel_draw(f, p, n, &panels[k], &v, shade, lo, hi);
  }
  if (shade && hi >= lo) report_svg_colour_legend(f, REPORT_LOT_MARGIN, height - 20, lo, hi);
  fprintf(f, "</svg>\n");
  return ferror(f) ? -1 : 0;
}
