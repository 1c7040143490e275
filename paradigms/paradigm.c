/*
** paradigm.c: the registry of chapter 2's algorithms and the one runner
** that validates, deduplicates, times and canonicalises for all of them.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "geom_key_internal.h"
#include "paradigm_internal.h"
#include "lot.h"
#include "shape.h"

#define BOTH_RULES (PARADIGM_RULE_DT | PARADIGM_RULE_ES)
#define PARADIGM_CONVEX_REFUSAL \
  "DT only: cpdt decides with the in-circle test, not a rule's homothet; no point sets, " \
  "constraints or non-convex polygons (the incremental, flip, select-constrained rows)"
#define CONVEX_ROW(name, paradigm, section, cost, fn) \
  {name, paradigm, section, PARADIGM_CONVEX, PARADIGM_RULE_DT, PARADIGM_CONVEX_REFUSAL, cost, \
   NULL, fn}

/* What the unconstrained selection rows leave to others. */
#define PARADIGM_SELECT_REFUSAL \
  "constraints: the row select-constrained (2.4.2); simple polygons: select-constrained, " \
  "incremental and flip (2.4.3's own polygon selection is not built)"

/* Why Watson's insertion and the history DAG refuse constraints and polygons. */
#define PARADIGM_CAVITY_REFUSAL \
  "constraints and polygons: not built (a cavity would have to stop at segments); " \
  "the row incremental inserts segments"

/* One row per algorithm; problems and rules as in paradigm.h. */
static const paradigm_algorithm paradigm_algorithms[] = {
  {"incremental", "incremental", "2.3.1", PARADIGM_DELAUNAY | PARADIGM_CONSTRAINED
   | PARADIGM_POLYGON, BOTH_RULES, "convex polygons: the convex-* rows",
   "O(n log n) expected (BRIO order, walk)", NULL, paradigm_lot_incremental},
  {"flip", "flip", "2.2.1", PARADIGM_DELAUNAY | PARADIGM_CONSTRAINED | PARADIGM_POLYGON,
   BOTH_RULES, "convex polygons: the convex-* rows",
   "O(n^2) worst, O(n log n) for the sweep's start", NULL, paradigm_lot_flip},
  {"sweep", "sweepline", "2.5.1", PARADIGM_DELAUNAY, BOTH_RULES,
   "constraints and polygons: the rows sweep-constrained (2.5.2) and sweep-monotone (2.5.4)",
   "O(n log n)", NULL, paradigm_lot_sweep},
  /* the constrained sweeps (paradigms/sweep_constrained.c, sweep_monotone.c) */
  {"sweep-constrained", "sweepline", "2.5.2", PARADIGM_DELAUNAY | PARADIGM_CONSTRAINED
   | PARADIGM_POLYGON | PARADIGM_CONVEX, PARADIGM_RULE_DT, PARADIGM_SWEEP_REFUSAL,
   "O(n log n) expected: skip lists for the constraint tree and the pieces, a heap of events",
   NULL, paradigm_sweep_constrained},
  {"sweep-monotone", "sweepline", "2.5.4", PARADIGM_POLYGON | PARADIGM_CONVEX,
   PARADIGM_RULE_DT, "x-monotone and convex polygons only (sweep-constrained serves the "
   "rest); " PARADIGM_SWEEP_REFUSAL, "O(n log n) expected: one piece, a heap of events",
   NULL, paradigm_sweep_monotone},
  {"dc-vertical", "divide", "2.6.1; 2.6.6", PARADIGM_DELAUNAY, BOTH_RULES, PARADIGM_DC_REFUSAL,
   "O(n log n): cuts at sampled medians, log n levels of O(n) merges; Theta(n log n) "
   "on uniform sites", NULL, paradigm_dc_vertical},
  {"dc-alternating", "divide", "2.6.1; 2.6.6", PARADIGM_DELAUNAY, BOTH_RULES,
   PARADIGM_DC_REFUSAL, "O(n log n): cuts at sampled medians; merges O(n) expected on "
   "uniform sites (Dwyer)", NULL, paradigm_dc_alternating},
  {"dc-constrained", "divide", "2.6.2", PARADIGM_CONSTRAINED, PARADIGM_RULE_DT,
   "DT only; point sets: dc-vertical, dc-alternating; polygons: dc-polygon",
   "O(n log n): cuts at medians, Guibas and Stolfi's zipper for each merge; plus each "
   "segment inserted by Sloan's flips at the merge of its ends (O(k^2) for k crossed edges "
   "at worst): Chew's virtual sites, which spare the insertions, are not built",
   "1: vertical strips, as Chew's (0: cuts alternating, Dwyer's)",
   paradigm_dc_constrained},
  {"dc-polygon", "divide", "2.6.3", PARADIGM_POLYGON | PARADIGM_CONVEX, PARADIGM_RULE_DT,
   "DT only: a rule's flips need not end at its LOT (2.6.6); point sets and constraints: "
   "the dc-* and select-constrained rows",
   "O(n log n) splits at n/3 diagonals of one ear-cut triangulation (ears O(n) tests "
   "through a grid when small, O(n^2 r) worst), merges by flips across each diagonal", NULL,
   paradigm_dc_polygon},
  {"select-stack", "selection", "2.4.1", PARADIGM_DELAUNAY, BOTH_RULES,
   PARADIGM_SELECT_REFUSAL, "O(n^2): a scan of every site per edge",
   NULL, paradigm_select_stack},
  {"select-queue", "selection", "2.4.1", PARADIGM_DELAUNAY, BOTH_RULES,
   PARADIGM_SELECT_REFUSAL, "O(n^2): a scan of every site per edge",
   NULL, paradigm_select_queue},
  {"select-strip", "selection", "2.4.1", PARADIGM_DELAUNAY, BOTH_RULES,
   PARADIGM_SELECT_REFUSAL,
   "O(n^{3/2}) expected on uniform sites (DT); ES polygons: the homothet's extent; "
   "O(n^2) for an ellipse", NULL,
   paradigm_select_strip},
  {"select-buckets", "selection", "2.4.1", PARADIGM_DELAUNAY, BOTH_RULES,
   PARADIGM_SELECT_REFUSAL,
   "O(n) expected on uniform sites (DT; ES polygons as measured: homothets and rounding "
   "shapes bound the search); O(n^2) for an ellipse",
   "p, the expected sites per bucket (default 1)", paradigm_select_buckets},
  {"select-constrained", "selection", "2.4.2", PARADIGM_DELAUNAY | PARADIGM_CONSTRAINED
   | PARADIGM_POLYGON, BOTH_RULES, "convex polygons: the convex-* rows",
   "O(n^2 e): a scan of every site per edge, e constraint pieces per site", NULL,
   paradigm_select_polygon},
  /* incremental variants (paradigms/incremental.c) */
  {"incremental-serpentine", "incremental", "2.3.1", PARADIGM_DELAUNAY, BOTH_RULES,
   "constraints and polygons: the row incremental inserts segments",
   "O(n^(5/4)) expected for uniform sites (sqrt(n) buckets, walk)",
   "buckets (0: sqrt(n))", paradigm_incr_serpentine},
  {"incremental-spiral", "incremental", "2.3.1", PARADIGM_DELAUNAY, BOTH_RULES,
   "constraints and polygons: the row incremental inserts segments",
   "O(n^(5/4)) expected for uniform sites (sqrt(n) buckets, walk)",
   "buckets (0: sqrt(n))", paradigm_incr_spiral},
  {"incremental-quaternary", "incremental", "2.3.1", PARADIGM_DELAUNAY, BOTH_RULES,
   "constraints and polygons: the row incremental inserts segments",
   "O(n) expected for uniform sites (n buckets in Morton order, walk)",
   "buckets (0: n)", paradigm_incr_quaternary},
  {"watson", "incremental", "2.3.1; 2.3.6", PARADIGM_DELAUNAY, BOTH_RULES,
   PARADIGM_CAVITY_REFUSAL,
   "O(n) expected for uniform sites (quaternary order, walk), O(n^2) worst",
   "1: random order (0: quaternary buckets)", paradigm_watson},
  {"incremental-dag", "incremental", "2.3.1; 2.3.6", PARADIGM_DELAUNAY, BOTH_RULES,
   PARADIGM_CAVITY_REFUSAL,
   "O(n log n) expected (random order, history DAG)",
   "1: quaternary buckets (0: random order)", paradigm_incr_dag},
  /* chapter 5's convex polygon algorithms (paradigms/convex_rows.c, cpdt/) */
  CONVEX_ROW("convex-circum", "selection", "5.4.1",
             "n^2/2 scans worst, Theta(n^1.5) on average over triangulations",
             paradigm_convex_circum),
  CONVEX_ROW("convex-circum-random", "selection", "5.4.1",
             "O(n^2) worst: the scans of circum on a random side of each piece",
             paradigm_convex_circum_random),
  CONVEX_ROW("convex-circum-walk", "selection", "5.4.1",
             "O(n^2) worst, O(1) extra space: a walk round the dual tree",
             paradigm_convex_circum_walk),
  CONVEX_ROW("convex-divide", "divide", "5.4.2",
             "O(n log n) worst, O(n) on average over triangulations "
             "(Theta(a) per merge of a cross edges)",
             paradigm_convex_divide),
  CONVEX_ROW("convex-incremental", "incremental", "5.4.3",
             "n^2/2 flips worst, O(n) on average over triangulations "
             "(a vertex's flips: its degree)",
             paradigm_convex_incremental),
  CONVEX_ROW("convex-random", "incremental", "5.4.3",
             "O(n) expected (Chew: deleted in random order, inserted back)",
             paradigm_convex_random),
  CONVEX_ROW("convex-flip", "flip", "2.2.1",
             "O(n^2) worst: the fan from vertex 0, then Lawson's flips",
             paradigm_convex_flip),
  CONVEX_ROW("convex-corners", "sweepline", "2.5.4",
             "O(n log n): a heap of corners, the smallest circumcircle cut first, "
             "then Lawson's flips",
             paradigm_convex_corners),
};

#define PARADIGM_ROWS (sizeof paradigm_algorithms / sizeof paradigm_algorithms[0])

size_t paradigm_count(void) {
  return PARADIGM_ROWS;
}

const paradigm_algorithm *paradigm_get(size_t i) {
  return i < PARADIGM_ROWS ? &paradigm_algorithms[i] : NULL;
}

const paradigm_algorithm *paradigm_find(const char *name) {
  for (size_t i = 0; i < PARADIGM_ROWS; i++)
    if (strcmp(paradigm_algorithms[i].name, name) == 0) return &paradigm_algorithms[i];
  return NULL;
}

const char *paradigm_problem_name(paradigm_problem pb) {
  switch (pb) {
    case PARADIGM_DELAUNAY: return "delaunay";
    case PARADIGM_CONSTRAINED: return "constrained";
    case PARADIGM_POLYGON: return "polygon";
    case PARADIGM_CONVEX: return "convex";
  }
  return "?";
}

/* The lexicographic order of docs/lot.md's tie-break: larger x, then
** larger y is greater. */
static int paradigm_greater(geom_point p, geom_point q) {
  return p.x > q.x || (p.x == q.x && p.y > q.y);
}

/* The symbolic perturbation of docs/lot.md, for any d: with each point's
** lift raised by eps^(n - rank), the in-circle determinant of a, b, c, d
** (rows p - d, lifts) is linear in the lifts, with coefficients
** orient(b, c, d), orient(c, a, d), orient(a, b, d) for a, b, c and
** -orient(a, b, c) for d; the greatest point with a non-zero coefficient
** decides.  For DT the result is never 0 unless all four are collinear. */
static int paradigm_perturbed(geom_point a, geom_point b, geom_point c, geom_point d) {
  geom_point q[4] = {a, b, c, d};
  int coef[4] = {geom_orient_valid(b, c, d), geom_orient_valid(c, a, d),
                 geom_orient_valid(a, b, d), -geom_orient_valid(a, b, c)};
  int best = -1;
  for (int i = 0; i < 4; i++)
    if (coef[i] != 0 && (best < 0 || paradigm_greater(q[i], q[best]))) best = i;
  return best < 0 ? 0 : coef[best];
}

/* DT: the exact in-circle test, its zeros settled by the perturbation.  ES:
** shape_decide_valid on the quadrilateral abcd, which must be strictly
** convex and anticlockwise (the rule decides nothing else); its EITHER
** settled by the same tie-break (the greatest vertex outside). */
int paradigm_inshape(const rule *r, ops_counts *c, geom_point a, geom_point b, geom_point d,
                     geom_point e) {
  const shape *k = rule_shape(r);
  if (k == NULL) {
    int s = ops_incircle(c, a, b, d, e);
    return s != 0 ? s : paradigm_perturbed(a, b, d, e);
  }
  ops_add(c, OPS_INSHAPE, 1);
  shape_choice ch = shape_decide_valid(k, a, b, d, e);
  if (ch == SHAPE_BD) return 1;
  if (ch == SHAPE_AC) return -1;
  return paradigm_perturbed(a, b, d, e);
}

/* For c and d strictly left of ab, d beats c when it lies strictly inside
** the rule's region through a, b, c (docs/paradigms.md, "Selection").  The
** rule decides only strictly convex quadrilaterals, so for ES the position
** of c and d is settled first by s = orient(b, c, d) and t = orient(a, c,
** d).  s > 0, t > 0: abcd is strictly convex, and d beats c when inside the
** shape through a, b, c.  s < 0, t < 0: abdc is, and c stays when inside
** the shape through a, b, d.  Otherwise one of c, d lies in the closed
** triangle of a, b and the other (a or b cannot: c and d would be on
** opposite sides of ab): s > 0, t < 0 puts d inside abc; s = 0 puts c, d
** on one ray from b and t < 0 says d is the nearer; t = 0 the same from a
** with s > 0.  A site inside triangle abc, or on its open side ac or bc,
** lies strictly inside every shape through a, b, c (a chord of a strictly
** convex region, and for a polygon K the perturbation of
** docs/emptyshape.md turns K so that no side of a homothet is parallel to
** a chord), so it beats c: d beats c exactly when s > 0 or t < 0.  For DT
** the perturbed in-circle sign is valid for d anywhere: one test. */
int paradigm_beats(const rule *r, ops_counts *c, geom_point a, geom_point b, geom_point pc,
                   geom_point d) {
  if (rule_shape(r) == NULL) return paradigm_inshape(r, c, a, b, pc, d) > 0;
  int sg = ops_orient(c, b, pc, d), tg = ops_orient(c, a, pc, d);
  if (sg > 0 && tg > 0) return paradigm_inshape(r, c, a, b, pc, d) > 0;
  if (sg < 0 && tg < 0) return paradigm_inshape(r, c, a, b, d, pc) < 0;
  return sg > 0 || tg < 0;
}

/* q strictly inside the rule's region through anticlockwise a, b, c, for q
** anywhere but a, b, c: q is strictly left of some side (the three open
** right half-planes have no common point), and on that side it is the
** order of paradigm_beats.  For ES: if q is left of ab, ask there; else if
** left of bc, there; else q lies in the closed angle opposite b, strictly
** left of ca (q is not b).  At most three orientation tests and one
** in-shape test. */
int paradigm_inregion(const rule *r, ops_counts *c, geom_point a, geom_point b,
                      geom_point pc, geom_point q) {
  if (rule_shape(r) == NULL) return paradigm_inshape(r, c, a, b, pc, q) > 0;
  if (ops_orient(c, a, b, q) > 0) return paradigm_beats(r, c, a, b, pc, q);
  if (ops_orient(c, b, pc, q) > 0) return paradigm_beats(r, c, b, pc, a, q);
  return paradigm_beats(r, c, pc, a, b, q);
}

static double paradigm_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Rotate each triangle to start at its smallest index, then sort. */
static int paradigm_tri_cmp(const void *x, const void *y) {
  const uint32_t *s = x, *t = y;
  for (int i = 0; i < 3; i++)
    if (s[i] != t[i]) return s[i] < t[i] ? -1 : 1;
  return 0;
}

/* A rotated triangle's smallest index, its bucket (geom_bucket_sort). */
static uint32_t paradigm_tri_first(const void *x) {
  return *(const uint32_t *)x;
}

/* Rotated triangles in paradigm_tri_cmp's order by geom_bucket_sort: -1 when the indices
** are sparse (the largest above 4t + 1024: no triangulation's) or the scratch cannot be
** had; the caller then sorts by qsort. */
static int paradigm_bucket_sort(uint32_t *tri, size_t ntri) {
  uint32_t top = 0;
  for (size_t t = 0; t < ntri; t++) top = tri[3 * t] > top ? tri[3 * t] : top;
  if ((size_t)top > 4 * ntri + 1024) return -1;
  return geom_bucket_sort(tri, ntri, 3 * sizeof *tri, top, paradigm_tri_first,
                          paradigm_tri_cmp);
}

void paradigm_canonical(uint32_t *tri, size_t ntri) {
  for (size_t t = 0; t < ntri; t++) {
    uint32_t *v = tri + 3 * t;
    while (v[0] > v[1] || v[0] > v[2]) {
      uint32_t x = v[0];
      v[0] = v[1], v[1] = v[2], v[2] = x;
    }
  }
  if (ntri > 64 && paradigm_bucket_sort(tri, ntri) == 0) return;
  qsort(tri, ntri, 3 * sizeof *tri, paradigm_tri_cmp);
}

/* Does algorithm a serve this problem and rule?  0, or -1 with its refusal. */
static int paradigm_serves(const paradigm_algorithm *a, const paradigm_input *in, char *err,
                           size_t errlen) {
  unsigned want = rule_is_shape(in->r) ? PARADIGM_RULE_ES
                : rule_is_delaunay(in->r) ? PARADIGM_RULE_DT : 0;
  if (!(a->problems & (unsigned)in->problem)) {
    snprintf(err, errlen, "algorithm %s does not solve the %s problem (%s)", a->name,
             paradigm_problem_name(in->problem), a->refusal);
    return -1;
  }
  if (!(a->rules & want)) {
    snprintf(err, errlen, "algorithm %s needs the rule DT%s, not %s", a->name,
             a->rules & PARADIGM_RULE_ES ? " or an empty-shape rule ES:SHAPE" : "",
             in->r->name);
    return -1;
  }
  return 0;
}

/* The distinct points (first occurrences, in input order) and the map
** from their index back to the input's.  0, or -1 with the message. */
static int paradigm_distinct(const paradigm_input *in, geom_point **q, uint32_t **back,
                             size_t *m, char *err, size_t errlen) {
  uint32_t *first = malloc((in->n ? in->n : 1) * sizeof *first);
  long d = first ? lot_distinct(in->p, in->n, first) : -1;
  *q = d >= 0 ? malloc((size_t)(d ? d : 1) * sizeof **q) : NULL;
  *back = d >= 0 ? malloc((size_t)(d ? d : 1) * sizeof **back) : NULL;
  if (*q == NULL || *back == NULL) {
    free(first), free(*q), free(*back);
    snprintf(err, errlen, "out of memory for %zu points", in->n);
    return -1;
  }
  *m = 0;
  for (size_t i = 0; i < in->n; i++)
    if (first[i] == i) (*q)[*m] = in->p[i], (*back)[(*m)++] = (uint32_t)i;
  free(first);
  return 0;
}

/* Coordinates within the contract, three distinct points not collinear. */
static int paradigm_check(const geom_point *q, size_t m, const paradigm_input *in, char *err,
                          size_t errlen) {
  for (size_t i = 0; i < in->n; i++)
    if (geom_coord_check(in->p[i].x) != GEOM_COORD_OK
        || geom_coord_check(in->p[i].y) != GEOM_COORD_OK) {
      snprintf(err, errlen, "point %zu: %s", i + 1,
               geom_coorderr_str(geom_coord_check(in->p[i].x) != GEOM_COORD_OK
                                 ? geom_coord_check(in->p[i].x) : geom_coord_check(in->p[i].y)));
      return -1;
    }
  for (size_t k = 2; k < m; k++)
    if (geom_orient_valid(q[0], q[1], q[k]) != 0) return 0;
  snprintf(err, errlen, "all %zu points are %s: a triangulation needs three non-collinear "
           "points", in->n, m < 2 ? "equal" : "collinear");
  return -1;
}

/* The segments of a constrained problem in the distinct points' indices
** (in->segments names input points, duplicates included): 0 with *seg
** (NULL when there are none), or -1 with the message. */
static int paradigm_segments(const paradigm_input *in, uint32_t **seg, char *err,
                             size_t errlen) {
  *seg = NULL;
  if (in->problem != PARADIGM_CONSTRAINED || in->nsegments == 0) return 0;
  for (size_t k = 0; k < 2 * in->nsegments; k++)
    if (in->segments[k] >= in->n) {
      snprintf(err, errlen, "segment %zu: point index %u out of range (%zu points)", k / 2,
               in->segments[k], in->n);
      return -1;
    }
  uint32_t *map = malloc(in->n * sizeof *map), m = 0;
  *seg = malloc(2 * in->nsegments * sizeof **seg);
  if (map == NULL || *seg == NULL || lot_distinct(in->p, in->n, map) < 0) {
    free(map), free(*seg), *seg = NULL;
    snprintf(err, errlen, "out of memory for %zu segments", in->nsegments);
    return -1;
  }
  for (size_t i = 0; i < in->n; i++) map[i] = map[i] == i ? m++ : map[map[i]];
  for (size_t k = 0; k < 2 * in->nsegments; k++) (*seg)[k] = map[in->segments[k]];
  free(map);
  return 0;
}

/* A polygon's vertices are its boundary in order: a repeated vertex is
** refused (merging it would make another polygon).  back is increasing
** with back[k] = k until the first repeat, so that repeat is the first k
** where back[k] != k (or m).  0, or -1 naming the vertex. */
static int paradigm_repeats(const paradigm_input *in, const uint32_t *back, size_t m,
                            char *err, size_t errlen) {
  if ((in->problem != PARADIGM_POLYGON && in->problem != PARADIGM_CONVEX) || m == in->n)
    return 0;
  size_t k = 0;
  while (k < m && back[k] == k) k++;
  snprintf(err, errlen, "%s polygon: vertex %zu repeats an earlier vertex",
           in->problem == PARADIGM_CONVEX ? "convex" : "simple", k + 1);
  return -1;
}

int paradigm_run(const paradigm_algorithm *a, const paradigm_input *in, paradigm_result *out,
                 char *err, size_t errlen) {
  memset(out, 0, sizeof *out);
  if (paradigm_serves(a, in, err, errlen) != 0) return -1;
  geom_point *q;
  uint32_t *back;
  size_t m;
  if (paradigm_distinct(in, &q, &back, &m, err, errlen) != 0) return -1;
  int rc = paradigm_check(q, m, in, err, errlen);
  if (rc == 0) rc = paradigm_repeats(in, back, m, err, errlen);
  uint32_t *seg = NULL;
  if (rc == 0) rc = paradigm_segments(in, &seg, err, errlen);
  paradigm_input sub = *in;
  sub.p = q, sub.n = m;
  if (seg != NULL) sub.segments = seg;
  paradigm_output o = {0};
  unsigned long exact0 = geom_exact_calls();
  double t0 = paradigm_now();
  if (rc == 0) rc = a->run(&sub, &o, err, errlen);
  out->seconds = paradigm_now() - t0;
  o.ops.v[OPS_EXACT] += geom_exact_calls() - exact0;
  if (rc == 0) {
    for (size_t k = 0; k < 3 * o.ntri; k++) o.tri[k] = back[o.tri[k]];
    paradigm_canonical(o.tri, o.ntri);
    out->tri = o.tri, out->ntri = o.ntri, out->ops = o.ops, out->distinct = m;
  } else {
    free(o.tri);
  }
  free(q), free(back), free(seg);
  return rc;
}

void paradigm_result_free(paradigm_result *r) {
  free(r->tri);
  r->tri = NULL;
  r->ntri = 0;
}
