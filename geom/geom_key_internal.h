/*
** geom_key_internal.h: the one key of an undirected edge between two point
** indices (smaller index << 32 | larger, so sorting keys sorts edges by
** their smaller end, then their larger), and the one order of 64-bit keys
** for qsort and bsearch.  Every part that looks edges up uses them: lot's
** checks, constrained and CDF triangulations, got's faces and Delaunay
** comparison, the paradigms' constraint look-ups; and the one sort of records
** by a small leading key (a triangulation's triangles by their smallest
** vertex: the paradigms' canonical order, a point set's GOT); and the one way to
** list items by a small key, each key's items together (a grid's points cell by
** cell: got's skeleton, the paradigms' selection and ear cutting; a triangulation's
** edges point by point: got's Delaunay certificate).  Not installed.
*/
#ifndef FLIPLAB_GEOM_KEY_INTERNAL_H
#define FLIPLAB_GEOM_KEY_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "fliplab_config.h"

/* The key of the undirected edge uv: the same for uv and vu. */
static inline uint64_t geom_edge_key(uint32_t u, uint32_t v) {
  return u < v ? (uint64_t)u << 32 | v : (uint64_t)v << 32 | u;
}

/* Ascending order of uint64_t values, for qsort and bsearch (geom/key.c). */
FLIPLAB_INTERNAL int geom_u64_cmp(const void *x, const void *y);

/* Bucket [s, s + k records) by insertion: each record moved down past the larger ones
** before it (hand: one record of scratch). */
static inline void geom_bucket_insertion(unsigned char *s, size_t k, size_t size,
                                         unsigned char *hand,
                                         int (*cmp)(const void *, const void *)) {
  for (size_t i = 1; i < k; i++) {
    size_t j = i;
    memcpy(hand, s + i * size, size);
    while (j > 0 && cmp(s + (j - 1) * size, hand) > 0) j--;
    memmove(s + (j + 1) * size, s + j * size, (i - j) * size);
    memcpy(s + j * size, hand, size);
  }
}

/* Sort n records of `size` bytes at base into cmp's ascending order, where cmp orders by
** key(record) first and every key is at most top: a counting sort by key, then each
** bucket by insertion (qsort past 16 records).  O(n + top + sum of k log k over buckets of
** k > 16), one scattered copy a record, against qsort's O(n log n) comparisons (about ten
** times slower for the 2 x 10^6 triangles of 10^6 points).  0, or -1 when the scratch
** cannot be had (base untouched: sort it by qsort).  Inline, so that each caller's
** constant size, key and cmp are compiled into its own copy (through pointers the
** paradigms' runner took a fifth longer at 10^6 points). */
static inline int geom_bucket_sort(void *base, size_t n, size_t size, uint32_t top,
                                   uint32_t (*key)(const void *),
                                   int (*cmp)(const void *, const void *)) {
  unsigned char *b = base, *tmp = malloc((n + 1) * size);   /* the records, and the hand */
  size_t *at = calloc((size_t)top + 2, sizeof *at);
  if (tmp == NULL || at == NULL) return free(tmp), free(at), -1;
  for (size_t i = 0; i < n; i++) at[(size_t)key(b + i * size) + 1]++;
  for (size_t v = 0; v <= top; v++) at[v + 1] += at[v];
  for (size_t i = 0; i < n; i++) memcpy(tmp + size * at[key(b + i * size)]++, b + i * size, size);
  for (size_t v = 0, lo = 0; v <= top; lo = at[v++]) {   /* bucket v: [lo, at[v]) */
    size_t k = at[v] - lo;
    if (k > 16) qsort(tmp + lo * size, k, size, cmp);
    else geom_bucket_insertion(tmp + lo * size, k, size, tmp + n * size, cmp);
  }
  memcpy(b, tmp, n * size);
  free(tmp), free(at);
  return 0;
}

/* The key that lists an item nowhere (geom_csr_build). */
#define GEOM_CSR_NONE SIZE_MAX

/* Lists by key, as compressed sparse rows: item i < n whose key(ctx, i) is k < nkeys goes
** to list k, an item whose key is GEOM_CSR_NONE to none; list k is idx[at[k] .. at[k + 1]),
** its items ascending (stable), so at holds nkeys + 1 offsets and idx the listed items,
** fewer than 2^32.  A counting sort: O(n + nkeys), two calls of key an item (the same key
** both times).  The counts become the lists' ends and the items go in from the last one
** down, each to the slot before its list's end, so the ends finish as the starts without a
** second array or a shift.  Inline, as geom_bucket_sort, so that each caller's key is
** compiled into its own copy. */
static inline void geom_csr_build(uint32_t *at, size_t nkeys, uint32_t *idx, size_t n,
                                  size_t (*key)(const void *ctx, size_t i), const void *ctx) {
  memset(at, 0, (nkeys + 1) * sizeof *at);
  for (size_t i = 0; i < n; i++) {
    size_t k = key(ctx, i);
    if (k != GEOM_CSR_NONE) at[k]++;
  }
  for (size_t k = 1; k < nkeys; k++) at[k] += at[k - 1];   /* at[k]: the end of list k */
  at[nkeys] = nkeys > 0 ? at[nkeys - 1] : 0;
  for (size_t i = n; i-- > 0;) {
    size_t k = key(ctx, i);
    if (k != GEOM_CSR_NONE) idx[--at[k]] = (uint32_t)i;
  }
}

#endif
