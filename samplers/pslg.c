/*
** pslg.c: random planar straight-line graphs for constrained triangulations
** (sampler.h): polygons with holes, non-crossing segments on a point set,
** a rotated grid with segments along its lines.  Each one's segments meet
** only at points of the graph, which is decided exactly here (geom_orient,
** geom_segments_meet), not hoped for: a draw that rounding spoilt is drawn
** again.  The samplers sit below lot/ in the layering, so none of them may
** triangulate; docs/sampling.md says how each gets its guarantee instead.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "sampler.h"

#define SAMPLER_PSLG_2PI 6.28318530717958647693
#define SAMPLER_PSLG_TRIES 100

/* m vertices around c, anticlockwise, at angles 2 pi (k + 0.4 u_k) / m and
** radii r (lo + (1 - lo) v_k).  Every angular gap is below 2 pi 1.4 / m,
** less than pi for m >= 3, so in exact arithmetic the ring is star-shaped
** from c, simple, with c strictly inside; the callers check that exactly,
** since rounding the sines and cosines may spoil it. */
static void sampler_pslg_ring(sampler_rng *g, geom_point c, double r, double lo, size_t m,
                              geom_point *out) {
  for (size_t k = 0; k < m; k++) {
    double t = SAMPLER_PSLG_2PI * ((double)k + 0.4 * sampler_uniform(g)) / (double)m;
    double rk = r * (lo + (1 - lo) * sampler_uniform(g));
    out[k] = (geom_point){c.x + rk * cos(t), c.y + rk * sin(t)};
  }
}

/* 1 when q is strictly inside the simple polygon v[0..m), 0 outside or on
** its boundary: the parity of the edges the rightward ray from q crosses,
** an edge counted when its end points lie on either side of q's y
** (half-open) and q lies on the ray's side of it; coordinate comparisons
** and geom_orient signs only, so exact. */
static int sampler_pslg_inside(const geom_point *v, size_t m, geom_point q) {
  int in = 0;
  for (size_t i = 0, j = m - 1; i < m; j = i++) {
    geom_point a = v[j], b = v[i];
    if (geom_segments_meet(a, b, q, q)) return 0;
    if ((a.y > q.y) != (b.y > q.y)) {
      int o = geom_orient(a, b, q);
      if (b.y > a.y ? o > 0 : o < 0) in ^= 1;
    }
  }
  return in;
}

/* Exactly simple and anticlockwise (a copy is checked: the check may
** reverse it). */
static int sampler_pslg_simple(const geom_point *v, size_t m, geom_point *scratch) {
  memcpy(scratch, v, m * sizeof *v);
  int rev = 0;
  return geom_simple_polygon_check(scratch, m, NULL, NULL, &rev) == GEOM_OK && !rev;
}

/* Append the ring v[0..m) as points and closing segments. */
static void sampler_pslg_add_ring(geom_pslg *o, const geom_point *v, size_t m) {
  uint32_t base = (uint32_t)o->npts;
  for (size_t k = 0; k < m; k++) {
    o->pts[o->npts++] = v[k];
    o->seg[2 * o->nseg] = base + (uint32_t)k;
    o->seg[2 * o->nseg + 1] = base + (uint32_t)((k + 1) % m);
    o->nseg++;
  }
}

/* The closed bounding boxes of two rings overlap. */
static int sampler_pslg_boxes_meet(const double *a, const double *b) {
  return !(a[1] < b[0] || b[1] < a[0] || a[3] < b[2] || b[3] < a[2]);
}

static void sampler_pslg_box(const geom_point *v, size_t m, double *box) {
  box[0] = box[1] = v[0].x;
  box[2] = box[3] = v[0].y;
  for (size_t k = 1; k < m; k++) {
    box[0] = fmin(box[0], v[k].x);
    box[1] = fmax(box[1], v[k].x);
    box[2] = fmin(box[2], v[k].y);
    box[3] = fmax(box[3], v[k].y);
  }
}

/* The placed holes' boxes (x0, x1, y0, y1 each), bucketed in a grid of
** side x side cells over [-1, 1]^2 (outside coordinates clamped to the
** border cells).  Cell indices are non-decreasing in the coordinate, so a
** point common to two boxes lies in a cell of both boxes' ranges: the boxes
** a candidate may meet are those listed in its cells.  A cell is wider
** than any hole's box, so a box spans at most 2 x 2 cells (4 list nodes a
** hole); a wider one (rounding beyond all reason) is simply not placed. */
typedef struct sampler_pslg_index {
  double *box;
  size_t side;
  double cell;
  uint32_t *head, *next, *of;   /* side^2 heads (UINT32_MAX: empty); 4 nodes a hole */
  size_t nodes;
} sampler_pslg_index;

static size_t sampler_pslg_index_cell(const sampler_pslg_index *x, double v) {
  double t = (v + 1) / x->cell;
  return t < 0 ? 0 : t >= (double)x->side ? x->side - 1 : (size_t)t;
}

static int sampler_pslg_index_init(sampler_pslg_index *x, size_t nholes, double rad) {
  x->cell = 2.01 * rad;
  x->side = (size_t)ceil(2 / x->cell);
  x->nodes = 0;
  size_t h = nholes ? nholes : 1;
  x->box = malloc(4 * h * sizeof *x->box);
  x->head = malloc(x->side * x->side * sizeof *x->head);
  x->next = malloc(4 * h * sizeof *x->next);
  x->of = malloc(4 * h * sizeof *x->of);
  if (!x->box || !x->head || !x->next || !x->of) return SAMPLER_ENOMEM;
  for (size_t k = 0; k < x->side * x->side; k++) x->head[k] = UINT32_MAX;
  return 0;
}

static void sampler_pslg_index_free(sampler_pslg_index *x) {
  free(x->box);
  free(x->head);
  free(x->next);
  free(x->of);
}

/* Does the box b meet a placed one (1), span more than 2 x 2 cells (1, so
** it is not placed), or neither (0)?  With add, register it as hole id. */
static int sampler_pslg_index_visit(sampler_pslg_index *x, const double *b, uint32_t id,
                                    int add) {
  size_t i0 = sampler_pslg_index_cell(x, b[0]), i1 = sampler_pslg_index_cell(x, b[1]);
  size_t j0 = sampler_pslg_index_cell(x, b[2]), j1 = sampler_pslg_index_cell(x, b[3]);
  if (i1 > i0 + 1 || j1 > j0 + 1) return 1;
  for (size_t j = j0; j <= j1; j++)
    for (size_t i = i0; i <= i1; i++) {
      size_t c = j * x->side + i;
      if (add) {
        x->of[x->nodes] = id;
        x->next[x->nodes] = x->head[c];
        x->head[c] = (uint32_t)x->nodes++;
        continue;
      }
      for (uint32_t k = x->head[c]; k != UINT32_MAX; k = x->next[k])
        if (sampler_pslg_boxes_meet(b, x->box + 4 * (size_t)x->of[k])) return 1;
    }
  return 0;
}

/* May the candidate hole h[0..m) around c join the graph: simple, c
** strictly inside it, its box apart from every placed hole's (then the
** holes are disjoint, and none holds another), no edge meeting an edge of
** the outer ring o[0..no), and a vertex strictly inside that ring (so,
** the ring being connected and crossing no outer edge, all of it).  Outer
** edges whose box misses the hole's are skipped, exactly. */
static int sampler_pslg_hole_ok(const geom_point *h, size_t m, geom_point c, const double *box,
                                const geom_point *o, size_t no, sampler_pslg_index *x,
                                geom_point *scratch) {
  if (sampler_pslg_index_visit(x, box, 0, 0)) return 0;
  if (!sampler_pslg_simple(h, m, scratch) || !sampler_pslg_inside(h, m, c)) return 0;
  for (size_t e = 0; e < no; e++) {
    geom_point a = o[e], b = o[(e + 1) % no];
    double eb[4] = {fmin(a.x, b.x), fmax(a.x, b.x), fmin(a.y, b.y), fmax(a.y, b.y)};
    if (!sampler_pslg_boxes_meet(eb, box)) continue;
    for (size_t k = 0; k < m; k++)
      if (geom_segments_meet(h[k], h[(k + 1) % m], a, b)) return 0;
  }
  return sampler_pslg_inside(o, no, h[0]);
}

/* Room for the whole graph of sampler_pslg_holes. */
static int sampler_pslg_alloc(geom_pslg *o, size_t npts, size_t nholes) {
  *o = (geom_pslg){0};
  o->pts = malloc(npts * sizeof *o->pts);
  o->seg = malloc(2 * npts * sizeof *o->seg);
  o->hole = malloc((nholes ? nholes : 1) * sizeof *o->hole);
  if (o->pts && o->seg && o->hole) return 0;
  geom_pslg_free(o);
  return SAMPLER_ENOMEM;
}

/* Place the holes one by one, each drawn up to 50 times per hole asked
** for in all; -1 when fewer fit, SAMPLER_ENOMEM. */
static int sampler_pslg_place_holes(sampler_rng *g, geom_pslg *o, size_t nouter, size_t nholes,
                                    size_t m, geom_point *h, geom_point *scratch) {
  double rad = fmin(0.2, 0.3 / sqrt((double)(nholes ? nholes : 1)));
  sampler_pslg_index x;
  int rc = sampler_pslg_index_init(&x, nholes, rad);
  for (size_t tries = 0; rc == 0 && o->nholes < nholes; tries++) {
    if (tries >= 50 * nholes) rc = -1;
    geom_point c = sampler_disc(g);
    c = (geom_point){0.6 * c.x, 0.6 * c.y};
    sampler_pslg_ring(g, c, rad * (0.5 + 0.5 * sampler_uniform(g)), 0.5, m, h);
    double *box = x.box + 4 * o->nholes;
    sampler_pslg_box(h, m, box);
    if (rc != 0 || !sampler_pslg_hole_ok(h, m, c, box, o->pts, nouter, &x, scratch)) continue;
    sampler_pslg_index_visit(&x, box, (uint32_t)o->nholes, 1);
    sampler_pslg_add_ring(o, h, m);
    o->hole[o->nholes++] = c;
  }
  sampler_pslg_index_free(&x);
  return rc;
}

int sampler_pslg_holes(sampler_rng *g, size_t nouter, size_t nholes, size_t m, geom_pslg *out) {
  if (nouter < 3 || m < 3 || nholes > SAMPLER_PSLG_MAX_HOLES) return -1;
  size_t npts = nouter + nholes * m, big = nouter > m ? nouter : m;
  int rc = sampler_pslg_alloc(out, npts, nholes);
  geom_point *h = malloc(m * sizeof *h), *scratch = malloc(big * sizeof *scratch);
  if (rc == 0 && (h == NULL || scratch == NULL)) rc = SAMPLER_ENOMEM;
  for (int tries = 0; rc == 0; tries++) {
    if (tries == SAMPLER_PSLG_TRIES) {
      rc = -1;
      break;
    }
    out->npts = out->nseg = out->nholes = 0;
    sampler_pslg_ring(g, (geom_point){0, 0}, 1, 0.75, nouter, out->pts);
    if (!sampler_pslg_simple(out->pts, nouter, scratch)) continue;
    sampler_pslg_add_ring(out, out->pts, nouter);
    out->npts = nouter;
    int placed = sampler_pslg_place_holes(g, out, nouter, nholes, m, h, scratch);
    if (placed == 0) break;
    if (placed == SAMPLER_ENOMEM) rc = SAMPLER_ENOMEM;
  }
  if (rc != 0) geom_pslg_free(out);
  free(h);
  free(scratch);
  return rc;
}

/* ---- segments on a point set ---- */

/* The cell of coordinate x among c cells of the range [lo, lo + c / s]:
** min(c - 1, floor((x - lo) s)), a non-decreasing function of x (every
** step is), so each cell is a closed interval of the doubles and two cells
** are disjoint intervals of the reals. */
static size_t sampler_pslg_cell(double x, double lo, double s, size_t c) {
  double t = (x - lo) * s;
  size_t k = t < (double)c ? (size_t)t : c - 1;
  return k < c ? k : c - 1;
}

/* Points a and b seen from h in the same direction (so the segments h-a
** and h-b overlap): collinear, and on the same side of h. */
static int sampler_pslg_same_ray(geom_point h, geom_point a, geom_point b) {
  if (geom_orient(h, a, b) != 0) return 0;
  return ((a.x > h.x) - (a.x < h.x)) == ((b.x > h.x) - (b.x < h.x)) &&
         ((a.y > h.y) - (a.y < h.y)) == ((b.y > h.y) - (b.y < h.y));
}

/* The candidate segments of one cell (its points idx[0..k), input order):
** from the first point, the hub, to every other point of the cell that is
** not equal to it and not in the direction of an earlier candidate. */
static size_t sampler_pslg_cell_rays(const geom_point *p, const uint32_t *idx, size_t k,
                                     uint32_t *cand) {
  size_t nc = 0;
  geom_point h = p[idx[0]];
  for (size_t i = 1; i < k; i++) {
    geom_point a = p[idx[i]];
    int ok = a.x != h.x || a.y != h.y;
    for (size_t j = 0; ok && j < nc; j++) ok = !sampler_pslg_same_ray(h, p[cand[2 * j + 1]], a);
    if (!ok) continue;
    cand[2 * nc] = idx[0];
    cand[2 * nc + 1] = idx[i];
    nc++;
  }
  return nc;
}

/* Bucket the points into c x c cells of their bounding box (counting sort,
** input order kept): start[0..c*c] and idx. */
static void sampler_pslg_bucket(const geom_point *p, size_t n, size_t c, size_t *start,
                                uint32_t *idx, uint32_t *cell) {
  double x0 = p[0].x, x1 = p[0].x, y0 = p[0].y, y1 = p[0].y;
  for (size_t i = 1; i < n; i++) {
    x0 = fmin(x0, p[i].x), x1 = fmax(x1, p[i].x);
    y0 = fmin(y0, p[i].y), y1 = fmax(y1, p[i].y);
  }
  double sx = x1 > x0 ? (double)c / (x1 - x0) : 0, sy = y1 > y0 ? (double)c / (y1 - y0) : 0;
  memset(start, 0, (c * c + 1) * sizeof *start);
  for (size_t i = 0; i < n; i++) {
    cell[i] = (uint32_t)(sampler_pslg_cell(p[i].y, y0, sy, c) * c +
                         sampler_pslg_cell(p[i].x, x0, sx, c));
    start[cell[i] + 1]++;
  }
  for (size_t k = 0; k < c * c; k++) start[k + 1] += start[k];
  for (size_t i = 0; i < n; i++) idx[start[cell[i]]++] = (uint32_t)i;
  for (size_t k = c * c; k > 0; k--) start[k] = start[k - 1];
  start[0] = 0;
}

int sampler_segments(sampler_rng *g, const geom_point *p, size_t n, size_t m, uint32_t *seg,
                     size_t *got) {
  *got = 0;
  if (n < 2 || m == 0 || n > UINT32_MAX) return 0;
  size_t c = (size_t)ceil(sqrt((double)(m < n / 4 ? m : n / 4)));
  if (c < 1) c = 1;
  size_t *start = malloc((c * c + 1) * sizeof *start);
  uint32_t *idx = malloc(n * sizeof *idx), *cell = malloc(n * sizeof *cell);
  uint32_t *cand = malloc(2 * n * sizeof *cand);
  int rc = start && idx && cell && cand ? 0 : SAMPLER_ENOMEM;
  if (rc == 0) {
    sampler_pslg_bucket(p, n, c, start, idx, cell);
    size_t nc = 0;
    for (size_t k = 0; k < c * c; k++)
      if (start[k + 1] > start[k])
        nc += sampler_pslg_cell_rays(p, idx + start[k], start[k + 1] - start[k], cand + 2 * nc);
    /* m of the nc candidates, uniformly (a partial Fisher-Yates shuffle;
    ** the modulo's bias is below nc / 2^64) */
    for (size_t i = 0; i < m && i < nc; i++) {
      size_t j = i + (size_t)(sampler_next(g) % (uint64_t)(nc - i));
      uint32_t a = cand[2 * j], b = cand[2 * j + 1];
      cand[2 * j] = cand[2 * i], cand[2 * j + 1] = cand[2 * i + 1];
      seg[2 * i] = a, seg[2 * i + 1] = b;
      cand[2 * i] = a, cand[2 * i + 1] = b;
      *got = i + 1;
    }
  }
  free(start);
  free(idx);
  free(cell);
  free(cand);
  return rc;
}

/* ---- a rotated grid ---- */

/* Grid point k of side s: (i, j) = (k mod s, k div s) turned by the angle
** atan(4/3), exactly: (3i - 4j, 4i + 3j), integers. */
static geom_point sampler_pslg_grid_point(size_t k, size_t s) {
  double i = (double)(k % s), j = (double)(k / s);
  return (geom_point){3 * i - 4 * j, 4 * i + 3 * j};
}

static void sampler_pslg_push(geom_pslg *o, uint32_t a, uint32_t b) {
  o->seg[2 * o->nseg] = a;
  o->seg[2 * o->nseg + 1] = b;
  o->nseg++;
}

/* Along each row every piece between neighbours is chosen with probability
** 1/2, and a run of chosen pieces is one segment, from the run's first
** point to its last, through the collinear points between (which split it). */
static void sampler_pslg_grid_rows(sampler_rng *g, geom_pslg *o, size_t s) {
  size_t n = o->npts;
  for (size_t row = 0; row * s < n; row++) {
    size_t first = SIZE_MAX, end = (row + 1) * s < n ? (row + 1) * s : n;
    for (size_t k = row * s; k < end; k++) {
      int piece = k + 1 < end && (sampler_next(g) >> 63);
      if (piece && first == SIZE_MAX) first = k;
      if (!piece && first != SIZE_MAX) {
        sampler_pslg_push(o, (uint32_t)first, (uint32_t)k);
        first = SIZE_MAX;
      }
    }
  }
}

int sampler_pslg_grid(sampler_rng *g, size_t n, geom_pslg *out) {
  *out = (geom_pslg){0};
  if (n < 3 || n > SAMPLER_PSLG_MAX_GRID) return -1;
  size_t s = (size_t)ceil(sqrt((double)n));
  while (s * s < n) s++;
  out->pts = malloc(n * sizeof *out->pts);
  out->seg = malloc(4 * n * sizeof *out->seg);
  out->hole = malloc(sizeof *out->hole);
  if (!out->pts || !out->seg || !out->hole) {
    geom_pslg_free(out);
    return SAMPLER_ENOMEM;
  }
  for (size_t k = 0; k < n; k++) out->pts[k] = sampler_pslg_grid_point(k, s);
  out->npts = n;
  sampler_pslg_grid_rows(g, out, s);
  for (size_t k = 0; k + s < n; k++)
    if (sampler_next(g) >> 63) sampler_pslg_push(out, (uint32_t)k, (uint32_t)(k + s));
  return 0;
}
