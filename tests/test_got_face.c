/*
** test_got_face.c: the exact solver for a point set's faces (got/got_face.c)
** against enumeration of every triangulation (classify/siteflip.h).
**
** For small point sets (n <= 10: uniform, small integer grids full of
** collinear triples, cocircular Pythagorean points, convex position with
** points inside) the whole convex hull is one face: outer walk the hull
** (collinear boundary points included), inner points the others, allowed
** edges every segment holding no third point.  The optimum must equal the
** least total over all triangulations, the runner-up the second least
** (a distinct triangulation), within the certified error bounds, the
** triangles must be the enumerated optimum's when it is clearly unique, and
** the certified verdict must never claim uniqueness of a tie.  Faces with a
** hole (an inner segment or triangle walked as a second walk) and with a
** dangling edge (a hull vertex to an inner point, walked twice) are checked
** against the triangulations containing those edges.  A face larger than
** the search's limit is refused with one line.  A triangle hole pinned to
** the outer walk at one vertex (visited twice) is checked the same way.
*/
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "geom.h"
#include "measure.h"
#include "rule.h"
#include "siteflip.h"
#include "got_face.h"
#include "testutil.h"

#define TF_MAXN 10
#define TF_MAXE (TF_MAXN * TF_MAXN)

static const char *const tf_rules[] = {"P_1", "R_1", "-alpha_1", "a_2", "Pinf_1", "P_3",
                                       "-A_1", "sigma_2"};
#define TF_NRULES (sizeof tf_rules / sizeof *tf_rules)

/* A face built from a point set, and what enumeration must respect. */
typedef struct tf_face {
  size_t n;
  geom_point p[TF_MAXN];
  size_t nwalks, walk_len[3], nwalk;
  uint32_t walk[3 * TF_MAXN];
  uint32_t inner[TF_MAXN];
  size_t ninner;
  uint32_t edge[2 * TF_MAXE];
  size_t nedges;
  int need[TF_MAXE][2];     /* edges every counted triangulation holds */
  size_t nneed;
  int hole[3];              /* a triangle hole, excluded from the totals (-1: none) */
} tf_face;

/* 1 when q lies on the open segment ab. */
static int tf_between(geom_point a, geom_point b, geom_point q) {
  if (geom_orient(a, b, q) != 0) return 0;
  return (q.x - a.x) * (q.x - b.x) + (q.y - a.y) * (q.y - b.y) < 0;
}

static int tf_segment_clear(const tf_face *f, size_t i, size_t j) {
  for (size_t k = 0; k < f->n; k++)
    if (k != i && k != j && tf_between(f->p[i], f->p[j], f->p[k])) return 0;
  return 1;
}

static int tf_lex_cmp(const void *x, const void *y, const geom_point *p) {
  geom_point a = p[*(const uint32_t *)x], b = p[*(const uint32_t *)y];
  return geom_lexless(a, b) ? -1 : geom_lexless(b, a);
}

/* The strict hull anticlockwise (Andrew's monotone chain) into h; its size. */
static size_t tf_strict_hull(const tf_face *f, uint32_t *h) {
  uint32_t o[TF_MAXN];
  size_t n = f->n, m = 0;
  for (size_t i = 0; i < n; i++) o[i] = (uint32_t)i;
  for (size_t i = 1; i < n; i++)   /* insertion sort, lexicographic */
    for (size_t j = i; j > 0 && tf_lex_cmp(&o[j], &o[j - 1], f->p) < 0; j--) {
      uint32_t t = o[j];
      o[j] = o[j - 1], o[j - 1] = t;
    }
  for (size_t pass = 0; pass < 2; pass++) {
    size_t base = m;
    for (size_t q = 0; q < n; q++) {
      uint32_t v = pass == 0 ? o[q] : o[n - 1 - q];
      while (m >= base + 2 && geom_orient(f->p[h[m - 2]], f->p[h[m - 1]], f->p[v]) <= 0) m--;
      h[m++] = v;
    }
    m--;   /* the last point starts the other chain */
  }
  return m;
}

/* The hull anticlockwise with the points on its edges, as walk 0; the
** other points inner; every clear segment allowed. */
static void tf_hull_face(tf_face *f) {
  uint32_t s[2 * TF_MAXN + 2];
  size_t n = f->n, hs = tf_strict_hull(f, s), h = 0;
  int on[TF_MAXN] = {0};
  for (size_t e = 0; e < hs; e++) {
    geom_point b = f->p[s[(e + 1) % hs]];
    f->walk[h++] = s[e];
    on[s[e]] = 1;
    for (;;) {   /* the points on edge e, nearest first */
      size_t best = n;
      for (size_t q = 0; q < n; q++)
        if (!on[q] && tf_between(f->p[f->walk[h - 1]], b, f->p[q])) best = q;
      if (best == n) break;
      for (size_t q = 0; q < n; q++)
        if (!on[q] && tf_between(f->p[f->walk[h - 1]], f->p[best], f->p[q])) best = q;
      f->walk[h++] = (uint32_t)best;
      on[best] = 1;
    }
  }
  f->nwalks = 1, f->walk_len[0] = h, f->nwalk = h;
  f->ninner = 0;
  for (size_t i = 0; i < n; i++)
    if (!on[i]) f->inner[f->ninner++] = (uint32_t)i;
  f->nedges = 0;
  for (size_t i = 0; i < n; i++)
    for (size_t j = i + 1; j < n; j++)
      if (tf_segment_clear(f, i, j))
        f->edge[2 * f->nedges] = (uint32_t)i, f->edge[2 * f->nedges++ + 1] = (uint32_t)j;
  f->nneed = 0;
  f->hole[0] = -1;
}

/* ---- enumeration ---- */

typedef struct tf_enum {
  double best, second;
  int has2, count, node;
  double gap;     /* second - best */
} tf_enum;

static int tf_tri_is_hole(const tf_face *f, const unsigned char v[3]) {
  if (f->hole[0] < 0) return 0;
  int m = 0;
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) m += v[a] == f->hole[b];
  return m == 3;
}

static double tf_node_total(const siteflip_graph *g, const tf_face *f, const rule *r, int u) {
  double s = 0;
  for (int t = 0; t < g->per; t++) {
    int q = g->node_tri[(size_t)u * (size_t)g->per + (size_t)t];
    if (tf_tri_is_hole(f, g->tri_v[q])) continue;
    s += rule_key(r, measure_eval(rule_measure(r), &g->tri[q]));
  }
  return s;
}

static tf_enum tf_enumerate(const siteflip_graph *g, const tf_face *f, const rule *r) {
  tf_enum e = {INFINITY, INFINITY, 0, 0, -1, INFINITY};
  for (int u = 0; u < g->nnodes; u++) {
    int ok = 1;
    for (size_t k = 0; k < f->nneed && ok; k++)
      ok = siteflip_has_edge(g, u, f->need[k][0], f->need[k][1]);
    if (!ok) continue;
    double s = tf_node_total(g, f, r, u);
    e.count++;
    if (s < e.best) e.second = e.best, e.best = s, e.node = u;
    else if (s < e.second) e.second = s;
  }
  e.has2 = e.count > 1;
  e.gap = e.second - e.best;
  return e;
}

/* ---- the comparison ---- */

static int tf_u32x3_cmp(const void *x, const void *y) {
  const uint32_t *a = x, *b = y;
  for (int k = 0; k < 3; k++)
    if (a[k] != b[k]) return a[k] < b[k] ? -1 : 1;
  return 0;
}

static void tf_sort3(uint32_t *t) {
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2 - i; j++)
      if (t[j] > t[j + 1]) {
        uint32_t s = t[j];
        t[j] = t[j + 1], t[j + 1] = s;
      }
}

/* The enumerated optimum's triangles equal the solver's (sorted). */
static void tf_same_triangles(const siteflip_graph *g, const tf_face *f, const tf_enum *e,
                              const got_face_out *o) {
  uint32_t want[3 * 32], got[3 * 32];
  size_t nw = 0;
  for (int t = 0; t < g->per; t++) {
    int q = g->node_tri[(size_t)e->node * (size_t)g->per + (size_t)t];
    if (tf_tri_is_hole(f, g->tri_v[q])) continue;
    for (int k = 0; k < 3; k++) want[3 * nw + (size_t)k] = g->tri_v[q][k];
    nw++;
  }
  assert_int_equal(nw, o->ntri);
  for (size_t t = 0; t < o->ntri; t++) {
    memcpy(got + 3 * t, o->tri + 3 * t, 3 * sizeof *got);
    assert_true(geom_orient(f->p[got[3 * t]], f->p[got[3 * t + 1]], f->p[got[3 * t + 2]]) > 0);
    tf_sort3(got + 3 * t);
  }
  qsort(got, nw, 3 * sizeof *got, tf_u32x3_cmp);
  qsort(want, nw, 3 * sizeof *want, tf_u32x3_cmp);
  assert_memory_equal(got, want, 3 * nw * sizeof *got);
}

/* The face, printed when a check fails. */
static void tf_dump(const tf_face *f) {
  for (size_t i = 0; i < f->n; i++) print_message("p%zu %.17g %.17g\n", i, f->p[i].x, f->p[i].y);
  for (size_t i = 0; i < f->nwalk; i++) print_message("walk %u\n", f->walk[i]);
}

static void tf_solve(const tf_face *f, const rule *r, got_face_out *o) {
  got_face_in in = {f->p, f->nwalks, f->walk_len, f->walk, f->inner, f->ninner, f->edge,
                    f->nedges};
  char err[256];
  if (got_face_solve(&in, r, o, err, sizeof err) != 0) {
    tf_dump(f);
    fail_msg("%s: %s", rule_name(r), err);
  }
}

/* What the checks met: faces with inner points, exact ties (the
** enumeration's two least totals equal), certified unique optima. */
static struct { int inner, ties, unique, checks; } tf_seen;

/* Solve f under r and compare with enumeration. */
static void tf_check(const siteflip_graph *g, const tf_face *f, const rule *r) {
  tf_enum e = tf_enumerate(g, f, r);
  got_face_out o;
  tf_solve(f, r, &o);
  double tol = 1e-12 * (1 + fabs(e.best));
  if (isfinite(o.err)) tol = fmax(tol, 2 * o.err);
  if (fabs(o.key - e.best) > tol) {
    tf_dump(f);
    fail_msg("%s n=%zu: key %.17g, enumeration %.17g", rule_name(r), f->n, o.key, e.best);
  }
  assert_int_equal(o.has_runner_up, e.has2);
  if (e.has2 && fabs(o.key2 - e.second) > tol)
    fail_msg("%s n=%zu: key2 %.17g, enumeration %.17g", rule_name(r), f->n, o.key2, e.second);
  if (o.unique && e.has2 && !(e.gap > 0))
    fail_msg("%s n=%zu: certified unique but tied in enumeration", rule_name(r), f->n);
  if (e.has2 && isfinite(o.err) && e.gap > 1e-9 * (1 + fabs(e.best))) assert_true(o.unique);
  if (!e.has2 || e.gap > 1e-9 * (1 + fabs(e.best))) tf_same_triangles(g, f, &e, &o);
  tf_seen.checks++, tf_seen.inner += f->ninner > 0, tf_seen.unique += o.unique;
  tf_seen.ties += e.has2 && e.gap == 0;
  got_face_out_free(&o);
}

static void tf_check_rules(const tf_face *f) {
  char err[256];
  siteflip_graph *g = siteflip_build(f->p, (int)f->n, err, sizeof err);
  if (g == NULL) fail_msg("siteflip_build: %s", err);
  for (size_t q = 0; q < TF_NRULES; q++) {
    rule r;
    assert_int_equal(rule_parse(tf_rules[q], &r, err, sizeof err), 0);
    tf_check(g, f, &r);
  }
  siteflip_free(g);
}

/* ---- point sets ---- */

static int tf_distinct_ok(const tf_face *f) {
  char err[256];
  return siteflip_check(f->p, (int)f->n, err, sizeof err) == 0;
}

/* kind 0: uniform; 1: integer grid 0..3; 2: Pythagorean points of the
** circle of radius 5 with up to two lattice points inside; 3: convex
** position (a circle) with 1..3 points inside. */
static void tf_points(testutil_rng *g, int kind, tf_face *f) {
  static const geom_point pyth[12] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3},
                                      {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  do {
    f->n = 4 + testutil_next(g) % (TF_MAXN - 3);
    size_t k = kind == 2 ? 4 + testutil_next(g) % 5 : kind == 3 ? 4 + testutil_next(g) % 5 : 0;
    if (kind >= 2 && f->n < k + 1) f->n = k + 1;
    for (size_t i = 0; i < f->n; i++) {
      double t = 6.283185307179586 * testutil_uniform(g);
      if (kind == 0) f->p[i] = (geom_point){testutil_uniform(g), testutil_uniform(g)};
      else if (kind == 1) f->p[i] = (geom_point){(double)(testutil_next(g) % 4),
                                                 (double)(testutil_next(g) % 4)};
      else if (kind == 2 && i < k) f->p[i] = pyth[testutil_next(g) % 12];
      else if (kind == 2) f->p[i] = (geom_point){(double)(testutil_next(g) % 5) - 2,
                                                 (double)(testutil_next(g) % 5) - 2};
      else if (i < k) f->p[i] = (geom_point){cos(t), sin(t)};
      else f->p[i] = (geom_point){0.5 * testutil_uniform(g) - 0.25,
                                  0.5 * testutil_uniform(g) - 0.25};
    }
  } while (!tf_distinct_ok(f));
  tf_hull_face(f);
}

static void test_hull_faces(void **state) {
  (void)state;
  testutil_rng g = {38};
  int reps = testutil_reps(300);
  for (int kind = 0; kind < 4; kind++)
    for (int s = 0; s < reps; s++) {
      tf_face f;
      tf_points(&g, kind, &f);
      tf_check_rules(&f);
    }
  print_message("hull faces: %d checks, %d with inner points, %d exact ties, %d unique\n",
                tf_seen.checks, tf_seen.inner, tf_seen.ties, tf_seen.unique);
  assert_true(tf_seen.inner > tf_seen.checks / 2);
  assert_true(tf_seen.ties > tf_seen.checks / 50);
  assert_true(tf_seen.unique > tf_seen.checks / 2);
}

/* A square under P_1 (two diagonals of one length), and -A_1 (every
** triangulation has the same total area): exact ties, never "unique". */
static void test_ties(void **state) {
  (void)state;
  tf_face f = {.n = 4, .p = {{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  tf_hull_face(&f);
  const char *names[] = {"P_1", "-A_1", "a_2", "Pinf_1", "P_3"};
  for (size_t q = 0; q < sizeof names / sizeof *names; q++) {
    rule r;
    char err[256];
    got_face_out o;
    assert_int_equal(rule_parse(names[q], &r, err, sizeof err), 0);
    tf_solve(&f, &r, &o);
    assert_int_equal(o.ntri, 2);
    assert_true(o.has_runner_up);
    assert_true(o.key2 == o.key);
    assert_int_equal(o.unique, 0);
    got_face_out_free(&o);
  }
  tf_check_rules(&f);
}

/* ---- holes and dangling edges ---- */

static void tf_need(tf_face *f, uint32_t u, uint32_t v) {
  f->need[f->nneed][0] = (int)u, f->need[f->nneed][1] = (int)v;
  f->nneed++;
}

static void tf_drop_inner(tf_face *f, uint32_t u) {
  size_t m = 0;
  for (size_t i = 0; i < f->ninner; i++)
    if (f->inner[i] != u) f->inner[m++] = f->inner[i];
  f->ninner = m;
}

/* 1 when u v w is a proper triangle with clear sides and no point inside. */
static int tf_empty_triangle(const tf_face *f, uint32_t u, uint32_t v, uint32_t w) {
  int o = geom_orient(f->p[u], f->p[v], f->p[w]);
  if (o == 0 || !tf_segment_clear(f, u, v) || !tf_segment_clear(f, v, w) ||
      !tf_segment_clear(f, w, u))
    return 0;
  for (size_t k = 0; k < f->n; k++)
    if (k != u && k != v && k != w && geom_orient(f->p[u], f->p[v], f->p[k]) == o &&
        geom_orient(f->p[v], f->p[w], f->p[k]) == o &&
        geom_orient(f->p[w], f->p[u], f->p[k]) == o)
      return 0;
  return 1;
}

/* A second walk: the inner segment u v (walked both ways), or the empty
** inner triangle u v w (clockwise: the face on its left, outside). */
static int tf_add_hole(tf_face *f, int tri) {
  if (f->ninner < (size_t)(2 + tri)) return 0;
  uint32_t u = f->inner[0], v = f->inner[1], w = tri ? f->inner[2] : 0;
  if (!tf_segment_clear(f, u, v)) return 0;
  uint32_t *h = f->walk + f->nwalk;
  if (!tri) {
    h[0] = u, h[1] = v;
  } else {
    int o = geom_orient(f->p[u], f->p[v], f->p[w]);
    if (!tf_empty_triangle(f, u, v, w)) return 0;
    if (o > 0) h[0] = u, h[1] = w, h[2] = v;
    else h[0] = u, h[1] = v, h[2] = w;
    tf_need(f, v, w), tf_need(f, w, u);
    f->hole[0] = (int)u, f->hole[1] = (int)v, f->hole[2] = (int)w;
    tf_drop_inner(f, w);
  }
  tf_need(f, u, v);
  tf_drop_inner(f, u), tf_drop_inner(f, v);
  f->walk_len[f->nwalks++] = 2 + (size_t)tri;
  f->nwalk += 2 + (size_t)tri;
  return 1;
}

/* A dangling edge from the outer walk's vertex 0 to an inner point u, and
** on to a second inner point v when chain: walk h u (v u) h. */
static int tf_add_dangling(tf_face *f, int chain) {
  if (f->nwalks != 1 || f->ninner < (size_t)(1 + chain)) return 0;
  uint32_t h = f->walk[0], u = f->inner[0], v = chain ? f->inner[1] : 0;
  if (!tf_segment_clear(f, h, u) || (chain && !tf_segment_clear(f, u, v))) return 0;
  size_t L = f->walk_len[0], add = chain ? 4 : 2;
  uint32_t w[3 * TF_MAXN];
  size_t m = 0;
  w[m++] = h, w[m++] = u;
  if (chain) w[m++] = v, w[m++] = u;
  for (size_t i = 0; i < L; i++) w[m++] = f->walk[i];
  memcpy(f->walk, w, m * sizeof *w);
  f->walk_len[0] = L + add, f->nwalk = L + add;
  tf_need(f, h, u), tf_drop_inner(f, u);
  if (chain) tf_need(f, u, v), tf_drop_inner(f, v);
  return 1;
}

/* A hole pinned to the outer walk's vertex 0: the empty triangle h x y
** with x, y inside, walked clockwise from h (h visited twice). */
static int tf_add_pinned(tf_face *f) {
  if (f->nwalks != 1 || f->ninner < 2) return 0;
  uint32_t h = f->walk[0], x = f->inner[0], y = f->inner[1];
  if (!tf_empty_triangle(f, h, x, y)) return 0;
  if (geom_orient(f->p[h], f->p[x], f->p[y]) > 0) {
    uint32_t t = x;
    x = y, y = t;
  }
  size_t L = f->walk_len[0];
  uint32_t w[3 * TF_MAXN];
  w[0] = h, w[1] = x, w[2] = y;
  memcpy(w + 3, f->walk, L * sizeof *w);
  memcpy(f->walk, w, (L + 3) * sizeof *w);
  f->walk_len[0] = L + 3, f->nwalk = L + 3;
  tf_need(f, h, x), tf_need(f, x, y), tf_need(f, y, h);
  f->hole[0] = (int)h, f->hole[1] = (int)x, f->hole[2] = (int)y;
  tf_drop_inner(f, x), tf_drop_inner(f, y);
  return 1;
}

static void test_holes_and_dangling(void **state) {
  (void)state;
  testutil_rng g = {3801};
  int reps = testutil_reps(200), done[5] = {0};
  for (int s = 0; s < reps; s++) {
    for (int mode = 0; mode < 5; mode++) {
      tf_face f;
      tf_points(&g, s % 2 == 0 ? 0 : 3, &f);
      int ok = mode < 2 ? tf_add_hole(&f, mode)
             : mode < 4 ? tf_add_dangling(&f, mode - 2) : tf_add_pinned(&f);
      if (!ok) continue;
      done[mode]++;
      tf_check_rules(&f);
    }
  }
  print_message("faces: %d segment holes, %d triangle holes, %d dangling edges, %d chains, "
                "%d pinned triangles\n", done[0], done[1], done[2], done[3], done[4]);
  for (int mode = 0; mode < 5; mode++) assert_true(done[mode] >= reps / 10);
}

/* ---- refusals ---- */

static void test_refusals(void **state) {
  (void)state;
  testutil_rng g = {7};
  tf_face f = {.n = TF_MAXN};
  for (size_t i = 0; i < 6; i++)
    f.p[i] = (geom_point){cos(1.0471975511965976 * (double)i), sin(1.0471975511965976 * (double)i)};
  for (size_t i = 6; i < TF_MAXN; i++)
    f.p[i] = (geom_point){0.6 * testutil_uniform(&g) - 0.3, 0.6 * testutil_uniform(&g) - 0.3};
  tf_hull_face(&f);
  got_face_in in = {f.p, f.nwalks, f.walk_len, f.walk, f.inner, f.ninner, f.edge, f.nedges};
  rule r;
  char err[256];
  got_face_out o;
  assert_int_equal(rule_parse("P_1", &r, err, sizeof err), 0);
  assert_int_equal(got_face_solve_limit(&in, &r, 20, &o, err, sizeof err), -1);
  assert_non_null(strstr(err, "too large"));
  assert_non_null(strstr(err, "20 regions"));
  assert_null(strchr(err, '\n'));
  assert_null(o.tri);
  assert_int_equal(rule_parse("P_inf", &r, err, sizeof err), 0);
  assert_int_equal(got_face_solve(&in, &r, &o, err, sizeof err), -1);
  assert_non_null(strstr(err, "not a sum rule"));
  assert_int_equal(rule_parse("P_1", &r, err, sizeof err), 0);
  uint32_t cw[TF_MAXN];   /* the hull walked clockwise: the face would be outside */
  for (size_t i = 0; i < f.walk_len[0]; i++) cw[i] = f.walk[f.walk_len[0] - 1 - i];
  in.walk = cw;
  assert_int_equal(got_face_solve(&in, &r, &o, err, sizeof err), -1);
  assert_null(strchr(err, '\n'));
  in.walk = f.walk;
  size_t bad = 2;
  in.walk_len = &bad;
  assert_int_equal(got_face_solve(&in, &r, &o, err, sizeof err), -1);
  assert_null(strchr(err, '\n'));
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_ties),
    cmocka_unit_test(test_hull_faces),
    cmocka_unit_test(test_holes_and_dangling),
    cmocka_unit_test(test_refusals),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
