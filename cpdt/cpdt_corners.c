/*
** cpdt_corners.c: corner cutting, the thesis's sweepline simplified for a
** monotone polygon (2.5.4, 2.5.5): with every site event taken first, the
** boundary is the polygon itself (a doubly linked list) and each convex
** corner a v b has a circle event; the least event cuts its corner off
** (triangle a v b out, v off the boundary) and the corners at a and b are
** rescheduled.  The thesis keys an event by its circle's rightmost point;
** with the sites all taken first that order is wrong (one random convex
** polygon of 4 to 8 vertices in fifteen gets a non-Delaunay triangle), so
** the key here is the circle's radius: the corner with the smallest
** circumcircle is cut first (no failure was seen on the tests' polygons,
** which assert it on vector polygons; no proof is claimed).
**
** The radius is computed in floating point (no exact predicate), so two
** keys within rounding may come out of order, and cocircular corners
** always tie.  Lawson's flips with the exact incircle test and lot's
** tie-break then finish the job (as lot's sweep does with a shape's ties):
** each diagonal is tested once, and the flips counted are the repairs.
*/
#include <stdlib.h>
#include "cpdt_internal.h"

typedef struct cpdt_event { double key; uint32_t v, stamp; } cpdt_event;

typedef struct cpdt_corner {
  cpdt_event *heap;
  size_t size;
  uint32_t *prev, *next, *stamp;
} cpdt_corner;

static int cpdt_event_less(const cpdt_event *x, const cpdt_event *y) {
  return x->key < y->key || (x->key == y->key && x->v < y->v);
}

static void cpdt_heap_push(cpdt_corner *s, cpdt_event e) {
  size_t i = s->size++;
  while (i > 0 && cpdt_event_less(&e, &s->heap[(i - 1) / 2])) {
    s->heap[i] = s->heap[(i - 1) / 2];
    i = (i - 1) / 2;
  }
  s->heap[i] = e;
}

static cpdt_event cpdt_heap_pop(cpdt_corner *s) {
  cpdt_event top = s->heap[0], last = s->heap[--s->size];
  size_t i = 0;
  for (;;) {
    size_t c = 2 * i + 1;
    if (c >= s->size) break;
    if (c + 1 < s->size && cpdt_event_less(&s->heap[c + 1], &s->heap[c])) c++;
    if (!cpdt_event_less(&s->heap[c], &last)) break;
    s->heap[i] = s->heap[c];
    i = c;
  }
  s->heap[i] = last;
  return top;
}

/* The squared radius of the circle through a, v, b (floating point; the
** order of squares is the order of radii). */
static double cpdt_key(const geom_point *p, uint32_t a, uint32_t v, uint32_t b) {
  double bx = p[v].x - p[a].x, by = p[v].y - p[a].y, cx = p[b].x - p[a].x, cy = p[b].y - p[a].y;
  double d = 2 * (bx * cy - by * cx), b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  double ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
  return ux * ux + uy * uy;
}

/* A new event for the corner at v (its older ones go stale). */
static void cpdt_schedule(cpdt_corner *s, const geom_point *p, uint32_t v) {
  s->stamp[v]++;
  cpdt_heap_push(s, (cpdt_event){cpdt_key(p, s->prev[v], v, s->next[v]), v, s->stamp[v]});
}

/* The polygon's sides as the first mesh: rings of two, first[v] = v -> v+1. */
static void cpdt_sides(cpdt_mesh *m, size_t n) {
  uint32_t back = CPDT_NONE, h0 = CPDT_NONE;
  for (uint32_t v = 0; v < (uint32_t)n; v++) {
    uint32_t w = v + 1 == (uint32_t)n ? 0 : v + 1;
    uint32_t h = cpdt_mesh_add(m, v, w, back, w == 0 ? h0 : CPDT_NONE);
    if (v == 0) h0 = h;
    m->first[v] = h;
    back = h ^ 1;
  }
}

/* Corner v cut off: the diagonal a b, after a -> v round a and before
** b -> v round b (a v b is a face). */
static void cpdt_cut(cpdt_mesh *m, cpdt_corner *s, uint32_t v) {
  uint32_t a = s->prev[v], b = s->next[v];
  m->first[a] = cpdt_mesh_add(m, a, b, m->first[a], m->pv[m->first[v] ^ 1]);
  s->next[a] = b;
  s->prev[b] = a;
  s->stamp[v]++;
}

/* Cost: n - 3 events cut corners, each O(log n) in the heap (a cut
** schedules two events; stale ones are skipped when they come up), so
** O(n log n); then Lawson's flips test each of the n - 3 diagonals once
** and flip only where the floating-point keys erred (none on generic
** input, a few among cocircular vertices).  Space: the mesh, the boundary
** list and a heap of at most 3n events. */
int cpdt_corners(cpdt_run *r) {
  size_t n = r->n;
  cpdt_mesh m;
  cpdt_corner s = {malloc(3 * n * sizeof *s.heap), 0, malloc(3 * n * sizeof *s.prev), NULL, NULL};
  uint32_t *queue = malloc(2 * n * sizeof *queue);
  unsigned char *queued = calloc(2 * n, 1);
  int rc = s.heap == NULL || s.prev == NULL || queue == NULL || queued == NULL ? -2
           : cpdt_mesh_init(&m, r, 2 * n);
  if (rc == 0) {
    cpdt_memory(r, 3 * n * (sizeof *s.heap + sizeof *s.prev) + 2 * n * (sizeof *queue + 1));
    s.next = s.prev + n;
    s.stamp = s.prev + 2 * n;
    for (uint32_t v = 0; v < (uint32_t)n; v++) {
      s.prev[v] = v == 0 ? (uint32_t)n - 1 : v - 1;
      s.next[v] = v + 1 == (uint32_t)n ? 0 : v + 1;
      s.stamp[v] = 0;
    }
    cpdt_sides(&m, n);
    for (uint32_t v = 0; v < (uint32_t)n; v++) cpdt_schedule(&s, r->p, v);
    for (size_t left = n; left > 3;) {
      cpdt_event e = cpdt_heap_pop(&s);
      if (e.stamp != s.stamp[e.v]) continue;
      uint32_t a = s.prev[e.v], b = s.next[e.v];
      cpdt_cut(&m, &s, e.v);
      left--;
      cpdt_schedule(&s, r->p, a);
      cpdt_schedule(&s, r->p, b);
    }
    cpdt_lawson(&m, r, queue, queued);
    cpdt_mesh_emit(&m, r);
    cpdt_mesh_free(&m);
  }
  free(s.heap), free(s.prev), free(queue), free(queued);
  return rc;
}
