/*
** geom_exact_internal.h: the exact arithmetic behind the predicates'
** fallback stages (predicates.c), shared with the parts above geom/ that
** run exact stages of their own (shapes/shape_arith.c): the error-free
** transformations of doubles and the floating-point expansions built on
** them (Shewchuk, Adaptive Precision Floating-Point Arithmetic and Fast
** Robust Geometric Predicates, 1997, section 2), the range test that says
** when they are exact, and the process-wide GMP-only switch.  One home for
** each: a caller states its own no-overflow, no-underflow argument.  Not
** installed.
*/
#ifndef FLIPLAB_GEOM_EXACT_INTERNAL_H
#define FLIPLAB_GEOM_EXACT_INTERNAL_H

#include <math.h>
#include "fliplab_config.h"

/* x is 0 or of magnitude in [lo, hi] (NaN and infinities are not).  The
** predicates' stages use coordinates in [2^-200, 2^200] and weights in
** [2^-400, 2^400]; each caller names its own range.  Combined with &
** rather than &&: every test of a call is evaluated, and nothing branches
** on the data. */
static inline int geom_moderate(double x, double lo, double hi) {
  double m = fabs(x);
  return (m == 0) | ((m >= lo) & (m <= hi));
}

/* 1 while geom_exact_gmp_only is on (predicates.h): every exact stage but
** GMP's is then skipped, in geom/ and in the parts that follow its switch. */
FLIPLAB_INTERNAL int geom_exact_gmp_forced(void);

/* ---- error-free transformations -----------------------------------------
**
** Exact under round to nearest even with no contraction into FMA
** (fliplab_config.h), provided nothing overflows or underflows. */

/* x + y = a + b exactly, x = fl(a + b). */
static inline void geom_two_sum(double a, double b, double *x, double *y) {
  double s = a + b, bv = s - a, av = s - bv;
  *x = s;
  *y = (a - av) + (b - bv);
}

/* x + y = a - b exactly, x = fl(a - b). */
static inline void geom_two_diff(double a, double b, double *x, double *y) {
  double d = a - b, bv = a - d, av = d + bv;
  *x = d;
  *y = (a - av) + (bv - b);
}

/* hi + lo = a, each with at most 26 significant bits (Dekker). */
static inline void geom_split(double a, double *hi, double *lo) {
  double c = 134217729.0 * a, big = c - a;
  *hi = c - big;
  *lo = a - *hi;
}

/* x + y = a * b exactly, x = fl(a * b). */
static inline void geom_two_product(double a, double b, double *x, double *y) {
  double p = a * b, ahi, alo, bhi, blo;
  geom_split(a, &ahi, &alo);
  geom_split(b, &bhi, &blo);
  double err = ((p - ahi * bhi) - alo * bhi) - ahi * blo;
  *x = p;
  *y = alo * blo - err;
}

/* ---- expansions ------------------------------------------------------------
**
** An expansion is a sum of doubles, nonoverlapping and increasing in
** magnitude, whose sign is the sign of its last (largest) component.  Each
** verb drops zero components but keeps at least one, and returns the
** result's length; the result may not alias an operand.  predicates.c. */

/* h = e + b: at most n + 1 components.  Cost O(n). */
FLIPLAB_INTERNAL int geom_grow_expansion(int n, const double *e, double b, double *h);
/* h = e + f: at most n + m components.  Cost O(n + m). */
FLIPLAB_INTERNAL int geom_expansion_sum(int n, const double *e, int m, const double *f,
                                        double *h);
/* h = e b: at most 2 n components.  Cost O(n). */
FLIPLAB_INTERNAL int geom_scale_expansion(int n, const double *e, double b, double *h);
/* e in place, the same value in as few components as it needs (at most
** n).  Cost O(n). */
FLIPLAB_INTERNAL int geom_expansion_compress(int n, double *e);
/* h = e f: at most 2 n m components, with scratch room for 2 n + 2 n m
** doubles.  Cost O(n m^2). */
FLIPLAB_INTERNAL int geom_expansion_product(int n, const double *e, int m, const double *f,
                                            double *h, double *scratch);

#endif
