/*
** shape_arith.c: the shape predicates (shape_internal.h) as programs over a
** register file that runs either on doubles with an error bound or on
** exact rationals, and the driver that runs the first and, when it cannot
** decide, the second.
*/
#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <gmp.h>
#include "fliplab_config.h"
#include "shape_internal.h"

/* ---- why the double run's sign can be trusted -------------------------
**
** A program is a tree of +, -, * over inputs (doubles, exact).  Beside each
** value v it carries its "absolute twin" t, the same tree evaluated with
** every input replaced by its magnitude and every - by a +, and a rounding
** count k: 0 for an input, 1 for the difference of two inputs (read as one
** rounded leaf, twin |fl(x - y)|), max(k_a, k_b) + 1 for a sum or
** difference, k_a + k_b + 2 for a product.  With u = 2^-53 and
** gamma_k = k u / (1 - k u), induction over the tree gives, for the exact
** value x and the exact twin X,
**     |v - x| <= gamma_k X   and   t = X (1 + theta), |theta| <= gamma_k:
**   a sum:     |v_a + v_b - (x_a + x_b)| <= gamma_m (X_a + X_b), m = max k,
**              and one more rounding, (1 + u)(1 + gamma_m) <= 1 + gamma_{m+1};
**   a product: |v_a v_b - x_a x_b| <= ((1 + gamma_a)(1 + gamma_b) - 1) X_a X_b
**              <= gamma_{a+b} X_a X_b, then the rounding of the product, whose
**              error is u |v_a v_b| + eta with eta <= 2^-1075 the absolute
**              error of an underflowing product; counting the product as two
**              roundings absorbs eta whenever X_a X_b >= 2^-1022 (then
**              eta <= u X_a X_b).
** So X <= t / (1 - gamma_k), and |v - x| <= gamma_k / (1 - gamma_k) t
** = k u t / (1 - 2 k u) < fl((2k + 2) u t) (k < 2^20, one rounding of a
** product of doubles, (2k + 2) u exact): when |v| exceeds that bound, v has
** the sign of x.  A twin of 0 means every monomial is 0: the value is 0.
**
** Underflow: a product whose twin is below 2^-1000 (but whose factors'
** twins are not 0) poisons the run, which then goes to the exact path, so
** every product that the bound relies on has X_a X_b >= 2^-1000 (1 -
** gamma) > 2^-1022.  Sums of non-negative twins cannot lose the bound (a
** subnormal sum is exact).  Overflow makes v or t infinite or NaN; the
** comparison then fails and the exact path decides.  The coordinate
** contract of geom.h (and the shape checks of shape.c) keep every
** predicate far from both: inputs are 0 or in [2^-100, 2^100], degrees at
** most 8.
**
** The exact run repeats the program on mpq_t registers (every double is a
** rational), so both runs are the same program: one place to get right. */

#define SHAPE_REGS 320

typedef struct shape_ar {
  int exact;               /* 0: the double run, 1: the exact run */
  int n;                   /* registers used */
  int nq;                  /* mpq registers initialised (exact run) */
  int poison;              /* a product underflowed: the double run decides nothing */
  double v[SHAPE_REGS], t[SHAPE_REGS];
  int k[SHAPE_REGS];
  mpq_t q[SHAPE_REGS];
  mpq_t s;                 /* scratch (exact run) */
} shape_ar;

static atomic_ulong shape_exact_count;

unsigned long shape_exact_calls(void) {
  return atomic_load_explicit(&shape_exact_count, memory_order_relaxed);
}

/* A new register.  The programs are fixed trees far smaller than the file
** (tests/test_shape.c runs every one), so running out is a bug. */
static int shape_ar_new(shape_ar *a) {
  if (a->n >= SHAPE_REGS) abort();
  int r = a->n++;
  if (a->exact && r >= a->nq) mpq_init(a->q[a->nq++]);
  return r;
}

/* The double run's value, twin and rounding count of register r. */
static void shape_set(shape_ar *a, int r, double v, double t, int k) {
  a->v[r] = v;
  a->t[r] = t;
  a->k[r] = k;
}

static int shape_in(shape_ar *a, double x) {
  int r = shape_ar_new(a);
  if (a->exact) mpq_set_d(a->q[r], x);
  else shape_set(a, r, x, fabs(x), 0);
  return r;
}

/* x - y of two inputs, one rounded leaf (the bound's argument). */
static int shape_dif(shape_ar *a, double x, double y) {
  int r = shape_ar_new(a);
  if (a->exact) {
    mpq_set_d(a->q[r], x);
    mpq_set_d(a->s, y);
    mpq_sub(a->q[r], a->q[r], a->s);
  } else {
    shape_set(a, r, x - y, fabs(x - y), 1);
  }
  return r;
}

static int shape_kmax(const shape_ar *a, int i, int j) {
  return a->k[i] > a->k[j] ? a->k[i] : a->k[j];
}

static int shape_add(shape_ar *a, int i, int j) {
  int r = shape_ar_new(a);
  if (a->exact) mpq_add(a->q[r], a->q[i], a->q[j]);
  else shape_set(a, r, a->v[i] + a->v[j], a->t[i] + a->t[j], shape_kmax(a, i, j) + 1);
  return r;
}

static int shape_sub(shape_ar *a, int i, int j) {
  int r = shape_ar_new(a);
  if (a->exact) mpq_sub(a->q[r], a->q[i], a->q[j]);
  else shape_set(a, r, a->v[i] - a->v[j], a->t[i] + a->t[j], shape_kmax(a, i, j) + 1);
  return r;
}

static int shape_neg(shape_ar *a, int i) {
  int r = shape_ar_new(a);
  if (a->exact) mpq_neg(a->q[r], a->q[i]);
  else shape_set(a, r, -a->v[i], a->t[i], a->k[i]);
  return r;
}

static int shape_mul(shape_ar *a, int i, int j) {
  int r = shape_ar_new(a);
  if (a->exact) {
    mpq_mul(a->q[r], a->q[i], a->q[j]);
    return r;
  }
  shape_set(a, r, a->v[i] * a->v[j], a->t[i] * a->t[j], a->k[i] + a->k[j] + 2);
  a->poison |= a->t[r] < 0x1p-1000 && a->t[i] != 0 && a->t[j] != 0;
  return r;
}

/* x_i y_j - x_j y_i style: a b - c d. */
static int shape_cross2(shape_ar *a, int pa, int pb, int pc, int pd) {
  return shape_sub(a, shape_mul(a, pa, pb), shape_mul(a, pc, pd));
}

/* The double run's verdict on register r: its sign, or 2 (undecided). */
static int shape_ar_filter(const shape_ar *a, int r) {
  if (a->poison) return 2;
  double v = a->v[r], t = a->t[r];
  if (t == 0) return 0;
  double bound = (2.0 * a->k[r] + 2.0) * 0x1p-53 * t;
  if (v > bound) return 1;
  if (-v > bound) return -1;
  return 2;
}

int shape_sign(shape_prog f, const shape_args *g) {
  shape_ar a;
  a.exact = 0;
  a.n = a.nq = a.poison = 0;
  int s = shape_ar_filter(&a, f(&a, g));
  if (s != 2) return s;
  atomic_fetch_add_explicit(&shape_exact_count, 1, memory_order_relaxed);
  a.exact = 1;
  a.n = 0;
  mpq_init(a.s);
  s = mpq_sgn(a.q[f(&a, g)]);
  for (int i = 0; i < a.nq; i++) mpq_clear(a.q[i]);
  mpq_clear(a.s);
  return s;
}

int shape_eps_sign(shape_prog f, shape_args g, int *level) {
  g.deriv = 0;
  int s = shape_sign(f, &g);
  if (s == 0) {
    g.deriv = 1;
    s = shape_sign(f, &g);
  }
  if (level) *level = g.deriv + (s == 0);
  return s;
}

/* ---- determinants of register matrices ------------------------------- */

/* m is row-major: m[3 * row + col]. */
static int shape_det3(shape_ar *a, const int m[9]) {
  int c0 = shape_cross2(a, m[4], m[8], m[5], m[7]);
  int c1 = shape_cross2(a, m[3], m[8], m[5], m[6]);
  int c2 = shape_cross2(a, m[3], m[7], m[4], m[6]);
  int s = shape_sub(a, shape_mul(a, m[0], c0), shape_mul(a, m[1], c1));
  return shape_add(a, s, shape_mul(a, m[2], c2));
}

/* Laplace along the first two columns: sum over row pairs of the 2x2 minor
** of columns 0, 1 times the complementary minor of columns 2, 3, signed. */
static int shape_det4(shape_ar *a, const int m[16]) {
  static const int pr[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                               {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  static const int sg[6] = {1, -1, 1, 1, -1, 1};
  int acc = -1;
  for (int p = 0; p < 6; p++) {
    const int *r = pr[p];
    int lo = shape_cross2(a, m[4 * r[0]], m[4 * r[1] + 1], m[4 * r[1]], m[4 * r[0] + 1]);
    int hi = shape_cross2(a, m[4 * r[2] + 2], m[4 * r[3] + 3], m[4 * r[3] + 2], m[4 * r[2] + 3]);
    int term = shape_mul(a, lo, hi);
    acc = acc < 0 ? term : sg[p] > 0 ? shape_add(a, acc, term) : shape_sub(a, acc, term);
  }
  return acc;
}

/* ---- polygon rows ------------------------------------------------------ */

static geom_point shape_vertex(const shape *K, int i) {
  return K->v[((i % K->n) + K->n) % K->n];
}

/* Edge e's direction (e_x, e_y) into r[0], r[1], and h = cross(k_e, k_{e+1})
** into r[2]. */
static void shape_edge_regs(shape_ar *a, const shape *K, int e, int r[3]) {
  geom_point p = shape_vertex(K, e), q = shape_vertex(K, e + 1);
  r[0] = shape_dif(a, q.x, p.x);
  r[1] = shape_dif(a, q.y, p.y);
  r[2] = shape_cross2(a, shape_in(a, p.x), shape_in(a, q.y), shape_in(a, p.y), shape_in(a, q.x));
}

/* w = cross(p - o, e) = n.(p - o), n the outward normal (e_y, -e_x); its
** eps coefficient is e.(p - o) (the sites turned by -eps). */
static int shape_w(shape_ar *a, const shape_args *g, int ex, int ey, geom_point p) {
  int dx = shape_dif(a, p.x, g->o.x), dy = shape_dif(a, p.y, g->o.y);
  if (g->deriv) return shape_add(a, shape_mul(a, ex, dx), shape_mul(a, ey, dy));
  return shape_cross2(a, dx, ey, dy, ex);
}

int shape_prog_cross(shape_ar *a, const shape_args *g) {
  geom_point p = shape_vertex(g->K, g->e[0]), q = shape_vertex(g->K, g->e[0] + 1);
  int ex = shape_dif(a, q.x, p.x), ey = shape_dif(a, q.y, p.y);
  int wx = shape_dif(a, g->p[1].x, g->p[0].x), wy = shape_dif(a, g->p[1].y, g->p[0].y);
  if (g->deriv) return shape_neg(a, shape_add(a, shape_mul(a, ex, wx), shape_mul(a, ey, wy)));
  return shape_cross2(a, ex, wy, ey, wx);
}

int shape_prog_det3h(shape_ar *a, const shape_args *g) {
  int m[9];
  for (int r = 0; r < 3; r++) shape_edge_regs(a, g->K, g->e[r], &m[3 * r]);
  return shape_det3(a, m);
}

int shape_prog_det3w(shape_ar *a, const shape_args *g) {
  int m[9], rr[3];
  for (int r = 0; r < 3; r++) {
    shape_edge_regs(a, g->K, g->e[r], rr);
    m[3 * r] = rr[0];
    m[3 * r + 1] = rr[1];
    m[3 * r + 2] = shape_w(a, g, rr[0], rr[1], g->p[r]);
  }
  return shape_det3(a, m);
}

int shape_prog_det4(shape_ar *a, const shape_args *g) {
  int m[16];
  for (int r = 0; r < 4; r++) {
    shape_edge_regs(a, g->K, g->e[r], &m[4 * r]);
    m[4 * r + 3] = shape_w(a, g, m[4 * r], m[4 * r + 1], g->p[r]);
  }
  return shape_det4(a, m);
}

/* ---- the rounding shape of a corner -------------------------------------
**
** Corner c with cone sides u = k_{c+1} - k_c and v = k_{c-1} - k_c
** (delta = cross(u, v) > 0: the polygon is anticlockwise).  The map
** x' = cross(p, v), y' = cross(u, p) is delta [u v]^-1: it sends u and v
** to the positive axes, scaled by delta > 0.  With X, Y the mapped
** differences p - o, the rows (X Y, X, Y) of p[0..2] give the 4x4
** determinant of rows (x'y', x', y', 1) of the three sites and o (the
** translation to o is a column operation).  Its eps coefficient: the
** sites turned by -eps change p - o = w by eps (w_y, -w_x), so X by
** eps w.v and Y by -eps u.w; the determinant's derivative is the sum of
** the three determinants with one column differentiated. */
static void shape_corner_row(shape_ar *a, const shape_args *g, int r, int out[6]) {
  geom_point c = shape_vertex(g->K, g->corner);
  geom_point nx = shape_vertex(g->K, g->corner + 1), pv = shape_vertex(g->K, g->corner - 1);
  int ux = shape_dif(a, nx.x, c.x), uy = shape_dif(a, nx.y, c.y);
  int vx = shape_dif(a, pv.x, c.x), vy = shape_dif(a, pv.y, c.y);
  int dx = shape_dif(a, g->p[r].x, g->o.x), dy = shape_dif(a, g->p[r].y, g->o.y);
  int X = shape_cross2(a, dx, vy, dy, vx), Y = shape_cross2(a, ux, dy, uy, dx);
  out[0] = shape_mul(a, X, Y);
  out[1] = X;
  out[2] = Y;
  if (!g->deriv) return;
  int X1 = shape_add(a, shape_mul(a, dx, vx), shape_mul(a, dy, vy));
  int Y1 = shape_neg(a, shape_add(a, shape_mul(a, ux, dx), shape_mul(a, uy, dy)));
  out[3] = shape_add(a, shape_mul(a, X1, Y), shape_mul(a, X, Y1));
  out[4] = X1;
  out[5] = Y1;
}

int shape_prog_corner(shape_ar *a, const shape_args *g) {
  int rows[3][6], m[9];
  for (int r = 0; r < 3; r++) shape_corner_row(a, g, r, rows[r]);
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) m[3 * r + c] = rows[r][c];
  if (!g->deriv) return shape_det3(a, m);
  int acc = -1;
  for (int col = 0; col < 3; col++) {
    int d[9];
    for (int r = 0; r < 3; r++)
      for (int c = 0; c < 3; c++) d[3 * r + c] = c == col ? rows[r][3 + c] : rows[r][c];
    int t = shape_det3(a, d);
    acc = acc < 0 ? t : shape_add(a, acc, t);
  }
  return acc;
}

/* ---- the ellipse ------------------------------------------------------- */

/* Rows (x, y, Q(x, y)) of p[r] - o: positive when o is inside the ellipse
** homothet through p[0..2] (anticlockwise), as the incircle determinant. */
int shape_prog_ellipse(shape_ar *a, const shape_args *g) {
  int m[9];
  int q11 = shape_in(a, g->K->q11), q12 = shape_in(a, 2 * g->K->q12), q22 = shape_in(a, g->K->q22);
  for (int r = 0; r < 3; r++) {
    int x = shape_dif(a, g->p[r].x, g->o.x), y = shape_dif(a, g->p[r].y, g->o.y);
    int xx = shape_mul(a, shape_mul(a, q11, x), x), yy = shape_mul(a, shape_mul(a, q22, y), y);
    int xy = shape_mul(a, shape_mul(a, q12, x), y);
    m[3 * r] = x;
    m[3 * r + 1] = y;
    m[3 * r + 2] = shape_add(a, shape_add(a, xx, xy), yy);
  }
  return shape_det3(a, m);
}
