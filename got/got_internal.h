/*
** got_internal.h: what the files of got/ share and nobody else needs.
*/
#ifndef FLIPLAB_GOT_INTERNAL_H
#define FLIPLAB_GOT_INTERNAL_H

#include "fliplab_config.h"
#include "got.h"

/* On x86-64 Linux with GCC the bulk loops (kernels, keys, log) are also
** compiled for AVX-512F and AVX2 and picked at run time (an ifunc): four
** or two times the lanes of the SSE2 baseline.  With -std=c11 GCC does not contract a*b+c into an
** FMA, so both versions perform the same IEEE operations and give
** bit-identical results on any x86-64 machine. */
#if FLIPLAB_HAVE_CLONES
#define GOT_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define GOT_CLONES
#endif

/* Number of n x n double tables the measure's kernel reads (0, 1 or 2). */
FLIPLAB_INTERNAL int got_kernel_tables(int measure);

/* Measures defined as the square root of something (sigma) can hand out
** b^2 directly: the l_2 key is b^2 and the l_0 key is log(b^2) / 2, so
** the sqrt is skipped (the keys then differ from joint_key(b) in the last
** bit only).  got_pairs_new_sq makes got_pairs_eval return b^2. */
FLIPLAB_INTERNAL int got_measure_has_square(int measure);
FLIPLAB_INTERNAL
got_pairs *got_pairs_new_sq(const geom_point *p, size_t n, int measure, int threads);

/* Bulk math for the kernels and keys (see got_kernels.c for accuracy). */
FLIPLAB_INTERNAL void got_sqrt_inplace(double *t, size_t m);
FLIPLAB_INTERNAL
void got_log_inplace(double *t, size_t m, double sign);   /* sign * log(sign * t) */

/* How a measure value becomes a key in bulk (got_dp.c: from the key shape
** of the joint table and the measure's sign; POWER is +-|x|^p, joint.h). */
typedef enum got_keyfn {
  GOT_KEY_IDENT, GOT_KEY_SQ, GOT_KEY_NEGSQ, GOT_KEY_NEGRECIP,
  GOT_KEY_LOG, GOT_KEY_NEGLOGNEG, GOT_KEY_POWER,
  GOT_KEY_FROM_SQ_IDENT, GOT_KEY_FROM_SQ_HALFLOG   /* kernel gives b^2 (got_measure_has_square) */
} got_keyfn;

/* The key shape of a joint's row for measures of sign s (got_dp.c). */
FLIPLAB_INTERNAL got_keyfn got_keyfn_of(joint_shape sh, int s);

/* The certified verdict (got_cert.c): from the DP's keys, the rule's key
** shape and the polygon, fill res->cert_* (see got.h). */
FLIPLAB_INTERNAL
void got_certify(got_result *res, const geom_point *p, size_t n, got_keyfn keyfn,
                 joint_keyop op);

/* Bytes of physical memory (got_check_memory allows 3/4 of it). */
FLIPLAB_INTERNAL size_t got_phys_memory(void);

/* The error model of one triangle key rule_key(r, measure_eval(...)) for
** triangles with vertices among p[0..n-1] (got_cert.c): |k^ - k| <= rho
** |k^| + alpha for the exact key k (the measures without a DP kernel bound
** included where measure_eval's value has one: got_eval_errmodels).  0, or
** -1 with *why saying why no bound is known (docs/got.md, "Certified
** verdicts": that measure and joint, a user measure, the scale guard). */
FLIPLAB_INTERNAL
int got_cert_model(const geom_point *p, size_t n, const rule *r, double *rho, double *alpha,
                   const char **why);
/* E(K) for a sum (joint key +) of m such keys whose floating total, in any
** order of addition, is key: |exact - key| <= E (INFINITY when key is not
** finite). */
FLIPLAB_INTERNAL double got_cert_err_sum(double rho, double alpha, size_t m, double key);

/* got_solve, with force_mask = 1 running the simple-polygon (masked)
** programme even on convex input (tests and benchmarks compare the two). */
FLIPLAB_INTERNAL
int got_solve_ex(const geom_point *p, size_t n, const rule *r, const got_options *opt,
                 int force_mask, got_result *out, char *err, size_t errlen);

#endif
