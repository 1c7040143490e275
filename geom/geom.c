/*
** geom.c: triangle quantities, convex and simple polygon validation.
** (The triangle's fields are computed in geom_tri_internal.h.)
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "geom.h"
#include "geom_tri_internal.h"

static void geom_swap(geom_point *p, geom_point *q) {
  geom_point t = *p;
  *p = *q;
  *q = t;
}

#if defined(__GNUC__)
__attribute__((cold, noinline))
#endif
double geom_twice_area_flat(geom_point p, geom_point q, geom_point r, double det) {
  if (!(geom_point_finite(p) && geom_point_finite(q) && geom_point_finite(r))) return det;
  return geom_twice_area_exact(p, q, r);
}

double geom_twice_area(geom_point p, geom_point q, geom_point r) {
  return geom_twice_area_inline(p, q, r);
}

void geom_tri_make(geom_tri *t, geom_point p, geom_point q, geom_point r) {
  geom_tri_fill(t, p, q, r, GEOM_F_ALL);
}

void geom_tri_make_n(geom_tri *t, const geom_point *v, size_t m) {
  for (size_t i = 0; i < m; i++) geom_tri_fill(&t[i], v[3 * i], v[3 * i + 1], v[3 * i + 2], GEOM_F_ALL);
}

void geom_tri_make_fields(geom_tri *t, geom_point p, geom_point q, geom_point r,
                          unsigned fields) {
  geom_tri_fill(t, p, q, r, fields);
}

/* ---- cheap enclosures of the angles (geom.h) -----------------------------
**
** atan on [0, 1] by Abramowitz and Stegun's 4.4.49 polynomial, whose error
** is below 2e-8 (their bound; 1.36e-8 measured on a grid of 2 10^6
** points); atan2 for y >= 0 by the usual reflections, which add no error
** beyond the rounding of pi/2 - a and pi - a.  tests/test_measures.c checks
** the enclosures on a dense sweep of angles and on stress triangles.
**
** Why GEOM_ANGLE_SLACK = 1e-6 covers every other difference between the
** approximation here and the angle c_v that geom_tri_fill computes at the
** same vertex v.  Let L = |u||w| (u, w the exact edge vectors at v); the
** exact twice area T and dot product D satisfy T^2 + D^2 = L^2.  Both sides
** work from a twice area within a relative 2^-40 of T (here: the same
** filter as geom_twice_area's, else no enclosure; there: that filter or the
** exact value) and a dot product within 4 eps L of D (rounded differences,
** products and sum; |ux wx| + |uy wy| <= L), so each sees the point (D, T)
** moved by under 2^-39 L, which turns its direction by under 2^-38.  libm's
** atan2 adds a few ulps of pi, and the third angle pi - (c1 + c2) at most
** the sum of two such errors and an ulp of pi: c_v is within 2^-35 of the
** exact angle, the value here within 2^-37 + 2e-8 of it (twice that for a
** third angle taken as pi minus the other two), and
** 2^-35 + 2 (2^-37 + 2e-8) + a few roundings of lo and hi < 1e-6. */
#define GEOM_ANGLE_SLACK 1e-6

static double geom_atan01(double z) {
  double z2 = z * z;
  double s = ((((0.0028662257 * z2 - 0.0161657367) * z2 + 0.0429096138) * z2 - 0.0752896400) * z2
              + 0.1065626393) * z2 - 0.1420889944;
  s = ((s * z2 + 0.1999355085) * z2 - 0.3333314528) * z2 + 1.0;
  return z * s;
}

static double geom_atan2_approx(double y, double x) {   /* y > 0 */
  double ax = fabs(x), lo = y < ax ? y : ax, hi = y < ax ? ax : y;
  double a = geom_atan01(lo / hi);
  a = y > ax ? M_PI_2 - a : a;
  return x < 0 ? M_PI - a : a;
}

static void geom_angle_enclose(double a, double *lo, double *hi) {
  *lo = a - GEOM_ANGLE_SLACK;
  *hi = a + GEOM_ANGLE_SLACK;
}

/* The edge vectors of p, q, r and twice the area; 1 when the area passes
** geom_twice_area_inline's filter (a relative error below 2^-40). */
typedef struct geom_edges {
  double bax, bay, cax, cay, cbx, cby, twice;
} geom_edges;

static inline int geom_edges_make(geom_point p, geom_point q, geom_point r, geom_edges *e) {
  e->bax = q.x - p.x, e->bay = q.y - p.y, e->cax = r.x - p.x, e->cay = r.y - p.y;
  e->cbx = r.x - q.x, e->cby = r.y - q.y;
  double l = e->bax * e->cay, rr = e->bay * e->cax, perm = fabs(l) + fabs(rr);
  e->twice = fabs(l - rr);
  return e->twice > 0x1p40 * GEOM_CCW_ERRBOUND_A * perm && perm >= 0x1p-900;
}

/* The dot product of the edges at vertex v: at p (to q and to r), q, r. */
static inline double geom_edges_dot(const geom_edges *e, int v) {
  return v == 0 ? e->bax * e->cax + e->bay * e->cay
       : v == 1 ? -(e->bax * e->cbx + e->bay * e->cby) : e->cax * e->cbx + e->cay * e->cby;
}

/* All three angles; the third exact angle is pi minus the others: within
** 2 (2^-37 + 2e-8). */
static void geom_angles_all(const geom_edges *e, double lo[3], double hi[3]) {
  double a0 = geom_atan2_approx(e->twice, geom_edges_dot(e, 0));
  double a1 = geom_atan2_approx(e->twice, geom_edges_dot(e, 1));
  geom_angle_enclose(a0, &lo[0], &hi[0]);
  geom_angle_enclose(a1, &lo[1], &hi[1]);
  geom_angle_enclose(M_PI - (a0 + a1), &lo[2], &hi[2]);
}

int geom_angle_bounds(geom_point p, geom_point q, geom_point r, double lo[3], double hi[3]) {
  geom_edges e;
  if (!geom_edges_make(p, q, r, &e)) return 0;
  geom_angles_all(&e, lo, hi);
  return 1;
}

/* alpha, beta or gamma from one angle.  Sort the vertices by the rounded
** squared length s_i of the side opposite each, and let v be the one in
** place k.  Each s_i is the exact S_i times (1 + t), |t| <= 4 eps/2 +
** O(eps^2) (two rounded differences, their squares, the sum), when s_i >=
** 2^-1000 (any absolute error of underflow is then below 2^-74 s_i).  So
** s_i < s_j (1 - 2^-48), rounding of the product included, gives S_i < S_j
** (2^-48 is 32 eps/2, the errors need 11).  When v's neighbours in that
** order are separated from it so, v's side is exactly in place k, and in
** a Euclidean triangle the strictly shorter side faces the strictly
** smaller angle: the exact angle A_v is the k-th smallest.  The angles c_i
** that geom_tri_fill computes are within 2^-35 of the exact ones, so their
** k-th smallest (an order statistic moves no more than its arguments) is
** within 2^-35 of A_v, and so is c_v; GEOM_ANGLE_SLACK exceeds the
** approximation's error (2^-35 + 2^-37 + 2e-8 + roundings < 3e-8, the
** argument above) by far more than that 2^-34.  Without the separation (an
** isosceles triangle, sides below 2^-500) all three angles are enclosed
** and the order statistic taken.  Why the separation matters: (0, 0),
** (1e-17, 1e-17), (1, 0) has angles 45 and 135 degrees at its first two
** points, whose opposite sides 1 and 1 - 1e-17 round to the same length. */
int geom_angle_rank_bounds(geom_point p, geom_point q, geom_point r, int k, double *lo,
                           double *hi) {
  geom_edges e;
  if (!geom_edges_make(p, q, r, &e)) return 0;
  double s0 = e.cbx * e.cbx + e.cby * e.cby, s1 = e.cax * e.cax + e.cay * e.cay;
  double s2 = e.bax * e.bax + e.bay * e.bay, t;
  int i0 = 0, i1 = 1, i2 = 2, it;
  if (s1 < s0) t = s0, s0 = s1, s1 = t, it = i0, i0 = i1, i1 = it;
  if (s2 < s1) t = s1, s1 = s2, s2 = t, it = i1, i1 = i2, i2 = it;
  if (s1 < s0) t = s0, s0 = s1, s1 = t, it = i0, i0 = i1, i1 = it;
  const double m = 1 - 0x1p-48;
  if (s0 >= 0x1p-1000 && (k == 2 || s0 < s1 * m) && (k == 0 || s1 < s2 * m)) {
    double dot = geom_edges_dot(&e, k == 0 ? i0 : k == 1 ? i1 : i2);
    geom_angle_enclose(geom_atan2_approx(e.twice, dot), lo, hi);
    return 1;
  }
  double l[3], h[3];
  geom_angles_all(&e, l, h);
  *lo = k == 0 ? geom_min3(l[0], l[1], l[2])
      : k == 1 ? geom_mid3(l[0], l[1], l[2]) : geom_max3(l[0], l[1], l[2]);
  *hi = k == 0 ? geom_min3(h[0], h[1], h[2])
      : k == 1 ? geom_mid3(h[0], h[1], h[2]) : geom_max3(h[0], h[1], h[2]);
  return 1;
}

int geom_ahead(geom_point a, geom_point b, geom_point x) {
  if (a.x != b.x) return x.x != a.x && (b.x > a.x) == (x.x > a.x);
  return x.y != a.y && (b.y > a.y) == (x.y > a.y);
}

int geom_on_segment(geom_point a, geom_point b, geom_point q) {
  return geom_orient(a, b, q) == 0 && geom_ahead(a, b, q) && geom_ahead(b, a, q);
}

double geom_dist(geom_point p, geom_point q) {
  double dx = p.x - q.x, dy = p.y - q.y;
  return sqrt(dx * dx + dy * dy);
}

int geom_point_finite(geom_point p) {
  return isfinite(p.x) && isfinite(p.y);
}

/* ---- the coordinate contract (geom.h) ----------------------------------- */

geom_coorderr geom_coord_check(double x) {
  if (isnan(x) || isinf(x)) return GEOM_COORD_NOT_FINITE;
  double m = fabs(x);
  if (m != 0 && (m < GEOM_COORD_MIN || m > GEOM_COORD_MAX)) return GEOM_COORD_OUT_OF_RANGE;
  return GEOM_COORD_OK;
}

geom_coorderr geom_weight_check(double w) {
  if (isnan(w) || isinf(w)) return GEOM_COORD_NOT_FINITE;
  double m = fabs(w);
  if (m != 0 && (m < GEOM_WEIGHT_MIN || m > GEOM_WEIGHT_MAX)) return GEOM_COORD_OUT_OF_RANGE;
  return GEOM_COORD_OK;
}

const char *geom_weighterr_str(geom_coorderr e) {
  return e == GEOM_COORD_OUT_OF_RANGE
             ? "is out of range (weights must be 0 or of magnitude between 1e-60 and 1e60)"
             : geom_coorderr_str(e);
}

int geom_threads_check(long long threads, char *err, size_t errlen) {
  if (threads >= 0 && threads <= GEOM_MAX_THREADS) return 0;
  if (err != NULL && errlen > 0)
    snprintf(err, errlen, "threads: expected 0 (all cores) or 1 .. %d, got %lld",
             GEOM_MAX_THREADS, threads);
  return -1;
}

int geom_threads_clamp(int threads, int all) {
  int t = threads > 0 && threads <= GEOM_MAX_THREADS ? threads : all;
  return t < 1 ? 1 : t > GEOM_MAX_THREADS ? GEOM_MAX_THREADS : t;
}

size_t geom_coord_check_n(const double *x, size_t n) {
  for (size_t i = 0; i < n; i++)
    if (geom_coord_check(x[i]) != GEOM_COORD_OK) return i;
  return n;
}

/* A number that overflows, underflows or is subnormal is out of range
** ("1e-400" is neither "not a number" nor silently 0), and so is one
** outside the contract. */
geom_coorderr geom_coord_parse_n(const char *s, size_t len, double *out) {
  double x = 0;
  switch (geom_number_parse(s, len, &x)) {
  case GEOM_NUM_OK: break;
  case GEOM_NUM_NOT_FINITE: return GEOM_COORD_NOT_FINITE;
  case GEOM_NUM_OUT_OF_RANGE: return GEOM_COORD_OUT_OF_RANGE;
  case GEOM_NUM_NOT_NUMBER:
  case GEOM_NUM_NO_MEMORY: return GEOM_COORD_NOT_NUMBER;
  }
  geom_coorderr e = geom_coord_check(x);
  if (e == GEOM_COORD_OK) *out = x;
  return e;
}

geom_coorderr geom_coord_parse(const char *s, double *out) {
  return geom_coord_parse_n(s, s != NULL ? strlen(s) : 0, out);
}

const char *geom_coorderr_str(geom_coorderr e) {
  static const char *const msg[] = {
    [GEOM_COORD_OK] = "is a valid coordinate",
    [GEOM_COORD_NOT_NUMBER] = "is not a number",
    [GEOM_COORD_NOT_FINITE] = "is not finite",
    [GEOM_COORD_OUT_OF_RANGE] = ("is out of range (coordinates must be 0 or of magnitude "
                                 "between 1e-30 and 1e30)"),
  };
  return (unsigned)e < sizeof msg / sizeof msg[0] ? msg[e] : "is not a valid coordinate";
}

/* ---- convex polygon validation ---------------------------------------- */

typedef struct geom_ranked { geom_point p; size_t i; } geom_ranked;

static int geom_ranked_cmp(const void *x, const void *y) {
  const geom_ranked *a = x, *b = y;
  if (geom_lexless(a->p, b->p)) return -1;
  if (geom_lexless(b->p, a->p)) return 1;
  return a->i < b->i ? -1 : a->i > b->i;
}

/* Duplicates anywhere in the list, in O(n log n): sort, compare neighbours.
** Reports the later of the two rows. */
static int geom_find_duplicate(const geom_point *p, size_t n, size_t *bad) {
  geom_ranked *r = malloc(n * sizeof *r);
  if (r == NULL) return 0;
  for (size_t i = 0; i < n; i++) r[i] = (geom_ranked){p[i], i};
  qsort(r, n, sizeof *r, geom_ranked_cmp);
  int found = 0;
  for (size_t i = 1; i < n && !found; i++)
    if (r[i].p.x == r[i - 1].p.x && r[i].p.y == r[i - 1].p.y) {
      *bad = r[i].i;
      found = 1;
    }
  free(r);
  return found;
}

/* Reverse keeping vertex 0 first: p0, p_{n-1}, ..., p1.  Keeping the first
** vertex means a quadrilateral's diagonals keep their names (AC stays AC). */
static void geom_reverse_tail(geom_point *p, size_t n) {
  for (size_t i = 1, j = n - 1; i < j; i++, j--) geom_swap(&p[i], &p[j]);
}

/* Which half of the circle an edge direction points into: 0 for angles in
** [0, pi), 1 for [pi, 2 pi).  The sign of a rounded difference of doubles is
** the sign of the exact difference, so this is exact. */
static int geom_half(geom_point from, geom_point to) {
  double dx = to.x - from.x, dy = to.y - from.y;
  return !(dy > 0 || (dy == 0 && dx > 0));
}

/* A polygon is strictly convex when every turn has the same (exact,
** non-zero) orientation and the boundary goes round once.  Equal turns
** alone admit star polygons (a pentagram turns left at every vertex but
** winds twice).  With every turn strictly between 0 and pi, the edge
** direction changes half (see geom_half) exactly twice per winding, so the
** winding number is exact too: no angle sums, no atan2, any scale. */
/* What every polygon's vertices must be, convex or simple: at least three,
** finite, inside the coordinate contract, no two equal (*bad: the vertex). */
static geom_polyerr geom_polygon_points_check(const geom_point *p, size_t n, size_t *bad) {
  if (n < 3) return GEOM_TOO_FEW;
  for (size_t i = 0; i < n; i++)
    if (!geom_point_finite(p[i])) {
      *bad = i;
      return GEOM_NOT_FINITE;
    }
  for (size_t i = 0; i < n; i++)
    if (geom_coord_check(p[i].x) != GEOM_COORD_OK || geom_coord_check(p[i].y) != GEOM_COORD_OK) {
      *bad = i;
      return GEOM_OUT_OF_SCALE;
    }
  if (geom_find_duplicate(p, n, bad)) return GEOM_DUPLICATE;
  return GEOM_OK;
}

geom_polyerr geom_polygon_check(geom_point *p, size_t n, size_t *bad, int *reversed) {
  size_t dummy;
  if (bad == NULL) bad = &dummy;
  if (reversed) *reversed = 0;
  *bad = 0;
  geom_polyerr e = geom_polygon_points_check(p, n, bad);
  if (e != GEOM_OK) return e;
  int sign = 0;
  size_t changes = 0;
  for (size_t i = 0; i < n; i++) {
    size_t j = (i + 1) % n, k = (i + 2) % n;
    int o = geom_orient(p[i], p[j], p[k]);
    if (o == 0) {
      *bad = j;
      return GEOM_COLLINEAR;
    }
    if (sign == 0) sign = o;
    else if (o != sign) {
      *bad = j;
      return GEOM_NOT_CONVEX;
    }
    changes += geom_half(p[i], p[j]) != geom_half(p[j], p[k]);
  }
  if (changes != 2) {
    *bad = 0;
    return GEOM_NOT_CONVEX;
  }
  if (sign < 0) {
    geom_reverse_tail(p, n);
    if (reversed) *reversed = 1;
  }
  return GEOM_OK;
}

const char *geom_polyerr_str(geom_polyerr e) {
  static const char *const msg[] = {
    [GEOM_OK] = "ok",
    [GEOM_TOO_FEW] = "too few vertices (need at least 3)",
    [GEOM_NOT_FINITE] = "coordinate is not a finite number",
    [GEOM_DUPLICATE] = "duplicate point",
    [GEOM_COLLINEAR] = "collinear with its neighbours (polygon must be strictly convex)",
    [GEOM_NOT_CONVEX] = "polygon is not convex",
    [GEOM_OUT_OF_SCALE] = ("coordinate out of range (coordinates must be 0 or of "
                           "magnitude between 1e-30 and 1e30)"),
    [GEOM_CROSSING] = "two edges cross or touch (polygon is not simple)",
  };
  return (unsigned)e < sizeof msg / sizeof msg[0] ? msg[e] : "unknown error";
}

/* ---- simple polygon validation ---------------------------------------- */

/* For collinear a, b, c: is c within the closed segment ab?  Points on a
** line are ordered lexicographically along it, so comparisons suffice. */
static int geom_between(geom_point a, geom_point b, geom_point c) {
  if (geom_lexless(b, a)) geom_swap(&a, &b);
  return !geom_lexless(c, a) && !geom_lexless(b, c);
}

int geom_segments_meet(geom_point a, geom_point b, geom_point c, geom_point d) {
  int o1 = geom_orient(a, b, c), o2 = geom_orient(a, b, d);
  int o3 = geom_orient(c, d, a), o4 = geom_orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return 1;           /* proper crossing */
  return (o1 == 0 && geom_between(a, b, c)) || (o2 == 0 && geom_between(a, b, d)) ||
         (o3 == 0 && geom_between(c, d, a)) || (o4 == 0 && geom_between(c, d, b));
}

typedef struct geom_span { double lo, hi; size_t e; } geom_span;

static int geom_span_cmp(const void *x, const void *y) {
  const geom_span *a = x, *b = y;
  if (a->lo != b->lo) return a->lo < b->lo ? -1 : 1;
  return a->e < b->e ? -1 : a->e > b->e;
}

/* Adjacent edges (u, v) and (v, w) meet beyond v only when they fold back:
** u, v, w collinear with u and w on the same side of v. */
static int geom_folds(geom_point u, geom_point v, geom_point w) {
  return geom_orient(u, v, w) == 0 && geom_lexless(u, v) == geom_lexless(w, v);
}

/* Every pair of edges whose x-ranges overlap, found by sorting the edges
** by their left end and scanning forward while the next left end is within
** reach: 1 with the pair (smaller index first) for the first meeting pair
** in that deterministic order. */
static int geom_find_crossing(const geom_point *p, size_t n, size_t *e1, size_t *e2) {
  for (size_t v = 0; v < n; v++)
    if (geom_folds(p[(v + n - 1) % n], p[v], p[(v + 1) % n])) {
      size_t a = (v + n - 1) % n, b = v;
      *e1 = a < b ? a : b;
      *e2 = a < b ? b : a;
      return 1;
    }
  geom_span *s = malloc(n * sizeof *s);
  if (s == NULL) {                          /* no memory to sort: every pair */
    for (size_t e = 0; e < n; e++)
      for (size_t f = e + 2; f < n; f++)
        if (!(e == 0 && f == n - 1) &&
            geom_segments_meet(p[e], p[(e + 1) % n], p[f], p[(f + 1) % n])) {
          *e1 = e;
          *e2 = f;
          return 1;
        }
    return 0;
  }
  for (size_t e = 0; e < n; e++) {
    double x0 = p[e].x, x1 = p[(e + 1) % n].x;
    s[e] = (geom_span){x0 < x1 ? x0 : x1, x0 < x1 ? x1 : x0, e};
  }
  qsort(s, n, sizeof *s, geom_span_cmp);
  int found = 0;
  for (size_t a = 0; a < n && !found; a++)
    for (size_t b = a + 1; b < n && s[b].lo <= s[a].hi && !found; b++) {
      size_t e = s[a].e, f = s[b].e;
      if ((e + 1) % n == f || (f + 1) % n == e) continue;   /* adjacent: folds above */
      if (geom_segments_meet(p[e], p[(e + 1) % n], p[f], p[(f + 1) % n])) {
        *e1 = e < f ? e : f;
        *e2 = e < f ? f : e;
        found = 1;
      }
    }
  free(s);
  return found;
}

/* After the crossing test the boundary is a Jordan curve, and its
** lexicographically smallest vertex is a strict convex corner (its
** neighbours are both lexicographically larger and cannot be collinear
** with it on opposite sides, nor on the same side: that would fold), so
** the sign of that one turn is the orientation. */
geom_polyerr geom_simple_polygon_check(geom_point *p, size_t n, size_t *bad, size_t *bad2,
                                       int *reversed) {
  size_t d1, d2;
  if (bad == NULL) bad = &d1;
  if (bad2 == NULL) bad2 = &d2;
  if (reversed) *reversed = 0;
  *bad = *bad2 = 0;
  geom_polyerr e = geom_polygon_points_check(p, n, bad);
  if (e != GEOM_OK) return e;
  if (geom_find_crossing(p, n, bad, bad2) != 0) return GEOM_CROSSING;
  size_t lo = 0;
  for (size_t i = 1; i < n; i++)
    if (geom_lexless(p[i], p[lo])) lo = i;
  if (geom_orient(p[(lo + n - 1) % n], p[lo], p[(lo + 1) % n]) < 0) {
    geom_reverse_tail(p, n);
    if (reversed) *reversed = 1;
  }
  return GEOM_OK;
}

void geom_pslg_free(geom_pslg *g) {
  free(g->pts);
  free(g->seg);
  free(g->hole);
  *g = (geom_pslg){0};
}
