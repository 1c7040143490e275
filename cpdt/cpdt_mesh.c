/*
** cpdt_mesh.c: the half-edge mesh of cpdt/ (cpdt_internal.h): rings of
** half-edges round each vertex, edges added, deleted and flipped in O(1).
*/
#include <stdlib.h>
#include "cpdt_internal.h"

int cpdt_mesh_init(cpdt_mesh *m, cpdt_run *r, size_t edges) {
  m->to = malloc(2 * edges * sizeof *m->to);
  m->nx = malloc(2 * edges * sizeof *m->nx);
  m->pv = malloc(2 * edges * sizeof *m->pv);
  m->first = malloc(r->n * sizeof *m->first);
  m->free = CPDT_NONE;
  m->used = 0;
  m->cap = (uint32_t)edges;
  if (m->to == NULL || m->nx == NULL || m->pv == NULL || m->first == NULL) {
    cpdt_mesh_free(m);
    return -2;
  }
  for (size_t v = 0; v < r->n; v++) m->first[v] = CPDT_NONE;
  cpdt_memory(r, (uint64_t)edges * 6 * sizeof(uint32_t) + r->n * sizeof(uint32_t));
  return 0;
}

void cpdt_mesh_free(cpdt_mesh *m) {
  free(m->to);
  free(m->nx);
  free(m->pv);
  free(m->first);
  m->to = m->nx = m->pv = m->first = NULL;
}

/* Half-edge h (origin v) into v's ring after `after`, or alone. */
static void cpdt_link(cpdt_mesh *m, uint32_t v, uint32_t h, uint32_t after) {
  if (after == CPDT_NONE) {
    m->nx[h] = m->pv[h] = h;
    m->first[v] = h;
    return;
  }
  uint32_t next = m->nx[after];
  m->nx[after] = h;
  m->pv[h] = after;
  m->nx[h] = next;
  m->pv[next] = h;
}

static void cpdt_unlink(cpdt_mesh *m, uint32_t v, uint32_t h) {
  uint32_t p = m->pv[h], q = m->nx[h];
  m->nx[p] = q;
  m->pv[q] = p;
  if (m->first[v] == h) m->first[v] = q != h ? q : CPDT_NONE;
}

uint32_t cpdt_mesh_add(cpdt_mesh *m, uint32_t a, uint32_t b, uint32_t pa, uint32_t pb) {
  uint32_t e;
  if (m->free != CPDT_NONE) {
    e = m->free;
    m->free = m->to[2 * e];
  } else {
    e = m->used++;   /* callers size the mesh for every edge they make */
  }
  uint32_t h = 2 * e;
  m->to[h] = b;
  m->to[h ^ 1] = a;
  cpdt_link(m, a, h, pa);
  cpdt_link(m, b, h ^ 1, pb);
  return h;
}

void cpdt_mesh_delete(cpdt_mesh *m, uint32_t h) {
  uint32_t a = m->to[h ^ 1], b = m->to[h];
  cpdt_unlink(m, a, h);
  cpdt_unlink(m, b, h ^ 1);
  m->to[h & ~1u] = m->free;
  m->free = h >> 1;
}

/* Faces a b c (c = to[nx[h]]) and b a d (d = to[pv[h]]).  Round c the ring
** reads a, b; round d it reads b, a: the new edge goes between them. */
uint32_t cpdt_mesh_flip(cpdt_mesh *m, uint32_t h) {
  uint32_t a = m->to[h ^ 1], b = m->to[h];
  uint32_t ac = m->nx[h], bd = m->nx[h ^ 1];
  uint32_t c = m->to[ac], d = m->to[bd];
  cpdt_unlink(m, a, h);
  cpdt_unlink(m, b, h ^ 1);
  m->to[h] = d;
  m->to[h ^ 1] = c;
  cpdt_link(m, c, h, ac ^ 1);
  cpdt_link(m, d, h ^ 1, bd ^ 1);
  return h;
}

uint32_t cpdt_mesh_find(const cpdt_mesh *m, uint32_t a, uint32_t b) {
  uint32_t h0 = m->first[a], h = h0;
  if (h0 == CPDT_NONE) return CPDT_NONE;
  do {
    if (m->to[h] == b) return h;
    h = m->nx[h];
  } while (h != h0);
  return CPDT_NONE;
}

/* Face v u w for anticlockwise neighbours u, w of v with v < u < w: each
** face once, from its smallest vertex (the exterior gap, from v-1 round to
** v+1, never has v < u < w). */
void cpdt_mesh_emit(const cpdt_mesh *m, cpdt_run *r) {
  for (uint32_t v = 0; v < (uint32_t)r->n; v++) {
    uint32_t h0 = m->first[v], h = h0;
    if (h0 == CPDT_NONE) continue;
    do {
      uint32_t u = m->to[h], w = m->to[m->nx[h]];
      if (v < u && u < w) cpdt_emit(r, v, u, w);
      h = m->nx[h];
    } while (h != h0);
  }
}
