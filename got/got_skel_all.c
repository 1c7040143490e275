/*
** got_skel_all.c: the trivial skeleton of a point set (got_skel.h): every segment between
** two points whose open segment holds no third point is a candidate edge, and the convex
** hull's edges, and every edge that crosses no other, are CERTAIN: a triangulation is a
** maximal set of non-crossing edges, so it holds every edge nothing crosses.  For tests
** and tiny inputs: Theta(n^3) exact orientation tests for the edges, then O(E^2) crossing
** tests at worst (each stops at the first crossing found: few in practice); no rule is
** consulted, so it is sound for every rule.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "got_skel.h"

/* Beyond this n the cubic scan takes seconds: use got_skel_build. */
#define GOT_SKEL_ALL_MAX 600

/* Is c strictly inside the segment ab, given that a, b, c are collinear?  Coordinates
** compare exactly, so this is exact. */
static int got_skel_between(geom_point a, geom_point b, geom_point c) {
  if (a.x != b.x) return (a.x < c.x && c.x < b.x) || (b.x < c.x && c.x < a.x);
  return (a.y < c.y && c.y < b.y) || (b.y < c.y && c.y < a.y);
}

/* The state of segment ab: -1 not an edge (a point on its open segment), else
** GOT_EDGE_CERTAIN when every point is on one closed side (a hull edge), else POSSIBLE. */
static int got_skel_classify(const geom_point *p, size_t n, size_t a, size_t b) {
  int left = 0, right = 0;
  for (size_t c = 0; c < n; c++) {
    if (c == a || c == b) continue;
    int o = geom_orient(p[a], p[b], p[c]);
    if (o == 0 && got_skel_between(p[a], p[b], p[c])) return -1;
    left |= o > 0;
    right |= o < 0;
  }
  return left && right ? GOT_EDGE_POSSIBLE : GOT_EDGE_CERTAIN;
}

/* Do the edges e and f cross?  Two edges with no point inside either cannot overlap or
** touch except at a shared end, so crossing is proper crossing: four exact orientations. */
static int got_skel_cross(const geom_point *p, const uint32_t *e, const uint32_t *f) {
  if (e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1]) return 0;
  return geom_segments_cross(p[e[0]], p[e[1]], p[f[0]], p[f[1]]);
}

/* Every POSSIBLE edge that crosses no edge becomes CERTAIN. */
static void got_skel_uncrossed(const geom_point *p, got_skel *s) {
  for (size_t e = 0; e < s->nedges; e++) {
    if (s->state[e] == GOT_EDGE_CERTAIN) continue;
    size_t f = 0;
    while (f < s->nedges && !got_skel_cross(p, s->edge + 2 * e, s->edge + 2 * f)) f++;
    if (f == s->nedges) s->state[e] = GOT_EDGE_CERTAIN;
  }
}

int got_skel_all(const geom_point *p, size_t n, got_skel *out, char *err, size_t errlen) {
  memset(out, 0, sizeof *out);
  out->n = n;
  if (n > GOT_SKEL_ALL_MAX) {
    snprintf(err, errlen, "the skeleton of all edges takes Theta(n^3) time: n = %zu is more "
             "than its limit %d (use the LMT-skeleton)", n, GOT_SKEL_ALL_MAX);
    return -1;
  }
  double t0 = omp_get_wtime();
  size_t cap = n * (n - 1) / 2 + 1;
  out->edge = malloc(2 * cap * sizeof *out->edge);
  out->state = malloc(cap);
  if (out->edge == NULL || out->state == NULL) {
    got_skel_free(out);
    snprintf(err, errlen, "out of memory for the %zu segments of %zu points", cap - 1, n);
    return -1;
  }
  for (size_t a = 0; a < n; a++)
    for (size_t b = a + 1; b < n; b++) {
      int s = got_skel_classify(p, n, a, b);
      if (s < 0) continue;
      out->edge[2 * out->nedges] = (uint32_t)a;
      out->edge[2 * out->nedges + 1] = (uint32_t)b;
      out->state[out->nedges++] = (unsigned char)s;
    }
  out->candidates = out->nedges;
  out->seconds_candidates = omp_get_wtime() - t0;
  got_skel_uncrossed(p, out);
  out->seconds_lmt = omp_get_wtime() - t0 - out->seconds_candidates;
  return 0;
}
