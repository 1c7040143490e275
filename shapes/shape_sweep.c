/*
** shape_sweep.c: what the sweepline algorithm (lot/sweep.c) asks of a shape
** beyond the empty-shape decision: the table of its exact primitives
** (shape_sweep_internal.h), made here by its kind, with what the tables
** share (the closing test, the comparison of square roots), and a polygon's
** circumscribing shape of a triangle, a homothet with its contact edges or
** a corner's rounding shape (shape_sweep_polygon.c's keys).
*/
#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include "geom_int_internal.h"
#include "shape.h"
#include "shape_internal.h"
#include "shape_sweep_internal.h"

void shape_sweep_make(const shape *k, shape_sweep_ctx *c, size_t *special, shape_sweep *s) {
  switch (k->kind) {
  case SHAPE_ELLIPSE:
    c->q = (shape_sweep_conic){k->q11, k->q12, k->q22};
    shape_sweep_ellipse(&c->q, s);
    return;
  case SHAPE_POLYGON:
    shape_sweep_polygon(&c->poly, k, special, s);
    return;
  }
}

static atomic_ulong shape_sweep_gmp_count;

unsigned long shape_sweep_gmp_calls(void) {
  return atomic_load_explicit(&shape_sweep_gmp_count, memory_order_relaxed);
}

void shape_sweep_note_gmp(void) {
  atomic_fetch_add_explicit(&shape_sweep_gmp_count, 1, memory_order_relaxed);
}

/* The run's frame: 1/u (geom_int_scale of every coordinate) and the
** smallest coordinates over u, then the common trailing zeros m of the
** sites' offsets from them: every site is then an integer in [0, 2^20)
** in the unit 2^m u, or the frame is refused (0).  O(n). */
int shape_sweep_frame_make(const void *ctx, const geom_point *p, size_t n,
                           shape_sweep_frame *f) {
  (void)ctx;
  if (n == 0) return 0;
  double big = 0;
  for (size_t k = 0; k < n; k++) {
    big = fabs(p[k].x) > big ? fabs(p[k].x) : big;
    big = fabs(p[k].y) > big ? fabs(p[k].y) : big;
  }
  double s = geom_int_scale(&big, 1);
  int64_t lo[2] = {INT64_MAX, INT64_MAX}, hi[2] = {INT64_MIN, INT64_MIN}, c[2];
  for (size_t k = 0; k < n; k++) {
    const double v[2] = {p[k].x, p[k].y};
    if (!geom_ints(v, 2, s, 0x1p62, c)) return 0;
    for (int i = 0; i < 2; i++) {
      lo[i] = c[i] < lo[i] ? c[i] : lo[i];
      hi[i] = c[i] > hi[i] ? c[i] : hi[i];
    }
  }
  uint64_t bits = 0;
  for (size_t k = 0; k < n; k++) {
    const double v[2] = {p[k].x, p[k].y};
    geom_ints(v, 2, s, 0x1p62, c);
    bits |= (uint64_t)(c[0] - lo[0]) | (uint64_t)(c[1] - lo[1]);
  }
  int m = bits != 0 ? shape_sweep_ctz(bits) : 0;
  *f = (shape_sweep_frame){s, {lo[0], lo[1]}, m};
  uint64_t w = (uint64_t)(hi[0] - lo[0]) | (uint64_t)(hi[1] - lo[1]);
  return (w >> m) < (1u << 20);
}

/* Site p in the frame (one of the run's sites, or a site's x with y = 0,
** whose z[1] is then meaningless). */
void shape_sweep_in_frame(const shape_sweep_frame *f, geom_point p, int64_t z[2]) {
  const double v[2] = {p.x, p.y};
  geom_ints(v, 2, f->scale, 0x1p62, z);
  z[0] = (int64_t)((uint64_t)(z[0] - f->lo[0]) >> f->shift);
  z[1] = (int64_t)((uint64_t)(z[1] - f->lo[1]) >> f->shift);
}

/* Consecutive a, b, c (bottom to top) close an event when c is strictly
** right of a -> b: then the arcs' breakpoints converge (for the circle:
** the circumcentre lies behind b). */
int shape_sweep_closes(const void *ctx, geom_point a, geom_point b, geom_point c) {
  (void)ctx;
  return geom_orient_valid(a, b, c) < 0;
}

/* e + 2 sqrt f, f >= 0: its sign is e's when e >= 0 (then 0 only when f
** is), and for e < 0 that of 4 f - e^2. */
int shape_sweep_root_sign(mpq_ptr e, mpq_ptr f) {
  if (mpq_sgn(e) >= 0) return mpq_sgn(e) > 0 || mpq_sgn(f) > 0;
  mpq_mul(e, e, e);
  mpq_mul_2exp(f, f, 2);
  int t = mpq_cmp(f, e);
  return (t > 0) - (t < 0);
}

/* sign((q1 + sqrt r1) - (q2 + sqrt r2)), r1, r2 >= 0, by the usual
** squaring.  With d = q1 - q2, the sign is d's when sqrt r1 - sqrt r2
** (which has the sign of r1 - r2) agrees with it or is 0, and r1 - r2's
** when d = 0.  Otherwise it is d's exactly when d^2 > (sqrt r1 - sqrt
** r2)^2 = r1 + r2 - 2 sqrt(r1 r2), i.e. when e + 2 sqrt(r1 r2) > 0 for
** e = d^2 - r1 - r2 (shape_sweep_root_sign), r1 - r2's when it is < 0,
** and 0 when it is 0. */
int shape_sweep_sqrt_cmp(mpq_ptr q1, mpq_srcptr r1, mpq_ptr q2, mpq_srcptr r2) {
  mpq_t e, f;
  mpq_inits(e, f, NULL);
  mpq_sub(q1, q1, q2);   /* d */
  mpq_sub(e, r1, r2);
  int sd = mpq_sgn(q1), sr = mpq_sgn(e), s;
  if (sd == 0 || sr == 0 || sd == sr) {
    s = sd != 0 ? sd : sr;
  } else {
    mpq_mul(e, q1, q1);
    mpq_sub(e, e, r1);
    mpq_sub(e, e, r2);
    mpq_mul(f, r1, r2);
    int t = shape_sweep_root_sign(e, f);
    s = t > 0 ? sd : t < 0 ? sr : 0;
  }
  mpq_clears(e, f, NULL);
  return s;
}

int shape_circumscribe(const shape *k, geom_point a, geom_point b, geom_point c, int contact[3],
                       int *corner) {
  int sup[3] = {shape_support(k, a, b), shape_support(k, b, c), shape_support(k, c, a)};
  /* All three cannot coincide (shape_polygon.c, shape_polygon_decide). */
  if (sup[0] == sup[1] || sup[0] == sup[2]) {
    *corner = sup[0];
    return 0;
  }
  if (sup[1] == sup[2]) {
    *corner = sup[1];
    return 0;
  }
  const geom_point p[3] = {a, b, c};
  return shape_contacts(k, sup, p, contact) != 0 ? 1 : -1;
}

/* ---- drawing the circumscribing shape (shape_circumscribe_draw) ----
** Rounded arithmetic on purpose: the contact edges are exact, the picture
** is not a decision.  O(n) for a polygon, O(max) for an ellipse. */

/* Homothet t + sK with A, B, C on the contact edges e[]: edge i (v_i to
** v_i+1, outward normal n_i = (dy, -dx), offset c_i = n_i.v_i) of the
** homothet is n_i.X = n_i.t + s c_i; three such rows, by Cramer's rule. */
static int shape_draw_polygon(const shape *k, const geom_point p[3], const int e[3],
                              geom_point *out) {
  double m[3][4];
  for (int j = 0; j < 3; j++) {
    geom_point u = k->v[e[j]], w = k->v[(e[j] + 1) % k->n];
    double nx = w.y - u.y, ny = u.x - w.x;
    m[j][0] = nx;
    m[j][1] = ny;
    m[j][2] = nx * u.x + ny * u.y;
    m[j][3] = nx * p[j].x + ny * p[j].y;
  }
#define SHAPE_DET3(c0, c1, c2) \
  (m[0][c0] * (m[1][c1] * m[2][c2] - m[2][c1] * m[1][c2]) - \
   m[1][c0] * (m[0][c1] * m[2][c2] - m[2][c1] * m[0][c2]) + \
   m[2][c0] * (m[0][c1] * m[1][c2] - m[1][c1] * m[0][c2]))
  double d = SHAPE_DET3(0, 1, 2);
  if (d == 0) return -1;
  double tx = SHAPE_DET3(3, 1, 2) / d, ty = SHAPE_DET3(0, 3, 2) / d;
  double s = SHAPE_DET3(0, 1, 3) / d;
#undef SHAPE_DET3
  for (int i = 0; i < k->n; i++) out[i] = (geom_point){tx + s * k->v[i].x, ty + s * k->v[i].y};
  return k->n;
}

/* The ellipse {X : X^T Q X <= 1} is the unit disc under L, Q = L^T L with L
** upper triangular (Cholesky): the homothet through A, B, C is L^-1 of the
** circumcircle of LA, LB, LC. */
static int shape_draw_ellipse(const shape *k, const geom_point p[3], geom_point *out, int max) {
  double l11 = sqrt(k->q11), l12 = k->q12 / l11, l22 = sqrt(k->q22 - l12 * l12);
  double u[3][2];
  for (int j = 0; j < 3; j++) {
    u[j][0] = l11 * p[j].x + l12 * p[j].y;
    u[j][1] = l22 * p[j].y;
  }
  double bx = u[1][0] - u[0][0], by = u[1][1] - u[0][1];
  double cx = u[2][0] - u[0][0], cy = u[2][1] - u[0][1];
  double d = 2 * (bx * cy - by * cx);
  if (d == 0 || !(l22 > 0)) return -1;
  double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  double mx = (cy * b2 - by * c2) / d, my = (bx * c2 - cx * b2) / d;
  double r = sqrt(mx * mx + my * my);
  for (int i = 0; i < max; i++) {
    double a = 2 * 3.14159265358979323846 * i / max;
    double y = (u[0][1] + my + r * sin(a)) / l22;
    out[i] = (geom_point){(u[0][0] + mx + r * cos(a) - l12 * y) / l11, y};
  }
  return max;
}

int shape_circumscribe_draw(const shape *k, geom_point a, geom_point b, geom_point c,
                            geom_point *out, int max, int *corner) {
  const geom_point p[3] = {a, b, c};
  if (geom_orient(a, b, c) <= 0) return -1;
  if (k->kind == SHAPE_ELLIPSE) return max >= 3 ? shape_draw_ellipse(k, p, out, max) : -1;
  int e[3];
  int r = shape_circumscribe(k, a, b, c, e, corner);
  return r == 1 ? shape_draw_polygon(k, p, e, out) : r == 0 ? 0 : -1;
}
