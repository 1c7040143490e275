/*
** got.h: globally optimal triangulations (GOT) of simple polygons
** (docs/got.md).
**
** The thesis's Algorithm 1 (Klincsek's dynamic programme generalised to any
** triangle-based rule b_f): Theta(n^3) time, Theta(n^2) memory, backtracking
** to the n - 2 triangles.  The programme works in key space (joints/joint.h):
** B(i, j) = min over i < k < j of key(B(i,k)) (+) key(b(p_i p_k p_j)) (+)
** key(B(k,j)), with (+) = +, min or max, so products of thousands of values
** neither overflow nor underflow.  The empty chain B(i, i+1) is the joint's
** identity; it never enters arithmetic: the k = i+1 and k = j-1 terms are
** peeled off the inner loop.  Ties are broken deterministically: the
** smallest k wins, in every cell; each cell is computed by one thread in the
** same order whatever the thread count, so results are bit-identical.
**
** Simple polygons.  The same programme runs over a simple, non-convex
** polygon when restricted to its valid diagonals (got_valid_diagonals):
** cell (i, j) exists when (i, j) is an edge or a valid diagonal, and split
** k is allowed when (i, k) and (k, j) both are (Klincsek's observation:
** every chain cut off by a valid diagonal is itself a simple polygon).
** Strictly convex input keeps the unmasked path, bit for bit.
**
** The runner-up is the second smallest total over all triangulations
** distinct from the returned one (equal to the optimum when the optimum is
** not unique).  It is computed after the main pass along the optimal tree
** only (O(n^2)), from the recurrence second(i,j) = min( second smallest
** candidate over k, t (+) second(i,k*) (+) best(k*,j),
** t (+) best(i,k*) (+) second(k*,j) ), valid for any monotone (+).
**
** Triangle badness in the O(n^3) loop comes from per-measure kernels that
** read per-pair data precomputed in O(n^2) (side lengths, edge directions)
** instead of recomputing a geom_tri; they agree with measure_eval on
** geom_tri_make to within rounding (a few ulps for lengths, products and
** quotients; about 1e-15 rad absolute for angles, which are differences of
** edge directions).  User-defined measures fall back to measure_eval (slower;
** measure functions are reentrant by contract, so still multithreaded).  Because of those last-bit
** differences the optimal value can differ from a recomputation in the last
** bits; compare totals with a relative tolerance.
*/
#ifndef FLIPLAB_GOT_H
#define FLIPLAB_GOT_H

#include <stddef.h>
#include <stdint.h>
#include "geom.h"
#include "joint.h"
#include "rule.h"

/* One triangle of a triangulation: polygon vertex indices i < k < j. */
typedef struct got_triangle {
  int i, k, j;
  double badness;       /* measure_eval of the triangle */
} got_triangle;

typedef struct got_options {
  int threads;          /* 0: all cores; else 1 .. GEOM_MAX_THREADS (others refused) */
  double tie_eps;       /* relative tie tolerance, default RULE_DEFAULT_TIE_EPS */
} got_options;

typedef struct got_result {
  size_t n;
  int measure;
  joint_id joint;
  int sign;             /* the measure's sign (+1, -1, 0) */
  double key;           /* optimal total in key space */
  double total;         /* joint_unkey(key); see got_format_total for l_0 */
  int has_runner_up;    /* 0 when there is one triangulation only (n = 3) */
  double key2, total2;  /* runner-up (second best distinct triangulation) */
  double gap;           /* total2 - total in badness units (>= 0) */
  double rel_gap;       /* gap / max(|total|, |total2|); exact in log space for l_0 */
  int unique;           /* 1 if rel_gap > tie_eps (the optimum is unique) */
  double tie_eps;
  got_triangle *tri;    /* n - 2 triangles, in backtracking order */
  size_t ntri;
  int simple;           /* 1: solved as a simple (non-convex) polygon, masked DP */
  /* Certified verdict (got_cert.c, docs/got.md): the exact optimal key lies
  ** in [key - cert_err, key + cert_err], and every other triangulation's
  ** exact key is at least key2 - cert_err2.  cert_unique is 1 only when
  ** that proves key2's triangulations all worse: key2 - cert_err2 > key +
  ** cert_err, i.e. cert_gap = key2 - key > cert_bound = cert_err +
  ** cert_err2 (both rounded so that the test is safe).  Errors are INFINITY
  ** when no bound is known (cert_why says why). */
  double cert_err, cert_err2, cert_gap, cert_bound;
  int cert_unique;
  const char *cert_why;
  /* The error model behind them, for keys made from measure_eval values
  ** (got_cert_err_of); NaN when none is known. */
  double cert_rho, cert_alpha;
  double seconds;       /* wall time: validation, diagonals, DP, backtracking */
  int threads;          /* threads used */
  /* A point set's GOT (got_points_solve; 0 for a polygon's): the skeleton used
  ** (got_skeleton), its candidate edges after the exclusion test, the edges kept, those
  ** certain and its rounds; the bounded faces of the certain edges, those left to solve
  ** (more than a triangle), those with points inside or not simple (got_face_solve), the
  ** points of the largest; the search states of those faces; seconds per stage. */
  int points, skeleton;
  size_t candidates, edges, certain, rounds;
  size_t faces, faces_left, faces_general, largest_face, face_states;
  double seconds_candidates, seconds_lmt, seconds_faces, seconds_solve;
  double seconds_delaunay;  /* the caller's Delaunay triangulation (study_got_points), or 0 */
} got_result;

/* Bytes of working memory the DP needs for n vertices and this measure. */
size_t got_memory_needed(size_t n, int measure);
/* 0 if that fits (at most 3/4 of physical memory); otherwise -1 and a
** one-line message stating the memory needed. */
int got_check_memory(size_t n, int measure, char *err, size_t errlen);

/* Solve GOT(rule) for the simple anticlockwise polygon p[0..n-1] (see
** geom_simple_polygon_check).  A strictly convex polygon takes the convex
** path (every diagonal valid, tiled kernels); any other simple polygon the
** same programme restricted to its valid diagonals (got_valid_diagonals).
** The rule must be triangle-based.  0 on success; -1 with a message. */
int got_solve(const geom_point *p, size_t n, const rule *r, const got_options *opt,
              got_result *out, char *err, size_t errlen);
void got_result_free(got_result *res);

/* The certified bound E(K) on |exact key - K| for the floating key K of any
** triangulation of the solved polygon whose n - 2 badness values come
** from measure_eval and are keyed and combined by the rule (rule_key,
** rule_key_add, in any order), such as a LOT's; INFINITY when no bound is
** known (res->cert_why).  A triangulation whose key K satisfies
** |K - res->key| <= res->cert_err + got_cert_err_of(res, K) cannot be told
** from the optimum in floating point. */
double got_cert_err_of(const got_result *res, double key);

/* The total of a key, readable: a plain number, or "exp(K)" / "-exp(-K)"
** when the l_0 product under/overflows a double. */
void got_format_total(const got_result *res, double key, char *buf, size_t len);

/* Per-pair data and triangle kernels (exposed for tests and benchmarks).
** got_pairs_eval writes b(p_i p_k p_j) for k in [k0, k1) into out[k - k0];
** requires i < k0 <= k1 <= j. */
typedef struct got_pairs got_pairs;
got_pairs *got_pairs_new(const geom_point *p, size_t n, int measure, int threads);
void got_pairs_eval(const got_pairs *pd, size_t i, size_t j, size_t k0, size_t k1,
                    double *out);
void got_pairs_free(got_pairs *pd);
/* 1 if the measure has a specialised kernel, 0 if it uses measure_eval. */
int got_measure_has_kernel(int measure);

/* The valid diagonals of a simple anticlockwise polygon, exactly:
** V[i*n + j] = V[j*n + i] = 1 when (i, j) is an edge of the polygon or a
** diagonal whose open segment lies in the open interior (touching no vertex
** or edge), else 0.  O(n^2 log n) (a rotational sweep per vertex, OpenMP
** over vertices).  0, or -1 when out of memory. */
int got_valid_diagonals(const geom_point *p, size_t n, unsigned char *V, int threads);

/* The Delaunay triangulation of a strictly convex anticlockwise polygon,
** exactly (geom_incircle): n - 2 triangles into out (badness left 0).
** *unique is 0 when four or more vertices are cocircular in a way that
** makes it ambiguous (then the smallest-k choice is returned).  0 or -1. */
int got_delaunay(const geom_point *p, size_t n, got_triangle *out, int *unique);

/* Compare two triangulations of the same n-gon: diagonals of a not in b,
** and triangles common to both. */
typedef struct got_diff {
  size_t diagonals;         /* n - 3 */
  size_t diagonals_differ;  /* diagonals of a that are not in b */
  size_t triangles;         /* n - 2 */
  size_t triangles_common;
} got_diff;
int got_compare(const got_triangle *a, const got_triangle *b, size_t n, got_diff *out);

/* ---- point sets (got/got_points.c; docs/got.md, "Point sets") ----
** GOT(b_f) of a set of points for a sum rule (the joint's keys add: l_1, l_2, l_0, l_-1
** and the power means): the skeleton's CERTAIN edges are in every GOT, so the optimum is
** the union of the optima of the faces they leave, each solved exactly (got_solve for an
** empty simple face, an exact search for the others), combined in a fixed order, so the
** result does not depend on the thread count.  res->tri: point indices i < k < j per
** triangle (i, k, j as fields), 2n - h - 2 of them, sorted.  res->key2 is the runner-up
** among the triangulations containing the skeleton; res->cert_unique is 1 when every
** face's optimum is certified unique (then the GOT is unique), and cert_gap and
** cert_bound are those of the face closest to a tie.  cert_rho and cert_alpha model keys
** of measure_eval summed over the 2n - h - 2 triangles (got_cert_err_of bounds a LOT's
** total with them); NaN when the rule has no such model. */
typedef enum got_skeleton {
  GOT_SKELETON_AUTO,    /* DELAUNAY when it applies and a triangulation is given, else LMT */
  GOT_SKELETON_ALL,     /* every edge, the hull certain (tiny n: got_skel_all) */
  GOT_SKELETON_LMT,     /* the rule's candidate edges and the LMT loop (got_skel_build) */
  GOT_SKELETON_DELAUNAY /* rule_got_cdt_theorem's rules: the certified Delaunay subdivision's
                           edges certain, its cocircular cells' diagonals possible */
} got_skeleton;

/* 0, or -1 with a one-line message: p[0..n-1] is no input of got_points_solve (fewer
** than 3 points, a coordinate outside the contract, two equal points naming both rows,
** all collinear) or r no sum rule. */
int got_points_check(const geom_point *p, size_t n, const rule *r, char *err, size_t errlen);
/* Bytes got_points_solve needs for n points (the skeleton's candidates included, about
** six per point, each face's tables for faces below a hundred points). */
size_t got_points_memory_needed(size_t n);
/* 0 if that fits in 3/4 of physical memory, else -1 and a one-line message. */
int got_points_check_memory(size_t n, char *err, size_t errlen);
/* The GOT of the point set; 0, or -1 with a one-line message (got_points_check's, the
** skeleton's, a face's: too large for the exact search, out of memory). */
int got_points_solve(const geom_point *p, size_t n, const rule *r, const got_options *opt,
                     got_skeleton skeleton, got_result *out, char *err, size_t errlen);
/* The same, given a triangulation of the points claimed to be Delaunay (dt: ndt
** anticlockwise triples of point indices, such as lot's exact Delaunay triangulation;
** NULL when none).  With the skeleton AUTO or DELAUNAY and a rule of rule_got_cdt_theorem, dt is
** certified exactly (every triangle anticlockwise, matched edges, a convex boundary winding
** once, every point a vertex, every edge locally Delaunay) and the candidates are its
** subdivision's edges (docs/got.md, "Point sets: rules whose GOT is Delaunay"); a failed
** certificate is refused with one line.  DELAUNAY without dt, or with another rule, is
** refused; AUTO falls back to LMT. */
int got_points_solve_dt(const geom_point *p, size_t n, const rule *r, const got_options *opt,
                        got_skeleton skeleton, const uint32_t *dt, size_t ndt, got_result *out,
                        char *err, size_t errlen);
/* got_points_solve_dt for points and a rule that have passed got_points_check already, as
** study_got_points checks them before it triangulates (so that got's one-line errors come
** before lot's): the same answer and the same refusals of the options, without running that
** check (its O(n log n) sort) a second time.  Input that has not passed it is the caller's
** error, not refused here. */
int got_points_solve_checked(const geom_point *p, size_t n, const rule *r,
                             const got_options *opt, got_skeleton skeleton, const uint32_t *dt,
                             size_t ndt, got_result *out, char *err, size_t errlen);
/* The skeleton's name ("auto", "all", "lmt", "delaunay"), and back (-1 for none). */
const char *got_skeleton_name(got_skeleton s);
int got_skeleton_find(const char *name);

/* ---- options and results through verbs (got/got_result.c) ----
** For callers that do not compile against this header (python/fliplab:
** docs/python.md, "How the package talks to the library"), as lot.h's
** lot_options and lot_stats verbs: got_options made and set by verbs,
** got_result on the heap and read by the names of its fields.  A field
** added to got_result needs its row in got_result.c's table. */

/* got_options on the heap: threads 0 (all cores), tie_eps
** RULE_DEFAULT_TIE_EPS; NULL when out of memory. */
got_options *got_options_new(void);
void got_options_free(got_options *o);
/* 0, or -1 leaving o unchanged: threads outside 0 .. GEOM_MAX_THREADS, a
** tie tolerance that is not a finite number >= 0. */
int got_options_set_threads(got_options *o, int threads);
int got_options_set_tie_eps(got_options *o, double tie_eps);

/* A zero got_result on the heap for got_solve (NULL when out of memory);
** got_result_delete frees its triangles (got_result_free) and itself. */
got_result *got_result_new(void);
void got_result_delete(got_result *res);

/* got_result by name: got_result_field(i) is its i-th field in declaration
** order (NULL past the last); got_result_get_i64 reads an integer (size_t,
** int, the joint as its joint_id), got_result_get_double a double,
** got_result_get_text cert_why (NULL when unset or for another name).
** 0, or -1 for a name that is no field of that type.  The triangles
** (tri) are read by got_result_get_triangles: ntri of them, i k j into
** ijk[3 q ..] and the badness into bad[q]; returns ntri. */
const char *got_result_field(size_t i);
int got_result_get_i64(const got_result *res, const char *name, int64_t *out);
int got_result_get_double(const got_result *res, const char *name, double *out);
const char *got_result_get_text(const got_result *res, const char *name);
size_t got_result_get_triangles(const got_result *res, int32_t *ijk, double *bad);

#endif
