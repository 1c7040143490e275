/*
** paradigm.h: every triangulation algorithm of chapter 2 behind one registry,
** exact and instrumented (docs/paradigms.md).
**
** Chapter 2 classifies triangulation algorithms by paradigm (flip,
** incremental, selection, sweepline, divide and conquer) and by problem
** (Delaunay and the empty-shape rules, constrained, simple polygon, convex
** polygon).  Each algorithm here is one row of paradigm_algorithms: its
** name, paradigm, section, the problems it serves (and, for the others, why
** not), its cost, and one function of the signature paradigm_fn.  The
** runner (paradigm_run) does what every row would otherwise repeat: it
** validates the input (coordinates, a rule it can use), merges exact
** duplicates (each point's index becomes its first occurrence's, as lot/
** does), hands the algorithm the distinct points, maps the triangles back to
** input indices, counts the exact fallbacks and the time, and writes the
** triangles in one canonical order, so that two algorithms agree exactly
** when their outputs are equal arrays.
*/
#ifndef FLIPLAB_PARADIGM_H
#define FLIPLAB_PARADIGM_H

#include <stddef.h>
#include <stdint.h>
#include "geom.h"
#include "ops.h"
#include "rule.h"

/* The problems of chapter 2 (a bit set in paradigm_algorithm.problems). */
typedef enum paradigm_problem {
  PARADIGM_DELAUNAY = 1,      /* unconstrained: DT, or an empty-shape rule ES:SHAPE */
  PARADIGM_CONSTRAINED = 2,   /* constrained Delaunay: segments given */
  PARADIGM_POLYGON = 4,       /* a simple polygon (the points in boundary order) */
  PARADIGM_CONVEX = 8         /* a convex polygon (the points in boundary order) */
} paradigm_problem;

/* What an algorithm is given: distinct points within the coordinate
** contract, not all collinear (the runner checks), 0-based indices, and
** the problem as the caller gave it.  For PARADIGM_POLYGON and
** PARADIGM_CONVEX the order of the points matters: it is the boundary's
** (a simple polygon either way round; a convex one anticlockwise), so the
** runner refuses a repeated vertex rather than merge it, and the distinct
** points keep the input's order. */
typedef struct paradigm_input {
  const geom_point *p;
  size_t n;
  const rule *r;              /* DT or ES:SHAPE (the in-shape test); never NULL */
  paradigm_problem problem;
  const uint32_t *segments;   /* PARADIGM_CONSTRAINED: 2 per segment */
  size_t nsegments;
  uint64_t seed;              /* randomised algorithms: same seed, same run */
  int threads;                /* 1 .. GEOM_MAX_THREADS; output identical for any */
  double param;               /* the algorithm's parameter (bucket size ...); 0: its default */
} paradigm_input;

/* What it returns: ntri triangles, 3 indices each, anticlockwise, and its
** counts.  The runner frees tri on failure. */
typedef struct paradigm_output {
  uint32_t *tri;
  size_t ntri;
  ops_counts ops;
} paradigm_output;

/* 0, or -1 with a one-line message (out of memory, a problem it refuses). */
typedef int (*paradigm_fn)(const paradigm_input *in, paradigm_output *out, char *err,
                           size_t errlen);

typedef struct paradigm_algorithm {
  const char *name;           /* "incremental", "dc-alternating", ... */
  const char *paradigm;       /* "flip", "incremental", "selection", "sweepline", "divide" */
  const char *section;        /* the thesis's section, "2.6.1" */
  unsigned problems;          /* the paradigm_problem bits it serves */
  unsigned rules;             /* PARADIGM_RULE_* it serves for PARADIGM_DELAUNAY */
  const char *refusal;        /* why it does not serve the other problems or rules */
  const char *cost;           /* its cost, as stated above its code */
  const char *param;          /* what in->param means, or NULL */
  paradigm_fn run;
} paradigm_algorithm;

#define PARADIGM_RULE_DT 1u   /* the Delaunay rule */
#define PARADIGM_RULE_ES 2u   /* every empty-shape rule ES:SHAPE */

/* The registry: paradigm_get(i) for i < paradigm_count(), or by name. */
size_t paradigm_count(void);
const paradigm_algorithm *paradigm_get(size_t i);
const paradigm_algorithm *paradigm_find(const char *name);
const char *paradigm_problem_name(paradigm_problem pb);

/* What a run gives back: triangles in input indices, canonical order (each
** triangle rotated to start at its smallest index, then sorted), the
** counts (OPS_EXACT from geom_exact_calls: run one at a time in a process
** to read it), the wall time and the distinct points. */
typedef struct paradigm_result {
  uint32_t *tri;
  size_t ntri;
  ops_counts ops;
  double seconds;
  size_t distinct;
} paradigm_result;

/* Run algorithm a on in (in->p and in->n the input as given: duplicates
** allowed).  0; or -1 with a one-line message: a problem or rule the
** algorithm does not serve (its refusal), a coordinate outside the contract
** (naming the point), fewer than three distinct points, all collinear, out
** of memory, or the algorithm's own error. */
int paradigm_run(const paradigm_algorithm *a, const paradigm_input *in, paradigm_result *out,
                 char *err, size_t errlen);
void paradigm_result_free(paradigm_result *r);

/* Sort triangles into the canonical order above (used by the runner; for
** tests comparing with lot's output).  O(t + n) for a triangulation's
** triangles (a bucket sort by the smallest index); O(t log t) otherwise. */
void paradigm_canonical(uint32_t *tri, size_t ntri);

#endif
