/*
** lot.h: locally optimal triangulations (LOT) of planar point sets.
**
** A LOT(F) of a point set is a triangulation in which the flip rule F keeps
** every interior edge whose two triangles form a strictly convex
** quadrilateral (thesis section 3.1).  Two algorithms make one:
**
**   flip         an initial triangulation by a sweep (points sorted by x,
**                then y, each connected to the hull vertices it sees), then
**                Lawson's flip algorithm: a queue of edges, each examined
**                and flipped when F prefers the other diagonal;
**   incremental  points inserted one at a time (input, random or spatial
**                order), located by a walk, connected to the triangle that
**                holds them or to every hull vertex they see, and the
**                triangulation flipped back to a LOT after each insertion
**                (theorem 5);
**   sweep        the thesis's sweepline algorithm (sections 2.5.1, 4.1.1):
**                a vertical line sweeps the points from left to right,
**                keeping the boundary of the part of the triangulation
**                that is certain; site events and circumshape events
**                (keyed by the circumscribing shape's rightmost point,
**                compared exactly) make the triangulation directly, no
**                flips (rule DT or an empty-shape rule ES:SHAPE; for a
**                polygon, ties of sites in special position are decided by
**                a fixed rule and the rule's flips with its tie-break
**                finish the job: lot_get_sweep_ties).
**
** Every geometric decision is exact (geom_orient, geom_incircle).  Rules are
** decided through the rule API (rule.h): DT exactly, triangle-based b_f with
** each triangle's badness kept per triangle, quadrilateral rules (plugins)
** on the canonical rotation.  Only strictly convex quadrilaterals are
** decided; EITHER, non-convex and degenerate ones are left alone.
**
** Never a hang: triangle-based rules and DT provably terminate (lot.c says
** why); for quadrilateral rules a repeated triangulation is detected (an
** incremental hash of the edge set, confirmed exactly) and reported as a
** cycle; every run also stops after max_flips flips.
**
** Exact duplicate points are merged: every index in the output is the first
** occurrence's 0-based input index.  Triangles are anticlockwise.
*/
#ifndef FLIPLAB_LOT_H
#define FLIPLAB_LOT_H

#include <stddef.h>
#include <stdint.h>
#include "geom.h"
#include "ops.h"
#include "rule.h"
#include "shape.h"

typedef enum lot_algorithm { LOT_INCREMENTAL, LOT_FLIP, LOT_SWEEP } lot_algorithm;
typedef enum lot_order { LOT_ORDER_SPATIAL, LOT_ORDER_INPUT, LOT_ORDER_RANDOM } lot_order;
typedef enum lot_status { LOT_CONVERGED, LOT_CYCLE, LOT_BUDGET } lot_status;

/* At most this many points (indices are 32-bit, with room for the ghost). */
#define LOT_MAX_POINTS 0x3fffffffu

/* A decision override for experiments and tests: called instead of the rule
** with the strictly convex anticlockwise quadrilateral q and its current
** diagonal (RULE_AC for q[0]q[2], RULE_BD for q[1]q[3]). */
typedef rule_choice (*lot_decide_fn)(const geom_point q[4], rule_choice current, void *ctx);

typedef struct lot_options {
  rule r;               /* the flip rule */
  lot_algorithm algorithm;
  lot_order order;      /* incremental only */
  uint64_t seed;        /* the random order's seed */
  uint64_t max_flips;   /* 0: lot_default_max_flips(n) */
  double tie_eps;       /* the rule's tie tolerance in this run (lot_options_init: r's) */
  lot_decide_fn decide; /* NULL: the rule decides */
  void *decide_ctx;
  /* Constraints (lot/cdt.c, docs/lot.md "Constrained triangulations"):
  ** none gives the unconstrained LOT, byte for byte. */
  const uint32_t *segments;  /* 2 per segment: 0-based input point indices */
  size_t nsegments;
  const geom_point *holes;   /* hole points: the regions holding them are removed */
  size_t nholes;
  int keep_hull;             /* 1: keep the triangles outside the outermost segment-bounded
                                region (0: removed, as Triangle's -p) */
  /* Per-site weights of the weighted Delaunay rule WDT (rule.h; docs/lot.md
  ** "Weighted Delaunay"): weights[i] is point i's, within the weight
  ** contract of geom.h.  NULL: none (WDT is then DT).  Only WDT takes them,
  ** with the incremental or flip algorithm and no segments or holes. */
  const double *weights;
  /* Operation counts (geom/ops.h, docs/paradigms.md "The counting layer"):
  ** when not NULL, the run adds its orientation and in-circle / in-shape
  ** tests, flips, walk steps, edges made and deleted, sweep events and peak
  ** working memory to *ops (the caller clears it).  NULL: nothing counted. */
  ops_counts *ops;
} lot_options;

/* Defaults: incremental, spatial order, seed 1, RULE_DEFAULT_TIE_EPS. */
void lot_options_init(lot_options *o, const rule *r);

/* The default flip budget for n points: 1000 n + 10^7. */
uint64_t lot_default_max_flips(size_t n);

#define LOT_CYCLE_QUADS 8     /* quadrilaterals of a cycle kept for the report */

typedef struct lot_stats {
  size_t n;             /* input points */
  size_t distinct;      /* after merging duplicates */
  size_t duplicates;    /* n - distinct */
  size_t hull;          /* vertices on the convex hull boundary (collinear ones included) */
  size_t triangles;
  uint64_t flips;
  lot_status status;
  uint64_t cycle_length;              /* LOT_CYCLE: flips in the cycle */
  size_t cycle_quads;                 /* how many quads below (<= LOT_CYCLE_QUADS) */
  uint32_t cycle_quad[LOT_CYCLE_QUADS][4];   /* input indices, anticlockwise */
  uint64_t max_flips;
  double seconds_init;  /* flip: the sweep triangulation; incremental, sweep: ordering the points */
  double seconds_flip;  /* flip: the flips; incremental: insertion and flips (interleaved);
                           sweep: the sweep */
  /* constrained runs */
  size_t segments;          /* input segments */
  size_t constrained;       /* constrained edges in the result (the segments' pieces: split
                               at the points on them, duplicates and overlaps merged) */
  size_t segments_merged;   /* input segments with a piece an earlier segment made */
  size_t segments_split;    /* input segments with a point inside them */
  size_t segments_removed;  /* input segments with a piece in no kept triangle */
  size_t holes;             /* hole points */
  size_t removed;           /* triangles removed (holes, and the outside) */
  /* weighted runs */
  size_t redundant;         /* distinct sites left out: their power cells are empty */
  size_t rounds;            /* triangulations made (1 + the rounds that found sites to drop) */
} lot_stats;

typedef struct lot lot;

/* Triangulate p[0 .. n-1] and flip to a LOT of o->r.  0 on success, or -1
** with a one-line message in err: fewer than three distinct points, all
** collinear, a coordinate outside the contract of geom.h (geom_coord_check,
** naming the point), too many points, out of memory, LOT_SWEEP with a rule
** other than DT or ES:SHAPE, or with a decision hook. */
int lot_build(lot **out, const geom_point *p, size_t n, const lot_options *o,
              char *err, size_t errlen);

/* The flip algorithm from the current triangulation with another rule
** (o->algorithm and o->order are ignored).  Statistics of this run replace
** the flip counts; returns 0, or -1 when out of memory. */
int lot_reflip(lot *L, const lot_options *o);

const lot_stats *lot_get_stats(const lot *L);

/* The sweep of a polygon rule (docs/lot.md, "Polygons"): the ties of sites
** in special position it decided by its fixed order (0 for every other
** run; the flips of lot_stats then made the tie-broken LOT), and in
** *restarted (may be NULL) 1 when its mesh was no triangulation and the
** circle's sweep (the Delaunay triangulation) was flipped instead. */
size_t lot_get_sweep_ties(const lot *L, int *restarted);

/* The constrained edges of the result: 2 input indices each, smaller
** first, sorted; out holds 2 * stats.constrained entries.  Returns the count. */
size_t lot_get_constrained(const lot *L, uint32_t *out);

/* A weighted run (WDT with weights): the input indices of the redundant
** sites, those no regular triangulation keeps (lot_stats.redundant of
** them, ascending; an exact duplicate of a heavier site is no such site:
** lot_stats.duplicates counts it).  The triangulation is the regular
** triangulation of the other sites.  Returns the count. */
size_t lot_get_redundant(const lot *L, uint32_t *out);

/* The triangles, 3 input indices each, anticlockwise, each starting at its
** smallest index, sorted; tri must hold 3 * stats.triangles entries. */
void lot_get_triangles(const lot *L, uint32_t *tri);

/* The neighbours of lot_get_triangles' rows, read off the mesh's adjacency
** (lot_neighbors' convention, scipy.spatial.Delaunay.neighbors'): nb[3t + k]
** is the row across the edge of row t opposite its vertex k, -1 on the
** boundary (the hull, a hole, a removed region); nb holds 3 *
** stats.triangles entries.  The rows' order is found again by the same
** counting sort, carrying each mesh triangle along: O(n + T) time for
** bounded degree, 16 bytes per triangle and 8 per point of scratch, no
** search for twin edges.  0, or -1 when out of memory. */
int lot_get_neighbors(const lot *L, int32_t *nb);


/* The convex hull's boundary vertices (collinear ones included),
** anticlockwise, as input indices; out holds stats.hull entries. */
size_t lot_get_hull(const lot *L, uint32_t *out);

/* 0 if n points fit in memory (at most 3/4 of physical memory, about 185
** bytes per point with a caller's input and output), else -1 and a
** one-line message. */
int lot_check_memory(size_t n, char *err, size_t errlen);

void lot_free(lot *L);
/* The exact duplicates of p[0..n-1], as lot_build merges them: first[i] is
** the smallest index j with p[j] == p[i] (so first[i] == i for the first
** occurrence).  Returns the number of distinct points, or -1 when out of
** memory or n > LOT_MAX_POINTS.  O(n log n). */
long lot_distinct(const geom_point *p, size_t n, uint32_t *first);


/* ---- independent checks (lot/check.c), from a triangle list alone ---- */

typedef struct lot_check_result {
  size_t interior_edges;    /* edges shared by two triangles */
  size_t boundary_edges;    /* edges of one triangle */
  size_t decided;           /* interior edges in a strictly convex quadrilateral */
  size_t not_optimal;       /* of those, the rule prefers the other diagonal */
  uint32_t bad_edge[2];     /* the first such edge */
  int valid;                /* a triangulation: anticlockwise, every edge in <= 2 triangles,
                               consistently oriented, T = 2n - h - 2 (Euler); constrained:
                               V - E + T = 2C - L with a vertex counted once per fan (check.c) */
  size_t segments_missing;  /* lot_check_constrained: segments that are no chain of edges */
  size_t missing_segment;   /* the first of them (an index into seg) */
} lot_check_result;

/* Re-verify a triangulation of p (indices into p) from scratch: structure,
** and local optimality of every interior edge for r, with r's tie
** tolerance (DT: the exact empty-circle test).  0, or -1 when out of memory. */
int lot_check(const geom_point *p, size_t n, const uint32_t *tri, size_t ntri,
              const rule *r, lot_check_result *out);

/* The ties of DT and of the empty-shape rules against lot's tie-break. */
typedef struct lot_tie_result {
  size_t ties;              /* decided edges the rule calls a tie (EITHER; DT: cocircular) */
  size_t not_tie_broken;    /* of those, the tie-break keeps the other diagonal: the
                               triangulation is not the rule's one tie-broken LOT */
  uint32_t tie_edge[2];     /* the first such edge, smaller index first */
} lot_tie_result;

/* lot_check, and for DT and ES:SHAPE every tie against the tie-break
** (docs/lot.md, Ties: the diagonal kept is the one not incident to the
** lexicographically greatest of the four sites) into *tie; for other
** rules tie is all zero.  0, or -1 when out of memory. */
int lot_check_ties(const geom_point *p, size_t n, const uint32_t *tri, size_t ntri,
                   const rule *r, lot_check_result *out, lot_tie_result *tie);

/* lot_check for a constrained triangulation, from the triangle list and the
** input segments seg (2 indices each) alone: each segment must be a chain of
** triangle edges through the points on it, else it counts as missing; those
** edges are not decided; every other interior edge is checked as lot_check
** does, and valid asks Euler's relation with holes.  0, or -1 (memory). */
/* lot_check for the weighted rule with per-site weights w (by input
** index): every interior edge must be regular, the lifted surface convex
** across it (geom_power <= 0 from its triangles), whether or not its
** quadrilateral is convex: the triangulation is then the regular one of
** the sites it uses.  Any other rule: lot_check. */
int lot_check_weighted(const geom_point *p, const double *w, size_t n, const uint32_t *tri,
                       size_t ntri, const rule *r, lot_check_result *out);

int lot_check_constrained(const geom_point *p, size_t n, const uint32_t *tri, size_t ntri,
                          const uint32_t *seg, size_t nseg, const rule *r,
                          lot_check_result *out);

/* The neighbours of the triangles tri (indices below n), in the convention
** of scipy.spatial.Delaunay.neighbors: nb[3t + k] is the triangle across
** the edge of t opposite its vertex k (from tri[3t + (k+1) % 3] to
** tri[3t + (k+2) % 3]), -1 on the boundary.  For a triangulation whose
** triangles are consistently oriented (lot_check's valid): the triangle
** across edge u -> v is the one with edge v -> u.  O(ntri) time and
** memory.  0, or -1 when out of memory. */
int lot_neighbors(const uint32_t *tri, size_t ntri, size_t n, int32_t *nb);

/* ---- point location (lot/locate.c) ---- */

#define LOT_LOCATE_CONVEX 1   /* the triangles cover their convex hull */
#define LOT_LOCATE_SCAN 2     /* no walk: every query scans the triangles */

/* For each query q[i], out[i] = the index of a triangle of tri (anticlockwise,
** indices below n, nb its neighbours in lot_neighbors' convention) holding
** q[i], closed, decided exactly (geom_orient), or -1: scipy's find_simplex.
** On an edge the smaller of its two triangles, on a vertex the smallest
** triangle with that vertex, so the answer is the same whatever the walk;
** a non-finite query gets -1.  Queries walk in a spatial order from the
** last one's triangle (the remembering stochastic walk); LOT_LOCATE_CONVEX
** says a walk that leaves through the boundary proves the point outside,
** else such a point is checked by a scan of every triangle.  Cost:
** O(nq) for the order, a walk of expected O(sqrt(ntri)) steps for an
** isolated query and far fewer for queries close to each other, at most
** O(ntri) per query (a walk is given up for the scan after ntri steps),
** and O(n + ntri) once for the first query on a vertex.  nb may be NULL
** with LOT_LOCATE_SCAN.  0, or -1 when out of memory. */
int lot_locate(const geom_point *p, size_t n, const uint32_t *tri, const int32_t *nb,
               size_t ntri, int flags, const geom_point *q, size_t nq, int32_t *out);

/* Each triangle's badness for the rule: measure_eval on the triangle of p
** (NaN for DT and quadrilateral rules). */
void lot_get_badness(const geom_point *p, const uint32_t *tri, size_t ntri, const rule *r,
                     double *out);

/* Edges and triangles two triangulations of the same points share
** (-1 when out of memory). */
typedef struct lot_diff {
  size_t edges_a, edges_b, edges_common;
  size_t triangles_a, triangles_b, triangles_common;
} lot_diff;
int lot_compare(const uint32_t *a, size_t na, const uint32_t *b, size_t nb, lot_diff *out);

/* ---- the convex-distance Delaunay graph (lot/cdf.c) ----
** Read off an empty-shape triangulation of the shape K (thesis 4.1.2,
** docs/emptyshape.md): a triangle is kept when its circumscribing shape is a
** homothet of K (its three support points differ); a dropped triangle's
** circumscribing shape is a corner's rounding shape, and of its edges exactly
** one is not CDF-Delaunay (lot_cdf_nonedge).  An edge is CDF-Delaunay iff it
** is no adjacent triangle's non-edge; the extra edges are those in no kept
** triangle.  For an ellipse every triangle is kept. */
typedef struct lot_cdf {
  size_t triangles;     /* kept triangles */
  uint32_t *tri;        /* 3 indices each, as in the input list */
  size_t edges;         /* CDF-Delaunay edges in no kept triangle */
  uint32_t *edge;       /* 2 indices each, smaller first, sorted */
  size_t rounded;       /* dropped triangles */
  size_t conflicts;     /* edges of a kept triangle that are a neighbour's non-edge:
                           0 on an empty-shape triangulation */
} lot_cdf;

/* The non-edge of the anticlockwise triangle ABC for K: -1 when ABC has a
** circumscribing homothet of K (and always for an ellipse), else 0 for AB,
** 1 for BC, 2 for CA: the edge whose support point differs from the other
** two (shape_support, with its tie-break). */
int lot_cdf_nonedge(const shape *k, geom_point a, geom_point b, geom_point c);

/* The CDF graph of the triangulation tri (anticlockwise triangles, indices
** into p) for K.  0, or -1 when out of memory; free with lot_cdf_free. */
int lot_cdf_extract(const geom_point *p, const uint32_t *tri, size_t ntri, const shape *k,
                    lot_cdf *out);
void lot_cdf_free(lot_cdf *c);

/* ---- options, statistics and checks through verbs (lot/lot_options.c,
** lot/lot_fields.c) ----
** For callers that do not compile against this header, such as a binding
** through a foreign-function interface (python/fliplab: docs/python.md,
** "How the package talks to the library"): lot_options made, set and
** checked by verbs, lot_stats and lot_check_result read by the names of
** their fields, so no such caller restates a layout.  A field added to one
** of these structures gets its setter here, or its row in lot_fields.c's
** table (python/tests/test_layout.py finds a field without one). */

/* lot_options_init's defaults for r, on the heap; NULL when out of memory.
** Free with lot_options_free. */
lot_options *lot_options_new(const rule *r);
void lot_options_free(lot_options *o);

/* Set one option.  The arrays are the caller's and must outlive
** lot_build (segments: 2 input indices each; holes: hole points).  The
** int setters return 0, or -1 leaving o unchanged for a value outside the
** type (an algorithm or order that is no enumerator; a tie tolerance that
** is not a finite number >= 0). */
int lot_options_set_algorithm(lot_options *o, int algorithm);
int lot_options_set_order(lot_options *o, int order);
void lot_options_set_seed(lot_options *o, uint64_t seed);
void lot_options_set_max_flips(lot_options *o, uint64_t max_flips);
int lot_options_set_tie_eps(lot_options *o, double tie_eps);
void lot_options_set_segments(lot_options *o, const uint32_t *segments, size_t nsegments);
void lot_options_set_holes(lot_options *o, const geom_point *holes, size_t nholes);
void lot_options_set_keep_hull(lot_options *o, int keep_hull);
/* weights[i]: point i's weight (WDT; NULL: none); lot_build checks them. */
void lot_options_set_weights(lot_options *o, const double *weights);
/* The counts a run adds to (the caller's, cleared by it; NULL: none). */
void lot_options_set_ops(lot_options *o, ops_counts *ops);

/* Whether the options make sense together, before lot_build: 0, or -1
** with a one-line message naming the options by their fields (no flag of
** the program): an algorithm, order or tie tolerance out of range, an
** order other than spatial with an algorithm other than incremental
** (which orders the points itself), keep_hull without a segments or holes
** array (an empty one counts, as an empty file does in the program).
** lot_build does not ask it: an order left set for another algorithm is
** ignored there, as tests and benchmarks rely on. */
int lot_options_check(const lot_options *o, char *err, size_t errlen);

/* lot_stats by name: lot_stats_field(i) is the name of its i-th field in
** declaration order (NULL past the last); lot_stats_get_u64 reads element
** i of a count (size_t, uint64_t, the status as its lot_status value;
** cycle_quad's elements are 4 q + corner), lot_stats_get_double a time.
** 0, or -1 for a name that is no field of that type, or i outside it. */
const char *lot_stats_field(size_t i);
int lot_stats_get_u64(const lot_stats *s, const char *name, size_t i, uint64_t *out);
int lot_stats_get_double(const lot_stats *s, const char *name, double *out);

/* A lot_check_result on the heap for lot_check and lot_check_constrained
** (zero; NULL when out of memory), and its fields by name as
** lot_stats' (bad_edge's elements are its two ends; valid 0 or 1). */
lot_check_result *lot_check_result_new(void);
void lot_check_result_free(lot_check_result *c);
const char *lot_check_result_field(size_t i);
int lot_check_result_get_u64(const lot_check_result *c, const char *name, size_t i,
                             uint64_t *out);

#endif
