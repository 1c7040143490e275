/*
** linf.h: the l_inf circumballs (axis-parallel circumcubes) of d + 1
** points in R^d, 2 <= d <= 8, and the l_inf Delaunay simplices of a small
** point set, exactly (the thesis's section 4.2; docs/linf.md).
**
** Points are rows of d doubles inside the coordinate contract of geom.h
** (integers up to 1e30 among them).  A circumcube of d + 1 points is a cube
** {x : |x_i - c_i| <= r for every i} with r > 0 and every point on its
** boundary.  The points fit in a cube of radius r only when 2r >= D, their
** l_inf diameter (the largest extent D_i = max_j p_ji - min_j p_ji), and a
** point lies on the cube's max-i face only if it is an i-maximum (its
** min-i face: an i-minimum).  So every circumcube of radius D/2 is a choice
** per coordinate: a coordinate of extent D has both faces at the points'
** extremes (the "forced" ones); any other coordinate has its max face at
** the i-maxima or its min face at the i-minima, and the choice is a
** circumcube when every point lies on one of the chosen faces.  There are
** infinitely many circumcubes ("truly degenerate" points) when a cover
** leaves a coordinate free to slide, or when the points are covered without
** a forced coordinate (then every radius above D/2 has one).  Otherwise
** there are finitely many, each the cube of radius D/2 of one choice.
**
** Every decision is exact: the comparisons of coordinates directly, the
** sums of four coordinates (an extent against the diameter, a point against
** a face at distance D) by floating-point expansions, orientations of d + 1
** points by GMP rationals.
*/
#ifndef FLIPLAB_LINF_H
#define FLIPLAB_LINF_H

#include <stddef.h>
#include <stdint.h>

#define LINF_DIM_MIN 2
#define LINF_DIM_MAX 8
/* The most circumcubes d + 1 points can have when they are finitely many:
** one per max/min choice of the d - 1 or fewer unforced coordinates. */
#define LINF_CUBES_MAX (1 << (LINF_DIM_MAX - 1))
/* linf_circumcubes' answer for infinitely many. */
#define LINF_INFINITE (-1)
/* The most points of a set the Delaunay verbs take (an index fits a byte,
** and their O(n^{d+1}) brute force is meant for small sets). */
#define LINF_POINTS_MAX 64

/* A circumcube of radius D/2, exactly: coordinate i spans the interval
** [face[i] - D, face[i]] when side[i] is +1 (its max face holds points),
** [face[i], face[i] + D] when -1 (its min face does), and both faces hold
** points when it is 0 (forced: face[i] is the i-maximum, face[i] - D the
** i-minimum).  D = top - bottom exactly (the extent of a forced
** coordinate), so that nothing here is rounded. */
typedef struct linf_cube {
  int d;
  signed char side[LINF_DIM_MAX];
  double face[LINF_DIM_MAX];
  double top, bottom;
} linf_cube;

/* The circumcubes of the d + 1 points pts[0 .. (d+1)d): their number (at
** most LINF_CUBES_MAX, written to out, which has room for that many), or
** LINF_INFINITE (out unwritten).  Cost O(2^d d^2) (the covers of at most
** d coordinates, as bit masks over the points).  The caller keeps d in
** LINF_DIM_MIN .. LINF_DIM_MAX and the coordinates inside the contract
** (geom_coord_check_n): the verbs of this header take both as given,
** except those with an error return, which refuse a d out of range. */
int linf_circumcubes(const double *pts, int d, linf_cube *out);

/* Where q (d coordinates) lies: -1 strictly inside the cube, 0 on its
** boundary, +1 outside.  Cost O(d), exact. */
int linf_cube_side(const linf_cube *c, const double *q);

/* The cube's centre and radius, or the l_inf distance from its centre to q
** (q NULL: the radius), exactly, as decimal text ("4", "4.5", "-0.125":
** every quantity is a dyadic rational); buf of len bytes, truncated text
** ends in "...".  linf_cube_centre writes "(c_1, ..., c_d)". */
void linf_cube_centre(const linf_cube *c, char *buf, size_t len);
void linf_cube_distance(const linf_cube *c, const double *q, char *buf, size_t len);

/* The orientation of d + 1 points (rows of pts): the sign of the
** determinant of p_1 - p_0, ..., p_d - p_0; 0 when they lie in one
** hyperplane.  Exact (GMP rationals), cost O(d^3) rational operations. */
int linf_orient(const double *pts, int d);

/* Is the facet f (d indices into the n rows of pts) a facet of their
** convex hull: its points span a hyperplane with no point strictly on
** each side?  Cost O(n) orientations. */
int linf_hull_facet(const double *pts, size_t n, int d, const unsigned char *f);

/* Theorem 14: the most circumcubes of non-degenerate d + 1 points,
** 2^floor((d - 1) / 2), and the configuration that attains it (the thesis's
** R^5 example, generalised): d + 1 rows written to pts. */
int linf_bound(int d);
void linf_extremal(int d, double *pts);

/* ---- l_inf Delaunay simplices of a small set ---------------------------
**
** A simplex of d + 1 of the n points (n <= LINF_POINTS_MAX) is l_inf
** Delaunay when its points are affinely independent and one of its
** circumcubes has no point of the set strictly inside.  A list holds
** simplices as d + 1 increasing indices each. */
typedef struct linf_simplices {
  int d;
  size_t n, cap;
  unsigned char *v;      /* n rows of d + 1 indices */
} linf_simplices;

/* What the selection algorithm did. */
typedef struct linf_select_stats {
  uint64_t facets;       /* facets searched */
  uint64_t hull_facets;  /* hull facets found, each a starting facet */
  uint64_t cube_tests;   /* point-in-circumcube tests */
  uint64_t largest_set;  /* the largest candidate set s */
  uint64_t degenerate;   /* candidates skipped: infinitely many circumcubes */
} linf_select_stats;

/* A row of at most 9 indices below 64 as one key, 6 bits each, the first
** highest: keys compare as the rows do lexicographically. */
uint64_t linf_row_key(const unsigned char *v, int w);
/* The next m-subset of 0 .. n-1 (c: m increasing indices) in lexicographic
** order; 0 after the last. */
int linf_next_subset(unsigned char *c, int m, size_t n);

void linf_simplices_init(linf_simplices *s, int d);
void linf_simplices_free(linf_simplices *s);
/* Is the simplex (d + 1 increasing indices) in the list?  Cost O(log n). */
int linf_simplices_has(const linf_simplices *s, const unsigned char *v);

/* Every l_inf Delaunay simplex, by brute force: all (d+1)-subsets, each
** circumcube tested against every point.  O(n^{d+2} 2^d d) time.  Sorted.
** 0, or -1 when memory ran out, d is out of range or n > LINF_POINTS_MAX.  Sets with infinitely many circumcubes are
** counted in *degenerate (may be NULL) and skipped. */
int linf_delaunay_brute(const double *pts, size_t n, int d, linf_simplices *out,
                        uint64_t *degenerate);

/* The selection algorithm of section 4.2.2: a traversal of facets from
** every hull facet; on each facet a set of candidates (a point and its
** circumcubes not yet found non-empty) in two passes over the points.  It
** finds every Delaunay simplex reachable through shared facets from a
** hull facet.  Sorted.  0, or -1 as linf_delaunay_brute. */
int linf_delaunay_select(const double *pts, size_t n, int d, linf_simplices *out,
                         linf_select_stats *st);

/* ---- the circumcube count of random points -------------------------------
**
** For d + 1 points independent and uniform in a box (any continuous law
** with independent coordinates), the number of circumcubes depends only on
** which point is the maximum and which the minimum of each coordinate and
** on which coordinate has the largest extent, all independent and uniform.
** linf_rank_law counts, over those equally likely cases, how many give k
** circumcubes: law[k] for k = 0 .. LINF_CUBES_MAX, out of the returned
** total (the law of the thesis's Monte Carlo, exactly).  d <= 5 (6^4 * 30^4
** cases at d = 5: O((d(d+1))^{d-1} 2^d) time); 0 for larger d. */
uint64_t linf_rank_law(int d, uint64_t *law);

#endif
