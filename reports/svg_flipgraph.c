/*
** svg_flipgraph.c: a pentagon's directed flip graph as SVG (thesis figure
** 3.7): five small triangulations on a cycle, arrows to the preferred one.
**
** Geometry of the figure.  The cycle T0 - T2 - T4 - T1 - T3 is a regular
** pentagon of slots (slot k holds T_{2k mod 5}), drawn clockwise from the
** top.  Neighbours on the cycle differ by 2 (mod 5): the edge between T_a
** and T_{a+2} is decided by Q_{a+1}, whose AC answer points at T_{a+2} and
** BD answer at T_a (flipgraph.h).
*/
#include <math.h>
#include <string.h>
#include "report.h"

#define RFG_W 720.0
#define RFG_CX 360.0
#define RFG_CY 340.0
#define RFG_RING 250.0          /* radius of the ring of slots */
#define RFG_BOX 140.0           /* side of a slot's frame */
#define RFG_PIC 106.0           /* the pentagon's extent inside a frame */
#define RFG_LINE 17.0           /* caption line height */

static const int report_flipgraph_cycle[5] = {0, 2, 4, 1, 3};

static void report_flipgraph_slot(int k, double *x, double *y) {
  double th = -M_PI / 2 + 2 * M_PI * k / 5;
  *x = RFG_CX + RFG_RING * cos(th);
  *y = RFG_CY + RFG_RING * sin(th);
}

/* Map pentagon coordinates into a picture centred at (cx, cy); y up. */
typedef struct report_flipgraph_map { double s, mx, my; } report_flipgraph_map;

static report_flipgraph_map report_flipgraph_fit(const geom_point v[5]) {
  double x0 = v[0].x, x1 = v[0].x, y0 = v[0].y, y1 = v[0].y;
  for (int i = 1; i < 5; i++) {
    x0 = fmin(x0, v[i].x);
    x1 = fmax(x1, v[i].x);
    y0 = fmin(y0, v[i].y);
    y1 = fmax(y1, v[i].y);
  }
  double ext = fmax(x1 - x0, y1 - y0);
  report_flipgraph_map m = {ext > 0 ? RFG_PIC / ext : 1, (x0 + x1) / 2, (y0 + y1) / 2};
  return m;
}

static void report_flipgraph_pt(const report_flipgraph_map *m, geom_point p, double cx,
                                double cy, double *x, double *y) {
  *x = cx + m->s * (p.x - m->mx);
  *y = cy - m->s * (p.y - m->my);
}

/* One triangulation T_i: boundary, its two diagonals v_i v_{i+2} and
** v_i v_{i+3}, vertex labels, frame by role. */
static void report_flipgraph_tri(FILE *f, const flipgraph_pentagon *p, const flipgraph *g,
                                 const report_flipgraph_map *m, int i, int source, int k) {
  double cx, cy, x[5], y[5];
  report_flipgraph_slot(k, &cx, &cy);
  for (int q = 0; q < 5; q++) report_flipgraph_pt(m, p->v[q], cx, cy, &x[q], &y[q]);
  int sink = (g->nsinks > 0 && g->sink[0] == i) || (g->nsinks > 1 && g->sink[1] == i);
  const char *frame = sink ? "stroke='#1a9850' stroke-width='6' fill='#e5f5e0'"
                    : (source >> i & 1) ? "stroke='#d73027' stroke-width='3' stroke-dasharray='8 5' fill='#fff5f0'"
                    : "stroke='#999999' stroke-width='1.2' fill='#ffffff'";
  double h = RFG_BOX / 2;
  fprintf(f, "<rect x='%.1f' y='%.1f' width='%.1f' height='%.1f' rx='10' %s/>\n", cx - h,
          cy - h, RFG_BOX, RFG_BOX, frame);
  fprintf(f, "<polygon points='");
  for (int q = 0; q < 5; q++) fprintf(f, "%.2f,%.2f ", x[q], y[q]);
  fprintf(f, "' fill='none' stroke='#222222' stroke-width='1.6'/>\n");
  for (int d = 2; d <= 3; d++)
    fprintf(f, "<line x1='%.2f' y1='%.2f' x2='%.2f' y2='%.2f' stroke='#2166ac' stroke-width='2'/>\n",
            x[i], y[i], x[(i + d) % 5], y[(i + d) % 5]);
  for (int q = 0; q < 5; q++)
    fprintf(f, "<circle cx='%.2f' cy='%.2f' r='2.5' fill='#222222'/>\n", x[q], y[q]);
  /* Vertex labels, pushed away from the pentagon's centre. */
  double gx = 0, gy = 0;
  for (int q = 0; q < 5; q++) {
    gx += x[q] / 5;
    gy += y[q] / 5;
  }
  for (int q = 0; q < 5; q++) {
    double dx = x[q] - gx, dy = y[q] - gy, dl = sqrt(dx * dx + dy * dy);
    if (dl <= 0) dl = 1;
    fprintf(f, "<text x='%.1f' y='%.1f' font-size='10' fill='#777777' text-anchor='middle'>v%d</text>\n",
            x[q] + 9 * dx / dl, y[q] + 9 * dy / dl + 3.5, q);
  }
  fprintf(f, "<text x='%.1f' y='%.1f' font-size='16' font-weight='bold' text-anchor='middle'>T%d</text>\n",
          cx, cy + h + 18, i);
  const char *role = sink ? "sink" : (source >> i & 1) ? "source" : NULL;
  if (role != NULL)
    fprintf(f, "<text x='%.1f' y='%.1f' font-size='13' text-anchor='middle' fill='%s'>%s</text>\n",
            cx, cy - h - 6, sink ? "#1a9850" : "#d73027", role);
  if (i == p->delaunay_sink)
    fprintf(f, "<text x='%.1f' y='%.1f' font-size='11' fill='#555555'>DT</text>\n", cx + h - 20,
            cy + h - 6);
}

/* The cycle edge from slot k to slot k+1, directed by Q_j. */
static void report_flipgraph_edge(FILE *f, const flipgraph *g, int k) {
  int a = report_flipgraph_cycle[k];       /* next slot holds T_{a+2} */
  int j = (a + 1) % 5;                      /* so Q_{a+1} decides the edge */
  double ax, ay, bx, by;
  report_flipgraph_slot(k, &ax, &ay);
  report_flipgraph_slot((k + 1) % 5, &bx, &by);
  double dx = bx - ax, dy = by - ay, len = sqrt(dx * dx + dy * dy);
  double ux = dx / len, uy = dy / len;
  /* Leave the frames: the chord crosses a square frame of half-side h at
  ** distance h / max(|ux|, |uy|) from its centre. */
  double cut = (RFG_BOX / 2) / fmax(fabs(ux), fabs(uy)) + 8;
  double x1 = ax + cut * ux, y1 = ay + cut * uy, x2 = bx - cut * ux, y2 = by - cut * uy;
  rule_choice d = g->dec[j];
  if (d == RULE_EITHER) {
    fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='#777777' stroke-width='3' "
               "stroke-dasharray='6 5'/>\n", x1, y1, x2, y2);
  } else {
    if (d == RULE_BD) {                     /* points at T_a: reverse */
      double t;
      t = x1; x1 = x2; x2 = t;
      t = y1; y1 = y2; y2 = t;
    }
    fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='#333333' stroke-width='3' "
               "marker-end='url(#arrow)'/>\n", x1, y1, x2, y2);
  }
  /* Label "Q_j: the chosen diagonal" (AC of Q_j is v_{j+1}v_{j+3}, BD is
  ** v_{j+2}v_{j+4}), inside the ring where there is room. */
  double mx = (ax + bx) / 2, my = (ay + by) / 2;
  double ox = mx - RFG_CX, oy = my - RFG_CY, ol = sqrt(ox * ox + oy * oy);
  double ix = -ox / ol, iy = -oy / ol;      /* unit vector towards the centre */
  double lx = mx + 12 * ix, ly = my + 12 * iy + 4;
  const char *anchor = ix > 0.3 ? "start" : ix < -0.3 ? "end" : "middle";
  if (d == RULE_EITHER)
    fprintf(f, "<text x='%.1f' y='%.1f' font-size='12' text-anchor='%s' fill='#444444'>"
               "Q%d: either</text>\n", lx, ly, anchor, j);
  else
    fprintf(f, "<text x='%.1f' y='%.1f' font-size='12' text-anchor='%s' fill='#444444'>"
               "Q%d: v%dv%d</text>\n", lx, ly, anchor, j, (j + 1 + (d == RULE_BD)) % 5,
            (j + 3 + (d == RULE_BD)) % 5);
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
    y += RFG_LINE;
    s += n;
    if (*s == '\n') s++;
  }
}

int report_flipgraph_svg(FILE *f, const flipgraph_pentagon *p, const flipgraph *g,
                         const char *caption) {
  int lines = 0;
  if (caption != NULL && *caption != '\0') {
    lines = 1;
    for (const char *c = caption; *c; c++) lines += *c == '\n';
  }
  double height = RFG_CY + RFG_RING + RFG_BOX / 2 + 40 + lines * RFG_LINE + 10;
  /* Sources (a bit mask): in = BD and out = AC (flipgraph.c's convention);
  ** type III has two. */
  int source = 0;
  for (int i = 0; i < 5; i++)
    if (g->dec[(i + 4) % 5] == RULE_BD && g->dec[(i + 1) % 5] == RULE_AC) source |= 1 << i;
  fprintf(f, "<?xml version='1.0' encoding='UTF-8'?>\n"
             "<svg xmlns='http://www.w3.org/2000/svg' width='%.0f' height='%.0f' "
             "viewBox='0 0 %.0f %.0f' font-family='sans-serif'>\n",
          RFG_W, height, RFG_W, height);
  fprintf(f, "<defs><marker id='arrow' viewBox='0 0 10 10' refX='9' refY='5' markerWidth='7' "
             "markerHeight='7' orient='auto-start-reverse'><path d='M0,0 L10,5 L0,10 z' "
             "fill='#333333'/></marker></defs>\n");
  fprintf(f, "<rect width='100%%' height='100%%' fill='white'/>\n");
  report_flipgraph_map m = report_flipgraph_fit(p->v);
  for (int k = 0; k < 5; k++) report_flipgraph_edge(f, g, k);
  for (int k = 0; k < 5; k++)
    report_flipgraph_tri(f, p, g, &m, report_flipgraph_cycle[k], source, k);
  fprintf(f, "<text x='%.1f' y='%.1f' font-size='13' text-anchor='middle' fill='#555555'>"
             "type %s</text>\n", RFG_CX, RFG_CY + 5, flipgraph_type_name(g->type));
  report_svg_caption(f, 12, RFG_CY + RFG_RING + RFG_BOX / 2 + 48, caption);
  fprintf(f, "</svg>\n");
  return ferror(f) ? -1 : 0;
}
