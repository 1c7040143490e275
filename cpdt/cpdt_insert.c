/*
** cpdt_insert.c: the flipping algorithms on the half-edge mesh: the
** incremental algorithm in input order (thesis 5.4.3), Chew's randomised
** incremental algorithm, and the fan from vertex 0 flipped by Lawson's
** algorithm (the thesis's further work, 7.6).  Here first[v] is always
** v's half-edge to its successor on the current polygon, so the half-edge
** before it in v's ring goes to v's predecessor and has the outside on its
** left.
*/
#include <stdlib.h>
#include "cpdt_internal.h"

/* The triangle a b c (anticlockwise), the first polygon. */
static void cpdt_triangle(cpdt_mesh *m, uint32_t a, uint32_t b, uint32_t c) {
  uint32_t ab = cpdt_mesh_add(m, a, b, CPDT_NONE, CPDT_NONE);
  uint32_t bc = cpdt_mesh_add(m, b, c, ab ^ 1, CPDT_NONE);
  uint32_t ac = cpdt_mesh_add(m, a, c, ab, bc ^ 1);
  m->first[a] = ab;
  m->first[b] = bc;
  m->first[c] = ac ^ 1;
}

/* Vertex p outside the current polygon between its neighbours q and s
** there: the edges q p and p s, then each edge opposite p flipped while p
** lies inside the circle beyond it.  Every flip joins p to one more vertex
** for good, so p's flips are its interior degree in the result.  stack:
** room for n half-edges (one flip pushes two, pops one). */
static void cpdt_insert(cpdt_mesh *m, cpdt_run *r, uint32_t q, uint32_t p, uint32_t s,
                        uint32_t *stack) {
  uint32_t qs = m->first[q];
  uint32_t ps = cpdt_mesh_add(m, p, s, CPDT_NONE, qs ^ 1);
  m->first[q] = cpdt_mesh_add(m, q, p, m->pv[qs], ps);
  m->first[p] = ps;
  size_t sp = 0;
  stack[sp++] = qs;            /* each with p on its right: faces b a p */
  while (sp > 0) {
    uint32_t h = stack[--sp], a = m->to[h ^ 1], b = m->to[h];
    if (m->nx[h] == m->first[a]) continue;   /* a side of the polygon */
    uint32_t ac = m->nx[h], cb = m->nx[ac ^ 1];
    if (cpdt_incircle(r, a, p, b, m->to[ac]) < 0) continue;
    cpdt_mesh_flip(m, h);
    r->c->flips++;
    stack[sp++] = cb;
    stack[sp++] = ac;
  }
}

/* Vertex order[t] for t = n-4 .. 0 inserted between q[t] and s[t] after the
** triangle order[n-3 .. n-1] (anticlockwise from `start`). */
static int cpdt_insert_all(cpdt_run *r, const uint32_t *order, const uint32_t *q,
                           const uint32_t *s, const uint32_t tri[3]) {
  size_t n = r->n;
  cpdt_mesh m;
  uint32_t *stack = malloc(n * sizeof *stack);
  if (stack == NULL || cpdt_mesh_init(&m, r, 2 * n) != 0) {
    free(stack);
    return -2;
  }
  cpdt_memory(r, n * sizeof *stack);
  cpdt_triangle(&m, tri[0], tri[1], tri[2]);
  for (size_t t = n - 3; t-- > 0;) cpdt_insert(&m, r, q[t], order[t], s[t], stack);
  cpdt_mesh_emit(&m, r);
  cpdt_mesh_free(&m);
  free(stack);
  return 0;
}

/* Cost: vertex i makes d_i flips, its interior degree in the triangulation
** D_i of p_0 .. p_i: n(n-1)/2 - ... at worst (a fan at p_{n-1}), and on
** average over triangulations d_i = 2(i-1)/(i+2), so O(n) (5.4.3).  Space:
** the mesh and the flip stack, O(n). */
int cpdt_incremental(cpdt_run *r) {
  size_t n = r->n;
  uint32_t *w = malloc(3 * n * sizeof *w);
  if (w == NULL) return -2;
  uint32_t *order = w, *q = w + n, *s = w + 2 * n;
  for (size_t t = 0; t + 3 < n; t++) {   /* deleted last first: n-1, n-2, ..., 3 */
    order[t] = (uint32_t)(n - 1 - t);
    q[t] = (uint32_t)(n - 2 - t);
    s[t] = 0;
  }
  const uint32_t tri[3] = {0, 1, 2};
  cpdt_memory(r, 3 * n * sizeof *w);
  int rc = cpdt_insert_all(r, order, q, s, tri);
  free(w);
  return rc;
}

/* Chew's algorithm.  Cost: deleting in a uniformly random order and putting
** back in reverse makes each insertion that of a random vertex of the
** polygon so far, whose expected degree in a triangulation of k vertices is
** below 4 (the interior edges of all vertices sum to 2(k - 3)): O(n)
** expected flips and time, whatever the polygon.  Space: O(n). */
int cpdt_random_incremental(cpdt_run *r) {
  size_t n = r->n;
  uint32_t *w = malloc(5 * n * sizeof *w);
  if (w == NULL) return -2;
  uint32_t *order = w, *q = w + n, *s = w + 2 * n, *prev = w + 3 * n, *next = w + 4 * n;
  for (size_t i = 0; i < n; i++) {
    order[i] = (uint32_t)i;
    prev[i] = (uint32_t)((i + n - 1) % n);
    next[i] = (uint32_t)((i + 1) % n);
  }
  for (size_t i = n; i > 1; i--) {   /* Fisher and Yates */
    size_t j = cpdt_random(r, (uint32_t)i);
    uint32_t t = order[i - 1];
    order[i - 1] = order[j];
    order[j] = t;
  }
  for (size_t t = 0; t + 3 < n; t++) {
    uint32_t v = order[t];
    q[t] = prev[v];
    s[t] = next[v];
    next[prev[v]] = next[v];
    prev[next[v]] = prev[v];
  }
  uint32_t a = order[n - 1];
  const uint32_t tri[3] = {a, next[a], next[next[a]]};
  cpdt_memory(r, 5 * n * sizeof *w);
  int rc = cpdt_insert_all(r, order, q, s, tri);
  free(w);
  return rc;
}

/* The fan from vertex 0: rings built in anticlockwise order (round i: i+1,
** 0, i-1), first[v] the side to v + 1. */
static void cpdt_fan(cpdt_mesh *m, size_t n) {
  uint32_t z = CPDT_NONE, back = CPDT_NONE;   /* 0 -> i-1; i-1 -> i-2 (1 -> 0) */
  for (uint32_t i = 1; i < (uint32_t)n; i++) {
    uint32_t zi = cpdt_mesh_add(m, 0, i, z, CPDT_NONE);
    if (i >= 2) {
      uint32_t side = cpdt_mesh_add(m, i - 1, i, back, zi ^ 1);
      m->first[i - 1] = side;
      back = side ^ 1;
    } else {
      back = zi ^ 1;
    }
    z = zi;
  }
  m->first[n - 1] = z ^ 1;
}

static int cpdt_is_side(uint32_t a, uint32_t b, size_t n) {
  uint32_t d = a > b ? a - b : b - a;
  return d == 1 || d == n - 1;
}

/* Lawson's flips from a queue of diagonals, each queued at most once
** (cpdt_internal.h). */
void cpdt_lawson(cpdt_mesh *m, cpdt_run *r, uint32_t *queue, unsigned char *queued) {
  size_t n = r->n, cap = m->used, head = 0, count = 0;
  for (uint32_t e = 0; e < m->used; e++)
    if (!cpdt_is_side(m->to[2 * e], m->to[2 * e + 1], n)) {
      queue[count++] = e;
      queued[e] = 1;
    }
  while (count > 0) {
    uint32_t e = queue[head], h = 2 * e;
    head = (head + 1) % cap;
    count--;
    queued[e] = 0;
    uint32_t a = m->to[h ^ 1], b = m->to[h], c = m->to[m->nx[h]], d = m->to[m->pv[h]];
    if (cpdt_incircle(r, a, b, c, d) < 0) continue;
    uint32_t around[4] = {m->nx[h], m->nx[m->nx[h] ^ 1], m->nx[h ^ 1], m->nx[m->nx[h ^ 1] ^ 1]};
    cpdt_mesh_flip(m, h);
    r->c->flips++;
    for (int k = 0; k < 4; k++) {
      uint32_t f = around[k] >> 1;
      if (queued[f] || cpdt_is_side(m->to[2 * f], m->to[2 * f + 1], n)) continue;
      queue[(head + count++) % cap] = f;
      queued[f] = 1;
    }
  }
}

/* Cost: the fan, O(n); then each flip lowers the lifted surface, so no
** triangulation comes twice and the flips are at most the pairs of vertices
** whose edge can be crossed, O(n^2) (reached when the Delaunay triangulation
** is a fan from another vertex); each flip queues at most four edges and
** each queued edge costs one incircle test.  Space: the mesh and a queue of
** n edges. */
int cpdt_flip(cpdt_run *r) {
  size_t n = r->n;
  cpdt_mesh m;
  uint32_t *queue = malloc(2 * n * sizeof *queue);
  unsigned char *queued = calloc(2 * n, 1);
  if (queue == NULL || queued == NULL || cpdt_mesh_init(&m, r, 2 * n) != 0) {
    free(queue), free(queued);
    return -2;
  }
  cpdt_memory(r, 2 * n * (sizeof *queue + 1));
  cpdt_fan(&m, n);
  cpdt_lawson(&m, r, queue, queued);
  cpdt_mesh_emit(&m, r);
  cpdt_mesh_free(&m);
  free(queue), free(queued);
  return 0;
}
