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

/* 1 when q lies strictly inside triangle abc of orientation o (+1 or -1), exactly (the
** coordinates obey the contract, checked by got_skel_build: geom_orient_valid). */
static int skel_in_triangle(geom_point a, geom_point b, geom_point c, geom_point q, int o) {
  return geom_orient_valid(a, b, q) == o && geom_orient_valid(b, c, q) == o &&
         geom_orient_valid(c, a, q) == o;
}

/* ---- candidate triangles ------------------------------------------------- */

/* The x-range of the triangle (x[k], y[k]) over the band ya <= y <= yb: its vertices in
** the band and its sides' crossings of the band's two lines.  A crossing is the side's
** start moved along its inverse slope sl[k] = dx / dy (computed once a triangle), within
** a few ulps of the coordinates' spread of its exact place, far below the padding
** SKEL_PAD of the callers.  (Plain selections rather than fmin and fmax, which are library
** calls: nothing here is NaN.) */
static void skel_band_x(const double *x, const double *y, const double *sl, double ya,
                        double yb, double *lo, double *hi) {
  *lo = INFINITY, *hi = -INFINITY;
  for (int k = 0; k < 3; k++) {
    double px = x[k], py = y[k], qy = y[k == 2 ? 0 : k + 1];
    if (py >= ya && py <= yb) *lo = px < *lo ? px : *lo, *hi = px > *hi ? px : *hi;
    for (int j = 0; j < 2; j++) {
      double yy = j ? yb : ya;
      if ((py - yy) * (qy - yy) < 0) {
        double xx = px + (yy - py) * sl[k];
        *lo = xx < *lo ? xx : *lo, *hi = xx > *hi ? xx : *hi;
      }
    }
  }
}

/* 1 when no point lies strictly inside triangle abc of orientation o (exact; the edges
** are candidates, so none lies on them).  Row by row of cells, only the cells of the
** triangle's x-range over the row's band (padded by SKEL_PAD: a point's cell is exact to
** that), each point first against the triangle's open box (which a vertex may pass, but
** no vertex is strictly inside).  Cost: the points of those cells. */
static int skel_empty(const skel *s, uint32_t a, uint32_t b, uint32_t c, int o) {
  const geom_point *p = s->p;
  const skel_grid *g = &s->g;
  double xa = geom_min3(p[a].x, p[b].x, p[c].x), xb = geom_max3(p[a].x, p[b].x, p[c].x);
  double ya = geom_min3(p[a].y, p[b].y, p[c].y), yb = geom_max3(p[a].y, p[b].y, p[c].y);
  double x[3] = {p[a].x - g->x0, p[b].x - g->x0, p[c].x - g->x0};
  double y[3] = {p[a].y - g->y0, p[b].y - g->y0, p[c].y - g->y0}, e = SKEL_PAD * g->h, lo, hi;
  double sl[3];
  for (int k = 0; k < 3; k++) {
    double dy = y[k == 2 ? 0 : k + 1] - y[k];
    sl[k] = dy != 0 ? (x[k == 2 ? 0 : k + 1] - x[k]) / dy : 0;
  }
  skel_box bx = skel_grid_box(g, xa, xb, ya, yb);
  for (int iy = bx.iy0; iy <= bx.iy1; iy++) {
    skel_band_x(x, y, sl, iy * g->h - e, (iy + 1) * g->h + e, &lo, &hi);
    if (lo > hi) continue;
    int ix0 = skel_cell(lo - e, g->inv, g->nx), ix1 = skel_cell(hi + e, g->inv, g->nx);
    size_t row = (size_t)iy * (size_t)g->nx;
    for (uint32_t k = g->off[row + (size_t)ix0]; k < g->off[row + (size_t)ix1 + 1]; k++) {
      geom_point pq = g->gp[k];
      if (pq.x <= xa || pq.x >= xb || pq.y <= ya || pq.y >= yb) continue;
      if (skel_in_triangle(p[a], p[b], p[c], pq, o)) return 0;
    }
  }
  return 1;
}

/* The candidate triangles with smallest vertex a, appended to out as two pairs: (edge ab,
** edge ac), (edge bc, 1 when c is left of ab): each neighbour c of a neighbour b > a of a,
** with c > b, that is a neighbour of a too (stamp[c] == a + 1, set here with the edge ac
** in stamp[n + c]), and empty.  Cost: the neighbours of a's neighbours, an emptiness test
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
      int o = geom_orient_valid(s->p[a], s->p[b], s->p[c]);
      if (o == 0 || !skel_empty(s, a, b, c, o)) continue;
      if (skel_vec_push(out, s->nbe[i], stamp[s->n + c]) != 0 ||
          skel_vec_push(out, s->nbe[k], o > 0) != 0)
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

/* Sorts v[0 .. n) ascending (dir 1) or descending (dir -1): insertion, for the few
** triangles of one edge. */
static void skel_sort_few(uint32_t *v, uint32_t n, int dir) {
  for (uint32_t i = 1; i < n; i++) {
    uint32_t x = v[i], j = i;
    for (; j > 0 && (dir > 0 ? v[j - 1] > x : v[j - 1] < x); j--) v[j] = v[j - 1];
    v[j] = x;
  }
}

/* The per-edge incidence (tinc: 2 t + side, the left ones ascending in [toff[e], tmid[e]),
** the right ones descending after), from the side bits left[t] (the third vertex is left
** of ab and of bc when abc turns anticlockwise, of ac when it turns clockwise).  Counted
** and placed in parallel with atomic counters, then each edge's lists sorted, so the
** result is the same for any thread count.  Cost: O(triangles), the sorts of a few each. */
static int skel_incidence(skel *s, const unsigned char *left) {
  s->toff = calloc(s->m + 1, sizeof *s->toff);
  s->tmid = malloc((s->m + 1) * sizeof *s->tmid);
  s->tinc = malloc(3 * s->nt * sizeof *s->tinc + 1);
  uint32_t *hi = malloc((s->m + 1) * sizeof *hi);
  if (!s->toff || !s->tmid || !s->tinc || !hi) return free(hi), -1;
  long long nt3 = 3 * (long long)s->nt, nt = (long long)s->nt, m = (long long)s->m;
#pragma omp parallel num_threads(s->threads)
  {
#pragma omp for schedule(static)
    for (long long t = 0; t < nt3; t++) {
#pragma omp atomic
      s->toff[s->te[t] + 1]++;
    }
#pragma omp single
    {
      for (size_t e = 0; e < s->m; e++) s->toff[e + 1] += s->toff[e];
      memcpy(s->tmid, s->toff, (s->m + 1) * sizeof *hi);
      memcpy(hi, s->toff + 1, s->m * sizeof *hi);
    }
#pragma omp for schedule(static)
    for (long long t = 0; t < nt; t++)
      for (int k = 0; k < 3; k++) {
        uint32_t e = s->te[3 * t + k], at, side = (k == 1) ^ left[t];
        if (side) {
#pragma omp atomic capture
          at = s->tmid[e]++;
        } else {
#pragma omp atomic capture
          at = --hi[e];
        }
        s->tinc[at] = (uint32_t)(2 * t) + side;
      }
#pragma omp for schedule(static, 4096)
    for (long long e = 0; e < m; e++) {
      skel_sort_few(s->tinc + s->toff[e], s->tmid[e] - s->toff[e], 1);
      skel_sort_few(s->tinc + s->tmid[e], s->toff[e + 1] - s->tmid[e], -1);
    }
  }
  free(hi);
  return 0;
}

/* Every candidate triangle's edges into s->te and its side bit into *left, found in
** parallel by blocks of points, each block copied at its offset (the same list for any
** thread count) and freed. */
static int skel_triangles_find(skel *s, unsigned char **left) {
  size_t nb = (s->n + SKEL_BLOCK - 1) / SKEL_BLOCK, *at = calloc(nb + 1, sizeof *at);
  skel_vec *part = calloc(nb, sizeof *part);
  int fail = !part || !at;
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
  for (size_t b = 0; part && at && b < nb; b++) at[b + 1] = at[b] + part[b].n / 2;
  s->nt = fail ? 0 : at[nb];
  s->te = fail ? NULL : malloc(3 * s->nt * sizeof *s->te + 1);
  *left = fail ? NULL : malloc(s->nt + 1);
#pragma omp parallel for schedule(dynamic, 1) num_threads(s->threads)
  for (long long b = 0; b < (long long)(part ? nb : 0); b++) {
    for (size_t k = 0, t = at ? at[b] : 0; k < part[b].n && s->te && *left; k += 2, t++) {
      const uint32_t *v = part[b].v + 2 * k;
      s->te[3 * t] = v[0], s->te[3 * t + 1] = v[1], s->te[3 * t + 2] = v[2];
      (*left)[t] = (unsigned char)v[3];
    }
    free(part[b].v);
  }
  free(part), free(at);
  return s->te && *left ? 0 : -1;
}

/* The candidate triangles, their edges, incidence and measures (a triangle's vertices
** a < b < c are the ends of its edges ab and ac). */
int skel_triangles(skel *s) {
  unsigned char *left = NULL;
  if (skel_triangles_find(s, &left) != 0) return free(left), -1;
  s->talive = malloc(s->nt + 1);
  if (!s->talive) return free(left), -1;
  memset(s->talive, 1, s->nt);
  if (s->kind == SKEL_CERTIFIED) {
    s->bad = malloc(s->nt * sizeof *s->bad + 1);
    if (!s->bad) return free(left), -1;
    for (size_t t = 0; t < s->nt; t++) {
      const uint32_t *ab = s->ev + 2 * s->te[3 * t], *ac = s->ev + 2 * s->te[3 * t + 1];
      s->bad[t] = s->mp(s->p[ab[0]], s->p[ab[1]], s->p[ac[1]]);
    }
  }
  int rc = skel_incidence(s, left);
  free(left);
  return rc;
}
