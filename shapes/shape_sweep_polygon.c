/*
** shape_sweep_polygon.c: a convex polygon's primitives for the sweepline
** algorithm (shape_sweep_internal.h), for lot --algorithm sweep with an
** empty-shape rule ES:SHAPE of a polygon K (docs/lot.md has the argument).
**
** The circumscribing shape of an event's triangle (shape_circumscribe, with
** the rule's tie-break) is a homothet H = t + sK of K, or the rounding shape
** of a corner c of K: the region (X - hx)(Y - hy) >= r, X > hx in the
** coordinates X = cross(p, v), Y = cross(u, p) of c's sides u = k_{c+1} -
** k_c, v = k_{c-1} - k_c (a point is u X / delta + v Y / delta, delta =
** cross(u, v) > 0).  Keys, the x of the rightmost point:
**   homothet: t.x + s xr, xr the x of K's rightmost corner J (of a vertical
**     right edge, its lower end: the tie-break turns K anticlockwise);
**     (t, s) solves the rows (n_m, h_m | n_m.P) of the contact edges
**     (shape_polygon.c), so the key is rational: A.x + (Dx + xr Ds) / D;
**   rounding shape of J (both sides point left, or one is vertical):
**     its rightmost point is where u_x X + v_x Y is largest on the branch,
**     A.x + (u_x hx + v_x hy - 2 sqrt(u_x v_x r)) / delta (AM-GM), with
**     the sites relative to A (so r = hx hy): q - sqrt(R), rationals q, R;
**   rounding shape of any other corner: unbounded to the right, an
**     infinite key omega alpha sqrt(r) + O(1), after every site and finite
**     event (thesis 4.1), ordered as below (shape_poly_inf_q).
** The "above" test of X against the breakpoint of A, B: as for the circle,
** X west of A -> B (or on its line) is above exactly when A.x < B.x; X east
** of it is above exactly when X is the top end of the vertical chord of
** the circumscribing shape S of A, B, X (S then reaches beyond the
** sweepline and its chord contains the breakpoint, by the nesting of the
** shapes through A and B), and so is every X when A.x = B.x.  X is the top
** end when the outward normal at X points up: for a homothet, when X's
** contact edge runs leftwards (or is a right vertical edge, running up:
** turned by the tie-break); for a rounding shape, when v_x (Y - hy) -
** u_x (X - hx) > 0 at X, which with X at the origin and the other two
** sites P, Q is the sign of u_x P_X Q_X (Q_Y - P_Y) - v_x P_Y Q_Y (P_X -
** Q_X) times that of P_X Q_Y - P_Y Q_X.
** Exactness: each quantity is a rational function of the inputs, first
** evaluated in certified intervals (shape_sweep_internal.h), then in GMP
** rationals (the pool of shape_internal.h) when the interval cannot
** decide.  What the rule's tie-break
** (K turned by an infinitesimal angle) would have to settle beyond the
** support points (equal keys of two events that share a boundary edge, a
** zero "above" sign, an 'either' between two infinite events) is decided
** by a fixed rule (creation order, "not above") and counted in *special:
** lot then checks the mesh and flips it to the tie-broken LOT (lot.c,
** lot_sweep_mesh).  Equal keys of events that share no edge are harmless:
** the events commute.
*/
#include <math.h>
#include <stdint.h>
#include "geom_int_internal.h"
#include "shape_internal.h"
#include "shape_sweep_internal.h"

typedef enum shape_poly_kind {
  SHAPE_PK_SITE, SHAPE_PK_HOMOTHET, SHAPE_PK_CORNER, SHAPE_PK_INFINITE
} shape_poly_kind;

/* An event's circumscribing shape: its kind, the triangle anticlockwise,
** the contact edges (homothet) or the corner. */
typedef struct shape_poly_ev {
  shape_poly_kind kind;
  geom_point p[3];
  int e[3], corner;
} shape_poly_ev;

static int shape_poly_same(const geom_point a[3], const geom_point b[3]) {
  return a[0].x == b[0].x && a[0].y == b[0].y && a[1].x == b[1].x && a[1].y == b[1].y
      && a[2].x == b[2].x && a[2].y == b[2].y;
}

/* Triangle t's circumscribing shape, from the memo when t was the last
** one classified (a special position, r < 0, is counted once). */
static void shape_poly_classify(const shape_sweep_poly *P, const geom_point t[3],
                                shape_poly_ev *ev) {
  /* t: bottom to top on the boundary, turning clockwise; a c b is anticlockwise. */
  ev->p[0] = t[0];
  ev->p[1] = t[2];
  ev->p[2] = t[1];
  shape_sweep_poly_memo *m = P->memo;
  if (m->ok && shape_poly_same(m->t, t)) {
    ev->kind = (shape_poly_kind)m->kind;
    ev->e[0] = m->e[0], ev->e[1] = m->e[1], ev->e[2] = m->e[2];
    ev->corner = m->corner;
    return;
  }
  int r = shape_circumscribe(P->k, ev->p[0], ev->p[1], ev->p[2], ev->e, &ev->corner);
  if (r < 0) ++*P->special;
  ev->kind = r != 0                    ? SHAPE_PK_HOMOTHET
           : ev->corner == P->right ? SHAPE_PK_CORNER
                                    : SHAPE_PK_INFINITE;
  *m = (shape_sweep_poly_memo){{t[0], t[1], t[2]}, 1, ev->kind, {ev->e[0], ev->e[1], ev->e[2]},
                               ev->corner};
}

/* ---- intervals ------------------------------------------------------- */

static shape_iv shape_poly_det3(shape_iv m[3][3]) {
  shape_iv a = shape_iv_mul(m[0][0], shape_iv_sub(shape_iv_mul(m[1][1], m[2][2]),
                                                  shape_iv_mul(m[1][2], m[2][1])));
  shape_iv b = shape_iv_mul(m[0][1], shape_iv_sub(shape_iv_mul(m[1][0], m[2][2]),
                                                  shape_iv_mul(m[1][2], m[2][0])));
  shape_iv c = shape_iv_mul(m[0][2], shape_iv_sub(shape_iv_mul(m[1][0], m[2][1]),
                                                  shape_iv_mul(m[1][1], m[2][0])));
  return shape_iv_add(shape_iv_sub(a, b), c);
}

/* The homothet's key in intervals: rows (n_x, n_y, h | w) of the contact
** edges, w = n.(P - A). */
static shape_iv shape_poly_hom_iv(const shape_sweep_poly *P, const shape_poly_ev *ev) {
  const geom_point *v = P->k->v;
  int n = P->k->n;
  shape_iv m[3][3], w[3];
  for (int r = 0; r < 3; r++) {
    geom_point a = v[ev->e[r]], b = v[(ev->e[r] + 1) % n];
    m[r][0] = shape_iv_diff(b.y, a.y);
    m[r][1] = shape_iv_diff(a.x, b.x);
    m[r][2] = shape_iv_sub(shape_iv_mul((shape_iv){a.x, 0}, (shape_iv){b.y, 0}),
                           shape_iv_mul((shape_iv){a.y, 0}, (shape_iv){b.x, 0}));
    w[r] = shape_iv_add(shape_iv_mul(m[r][0], shape_iv_diff(ev->p[r].x, ev->p[0].x)),
                        shape_iv_mul(m[r][1], shape_iv_diff(ev->p[r].y, ev->p[0].y)));
  }
  shape_iv d = shape_poly_det3(m), mx[3][3], ms[3][3];
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) {
      mx[r][c] = c == 0 ? w[r] : m[r][c];
      ms[r][c] = c == 2 ? w[r] : m[r][c];
    }
  shape_iv num = shape_iv_add(shape_poly_det3(mx),
                              shape_iv_mul((shape_iv){P->xr, 0}, shape_poly_det3(ms)));
  return shape_iv_add((shape_iv){ev->p[0].x, 0}, shape_iv_div(num, d));
}

/* Corner c's sides u, v and the mapped coordinates (X, Y) of p - o. */
static void shape_poly_sides_iv(const shape_sweep_poly *P, int c, shape_iv u[2],
                                shape_iv v[2]) {
  const geom_point *k = P->k->v;
  int n = P->k->n;
  geom_point a = k[c], b = k[(c + 1) % n], z = k[(c + n - 1) % n];
  u[0] = shape_iv_diff(b.x, a.x);
  u[1] = shape_iv_diff(b.y, a.y);
  v[0] = shape_iv_diff(z.x, a.x);
  v[1] = shape_iv_diff(z.y, a.y);
}

static void shape_poly_map_iv(const shape_iv u[2], const shape_iv v[2], geom_point p,
                              geom_point o, shape_iv out[2]) {
  shape_iv dx = shape_iv_diff(p.x, o.x), dy = shape_iv_diff(p.y, o.y);
  out[0] = shape_iv_sub(shape_iv_mul(dx, v[1]), shape_iv_mul(dy, v[0]));   /* cross(p - o, v) */
  out[1] = shape_iv_sub(shape_iv_mul(u[0], dy), shape_iv_mul(u[1], dx));   /* cross(u, p - o) */
}

/* The hyperbola's centre (hx, hy) through the origin and the mapped P, Q:
** hy P_X + hx P_Y = P_X P_Y, likewise Q (Cramer). */
static void shape_poly_centre_iv(const shape_iv p[2], const shape_iv q[2], shape_iv *hx,
                                 shape_iv *hy) {
  shape_iv d = shape_iv_sub(shape_iv_mul(p[0], q[1]), shape_iv_mul(p[1], q[0]));
  *hx = shape_iv_div(shape_iv_mul(shape_iv_mul(p[0], q[0]), shape_iv_sub(q[1], p[1])), d);
  *hy = shape_iv_div(shape_iv_mul(shape_iv_mul(p[1], q[1]), shape_iv_sub(p[0], q[0])), d);
}

static shape_iv shape_poly_corner_iv(const shape_sweep_poly *P, const shape_poly_ev *ev) {
  shape_iv u[2], v[2], b[2], c[2], hx, hy;
  shape_poly_sides_iv(P, ev->corner, u, v);
  shape_poly_map_iv(u, v, ev->p[1], ev->p[0], b);
  shape_poly_map_iv(u, v, ev->p[2], ev->p[0], c);
  shape_poly_centre_iv(b, c, &hx, &hy);
  shape_iv delta = shape_iv_sub(shape_iv_mul(u[0], v[1]), shape_iv_mul(u[1], v[0]));
  shape_iv lin = shape_iv_add(shape_iv_mul(u[0], hx), shape_iv_mul(v[0], hy));
  shape_iv rt = shape_iv_sqrt(shape_iv_mul(shape_iv_mul(u[0], v[0]), shape_iv_mul(hx, hy)));
  shape_iv num = shape_iv_sub(lin, shape_iv_add(rt, rt));
  return shape_iv_add((shape_iv){ev->p[0].x, 0}, shape_iv_div(num, delta));
}

/* The infinite key's leading coefficient alpha sqrt(r) (shape_poly_inf_q)
** in intervals; *level 1 for the top end of a vertical right edge. */
static shape_iv shape_poly_inf_iv(const shape_sweep_poly *P, const shape_poly_ev *ev,
                                  int *level) {
  shape_iv u[2], v[2], b[2], c[2], hx, hy;
  shape_poly_sides_iv(P, ev->corner, u, v);
  shape_poly_map_iv(u, v, ev->p[1], ev->p[0], b);
  shape_poly_map_iv(u, v, ev->p[2], ev->p[0], c);
  shape_poly_centre_iv(b, c, &hx, &hy);
  geom_point kc = P->k->v[ev->corner], kj = P->k->v[P->right];
  *level = kc.x == kj.x;
  shape_iv al = *level ? shape_iv_diff(kc.y, kj.y) : shape_iv_diff(kj.x, kc.x);
  return shape_iv_mul(al, shape_iv_sqrt(shape_iv_mul(hx, hy)));
}

/* Heap bounds of an infinite key, in bands above every finite one: the
** heap decides by disjoint bounds only, so they need only be monotone in
** the key's order (a larger band, or the same band and a larger
** coefficient), never enclose it.  Finite bounds are clipped to
** [-inf, 2^140] from above (lo) and sent to +inf beyond 2^140 (hi), so a
** finite key never looks larger than a band: level 1 maps the coefficient
** a to 2^300 clamp(a, 2^-150, 2^150) in [2^150, 2^450], level 0 to 2^600
** clamp(a, 2^-140, 2^390) in [2^460, 2^990]; anything overlapping goes to
** the exact comparison. */
static double shape_poly_band(int level, double a) {
  double lo = level ? 0x1p-150 : 0x1p-140, hi = level ? 0x1p150 : 0x1p390;
  a = a < lo ? lo : a > hi ? hi : a;
  return a * (level ? 0x1p300 : 0x1p600);
}

static void shape_poly_key_bounds(const void *ctx, const geom_point t[3], double *lo,
                                  double *hi) {
  const shape_sweep_poly *P = ctx;
  shape_poly_ev ev;
  int level;
  double l, h;
  shape_poly_classify(P, t, &ev);
  switch (ev.kind) {
  case SHAPE_PK_INFINITE:
    shape_iv_bounds(shape_poly_inf_iv(P, &ev, &level), &l, &h);   /* infinite when unknown */
    *lo = shape_poly_band(level, l);
    *hi = shape_poly_band(level, h);
    return;
  case SHAPE_PK_HOMOTHET: shape_iv_bounds(shape_poly_hom_iv(P, &ev), lo, hi); break;
  case SHAPE_PK_CORNER: shape_iv_bounds(shape_poly_corner_iv(P, &ev), lo, hi); break;
  case SHAPE_PK_SITE: break;   /* never: an event */
  }
  if (*lo > 0x1p140) *lo = 0x1p140;
  if (*hi > 0x1p140) *hi = INFINITY;
}

/* ---- rationals --------------------------------------------------------- */

static mpq_ptr shape_poly_det3_q(shape_mpq *Q, mpq_ptr m[3][3]) {
  mpq_ptr x = shape_mpq_new(Q), t = shape_mpq_new(Q);
  mpq_mul(x, m[0][0], shape_mpq_cross(Q, m[1][1], m[2][2], m[1][2], m[2][1]));
  mpq_mul(t, m[0][1], shape_mpq_cross(Q, m[1][0], m[2][2], m[1][2], m[2][0]));
  mpq_sub(x, x, t);
  mpq_mul(t, m[0][2], shape_mpq_cross(Q, m[1][0], m[2][1], m[1][1], m[2][0]));
  mpq_add(x, x, t);
  return x;
}

/* The homothet's key, exactly, into q. */
static void shape_poly_hom_q(const shape_sweep_poly *P, const shape_poly_ev *ev, mpq_ptr q) {
  shape_mpq Q;
  shape_mpq_init(&Q);
  const geom_point *v = P->k->v;
  int n = P->k->n;
  mpq_ptr m[3][3], w[3], mx[3][3], ms[3][3];
  for (int r = 0; r < 3; r++) {
    geom_point a = v[ev->e[r]], b = v[(ev->e[r] + 1) % n];
    m[r][0] = shape_mpq_diff(&Q, b.y, a.y);
    m[r][1] = shape_mpq_diff(&Q, a.x, b.x);
    m[r][2] = shape_mpq_cross(&Q, shape_mpq_d(&Q, a.x), shape_mpq_d(&Q, b.y),
                              shape_mpq_d(&Q, a.y), shape_mpq_d(&Q, b.x));
    mpq_ptr dx = shape_mpq_diff(&Q, ev->p[r].x, ev->p[0].x);
    mpq_ptr dy = shape_mpq_diff(&Q, ev->p[r].y, ev->p[0].y);
    w[r] = shape_mpq_new(&Q);
    mpq_mul(w[r], m[r][0], dx);
    mpq_mul(dy, m[r][1], dy);
    mpq_add(w[r], w[r], dy);
  }
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) {
      mx[r][c] = c == 0 ? w[r] : m[r][c];
      ms[r][c] = c == 2 ? w[r] : m[r][c];
    }
  mpq_ptr d = shape_poly_det3_q(&Q, m), dx = shape_poly_det3_q(&Q, mx);
  mpq_ptr ds = shape_poly_det3_q(&Q, ms);
  mpq_mul(ds, ds, shape_mpq_d(&Q, P->xr));
  mpq_add(dx, dx, ds);
  mpq_div(q, dx, d);
  mpq_add(q, q, shape_mpq_d(&Q, ev->p[0].x));
  shape_mpq_clear(&Q);
}

/* Corner c's sides, and p - o mapped (cross(p - o, v), cross(u, p - o)). */
static void shape_poly_sides_q(shape_mpq *Q, const shape_sweep_poly *P, int c, mpq_ptr u[2],
                               mpq_ptr v[2]) {
  const geom_point *k = P->k->v;
  int n = P->k->n;
  geom_point a = k[c], b = k[(c + 1) % n], z = k[(c + n - 1) % n];
  u[0] = shape_mpq_diff(Q, b.x, a.x);
  u[1] = shape_mpq_diff(Q, b.y, a.y);
  v[0] = shape_mpq_diff(Q, z.x, a.x);
  v[1] = shape_mpq_diff(Q, z.y, a.y);
}

static void shape_poly_map_q(shape_mpq *Q, mpq_ptr u[2], mpq_ptr v[2], geom_point p,
                             geom_point o, mpq_ptr out[2]) {
  mpq_ptr dx = shape_mpq_diff(Q, p.x, o.x), dy = shape_mpq_diff(Q, p.y, o.y);
  out[0] = shape_mpq_cross(Q, dx, v[1], dy, v[0]);
  out[1] = shape_mpq_cross(Q, u[0], dy, u[1], dx);
}

/* hx, hy (shape_poly_centre_iv) times d = P_X Q_Y - P_Y Q_X, and d. */
static void shape_poly_centre_q(shape_mpq *Q, mpq_ptr p[2], mpq_ptr q[2], mpq_ptr *hx,
                                mpq_ptr *hy, mpq_ptr *d) {
  *d = shape_mpq_cross(Q, p[0], q[1], p[1], q[0]);
  *hx = shape_mpq_new(Q);
  *hy = shape_mpq_new(Q);
  mpq_ptr t = shape_mpq_new(Q);
  mpq_mul(*hx, p[0], q[0]);
  mpq_sub(t, q[1], p[1]);
  mpq_mul(*hx, *hx, t);
  mpq_mul(*hy, p[1], q[1]);
  mpq_sub(t, p[0], q[0]);
  mpq_mul(*hy, *hy, t);
}

/* Event ev's corner in rationals from Q: its sides u, v, delta = cross(u,
** v), the centre (hx, hy) of its hyperbola through the mapped sites, and
** the apex's x (the centre mapped back, plus the first site's x). */
static void shape_poly_apex_q(shape_mpq *Q, const shape_sweep_poly *P, const shape_poly_ev *ev,
                              mpq_ptr u[2], mpq_ptr v[2], mpq_ptr *hx, mpq_ptr *hy,
                              mpq_ptr *delta, mpq_ptr x) {
  mpq_ptr b[2], c[2], d;
  shape_poly_sides_q(Q, P, ev->corner, u, v);
  shape_poly_map_q(Q, u, v, ev->p[1], ev->p[0], b);
  shape_poly_map_q(Q, u, v, ev->p[2], ev->p[0], c);
  shape_poly_centre_q(Q, b, c, hx, hy, &d);
  mpq_div(*hx, *hx, d);
  mpq_div(*hy, *hy, d);
  *delta = shape_mpq_cross(Q, u[0], v[1], u[1], v[0]);
  mpq_ptr t = shape_mpq_new(Q);
  mpq_mul(x, u[0], *hx);
  mpq_mul(t, v[0], *hy);
  mpq_add(x, x, t);
  mpq_div(x, x, *delta);
  mpq_add(x, x, shape_mpq_d(Q, ev->p[0].x));
}

/* The corner's key as q - sqrt(R), exactly. */
static void shape_poly_corner_q(const shape_sweep_poly *P, const shape_poly_ev *ev, mpq_ptr q,
                                mpq_ptr R) {
  shape_mpq Q;
  shape_mpq_init(&Q);
  mpq_ptr u[2], v[2], hx, hy, delta;
  shape_poly_apex_q(&Q, P, ev, u, v, &hx, &hy, &delta, q);
  mpq_ptr t = shape_mpq_new(&Q);
  mpq_mul(R, u[0], v[0]);
  mpq_mul(R, R, hx);
  mpq_mul(R, R, hy);
  mpq_mul_2exp(R, R, 2);
  mpq_mul(t, delta, delta);
  mpq_div(R, R, t);
  shape_mpq_clear(&Q);
}

/* ---- integer keys ------------------------------------------------------
**
** A homothet's key A.x + (det Mx + xr det Ms) / det M is rational, and on
** grids many are equal (the squares of a grid column), which the bounds
** cannot separate.  The key does not change when K is scaled (t stays, s
** scales inversely), so K is taken times kscale = 2^p, the least power of
** two that makes its corners integers, when those are within 2^20
** (square, diamond, triangle, integer polygons, and the hexagon and the
** octagon, whose corners have 20 fraction bits: P->kscale), and the run's
** sites fit its frame (integers in [0, 2^20), shape_sweep_frame_make):
** then every entry is an integer: an edge's n = (b.y - a.y, a.x - b.x)
** within 2^21, h = a.x b.y - a.y b.x within 2^41, w = n.(P - A) within
** 2^42, so |det M| < 6 2^83 < 2^86, |det Mx| < 6 2^104 < 2^107, |det Ms|
** < 6 2^84 < 2^87 and the numerator N = det Mx + xr det Ms < 2^108
** (__int128; every partial product is below 2^106).  The key's record
** keeps N / D when |D| < 2^46 and |N| < 2^78, reduced by their gcd when
** they are not (corners within 2^10 always fit unreduced: |D| < 2^46, |N|
** < 2^68).  Two keys then compare as (ax1 - ax2) D1 D2 + N1 D2 - N2 D1
** times the sign of D1 D2, below 2^20 2^92 + 2 2^124 < 2^126.  A site's
** key x is N = 0, D = 1.  Other keys (corners', infinite ones, every key
** of a K with other corners, a homothet's whose reduced terms do not fit)
** get a translate record (known = 2): the kind, the contact edges or
** corner, and the triangle's differences over the frame.  Keys are
** functions of those and of a.x alone (the exact classification and keys
** are translation invariant), so two equal records differ by a1.x - a2.x:
** the grid's columns of equal keys, compared without GMP; other pairs are
** left to key_cmp.  The sweep makes each event's record once (ikey) and
** compares records (ikey_cmp) before it compares points. */
#if GEOM_HAVE_INT128
static geom_i128 shape_poly_det3_i(geom_i128 m[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
       - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
       + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/* gcd(a, b), b > 0, binary: at most 2 x 128 shifts and subtractions. */
static geom_u128 shape_poly_gcd(geom_u128 a, geom_u128 b) {
  if (a == 0) return b;
  int z = 0;
  while (((a | b) & 1) == 0) a >>= 1, b >>= 1, z++;
  while ((a & 1) == 0) a >>= 1;
  while (b != 0) {
    while ((b & 1) == 0) b >>= 1;
    if (a > b) {
      geom_u128 t = a;
      a = b, b = t;
    }
    b -= a;
  }
  return a << z;
}

static geom_u128 shape_poly_abs(geom_i128 v) {
  return v < 0 ? -(geom_u128)v : (geom_u128)v;
}

/* The record of N / D (D != 0) at a.x: reduced if it must be, translate
** record (known 0, to be filled) if it does not fit even so. */
static shape_sweep_ikey shape_poly_ratio_i(int64_t ax, geom_i128 N, geom_i128 D) {
  const geom_u128 dmax = (geom_u128)1 << 46, nmax = (geom_u128)1 << 78;
  if (shape_poly_abs(D) >= dmax || shape_poly_abs(N) >= nmax) {
    geom_i128 g = (geom_i128)shape_poly_gcd(shape_poly_abs(N), shape_poly_abs(D));
    N /= g, D /= g;
    if (shape_poly_abs(D) >= dmax || shape_poly_abs(N) >= nmax)
      return (shape_sweep_ikey){.known = 0};
  }
  geom_u128 un = (geom_u128)N;
  return (shape_sweep_ikey){ax, (int64_t)D, 0, (uint64_t)un, (uint64_t)(un >> 64), 1};
}

/* The homothet's key of ev over the frame: a.x, D, N (shape_poly_hom_q's
** formula, in integers, K times kscale). */
static shape_sweep_ikey shape_poly_hom_i(const shape_sweep_poly *P, const shape_sweep_frame *f,
                                         const shape_poly_ev *ev) {
  const geom_point *v = P->k->v;
  int n = P->k->n;
  double ks = P->kscale;
  int64_t z[3][2];
  for (int r = 0; r < 3; r++) shape_sweep_in_frame(f, ev->p[r], z[r]);
  geom_i128 m[3][3], mx[3][3], ms[3][3], w[3];
  for (int r = 0; r < 3; r++) {
    geom_point a = v[ev->e[r]], b = v[(ev->e[r] + 1) % n];
    int64_t ax = (int64_t)(a.x * ks), ay = (int64_t)(a.y * ks);   /* exact: see above */
    int64_t bx = (int64_t)(b.x * ks), by = (int64_t)(b.y * ks);
    m[r][0] = by - ay;
    m[r][1] = ax - bx;
    m[r][2] = ax * by - ay * bx;
    w[r] = m[r][0] * (z[r][0] - z[0][0]) + m[r][1] * (z[r][1] - z[0][1]);
  }
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) {
      mx[r][c] = c == 0 ? w[r] : m[r][c];
      ms[r][c] = c == 2 ? w[r] : m[r][c];
    }
  geom_i128 xr = (geom_i128)(int64_t)(P->xr * ks);
  geom_i128 N = shape_poly_det3_i(mx) + xr * shape_poly_det3_i(ms);
  return shape_poly_ratio_i(z[0][0], N, shape_poly_det3_i(m));
}

static void shape_poly_ikey(const void *ctx, const shape_sweep_frame *f, const geom_point *t,
                            double x, shape_sweep_ikey *k) {
  const shape_sweep_poly *P = ctx;
  if (t == NULL) {
    int64_t z[2];
    shape_sweep_in_frame(f, (geom_point){x, 0}, z);
    *k = (shape_sweep_ikey){z[0], 1, 0, 0, 0, 1};
    return;
  }
  shape_poly_ev ev;
  shape_poly_classify(P, t, &ev);   /* key_bounds's, from the memo */
  if (P->kscale > 0 && ev.kind == SHAPE_PK_HOMOTHET) {
    *k = shape_poly_hom_i(P, f, &ev);
    if (k->known) return;
  }
  int64_t z[3][2];   /* in t's order: the same differences for translates */
  for (int r = 0; r < 3; r++) shape_sweep_in_frame(f, t[r], z[r]);
  uint64_t tag = (uint64_t)ev.kind;
  const int idx[4] = {ev.e[0], ev.e[1], ev.e[2], ev.corner};
  for (int i = 0; i < 4; i++) tag = tag << 12 | ((uint64_t)idx[i] & 0xfff);
  uint64_t d1 = (uint64_t)(z[1][0] - z[0][0]) << 32 | (uint32_t)(z[1][1] - z[0][1]);
  uint64_t d2 = (uint64_t)(z[2][0] - z[0][0]) << 32 | (uint32_t)(z[2][1] - z[0][1]);
  *k = (shape_sweep_ikey){z[0][0], (int64_t)tag, (int64_t)d1, d2, 0, 2};
}

static int shape_poly_ikey_cmp(const shape_sweep_ikey *a, const shape_sweep_ikey *b) {
  if (a->known == 2 && b->known == 2 && a->d == b->d && a->snx == b->snx && a->nlo == b->nlo)
    return (a->ax > b->ax) - (a->ax < b->ax);   /* translates */
  if (a->known != 1 || b->known != 1) return 2;
  geom_i128 na = (geom_i128)((geom_u128)a->nhi << 64 | a->nlo);
  geom_i128 nb = (geom_i128)((geom_u128)b->nhi << 64 | b->nlo);
  geom_i128 v = (geom_i128)(a->ax - b->ax) * a->d * b->d + na * b->d - nb * a->d;
  int s = (v > 0) - (v < 0);
  return (a->d < 0) != (b->d < 0) ? -s : s;
}

#endif

/* The least 2^p (p <= 60) that makes K's corners integers within 2^20,
** or 0 (the integer keys above). */
static double shape_poly_int_scale(const shape *k) {
  double big = 0;
  int p = 0;
  for (int c = 0; c < k->n; c++)
    for (int i = 0; i < 2; i++) {
      double v = fabs(i ? k->v[c].y : k->v[c].x);
      big = v > big ? v : big;
      while (p <= 60 && ldexp(v, p) != floor(ldexp(v, p))) p++;
    }
  return p <= 60 && ldexp(big, p) <= 0x1p20 ? ldexp(1, p) : 0;
}

/* ---- infinite keys ----------------------------------------------------- */

/* The rounding shape of corner c != J is the limit of homothets t + sK' of
** K' (K with its corners rounded by (X - k_c)(Y - k_c) = rho in each
** corner's coordinates) with s = sqrt(r / rho) -> infinity; its rightmost
** point is at t.x + s xr' = apex.x + s (xr - k_c.x) + O(1): the key is
** omega alpha sqrt(r) + O(1), omega = rho^-1/2 infinite, alpha = xr - k_c.x
** > 0.  For the top end c = J + 1 of a vertical right edge alpha is 0, and
** the tie-break (K turned by eps) makes it eps (y_{J+1} - y_J): smaller
** than every other alpha, and infinite still (rho -> 0 first).  Two such
** keys are ordered by (alpha0, alpha1) sqrt(r) lexicographically (alpha =
** alpha0 + eps alpha1), i.e. by alpha^2 r, rationals; equal leading terms
** of one corner (equal r) by the apex's x; others count as special. */
static void shape_poly_inf_q(const shape_sweep_poly *P, const shape_poly_ev *ev, mpq_ptr a2r,
                             mpq_ptr apex, int *level) {
  shape_mpq Q;
  shape_mpq_init(&Q);
  mpq_ptr u[2], v[2], hx, hy, delta;
  shape_poly_apex_q(&Q, P, ev, u, v, &hx, &hy, &delta, apex);
  geom_point kc = P->k->v[ev->corner], kj = P->k->v[P->right];
  *level = kc.x == kj.x;
  mpq_ptr al = *level ? shape_mpq_diff(&Q, kc.y, kj.y) : shape_mpq_diff(&Q, kj.x, kc.x);
  mpq_mul(a2r, al, al);
  mpq_mul(a2r, a2r, hx);
  mpq_mul(a2r, a2r, hy);
  shape_mpq_clear(&Q);
}

static int shape_poly_inf_cmp(const shape_sweep_poly *P, const shape_poly_ev *e1,
                              const shape_poly_ev *e2) {
  mpq_t a1, p1, a2, p2;
  mpq_inits(a1, p1, a2, p2, NULL);
  int l1, l2;
  shape_poly_inf_q(P, e1, a1, p1, &l1);
  shape_poly_inf_q(P, e2, a2, p2, &l2);
  int s = l1 != l2 ? (l1 < l2 ? 1 : -1) : mpq_cmp(a1, a2);
  if (s == 0 && e1->corner == e2->corner) s = mpq_cmp(p1, p2);
  s = (s > 0) - (s < 0);
  mpq_clears(a1, p1, a2, p2, NULL);
  return s;
}

/* A key as q + sg sqrt(r) (sites and homothets: r = 0), or infinite. */
static shape_poly_kind shape_poly_key_q(const shape_sweep_poly *P, const geom_point *t,
                                        double x, mpq_ptr q, mpq_ptr r, shape_poly_ev *ev) {
  mpq_set_ui(r, 0, 1);
  if (t == NULL) {
    mpq_set_d(q, x);
    return ev->kind = SHAPE_PK_SITE;
  }
  shape_poly_classify(P, t, ev);
  switch (ev->kind) {
  case SHAPE_PK_HOMOTHET: shape_poly_hom_q(P, ev, q); break;
  case SHAPE_PK_CORNER: shape_poly_corner_q(P, ev, q, r); break;
  case SHAPE_PK_INFINITE: break;   /* shape_poly_inf_cmp */
  case SHAPE_PK_SITE: break;       /* never: an event */
  }
  return ev->kind;
}

/* sign(d + sqrt r1 + sqrt r2), r1, r2 >= 0: d's when d >= 0; else by
** squaring, (sqrt r1 + sqrt r2)^2 - d^2 = e + 2 sqrt(r1 r2), e = r1 + r2 - d^2
** (shape_sweep_root_sign). */
static int shape_poly_sum_sign(mpq_srcptr d, mpq_srcptr r1, mpq_srcptr r2) {
  if (mpq_sgn(d) >= 0) return mpq_sgn(d) > 0 || mpq_sgn(r1) > 0 || mpq_sgn(r2) > 0;
  mpq_t e, f;
  mpq_inits(e, f, NULL);
  mpq_mul(e, d, d);
  mpq_sub(e, r1, e);
  mpq_add(e, e, r2);
  mpq_mul(f, r1, r2);
  int s = shape_sweep_root_sign(e, f);
  mpq_clears(e, f, NULL);
  return s;
}

/* sign((q1 + s1 sqrt r1) - (q2 + s2 sqrt r2)), s1, s2 = +-1. */
static int shape_poly_cmp_q(mpq_ptr q1, int s1, mpq_ptr r1, mpq_ptr q2, int s2, mpq_ptr r2) {
  if (s1 > 0 && s2 > 0) return shape_sweep_sqrt_cmp(q1, r1, q2, r2);
  if (s1 < 0 && s2 < 0) {
    mpq_neg(q1, q1);
    mpq_neg(q2, q2);
    return -shape_sweep_sqrt_cmp(q1, r1, q2, r2);
  }
  mpq_t d;
  mpq_init(d);
  mpq_sub(d, q1, q2);
  if (s1 < 0) mpq_neg(d, d);   /* (q1 - sqrt r1) - (q2 + sqrt r2) = -(q2 - q1 + ...) */
  int s = shape_poly_sum_sign(d, r1, r2);
  mpq_clear(d);
  return s1 < 0 ? -s : s;
}

static int shape_poly_key_cmp(const void *ctx, const geom_point *t, double tx,
                              const geom_point *u, double ux) {
  const shape_sweep_poly *P = ctx;
  if (t == NULL && u == NULL) return (tx > ux) - (tx < ux);
  shape_sweep_note_gmp();
  mpq_t q1, r1, q2, r2;
  mpq_inits(q1, r1, q2, r2, NULL);
  shape_poly_ev e1, e2;
  shape_poly_kind k1 = shape_poly_key_q(P, t, tx, q1, r1, &e1);
  shape_poly_kind k2 = shape_poly_key_q(P, u, ux, q2, r2, &e2);
  int s;
  if (k1 == SHAPE_PK_INFINITE && k2 == SHAPE_PK_INFINITE) {
    s = shape_poly_inf_cmp(P, &e1, &e2);
  } else if (k1 == SHAPE_PK_INFINITE || k2 == SHAPE_PK_INFINITE) {
    s = k1 == SHAPE_PK_INFINITE ? 1 : -1;
  } else {
    int s1 = k1 == SHAPE_PK_CORNER ? -1 : 1, s2 = k2 == SHAPE_PK_CORNER ? -1 : 1;
    s = shape_poly_cmp_q(q1, s1, r1, q2, s2, r2);
  }
  mpq_clears(q1, r1, q2, r2, NULL);
  return s;
}

/* ---- the "above" test -------------------------------------------------- */

/* The sign of u_x P_X Q_X (Q_Y - P_Y) - v_x P_Y Q_Y (P_X - Q_X) times that
** of P_X Q_Y - P_Y Q_X (P, Q mapped relative to X): > 0 when X is the top
** end of the rounding shape's vertical chord. */
static int shape_poly_round_top(const shape_sweep_poly *P, int c, geom_point p, geom_point q,
                                geom_point x) {
  shape_iv u[2], v[2], a[2], b[2], hx, hy;
  shape_poly_sides_iv(P, c, u, v);
  shape_poly_map_iv(u, v, p, x, a);
  shape_poly_map_iv(u, v, q, x, b);
  shape_poly_centre_iv(a, b, &hx, &hy);
  int s = shape_iv_sign(shape_iv_sub(shape_iv_mul(u[0], hx), shape_iv_mul(v[0], hy)));
  if (s != 2) return s;
  shape_sweep_note_gmp();
  shape_mpq Q;
  shape_mpq_init(&Q);
  mpq_ptr uq[2], vq[2], aq[2], bq[2], hxq, hyq, d;
  shape_poly_sides_q(&Q, P, c, uq, vq);
  shape_poly_map_q(&Q, uq, vq, p, x, aq);
  shape_poly_map_q(&Q, uq, vq, q, x, bq);
  shape_poly_centre_q(&Q, aq, bq, &hxq, &hyq, &d);
  mpq_ptr n = shape_mpq_cross(&Q, uq[0], hxq, vq[0], hyq);
  mpq_mul(n, n, d);
  return shape_mpq_done(&Q, n);
}

/* Is X the top end of the vertical chord of the circumscribing shape of
** the anticlockwise triangle p (X = p[ix])? */
static int shape_poly_top(const shape_sweep_poly *P, const geom_point p[3], int ix) {
  int e[3], corner;
  int r = shape_circumscribe(P->k, p[0], p[1], p[2], e, &corner);
  if (r < 0) {
    ++*P->special;
    return 0;
  }
  if (r > 0) {
    geom_point a = P->k->v[e[ix]], b = P->k->v[(e[ix] + 1) % P->k->n];
    return b.x < a.x || (b.x == a.x && b.y > a.y);
  }
  int s = shape_poly_round_top(P, corner, p[(ix + 1) % 3], p[(ix + 2) % 3], p[ix]);
  if (s == 0) ++*P->special;
  return s > 0;
}

/* X against the breakpoint of A, B.  A site S of A, B on the sweepline is
** the contact point itself: the shape through A and B lies left of the
** sweepline and touches it in one point (K turned by the tie-break has one
** rightmost point), which must be S.  Sites come in (x, y) order and equal
** ones are merged, so S.y < X.y: X is above.  That is special position all
** the same, counted (the events of sites on one vertical line may tie).
** Without this case the contact test met a tie, whose fixed answer "not
** above" located X at a site on its own sweepline that is no top of the
** first column, which the site event cannot split. */
static int shape_poly_above(const void *ctx, geom_point A, geom_point B, geom_point X) {
  const shape_sweep_poly *P = ctx;
  int oab = geom_orient_valid(A, B, X);
  if (A.x == B.x && oab == 0) return 2 * X.y > A.y + B.y;   /* a column on the sweepline */
  if (A.x == X.x || B.x == X.x) {   /* a site on the sweepline: see above */
    ++*P->special;
    return 1;
  }
  if (A.x != B.x && oab >= 0) return A.x < B.x;             /* X west of A -> B, or on it */
  const geom_point ccw[3] = {A, oab < 0 ? X : B, oab < 0 ? B : X};
  return shape_poly_top(P, ccw, oab < 0 ? 1 : 2);
}

/* The rightmost corner of K turned anticlockwise by an infinitesimal
** angle: the corner whose sides both point left, a vertical side counting
** as pointing left when it runs up (its top end turns left). */
static int shape_poly_leftward(geom_point from, geom_point to) {
  return to.x != from.x ? to.x < from.x : to.y > from.y;
}

void shape_sweep_polygon(shape_sweep_poly *P, const shape *k, size_t *special,
                         shape_sweep *s) {
  int n = k->n;
  P->k = k;
  P->special = special;
  P->right = 0;
  for (int c = 0; c < n; c++)
    if (shape_poly_leftward(k->v[c], k->v[(c + 1) % n]) &&
        shape_poly_leftward(k->v[c], k->v[(c + n - 1) % n]))
      P->right = c;
  P->xr = k->v[P->right].x;
  P->kscale = shape_poly_int_scale(k);
  P->memo = &P->last;
  P->last.ok = 0;
  *s = (shape_sweep){"polygon", P, shape_sweep_closes, shape_poly_key_bounds, shape_poly_key_cmp,
                     shape_poly_above, special,
#if GEOM_HAVE_INT128
                     shape_sweep_frame_make, shape_poly_ikey, shape_poly_ikey_cmp
#else
                     NULL, NULL, NULL
#endif
  };
}
