/*
** geom.h: points, triangles and exact predicates.
**
** A geom_tri holds every quantity of a triangle that a badness measure may
** need, computed once.  The three vertices are put in a canonical order
** (lexicographic by x, then y) before anything is computed, so the same
** triangle gets bit-identical values however its vertices are listed; the
** flip rules rely on that to be independent of the quadrilateral's first
** vertex bit for bit.
*/
#ifndef FLIPLAB_GEOM_H
#define FLIPLAB_GEOM_H

#include <stddef.h>
#include <stdint.h>
#include "fliplab_config.h"

#include "predicates.h"   /* geom_point, geom_orient, geom_incircle */

typedef struct geom_tri {
  geom_point v[3];            /* vertices in canonical (lexicographic) order */
  double a, b, c;             /* side lengths, a >= b >= c */
  double alpha, beta, gamma;  /* angles in radians, alpha <= beta <= gamma */
  double area;                /* A > 0 for a proper triangle */
  double P;                   /* perimeter a + b + c */
  double R;                   /* circumradius abc / (4A) */
  double r;                   /* inradius 2A / P */
  double h;                   /* shortest altitude a' = 2A / a */
  double rx, ry;              /* coordinate ranges of the vertices */
} geom_tri;

/* Fill *t from three points, in any order. */
void geom_tri_make(geom_tri *t, geom_point p, geom_point q, geom_point r);
/* geom_tri_make on each of m triangles v[3i], v[3i+1], v[3i+2], into t[i]. */
void geom_tri_make_n(geom_tri *t, const geom_point *v, size_t m);

/* Groups of geom_tri fields, for geom_tri_make_fields. */
enum {
  GEOM_F_SIDES = 1,    /* a, b, c */
  GEOM_F_ANGLES = 2,   /* alpha, beta, gamma (two atan2, most of the cost) */
  GEOM_F_AREA = 4,     /* area */
  GEOM_F_PERIM = 8,    /* P */
  GEOM_F_CIRCUM = 16,  /* R (each of R, r, h costs a division) */
  GEOM_F_RANGES = 32,  /* rx, ry */
  GEOM_F_INRADIUS = 64,   /* r */
  GEOM_F_HEIGHT = 128,    /* h */
  GEOM_F_ALL = 255
};
/* Only the fields asked for (an OR of GEOM_F_*), each bit-identical to
** geom_tri_make's, the others NaN (v is always set): for a measure that
** reads a few fields (measure_fields) on hot paths. */
void geom_tri_make_fields(geom_tri *t, geom_point p, geom_point q, geom_point r,
                          unsigned fields);

/* Smallest, largest and median of three non-NaN values: plain comparisons
** rather than fmin/fmax (libm calls); they compile to branch-free
** minsd/maxsd. */
static inline double geom_min3(double a, double b, double c) {
  double m = a < b ? a : b;
  return m < c ? m : c;
}

static inline double geom_max3(double a, double b, double c) {
  double m = a > b ? a : b;
  return m > c ? m : c;
}

/* The median as c clamped to [lo, hi], written as two plain selections
** so that it too compiles to minsd/maxsd instead of a branch that random
** values mispredict half the time.  The same bits as "c < lo ? lo : c > hi
** ? hi : c" for every input, signed zeros and NaN included: c is kept
** whenever it is neither above hi nor below lo. */
static inline double geom_mid3(double a, double b, double c) {
  double lo = a < b ? a : b, hi = a > b ? a : b;
  double m = c > hi ? hi : c;
  return m < lo ? lo : m;
}

/* Cheap enclosures of the angles geom_tri_make computes, without atan2:
** lo[i] <= (the angle it computes at vertex i of p, q, r) <= hi[i], the
** enclosures about 2e-6 wide.  Since min, median and max are monotone in
** each argument, the order statistics of lo and hi enclose alpha, beta and
** gamma.  Returns 0 (lo, hi unset) for a triangle so flat that its area
** needs geom_twice_area's exact path.  For decisions that need the exact
** values only when enclosures cannot decide (lot/lot.c, measure_bounds). */
int geom_angle_bounds(geom_point p, geom_point q, geom_point r, double lo[3], double hi[3]);
/* The same for one of alpha, beta, gamma (k = 0, 1, 2) alone: the angle
** opposite the shortest, median or longest side, when rounded squared
** lengths tell that side apart from the others, with one approximate
** atan2 instead of two (geom.c says why that is safe); else (an isosceles
** triangle) the order statistic of all three. */
int geom_angle_rank_bounds(geom_point p, geom_point q, geom_point r, int k, double *lo,
                           double *hi);

/* The lexicographic order of points (by x, then y): a triangle's canonical
** vertex order, the samplers' collinear tie-break, the plugin rotation.
** Bitwise & and | rather than && and ||: the same value, without branches
** (geom_tri_make's canonical sort depends on it). */
static inline int geom_lexless(geom_point a, geom_point b) {
  return (a.x < b.x) | ((a.x == b.x) & (a.y < b.y));
}

double geom_dist(geom_point p, geom_point q);
int geom_point_finite(geom_point p);

/* ---- the coordinate contract --------------------------------------------
**
** fliplab answers correctly for every point whose coordinates are 0 or of
** magnitude in [GEOM_COORD_MIN, GEOM_COORD_MAX] = [1e-30, 1e30], and refuses
** every other coordinate (subnormal, underflowing, overflowing, too small or
** too large, NaN, infinite) with a one-line error.  Every reader of
** coordinates (command line, pentagon, polygon and point CSV) goes through
** geom_coord_parse, every polygon through geom_polygon_check, which apply it.
**
** Why these bounds: no quantity a built-in measure or joint computes can
** underflow or overflow inside them (docs/scale.md has the argument in
** full).  1e30 < 2^100 and 1e-30 > 2^-100, so every coordinate is a
** multiple of 2^-152 (its ulp is at least 2^-152) of magnitude below 2^100,
** and so is every coordinate difference, exact or rounded.  Hence, for a
** triangle with vertices inside the contract:
**   side lengths          in [2^-152, 2^101]
**   twice the area        in [2^-304, 2^203]   (a non-zero multiple of 2^-304)
**   R = abc / (4A)        at most 2^608, r = 2A/P at least 2^-408,
**   dimensionless values  (angles, r/R, 4A/P^2, c/a, lambda) in
**                         [2^-1015, 2^507], the smallest being
**                         r/R = 8A^2 / (P abc) >= 2^-1014.6,
** all normal doubles, so each measure is computed with its usual relative
** error.  Joints: min, max, sum and the harmonic mean of such values stay in
** range; the product and the root-sum-square do not (R * R > 2^1023,
** (r/R)^2 < 2^-1022), so they are compared in split form, a mantissa and a
** binary exponent (joint_compare in joints/joint.h).  There is no bound on
** edge lengths or heights beyond what the contract implies: the shortest
** edge is 2^-152 and the flattest triangle has twice the area 2^-304 with
** sides near 2^100. */
#define GEOM_COORD_MAX 1e30
#define GEOM_COORD_MIN 1e-30

/* The weight contract (per-site weights of the weighted Delaunay rule, a
** squared length): every weight is 0 or of magnitude in [1e-60, 1e60],
** the squares of the coordinate range.  Then every non-zero difference of
** two weights is at least 2^-252 and every term of the power test's error
** bound (geom_power, predicates.c) a normal double: the filter's relative
** bound holds.  geom_weight_check: GEOM_COORD_OK, NOT_FINITE or
** OUT_OF_RANGE (geom_weighterr_str words the last for weights). */
#define GEOM_WEIGHT_MAX 1e60
#define GEOM_WEIGHT_MIN 1e-60

typedef enum geom_coorderr {
  GEOM_COORD_OK = 0,
  GEOM_COORD_NOT_NUMBER,   /* empty, or not entirely a decimal/hex number */
  GEOM_COORD_NOT_FINITE,   /* nan, inf */
  GEOM_COORD_OUT_OF_RANGE  /* overflows, underflows, or outside the contract */
} geom_coorderr;

/* ---- numbers (geom/number.c): the one parser of every reader ----------
**
** Each verb reads the byte span s[0..len), which need not end in a NUL: a
** span is a number only if all of its bytes are, so a field with a NUL byte
** inside it is refused rather than cut short. */
typedef enum geom_numerr {
  GEOM_NUM_OK = 0,
  GEOM_NUM_NOT_NUMBER,     /* empty, or not entirely a decimal/hex number */
  GEOM_NUM_NOT_FINITE,     /* nan, inf */
  GEOM_NUM_OUT_OF_RANGE,   /* beyond the doubles, or below the normal ones */
  GEOM_NUM_NO_MEMORY       /* a very long number could not be copied */
} geom_numerr;

/* A real in strtod syntax filling the whole span, with no blank before or
** after it (as geom_count_parse: the CSV layer has already dropped the
** unquoted blanks around a field, so a blank left is inside quotes, and
** " 0" and "0 " are read alike, as no number): GEOM_NUM_OK and *out set,
** or why not.  Unlike strtod, a value that
** overflows, underflows to 0 or is subnormal is an error, not a number. */
geom_numerr geom_number_parse(const char *s, size_t len, double *out);
/* The longest prefix of the span that strtod reads as a number: *used is
** its length (0: none, GEOM_NUM_NOT_NUMBER) and *out what strtod made of
** it (HUGE_VAL on overflow, 0 or a subnormal on underflow, which are
** GEOM_NUM_OUT_OF_RANGE). */
geom_numerr geom_number_scan(const char *s, size_t len, double *out, size_t *used);
/* A strict decimal count: digits only, no sign, no blank, no overflow;
** 0 and *out set, or -1. */
int geom_count_parse(const char *s, size_t len, uint64_t *out);
/* "is not a number", "is not finite", "is out of range", ... */
const char *geom_numerr_str(geom_numerr e);

/* Is x a coordinate of the contract? */
geom_coorderr geom_coord_check(double x);
/* The index of the first of x[0 .. n-1] that is not (geom_coord_check), or
** n when all are: the check of a whole array (python/'s inputs). */
size_t geom_coord_check_n(const double *x, size_t n);
/* Parse a whole string (geom_number_parse on its strlen bytes) into *out
** and check it against the contract; geom_coord_parse_n reads a span of
** len bytes (a CSV field), refusing a NUL byte inside it. */
geom_coorderr geom_coord_parse(const char *s, double *out);
geom_coorderr geom_coord_parse_n(const char *s, size_t len, double *out);
/* "is not a number", "is not finite", "is out of range (coordinates must be
** 0 or of magnitude between 1e-30 and 1e30)". */
const char *geom_coorderr_str(geom_coorderr e);

/* Thread counts.  Every entry point of the library that takes a thread
** count takes 0 for all cores or 1 .. GEOM_MAX_THREADS (the program's
** --threads range): an OpenMP team of 10^5 threads overflows the runtime's
** stacks, and a negative count is a caller's mistake, not a request.
** geom_threads_check: 0, or -1 with "threads: expected 0 (all cores) or 1
** .. 1024, got T".  geom_threads_clamp: the count to run with, threads
** itself when valid and non-zero, else all (the caller's "all cores", e.g.
** omp_get_max_threads()), always within 1 .. GEOM_MAX_THREADS: a guard for
** the entry points without an error channel. */
#define GEOM_MAX_THREADS 1024
int geom_threads_check(long long threads, char *err, size_t errlen);
int geom_threads_clamp(int threads, int all);

geom_coorderr geom_weight_check(double w);
/* "is out of range (weights must be 0 or of magnitude between 1e-60 and
** 1e60)", or geom_coorderr_str's words for the other errors. */
const char *geom_weighterr_str(geom_coorderr e);

/* Twice the area of triangle p q r, |orientation determinant|, with a
** relative error below 2^-40 (geom.c explains how). */
double geom_twice_area(geom_point p, geom_point q, geom_point r);

/* Convex polygon validation, used for every polygon a user hands us.
** geom_polygon_check reverses a clockwise polygon in place (the documented
** normalisation: fliplab works anticlockwise) and returns GEOM_OK, or an
** error code with *bad set to the 0-based index of the offending vertex. */
typedef enum geom_polyerr {
  GEOM_OK = 0,
  GEOM_TOO_FEW,        /* fewer than 3 vertices */
  GEOM_NOT_FINITE,     /* NaN or infinite coordinate */
  GEOM_DUPLICATE,      /* two equal vertices */
  GEOM_COLLINEAR,      /* three consecutive vertices on a line */
  GEOM_NOT_CONVEX,     /* a reflex vertex, or the boundary winds more than once */
  GEOM_OUT_OF_SCALE,   /* a coordinate outside the contract (geom_coord_check) */
  GEOM_CROSSING        /* two edges cross, touch or overlap (simple polygons) */
} geom_polyerr;

geom_polyerr geom_polygon_check(geom_point *p, size_t n, size_t *bad, int *reversed);

/* Simple polygon validation, exact (geom_orient only): finite coordinates
** within the contract (geom_coord_check), no repeated vertex,
** and no two edges meeting except adjacent edges at their shared vertex
** (crossing, touching and overlapping are all refused; an adjacent pair
** that folds back onto itself overlaps).  Consecutive collinear vertices
** are allowed.  Edge e joins vertices e and e+1 (mod n).  On GEOM_CROSSING
** *bad < *bad2 are the two offending edges; on the other errors *bad is the
** vertex, as for geom_polygon_check.  A clockwise polygon is reversed in
** place keeping vertex 0 (the same convention).  O(n log n) to sort the
** edges plus one exact test per pair of edges whose x-ranges overlap
** (O(n^2) at worst). */
geom_polyerr geom_simple_polygon_check(geom_point *p, size_t n, size_t *bad, size_t *bad2,
                                       int *reversed);
/* 1 if the closed segments ab and cd have a point in common (exact). */
int geom_segments_meet(geom_point a, geom_point b, geom_point c, geom_point d);
/* For x on the line through a != b: 1 when x lies strictly beyond a in the
** direction of b (comparisons of coordinates only, so exact). */
int geom_ahead(geom_point a, geom_point b, geom_point x);
/* 1 when q lies on the open segment ab, a != b (exact: an orientation
** test and geom_ahead from each end). */
int geom_on_segment(geom_point a, geom_point b, geom_point q);
const char *geom_polyerr_str(geom_polyerr e);

/* A planar straight-line graph: points, segments between them (pairs of
** 0-based point indices) and hole points, the input of a constrained
** triangulation.  Made by the samplers (samplers/), read and written as
** Triangle's .poly files (reports/poly.c); every array malloc'ed. */
typedef struct geom_pslg {
  geom_point *pts;
  size_t npts;
  uint32_t *seg;          /* 2 per segment */
  size_t nseg;
  geom_point *hole;
  size_t nholes;
} geom_pslg;

/* Free the arrays and zero the counts. */
void geom_pslg_free(geom_pslg *g);

#endif
