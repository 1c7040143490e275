/*
** geom_key_internal.h: the one key of an undirected edge between two point
** indices (smaller index << 32 | larger, so sorting keys sorts edges by
** their smaller end, then their larger), and the one order of 64-bit keys
** for qsort and bsearch.  Every part that looks edges up uses them: lot's
** checks, constrained and CDF triangulations, got's faces and Delaunay
** comparison, the paradigms' constraint look-ups.  Not installed.
*/
#ifndef FLIPLAB_GEOM_KEY_INTERNAL_H
#define FLIPLAB_GEOM_KEY_INTERNAL_H

#include <stdint.h>
#include "fliplab_config.h"

/* The key of the undirected edge uv: the same for uv and vu. */
static inline uint64_t geom_edge_key(uint32_t u, uint32_t v) {
  return u < v ? (uint64_t)u << 32 | v : (uint64_t)v << 32 | u;
}

/* Ascending order of uint64_t values, for qsort and bsearch (geom/key.c). */
FLIPLAB_INTERNAL int geom_u64_cmp(const void *x, const void *y);

#endif
