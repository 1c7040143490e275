/*
** shape_sweep.c: what the sweepline algorithm (lot/sweep_polygon.c) asks of
** a polygon beyond the empty-shape decision: the circumscribing shape of a
** triangle, a homothet with its contact edges or a corner's rounding shape.
*/
#include "shape.h"
#include "shape_internal.h"

int shape_circumscribe(const shape *k, geom_point a, geom_point b, geom_point c, int contact[3],
                       int *corner) {
  int sup[3] = {shape_support(k, a, b), shape_support(k, b, c), shape_support(k, c, a)};
  /* All three cannot coincide (shape.c, shape_polygon_decide). */
  if (sup[0] == sup[1] || sup[0] == sup[2]) {
    *corner = sup[0];
    return 0;
  }
  if (sup[1] == sup[2]) {
    *corner = sup[1];
    return 0;
  }
  const geom_point p[3] = {a, b, c};
  return shape_contacts(k, sup, p, contact) != 0 ? 1 : -1;
}
