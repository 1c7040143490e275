/*
** weighted.h: the sites the weighted Delaunay rule leaves out (private to
** lot/, not installed; lot/weighted.c has the argument).
*/
#ifndef FLIPLAB_LOT_WEIGHTED_H
#define FLIPLAB_LOT_WEIGHTED_H

#include <stddef.h>
#include "mesh.h"

/* Mark in mark[] (by input index, m->inp) every site that a concave edge
** of the LOT m, under the weights w (by input index), certifies redundant;
** returns how many were newly marked, 0 when the triangulation is
** regular.  O(edges). */
FLIPLAB_INTERNAL size_t lot_weighted_hidden(const lot_mesh *m, const double *w,
                                            unsigned char *mark);

#endif
