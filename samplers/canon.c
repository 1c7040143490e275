/*
** canon.c: the output contract of the random convex n-gon samplers of
** chapter 6 (bounce, triangulation, dual, prior art): strictly convex,
** checked exactly, anticlockwise from the lexicographically smallest vertex.
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
