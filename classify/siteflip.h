/*
** siteflip.h: every triangulation of a small planar site set (convex or
** not), its flip graph, the graph directed by a flip rule, and the census
** of many random site sets under many rules (the generalisation of table
** 3.4 from convex pentagons to any n <= SITEFLIP_MAX_SITES).
**
** Nodes are triangulations, numbered in breadth-first order from a first
** triangulation; edges are flips of strictly convex quadrilaterals.  Every
** quadrilateral A B C D (four sites, anticlockwise, A the smallest site
** index) is stored once: a rule decides it once, and that decision orients
** every flip between a triangulation holding the diagonal AC and one
** holding BD.  All predicates are exact (geom_orient, geom_incircle).
** Definitions (sinks with ties, Delaunay node, GOT, gap): docs/sitesets.md.
*/
#ifndef FLIPLAB_SITEFLIP_H
#define FLIPLAB_SITEFLIP_H

#include <stddef.h>
#include <stdint.h>
#include "census.h"
#include "geom.h"
#include "rule.h"

/* 16 sites: 120 segments still fit the 128-bit edge mask.  What bounds an
** enumeration is memory, not the site count (the number of triangulations
** grows exponentially: a convex 12-gon has 16 796, a convex 16-gon
** 2 674 440): every build counts its bytes against a budget. */
#define SITEFLIP_MAX_SITES 16

/* The default memory budget of one flip graph: 1 GiB. */
#define SITEFLIP_MEMORY_DEFAULT ((size_t)1 << 30)

/* Bytes the budget sets aside per triangulation and per flip beyond the
** enumeration's own arrays: the adjacency (offsets, its fill pointers and
** two entries per flip) and what directing the graph by a rule takes
** (siteflip_direct's degrees and queue, a sink list; the census's masks,
** keys and flags), so that a graph within the budget can be used. */
#define SITEFLIP_NODE_RESERVE 32
#define SITEFLIP_EDGE_RESERVE 8

/* A set of segments i-j (i < j), bit siteflip_seg(n, i, j) of lo:hi. */
typedef struct siteflip_mask { uint64_t lo, hi; } siteflip_mask;

typedef struct siteflip_quad {
  unsigned char v[4];    /* sites A B C D, anticlockwise, A smallest */
  int tri[4];            /* triangles ABC, ACD (diagonal AC), ABD, BCD (BD) */
} siteflip_quad;

typedef struct siteflip_edge {
  int ac, bd;            /* the triangulations holding AC and BD */
  int quad;
} siteflip_edge;

typedef struct siteflip_graph {
  int n;
  geom_point p[SITEFLIP_MAX_SITES];
  int nnodes;
  siteflip_mask *node;   /* edge set of each triangulation */
  int per;               /* triangles per triangulation: 2n - h - 2 */
  int *node_tri;         /* nnodes * per triangle indices, ascending */
  int ntris;             /* empty triangles used by some triangulation */
  unsigned char (*tri_v)[3];   /* their sites, ascending */
  geom_tri *tri;
  int nquads;
  siteflip_quad *quad;
  int nedges;
  siteflip_edge *edge;
  int *adj_off, *adj;    /* edges incident to node u: adj[adj_off[u] .. adj_off[u+1]) */
  int delaunay;          /* the Delaunay triangulation, -1 if not unique */
} siteflip_graph;

/* Check a site set: 3 <= n <= SITEFLIP_MAX_SITES, coordinates within the
** contract (geom_coord_check), no two equal sites, not all collinear.  0,
** or -1 with a one-line reason naming the sites (1-based) in err. */
int siteflip_check(const geom_point *p, int n, char *err, size_t errlen);

/* Enumerate every triangulation and flip of p[0..n-1] (checked first)
** within SITEFLIP_MEMORY_DEFAULT.  NULL with a one-line reason in err. */
siteflip_graph *siteflip_build(const geom_point *p, int n, char *err, size_t errlen);

/* What bounds and reports a build: the memory budget in bytes (0: the
** default), and a progress callback (may be NULL) called now and then with
** the triangulations expanded out of those found so far. */
typedef struct siteflip_limits {
  size_t memory;
  census_progress_fn progress;
  void *ctx;
} siteflip_limits;

/* siteflip_build within lim.  When the graph would outgrow the budget the
** build stops, frees everything and returns NULL with *over = 1 (over may
** be NULL) and a one-line reason saying how many triangulations it had
** found; out of memory, *over = 0. */
siteflip_graph *siteflip_build_within(const geom_point *p, int n, const siteflip_limits *lim,
                                      int *over, char *err, size_t errlen);
void siteflip_free(siteflip_graph *g);

/* How many triangulations p[0..n-1] (checked first) has, up to cap >= 1:
** 0 with *count the number when it is at most cap; 1 with *count = cap + 1
** when there are more (the enumeration stops as soon as it has found cap +
** 1, so "too many" costs no more than cap + 1 of them); -1 with a one-line
** reason in err. */
int siteflip_count_upto(const geom_point *p, int n, int cap, int *count, char *err,
                        size_t errlen);

/* Move g to new sites with the same order type (e.g. another convex n-gon
** labelled anticlockwise): the triangles and the Delaunay node are redone,
** the shape is kept.  The caller guarantees the order type.  0, or -1
** when memory runs out (g is then not to be used). */
int siteflip_move(siteflip_graph *g, const geom_point *p);

/* Index of segment i-j (i != j) among the n(n-1)/2 segments; whether
** triangulation u has the edge i-j. */
int siteflip_seg(int n, int i, int j);
int siteflip_has_edge(const siteflip_graph *g, int u, int i, int j);

/* The graph directed by one rule. */
typedef struct siteflip_result {
  int nsinks, nsources;
  int ties;              /* some flip's quadrilateral was decided `either` */
  int cycle;             /* a directed cycle among the strict edges */
  int sink_dt;           /* 1 / 0: the unique sink is / is not DT; -1: no
                         ** unique sink, or DT not unique */
  int has_got;           /* triangle-based rule: the fields below are set */
  int got_node;          /* the best triangulation (smallest index on ties) */
  double got_total;      /* its total badness (joint over its triangles) */
  int worst_sink;        /* the sink of largest total */
  double worst_gap;      /* (total(worst sink) - GOT) / max(|both|), >= 0 */
} siteflip_result;

/* Direct g by r: dec[0..nquads-1] receives the decisions, sinks (room for
** nnodes, may be NULL) the sinks in ascending order.  Sinks are the
** triangulations no flip strictly improves (an `either` edge leads
** nowhere); sources those no flip strictly reaches.  0, or -1 when out of
** memory. */
int siteflip_direct(const siteflip_graph *g, const rule *r, double tie_eps,
                    rule_choice *dec, int *sinks, siteflip_result *res);
/* The same with per-site weights w[0..n-1] (by site index; NULL: none;
** each within the weight contract, geom_weight_check: the caller checks),
** which a rule that reads them (WDT, rule_wants_weights) decides by.  Every
** triangulation uses every site, so where a site is redundant (its power
** cell empty) no node is regular and the sinks are the LOTs of the power
** rule among the triangulations that keep it. */
int siteflip_direct_weighted(const siteflip_graph *g, const rule *r, const double *w,
                             double tie_eps, rule_choice *dec, int *sinks,
                             siteflip_result *res);

/* Total badness of node u under a triangle-based rule, in key space
** (joint.h): keys compare as the totals do. */
double siteflip_node_key(const siteflip_graph *g, const rule *r, int u);

/* ---- census ---------------------------------------------------------- */

/* Samplers of sites (samplers/sampler.h, sampler_sites). */
typedef struct siteflip_counts {
  uint64_t samples;
  uint64_t tie, no_sink, one_sink, multi_sink, sink_dt;
  uint64_t sinks;        /* total sinks over the samples without a tie */
  uint64_t max_sinks;
  uint64_t gap_units;    /* sum of worst gaps in units of SITEFLIP_GAP_UNIT */
} siteflip_counts;

/* Each sample's worst gap is rounded to a multiple of 2^-20 (about 1e-6)
** and summed as an integer, so any thread count and any shard split add to
** the same bits. */
#define SITEFLIP_GAP_UNIT 0x1p-20

/* Census of samples first .. first+count-1 of sampler `sampler` (a
** sampler_sites_kind) with n sites, seed `seed`, under every rule, added to
** out[0..nrules-1].  threads: 0 for all cores, or 1 .. GEOM_MAX_THREADS
** (another count: -1 with geom_threads_check's message).  memory: the
** budget of each set's flip graph (0: SITEFLIP_MEMORY_DEFAULT; each thread holds one).
** 0, or -1 with err (a set over the budget: its index, and *over = 1 when
** over is not NULL). */
int siteflip_census(const rule *rules, int nrules, int sampler, int n, uint64_t seed,
                    uint64_t first, uint64_t count, double tie_eps, int threads,
                    size_t memory, siteflip_counts *out, census_progress_fn progress,
                    void *ctx, int *over, char *err, size_t errlen);

/* The first sample in [first, first+count) where rule r has two or more
** sinks (witness of non-systematicity); its sites into p.  Index or -1. */
int64_t siteflip_find_multi(const rule *r, int sampler, int n, uint64_t seed,
                            uint64_t first, uint64_t count, double tie_eps,
                            geom_point *p);

#endif
