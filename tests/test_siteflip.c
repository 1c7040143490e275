/*
** test_siteflip.c: the triangulations and flip graphs of small site sets.
** Counts against Catalan numbers and against an independent brute force
** (every maximal non-crossing set of segments, in integer arithmetic, on
** integer sites that include collinear triples); thesis figure 3.8; the
** DT-equivalent rules; triangle rules never cycle; the best sink is the
** GOT of `got` for convex polygons and the GOT itself is a sink for the
** joints -1, 0, 1, 2; the capped count says "more than K" exactly when
** the full count exceeds K; bad site sets are refused with one line.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "got.h"
#include "measure.h"
#include "rule.h"
#include "sampler.h"
#include "siteflip.h"
#include "testutil.h"

static siteflip_graph *tsf_build(const geom_point *p, int n) {
  char err[256];
  siteflip_graph *g = siteflip_build(p, n, err, sizeof err);
  if (g == NULL) fail_msg("siteflip_build: %s", err);
  return g;
}

static rule tsf_rule(const char *name) {
  rule r;
  char err[4096];
  if (rule_parse(name, &r, err, sizeof err) != 0) fail_msg("%s: %s", name, err);
  return r;
}

/* ---- counts ------------------------------------------------------------- */

static void test_catalan(void **state) {
  (void)state;
  long cat[13] = {1, 1, 2, 5, 14, 42, 132, 429, 1430, 4862, 16796, 58786, 208012};
  for (int n = 3; n <= 14; n++) {
    geom_point p[14];
    sampler_convex(7, (uint64_t)n, n, p);
    siteflip_graph *g = tsf_build(p, n);
    assert_int_equal(g->nnodes, cat[n - 2]);
    assert_int_equal(g->per, n - 2);
    assert_int_equal(g->ntris, n * (n - 1) * (n - 2) / 6);
    /* every triangulation has n - 3 diagonals, each flippable */
    assert_int_equal(g->nedges, cat[n - 2] * (n - 3) / 2);
    assert_int_equal(g->nquads, n < 4 ? 0 : n * (n - 1) * (n - 2) * (n - 3) / 24);
    siteflip_free(g);
  }
}

static void test_quad_with_interior_site(void **state) {
  (void)state;
  geom_point p[5] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.45, 0.4}};
  siteflip_graph *g = tsf_build(p, 5);
  assert_int_equal(g->nnodes, 3);
  assert_int_equal(g->nedges, 2);
  assert_int_equal(g->per, 4);
  siteflip_free(g);
  /* on the diagonal: the diagonal is blocked, one triangulation (the star) */
  geom_point c[5] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
  g = tsf_build(c, 5);
  assert_int_equal(g->nnodes, 1);
  assert_int_equal(g->nedges, 0);
  siteflip_free(g);
}

/* Independent brute force, integer sites: every set of valid segments with
** no proper crossing, by backtracking over segments, counted when maximal. */
typedef struct tsf_bf {
  int n, nseg, a[28], b[28];
  long long x[8], y[8];
  int cross[28][28];
  int chosen[28];
  long count;
} tsf_bf;

static long long tsf_orient(const tsf_bf *s, int i, int j, int k) {
  long long d = (s->x[j] - s->x[i]) * (s->y[k] - s->y[i]) - (s->y[j] - s->y[i]) * (s->x[k] - s->x[i]);
  return (d > 0) - (d < 0);
}

static int tsf_inside(const tsf_bf *s, int i, int j, int k) {
  if (tsf_orient(s, i, j, k) != 0) return 0;
  long long lx = s->x[i] < s->x[j] ? s->x[i] : s->x[j], hx = s->x[i] ^ s->x[j] ^ lx;
  long long ly = s->y[i] < s->y[j] ? s->y[i] : s->y[j], hy = s->y[i] ^ s->y[j] ^ ly;
  return lx <= s->x[k] && s->x[k] <= hx && ly <= s->y[k] && s->y[k] <= hy;
}

static void tsf_bf_walk(tsf_bf *s, int at) {
  if (at == s->nseg) {
    for (int t = 0; t < s->nseg; t++) {
      if (s->chosen[t]) continue;
      int free_ = 1;
      for (int u = 0; u < s->nseg && free_; u++) free_ = !(s->chosen[u] && s->cross[t][u]);
      if (free_) return;   /* t could be added: not maximal */
    }
    s->count++;
    return;
  }
  int ok = 1;
  for (int u = 0; u < at && ok; u++) ok = !(s->chosen[u] && s->cross[at][u]);
  if (ok) {
    s->chosen[at] = 1;
    tsf_bf_walk(s, at + 1);
    s->chosen[at] = 0;
  }
  tsf_bf_walk(s, at + 1);
}

static long tsf_brute(const geom_point *p, int n) {
  tsf_bf *s = calloc(1, sizeof *s);
  s->n = n;
  for (int i = 0; i < n; i++) {
    s->x[i] = (long long)p[i].x;
    s->y[i] = (long long)p[i].y;
  }
  for (int i = 0; i < n; i++)
    for (int j = i + 1; j < n; j++) {
      int ok = 1;
      for (int k = 0; k < n; k++) ok &= k == i || k == j || !tsf_inside(s, i, j, k);
      if (!ok) continue;   /* a site on it: never an edge */
      s->a[s->nseg] = i;
      s->b[s->nseg++] = j;
    }
  for (int t = 0; t < s->nseg; t++)
    for (int u = 0; u < s->nseg; u++) {
      int i = s->a[t], j = s->b[t], k = s->a[u], l = s->b[u];
      s->cross[t][u] = i != k && i != l && j != k && j != l &&
                       tsf_orient(s, i, j, k) * tsf_orient(s, i, j, l) < 0 &&
                       tsf_orient(s, k, l, i) * tsf_orient(s, k, l, j) < 0;
    }
  tsf_bf_walk(s, 0);
  long c = s->count;
  free(s);
  return c;
}

static void test_brute_force(void **state) {
  (void)state;
  testutil_rng r = {4242};
  int sets = 0, collinear_sets = 0;
  while (sets < 300) {
    int n = 4 + (int)(testutil_next(&r) % 5);   /* 4 .. 8 */
    geom_point p[8];
    for (int i = 0; i < n; i++)
      p[i] = (geom_point){(double)(testutil_next(&r) % 7), (double)(testutil_next(&r) % 7)};
    char err[256];
    if (siteflip_check(p, n, err, sizeof err) != 0) continue;   /* duplicates, all collinear */
    sets++;
    int col = 0;
    for (int i = 0; i < n; i++)
      for (int j = i + 1; j < n; j++)
        for (int k = j + 1; k < n; k++) col |= geom_orient(p[i], p[j], p[k]) == 0;
    collinear_sets += col;
    siteflip_graph *g = tsf_build(p, n);
    long want = tsf_brute(p, n);
    if (g->nnodes != want) {
      for (int i = 0; i < n; i++) print_error("(%g,%g) ", p[i].x, p[i].y);
      fail_msg("siteflip %d triangulations, brute force %ld", g->nnodes, want);
    }
    /* every node distinct, every flip joins nodes differing in one edge */
    for (int e = 0; e < g->nedges; e++) {
      siteflip_mask a = g->node[g->edge[e].ac], b = g->node[g->edge[e].bd];
      int d = __builtin_popcountll(a.lo ^ b.lo) + __builtin_popcountll(a.hi ^ b.hi);
      assert_int_equal(d, 2);
    }
    siteflip_free(g);
  }
  print_message("300 integer site sets, %d with collinear triples\n", collinear_sets);
  assert_true(collinear_sets > 50);
}


/* ---- beyond 12 sites --------------------------------------------------- */

/* A second independent count, by triangles instead of segments and flips
** (an advancing front): the open directed edge of least index (the region
** to its left not yet covered) gets its one triangle, any empty triangle
** to its left whose directed sides are unused and whose new sides cross no
** placed edge.  Hull edges start open; the outside of a hull edge never
** opens.  Every triangulation is reached once, by the triangles it has on
** the edges chosen.  Integer sites, exact orientation. */
#define TSF_FR_MAX 16
typedef struct tsf_front {
  int n;
  long long x[TSF_FR_MAX], y[TSF_FR_MAX];
  unsigned char used[TSF_FR_MAX][TSF_FR_MAX];    /* a triangle lies left of i->j */
  unsigned char hull[TSF_FR_MAX][TSF_FR_MAX];    /* i->j is a hull edge (interior left) */
  unsigned char empty[TSF_FR_MAX][TSF_FR_MAX][TSF_FR_MAX];   /* ijk anticlockwise, empty */
  long count;
} tsf_front;

static int tsf_fr_orient(const tsf_front *f, int i, int j, int k) {
  long long d = (f->x[j] - f->x[i]) * (f->y[k] - f->y[i]) - (f->y[j] - f->y[i]) * (f->x[k] - f->x[i]);
  return (d > 0) - (d < 0);
}

/* k on the closed segment ij (collinear and inside its box) */
static int tsf_fr_on(const tsf_front *f, int i, int j, int k) {
  if (tsf_fr_orient(f, i, j, k) != 0) return 0;
  return (f->x[k] - f->x[i]) * (f->x[k] - f->x[j]) <= 0 && (f->y[k] - f->y[i]) * (f->y[k] - f->y[j]) <= 0;
}

static int tsf_fr_cross(const tsf_front *f, int a, int b, int c, int d) {
  if (a == c || a == d || b == c || b == d) return 0;
  return tsf_fr_orient(f, a, b, c) * tsf_fr_orient(f, a, b, d) < 0 &&
         tsf_fr_orient(f, c, d, a) * tsf_fr_orient(f, c, d, b) < 0;
}

static int tsf_fr_blocked(const tsf_front *f, int p, int q) {
  for (int x = 0; x < f->n; x++)
    for (int y = x + 1; y < f->n; y++)
      if ((f->used[x][y] || f->used[y][x]) && tsf_fr_cross(f, p, q, x, y)) return 1;
  return 0;
}

static void tsf_fr_walk(tsf_front *f) {
  int a = -1, b = -1;
  for (int i = 0; i < f->n && a < 0; i++)
    for (int j = 0; j < f->n && a < 0; j++)
      if (!f->used[i][j] && (f->hull[i][j] || (f->used[j][i] && !f->hull[j][i]))) {
        a = i;
        b = j;
      }
  if (a < 0) {
    f->count++;
    return;
  }
  for (int c = 0; c < f->n; c++) {
    if (c == a || c == b || !f->empty[a][b][c] || f->used[b][c] || f->used[c][a]) continue;
    if (tsf_fr_blocked(f, b, c) || tsf_fr_blocked(f, c, a)) continue;
    f->used[a][b] = f->used[b][c] = f->used[c][a] = 1;
    tsf_fr_walk(f);
    f->used[a][b] = f->used[b][c] = f->used[c][a] = 0;
  }
}

static long tsf_front_count(const geom_point *p, int n) {
  tsf_front *f = calloc(1, sizeof *f);
  f->n = n;
  for (int i = 0; i < n; i++) {
    f->x[i] = (long long)p[i].x;
    f->y[i] = (long long)p[i].y;
  }
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) {
      int hull = i != j;
      for (int k = 0; k < n && hull; k++)
        if (k != i && k != j) hull = tsf_fr_orient(f, i, j, k) > 0 || (tsf_fr_orient(f, i, j, k) == 0 && !tsf_fr_on(f, i, j, k));
      f->hull[i][j] = (unsigned char)hull;
      for (int k = 0; k < n; k++) {
        int e = i != j && k != i && k != j && tsf_fr_orient(f, i, j, k) > 0;
        for (int m = 0; m < n && e; m++)
          if (m != i && m != j && m != k)
            e = !(tsf_fr_orient(f, i, j, m) >= 0 && tsf_fr_orient(f, j, k, m) >= 0 && tsf_fr_orient(f, k, i, m) >= 0);
        f->empty[i][j][k] = (unsigned char)e;
      }
    }
  tsf_fr_walk(f);
  long c = f->count;
  free(f);
  return c;
}

static void tsf_grid(geom_point *p, int w, int h) {
  for (int j = 0; j < h; j++)
    for (int i = 0; i < w; i++) p[j * w + i] = (geom_point){i, j};
}

/* Two chains of m sites each, bent towards each other, anticlockwise:
** the lower one left to right, the upper one right to left. */
static void tsf_double_chain(geom_point *p, int m) {
  for (int i = 0; i < m; i++) {
    p[i] = (geom_point){10 * i, i * (m - 1 - i)};
    p[2 * m - 1 - i] = (geom_point){10 * i, 100 - i * (m - 1 - i)};
  }
}

static void test_grids_front(void **state) {
  (void)state;
  /* the k x k grids: 1, 2, 64, 46 456 triangulations (and 3 x 4) */
  long want[5] = {0, 1, 2, 64, 46456};
  for (int k = 2; k <= 4; k++) {
    geom_point p[16];
    tsf_grid(p, k, k);
    siteflip_graph *g = tsf_build(p, k * k);
    assert_int_equal(g->nnodes, want[k]);
    assert_int_equal(tsf_front_count(p, k * k), want[k]);
    siteflip_free(g);
  }
  geom_point p[16];
  tsf_grid(p, 3, 4);
  siteflip_graph *g = tsf_build(p, 12);
  assert_int_equal(g->nnodes, tsf_front_count(p, 12));
  print_message("3 x 4 grid: %d triangulations\n", g->nnodes);
  siteflip_free(g);
  /* the 12-site double chain, and random integer sets of 10 to 13 sites */
  tsf_double_chain(p, 6);
  g = tsf_build(p, 12);
  assert_int_equal(g->nnodes, tsf_front_count(p, 12));
  siteflip_free(g);
  testutil_rng r = {77};
  for (int s = 0; s < 12; s++) {
    int n = 10 + s % 4;
    char err[256];
    do
      for (int i = 0; i < n; i++)
        p[i] = (geom_point){(double)(testutil_next(&r) % 9), (double)(testutil_next(&r) % 9)};
    while (siteflip_check(p, n, err, sizeof err) != 0);
    g = tsf_build(p, n);
    assert_int_equal(g->nnodes, tsf_front_count(p, n));
    siteflip_free(g);
  }
}

static int tsf_or(geom_point a, geom_point b, geom_point c) {
  long long d = ((long long)b.x - (long long)a.x) * ((long long)c.y - (long long)a.y) -
                ((long long)b.y - (long long)a.y) * ((long long)c.x - (long long)a.x);
  return (d > 0) - (d < 0);
}

/* Is i-k a side or a diagonal inside the simple polygon q[0..m-1]
** (integer, no three vertices collinear): no proper crossing with a side,
** and its midpoint inside (crossing number, exact). */
static int tsf_poly_diag(const geom_point *q, int m, int i, int k) {
  if (k == i + 1 || (i == 0 && k == m - 1)) return 1;
  geom_point mid2 = {q[i].x + q[k].x, q[i].y + q[k].y};
  int inside = 0;
  for (int e = 0; e < m; e++) {
    int f = (e + 1) % m;
    if (e != i && e != k && f != i && f != k && tsf_or(q[e], q[f], q[i]) * tsf_or(q[e], q[f], q[k]) < 0 &&
        tsf_or(q[i], q[k], q[e]) * tsf_or(q[i], q[k], q[f]) < 0)
      return 0;
    geom_point a = {2 * q[e].x, 2 * q[e].y}, b = {2 * q[f].x, 2 * q[f].y};
    if ((a.y > mid2.y) != (b.y > mid2.y)) inside ^= b.y > a.y ? tsf_or(a, b, mid2) > 0 : tsf_or(a, b, mid2) < 0;
  }
  return inside;
}

/* The interval recursion: T(i, j) = sum over k of T(i, k) T(k, j). */
static long long tsf_poly_count(const geom_point *q, int m) {
  static long long T[TSF_FR_MAX][TSF_FR_MAX];
  for (int len = 1; len < m; len++)
    for (int i = 0; i + len < m; i++) {
      int j = i + len;
      T[i][j] = len == 1;
      for (int k = i + 1; k < j; k++)
        if (tsf_poly_diag(q, m, i, k) && tsf_poly_diag(q, m, k, j)) T[i][j] += T[i][k] * T[k][j];
    }
  return T[0][m - 1];
}

/* Every chain edge is in every triangulation of a double chain (a segment
** crossing one would join the pocket between a chain and its hull edge to
** the polygon between the chains, and no site lies outside both), so the
** count is Catalan(m-2)^2 (the two convex pockets) times the triangulations
** of the polygon the chains bound. */
static void test_double_chain(void **state) {
  (void)state;
  const long long cat[6] = {1, 1, 2, 5, 14, 42};
  for (int m = 6; m <= 7; m++) {
    geom_point p[14];
    tsf_double_chain(p, m);
    long long want = cat[m - 2] * cat[m - 2] * tsf_poly_count(p, 2 * m);
    siteflip_graph *g = tsf_build(p, 2 * m);
    assert_int_equal(g->nnodes, want);
    print_message("double chain of %d sites: %d triangulations\n", 2 * m, g->nnodes);
    siteflip_free(g);
  }
}

typedef struct tsf_prog { uint64_t calls, last_done, last_total; int backwards; } tsf_prog;

static void tsf_progress(uint64_t done, uint64_t total, void *ctx) {
  tsf_prog *pr = ctx;
  pr->backwards |= done < pr->last_done || done > total;
  pr->calls++;
  pr->last_done = done;
  pr->last_total = total;
}

/* The budget: a graph within it is the same graph whatever the budget
** (progress reported up to done == total == nodes); past it, NULL with
** the count found and *over; below the context's own bytes, 0 found. */
static void test_memory_budget(void **state) {
  (void)state;
  geom_point p[16];
  tsf_grid(p, 4, 4);
  char err[256];
  int over = -1;
  tsf_prog pr = {0};
  siteflip_limits big = {SITEFLIP_MEMORY_DEFAULT, tsf_progress, &pr}, snug = {64u << 20, NULL, NULL};
  siteflip_graph *a = siteflip_build_within(p, 16, &big, &over, err, sizeof err);
  siteflip_graph *b = siteflip_build_within(p, 16, &snug, &over, err, sizeof err);
  assert_non_null(a);
  assert_non_null(b);
  assert_int_equal(over, 0);
  assert_int_equal(a->nnodes, 46456);
  assert_int_equal(b->nnodes, a->nnodes);
  assert_int_equal(b->nedges, a->nedges);
  assert_memory_equal(a->node, b->node, (size_t)a->nnodes * sizeof *a->node);
  assert_memory_equal(a->edge, b->edge, (size_t)a->nedges * sizeof *a->edge);
  assert_true(pr.calls >= 2 && !pr.backwards);
  assert_true(pr.last_done == 46456 && pr.last_total == 46456);
  siteflip_free(a);
  siteflip_free(b);
  siteflip_limits tight = {1u << 20, NULL, NULL}, tiny = {4096, NULL, NULL};
  assert_null(siteflip_build_within(p, 16, &tight, &over, err, sizeof err));
  assert_int_equal(over, 1);
  assert_non_null(strstr(err, "outgrows the memory budget of 1 MiB"));
  const char *k = strstr(err, "MiB: ");
  assert_non_null(k);
  long found = strtol(k + 5, NULL, 10);
  assert_true(found > 100 && found < 46456);
  assert_null(siteflip_build_within(p, 16, &tiny, &over, err, sizeof err));
  assert_int_equal(over, 1);
  assert_non_null(strstr(err, "budget of 4 KiB: 0 triangulations found"));
}

/* ---- directed graphs ------------------------------------------------------ */

static double tsf_neg_R(const geom_tri *t, void *ctx) {
  (void)ctx;
  return -t->R;
}

static void test_figure_3_8(void **state) {
  (void)state;
  geom_point p[5] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.45, 0.4}};
  siteflip_graph *g = tsf_build(p, 5);
  assert_true(g->delaunay >= 0);
  /* the star (site 5 joined to all four corners) is Delaunay */
  int star = -1;
  for (int u = 0; u < g->nnodes; u++) {
    int deg = 0;
    for (int k = 0; k < 4; k++) deg += siteflip_has_edge(g, u, k, 4);
    if (deg == 4) star = u;
  }
  assert_int_equal(g->delaunay, star);
  rule_choice dec[8];
  int sinks[3];
  siteflip_result res;
  rule r1 = tsf_rule("R_1");
  assert_int_equal(siteflip_direct(g, &r1, RULE_DEFAULT_TIE_EPS, dec, sinks, &res), 0);
  assert_int_equal(res.nsinks, 1);
  assert_int_equal(sinks[0], star);
  assert_int_equal(res.sink_dt, 1);
  assert_int_equal(res.ties, 0);
  measure m = {"tsfnegR", "-R", "minus the circumradius", MEASURE_NONPOS, tsf_neg_R, NULL};
  assert_true(measure_register(&m) >= 0);
  rule nr = tsf_rule("tsfnegR_1");
  assert_int_equal(siteflip_direct(g, &nr, RULE_DEFAULT_TIE_EPS, dec, sinks, &res), 0);
  assert_int_equal(res.nsinks, 2);
  assert_true(sinks[0] != star && sinks[1] != star);
  assert_int_equal(res.nsources, 1);
  assert_int_equal(res.sink_dt, -1);
  assert_int_equal(res.cycle, 0);
  measure_unregister_user();
  siteflip_free(g);
}

static const char *const tsf_dt_rules[] = {"DT", "R_-inf", "R_-1", "R_0", "R_1", "R_2", "R_inf",
                                          "-alpha_inf", "-r_1", "abc_1", "-r/R_1", "-r2/A_0"};
#define TSF_NDT (int)(sizeof tsf_dt_rules / sizeof tsf_dt_rules[0])

static void test_dt_equivalent(void **state) {
  (void)state;
  rule rules[TSF_NDT];
  for (int i = 0; i < TSF_NDT; i++) rules[i] = tsf_rule(tsf_dt_rules[i]);
  int checked = 0;
  for (int kind = 0; kind < SAMPLER_SITES_COUNT; kind++)
    for (int n = 4; n <= 8; n++)
      for (uint64_t s = 0; s < 40; s++) {
        geom_point p[8];
        assert_int_equal(sampler_sites(kind, 99, s, n, p), 0);
        siteflip_graph *g = tsf_build(p, n);
        rule_choice *dec = malloc((size_t)(g->nquads + 1) * sizeof *dec);
        int *sinks = malloc((size_t)g->nnodes * sizeof *sinks);
        for (int i = 0; i < TSF_NDT; i++) {
          siteflip_result res;
          assert_int_equal(siteflip_direct(g, &rules[i], RULE_DEFAULT_TIE_EPS, dec, sinks, &res), 0);
          if (res.ties) continue;
          if (res.nsinks != 1 || res.sink_dt != 1)
            fail_msg("%s on %s set %d/%llu: %d sinks, sink is DT %d", tsf_dt_rules[i],
                     sampler_sites_name(kind), n, (unsigned long long)s, res.nsinks, res.sink_dt);
          checked++;
        }
        free(dec);
        free(sinks);
        siteflip_free(g);
      }
  assert_true(checked > SAMPLER_SITES_COUNT * 5 * 40 * TSF_NDT * 9 / 10);
}

/* Every triangle rule on small sets: never a cycle, never no sink; for
** convex sets the best sink's total is GOT's (as `got` computes it), and
** for the joints -1, 0, 1, 2 the GOT itself is a sink. */
static void test_triangle_rules(void **state) {
  (void)state;
  int ids[MEASURE_BUILTIN_COUNT];
  for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++) ids[m] = m;
  rule rules[MEASURE_BUILTIN_COUNT * JOINT_COUNT];
  int nr = rule_list_triangle(ids, MEASURE_BUILTIN_COUNT, rules, MEASURE_BUILTIN_COUNT * JOINT_COUNT);
  assert_true(nr >= 120);
  int got_checked = 0;
  for (int kind = 0; kind < SAMPLER_SITES_COUNT; kind++)
    for (int n = 5; n <= 7; n++)
      for (uint64_t s = 0; s < 6; s++) {
        geom_point p[7];
        assert_int_equal(sampler_sites(kind, 5, s, n, p), 0);
        siteflip_graph *g = tsf_build(p, n);
        rule_choice *dec = malloc((size_t)g->nquads * sizeof *dec);
        int *sinks = malloc((size_t)g->nnodes * sizeof *sinks);
        for (int i = 0; i < nr; i++) {
          siteflip_result res;
          assert_int_equal(siteflip_direct(g, &rules[i], RULE_DEFAULT_TIE_EPS, dec, sinks, &res), 0);
          assert_int_equal(res.cycle, 0);
          assert_true(res.nsinks >= 1);
          assert_true(res.has_got);
          if (kind != SAMPLER_SITES_CONVEX || res.ties) continue;
          /* best sink = GOT */
          double best = INFINITY;
          for (int k = 0; k < res.nsinks; k++) {
            double key = siteflip_node_key(g, &rules[i], sinks[k]);
            if (key < best) best = key;
          }
          assert_true(best == siteflip_node_key(g, &rules[i], res.got_node));
          got_options o = {1, RULE_DEFAULT_TIE_EPS};
          got_result gr;
          char err[256];
          assert_int_equal(got_solve(p, (size_t)n, &rules[i], &o, &gr, err, sizeof err), 0);
          TESTUTIL_NEAR(res.got_total, gr.total, 1e-12, 1e-300);
          got_result_free(&gr);
          got_checked++;
          joint_id j = rules[i].joint;
          if (j == JOINT_HARMONIC || j == JOINT_PRODUCT || j == JOINT_SUM || j == JOINT_RSS) {
            int is_sink = 0;
            for (int k = 0; k < res.nsinks; k++) is_sink |= sinks[k] == res.got_node;
            if (!is_sink) fail_msg("%s: GOT is not a sink", rules[i].name);
          }
        }
        free(dec);
        free(sinks);
        siteflip_free(g);
      }
  assert_true(got_checked > 3 * 6 * 100);
}

/* siteflip_count_upto(K) says "more than K" exactly when the whole
** enumeration finds more than K triangulations, and otherwise their number:
** K around the true count N (N - 1, N, N + 1), K = 1 and a K in between, on
** every site sampler; and the convex 12-gon's Catalan(10) = 16796 against
** the explorer's 5000 and against itself. */
static void tsf_count_check(const geom_point *p, int n, int N, int K) {
  char err[256];
  int count = -1, rc = siteflip_count_upto(p, n, K, &count, err, sizeof err);
  if (rc < 0) fail_msg("siteflip_count_upto(%d): %s", K, err);
  if (rc != (N > K) || count != (N > K ? K + 1 : N))
    fail_msg("%d sites, %d triangulations, cap %d: rc %d, count %d", n, N, K, rc, count);
}

static void test_count_upto(void **state) {
  (void)state;
  for (int kind = 0; kind < SAMPLER_SITES_COUNT; kind++)
    for (int n = 3; n <= 9; n++)
      for (uint64_t s = 0; s < 6; s++) {
        geom_point p[9];
        assert_int_equal(sampler_sites(kind, 41, s, n, p), 0);
        siteflip_graph *g = tsf_build(p, n);
        int N = g->nnodes, ks[5] = {1, N - 1, N, N + 1, 1 + (int)s * N / 5};
        for (int k = 0; k < 5; k++)
          if (ks[k] >= 1) tsf_count_check(p, n, N, ks[k]);
        siteflip_free(g);
      }
  geom_point gon[12];
  sampler_convex(7, 12, 12, gon);
  tsf_count_check(gon, 12, 16796, 5000);
  tsf_count_check(gon, 12, 16796, 16795);
  tsf_count_check(gon, 12, 16796, 16796);
  char err[256];
  int count;
  assert_int_equal(siteflip_count_upto(gon, 12, 0, &count, err, sizeof err), -1);
  assert_non_null(strstr(err, "cap 0"));
  geom_point dup[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 0}};
  assert_int_equal(siteflip_count_upto(dup, 4, 10, &count, err, sizeof err), -1);
  assert_non_null(strstr(err, "sites 2 and 4 are equal"));
}

static void test_bad_input(void **state) {
  (void)state;
  char err[256];
  geom_point dup[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 0}};
  assert_int_not_equal(siteflip_check(dup, 4, err, sizeof err), 0);
  assert_non_null(strstr(err, "sites 2 and 4 are equal"));
  geom_point line[4] = {{0, 0}, {1, 1}, {2, 2}, {5, 5}};
  assert_int_not_equal(siteflip_check(line, 4, err, sizeof err), 0);
  assert_non_null(strstr(err, "collinear"));
  geom_point many[17];
  for (int i = 0; i < 17; i++) many[i] = (geom_point){cos(i), sin(i)};
  assert_null(siteflip_build(many, 17, err, sizeof err));
  assert_non_null(strstr(err, "at most 16 sites"));
  geom_point nan_[3] = {{0, 0}, {NAN, 0}, {0, 1}};
  assert_int_not_equal(siteflip_check(nan_, 3, err, sizeof err), 0);
  assert_non_null(strstr(err, "site 2"));
  assert_int_not_equal(siteflip_check(nan_, 2, err, sizeof err), 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_catalan),
    cmocka_unit_test(test_quad_with_interior_site),
    cmocka_unit_test(test_brute_force),
    cmocka_unit_test(test_grids_front),
    cmocka_unit_test(test_double_chain),
    cmocka_unit_test(test_memory_budget),
    cmocka_unit_test(test_figure_3_8),
    cmocka_unit_test(test_dt_equivalent),
    cmocka_unit_test(test_triangle_rules),
    cmocka_unit_test(test_count_upto),
    cmocka_unit_test(test_bad_input),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
