/*
** splitmix.h: splitmix64 (Steele, Lea and Flood), the one small seeded
** generator of fliplab, and the one way a point uniform in the unit disc is
** drawn.  Used to seed the samplers' streams (pentagon/), to draw the sample
** triangles a formula's sign is inferred from (badness/), and by the tests.
** Header-only: both are a handful of integer operations on hot paths.
*/
#ifndef FLIPLAB_SPLITMIX_H
#define FLIPLAB_SPLITMIX_H

#include <stdint.h>
#include "predicates.h"

/* Advance the counter *x by the golden-ratio increment and return its
** mixed value.  The output function is a bijection of the counter. */
static inline uint64_t geom_splitmix64(uint64_t *x) {
  uint64_t z = (*x += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/* The top 53 bits of a 64-bit draw as a double uniform in [0, 1): every
** value is a multiple of 2^-53, exactly representable. */
static inline double geom_unit53(uint64_t bits) {
  return (double)(bits >> 11) * 0x1.0p-53;
}

/* Rejection sampling of the open unit disc from the square [-1, 1)^2: the
** point 2u-1, 2v-1 of two uniforms u, v in [0, 1) (exact: a power-of-two
** scaling and a subtraction of numbers within a factor of two) is accepted
** when strictly inside the circle; otherwise draw both again. *p is set
** either way.  Acceptance probability pi/4. */
static inline int geom_disc_accept(double u, double v, geom_point *p) {
  double x = 2 * u - 1, y = 2 * v - 1;
  *p = (geom_point){x, y};
  return x * x + y * y < 1;
}

#endif
