/*
** got_skel_tri.c: the skeleton's candidate triangles (got/got_skel_internal.h): every
** empty triangle whose three edges are candidates, found from pairs of neighbours in the
** candidate graph, its emptiness tested exactly on the grid; and each edge's triangles on
** either side.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "got_skel_internal.h"

/* 1 when q lies strictly inside triangle abc of orientation o (+1 or -1), exactly. */
static int skel_in_triangle(geom_point a, geom_point b, geom_point c, geom_point q, int o) {
  return geom_orient(a, b, q) == o && geom_orient(b, c, q) == o && geom_orient(c, a, q) == o;
}

/* ---- candidate triangles ------------------------------------------------- */

/* The x-range of the triangle (x[k], y[k]) over the band ya <= y <= yb: its vertices in
** the band and its sides' crossings of the band's two lines.  A crossing is interpolated
** between the side's ends (t in [0, 1]), within a few ulps of the coordinates' spread of
** its exact place, far below the padding SKEL_PAD of the callers. */
static void skel_band_x(const double *x, const double *y, double ya, double yb, double *lo,
                        double *hi) {
  *lo = INFINITY, *hi = -INFINITY;
  for (int k = 0; k < 3; k++) {
    double px = x[k], py = y[k], qx = x[(k + 1) % 3], qy = y[(k + 1) % 3];
    if (py >= ya && py <= yb) *lo = fmin(*lo, px), *hi = fmax(*hi, px);
    for (int j = 0; j < 2; j++) {
      double yy = j ? yb : ya;
      if ((py - yy) * (qy - yy) < 0) {
        double xx = px + (yy - py) / (qy - py) * (qx - px);
        *lo = fmin(*lo, xx), *hi = fmax(*hi, xx);
      }
    }
  }
}

/* 1 when no point lies strictly inside triangle abc of orientation o (exact; the edges
** are candidates, so none lies on them).  Row by row of cells, only the cells of the
** triangle's x-range over the row's band (padded by SKEL_PAD: a point's cell is exact to
** that), each point first against the triangle's box.  Cost: the points of those cells. */
static int skel_empty(const skel *s, uint32_t a, uint32_t b, uint32_t c, int o) {
  const geom_point *p = s->p;
  const skel_grid *g = &s->g;
  double xa = geom_min3(p[a].x, p[b].x, p[c].x), xb = geom_max3(p[a].x, p[b].x, p[c].x);
  double ya = geom_min3(p[a].y, p[b].y, p[c].y), yb = geom_max3(p[a].y, p[b].y, p[c].y);
  double x[3] = {p[a].x - g->x0, p[b].x - g->x0, p[c].x - g->x0};
  double y[3] = {p[a].y - g->y0, p[b].y - g->y0, p[c].y - g->y0}, e = SKEL_PAD * g->h, lo, hi;
  skel_box bx = skel_grid_box(g, xa, xb, ya, yb);
  for (int iy = bx.iy0; iy <= bx.iy1; iy++) {
    skel_band_x(x, y, iy * g->h - e, (iy + 1) * g->h + e, &lo, &hi);
    if (lo > hi) continue;
    int ix0 = skel_cell(lo - e, g->inv, g->nx), ix1 = skel_cell(hi + e, g->inv, g->nx);
    size_t row = (size_t)iy * (size_t)g->nx;
    for (uint32_t k = g->off[row + (size_t)ix0]; k < g->off[row + (size_t)ix1 + 1]; k++) {
      uint32_t q = g->pt[k];
      geom_point pq = g->gp[k];
      if (q == a || q == b || q == c || pq.x <= xa || pq.x >= xb || pq.y <= ya || pq.y >= yb)
        continue;
      if (skel_in_triangle(p[a], p[b], p[c], pq, o)) return 0;
    }
  }
  return 1;
}

/* The candidate triangles with smallest vertex a, appended to out as three pairs: (a, b),
** (c, edge ab), (edge ac, edge bc): each neighbour c of a neighbour b > a of a, with c > b,
** that is a neighbour of a too (stamp[c] == a + 1, set here with the edge ac in
** stamp[n + c]), and empty.  Cost: the neighbours of a's neighbours, an emptiness test
** (the points of a box) for each triangle. */
static int skel_triangles_at(const skel *s, uint32_t a, uint32_t *stamp, skel_vec *out) {
  uint32_t lo = s->off[a], hi = s->off[a + 1];
  for (uint32_t i = lo; i < hi; i++) stamp[s->nbr[i]] = a + 1, stamp[s->n + s->nbr[i]] = s->nbe[i];
  while (lo < hi && s->nbr[lo] < a) lo++;
  for (uint32_t i = lo; i < hi; i++) {
    uint32_t b = s->nbr[i], k = s->off[b + 1];
    while (k > s->off[b] && s->nbr[k - 1] > b) k--;
    for (; k < s->off[b + 1]; k++) {
      uint32_t c = s->nbr[k];
      if (stamp[c] != a + 1) continue;
      int o = geom_orient(s->p[a], s->p[b], s->p[c]);
      if (o == 0 || !skel_empty(s, a, b, c, o)) continue;
      if (skel_vec_push(out, a, b) != 0 || skel_vec_push(out, c, s->nbe[i]) != 0 ||
          skel_vec_push(out, stamp[s->n + c], s->nbe[k]) != 0)
        return -1;
    }
  }
  return 0;
}

/* The candidate triangles of points [a0, a1), in order. */
static int skel_triangles_block(const skel *s, size_t a0, size_t a1, uint32_t *stamp,
                                skel_vec *out) {
  for (size_t a = a0; a < a1; a++)
    if (skel_triangles_at(s, (uint32_t)a, stamp, out) != 0) return -1;
  return 0;
}

/* Fills tv, te, the per-edge incidence (tinc: 2 t + side) and the measures. */
static int skel_incidence(skel *s) {
  s->toff = calloc(s->m + 1, sizeof *s->toff);
  s->tmid = malloc((s->m + 1) * sizeof *s->tmid);
  s->tinc = malloc(3 * s->nt * sizeof *s->tinc + 1);
  uint32_t *hi = malloc((s->m + 1) * sizeof *hi);
  if (!s->toff || !s->tmid || !s->tinc || !hi) return free(hi), -1;
  for (size_t t = 0; t < 3 * s->nt; t++) s->toff[s->te[t] + 1]++;
  for (size_t e = 0; e < s->m; e++) s->toff[e + 1] += s->toff[e];
  memcpy(s->tmid, s->toff, (s->m + 1) * sizeof *hi);
  memcpy(hi, s->toff + 1, s->m * sizeof *hi);
  for (size_t t = 0; t < s->nt; t++) {
    const uint32_t *v = s->tv + 3 * t;
    int o = geom_orient(s->p[v[0]], s->p[v[1]], s->p[v[2]]);
    /* the third vertex is left of ab and of bc when o > 0, of ac when o < 0 */
    int side[3] = {o > 0, o < 0, o > 0};
    for (int k = 0; k < 3; k++) {
      uint32_t e = s->te[3 * t + k];
      s->tinc[side[k] ? s->tmid[e]++ : --hi[e]] = (uint32_t)(2 * t) + side[k];
    }
  }
  free(hi);
  return 0;
}

/* Every candidate triangle into s->tv and its edges into s->te, found in parallel by
** blocks of points joined in order (the same list for any thread count), each block freed
** once copied. */
static int skel_triangles_find(skel *s) {
  size_t nb = (s->n + SKEL_BLOCK - 1) / SKEL_BLOCK;
  skel_vec *part = calloc(nb, sizeof *part);
  int fail = !part;
#pragma omp parallel num_threads(s->threads) reduction(| : fail)
  {
    uint32_t *stamp = calloc(2 * s->n, sizeof *stamp);
    fail |= stamp == NULL;
#pragma omp for schedule(dynamic, 1)
    for (long long b = 0; b < (long long)nb; b++)
      if (!fail)
        fail |= skel_triangles_block(s, (size_t)b * SKEL_BLOCK,
                                     fmin((double)s->n, (double)(b + 1) * SKEL_BLOCK), stamp,
                                     &part[b]) != 0;
    free(stamp);
  }
  s->nt = 0;
  for (size_t b = 0; part && b < nb; b++) s->nt += part[b].n / 3;
  s->tv = fail ? NULL : malloc(3 * s->nt * sizeof *s->tv + 1);
  s->te = fail ? NULL : malloc(3 * s->nt * sizeof *s->te + 1);
  for (size_t b = 0, t = 0; part && b < nb; b++) {
    for (size_t k = 0; k < part[b].n && s->tv && s->te; k += 3, t++) {
      const uint32_t *v = part[b].v + 2 * k;
      s->tv[3 * t] = v[0], s->tv[3 * t + 1] = v[1], s->tv[3 * t + 2] = v[2];
      s->te[3 * t] = v[3], s->te[3 * t + 1] = v[4], s->te[3 * t + 2] = v[5];
    }
    free(part[b].v);
  }
  free(part);
  return s->tv && s->te ? 0 : -1;
}

/* The candidate triangles, their edges, incidence and measures. */
int skel_triangles(skel *s) {
  if (skel_triangles_find(s) != 0) return -1;
  s->talive = malloc(s->nt + 1);
  if (!s->talive) return -1;
  memset(s->talive, 1, s->nt);
  if (s->kind == SKEL_CERTIFIED) {
    s->bad = malloc(s->nt * sizeof *s->bad + 1);
    if (!s->bad) return -1;
    for (size_t t = 0; t < s->nt; t++)
      s->bad[t] = s->mp(s->p[s->tv[3 * t]], s->p[s->tv[3 * t + 1]], s->p[s->tv[3 * t + 2]]);
  }
  return skel_incidence(s);
}
