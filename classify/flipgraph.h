/*
** flipgraph.h: the directed flip graph of a convex pentagon under a rule.
**
** Vertices v0..v4 anticlockwise; the five triangulations are the fans
** T_i = {v_i v_{i+2}, v_i v_{i+3}}.  Quadrilateral Q_j = v_{j+1} v_{j+2}
** v_{j+3} v_{j+4} (vertex v_j deleted) decides the edge T_{j+1} - T_{j-1}:
** RULE_AC (diagonal v_{j+1}v_{j+3}) points it at T_{j+1}, RULE_BD (diagonal
** v_{j+2}v_{j+4}) at T_{j-1}.  Types I-V follow
** ../shared/spec/classification.md.
*/
#ifndef FLIPLAB_FLIPGRAPH_H
#define FLIPLAB_FLIPGRAPH_H

#include <stdint.h>
#include "geom/geom.h"
#include "fliprules/rule.h"

typedef enum flipgraph_type {
  FLIPGRAPH_I, FLIPGRAPH_II, FLIPGRAPH_III, FLIPGRAPH_IV, FLIPGRAPH_V,
  FLIPGRAPH_NTYPES
} flipgraph_type;

/* A pentagon with its ten triangles made once and shared by every rule. */
typedef struct flipgraph_pentagon {
  geom_point v[5];
  geom_tri tri[10];      /* see flipgraph_tri_index */
  int delaunay_sink;     /* fan index of the Delaunay triangulation, -1 if not unique */
} flipgraph_pentagon;

typedef struct flipgraph {
  rule_choice dec[5];    /* decision of Q_0..Q_4 */
  flipgraph_type type;
  int nsinks;
  int sink[2];           /* fan indices of the sinks, ascending */
  int delaunay;          /* 1 if type I and the sink is the Delaunay triangulation */
} flipgraph;

typedef struct flipgraph_counts {
  uint64_t samples;
  uint64_t type[FLIPGRAPH_NTYPES];
  uint64_t dt;           /* type I with sink = Delaunay */
} flipgraph_counts;

#endif
