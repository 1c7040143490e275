/*
** svg_siteflip.c: the directed flip graph of a small site set as SVG, in
** the manner of thesis figures 3.7 and 3.8: each triangulation drawn small
** in its frame, an arrow on every flip pointing at the triangulation the
** rule prefers.
**
** Layout.  Column c holds the triangulations c flips away from
** triangulation 1 (breadth-first distance; the flip graph is connected),
** in index order from the top, so the drawing is deterministic and flips
** join neighbouring columns or run inside one.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"

#define RSF_BOX 120.0          /* a triangulation's frame */
#define RSF_PIC 92.0           /* the sites' extent inside a frame */
#define RSF_GAPX 90.0
#define RSF_GAPY 50.0
#define RSF_MARGIN 40.0
#define RSF_LINE 17.0

typedef struct report_sf_layout {
  double *x, *y;               /* frame centres */
  double width, height;
} report_sf_layout;

static int report_sf_layout_make(const siteflip_graph *g, report_sf_layout *L) {
  int n = g->nnodes;
  int *dist = malloc((size_t)n * sizeof *dist), *queue = malloc((size_t)n * sizeof *queue);
  int *row = calloc((size_t)n + 1, sizeof *row);
  L->x = malloc((size_t)n * sizeof *L->x);
  L->y = malloc((size_t)n * sizeof *L->y);
  if (!dist || !queue || !row || !L->x || !L->y) {
    free(dist);
    free(queue);
    free(row);
    return -1;
  }
  for (int u = 0; u < n; u++) dist[u] = -1;
  int head = 0, tail = 0, cols = 1, rows = 1;
  dist[0] = 0;
  queue[tail++] = 0;
  while (head < tail) {
    int u = queue[head++];
    for (int a = g->adj_off[u]; a < g->adj_off[u + 1]; a++) {
      const siteflip_edge *e = &g->edge[g->adj[a]];
      int w = e->ac == u ? e->bd : e->ac;
      if (dist[w] < 0) {
        dist[w] = dist[u] + 1;
        queue[tail++] = w;
      }
    }
  }
  for (int u = 0; u < n; u++) {
    int c = dist[u] < 0 ? 0 : dist[u];
    if (c + 1 > cols) cols = c + 1;
    L->x[u] = RSF_MARGIN + RSF_BOX / 2 + c * (RSF_BOX + RSF_GAPX);
    L->y[u] = RSF_MARGIN + 20 + RSF_BOX / 2 + row[c] * (RSF_BOX + RSF_GAPY);
    if (++row[c] > rows) rows = row[c];
  }
  L->width = 2 * RSF_MARGIN + cols * RSF_BOX + (cols - 1) * RSF_GAPX;
  L->height = RSF_MARGIN + 20 + rows * (RSF_BOX + RSF_GAPY);
  free(dist);
  free(queue);
  free(row);
  return 0;
}

static void report_sf_edge(FILE *f, const report_sf_layout *L, const siteflip_edge *e,
                           rule_choice d) {
  int from = d == RULE_AC ? e->bd : e->ac, to = d == RULE_AC ? e->ac : e->bd;
  double ax = L->x[from], ay = L->y[from], bx = L->x[to], by = L->y[to];
  double dx = bx - ax, dy = by - ay, len = sqrt(dx * dx + dy * dy);
  if (len <= 0) return;
  double ux = dx / len, uy = dy / len;
  double cut = (RSF_BOX / 2) / fmax(fabs(ux), fabs(uy)) + 6;
  if (2 * cut >= len) return;
  double x1 = ax + cut * ux, y1 = ay + cut * uy, x2 = bx - cut * ux, y2 = by - cut * uy;
  if (d == RULE_EITHER)
    fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='#777777' "
               "stroke-width='2.5' stroke-dasharray='6 5'/>\n", x1, y1, x2, y2);
  else
    fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='#333333' "
               "stroke-width='2.5' marker-end='url(#arrow)'/>\n", x1, y1, x2, y2);
}

/* Scale and centre of the sites inside a frame (y up). */
static void report_sf_fit(const siteflip_graph *g, double *s, double *mx, double *my) {
  double x0 = g->p[0].x, x1 = x0, y0 = g->p[0].y, y1 = y0;
  for (int i = 1; i < g->n; i++) {
    x0 = fmin(x0, g->p[i].x);
    x1 = fmax(x1, g->p[i].x);
    y0 = fmin(y0, g->p[i].y);
    y1 = fmax(y1, g->p[i].y);
  }
  double ext = fmax(x1 - x0, y1 - y0);
  *s = ext > 0 ? RSF_PIC / ext : 1;
  *mx = (x0 + x1) / 2;
  *my = (y0 + y1) / 2;
}

static void report_sf_node(FILE *f, const siteflip_graph *g, const report_sf_layout *L, int u,
                           int sink, int source) {
  double cx = L->x[u], cy = L->y[u], h = RSF_BOX / 2, s, mx, my;
  report_sf_fit(g, &s, &mx, &my);
  const char *frame = sink ? "stroke='#1a9850' stroke-width='5' fill='#e5f5e0'"
                    : source ? "stroke='#d73027' stroke-width='2.5' stroke-dasharray='7 4' fill='#fff5f0'"
                    : "stroke='#999999' stroke-width='1.2' fill='#ffffff'";
  fprintf(f, "<rect x='%.1f' y='%.1f' width='%.1f' height='%.1f' rx='9' %s/>\n", cx - h, cy - h,
          RSF_BOX, RSF_BOX, frame);
  for (int i = 0; i < g->n; i++)
    for (int j = i + 1; j < g->n; j++)
      if (siteflip_has_edge(g, u, i, j))
        fprintf(f, "<line x1='%.2f' y1='%.2f' x2='%.2f' y2='%.2f' stroke='#2166ac' "
                   "stroke-width='1.6'/>\n",
                cx + s * (g->p[i].x - mx), cy - s * (g->p[i].y - my), cx + s * (g->p[j].x - mx),
                cy - s * (g->p[j].y - my));
  for (int i = 0; i < g->n; i++)
    fprintf(f, "<circle cx='%.2f' cy='%.2f' r='2.6' fill='#222222'/>\n",
            cx + s * (g->p[i].x - mx), cy - s * (g->p[i].y - my));
  fprintf(f, "<text x='%.1f' y='%.1f' font-size='13' text-anchor='middle'>T%d</text>\n", cx,
          cy + h + 15, u + 1);
  const char *role = sink ? "sink" : source ? "source" : NULL;
  if (role != NULL)
    fprintf(f, "<text x='%.1f' y='%.1f' font-size='12' text-anchor='middle' fill='%s'>%s</text>\n",
            cx, cy - h - 5, sink ? "#1a9850" : "#d73027", role);
  if (u == g->delaunay)
    fprintf(f, "<text x='%.1f' y='%.1f' font-size='11' fill='#555555'>DT</text>\n", cx + h - 20,
            cy + h - 5);
}

int report_siteflip_svg(FILE *f, const siteflip_graph *g, const rule_choice *dec,
                        const char *caption) {
  if (g->nnodes > REPORT_SITEFLIP_SVG_MAX) return -2;
  report_sf_layout L;
  if (report_sf_layout_make(g, &L) != 0) return -1;
  int lines = 0;
  for (const char *c = caption; c != NULL && *c; c++) lines += *c == '\n';
  if (caption != NULL && *caption) lines++;
  double height = L.height + 20 + lines * RSF_LINE;
  fprintf(f, "<?xml version='1.0' encoding='UTF-8'?>\n"
             "<svg xmlns='http://www.w3.org/2000/svg' width='%.0f' height='%.0f' "
             "viewBox='0 0 %.0f %.0f' font-family='sans-serif'>\n",
          L.width, height, L.width, height);
  fprintf(f, "<defs><marker id='arrow' viewBox='0 0 10 10' refX='9' refY='5' markerWidth='7' "
             "markerHeight='7' orient='auto-start-reverse'><path d='M0,0 L10,5 L0,10 z' "
             "fill='#333333'/></marker></defs>\n<rect width='100%%' height='100%%' fill='white'/>\n");
  int *out = calloc((size_t)g->nnodes, sizeof *out), *in = calloc((size_t)g->nnodes, sizeof *in);
  if (out == NULL || in == NULL) {
    free(out);
    free(in);
    free(L.x);
    free(L.y);
    return -1;
  }
  for (int e = 0; e < g->nedges; e++) {
    rule_choice d = dec[g->edge[e].quad];
    report_sf_edge(f, &L, &g->edge[e], d);
    if (d == RULE_EITHER) continue;
    out[d == RULE_AC ? g->edge[e].bd : g->edge[e].ac] = 1;
    in[d == RULE_AC ? g->edge[e].ac : g->edge[e].bd] = 1;
  }
  for (int u = 0; u < g->nnodes; u++) report_sf_node(f, g, &L, u, !out[u], !in[u] && out[u]);
  report_svg_caption(f, 12, L.height + 24, caption);
  fprintf(f, "</svg>\n");
  free(out);
  free(in);
  free(L.x);
  free(L.y);
  return ferror(f) ? -1 : 0;
}
