/*
** shape_sweep_ellipse.c: an ellipse's primitives for the sweepline
** algorithm (shape_sweep_internal.h), for lot --algorithm sweep with the
** rule ES:ellipse, and the exact arithmetic of every conic (the circle's,
** shape_sweep_circle.c, is the form x^2 + y^2).
**
** The ellipse E = {p : Q(p) <= 1}, Q(x, y) = q11 x^2 + 2 q12 x y + q22 y^2
** (the doubles of shape.h), is the unit circle under a linear map, so
** everything the circle does (lot/sweep_circle.c) holds with |v|^2 read as
** Q(v): the homothet through A, B, C is {p : Q(p - c) <= rho}, and with
** b' = B - A, c' = C - A its centre c (relative to A) is Q^-1 w, where
** 2 b'.w = Q(b'), 2 c'.w = Q(c') (the circle's centre formula with Q for
** |.|^2).  Its rightmost point is at c.x + sqrt(rho (Q^-1)_11), so with
** det = q11 q22 - q12^2 and m = q22 wx^2 - 2 q12 wx wy + q11 wy^2
** (= rho det):
**   key = A.x + (q22 wx - q12 wy + sqrt(q22 m)) / det,
** of the form q + sqrt(r) as the circle's, compared by shape_sweep_sqrt_cmp.
** The "above" test is the circle's argument after the map: the vertical
** chord of the homothet through A, B, X has its midpoint at height
** c.y + q12 (c.x - X.x) / q22, which is below X exactly when w.y < 0
** relative to X, and w.y = (a.x Q(b) - b.x Q(a)) / (2 orient(A, B, X))
** for a = A - X, b = B - X.  Sites of equal x (the first column) have
** their contact point where the conjugate diameter of the vertical
** direction through their midpoint meets the sweepline.
**
** Filters: the certified intervals of shape_sweep_internal.h decide when
** the interval excludes 0 (or the keys' bounds are disjoint); GMP rationals
** (the pool of shape_internal.h) decide the rest, exactly.
*/
#include <math.h>
#include "shape_internal.h"
#include "shape_sweep_internal.h"

/* Q(x, y) on intervals: Q's entries are exact doubles. */
static shape_iv shape_ell_qiv(const shape_sweep_conic *q, shape_iv x, shape_iv y) {
  shape_iv a = shape_iv_mul((shape_iv){q->q11, 0}, shape_iv_mul(x, x));
  shape_iv b = shape_iv_mul((shape_iv){2 * q->q12, 0}, shape_iv_mul(x, y));
  shape_iv c = shape_iv_mul((shape_iv){q->q22, 0}, shape_iv_mul(y, y));
  return shape_iv_add(shape_iv_add(a, b), c);
}

/* Q(x, y) in rationals, in a new register of P. */
static mpq_ptr shape_ell_qmpq(shape_mpq *P, const shape_sweep_conic *q, mpq_srcptr x,
                              mpq_srcptr y) {
  mpq_ptr out = shape_mpq_new(P), t = shape_mpq_new(P);
  mpq_mul(out, x, x);
  mpq_mul(out, out, shape_mpq_d(P, q->q11));
  mpq_mul(t, x, y);
  mpq_mul(t, t, shape_mpq_d(P, 2 * q->q12));
  mpq_add(out, out, t);
  mpq_mul(t, y, y);
  mpq_mul(t, t, shape_mpq_d(P, q->q22));
  mpq_add(out, out, t);
  return out;
}

/* ---- the event key ----------------------------------------------------- */

static void shape_ell_key_bounds(const void *ctx, const geom_point t[3], double *lo,
                                 double *hi) {
  const shape_sweep_conic *q = ctx;
  shape_iv bx = shape_iv_diff(t[1].x, t[0].x), by = shape_iv_diff(t[1].y, t[0].y);
  shape_iv cx = shape_iv_diff(t[2].x, t[0].x), cy = shape_iv_diff(t[2].y, t[0].y);
  shape_iv qb = shape_ell_qiv(q, bx, by), qc = shape_ell_qiv(q, cx, cy);
  shape_iv d = shape_iv_sub(shape_iv_mul(bx, cy), shape_iv_mul(by, cx));
  d.v *= 2;   /* exact */
  d.e *= 2;
  shape_iv wx = shape_iv_div(shape_iv_sub(shape_iv_mul(qb, cy), shape_iv_mul(qc, by)), d);
  shape_iv wy = shape_iv_div(shape_iv_sub(shape_iv_mul(qc, bx), shape_iv_mul(qb, cx)), d);
  shape_iv q11 = {q->q11, 0}, q22 = {q->q22, 0}, q12 = {q->q12, 0};
  shape_iv det = shape_iv_sub(shape_iv_mul(q11, q22), shape_iv_mul(q12, q12));
  shape_iv m = shape_iv_add(shape_iv_mul(q22, shape_iv_mul(wx, wx)),
                            shape_iv_sub(shape_iv_mul(q11, shape_iv_mul(wy, wy)),
                                         shape_iv_mul((shape_iv){2 * q->q12, 0},
                                                      shape_iv_mul(wx, wy))));
  shape_iv num = shape_iv_add(shape_iv_sub(shape_iv_mul(q22, wx), shape_iv_mul(q12, wy)),
                              shape_iv_sqrt(shape_iv_mul(q22, m)));
  shape_iv k = shape_iv_add((shape_iv){t[0].x, 0}, shape_iv_div(num, det));
  shape_iv_bounds(k, lo, hi);
}

/* The exact key as *qq + sqrt(*r2), in registers of P (the formula above,
** in rationals; the sites of an event are never collinear, so D != 0;
** det > 0).  A site's key is its x: qq = x, r2 = 0. */
static void shape_ell_key_q(shape_mpq *P, const shape_sweep_conic *q, const geom_point *t,
                            double x, mpq_ptr *qq, mpq_ptr *r2) {
  if (t == NULL) {
    *qq = shape_mpq_d(P, x);
    *r2 = shape_mpq_new(P);
    return;
  }
  mpq_ptr bx = shape_mpq_diff(P, t[1].x, t[0].x), by = shape_mpq_diff(P, t[1].y, t[0].y);
  mpq_ptr cx = shape_mpq_diff(P, t[2].x, t[0].x), cy = shape_mpq_diff(P, t[2].y, t[0].y);
  mpq_ptr qb = shape_ell_qmpq(P, q, bx, by), qc = shape_ell_qmpq(P, q, cx, cy);
  mpq_ptr d = shape_mpq_cross(P, bx, cy, by, cx);
  mpq_add(d, d, d);                                                        /* D */
  mpq_ptr wx = shape_mpq_cross(P, qb, cy, qc, by), wy = shape_mpq_cross(P, qc, bx, qb, cx);
  mpq_div(wx, wx, d);
  mpq_div(wy, wy, d);
  mpq_ptr q11 = shape_mpq_d(P, q->q11), q12 = shape_mpq_d(P, q->q12);
  mpq_ptr q22 = shape_mpq_d(P, q->q22), det = shape_mpq_cross(P, q11, q22, q12, q12);
  /* m = Q^-1-form of w times det: q22 wx^2 - 2 q12 wx wy + q11 wy^2, i.e. the
  ** form with q11 and q22 swapped and q12 negated. */
  const shape_sweep_conic adj = {q->q22, -q->q12, q->q11};
  *r2 = shape_ell_qmpq(P, &adj, wx, wy);
  mpq_mul(*r2, *r2, q22);                                                  /* q22 m */
  mpq_div(*r2, *r2, det);
  mpq_div(*r2, *r2, det);                                                  /* / det^2 */
  *qq = shape_mpq_cross(P, q22, wx, q12, wy);
  mpq_div(*qq, *qq, det);
  mpq_add(*qq, *qq, shape_mpq_d(P, t[0].x));                               /* A.x + ... */
}

int shape_sweep_conic_key_cmp(const void *ctx, const geom_point *t, double tx,
                              const geom_point *u, double ux) {
  if (t == NULL && u == NULL) return (tx > ux) - (tx < ux);
  shape_sweep_note_gmp();
  shape_mpq P;
  shape_mpq_init(&P);
  mpq_ptr q1, r1, q2, r2;
  shape_ell_key_q(&P, ctx, t, tx, &q1, &r1);
  shape_ell_key_q(&P, ctx, u, ux, &q2, &r2);
  int s = shape_sweep_sqrt_cmp(q1, r1, q2, r2);
  shape_mpq_clear(&P);
  return s;
}

/* ---- the "above" test -------------------------------------------------- */

/* sign(q22 (2 X.y - A.y - B.y) + 2 q12 (X.x - A.x)) for A.x = B.x: X above
** the contact point of the sites A, B of one column. */
static int shape_ell_column_sign(const shape_sweep_conic *q, geom_point A, geom_point B,
                                 geom_point X) {
  shape_iv dy = shape_iv_add(shape_iv_diff(X.y, A.y), shape_iv_diff(X.y, B.y));
  int s = shape_iv_sign(shape_iv_add(shape_iv_mul((shape_iv){q->q22, 0}, dy),
                                     shape_iv_mul((shape_iv){2 * q->q12, 0},
                                                  shape_iv_diff(X.x, A.x))));
  return s != 2 ? s : shape_sweep_conic_column(q, A, B, X);
}

int shape_sweep_conic_column(const shape_sweep_conic *q, geom_point A, geom_point B,
                             geom_point X) {
  shape_sweep_note_gmp();
  shape_mpq P;
  shape_mpq_init(&P);
  mpq_ptr dy = shape_mpq_diff(&P, X.y, A.y);   /* 2 X.y - A.y - B.y */
  mpq_add(dy, dy, shape_mpq_diff(&P, X.y, B.y));
  return shape_mpq_done(&P, shape_mpq_cross(&P, shape_mpq_d(&P, q->q22), dy,
                                            shape_mpq_d(&P, -2 * q->q12),
                                            shape_mpq_diff(&P, X.x, A.x)));
}

/* sign(a.x Q(b) - b.x Q(a)), a = A - X, b = B - X (the circle's lift sign
** with Q for |.|^2). */
static int shape_ell_lift_sign(const shape_sweep_conic *q, geom_point A, geom_point B,
                               geom_point X) {
  shape_iv ax = shape_iv_diff(A.x, X.x), ay = shape_iv_diff(A.y, X.y);
  shape_iv bx = shape_iv_diff(B.x, X.x), by = shape_iv_diff(B.y, X.y);
  int s = shape_iv_sign(shape_iv_sub(shape_iv_mul(ax, shape_ell_qiv(q, bx, by)),
                                     shape_iv_mul(bx, shape_ell_qiv(q, ax, ay))));
  return s != 2 ? s : shape_sweep_conic_lift(q, A, B, X);
}

int shape_sweep_conic_lift(const shape_sweep_conic *q, geom_point A, geom_point B,
                           geom_point X) {
  shape_sweep_note_gmp();
  shape_mpq P;
  shape_mpq_init(&P);
  mpq_ptr ax = shape_mpq_diff(&P, A.x, X.x), ay = shape_mpq_diff(&P, A.y, X.y);
  mpq_ptr bx = shape_mpq_diff(&P, B.x, X.x), by = shape_mpq_diff(&P, B.y, X.y);
  mpq_ptr qa = shape_ell_qmpq(&P, q, ax, ay), qb = shape_ell_qmpq(&P, q, bx, by);
  return shape_mpq_done(&P, shape_mpq_cross(&P, ax, qb, bx, qa));
}

/* The conics' case analysis (shape_sweep_conic_side), with the ellipse's
** column and lift signs. */
static int shape_ell_above(const void *ctx, geom_point A, geom_point B, geom_point X) {
  const shape_sweep_conic *q = ctx;
  if (A.x == B.x) return shape_ell_column_sign(q, A, B, X) > 0;
  int oab, side = shape_sweep_conic_side(A, B, X, &oab);
  return side != 2 ? side : shape_ell_lift_sign(q, A, B, X) * oab < 0;
}

void shape_sweep_ellipse(const shape_sweep_conic *q, shape_sweep *s) {
  *s = (shape_sweep){"ellipse", q, shape_sweep_closes, shape_ell_key_bounds,
                     shape_sweep_conic_key_cmp, shape_ell_above, NULL, NULL, NULL, NULL};
}
