/*
** splitmix.h: splitmix64 (Steele, Lea and Flood), the one small seeded
** generator of fliplab, and the one way a point uniform in the unit disc is
** drawn.  Used to seed the samplers' streams (samplers/), to draw the sample
** triangles a formula's sign is inferred from (badness/), and by the tests.
** Header-only: both are a handful of integer operations on hot paths.
** Below them, the registry of every random stream fliplab draws from.
*/
#ifndef FLIPLAB_SPLITMIX_H
#define FLIPLAB_SPLITMIX_H

#include <stdint.h>
#include "predicates.h"

/* Advance the counter *x by the golden-ratio increment and return its
** mixed value.  The output function is a bijection of the counter. */
static inline uint64_t geom_splitmix64(uint64_t *x) {
  uint64_t z = (*x += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/* The top 53 bits of a 64-bit draw as a double uniform in [0, 1): every
** value is a multiple of 2^-53, exactly representable. */
static inline double geom_unit53(uint64_t bits) {
  return (double)(bits >> 11) * 0x1.0p-53;
}

/* Rejection sampling of the open unit disc from the square [-1, 1)^2: the
** point 2u-1, 2v-1 of two uniforms u, v in [0, 1) (exact: a power-of-two
** scaling and a subtraction of numbers within a factor of two) is accepted
** when strictly inside the circle; otherwise draw both again. *p is set
** either way.  Acceptance probability pi/4. */
static inline int geom_disc_accept(double u, double v, geom_point *p) {
  double x = 2 * u - 1, y = 2 * v - 1;
  p->x = x;   /* no compound literal: C++ (bench_lot_cgal.cpp) includes this header */
  p->y = y;
  return x * x + y * y < 1;
}

/* ---- the registry of random streams ------------------------------------
**
** Every random number of fliplab comes from one of the streams listed here,
** so that two consumers never share one by accident and a new one can see
** which values are taken.  The values are part of the output contract:
** changing one changes every sample drawn from it (tests/golden.sh).
**
** Streams of sampler_seed(g, seed, stream) (samplers/sampler.h), with the
** user's --seed:
**   GEOM_STREAM_SAMPLE(i)   sample i of a census or table: pentagon i of
**                           every pentagon sampler (table34, rule,
**                           classify's inputs via sample), site set i of
**                           every site sampler (census, rule --sites),
**                           polygon i of `convex` (every n-gon sampler),
**                           configuration i of `linf --montecarlo`; so
**                           sample i depends on (seed, i) alone, whatever
**                           the threads and shards.  Indices run from 0 up
**                           to the 2^40 samples a run may ask for.
**   quadrilateral i         stream i of the seed xor GEOM_SALT_QUAD
**                           (sampler_quad: the Delaunay-equivalence check
**                           of `rule`), unrelated to pentagon i.
**   GEOM_STREAM_GOT_POLYGON `got --random N`: the polygon samplers (star,
**                           monotone, convex, ...) of cli/cmd_got.c; the
**                           simple polygons of `paradigms --problem polygon`.
**   GEOM_STREAM_POINTS      "points" in ASCII: sampler_points, the point
**                           sets of `lot --random`.
**   GEOM_STREAM_BRIO        "brio": lot's biased randomised insertion order.
**   GEOM_STREAM_RANDOM_ORDER "rand": lot's uniformly random insertion order.
**   GEOM_STREAM_PSLG        "pslgraph": the graph samplers that make their own
**                           points (polygons with holes, the rotated grid's
**                           segments) of `sample --sampler holes|grid`.
**   GEOM_STREAM_SEGMENTS    "segments": the segments sampler_segments draws
**                           on a point set drawn from GEOM_STREAM_POINTS
**                           (`sample --sampler segments`, the benchmark,
**                           `paradigms --problem constrained`).
**   GEOM_STREAM_CPDT        "cpdt": xored into the seed of the randomised
**                           convex-polygon Delaunay algorithms (cpdt/: the
**                           random sides, the random insertion order).
**   GEOM_STREAM_CPDT_GON(n, t) "cpdtgon": polygon t of size n of the
**                           experiment of `fliplab cpdt` (studies/), the
**                           size times the 64-bit golden ratio xored in
**                           (above 2^62 for every n and t it takes).
** One run never draws two of these from one seed under the same number:
** lot draws its points, then one order, and no samples; "points" (about
** 1.2e14) lies above every sample index anyway; got draws only its polygon
** (stream 0, which is sample 0's stream of another command); the two graph
** streams, above 2^62, are taken by `sample` alone and lie above every
** sample index too.
**
** Fixed generator states (no user seed):
**   GEOM_STATE_FORMULA_SIGNS the splitmix64 counter of the sample triangles
**                           a user formula's sign is inferred from
**                           (badness/formula.c): the same triangles every run.
**   GEOM_STATE_LOT_WALK     the xorshift64 state of the mesh's point-location
**                           walk (lot/mesh.c), reset with every mesh.
**   GEOM_STATE_LOT_SWEEP    the splitmix64 counter of the tower heights of
**                           the sweepline's skip list (lot/sweep.c): the
**                           same structure, and so the same run, every time. */
#define GEOM_STREAM_SAMPLE(i) ((uint64_t)(i))
#define GEOM_SALT_QUAD 0x51A7C0DE5EEDF00Dull
#define GEOM_STREAM_GOT_POLYGON 0ull
#define GEOM_STREAM_POINTS 0x706f696e7473ull          /* "points" */
#define GEOM_STREAM_BRIO 0x6272696full                /* "brio" */
#define GEOM_STREAM_RANDOM_ORDER 0x72616e64ull        /* "rand" */
#define GEOM_STREAM_PSLG 0x70736c6772617068ull        /* "pslgraph" */
#define GEOM_STREAM_SEGMENTS 0x7365676d656e7473ull    /* "segments" */
#define GEOM_STREAM_CPDT 0x63706474ull                /* "cpdt" */
#define GEOM_STREAM_CPDT_GON(n, t) \
  ((0x63706474676f6eull << 8) ^ ((uint64_t)(n) * 0x9e3779b97f4a7c15ull >> 2) ^ (uint64_t)(t))
#define GEOM_STATE_FORMULA_SIGNS 0x5EED5167ull
#define GEOM_STATE_LOT_WALK 0x9e3779b97f4a7c15ull
#define GEOM_STATE_LOT_SWEEP 0x5357454550ull                /* "SWEEP" */

#endif
