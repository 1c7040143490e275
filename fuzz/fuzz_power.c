/*
** fuzz_power.c: a differential oracle for the power test.  Eight doubles
** make four points and four more their weights; whenever all are finite,
** geom_power (the filter) must give the sign of geom_power_exact (GMP),
** and equal weights must give geom_incircle's answer.  The filter's bound
** is written for inputs anywhere in the doubles, tiny or huge; this is
** where its argument meets raw bit patterns.
*/
#include <math.h>
#include "fuzz_support.h"
#include "geom.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  double v[12];
  if (size < sizeof v) return 0;
  memcpy(v, data, sizeof v);
  for (int i = 0; i < 12; i++)
    if (!isfinite(v[i])) return 0;
  const geom_point a = {v[0], v[1]}, b = {v[2], v[3]}, c = {v[4], v[5]}, d = {v[6], v[7]};
  const double w[4] = {v[8], v[9], v[10], v[11]};
  if (geom_power(a, b, c, d, w) != geom_power_exact(a, b, c, d, w)) abort();
  const double eq[4] = {v[8], v[8], v[8], v[8]};
  if (geom_power(a, b, c, d, eq) != geom_incircle(a, b, c, d)) abort();
  return 0;
}
