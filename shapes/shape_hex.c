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
#include <stdlib.h>
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
** being exact: shape_hex_build checks), so at most 4 u S with S the sum
** over B and C of (|dx| + |dy|) emax, emax the edges' largest coordinate
** (a sum, at least each point's term, where a max would cost a branch that
** is a coin toss; S as computed is within three roundings of it).  Every
** comparison below is the sign of an integer combination of the values
** with total coefficient magnitude at most 12 (the widest: 2 r m - m W_i
** and r m - |d_i m - t_i m| of case (1), m = 3), evaluated in at most 10
** roundings of partial sums at most 12 S in magnitude: its error is at
** most 12 (4 u S) + 10 u (12 S) (1 + u)^10 < 2^8 u S.  A sign is taken
** only beyond 2^-40 S = 2^13 u S; nearer, it gives up.  D's term joins the
** sum for D's own comparisons.  In the coordinate contract (docs/scale.md)
** no product underflows (a non-zero difference of two coordinates is at
** least 2^-152, so a non-zero product at least 2^-304) or overflows. */

/* The homothet of a contact triple t (the sides of A, B, C), from the
** values vB and vC of B and C in their sides' slabs (A's is 0): m t_0 =
** t0[0] vB + t0[1] vC, m t_2 and m r likewise (t_1 = t_0 + t_2); m = 0 when
** t fits no homothet.  Small integers, kept as floats: one instruction
** each to widen. */
typedef struct shape_hex_eq {
  float m, t0[2], t2[2], r[2];
  signed char sb, sc;      /* the slabs of B's and C's sides */
} shape_hex_eq;

/* What the order of A, B, C in the three slabs implies, by the code of
** shape_hex_decide: who is extreme where, whether a corner's rounding
** shape is the triangle's, and which candidates can hold the three. */
typedef struct shape_hex_plan {
  signed char corner;      /* -1: each point is extreme on some side; else the
                           ** corner of the rounding shape (6: none, too close) */
  unsigned char at[2][3];  /* slab i's largest (at[0]) and least (at[1]) point: 0 A, 1 B, 2 C */
  unsigned char wide[3][2];   /* slab i the widest: its middle point's two options,
                              ** bit 0 a side of slab j (bits 2-3) there, bit 1 the lo side */
  unsigned char cand[2];   /* the two case (1) candidates: bit i set, lo side of slab i */
} shape_hex_plan;

struct shape_hex {
  geom_point e[3];         /* edges 0, 1, 2 */
  double emax;             /* their largest coordinate's magnitude */
  shape_hex_plan plan[512];   /* by code */
  shape_hex_eq eq[216];    /* by t0 + 6 t1 + 36 t2 */
};

typedef struct shape_hex_case {
  double v[4][3];     /* the slab values of A (0), B, C, D, relative to A */
  double ext[2][3];   /* each slab's largest (ext[0]) and least (ext[1]) of A, B, C */
  double w[3];        /* each slab's width */
  double eps;         /* the bound: a value beyond it has its exact sign */
  double sd;          /* D's share of the bound's scale */
  const shape_hex_plan *pl;
  int edge[3];        /* the shape found: the contact edges of A, B, C */
} shape_hex_case;

/* Branches are few below: which point is where is a coin toss, so choices
** are made by tables and flags, and a branch is taken on outcomes only. */

/* The values of p - A into v; returned, the scale of their errors:
** (|dx| + |dy|) emax >= |dx e_y| + |dy e_x| (emax: the edges' largest
** coordinate magnitude). */
static inline double shape_hex_values(const shape *k, geom_point a, geom_point p, double v[3]) {
  const struct shape_hex *x = k->impl->hexa;
  double dx = p.x - a.x, dy = p.y - a.y;
  for (int i = 0; i < 3; i++) v[i] = dx * x->e[i].y - dy * x->e[i].x;
  return (fabs(dx) + fabs(dy)) * x->emax;
}

/* D's answer against the homothet t (times m) and r (times m), m > 0, from
** D's values d: SHAPE_BD, SHAPE_AC, or -1 when a comparison is within eps
** (whose scale must cover D's values too). */
static inline int shape_hex_dtest(const double d[3], const double t[3], double r, double m,
                                  double eps) {
  int in = 1, out = 0;
  for (int i = 0; i < 3; i++) {
    double u = d[i] * m - t[i], above = r - u, below = r + u;
    out |= (above < -eps) | (below < -eps);
    in &= (above > eps) & (below > eps);
  }
  /* in and out exclude each other: BD (1), AC (0) or -1, with no branch */
  return in - !(in | out);
}

/* k = s_a + s_c - s_b by the sides c of case (1) (s_i = -1 for the lo side). */
static const double shape_hex_k[8] = {1, -1, 3, 1, -1, -3, 1, -1};

/* Case (1)'s radius for sides c (a guess only: not certain). */
static inline double shape_hex_radius(const shape_hex_case *h, int c) {
  double e0 = h->ext[c & 1][0], e1 = h->ext[c >> 1 & 1][1], e2 = h->ext[c >> 2 & 1][2];
  return (e0 + e2 - e1) / shape_hex_k[c];
}

/* Case (1), touched sides c (bit i set: the lo side of slab i, else hi),
** whose points are known to be three: the answer, or -1 when this is not
** certainly the shape. */
static int shape_hex_sides(shape_hex_case *h, int c) {
  static const double sgn[2] = {1, -1};
  double e[3], t[3], k = shape_hex_k[c], m = fabs(k);
  for (int i = 0; i < 3; i++) e[i] = h->ext[c >> i & 1][i];
  double r = (e[0] + e[2] - e[1]) * sgn[k < 0];   /* r m */
  double eps = h->eps, r2 = 2 * r;
  if (!((r2 - m * h->w[0] > eps) & (r2 - m * h->w[1] > eps) & (r2 - m * h->w[2] > eps))) return -1;
  for (int i = 0; i < 3; i++) {
    int lo = c >> i & 1;
    t[i] = e[i] * m - sgn[lo] * r;
    h->edge[h->pl->at[lo][i]] = lo * 3 + i;
  }
  return shape_hex_dtest(h->v[3], t, r, m, h->sd + h->eps);
}

/* Case (2) with slab i the widest (certainly): the answer, or -1.  Both of
** the middle point's options are evaluated, then the first that holds the
** three is taken.  Slab o's t from tb = ta + tc: t_o = t_f[o] + g t_fs[o]. */
static int shape_hex_wide(shape_hex_case *h, int i) {
  static const int f[3] = {1, 0, 1}, fs[3] = {2, 2, 0};
  static const double g[3] = {-1, 1, -1}, sgn[2] = {1, -1};
  double r = h->w[i], eps = h->eps, t[2][3];   /* 2 r, and every t doubled */
  int ok[2];
  for (int n = 0; n < 2; n++) {
    int opt = h->pl->wide[i][n], j = opt >> 2, lo = opt >> 1 & 1, o = 3 - i - j;
    double *u = t[n];
    u[i] = h->ext[0][i] + h->ext[1][i];
    u[j] = 2 * h->ext[lo][j] - sgn[lo] * r;
    u[o] = u[f[o]] + g[o] * u[fs[o]];
    ok[n] = (opt & 1) & (u[o] + r - 2 * h->ext[0][o] > eps) & (2 * h->ext[1][o] - u[o] + r > eps);
  }
  if (!(ok[0] | ok[1])) return -1;
  int n = !ok[0], opt = h->pl->wide[i][n], j = opt >> 2, lo = opt >> 1 & 1;
  int top = h->pl->at[0][i], bottom = h->pl->at[1][i];
  h->edge[top] = i, h->edge[bottom] = i + 3, h->edge[3 - top - bottom] = j + 3 * lo;
  return shape_hex_dtest(h->v[3], t[n], r, 2, h->sd + h->eps);
}

/* The plan of a code (slab i's code in bits 3i .. 3i + 2: (b > 0) |
** (c > 0) << 1 | (b > c) << 2, of the values b, c of B, C; 1 and 6 cannot
** occur).  A point extreme on no side makes the triangle's shape the
** rounding shape of the vertex where the next point's run of sides starts
** (docs/emptyshape.md: two supports coincide there).  Side 0 1 2 3 4 5 is
** slab 0 1 2 hi, then slab 0 1 2 lo; runs go A, B, C anticlockwise: from
** P's straight to P + 2's skips P + 1. */
static void shape_hex_plan_of(unsigned code, shape_hex_plan *pl) {
  static const signed char top[8] = {0, -1, 2, 2, 0, 1, -1, 1};
  static const signed char bottom[8] = {1, -1, 1, 0, 2, 2, -1, 0};
  int has = 0;
  *pl = (shape_hex_plan){.corner = 6};
  for (int i = 0; i < 3; i++) {
    int c = code >> 3 * i & 7;
    if (top[c] < 0) return;
    pl->at[0][i] = (unsigned char)top[c], pl->at[1][i] = (unsigned char)bottom[c];
    has |= 1 << top[c] | 1 << bottom[c];
  }
  if (has != 7) {
    int own[6];
    for (int i = 0; i < 3; i++) own[i] = pl->at[0][i], own[i + 3] = pl->at[1][i];
    for (int j = 0; j < 6; j++)
      if (own[(j + 5) % 6] == (own[j] + 1) % 3) {
        pl->corner = (signed char)j;
        break;
      }
    return;
  }
  pl->corner = -1;
  for (int i = 0; i < 3; i++) {
    int q = 3 - pl->at[0][i] - pl->at[1][i];
    for (int n = 0; n < 2; n++) {   /* q on a side of slab j, if it is an extreme there */
      int j = (i + n + 1) % 3, hi = pl->at[0][j] == q, lo = pl->at[1][j] == q;
      pl->wide[i][n] = (unsigned char)(j << 2 | lo << 1 | (hi | lo));
    }
  }
  /* the sides of one point each: two choices always (a point on two slabs'
  ** sides leaves the third slab's other extreme for another) */
  int nc = 0;
  for (int c = 0; c < 8; c++) {
    int pts = 0;
    for (int i = 0; i < 3; i++) pts |= 1 << pl->at[c >> i & 1][i];
    if (pts == 7 && nc < 2) pl->cand[nc++] = (unsigned char)c;
  }
  if (nc < 2) pl->corner = 6;   /* never, by the count above */
}

/* The circumscribing homothet of A, B, C and D's answer against it, or -1.
** Any candidate certainly the shape is the shape, so the order of the tries
** is a guess.  A homothet holding A, B, C has r >= W_i / 2 in every slab;
** the widest slab's (case (2), r = W_i / 2) is the least, so when a case
** (1) triple's radius exceeds that it is the likely shape (the larger of
** the two first), else the widest slab's.  (The least homothet's linear
** program gives its radius as max(W_i / 2, (hi_0 + hi_2 - lo_1) / 3,
** (hi_1 - lo_0 - lo_2) / 3), the alternate triples c = 2 and 5.) */
static int shape_hex_search(shape_hex_case *h) {
  static const int next[3] = {1, 2, 0}, prev[3] = {2, 0, 1};
  const double *w = h->w;
  int g01 = w[0] > w[1], g02 = w[0] > w[2], g12 = w[1] > w[2];
  int i = !(g01 & g02) * (2 - ((!g01) & g12)), ans = -1;
  int widest = (w[i] - w[next[i]] > h->eps) & (w[i] - w[prev[i]] > h->eps);
  const unsigned char *cand = h->pl->cand;
  double r[2] = {shape_hex_radius(h, cand[0]), shape_hex_radius(h, cand[1])};
  int big = r[1] > r[0], first = cand[big], second = cand[!big], tried = 2 * r[big] > w[i];
  if (tried) ans = shape_hex_sides(h, first);
  if (ans < 0 && widest) ans = shape_hex_wide(h, i);
  if (ans < 0 && !tried) ans = shape_hex_sides(h, first);
  if (ans < 0) ans = shape_hex_sides(h, second);
  return ans;
}

int shape_hex_decide(const shape *k, const geom_point p[4], shape_hint *out) {
  shape_hex_case h;
  for (int i = 0; i < 3; i++) h.v[0][i] = 0;
  double s = shape_hex_values(k, p[0], p[1], h.v[1]), sc = shape_hex_values(k, p[0], p[2], h.v[2]);
  double eps = h.eps = 0x1p-40 * (s + sc);   /* a sum, not the max: no branch */
  /* a sign too close to call (two sites on a line parallel to a side)
  ** leaves the decision to the general path */
  int clear = 1;
  unsigned code = 0;
  for (int i = 0; i < 3; i++) {
    double b = h.v[1][i], c = h.v[2][i];
    clear &= (fabs(b) > eps) & (fabs(c) > eps) & (fabs(b - c) > eps);
    code |= (unsigned)((b > 0) | (c > 0) << 1 | (b > c) << 2) << 3 * i;
  }
  if (!clear) return -1;
  const shape_hex_plan *pl = h.pl = &k->impl->hexa->plan[code];
  if (pl->corner >= 0) {   /* a point extreme on no side: a corner's rounding shape */
    int corner = pl->corner, c = corner == 6 ? 2 : shape_quick_corner(k, corner, p);
    if (c != 2 && out != NULL)
      *out = (shape_hint){SHAPE_HINT_CORNER, {(unsigned char)corner, 0, 0}};
    return c == 2 ? -1 : c < 0 ? SHAPE_BD : SHAPE_AC;
  }
  for (int i = 0; i < 3; i++) {
    h.ext[0][i] = h.v[pl->at[0][i]][i], h.ext[1][i] = h.v[pl->at[1][i]][i];
    h.w[i] = h.ext[0][i] - h.ext[1][i];
  }
  h.sd = 0x1p-40 * shape_hex_values(k, p[0], p[3], h.v[3]);
  int ans = shape_hex_search(&h);
  if (ans >= 0 && out != NULL)
    *out = (shape_hint){SHAPE_HINT_HOMOTHET, {(unsigned char)h.edge[0], (unsigned char)h.edge[1],
                                               (unsigned char)h.edge[2]}};
  return ans;
}

/* ---- a known shape ------------------------------------------------------
**
** With the contact sides of A, B, C known (a triangle's hint: the sides of
** its circumscribing homothet that A, B and C are on), the homothet is the
** solution of their three equations, with no extremes and no candidates:
** for case (1) each point's value in its own slab, for case (2) the two
** points of the widest slab and the third's value in its slab.  Only D's
** test is a comparison, bounded as above (S the sum over B, C and D).  A
** hint that names a side twice (a special position the general path
** resolved) fixes no homothet and is left to the caller.  The table of
** equations (216 triples) is built with the shape: lot asks this of 44%
** of its decisions. */

/* The equations of contact triple t: each point P on side s, of slab i =
** s mod 3 with sign g = +1 (s < 3) or -1, gives v_i(P) = t_i + g r, and
** t_1 = t_0 + t_2; in unknowns (t0, t2, r) the rows of slabs 0, 1, 2 are
** (1, 0, g), (1, 1, g), (0, 1, g).  Cramer: m = |det| (1, 2 or 3 for a
** homothet: case (1) gives det = k, case (2) +-2), and m times the solution
** is the adjugate's columns of B and C (A's right side is 0) times the
** sign of det: cofactors of magnitude at most 2.  So in shape_hex_at m r
** +- (m d_i - m t_i) has total coefficient at most 4 + 3 + 8 = 15 on the
** values vB, vC, d_i of error 4 u S each (m t_1 = m t_0 + m t_2 has 8),
** and is evaluated in seven roundings of partial sums at most 15 S: its
** error is under 15 (4 u S) + 7 (15 u S) (1 + u)^7 < 2^8 u S, far inside
** 2^-40 S = 2^13 u S. */
static void shape_hex_equations(int t0, int t1, int t2, shape_hex_eq *q) {
  int t[3] = {t0, t1, t2}, M[3][3];
  static const int row[3][2] = {{1, 0}, {1, 1}, {0, 1}};
  for (int j = 0; j < 3; j++) {
    int i = t[j] % 3;
    M[j][0] = row[i][0], M[j][1] = row[i][1], M[j][2] = t[j] < 3 ? 1 : -1;
  }
  int adj[3][3];   /* adj[u][j]: the cofactor of M[j][u] */
  for (int u = 0; u < 3; u++)
    for (int j = 0; j < 3; j++) {
      int r0 = j == 0 ? 1 : 0, r1 = j == 2 ? 1 : 2, c0 = u == 0 ? 1 : 0, c1 = u == 2 ? 1 : 2;
      int minor = M[r0][c0] * M[r1][c1] - M[r0][c1] * M[r1][c0];
      adj[u][j] = (u + j) % 2 ? -minor : minor;
    }
  int det = M[0][0] * adj[0][0] + M[1][0] * adj[0][1] + M[2][0] * adj[0][2];
  *q = (shape_hex_eq){.m = 0};
  if (det == 0) return;
  int g = det > 0 ? 1 : -1;
  q->m = (float)(det * g), q->sb = (signed char)(t1 % 3), q->sc = (signed char)(t2 % 3);
  for (int j = 1; j <= 2; j++) {   /* B, C */
    q->t0[j - 1] = (float)(g * adj[0][j]);
    q->t2[j - 1] = (float)(g * adj[1][j]);
    q->r[j - 1] = (float)(g * adj[2][j]);
  }
}

int shape_hex_at(const shape *k, const int t[3], const geom_point p[4]) {
  const struct shape_hex *x = k->impl->hexa;
  if ((unsigned)t[0] >= 6 || (unsigned)t[1] >= 6 || (unsigned)t[2] >= 6) return -1;
  const shape_hex_eq *q = &x->eq[t[0] + 6 * t[1] + 36 * t[2]];
  if (q->m == 0) return -1;
  const geom_point *e = x->e;
  double bx = p[1].x - p[0].x, by = p[1].y - p[0].y, cx = p[2].x - p[0].x, cy = p[2].y - p[0].y;
  double vb = bx * e[q->sb].y - by * e[q->sb].x, vc = cx * e[q->sc].y - cy * e[q->sc].x;
  /* the bound's scale: the sum of B's, C's and D's terms (at least the max) */
  double d[3], sd = shape_hex_values(k, p[0], p[3], d);
  double eps = 0x1p-40 * (((fabs(bx) + fabs(by)) + (fabs(cx) + fabs(cy))) * x->emax + sd);
  double t0 = q->t0[0] * vb + q->t0[1] * vc, t2 = q->t2[0] * vb + q->t2[1] * vc;
  const double h[3] = {t0, t0 + t2, t2};
  return shape_hex_dtest(d, h, q->r[0] * vb + q->r[1] * vc, q->m, eps);
}

int shape_hex_build(shape *k) {
  k->impl->hexa = NULL;
  if (k->n != 6) return 0;
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
  struct shape_hex *x = malloc(sizeof *x);
  if (x == NULL) return -1;
  x->emax = 0;
  for (int i = 0; i < 3; i++) {
    x->e[i] = e[i];
    x->emax = fmax(x->emax, fmax(fabs(e[i].x), fabs(e[i].y)));
  }
  for (unsigned c = 0; c < 512; c++) shape_hex_plan_of(c, &x->plan[c]);
  for (int t = 0; t < 216; t++) shape_hex_equations(t % 6, t / 6 % 6, t / 36, &x->eq[t]);
  k->impl->hexa = x;
  return 0;
}

void shape_hex_free(shape *k) {
  free(k->impl->hexa);
  k->impl->hexa = NULL;
}

/* ---- the hexagon's variant (shape_internal.h) ----------------------------- */

static int shape_hex_wants_hints(const shape *k) {
  (void)k;
  return 1;
}

/* Its slabs give up at ties only: on a grid a third of its decisions, whose
** configurations come back, are kept (shape_polygon_kept). */
SHAPE_VARIANT_OPS(hexagon, shape_hex_decide, shape_hex_at, shape_hex_wants_hints, 1);
