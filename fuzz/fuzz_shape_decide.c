/*
** fuzz_shape_decide.c: a differential oracle for the empty-shape rules'
** fast decisions (the square's bounding boxes, the hexagon's slabs, the
** quick path with its octant tables) against the purely exact decision.
** The first byte picks the shape and how the eight coordinates are read:
** as small integers (grids: sites in special position everywhere) or as raw
** doubles; a strictly convex quadrilateral (put anticlockwise) inside the
** coordinate contract must get the same answer both ways, and again when
** asked with the hint its first hinted decision kept (the hexagon's known
** contact triple, the quick path's, a corner's).
*/
#include <math.h>
#include "fuzz_support.h"
#include "geom.h"
#include "shape.h"
#include "shape_internal.h"

static const char *const fuzz_shapes[] = {"square", "hexagon", "diamond", "triangle", "octagon",
                                          "poly:2 0;3 1;2 2;0 2;-1 1;0 0", "ngon:7",
                                          "poly:1 1;1.5 1;1.5 1.5;1 1.5"};
#define FUZZ_NSHAPES (sizeof fuzz_shapes / sizeof fuzz_shapes[0])

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static shape *shapes[FUZZ_NSHAPES];
  if (shapes[0] == NULL) {
    char err[256];
    for (size_t i = 0; i < FUZZ_NSHAPES; i++)
      if (shape_parse(fuzz_shapes[i], &shapes[i], err, sizeof err) != 0) abort();
  }
  if (size < 1) return 0;
  const shape *k = shapes[data[0] % FUZZ_NSHAPES];
  geom_point q[4];
  if (data[0] & 0x80) {   /* small integers, scaled by a power of two */
    if (size < 10) return 0;
    double scale = ldexp(1, (int)(data[1] % 64) - 32);
    for (int i = 0; i < 4; i++)
      q[i] = (geom_point){(int8_t)data[2 + 2 * i] * scale, (int8_t)data[3 + 2 * i] * scale};
  } else {
    if (size < 1 + sizeof q) return 0;
    memcpy(q, data + 1, sizeof q);
  }
  size_t bad;
  int reversed;
  if (geom_polygon_check(q, 4, &bad, &reversed) != GEOM_OK) return 0;   /* now anticlockwise */
  shape_choice fast = shape_decide(k, q[0], q[1], q[2], q[3], NULL);
  shape_set_exact_only(1);
  shape_choice exact = shape_decide(k, q[0], q[1], q[2], q[3], NULL);
  shape_set_exact_only(0);
  shape_hint h = {0};
  shape_choice first = shape_decide_hinted(k, q[0], q[1], q[2], q[3], &h);
  shape_choice again = shape_decide_hinted(k, q[0], q[1], q[2], q[3], &h);
  if (fast != exact || first != exact || again != exact) {
    fprintf(stderr, "%s: fast %d, hinted %d then %d, exact %d on (%a,%a) (%a,%a) (%a,%a) (%a,%a)\n",
            fuzz_shapes[data[0] % FUZZ_NSHAPES], fast, first, again, exact, q[0].x, q[0].y,
            q[1].x, q[1].y, q[2].x, q[2].y, q[3].x, q[3].y);
    abort();
  }
  return 0;
}
