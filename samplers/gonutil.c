/*
** gonutil.c: what the random convex n-gon samplers of chapter 6 (bounce,
** triangulation, dual, prior art) share: their output contract (strictly
** convex, checked exactly, anticlockwise from the lexicographically
** smallest vertex) and uniform integers.
*/
#include "sampler.h"

static void canon_reverse(geom_point *p, size_t lo, size_t hi) {   /* [lo, hi) */
  while (lo + 1 < hi) {
    geom_point t = p[lo];
    p[lo++] = p[--hi];
    p[hi] = t;
  }
}

/* geom_polygon_check (exact orientation tests, the coordinate contract),
** then a rotation in place by three reversals: O(n) time, O(1) space. */
int sampler_gon_canon(geom_point *p, size_t n, size_t *first) {
  size_t bad, s = 0;
  int rev = 0;
  if (geom_polygon_check(p, n, &bad, &rev) != GEOM_OK || rev) return -1;
  for (size_t k = 1; k < n; k++)
    if (geom_lexless(p[k], p[s])) s = k;
  canon_reverse(p, 0, s);
  canon_reverse(p, s, n);
  canon_reverse(p, 0, n);
  if (first != NULL) *first = s;
  return 0;
}

/* Rejection of the top 2^64 mod k values keeps the result exactly uniform
** (fewer than half the draws are rejected, so O(1) expected). */
uint64_t sampler_below(sampler_rng *g, uint64_t k) {
  uint64_t limit = UINT64_MAX - UINT64_MAX % k, x;
  do x = sampler_next(g); while (x >= limit);
  return x % k;
}
