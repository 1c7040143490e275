/*
** siteflip_internal.h: what siteflip.c shares with sitecensus.c (not
** installed).
*/
#ifndef FLIPLAB_SITEFLIP_INTERNAL_H
#define FLIPLAB_SITEFLIP_INTERNAL_H

#include "siteflip.h"

/* siteflip_move in steps, for callers that keep DT's decisions: the new
** sites and triangles; the exact in-circle decision of every quadrilateral
** (rule_eval's for DT: the test is exact, so the vertex order does not
** matter); the Delaunay node from them (-1 unless unique). */
FLIPLAB_INTERNAL void siteflip_move_tris(siteflip_graph *g, const geom_point *p);
FLIPLAB_INTERNAL void siteflip_dt_decisions(const siteflip_graph *g, rule_choice *d);
FLIPLAB_INTERNAL int siteflip_delaunay_of(const siteflip_graph *g, const rule_choice *d);

#endif
