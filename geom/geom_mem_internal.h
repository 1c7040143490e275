/*
** geom_mem_internal.h: the one growth rule of the library's growable
** arrays (lot/sweep.c's nodes and heaps, got/got_face.c's memo, the got
** skeleton's edge lists): capacity doubled from 256 until it holds need
** elements of size bytes, so n appends cost O(n) copies in all.  Inline:
** no symbol of its own.  Not installed.
*/
#ifndef FLIPLAB_GEOM_MEM_INTERNAL_H
#define FLIPLAB_GEOM_MEM_INTERNAL_H

#include <stdlib.h>

/* Make *a hold need elements: 0, or -1 when out of memory (*a and *cap
** unchanged). */
static inline int geom_grow(void **a, size_t *cap, size_t need, size_t size) {
  if (need <= *cap) return 0;
  size_t c = *cap ? *cap : 256;
  while (c < need) c *= 2;
  void *q = realloc(*a, c * size);
  if (q == NULL) return -1;
  *a = q;
  *cap = c;
  return 0;
}

#endif
