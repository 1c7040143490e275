/*
** linf_internal.h: what the files of linf/ share: rows of point indices
** (subsets, simplices, facets) and the lists they go in.
*/
#ifndef FLIPLAB_LINF_INTERNAL_H
#define FLIPLAB_LINF_INTERNAL_H

#include "fliplab_config.h"
#include "linf.h"

/* The rows of the points idx[0 .. m) into rows. */
FLIPLAB_INTERNAL void linf_gather(const double *pts, int d, const unsigned char *idx, int m,
                                  double *rows);
/* Append a row; sort the list (through keys).  0, or -1 when memory ran out. */
FLIPLAB_INTERNAL int linf_simplices_push(linf_simplices *s, const unsigned char *v);
FLIPLAB_INTERNAL int linf_simplices_sort(linf_simplices *s);

#endif
