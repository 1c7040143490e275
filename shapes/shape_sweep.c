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
