/* got_skel_internal.h: what the files of the skeleton share (got/got_skel.c and
** got/got_skel_grid.c, got_skel_cand.c, got_skel_tri.c; docs/got.md, "Point sets: the
** skeleton"): the point grid, the skeleton's state, and the verbs that cross files. */
#ifndef FLIPLAB_GOT_SKEL_INTERNAL_H
#define FLIPLAB_GOT_SKEL_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "measure.h"
#include "got_internal.h"
#include "got_skel.h"
#include "geom_mem_internal.h"

#define SKEL_U 0x1p-53

/* Points searched in parallel in blocks of SKEL_BLOCK, the blocks joined in order. */
#define SKEL_BLOCK 4096

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

/* The cell of coordinate v (relative to the grid's corner) among cap, clamped. */
static inline int skel_cell(double v, double inv, int cap) {
  double c = v * inv;
  if (!(c > 0)) return 0;
  return c >= cap - 1 ? cap - 1 : (int)c;
}
static inline int skel_cellx(const skel_grid *g, double x) {
  return skel_cell(x - g->x0, g->inv, g->nx);
}
static inline int skel_celly(const skel_grid *g, double y) {
  return skel_cell(y - g->y0, g->inv, g->ny);
}

/* The cells that can hold a point of the box [xa, xb] x [ya, yb] (padded: SKEL_PAD). */
typedef struct skel_box { int ix0, ix1, iy0, iy1; } skel_box;

static inline skel_box skel_grid_box(const skel_grid *g, double xa, double xb, double ya,
                                     double yb) {
  double e = SKEL_PAD * g->h;
  skel_box r = {skel_cell((xa - g->x0) - e, g->inv, g->nx),
                skel_cell((xb - g->x0) + e, g->inv, g->nx),
                skel_cell((ya - g->y0) - e, g->inv, g->ny),
                skel_cell((yb - g->y0) + e, g->inv, g->ny)};
  return r;
}

/* A growing array of edges (a, b), a < b, 2 entries each (n and cap count pairs; the
** library's one growth rule, geom_grow). */
typedef struct skel_vec { uint32_t *v; size_t n, cap; } skel_vec;

/* Appends (a, b): inline, as the searches push tens of pairs a point; 0, or -1 out of
** memory. */
static inline int skel_vec_push(skel_vec *s, uint32_t a, uint32_t b) {
  if (geom_grow((void **)&s->v, &s->cap, s->n + 1, 2 * sizeof *s->v) != 0) return -1;
  s->v[2 * s->n] = a, s->v[2 * s->n + 1] = b;
  s->n++;
  return 0;
}

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
  uint32_t *te;            /* 3 per triangle a < b < c: its edges ab, ac, bc */
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

/* The sum of triangle t's vertices (modulo 2^32): a + b + c, the ends of ab and of ac. */
static inline uint32_t skel_tri_sum(const skel *s, uint32_t t) {
  const uint32_t *ab = s->ev + 2 * s->te[3 * t], *ac = s->ev + 2 * s->te[3 * t + 1];
  return ab[0] + ab[1] + ac[1];
}

typedef void (*skel_cell_fn)(void *ctx, size_t cell);

/* got_skel_grid.c */
FLIPLAB_INTERNAL int skel_grid_build(skel_grid *g, const geom_point *p, size_t n);
FLIPLAB_INTERNAL void skel_grid_free(skel_grid *g);
FLIPLAB_INTERNAL void skel_segment_cells(const skel_grid *g, geom_point a, geom_point b,
                                         skel_cell_fn visit, void *ctx);
/* got_skel_cand.c */
FLIPLAB_INTERNAL int skel_candidates(skel *s, int diamond);
FLIPLAB_INTERNAL int skel_adjacency(skel *s);
FLIPLAB_INTERNAL uint32_t skel_edge_find(const skel *s, uint32_t u, uint32_t v);
/* got_skel_tri.c */
FLIPLAB_INTERNAL int skel_triangles(skel *s);

#endif
