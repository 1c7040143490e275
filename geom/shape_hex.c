/*
** shape_hex.c: the empty-hexagon rule of an affinely regular hexagon (the
** `hexagon`, or any centrally symmetric hexagon whose middle edge is the
** sum of its neighbours) decided in its three slab coordinates, as the
** square's is by bounding boxes (shape_square.c): sums and comparisons of
** nine values instead of supports and a contact search.  Each comparison is
** filtered by one bound per decision; a corner's rounding shape goes to the
** quick corner test (shape_quick.c); where a comparison is too close to
** call it gives up and the general path decides, so every answer is the
** general path's.
*/
#include <math.h>
#include "shape_internal.h"

/* ---- the geometry ------------------------------------------------------
**
** With edges e0, e1, e2 = e1 - e0 (exactly) and e_{i+3} = -e_i, the
** functionals a = cross(X, e0), b = cross(X, e1), c = cross(X, e2) (the
** outward normals of edges 0, 1, 2 applied to X) satisfy b = a + c, and
** every homothet of K is {X : |a(X) - ta| <= r, |b(X) - tb| <= r,
** |c(X) - tc| <= r} with tb = ta + tc: three slabs of one width 2r (an
** affine image of the regular hexagon has one width in every direction of
** its edges).  Edge 0 is the side a = ta + r, edge 3 a = ta - r, and so on.
**
** Of A, B, C, let hi_i and lo_i be the largest and least value of slab i,
** W_i = hi_i - lo_i.  A homothet through A, B, C has each on a side, and
** either (1) one side of every slab touched, at the extreme on that side
** (signs s_i: + for hi, - for lo), by three different points: then
** t_i = e_i - s_i r (e_i the touched extreme), and tb = ta + tc gives
** r (s_a + s_c - s_b) = e_a + e_c - e_b, k = s_a + s_c - s_b in {+-1, +-3};
** it holds the three exactly when 2r >= W_i for every slab (the side
** opposite each touched one is then beyond the other extreme); or (2) both
** sides of one slab i touched (r = W_i / 2, so i is the widest, and strictly
** for a generic triangle) by two points and the third, Q, on a side of
** another slab j at Q's extreme there: t_i = (hi_i + lo_i) / 2,
** t_j = e_j - s r, the third slab's t from tb = ta + tc, and it holds the
** three when that slab's extremes are within r of its t.  Two sides of one
** slab and one of each other would put a point on two sides: a corner.
** A candidate that certainly holds the three with them on its boundary is
** a homothet through A, B, C, and there is at most one (docs/emptyshape.md),
** so it is the circumscribing shape.  None: the triangle's shape is a
** corner's rounding shape (or the case is too close to call): left to the
** general path.  D is strictly inside when |d_i - t_i| < r for every slab.
**
** Exactness.  A, B, C, D are taken relative to A: dx = fl(X - A), and each
** value fl(fl(dx e_y) - fl(dy e_x)) has error at most 3 u (|dx e_y| +
** |dy e_x|) (1 + 2 u) (three roundings on each path, the edge components
** being exact: shape_hex_is checks), so at most 4 u S with S = (|dx| + |dy|)
** emax over the points, emax the edges' largest coordinate (S as computed
** is within two roundings of that).  Every comparison below is the sign of
** an integer combination of the values with total coefficient magnitude at
** most 12 (the widest: 2 r m - m W_i and r m - |d_i m - t_i m| of case (1),
** m = 3), evaluated in at most 10 roundings of partial sums at most 12 S in
** magnitude: its error is at most 12 (4 u S) + 10 u (12 S) (1 + u)^10 <
** 2^8 u S.  A sign is taken only beyond 2^-40 S = 2^13 u S; nearer, it
** gives up.  D's values join S for D's own comparisons.  In the coordinate
** contract (docs/scale.md) no product underflows (a non-zero difference of
** two coordinates is at least 2^-152, so a non-zero product at least
** 2^-304) or overflows. */

typedef struct shape_hex_case {
  double v[4][3];     /* the slab values of A (0), B, C, D, relative to A */
  double hi[3], lo[3], w[3];
  int ihi[3], ilo[3];
  double eps;         /* the bound: a value beyond it has its exact sign */
  double sd;          /* D's share of the bound's scale */
  int edge[3];        /* the shape found: the contact edges of A, B, C */
} shape_hex_case;

/* The certain sign of x under the bound eps, or 0. */
static inline int shape_hex_sign(double eps, double x) {
  return (x > eps) - (x < -eps);
}

/* The values of p - A into v; returned, the scale of their errors:
** (|dx| + |dy|) emax >= |dx e_y| + |dy e_x| (emax: the edges' largest
** coordinate magnitude). */
static inline double shape_hex_values(const shape *k, geom_point a, geom_point p, double v[3]) {
  double dx = p.x - a.x, dy = p.y - a.y;
  for (int i = 0; i < 3; i++) v[i] = dx * k->hex[i].y - dy * k->hex[i].x;
  return (fabs(dx) + fabs(dy)) * k->hexmax;
}

/* D's answer against the homothet t (times m) and r (times m), m > 0:
** SHAPE_BD, SHAPE_AC, or -1.  Its bound covers D's values too. */
static inline int shape_hex_dtest(const shape_hex_case *h, const double t[3], double r, double m) {
  double eps = h->sd > h->eps ? h->sd : h->eps;
  int in = 1, out = 0;
  for (int i = 0; i < 3; i++) {
    double u = h->v[3][i] * m - t[i];
    int up = shape_hex_sign(eps, r - u), down = shape_hex_sign(eps, r + u);
    out |= (up < 0) | (down < 0);
    in &= (up > 0) & (down > 0);
  }
  return out ? SHAPE_AC : in ? SHAPE_BD : -1;
}

/* Case (1), touched sides c (bit i set: the lo side of slab i, else hi),
** whose points are known to be three: the answer, or -1 when this is not
** certainly the shape. */
static int shape_hex_sides(shape_hex_case *h, int c) {
  double e[3], t[3], s[3];
  for (int i = 0; i < 3; i++) {
    int lo = c >> i & 1;
    s[i] = lo ? -1 : 1;
    e[i] = lo ? h->lo[i] : h->hi[i];
  }
  double k = s[0] + s[2] - s[1], m = fabs(k);
  double r = (e[0] + e[2] - e[1]) * (k < 0 ? -1 : 1);   /* r m */
  for (int i = 0; i < 3; i++)
    if (shape_hex_sign(h->eps, 2 * r - m * h->w[i]) <= 0) return -1;
  for (int i = 0; i < 3; i++) {
    t[i] = e[i] * m - s[i] * r;
    h->edge[c >> i & 1 ? h->ilo[i] : h->ihi[i]] = (c >> i & 1) * 3 + i;
  }
  return shape_hex_dtest(h, t, r, m);
}

/* Case (2) with slab i the widest (certainly): the answer, or -1. */
static int shape_hex_wide(shape_hex_case *h, int i) {
  int q = 3 - h->ihi[i] - h->ilo[i];
  double r = h->w[i];   /* 2 r, and every t below doubled */
  for (int n = 1; n <= 2; n++) {
    /* q on side s of the next slab j, if it is the extreme of one */
    int j = i + n >= 3 ? i + n - 3 : i + n, s = (h->ihi[j] == q) - (h->ilo[j] == q);
    if (s == 0) continue;
    double t[3];
    t[i] = h->hi[i] + h->lo[i];
    t[j] = 2 * (s > 0 ? h->hi[j] : h->lo[j]) - s * r;
    int o = 3 - i - j;   /* tb = ta + tc: slab 1 is the sum of 0 and 2 */
    t[o] = o == 1 ? t[0] + t[2] : t[1] - t[2 - o];
    int above = shape_hex_sign(h->eps, t[o] + r - 2 * h->hi[o]) > 0;
    int below = shape_hex_sign(h->eps, 2 * h->lo[o] - t[o] + r) > 0;
    if (above & below) {   /* both made: no branch between them */
      h->edge[h->ihi[i]] = i, h->edge[h->ilo[i]] = i + 3, h->edge[q] = s > 0 ? j : j + 3;
      return shape_hex_dtest(h, t, r, 2);
    }
  }
  return -1;
}

/* When a point is the extreme of no side, the triangle's shape is the
** rounding shape of the vertex where the next point's run of sides starts
** (docs/emptyshape.md: two supports coincide there).  Side 0 1 2 3 4 5 is
** slab 0 1 2 hi, then slab 0 1 2 lo. */
static int shape_hex_corner(const shape_hex_case *h) {
  int own[6];
  for (int i = 0; i < 3; i++) own[i] = h->ihi[i], own[i + 3] = h->ilo[i];
  /* runs go A, B, C anticlockwise: from P's straight to P + 2's skips P + 1 */
  for (int j = 0; j < 6; j++)
    if (own[(j + 5) % 6] == (own[j] + 1) % 3) return j;
  return -1;
}

static int shape_hex_found(const shape_hex_case *h, int ans, shape_hint *out) {
  if (ans >= 0 && out != NULL)
    *out = (shape_hint){SHAPE_HINT_HOMOTHET, {(unsigned char)h->edge[0],
                        (unsigned char)h->edge[1], (unsigned char)h->edge[2]}};
  return ans;
}

int shape_hex_decide(const shape *k, const geom_point p[4], shape_hint *out) {
  shape_hex_case h;
  for (int i = 0; i < 3; i++) h.v[0][i] = 0;
  double s = shape_hex_values(k, p[0], p[1], h.v[1]), sc = shape_hex_values(k, p[0], p[2], h.v[2]);
  h.eps = 0x1p-40 * (sc > s ? sc : s);
  h.sd = 0x1p-40 * shape_hex_values(k, p[0], p[3], h.v[3]);
  int hb[3], lb[3], has = 0;   /* has: the points extreme on some side, by bit */
  for (int i = 0; i < 3; i++) {
    double b = h.v[1][i], c = h.v[2][i];
    /* a sign too close to call: two sites on a line parallel to a side */
    if (!(fabs(b) > h.eps) | !(fabs(c) > h.eps) | !(fabs(b - c) > h.eps)) return -1;
    int pb = b > 0, pc = c > 0, bc = b > c;   /* arithmetic, not branches: coin tosses */
    h.ihi[i] = (bc & pb) | ((!bc) & pc) << 1;
    h.ilo[i] = ((!bc) & (!pb)) | (bc & (!pc)) << 1;
    h.hi[i] = h.v[h.ihi[i]][i], h.lo[i] = h.v[h.ilo[i]][i];
    h.w[i] = h.hi[i] - h.lo[i];
    hb[i] = 1 << h.ihi[i], lb[i] = 1 << h.ilo[i];
    has |= hb[i] | lb[i];
  }
  if (has != 7) {   /* a point extreme on no side: a corner's rounding shape */
    int corner = shape_hex_corner(&h), c = corner < 0 ? 2 : shape_quick_corner(k, corner, p);
    if (c != 2 && out != NULL)
      *out = (shape_hint){SHAPE_HINT_CORNER, {(unsigned char)corner, 0, 0}};
    return c == 2 ? -1 : c < 0 ? SHAPE_BD : SHAPE_AC;
  }
  /* any candidate certainly the shape is the shape: the first one wins */
  int g01 = h.w[0] > h.w[1], g02 = h.w[0] > h.w[2], g12 = h.w[1] > h.w[2];
  int i = !(g01 & g02) * (2 - ((!g01) & g12));
  if (shape_hex_sign(h.eps, h.w[i] - h.w[(i + 1) % 3]) > 0 &&
      shape_hex_sign(h.eps, h.w[i] - h.w[(i + 2) % 3]) > 0) {
    int ans = shape_hex_wide(&h, i);
    if (ans >= 0) return shape_hex_found(&h, ans, out);
  }
  for (int c = 0; c < 8; c++) {
    if (((c & 1 ? lb[0] : hb[0]) | (c & 2 ? lb[1] : hb[1]) | (c & 4 ? lb[2] : hb[2])) != 7)
      continue;   /* not three points */
    int ans = shape_hex_sides(&h, c);
    if (ans >= 0) return shape_hex_found(&h, ans, out);
  }
  return -1;
}

int shape_hex_is(shape *k) {
  if (k->kind != SHAPE_POLYGON || k->n != 6) return 0;
  geom_point e[6];
  for (int i = 0; i < 6; i++) {
    geom_point a = k->v[i], b = k->v[(i + 1) % 6];
    if (!shape_exact_diff(b.x, a.x, &e[i].x) || !shape_exact_diff(b.y, a.y, &e[i].y))
      return 0;
  }
  for (int i = 0; i < 3; i++)
    if (e[i + 3].x != -e[i].x || e[i + 3].y != -e[i].y) return 0;
  /* e1 = e0 + e2 exactly: e1 - e0 must be exact and equal e2 */
  double dx, dy;
  if (!shape_exact_diff(e[1].x, e[0].x, &dx) || !shape_exact_diff(e[1].y, e[0].y, &dy) ||
      dx != e[2].x || dy != e[2].y)
    return 0;
  k->hexmax = 0;
  for (int i = 0; i < 3; i++) {
    k->hex[i] = e[i];
    k->hexmax = fmax(k->hexmax, fmax(fabs(e[i].x), fabs(e[i].y)));
  }
  return 1;
}
