/*
** fliplab_config.h: the floating-point model fliplab is built for, checked
** at compile time, and the home of compiler and feature guards.
**
** fliplab promises bit-identical output whatever the compiler, -march,
** thread count or shard split, and its exactness arguments (the predicate
** filters of geom.h, the joints' exact commutativity, the flip-graph
** filters) assume that every double operation is one correctly rounded
** IEEE 754 binary64 operation, done where the source says.  Three things
** break that, so all three are part of the build contract:
**
** - Excess precision (x87 arithmetic, FLT_EVAL_METHOD 1 or 2): an
**   intermediate kept in a wider register rounds twice or not at all.
**   Refused below.
** - Fast-math (-ffast-math, -ffinite-math-only, -fassociative-math ...):
**   reassociation, reciprocal approximations and "no NaN/inf" assumptions
**   change decisions and break the NaN-means-tie convention.  Refused below.
** - Contraction of a*b + c into a fused multiply-add: clang does it by
**   default with -march=haswell, GCC outside strict ISO mode.  One rounding
**   instead of two changes x*x + y*y depending on the operand order, so
**   commutativity and rotation invariance fail.  The build passes
**   -ffp-contract=off to everything (top CMakeLists.txt) and pkg-config
**   hands it to plugins (fliplab.pc); for clang the pragma below also turns
**   it off in every file that includes geom.h, whatever the flags.  (GCC
**   ignores the pragma; it has no macro telling whether contraction is on.)
**
** Every public header includes this one through geom.h (predicates.h, the
** lowest header, includes it directly).  The rest of the code asks the
** feature macros at the end, never the compiler: what each one turns on is
** the same IEEE arithmetic (vector extensions, SSE2 square roots, function
** clones chosen at load time), so a build with or without them gives the
** same bits.
*/
#ifndef FLIPLAB_CONFIG_H
#define FLIPLAB_CONFIG_H

#include <float.h>

#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "fliplab needs FLT_EVAL_METHOD == 0 (double arithmetic in double precision; on x86 use SSE2, e.g. -msse2 -mfpmath=sse)"
#endif

#if defined(__FAST_MATH__)
#error "fliplab must not be built with -ffast-math: decisions depend on IEEE rounding, NaN and infinities"
#endif

#if defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
#error "fliplab must not be built with -ffinite-math-only: NaN and infinite values carry meaning"
#endif

#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

/* ---- compiler features ---------------------------------------------------- */

/* printf-style format checking of a function's arguments. */
#if defined(__GNUC__)
#define FLIPLAB_PRINTF(fmt, first) __attribute__((format(printf, fmt, first)))
#else
#define FLIPLAB_PRINTF(fmt, first)
#endif

/* Rare slow paths (exact arithmetic) kept out of line, so the filters that
** call them stay small enough to inline into hot loops. */
#if defined(__GNUC__)
#define FLIPLAB_COLD __attribute__((noinline, cold))
#else
#define FLIPLAB_COLD
#endif

/* Out of line but compiled for speed: the body behind a cold entry point
** that some inputs reach often (the exact predicates' integer stage on
** grids; a cold function is optimised for size, and so is all it inlines). */
#if defined(__GNUC__)
#define FLIPLAB_NOINLINE __attribute__((noinline))
#else
#define FLIPLAB_NOINLINE
#endif

/* A function (or object) declared in a *_internal.h header: shared by the
** files of libfliplab, never part of its interface.  Hidden, so that a
** shared build of the library exports only what the public headers
** declare (as Lua's LUAI_FUNC); a static library and its tests link as
** before.  Every declaration of a *_internal.h header carries it. */
#if defined(__GNUC__)
#define FLIPLAB_INTERNAL __attribute__((visibility("hidden"))) extern
#else
#define FLIPLAB_INTERNAL extern
#endif

/* A small helper that must be inlined into its caller, so that a constant
** argument (shape_arith.c's double run) folds away. */
#if defined(__GNUC__)
#define FLIPLAB_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define FLIPLAB_ALWAYS_INLINE inline
#endif

/* GCC/Clang generic vectors (vector_size) and always_inline. */
#if defined(__GNUC__)
#define FLIPLAB_HAVE_VECTORS 1
#else
#define FLIPLAB_HAVE_VECTORS 0
#endif

/* SSE2 intrinsics (<emmintrin.h>): the correctly rounded sqrtpd. */
#if defined(__SSE2__)
#define FLIPLAB_HAVE_SSE2 1
#else
#define FLIPLAB_HAVE_SSE2 0
#endif

/* Function clones for wider vector units, picked at load time (an ifunc):
** GCC on x86-64 Linux only.  Every clone performs the same IEEE basic
** operations, so they give the same bits. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define FLIPLAB_HAVE_CLONES 1
#else
#define FLIPLAB_HAVE_CLONES 0
#endif

#endif
