/*
** report_flipgraph.h: one pentagon's directed flip graph as an SVG picture,
** in the style of thesis figure 3.7.
*/
#ifndef FLIPLAB_REPORT_FLIPGRAPH_H
#define FLIPLAB_REPORT_FLIPGRAPH_H

#include <stdio.h>
#include "classify/flipgraph.h"

/* The five triangulations of p drawn as small pictures around the cycle
** T0 - T2 - T4 - T1 - T3, an arrow on each cycle edge pointing to the
** triangulation the rule prefers (a dashed undirected line for EITHER),
** sinks in a thick green frame, sources in a dashed red one, the Delaunay
** triangulation tagged "DT".  caption: lines separated by '\n' (rule, type,
** coordinates...), drawn below.  0, or -1 on a write error. */
int report_flipgraph_svg(FILE *f, const flipgraph_pentagon *p, const flipgraph *g,
                         const char *caption);

#endif
