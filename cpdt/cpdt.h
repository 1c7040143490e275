/*
** cpdt.h: the Delaunay triangulation of a convex polygon by each algorithm
** of the thesis's chapter 5 and of its further work, every one exact and
** counting its operations (docs/cpdt.md).
**
** Input: n >= 3 vertices of a strictly convex polygon, anticlockwise
** (cpdt_check).  Output: its n - 2 triangles, each as three increasing
** vertex indices i < j < k (anticlockwise), in the order of their middle
** vertex j = 1 .. n-2 (every vertex but the first and the last is the
** middle vertex of exactly one triangle).  Cocircular vertices are settled
** by lot's tie-break (docs/lot.md, Ties: the lexicographically greatest
** of four cocircular vertices counts as outside the circle of the other
** three), so every algorithm returns exactly lot's Delaunay triangulation
** of the same points.
**
**   circum         circumcircle algorithm (5.4.1): the apex on side (0, n-1)
**                  by one scan, then the same on the two new sides (the
**                  newest-side recursion); O(n^2) worst, O(n^1.5) on average
**                  over triangulations
**   circum-random  the same on a side of each piece drawn at random
**   circum-walk    the same triangles with O(1) extra space: a walk round the
**                  dual tree, each step one scan
**   divide         divide and conquer (5.4.2): halves by index, merged along
**                  the cross edges
**   incremental    vertices added in input order (5.4.3), each joined to its
**                  two neighbours and flipped in; as many flips as its degree
**   random         Chew's randomised incremental algorithm: vertices deleted
**                  in random order (each remembers its neighbours), then
**                  inserted back; expected O(n)
**   flip           the fan from vertex 0, then Lawson's flips
**   corners        the thesis's sweepline simplified for monotone polygons
**                  (2.5.4-2.5.5): corners cut off, the smallest circumcircle
**                  first, then Lawson's flips where the floating-point keys
**                  erred; O(n log n)
*/
#ifndef FLIPLAB_CPDT_H
#define FLIPLAB_CPDT_H

#include <stddef.h>
#include <stdint.h>
#include "geom.h"

typedef enum cpdt_algorithm {
  CPDT_CIRCUM, CPDT_CIRCUM_RANDOM, CPDT_CIRCUM_WALK, CPDT_DIVIDE, CPDT_INCREMENTAL,
  CPDT_RANDOM, CPDT_FLIP, CPDT_CORNERS, CPDT_ALGORITHM_COUNT
} cpdt_algorithm;

/* At most this many vertices (indices are 32-bit, half-edges twice that). */
#define CPDT_MAX_N ((size_t)1 << 29)

/* What a run did.  Each counter is a plain increment where the work is done.
**   scanned      vertices scanned by the circumcircle scans (each scan of a
**                piece of m vertices looks at m - 2)
**   incircle     incircle tests (geom_incircle calls)
**   orient       orientation tests (ties of four cocircular vertices)
**   flips        edge flips (incremental, random, flip; corners: its repairs)
**   merges       merges of divide and conquer; cross_sum and cross_max: the
**                cross edges a merge adds that are diagonals of the merged
**                piece (the thesis's a), summed and largest; added and
**                deleted: its edge additions and deletions (a and a - 1)
**   depth        the deepest recursion (pieces pending on the stack, or the
**                levels of divide and conquer)
**   memory       the most bytes of working memory held at once
**   index_length the average index length min(j - i, n - j + i) of the
**                diagonals of the result (the thesis's L(D); 0 when n = 3) */
typedef struct cpdt_counts {
  uint64_t scanned, incircle, orient, flips;
  uint64_t merges, cross_sum, cross_max, added, deleted;
  uint64_t depth, memory;
  double index_length;
} cpdt_counts;

/* The counts by name, for bindings that mirror no layout: a heap copy
** (cpdt_counts_new: zeroed, NULL when memory ran out), the names in order
** (cpdt_counts_field(i), NULL past the last), a field as an integer (the
** counts) or a double (any): 0, or -1 for an unknown name. */
cpdt_counts *cpdt_counts_new(void);
void cpdt_counts_delete(cpdt_counts *c);
const char *cpdt_counts_field(size_t i);
int cpdt_counts_get_u64(const cpdt_counts *c, const char *name, uint64_t *out);
int cpdt_counts_get_double(const cpdt_counts *c, const char *name, double *out);

/* Names ("circum", "circum-random", ...), a line about each, and back. */
const char *cpdt_algorithm_name(int algorithm);
const char *cpdt_algorithm_about(int algorithm);
int cpdt_algorithm_find(const char *name);   /* -1 if unknown */

/* 0 when p[0..n-1] is a strictly convex anticlockwise polygon within the
** coordinate contract and n <= CPDT_MAX_N; else an error code with *bad the
** 0-based vertex at fault (cpdt_check_str words it).  O(n log n). */
#define CPDT_CLOCKWISE 100
#define CPDT_TOO_MANY 101
int cpdt_check(const geom_point *p, size_t n, size_t *bad);
const char *cpdt_check_str(int err);

/* The Delaunay triangulation of the checked polygon p by `algorithm` into
** tri[3 (n - 2)] (above), its counts into *counts (may be NULL); seed drives
** the randomised algorithms (same seed, same counts).  0; -1 for a bad
** algorithm or n < 3; -2 when memory ran out.  The polygon is not checked
** again: an unchecked one gives an unspecified triangulation. */
int cpdt_triangulate(const geom_point *p, size_t n, int algorithm, uint64_t seed,
                     uint32_t *tri, cpdt_counts *counts);

/* Of any triangulation of a convex n-gon in that layout: the average index
** length of its diagonals (L(D)), and the vertices the newest-side
** circumcircle algorithm scans when the triangulation is its result (the sum
** over triangles of k - i - 1, which solves T(m+1) = m+1 + T(k) + T(m-k)). */
double cpdt_index_length(const uint32_t *tri, size_t n);
uint64_t cpdt_circum_cost(const uint32_t *tri, size_t n);

#endif
