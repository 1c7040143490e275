/*
** fuzz_polygon_check.c: the polygon validator on raw doubles (any bit
** pattern: NaN, infinities, subnormals, huge and tiny values), checked
** against its contract with the exact orientation predicate.
*/
#include <math.h>
#include "fuzz_support.h"
#include "geom.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  size_t n = size / sizeof(geom_point);
  if (n > 64) n = 64;
  geom_point p[64], q[64];
  if (n) memcpy(p, data, n * sizeof *p);
  memcpy(q, p, n * sizeof *p);
  size_t bad = 0;
  int rev = 0;
  geom_polyerr e = geom_polygon_check(q, n, &bad, &rev);
  if (e != GEOM_OK) {
    if (n >= 3 && bad >= n) abort();
    return 0;
  }
  /* Accepted: finite, in scale, anticlockwise, every turn strictly left. */
  for (size_t i = 0; i < n; i++) {
    if (!geom_point_finite(q[i])) abort();
    if (geom_orient_exact(q[i], q[(i + 1) % n], q[(i + 2) % n]) != 1) abort();
    if (geom_orient(q[i], q[(i + 1) % n], q[(i + 2) % n]) != 1) abort();
  }
  /* The same polygon given clockwise is accepted and reversed. */
  geom_point r[64];
  r[0] = q[0];
  for (size_t i = 1; i < n; i++) r[i] = q[n - i];
  if (geom_polygon_check(r, n, &bad, &rev) != GEOM_OK || !rev) abort();
  for (size_t i = 0; i < n; i++)
    if (r[i].x != q[i].x || r[i].y != q[i].y) abort();
  return 0;
}
