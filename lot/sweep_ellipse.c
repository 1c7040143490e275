/*
** sweep_ellipse.c: an ellipse's primitives for the sweepline algorithm
** (sweep_internal.h), for lot --algorithm sweep with the rule ES:ellipse.
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
** of the form q + sqrt(r) as the circle's, compared by lot_sweep_sqrt_cmp.
** The "above" test is the circle's argument after the map: the vertical
** chord of the homothet through A, B, X has its midpoint at height
** c.y + q12 (c.x - X.x) / q22, which is below X exactly when w.y < 0
** relative to X, and w.y = (a.x Q(b) - b.x Q(a)) / (2 orient(A, B, X))
** for a = A - X, b = B - X.  Sites of equal x (the first column) have
** their contact point where the conjugate diameter of the vertical
** direction through their midpoint meets the sweepline.
**
** Filters: the certified intervals of sweep_internal.h decide when the
** interval excludes 0 (or the keys' bounds are disjoint); GMP rationals
** decide the rest, exactly.
*/
#include <gmp.h>
#include <math.h>
#include "sweep_internal.h"

/* Q(x, y) on intervals: Q's entries are exact doubles. */
static lot_iv lot_ell_qiv(const lot_sweep_conic *q, lot_iv x, lot_iv y) {
  lot_iv a = lot_iv_mul((lot_iv){q->q11, 0}, lot_iv_mul(x, x));
  lot_iv b = lot_iv_mul((lot_iv){2 * q->q12, 0}, lot_iv_mul(x, y));
  lot_iv c = lot_iv_mul((lot_iv){q->q22, 0}, lot_iv_mul(y, y));
  return lot_iv_add(lot_iv_add(a, b), c);
}

/* out = Q(x, y) in rationals; s is scratch. */
static void lot_ell_qmpq(const lot_sweep_conic *q, mpq_t out, const mpq_t x, const mpq_t y,
                         mpq_t s) {
  mpq_t c;
  mpq_init(c);
  mpq_mul(out, x, x);
  mpq_set_d(c, q->q11);
  mpq_mul(out, out, c);
  mpq_mul(s, x, y);
  mpq_set_d(c, 2 * q->q12);
  mpq_mul(s, s, c);
  mpq_add(out, out, s);
  mpq_mul(s, y, y);
  mpq_set_d(c, q->q22);
  mpq_mul(s, s, c);
  mpq_add(out, out, s);
  mpq_clear(c);
}

/* ---- the event key ----------------------------------------------------- */

static void lot_ell_key_bounds(const void *ctx, const geom_point t[3], double *lo, double *hi) {
  const lot_sweep_conic *q = ctx;
  lot_iv bx = lot_iv_diff(t[1].x, t[0].x), by = lot_iv_diff(t[1].y, t[0].y);
  lot_iv cx = lot_iv_diff(t[2].x, t[0].x), cy = lot_iv_diff(t[2].y, t[0].y);
  lot_iv qb = lot_ell_qiv(q, bx, by), qc = lot_ell_qiv(q, cx, cy);
  lot_iv d = lot_iv_add(lot_iv_mul(bx, cy), lot_iv_neg(lot_iv_mul(by, cx)));
  d.v *= 2;   /* exact */
  d.e *= 2;
  lot_iv wx = lot_iv_div(lot_iv_add(lot_iv_mul(qb, cy), lot_iv_neg(lot_iv_mul(qc, by))), d);
  lot_iv wy = lot_iv_div(lot_iv_add(lot_iv_mul(qc, bx), lot_iv_neg(lot_iv_mul(qb, cx))), d);
  lot_iv q11 = {q->q11, 0}, q22 = {q->q22, 0}, q12 = {q->q12, 0};
  lot_iv det = lot_iv_add(lot_iv_mul(q11, q22), lot_iv_neg(lot_iv_mul(q12, q12)));
  lot_iv m = lot_iv_add(lot_iv_mul(q22, lot_iv_mul(wx, wx)),
                        lot_iv_add(lot_iv_mul(q11, lot_iv_mul(wy, wy)),
                                   lot_iv_neg(lot_iv_mul((lot_iv){2 * q->q12, 0},
                                                         lot_iv_mul(wx, wy)))));
  lot_iv num = lot_iv_add(lot_iv_add(lot_iv_mul(q22, wx), lot_iv_neg(lot_iv_mul(q12, wy))),
                          lot_iv_sqrt(lot_iv_mul(q22, m)));
  lot_iv k = lot_iv_add((lot_iv){t[0].x, 0}, lot_iv_div(num, det));
  lot_iv_bounds(k, lo, hi);
}

/* The exact key as qq + sqrt(r2) (the formula above, in rationals; the
** sites of an event are never collinear, so D != 0; det > 0).  A site's
** key is its x: qq = x, r2 = 0. */
static void lot_ell_key_q(const lot_sweep_conic *q, const geom_point *t, double x, mpq_t qq,
                          mpq_t r2) {
  if (t == NULL) {
    mpq_set_d(qq, x);
    mpq_set_ui(r2, 0, 1);
    return;
  }
  mpq_t v[10];   /* b'x b'y c'x c'y Q(b') Q(c') D, det, scratch x 2 */
  for (int i = 0; i < 10; i++) mpq_init(v[i]);
  const double in[4][2] = {{t[1].x, t[0].x}, {t[1].y, t[0].y}, {t[2].x, t[0].x},
                           {t[2].y, t[0].y}};
  for (int i = 0; i < 4; i++) {
    mpq_set_d(v[i], in[i][0]);
    mpq_set_d(v[8], in[i][1]);
    mpq_sub(v[i], v[i], v[8]);
  }
  lot_ell_qmpq(q, v[4], v[0], v[1], v[8]);
  lot_ell_qmpq(q, v[5], v[2], v[3], v[8]);
  mpq_mul(v[6], v[0], v[3]); mpq_mul(v[8], v[1], v[2]); mpq_sub(v[6], v[6], v[8]);
  mpq_add(v[6], v[6], v[6]);
  mpq_mul(qq, v[4], v[3]); mpq_mul(v[8], v[5], v[1]); mpq_sub(qq, qq, v[8]);
  mpq_div(qq, qq, v[6]);                                                     /* wx */
  mpq_mul(r2, v[5], v[0]); mpq_mul(v[8], v[4], v[2]); mpq_sub(r2, r2, v[8]);
  mpq_div(r2, r2, v[6]);                                                     /* wy */
  mpq_set_d(v[8], q->q11); mpq_set_d(v[9], q->q22); mpq_mul(v[7], v[8], v[9]);
  mpq_set_d(v[8], q->q12); mpq_mul(v[8], v[8], v[8]); mpq_sub(v[7], v[7], v[8]);   /* det */
  /* m = Q^-1-form of w times det: q22 wx^2 - 2 q12 wx wy + q11 wy^2, i.e. the
  ** form with q11 and q22 swapped and q12 negated. */
  const lot_sweep_conic adj = {q->q22, -q->q12, q->q11};
  lot_ell_qmpq(&adj, v[4], qq, r2, v[8]);                                    /* m */
  mpq_set_d(v[9], q->q22);
  mpq_mul(v[4], v[4], v[9]);                                                 /* q22 m */
  mpq_mul(qq, qq, v[9]);
  mpq_set_d(v[8], q->q12);
  mpq_mul(r2, r2, v[8]);
  mpq_sub(qq, qq, r2);
  mpq_div(qq, qq, v[7]);
  mpq_set_d(v[8], t[0].x);
  mpq_add(qq, qq, v[8]);                                                     /* A.x + ... */
  mpq_mul(v[7], v[7], v[7]);
  mpq_div(r2, v[4], v[7]);                                                   /* q22 m / det^2 */
  for (int i = 0; i < 10; i++) mpq_clear(v[i]);
}

static int lot_ell_key_cmp(const void *ctx, const geom_point *t, double tx, const geom_point *u,
                           double ux) {
  if (t == NULL && u == NULL) return (tx > ux) - (tx < ux);
  mpq_t q1, r1, q2, r2;
  mpq_inits(q1, r1, q2, r2, NULL);
  lot_ell_key_q(ctx, t, tx, q1, r1);
  lot_ell_key_q(ctx, u, ux, q2, r2);
  int s = lot_sweep_sqrt_cmp(q1, r1, q2, r2);
  mpq_clears(q1, r1, q2, r2, NULL);
  return s;
}

/* ---- the "above" test -------------------------------------------------- */

/* sign(q22 (2 X.y - A.y - B.y) + 2 q12 (X.x - A.x)) for A.x = B.x: X above
** the contact point of the sites A, B of one column. */
static int lot_ell_column_sign(const lot_sweep_conic *q, geom_point A, geom_point B,
                               geom_point X) {
  lot_iv dy = lot_iv_add(lot_iv_diff(X.y, A.y), lot_iv_diff(X.y, B.y));
  lot_iv s = lot_iv_add(lot_iv_mul((lot_iv){q->q22, 0}, dy),
                        lot_iv_mul((lot_iv){2 * q->q12, 0}, lot_iv_diff(X.x, A.x)));
  if (s.v > s.e) return 1;
  if (-s.v > s.e) return -1;
  mpq_t a, b, c;
  mpq_inits(a, b, c, NULL);
  mpq_set_d(a, X.y); mpq_add(a, a, a);
  mpq_set_d(b, A.y); mpq_sub(a, a, b);
  mpq_set_d(b, B.y); mpq_sub(a, a, b);
  mpq_set_d(b, q->q22); mpq_mul(a, a, b);
  mpq_set_d(b, X.x); mpq_set_d(c, A.x); mpq_sub(b, b, c);
  mpq_set_d(c, 2 * q->q12); mpq_mul(b, b, c);
  mpq_add(a, a, b);
  int r = mpq_sgn(a);
  mpq_clears(a, b, c, NULL);
  return r;
}

/* sign(a.x Q(b) - b.x Q(a)), a = A - X, b = B - X (the circle's lift sign
** with Q for |.|^2). */
static int lot_ell_lift_sign(const lot_sweep_conic *q, geom_point A, geom_point B, geom_point X) {
  lot_iv ax = lot_iv_diff(A.x, X.x), ay = lot_iv_diff(A.y, X.y);
  lot_iv bx = lot_iv_diff(B.x, X.x), by = lot_iv_diff(B.y, X.y);
  lot_iv n = lot_iv_add(lot_iv_mul(ax, lot_ell_qiv(q, bx, by)),
                        lot_iv_neg(lot_iv_mul(bx, lot_ell_qiv(q, ax, ay))));
  if (n.v > n.e) return 1;
  if (-n.v > n.e) return -1;
  mpq_t v[7];
  for (int i = 0; i < 7; i++) mpq_init(v[i]);
  const double in[4][2] = {{A.x, X.x}, {A.y, X.y}, {B.x, X.x}, {B.y, X.y}};
  for (int i = 0; i < 4; i++) {
    mpq_set_d(v[i], in[i][0]);
    mpq_set_d(v[6], in[i][1]);
    mpq_sub(v[i], v[i], v[6]);
  }
  lot_ell_qmpq(q, v[4], v[2], v[3], v[6]);
  mpq_mul(v[4], v[4], v[0]);                                    /* ax Q(b) */
  lot_ell_qmpq(q, v[5], v[0], v[1], v[6]);
  mpq_mul(v[5], v[5], v[2]);                                    /* bx Q(a) */
  mpq_sub(v[4], v[4], v[5]);
  int r = mpq_sgn(v[4]);
  for (int i = 0; i < 7; i++) mpq_clear(v[i]);
  return r;
}

/* The circle's case analysis (lot_circle_above), with the ellipse's column
** and lift signs. */
static int lot_ell_above(const void *ctx, geom_point A, geom_point B, geom_point X) {
  const lot_sweep_conic *q = ctx;
  if (A.x == B.x) return lot_ell_column_sign(q, A, B, X) > 0;
  int lower = A.x < B.x, oab = geom_orient_valid(A, B, X);
  int o = lower ? oab : -oab;
  if (o == 0) return lower;
  if (o > 0 && lower) return 1;
  if (o < 0 && !lower) return 0;
  return lot_ell_lift_sign(q, A, B, X) * oab < 0;
}

void lot_sweep_ellipse(const lot_sweep_conic *q, lot_sweep_shape *s) {
  *s = (lot_sweep_shape){"ellipse", q, lot_sweep_closes, lot_ell_key_bounds, lot_ell_key_cmp,
                         lot_ell_above, NULL};
}
