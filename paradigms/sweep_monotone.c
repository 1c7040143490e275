/*
** sweep_monotone.c: the monotone-polygon sweep of section 2.5.4 (row
** sweep-monotone), which is the constrained sweep of 2.5.2
** (sweep_constrained.c) on a polygon monotone in x, and the checks of the
** polygon kinds the sweeps serve.
**
** On an x-monotone polygon every vertex but the two ends has one incoming
** and one outgoing side (but at the ends of a vertical side, which the
** lexicographic order turns), so the constraint list holds the polygon's
** two sides that cross the sweepline and the interior is one piece: its
** boundary is the polygon's part already swept, a list, and each site
** event joins the new vertex to it.  The thesis goes further: it
** takes every site event first, so that the boundary is the whole polygon
** from the start, and then cuts the convex corners in the order of their
** circles' rightmost points.  That order is not the Delaunay one (cpdt/'s
** corners algorithm measured 97 non-Delaunay triangulations in 1,501
** random convex polygons of 4 to 8 vertices), and on a polygon that is not
** convex a corner cut out of order can hold a reflex vertex, which no flip
** repairs.  So the site events stay interleaved with the circle events, and
** a new vertex is joined where the breakpoint search of its piece finds
** it: to its neighbour along the polygon when that neighbour's arc reaches
** its height, else to the arc found (the sites between then close a
** pocket, which sweep_constrained.c counts).
**
** Cost: O(n log n) expected, as the constrained sweep's, with one piece
** inside the polygon; the check of the polygon is O(n).
*/
#include <stdio.h>
#include "paradigm_internal.h"
#include "cpdt.h"

/* The sign of side i's run in x (0: vertical). */
static int paradigm_side_dx(const geom_point *p, size_t n, size_t i) {
  double d = p[(i + 1) % n].x - p[i].x;
  return (d > 0) - (d < 0);
}

/* x-monotone: every vertical line meets the polygon in one interval, so
** walking round it the sides' runs in x change sign exactly twice
** (vertical sides do not count).  0, or -1 with *bad the vertex where a
** third change starts.  O(n). */
static int paradigm_monotone_check(const geom_point *p, size_t n, size_t *bad) {
  size_t s0 = 0;
  while (s0 < n && paradigm_side_dx(p, n, s0) == 0) s0++;
  int cur = s0 < n ? paradigm_side_dx(p, n, s0) : 0, changes = 0;
  for (size_t k = 1; k <= n && s0 < n; k++) {
    size_t i = (s0 + k) % n;
    int d = paradigm_side_dx(p, n, i);
    if (d == 0 || d == cur) continue;
    cur = d;
    if (++changes > 2) {
      *bad = i;
      return -1;
    }
  }
  return 0;
}

int paradigm_polygon_kind(const paradigm_input *in, int monotone, char *err, size_t errlen) {
  size_t bad = 0;
  if (in->problem == PARADIGM_CONVEX) {
    int e = cpdt_check(in->p, in->n, &bad);
    if (e != 0) {
      snprintf(err, errlen, "convex polygon: vertex %zu: %s", bad + 1, cpdt_check_str(e));
      return -1;
    }
  } else if (monotone && paradigm_monotone_check(in->p, in->n, &bad) != 0) {
    snprintf(err, errlen, "polygon is not x-monotone at vertex %zu (it turns back in x a "
             "third time: the row sweep-constrained serves any simple polygon)", bad + 1);
    return -1;
  }
  return 0;
}

int paradigm_sweep_monotone(const paradigm_input *in, paradigm_output *out, char *err,
                            size_t errlen) {
  return paradigm_sweep_run(in, 1, out, NULL, err, errlen);
}
