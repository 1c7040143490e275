/*
** sweep_circle.c: the circle's primitives for the sweepline algorithm
** (sweep_internal.h): the event key cx + R of a circumcircle, its exact
** comparison with another key or a site's x, and the "above" test of a
** site against the contact point of the circle through two boundary sites
** tangent to the sweepline.  Every answer is exact for points within the
** coordinate contract of geom.h (lot_build has checked them): a
** floating-point evaluation with a proven error bound decides when it can,
** GMP rationals (mpq: every double is a rational) when it cannot.
*/
#include <gmp.h>
#include <math.h>
#include "sweep_internal.h"

/* ---- the event key ----------------------------------------------------- */

/* The circumcentre of a, b, c relative to a, with b' = b - a, c' = c - a:
**   ox = nx / D, oy = ny / D,  D = 2 (b'x c'y - b'y c'x),
**   nx = |b'|^2 c'y - |c'|^2 b'y,  ny = |c'|^2 b'x - |b'|^2 c'x,
** and the key is a.x + ox + sqrt(ox^2 + oy^2), evaluated here in
** certified intervals (sweep_internal.h): the slow path of
** lot_circle_key_bounds, for triangles near collinear. */
static lot_iv lot_circle_key_iv(const geom_point t[3]) {
  lot_iv bx = lot_iv_diff(t[1].x, t[0].x), by = lot_iv_diff(t[1].y, t[0].y);
  lot_iv cx = lot_iv_diff(t[2].x, t[0].x), cy = lot_iv_diff(t[2].y, t[0].y);
  lot_iv bb = lot_iv_add(lot_iv_mul(bx, bx), lot_iv_mul(by, by));
  lot_iv cc = lot_iv_add(lot_iv_mul(cx, cx), lot_iv_mul(cy, cy));
  lot_iv d = lot_iv_add(lot_iv_mul(bx, cy), lot_iv_neg(lot_iv_mul(by, cx)));
  d.v *= 2;   /* exact */
  d.e *= 2;
  lot_iv nx = lot_iv_add(lot_iv_mul(bb, cy), lot_iv_neg(lot_iv_mul(cc, by)));
  lot_iv ny = lot_iv_add(lot_iv_mul(cc, bx), lot_iv_neg(lot_iv_mul(bb, cx)));
  lot_iv ox = lot_iv_div(nx, d), oy = lot_iv_div(ny, d);
  lot_iv r = lot_iv_sqrt(lot_iv_add(lot_iv_mul(ox, ox), lot_iv_mul(oy, oy)));
  return lot_iv_add(lot_iv_add((lot_iv){t[0].x, 0}, ox), r);
}

/* The key with one error bound instead of an interval per operation.  An
** event's triangle turns clockwise (D < 0), so with S = sqrt(nx^2 + ny^2)
** the key is a.x + (S - nx) / |D|: one division and one square root.
** Error bound (eps = 2^-53; within the coordinate contract nothing under-
** or overflows, geom_orient_valid): each difference b'x ... is exact times
** (1 + d), |d| <= eps.  D / 2 is the orientation determinant, whose error
** is at most (3 + 16 eps) eps (|l| + |r|), l, r its products (Shewchuk's
** bound, geom/predicates.h): |fl(D) - D| <= eD = 16 eps (|l| + |r|).
** |b'|^2 carries (1 + eps)^4 - 1 < 4.01 eps, each product of nx one more
** factor of a difference and one rounding, so u1 = fl(|b'|^2 c'y) = U1 (1
** + th), |th| < 6.01 eps, and with the subtraction |fl(nx) - nx| <= 6.01
** eps (|U1| + |U2|) + eps |fl(nx)| < 7.1 eps (|u1| + |u2|) <= eNx = 8 eps
** (|u1| + |u2|), likewise ny.  S: by the triangle inequality
** |sqrt(fl(nx)^2 + fl(ny)^2) - S| <= eNx + eNy, and the rounded sum of
** squares and its rounded root add (1 + eps)^2 - 1 < 2.01 eps relatively:
** |s - S| <= eNx + eNy + 3 eps s.  num = fl(s - nx): |num - NUM| <= eNum
** = |s - S| + eNx + eps |num|.  With ad = |fl(D)| (= fl(r - l) doubled,
** exactly) and rho = eD / ad <= 1/64 (else the interval path decides),
** |D| >= ad (1 - rho), and |num / ad - NUM / |D|| = |(num - NUM) ad +
** num (|D| - ad)| / (ad |D|) <= (eNum + |num| rho) / (ad (1 - rho)) <=
** 1.02 eNum / ad + 1.03 rho |q| (1 / (1 - rho) <= 64/63, |num| / ad <=
** (1 + eps) |q| for q = fl(num / ad)), plus eps |q| for q's rounding; the sum a.x + q adds eps |key|.  The bound is
** computed in floating point from non-negative terms, a few dozen
** roundings each shrinking it by a factor (1 - eps) at worst, which the
** margins (8 for 7.1, 3 for 2.01, 1.02 for 1.016, 16 for 6) and
** lot_iv_bounds's lot_iv_fix outweigh; lot_iv_bounds then rounds the
** final bounds outwards. */
static int lot_circle_key_fast(const geom_point t[3], lot_iv *k) {
  double bx = t[1].x - t[0].x, by = t[1].y - t[0].y, cx = t[2].x - t[0].x, cy = t[2].y - t[0].y;
  double l = bx * cy, r = by * cx, ad = 2 * (r - l), eD = 16 * GEOM_EPS * (fabs(l) + fabs(r));
  if (!(ad > 64 * eD)) return 0;   /* D not certainly negative and far from 0 */
  double bb = bx * bx + by * by, cc = cx * cx + cy * cy;
  double u1 = bb * cy, u2 = cc * by, v1 = cc * bx, v2 = bb * cx;
  double nx = u1 - u2, ny = v1 - v2, s = sqrt(nx * nx + ny * ny), num = s - nx;
  double eNx = 8 * GEOM_EPS * (fabs(u1) + fabs(u2)), eNy = 8 * GEOM_EPS * (fabs(v1) + fabs(v2));
  double eNum = 2 * eNx + eNy + 3 * GEOM_EPS * s + GEOM_EPS * fabs(num);
  double q = num / ad, key = t[0].x + q;
  double eQ = 1.02 * (eNum / ad) + (1.03 * (eD / ad) + GEOM_EPS) * fabs(q);
  *k = (lot_iv){key, eQ + GEOM_EPS * fabs(key)};
  return 1;
}

static void lot_circle_key_bounds(const void *ctx, const geom_point t[3], double *lo, double *hi) {
  (void)ctx;
  lot_iv k;
  if (!lot_circle_key_fast(t, &k)) k = lot_circle_key_iv(t);
  lot_iv_bounds(k, lo, hi);
}

/* The exact key as q + sqrt(r2): q = a.x + nx / D, r2 = (nx^2 + ny^2) / D^2
** (the formulas above, in rationals; D != 0: an event's sites are never
** collinear).  A site's key is its x: q = x, r2 = 0. */
static void lot_circle_key_q(const geom_point *t, double x, mpq_t q, mpq_t r2) {
  if (t == NULL) {
    mpq_set_d(q, x);
    mpq_set_ui(r2, 0, 1);
    return;
  }
  mpq_t v[8];   /* b'x b'y c'x c'y, |b'|^2 |c'|^2, D, scratch */
  for (int i = 0; i < 8; i++) mpq_init(v[i]);
  mpq_set_d(v[7], t[0].x);
  mpq_set_d(v[0], t[1].x); mpq_sub(v[0], v[0], v[7]);
  mpq_set_d(v[2], t[2].x); mpq_sub(v[2], v[2], v[7]);
  mpq_set_d(v[7], t[0].y);
  mpq_set_d(v[1], t[1].y); mpq_sub(v[1], v[1], v[7]);
  mpq_set_d(v[3], t[2].y); mpq_sub(v[3], v[3], v[7]);
  mpq_mul(v[4], v[0], v[0]); mpq_mul(v[7], v[1], v[1]); mpq_add(v[4], v[4], v[7]);
  mpq_mul(v[5], v[2], v[2]); mpq_mul(v[7], v[3], v[3]); mpq_add(v[5], v[5], v[7]);
  mpq_mul(v[6], v[0], v[3]); mpq_mul(v[7], v[1], v[2]); mpq_sub(v[6], v[6], v[7]);
  mpq_add(v[6], v[6], v[6]);
  mpq_mul(q, v[4], v[3]); mpq_mul(v[7], v[5], v[1]); mpq_sub(q, q, v[7]);       /* nx */
  mpq_mul(r2, v[5], v[0]); mpq_mul(v[7], v[4], v[2]); mpq_sub(r2, r2, v[7]);    /* ny */
  mpq_div(q, q, v[6]);                                                          /* ox */
  mpq_div(r2, r2, v[6]);                                                        /* oy */
  mpq_mul(r2, r2, r2); mpq_mul(v[7], q, q); mpq_add(r2, r2, v[7]);              /* R^2 */
  mpq_set_d(v[7], t[0].x);
  mpq_add(q, q, v[7]);
  for (int i = 0; i < 8; i++) mpq_clear(v[i]);
}

/* sign((q1 + sqrt r1) - (q2 + sqrt r2)), r1, r2 >= 0, by the usual
** squaring.  With d = q1 - q2, the sign is d's when sqrt r1 - sqrt r2
** (which has the sign of r1 - r2) agrees with it or is 0, and r1 - r2's
** when d = 0.  Otherwise it is d's exactly when d^2 > (sqrt r1 - sqrt
** r2)^2 = r1 + r2 - 2 sqrt(r1 r2), i.e. when e + 2 sqrt(r1 r2) > 0 for
** e = d^2 - r1 - r2: true when e > 0 (e = 0: when r1 r2 > 0), and for
** e < 0 when 4 r1 r2 > e^2; equality gives 0. */
int lot_sweep_sqrt_cmp(mpq_t q1, mpq_t r1, mpq_t q2, mpq_t r2) {
  mpq_t d, e, f;
  mpq_inits(d, e, f, NULL);
  mpq_sub(d, q1, q2);
  mpq_sub(e, r1, r2);
  int sd = mpq_sgn(d), sr = mpq_sgn(e), s;
  if (sd == 0 || sr == 0 || sd == sr) {
    s = sd != 0 ? sd : sr;
  } else {
    mpq_mul(e, d, d);
    mpq_sub(e, e, r1);
    mpq_sub(e, e, r2);
    mpq_mul(f, r1, r2);
    int t;
    if (mpq_sgn(e) >= 0) {
      t = mpq_sgn(e) > 0 || mpq_sgn(f) > 0;
    } else {
      mpq_mul(e, e, e);
      mpq_mul_2exp(f, f, 2);
      t = mpq_cmp(f, e);
    }
    s = t > 0 ? sd : t < 0 ? sr : 0;
  }
  mpq_clears(d, e, f, NULL);
  return s;
}

/* Exact: both keys as q + sqrt(r2) (lot_circle_key_q), compared by
** lot_sweep_sqrt_cmp.  The sweep calls it only when the certified bounds of the
** two keys overlap. */
static int lot_circle_key_cmp(const void *ctx, const geom_point *t, double tx, const geom_point *u,
                              double ux) {
  (void)ctx;
  if (t == NULL && u == NULL) return (tx > ux) - (tx < ux);
  mpq_t q1, r1, q2, r2;
  mpq_inits(q1, r1, q2, r2, NULL);
  lot_circle_key_q(t, tx, q1, r1);
  lot_circle_key_q(u, ux, q2, r2);
  int s = lot_sweep_sqrt_cmp(q1, r1, q2, r2);
  mpq_clears(q1, r1, q2, r2, NULL);
  return s;
}

/* ---- the "above" test -------------------------------------------------- */

/* sign(2 xy - ay - by).  d1 = fl(xy - ay), d2 = fl(xy - by) and fl(d1 + d2)
** carry one rounding each: |fl(d1 + d2) - (2 xy - ay - by)| <= eps (|xy -
** ay| + |xy - by| + |d1 + d2|) < 4 eps (|d1| + |d2|) (the margin absorbs
** the rounding of the bound itself), so a larger |fl(d1 + d2)| has the
** true sign; otherwise rationals decide. */
static int lot_mid_sign(double ay, double by, double xy) {
  double d1 = xy - ay, d2 = xy - by, s = d1 + d2;
  double bound = 4 * GEOM_EPS * (fabs(d1) + fabs(d2));
  if (s > bound) return 1;
  if (-s > bound) return -1;
  mpq_t a, b, x;
  mpq_inits(a, b, x, NULL);
  mpq_set_d(a, ay);
  mpq_set_d(b, by);
  mpq_set_d(x, xy);
  mpq_add(x, x, x);
  mpq_sub(x, x, a);
  mpq_sub(x, x, b);
  int r = mpq_sgn(x);
  mpq_clears(a, b, x, NULL);
  return r;
}

/* The sign of N = ax |b|^2 - bx |a|^2 with a = A - X, b = B - X, which
** with orient(X, A, B) gives the side of the circumcentre of A, B, X:
** oy - X.y = N / (2 orient det) (Cramer's rule on 2 a.o = |a|^2,
** 2 b.o = |b|^2).  Error bound: the four differences carry a relative
** error eps each (no underflow within the coordinate contract: every
** non-zero difference is at least 2^-152, so every non-zero term here is
** at least 2^-456); |b|^2 sums two non-negative products, so t1 = fl(ax
** fl(|b|^2)) is T1 (1 + th), |th| <= (1 + eps)^6 - 1 < 6.01 eps, and
** likewise t2; with the final subtraction, |fl(N) - N| <= 6.01 eps (|T1|
** + |T2|) + eps |t1 - t2| < 7.1 eps (|t1| + |t2|).  The test uses 8 eps,
** which covers the rounding of the bound. */
static int lot_lift_sign(geom_point A, geom_point B, geom_point X) {
  double ax = A.x - X.x, ay = A.y - X.y, bx = B.x - X.x, by = B.y - X.y;
  double t1 = ax * (bx * bx + by * by), t2 = bx * (ax * ax + ay * ay), n = t1 - t2;
  double bound = 8 * GEOM_EPS * (fabs(t1) + fabs(t2));
  if (n > bound) return 1;
  if (-n > bound) return -1;
  mpq_t v[5];
  for (int i = 0; i < 5; i++) mpq_init(v[i]);
  const double in[4][2] = {{A.x, X.x}, {A.y, X.y}, {B.x, X.x}, {B.y, X.y}};
  for (int i = 0; i < 4; i++) {
    mpq_set_d(v[i], in[i][0]);
    mpq_set_d(v[4], in[i][1]);
    mpq_sub(v[i], v[i], v[4]);
  }
  mpq_t s;
  mpq_init(s);
  mpq_mul(v[4], v[2], v[2]); mpq_mul(s, v[3], v[3]); mpq_add(v[4], v[4], s);
  mpq_mul(v[4], v[4], v[0]);                                    /* ax |b|^2 */
  mpq_mul(v[1], v[1], v[1]); mpq_mul(s, v[0], v[0]); mpq_add(v[1], v[1], s);
  mpq_mul(v[1], v[1], v[2]);                                    /* bx |a|^2 */
  mpq_sub(v[4], v[4], v[1]);
  int r = mpq_sgn(v[4]);
  mpq_clear(s);
  for (int i = 0; i < 5; i++) mpq_clear(v[i]);
  return r;
}

/* Is X above the contact point T of the circle through A and B tangent
** to the sweepline x = X.x, for A's arc below B's?  The circles through A
** and B cut the sweepline in pairs X, X' with (X - M)(X' - M) = MA MB
** (the power of M, where the line AB meets the sweepline), so the two
** tangent points T1 < T2 lie at M -+ sqrt(MA MB) and the one on X's side
** of M lies between X and X', whose midpoint is the circumcentre's height
** oy: X is above it exactly when X.y > oy.  Which of T1 and T2 is the
** pair's: f_S(y), the x where the circle tangent at (X.x, y) first meets
** S, has leading coefficient -1/(2 (X.x - S.x)), so the site further from
** the sweepline owns both ends: (A, B) with A.x < B.x is the lower contact
** point T1, with A.x > B.x the upper T2.  So, with L, R the sites of
** smaller and larger x and o = orient(L, R, X) (X above line LR):
**   T1: X above it iff o > 0, or X.y > oy;   T2: iff o > 0 and X.y > oy;
** o = 0 puts X at M, strictly between T1 and T2.  A.x = B.x: the contact
** point is at (A.y + B.y) / 2 whatever the sweepline.  All exact. */
static int lot_circle_above(const void *ctx, geom_point A, geom_point B, geom_point X) {
  (void)ctx;
  if (A.x == B.x) return lot_mid_sign(A.y, B.y, X.y) > 0;
  int lower = A.x < B.x, oab = geom_orient_valid(A, B, X);   /* = orient(X, A, B) */
  int o = lower ? oab : -oab;
  if (o == 0) return lower;
  if (o > 0 && lower) return 1;
  if (o < 0 && !lower) return 0;
  return lot_lift_sign(A, B, X) * oab < 0;
}

/* Consecutive a, b, c (bottom to top) close an event when c is strictly
** right of a -> b: then the arcs' breakpoints converge (the circumcentre
** lies behind b). */
int lot_sweep_closes(const void *ctx, geom_point a, geom_point b, geom_point c) {
  (void)ctx;
  return geom_orient_valid(a, b, c) < 0;
}

const lot_sweep_shape lot_sweep_circle = {"circle", NULL, lot_sweep_closes, lot_circle_key_bounds,
                                          lot_circle_key_cmp, lot_circle_above, NULL};
