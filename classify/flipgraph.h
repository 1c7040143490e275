/*
** flipgraph.h: the directed flip graph of a convex pentagon under a rule.
**
** Vertices v0..v4 anticlockwise; the five triangulations are the fans
** T_i = {v_i v_{i+2}, v_i v_{i+3}}.  Quadrilateral Q_j = v_{j+1} v_{j+2}
** v_{j+3} v_{j+4} (vertex v_j deleted) decides the edge T_{j+1} - T_{j-1}:
** RULE_AC (diagonal v_{j+1}v_{j+3}) points it at T_{j+1}, RULE_BD (diagonal
** v_{j+2}v_{j+4}) at T_{j-1}.  Types I-V: docs/classification.md.
*/
#ifndef FLIPLAB_FLIPGRAPH_H
#define FLIPLAB_FLIPGRAPH_H

#include <stdint.h>
#include "census.h"
#include "geom.h"
#include "rule.h"
#include "sampler.h"

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

/* Make the ten triangles and the Delaunay fan of an anticlockwise pentagon. */
void flipgraph_prepare(flipgraph_pentagon *p, const geom_point v[5]);

/* The directed flip graph of p under r. */
void flipgraph_classify(const flipgraph_pentagon *p, const rule *r, double tie_eps,
                        flipgraph *out);

const char *flipgraph_type_name(flipgraph_type t);   /* "I" .. "V" */

/* The graphs of m pentagons v[5i..5i+4] under rules[0..nrules-1], into
** out[i * nrules + r] (the library's batch for `fliplab classify`).  Each
** pentagon goes through geom_polygon_check first, which reverses a
** clockwise one in place keeping its first vertex, as the classify
** command's reader does.  Returns m, or the index of the first pentagon
** refused, with its error in *err and the vertex in *bad (nothing
** classified then).  threads as flipgraph_tally's; no output depends on it. */
size_t flipgraph_classify_n(geom_point *v, size_t m, const rule *rules, int nrules,
                            double tie_eps, int threads, flipgraph *out, geom_polyerr *err,
                            size_t *bad);

/* Classify pentagons first .. first+count-1 of the sampler stream `seed`
** (sampler_pentagon) under every rule and add the outcomes to out[0..nrules-1].
** threads: 0 for all cores, or 1 .. GEOM_MAX_THREADS (any other count is
** refused: -1).  Counts do not depend on the thread count.
** progress (may be NULL) is called now and then from one thread. */
int flipgraph_tally(const rule *rules, int nrules, uint64_t seed, uint64_t first,
                    uint64_t count, double tie_eps, int threads,
                    flipgraph_counts *out, census_progress_fn progress, void *ctx);

/* The same tally with a per-sample hook: each(ctx, thread, index, p, g) is
** called for every pentagon after its classification, with g[0..nrules-1]
** its graphs under the rules, from the thread numbered `thread` (0 <= thread
** < the thread count in use, which is threads, or all cores when threads
** <= 0), so a hook may keep per-thread state without locks.  Pentagons are
** handed out in chunks of ascending indices, in no fixed order between
** threads: a hook that wants "the first K" keeps each thread's first K and
** merges them afterwards (the first K of the union are the first K).
** flipgraph_tally is flipgraph_tally_run without a hook.  run->sampler
** draws the pentagons (NULL: sampler_pentagon); when it runs out of memory
** the tally returns -1. */
typedef void (*flipgraph_sample_fn)(void *ctx, int thread, uint64_t index,
                                    const flipgraph_pentagon *p, const flipgraph *g);
typedef struct flipgraph_run {
  uint64_t seed, first, count;
  double tie_eps;
  int threads;                        /* 0: all cores; 1 .. GEOM_MAX_THREADS */
  census_progress_fn progress;        /* may be NULL */
  void *progress_ctx;
  flipgraph_sample_fn each;           /* may be NULL */
  void *each_ctx;
  sampler_pentagon_fn sampler;        /* NULL: sampler_pentagon (iteration) */
} flipgraph_run;
int flipgraph_tally_run(const rule *rules, int nrules, const flipgraph_run *run,
                        flipgraph_counts *out);

/* The thread count flipgraph_tally_run will use for `threads` and `count`
** pentagons (never more threads than chunks of work). */
int flipgraph_tally_threads(int threads, uint64_t count);

/* ---- additions (helper "table") ---------------------------------------- */

/* flipgraph_tally returns 0, or -1 (out untouched) when a rule is invalid
** (see flipgraph_plan_new), the thread count is outside 0 .. GEOM_MAX_THREADS,
** count would run past 2^64, or memory runs out.
** With threads != 1 the rules' measure and quadrilateral functions are
** called from several threads at once: they must be reentrant. */

/* Index 0..9 in flipgraph_pentagon.tri of triangle v_i v_j v_k (distinct,
** any order, taken mod 5): the triples in lexicographic order 012, 013,
** 014, 023, 024, 034, 123, 124, 134, 234.  -1 if two indices coincide. */
int flipgraph_tri_index(int i, int j, int k);

/* The directed flip graph of five decisions dec[j] of Q_j: type, sinks,
** and delaunay = (type I and sink == delaunay_sink >= 0). */
void flipgraph_from_decisions(const rule_choice dec[5], int delaunay_sink,
                              flipgraph *out);

/* The fast path of flipgraph_tally, for callers classifying each pentagon
** under many rules (same decisions as flipgraph_classify, bit for bit):
** each measure is evaluated once per triangle, rules are grouped by joint,
** DT is decided once.  flipgraph_plan_new copies the rules; NULL when a rule
** names an unknown measure, joint or quadrilateral rule, or out of memory.
** flipgraph_plan_run fills out[0..nrules-1]; a plan may be shared by
** threads (it is read-only after creation). */
typedef struct flipgraph_plan flipgraph_plan;
flipgraph_plan *flipgraph_plan_new(const rule *rules, int nrules, double tie_eps);
void flipgraph_plan_run(const flipgraph_plan *pl, const flipgraph_pentagon *p,
                        flipgraph *out);
void flipgraph_plan_free(flipgraph_plan *pl);

/* The engines behind plans and the site-set census decide in vector lanes
** where the compiler offers them; on = 1 switches every later batch to the
** portable form, 0 back (where vectors exist).  Both give the same bits;
** the tests compare them.  Switch only while no tally runs. */
void flipgraph_use_portable(int on);

#endif
