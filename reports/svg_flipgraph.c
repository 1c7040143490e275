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
#include "report_internal.h"

#define RFG_W 720.0
#define RFG_CX 360.0
#define RFG_CY 340.0
#define RFG_RING 250.0          /* radius of the ring of slots */
#define RFG_BOX 140.0           /* side of a slot's frame */
#define RFG_PIC 106.0           /* the pentagon's extent inside a frame */

static const int report_flipgraph_cycle[5] = {0, 2, 4, 1, 3};

static void report_flipgraph_slot(int k, double *x, double *y) {
  double th = -M_PI / 2 + 2 * M_PI * k / 5;
  *x = RFG_CX + RFG_RING * cos(th);
  *y = RFG_CY + RFG_RING * sin(th);
}

/* Map pentagon coordinates into a picture centred at (cx, cy); y up. */
typedef struct report_flipgraph_map { double s, mx, my; } report_flipgraph_map;

static report_flipgraph_map report_flipgraph_fit(const geom_point v[5]) {
  report_svg_box b = report_svg_bbox(v, 5);
  report_flipgraph_map m = {report_svg_fit_scale(&b, RFG_PIC), (b.minx + b.maxx) / 2,
                            (b.miny + b.maxy) / 2};
  return m;
}

/* The frames and tags of the five triangulations (svg.c's one style). */
static const report_svg_node_style report_flipgraph_style = {
  RFG_BOX, 10, 6, 3, "8 5", 16, 1, 18, 13, 6};

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
  report_svg_role role = sink ? REPORT_SVG_SINK
                       : (source >> i & 1) ? REPORT_SVG_SOURCE : REPORT_SVG_PLAIN;
  report_svg_node_frame(f, &report_flipgraph_style, cx, cy, role);
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
  report_svg_node_tags(f, &report_flipgraph_style, cx, cy, i, role, i == p->delaunay_sink);
}

/* The cycle edge from slot k to slot k+1, directed by Q_j. */
static void report_flipgraph_edge(FILE *f, const flipgraph *g, int k) {
  int a = report_flipgraph_cycle[k];       /* next slot holds T_{a+2} */
  int j = (a + 1) % 5;                      /* so Q_{a+1} decides the edge */
  double ax, ay, bx, by;
  report_flipgraph_slot(k, &ax, &ay);
  report_flipgraph_slot((k + 1) % 5, &bx, &by);
  rule_choice d = g->dec[j];
  if (d == RULE_BD)                         /* points at T_a */
    report_svg_flip(f, RFG_BOX, 8, 3, bx, by, ax, ay, 0);
  else
    report_svg_flip(f, RFG_BOX, 8, 3, ax, ay, bx, by, d == RULE_EITHER);
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

int report_flipgraph_svg(FILE *f, const flipgraph_pentagon *p, const flipgraph *g,
                         const char *caption) {
  double height = RFG_CY + RFG_RING + RFG_BOX / 2 + 40 +
                  report_svg_caption_lines(caption) * REPORT_SVG_LINE + 10;
  /* Sources (a bit mask): in = BD and out = AC (flipgraph.c's convention);
  ** type III has two. */
  int source = 0;
  for (int i = 0; i < 5; i++)
    if (g->dec[(i + 4) % 5] == RULE_BD && g->dec[(i + 1) % 5] == RULE_AC) source |= 1 << i;
  report_svg_graph_open(f, RFG_W, height);
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
