/*
** cpdt_divide.c: divide and conquer (thesis 5.4.2) on the half-edge mesh:
** the chain lo .. hi split by index into lo .. mid and mid+1 .. hi in O(1),
** each triangulated, then merged from the side mid mid+1 up to the side
** lo hi along the cross edges, as Guibas and Stolfi merge.
*/
#include "cpdt_internal.h"

/* The merge of lo .. mid and mid+1 .. hi, each triangulated with its closing
** side.  Base l->r, l left of r; above it lie lo .. l-1 and r+1 .. hi (on
** the left of l->r).  Round l the left candidates come anticlockwise after
** r (increasing index, smallest first); round r the right ones clockwise
** after l (decreasing index).  A candidate whose next one lies inside the
** circle through the base and it is no Delaunay neighbour: its edge goes.
** Cost: Theta(a) for a cross edges, one incircle test per candidate looked
** at; additions a + 1 (the side lo hi among them), deletions a - 1. */
static void cpdt_merge(cpdt_mesh *m, cpdt_run *r, uint32_t lo, uint32_t mid, uint32_t hi) {
  uint32_t lm = cpdt_mesh_find(m, mid, mid - 1), rm = cpdt_mesh_find(m, mid + 1, hi);
  uint32_t base = cpdt_mesh_add(m, mid, mid + 1, lm, rm);
  uint64_t added = 0, deleted = 0;
  for (;;) {
    uint32_t l = m->to[base ^ 1], rv = m->to[base];
    uint32_t lc = m->nx[base], rc = m->pv[base ^ 1];
    int lok = m->to[lc] < l, rok = m->to[rc] > rv;
    while (lok && m->to[m->nx[lc]] < l &&
           cpdt_incircle(r, l, rv, m->to[lc], m->to[m->nx[lc]]) > 0) {
      uint32_t next = m->nx[lc];
      cpdt_mesh_delete(m, lc);
      deleted++;
      lc = next;
    }
    while (rok && m->to[m->pv[rc]] > rv &&
           cpdt_incircle(r, l, rv, m->to[rc], m->to[m->pv[rc]]) > 0) {
      uint32_t next = m->pv[rc];
      cpdt_mesh_delete(m, rc);
      deleted++;
      rc = next;
    }
    if (!lok && !rok) break;
    added++;
    if (lok && (!rok || cpdt_incircle(r, l, rv, m->to[lc], m->to[rc]) < 0))
      base = cpdt_mesh_add(m, m->to[lc], rv, lc ^ 1, m->pv[base ^ 1]);   /* j -> r */
    else
      base = cpdt_mesh_add(m, l, m->to[rc], base, m->pv[rc ^ 1]);        /* l -> k */
  }
  uint64_t a = added - 1;   /* the last is the side lo hi */
  r->c->merges++;
  r->c->cross_sum += a;
  if (a > r->c->cross_max) r->c->cross_max = a;
  r->c->added += a;
  r->c->deleted += deleted;
  (void)lo, (void)hi;
}

/* Pieces of 2 and 3 vertices directly; anticlockwise rings as they grow. */
static void cpdt_divide_rec(cpdt_mesh *m, cpdt_run *r, uint32_t lo, uint32_t hi,
                            uint64_t level) {
  if (level > r->c->depth) r->c->depth = level;
  if (hi - lo == 1) {
    cpdt_mesh_add(m, lo, hi, CPDT_NONE, CPDT_NONE);
    return;
  }
  if (hi - lo == 2) {
    uint32_t h01 = cpdt_mesh_add(m, lo, lo + 1, CPDT_NONE, CPDT_NONE);
    uint32_t h12 = cpdt_mesh_add(m, lo + 1, hi, h01 ^ 1, CPDT_NONE);
    cpdt_mesh_add(m, lo, hi, h01, h12 ^ 1);
    return;
  }
  uint32_t mid = lo + (hi - lo - 1) / 2;   /* both halves of at least 2 */
  cpdt_divide_rec(m, r, lo, mid, level + 1);
  cpdt_divide_rec(m, r, mid + 1, hi, level + 1);
  cpdt_merge(m, r, lo, mid, hi);
}

/* Cost: T(n) = Theta(a) + 2 T(n/2), a the cross edges of the top merge:
** O(n log n) at worst, and O(n) when a = O(n^c), c < 1 (on average over
** triangulations a = Theta(sqrt n), 5.4.2).  Space: the mesh, at most 3n
** edges at once (2n - 3 in the result, a merge's extra sides), and a
** recursion log2 n deep. */
int cpdt_divide(cpdt_run *r) {
  cpdt_mesh m;
  if (cpdt_mesh_init(&m, r, 3 * r->n) != 0) return -2;
  cpdt_divide_rec(&m, r, 0, (uint32_t)r->n - 1, 1);
  cpdt_mesh_emit(&m, r);
  cpdt_mesh_free(&m);
  return 0;
}
