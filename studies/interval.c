/*
** interval.c: the 95% Wilson score interval of a proportion, for the
** verdicts of a study and the largest half-width a table 3.4 header gives
** (and the interval at any level, for the l_inf Monte Carlo's 99%).
*/
#include <math.h>
#include "study.h"

#define STUDY_Z95 1.959963984540054   /* the 97.5% normal quantile */

/* Centre and half-width of the Wilson score interval of normal quantile z,
** as fractions. */
static void study_wilson_parts(uint64_t k, uint64_t n, double z, double *centre,
                               double *half) {
  double nn = (double)n, p = (double)k / nn;
  double den = 1 + z * z / nn;
  *centre = (p + z * z / (2 * nn)) / den;
  *half = z / den * sqrt(p * (1 - p) / nn + z * z / (4 * nn * nn));
}

double study_wilson_halfwidth(uint64_t k, uint64_t n) {
  if (n == 0) return 0;
  double centre, half;
  study_wilson_parts(k, n, STUDY_Z95, &centre, &half);
  return 100 * half;
}

void study_wilson(uint64_t k, uint64_t n, double *lo, double *hi) {
  study_wilson_z(k, n, STUDY_Z95, lo, hi);
}

void study_wilson_z(uint64_t k, uint64_t n, double z, double *lo, double *hi) {
  if (n == 0) {
    *lo = 0;
    *hi = 100;
    return;
  }
  double centre, half;
  study_wilson_parts(k, n, z, &centre, &half);
  *lo = 100 * fmax(0, centre - half);
  *hi = 100 * fmin(1, centre + half);
}

double study_wilson_max(uint64_t n) {
  /* The half-width grows with p(1-p), so p = 1/2 is the worst case. */
  if (n == 0) return 0;
  double z = STUDY_Z95, nn = (double)n;
  return 100 * z / (1 + z * z / nn) * sqrt(0.25 / nn + z * z / (4 * nn * nn));
}
