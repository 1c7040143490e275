/*
** svg_got.c: an SVG picture of a convex polygon and its globally optimal
** triangulation (`fliplab got --svg`).
**
** Readable for large n: the polygon is scaled so that its larger side is
** 1000 px, diagonals are hairlines (one <path>), the outline is a little
** heavier and vertices are small dots.  With shading, each triangle is
** filled on a light-to-dark scale of its badness between the best and the
** worst triangle (small is good, so dark marks the bad triangles), with a
** legend giving the two ends.
*/
#include <math.h>
#include <stdio.h>
#include "report.h"

#define REPORT_GOT_SIZE 1000.0
#define REPORT_GOT_MARGIN 12.0
#define REPORT_GOT_TOP 30.0

typedef struct report_got_view {
  double minx, maxy, s;
} report_got_view;

static double report_got_px(const report_got_view *v, double x) {
  return REPORT_GOT_MARGIN + (x - v->minx) * v->s;
}
static double report_got_py(const report_got_view *v, double y) {
  return REPORT_GOT_TOP + (v->maxy - y) * v->s;
}

/* Light yellow (good) to dark red (bad), piecewise linear through 4 stops. */
static void report_got_colour(double f, char *buf, size_t len) {
  static const double stop[4][3] = {
    {255, 247, 214}, {253, 174, 97}, {215, 48, 39}, {103, 0, 13}};
  if (!(f >= 0)) f = 0;
  if (f > 1) f = 1;
  double x = f * 3;
  int q = x >= 3 ? 2 : (int)x;
  double u = x - q;
  int c[3];
  for (int a = 0; a < 3; a++) c[a] = (int)lround(stop[q][a] + u * (stop[q + 1][a] - stop[q][a]));
  snprintf(buf, len, "#%02x%02x%02x", c[0], c[1], c[2]);
}

/* A line of text, with the XML specials escaped. */
static void report_got_text(FILE *f, double x, double y, int size, const char *s) {
  fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"%d\">", x, y, size);
  report_xml_text(f, s);
  fputs("</text>\n", f);
}

int report_got_svg(FILE *f, const geom_point *p, size_t n, const got_triangle *t,
                   size_t ntri, const report_got_svg_opts *o) {
  report_got_view v = {p[0].x, p[0].y, 1};
  double maxx = p[0].x, miny = p[0].y;
  for (size_t q = 1; q < n; q++) {
    if (p[q].x < v.minx) v.minx = p[q].x;
    if (p[q].x > maxx) maxx = p[q].x;
    if (p[q].y < miny) miny = p[q].y;
    if (p[q].y > v.maxy) v.maxy = p[q].y;
  }
  double w = maxx - v.minx, h = v.maxy - miny, big = w > h ? w : h;
  v.s = big > 0 ? REPORT_GOT_SIZE / big : 1;
  double width = w * v.s + 2 * REPORT_GOT_MARGIN;
  double height = h * v.s + REPORT_GOT_TOP + REPORT_GOT_MARGIN + (o && o->shade ? 24 : 0);
  if (width < 400) width = 400;
  double hair = n > 300 ? 0.35 : n > 60 ? 0.6 : 1.0;
  double dot = n > 300 ? 0.8 : n > 60 ? 1.8 : 3.0;

  fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
             "viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\">\n",
          width, height, width, height);
  fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
  if (o && o->title)
    report_got_text(f, REPORT_GOT_MARGIN, 20, 14, o->title);

  double bmin = INFINITY, bmax = -INFINITY;
  if (o && o->shade) {
    for (size_t q = 0; q < ntri; q++)
      if (isfinite(t[q].badness)) {
        if (t[q].badness < bmin) bmin = t[q].badness;
        if (t[q].badness > bmax) bmax = t[q].badness;
      }
    fprintf(f, "<g stroke=\"none\">\n");
    for (size_t q = 0; q < ntri; q++) {
      char col[16];
      double fr = bmax > bmin ? (t[q].badness - bmin) / (bmax - bmin) : 0;
      if (isfinite(t[q].badness)) report_got_colour(fr, col, sizeof col);
      else snprintf(col, sizeof col, "#999999");
      const geom_point *a = &p[t[q].i], *b = &p[t[q].k], *c = &p[t[q].j];
      fprintf(f, "<polygon fill=\"%s\" points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f\"/>\n", col,
              report_got_px(&v, a->x), report_got_py(&v, a->y), report_got_px(&v, b->x),
              report_got_py(&v, b->y), report_got_px(&v, c->x), report_got_py(&v, c->y));
    }
    fprintf(f, "</g>\n");
  }

  /* Diagonals: every diagonal is the chord (i, j) of exactly one
  ** triangle (i, k, j) of the DP's tree, so each is drawn once. */
  fprintf(f, "<path fill=\"none\" stroke=\"#1f4e79\" stroke-width=\"%.2f\" d=\"", hair);
  for (size_t q = 0; q < ntri; q++) {
    size_t i = (size_t)t[q].i, j = (size_t)t[q].j;
    if (j - i == 1 || (i == 0 && j == n - 1)) continue;
    fprintf(f, "M%.2f %.2fL%.2f %.2f", report_got_px(&v, p[i].x), report_got_py(&v, p[i].y),
            report_got_px(&v, p[j].x), report_got_py(&v, p[j].y));
  }
  fprintf(f, "\"/>\n");

  fprintf(f, "<polygon fill=\"none\" stroke=\"black\" stroke-width=\"%.2f\" points=\"",
          hair * 2.5);
  for (size_t q = 0; q < n; q++)
    fprintf(f, "%s%.2f,%.2f", q ? " " : "", report_got_px(&v, p[q].x), report_got_py(&v, p[q].y));
  fprintf(f, "\"/>\n<g fill=\"black\">\n");
  for (size_t q = 0; q < n; q++)
    fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.1f\"/>\n", report_got_px(&v, p[q].x),
            report_got_py(&v, p[q].y), dot);
  fprintf(f, "</g>\n");

  if (o && o->shade && bmax >= bmin) {
    double y = height - 18;
    for (int s = 0; s < 20; s++) {
      char col[16];
      report_got_colour(s / 19.0, col, sizeof col);
      fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"10\" height=\"10\" fill=\"%s\"/>\n",
              REPORT_GOT_MARGIN + 120 + 10 * s, y, col);
    }
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\">badness %.4g</text>\n",
            REPORT_GOT_MARGIN, y + 9, bmin);
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\">%.4g</text>\n",
            REPORT_GOT_MARGIN + 325, y + 9, bmax);
  }
  fprintf(f, "</svg>\n");
  return ferror(f) ? -1 : 0;
}
