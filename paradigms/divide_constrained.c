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
** of the strips' Delaunay triangulation, no region boundary ever stops a
** merge and the constrained Delaunay triangulation is the Delaunay one
** (a segment that is an edge crosses no edge, and every triangle's circle
** is empty of all sites, so of the visible ones), which is then lot's
** exactly (the same tie-break).  Any other segment is refused, naming it:
** the regions and virtual sites that would carry it across strip borders
** are not built (docs/paradigms.md says what they need).
**
** Cost: dc-vertical's O(n log n), then the e = 3n - 3 - h edges sorted,
** O(n log n), and a binary search per segment, O(s log n).
*/
#include <stdio.h>
#include <stdlib.h>
#include "paradigm_internal.h"

/* Is every segment an edge of out's triangles?  0, or -1 naming the first
** that is not (or joins a point to itself), or out of memory. */
static int dcc_segments_are_edges(const paradigm_input *in, const paradigm_output *out,
                                  char *err, size_t errlen) {
  size_t m = 3 * out->ntri;
  uint64_t *key = malloc((m ? m : 1) * sizeof *key);
  if (key == NULL) {
    snprintf(err, errlen, "out of memory for the edges of %zu triangles", out->ntri);
    return -1;
  }
  for (size_t t = 0; t < out->ntri; t++)
    for (int k = 0; k < 3; k++)
      key[3 * t + k] = paradigm_edge_key(out->tri[3 * t + k], out->tri[3 * t + (k + 1) % 3]);
  qsort(key, m, sizeof *key, paradigm_key_cmp);
  int rc = 0;
  for (size_t s = 0; s < in->nsegments && rc == 0; s++) {
    uint32_t a = in->segments[2 * s], b = in->segments[2 * s + 1];
    if (a == b)
      snprintf(err, errlen, "segment %zu joins a point to itself", s), rc = -1;
    else if (!bsearch(&(uint64_t){paradigm_edge_key(a, b)}, key, m, sizeof *key,
                      paradigm_key_cmp))
      snprintf(err, errlen, "dc-constrained: segment %zu is no edge of the strips' Delaunay "
               "triangulation, and the virtual sites that carry a segment across strip "
               "borders (Chew, 2.6.2) are not built", s), rc = -1;
  }
  free(key);
  return rc;
}

int paradigm_dc_constrained(const paradigm_input *in, paradigm_output *out, char *err,
                            size_t errlen) {
  if (paradigm_divide(in, 0, &out->ops, out, err, errlen) != 0) return -1;
  if (in->problem != PARADIGM_CONSTRAINED) return 0;
  return dcc_segments_are_edges(in, out, err, errlen);
}
