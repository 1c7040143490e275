/*
** bounce.c: the bounce method (thesis section 6.5, after Thurston): a convex
** polygon whose vertices move with random velocities, each vertex bounced
** whenever it is about to become reflex, by discrete-event simulation.
**
** Start: the regular n-gon on the unit circle (vertex k at angle 2 pi k / n),
** every velocity uniform in the unit disc.  For consecutive A, B, C with
** relative positions a = A - B, c = C - B and relative velocities va, vc,
** twice the area of ABC at time T + t is the quadratic
**   k0 + k1 t + k2 t^2 = cross(c + t vc, a + t va),
**   k0 = cross(c, a), k1 = cross(vc, a) + cross(c, va), k2 = cross(vc, va),
** and B's event is its smallest positive root.  Every vertex keeps its
** event time in a binary heap (ties broken by the vertex's index, so the
** run is the same on every machine).  At an event at B, time T:
**   law 0  B's velocity is redrawn uniform on the unit disc intersected with
**          the half-plane of velocities that make d(area)/dt > 0 at T (the
**          derivative is K + cross(V_B, C - A), linear in V_B), by rejection
**          from the bounding box of that part of the disc (at least half
**          the box, so O(1) expected draws).  When A and C already move
**          with speed at most 1 the part is never empty, and speeds stay
**          at most 1.
**   law 1  B's velocity is reflected in the frame that moves with A and
**          turns with the line AC (C moving along it): its component
**          perpendicular to AC changes sign, V_B -= 2 (u . n) n with n the
**          unit normal of AC and u B's velocity relative to that frame.
**          The turning frame is not inertial: speeds may grow.  So d(area)
**          /dt at T changes sign; if rounding leaves it <= 0 the velocity is
**          redrawn by law 0 instead.
** Only B's velocity changes, so only the events of B - 1, B and B + 1 are
** recomputed: O(log n) per event (for a triangle the three are one
** triple, flat at T).  B's own next event is the other root of
** k1 t + k2 t^2 (its area is 0 at T by definition).  After each event the
** two neighbouring triples are checked exactly (geom_orient at time T):
** one that rounding has left flat or reflex is given an event at T itself,
** so it is bounced next.
**
** The run processes 2n events (the thesis's O(n)), or stops earlier when
** no event is left (the polygon then only grows); the output is the
** polygon at the time halfway to the next event (at most one time unit
** later).  That polygon is checked exactly (sampler_gon_canon); when
** rounding spoilt it (a vertex bounced a moment before, still flat to
** within rounding), the simulation processes one more event and tries the
** next gap, at most 64 times, then returns -1.  The whole run is
** O(n log n).
**
** Vectors are written with the same operation in both components (a + b,
** a + b; never a - b, a + b): gcc's vectoriser fuses the mixed pair into
** one vfmaddsub under -march=native despite -ffp-contract=off, and the
** output would then depend on -march.
*/
#include <math.h>
#include <stdlib.h>
#include "sampler.h"

#define BOUNCE_PI 3.14159265358979323846
#define BOUNCE_RETRIES 64

typedef struct bounce_sim {
  size_t n;
  geom_point *x, *v;     /* position at time tau[i], velocity */
  double *tau, *key;     /* key[i]: the time of vertex i's next event, or INFINITY */
  size_t *heap, *pos;    /* a binary min-heap of vertices by (key, index) */
  int law;
  sampler_rng *g;
} bounce_sim;

static int bounce_less(const bounce_sim *s, size_t i, size_t j) {
  return s->key[i] < s->key[j] || (s->key[i] == s->key[j] && i < j);
}

static void bounce_swap(bounce_sim *s, size_t a, size_t b) {
  size_t t = s->heap[a];
  s->heap[a] = s->heap[b];
  s->heap[b] = t;
  s->pos[s->heap[a]] = a;
  s->pos[s->heap[b]] = b;
}

/* Restore the heap after vertex i's key changed: O(log n). */
static void bounce_fix(bounce_sim *s, size_t i) {
  size_t h = s->pos[i];
  while (h > 0 && bounce_less(s, s->heap[h], s->heap[(h - 1) / 2])) {
    bounce_swap(s, h, (h - 1) / 2);
    h = (h - 1) / 2;
  }
  for (;;) {
    size_t l = 2 * h + 1, r = l + 1, m = h;
    if (l < s->n && bounce_less(s, s->heap[l], s->heap[m])) m = l;
    if (r < s->n && bounce_less(s, s->heap[r], s->heap[m])) m = r;
    if (m == h) return;
    bounce_swap(s, h, m);
    h = m;
  }
}

static geom_point bounce_at(const bounce_sim *s, size_t i, double t) {
  double dt = t - s->tau[i];
  return (geom_point){s->x[i].x + dt * s->v[i].x, s->x[i].y + dt * s->v[i].y};
}

static double bounce_cross(geom_point u, geom_point w) {
  return u.x * w.y - u.y * w.x;
}

static geom_point bounce_sub(geom_point u, geom_point w) {
  return (geom_point){u.x - w.x, u.y - w.y};
}

/* The smallest positive root of k0 + k1 t + k2 t^2 with k0 > 0, or
** INFINITY; the roots by the cancellation-free pair q / k2, k0 / q. */
static double bounce_root(double k0, double k1, double k2) {
  if (k2 == 0) return k1 < 0 ? -k0 / k1 : INFINITY;
  double disc = k1 * k1 - 4 * k2 * k0;
  if (disc < 0) return INFINITY;
  double q = -(k1 + (k1 < 0 ? -sqrt(disc) : sqrt(disc))) / 2;
  double r1 = q / k2, r2 = q != 0 ? k0 / q : INFINITY;
  double lo = r1 < r2 ? r1 : r2, hi = r1 < r2 ? r2 : r1;
  return lo > 0 ? lo : hi > 0 ? hi : INFINITY;
}

/* Vertex b's next event after time t; flat says its area is 0 at t (b has
** just bounced), so that the root at t itself is not found again.  A triple
** that rounding has left flat or reflex at t (exact geom_orient) is taken
** as flat too: bounced now if it is still closing (k1 <= 0), else
** scheduled as one that has just bounced. */
static void bounce_schedule(bounce_sim *s, size_t b, double t, int flat) {
  size_t a = (b + s->n - 1) % s->n, c = (b + 1) % s->n;
  geom_point A = bounce_at(s, a, t), B = bounce_at(s, b, t), C = bounce_at(s, c, t);
  geom_point pa = bounce_sub(A, B), pc = bounce_sub(C, B);
  geom_point va = bounce_sub(s->v[a], s->v[b]), vc = bounce_sub(s->v[c], s->v[b]);
  double k1 = bounce_cross(vc, pa) + bounce_cross(pc, va), k2 = bounce_cross(vc, va);
  double dt;
  if (!flat && geom_orient(A, B, C) > 0) dt = bounce_root(bounce_cross(pc, pa), k1, k2);
  else if (k1 > 0) dt = k2 < 0 ? -k1 / k2 : INFINITY;   /* opening: the other root */
  else dt = 0;                                          /* closing: bounce now */
  s->key[b] = t + dt;
  bounce_fix(s, b);
}

/* d(twice area of ABC)/dt at time t as K + cross(V_B, d), d = C - A. */
static double bounce_rate_k(const bounce_sim *s, size_t b, double t, geom_point *d) {
  size_t a = (b + s->n - 1) % s->n, c = (b + 1) % s->n;
  geom_point A = bounce_at(s, a, t), B = bounce_at(s, b, t), C = bounce_at(s, c, t);
  *d = bounce_sub(C, A);
  return bounce_cross(s->v[c], bounce_sub(A, B)) + bounce_cross(bounce_sub(C, B), s->v[a]);
}

/* Law 0: uniform on {|v| < 1, v . m > h}, m the unit normal (d.y, -d.x) /
** |d|, h = -K / |d|: rejection from the part's bounding box in the frame
** (m, m rotated a quarter turn). */
static void bounce_law0(bounce_sim *s, size_t b, double t) {
  geom_point d;
  double k = bounce_rate_k(s, b, t, &d), len = hypot(d.x, d.y);
  geom_point m = {d.y / len, -d.x / len};
  double h = -k / len;
  if (!(h < 1)) {   /* no disc velocity will do (rounding at the rim): the least that does */
    s->v[b] = (geom_point){m.x * h * (1 + 0x1p-20), m.y * h * (1 + 0x1p-20)};
    return;
  }
  double lo = h > -1 ? h : -1, half = h > 0 ? sqrt(1 - h * h) : 1, u, w;
  do {
    u = lo + (1 - lo) * sampler_uniform(s->g);
    w = half * (2 * sampler_uniform(s->g) - 1);
  } while (!(u * u + w * w < 1 && u > h));
  geom_point mq = {-m.y, m.x};   /* m turned a quarter: the same operation in both lanes */
  s->v[b] = (geom_point){u * m.x + w * mq.x, u * m.y + w * mq.y};
}

/* Law 1: reflect the component normal to AC of B's velocity relative to
** the frame that moves with A and turns with AC at rate omega. */
static void bounce_law1(bounce_sim *s, size_t b, double t) {
  size_t a = (b + s->n - 1) % s->n, c = (b + 1) % s->n;
  geom_point A = bounce_at(s, a, t), B = bounce_at(s, b, t), C = bounce_at(s, c, t);
  geom_point d = bounce_sub(C, A), r = bounce_sub(B, A);
  double dd = d.x * d.x + d.y * d.y, len = sqrt(dd);
  double omega = bounce_cross(d, bounce_sub(s->v[c], s->v[a])) / dd;
  geom_point rq = {r.y, -r.x};
  geom_point u = {s->v[b].x - s->v[a].x + omega * rq.x, s->v[b].y - s->v[a].y + omega * rq.y};
  geom_point nrm = {-d.y / len, d.x / len};
  double un = u.x * nrm.x + u.y * nrm.y;
  s->v[b] = (geom_point){s->v[b].x - 2 * un * nrm.x, s->v[b].y - 2 * un * nrm.y};
  if (!(bounce_rate_k(s, b, t, &d) + bounce_cross(s->v[b], d) > 0)) bounce_law0(s, b, t);
}

/* The event at the heap's top: anchor B at time t, change its velocity,
** reschedule B and its two neighbours. */
static double bounce_event(bounce_sim *s) {
  size_t b = s->heap[0];
  double t = s->key[b];
  s->x[b] = bounce_at(s, b, t);
  s->tau[b] = t;
  if (s->law == 1) bounce_law1(s, b, t);
  else bounce_law0(s, b, t);
  int tri = s->n == 3;   /* a triangle's three triples are one: all flat now */
  bounce_schedule(s, b, t, 1);
  bounce_schedule(s, (b + s->n - 1) % s->n, t, tri);
  bounce_schedule(s, (b + 1) % s->n, t, tri);
  return t;
}

/* The polygon at time t into out, checked exactly; 0 or -1.  Every triple
** by geom_orient first: O(n), where a failed sampler_gon_canon would have
** sorted the vertices for duplicates, O(n log n), at every retry. */
static int bounce_output(const bounce_sim *s, double t, geom_point *out) {
  size_t n = s->n;
  for (size_t i = 0; i < n; i++) out[i] = bounce_at(s, i, t);
  for (size_t i = 0; i < n; i++)
    if (geom_orient(out[(i + n - 1) % n], out[i], out[(i + 1) % n]) <= 0) return -1;
  return sampler_gon_canon(out, n, NULL);
}

/* Output at the time halfway to the next event (at most one unit on), once
** that is later than t; when rounding spoilt that polygon, the next event
** is processed and the next gap tried, at most BOUNCE_RETRIES times (extra
** events counted in *events). */
static int bounce_finish(bounce_sim *s, double t, geom_point *out, uint64_t *events) {
  for (int k = 0; k <= BOUNCE_RETRIES; k++) {
    double next = s->key[s->heap[0]], half = (next - t) / 2;
    double at = t + (half < 1 ? half : 1);
    if (at > t && bounce_output(s, at, out) == 0) return 0;
    if (!isfinite(next)) return -1;
    t = bounce_event(s);
    ++*events;
  }
  return -1;
}

static int bounce_init(bounce_sim *s, sampler_rng *g, size_t n, int law) {
  s->n = n;
  s->law = law;
  s->g = g;
  s->x = malloc(2 * n * sizeof *s->x);
  s->tau = malloc(2 * n * sizeof *s->tau);
  s->heap = calloc(2 * n, sizeof *s->heap);   /* calloc: gcc cannot see n > 0 */
  if (s->x == NULL || s->tau == NULL || s->heap == NULL) return SAMPLER_ENOMEM;
  s->v = s->x + n;
  s->key = s->tau + n;
  s->pos = s->heap + n;
  for (size_t i = 0; i < n; i++) {
    double th = 2 * BOUNCE_PI * (double)i / (double)n;
    s->x[i] = (geom_point){cos(th), sin(th)};
    s->v[i] = sampler_disc(g);
    s->tau[i] = 0;
    s->key[i] = INFINITY;
    s->heap[i] = s->pos[i] = i;
  }
  for (size_t i = 0; i < n; i++) bounce_schedule(s, i, 0, 0);
  return 0;
}

/* O(n log n): 2n events of O(log n) each, then the exact check. */
int sampler_gon_bounce(sampler_rng *g, size_t n, const sampler_gon_params *p, geom_point *out,
                       sampler_gon_info *info) {
  if (info != NULL) *info = (sampler_gon_info){0, 0, 0};
  int law = p != NULL ? p->law : 0;
  if (n < 3 || law < 0 || law > 1) return -1;
  bounce_sim s;
  int rc = bounce_init(&s, g, n, law);
  uint64_t events = 0;
  double t = 0;
  for (; rc == 0 && events < 2 * (uint64_t)n && isfinite(s.key[s.heap[0]]); events++)
    t = bounce_event(&s);
  if (rc == 0) rc = bounce_finish(&s, t, out, &events);
  if (info != NULL) info->draws = events;
  free(s.x);
  free(s.tau);
  free(s.heap);
  return rc;
}
