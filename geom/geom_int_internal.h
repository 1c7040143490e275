/*
** geom_int_internal.h: the integers behind the predicates' first exact
** stage (predicates.c), shared with the parts above geom/ that run an
** integer stage of their own (the sweep's event keys,
** shapes/shape_sweep_circle.c): the unit that turns exact doubles into
** integers, and unsigned 256-bit sums of products.  One home for each; a
** caller states its own bounds.  Not installed.
*/
#ifndef FLIPLAB_GEOM_INT_INTERNAL_H
#define FLIPLAB_GEOM_INT_INTERNAL_H

#include <stdint.h>
#include "fliplab_config.h"

/* 1/u = 2^(62 - e) for the n normal or zero doubles v, 2^(e-1) <= max |v|
** < 2^e (1 when all are 0): every v/u is then below 2^62 in magnitude,
** and any coarser unit that makes them integers is a multiple of u. */
FLIPLAB_INTERNAL double geom_int_scale(const double *v, int n);

/* z[i] = v[i] s for i < n when every one is an integer of magnitude below
** lim (<= 2^62): 1; else 0. */
FLIPLAB_INTERNAL int geom_ints(const double *v, int n, double s, double lim, int64_t *z);

#if defined(__SIZEOF_INT128__)
#define GEOM_HAVE_INT128 1
__extension__ typedef __int128 geom_i128;
__extension__ typedef unsigned __int128 geom_u128;

/* Unsigned 256-bit numbers: four 64-bit limbs, the lowest first. */
typedef struct geom_u256 {
  uint64_t w[4];
} geom_u256;

/* r += a b, for a, b below 2^127 whose products, summed into r, stay below
** 2^256 (the caller's bound). */
FLIPLAB_INTERNAL void geom_u256_addmul(geom_u256 *r, geom_u128 a, geom_u128 b);
/* The sign of a - b. */
FLIPLAB_INTERNAL int geom_u256_cmp(const geom_u256 *a, const geom_u256 *b);
#else
#define GEOM_HAVE_INT128 0
#endif

#endif
