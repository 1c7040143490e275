/*
** sweep_finish.c: the last step of the constrained sweeps (sweep_constrained.c):
** their triangles checked exactly, then their ties settled by lot's
** tie-break, as lot's own sweep ends (docs/lot.md, "Sweepline algorithm").
*/
#include <stdio.h>
#include <stdlib.h>
#include "geom_mem_internal.h"
#include "geom_key_internal.h"
#include "paradigm_internal.h"
#include "lot.h"

/* A triangulation of the hull of the n sites: every triangle strictly
** anticlockwise, every neighbour link an involution across the reversed
** edge, and Euler's count t = 2n - 2 - h with h the edges on one triangle
** only (for the hull polygon of n sites, h of them on its sides).  O(t). */
static int fin_valid(const geom_point *p, size_t n, const uint32_t *tri, size_t ntri,
                     const int32_t *nb) {
  size_t h = 0;
  for (size_t t = 0; t < ntri; t++) {
    const uint32_t *v = tri + 3 * t;
    if (geom_orient_valid(p[v[0]], p[v[1]], p[v[2]]) <= 0) return 0;
    for (int k = 0; k < 3; k++) {
      int32_t u = nb[3 * t + (size_t)k];
      if (u < 0) {
        h++;
        continue;
      }
      int b = paradigm_nb_corner(nb, (size_t)u, t);
      if (b < 0 || tri[3 * (size_t)u + (size_t)(b + 1) % 3] != v[(k + 2) % 3]) return 0;
    }
  }
  return ntri + h + 2 == 2 * n;
}

typedef struct fin_state {
  const geom_point *p;
  const rule *r;
  ops_counts *c;
  uint32_t *tri;
  int32_t *nb;
  const uint64_t *cons;       /* the constraint pieces, sorted keys */
  size_t ncons;
  size_t *stack, nstack, cap;
  int oom;
} fin_state;

/* The edge of triangle t opposite its corner k: flipped when the apex
** across it lies inside the circle of t (paradigm_inshape: lot's
** tie-break) and the quadrilateral is strictly convex, as lot flips.  The
** four outer edges are pushed.  t = (P, A, B), u = (Q, B, A) become
** (P, A, Q) and (Q, B, P). */
static void fin_edge(fin_state *F, size_t t, int k) {
  int32_t ui = F->nb[3 * t + (size_t)k];
  uint32_t *v = F->tri + 3 * t;
  uint32_t P = v[k], A = v[(k + 1) % 3], B = v[(k + 2) % 3];
  uint64_t key = geom_edge_key(A, B);
  if (ui < 0 || bsearch(&key, F->cons, F->ncons, sizeof key, geom_u64_cmp) != NULL) return;
  size_t u = (size_t)ui;
  int j = paradigm_nb_corner(F->nb, u, t);
  uint32_t Q = F->tri[3 * u + (size_t)j];
  const geom_point *p = F->p;
  if (paradigm_inshape(F->r, F->c, p[P], p[A], p[B], p[Q]) <= 0) return;
  if (ops_orient(F->c, p[P], p[A], p[Q]) <= 0 || ops_orient(F->c, p[Q], p[B], p[P]) <= 0) return;
  int32_t tA = F->nb[3 * t + (size_t)(k + 1) % 3], tB = F->nb[3 * t + (size_t)(k + 2) % 3];
  int32_t uB = F->nb[3 * u + (size_t)(j + 1) % 3], uA = F->nb[3 * u + (size_t)(j + 2) % 3];
  uint32_t *w = F->tri + 3 * u;
  v[0] = P, v[1] = A, v[2] = Q, w[0] = Q, w[1] = B, w[2] = P;
  int32_t *nt = F->nb + 3 * t, *nu = F->nb + 3 * u;
  nt[0] = uB, nt[1] = (int32_t)u, nt[2] = tB;
  nu[0] = tA, nu[1] = (int32_t)t, nu[2] = uA;
  paradigm_nb_relink(F->nb, uB, u, t);
  paradigm_nb_relink(F->nb, tA, t, u);
  ops_add(F->c, OPS_FLIPS, 1);
  ops_add(F->c, OPS_EDGES_MADE, 1);
  ops_add(F->c, OPS_EDGES_DELETED, 1);
  if (geom_grow((void **)&F->stack, &F->cap, F->nstack + 4, sizeof *F->stack) != 0) {
    F->oom = 1;
    return;
  }
  size_t *s = F->stack + F->nstack;
  s[0] = 3 * t, s[1] = 3 * t + 2, s[2] = 3 * u, s[3] = 3 * u + 2;
  F->nstack += 4;
}

/* Lawson's flips from every edge until none flips: each flip lowers the
** perturbed lifted surface, so they end, at the one triangulation whose
** every edge that is no constraint is locally Delaunay under the
** tie-break (lot's).  With no ties and no pocket cut out of order: one
** in-circle test per edge, no flip. */
static void fin_lawson(fin_state *F, size_t ntri) {
  for (size_t t = ntri; t-- > 0;)
    for (int k = 2; k >= 0; k--)
      if (F->nb[3 * t + (size_t)k] > (int32_t)t) F->stack[F->nstack++] = 3 * t + (size_t)k;
  while (F->nstack > 0 && !F->oom) {
    size_t c = F->stack[--F->nstack];
    fin_edge(F, c / 3, (int)(c % 3));
  }
}

int paradigm_sweep_finish(const paradigm_input *in, uint32_t *tri, size_t ntri,
                          const uint32_t *cons, size_t ncons, ops_counts *c, char *err,
                          size_t errlen) {
  int32_t *nb = malloc((ntri ? 3 * ntri : 1) * sizeof *nb);
  uint64_t *keys = malloc((ncons ? ncons : 1) * sizeof *keys);
  size_t cap = 3 * ntri + 4, *stack = malloc(cap * sizeof *stack);
  int rc = nb && keys && stack ? lot_neighbors(tri, ntri, in->n, nb) : -1;
  if (rc != 0) {
    snprintf(err, errlen, "out of memory for %zu triangles", ntri);
  } else if (!fin_valid(in->p, in->n, tri, ntri, nb)) {
    snprintf(err, errlen, "the sweep made no triangulation (%zu triangles for %zu sites): "
             "a bug, please report the input", ntri, in->n);
    rc = -1;
  } else {
    for (size_t i = 0; i < ncons; i++) keys[i] = geom_edge_key(cons[2 * i], cons[2 * i + 1]);
    qsort(keys, ncons, sizeof *keys, geom_u64_cmp);
    fin_state F = {in->p, in->r, c, tri, nb, keys, ncons, stack, 0, cap, 0};
    fin_lawson(&F, ntri);
    stack = F.stack;
    if (F.oom) snprintf(err, errlen, "out of memory for the flips of %zu triangles", ntri);
    rc = -F.oom;
  }
  free(nb), free(keys), free(stack);
  return rc;
}
