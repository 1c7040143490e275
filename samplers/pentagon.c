/*
** pentagon.c: the generator streams and the iteration sampler.
**
** Generator: xoshiro256** (Blackman and Vigna), its 256-bit state filled by
** splitmix64 from a hash of (seed, stream).  Pentagon i of seed S is drawn
** from stream i alone, so it depends only on (S, i): any thread count and
** any split into shards give bit-identical samples.
**
** Iteration method (thesis section 6.3, docs/sampling.md):
** points uniform in the unit disc (rejection from the square [-1,1]^2), one
** at a time, keeping their convex hull, until the hull has exactly five
** vertices (sampler_convex: n vertices, 3 <= n <= SAMPLER_HULL_MAX - 1).
** Adding one point raises the hull size by at most one, so n is hit exactly.  Every hull test is exact (geom_orient, whose filter is
** inline), so duplicate, collinear and on-the-boundary draws are handled
** without tolerances: a
** point on the hull's boundary is not a new vertex, and a vertex left
** between two collinear hull points is dropped; the hull stays strictly
** convex and anticlockwise throughout.
*/
#include <math.h>
#include <string.h>
#include "sampler.h"
#include "splitmix.h"
#include "gon_internal.h"

static inline uint64_t sampler_rotl(uint64_t x, int k) {
  return (x << k) | (x >> (64 - k));
}

/* The stream's starting point hashes the seed, then adds the stream number
** and hashes again: distinct (seed, stream) pairs give unrelated states.
** splitmix64's output function is a bijection of its counter, so the four
** consecutive outputs cannot all be zero (xoshiro's one forbidden state). */
void sampler_seed(sampler_rng *g, uint64_t seed, uint64_t stream) {
  uint64_t x = seed;
  uint64_t h = geom_splitmix64(&x);
  x = h ^ (stream * 0xD1B54A32D192ED03ull);
  (void)geom_splitmix64(&x);
  for (int i = 0; i < 4; i++) g->s[i] = geom_splitmix64(&x);
}

uint64_t sampler_next(sampler_rng *g) {
  uint64_t *s = g->s;
  uint64_t out = sampler_rotl(s[1] * 5, 7) * 9;
  uint64_t t = s[1] << 17;
  s[2] ^= s[0];
  s[3] ^= s[1];
  s[1] ^= s[2];
  s[0] ^= s[3];
  s[2] ^= t;
  s[3] = sampler_rotl(s[3], 45);
  return out;
}

double sampler_uniform(sampler_rng *g) {
  return geom_unit53(sampler_next(g));
}

/* Marsaglia's polar method; the second deviate is dropped so that the
** generator carries no hidden state besides its four words. */
double sampler_normal(sampler_rng *g) {
  for (;;) {
    double x = 2 * sampler_uniform(g) - 1, y = 2 * sampler_uniform(g) - 1;
    double s = x * x + y * y;
    if (s > 0 && s < 1) return x * sqrt(-2 * log(s) / s);
  }
}

geom_point sampler_disc(sampler_rng *g) {
  geom_point p;
  for (;;) {
    double u = sampler_uniform(g), v = sampler_uniform(g);
    if (geom_disc_accept(u, v, &p)) return p;
  }
}

/* Hull of at most two points plus p; collinear points are ordered along
** their line by the lexicographic order, exactly. */
static int sampler_hull_small(geom_point *h, int n, geom_point p) {
  if (n == 0) {
    h[0] = p;
    return 1;
  }
  if (n == 1) {
    if (p.x == h[0].x && p.y == h[0].y) return 1;
    h[1] = p;
    return 2;
  }
  int o = geom_orient(h[0], h[1], p);
  if (o > 0) {
    h[2] = p;
    return 3;
  }
  if (o < 0) {
    geom_point t = h[0];
    h[0] = h[1];
    h[1] = t;
    h[2] = p;
    return 3;
  }
  /* Collinear: keep the lexicographic extremes of the three. */
  geom_point lo = h[0], hi = h[1];
  if (geom_lexless(hi, lo)) {
    lo = h[1];
    hi = h[0];
  }
  if (geom_lexless(p, lo)) lo = p;
  if (geom_lexless(hi, p)) hi = p;
  h[0] = lo;
  h[1] = hi;
  return 2;
}

/* Insert p into the strictly convex anticlockwise hull h[0..n-1], n >= 3.
** side[k] = orient(h_k, h_{k+1}, p).  If no side is negative p lies inside
** or on the boundary (a duplicate of a vertex gives zeros only at its two
** sides) and the hull is unchanged.  Otherwise the sides with side <= 0
** form one contiguous chain from vertex L to vertex R (p is outside a
** convex polygon); the vertices strictly inside that chain are dropped,
** including one left on a segment between its neighbour and p (a zero
** side next to a negative one), and p goes between L and R. */
static int sampler_hull_insert(geom_point *h, int n, geom_point p) {
  int side[SAMPLER_HULL_MAX], any = 0;   /* n < SAMPLER_HULL_MAX */
  for (int k = 0; k < n; k++) {
    side[k] = geom_orient(h[k], h[(k + 1) % n], p);
    if (side[k] < 0) any = 1;
  }
  if (!any) return n;
  int L = -1, R = -1;
  for (int k = 0; k < n; k++) {
    int prev = side[(k + n - 1) % n];
    if (side[k] <= 0 && prev > 0) L = k;           /* chain starts at h_k */
    if (side[k] > 0 && prev <= 0) R = k;           /* chain ends at h_k */
  }
  /* New hull: p, then h_R, h_{R+1}, ..., h_L anticlockwise. */
  geom_point t[SAMPLER_HULL_MAX] = {{0, 0}};
  int m = 0;
  t[m++] = p;
  for (int k = R;; k = (k + 1) % n) {
    t[m++] = h[k];
    if (k == L) break;
  }
  for (int k = 0; k < m; k++) h[k] = t[k];
  return m;
}

/* Add p to the strictly convex anticlockwise hull h[0..n-1] (h has room
** for n + 1 points; n < SAMPLER_HULL_MAX) and return the new size.  Not in sampler.h:
** declared in gon_internal.h (naive rejection uses it) and by test_sampler
** for its degenerate cases. */
int sampler_hull_add(geom_point *h, int n, geom_point p) {
  return n <= 2 ? sampler_hull_small(h, n, p) : sampler_hull_insert(h, n, p);
}

/* Did the hull change?  The new hull holds p exactly when p was outside
** (or extended a segment of collinear points); compared whole, it is O(n). */
static int sampler_hull_changed(const geom_point *a, int na, const geom_point *b, int nb) {
  return na != nb || memcmp(a, b, (size_t)na * sizeof *a) != 0;
}

void sampler_convex_rng(sampler_rng *g, int n, geom_point *v, uint64_t *changes) {
  geom_point h[SAMPLER_HULL_MAX], old[SAMPLER_HULL_MAX];
  int m = 0;
  while (m != n) {
    geom_point p = sampler_disc(g);
    int was = m;
    if (changes != NULL) memcpy(old, h, (size_t)m * sizeof *h);
    m = sampler_hull_add(h, m, p);
    if (changes != NULL) *changes += (uint64_t)sampler_hull_changed(old, was, h, m);
  }
  memcpy(v, h, (size_t)n * sizeof *v);
  sampler_lexfirst(v, (size_t)n);
}

void sampler_convex(uint64_t seed, uint64_t index, int n, geom_point *v) {
  sampler_rng g;
  sampler_seed(&g, seed, GEOM_STREAM_SAMPLE(index));
  sampler_convex_rng(&g, n, v, NULL);
}

void sampler_pentagon(uint64_t seed, uint64_t index, geom_point v[5]) {
  sampler_convex(seed, index, 5, v);
}

/* Quadrilateral i of seed S: four points uniform in the unit disc, drawn
** again until they are in strictly convex position, ordered anticlockwise
** from the one with the smallest angle about their centroid.  The stream
** is (S xor GEOM_SALT_QUAD, i), so quadrilateral i and pentagon i are
** unrelated (the registry of streams: geom/splitmix.h).
** atan2 only orders the points; the convexity test is exact. */
static void sampler_by_angle(geom_point q[4], double cx, double cy) {
  double ang[4];
  for (int k = 0; k < 4; k++) ang[k] = atan2(q[k].y - cy, q[k].x - cx);
  for (int a = 1; a < 4; a++)
    for (int b = a; b > 0 && ang[b] < ang[b - 1]; b--) {
      double t = ang[b];
      ang[b] = ang[b - 1];
      ang[b - 1] = t;
      geom_point p = q[b];
      q[b] = q[b - 1];
      q[b - 1] = p;
    }
}

void sampler_quad(uint64_t seed, uint64_t index, geom_point q[4]) {
  sampler_rng g;
  sampler_seed(&g, seed ^ GEOM_SALT_QUAD, index);
  for (;;) {
    double cx = 0, cy = 0;
    for (int k = 0; k < 4; k++) {
      q[k] = sampler_disc(&g);
      cx += q[k].x / 4;
      cy += q[k].y / 4;
    }
    sampler_by_angle(q, cx, cy);
    int ok = 1;
    for (int k = 0; k < 4; k++) ok &= geom_orient(q[k], q[(k + 1) % 4], q[(k + 2) % 4]) > 0;
    if (ok) return;
  }
}

/* ---- pentagon samplers for table34 --sampler ---------------------------- */

static int sampler_pentagon_iteration(uint64_t seed, uint64_t index, geom_point v[5]) {
  sampler_pentagon(seed, index, v);
  return 0;
}

/* sampler_vector and sampler_circle fail (-1) only when 100 draws in a row
** are spoilt by rounding, which for n = 5 never happens in practice; the
** stream simply goes on then. */
static int sampler_pentagon_polygon(uint64_t seed, uint64_t index, geom_point v[5],
                                    int (*draw)(sampler_rng *, size_t, geom_point *)) {
  sampler_rng g;
  geom_point h[5];
  int rc;
  sampler_seed(&g, seed, GEOM_STREAM_SAMPLE(index));
  while ((rc = draw(&g, 5, h)) == -1) {}
  if (rc != 0) return rc;
  memcpy(v, h, sizeof h);
  sampler_lexfirst(v, 5);
  return 0;
}

static int sampler_pentagon_vector(uint64_t seed, uint64_t index, geom_point v[5]) {
  return sampler_pentagon_polygon(seed, index, v, sampler_vector);
}

static int sampler_pentagon_circle(uint64_t seed, uint64_t index, geom_point v[5]) {
  return sampler_pentagon_polygon(seed, index, v, sampler_circle);
}

/* Five points at once; their hull (exact, sampler_hull_add) has five
** vertices exactly when all five are in strictly convex position. */
static int sampler_pentagon_dischull(uint64_t seed, uint64_t index, geom_point v[5]) {
  sampler_rng g;
  geom_point h[SAMPLER_HULL_MAX];
  int m;
  sampler_seed(&g, seed, GEOM_STREAM_SAMPLE(index));
  do {
    m = 0;
    for (int k = 0; k < 5; k++) m = sampler_hull_add(h, m, sampler_disc(&g));
  } while (m != 5);
  memcpy(v, h, 5 * sizeof *v);
  sampler_lexfirst(v, 5);
  return 0;
}

const sampler_pentagons sampler_pentagons_table[SAMPLER_PENTAGONS_COUNT] = {
  {"iteration", sampler_pentagon_iteration},
  {"vector", sampler_pentagon_vector},
  {"circle", sampler_pentagon_circle},
  {"disc-hull", sampler_pentagon_dischull},
};

const sampler_pentagons *sampler_pentagons_find(const char *s) {
  for (int k = 0; k < SAMPLER_PENTAGONS_COUNT; k++)
    if (strcmp(s, sampler_pentagons_table[k].name) == 0) return &sampler_pentagons_table[k];
  return NULL;
}
