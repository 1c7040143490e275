/*
** key.c: the order of 64-bit keys (geom_key_internal.h), one function so
** that every qsort and bsearch of edge keys in the library shares it.
*/
#include "geom_key_internal.h"

int geom_u64_cmp(const void *x, const void *y) {
  uint64_t a = *(const uint64_t *)x, b = *(const uint64_t *)y;
  return (a > b) - (a < b);
}
