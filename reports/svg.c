/*
** svg.c: the SVG kit of reports/ (report_internal.h): escaped text and
** captions, the fit of a point set into a view, the badness colour scale
** of shaded drawings, and the frames and arrows that both flip-graph
** pictures (a pentagon's, svg_flipgraph.c; a site set's, svg_siteflip.c)
** draw in one style.  Every picture of fliplab is written through these,
** so a colour or an escaping rule changes in one place.
*/
#include <math.h>
#include <string.h>
#include "report_internal.h"

/* ---- text ---------------------------------------------------------------- */

/* The five XML specials, so a string is safe both as element text and
** inside an attribute value quoted with either quote character. */
int report_xml_text(FILE *f, const char *s) {
  for (; *s; s++) {
    const char *e = NULL;
    switch (*s) {
    case '&': e = "&amp;"; break;
    case '<': e = "&lt;"; break;
    case '>': e = "&gt;"; break;
    case '"': e = "&quot;"; break;
    case '\'': e = "&apos;"; break;
    default: break;
    }
    if ((e != NULL ? fputs(e, f) : fputc(*s, f)) == EOF) return -1;
  }
  return 0;
}

void report_svg_text(FILE *f, double x, double y, int size, const char *s) {
  fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"%d\">", x, y, size);
  report_xml_text(f, s);
  fputs("</text>\n", f);
}

void report_svg_caption(FILE *f, double x, double y, const char *caption) {
  if (caption == NULL) return;
  const char *s = caption;
  while (*s) {
    const char *e = strchr(s, '\n');
    size_t n = e ? (size_t)(e - s) : strlen(s);
    char line[1024];
    if (n >= sizeof line) n = sizeof line - 1;
    memcpy(line, s, n);
    line[n] = '\0';
    fprintf(f, "<text x='%g' y='%.1f' font-size='12' font-family='monospace'>", x, y);
    report_xml_text(f, line);
    fprintf(f, "</text>\n");
    y += REPORT_SVG_LINE;
    s += n;
    if (*s == '\n') s++;
  }
}

int report_svg_caption_lines(const char *caption) {
  if (caption == NULL || *caption == '\0') return 0;
  int lines = 1;
  for (const char *c = caption; *c; c++) lines += *c == '\n';
  return lines;
}

/* ---- view fit ------------------------------------------------------------ */

report_svg_box report_svg_bbox(const geom_point *p, size_t n) {
  report_svg_box b = {p[0].x, p[0].y, p[0].x, p[0].y};
  for (size_t q = 1; q < n; q++) {
    if (p[q].x < b.minx) b.minx = p[q].x;
    if (p[q].x > b.maxx) b.maxx = p[q].x;
    if (p[q].y < b.miny) b.miny = p[q].y;
    if (p[q].y > b.maxy) b.maxy = p[q].y;
  }
  return b;
}

double report_svg_fit_scale(const report_svg_box *b, double size) {
  double w = b->maxx - b->minx, h = b->maxy - b->miny, big = w > h ? w : h;
  return big > 0 ? size / big : 1;
}

/* ---- the badness colour scale -------------------------------------------- */

/* Piecewise linear through 4 stops. */
void report_svg_colour(double f, char *buf, size_t len) {
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

void report_svg_colour_legend(FILE *f, double x0, double y, double lo, double hi) {
  for (int s = 0; s < 20; s++) {
    char col[16];
    report_svg_colour(s / 19.0, col, sizeof col);
    fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"10\" height=\"10\" fill=\"%s\"/>\n",
            x0 + 120 + 10 * s, y, col);
  }
  fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\">badness %.4g</text>\n",
          x0, y + 9, lo);
  fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\">%.4g</text>\n",
          x0 + 325, y + 9, hi);
}

/* ---- directed flip graphs ------------------------------------------------ */

void report_svg_graph_open(FILE *f, double w, double h) {
  fprintf(f, "<?xml version='1.0' encoding='UTF-8'?>\n"
             "<svg xmlns='http://www.w3.org/2000/svg' width='%.0f' height='%.0f' "
             "viewBox='0 0 %.0f %.0f' font-family='sans-serif'>\n",
          w, h, w, h);
  fprintf(f, "<defs><marker id='arrow' viewBox='0 0 10 10' refX='9' refY='5' markerWidth='7' "
             "markerHeight='7' orient='auto-start-reverse'><path d='M0,0 L10,5 L0,10 z' "
             "fill='#333333'/></marker></defs>\n<rect width='100%%' height='100%%' fill='white'/>\n");
}

/* The chord between two frame centres leaves a square frame of half-side
** h at distance h / max(|ux|, |uy|) from its centre (u the unit direction). */
void report_svg_flip(FILE *f, double box, double pad, double width, double ax, double ay,
                     double bx, double by, int either) {
  double dx = bx - ax, dy = by - ay, len = sqrt(dx * dx + dy * dy);
  if (len <= 0) return;
  double ux = dx / len, uy = dy / len;
  double cut = (box / 2) / fmax(fabs(ux), fabs(uy)) + pad;
  if (2 * cut >= len) return;
  double x1 = ax + cut * ux, y1 = ay + cut * uy, x2 = bx - cut * ux, y2 = by - cut * uy;
  if (either)
    fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='#777777' "
               "stroke-width='%g' stroke-dasharray='6 5'/>\n", x1, y1, x2, y2, width);
  else
    fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='#333333' "
               "stroke-width='%g' marker-end='url(#arrow)'/>\n", x1, y1, x2, y2, width);
}

/* The colours of the three roles: frame stroke (also the role label's
** colour), frame fill, and the label above the frame. */
static const struct {
  const char *stroke, *fill, *label;
} report_svg_roles[3] = {
  [REPORT_SVG_PLAIN] = {"#999999", "#ffffff", NULL},
  [REPORT_SVG_SINK] = {"#1a9850", "#e5f5e0", "sink"},
  [REPORT_SVG_SOURCE] = {"#d73027", "#fff5f0", "source"},
};

void report_svg_node_frame(FILE *f, const report_svg_node_style *st, double cx, double cy,
                           report_svg_role role) {
  double h = st->box / 2;
  double width = role == REPORT_SVG_SINK ? st->sink_width
               : role == REPORT_SVG_SOURCE ? st->source_width : 1.2;
  fprintf(f, "<rect x='%.1f' y='%.1f' width='%.1f' height='%.1f' rx='%g' stroke='%s' "
             "stroke-width='%g'", cx - h, cy - h, st->box, st->box, st->rx,
          report_svg_roles[role].stroke, width);
  if (role == REPORT_SVG_SOURCE) fprintf(f, " stroke-dasharray='%s'", st->source_dash);
  fprintf(f, " fill='%s'/>\n", report_svg_roles[role].fill);
}

void report_svg_node_tags(FILE *f, const report_svg_node_style *st, double cx, double cy,
                          int name, report_svg_role role, int dt) {
  double h = st->box / 2;
  fprintf(f, "<text x='%.1f' y='%.1f' font-size='%d'%s text-anchor='middle'>T%d</text>\n", cx,
          cy + h + st->name_gap, st->name_size, st->name_bold ? " font-weight='bold'" : "", name);
  if (report_svg_roles[role].label != NULL)
    fprintf(f, "<text x='%.1f' y='%.1f' font-size='%d' text-anchor='middle' fill='%s'>%s</text>\n",
            cx, cy - h - st->tag_gap, st->role_size, report_svg_roles[role].stroke,
            report_svg_roles[role].label);
  if (dt)
    fprintf(f, "<text x='%.1f' y='%.1f' font-size='11' fill='#555555'>DT</text>\n", cx + h - 20,
            cy + h - st->tag_gap);
}

/* ---- log-log line plots ------------------------------------------------ */

/* Canvas, plot area (pixels); one colour per series. */
enum { LL_W = 640, LL_H = 480, LL_X0 = 70, LL_Y0 = 40, LL_PW = 380, LL_PH = 380 };
static const char *const report_loglog_colours[] = {
  "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf",
};

static double report_loglog_px(const report_loglog *a, double n) {
  return LL_X0 + (log10(n) - a->x0) / (a->x1 - a->x0) * LL_PW;
}

static double report_loglog_py(const report_loglog *a, double v) {
  return LL_Y0 + LL_PH - (log10(v) - a->y0) / (a->y1 - a->y0) * LL_PH;
}

report_loglog report_loglog_range(double xlo, double xhi, double ylo, double yhi) {
  if (xhi == 0) return (report_loglog){0, 1, 0, 1};
  report_loglog a = {floor(log10(xlo)), ceil(log10(xhi)), floor(log10(ylo)), ceil(log10(yhi))};
  if (a.x1 <= a.x0) a.x1 = a.x0 + 1;
  if (a.y1 <= a.y0) a.y1 = a.y0 + 1;
  return a;
}

void report_loglog_frame(FILE *f, const report_loglog *a, const char *title, const char *xlabel,
                         const char *ylabel) {
  fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
             "font-family=\"sans-serif\">\n"
             "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n", LL_W, LL_H);
  fprintf(f, "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" "
             "stroke=\"black\"/>\n", LL_X0, LL_Y0, LL_PW, LL_PH);
  char lab[32];
  for (double e = a->x0; e <= a->x1; e++) {
    double x = LL_X0 + (e - a->x0) / (a->x1 - a->x0) * LL_PW;
    snprintf(lab, sizeof lab, "1e%g", e);
    fprintf(f, "<line x1=\"%.2f\" y1=\"%d\" x2=\"%.2f\" y2=\"%d\" stroke=\"#ccc\"/>\n", x, LL_Y0,
            x, LL_Y0 + LL_PH);
    report_svg_text(f, x - 12, LL_Y0 + LL_PH + 16, 11, lab);
  }
  for (double e = a->y0; e <= a->y1; e++) {
    double y = LL_Y0 + LL_PH - (e - a->y0) / (a->y1 - a->y0) * LL_PH;
    snprintf(lab, sizeof lab, "1e%g", e);
    fprintf(f, "<line x1=\"%d\" y1=\"%.2f\" x2=\"%d\" y2=\"%.2f\" stroke=\"#ccc\"/>\n", LL_X0, y,
            LL_X0 + LL_PW, y);
    report_svg_text(f, LL_X0 - 40, y + 4, 11, lab);
  }
  report_svg_text(f, LL_X0, 24, 14, title);
  report_svg_text(f, LL_X0 + LL_PW / 2 - 60, LL_H - 12, 12, xlabel);
  report_svg_text(f, LL_X0 + LL_PW + 16, LL_Y0 + 8, 12, ylabel);
}

void report_loglog_series(FILE *f, const report_loglog *a, const double *x, const double *y,
                          size_t k, int slot, const char *label) {
  const char *col = report_loglog_colours[slot % 8];
  fprintf(f, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\" points=\"", col);
  for (size_t i = 0; i < k; i++)
    fprintf(f, "%.2f,%.2f ", report_loglog_px(a, x[i]), report_loglog_py(a, y[i]));
  fprintf(f, "\"/>\n");
  for (size_t i = 0; i < k; i++)
    fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"3\" fill=\"%s\"/>\n",
            report_loglog_px(a, x[i]), report_loglog_py(a, y[i]), col);
  double ly = LL_Y0 + 40 + 20 * slot;
  fprintf(f, "<rect x=\"%d\" y=\"%.2f\" width=\"12\" height=\"4\" fill=\"%s\"/>\n",
          LL_X0 + LL_PW + 16, ly - 4, col);
  report_svg_text(f, LL_X0 + LL_PW + 34, ly, 11, label);
}
