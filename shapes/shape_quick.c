/*
** shape_quick.c: the quick polygon decision.  The support vertices and the
** circumscribing homothet's test of shape_polygon.c, computed in straight-line
** doubles with a proven error bound on a per-shape table; at the first sign
** the bound cannot certify as non-zero it gives up, and shape_polygon.c takes its
** filtered-exact path, so every answer is that path's answer.
*/
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include "shape_internal.h"

/* ---- why a quick answer is shape_polygon.c's answer ---------------------------
**
** Signs.  Every value below is a tree of +, -, * over inputs, differences
** of two inputs (one rounded leaf) and the kept det3h runs of
** shape_arith.c, with the twin computed beside it; so the argument at the
** top of shape_arith.c bounds its error by (2k + 2) u t for any k at least
** the tree's rounding count, and a value beyond that bound has the exact
** value's sign (values that only choose where to look are not trusted:
** the signs the answer rests on are certified).  The counts: a
** difference 1; cross(e, d) and w = cross(P - A, e) (two products of
** differences, one subtraction) 5; cross(e_i, e_j) 5; det3w = -w_B X_ik +
** w_C X_ij, 13; det4 = w_B M + w_C M' + w_P M'' (M the kept det3h, count
** at most kmax), kmax + 9.  Underflow: every site and
** shape coordinate is 0 or of magnitude at least 2^-100 (shape_quick_ready
** checks the sites, geom_polygon_check the shape), so each is a
** multiple of 2^-152 and every non-zero difference is at least 2^-152; a
** non-zero twin of a product of two differences is at least 2^-304, a
** det3h twin at least 2^-504 (its products multiply two differences by an
** h of twin at least 2^-200), and every product in these trees whose
** factors' twins are non-zero has twin at least 2^-808 > 2^-1000: none
** underflows (the kept runs are checked unpoisoned).  Overflow makes a
** value or twin infinite or NaN, whose comparison fails: the sign is
** uncertain.
**
** Decisions.  shape_polygon.c reads every predicate under the perturbation (the
** value's sign, or the eps coefficient's when the value is 0).  A certain
** sign is non-zero, so it is the perturbed sign too; each step below then
** gives shape_polygon.c's result:
** - support(P, Q) is the start s of the first edge not before Q - P: the
**   perturbed cross(e_j, Q - P) changes sign from + to - exactly once
**   going round the edges (it is never 0, P != Q), from e_{s-1} to e_s,
**   so a certain + at s - 1 and a certain - at s find it, whatever search
**   shape_polygon.c uses.
** - The contact triple: a triple t whose det3h is not 0, whose det3w has
**   det3h's sign (s > 0) and whose slacks (each point against the two
**   edges next to its own) are certainly positive, but for those that
**   shape_polygon.c's contact test skips because it proves them positive under the
**   perturbation (above shape_contact_ok), passes that test, with all six
**   perturbed slacks positive.  Every passing triple gives the same
**   homothet H (of the turned shape), and each point lies strictly inside
**   its edge of H (both neighbouring slacks positive), so on no other
**   edge: t is the only passing triple, the one shape_polygon.c's search returns.
**   How the quick search reaches t does not matter.
** - D: shape_polygon.c answers AC at the first arc edge (from C's contact edge to
**   A's) with a negative slack, else BD when none is 0; the same edges in
**   the same order, each certain, give the same answer. */

/* The sign pattern of cross(e_j, d) for every d in one open octant: bit j
** of pos (neg) when that sign is + (-) throughout, the other edges in var
** (nvar of them).  Entry i's certain sign c of cross(e_var[i], d) sets the
** bits of plus[i] in pos (c > 0) or neg (c < 0) and those of minus[i] the
** other way: minus[i] holds an edge whose rounded direction is exactly
** -e_var[i], whose computed cross product is then exactly -c's, with the
** same twin, so its own certain sign (centrally symmetric shapes: one
** cross for both).  When the octants leave at most SHAPE_Q_TAB open entries
** (vmax), tab holds the support for every pattern of their signs (-1, 0 or
** 1 each, uncertain 0 too: the base-3 number of the signs plus one, entry
** 0 first), worked out once by the same masks. */
#define SHAPE_Q_TAB 3
typedef struct shape_q_oct {
  uint32_t pos, neg;
  int nvar;
  unsigned char var[32];  /* padded to the shape's vmax with edge 0 ... */
  uint32_t plus[32], minus[32];   /* ... whose masks here are 0 */
  signed char tab[27];    /* 3^SHAPE_Q_TAB */
} shape_q_oct;

typedef struct shape_quick {
  int n;
  double *ex, *ey;       /* edge i's direction fl(k_{i+1} - k_i) */
  double *xv, *xt;       /* cross(e_i, e_j) and its twin, [i n + j] */
  shape_memo_flat_view m;
  double bdet4;          /* (2 (kmax + 9) + 2) u */
  double *gx, *gy;       /* edge i's outward normal over its support from the centroid, */
                         /* twice over (i and i + n: a range is read without wrapping) */
  double *dgx, *dgy;     /* g_{i+1} - g_i (i + 1 mod n: a range of two edges) */
  shape_q_oct oct[9];    /* the signs fixed in each open octant (shape_q_octants); */
                         /* 8: a boundary ray's, none fixed, every edge open */
  int vmax;              /* the most edges an octant leaves open */
  unsigned char nb[2][32];   /* edge i's neighbours: [0] i - 1, [1] i + 1 (mod n) */
} shape_quick;

#define SHAPE_Q_U 0x1p-53
#define SHAPE_Q_BCROSS (12 * SHAPE_Q_U)   /* count 5 */
#define SHAPE_Q_BDET3W (28 * SHAPE_Q_U)   /* count 13 */

void shape_quick_free(shape *k) {
  shape_quick *q = k->impl->quick;
  if (q == NULL) return;
  free(q->ex);
  free(q->xv);
  free(q);
  k->impl->quick = NULL;
}

/* The support where a sign pattern changes from + at s - 1 to - at s (the
** bit of (pos turned by one) & neg, at most one: below), or -1. */
static int shape_q_change(uint32_t pos, uint32_t neg, int n) {
  uint32_t full = (1u << n) - 1;
  uint32_t change = (pos << 1 | pos >> (n - 1)) & full & neg;
  return change ? __builtin_ctz(change) : -1;
}

/* Entry i's certain sign c (0: not certain) into the sign words. */
static inline void shape_q_apply(const shape_q_oct *w, int i, int c, uint32_t *pos,
                                 uint32_t *neg) {
  uint32_t gt = -(uint32_t)(c > 0), lt = -(uint32_t)(c < 0);
  *pos |= (gt & w->plus[i]) | (lt & w->minus[i]);
  *neg |= (lt & w->plus[i]) | (gt & w->minus[i]);
}

/* w's support for every sign pattern of its first vmax entries. */
static void shape_q_table(shape_q_oct *w, int vmax, int n) {
  int count = 1;
  for (int i = 0; i < vmax; i++) count *= 3;
  for (int idx = 0; idx < count; idx++) {
    uint32_t pos = w->pos, neg = w->neg;
    for (int i = vmax - 1, rest = idx; i >= 0; i--, rest /= 3)
      shape_q_apply(w, i, rest % 3 - 1, &pos, &neg);
    w->tab[idx] = (signed char)shape_q_change(pos, neg, n);
  }
}

/* Leave edge j open in w: its own entry, or the minus side of an entry
** whose edge is its exact opposite. */
static void shape_q_open(const shape_quick *q, shape_q_oct *w, int j) {
  for (int i = 0; i < w->nvar; i++)
    if (w->minus[i] == 0 && q->ex[w->var[i]] == -q->ex[j] && q->ey[w->var[i]] == -q->ey[j]) {
      w->minus[i] = 1u << j;
      return;
    }
  w->plus[w->nvar] = 1u << j;
  w->var[w->nvar++] = (unsigned char)j;
}

/* ---- octant windows ------------------------------------------------------
**
** The open octant o = 4 (dx < 0) + 2 (dy < 0) + (|dy| > |dx|) is the open
** cone spanned by its two boundary rays r1 = (sx, 0) or (0, sy) and r2 =
** (sx, sy), s the signs: any d in it is a r1 + b r2 with a, b > 0 (a =
** ||dx| - |dy||, b the smaller of |dx|, |dy|).  cross(e_j, d) is linear in
** d, so when the exact cross(e_j, r1) and cross(e_j, r2) are both >= 0
** (both <= 0), not both 0 (r1, r2 are independent and e_j != 0), it is > 0
** (< 0) for every d of the octant: an exact sign, the perturbed one too,
** known before d is.  Only the other edges, whose direction lies inside
** the octant or its opposite, need a cross product; the square needs none
** and a regular hexagon one (two edges, one the other's opposite).  d on a
** boundary ray (dx = 0, dy = 0 or |dx| = |dy|) takes every edge.  The
** octant is read off the rounded differences, and it is the exact d's:
** rounding is monotone and odd, so fl(dx) has dx's sign and |fl(dx)| >
** |fl(dy)| implies |dx| > |dy|. */
static void shape_q_octants(const shape *k, shape_quick *q) {
  for (int o = 0; o < 8; o++) {
    double sx = o & 4 ? -1 : 1, sy = o & 2 ? -1 : 1;
    geom_point r1 = o & 1 ? (geom_point){0, sy} : (geom_point){sx, 0}, r2 = {sx, sy};
    shape_q_oct *w = &q->oct[o];
    *w = (shape_q_oct){.nvar = 0};
    for (int j = 0; j < k->n; j++) {
      shape_args g1 = {.K = k, .e = {j}, .p = {{0, 0}, r1}}, g2 = g1;
      g2.p[1] = r2;
      int c1 = shape_sign(SHAPE_PROG_CROSS, &g1), c2 = shape_sign(SHAPE_PROG_CROSS, &g2);
      if (c1 >= 0 && c2 >= 0) w->pos |= 1u << j;
      else if (c1 <= 0 && c2 <= 0) w->neg |= 1u << j;
      else shape_q_open(q, w, j);
    }
    q->vmax = w->nvar > q->vmax ? w->nvar : q->vmax;
  }
  for (int o = 0; o < 8 && q->vmax <= SHAPE_Q_TAB; o++) shape_q_table(&q->oct[o], q->vmax, k->n);
  shape_q_oct *all = &q->oct[8];
  *all = (shape_q_oct){.nvar = 0};
  for (int j = 0; j < k->n; j++) shape_q_open(q, all, j);
}

int shape_quick_build(shape *k) {
  shape_memo_flat_view m;
  /* (shape_q_support keeps one bit per edge in a 32-bit word) */
  if (k->n > 32 || shape_memo_flat(k, &m) != 0) return 0;
  int n = k->n;
  shape_quick *q = calloc(1, sizeof *q);
  double *e = malloc(8 * (size_t)n * sizeof *e), *x = malloc(2 * (size_t)n * (size_t)n * sizeof *x);
  if (q == NULL || e == NULL || x == NULL) {
    free(q);
    free(e);
    free(x);
    return -1;
  }
  *q = (shape_quick){.n = n, .ex = e, .ey = e + n, .gx = e + 2 * n, .gy = e + 4 * n,
                     .dgx = e + 6 * n, .dgy = e + 7 * n,
                     .xv = x, .xt = x + n * n, .m = m,
                     .bdet4 = (2.0 * (m.kmax + 9) + 2) * SHAPE_Q_U};
  double cx = 0, cy = 0;
  for (int i = 0; i < n; i++) {
    q->ex[i] = k->v[(i + 1) % n].x - k->v[i].x;
    q->ey[i] = k->v[(i + 1) % n].y - k->v[i].y;
    cx += k->v[i].x / n;
    cy += k->v[i].y / n;
  }
  for (int i = 0; i < n; i++) {
    q->nb[0][i] = (unsigned char)(i == 0 ? n - 1 : i - 1);
    q->nb[1][i] = (unsigned char)(i == n - 1 ? 0 : i + 1);
  }
  for (int i = 0; i < n; i++) {
    /* the vertex average is inside K, so every support from it is > 0 */
    double h = q->ey[i] * (k->v[i].x - cx) - q->ex[i] * (k->v[i].y - cy);
    q->gx[i] = q->gx[i + n] = q->ey[i] / h;
    q->gy[i] = q->gy[i + n] = -q->ex[i] / h;
  }
  for (int i = 0; i < n; i++) {
    q->dgx[i] = q->gx[i + 1] - q->gx[i];
    q->dgy[i] = q->gy[i + 1] - q->gy[i];
  }
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) {
      q->xv[i * n + j] = q->ex[i] * q->ey[j] - q->ey[i] * q->ex[j];
      q->xt[i * n + j] = fabs(q->ex[i] * q->ey[j]) + fabs(q->ey[i] * q->ex[j]);
    }
  shape_q_octants(k, q);
  k->impl->quick = q;
  return 0;
}

int shape_quick_ready(const shape *k, const geom_point p[4]) {
  if (!shape_quick_on(k)) return 0;
  int ok = 1;
  for (int r = 0; r < 4; r++) {
    double x = fabs(p[r].x), y = fabs(p[r].y);
    ok &= ((x == 0) | (x >= 0x1p-100)) & ((y == 0) | (y >= 0x1p-100));
  }
  return ok;
}

/* The certain sign of a value v with twin t and bound factor b, or 0. */
static inline int shape_q_sign(double v, double t, double b) {
  double bound = b * t;
  return (v > bound) - (-v > bound);
}

/* The certain sign of cross(e_j, (dx, dy)), or 0. */
static inline int shape_q_cross(const shape_quick *q, int j, double dx, double dy) {
  double a = q->ex[j] * dy, b = q->ey[j] * dx;
  return shape_q_sign(a - b, fabs(a) + fabs(b), SHAPE_Q_BCROSS);
}

/* support(P, Q) for (dx, dy) = Q - P: the s where cross(e_j, Q - P)
** changes sign from + at s - 1 to - at s, or -1 when a sign there is not
** certain.  Only shapes of at most SHAPE_MEMO_MAX = 16 edges have a quick
** table, so every sign fits one word: bit j of pos (neg) is a certain +
** (-) of cross(e_j, d), the octant's fixed signs (shape_q_octants) and a
** certified cross product for each edge it leaves open, and support s is
** the bit of (pos turned by one) & neg, a certain + at s - 1 and - at s.
** Certain signs are exact, and the exact signs change from + to - once, so
** there is at most one such bit; none: uncertain.  o: the octant of
** (dx, dy), 8 on a boundary ray (shape_q_octant). */
static int shape_q_support_open(const shape_quick *q, int o, double dx, double dy) {
  const shape_q_oct *w = &q->oct[o];
  /* an octant takes vmax crosses, the padding's ignored: the count is the
  ** shape's, so the loop's branch is predicted (a ray, rare, takes every
  ** edge); with few, the signs index the octant's table */
  if (o < 8 && q->vmax <= SHAPE_Q_TAB) {
    int idx = 0;
    for (int i = 0; i < q->vmax; i++) idx = 3 * idx + 1 + shape_q_cross(q, w->var[i], dx, dy);
    return w->tab[idx];
  }
  int open = o == 8 ? w->nvar : q->vmax;
  uint32_t pos = w->pos, neg = w->neg;
  for (int i = 0; i < open; i++)
    shape_q_apply(w, i, shape_q_cross(q, w->var[i], dx, dy), &pos, &neg);
  return shape_q_change(pos, neg, q->n);
}

/* The open octant of (dx, dy), or 8 on a boundary ray (rare: no branches
** for it). */
static inline int shape_q_octant(double dx, double dy) {
  double ax = fabs(dx), ay = fabs(dy);
  int ray = (dx == 0) | (dy == 0) | (ax == ay);
  return ray ? 8 : (dx < 0) << 2 | (dy < 0) << 1 | (ay > ax);
}

/* A shape whose octants leave at most one edge open (vmax <= 1: the
** square, the diamond, the triangle, the regular hexagon and octagon) reads
** an off-ray support from the table after at most one cross product,
** written out here (its three supports are a sixth of an ES LOT); the rest
** take shape_q_support_open. */
static inline int shape_q_support(const shape_quick *q, double dx, double dy) {
  int o = shape_q_octant(dx, dy);
  if (o == 8 || q->vmax > 1) return shape_q_support_open(q, o, dx, dy);
  const shape_q_oct *w = &q->oct[o];
  return w->tab[q->vmax ? 1 + shape_q_cross(q, w->var[0], dx, dy) : 0];
}

int shape_quick_supports(const shape *k, const geom_point p[3], int sup[3]) {
  const shape_quick *q = k->impl->quick;
  sup[0] = shape_q_support(q, p[1].x - p[0].x, p[1].y - p[0].y);
  sup[1] = shape_q_support(q, p[2].x - p[1].x, p[2].y - p[1].y);
  sup[2] = shape_q_support(q, p[0].x - p[2].x, p[0].y - p[2].y);
  return (sup[0] | sup[1] | sup[2]) < 0 ? -1 : 0;
}

/* ---- the homothet ---------------------------------------------------------
**
** Rows (e, h, w) of (t0, A), (t1, B), (t2, C), w relative to A: w_A = 0,
** so det3w = -w_B cross(e_t0, e_t2) + w_C cross(e_t0, e_t1) and, for a
** fourth row (m, P), det4 = w_B M(t0, t2, m) - w_C M(t0, t1, m) + w_P
** M(t0, t1, t2) (shape_arith.c's expansions, with the origin A: a column
** operation, the same determinants). */

typedef struct shape_q_tri {
  const shape_quick *q;
  int t[3], d3;
  double ax, ay;           /* A */
  double wb, wbt, wc, wct; /* w_B, w_C and their twins */
  const double *m1, *m1t, *m2, *m2t;   /* M(t0, t2, .), M(t0, t1, .) and twins */
  double m3, m3t;          /* M(t0, t1, t2) */
} shape_q_tri;

/* w = cross(P - A, e_j) and its twin. */
static inline double shape_q_w(const shape_q_tri *T, int j, geom_point p, double *tw) {
  double dx = p.x - T->ax, dy = p.y - T->ay;
  double a = dx * T->q->ey[j], b = dy * T->q->ex[j];
  *tw = fabs(a) + fabs(b);
  return a - b;
}

/* The certain sign of P's slack c_m - n_m.P on edge m, or 0. */
static FLIPLAB_ALWAYS_INLINE int shape_q_slack(const shape_q_tri *T, int m, geom_point p) {
  double wpt, wp = shape_q_w(T, m, p, &wpt);
  double v = T->wb * T->m1[m] - T->wc * T->m2[m] + wp * T->m3;
  double tw = T->wbt * T->m1t[m] + T->wct * T->m2t[m] + wpt * T->m3t;
  return -shape_q_sign(v, tw, T->q->bdet4) * T->d3;
}

/* Triple T->t's determinants: det3h's sign (0: no triple) and the rows of M. */
static FLIPLAB_ALWAYS_INLINE void shape_q_rows(shape_q_tri *T) {
  const shape_quick *q = T->q;
  size_t n = (size_t)q->n, b1 = ((size_t)T->t[0] * n + (size_t)T->t[2]) * n;
  size_t b2 = ((size_t)T->t[0] * n + (size_t)T->t[1]) * n;
  T->m1 = q->m.val + b1, T->m1t = q->m.twin + b1;
  T->m2 = q->m.val + b2, T->m2t = q->m.twin + b2;
  T->m3 = T->m2[T->t[2]], T->m3t = T->m2t[T->t[2]];
  T->d3 = q->m.sgn[b2 + (size_t)T->t[2]];
}

/* ---- which checks a contact triple needs ---------------------------------
**
** shape_polygon.c's contact test checks each point against both neighbours of its
** contact edge.  Here only the neighbours inside the point's own range are
** checked (the movable bits): the others follow.  Say A's contact edge t0
** is the first of its range, t0 = s_CA, so its previous edge m = t0 - 1 is
** the last of C's range, and C's contact t2 is m or before it there.  For
** any X, n_m.X = cross(X, e_m), so A's slack on m is
**   c_m - n_m.A = (c_m - n_m.C) + cross(e_m, A - C),
** and cross(e_m, A - C) > 0 is the support s_CA itself (its + at s - 1).
** c_m - n_m.C >= 0: when t2 = m, C is on that edge line (0); otherwise C
** lies on the line of t2 on the inner side of edge t2 + 1 (a checked
** neighbour: t2 + 1 <= m is in C's range), so on the ray of that line from
** H's vertex t2 + 1 backwards; the vertex is in H, and going back along
** e_t2 changes n_m.X by -cross(e_t2, e_m) < 0 (e_m turns from e_t2 by more
** than 0 and less than pi: the directions of a range lie within the
** triangle's exterior angle at its point), so the ray stays inside edge m.
** The last edge of a range and the next point's range are the mirror
** image (s_AB's - at s).  This is exact geometry under the perturbation
** (every sign used is a perturbed sign: the certified supports and slacks
** are), so the triple passing these checks passes shape_polygon.c's six; and a
** range never holds another point's contact edge, so shape_polygon.c's settled
** checks are all among those left out. */

/* Test triple T->t: 1 when it is the contact triple, 0 with *move set to
** the first violation (point r beyond its edge's neighbour on side side,
** bit 2 r + (side > 0)), or -1 (a sign uncertain, no homothet with s > 0).
** Only the neighbours in movable (those in the point's range) are tested:
** the others follow (above). */
static FLIPLAB_ALWAYS_INLINE int shape_q_contact(shape_q_tri *T, const geom_point p[3],
                                                  int movable, int *move) {
  const shape_quick *q = T->q;
  int n = q->n, *t = T->t;
  shape_q_rows(T);
  if (T->d3 == 0) return -1;
  T->wb = shape_q_w(T, t[1], p[1], &T->wbt);
  T->wc = shape_q_w(T, t[2], p[2], &T->wct);
  double v = -T->wb * q->xv[t[0] * n + t[2]] + T->wc * q->xv[t[0] * n + t[1]];
  double tw = T->wbt * q->xt[t[0] * n + t[2]] + T->wct * q->xt[t[0] * n + t[1]];
  if (shape_q_sign(v, tw, SHAPE_Q_BDET3W) != T->d3) return -1;
  for (; movable != 0; movable &= movable - 1) {
    int bit = __builtin_ctz((unsigned)movable), r = bit >> 1;
    int s = shape_q_slack(T, q->nb[bit & 1][t[r]], p[r]);
    if (s == 0) return -1;
    if (s < 0) {
      *move = bit;
      return 0;
    }
  }
  return 1;
}

/* The contact triple into T: from the middles of the ranges, each failed
** test moves the first violating point that can stay in its range one edge
** towards the edge it lies beyond; 0, or -1 (uncertain, stalled, too many
** steps). */
/* Where the walk starts: on a circle, the point of contact faces away from
** the centre, so in a range of two edges or more each point starts on the
** edge whose outward normal, scaled by its support (the gauge of K), is
** largest at P - O, O the circumcentre of ABC, the guessed centre of H.
** O = A + (u, v) / 2d with d = cross(B - A, C - A) > 0, so the largest of
** g.(2d (P - A) - (u, v)) is the same edge, without a division; of two
** edges, the sign of (g_{i+1} - g_i).(...) chooses.  A guess only (the
** walk and the contact test decide). */
static void shape_q_guess(const shape_quick *q, const geom_point p[3], const int start[3],
                          const int len[3], int off[3]) {
  double bx = p[1].x - p[0].x, by = p[1].y - p[0].y, cx = p[2].x - p[0].x, cy = p[2].y - p[0].y;
  double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy, d2 = 2 * (bx * cy - by * cx);
  double u = b2 * cy - c2 * by, v = c2 * bx - b2 * cx;
  for (int r = 0; r < 3; r++) {
    if (len[r] < 2) continue;
    double dx = d2 * (p[r].x - p[0].x) - u, dy = d2 * (p[r].y - p[0].y) - v, best = -INFINITY;
    if (len[r] == 2) {
      off[r] = q->dgx[start[r]] * dx + q->dgy[start[r]] * dy > 0;
      continue;
    }
    int at = 0;
    const double *gx = q->gx + start[r], *gy = q->gy + start[r];
    for (int i = 0; i < len[r]; i++) {
      double g = gx[i] * dx + gy[i] * dy;
      int better = g > best;   /* selects, not branches: the outcome is a coin toss */
      best = better ? g : best;
      at = better ? i : at;
    }
    off[r] = at;
  }
}

static int shape_q_contacts(const shape *k, shape_q_tri *T, const int sup[3],
                            const geom_point p[3]) {
  int n = T->q->n, start[3] = {sup[2], sup[0], sup[1]}, len[3], off[3] = {0, 0, 0};
  for (int r = 0; r < 3; r++) len[r] = shape_range(k, start[r], sup[r]);
  if (len[0] > 1 || len[1] > 1 || len[2] > 1) shape_q_guess(T->q, p, start, len, off);
  int movable = 0;
  for (int r = 0; r < 3; r++) {
    T->t[r] = start[r] + off[r] < n ? start[r] + off[r] : start[r] + off[r] - n;
    movable |= (off[r] > 0) << 2 * r | (off[r] + 1 < len[r]) << (2 * r + 1);
  }
  for (int step = 0; step < 2 * n; step++) {
    int move = 0, ok = shape_q_contact(T, p, movable, &move);
    if (ok != 0) return ok > 0 ? 0 : -1;
    /* only the moved point's edge and its two bits change */
    int r = move >> 1, up = move & 1;
    off[r] += up ? 1 : -1;
    T->t[r] = T->q->nb[up][T->t[r]];
    movable &= ~(3 << 2 * r);
    movable |= (off[r] > 0) << 2 * r | (off[r] + 1 < len[r]) << (2 * r + 1);
  }
  return -1;
}

/* D's slack on an edge of the arc from C's contact edge t2 to A's t0.  On
** the two ends no determinant is needed: C is on edge line t2, so c_t2 -
** n_t2.D = n_t2.(C - D) = cross(e_t2, D - C), and likewise cross(e_t0, D -
** A) on t0 (n_m.X = cross(X, e_m)); the settled checks of shape_polygon.c's contact
** test are the same identity, and both are certified as the supports are
** (one rounded difference, count 5). */
static FLIPLAB_ALWAYS_INLINE int shape_q_dslack(const shape_q_tri *T, int m,
                                                 const geom_point p[4]) {
  if (m == T->t[2]) return shape_q_cross(T->q, m, p[3].x - p[2].x, p[3].y - p[2].y);
  if (m == T->t[0]) return shape_q_cross(T->q, m, p[3].x - p[0].x, p[3].y - p[0].y);
  return shape_q_slack(T, m, p[3]);
}

/* D against the homothet of contact triple T->t: shape_polygon.c's arc walk. */
static FLIPLAB_ALWAYS_INLINE int shape_q_dtest(const shape_q_tri *T, const geom_point p[4]) {
  for (int m = T->t[2];; m = T->q->nb[1][m]) {
    int s = shape_q_dslack(T, m, p);
    if (s == 0) return -1;
    if (s < 0) return SHAPE_AC;
    if (m == T->t[0]) return SHAPE_BD;
  }
}

int shape_quick_homothet(const shape *k, const int sup[3], const geom_point p[4], int t[3]) {
  shape_q_tri T;
  T.q = k->impl->quick, T.ax = p[0].x, T.ay = p[0].y;
  if (shape_q_contacts(k, &T, sup, p) != 0) return -1;
  int ans = shape_q_dtest(&T, p);
  for (int r = 0; r < 3; r++) t[r] = T.t[r];
  return ans;
}

/* With t known to be the contact triple (a hint: shape_decide_hinted),
** only the rows the slacks read are set up; the contact test is not
** repeated, its sign of det3w having been certain when t was found. */
int shape_quick_at(const shape *k, const int t[3], const geom_point p[4]) {
  shape_q_tri T = {.q = k->impl->quick, .t = {t[0], t[1], t[2]}, .ax = p[0].x, .ay = p[0].y};
  shape_q_rows(&T);
  if (T.d3 == 0) return -1;
  T.wb = shape_q_w(&T, t[1], p[1], &T.wbt);
  T.wc = shape_q_w(&T, t[2], p[2], &T.wct);
  return shape_q_dtest(&T, p);
}

/* ---- the rounding shape ---------------------------------------------------
**
** shape_arith.c's corner program with o = D: u = e_c, v = k_{c-1} - k_c =
** -e_{c-1} (a rounded difference is odd in its order), d = P - D, X =
** cross(d, v), Y = cross(u, d) (count 5), rows (X Y, X, Y) of A, B, C
** (count 12 for X Y) and their det3, m0 (m4 m8 - m5 m7) - m1 (m3 m8 - m5 m6)
** + m2 (m3 m7 - m4 m6): inner counts 13, 20, 20, products 27, total 29.
** Degree 8 in differences, so the underflow argument above does not cover
** the three outer products (their twins may fall to 2^-1216): one below
** 2^-1000 makes the sign uncertain; the inner ones have twins of at least
** 2^-912.  A certain sign is the perturbed one, shape_corner_decide's. */
#define SHAPE_Q_BCORNER (60 * SHAPE_Q_U)

int shape_quick_corner(const shape *k, int c, const geom_point p[4]) {
  const shape_quick *q = k->impl->quick;
  int b = c > 0 ? c - 1 : q->n - 1;
  double ux = q->ex[c], uy = q->ey[c], vx = -q->ex[b], vy = -q->ey[b];
  double X[3], Xt[3], Y[3], Yt[3], Z[3], Zt[3];
  for (int r = 0; r < 3; r++) {
    double dx = p[r].x - p[3].x, dy = p[r].y - p[3].y;
    double a = dx * vy, e = dy * vx, f = ux * dy, g = uy * dx;
    X[r] = a - e, Xt[r] = fabs(a) + fabs(e);
    Y[r] = f - g, Yt[r] = fabs(f) + fabs(g);
    Z[r] = X[r] * Y[r], Zt[r] = Xt[r] * Yt[r];
  }
  double c0 = X[1] * Y[2] - Y[1] * X[2], c0t = Xt[1] * Yt[2] + Yt[1] * Xt[2];
  double c1 = Z[1] * Y[2] - Y[1] * Z[2], c1t = Zt[1] * Yt[2] + Yt[1] * Zt[2];
  double c2 = Z[1] * X[2] - X[1] * Z[2], c2t = Zt[1] * Xt[2] + Xt[1] * Zt[2];
  double t0 = Zt[0] * c0t, t1 = Xt[0] * c1t, t2 = Yt[0] * c2t;
  if (t0 < 0x1p-1000 || t1 < 0x1p-1000 || t2 < 0x1p-1000) return 2;
  int s = shape_q_sign(Z[0] * c0 - X[0] * c1 + Y[0] * c2, t0 + t1 + t2, SHAPE_Q_BCORNER);
  return s != 0 ? s : 2;
}
