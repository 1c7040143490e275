/*
** shape_square.c: the empty-square (L_inf) rule decided by bounding boxes,
** and the empty-diamond (L_1) rule as the square's in a turned frame.
** For an axis-parallel square K the circumscribing homothet of a triangle
** is read off the triangle's bounding box, and D's test is comparisons of
** coordinates and of differences of coordinates: no product, no filter.
** Special position (a grid's common case) is decided here too, by the same
** comparisons of the turned sites; only a second-order tie, a staircase
** or equal sites go to shape_polygon.c's quick and exact paths (so every
** answer is theirs).
*/
#include <math.h>
#include "geom_exact_internal.h"
#include "shape_internal.h"

/* ---- why the bounding box gives the circumscribing square --------------
**
** Let A, B, C have x-extent W (max x - min x) and y-extent H, and say
** W > H.  A homothet of the square containing the three has side at least
** W; one with all three on its boundary has side exactly W when the two
** x-extremes are on its left and right sides: then the third point Q must
** touch the top or the bottom, so Q is the topmost or the bottommost of the
** three, and the square is [xmin, xmax] x [yQ - W, yQ] (or [yQ, yQ + W]); it
** holds the other two (their y is within H < W of yQ) and has the three on
** its boundary, so it is THE circumscribing homothet (docs/emptyshape.md:
** it is unique when it exists).  When Q's y is strictly between the others'
** no homothet passes through the three (the triangle is a staircase, whose
** circumscribing shape is a corner's rounding shape): left to shape_polygon.c.  A
** side longer than W would need a third side touched on the x-slab's
** behalf, impossible with one point per side and the x-extremes strictly
** inside the slab's two sides.  Two of A, B, C with one x or one y (two
** sites on a line parallel to a side), or W = H (a site on a corner's
** cone), are special position, decided by the turned sites (below), for
** which the three x and the three y are different.  H > W is the same
** with x and y swapped.
**
** Exactness.  D is inside the open square when xmin < xD < xmax, yD < yQ and
** yQ - yD < W (top case), and outside when one of them fails strictly.
** Plain comparisons of doubles are exact.  A comparison of two rounded
** differences, fl(a - b) < fl(c - d), implies a - b < c - d: rounding is
** monotone, so a - b >= c - d would give fl(a - b) >= fl(c - d); equal
** rounded values leave the sign to the rounding errors (below).  W > H is
** such a comparison too.  No difference overflows inside the coordinate
** contract (docs/scale.md).  So every outcome below is the exact one. */

/* ---- special position: the turned sites -----------------------------------
**
** Ties are the rule on grids, and the tie-break (docs/emptyshape.md) turns
** K by an infinitesimal eps > 0, which is the same as turning the sites by
** -eps: (x, y) becomes (x + eps y, y - eps x) to first order.  The square
** stays axis-parallel, so the argument above holds for the turned sites as
** it stands, once every comparison is read with its eps coefficient: a
** coordinate u is the pair (u, e) with e = y for u = x and e = -x for
** u = y, and two of them compare by u, then by e (their difference is
** (u_i - u_j) + eps (e_i - e_j)).  Distinct sites give a strict order on
** either axis: (x, y) and (y, -x) are injective.  The extents and D's last
** test compare differences, (p0 - p1) - (q0 - q1) + eps (...), in
** shape_sq_cmp: the rounded differences decide when they differ
** (monotone rounding, above); when they are equal their rounding errors
** (geom_two_diff, exact) decide, so a tie of values is an exact tie, and
** then the eps coefficients decide the same way.  Where those tie too, D
** on the square (four sites on one square of every small turn) answers
** either, as the general path does; any other second-order tie (a site on
** a corner's cone of every small turn, or two equal sites) goes to the
** general path.  So every answer here is its answer, the rule of the
** turned square (tests/test_shape_exact.c checks it against the purely
** exact decision on grids and lattices). */

/* The sign of a - b against c - d: the rounded differences when they
** differ, else their rounding errors (geom_two_diff: each difference as
** two exact doubles), asked only then. */
static FLIPLAB_NOINLINE int shape_sq_tie(double a, double b, double c, double d) {
  double x, xe, y, ye;
  geom_two_diff(a, b, &x, &xe);
  geom_two_diff(c, d, &y, &ye);
  return (xe > ye) - (xe < ye);
}

static inline int shape_sq_diffcmp(double a, double b, double c, double d) {
  double x = a - b, y = c - d;
  return x != y ? (x > y) - (x < y) : shape_sq_tie(a, b, c, d);
}

/* The sign of (p0 - p1) - (q0 - q1) + eps ((e0 - e1) - (f0 - f1)), or 0
** when both parts are 0; plain (turned 0): the rounded differences' sign,
** 0 when they are equal. */
static FLIPLAB_ALWAYS_INLINE int shape_sq_cmp(const double p[2], const double q[2],
                                              const double e[2], const double f[2], int turned) {
  if (!turned) {
    double x = p[0] - p[1], y = q[0] - q[1];
    return (x > y) - (x < y);
  }
  int s = shape_sq_diffcmp(p[0], p[1], q[0], q[1]);
  return s != 0 ? s : shape_sq_diffcmp(e[0], e[1], f[0], f[1]);
}

/* The sites' coordinates: c[ax][i] the value of site i on axis ax (0: x,
** 1: y); turned, its eps coefficient is c[1][i] on axis 0, -c[0][i] on
** axis 1 (shape_sq_eps). */
typedef struct shape_sq_pts {
  double c[2][4];
} shape_sq_pts;

static FLIPLAB_ALWAYS_INLINE double shape_sq_eps(const shape_sq_pts *t, int ax, int i) {
  return ax == 0 ? t->c[1][i] : -t->c[0][i];
}

/* Site i before site j on axis ax, turned (distinct sites: strict), or
** plain (turned 0: by the values alone). */
static FLIPLAB_ALWAYS_INLINE int shape_sq_lt(const shape_sq_pts *t, int ax, int i, int j,
                                             int turned) {
  const double *c = t->c[ax];
  if (!turned) return c[i] < c[j];
  return (c[i] < c[j]) | ((c[i] == c[j]) & (shape_sq_eps(t, ax, i) < shape_sq_eps(t, ax, j)));
}

/* Which of A, B, C is where is a coin toss, so below the choices are
** made by tables and flags, and a branch is taken on rare cases and on the
** answer only.  The least and the greatest of three different values, by
** (v0 < v1) | (v0 < v2) << 1 | (v1 < v2) << 2 (2 and 5 cannot occur). */
static const unsigned char shape_sq_least[8] = {2, 2, 0, 0, 1, 0, 1, 0};
static const unsigned char shape_sq_most[8] = {0, 1, 0, 1, 0, 0, 2, 2};

static FLIPLAB_ALWAYS_INLINE int shape_sq_order(const shape_sq_pts *t, int ax, int turned) {
  return shape_sq_lt(t, ax, 0, 1, turned) | shape_sq_lt(t, ax, 0, 2, turned) << 1 |
         shape_sq_lt(t, ax, 1, 2, turned) << 2;
}

/* The sign of the turned extent of axis ax (most minus least, indices lo,
** hi) against that of axis bx (lo2, hi2). */
static FLIPLAB_ALWAYS_INLINE int shape_sq_ext_cmp(const shape_sq_pts *t, int ax, int lo, int hi,
                                                  int bx, int lo2, int hi2, int turned) {
  const double p[2] = {t->c[ax][hi], t->c[ax][lo]}, q[2] = {t->c[bx][hi2], t->c[bx][lo2]};
  const double e[2] = {shape_sq_eps(t, ax, hi), shape_sq_eps(t, ax, lo)};
  const double f[2] = {shape_sq_eps(t, bx, hi2), shape_sq_eps(t, bx, lo2)};
  return shape_sq_cmp(p, q, e, f, turned);
}

/* Equal values among A, B, C on either axis: a tie the plain decision
** cannot read. */
static inline int shape_sq_ties(const shape_sq_pts *t) {
  int tie = 0;
  for (int ax = 0; ax < 2; ax++) {
    const double *c = t->c[ax];
    tie |= (c[0] == c[1]) | (c[0] == c[2]) | (c[1] == c[2]);
  }
  return tie;
}

/* D's test read plainly (no tie: the values alone), as differences whose
** signs are taken together (no branch on which one fails): the answer, or
** -2 at a tie.  The extent against the rounded difference s (vQ - vD) is
** a comparison of two rounded differences (above). */
static inline int shape_sq_plain_d(const shape_sq_pts *t, int iu, int ulo, int uhi, int q,
                                   int s) {
  const double *u = t->c[iu], *v = t->c[!iu];
  double a = u[3] - u[ulo], b = u[uhi] - u[3], c = s * (v[q] - v[3]);
  double d = (u[uhi] - u[ulo]) - c;
  if ((a < 0) | (b < 0) | (c < 0) | (d < 0)) return SHAPE_AC;
  if ((a > 0) & (b > 0) & (c > 0) & (d > 0)) return SHAPE_BD;
  return -2;
}

/* The sign of site j minus site i on axis ax (turned, or plain). */
static FLIPLAB_ALWAYS_INLINE int shape_sq_sgn(const shape_sq_pts *t, int ax, int i, int j,
                                              int turned) {
  return shape_sq_lt(t, ax, i, j, turned) - shape_sq_lt(t, ax, j, i, turned);
}

/* The decision of the sites t: shape_square_decide's answer.  Written
** once, instantiated twice (turned a constant): plain, by the values alone,
** which answers -2 at any tie (uniform sites seldom have one, and pay no
** more than the comparisons), and turned, which reads every tie. */
static FLIPLAB_ALWAYS_INLINE int shape_sq_decide(const shape_sq_pts *t, int turned) {
  if (!turned && shape_sq_ties(t)) return -2;
  for (int i = 0; turned && i < 4; i++)   /* equal sites: no order; the general path */
    for (int j = i + 1; j < 4; j++)
      if (t->c[0][i] == t->c[0][j] && t->c[1][i] == t->c[1][j]) return -1;
  int o[2] = {shape_sq_order(t, 0, turned), shape_sq_order(t, 1, turned)};
  int lo[2] = {shape_sq_least[o[0]], shape_sq_least[o[1]]};
  int hi[2] = {shape_sq_most[o[0]], shape_sq_most[o[1]]};
  int wider = shape_sq_ext_cmp(t, 1, lo[1], hi[1], 0, lo[0], hi[0], turned);
  if (wider == 0) return turned ? -1 : -2;   /* a site on a corner's cone (every small turn) */
  /* u: the axis of the larger extent (its slab holds two of the three on
  ** its sides), v the other */
  int iu = wider > 0, iv = !iu;
  int ulo = lo[iu], uhi = hi[iu], q = 3 - ulo - uhi;
  /* s: +1 when Q is on the top side, -1 on the bottom, 0 when Q's v is
  ** between the others' (a staircase: a corner's rounding shape) */
  int s = (q == hi[iv]) - (q == lo[iv]);
  if (s == 0) return -1;
  /* the inside of the square across the slab is s (vQ - vD) in (0, W) */
  if (!turned) return shape_sq_plain_d(t, iu, ulo, uhi, q, s);
  int a = shape_sq_sgn(t, iu, ulo, 3, turned), b = shape_sq_sgn(t, iu, 3, uhi, turned);
  int c = s > 0 ? shape_sq_sgn(t, iv, 3, q, turned) : shape_sq_sgn(t, iv, q, 3, turned);
  int top = s > 0 ? q : 3, bot = s > 0 ? 3 : q;
  const double p[2] = {t->c[iu][uhi], t->c[iu][ulo]}, r[2] = {t->c[iv][top], t->c[iv][bot]};
  const double e[2] = {shape_sq_eps(t, iu, uhi), shape_sq_eps(t, iu, ulo)};
  const double f[2] = {shape_sq_eps(t, iv, top), shape_sq_eps(t, iv, bot)};
  if ((a < 0) | (b < 0) | (c < 0)) return SHAPE_AC;
  if (!(a & b & c)) return turned ? -1 : -2;   /* D ties with a site (turned: never) */
  int d = shape_sq_cmp(p, r, e, f, turned);
  /* d = 0: D on the far side of the square of every small turn, inside
  ** the other three: on the circumscribing shape, either (the general
  ** path's slack on that side is 0 at both levels); plain: a tie */
  return d > 0 ? SHAPE_BD : d < 0 ? SHAPE_AC : turned ? SHAPE_EITHER : -2;
}

/* The plain decision, then at a tie the turned one. */
static int shape_sq_answer(const shape_sq_pts *t) {
  int ans = shape_sq_decide(t, 0);
  return ans != -2 ? ans : shape_sq_decide(t, 1);
}

int shape_square_decide(const geom_point p[4]) {
  shape_sq_pts t;
  for (int i = 0; i < 4; i++) {
    t.c[0][i] = p[i].x;
    t.c[1][i] = p[i].y;
  }
  return shape_sq_answer(&t);
}

/* The diamond's frame (u, v) = (x + y, y - x) of p, a turn by -pi/4 and a
** scaling by sqrt 2: 1 when both are exact (geom_two_sum's and
** geom_two_diff's errors 0), else 0.  A similarity with a positive
** determinant keeps anticlockwise order, maps homothets of K to homothets
** of its image and commutes with the tie-break's turn: a site (x, y)
** turned by -eps has u + eps v, v - eps u, the same form as (x, y)'s.  So
** the rule of a square turned by pi/4 on the sites is the axis-parallel
** square's rule on their frames, exactly when the frames are exact. */
static int shape_sq_frame(geom_point p, geom_point *f) {
  double eu, ev;
  geom_two_sum(p.x, p.y, &f->x, &eu);
  geom_two_diff(p.y, p.x, &f->y, &ev);
  return (eu == 0) & (ev == 0);
}

int shape_diamond_decide(const geom_point p[4]) {
  shape_sq_pts t;
  for (int i = 0; i < 4; i++) {
    geom_point f;
    if (!shape_sq_frame(p[i], &f)) return -1;
    t.c[0][i] = f.x;
    t.c[1][i] = f.y;
  }
  return shape_sq_answer(&t);
}

/* The quadrilateral v an axis-parallel square? */
static int shape_sq_is(const geom_point v[4]) {
  for (int i = 0; i < 4; i++) {
    geom_point a = v[i], b = v[(i + 1) & 3];
    if ((a.x == b.x) == (a.y == b.y)) return 0;   /* not axis-parallel */
  }
  /* a convex quadrilateral with axis-parallel sides is a rectangle: a
  ** square when two adjacent sides are equally long, exactly (sides that
  ** are no exact difference of doubles are not taken) */
  int horizontal = v[0].y == v[1].y;
  double s0a = horizontal ? v[1].x : v[1].y, s0b = horizontal ? v[0].x : v[0].y;
  double s1a = horizontal ? v[2].y : v[2].x, s1b = horizontal ? v[1].y : v[1].x;
  double d0, d1;
  return shape_exact_diff(s0a, s0b, &d0) && shape_exact_diff(s1a, s1b, &d1) && fabs(d0) == fabs(d1);
}

int shape_square_is(const shape *k) {
  return k->n == 4 && shape_sq_is(k->v);
}

int shape_diamond_is(const shape *k) {
  geom_point f[4];
  if (k->n != 4) return 0;
  for (int i = 0; i < 4; i++)
    if (!shape_sq_frame(k->v[i], &f[i])) return 0;
  return shape_sq_is(f);
}

/* ---- the square's variant (shape_internal.h) ------------------------------ */

/* The bounding boxes need no hint and leave none. */
static int shape_square_own(const shape *k, const geom_point p[4], shape_hint *h) {
  (void)k;
  (void)h;
  return shape_square_decide(p);
}

/* Without hints lot's square takes 12% fewer instructions. */
static int shape_square_wants_hints(const shape *k) {
  (void)k;
  return 0;
}

SHAPE_VARIANT_OPS(square, shape_square_own, NULL, shape_square_wants_hints, 0);

/* ---- the diamond's variant: the square's in its frame -------------------- */

static int shape_diamond_own(const shape *k, const geom_point p[4], shape_hint *h) {
  (void)k;
  (void)h;
  return shape_diamond_decide(p);
}

/* The diamond keeps hints: where its own decision gives up (staircases)
** the quick path reads them, and with them lot's diamond on 30,000
** uniform sites takes 254 million instructions, 267 million without. */
static int shape_diamond_wants_hints(const shape *k) {
  (void)k;
  return 1;
}

SHAPE_VARIANT_OPS(diamond, shape_diamond_own, NULL, shape_diamond_wants_hints, 0);
