/*
** triavg_internal.h: the enumerator of every triangulation of a convex
** polygon and the per-diagonal terms it shares with study_tri_measure
** (studies/trienum.c), and the exact values behind study_avg (triavg.c).
*/
#ifndef FLIPLAB_TRIAVG_INTERNAL_H
#define FLIPLAB_TRIAVG_INTERNAL_H

#include <gmp.h>
#include <stdint.h>
#include "fliplab_config.h"
#include "triavg.h"

#define STUDY_ENUM_VMAX (STUDY_AVG_ENUM_NMAX + 2)   /* vertices of the largest polygon */

/* What diagonal p_i p_j (i < j, j - i >= 2) of the N-gon adds to a
** triangulation's sums: the vertices the circumcircle algorithm scans in the
** piece p_i .. p_j (the side of the diagonal away from the root side
** p_0 p_{N-1}, so j - i - 1 of them); 1 if it crosses the cut after p_k;
** its index length.  One home for the three, read by the enumerator and by
** study_tri_measure. */
static inline void study_diag_terms(uint32_t i, uint32_t j, uint32_t nv, uint32_t k,
                                    uint64_t t[3]) {
  uint32_t span = j - i;
  t[0] = span - 1;
  t[1] = (i <= k && k < j);
  t[2] = span < nv - span ? span : nv - span;
}

/* An enumeration in progress over the triangulations of the (n+2)-gon.
** A triangulation is built by one pass over p_1 .. p_{N-1} with a stack of
** the open chain: at p_v it pops c_v vertices, each pop closing the
** triangle (below, top, p_v) with the new edge (below, p_v), then pushes
** p_v; every sequence with c_v <= (stack size - 1), the last vertex popping
** down to p_0, is one triangulation and each triangulation is one sequence.
** The enumeration is a depth-first walk of these sequences with the sums
** of the current triangulation kept as diagonals come and go: O(1)
** amortised per triangulation beyond the O(N) at its last vertex. */
typedef struct study_trienum {
  int nv, cut, started;
  int sz;                                   /* the open chain: stack[0 .. sz-1] */
  uint8_t stack[STUDY_ENUM_VMAX];
  int h[STUDY_ENUM_VMAX], c[STUDY_ENUM_VMAX];   /* chain size before p_v, pops at p_v */
  uint8_t saved[STUDY_ENUM_VMAX];           /* what p_v's push overwrote */
  int ndiag;
  uint8_t diag[STUDY_ENUM_VMAX][2];         /* the current diagonals, i < j */
  uint8_t deg[STUDY_ENUM_VMAX];             /* interior degrees */
  uint64_t sum[3];                          /* tc - n, cross, len_sum (study_diag_terms) */
} study_trienum;

/* Start an enumeration of the (n+2)-gon (1 <= n <= STUDY_AVG_ENUM_NMAX);
** each study_trienum_next then makes e hold the next triangulation
** (diagonals, degrees, sums) and returns 1, or returns 0 after the last. */
FLIPLAB_INTERNAL void study_trienum_start(study_trienum *e, int n);
FLIPLAB_INTERNAL int study_trienum_next(study_trienum *e);

/* The totals of a whole enumeration of the (n+2)-gon. */
typedef struct study_enum_totals {
  int n;
  uint64_t count;                         /* C_n */
  uint64_t tc, tc_min, tc_max;            /* sum, least and greatest T_c */
  uint64_t cross;                         /* sum of the crossing counts */
  uint64_t len, len_min, len_max;         /* of len_sum = (n-1) L(D) */
  uint64_t hist[STUDY_ENUM_VMAX][STUDY_ENUM_VMAX];   /* [vertex][interior degree] */
} study_enum_totals;

/* Enumerate the (n+2)-gon into t: the degree histogram of every vertex, or
** (every_vertex == 0, O(1) per triangulation) of p_n and p_{n+1} only,
** the two that G^d_n and T_i read. */
FLIPLAB_INTERNAL void study_enum_run(int n, int every_vertex, study_enum_totals *t);

/* The exact value behind study_avg_text (0: it does not exist). */
FLIPLAB_INTERNAL int study_avg_value(const study_avg *a, int kind, int enumerated, mpq_t out);

/* The closed forms one by one (n in range, as study_avg_new checks), and
** the second routes the tests compare them with: T_c as n plus the sum over
** diagonals of the vertices each one's piece holds, L_a as the sum over
** chords of length times frequency, T_i as the sum of 2(i-1)/(i+2). */
FLIPLAB_INTERNAL void study_avg_closed(int kind, int n, mpq_t out);
FLIPLAB_INTERNAL void study_avg_tc_by_chords(int n, mpq_t out);
FLIPLAB_INTERNAL void study_avg_la_by_chords(int n, mpq_t out);
FLIPLAB_INTERNAL void study_avg_ti_by_sum(int n, mpq_t out);
FLIPLAB_INTERNAL void study_avg_degcount(int n, int d, mpz_t out);

#endif
