/*
** got_skel.c: the skeleton of a point set's GOT for a sum rule (got/got_skel.h; docs/got.md,
** "Point sets: the skeleton"): candidate edges, the LMT-skeleton loop, the certain edges.
**
** 1. Candidates.  P_1 (the minimum-weight triangulation): the diamond test on a uniform grid
**    (skel_diamond_point: a ring search bounded by sectors, far rings read by the open
**    sectors' arcs, pairs tried on the points seen before the full test); every other sum
**    rule: every segment through no third point, for n <= GOT_SKEL_ALL_MAX (no exclusion
**    is proven for them).  P_1 works on the points renumbered in the grid's cell order
**    (skel_renumber), mapped back at the output.
** 2. Candidate triangles: every empty triangle whose three edges are candidates, found from
**    pairs of neighbours in the candidate graph, emptiness tested exactly on the grid.
** 3. LMT loop, in rounds: an edge that is not a hull edge stays only while some pair of live
**    candidate triangles, one on each side, makes it locally optimal (skel_witness); when it
**    goes, its triangles go, and the other edges of those triangles are examined again in
**    the next round.  Each round decides every queued edge against the state at its start,
**    so the result is the same whatever the thread count; the final set is the largest
**    fixed point whatever the order (removal is monotone).
** 4. Certain edges: live edges that cross no other live edge (a segment grid), and the hull.
**
** Soundness (docs/got.md has the argument): every GOT of a sum rule is weakly locally
** optimal, so its own triangles witness its edges in every round; an edge is removed only
** when the flip is certainly a strict improvement: exact squared lengths for P_1
** (geom_dist2_cmp), else the certified key error model of got_cert.c and the rule's own tie
** tolerance together.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "measure.h"
#include "got_internal.h"
#include "got_skel.h"

/* Largest n for the rules without a candidate exclusion (all pairs are candidates). */
#define GOT_SKEL_ALL_MAX 200

#define SKEL_U 0x1p-53

/* ---- the point grid ------------------------------------------------------ */

/* Points bucketed into square cells of side h (about two points a cell), cell
** (ix, iy) holding pt[off[iy * nx + ix] .. off[iy * nx + ix + 1]) in ascending order,
** with their coordinates alongside in gp (the scans read points cell by cell: in memory
** order rather than scattered over the input).
** Positions are taken relative to the lower left corner (x0, y0), so rounding errors
** scale with the spread of the points, not their distance from the origin: a cell
** coordinate (x - x0) / h below 2^31 is computed with two roundings, within 2^-21 cells
** of its exact value, so a query pads its range by SKEL_PAD = 4e-6 cells, which covers
** the rounding of both the query and the points. */
#define SKEL_PAD 4e-6
typedef struct skel_grid {
  double x0, y0, x1, y1, h, inv;   /* the bounding box, the cell side and its inverse */
  int nx, ny;
  uint32_t *off, *pt;
  geom_point *gp;                   /* gp[k] = p[pt[k]] */
  unsigned char *sect_lo, *sect_n;  /* per cell offset: sectors it can meet (diamond search) */
} skel_grid;

static int skel_cell(double v, double inv, int cap) {
  double c = v * inv;
  if (!(c > 0)) return 0;
  return c >= cap - 1 ? cap - 1 : (int)c;
}

static int skel_cellx(const skel_grid *g, double x) { return skel_cell(x - g->x0, g->inv, g->nx); }
static int skel_celly(const skel_grid *g, double y) { return skel_cell(y - g->y0, g->inv, g->ny); }

static int skel_grid_build(skel_grid *g, const geom_point *p, size_t n) {
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
  g->off = calloc(cells + 1, sizeof *g->off);
  g->pt = malloc(n * sizeof *g->pt);
  g->gp = malloc(n * sizeof *g->gp);
  if (!g->off || !g->pt || !g->gp) return -1;
  for (size_t i = 0; i < n; i++)
    g->off[(size_t)skel_celly(g, p[i].y) * (size_t)g->nx + (size_t)skel_cellx(g, p[i].x) + 1]++;
  for (size_t c = 0; c < cells; c++) g->off[c + 1] += g->off[c];
  uint32_t *fill = malloc(cells * sizeof *fill);
  if (!fill) return -1;
  memcpy(fill, g->off, cells * sizeof *fill);
  for (size_t i = 0; i < n; i++)
    g->pt[fill[(size_t)skel_celly(g, p[i].y) * (size_t)g->nx + (size_t)skel_cellx(g, p[i].x)]++] =
        (uint32_t)i;
  for (size_t k = 0; k < n; k++) g->gp[k] = p[g->pt[k]];
  free(fill);
  return 0;
}

static void skel_grid_free(skel_grid *g) {
  free(g->off);
  free(g->pt);
  free(g->gp);
  free(g->sect_lo);
  free(g->sect_n);
}

/* The cells that can hold a point of the box [xa, xb] x [ya, yb] (padded: SKEL_PAD). */
typedef struct skel_box { int ix0, ix1, iy0, iy1; } skel_box;

static skel_box skel_grid_box(const skel_grid *g, double xa, double xb, double ya, double yb) {
  double e = SKEL_PAD * g->h;
  skel_box r = {skel_cell((xa - g->x0) - e, g->inv, g->nx),
                skel_cell((xb - g->x0) + e, g->inv, g->nx),
                skel_cell((ya - g->y0) - e, g->inv, g->ny),
                skel_cell((yb - g->y0) + e, g->inv, g->ny)};
  return r;
}

/* ---- predicates ---------------------------------------------------------- */

/* 1 when q lies on the open segment ab (exact). */
static int skel_on_segment(geom_point a, geom_point b, geom_point q) {
  return geom_orient(a, b, q) == 0 && geom_ahead(a, b, q) && geom_ahead(b, a, q);
}

/* 1 when q certainly lies strictly inside the isosceles triangle on base ab, on the side
** `side` (+1 left of a->b, -1 right), with base angles pi/8 (the diamond test's region).
** Inside means: q strictly on that side, and its angles at a and at b both below pi/8,
** i.e. 0 < side * cross < tan(pi/8) dot at both ends (cross = twice the area, the same at
** both ends; dot = (b - a).(q - a) at a, (a - b).(q - b) at b).  Each of these is a
** determinant of degree 2 in rounded differences, within (3 + 16u) u (|l| + |r|) of its
** exact value (Shewchuk's bound, as geom_orient's filter); the test uses the worst end of
** each interval, and T below tan(pi/8) = 0.41421356237..., so a 1 is certain.  A 0 may
** be wrong: that only keeps an edge, which is safe. */
#define SKEL_TAN8 0.414213562
static int skel_in_cone(geom_point a, geom_point b, geom_point q, int side) {
  double ux = b.x - a.x, uy = b.y - a.y, vx = q.x - a.x, vy = q.y - a.y;
  double wx = q.x - b.x, wy = q.y - b.y, k = (3 + 16 * SKEL_U) * SKEL_U;
  double l = ux * vy, r = uy * vx, cr = side * (l - r), ecr = k * (fabs(l) + fabs(r));
  double da = ux * vx + uy * vy, eda = k * (fabs(ux * vx) + fabs(uy * vy));
  double db = -(ux * wx + uy * wy), edb = k * (fabs(ux * wx) + fabs(uy * wy));
  double hi = (cr + ecr) * (1 + 0x1p-40);
  return cr - ecr > 0 && hi < SKEL_TAN8 * (da - eda) && hi < SKEL_TAN8 * (db - edb);
}

/* 1 when q lies strictly inside triangle abc of orientation o (+1 or -1), exactly. */
static int skel_in_triangle(geom_point a, geom_point b, geom_point c, geom_point q, int o) {
  return geom_orient(a, b, q) == o && geom_orient(b, c, q) == o && geom_orient(c, a, q) == o;
}

/* ---- candidate edges ----------------------------------------------------- */

/* A growing array of edges (a, b), a < b, 2 entries each. */
typedef struct skel_vec { uint32_t *v; size_t n, cap; } skel_vec;

static int skel_vec_push(skel_vec *s, uint32_t a, uint32_t b) {
  if (s->n == s->cap) {
    size_t cap = s->cap ? 2 * s->cap : 64;
    uint32_t *v = realloc(s->v, 2 * cap * sizeof *v);
    if (!v) return -1;
    s->v = v, s->cap = cap;
  }
  s->v[2 * s->n] = a, s->v[2 * s->n + 1] = b;
  s->n++;
  return 0;
}

/* Is ab an edge candidate?  0 when a third point lies on the open segment, or, with
** diamond = 1, when both diamond triangles on ab hold a point (Das and Joseph: an edge of
** a minimum-weight triangulation has an empty isosceles triangle with base angles pi/8 on
** at least one side; skel_in_cone errs only towards keeping).  Every point of either
** triangle or of the segment lies in the box of a, b and the apexes, which stand at
** tan(pi/8) / 2 < 0.21 of |ab| from the midpoint.  Cost: the points of the padded box. */
static int skel_edge_ok(const skel_grid *g, uint32_t a, geom_point pa, uint32_t b,
                        geom_point pb, int diamond) {
  double ex = diamond ? 0.21 * fabs(pb.y - pa.y) : 0;
  double ey = diamond ? 0.21 * fabs(pb.x - pa.x) : 0;
  double xa = fmin(pa.x, pb.x) - ex, xb = fmax(pa.x, pb.x) + ex;
  double ya = fmin(pa.y, pb.y) - ey, yb = fmax(pa.y, pb.y) + ey;
  skel_box bx = skel_grid_box(g, xa, xb, ya, yb);
  int left = 0, right = 0;
  for (int iy = bx.iy0; iy <= bx.iy1; iy++)
    for (int ix = bx.ix0; ix <= bx.ix1; ix++) {
      size_t c = (size_t)iy * (size_t)g->nx + (size_t)ix;
      for (uint32_t k = g->off[c]; k < g->off[c + 1]; k++) {
        uint32_t q = g->pt[k];
        geom_point pq = g->gp[k];
        if (q == a || q == b || pq.x < xa || pq.x > xb || pq.y < ya || pq.y > yb) continue;
        if (skel_on_segment(pa, pb, pq)) return 0;
        if (diamond) {
          left |= skel_in_cone(pa, pb, pq, 1);
          right |= skel_in_cone(pa, pb, pq, -1);
          if (left && right) return 0;
        }
      }
    }
  return 1;
}

/* The far-edge argument of the diamond search.  A point q at distance r from a, at an
** angle delta in (0, pi/8) anticlockwise from the direction of b, lies strictly inside
** the left diamond triangle of ab whenever |ab| > r f(delta), f(delta) = cos(delta) +
** sin(delta) / tan(pi/8): its angle at a is delta, and its angle at b has tangent
** r sin(delta) / (|ab| - r cos(delta)) < tan(pi/8).  The same clockwise for the right
** triangle.  Directions fall into SKEL_SECT sectors of w = pi/64 (skel_sector, whose
** rounding is far below a sector): for b in sector t, a point of sector t+k, k = 2 .. 6,
** has delta in ((k - 1) w, (k + 1) w), inside (0, pi/8) with a sector to spare, and f
** grows on it, so f((k + 1) w) = SKEL_FK[k] bounds it (1.34 for k = 2 to 1.75 for k = 6;
** the same for t-k on the right).  With dmin[s] the distance of the nearest point seen in
** sector s, every edge ab of sector t fails the diamond test when |ab| >= far[t] =
** max(min over k of dmin[t+k] SKEL_FK[k], min over k of dmin[t-k] SKEL_FK[k]), with a
** relative margin of 1e-6, far above the rounding of distances and f, so that the point
** is inside by more than skel_in_cone's tolerance and the full test drops the pair too. */
#define SKEL_SECT 128
#define SKEL_WIN 64       /* cell offsets with a table of the sectors they can meet */

/* A point q seen from a: its sector, distance, ring and coordinates. */
typedef struct skel_seen { uint32_t q; int sect; double d; geom_point pt; int ring; } skel_seen;

/* The scratch of one search (one per thread), with the directions of the sectors'
** boundaries: sector t holds the angles from t w - pi to (t + 1) w - pi, w = 2 pi / 128. */
typedef struct skel_search {
  skel_seen *seen;
  size_t ns, cap;
  double dmin[SKEL_SECT], far[SKEL_SECT], reach[SKEL_SECT];
  unsigned char done[SKEL_SECT];
  int open[SKEL_SECT], nopen;       /* the sectors not done, ascending */
  double bx[SKEL_SECT], by[SKEL_SECT], fk[7];   /* fk: the far argument's factors */
  uint32_t *stamp, tick;            /* ring places visited (skel_ring_arcs), by tick */
  size_t stcap;
  uint32_t *sidx, scap;             /* the seen points by sector (skel_seen_fails) */
  uint32_t soff[SKEL_SECT + 1];
} skel_search;

static void skel_search_init(skel_search *z) {
  for (int t = 0; t < SKEL_SECT; t++) {
    double th = t * (2 * M_PI / SKEL_SECT) - M_PI;
    z->bx[t] = cos(th), z->by[t] = sin(th);
  }
  for (int k = 2; k <= 6; k++) {
    double d = (k + 1) * (2 * M_PI / SKEL_SECT);
    z->fk[k] = cos(d) + sin(d) / tan(M_PI / 8);
  }
}

/* The sector of direction (dx, dy) != 0: the lower half plane holds sectors 0 .. 63, the
** upper one 64 .. 127, and within a half the boundaries are in anticlockwise order, so a
** binary search with cross products finds the last boundary at or before the direction.
** The boundaries' rounding moves them by about 1e-16 rad, far inside the margins of the
** far argument (a sector's neighbours at two sectors' distance). */
static int skel_sector(const skel_search *z, double dx, double dy) {
  int lo = dy < 0 || (dy == 0 && dx < 0) ? 0 : SKEL_SECT / 2, hi = lo + SKEL_SECT / 2 - 1;
  while (lo < hi) {
    int mid = (lo + hi + 1) / 2;
    if (z->bx[mid] * dy - z->by[mid] * dx >= 0) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

static void skel_far_update(skel_search *z) {
  for (int j = 0; j < z->nopen; j++) {
    int t = z->open[j];
    double l = INFINITY, r = INFINITY;
    for (int k = 2; k <= 6; k++) {
      double x = z->dmin[(t + k) % SKEL_SECT] * z->fk[k];
      double y = z->dmin[(t + SKEL_SECT - k) % SKEL_SECT] * z->fk[k];
      l = x < l ? x : l, r = y < r ? y : r;
    }
    z->far[t] = (l > r ? l : r) * (1 + 1e-6);
  }
}

/* The sectors a point of the cell at offset (dx, dy) from a's cell can lie in, a at any
** place of its cell: the angles of the corners of [dx - 1, dx + 1] x [dy - 1, dy + 1]
** (cell units) from the origin, padded by a sector; all of them for the cells around a.
** Written as the first sector and a count into the grid's table. */
static void skel_offset_sectors(int dx, int dy, unsigned char *lo, unsigned char *cnt) {
  if (abs(dx) <= 1 && abs(dy) <= 1) {
    *lo = 0, *cnt = SKEL_SECT;
    return;
  }
  double ref = atan2(dy, dx), dl = 0, dh = 0, w = 2 * M_PI / SKEL_SECT;
  for (int k = 0; k < 4; k++) {
    double d = atan2(dy + (k & 1 ? 1 : -1), dx + (k & 2 ? 1 : -1)) - ref;
    d = d > M_PI ? d - 2 * M_PI : d < -M_PI ? d + 2 * M_PI : d;
    dl = fmin(dl, d), dh = fmax(dh, d);
  }
  int t0 = (int)floor((ref + dl + M_PI) / w) - 1, t1 = (int)floor((ref + dh + M_PI) / w) + 1;
  *lo = (unsigned char)((t0 + SKEL_SECT) % SKEL_SECT);
  *cnt = (unsigned char)(t1 - t0 + 1 > SKEL_SECT ? SKEL_SECT : t1 - t0 + 1);
}

static int skel_offset_table(skel_grid *g) {
  size_t w = 2 * SKEL_WIN + 1;
  g->sect_lo = malloc(w * w);
  g->sect_n = malloc(w * w);
  if (!g->sect_lo || !g->sect_n) return -1;
  for (int dy = -SKEL_WIN; dy <= SKEL_WIN; dy++)
    for (int dx = -SKEL_WIN; dx <= SKEL_WIN; dx++) {
      size_t o = (size_t)(dy + SKEL_WIN) * w + (size_t)(dx + SKEL_WIN);
      skel_offset_sectors(dx, dy, &g->sect_lo[o], &g->sect_n[o]);
    }
  return 0;
}

/* How far from a the points of sector t can be: the farthest point of the bounding box
** within the sector's cone (widened by 1e-9 rad), which is a corner of the box inside the
** cone or where one of the cone's two boundary rays leaves the box; plus a relative 1e-9
** for rounding.  Only points near the boundary of the set ask. */
static double skel_exit(const skel_grid *g, geom_point a, double th) {
  double ux = cos(th), uy = sin(th), rx = INFINITY, ry = INFINITY;
  if (ux > 0) rx = (g->x1 - a.x) / ux;
  if (ux < 0) rx = (g->x0 - a.x) / ux;
  if (uy > 0) ry = (g->y1 - a.y) / uy;
  if (uy < 0) ry = (g->y0 - a.y) / uy;
  return fmin(rx, ry);
}

static double skel_reach(const skel_grid *g, geom_point a, int t) {
  double w = 2 * M_PI / SKEL_SECT, th0 = t * w - M_PI - 1e-9, th1 = (t + 1) * w - M_PI + 1e-9;
  double far = fmax(skel_exit(g, a, th0), skel_exit(g, a, th1));
  const double cx[4] = {g->x0, g->x1, g->x0, g->x1}, cy[4] = {g->y0, g->y0, g->y1, g->y1};
  for (int k = 0; k < 4; k++) {
    double dx = cx[k] - a.x, dy = cy[k] - a.y, th = atan2(dy, dx);
    if (th < th0) th += 2 * M_PI;
    if (th <= th1) far = fmax(far, sqrt(dx * dx + dy * dy));
  }
  return far * (1 + 1e-9);
}

/* Before ring k (cells at Chebyshev offset k from a's cell): every point not yet seen
** lies at least r = (k - 1 - 2 SKEL_PAD) h from a (cells are exact to SKEL_PAD).
** Sector t is done when every edge of it longer than r fails (far) or no
** point of it is that far (skel_reach); the search ends when every sector is done or
** the rings have covered the grid.  1: ended. */
static int skel_search_done(const skel_grid *g, geom_point a, skel_search *z, int k) {
  if (k - 1 >= g->nx && k - 1 >= g->ny) return 1;
  if (k < 2) return 0;
  double r = (k - 1 - 2 * SKEL_PAD) * g->h;
  /* a sector reaches at least as far as the nearest side of the box: no need to ask
  ** skel_reach (four atan2) before r gets there */
  double side = fmin(fmin(a.x - g->x0, g->x1 - a.x), fmin(a.y - g->y0, g->y1 - a.y));
  int open = 0;
  for (int j = 0; j < z->nopen; j++) {
    int t = z->open[j];
    if (!(z->far[t] <= r) && r >= side && isnan(z->reach[t])) z->reach[t] = skel_reach(g, a, t);
    z->done[t] = z->far[t] <= r || z->reach[t] <= r;
    if (!z->done[t]) z->open[open++] = t;
  }
  z->nopen = open;
  return open == 0;
}

/* 1 when no point of the cell at offset (dx, dy) can end an edge that passes: each of
** its sectors is done, or its far distance is below the cell's nearest possible point. */
static int skel_cell_dead(const skel_grid *g, const skel_search *z, int dx, int dy) {
  if (g->sect_lo == NULL || abs(dx) > SKEL_WIN || abs(dy) > SKEL_WIN) return 0;
  size_t o = (size_t)(dy + SKEL_WIN) * (2 * SKEL_WIN + 1) + (size_t)(dx + SKEL_WIN);
  int ax = abs(dx) - 1, ay = abs(dy) - 1;
  ax = ax < 0 ? 0 : ax, ay = ay < 0 ? 0 : ay;
  double mind = (sqrt((double)(ax * ax + ay * ay)) - 2 * SKEL_PAD) * g->h;
  for (int k = 0; k < g->sect_n[o]; k++) {
    int t = (g->sect_lo[o] + k) % SKEL_SECT;
    if (!z->done[t] && !(z->far[t] <= mind)) return 0;
  }
  return 1;
}

static int skel_seen_push(skel_search *z, skel_seen v) {
  if (z->ns == z->cap) {
    size_t nc = z->cap ? 2 * z->cap : 256;
    skel_seen *s = realloc(z->seen, nc * sizeof *s);
    if (!s) return -1;
    z->seen = s, z->cap = nc;
  }
  z->seen[z->ns++] = v;
  return 0;
}

/* Adds the points of cell (ix, iy) of ring k to the search. */
static int skel_cell_take(const skel_grid *g, geom_point pa, uint32_t a, size_t c, int k,
                          skel_search *z) {
  for (uint32_t j = g->off[c]; j < g->off[c + 1]; j++) {
    uint32_t q = g->pt[j];
    if (q == a) continue;
    double dx = g->gp[j].x - pa.x, dy = g->gp[j].y - pa.y, d = sqrt(dx * dx + dy * dy);
    int t = skel_sector(z, dx, dy);
    if (skel_seen_push(z, (skel_seen){q, t, d, g->gp[j], k}) != 0) return -1;
    z->dmin[t] = d < z->dmin[t] ? d : z->dmin[t];
  }
  return 0;
}

/* Ring k (cells at Chebyshev offset k >= 1 from a's) by places 0 .. 8k - 1, anticlockwise
** from offset (-k, 0), the direction -pi where sector 0 starts: seen from any point of
** a's cell the places are in the order of their directions. */
static int skel_ring_place(int dx, int dy, int k) {
  if (dx == -k && dy <= 0) return -dy;
  if (dy == -k) return 2 * k + dx;
  if (dx == k) return 4 * k + dy;
  if (dy == k) return 6 * k - dx;
  return 8 * k - dy;
}

static void skel_ring_offset(int i, int k, int *dx, int *dy) {
  if (i <= k) *dx = -k, *dy = -i;
  else if (i <= 3 * k) *dx = i - 2 * k, *dy = -k;
  else if (i <= 5 * k) *dx = k, *dy = i - 4 * k;
  else if (i <= 7 * k) *dx = 6 * k - i, *dy = k;
  else *dx = -k, *dy = 8 * k - i;
}

/* The place on ring k of the cell where the ray from a in direction (c, s) crosses the
** square of half-side k cells around the centre of a's cell ((fx, fy): a's offset from
** that centre, in cells). */
static int skel_ray_place(double c, double s, double fx, double fy, int k) {
  double rx = c > 0 ? (k - fx) / c : c < 0 ? (-k - fx) / c : INFINITY;
  double ry = s > 0 ? (k - fy) / s : s < 0 ? (-k - fy) / s : INFINITY;
  double v = rx <= ry ? fy + rx * s : fx + ry * c;
  int w = (int)floor(fmin(fmax(v + 0.5, -k), k));
  if (rx <= ry) return skel_ring_place(c > 0 ? k : -k, w, k);
  return skel_ring_place(w, s > 0 ? k : -k, k);
}

/* Ring k by the cells that meet the open sectors: for each, the places between its two
** boundary rays, padded by SKEL_ARC_PAD places, each place once (stamps).  Why the pad
** suffices: a ray crosses the ring's band (one cell wide) within 1.6 cells of its
** crossing of the middle square, so within 3 places of that crossing's cell (4 pads it
** for cells' and sectors' rounding).  Cost: the open sectors times (k w sqrt 2 + 9)
** places, against 8k for the whole ring (w = 2 pi / 128). */
#define SKEL_ARC_PAD 4
static int skel_ring_arcs(const skel_grid *g, geom_point pa, uint32_t a, int cx, int cy, int k,
                          skel_search *z) {
  int len = 8 * k;
  if ((size_t)len > z->stcap) {
    uint32_t *st = realloc(z->stamp, 2 * (size_t)len * sizeof *st);
    if (!st) return -1;
    memset(st, 0, 2 * (size_t)len * sizeof *st);
    z->stamp = st, z->stcap = 2 * (size_t)len, z->tick = 0;
  }
  if (++z->tick == 0) memset(z->stamp, 0, z->stcap * sizeof *z->stamp), z->tick = 1;
  double fx = (pa.x - g->x0) * g->inv - (cx + 0.5), fy = (pa.y - g->y0) * g->inv - (cy + 0.5);
  for (int j = 0; j < z->nopen; j++) {
    int t = z->open[j], u = (t + 1) % SKEL_SECT;
    int i0 = skel_ray_place(z->bx[t], z->by[t], fx, fy, k);
    int i1 = skel_ray_place(z->bx[u], z->by[u], fx, fy, k);
    int span = (i1 - i0 + len) % len + 2 * SKEL_ARC_PAD + 1;
    span = span > len ? len : span;
    for (int v = 0; v < span; v++) {
      int i = ((i0 - SKEL_ARC_PAD + v) % len + len) % len, dx, dy;
      if (z->stamp[i] == z->tick) continue;
      z->stamp[i] = z->tick;
      skel_ring_offset(i, k, &dx, &dy);
      int ix = cx + dx, iy = cy + dy;
      if (ix < 0 || ix >= g->nx || iy < 0 || iy >= g->ny || skel_cell_dead(g, z, dx, dy)) continue;
      if (skel_cell_take(g, pa, a, (size_t)iy * (size_t)g->nx + (size_t)ix, k, z) != 0) return -1;
    }
  }
  return 0;
}

/* Adds the points of the live cells of ring k to the search: by arcs when the open sectors
** need fewer places than the ring has, else the whole ring. */
static int skel_ring(const skel_grid *g, const geom_point *p, uint32_t a, int k,
                     skel_search *z) {
  int cx = skel_cellx(g, p[a].x), cy = skel_celly(g, p[a].y);
  if (k >= 2 && z->nopen * (0.11 * k + 2 * SKEL_ARC_PAD + 2) < 8.0 * k) {
    if (skel_ring_arcs(g, p[a], a, cx, cy, k, z) != 0) return -1;
    skel_far_update(z);
    return 0;
  }
  for (int iy = cy - k; iy <= cy + k; iy++) {
    if (iy < 0 || iy >= g->ny) continue;
    int step = (iy == cy - k || iy == cy + k || k == 0) ? 1 : 2 * k;
    for (int ix = cx - k; ix <= cx + k; ix += step) {
      if (ix < 0 || ix >= g->nx || skel_cell_dead(g, z, ix - cx, iy - cy)) continue;
      if (skel_cell_take(g, p[a], a, (size_t)iy * (size_t)g->nx + (size_t)ix, k, z) != 0)
        return -1;
    }
  }
  skel_far_update(z);
  return 0;
}

static int skel_cmp_seen(const void *x, const void *y) {
  uint32_t a = ((const skel_seen *)x)->q, b = ((const skel_seen *)y)->q;
  return (a > b) - (a < b);
}

/* The seen points by sector, each sector's in the order seen (ring by ring): sidx[soff[t]
** .. soff[t + 1]).  A counting sort: O(seen + sectors). */
static int skel_seen_sectors(skel_search *z) {
  if (z->ns > z->scap) {
    uint32_t *v = realloc(z->sidx, 2 * z->ns * sizeof *v);
    if (!v) return -1;
    z->sidx = v, z->scap = (uint32_t)(2 * z->ns);
  }
  memset(z->soff, 0, sizeof z->soff);
  for (size_t i = 0; i < z->ns; i++) z->soff[z->seen[i].sect + 1]++;
  for (int t = 0; t < SKEL_SECT; t++) z->soff[t + 1] += z->soff[t];
  uint32_t fill[SKEL_SECT];
  memcpy(fill, z->soff, sizeof fill);
  for (size_t i = 0; i < z->ns; i++) z->sidx[fill[z->seen[i].sect]++] = (uint32_t)i;
  return 0;
}

/* 1 when the points seen around a prove that pair ab (b = z->seen[ib]) fails the diamond
** test: a point certainly inside each diamond triangle (skel_in_cone, the pair's ends in
** the order P, Q that skel_edge_ok gets, so this drops only pairs that skel_edge_ok
** drops).  A triangle's directions from a are within pi/8 (8 sectors) of b's, so only the
** 19 sectors around b's are read, nearest first; both triangles lie within |ab| /
** cos(pi/8) < 1.09 |ab| of a, and points of ring k are at least (k - 1) h away, so each
** sector is read up to ring 1.09 |ab| / h + 2.  Cost: those points, until both sides hold
** one. */
static int skel_seen_fails(const skel_search *z, size_t ib, geom_point P, geom_point Q,
                           double h) {
  const skel_seen *b = &z->seen[ib];
  double kmax = 1.09 * b->d / h + 2;
  int left = 0, right = 0;
  for (int k = 0; k <= 18; k++) {
    int t = (b->sect + (k & 1 ? (k + 1) / 2 : SKEL_SECT - k / 2)) % SKEL_SECT;
    for (uint32_t j = z->soff[t]; j < z->soff[t + 1]; j++) {
      const skel_seen *q = &z->seen[z->sidx[j]];
      if (q->ring > kmax) break;
      if (z->sidx[j] == ib) continue;
      left |= skel_in_cone(P, Q, q->pt, 1);
      right |= skel_in_cone(P, Q, q->pt, -1);
      if (left && right) return 1;
    }
  }
  return 0;
}

/* The diamond candidates (a, b), b > a, into out, ascending in b.  The test of a pair is
** run with its ends in input order (orig: the input index of each point, or NULL), so
** its rounding, and the candidates, do not depend on the internal numbering.  The pairs
** the sectors leave are queued behind the seen points, sorted, tried on the seen points
** (skel_seen_fails), and the survivors get the full test.  Cost: the live cells around a
** (about a hundred points for uniform points), and for each pair left the seen points
** near a until the diamond holds a point on both sides, or the points of its box. */
static int skel_diamond_point(const skel_grid *g, const geom_point *p, const uint32_t *orig,
                              uint32_t a, skel_search *z, skel_vec *out) {
  z->ns = 0;
  for (int t = 0; t < SKEL_SECT; t++)
    z->dmin[t] = z->far[t] = INFINITY, z->reach[t] = NAN, z->done[t] = 0, z->open[t] = t;
  z->nopen = SKEL_SECT;
  for (int k = 0; !skel_search_done(g, p[a], z, k); k++)
    if (skel_ring(g, p, a, k, z) != 0) return -1;
  size_t ns = z->ns;
  for (size_t i = 0; i < ns; i++)
    if (z->seen[i].q > a && !(z->far[z->seen[i].sect] <= z->seen[i].d)) {
      skel_seen v = z->seen[i];
      v.ring = (int)i;                      /* its place among the seen points */
      if (skel_seen_push(z, v) != 0) return -1;
    }
  size_t m = z->ns - ns;
  skel_seen *pair = z->seen + ns;
  qsort(pair, m, sizeof *pair, skel_cmp_seen);
  z->ns = ns;
  if (skel_seen_sectors(z) != 0) return -1;
  for (size_t i = 0; i < m; i++) {
    uint32_t b = pair[i].q;
    int fwd = orig == NULL || orig[a] < orig[b];
    geom_point P = fwd ? p[a] : p[b], Q = fwd ? p[b] : p[a];
    if (skel_seen_fails(z, (size_t)pair[i].ring, P, Q, g->h)) continue;
    int ok = fwd ? skel_edge_ok(g, a, p[a], b, p[b], 1) : skel_edge_ok(g, b, p[b], a, p[a], 1);
    if (ok && skel_vec_push(out, a, b) != 0) return -1;
  }
  return 0;
}

/* ---- the candidate graph ------------------------------------------------- */

/* How a flip is decided (chosen once, skel_decider). */
typedef enum skel_kind {
  SKEL_EXACT_LENGTH,    /* P_1: exact squared lengths of the diagonals */
  SKEL_CERTIFIED,       /* a key error model (got_cert_model) and the tie tolerance */
  SKEL_NEVER            /* no model: no flip is certain, no edge leaves */
} skel_kind;

typedef struct skel {
  const geom_point *p;
  size_t n, m;             /* points, candidate edges */
  uint32_t *ev;            /* 2 per edge (a, b), a < b, ascending */
  uint32_t *off, *nbr, *nbe;   /* neighbours of each point, ascending, with edge ids */
  size_t nt;               /* candidate triangles */
  uint32_t *tv, *te;       /* 3 per triangle: a < b < c, and edges ab, ac, bc */
  double *bad;             /* the measure of each triangle (SKEL_CERTIFIED) */
  uint32_t *toff, *tinc;   /* per edge its triangles, 2 t + (1: third vertex on the left) */
  uint32_t *tmid;          /* ... the left ones in [toff[e], tmid[e]), the right ones after */
  unsigned char *ealive, *hull, *talive;
  uint32_t *wit;           /* 2 per edge: the last witness pair, or UINT32_MAX */
  uint32_t *hpair;         /* 2 per hull edge (a < b) */
  size_t nh;
  skel_grid g;
  uint32_t *orig;          /* P_1: the input index of each point (skel_renumber), else NULL */
  geom_point *q;           /* ... and the points in that order (s->p == q) */
  skel_kind kind;
  const rule *r;
  measure_points_fn mp;
  double rho, alpha;
  int threads;
} skel;

static void skel_free_all(skel *s) {
  free(s->ev), free(s->off), free(s->nbr), free(s->nbe);
  free(s->tv), free(s->te), free(s->bad), free(s->toff), free(s->tinc), free(s->tmid);
  free(s->ealive), free(s->hull), free(s->talive), free(s->wit), free(s->hpair);
  skel_grid_free(&s->g);
  free(s->orig), free(s->q);
}

/* The adjacency of the sorted edge list: pushing edges in order leaves every list
** ascending (neighbours below v come from edges (u, v), all before the edges (v, w)). */
static int skel_adjacency(skel *s) {
  s->off = calloc(s->n + 1, sizeof *s->off);
  s->nbr = malloc(2 * s->m * sizeof *s->nbr + 1);
  s->nbe = malloc(2 * s->m * sizeof *s->nbe + 1);
  uint32_t *fill = malloc((s->n + 1) * sizeof *fill);
  if (!s->off || !s->nbr || !s->nbe || !fill) return free(fill), -1;
  for (size_t e = 0; e < s->m; e++) s->off[s->ev[2 * e] + 1]++, s->off[s->ev[2 * e + 1] + 1]++;
  for (size_t v = 0; v < s->n; v++) s->off[v + 1] += s->off[v];
  memcpy(fill, s->off, (s->n + 1) * sizeof *fill);
  for (size_t e = 0; e < s->m; e++) {
    uint32_t a = s->ev[2 * e], b = s->ev[2 * e + 1];
    s->nbr[fill[a]] = b, s->nbe[fill[a]++] = (uint32_t)e;
    s->nbr[fill[b]] = a, s->nbe[fill[b]++] = (uint32_t)e;
  }
  free(fill);
  return 0;
}

/* The id of edge uv, or UINT32_MAX when it is no candidate (binary search). */
static uint32_t skel_edge_find(const skel *s, uint32_t u, uint32_t v) {
  uint32_t lo = s->off[u], hi = s->off[u + 1];
  while (lo < hi) {
    uint32_t mid = lo + (hi - lo) / 2;
    if (s->nbr[mid] < v) lo = mid + 1;
    else hi = mid;
  }
  return lo < s->off[u + 1] && s->nbr[lo] == v ? s->nbe[lo] : UINT32_MAX;
}

/* The candidates of points [a0, a1) into out: diamond = 1 the diamond test (P_1), else
** every clear segment. */
static int skel_candidates_block(const skel *s, size_t a0, size_t a1, int diamond,
                                 skel_search *z, skel_vec *out) {
  for (size_t a = a0; a < a1; a++) {
    if (diamond) {
      if (skel_diamond_point(&s->g, s->p, s->orig, (uint32_t)a, z, out) != 0) return -1;
      continue;
    }
    for (size_t b = a + 1; b < s->n; b++)
      if (skel_edge_ok(&s->g, (uint32_t)a, s->p[a], (uint32_t)b, s->p[b], 0) &&
          skel_vec_push(out, (uint32_t)a, (uint32_t)b) != 0)
        return -1;
  }
  return 0;
}

/* The candidate edges, ascending.  Points are searched in parallel in blocks of
** SKEL_BLOCK, each block's edges kept in order and the blocks joined in order, so the
** list is the same for any thread count. */
#define SKEL_BLOCK 4096
static int skel_candidates(skel *s, int diamond) {
  size_t nb = (s->n + SKEL_BLOCK - 1) / SKEL_BLOCK, total = 0;
  skel_vec *part = calloc(nb, sizeof *part);
  /* the table costs 4 atan2 for each of its 16641 offsets: worth it for 512 points up */
  int fail = !part || (diamond && s->n >= 512 && skel_offset_table(&s->g) != 0);
#pragma omp parallel num_threads(s->threads) reduction(| : fail)
  {
    skel_search z = {0};
    skel_search_init(&z);
#pragma omp for schedule(dynamic, 1)
    for (long long b = 0; b < (long long)nb; b++)
      if (!fail)
        fail |= skel_candidates_block(s, (size_t)b * SKEL_BLOCK,
                                      fmin((double)s->n, (double)(b + 1) * SKEL_BLOCK), diamond,
                                      &z, &part[b]) != 0;
    free(z.seen), free(z.stamp), free(z.sidx);
  }
  for (size_t b = 0; part && b < nb; b++) total += part[b].n;
  s->ev = fail ? NULL : malloc(2 * total * sizeof *s->ev + 1);
  for (size_t b = 0, k = 0; part && b < nb; k += part[b].n, b++) {
    if (s->ev) memcpy(s->ev + 2 * k, part[b].v, 2 * part[b].n * sizeof *s->ev);
    free(part[b].v);
  }
  free(part);
  s->m = total;
  return s->ev ? 0 : -1;
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
static int skel_triangles(skel *s) {
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

/* ---- the LMT loop -------------------------------------------------------- */

/* 1 when flipping ab to cd certainly lowers the total (c left of ab, d right, the
** quadrilateral a d b c strictly convex); t1 = abc and t2 = abd are candidate triangles.
** SKEL_CERTIFIED: with keys k^ within rho |k^| + alpha of the exact keys (got_cert.c),
** D = (k1 + k2) - (k3 + k4) rounded three times is within 3.01 u S of the sum of the
** computed keys (S = sum |k^|), so the exact difference exceeds D - E with E = (rho +
** 3.01 u) S + 4 alpha: D > E proves it positive.  The rule's own decision must agree
** (a strict preference beyond its tie tolerance), so what the rule calls a tie is kept. */
static int skel_flip_better(const skel *s, uint32_t a, uint32_t b, uint32_t c, uint32_t d,
                            uint32_t t1, uint32_t t2) {
  const geom_point *p = s->p;
  switch (s->kind) {
    case SKEL_EXACT_LENGTH:
      return geom_dist2_cmp(p[c], p[d], p[a], p[b]) < 0;
    case SKEL_CERTIFIED: {
      double x1 = s->bad[t1], y1 = s->bad[t2];
      double x2 = s->mp(p[a], p[d], p[c]), y2 = s->mp(p[d], p[b], p[c]);
      double k1 = rule_key(s->r, x1), k2 = rule_key(s->r, y1);
      double k3 = rule_key(s->r, x2), k4 = rule_key(s->r, y2);
      double D = (k1 + k2) - (k3 + k4), S = fabs(k1) + fabs(k2) + fabs(k3) + fabs(k4);
      double E = ((s->rho + 3.01 * SKEL_U) * S + 4 * s->alpha) * (1 + 0x1p-40);
      return D > E && rule_decide(s->r, x1, y1, x2, y2) == RULE_BD;
    }
    case SKEL_NEVER:
      return 0;
  }
  return 0;
}

/* 1 when triangles t1 (third vertex c, left of ab) and t2 (d, right) keep edge e = ab:
** the quadrilateral is not strictly convex, or the flip is not certainly better. */
static int skel_pair_keeps(const skel *s, uint32_t e, uint32_t t1, uint32_t t2) {
  uint32_t a = s->ev[2 * e], b = s->ev[2 * e + 1];
  const uint32_t *v1 = s->tv + 3 * t1, *v2 = s->tv + 3 * t2;
  uint32_t c = v1[0] + v1[1] + v1[2] - a - b, d = v2[0] + v2[1] + v2[2] - a - b;
  const geom_point *p = s->p;
  if (geom_orient(p[c], p[d], p[a]) * geom_orient(p[c], p[d], p[b]) >= 0) return 1;
  return !skel_flip_better(s, a, b, c, d, t1, t2);
}

/* Has edge e a witness pair among the live triangles?  The last pair found is tried
** first; then every live left triangle against every live right one.  Cost: the product
** of the two counts at worst. */
static int skel_witness(skel *s, uint32_t e) {
  uint32_t *w = s->wit + 2 * e;
  if (w[0] != UINT32_MAX && s->talive[w[0]] && s->talive[w[1]]) return 1;
  for (uint32_t i = s->toff[e]; i < s->tmid[e]; i++) {
    uint32_t ti = s->tinc[i] >> 1;
    if (!s->talive[ti]) continue;
    for (uint32_t j = s->tmid[e]; j < s->toff[e + 1]; j++) {
      uint32_t tj = s->tinc[j] >> 1;
      if (s->talive[tj] && skel_pair_keeps(s, e, ti, tj)) {
        w[0] = ti, w[1] = tj;
        return 1;
      }
    }
  }
  return 0;
}

/* The next round's queue: the live edges (not hull edges) of the triangles that edge e's
** removal kills, each once (flag). */
static void skel_remove(skel *s, uint32_t e, uint32_t *next, size_t *nn, unsigned char *flag) {
  s->ealive[e] = 0;
  for (uint32_t i = s->toff[e]; i < s->toff[e + 1]; i++) {
    uint32_t t = s->tinc[i] >> 1;
    if (!s->talive[t]) continue;
    s->talive[t] = 0;
    for (int k = 0; k < 3; k++) {
      uint32_t f = s->te[3 * t + k];
      if (f != e && s->ealive[f] && !s->hull[f] && !flag[f]) flag[f] = 1, next[(*nn)++] = f;
    }
  }
}

/* The LMT loop in rounds (Jacobi: every queued edge is judged against the state at the
** start of its round, in parallel, then the losers are removed in queue order).  Cost per
** round: the witness searches of the queued edges. */
static int skel_lmt(skel *s, size_t *rounds) {
  uint32_t *W = malloc(s->m * sizeof *W + 1), *next = malloc(s->m * sizeof *next + 1);
  unsigned char *keep = malloc(s->m + 1), *flag = calloc(s->m + 1, 1);
  if (!W || !next || !keep || !flag) return free(W), free(next), free(keep), free(flag), -1;
  size_t nw = 0;
  for (size_t e = 0; e < s->m; e++)
    if (!s->hull[e]) W[nw++] = (uint32_t)e;
  *rounds = 0;
  while (nw > 0) {
    ++*rounds;
    long long nwl = (long long)nw;
#pragma omp parallel for schedule(dynamic, 256) num_threads(s->threads)
    for (long long i = 0; i < nwl; i++)
      keep[i] = !s->ealive[W[i]] || skel_witness(s, W[i]);
    size_t nn = 0;
    for (size_t i = 0; i < nw; i++)
      if (!keep[i]) skel_remove(s, W[i], next, &nn, flag);
    for (size_t i = 0; i < nn; i++) flag[next[i]] = 0;
    uint32_t *t = W;
    W = next, next = t, nw = nn;
  }
  free(W), free(next), free(keep), free(flag);
  return 0;
}

/* ---- certain edges ------------------------------------------------------- */

/* The cells segment ab passes through (padded: SKEL_PAD), line by line along its major
** axis: for each column (|dx| >= |dy|; rows otherwise) the range of the other coordinate
** over the column, in positions relative to the grid's corner.  With a slope of at most
** 1 in magnitude each end of that range is within a few ulps of the coordinates' spread,
** far below the padding.  visit(ctx, cell) for each. */
typedef void (*skel_cell_fn)(void *ctx, size_t cell);

static void skel_segment_cells(const skel_grid *g, geom_point a, geom_point b,
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

typedef struct skel_cells { uint32_t *off, *list; uint32_t cur; int fill; } skel_cells;

static void skel_cells_visit(void *ctx, size_t cell) {
  skel_cells *c = ctx;
  if (c->fill) c->list[c->off[cell]++] = c->cur;
  else c->off[cell + 1]++;
}

/* 1 when segments e and f (no common endpoint) cross (exact). */
static int skel_cross(const skel *s, uint32_t e, uint32_t f) {
  const geom_point *p = s->p;
  uint32_t a = s->ev[2 * e], b = s->ev[2 * e + 1], c = s->ev[2 * f], d = s->ev[2 * f + 1];
  if (a == c || a == d || b == c || b == d) return 0;
  return geom_orient(p[a], p[b], p[c]) * geom_orient(p[a], p[b], p[d]) < 0 &&
         geom_orient(p[c], p[d], p[a]) * geom_orient(p[c], p[d], p[b]) < 0;
}

typedef struct skel_probe {
  const skel *s;
  const uint32_t *start, *list;
  uint32_t e;
  int crossed;
} skel_probe;

static void skel_probe_visit(void *ctx, size_t cell) {
  skel_probe *q = ctx;
  for (uint32_t k = q->start[cell]; k < q->start[cell + 1] && !q->crossed; k++)
    q->crossed = q->list[k] != q->e && skel_cross(q->s, q->e, q->list[k]);
}

/* cert[e] = 1 for the live edges no other live edge crosses (hull edges included): two
** crossing segments share the cell of their crossing point, which both visit.  Cost:
** the cells of each edge, and the edges of those cells until a crossing is found. */
static int skel_certain(const skel *s, unsigned char *cert) {
  size_t cells = (size_t)s->g.nx * (size_t)s->g.ny;
  skel_cells c = {calloc(cells + 1, sizeof(uint32_t)), NULL, 0, 0};
  uint32_t *start = malloc((cells + 1) * sizeof *start);
  if (!c.off || !start) return free(c.off), free(start), -1;
  for (size_t e = 0; e < s->m; e++)
    if (s->ealive[e])
      c.cur = (uint32_t)e,
      skel_segment_cells(&s->g, s->p[s->ev[2 * e]], s->p[s->ev[2 * e + 1]], skel_cells_visit, &c);
  for (size_t k = 0; k < cells; k++) c.off[k + 1] += c.off[k];
  memcpy(start, c.off, (cells + 1) * sizeof *start);
  c.list = malloc((size_t)c.off[cells] * sizeof *c.list + 1);
  if (!c.list) return free(c.off), free(start), -1;
  c.fill = 1;
  for (size_t e = 0; e < s->m; e++)
    if (s->ealive[e])
      c.cur = (uint32_t)e,
      skel_segment_cells(&s->g, s->p[s->ev[2 * e]], s->p[s->ev[2 * e + 1]], skel_cells_visit, &c);
  long long m = (long long)s->m;
#pragma omp parallel for schedule(dynamic, 1024) num_threads(s->threads)
  for (long long e = 0; e < m; e++) {
    skel_probe q = {s, start, c.list, (uint32_t)e, 0};
    if (s->ealive[e] && !s->hull[e])
      skel_segment_cells(&s->g, s->p[s->ev[2 * e]], s->p[s->ev[2 * e + 1]], skel_probe_visit,
                         &q);
    cert[e] = s->ealive[e] && !q.crossed;
  }
  free(c.off), free(start), free(c.list);
  return 0;
}

/* ---- the convex hull ----------------------------------------------------- */

typedef struct skel_lexpt { geom_point p; uint32_t i; } skel_lexpt;

static int skel_cmp_lex(const void *x, const void *y) {
  geom_point a = ((const skel_lexpt *)x)->p, b = ((const skel_lexpt *)y)->p;
  return geom_lexless(a, b) ? -1 : geom_lexless(b, a);
}

/* One chain of the monotone-chain hull over the points in lexicographic order (dir +1:
** lower chain forwards; -1: upper chain backwards), keeping collinear boundary points
** (only strict right turns are popped); its consecutive pairs appended to s->hpair.
** O(n) after the sort. */
static void skel_hull_chain(skel *s, const skel_lexpt *o, uint32_t *st, int dir) {
  size_t k = 0;
  for (size_t j = 0; j < s->n; j++) {
    uint32_t v = o[dir > 0 ? j : s->n - 1 - j].i;
    while (k >= 2 && geom_orient(s->p[st[k - 2]], s->p[st[k - 1]], s->p[v]) < 0) k--;
    st[k++] = v;
  }
  for (size_t j = 0; j + 1 < k; j++) {
    s->hpair[2 * s->nh] = st[j] < st[j + 1] ? st[j] : st[j + 1];
    s->hpair[2 * s->nh++ + 1] = st[j] < st[j + 1] ? st[j + 1] : st[j];
  }
}

/* The hull's boundary pairs into s->hpair, and the input's check: 0, -1 out of memory,
** -2 two equal points (*bad, *bad2 their indices), -3 all points on a line. */
static int skel_hull(skel *s, size_t *bad, size_t *bad2) {
  skel_lexpt *o = malloc(s->n * sizeof *o);
  uint32_t *st = malloc(s->n * sizeof *st);
  s->hpair = malloc(4 * s->n * sizeof *s->hpair);
  if (!o || !st || !s->hpair) return free(o), free(st), -1;
  for (size_t i = 0; i < s->n; i++) o[i] = (skel_lexpt){s->p[i], (uint32_t)i};
  qsort(o, s->n, sizeof *o, skel_cmp_lex);
  int rc = 0;
  for (size_t i = 1; i < s->n && rc == 0; i++)
    if (o[i].p.x == o[i - 1].p.x && o[i].p.y == o[i - 1].p.y)
      rc = -2, *bad = o[i - 1].i < o[i].i ? o[i - 1].i : o[i].i, *bad2 = o[i - 1].i ^ o[i].i ^ *bad;
  size_t k = 1;
  while (rc == 0 && k + 1 < s->n && geom_orient(o[0].p, o[s->n - 1].p, o[k].p) == 0) k++;
  if (rc == 0 && geom_orient(o[0].p, o[s->n - 1].p, o[k].p) == 0) rc = -3;
  if (rc == 0) skel_hull_chain(s, o, st, 1), skel_hull_chain(s, o, st, -1);
  free(o), free(st);
  return rc;
}

/* hull[e] = 1 for the hull's boundary edges; -1 when out of memory or when one is no
** candidate (it always is: nothing lies beyond it, nor on it). */
static int skel_hull_mark(skel *s) {
  s->hull = calloc(s->m + 1, 1);
  if (!s->hull) return -1;
  for (size_t k = 0; k < s->nh; k++) {
    uint32_t e = skel_edge_find(s, s->hpair[2 * k], s->hpair[2 * k + 1]);
    if (e == UINT32_MAX) return -1;
    s->hull[e] = 1;
  }
  return 0;
}

/* ---- got_skel_build ------------------------------------------------------ */

/* The rule's flip decision, chosen once: 0, or -1 with a message for a rule that is no
** sum rule (a quadrilateral rule, or a joint whose keys combine by min or max). */
static int skel_decider(skel *s, const rule *r, char *err, size_t errlen) {
  const joint *J = rule_is_triangle(r) ? joint_get(rule_joint(r)) : NULL;
  if (J == NULL || J->keyop != JOINT_KEY_ADD) {
    snprintf(err, errlen, "got skeleton: rule %s is not a sum rule (the skeleton needs a "
             "triangle-based rule whose joint is l_p for a finite p)", rule_name(r));
    return -1;
  }
  const char *why;
  s->r = r;
  s->mp = measure_points(rule_measure(r));
  s->kind = SKEL_NEVER;
  if (rule_measure(r) == MEASURE_P && rule_joint(r) == JOINT_SUM)
    s->kind = SKEL_EXACT_LENGTH;
  else if (s->mp != NULL && got_cert_model(s->p, s->n, r, &s->rho, &s->alpha, &why) == 0)
    s->kind = SKEL_CERTIFIED;
  return 0;
}

/* The output's edges in ascending order (a, b): a counting sort by b, then a stable one
** by a.  O(n + m). */
static int skel_sort_edges(got_skel *o) {
  size_t m = o->nedges;
  uint32_t *e2 = malloc(2 * m * sizeof *e2 + 1), *cnt = malloc((o->n + 1) * sizeof *cnt);
  unsigned char *s2 = malloc(m + 1);
  if (!e2 || !cnt || !s2) return free(e2), free(cnt), free(s2), -1;
  for (int key = 1; key >= 0; key--) {
    memset(cnt, 0, (o->n + 1) * sizeof *cnt);
    for (size_t e = 0; e < m; e++) cnt[o->edge[2 * e + key] + 1]++;
    for (size_t v = 0; v < o->n; v++) cnt[v + 1] += cnt[v];
    for (size_t e = 0; e < m; e++) {
      uint32_t k = cnt[o->edge[2 * e + key]]++;
      e2[2 * k] = o->edge[2 * e], e2[2 * k + 1] = o->edge[2 * e + 1], s2[k] = o->state[e];
    }
    uint32_t *te = o->edge;
    unsigned char *ts = o->state;
    o->edge = e2, o->state = s2, e2 = te, s2 = ts;
  }
  free(e2), free(cnt), free(s2);
  return 0;
}

/* The live edges into out, in ascending order of input indices, with their states. */
static int skel_output(const skel *s, got_skel *out) {
  unsigned char *cert = malloc(s->m + 1);
  size_t k = 0, live = 0;
  if (!cert || skel_certain(s, cert) != 0) return free(cert), -1;
  for (size_t e = 0; e < s->m; e++) live += s->ealive[e];
  out->edge = malloc(2 * live * sizeof *out->edge + 1);
  out->state = malloc(live + 1);
  if (!out->edge || !out->state) return free(cert), -1;
  for (size_t e = 0; e < s->m; e++) {
    if (!s->ealive[e]) continue;
    uint32_t a = s->ev[2 * e], b = s->ev[2 * e + 1];
    if (s->orig) a = s->orig[a], b = s->orig[b];
    out->edge[2 * k] = a < b ? a : b, out->edge[2 * k + 1] = a < b ? b : a;
    out->state[k++] = cert[e] ? GOT_EDGE_CERTAIN : GOT_EDGE_POSSIBLE;
  }
  out->nedges = live;
  free(cert);
  return s->orig ? skel_sort_edges(out) : 0;
}

/* P_1: the points renumbered in the grid's cell order (rows of cells), so that the
** searches, the box scans and the loop read neighbours from nearby memory; s->orig maps
** back, and the hull's pairs are renumbered.  The grid then built on the renumbered points
** has the same cells, and holds point k at place k.  O(n).  (The other rules take at most
** GOT_SKEL_ALL_MAX points and keep the input's numbering: their flip decisions round the
** measures of triangles whose vertices come in index order.) */
static int skel_renumber(skel *s) {
  if (skel_grid_build(&s->g, s->p, s->n) != 0) return -1;
  s->orig = s->g.pt, s->q = s->g.gp, s->g.pt = NULL, s->g.gp = NULL;
  skel_grid_free(&s->g);
  memset(&s->g, 0, sizeof s->g);
  uint32_t *inv = malloc(s->n * sizeof *inv);
  if (!inv) return -1;
  for (size_t k = 0; k < s->n; k++) inv[s->orig[k]] = (uint32_t)k;
  for (size_t k = 0; k < s->nh; k++) {
    uint32_t a = inv[s->hpair[2 * k]], b = inv[s->hpair[2 * k + 1]];
    s->hpair[2 * k] = a < b ? a : b, s->hpair[2 * k + 1] = a < b ? b : a;
  }
  free(inv);
  s->p = s->q;
  return 0;
}

/* Candidates, triangles and the hull, with the time they took. */
static int skel_prepare(skel *s) {
  if ((s->kind == SKEL_EXACT_LENGTH && skel_renumber(s) != 0) ||
      skel_grid_build(&s->g, s->p, s->n) != 0 ||
      skel_candidates(s, s->kind == SKEL_EXACT_LENGTH) != 0)
    return -1;
  if (s->m >= UINT32_MAX / 4) return -1;
  s->ealive = malloc(s->m + 1);
  s->wit = malloc(2 * s->m * sizeof *s->wit + 1);
  if (!s->ealive || !s->wit) return -1;
  memset(s->ealive, 1, s->m);
  memset(s->wit, 0xff, 2 * s->m * sizeof *s->wit);
  if (skel_adjacency(s) != 0 || skel_hull_mark(s) != 0) return -1;
  return skel_triangles(s);
}

/* The checks of the arguments: 0, or -1 with the message. */
static int skel_check(skel *s, const rule *r, int threads, char *err, size_t errlen) {
  size_t bad = 0, bad2 = 0;
  if (geom_threads_check(threads, err, errlen) != 0 || skel_decider(s, r, err, errlen) != 0)
    return -1;
  if (s->n < 3 || s->n > UINT32_MAX / 8) {
    snprintf(err, errlen, "got skeleton: %zu points (expected 3 to %u)", s->n, UINT32_MAX / 8);
    return -1;
  }
  if (s->kind != SKEL_EXACT_LENGTH && s->n > GOT_SKEL_ALL_MAX) {
    snprintf(err, errlen, "got skeleton: %zu points is too many for rule %s: every pair of "
             "points is a candidate for it (no exclusion test), so at most %d points",
             s->n, rule_name(r), GOT_SKEL_ALL_MAX);
    return -1;
  }
  int rc = skel_hull(s, &bad, &bad2);
  if (rc == -2)
    snprintf(err, errlen, "got skeleton: points %zu and %zu are equal (0-based)", bad, bad2);
  else if (rc == -3)
    snprintf(err, errlen, "got skeleton: all %zu points lie on one line", s->n);
  else if (rc != 0)
    snprintf(err, errlen, "got skeleton: out of memory for %zu points", s->n);
  return rc == 0 ? 0 : -1;
}

int got_skel_build(const geom_point *p, size_t n, const rule *r, int threads, got_skel *out,
                   char *err, size_t errlen) {
  skel s = {.p = p, .n = n};
  memset(out, 0, sizeof *out);
  out->n = n;
  if (skel_check(&s, r, threads, err, errlen) != 0) return skel_free_all(&s), -1;
  s.threads = threads > 0 ? threads : omp_get_max_threads();
  double t0 = omp_get_wtime();
  int rc = skel_prepare(&s);
  double t1 = omp_get_wtime();
  out->candidates = s.m;
  if (rc == 0) rc = skel_lmt(&s, &out->rounds);
  if (rc == 0) rc = skel_output(&s, out);
  out->seconds_candidates = t1 - t0;
  out->seconds_lmt = omp_get_wtime() - t1;
  skel_free_all(&s);
  if (rc != 0) {
    got_skel_free(out);
    snprintf(err, errlen, "got skeleton: out of memory for %zu points", n);
  }
  return rc;
}

void got_skel_free(got_skel *s) {
  if (!s) return;
  free(s->edge);
  free(s->state);
  s->edge = NULL;
  s->state = NULL;
  s->nedges = 0;
}
