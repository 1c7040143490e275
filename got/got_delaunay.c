/*
** got_delaunay.c: the exact Delaunay triangulation of a convex polygon, and
** the comparison of two triangulations (for `fliplab got --compare DT`).
**
** For a convex polygon the edge (0, n-1) is a hull edge, so it is Delaunay,
** and the Delaunay triangle on a Delaunay edge (i, j) whose other vertices
** are the chain i+1 .. j-1 has as third vertex the chain vertex seen from
** i j under the largest angle: its circumcircle through p_i p_j contains no
** other chain vertex, and vertices outside the chain lie on the other side
** of i j.  "m sees i j under a larger angle than k" is exactly "m is inside
** the circle through p_i, p_k, p_j" (same side of the chord), which
** geom_incircle decides exactly, so a linear scan finds the maximum in
** O(j - i) and the recursion takes O(n^2).  The scan keeps the first of
** equal candidates (smallest k) and flags a cocircular tie: the Delaunay
** triangulation is unique exactly when no cell has such a tie.
*/
#include <stdlib.h>
#include "got_internal.h"
#include "geom_key_internal.h"

int got_delaunay(const geom_point *p, size_t n, got_triangle *out, int *unique) {
  if (n < 3) return -1;
  typedef struct { size_t i, j; } chain;
  chain *stack = malloc(n * sizeof *stack);
  if (stack == NULL) return -1;
  size_t sp = 0, count = 0;
  int uniq = 1;
  stack[sp++] = (chain){0, n - 1};
  while (sp > 0) {
    chain c = stack[--sp];
    size_t k = c.i + 1;
    for (size_t m = c.i + 2; m < c.j; m++)
      if (geom_incircle(p[c.i], p[k], p[c.j], p[m]) > 0) k = m;
    for (size_t m = c.i + 1; m < c.j && uniq; m++)
      if (m != k && geom_incircle(p[c.i], p[k], p[c.j], p[m]) == 0) uniq = 0;
    out[count++] = (got_triangle){(int)c.i, (int)k, (int)c.j, 0};
    if (c.j - k >= 2) stack[sp++] = (chain){k, c.j};
    if (k - c.i >= 2) stack[sp++] = (chain){c.i, k};
  }
  free(stack);
  if (unique) *unique = uniq;
  return 0;
}

/* Diagonals and triangles as sorted keys, then a merge. */
static uint64_t got_tri_key(const got_triangle *t) {
  int v[3] = {t->i, t->k, t->j};
  for (int x = 0; x < 2; x++)
    for (int y = 0; y < 2 - x; y++)
      if (v[y] > v[y + 1]) { int s = v[y]; v[y] = v[y + 1]; v[y + 1] = s; }
  return ((uint64_t)(unsigned)v[0] << 42) | ((uint64_t)(unsigned)v[1] << 21) | (unsigned)v[2];
}

/* The diagonals of a triangulation: triangle sides that are not hull edges. */
static size_t got_diagonals(const got_triangle *t, size_t n, uint64_t *out) {
  size_t m = 0;
  for (size_t q = 0; q + 2 < n; q++) {
    int v[3] = {t[q].i, t[q].k, t[q].j};
    for (int e = 0; e < 3; e++) {
      int a = v[e], b = v[(e + 1) % 3];
      int d = abs(a - b);
      if (d == 1 || (size_t)d == n - 1) continue;
      out[m++] = geom_edge_key((uint32_t)a, (uint32_t)b);
    }
  }
  qsort(out, m, sizeof *out, geom_u64_cmp);
  size_t u = 0;   /* each diagonal is shared by two triangles */
  for (size_t q = 0; q < m; q++)
    if (u == 0 || out[u - 1] != out[q]) out[u++] = out[q];
  return u;
}

static size_t got_common(const uint64_t *a, size_t na,
                         const uint64_t *b, size_t nb) {
  size_t x = 0, y = 0, c = 0;
  while (x < na && y < nb) {
    if (a[x] < b[y]) x++;
    else if (a[x] > b[y]) y++;
    else { c++; x++; y++; }
  }
  return c;
}

int got_compare(const got_triangle *a, const got_triangle *b, size_t n, got_diff *out) {
  if (n < 3 || n > ((size_t)1 << 20)) return -1;
  uint64_t *da = malloc(4 * n * sizeof *da), *db = malloc(4 * n * sizeof *db);
  if (da == NULL || db == NULL) {
    free(da);
    free(db);
    return -1;
  }
  size_t na = got_diagonals(a, n, da), nb = got_diagonals(b, n, db);
  out->diagonals = n - 3;
  out->diagonals_differ = na - got_common(da, na, db, nb);
  for (size_t q = 0; q + 2 < n; q++) {
    da[q] = got_tri_key(&a[q]);
    db[q] = got_tri_key(&b[q]);
  }
  qsort(da, n - 2, sizeof *da, geom_u64_cmp);
  qsort(db, n - 2, sizeof *db, geom_u64_cmp);
  out->triangles = n - 2;
  out->triangles_common = got_common(da, n - 2, db, n - 2);
  free(da);
  free(db);
  return 0;
}
