/*
** shape_sweep_circle.c: the circle's primitives for the sweepline algorithm
** (shape_sweep_internal.h): the event key cx + R of a circumcircle, its
** exact comparison with another key or a site's x, and the "above" test of
** a site against the contact point of the circle through two boundary
** sites tangent to the sweepline.  Every answer is exact for points within
** the coordinate contract of geom.h (lot_build has checked them): a
** floating-point evaluation with a proven error bound decides when it can,
** GMP rationals (mpq: every double is a rational) when it cannot, in the
** exact arithmetic of the ellipses (shape_sweep_ellipse.c) with the
** circle's form x^2 + y^2.
*/
#include <math.h>
#include <stdint.h>
#include "geom_int_internal.h"
#include "shape_sweep_internal.h"

static const shape_sweep_conic shape_circle_form = {1, 0, 1};

/* ---- the event key ----------------------------------------------------- */

/* The circumcentre of a, b, c relative to a, with b' = b - a, c' = c - a:
**   ox = nx / D, oy = ny / D,  D = 2 (b'x c'y - b'y c'x),
**   nx = |b'|^2 c'y - |c'|^2 b'y,  ny = |c'|^2 b'x - |b'|^2 c'x,
** and the key is a.x + ox + sqrt(ox^2 + oy^2), evaluated here in
** certified intervals (shape_sweep_internal.h): the slow path of
** shape_circle_key_bounds, for triangles near collinear. */
static shape_iv shape_circle_key_iv(const geom_point t[3]) {
  shape_iv bx = shape_iv_diff(t[1].x, t[0].x), by = shape_iv_diff(t[1].y, t[0].y);
  shape_iv cx = shape_iv_diff(t[2].x, t[0].x), cy = shape_iv_diff(t[2].y, t[0].y);
  shape_iv bb = shape_iv_add(shape_iv_mul(bx, bx), shape_iv_mul(by, by));
  shape_iv cc = shape_iv_add(shape_iv_mul(cx, cx), shape_iv_mul(cy, cy));
  shape_iv d = shape_iv_sub(shape_iv_mul(bx, cy), shape_iv_mul(by, cx));
  d.v *= 2;   /* exact */
  d.e *= 2;
  shape_iv nx = shape_iv_sub(shape_iv_mul(bb, cy), shape_iv_mul(cc, by));
  shape_iv ny = shape_iv_sub(shape_iv_mul(cc, bx), shape_iv_mul(bb, cx));
  shape_iv ox = shape_iv_div(nx, d), oy = shape_iv_div(ny, d);
  shape_iv r = shape_iv_sqrt(shape_iv_add(shape_iv_mul(ox, ox), shape_iv_mul(oy, oy)));
  return shape_iv_add(shape_iv_add((shape_iv){t[0].x, 0}, ox), r);
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
** (1 + eps) |q| for q = fl(num / ad)), plus eps |q| for q's rounding; the
** sum a.x + q adds eps |key|.  The bound is computed in floating point
** from non-negative terms, a few dozen roundings each shrinking it by a
** factor (1 - eps) at worst, which the margins (8 for 7.1, 3 for 2.01,
** 1.02 for 1.016, 16 for 6) and shape_iv_bounds's shape_iv_fix outweigh;
** shape_iv_bounds then rounds the final bounds outwards. */
static int shape_circle_key_fast(const geom_point t[3], shape_iv *k) {
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
  *k = (shape_iv){key, eQ + GEOM_EPS * fabs(key)};
  return 1;
}

static void shape_circle_key_bounds(const void *ctx, const geom_point t[3], double *lo,
                                    double *hi) {
  (void)ctx;
  shape_iv k;
  if (!shape_circle_key_fast(t, &k)) k = shape_circle_key_iv(t);
  shape_iv_bounds(k, lo, hi);
}

/* ---- the integer stage of the key comparison --------------------------
**
** Grids and integer coordinates make many keys exactly equal (every unit
** square of a grid's column has its column's key), which no bound can
** separate: in GMP they took nearly all of a grid's sweep.  With sites
** a, b, c of an event, s the sign and d = |D| of D = 2 (b'x c'y - b'y c'x),
** nx, ny as above and N = nx^2 + ny^2, the key is a.x + (s nx + sqrt N) / d,
** so for two keys (a site's key x: d = 1, nx = N = 0, a.x = x)
**   d1 d2 (key1 - key2) = P + sqrt A - sqrt B,
**   P = d1 d2 (a1.x - a2.x) + d2 s1 nx1 - d1 s2 nx2,  A = d2^2 N1,  B = d1^2 N2.
** When the coordinates are integers in one unit u (a power of two), each
** triangle's differences b - a, c - a below 2^20 and a1.x - a2.x below 2^40
** in it, all of it is exact in integers: |D| < 2^42, |nx|, |ny| < 2^62
** (|b'|^2 < 2^41 times a difference), N < 2^125, d^2 < 2^84, so A, B <
** 2^209 (geom_u256); |P| < 2^124 + 2^105 < 2^125 (__int128).  The sign of
** P + sqrt A - sqrt B is then P's when A - B has the same sign or is 0,
** A - B's when P = 0 (equal keys: both 0), and with a site's key (A or B
** 0) one squaring settles the rest: sign(A - P^2) or sign(P^2 - B) (P^2 <
** 2^250).  Two events whose signs differ need a second squaring (2^420):
** that rare case, and inputs beyond the bounds, go to GMP.  Scaling every
** coordinate by 1/u multiplies both keys by it, and translating them
** moves both alike, so the sign is the same.
**
** The unit comes either from the two keys' own coordinates (key_cmp,
** geom_int_internal.h's unit coarsened by the common trailing zeros of the
** differences), or once for the whole run (the frame: every site an
** integer below 2^20 in one unit, relative to the smallest coordinates),
** and then each event's key is made once in integers (shape_sweep_ikey)
** and compared many times. */
#if GEOM_HAVE_INT128
/* The key of a's x (integer, in the unit) and the triangle of differences
** z[0..3] = b'x, b'y, c'x, c'y (z == NULL: a site's key). */
static shape_sweep_ikey shape_circle_ik(int64_t ax, const int64_t *z) {
  if (z == NULL) return (shape_sweep_ikey){ax, 1, 0, 0, 0, 1};
  geom_i128 bx = z[0], by = z[1], cx = z[2], cy = z[3];
  geom_i128 D = 2 * (bx * cy - by * cx), bb = bx * bx + by * by, cc = cx * cx + cy * cy;
  geom_i128 nx = bb * cy - cc * by, ny = cc * bx - bb * cx;
  geom_u128 n = (geom_u128)(nx * nx + ny * ny);
  return (shape_sweep_ikey){ax, (int64_t)(D < 0 ? -D : D), (int64_t)(D < 0 ? -nx : nx),
                            (uint64_t)n, (uint64_t)(n >> 64), 1};
}

static geom_u256 shape_circle_u256(geom_u128 a, geom_u128 b) {
  geom_u256 r = {{0, 0, 0, 0}};
  geom_u256_addmul(&r, a, b);
  return r;
}

/* The sign of key(a) - key(b), or 2 when it needs the second squaring. */
static int shape_circle_ik_cmp(const shape_sweep_ikey *a, const shape_sweep_ikey *b) {
  if (a->d == b->d && a->snx == b->snx && a->nlo == b->nlo && a->nhi == b->nhi)
    return (a->ax > b->ax) - (a->ax < b->ax);   /* translates along x: the common case */
  geom_i128 P = (geom_i128)a->d * b->d * (a->ax - b->ax) + (geom_i128)b->d * a->snx
              - (geom_i128)a->d * b->snx;
  geom_u128 na = (geom_u128)a->nhi << 64 | a->nlo, nb = (geom_u128)b->nhi << 64 | b->nlo;
  geom_u256 A = shape_circle_u256((geom_u128)b->d * (geom_u128)b->d, na);
  geom_u256 B = shape_circle_u256((geom_u128)a->d * (geom_u128)a->d, nb);
  int sp = (P > 0) - (P < 0), sr = geom_u256_cmp(&A, &B);
  if (sp == 0 || sr == 0 || sp == sr) return sp != 0 ? sp : sr;
  geom_u128 ap = (geom_u128)(P < 0 ? -P : P);
  geom_u256 pp = shape_circle_u256(ap, ap);
  if (nb == 0) return geom_u256_cmp(&A, &pp);    /* P < 0 < A: sign(A - P^2) */
  if (na == 0) return geom_u256_cmp(&pp, &B);    /* B > 0 < P: sign(P^2 - B) */
  return 2;
}

/* The coordinates of t (six) or the site's x, then u's: 1 and the
** differences over one unit (z[0..3], z[4..7] the triangles' b - a, c - a,
** z[8] a1.x - a2.x) when they are integers within the bounds above. */
static int shape_circle_idiffs(const geom_point *t, double tx, const geom_point *u, double ux,
                               int64_t z[9]) {
  double v[12];
  int n = 0;
  for (int k = 0; k < 2; k++) {
    const geom_point *p = k ? u : t;
    for (int i = 0; p != NULL && i < 3; i++) {
      v[n++] = p[i].x;
      v[n++] = p[i].y;
    }
    if (p == NULL) v[n++] = k ? ux : tx;
  }
  int64_t c[12];
  if (!geom_ints(v, n, geom_int_scale(v, n), 0x1p62, c)) return 0;
  int nt = t != NULL ? 6 : 1;
  for (int k = 0; k < 2; k++) {   /* |c| < 2^62: every difference fits int64_t */
    const int64_t *q = c + (k ? nt : 0);
    for (int i = 0; i < 4; i++) z[4 * k + i] = (k ? u : t) != NULL ? q[2 + i] - q[i % 2] : 0;
  }
  z[8] = c[0] - c[nt];
  uint64_t bits = 0, mag[9], tri = 0;
  for (int i = 0; i < 9; i++) bits |= mag[i] = (uint64_t)(z[i] < 0 ? -z[i] : z[i]);
  int m = bits != 0 ? shape_sweep_ctz(bits) : 0;
  for (int i = 0; i < 9; i++) {   /* exact: every z[i] is a multiple of 2^m */
    mag[i] >>= m;
    z[i] = z[i] < 0 ? -(int64_t)mag[i] : (int64_t)mag[i];
    tri |= i < 8 ? mag[i] : 0;
  }
  return tri < (1u << 20) && mag[8] < ((uint64_t)1 << 40);
}

/* The sign of key(t) - key(u) in integers (t == NULL: the site key tx, u
** == NULL: ux), or 2 when this stage cannot tell. */
static int shape_circle_key_int(const geom_point *t, double tx, const geom_point *u, double ux) {
  int64_t z[9];
  if (!shape_circle_idiffs(t, tx, u, ux, z)) return 2;
  shape_sweep_ikey k1 = shape_circle_ik(z[8], t != NULL ? z : NULL);
  shape_sweep_ikey k2 = shape_circle_ik(0, u != NULL ? z + 4 : NULL);
  return shape_circle_ik_cmp(&k1, &k2);
}

/* t's key (t == NULL: the site key x) in the frame. */
static void shape_circle_ikey(const void *ctx, const shape_sweep_frame *f, const geom_point *t,
                              double x, shape_sweep_ikey *k) {
  (void)ctx;
  int64_t a[2], b[2], c[2];
  shape_sweep_in_frame(f, t != NULL ? t[0] : (geom_point){x, 0}, a);
  if (t == NULL) {
    *k = shape_circle_ik(a[0], NULL);
    return;
  }
  shape_sweep_in_frame(f, t[1], b);
  shape_sweep_in_frame(f, t[2], c);
  const int64_t z[4] = {b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]};
  *k = shape_circle_ik(a[0], z);
}
#endif

/* Exact: the integer stage above when it applies, else both keys as q +
** sqrt(r2), compared by shape_sweep_sqrt_cmp, in the ellipses' arithmetic
** with the circle's form (the circumcentre is the centre formula with
** |.|^2 for Q).  The sweep calls it only when the certified bounds of the
** two keys overlap. */
static int shape_circle_key_cmp(const void *ctx, const geom_point *t, double tx,
                                const geom_point *u, double ux) {
  (void)ctx;
#if GEOM_HAVE_INT128
  if (t != NULL || u != NULL) {
    int s = shape_circle_key_int(t, tx, u, ux);
    if (s != 2) return s;
  }
#endif
  return shape_sweep_conic_key_cmp(&shape_circle_form, t, tx, u, ux);
}

/* ---- the "above" test -------------------------------------------------- */

/* sign(2 X.y - A.y - B.y).  d1 = fl(X.y - A.y), d2 = fl(X.y - B.y) and
** fl(d1 + d2) carry one rounding each: |fl(d1 + d2) - (2 X.y - A.y - B.y)|
** <= eps (|X.y - A.y| + |X.y - B.y| + |d1 + d2|) < 4 eps (|d1| + |d2|)
** (the margin absorbs the rounding of the bound itself), so a larger
** |fl(d1 + d2)| has the true sign; otherwise rationals decide (the
** column's sign of the form x^2 + y^2). */
static int shape_circle_mid_sign(geom_point A, geom_point B, geom_point X) {
  double d1 = X.y - A.y, d2 = X.y - B.y, s = d1 + d2;
  double bound = 4 * GEOM_EPS * (fabs(d1) + fabs(d2));
  if (s > bound) return 1;
  if (-s > bound) return -1;
  return shape_sweep_conic_column(&shape_circle_form, A, B, X);
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
** which covers the rounding of the bound; otherwise rationals decide (the
** lift sign of the form x^2 + y^2). */
static int shape_circle_lift_sign(geom_point A, geom_point B, geom_point X) {
  double ax = A.x - X.x, ay = A.y - X.y, bx = B.x - X.x, by = B.y - X.y;
  double t1 = ax * (bx * bx + by * by), t2 = bx * (ax * ax + ay * ay), n = t1 - t2;
  double bound = 8 * GEOM_EPS * (fabs(t1) + fabs(t2));
  if (n > bound) return 1;
  if (-n > bound) return -1;
  return shape_sweep_conic_lift(&shape_circle_form, A, B, X);
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
** o = 0 puts X at M, strictly between T1 and T2 (shape_sweep_conic_side).
** A.x = B.x: the contact point is at (A.y + B.y) / 2 whatever the
** sweepline.  All exact. */
static int shape_circle_above(const void *ctx, geom_point A, geom_point B, geom_point X) {
  (void)ctx;
  if (A.x == B.x) return shape_circle_mid_sign(A, B, X) > 0;
  int oab, side = shape_sweep_conic_side(A, B, X, &oab);
  return side != 2 ? side : shape_circle_lift_sign(A, B, X) * oab < 0;
}

const shape_sweep shape_sweep_circle = {"circle", NULL, shape_sweep_closes,
                                        shape_circle_key_bounds, shape_circle_key_cmp,
                                        shape_circle_above, NULL,
#if GEOM_HAVE_INT128
                                        shape_sweep_frame_make, shape_circle_ikey,
                                        shape_circle_ik_cmp
#else
                                        NULL, NULL, NULL
#endif
};
