/*
** gon_region.c: the regions rejection and iteration draw their points in
** (thesis sections 6.2 and 6.3, docs/sampling.md): a region is the part of
** the domain (square, disc or triangle) right of one hull edge and left of
** one or two neighbouring edges' lines.  Its mass is its area over the
** domain's; a point is drawn uniformly in it.
**
** The region is clipped from a convex polygon around the domain's part
** right of the edge (Sutherland-Hodgman, one pass per line, at most 3 + 3
** or 7 + 3 vertices): the square or triangle itself, or for the disc the
** circumscribed polygon of the cap the edge's line cuts off (its chord and
** the tangents at k + 1 points of its arc, k = ceil(arc / 90 degrees) <= 4,
** so at most 2/3 of it ... 1/(1 - pi/4) of the cap: bounded waste).  The
** clipping is in floating point: the caller tests each drawn point exactly
** (geom_orient) against the true region and draws again when rounding put
** it outside (a set of measure about 1e-16 of the region).  The disc's mass
** is exact up to rounding: the polygon of the clipped vertices inside the
** disc and the crossing points, plus a circular segment per arc, each
** computed from local differences (no cancellation of whole-disc areas, so
** a region of area 1e-20 keeps its relative precision).  Every function is
** O(1): at most SAMPLER_CLIP_MAX vertices.
*/
#include <math.h>
#include "gon_internal.h"

#define SAMPLER_PI 3.14159265358979323846

/* cross(b - a, p - a): > 0 when p is left of a->b (floating point). */
static double sampler_side(geom_point a, geom_point b, geom_point p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

/* Keep the part of c where sign * side(a, b, .) >= 0. */
static void sampler_clip_line(sampler_clip *c, geom_point a, geom_point b, double sign) {
  sampler_clip o;
  o.n = 0;
  for (int i = 0; i < c->n; i++) {
    geom_point p = c->v[i], q = c->v[(i + 1) % c->n];
    double sp = sign * sampler_side(a, b, p), sq = sign * sampler_side(a, b, q);
    if (sp >= 0 && o.n < SAMPLER_CLIP_MAX) o.v[o.n++] = p;
    if (((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) && o.n < SAMPLER_CLIP_MAX) {
      double t = sp / (sp - sq);
      o.v[o.n++] = (geom_point){p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
    }
  }
  *c = o;
}

/* Twice the signed area of c, from differences to its first vertex. */
static double sampler_clip_area2(const sampler_clip *c) {
  double s = 0;
  for (int i = 1; i + 1 < c->n; i++)
    s += sampler_side(c->v[0], c->v[i], c->v[i + 1]);
  return s;
}

static geom_point sampler_unit(double t) {
  return (geom_point){cos(t), sin(t)};
}

/* The polygon around the disc's part right of a->b (empty when the line
** misses the disc): chord end, the tangents' crossings, chord end. */
static void sampler_cap_polygon(geom_point a, geom_point b, sampler_clip *c) {
  double dx = b.x - a.x, dy = b.y - a.y, len = hypot(dx, dy);
  double nx = dy / len, ny = -dx / len;           /* the normal into the right side */
  double d = nx * a.x + ny * a.y;                  /* the line is {p : n.p = d} */
  c->n = 0;
  if (!(d < 1)) return;
  double half = d > -1 ? acos(d) : SAMPLER_PI, mid = atan2(ny, nx);
  int k = (int)ceil(2 * half / (SAMPLER_PI / 2));
  if (k < 1) k = 1;
  double step = 2 * half / k, r = 1 / cos(step / 2);
  c->v[c->n++] = sampler_unit(mid - half);
  for (int j = 0; j < k; j++) {
    geom_point u = sampler_unit(mid - half + (j + 0.5) * step);
    c->v[c->n++] = (geom_point){r * u.x, r * u.y};
  }
  c->v[c->n++] = sampler_unit(mid + half);
}

/* The area of a circular segment of arc phi, (phi - sin phi) / 2, by its
** series where the difference would cancel. */
static double sampler_segment_area(double phi) {
  if (phi > 1e-2) return (phi - sin(phi)) / 2;
  double p2 = phi * phi;
  return phi * p2 / 12 * (1 - p2 / 20 * (1 - p2 / 42));
}

/* The roots t[0] <= t[1] of |p + t (q - p)| = 1; 0 when the line misses
** the circle. */
static int sampler_circle_cross(geom_point p, geom_point q, double t[2]) {
  double dx = q.x - p.x, dy = q.y - p.y;
  double A = dx * dx + dy * dy, B = p.x * dx + p.y * dy, C = p.x * p.x + p.y * p.y - 1;
  double disc = B * B - A * C;
  if (!(A > 0) || !(disc >= 0)) return 0;
  double s = sqrt(disc), q0 = -B - (B < 0 ? -s : s);     /* no cancellation */
  double r1 = q0 / A, r2 = q0 != 0 ? C / q0 : r1;
  t[0] = r1 < r2 ? r1 : r2;
  t[1] = r1 < r2 ? r2 : r1;
  return 1;
}

static geom_point sampler_lerp(geom_point p, geom_point q, double t) {
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  return (geom_point){p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
}

/* The anticlockwise angle from unit vector e to unit vector f, in [0, 2pi). */
static double sampler_arc(geom_point e, geom_point f) {
  double a = atan2(e.x * f.y - e.y * f.x, e.x * f.x + e.y * f.y);
  return a < 0 ? a + 2 * SAMPLER_PI : a;
}

/* Area of the convex polygon c intersected with the unit disc: the polygon
** q of its inside vertices and boundary crossings, plus a segment for each
** arc from a leaving crossing to the next entering one.  The crossings
** follow the vertices' inside test (|p|^2 < 1) and sampler_dips, clamped
** onto their edge, so that entries and exits alternate even for vertices
** on the circle. */
typedef struct sampler_arcs {
  sampler_clip q;
  geom_point out;
  int have_out, first_entry;
  double seg;
} sampler_arcs;

static void sampler_arcs_entry(sampler_arcs *s, geom_point x) {
  if (s->have_out) s->seg += sampler_segment_area(sampler_arc(s->out, x));
  else if (s->first_entry < 0) s->first_entry = s->q.n;
  s->q.v[s->q.n++] = x;
}

static void sampler_arcs_exit(sampler_arcs *s, geom_point x) {
  s->out = x;
  s->have_out = 1;
  s->q.v[s->q.n++] = x;
}

/* Does the segment p r, both ends outside, pass inside the disc?  Its
** point nearest the centre (the roots' midpoint, clamped to the segment) is
** inside: a chord whose ends lie on the circle (the cap polygon's) counts,
** which a test of the roots against (0, 1) can miss by rounding. */
static int sampler_dips(geom_point p, geom_point r, const double t[2]) {
  geom_point m = sampler_lerp(p, r, (t[0] + t[1]) / 2);
  return m.x * m.x + m.y * m.y < 1;
}

static double sampler_disc_area(const sampler_clip *c) {
  sampler_arcs s = {.have_out = 0, .first_entry = -1, .seg = 0};
  s.q.n = 0;
  for (int i = 0; i < c->n && s.q.n + 2 < SAMPLER_CLIP_MAX; i++) {
    geom_point p = c->v[i], r = c->v[(i + 1) % c->n];
    int pin = p.x * p.x + p.y * p.y < 1, rin = r.x * r.x + r.y * r.y < 1;
    double t[2] = {1, 0};   /* no root (a tangent, by rounding): cross at the inside end */
    int m = sampler_circle_cross(p, r, t);
    if (pin) s.q.v[s.q.n++] = p;
    if (pin && !rin) sampler_arcs_exit(&s, sampler_lerp(p, r, t[1]));
    if (!pin && rin) sampler_arcs_entry(&s, sampler_lerp(p, r, t[0]));
    if (!pin && !rin && m && sampler_dips(p, r, t)) {
      sampler_arcs_entry(&s, sampler_lerp(p, r, t[0]));
      sampler_arcs_exit(&s, sampler_lerp(p, r, t[1]));
    }
  }
  if (s.have_out && s.first_entry >= 0)   /* the arc that wraps round to the first entry */
    s.seg += sampler_segment_area(sampler_arc(s.out, s.q.v[s.first_entry]));
  return s.q.n >= 3 ? sampler_clip_area2(&s.q) / 2 + s.seg : s.seg;
}

/* The domains as polygons, anticlockwise, and their areas. */
static const geom_point sampler_square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
static const geom_point sampler_triangle[3] = {{0, 0}, {1, 0}, {0, 1}};

double sampler_region_mass(sampler_region r, geom_point a, geom_point b,
                           const geom_point (*left)[2], int nleft, sampler_clip *c) {
  c->n = 0;
  if (r == SAMPLER_REGION_DISC) {
    sampler_cap_polygon(a, b, c);
  } else {
    const geom_point *d = r == SAMPLER_REGION_SQUARE ? sampler_square : sampler_triangle;
    c->n = r == SAMPLER_REGION_SQUARE ? 4 : 3;
    for (int i = 0; i < c->n; i++) c->v[i] = d[i];
  }
  sampler_clip_line(c, a, b, -1);
  for (int k = 0; k < nleft && c->n >= 3; k++) sampler_clip_line(c, left[k][0], left[k][1], 1);
  if (c->n < 3) {
    c->n = 0;
    return 0;
  }
  double m = r == SAMPLER_REGION_DISC ? sampler_disc_area(c) / SAMPLER_PI
             : r == SAMPLER_REGION_SQUARE ? sampler_clip_area2(c) / 2 : sampler_clip_area2(c);
  return m > 0 ? m : 0;
}

/* Fan triangle k of c (from its first vertex), k chosen by area. */
static int sampler_clip_pick(const sampler_clip *c, double u) {
  double w[SAMPLER_CLIP_MAX], tot = 0;
  for (int i = 1; i + 1 < c->n; i++) {
    double a = sampler_side(c->v[0], c->v[i], c->v[i + 1]);
    tot += w[i] = a > 0 ? a : 0;
  }
  double x = u * tot;
  for (int i = 1; i + 2 < c->n; i++) {
    if (x < w[i]) return i;
    x -= w[i];
  }
  return c->n - 2;
}

/* A point uniform in triangle a, b, c from u, v: the parallelogram's
** point, folded back into the triangle when beyond the diagonal. */
static geom_point sampler_in_triangle(geom_point a, geom_point b, geom_point c, double u,
                                      double v) {
  if (u + v > 1) {
    u = 1 - u;
    v = 1 - v;
  }
  return (geom_point){a.x + u * (b.x - a.x) + v * (c.x - a.x),
                      a.y + u * (b.y - a.y) + v * (c.y - a.y)};
}

#define SAMPLER_REGION_TRIES 100000

int sampler_region_draw(sampler_rng *g, sampler_region r, const sampler_clip *c, geom_point *p,
                        uint64_t *draws) {
  if (c->n < 3) return -1;
  for (int t = 0; t < SAMPLER_REGION_TRIES; t++) {
    int k = sampler_clip_pick(c, sampler_uniform(g));
    double u = sampler_uniform(g), v = sampler_uniform(g);
    *p = sampler_in_triangle(c->v[0], c->v[k], c->v[k + 1], u, v);
    ++*draws;
    if (r != SAMPLER_REGION_DISC || p->x * p->x + p->y * p->y < 1) return 0;
  }
  return -1;
}

geom_point sampler_region_point(sampler_rng *g, sampler_region r) {
  if (r == SAMPLER_REGION_DISC) return sampler_disc(g);
  double u = sampler_uniform(g), v = sampler_uniform(g);
  if (r == SAMPLER_REGION_TRIANGLE && u + v > 1) {   /* exact: 1 - u is a multiple of 2^-53 */
    u = 1 - u;
    v = 1 - v;
  }
  return (geom_point){u, v};
}
