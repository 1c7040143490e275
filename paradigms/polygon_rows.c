/*
** polygon_rows.c: the simple polygon problem (PARADIGM_POLYGON) for the
** constrained rows: the polygon checked, its sides as segments, and the
** triangles outside it dropped for a row that keeps the whole hull.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "paradigm_internal.h"
#include "lot.h"

/* Check that in->p is a simple polygon (geom_simple_polygon_check on a
** copy, O(n log n) plus the crossing tests) and give its n sides as
** segments (i, i + 1 mod n), *ccw its orientation.  0, or -1 (err). */
int paradigm_polygon_sides(const paradigm_input *in, uint32_t **seg, int *ccw, char *err,
                           size_t errlen) {
  geom_point *q = malloc(in->n * sizeof *q);
  *seg = malloc(2 * in->n * sizeof **seg);
  if (q == NULL || *seg == NULL) {
    free(q), free(*seg), *seg = NULL;
    snprintf(err, errlen, "out of memory for a polygon of %zu vertices", in->n);
    return -1;
  }
  memcpy(q, in->p, in->n * sizeof *q);
  size_t bad = 0, bad2 = 0;
  int reversed = 0;
  geom_polyerr e = geom_simple_polygon_check(q, in->n, &bad, &bad2, &reversed);
  free(q);
  if (e != GEOM_OK) {
    if (e == GEOM_CROSSING)
      snprintf(err, errlen, "simple polygon: sides %zu and %zu: %s", bad + 1, bad2 + 1,
               geom_polyerr_str(e));
    else
      snprintf(err, errlen, "simple polygon: vertex %zu: %s", bad + 1, geom_polyerr_str(e));
    free(*seg), *seg = NULL;
    return -1;
  }
  for (size_t i = 0; i < in->n; i++)
    (*seg)[2 * i] = (uint32_t)i, (*seg)[2 * i + 1] = (uint32_t)((i + 1) % in->n);
  *ccw = !reversed;
  return 0;
}

/* Is u -> v a side, and which way: +1 along the boundary order, -1
** against it, 0 not a side (a side joins consecutive vertices: the check
** refused sides through other vertices, so no side is split). */
static int paradigm_polygon_side(uint32_t u, uint32_t v, size_t n) {
  if ((size_t)v == ((size_t)u + 1) % n) return 1;
  if ((size_t)u == ((size_t)v + 1) % n) return -1;
  return 0;
}

/* Each triangle in (1) or out (0): a triangle on a side is inside when it
** lies to the left of the side walked anticlockwise; the others take the
** mark of a neighbour across a diagonal (every region the sides bound has
** a side on its boundary).  O(t) with a queue. */
static void paradigm_polygon_mark(const uint32_t *tri, size_t ntri, size_t n, int ccw,
                                  const int32_t *nb, signed char *in, size_t *queue) {
  size_t head = 0, tail = 0;
  for (size_t t = 0; t < ntri; t++) {
    in[t] = -1;
    for (int k = 0; k < 3 && in[t] < 0; k++) {
      int s = paradigm_polygon_side(tri[3 * t + k], tri[3 * t + (k + 1) % 3], n);
      if (s != 0) in[t] = (signed char)((s > 0) == (ccw != 0)), queue[tail++] = t;
    }
  }
  while (head < tail) {
    size_t t = queue[head++];
    for (int k = 0; k < 3; k++) {
      int32_t u = nb[3 * t + k];
      uint32_t a = tri[3 * t + (k + 1) % 3], b = tri[3 * t + (k + 2) % 3];
      if (u < 0 || in[u] >= 0 || paradigm_polygon_side(a, b, n) != 0) continue;
      in[u] = in[t], queue[tail++] = (size_t)u;
    }
  }
}

/* Keep only out's triangles inside the polygon (in place).  O(t). */
int paradigm_polygon_inside(paradigm_output *out, size_t n, int ccw, char *err,
                            size_t errlen) {
  size_t t = out->ntri, m = 0;
  int32_t *nb = malloc((t ? t : 1) * 3 * sizeof *nb);
  signed char *in = malloc(t ? t : 1);
  size_t *queue = malloc((t ? t : 1) * sizeof *queue);
  int rc = nb && in && queue ? lot_neighbors(out->tri, t, n, nb) : -1;
  if (rc == 0) {
    paradigm_polygon_mark(out->tri, t, n, ccw, nb, in, queue);
    for (size_t k = 0; k < t; k++)
      if (in[k] == 1) memmove(out->tri + 3 * m++, out->tri + 3 * k, 3 * sizeof *out->tri);
    out->ntri = m;
  } else {
    snprintf(err, errlen, "out of memory for %zu triangles", t);
  }
  free(nb), free(in), free(queue);
  return rc == 0 ? 0 : -1;
}

/* select-constrained on a polygon: its CDT of the hull with the sides as
** segments, then the outside dropped; any other problem as it is. */
int paradigm_select_polygon(const paradigm_input *in, paradigm_output *out, char *err,
                            size_t errlen) {
  if (in->problem != PARADIGM_POLYGON) return paradigm_select_constrained(in, out, err, errlen);
  paradigm_input sub = *in;
  uint32_t *seg;
  int ccw;
  if (paradigm_polygon_sides(in, &seg, &ccw, err, errlen) != 0) return -1;
  sub.problem = PARADIGM_CONSTRAINED, sub.segments = seg, sub.nsegments = in->n;
  int rc = paradigm_select_constrained(&sub, out, err, errlen);
  if (rc == 0) rc = paradigm_polygon_inside(out, in->n, ccw, err, errlen);
  free(seg);
  return rc;
}
