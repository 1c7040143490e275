/*
** divide_constrained.c: the row dc-constrained, Chew's divide and conquer
** for the constrained Delaunay triangulation (section 2.6.2), as far as it
** is built.
**
** Chew cuts the sites into vertical strips (the cuts of dc-vertical, whose
** merges are Guibas and Stolfi's).  A segment that crosses a strip's border
** splits the strip into regions and ends, inside the strip, at a virtual
** site on the border, infinitely far for the in-circle tests; a merge
** matches the two strips' virtual sites on their common border, drops
** them, and merges each pair of facing regions by the same zipper.  What
** is built is the case with no virtual site: when every segment is an edge
** of the strips' Delaunay triangulation, or a chain of its edges through
** the sites that lie on the segment (lot splits a segment there, so its
** pieces are the constraints), no region boundary ever stops a merge and
** the constrained Delaunay triangulation is the Delaunay one (a piece that
** is an edge crosses no edge, and every triangle's circle is empty of all
** sites, so of the visible ones), which is then lot's exactly (the same
** tie-break).  Any other segment is refused, naming it: the regions and
** virtual sites that would carry it across strip borders are not built
** (docs/paradigms.md says what they need).
**
** Cost: dc-vertical's O(n log n), then each site's neighbours listed by a
** counting sort of the 3t triangle sides, O(n), and each segment followed
** from one end along the edges on it, O(sum of the degrees of its sites):
** O(n + s d) for s segments through sites of degree at most d.
*/
#include <stdio.h>
#include <stdlib.h>
#include "paradigm_internal.h"

/* Each site's neighbours, nb[at[v] .. at[v + 1]): every side of every
** triangle listed at both ends (an inner edge twice, a hull side once at
** each), by a counting sort.  0, or -1 out of memory. */
static int dcc_neighbours(const paradigm_output *out, size_t n, size_t **at, uint32_t **nb) {
  size_t m = 3 * out->ntri;
  *at = calloc(n + 1, sizeof **at);
  *nb = malloc((m ? 2 * m : 1) * sizeof **nb);
  if (*at == NULL || *nb == NULL) return -1;
  const uint32_t *t = out->tri;
  for (size_t k = 0; k < m; k++) (*at)[t[k]] += 2;   /* k's side to its successor and from */
  for (size_t v = 1; v <= n; v++) (*at)[v] += (*at)[v - 1];   /* its predecessor */
  for (size_t k = 0; k < m; k++) {   /* at[v] ends at v's start */
    uint32_t u = t[k], w = t[k - k % 3 + (k + 1) % 3];
    (*nb)[--(*at)[u]] = w, (*nb)[--(*at)[w]] = u;
  }
  return 0;
}

/* Is w on the open segment (u, b) of the line through a and b?  The
** lexicographic order is monotone along a line (up: u before b), so
** "between" is two exact comparisons; on the line, one exact orientation. */
static int dcc_between(const geom_point *p, ops_counts *c, uint32_t a, uint32_t b, uint32_t u,
                       uint32_t w, int up) {
  return w != b && geom_lexless(p[u], p[w]) == up && geom_lexless(p[w], p[b]) == up
         && ops_orient(c, p[a], p[b], p[w]) == 0;
}

/* Is segment a-b an edge, or a chain of edges through the sites on it?
** From u = a: done when b is u's neighbour, else on to u's neighbour on
** the open segment (u, b) (a triangulation has at most one), else no. */
static int dcc_chain(const paradigm_input *in, ops_counts *c, const size_t *at,
                     const uint32_t *nb, uint32_t a, uint32_t b) {
  int up = geom_lexless(in->p[a], in->p[b]);
  for (uint32_t u = a;;) {
    size_t j = at[u], end = at[u + 1];
    while (j < end && nb[j] != b) j++;
    if (j < end) return 1;
    for (j = at[u]; j < end && !dcc_between(in->p, c, a, b, u, nb[j], up);) j++;
    if (j == end) return 0;
    u = nb[j];
  }
}

/* Is every segment an edge or a chain of edges of out's triangles?  0, or
** -1 naming the first that is not (or joins a point to itself), or out of
** memory. */
static int dcc_segments_are_edges(const paradigm_input *in, paradigm_output *out, char *err,
                                  size_t errlen) {
  size_t *at;
  uint32_t *nb;
  int64_t bytes = (int64_t)((in->n + 1) * sizeof *at + 6 * out->ntri * sizeof *nb);
  ops_memory(&out->ops, bytes);
  int rc = dcc_neighbours(out, in->n, &at, &nb);
  if (rc != 0)
    snprintf(err, errlen, "out of memory for the edges of %zu triangles", out->ntri);
  for (size_t s = 0; s < in->nsegments && rc == 0; s++) {
    uint32_t a = in->segments[2 * s], b = in->segments[2 * s + 1];
    if (a == b)
      snprintf(err, errlen, "segment %zu joins a point to itself", s), rc = -1;
    else if (!dcc_chain(in, &out->ops, at, nb, a, b))
      snprintf(err, errlen, "dc-constrained: segment %zu is no edge (nor a chain of edges "
               "through the sites on it) of the strips' Delaunay triangulation, and the "
               "virtual sites that carry a segment across strip borders (Chew, 2.6.2) are "
               "not built", s), rc = -1;
  }
  free(at), free(nb);
  ops_memory(&out->ops, -bytes);
  return rc;
}

int paradigm_dc_constrained(const paradigm_input *in, paradigm_output *out, char *err,
                            size_t errlen) {
  if (paradigm_divide(in, 0, &out->ops, out, err, errlen) != 0) return -1;
  if (in->problem != PARADIGM_CONSTRAINED) return 0;
  return dcc_segments_are_edges(in, out, err, errlen);
}
