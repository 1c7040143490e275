/*
** geom_tri_internal.h: how a geom_tri's fields are computed, inline.
**
** geom.c's geom_tri_make and geom_tri_make_fields are this code; so are
** the per-measure evaluations of badness/measure.c (measure_points), which
** inline geom_tri_fill with their measure's constant field mask so that the
** compiler drops every field the measure does not read.  One body, so the
** values are the same bits whichever way a triangle is measured (the build
** contract forbids FMA contraction and fast-math, so inlining cannot change
** a rounding).  Not installed.
*/
#ifndef FLIPLAB_GEOM_TRI_INTERNAL_H
#define FLIPLAB_GEOM_TRI_INTERNAL_H

#include <math.h>
#include <stdint.h>
#include <string.h>
#include "geom.h"
#if FLIPLAB_HAVE_SSE2
#include <emmintrin.h>
#endif

/* The angle at vertex o between the edges to u and w: atan2(|u x w|, u . w),
** accurate for tiny and for near-straight angles alike (acos of the law of
** cosines loses half the digits there).  twice_area = |u x w| is passed in
** so the three angles share one cross product. */
static inline double geom_angle(geom_point o, geom_point u, geom_point w, double twice_area) {
  double dot = (u.x - o.x) * (w.x - o.x) + (u.y - o.y) * (w.y - o.y);
  return atan2(twice_area, dot);
}

/* Twice the area, accurate to a relative 2^-40.  The plain evaluation
** fl(l - r), l and r the two products of the orientation determinant, is
** off by at most bound = GEOM_CCW_ERRBOUND_A (|l| + |r|) (predicates.h:
** Shewchuk's bound, which covers the rounding of the differences too), so
** when |fl(l - r)| > 2^40 bound its relative error is below 2^-40 and it is
** returned as it is (the same bits as before this filter existed).  Below
** that, the triangle is flat (the determinant is under 2^-11 of the
** permanent) and the value is computed exactly (floating-point expansions,
** geom_twice_area_exact) and rounded toward zero (relative error below
** 2^-52): cancellation would otherwise leave thin triangles with an area
** that is wrong in every digit, or 0.  Out of line: random triangles pass
** the filter 99.9% of the time, though the skinny candidates of some LOT
** rules (beta, -c, -A) fail it about 4% of the time. */
/* The slow path, out of line (geom.c): det for non-finite points, else the
** exact value.  A call on the fast path's far side keeps the inlined
** callers' registers free. */
FLIPLAB_INTERNAL double geom_twice_area_flat(geom_point p, geom_point q, geom_point r, double det);

static inline double geom_twice_area_inline(geom_point p, geom_point q, geom_point r) {
  double bax = q.x - p.x, bay = q.y - p.y, cax = r.x - p.x, cay = r.y - p.y;
  double l = bax * cay, rr = bay * cax;
  double det = fabs(l - rr), perm = fabs(l) + fabs(rr);
  /* perm >= 2^-900: the few absolute errors of 2^-1075 that underflow can
  ** add (geom_filter_tiny's argument) are far below 2^-40 eps perm. */
  if (det > 0x1p40 * GEOM_CCW_ERRBOUND_A * perm && perm >= 0x1p-900) return det;
  return geom_twice_area_flat(p, q, r, det);
}

/* The three angles from the sides (opposite v0, v1, v2) and twice the area.
** The two angles opposite the two shorter sides come from atan2, which
** keeps its relative accuracy for tiny angles (a needle has two); the
** largest angle, at least pi/3, is pi minus their sum to within an ulp or
** two of pi, which is a relative error of 1e-16 for it. */
static inline void geom_tri_angles(geom_tri *t, const double side[3], double twice) {
  int big = side[0] >= side[1] ? (side[0] >= side[2] ? 0 : 2) : (side[1] >= side[2] ? 1 : 2);
  int i1 = (big + 1) % 3, i2 = (big + 2) % 3;
  double ang[3];
  ang[i1] = geom_angle(t->v[i1], t->v[i2], t->v[big], twice);
  ang[i2] = geom_angle(t->v[i2], t->v[big], t->v[i1], twice);
  ang[big] = M_PI - (ang[i1] + ang[i2]);
  /* The two longest sides can round to the same double while their
  ** opposite angles are pi - 5e-20 and 5e-20 (a flat triangle with one
  ** very short side; found by fuzz/fuzz_quad_dt): then "big" may name the
  ** tiny angle, and pi minus the others leaves 0 or less.  The largest
  ** angle is at least pi/3 > 1, so a value below 1 means the guess was
  ** wrong: compute that angle by atan2 as well. */
  if (ang[big] < 1.0) ang[big] = geom_angle(t->v[big], t->v[i1], t->v[i2], twice);
  /* Sorting the angle values themselves (not pairing them with sorted
  ** sides) keeps alpha <= beta <= gamma even where rounding disagrees. */
  t->alpha = geom_min3(ang[0], ang[1], ang[2]);
  t->beta = geom_mid3(ang[0], ang[1], ang[2]);
  t->gamma = geom_max3(ang[0], ang[1], ang[2]);
}

/* The canonical order: the three-comparator network (compare-exchange
** (0,1), (1,2), (0,1)) by geom_lexless.  A network of strict comparisons
** is a stable sort, and its comparisons are the same on the same values
** whatever the input, NaN included.  Without a branch: the order of three
** random points is a coin toss, and as branches the exchanges were
** mispredicted half the time (more than the rest of a sides-only triangle
** cost, with the LOT's 27 triangles per point).
** SSE2: a point is one register (x, y); "b before a" is lt.x | (eq.x &
** lt.y) from the two packed comparisons (the same IEEE comparisons as
** geom_lexless, unordered counting as false), spread to both lanes, and
** the exchange xors the masked difference into both points.  Elsewhere:
** the same exchange on the points' bits, with geom_lexless. */
#if FLIPLAB_HAVE_SSE2
static inline void geom_cswap_sse2(__m128d *a, __m128d *b) {
  __m128d lt = _mm_cmplt_pd(*b, *a), eq = _mm_cmpeq_pd(*b, *a);
  __m128d s = _mm_or_pd(lt, _mm_and_pd(eq, _mm_unpackhi_pd(lt, lt)));
  __m128d d = _mm_and_pd(_mm_xor_pd(*a, *b), _mm_unpacklo_pd(s, s));
  *a = _mm_xor_pd(*a, d);
  *b = _mm_xor_pd(*b, d);
}

static inline void geom_tri_sort3(geom_point *p, geom_point *q, geom_point *r) {
  __m128d vp = _mm_set_pd(p->y, p->x), vq = _mm_set_pd(q->y, q->x), vr = _mm_set_pd(r->y, r->x);
  geom_cswap_sse2(&vp, &vq);
  geom_cswap_sse2(&vq, &vr);
  geom_cswap_sse2(&vp, &vq);
  *p = (geom_point){_mm_cvtsd_f64(vp), _mm_cvtsd_f64(_mm_unpackhi_pd(vp, vp))};
  *q = (geom_point){_mm_cvtsd_f64(vq), _mm_cvtsd_f64(_mm_unpackhi_pd(vq, vq))};
  *r = (geom_point){_mm_cvtsd_f64(vr), _mm_cvtsd_f64(_mm_unpackhi_pd(vr, vr))};
}

/* The first vertex of geom_tri_sort3's order in *p (the other two in
** some order): compare-exchanges (0,1) and (0,2). */
static inline void geom_tri_first3(geom_point *p, geom_point *q, geom_point *r) {
  __m128d vp = _mm_set_pd(p->y, p->x), vq = _mm_set_pd(q->y, q->x), vr = _mm_set_pd(r->y, r->x);
  geom_cswap_sse2(&vp, &vq);
  geom_cswap_sse2(&vp, &vr);
  *p = (geom_point){_mm_cvtsd_f64(vp), _mm_cvtsd_f64(_mm_unpackhi_pd(vp, vp))};
  *q = (geom_point){_mm_cvtsd_f64(vq), _mm_cvtsd_f64(_mm_unpackhi_pd(vq, vq))};
  *r = (geom_point){_mm_cvtsd_f64(vr), _mm_cvtsd_f64(_mm_unpackhi_pd(vr, vr))};
}
#else
static inline void geom_cswap(unsigned s, geom_point *a, geom_point *b) {
  uint64_t m = -(uint64_t)s, ax, ay, bx, by;
  memcpy(&ax, &a->x, 8); memcpy(&ay, &a->y, 8);
  memcpy(&bx, &b->x, 8); memcpy(&by, &b->y, 8);
  uint64_t dx = (ax ^ bx) & m, dy = (ay ^ by) & m;
  ax ^= dx; bx ^= dx; ay ^= dy; by ^= dy;
  memcpy(&a->x, &ax, 8); memcpy(&a->y, &ay, 8);
  memcpy(&b->x, &bx, 8); memcpy(&b->y, &by, 8);
}

static inline void geom_tri_sort3(geom_point *p, geom_point *q, geom_point *r) {
  geom_cswap((unsigned)geom_lexless(*q, *p), p, q);
  geom_cswap((unsigned)geom_lexless(*r, *q), q, r);
  geom_cswap((unsigned)geom_lexless(*q, *p), p, q);
}

static inline void geom_tri_first3(geom_point *p, geom_point *q, geom_point *r) {
  geom_cswap((unsigned)geom_lexless(*q, *p), p, q);
  geom_cswap((unsigned)geom_lexless(*r, *p), p, r);
}
#endif

/* Everything below is computed from the canonically ordered vertices
** v0 < v1 < v2 (lexicographic), so the result does not depend on the order
** the caller listed them in.  Each field is computed by the same
** operations whatever else is asked for, so it has the same bits; the
** fields not asked for are NaN. */
static inline void geom_tri_fill_sorted(geom_tri *t, geom_point p, geom_point q, geom_point r,
                                        unsigned f) {
  t->v[0] = p;
  t->v[1] = q;
  t->v[2] = r;
  t->a = t->b = t->c = t->alpha = t->beta = t->gamma = t->area = NAN;
  t->P = t->R = t->r = t->h = t->rx = t->ry = NAN;

  double twice = 0, side[3] = {0, 0, 0}, a = 0, b = 0, c = 0, P = 0;
  const unsigned radii = GEOM_F_CIRCUM | GEOM_F_INRADIUS | GEOM_F_HEIGHT;
  if (f & (GEOM_F_AREA | GEOM_F_ANGLES | radii)) twice = geom_twice_area_inline(p, q, r);
  if (f & (GEOM_F_SIDES | GEOM_F_ANGLES | GEOM_F_PERIM | radii)) {
    double e01x = q.x - p.x, e01y = q.y - p.y;
    double e02x = r.x - p.x, e02y = r.y - p.y;
    double e12x = r.x - q.x, e12y = r.y - q.y;
    side[0] = sqrt(e12x * e12x + e12y * e12y);   /* opposite v0 */
    side[1] = sqrt(e02x * e02x + e02y * e02y);   /* opposite v1 */
    side[2] = sqrt(e01x * e01x + e01y * e01y);   /* opposite v2 */
    a = geom_max3(side[0], side[1], side[2]);
    b = geom_mid3(side[0], side[1], side[2]);
    c = geom_min3(side[0], side[1], side[2]);
    P = a + b + c;
  }
  if (f & GEOM_F_SIDES) {
    t->a = a;
    t->b = b;
    t->c = c;
  }
  if (f & GEOM_F_ANGLES) geom_tri_angles(t, side, twice);
  if (f & GEOM_F_AREA) t->area = 0.5 * twice;
  if (f & GEOM_F_PERIM) t->P = P;
  if (f & GEOM_F_CIRCUM) t->R = a * b * c / (2.0 * twice);
  if (f & GEOM_F_INRADIUS) t->r = twice / P;
  if (f & GEOM_F_HEIGHT) t->h = twice / a;
  if (f & GEOM_F_RANGES) {
    t->rx = geom_max3(p.x, q.x, r.x) - geom_min3(p.x, q.x, r.x);
    t->ry = geom_max3(p.y, q.y, r.y) - geom_min3(p.y, q.y, r.y);
  }
}

static inline void geom_tri_fill(geom_tri *t, geom_point p0, geom_point p1, geom_point p2,
                                 unsigned f) {
  geom_tri_sort3(&p0, &p1, &p2);
  geom_tri_fill_sorted(t, p0, p1, p2, f);
}

/* The fields whose values depend on which vertex comes first: the twice
** area (its origin vertex), and all that is made from it. */
#define GEOM_F_ORDERED (GEOM_F_AREA | GEOM_F_ANGLES | GEOM_F_CIRCUM | GEOM_F_INRADIUS | GEOM_F_HEIGHT)

/* geom_tri_fill's values of the fields f, without the canonical sort when
** none of them needs it (t->v is then in the caller's order).  Why the sort
** cannot matter to sides and perimeter: a side is sqrt(dx*dx + dy*dy) of
** its two endpoints' coordinate differences, and swapping the endpoints
** negates dx and dy exactly, so each of the three values has the same bits
** in any vertex order, only its slot changes; they are >= +0 (never -0),
** so for points without NaN the max, median and min, and P = a + b + c
** from them, are the same values too.  (The ranges are left to the sorted
** path: a range of three zero coordinates could come out -0 or +0.)
** The area and the radii need only the first vertex of the sort: with
** origin p the twice area is |fl(l - r)|, l and r the two products, and
** exchanging q and r exchanges l and r, which gives |fl(r - l)| =
** |-fl(l - r)|, the same bits (and the same filter decision; the exact
** path's |det| does not depend on the order at all).  The first vertex of
** the stable sort is the first smallest one, which two compare-exchanges
** bring to the front.  Only the angles need the whole order (which vertex
** is "big" when two sides tie).  For hot loops (the LOT's 27 triangles per
** point). */
static inline void geom_tri_fill_values(geom_tri *t, geom_point p0, geom_point p1,
                                        geom_point p2, unsigned f) {
  if (f & (GEOM_F_ANGLES | GEOM_F_RANGES)) {
    geom_tri_fill(t, p0, p1, p2, f);
  } else if (f & GEOM_F_ORDERED) {
    geom_tri_first3(&p0, &p1, &p2);
    geom_tri_fill_sorted(t, p0, p1, p2, f);
  } else {
    geom_tri_fill_sorted(t, p0, p1, p2, f);
  }
}

#endif
