/*
** triavg.h: chapter 5's exact averages over all triangulations of a convex
** polygon (docs/averages.md).
**
** P is the (n+2)-gon p_0 .. p_{n+1}; its C_n triangulations are taken as
** equally likely, and every quantity depends on the triangulation alone,
** not on coordinates.  For each quantity this module gives its closed form
** as an exact rational for any n in [1, STUDY_AVG_NMAX] and, for n up to
** STUDY_AVG_ENUM_NMAX, the same average found by enumerating every
** triangulation; also the quantities of one given triangulation:
**   - study_avg_new: every closed form (and with `enumerate` every
**     enumerated average) of the (n+2)-gon, read as text ("p/q", exact) or
**     as a double by study_avg_text / study_avg_double, the degree counts
**     G^d_n by study_avg_degcount_text;
**   - study_tri_measure: T_c, the crossing count, the index lengths and the
**     interior degrees of a given triangulation of the N-gon.
*/
#ifndef FLIPLAB_TRIAVG_H
#define FLIPLAB_TRIAVG_H

#include <stddef.h>
#include <stdint.h>

/* The largest n of a closed form (its sums take O(n^2) word operations:
** a few seconds at the bound) and of an enumeration (C_18 = 477,638,700
** triangulations of the 20-gon, and a third more for T_i's smaller
** polygons: about 20 s of CPU). */
#define STUDY_AVG_NMAX 100000
#define STUDY_AVG_ENUM_NMAX 18

/* The quantities, in the order study_avg_name lists them:
**   TC      vertices scanned by the circumcircle algorithm building on the
**           newest side, from side p_0 p_{n+1} (thesis 5.4.1): the mean;
**   TC_MIN, TC_MAX  its least and greatest value over the triangulations;
**   CROSS   diagonals crossing the cut from the middle of p_{n+1} p_0 to the
**           middle of p_k p_{k+1}, k = floor(n/2) (the divide-and-conquer
**           merge, 5.4.2): the mean (the thesis's A for the (2m+2)-gon is
**           this at n = 2m);
**   LA      L(D), the mean index length min(j-i, n+2-j+i) of the n-1
**           diagonals of D (5.5): its mean over D (n >= 2);
**   LMIN, LMAX  the least and greatest L(D) (n >= 2);
**   DEGREE  the interior degree of one vertex (any: they share a law): the
**           mean;
**   TI      flips of the incremental algorithm in input order (5.4.3): the
**           sum over i = 1..n of the mean interior degree of the newest
**           vertex of the (i+2)-gon, each prefix's triangulation uniform. */
typedef enum study_avg_kind {
  STUDY_AVG_TC, STUDY_AVG_TC_MIN, STUDY_AVG_TC_MAX, STUDY_AVG_CROSS, STUDY_AVG_LA,
  STUDY_AVG_LMIN, STUDY_AVG_LMAX, STUDY_AVG_DEGREE, STUDY_AVG_TI, STUDY_AVG_COUNT
} study_avg_kind;

typedef struct study_avg study_avg;

/* The short name of quantity i ("Tc", "A", ...; NULL past the last) and
** its one-line description. */
const char *study_avg_name(int i);
const char *study_avg_about(int i);

/* Every closed form of the (n+2)-gon, and with enumerate != 0 every
** average by enumeration (n <= STUDY_AVG_ENUM_NMAX).  NULL with a one-line
** err when n is out of range or memory runs out. */
study_avg *study_avg_new(int n, int enumerate, char *err, size_t errcap);
void study_avg_delete(study_avg *a);

/* Quantity `kind`, closed form (enumerated == 0) or enumeration, as exact
** text "p/q" (or "p") in base 10, or 16 when hex is set (Python reads that
** one: its decimal conversion stops at 4300 digits), in buf, as snprintf
** does: the length of the whole text is returned, at most cap - 1 bytes
** and a NUL are written.  0 when the value does not exist (L at n = 1; no
** enumeration made).  The double is the nearest below or equal (NaN when
** the value does not exist). */
size_t study_avg_text(const study_avg *a, int kind, int enumerated, int hex, char *buf,
                      size_t cap);
double study_avg_double(const study_avg *a, int kind, int enumerated);

/* G^d_n, the number of triangulations in which p_n has interior degree d
** (0 <= d <= n-1), closed form or enumerated, as text as above (0 when d
** is out of range or no enumeration was made). */
size_t study_avg_degcount_text(const study_avg *a, int d, int enumerated, int hex, char *buf,
                               size_t cap);

/* ---- one triangulation ---------------------------------------------------- */

/* The quantities of one triangulation D of the convex N-gon p_0 .. p_{N-1}
** (N >= 3): tc, vertices the newest-side circumcircle algorithm scans from
** side p_0 p_{N-1}; cross, diagonals crossing the cut of STUDY_AVG_CROSS
** (k = floor((N-2)/2)); len_sum, the sum of the index lengths of the N-3
** diagonals (L(D) = len_sum / (N-3)).  Three uint64_t in this order (the
** Python package reads it as such an array). */
typedef struct study_tri_stats {
  uint64_t tc, cross, len_sum;
} study_tri_stats;

/* Measure the triangulation given as N-2 triangles (rows of three vertex
** indices, any order), and when degree is not NULL write the interior
** degree of each vertex in degree[0..N-1].  O(N log N) time, O(N) space.
** 0, or -1 with a one-line err naming the triangle at fault when the
** triangles are not a triangulation of the N-gon. */
int study_tri_measure(const uint32_t *tri, size_t ntri, uint32_t nv, study_tri_stats *out,
                      uint32_t *degree, char *err, size_t errcap);

#endif
