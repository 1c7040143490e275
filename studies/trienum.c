/*
** trienum.c: every triangulation of a convex polygon, one after the other,
** with the sums chapter 5 averages kept up to date as diagonals come and
** go; the totals of a whole enumeration; and the same quantities measured
** on one given triangulation (docs/averages.md).
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "triavg_internal.h"

/* ---- the enumerator ------------------------------------------------------- */

static void study_trienum_add(study_trienum *e, int i, int j) {
  uint64_t t[3];
  study_diag_terms((uint32_t)i, (uint32_t)j, (uint32_t)e->nv, (uint32_t)e->cut, t);
  for (int q = 0; q < 3; q++) e->sum[q] += t[q];
  e->diag[e->ndiag][0] = (uint8_t)i;
  e->diag[e->ndiag][1] = (uint8_t)j;
  e->ndiag++;
  e->deg[i]++;
  e->deg[j]++;
}

/* Remove the newest diagonal (diagonals come and go last in, first out). */
static void study_trienum_drop(study_trienum *e) {
  uint64_t t[3];
  e->ndiag--;
  int i = e->diag[e->ndiag][0], j = e->diag[e->ndiag][1];
  study_diag_terms((uint32_t)i, (uint32_t)j, (uint32_t)e->nv, (uint32_t)e->cut, t);
  for (int q = 0; q < 3; q++) e->sum[q] -= t[q];
  e->deg[i]--;
  e->deg[j]--;
}

/* Pop one vertex of the chain at p_v: the edge (below, p_v) is made, a
** diagonal unless it is the root side p_0 p_{N-1}. */
static void study_trienum_pop(study_trienum *e, int v) {
  int below = e->stack[e->sz - 2];
  if (!(below == 0 && v == e->nv - 1)) study_trienum_add(e, below, v);
  e->sz--;
}

static void study_trienum_push(study_trienum *e, int v) {
  e->saved[v] = e->stack[e->sz];
  e->stack[e->sz++] = (uint8_t)v;
}

static void study_trienum_unpush(study_trienum *e, int v) {
  e->stack[--e->sz] = e->saved[v];
}

/* Take p_from .. p_{N-2} with no pops, then the last vertex with all of
** them: the first triangulation below the current prefix. */
static void study_trienum_descend(study_trienum *e, int from) {
  for (int v = from; v < e->nv - 1; v++) {
    e->h[v] = e->sz;
    e->c[v] = 0;
    study_trienum_push(e, v);
  }
  int last = e->nv - 1;
  e->h[last] = e->sz;
  e->c[last] = e->sz - 1;
  for (int t = 0; t < e->c[last]; t++) study_trienum_pop(e, last);
}

/* Undo p_v's pops and push (the popped vertices are still in place). */
static void study_trienum_undo(study_trienum *e, int v) {
  int last = v == e->nv - 1;
  if (!last) study_trienum_unpush(e, v);
  for (int t = 0; t < e->c[v] - last; t++) study_trienum_drop(e);
  e->sz += e->c[v];
}

void study_trienum_start(study_trienum *e, int n) {
  memset(e, 0, sizeof *e);
  e->nv = n + 2;
  e->cut = n / 2;
  e->sz = 1;                 /* the chain holds p_0 */
}

/* Cost: O(1) amortised per triangulation beyond the O(N) of the last
** vertex's pops (the walk's inner nodes are fewer than a small multiple
** of its leaves). */
int study_trienum_next(study_trienum *e) {
  if (!e->started) {
    e->started = 1;
    study_trienum_descend(e, 1);
    return 1;
  }
  study_trienum_undo(e, e->nv - 1);
  for (int v = e->nv - 2; v >= 1; v--) {
    if (e->c[v] < e->h[v] - 1) {
      study_trienum_unpush(e, v);
      study_trienum_pop(e, v);
      e->c[v]++;
      study_trienum_push(e, v);
      study_trienum_descend(e, v + 1);
      return 1;
    }
    study_trienum_undo(e, v);
  }
  return 0;
}

/* ---- the totals of an enumeration ----------------------------------------- */

static uint64_t study_min_u64(uint64_t a, uint64_t b) { return a < b ? a : b; }
static uint64_t study_max_u64(uint64_t a, uint64_t b) { return a > b ? a : b; }

/* Cost: C_n triangulations, O(1) amortised each, O(n) with every vertex's
** histogram; the sums stay below 2^64 (C_18 times at most 200). */
void study_enum_run(int n, int every_vertex, study_enum_totals *t) {
  study_trienum e;
  memset(t, 0, sizeof *t);
  t->n = n;
  t->tc_min = t->len_min = UINT64_MAX;
  study_trienum_start(&e, n);
  while (study_trienum_next(&e)) {
    uint64_t tc = e.sum[0] + (uint64_t)n;
    t->count++;
    t->tc += tc;
    t->tc_min = study_min_u64(t->tc_min, tc);
    t->tc_max = study_max_u64(t->tc_max, tc);
    t->cross += e.sum[1];
    t->len += e.sum[2];
    t->len_min = study_min_u64(t->len_min, e.sum[2]);
    t->len_max = study_max_u64(t->len_max, e.sum[2]);
    for (int v = every_vertex ? 0 : n; v < e.nv; v++) t->hist[v][e.deg[v]]++;
  }
}

/* ---- one given triangulation ---------------------------------------------- */

/* A triangle by its vertices a < b < c: in a triangulation of the convex
** polygon, (a, c) is the edge toward the root side p_0 p_{N-1} and no two
** triangles share it. */
typedef struct study_tri_key {
  uint32_t a, b, c;
  size_t row;
} study_tri_key;

static int study_tri_key_cmp(const void *x, const void *y) {
  const study_tri_key *p = x, *q = y;
  if (p->a != q->a) return p->a < q->a ? -1 : 1;
  if (p->c != q->c) return p->c < q->c ? -1 : 1;
  return 0;
}

/* The rows as sorted keys, or -1 with err. */
static int study_tri_keys(const uint32_t *tri, size_t ntri, uint32_t nv, study_tri_key *k,
                          char *err, size_t errcap) {
  for (size_t r = 0; r < ntri; r++) {
    uint32_t v[3] = {tri[3 * r], tri[3 * r + 1], tri[3 * r + 2]};
    for (int q = 0; q < 3; q++)
      if (v[q] >= nv) {
        snprintf(err, errcap, "triangle %zu: vertex %u is out of range (the vertices are "
                 "0 .. %u)", r, (unsigned)v[q], (unsigned)nv - 1);
        return -1;
      }
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
      snprintf(err, errcap, "triangle %zu repeats a vertex", r);
      return -1;
    }
    uint32_t lo = v[0] < v[1] ? v[0] : v[1], hi = v[0] < v[1] ? v[1] : v[0];
    uint32_t mid = v[2] < lo ? lo : v[2] > hi ? hi : v[2];
    k[r] = (study_tri_key){v[2] < lo ? v[2] : lo, mid, v[2] > hi ? v[2] : hi, r};
  }
  qsort(k, ntri, sizeof *k, study_tri_key_cmp);
  for (size_t r = 1; r < ntri; r++)
    if (study_tri_key_cmp(&k[r - 1], &k[r]) == 0) {
      snprintf(err, errcap, "triangles %zu and %zu both lie inside edge p_%u p_%u",
               k[r - 1].row, k[r].row, (unsigned)k[r].a, (unsigned)k[r].c);
      return -1;
    }
  return 0;
}

/* Walk the tree of pieces from the root side: the piece p_a .. p_c must
** hold a triangle (a, b, c); its pieces p_a .. p_b and p_b .. p_c follow.
** Returns 0 when every triangle is reached, -1 with err otherwise. */
static int study_tri_walk(const study_tri_key *k, size_t ntri, uint32_t nv, uint32_t *stk,
                          study_tri_stats *out, uint32_t *degree, char *err, size_t errcap) {
  size_t top = 0;
  stk[top++] = 0;
  stk[top++] = nv - 1;
  while (top) {
    uint32_t c = stk[--top], a = stk[--top];
    study_tri_key key = {a, 0, c, 0};
    const study_tri_key *f = bsearch(&key, k, ntri, sizeof *k, study_tri_key_cmp);
    if (!f) {
      snprintf(err, errcap, "no triangle lies inside edge p_%u p_%u: the triangles do "
               "not tile the %u-gon", (unsigned)a, (unsigned)c, (unsigned)nv);
      return -1;
    }
    out->tc += c - a - 1;
    if (!(a == 0 && c == nv - 1)) {
      uint64_t t[3];
      study_diag_terms(a, c, nv, (nv - 2) / 2, t);
      out->cross += t[1];
      out->len_sum += t[2];
      if (degree) degree[a]++, degree[c]++;
    }
    if (f->b - a >= 2) stk[top++] = a, stk[top++] = f->b;
    if (c - f->b >= 2) stk[top++] = f->b, stk[top++] = c;
  }
  return 0;
}

/* Cost: O(N log N) for the sort and the lookups, O(N) space. */
int study_tri_measure(const uint32_t *tri, size_t ntri, uint32_t nv, study_tri_stats *out,
                      uint32_t *degree, char *err, size_t errcap) {
  if (nv < 3 || ntri != (size_t)nv - 2) {
    snprintf(err, errcap, "a triangulation of the %u-gon has %u triangles, not %zu",
             (unsigned)nv, nv < 2 ? 0u : (unsigned)nv - 2, ntri);
    return -1;
  }
  study_tri_key *k = malloc(ntri * sizeof *k);
  uint32_t *stk = malloc(2 * (size_t)nv * sizeof *stk);
  int rc = -1;
  if (!k || !stk) {
    snprintf(err, errcap, "out of memory");
  } else if (study_tri_keys(tri, ntri, nv, k, err, errcap) == 0) {
    *out = (study_tri_stats){0, 0, 0};
    if (degree) memset(degree, 0, nv * sizeof *degree);
    rc = study_tri_walk(k, ntri, nv, stk, out, degree, err, errcap);
  }
  free(k);
  free(stk);
  return rc;
}
