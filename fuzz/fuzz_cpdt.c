/*
** fuzz_cpdt.c: the convex-polygon Delaunay algorithms (cpdt/) on polygons
** near degeneracy: byte 0 picks n (3 .. 64) and a radius, the next bytes
** nudge the vertices of a regular n-gon rounded to integers (so many are
** exactly or nearly cocircular).  cpdt_check must name a vertex inside the
** polygon when it refuses; when it accepts, every algorithm must give the
** same triangles, each row i < j < k with j its middle vertex.
*/
#include <math.h>
#include "fuzz_support.h"
#include "cpdt.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size < 1) return 0;
  size_t n = 3 + data[0] % 62;
  double radius = (data[0] & 0x80) ? 1105 : 65;
  geom_point p[64];
  for (size_t i = 0; i < n; i++) {
    double t = 2 * M_PI * (double)i / (double)n;
    int8_t dx = 1 + 2 * i < size ? (int8_t)data[1 + 2 * i] : 0;
    int8_t dy = 2 + 2 * i < size ? (int8_t)data[2 + 2 * i] : 0;
    p[i] = (geom_point){round(radius * cos(t)) + dx / 16.0, round(radius * sin(t)) + dy / 16.0};
  }
  size_t bad = 0;
  int e = cpdt_check(p, n, &bad);
  if (e != 0) {
    if (bad >= n || cpdt_check_str(e) == NULL) abort();
    return 0;
  }
  uint32_t want[3 * 64], got[3 * 64];
  if (cpdt_triangulate(p, n, 0, 1, want, NULL) != 0) abort();
  for (size_t t = 0; t + 2 < n; t++)
    if (want[3 * t] >= want[3 * t + 1] || want[3 * t + 1] != t + 1 ||
        want[3 * t + 2] <= want[3 * t + 1] || want[3 * t + 2] >= n)
      abort();
  for (int a = 1; a < CPDT_ALGORITHM_COUNT; a++) {
    if (cpdt_triangulate(p, n, a, data[0], got, NULL) != 0) abort();
    if (memcmp(got, want, 3 * (n - 2) * sizeof *got) != 0) abort();
  }
  return 0;
}
