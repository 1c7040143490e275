/*
** order.h: the insertion orders of lot/ (lot/order.c; private to lot/, not
** installed): a spatial order (BRIO rounds, each sorted along a Hilbert
** curve), a seeded random permutation, and the lexicographic order of the
** flip algorithm's sweep; the radix sort behind them.
*/
#ifndef FLIPLAB_LOT_ORDER_H
#define FLIPLAB_LOT_ORDER_H

#include <stdint.h>
#include "geom.h"

/* ord[0..n-1] = input indices. */
FLIPLAB_INTERNAL
int lot_order_spatial(const geom_point *p, uint32_t n, uint64_t seed, uint32_t *ord);
FLIPLAB_INTERNAL void lot_order_random(uint32_t n, uint64_t seed, uint32_t *ord);
FLIPLAB_INTERNAL int lot_order_lexicographic(const geom_point *p, uint32_t n, uint32_t *ord);
/* Stable LSD radix sort of key[0..n-1] on its low `bits` bits, idx (may be
** NULL) permuted alongside: 0, or -1 when out of memory. */
FLIPLAB_INTERNAL int lot_radix(uint64_t *key, uint32_t *idx, uint32_t n, int bits);

#endif
