/*
** svg_got.c: an SVG picture of a simple polygon (convex or not) and its
** globally optimal triangulation (`fliplab got --svg`).
**
** Readable for large n: the polygon is scaled so that its larger side is
** 1000 px, diagonals are hairlines (one <path>), the outline is a little
** heavier and vertices are small dots.  Up to REPORT_GOT_LABEL_N vertices
** each dot carries its number (the input's row when a map is given), set
** off outwards along the bisector of the two edges' outward normals, so a
** reflex vertex's number sits outside the notch too.  With shading, each
** triangle is filled on a light-to-dark scale of its badness between the
** best and the worst triangle (small is good, so dark marks the bad
** triangles), with a legend giving the two ends.  Nothing assumes
** convexity: the outline is the polygon itself and every diagonal is the
** chord (i, j) of exactly one triangle of the programme's tree.
*/
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include "report_internal.h"

#define REPORT_GOT_SIZE 1000.0
#define REPORT_GOT_MARGIN 12.0
#define REPORT_GOT_TOP 30.0
#define REPORT_GOT_LABEL_N 60     /* vertex numbers up to this n */

typedef struct report_got_view {
  double minx, maxy, s, margin;
  double width, height, hair, dot;
} report_got_view;

static double report_got_px(const report_got_view *v, double x) {
  return v->margin + (x - v->minx) * v->s;
}
static double report_got_py(const report_got_view *v, double y) {
  return REPORT_GOT_TOP + v->margin - REPORT_GOT_MARGIN + (v->maxy - y) * v->s;
}

/* Scale and page size; labels get a wider margin. */
static report_got_view report_got_fit(const geom_point *p, size_t n, int shade) {
  report_svg_box b = report_svg_bbox(p, n);
  report_got_view v = {b.minx, b.maxy, report_svg_fit_scale(&b, REPORT_GOT_SIZE),
                       REPORT_GOT_MARGIN, 0, 0, 0, 0};
  if (n <= REPORT_GOT_LABEL_N) v.margin = 2 * REPORT_GOT_MARGIN + 8;
  double w = b.maxx - b.minx, h = b.maxy - b.miny;
  v.width = w * v.s + 2 * v.margin;
  v.height = h * v.s + REPORT_GOT_TOP + 2 * v.margin - REPORT_GOT_MARGIN + (shade ? 24 : 0);
  if (v.width < 400) v.width = 400;
  v.hair = n > 300 ? 0.35 : n > 60 ? 0.6 : 1.0;
  v.dot = n > 300 ? 0.8 : n > 60 ? 1.8 : 3.0;
  return v;
}

static void report_got_tri_range(const got_triangle *t, size_t ntri, double *bmin, double *bmax) {
  *bmin = INFINITY;
  *bmax = -INFINITY;
  for (size_t q = 0; q < ntri; q++)
    if (isfinite(t[q].badness)) {
      if (t[q].badness < *bmin) *bmin = t[q].badness;
      if (t[q].badness > *bmax) *bmax = t[q].badness;
    }
}

static void report_got_shade(FILE *f, const report_got_view *v, const geom_point *p,
                             const got_triangle *t, size_t ntri, double bmin, double bmax) {
  fprintf(f, "<g stroke=\"none\">\n");
  for (size_t q = 0; q < ntri; q++) {
    char col[16];
    double fr = bmax > bmin ? (t[q].badness - bmin) / (bmax - bmin) : 0;
    if (isfinite(t[q].badness)) report_svg_colour(fr, col, sizeof col);
    else snprintf(col, sizeof col, "#999999");
    const geom_point *a = &p[t[q].i], *b = &p[t[q].k], *c = &p[t[q].j];
    fprintf(f, "<polygon fill=\"%s\" points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f\"/>\n", col,
            report_got_px(v, a->x), report_got_py(v, a->y), report_got_px(v, b->x),
            report_got_py(v, b->y), report_got_px(v, c->x), report_got_py(v, c->y));
  }
  fprintf(f, "</g>\n");
}

/* Diagonals: every diagonal is the chord (i, j) of exactly one triangle
** (i, k, j) of the DP's tree, so each is drawn once. */
static void report_got_diagonals(FILE *f, const report_got_view *v, const geom_point *p,
                                 size_t n, const got_triangle *t, size_t ntri) {
  fprintf(f, "<path fill=\"none\" stroke=\"#1f4e79\" stroke-width=\"%.2f\" d=\"", v->hair);
  for (size_t q = 0; q < ntri; q++) {
    size_t i = (size_t)t[q].i, j = (size_t)t[q].j;
    if (j - i == 1 || (i == 0 && j == n - 1)) continue;
    fprintf(f, "M%.2f %.2fL%.2f %.2f", report_got_px(v, p[i].x), report_got_py(v, p[i].y),
            report_got_px(v, p[j].x), report_got_py(v, p[j].y));
  }
  fprintf(f, "\"/>\n");
}

static int report_got_pair_cmp(const void *x, const void *y) {
  const size_t *a = x, *b = y;
  return a[0] != b[0] ? (a[0] > b[0]) - (a[0] < b[0]) : (a[1] > b[1]) - (a[1] < b[1]);
}

/* The diagonals (i, j), i < j, of a triangulation's triangles (i, k, j),
** sorted; polygon edges are left out.  *m pairs into a malloc'ed array. */
static size_t *report_got_chords(const got_triangle *t, size_t ntri, size_t n, size_t *m) {
  size_t *c = malloc((ntri > 0 ? ntri : 1) * 2 * sizeof *c);
  *m = 0;
  if (c == NULL) return NULL;
  for (size_t q = 0; q < ntri; q++) {
    size_t i = (size_t)t[q].i, j = (size_t)t[q].j;
    if (i > j) { size_t s = i; i = j; j = s; }
    if (j - i == 1 || (i == 0 && j == n - 1)) continue;
    c[2 * *m] = i;
    c[2 * *m + 1] = j;
    (*m)++;
  }
  qsort(c, *m, 2 * sizeof *c, report_got_pair_cmp);
  return c;
}

/* The overlay's diagonals that the drawn triangulation lacks, dashed red on
** top (the caller's title says so); -1 if out of memory. */
static int report_got_overlay(FILE *f, const report_got_view *v, const geom_point *p, size_t n,
                              const got_triangle *t, size_t ntri, const report_got_svg_opts *o) {
  size_t ma, mb, shown = 0;
  size_t *a = report_got_chords(t, ntri, n, &ma), *b = report_got_chords(o->overlay, o->noverlay, n, &mb);
  if (a == NULL || b == NULL) {
    free(a);
    free(b);
    return -1;
  }
  fprintf(f, "<path fill=\"none\" stroke=\"#d62728\" stroke-dasharray=\"%.2f %.2f\" "
             "stroke-width=\"%.2f\" d=\"", 4 * v->hair, 3 * v->hair, 1.5 * v->hair);
  for (size_t q = 0; q < mb; q++) {
    if (bsearch(&b[2 * q], a, ma, 2 * sizeof *a, report_got_pair_cmp) != NULL) continue;
    size_t i = b[2 * q], j = b[2 * q + 1];
    fprintf(f, "M%.2f %.2fL%.2f %.2f", report_got_px(v, p[i].x), report_got_py(v, p[i].y),
            report_got_px(v, p[j].x), report_got_py(v, p[j].y));
    shown++;
  }
  fprintf(f, "\"><title>%zu diagonals of %s not in this triangulation</title></path>\n", shown,
          o->overlay_name ? o->overlay_name : "the other triangulation");
  free(a);
  free(b);
  return 0;
}

static void report_got_outline(FILE *f, const report_got_view *v, const geom_point *p, size_t n) {
  fprintf(f, "<polygon fill=\"none\" stroke=\"black\" stroke-width=\"%.2f\" points=\"",
          v->hair * 2.5);
  for (size_t q = 0; q < n; q++)
    fprintf(f, "%s%.2f,%.2f", q ? " " : "", report_got_px(v, p[q].x), report_got_py(v, p[q].y));
  fprintf(f, "\"/>\n<g fill=\"black\">\n");
  for (size_t q = 0; q < n; q++)
    fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.1f\"/>\n", report_got_px(v, p[q].x),
            report_got_py(v, p[q].y), v->dot);
  fprintf(f, "</g>\n");
}

/* Vertex numbers, set off outwards (anticlockwise polygon: the outward
** normal of edge a -> b is (dy, -dx)), in pixel space (y points down). */
static void report_got_labels(FILE *f, const report_got_view *v, const geom_point *p, size_t n,
                              const size_t *labels) {
  fprintf(f, "<g font-size=\"11\" fill=\"#444\" text-anchor=\"middle\">\n");
  for (size_t q = 0; q < n; q++) {
    geom_point a = p[(q + n - 1) % n], b = p[q], c = p[(q + 1) % n];
    double n1x = b.y - a.y, n1y = -(b.x - a.x), n2x = c.y - b.y, n2y = -(c.x - b.x);
    double l1 = hypot(n1x, n1y), l2 = hypot(n2x, n2y);
    double ox = n1x / l1 + n2x / l2, oy = n1y / l1 + n2y / l2, lo = hypot(ox, oy);
    if (!(lo > 1e-9)) {            /* a spike-free straight angle has lo = 2; a cusp ~0 */
      ox = n1x / l1;
      oy = n1y / l1;
      lo = 1;
    }
    double x = report_got_px(v, b.x) + 10 * ox / lo, y = report_got_py(v, b.y) - 10 * oy / lo;
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\">%zu</text>\n", x, y + 4,
            labels ? labels[q] : q);
  }
  fprintf(f, "</g>\n");
}

int report_got_svg(FILE *f, const geom_point *p, size_t n, const got_triangle *t,
                   size_t ntri, const report_got_svg_opts *o) {
  int shade = o && o->shade;
  report_got_view v = report_got_fit(p, n, shade);
  fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
             "viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\">\n",
          v.width, v.height, v.width, v.height);
  fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
  if (o && o->title) report_svg_text(f, REPORT_GOT_MARGIN, 20, 14, o->title);
  double bmin, bmax;
  report_got_tri_range(t, ntri, &bmin, &bmax);
  if (shade) report_got_shade(f, &v, p, t, ntri, bmin, bmax);
  report_got_diagonals(f, &v, p, n, t, ntri);
  if (o && o->overlay && report_got_overlay(f, &v, p, n, t, ntri, o) != 0) return -1;
  report_got_outline(f, &v, p, n);
  if (n <= REPORT_GOT_LABEL_N) report_got_labels(f, &v, p, n, o ? o->labels : NULL);
  if (shade && bmax >= bmin) report_svg_colour_legend(f, REPORT_GOT_MARGIN, v.height - 18, bmin, bmax);
  fprintf(f, "</svg>\n");
  return ferror(f) ? -1 : 0;
}
