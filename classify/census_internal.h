/*
** census_internal.h: the scaffolding both census engines of classify/
** stand on (census.c), the pentagon plans of flipgraph.c and the site-set
** census of sitecensus.c: one plan of the rules (checked, one slot per
** distinct measure with its sign, the joints in use) and one deterministic
** chunked parallel loop.  Each engine keeps its own representation of the
** work (quadvec's decision codes for pentagons, BD bits and sink masks for
** site sets) behind these.  Not installed.
*/
#ifndef FLIPLAB_CENSUS_INTERNAL_H
#define FLIPLAB_CENSUS_INTERNAL_H

#include "census.h"
#include "measure.h"
#include "quadvec_internal.h"
#include "rule.h"

/* Columns of the per-triangle value tables: every measure, padded. */
#define CENSUS_SLOTS QUADVEC_PAD(MEASURE_MAX)

typedef enum census_kind {
  CENSUS_TRIANGLE,   /* MEASURE_JOINT: decided by quadvec from its slot */
  CENSUS_DT,         /* the Delaunay rule: decided once per sample, exactly */
  CENSUS_QUAD        /* another quadrilateral rule (a plugin): one call per quadrilateral */
} census_kind;

typedef struct census_item {
  census_kind kind;
  int slot;          /* CENSUS_TRIANGLE: the column of its measure */
  joint_id joint;    /* CENSUS_TRIANGLE */
} census_item;

/* Slots are in increasing measure order, so that runs of consecutive
** measures copy as blocks out of measure_eval_all.  Padding lanes up to
** QUADVEC_PAD(nslots) have sign 1.0 (quadvec's contract). */
typedef struct census_plan {
  const rule *rules;                 /* not copied: the caller keeps them */
  int nrules;
  census_item *item;                 /* [nrules] */
  int nslots;
  int slot_measure[MEASURE_MAX];
  double slot_sign[CENSUS_SLOTS];    /* -1.0 for measures <= 0, else 1.0 */
  int joint_used[JOINT_CAPACITY];    /* some triangle rule has this joint */
  int ndt, nquad;                    /* rules of kind CENSUS_DT, CENSUS_QUAD */
  int eval_all_ok;                   /* measure_eval_all runs no user measure
                                        (maybe a slow formula) the plan does not need */
} census_plan;

/* 0; -1 for a rule naming an unknown measure, joint or quadrilateral rule;
** -2 out of memory.  census_plan_free after either (it frees the items). */
FLIPLAB_INTERNAL int census_plan_make(census_plan *pl, const rule *rules, int nrules);
FLIPLAB_INTERNAL void census_plan_free(census_plan *pl);

/* The loop.  Samples [first, first + count) are cut into chunks of `chunk`
** ascending indices handed out dynamically to `threads` threads; range(ctx,
** thread, lo, hi) does one chunk, adding into the thread's own counts
** (0 <= thread < threads), and returns 0 or -1 (out of memory: the other
** chunks are skipped).  Counts are integer sums, so neither the thread
** count nor the schedule can change them.  0, or -1 when a chunk failed. */
typedef int (*census_range_fn)(void *ctx, int thread, uint64_t lo, uint64_t hi);
typedef struct census_loop {
  uint64_t first, count, chunk;
  int threads;                       /* census_threads's */
  census_range_fn range;
  void *ctx;
  census_progress_fn progress;       /* may be NULL */
  void *progress_ctx;
} census_loop;
FLIPLAB_INTERNAL int census_loop_run(const census_loop *l);

/* The thread count for `threads` (0, or any invalid count: all cores,
** geom_threads_clamp): never more threads than
** chunks of work, and at least one. */
FLIPLAB_INTERNAL int census_threads(int threads, uint64_t count, uint64_t chunk);

#endif
