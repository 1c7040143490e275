/*
** linf_delaunay.c: the l_inf Delaunay simplices of a small point set in
** R^d, by brute force (the oracle) and by the selection algorithm of the
** thesis's section 4.2.2 (a set of candidates per facet, since the
** circumcubes through a facet need not nest).
*/
#include <stdlib.h>
#include <string.h>
#include "linf_internal.h"

void linf_simplices_init(linf_simplices *s, int d) {
  s->d = d;
  s->n = s->cap = 0;
  s->v = NULL;
}

void linf_simplices_free(linf_simplices *s) {
  free(s->v);
  s->v = NULL;
  s->n = s->cap = 0;
}

int linf_simplices_push(linf_simplices *s, const unsigned char *v) {
  size_t w = (size_t)s->d + 1;
  if (s->n == s->cap) {
    size_t cap = s->cap ? 2 * s->cap : 16;
    unsigned char *nv = realloc(s->v, cap * w);
    if (nv == NULL) return -1;
    s->v = nv;
    s->cap = cap;
  }
  memcpy(s->v + s->n++ * w, v, w);
  return 0;
}

uint64_t linf_row_key(const unsigned char *v, int w) {
  uint64_t k = 0;
  for (int j = 0; j < w; j++) k = k << 6 | v[j];
  return k;
}

static int linf_key_cmp(const void *a, const void *b) {
  uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
  return (x > y) - (x < y);
}

/* Sorted through the keys. */
int linf_simplices_sort(linf_simplices *s) {
  int w = s->d + 1;
  if (s->n < 2) return 0;
  uint64_t *key = malloc(s->n * sizeof *key);
  if (key == NULL) return -1;
  for (size_t i = 0; i < s->n; i++) key[i] = linf_row_key(s->v + i * (size_t)w, w);
  qsort(key, s->n, sizeof *key, linf_key_cmp);
  for (size_t i = 0; i < s->n; i++)
    for (int j = 0; j < w; j++)
      s->v[i * (size_t)w + (size_t)j] = (unsigned char)(key[i] >> (6 * (w - 1 - j)) & 63);
  free(key);
  return 0;
}

int linf_simplices_has(const linf_simplices *s, const unsigned char *v) {
  size_t w = (size_t)s->d + 1, lo = 0, hi = s->n;
  while (lo < hi) {
    size_t mid = lo + (hi - lo) / 2;
    int c = memcmp(s->v + mid * w, v, w);
    if (c == 0) return 1;
    if (c < 0) lo = mid + 1;
    else hi = mid;
  }
  return 0;
}

void linf_gather(const double *pts, int d, const unsigned char *idx, int m,
                        double *rows) {
  for (int j = 0; j < m; j++) memcpy(rows + j * d, pts + (size_t)idx[j] * d, d * sizeof *rows);
}

int linf_next_subset(unsigned char *c, int m, size_t n) {
  int i = m - 1;
  while (i >= 0 && c[i] == n - (size_t)(m - i)) i--;
  if (i < 0) return 0;
  c[i]++;
  for (int j = i + 1; j < m; j++) c[j] = (unsigned char)(c[j - 1] + 1);
  return 1;
}

/* Has one of the cubes no point of the set strictly inside? */
static int linf_some_empty(const double *pts, size_t n, int d, const linf_cube *cubes,
                           int nc) {
  for (int b = 0; b < nc; b++) {
    size_t q = 0;
    while (q < n && linf_cube_side(&cubes[b], pts + q * d) != -1) q++;
    if (q == n) return 1;
  }
  return 0;
}

/* Cost: C(n, d+1) subsets, each an orientation, its circumcubes (at most
** 2^{d-1}) and n tests per cube: O(n^{d+2} 2^d d). */
int linf_delaunay_brute(const double *pts, size_t n, int d, linf_simplices *out,
                        uint64_t *degenerate) {
  unsigned char c[LINF_DIM_MAX + 1];
  double rows[(LINF_DIM_MAX + 1) * LINF_DIM_MAX] = {0};
  linf_cube cubes[LINF_CUBES_MAX];
  linf_simplices_init(out, d);
  if (degenerate) *degenerate = 0;
  if (d < LINF_DIM_MIN || d > LINF_DIM_MAX || n > LINF_POINTS_MAX) return -1;
  if (n < (size_t)d + 1) return 0;
  for (int j = 0; j <= d; j++) c[j] = (unsigned char)j;
  do {
    linf_gather(pts, d, c, d + 1, rows);
    if (linf_orient(rows, d) == 0) continue;
    int nc = linf_circumcubes(rows, d, cubes);
    if (nc == LINF_INFINITE) {
      if (degenerate) (*degenerate)++;
      continue;
    }
    if (linf_some_empty(pts, n, d, cubes, nc) && linf_simplices_push(out, c) != 0) return -1;
  } while (linf_next_subset(c, d + 1, n));
  return linf_simplices_sort(out);
}
