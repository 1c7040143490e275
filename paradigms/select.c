/*
** select.c: the selection algorithms of thesis 2.4.1 (docs/paradigms.md,
** "Selection").  The circumcircle algorithm grows the triangulation one
** triangle at a time from a hull edge: the boundary holds the directed
** edges whose left side is still unknown; an edge is taken from it, the
** apex on its left is selected, and the triangle's two other sides either
** close a boundary edge (the reverse was waiting) or join the boundary.
** Lifted to the paraboloid it is gift wrapping.  The boundary is a stack
** (a depth-first walk of the dual graph: figure 2.9) or a queue (breadth
** first: figure 2.10); the apex search scans every site, or an x-sorted
** strip, or a bucket grid.
**
** The apex of edge ab is the site c on its left such that no other site on
** its left beats it, "d beats c" meaning that d lies inside the rule's
** region through a, b, c (paradigm_inshape, lot's tie-break included).  For
** every rule here the regions through a and b are nested on the left of ab
** (circles of one pencil; for ES the circumscribing homothets and rounding
** shapes of docs/emptyshape.md), so "beats" is a strict order there and one
** pass that keeps the better of the candidate and each site finds the
** minimum: the output is lot's triangulation exactly.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "geom_key_internal.h"
#include "paradigm_internal.h"
#include "rule.h"
#include "shape.h"

#define SEL_NONE UINT32_MAX
#define SEL_EMPTY UINT64_MAX          /* hash slots: never a key (indices < 2^32 - 1) */
#define SEL_GONE (UINT64_MAX - 1)

typedef struct sel_edge { uint32_t u, v; } sel_edge;

/* Where the sites that beat the candidate can lie, widened by its
** rounding error: SEL_DISC, the part of the circle on the left of ab (DT);
** SEL_BOX, a box around the circumscribing homothet (ES, polygon K);
** SEL_CONE, a rounding shape's cone and hyperbola (ES, polygon K);
** SEL_ANYWHERE when nothing is known (no candidate, an ellipse, or a
** triangle too flat for the floating-point bounds below).  xlo, xhi: the
** x-extent of a disc or a box. */
typedef enum sel_bound { SEL_ANYWHERE, SEL_DISC, SEL_BOX, SEL_CONE } sel_bound;
typedef struct sel_cap {
  sel_bound bounded;
  double cx, cy, r, tol, xlo, xhi, ylo, yhi, rtol;   /* SEL_CONE: r, rtol its hyperbola's */
  double tx, ty, ts, big;              /* SEL_BOX: the homothet t + sK, |K|'s bound */
  geom_point o, u, v;                  /* SEL_CONE: cross(P - o, v) >= xlo, */
                                       /* cross(u, P - o) >= ylo */
} sel_cap;

/* The bucket grid: gx * gy cells over the bounding box, the sites of cell k
** at site[start[k] .. start[k + 1]), a stamp per cell (the search that last
** queued it) and the breadth-first queue of one search. */
typedef struct sel_grid {
  size_t gx, gy;
  double x0, y0, w, h, span, tol;
  uint32_t *start, *site, *stamp, *queue;
  uint32_t search;
} sel_grid;

typedef struct sel_state sel_state;
typedef uint32_t (*sel_search_fn)(sel_state *s, uint32_t a, uint32_t b);

struct sel_state {
  const geom_point *p;
  size_t n;
  const rule *r;
  ops_counts *c;
  int dt;                              /* the rule is DT (bounds known) */
  int (*beats)(sel_state *s, uint32_t a, uint32_t b, uint32_t c, uint32_t d);
  void (*cap)(const sel_state *s, uint32_t a, uint32_t b, uint32_t c, sel_cap *k);
  sel_search_fn search;
  uint32_t *ord, *pos, *hprev;         /* lexicographic order, its inverse, hull links */
  uint32_t h0, h1;                     /* the first hull edge, interior on its left */
  size_t hull;
  sel_edge *edge;                      /* pushed edges: [head, top) */
  size_t head, top;
  uint64_t *hkey;                      /* the live boundary, open addressing */
  size_t hmask, live, peak;
  double live_sum;
  uint32_t *tri;
  size_t ntri;
  sel_grid g;
  uint32_t *piece;                     /* constraints: 2 sites per piece */
  size_t npiece;
  double box[4];                       /* the sites' bounding box: x0, x1, y0, y1 */
  uint64_t tried;                      /* sites the apex searches tried */
};

/* ---- the apex order ---------------------------------------------------- */

/* DT: d beats c when it lies inside the circle abc; the in-circle sign with
** its tie-break is valid for d anywhere, one test per site. */
static int sel_beats_dt(sel_state *s, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  return paradigm_inshape(s->r, s->c, s->p[a], s->p[b], s->p[c], s->p[d]) > 0;
}

/* ES: the rule decides strictly convex quadrilaterals only; paradigm_beats
** places c and d by two orientation tests first (the argument is there). */
static int sel_beats_es(sel_state *s, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  return paradigm_beats(s->r, s->c, s->p[a], s->p[b], s->p[c], s->p[d]);
}

/* Does the open segment uv cross the open piece k at one point inside
** both?  Four orientation tests. */
static int sel_crosses(sel_state *s, uint32_t u, uint32_t v, size_t k) {
  return ops_segments_cross(s->c, s->p[u], s->p[v], s->p[s->piece[2 * k]],
                            s->p[s->piece[2 * k + 1]]);
}

/* 2.4.2: apex d of edge ab must see a and b, across no constraint (a
** constraint inside triangle abd has its ends inside the circle, and they
** are candidates themselves).  O(e) per site. */
static int sel_visible(sel_state *s, uint32_t a, uint32_t b, uint32_t d) {
  for (size_t k = 0; k < s->npiece; k++)
    if (sel_crosses(s, a, d, k) || sel_crosses(s, b, d, k)) return 0;
  return 1;
}

/* Site d against the best apex so far of edge ab: the new best (the best
** of the visible sites, the cheaper in-shape test first). */
static uint32_t sel_try(sel_state *s, uint32_t a, uint32_t b, uint32_t best, uint32_t d) {
  s->tried++;
  if (d == a || d == b || ops_orient(s->c, s->p[a], s->p[b], s->p[d]) <= 0) return best;
  if (best != SEL_NONE && !s->beats(s, a, b, best, d)) return best;
  return s->npiece == 0 || sel_visible(s, a, b, d) ? d : best;
}

/* ---- the boundary: a stack or a queue, and the set of live edges -------- */

static size_t sel_slot(const sel_state *s, uint64_t key) {
  uint64_t z = key + 0x9e3779b97f4a7c15u;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
  return (size_t)(z ^ (z >> 31)) & s->hmask;
}

static uint64_t sel_key(uint32_t u, uint32_t v) {
  return (uint64_t)u << 32 | v;
}

/* Remove u->v from the live boundary: 1 when it was there. */
static int sel_take(sel_state *s, uint32_t u, uint32_t v) {
  uint64_t key = sel_key(u, v);
  for (size_t i = sel_slot(s, key);; i = (i + 1) & s->hmask) {
    if (s->hkey[i] == SEL_EMPTY) return 0;
    if (s->hkey[i] != key) continue;
    s->hkey[i] = SEL_GONE;
    s->live--;
    ops_memory(s->c, -(int64_t)sizeof(sel_edge));
    return 1;
  }
}

/* A new boundary edge u->v (its left side unknown).  Each directed edge
** is pushed at most once, so the table never holds more than 3n keys and
** tombstones in its 8n slots or more. */
static void sel_push(sel_state *s, uint32_t u, uint32_t v) {
  size_t i = sel_slot(s, sel_key(u, v));
  while (s->hkey[i] != SEL_EMPTY) i = (i + 1) & s->hmask;
  s->hkey[i] = sel_key(u, v);
  s->edge[s->top++] = (sel_edge){u, v};
  if (++s->live > s->peak) s->peak = s->live;
  ops_memory(s->c, (int64_t)sizeof(sel_edge));
  ops_add(s->c, OPS_EDGES_MADE, 1);
}

/* Side x->y of a new triangle (the triangle on its left): it closes the
** boundary edge x->y if that waits, else y->x joins the boundary. */
static void sel_close(sel_state *s, uint32_t x, uint32_t y) {
  if (!sel_take(s, x, y)) sel_push(s, y, x);
}

/* The circumcircle algorithm: O(n) boundary steps, each one apex search.
** A triangulation of n sites has at most 2n - 5 triangles and 3n - 6
** edges, each pushed at most once a direction; a wrong apex (a bound of
** the searches too tight: a bug) could go on past them, so the loop
** stops there, returning -1, and never writes past its arrays or runs on. */
static int sel_wrap(sel_state *s, paradigm_select_order order) {
  sel_push(s, s->h0, s->h1);
  while (s->head < s->top) {
    if (s->ntri >= 2 * s->n || s->top + 2 > 3 * s->n) return -1;
    sel_edge e = order == PARADIGM_SELECT_STACK ? s->edge[--s->top] : s->edge[s->head++];
    if (!sel_take(s, e.u, e.v)) continue;          /* closed while it waited */
    if (s->hprev[e.u] == e.v) continue;            /* a hull edge seen from outside */
    uint32_t c = s->search(s, e.u, e.v);
    if (c == SEL_NONE) continue;                   /* never: only hull edges see nothing */
    uint32_t *t = s->tri + 3 * s->ntri++;
    t[0] = e.u, t[1] = e.v, t[2] = c;
    sel_close(s, e.v, c);
    sel_close(s, c, e.u);
    s->live_sum += (double)s->live;
  }
  return 0;
}

/* ---- the hull: where the wrapping starts and which edges face out ------- */

typedef struct sel_site { geom_point p; uint32_t i; } sel_site;

static int sel_lex_cmp(const void *x, const void *y) {
  const sel_site *p = x, *q = y;
  return geom_lexless(p->p, q->p) ? -1 : geom_lexless(q->p, p->p);
}

/* The sites in lexicographic order, and the convex hull with the sites on
** its sides (every site is a vertex of lot's triangulation), anticlockwise
** by Andrew's monotone chain keeping collinear turns: O(n log n).  The
** hull's turns are counted as orientation tests. */
static int sel_hull(sel_state *s, uint32_t *h) {
  sel_site *t = malloc(s->n * sizeof *t);
  if (t == NULL) return -1;
  for (size_t i = 0; i < s->n; i++) t[i] = (sel_site){s->p[i], (uint32_t)i};
  qsort(t, s->n, sizeof *t, sel_lex_cmp);
  for (size_t i = 0; i < s->n; i++) s->ord[i] = t[i].i;
  free(t);
  size_t k = 0;
  for (size_t i = 0; i < s->n; i++) {
    s->pos[s->ord[i]] = (uint32_t)i;
    while (k >= 2 && ops_orient(s->c, s->p[h[k - 2]], s->p[h[k - 1]], s->p[s->ord[i]]) < 0) k--;
    h[k++] = s->ord[i];
  }
  for (size_t i = s->n - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && ops_orient(s->c, s->p[h[k - 2]], s->p[h[k - 1]], s->p[s->ord[i]]) < 0)
      k--;
    h[k++] = s->ord[i];
  }
  s->hull = k - 1;                                 /* h[k - 1] is h[0] again */
  for (size_t i = 0; i < s->n; i++) s->hprev[i] = SEL_NONE;
  for (size_t j = 0; j < s->hull; j++) s->hprev[h[j + 1]] = h[j];
  s->h0 = h[0], s->h1 = h[1];
  return 0;
}

/* ---- the apex searches ------------------------------------------------- */

/* Every site: O(n) per edge, O(n^2) in all (2.4.1). */
static uint32_t sel_search_scan(sel_state *s, uint32_t a, uint32_t b) {
  uint32_t best = SEL_NONE;
  for (size_t i = 0; i < s->n; i++) best = sel_try(s, a, b, best, (uint32_t)i);
  return best;
}

/* The cap of the candidate c of edge ab: the part of circle abc on the
** left of ab, as centre, radius and x-extent, all widened by tol.  Only a
** bound: a site outside it cannot lie inside the circle, and the choice
** among the sites inside is the exact test's.  Why tol suffices: with
** v = b - a, the centre is m + t n (m the midpoint, n the unit left normal)
** with t = |v| (c - a).(c - b) / (2 cross(v, c - a)).  Differences, products
** and sums of doubles carry a relative error u = 2^-53 each, so cross
** carries at most 5u |v| |c - a| and the dot product 5u |c - a| |c - b|;
** when cross >= 2^-20 |v| |c - a| (else nothing is bounded) t is good to
** 2^-30 |t| + 2^-31 |c - b|, and the centre and the radius r to 2^-28 of
** |m| + |t| + |c - b| + |v|.  tol is 2^-24 of the sum of those magnitudes
** and r: 16 times the error, with room for the comparisons made with it. */
static void sel_cap_circle(const sel_state *s, uint32_t a, uint32_t b, uint32_t c,
                           sel_cap *k) {
  geom_point pa = s->p[a], pb = s->p[b], pc = s->p[c];
  double vx = pb.x - pa.x, vy = pb.y - pa.y, len = hypot(vx, vy);
  double ax = pc.x - pa.x, ay = pc.y - pa.y, bx = pc.x - pb.x, by = pc.y - pb.y;
  double la = hypot(ax, ay), lb = hypot(bx, by), cr = vx * ay - vy * ax;
  if (!(cr >= 0x1p-20 * len * la)) return;
  double t = len * (ax * bx + ay * by) / (2 * cr), nx = -vy / len, ny = vx / len;
  double mx = 0.5 * pa.x + 0.5 * pb.x, my = 0.5 * pa.y + 0.5 * pb.y;
  k->cx = mx + t * nx, k->cy = my + t * ny, k->r = hypot(0.5 * len, t);
  k->tol = 0x1p-24 * (fabs(mx) + fabs(my) + fabs(t) + k->r + len + la + lb);
  k->xlo = fmin(pa.x, pb.x), k->xhi = fmax(pa.x, pb.x);
  if (t - k->r * nx >= -k->tol) k->xlo = fmin(k->xlo, k->cx - k->r);  /* leftmost point on it */
  if (t + k->r * nx >= -k->tol) k->xhi = fmax(k->xhi, k->cx + k->r);  /* rightmost */
  k->xlo -= k->tol, k->xhi += k->tol;
  k->bounded = SEL_DISC;
}

/* The 3 x 3 determinant of rows m[0..2] and its absolute twin (the same
** sum of products with every term's magnitude). */
static double sel_det3(const double m[3][3], double *twin) {
  double a = m[1][1] * m[2][2], b = m[1][2] * m[2][1], c = m[1][0] * m[2][2];
  double d = m[1][2] * m[2][0], e = m[1][0] * m[2][1], f = m[1][1] * m[2][0];
  *twin = fabs(m[0][0]) * (fabs(a) + fabs(b)) + fabs(m[0][1]) * (fabs(c) + fabs(d))
        + fabs(m[0][2]) * (fabs(e) + fabs(f));
  return m[0][0] * (a - b) - m[0][1] * (c - d) + m[0][2] * (e - f);
}

/* Unknown j of m x = rhs by Cramer's rule (d the determinant of m), and
** the twin of its numerator in *tw. */
static double sel_cramer(const double m[3][3], const double rhs[3], int j, double d,
                         double *tw) {
  double mj[3][3];
  memcpy(mj, m, sizeof mj);
  for (int r = 0; r < 3; r++) mj[r][j] = rhs[r];
  return sel_det3((const double (*)[3])mj, tw) / d;
}

/* ES, polygon K, when the circumscribing shape of abc is the rounding
** shape of corner c0 (sides u, v): in the coordinates X = cross(P - a, v),
** Y = cross(u, P - a) (the map of docs/emptyshape.md) it is the convex
** side of the branch X > -beta, Y > -alpha of (X + beta)(Y + alpha) = r
** through the three sites: inside that quadrant, a cone with its apex at
** the hyperbola's centre, and beyond the branch.  alpha X + beta Y + gamma
** = -X Y at the three sites, so r = alpha beta - gamma: Cramer's rule with
** the error argument of sel_cap_homothet (entries and products of at most
** three rounded factors, 12u of the twins), tol 2^-24 of the numerators'
** twins over |D|.  The cone alone is a poor bound when the apex lies far
** from the sites (a flat branch near the hull: the cone then covers the
** whole grid), so the branch bounds too (sel_rect_meets_cone).  Its error:
** each of alpha, beta, gamma is within e_j = 2^-29 t_j of its exact value
** (t_j its numerator's twin over |D|; D within 12u of its twin, at least
** 2^-20 of it), so alpha beta - gamma is within (|alpha| + e_a) e_b +
** |beta| e_a + e_g, and the product and difference round by 3u of |alpha
** beta| + |gamma|; rtol is 2^-20 of the first sum with t_j for e_j (512
** times it) plus 2^-40 of the second. */
static void sel_cap_cone(const sel_state *s, uint32_t a, uint32_t b, uint32_t c, int c0,
                         sel_cap *k) {
  const shape *K = rule_shape(s->r);
  geom_point kc = K->v[c0], k1 = K->v[(c0 + 1) % K->n], k2 = K->v[(c0 + K->n - 1) % K->n];
  geom_point u = {k1.x - kc.x, k1.y - kc.y}, v = {k2.x - kc.x, k2.y - kc.y}, o = s->p[a];
  const uint32_t site[3] = {a, b, c};
  double m[3][3], rhs[3], x[3], tw[3], dtw;
  for (int r = 0; r < 3; r++) {
    double px = s->p[site[r]].x - o.x, py = s->p[site[r]].y - o.y;
    m[r][0] = px * v.y - py * v.x, m[r][1] = u.x * py - u.y * px, m[r][2] = 1;
    rhs[r] = -m[r][0] * m[r][1];
  }
  double d = sel_det3((const double (*)[3])m, &dtw);
  if (!(fabs(d) >= 0x1p-20 * dtw)) return;
  for (int j = 0; j < 3; j++) x[j] = sel_cramer((const double (*)[3])m, rhs, j, d, &tw[j]);
  double ta = tw[0] / fabs(d), tb = tw[1] / fabs(d), tg = tw[2] / fabs(d);
  k->tol = 0x1p-24 * (ta + tb);
  k->o = o, k->u = u, k->v = v;
  k->xlo = -x[1], k->ylo = -x[0];                   /* X >= -beta, Y >= -alpha */
  k->r = x[0] * x[1] - x[2];                        /* (X - xlo)(Y - ylo) >= r */
  k->rtol = 0x1p-20 * ((fabs(x[0]) + ta) * tb + fabs(x[1]) * ta + tg)
          + 0x1p-40 * (fabs(x[0] * x[1]) + fabs(x[2]));
  k->bounded = SEL_CONE;
}

/* ES, polygon K: a box around the circumscribing homothet t + sK of abc
** (every site that beats c lies in it).  shape_circumscribe gives the
** contact edges exactly; edge i (outward normal n_i, support value h_i of
** K) holds its site P when n_i.P = n_i.t + s h_i, three linear equations
** solved by Cramer's rule in doubles.  Each entry carries at most 3u of
** its magnitude and each determinant 12u of its twin; when the system's
** determinant D is at least 2^-20 of its twin (else nothing is bounded) D
** is good to 2^-28 and t and s to 2^-27 of (twin of their numerator) / |D|.
** tol is 2^-24 of the numerators' twins over |D|: 8 times that, and the
** box t + s bbox(K) is widened by tol (1 + |K|) and 2^-40 of its size. */
static void sel_cap_homothet(const sel_state *s, uint32_t a, uint32_t b, uint32_t c,
                             sel_cap *k) {
  const shape *K = rule_shape(s->r);
  int e[3], corner, kind = shape_circumscribe(K, s->p[a], s->p[b], s->p[c], e, &corner);
  if (kind == 0) sel_cap_cone(s, a, b, c, corner, k);
  if (kind != 1) return;
  double m[3][3], rhs[3], x[3], tw[3], dtw;
  const uint32_t site[3] = {a, b, c};
  for (int r = 0; r < 3; r++) {
    geom_point v0 = K->v[e[r]], v1 = K->v[(e[r] + 1) % K->n], p = s->p[site[r]];
    m[r][0] = v1.y - v0.y, m[r][1] = v0.x - v1.x;
    m[r][2] = m[r][0] * v0.x + m[r][1] * v0.y, rhs[r] = m[r][0] * p.x + m[r][1] * p.y;
  }
  double d = sel_det3((const double (*)[3])m, &dtw);
  if (!(fabs(d) >= 0x1p-20 * dtw)) return;
  for (int j = 0; j < 3; j++) x[j] = sel_cramer((const double (*)[3])m, rhs, j, d, &tw[j]);
  if (!(x[2] > 0)) return;
  double tol = 0x1p-24 * (tw[0] + tw[1] + tw[2]) / fabs(d), kx0 = K->v[0].x, kx1 = kx0;
  double ky0 = K->v[0].y, ky1 = ky0;
  for (int i = 1; i < K->n; i++) {
    kx0 = fmin(kx0, K->v[i].x), kx1 = fmax(kx1, K->v[i].x);
    ky0 = fmin(ky0, K->v[i].y), ky1 = fmax(ky1, K->v[i].y);
  }
  double big = fmax(fmax(fabs(kx0), fabs(kx1)), fmax(fabs(ky0), fabs(ky1)));
  k->tol = tol * (1 + big) + 0x1p-40 * (fabs(x[0]) + fabs(x[1]) + x[2] * big);
  k->xlo = x[0] + x[2] * kx0 - k->tol, k->xhi = x[0] + x[2] * kx1 + k->tol;
  k->ylo = x[1] + x[2] * ky0 - k->tol, k->yhi = x[1] + x[2] * ky1 + k->tol;
  k->tx = x[0], k->ty = x[1], k->ts = x[2], k->big = big;
  k->bounded = SEL_BOX;
}

/* The bound of candidate c (none yet: SEL_NONE), by the rule's kind. */
static void sel_cap_make(const sel_state *s, uint32_t a, uint32_t b, uint32_t c, sel_cap *k) {
  k->bounded = SEL_ANYWHERE;
  if (c != SEL_NONE && s->cap != NULL) s->cap(s, a, b, c, k);
}

/* Does the rectangle [x0, x1] x [y0, y1] meet the homothet of k (ES,
** polygon K)?  Separating axes: the box's, then each edge's outward normal
** n (K of at most 64 edges): the rectangle's least n.x beyond the edge's
** support value n.t + s h, with the slack of t, s (tol, as above) and
** 2^-40 of the magnitudes for the rounding here. */
static int sel_rect_meets_homothet(const sel_state *s, const sel_cap *k, double x0, double x1,
                                   double y0, double y1) {
  if (x1 < k->xlo || x0 > k->xhi || y1 < k->ylo || y0 > k->yhi) return 0;
  const shape *K = rule_shape(s->r);
  if (K->n > 64) return 1;
  double mag = fabs(x0) + fabs(x1) + fabs(y0) + fabs(y1) + fabs(k->tx) + fabs(k->ty)
             + k->ts * k->big;
  for (int i = 0; i < K->n; i++) {
    geom_point v0 = K->v[i], v1 = K->v[(i + 1) % K->n];
    double nx = v1.y - v0.y, ny = v0.x - v1.x, h = nx * v0.x + ny * v0.y, nn = fabs(nx) + fabs(ny);
    double least = nx * (nx > 0 ? x0 : x1) + ny * (ny > 0 ? y0 : y1);
    double slack = k->tol * (nn + fabs(h)) + 0x1p-40 * nn * (mag + k->big);
    if (least > nx * k->tx + ny * k->ty + k->ts * h + slack) return 0;
  }
  return 1;
}

/* The slack of a corner's X - xlo and Y - ylo over the rectangle [x0, x1]
** x [y0, y1] (the rounding shape of k): tol, and 2^-40 of the magnitudes
** for the rounding of the cross products, the differences and xlo, ylo. */
static double sel_cone_slack(const sel_cap *k, double x0, double x1, double y0, double y1) {
  geom_point o = k->o, u = k->u, v = k->v;
  double mag = (fabs(x0 - o.x) + fabs(x1 - o.x) + fabs(y0 - o.y) + fabs(y1 - o.y))
             * (fabs(u.x) + fabs(u.y) + fabs(v.x) + fabs(v.y));
  return k->tol + 0x1p-40 * mag;
}

/* X - xlo and Y - ylo of the point (x, y) for the rounding shape of k,
** each widened by slack (sel_cone_slack: then at least its exact value). */
static void sel_cone_at(const sel_cap *k, double x, double y, double slack, double w[2]) {
  double px = x - k->o.x, py = y - k->o.y;
  w[0] = px * k->v.y - py * k->v.x - k->xlo + slack;
  w[1] = k->u.x * py - k->u.y * px - k->ylo + slack;
}

/* Does the rectangle [x0, x1] x [y0, y1] meet the rounding shape of k?
** The rectangle's largest X and Y against the cone's bounds: Xm and Ym,
** the largest X - xlo and Y - ylo widened by the slack (sel_cone_at), are
** at least their exact values.  A point of the shape has X - xlo, Y - ylo
** > 0 and their product at least r, so the rectangle meets it only if Xm,
** Ym >= 0 and Xm Ym >= r: that with rtol on r and 2^-30 of Xm Ym for the
** three roundings here.  Tight on a small cell; on a tall or wide
** rectangle Xm and Ym come from corners far apart, and
** sel_rect_meets_branch answers then. */
static int sel_rect_meets_cone(const sel_cap *k, double x0, double x1, double y0, double y1) {
  geom_point u = k->u, v = k->v;
  double slack = sel_cone_slack(k, x0, x1, y0, y1), wm[2], wn[2];
  sel_cone_at(k, v.y > 0 ? x1 : x0, v.x > 0 ? y0 : y1, slack, wm);
  sel_cone_at(k, u.y > 0 ? x0 : x1, u.x > 0 ? y1 : y0, slack, wn);
  double xm = wm[0], ym = wn[1];
  return xm >= 0 && ym >= 0 && xm * ym + 0x1p-30 * (xm * ym) >= k->r - k->rtol;
}

/* An upper bound on X Y over the points of segment pq (exact inputs here)
** in the closed quadrant X, Y >= 0; -1 when it has none.  Along the
** segment X Y is a quadratic in the parameter t: monotone in the quadrant
** when dX, dY have one sign (the top end then, if it is in the quadrant),
** else concave, with its top c^2 / (4 |dX dY|) at t* (c = cross(p, q),
** the top's X = c / (2 dY)), and its largest value on the segment at the
** end nearer t* when t* is outside (0, 1).  t* lies inside when the slopes
** at the ends, g0 = pX dY + pY dX > 0 > g1 = qX dY + qY dX.  Those slopes
** and c carry at most 3u of their twins (the signs of dX, dY are exact):
** 2^-40 of the twins decides only what is certain, and in doubt the top
** counts (an upper bound either way).  The top itself: |c| + its error
** bound, squared over 4 |dX dY|, within 6u below its exact value at worst. */
static double sel_seg_peak(const double p[2], const double q[2]) {
  double m = -1, dx = q[0] - p[0], dy = q[1] - p[1];
  if (p[0] >= 0 && p[1] >= 0) m = p[0] * p[1];
  if (q[0] >= 0 && q[1] >= 0 && q[0] * q[1] > m) m = q[0] * q[1];
  if (!((dx < 0 && dy > 0) || (dx > 0 && dy < 0))) return m;
  double g0 = p[0] * dy + p[1] * dx, e0 = 0x1p-40 * (fabs(p[0] * dy) + fabs(p[1] * dx));
  double g1 = q[0] * dy + q[1] * dx, e1 = 0x1p-40 * (fabs(q[0] * dy) + fabs(q[1] * dx));
  double c = p[0] * q[1] - p[1] * q[0], ec = 0x1p-40 * (fabs(p[0] * q[1]) + fabs(p[1] * q[0]));
  if (g0 <= -e0 || g1 >= e1) return m;                /* t* outside: an end is the top */
  if (dy > 0 ? c <= -ec : c >= ec) return m;          /* the top in X, Y < 0: no quadrant */
  double ac = fabs(c) + ec, top = ac * ac / (4 * fabs(dx * dy));
  return top > m ? top : m;
}

/* Does the rectangle [x0, x1] x [y0, y1] meet the rounding shape of k?
** Exactly, but for rounding: (X - xlo, Y - ylo) is affine in the point,
** so the rectangle's image is the hull of its corners' images, each below
** its widened value (sel_rect_meets_cone's argument, at all four corners).
** A point of the image in the quadrant lies below a point of the widened
** corners' hull, in the quadrant too, where X Y is larger; and X Y,
** whose Hessian is indefinite, takes its largest value on that hull at
** its boundary, within the six segments between the corners
** (sel_seg_peak).  The rectangle meets the shape only if that bound
** reaches r, less rtol and 2^-30 of the bound (its 6u and the roundings
** here).  Eight cross products and six segments: for the strip's tall
** rectangles, where the cheap test is loose. */
static int sel_rect_meets_branch(const sel_cap *k, double x0, double x1, double y0, double y1) {
  double slack = sel_cone_slack(k, x0, x1, y0, y1), w[4][2], m = -1, rm = k->r - k->rtol;
  for (int i = 0; i < 4; i++) sel_cone_at(k, i & 1 ? x1 : x0, i & 2 ? y1 : y0, slack, w[i]);
  for (int i = 0; i < 4 && !(m >= 0 && m + 0x1p-30 * m >= rm); i++)
    for (int j = i + 1; j < 4; j++) {
      double t = sel_seg_peak(w[i], w[j]);
      m = t > m ? t : m;
    }
  return m >= 0 && m + 0x1p-30 * m >= rm;
}

/* May a site with x in [x0, x1] (site coordinates, exact) beat the
** candidate whose bound is k?  Its y lies in the sites' box.  A disc or a
** homothet answers by its x-extent; a rounding shape by whether the
** rectangle [x0, x1] x [the box's y-range] meets its cone and hyperbola
** (sel_rect_meets_cone: it answers no only when no point of the
** rectangle lies in the shape, every rounding error counted there), which
** bounds the strip although the shape is unbounded. */
static int sel_strip_open(const sel_state *s, const sel_cap *k, double x0, double x1) {
  switch (k->bounded) {
    case SEL_ANYWHERE: return 1;
    case SEL_DISC: case SEL_BOX: return x1 >= k->xlo && x0 <= k->xhi;
    case SEL_CONE:
      return sel_rect_meets_cone(k, x0, x1, s->box[2], s->box[3])
          && sel_rect_meets_branch(k, x0, x1, s->box[2], s->box[3]);
  }
  return 1;
}

/* The strip's next position, or SIZE_MAX when both sides are shut: the
** side whose next site is nearer ab's x-range [xlo, xhi] first; a side
** whose remainder cannot reach the bound k is shut (its remainder only
** shrinks, so it stays shut until the caller opens both for a new k). */
static size_t sel_strip_next(const sel_state *s, const sel_cap *k, size_t *l, size_t *r,
                             int shut[2], double xlo, double xhi) {
  for (;;) {
    int gol = *l > 0 && !shut[0], gor = *r < s->n && !shut[1];
    if (!gol && !gor) return SIZE_MAX;
    double xl = gol ? s->p[s->ord[*l - 1]].x : 0, xr = gor ? s->p[s->ord[*r]].x : 0;
    int left = gol && (!gor || xlo - xl <= xr - xhi);
    if (left ? sel_strip_open(s, k, s->box[0], xl) : sel_strip_open(s, k, xr, s->box[1]))
      return left ? --*l : (*r)++;
    shut[!left] = 1;
  }
}

/* The x-sorted strip (2.4.1, figure 2.13): the sites between a and b in x
** first, then outwards, the nearer side in x first, until neither side's
** remaining sites (x up to the next site's on the left, from it on the
** right) can reach the candidate's bound (sel_strip_open).  Expected
** O(sqrt n) sites per edge on uniform sites, O(n^{3/2}) in all (DT); for ES
** the homothet's x-extent or the rounding shape inside the sites' box; an
** ellipse gives none (O(n) per edge). */
static uint32_t sel_search_strip(sel_state *s, uint32_t a, uint32_t b) {
  size_t i0 = s->pos[a] < s->pos[b] ? s->pos[a] : s->pos[b];
  size_t i1 = s->pos[a] ^ s->pos[b] ^ i0, l = i0, r = i1 + 1, i;
  double xlo = fmin(s->p[a].x, s->p[b].x), xhi = fmax(s->p[a].x, s->p[b].x);
  uint32_t best = SEL_NONE;
  for (i = i0; i <= i1; i++) best = sel_try(s, a, b, best, s->ord[i]);
  sel_cap k;
  sel_cap_make(s, a, b, best, &k);
  int shut[2] = {0, 0};
  while ((i = sel_strip_next(s, &k, &l, &r, shut, xlo, xhi)) != SIZE_MAX) {
    uint32_t nb = sel_try(s, a, b, best, s->ord[i]);
    if (nb != best) best = nb, sel_cap_make(s, a, b, best, &k), shut[0] = shut[1] = 0;
  }
  return best;
}

/* Does cell (i, j), widened by the grid's rounding margin, meet the left
** half-plane of ab and the cap?  Bounds only, as for sel_cap_make: the
** corners' cross products carry at most 8u |v| span. */
static int sel_cell_meets(const sel_state *s, uint32_t a, uint32_t b, const sel_cap *k,
                          size_t i, size_t j) {
  const sel_grid *g = &s->g;
  double x0 = g->x0 + (double)i * g->w - g->tol, x1 = g->x0 + (double)(i + 1) * g->w + g->tol;
  double y0 = g->y0 + (double)j * g->h - g->tol, y1 = g->y0 + (double)(j + 1) * g->h + g->tol;
  geom_point pa = s->p[a];
  double vx = s->p[b].x - pa.x, vy = s->p[b].y - pa.y;
  double cx = vx * ((vx > 0 ? y1 : y0) - pa.y) - vy * ((vy > 0 ? x0 : x1) - pa.x);
  if (cx < -0x1p-28 * hypot(vx, vy) * g->span) return 0;   /* the corner furthest left */
  if (k->bounded == SEL_ANYWHERE) return 1;
  if (k->bounded == SEL_BOX) return sel_rect_meets_homothet(s, k, x0, x1, y0, y1);
  if (k->bounded == SEL_CONE) return sel_rect_meets_cone(k, x0, x1, y0, y1);
  double dx = fmax(fmax(x0 - k->cx, k->cx - x1), 0), dy = fmax(fmax(y0 - k->cy, k->cy - y1), 0);
  return dx * dx + dy * dy <= (k->r + k->tol) * (k->r + k->tol);
}

static size_t sel_cell_of(const sel_grid *g, double x, double y) {
  double fx = (x - g->x0) / g->w, fy = (y - g->y0) / g->h;
  size_t i = fx < (double)g->gx ? (size_t)fx : g->gx - 1;
  size_t j = fy < (double)g->gy ? (size_t)fy : g->gy - 1;
  return j * g->gx + i;
}

/* The cell of site i, geom_csr_build's key over the state. */
static size_t sel_site_cell(const void *ctx, size_t i) {
  const sel_state *s = ctx;
  return sel_cell_of(&s->g, s->p[i].x, s->p[i].y);
}

/* Visit cell k: count it, try its sites, queue its unqueued neighbours. */
static uint32_t sel_cell_visit(sel_state *s, uint32_t a, uint32_t b, uint32_t best, size_t k,
                               size_t *qt) {
  sel_grid *g = &s->g;
  ops_add(s->c, OPS_BUCKETS, 1);
  for (uint32_t q = g->start[k]; q < g->start[k + 1]; q++)
    best = sel_try(s, a, b, best, g->site[q]);
  size_t i = k % g->gx, j = k / g->gx;
  size_t nb[4] = {i > 0 ? k - 1 : k, i + 1 < g->gx ? k + 1 : k,
                  j > 0 ? k - g->gx : k, j + 1 < g->gy ? k + g->gx : k};
  for (int d = 0; d < 4; d++)
    if (g->stamp[nb[d]] != g->search)
      g->stamp[nb[d]] = g->search, g->queue[(*qt)++] = (uint32_t)nb[d];
  return best;
}

/* The bucket grid (2.4.1, figure 2.14): a breadth-first search of the
** cells from the one holding the midpoint of ab, through the cells that
** meet the left half-plane and the current cap.  Every cell meeting the
** final cap is reached: those cells are 4-connected (closed cells), hold
** the midpoint's, and meet every earlier, larger cap.  O(1) expected cells
** and sites per edge on uniform sites, O(n) in all (DT; ES polygons as
** measured, docs/paradigms.md: homothets by their edges, rounding shapes
** by their cone and hyperbola); every search of an ellipse goes through
** every cell on the left (O(n / p)). */
static uint32_t sel_search_buckets(sel_state *s, uint32_t a, uint32_t b) {
  sel_grid *g = &s->g;
  size_t qh = 0, qt = 0, k0 = sel_cell_of(g, 0.5 * s->p[a].x + 0.5 * s->p[b].x,
                                          0.5 * s->p[a].y + 0.5 * s->p[b].y);
  g->search++;
  g->stamp[k0] = g->search, g->queue[qt++] = (uint32_t)k0;
  uint32_t best = SEL_NONE;
  sel_cap cap;
  sel_cap_make(s, a, b, best, &cap);
  while (qh < qt) {
    size_t k = g->queue[qh++];
    if (!sel_cell_meets(s, a, b, &cap, k % g->gx, k / g->gx)) continue;
    uint32_t nb = sel_cell_visit(s, a, b, best, k, &qt);
    if (nb != best) best = nb, sel_cap_make(s, a, b, best, &cap);
  }
  return best;
}

/* ---- constraints (2.4.2): the segments cut at the sites inside them ---- */

/* Append the pieces of segment (u, v): the sites strictly inside it
** (collinear, and between the ends in the lexicographic order, which is
** the order along the line) cut it, as lot/ cuts it.  O(n). */
static int sel_cut(sel_state *s, uint32_t u, uint32_t v, sel_site *on, size_t *cap) {
  if (geom_lexless(s->p[v], s->p[u])) {
    uint32_t w = u;
    u = v, v = w;
  }
  size_t k = 0;
  on[k++] = (sel_site){s->p[u], u};
  for (size_t i = 0; i < s->n; i++)
    if (geom_lexless(s->p[u], s->p[i]) && geom_lexless(s->p[i], s->p[v])
        && ops_orient(s->c, s->p[u], s->p[v], s->p[i]) == 0)
      on[k++] = (sel_site){s->p[i], (uint32_t)i};
  qsort(on + 1, k - 1, sizeof *on, sel_lex_cmp);
  on[k++] = (sel_site){s->p[v], v};
  if (s->npiece + k > *cap) {
    *cap = 2 * (s->npiece + k);
    uint32_t *grown = realloc(s->piece, 2 * *cap * sizeof *grown);
    if (grown == NULL) return -1;
    s->piece = grown;
  }
  for (size_t j = 0; j + 1 < k; j++)
    s->piece[2 * s->npiece] = on[j].i, s->piece[2 * s->npiece++ + 1] = on[j + 1].i;
  return 0;
}

/* The pieces of every segment, refused when two of them cross (one point
** inside both) or a segment's ends are one point.  O(n e + P^2), P pieces.
** 0; -1 with the message; -2 out of memory. */
static int sel_pieces(sel_state *s, const uint32_t *seg, size_t ns, char *err, size_t errlen) {
  size_t cap = 0;
  uint32_t *from = malloc((ns ? ns : 1) * sizeof *from);
  sel_site *on = malloc((s->n + 1) * sizeof *on);
  int rc = from && on ? 0 : -2;
  for (size_t k = 0; k < ns && rc == 0; k++) {
    if (seg[2 * k] == seg[2 * k + 1]) {
      snprintf(err, errlen, "segment %zu: both ends are point %u", k, seg[2 * k]);
      rc = -1;
    } else if (sel_cut(s, seg[2 * k], seg[2 * k + 1], on, &cap) != 0) {
      rc = -2;
    }
    if (rc == 0) from[k] = (uint32_t)s->npiece;      /* segment k's pieces end here */
  }
  for (size_t k = 0, i = 0; rc == 0 && i < s->npiece; i++) {
    while (from[k] <= i) k++;                       /* piece i is segment k's */
    for (size_t j = 0, l = 0; rc == 0 && j < i; j++) {
      while (from[l] <= j) l++;
      if (sel_crosses(s, s->piece[2 * i], s->piece[2 * i + 1], j)) {
        snprintf(err, errlen, "segments %zu and %zu cross", l, k);
        rc = -1;
      }
    }
  }
  free(from), free(on);
  return rc;
}

/* ---- setting up -------------------------------------------------------- */

/* The grid of about n / p cells of the bounding box's shape, p sites
** expected per cell on uniform sites: O(n + n / p). */
static int sel_grid_make(sel_state *s, double p) {
  sel_grid *g = &s->g;
  g->x0 = s->box[0], g->y0 = s->box[2];
  double cells = fmax(1, floor((double)s->n / p)), wd = s->box[1] - g->x0;
  double ht = s->box[3] - g->y0;
  g->gx = (size_t)fmin(cells, fmax(1, round(sqrt(cells * wd / ht))));
  g->gy = (size_t)fmin(cells, fmax(1, round(cells / (double)g->gx)));
  g->w = wd / (double)g->gx, g->h = ht / (double)g->gy;
  g->span = fabs(g->x0) + fabs(g->y0) + wd + ht;
  g->tol = 0x1p-30 * g->span;
  size_t m = g->gx * g->gy;
  g->start = malloc((m + 1) * sizeof *g->start);
  g->site = malloc(s->n * sizeof *g->site);
  g->stamp = calloc(m, sizeof *g->stamp);
  g->queue = malloc(m * sizeof *g->queue);
  if (!g->start || !g->site || !g->stamp || !g->queue) return -1;
  geom_csr_build(g->start, m, g->site, s->n, sel_site_cell, s);
  return 0;
}

static void sel_free(sel_state *s) {
  free(s->ord), free(s->pos), free(s->hprev), free(s->edge), free(s->hkey);
  free(s->g.start), free(s->g.site), free(s->g.stamp), free(s->g.queue), free(s->piece);
}

/* The sites' bounding box (the grid's, and the strip's y-range): O(n). */
static void sel_box(sel_state *s) {
  double *b = s->box;
  b[0] = b[1] = s->p[0].x, b[2] = b[3] = s->p[0].y;
  for (size_t i = 1; i < s->n; i++) {
    b[0] = fmin(b[0], s->p[i].x), b[1] = fmax(b[1], s->p[i].x);
    b[2] = fmin(b[2], s->p[i].y), b[3] = fmax(b[3], s->p[i].y);
  }
}

static int sel_alloc(sel_state *s, double p) {
  size_t n = s->n, slots = 16;
  while (slots < 8 * n) slots *= 2;
  s->hmask = slots - 1;
  s->ord = malloc(n * sizeof *s->ord);
  s->pos = malloc(n * sizeof *s->pos);
  s->hprev = malloc(3 * n * sizeof *s->hprev);      /* and 2n for the hull's chain */
  s->edge = malloc(3 * n * sizeof *s->edge);
  s->hkey = malloc(slots * sizeof *s->hkey);
  s->tri = malloc(3 * 2 * n * sizeof *s->tri);
  if (!s->ord || !s->pos || !s->hprev || !s->edge || !s->hkey || !s->tri) return -1;
  memset(s->hkey, 0xff, slots * sizeof *s->hkey);
  sel_box(s);
  return p > 0 ? sel_grid_make(s, p) : 0;
}

/* The search chosen once: its function, and the bucket size (0: no grid);
** 0, or -1 with the message (a bucket size out of range). */
static int sel_choose(sel_state *s, const paradigm_input *in, paradigm_select_search search,
                      double *bucket, char *err, size_t errlen) {
  *bucket = in->param == 0 ? 1 : in->param;
  switch (search) {
    case PARADIGM_SELECT_SCAN: s->search = sel_search_scan, *bucket = 0; break;
    case PARADIGM_SELECT_STRIP: s->search = sel_search_strip, *bucket = 0; break;
    case PARADIGM_SELECT_BUCKETS: s->search = sel_search_buckets; break;
  }
  if (*bucket != 0 && !(*bucket >= 0.0625 && *bucket <= 1e6)) {
    snprintf(err, errlen, "select-buckets: the bucket size p = %g (sites per bucket) must lie "
             "in [0.0625, 1e6]", *bucket);
    return -1;
  }
  return 0;
}

/* Allocate, find the hull, cut the constraints: 0, or -1 with the message. */
static int sel_setup(sel_state *s, const paradigm_input *in, double bucket, char *err,
                     size_t errlen) {
  int rc = sel_alloc(s, bucket) != 0 || sel_hull(s, s->hprev + in->n) != 0 ? -2 : 0;
  if (rc == 0 && in->problem == PARADIGM_CONSTRAINED)
    rc = sel_pieces(s, in->segments, in->nsegments, err, errlen);
  if (rc == -2)
    snprintf(err, errlen, "out of memory for the selection of %zu points", in->n);
  return rc == 0 ? 0 : -1;
}

int paradigm_select_run(const paradigm_input *in, paradigm_select_order order,
                        paradigm_select_search search, paradigm_output *out,
                        paradigm_select_stats *st, char *err, size_t errlen) {
  sel_state s;
  memset(&s, 0, sizeof s);
  s.p = in->p, s.n = in->n, s.r = in->r, s.c = &out->ops;
  s.dt = rule_shape(in->r) == NULL;
  s.beats = s.dt ? sel_beats_dt : sel_beats_es;
  s.cap = s.dt ? sel_cap_circle
        : rule_shape(in->r)->kind == SHAPE_POLYGON ? sel_cap_homothet : NULL;
  double bucket;
  if (sel_choose(&s, in, search, &bucket, err, errlen) != 0) return -1;
  if (sel_setup(&s, in, bucket, err, errlen) != 0) {
    sel_free(&s), free(s.tri);
    return -1;
  }
  if (sel_wrap(&s, order) != 0) {
    snprintf(err, errlen, "selection: more than the %zu triangles of %zu sites (a bug: please "
             "report it)", 2 * s.n, s.n);
    sel_free(&s), free(s.tri);
    return -1;
  }
  out->tri = s.tri, out->ntri = s.ntri;
  if (st) {
    st->mean_boundary = s.ntri ? s.live_sum / (double)s.ntri : 0;
    st->peak_boundary = s.peak, st->hull = s.hull, st->buckets = s.g.gx * s.g.gy;
    st->examined = s.tried;
  }
  sel_free(&s);
  return 0;
}

int paradigm_select_stack(const paradigm_input *in, paradigm_output *out, char *err,
                          size_t errlen) {
  return paradigm_select_run(in, PARADIGM_SELECT_STACK, PARADIGM_SELECT_SCAN, out, NULL, err,
                             errlen);
}

int paradigm_select_queue(const paradigm_input *in, paradigm_output *out, char *err,
                          size_t errlen) {
  return paradigm_select_run(in, PARADIGM_SELECT_QUEUE, PARADIGM_SELECT_SCAN, out, NULL, err,
                             errlen);
}

int paradigm_select_strip(const paradigm_input *in, paradigm_output *out, char *err,
                          size_t errlen) {
  return paradigm_select_run(in, PARADIGM_SELECT_STACK, PARADIGM_SELECT_STRIP, out, NULL, err,
                             errlen);
}

int paradigm_select_buckets(const paradigm_input *in, paradigm_output *out, char *err,
                            size_t errlen) {
  return paradigm_select_run(in, PARADIGM_SELECT_STACK, PARADIGM_SELECT_BUCKETS, out, NULL, err,
                             errlen);
}

int paradigm_select_constrained(const paradigm_input *in, paradigm_output *out, char *err,
                                size_t errlen) {
  return paradigm_select_run(in, PARADIGM_SELECT_STACK, PARADIGM_SELECT_SCAN, out, NULL, err,
                             errlen);
}
