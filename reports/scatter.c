/*
** scatter.c: thesis figure 3.9 as a hand-written SVG: for every rule that
** produced no type-V graph, the % of type-I flip graphs (x) against the %
** whose sink is the Delaunay triangulation (y).  Since a DT count is a
** subset of the type-I count, every point lies on or below the diagonal;
** the legend sits in the empty upper-left triangle.
**
** Rules with identical counts land on one spot (the R_f rules all sit at
** (100, 100)): they are drawn as one larger circle whose hover title lists
** them all, white when their joints differ.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "joint.h"
#include "report_internal.h"

/* Legend entries: the joints (their colours live with them, in joints/),
** then quadrilateral rules such as DT, then groups mixing several of these.
** Only entries that some drawn circle uses appear in the legend. */
enum { REPORT_QUAD = JOINT_CAPACITY, REPORT_MIXED, REPORT_NKINDS };
#define REPORT_QUAD_COLOUR "#000000"
#define REPORT_MIXED_COLOUR "#FFFFFF"

/* Canvas and plot square, in pixels. */
enum { SVG_W = 640, SVG_H = 660, PX0 = 80, PY0 = 60, PSIZE = 520, PAD = 14 };

/* Pixel position of a percentage on the x and y axes running from lo to
** 100; PAD keeps the circles at 0 and 100 inside the frame. */
static double report_px(double v, double lo) {
  return PX0 + PAD + (v - lo) / (100 - lo) * (PSIZE - 2 * PAD);
}
static double report_py(double v, double lo) {
  return PY0 + PSIZE - PAD - (v - lo) / (100 - lo) * (PSIZE - 2 * PAD);
}

/* A row's legend entry: its joint, or REPORT_QUAD for a rule without one. */
static int report_kind(const char *joint) {
  int j = joint[0] ? joint_find(joint) : -1;
  return j >= 0 ? j : REPORT_QUAD;
}

static const char *report_kind_colour(int k) {
  return k < REPORT_QUAD ? joint_get((joint_id)k)->colour
       : k == REPORT_QUAD ? REPORT_QUAD_COLOUR : REPORT_MIXED_COLOUR;
}

typedef struct report_group {
  uint64_t i, dt;     /* the shared counts */
  int first, size;    /* first member (row index) and how many */
} report_group;

static int report_group_cmp(const void *a, const void *b) {
  const report_group *x = a, *y = b;
  return (y->size > x->size) - (y->size < x->size);
}

static double report_pc(uint64_t k, uint64_t n) {
  return n ? 100.0 * (double)k / (double)n : 0;
}

static void report_scatter_axes(FILE *f, double lo) {
  double step = (100 - lo) / 10 >= 5 ? 10 : ((100 - lo) > 20 ? 5 : 2);
  for (double t = lo; t <= 100 + 1e-9; t += step) {
    double x = report_px(t, lo), y = report_py(t, lo);
    fprintf(f, "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#e0e0e0\"/>\n",
            x, PY0, x, PY0 + PSIZE);
    fprintf(f, "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#e0e0e0\"/>\n",
            PX0, y, PX0 + PSIZE, y);
    fprintf(f, "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#000\"/>\n",
            x, PY0 + PSIZE, x, PY0 + PSIZE + 5);
    fprintf(f, "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#000\"/>\n",
            PX0 - 5, y, PX0, y);
    fprintf(f, "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%g</text>\n",
            x, PY0 + PSIZE + 19, t);
    fprintf(f, "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%g</text>\n",
            PX0 - 8, y + 4, t);
  }
  fprintf(f, "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" stroke=\"#000\"/>\n",
          PX0, PY0, PSIZE, PSIZE);
  /* The bound DT % <= type I %. */
  fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#888\" "
             "stroke-dasharray=\"6 4\"><title>DT %% = type I %%: the upper bound</title></line>\n",
          report_px(lo, lo), report_py(lo, lo), report_px(100, lo), report_py(100, lo));
  fprintf(f, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\" font-size=\"14\">"
             "type I flip graphs (%% of samples)</text>\n",
          PX0 + PSIZE / 2, PY0 + PSIZE + 44);
  fprintf(f, "<text transform=\"translate(%d %d) rotate(-90)\" text-anchor=\"middle\" "
             "font-size=\"14\">type I with the Delaunay sink (%% of samples)</text>\n",
          PX0 - 50, PY0 + PSIZE / 2);
}

/* The legend lists exactly the entries used[] marks (what was drawn). */
static void report_scatter_legend(FILE *f, const int used[REPORT_NKINDS]) {
  int x = PX0 + 14, y = PY0 + 16, n = 0;
  for (int k = 0; k < REPORT_NKINDS; k++) n += used[k] != 0;
  fprintf(f, "<rect x=\"%d\" y=\"%d\" width=\"230\" height=\"%d\" fill=\"#fff\" "
             "fill-opacity=\"0.9\" stroke=\"#bbb\"/>\n",
          x - 8, y - 12, 16 * n + 30);
  fprintf(f, "<text x=\"%d\" y=\"%d\" font-weight=\"bold\">joint</text>\n", x, y + 2);
  int yy = y + 18;
  for (int k = 0; k < REPORT_NKINDS; k++) {
    if (!used[k]) continue;
    fprintf(f, "<circle cx=\"%d\" cy=\"%d\" r=\"5\" fill=\"%s\" stroke=\"#333\"/>"
               "<text x=\"%d\" y=\"%d\">", x + 5, yy - 4, report_kind_colour(k), x + 16, yy);
    if (k < REPORT_QUAD)
      fprintf(f, "%s (%s)", joint_get((joint_id)k)->symbol, joint_get((joint_id)k)->word);
    else
      fputs(k == REPORT_QUAD ? "quadrilateral rule (DT)" : "several joints", f);
    fputs("</text>\n", f);
    yy += 16;
  }
  fprintf(f, "<text x=\"%d\" y=\"%d\" fill=\"#555\">larger circle: rules with equal counts</text>\n",
          x, yy + 2);
}

/* Draw one group; returns its legend entry. */
static int report_scatter_point(FILE *f, const report_row *rows, int nrows,
                            const report_group *g, double lo, uint64_t n) {
  int kind = report_kind(rows[g->first].joint);
  int shown = 0;
  for (int i = g->first; i < nrows && shown < g->size; i++) {
    if (rows[i].c.type[FLIPGRAPH_V] != 0 || rows[i].c.type[FLIPGRAPH_I] != g->i ||
        rows[i].c.dt != g->dt)
      continue;
    if (report_kind(rows[i].joint) != kind) kind = REPORT_MIXED;
    shown++;
  }
  const char *colour = report_kind_colour(kind);
  double px = report_px(report_pc(g->i, n), lo), py = report_py(report_pc(g->dt, n), lo);
  double r = 4.5 + 1.5 * sqrt((double)(g->size - 1));
  fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"%s\" fill-opacity=\"0.8\" "
             "stroke=\"#222\" stroke-width=\"%s\"><title>",
          px, py, r, colour, g->size > 1 ? "1.5" : "0.8");
  shown = 0;
  for (int i = g->first; i < nrows && shown < g->size; i++) {
    const flipgraph_counts *c = &rows[i].c;
    if (c->type[FLIPGRAPH_V] != 0 || c->type[FLIPGRAPH_I] != g->i || c->dt != g->dt) continue;
    if (shown++) fputc('\n', f);
    report_xml_text(f, rows[i].rule);
    fprintf(f, ": type I %.2f%%, DT %.2f%% (II %.2f%%, III %.2f%%)",
            report_pc(c->type[FLIPGRAPH_I], n), report_pc(c->dt, n),
            report_pc(c->type[FLIPGRAPH_II], n), report_pc(c->type[FLIPGRAPH_III], n));
  }
  fprintf(f, "</title></circle>\n");
  return kind;
}

int report_scatter_svg(FILE *f, const report_meta *m, const report_row *rows, int nrows) {
  report_group *g = malloc((size_t)(nrows > 0 ? nrows : 1) * sizeof *g);
  if (g == NULL) return -1;
  int ng = 0;
  uint64_t n = m->samples;
  double lo = 100;
  for (int i = 0; i < nrows; i++) {
    const flipgraph_counts *c = &rows[i].c;
    if (c->type[FLIPGRAPH_V] != 0) continue;
    int k = 0;
    while (k < ng && !(g[k].i == c->type[FLIPGRAPH_I] && g[k].dt == c->dt)) k++;
    if (k == ng) g[ng++] = (report_group){c->type[FLIPGRAPH_I], c->dt, i, 0};
    g[k].size++;
    double y = report_pc(c->dt, n);
    if (y < lo) lo = y;
  }
  /* Axis from a multiple of 10 below the lowest point (DT % <= type I %). */
  lo = floor(lo / 10) * 10;
  if (lo >= 100 || lo < 0) lo = lo >= 100 ? 90 : 0;
  qsort(g, (size_t)ng, sizeof *g, report_group_cmp);
  int nplot = 0;
  for (int k = 0; k < ng; k++) nplot += g[k].size;

  fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
             "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
             "viewBox=\"0 0 %d %d\" font-family=\"sans-serif\" font-size=\"12\">\n",
          SVG_W, SVG_H, SVG_W, SVG_H);
  fprintf(f, "<title>fliplab: type I against DT (thesis figure 3.9)</title>\n"
             "<rect width=\"%d\" height=\"%d\" fill=\"#fff\"/>\n", SVG_W, SVG_H);
  fprintf(f, "<text x=\"%d\" y=\"24\" text-anchor=\"middle\" font-size=\"16\" "
             "font-weight=\"bold\">Flip rules: type I against Delaunay sink</text>\n",
          SVG_W / 2);
  fprintf(f, "<text x=\"%d\" y=\"42\" text-anchor=\"middle\" fill=\"#444\">%llu samples",
          SVG_W / 2, (unsigned long long)n);
  if (m->has_seed) fprintf(f, ", seed %llu", (unsigned long long)m->seed);
  fprintf(f, "; %d rules without type-V graphs; hover a point for its rules</text>\n",
          nplot);
  report_scatter_axes(f, lo);
  int used[REPORT_NKINDS] = {0};
  for (int k = 0; k < ng; k++) used[report_scatter_point(f, rows, nrows, &g[k], lo, n)] = 1;
  report_scatter_legend(f, used);
  fprintf(f, "</svg>\n");
  free(g);
  return ferror(f) ? -1 : 0;
}
