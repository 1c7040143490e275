/*
** got_skel_grid.c: the skeleton's point grid (got/got_skel_internal.h): the cells, the
** cells a segment passes through (the certain edges' crossing test), and the growing
** edge arrays the searches fill.
*/
#include <math.h>
#include <stdlib.h>
#include "got_skel_internal.h"
#include "geom_key_internal.h"

/* The cell of point i (row-major), geom_csr_build's key over the grid and the points. */
typedef struct skel_grid_pts { const skel_grid *g; const geom_point *p; } skel_grid_pts;

static size_t skel_grid_key(const void *ctx, size_t i) {
  const skel_grid_pts *c = ctx;
  size_t ix = (size_t)skel_cellx(c->g, c->p[i].x), iy = (size_t)skel_celly(c->g, c->p[i].y);
  return iy * (size_t)c->g->nx + ix;
}

int skel_grid_build(skel_grid *g, const geom_point *p, size_t n) {
  g->x0 = g->x1 = p[0].x, g->y0 = g->y1 = p[0].y;
  for (size_t i = 1; i < n; i++) {
    g->x0 = fmin(g->x0, p[i].x), g->x1 = fmax(g->x1, p[i].x);
    g->y0 = fmin(g->y0, p[i].y), g->y1 = fmax(g->y1, p[i].y);
  }
  double w = g->x1 - g->x0, ht = g->y1 - g->y0, cap = 2.0 * (double)n + 4;
  g->h = sqrt(2.0 * fmax(w * ht, fmax(w, ht) * fmax(w, ht) / cap) / (double)n);
  g->inv = 1 / g->h;
  g->h = 1 / g->inv;
  g->nx = (int)fmin(cap, w * g->inv + 1);
  g->ny = (int)fmin(cap, ht * g->inv + 1);
  size_t cells = (size_t)g->nx * (size_t)g->ny;
  g->off = malloc((cells + 1) * sizeof *g->off);
  g->pt = malloc(n * sizeof *g->pt);
  g->gp = malloc(n * sizeof *g->gp);
  if (!g->off || !g->pt || !g->gp) return -1;
  geom_csr_build(g->off, cells, g->pt, n, skel_grid_key, &(skel_grid_pts){g, p});
  for (size_t k = 0; k < n; k++) g->gp[k] = p[g->pt[k]];
  return 0;
}

void skel_grid_free(skel_grid *g) {
  free(g->off);
  free(g->pt);
  free(g->gp);
  free(g->sect_lo);
  free(g->sect_n);
}

/* The cells segment ab passes through (padded: SKEL_PAD), line by line along its major
** axis: for each column (|dx| >= |dy|; rows otherwise) the range of the other coordinate
** over the column, in positions relative to the grid's corner.  With a slope of at most
** 1 in magnitude each end of that range is within a few ulps of the coordinates' spread,
** far below the padding.  visit(ctx, cell) for each. */

void skel_segment_cells(const skel_grid *g, geom_point a, geom_point b,
                               skel_cell_fn visit, void *ctx) {
  double u0 = a.x - g->x0, v0 = a.y - g->y0, u1 = b.x - g->x0, v1 = b.y - g->y0;
  int swap = fabs(v1 - v0) > fabs(u1 - u0), nu = swap ? g->ny : g->nx, nv = swap ? g->nx : g->ny;
  if (swap) {
    double t = u0;
    u0 = v0, v0 = t, t = u1, u1 = v1, v1 = t;
  }
  if (u1 < u0) {
    double t = u0;
    u0 = u1, u1 = t, t = v0, v0 = v1, v1 = t;
  }
  double e = SKEL_PAD * g->h, slope = u1 > u0 ? (v1 - v0) / (u1 - u0) : 0;
  int i0 = skel_cell(u0 - e, g->inv, nu), i1 = skel_cell(u1 + e, g->inv, nu);
  for (int i = i0; i <= i1; i++) {
    double ul = fmax(u0, i * g->h), ur = fmin(u1, (i + 1) * g->h);
    double va = v0 + (ul - u0) * slope, vb = v0 + (ur - u0) * slope;
    if (ul > ur) va = vb = ul > u1 ? v1 : v0;
    int j0 = skel_cell(fmin(va, vb) - e, g->inv, nv), j1 = skel_cell(fmax(va, vb) + e, g->inv, nv);
    for (int j = j0; j <= j1; j++)
      visit(ctx, swap ? (size_t)i * (size_t)g->nx + (size_t)j
                      : (size_t)j * (size_t)g->nx + (size_t)i);
  }
}
