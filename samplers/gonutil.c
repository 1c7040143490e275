/*
** gonutil.c: what the random convex n-gon samplers of chapter 6 share:
** the rotation to the lexicographically smallest vertex, the output
** contract (strictly convex, checked exactly, anticlockwise from that
** vertex) and exactly uniform integers.
*/
#include "gon_internal.h"

static void sampler_reverse(geom_point *v, size_t lo, size_t hi) {   /* [lo, hi) */
  for (; lo + 1 < hi; lo++, hi--) {
    geom_point t = v[lo];
    v[lo] = v[hi - 1];
    v[hi - 1] = t;
  }
}

/* Three reversals: O(n) time, O(1) space; the labelling v0..v{n-1} then
** does not depend on the order the polygon was built in. */
size_t sampler_lexfirst(geom_point *v, size_t n) {
  size_t s = 0;
  for (size_t k = 1; k < n; k++)
    if (geom_lexless(v[k], v[s])) s = k;
  if (s == 0) return 0;
  sampler_reverse(v, 0, s);
  sampler_reverse(v, s, n);
  sampler_reverse(v, 0, n);
  return s;
}

/* geom_polygon_check (exact orientation tests, the coordinate contract),
** then sampler_lexfirst. */
int sampler_gon_canon(geom_point *p, size_t n, size_t *first) {
  size_t bad, s;
  int rev = 0;
  if (geom_polygon_check(p, n, &bad, &rev) != GEOM_OK || rev) return -1;
  s = sampler_lexfirst(p, n);
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
