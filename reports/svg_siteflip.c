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
#include "report_internal.h"

#define RSF_BOX 120.0          /* a triangulation's frame */
#define RSF_PIC 92.0           /* the sites' extent inside a frame */
#define RSF_GAPX 90.0
#define RSF_GAPY 50.0
#define RSF_MARGIN 40.0

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
  report_svg_flip(f, RSF_BOX, 6, 2.5, L->x[from], L->y[from], L->x[to], L->y[to],
                  d == RULE_EITHER);
}

/* The frames and tags of the triangulations (svg.c's one style). */
static const report_svg_node_style report_sf_style = {
  RSF_BOX, 9, 5, 2.5, "7 4", 13, 0, 15, 12, 5};

static void report_sf_node(FILE *f, const siteflip_graph *g, const report_sf_layout *L, int u,
                           report_svg_role role) {
  double cx = L->x[u], cy = L->y[u];
  report_svg_box b = report_svg_bbox(g->p, (size_t)g->n);   /* the sites, y up */
  double s = report_svg_fit_scale(&b, RSF_PIC), mx = (b.minx + b.maxx) / 2;
  double my = (b.miny + b.maxy) / 2;
  report_svg_node_frame(f, &report_sf_style, cx, cy, role);
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
  report_svg_node_tags(f, &report_sf_style, cx, cy, u + 1, role, u == g->delaunay);
}

int report_siteflip_svg(FILE *f, const siteflip_graph *g, const rule_choice *dec,
                        const char *caption) {
  if (g->nnodes > REPORT_SITEFLIP_SVG_MAX) return -2;
  report_sf_layout L;
  if (report_sf_layout_make(g, &L) != 0) return -1;
  double height = L.height + 20 + report_svg_caption_lines(caption) * REPORT_SVG_LINE;
  report_svg_graph_open(f, L.width, height);
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
  for (int u = 0; u < g->nnodes; u++)
    report_sf_node(f, g, &L, u, !out[u] ? REPORT_SVG_SINK
                                : !in[u] ? REPORT_SVG_SOURCE : REPORT_SVG_PLAIN);
  report_svg_caption(f, 12, L.height + 24, caption);
  fprintf(f, "</svg>\n");
  free(out);
  free(in);
  free(L.x);
  free(L.y);
  return ferror(f) ? -1 : 0;
}
