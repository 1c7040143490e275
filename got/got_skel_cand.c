/*
** got_skel_cand.c: the skeleton's candidate edges (got/got_skel_internal.h): for P_1 the
** diamond test of Das and Joseph by a ring search bounded by sectors around each point
** (skel_diamond_point), for the other sum rules every segment through no third point; and
** the candidate graph (adjacency lists, edge lookup).
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "got_skel_internal.h"

/* ---- predicates ---------------------------------------------------------- */

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


/* ---- candidate edges ----------------------------------------------------- */


/* Where q stands for the diamond test of ab: 2 on the open segment ab (exact), +1 inside
** the left diamond triangle, -1 inside the right one (skel_in_cone), 0 elsewhere.  One
** orientation determinant decides which side to test: computed, it is within ecr of its
** exact value (the bound of skel_in_cone, Shewchuk's), so beyond ecr q is certainly off
** the line (geom_on_segment's exact test would say 0) and certainly not inside the other
** side's triangle (skel_in_cone asks more than that margin); within it, neither cone test
** can succeed, and only the exact test on the segment is left.  The same answers as
** geom_on_segment and skel_in_cone on both sides, one cone test instead of two. */
static int skel_diamond_side(geom_point a, geom_point b, geom_point q) {
  double ux = b.x - a.x, uy = b.y - a.y, vx = q.x - a.x, vy = q.y - a.y;
  double l = ux * vy, r = uy * vx, cr = l - r;
  double ecr = (3 + 16 * SKEL_U) * SKEL_U * (fabs(l) + fabs(r));
  if (!(fabs(cr) > ecr)) return geom_on_segment(a, b, q) ? 2 : 0;
  int side = cr > 0 ? 1 : -1;
  return skel_in_cone(a, b, q, side) ? side : 0;
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
  int sx = pa.x < pb.x, sy = pa.y < pb.y;   /* plain selections: fmin is a library call */
  double xa = (sx ? pa.x : pb.x) - ex, xb = (sx ? pb.x : pa.x) + ex;
  double ya = (sy ? pa.y : pb.y) - ey, yb = (sy ? pb.y : pa.y) + ey;
  skel_box bx = skel_grid_box(g, xa, xb, ya, yb);
  int left = 0, right = 0;
  for (int iy = bx.iy0; iy <= bx.iy1; iy++)
    for (int ix = bx.ix0; ix <= bx.ix1; ix++) {
      size_t c = (size_t)iy * (size_t)g->nx + (size_t)ix;
      for (uint32_t k = g->off[c]; k < g->off[c + 1]; k++) {
        uint32_t q = g->pt[k];
        geom_point pq = g->gp[k];
        if (q == a || q == b || pq.x < xa || pq.x > xb || pq.y < ya || pq.y > yb) continue;
        int w = diamond ? skel_diamond_side(pa, pb, pq) : 2 * geom_on_segment(pa, pb, pq);
        if (w == 2) return 0;
        left |= w == 1, right |= w == -1;
        if (left && right) return 0;
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

/* Bins of the pseudo-angle of skel_sector: 512 over its range [0, 2), each narrower
** than 0.008 rad (the pseudo-angle grows at least half as fast as the angle), so a bin
** meets at most one sector boundary (w = 0.049 rad). */
#define SKEL_GUESS 512

/* A point q seen from a: its sector, distance, ring and coordinates. */
typedef struct skel_seen { uint32_t q; int sect; double d; geom_point pt; int ring; } skel_seen;

/* The scratch of one search (one per thread), with the directions of the sectors'
** boundaries: sector t holds the angles from t w - pi to (t + 1) w - pi, w = 2 pi / 128. */
typedef struct skel_search {
  skel_seen *seen;
  size_t ns, cap;
  double dmin[SKEL_SECT], far[SKEL_SECT], reach[SKEL_SECT];
  unsigned char done[SKEL_SECT];
  int cover[SKEL_SECT];             /* rings 0 .. cover[t] - 1 read whole in sector t */
  unsigned char gap[SKEL_SECT];     /* sector t has a cell left out of the current ring */
  int open[SKEL_SECT], nopen;       /* the sectors not done, ascending */
  double bx[SKEL_SECT], by[SKEL_SECT], fk[7];   /* fk: the far argument's factors */
  unsigned char guess[SKEL_GUESS];  /* skel_sector's first guess by pseudo-angle */
  uint32_t *stamp, tick;            /* ring places visited (skel_ring_arcs), by tick */
  size_t stcap;
  uint32_t *sidx, scap;             /* the seen points by sector (skel_seen_decides) */
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
  for (int i = 0; i < SKEL_GUESS; i++) {
    double q = 2.0 * i / SKEL_GUESS, phi = q <= 1 ? atan2(q, 1 - q) : atan2(2 - q, 1 - q);
    int t = (int)floor(phi / (2 * M_PI / SKEL_SECT));
    z->guess[i] = (unsigned char)(t < 0 ? 0 : t > SKEL_SECT / 2 - 1 ? SKEL_SECT / 2 - 1 : t);
  }
}

/* The sector of direction (dx, dy) != 0: the lower half plane holds sectors 0 .. 63, the
** upper one 64 .. 127, and within a half the boundaries are in anticlockwise order, so the
** sector is the last boundary t of the half with cross(b_t, d) >= 0 (that test is true up
** to the sector and false after it).  A first guess from the pseudo-angle's bin (the
** direction turned into the upper half as (u, v), q = 1 - u / (|u| + v), which grows with
** the angle) is then moved to that last boundary: the answer of a binary search over the
** half, in one or two tests instead of six unpredictable ones.  The boundaries' rounding
** moves them by about 1e-16 rad, far inside the margins of the far argument (a sector's
** neighbours at two sectors' distance). */
static int skel_sector(const skel_search *z, double dx, double dy) {
  int low = dy < 0 || (dy == 0 && dx < 0), base = low ? 0 : SKEL_SECT / 2;
  int top = base + SKEL_SECT / 2 - 1;
  double u = low ? -dx : dx, v = low ? -dy : dy, q = 1 - u / (fabs(u) + v);
  int i = (int)(q * (SKEL_GUESS / 2)), t;
  t = base + z->guess[i < 0 ? 0 : i > SKEL_GUESS - 1 ? SKEL_GUESS - 1 : i];
  while (t > base && !(z->bx[t] * dy - z->by[t] * dx >= 0)) t--;
  while (t < top && z->bx[t + 1] * dy - z->by[t + 1] * dx >= 0) t++;
  return t;
}

/* far[t] for the open sectors (indices wrap by a mask: SKEL_SECT is a power of two).
** Cost: 10 products an open sector. */
static void skel_far_update(skel_search *z) {
  for (int j = 0; j < z->nopen; j++) {
    unsigned t = (unsigned)z->open[j];
    double l = INFINITY, r = INFINITY;
    for (unsigned k = 2; k <= 6; k++) {
      double x = z->dmin[(t + k) & (SKEL_SECT - 1)] * z->fk[k];
      double y = z->dmin[(t - k) & (SKEL_SECT - 1)] * z->fk[k];
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
** its sectors is done, or its far distance is below the cell's nearest possible point.
** The cell is then left out, and its sectors marked as not read whole in this ring. */
static int skel_cell_dead(const skel_grid *g, skel_search *z, int dx, int dy) {
  if (g->sect_lo == NULL || abs(dx) > SKEL_WIN || abs(dy) > SKEL_WIN) return 0;
  size_t o = (size_t)(dy + SKEL_WIN) * (2 * SKEL_WIN + 1) + (size_t)(dx + SKEL_WIN);
  int ax = abs(dx) - 1, ay = abs(dy) - 1;
  ax = ax < 0 ? 0 : ax, ay = ay < 0 ? 0 : ay;
  double mind = (sqrt((double)(ax * ax + ay * ay)) - 2 * SKEL_PAD) * g->h;
  for (int k = 0; k < g->sect_n[o]; k++) {
    int t = (g->sect_lo[o] + k) % SKEL_SECT;
    if (!z->done[t] && !(z->far[t] <= mind)) return 0;
  }
  for (int k = 0; k < g->sect_n[o]; k++) z->gap[(g->sect_lo[o] + k) % SKEL_SECT] = 1;
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

/* After ring k: the far distances, and the sectors read whole so far (cover).  A ring by
** arcs reads every cell that meets an open sector (skel_ring_arcs) but the dead ones; a
** whole ring every cell but the dead ones; a dead cell marks every sector it can meet
** (the grid's table, padded by a sector), so a sector with no mark lost no point. */
static void skel_ring_cover(skel_search *z, int k) {
  for (int t = 0; t < SKEL_SECT; t++)
    if (!z->gap[t] && z->cover[t] == k) z->cover[t] = k + 1;
  skel_far_update(z);
}

/* Adds the points of the live cells of ring k to the search: by arcs when the open sectors
** need fewer places than the ring has, else the whole ring; the sectors' cover updated. */
static int skel_ring(const skel_grid *g, const geom_point *p, uint32_t a, int k,
                     skel_search *z) {
  int cx = skel_cellx(g, p[a].x), cy = skel_celly(g, p[a].y);
  if (k >= 2 && z->nopen * (0.11 * k + 2 * SKEL_ARC_PAD + 2) < 8.0 * k) {
    memset(z->gap, 1, sizeof z->gap);
    for (int j = 0; j < z->nopen; j++) z->gap[z->open[j]] = 0;
    if (skel_ring_arcs(g, p[a], a, cx, cy, k, z) != 0) return -1;
    skel_ring_cover(z, k);
    return 0;
  }
  memset(z->gap, 0, sizeof z->gap);
  for (int iy = cy - k; iy <= cy + k; iy++) {
    if (iy < 0 || iy >= g->ny) continue;
    int step = (iy == cy - k || iy == cy + k || k == 0) ? 1 : 2 * k;
    for (int ix = cx - k; ix <= cx + k; ix += step) {
      if (ix < 0 || ix >= g->nx || skel_cell_dead(g, z, ix - cx, iy - cy)) continue;
      if (skel_cell_take(g, p[a], a, (size_t)iy * (size_t)g->nx + (size_t)ix, k, z) != 0)
        return -1;
    }
  }
  skel_ring_cover(z, k);
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

/* What the points seen around a say of pair ab (b = z->seen[ib]): 1 it fails the diamond
** test (a point certainly inside each diamond triangle, or one on the open segment:
** skel_diamond_side, the pair's ends in the order P, Q that skel_edge_ok gets, so this
** drops only pairs that skel_edge_ok drops); 2 it passes; 0 the seen points cannot tell.
** A triangle's directions from a are within pi/8 (8 sectors) of b's, so only the 19
** sectors around b's are read, nearest first (b's sector anywhere in [t, t + 1) w, the
** triangles span 16 sectors and a bit: a sector to spare at each end for the rounding of
** sectors); both triangles lie within |ab| / cos(pi/8) < 1.09 |ab| of a, and points of
** ring k are at least (k - 1 - 2 SKEL_PAD) h away, so they lie in rings up to 1.09 |ab| / h
** + 1 + 1e-5, and each sector is read up to ring 1.09 |ab| / h + 2.  When those rings were
** read whole in all 19 sectors (z->cover), the seen points hold every point of the two
** triangles and the segment: the pair passes when neither fails (skel_edge_ok would find
** the same points, and the others give it 0).  Cost: those points, until both sides hold
** one. */
static int skel_seen_decides(const skel_search *z, size_t ib, geom_point P, geom_point Q,
                             double h) {
  const skel_seen *b = &z->seen[ib];
  double kmax = 1.09 * b->d / h + 2;
  int left = 0, right = 0, whole = 1, kneed = (int)(1.09 * b->d / h + 1 + 1e-5);
  for (int k = 0; k <= 18; k++) {
    int t = (b->sect + (k & 1 ? (k + 1) / 2 : SKEL_SECT - k / 2)) % SKEL_SECT;
    whole &= z->cover[t] > kneed;
    for (uint32_t j = z->soff[t]; j < z->soff[t + 1]; j++) {
      const skel_seen *q = &z->seen[z->sidx[j]];
      if (q->ring > kmax) break;
      if (z->sidx[j] == ib) continue;
      int w = skel_diamond_side(P, Q, q->pt);
      left |= w == 1, right |= w == -1;
      if ((left && right) || w == 2) return 1;
    }
  }
  return whole ? 2 : 0;
}

/* The diamond candidates (a, b), b > a, into out, ascending in b.  The test of a pair is
** run with its ends in input order (orig: the input index of each point, or NULL), so
** its rounding, and the candidates, do not depend on the internal numbering.  The pairs
** the sectors leave are queued behind the seen points, sorted, tried on the seen points
** (skel_seen_decides), and the survivors get the full test.  Cost: the live cells around a
** (about a hundred points for uniform points), and for each pair left the seen points
** near a until the diamond holds a point on both sides, or the points of its box. */
static int skel_diamond_point(const skel_grid *g, const geom_point *p, const uint32_t *orig,
                              uint32_t a, skel_search *z, skel_vec *out) {
  z->ns = 0;
  for (int t = 0; t < SKEL_SECT; t++)
    z->dmin[t] = z->far[t] = INFINITY, z->reach[t] = NAN, z->done[t] = 0, z->open[t] = t,
    z->cover[t] = 0;
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
    int seen = skel_seen_decides(z, (size_t)pair[i].ring, P, Q, g->h);
    if (seen == 1) continue;
    int ok = seen == 2 || (fwd ? skel_edge_ok(g, a, p[a], b, p[b], 1)
                               : skel_edge_ok(g, b, p[b], a, p[a], 1));
    if (ok && skel_vec_push(out, a, b) != 0) return -1;
  }
  return 0;
}

/* ---- the candidate graph ------------------------------------------------- */

/* The adjacency of the sorted edge list: pushing edges in order leaves every list
** ascending (neighbours below v come from edges (u, v), all before the edges (v, w)). */
int skel_adjacency(skel *s) {
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
uint32_t skel_edge_find(const skel *s, uint32_t u, uint32_t v) {
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
int skel_candidates(skel *s, int diamond) {
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

