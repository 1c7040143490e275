/*
** test_flipgraph.c: directed flip graphs of convex pentagons.
**
** - the triangle and quadrilateral bookkeeping (tri[10], Q_j's triangles);
** - the thesis's figure 3.3 site set under P_1 (two sinks), checked against
**   a brute-force "no flip shortens a diagonal" search;
** - DT is type I on every sampled pentagon, and its sink is the fan whose
**   triangles all have empty circumcircles (brute force);
** - the fast path (flipgraph_plan_run, flipgraph_tally) decides exactly as
**   flipgraph_classify and rule_eval do, for every rule, on sampled
**   pentagons and on integer-grid pentagons full of exact ties, also for
**   measures with extreme values (under- and overflowing products, +inf,
**   0), with the vector engine and the portable one (quadvec);
** - no triangle-based rule gives type IV; types I, II, III and V are all
**   reached by triangle rules, and type IV by a hand-made quadrilateral rule.
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

#include "measure.h"
#include "flipgraph.h"
#include "rule.h"
#include "sampler.h"
#include "testutil.h"

#define TFG_EPS RULE_DEFAULT_TIE_EPS
#define TFG_MAXRULES 160

/* Every triangle-based rule over all measures (138: 23 x 6 less the
** finite-p joints of any-sign measures, if any), then DT. */
static int tfg_all_rules(rule *out) {
  int ids[MEASURE_MAX];
  int nm = measure_count();
  for (int i = 0; i < nm; i++) ids[i] = i;
  int n = rule_list_triangle(ids, nm, out, TFG_MAXRULES - 1);
  out[n++] = rule_delaunay();
  return n;
}

/* Five integer points in strictly convex position, anticlockwise: a small
** grid makes exact ties (equal sums, equal ranges) and cocircular quads
** common, the corner cases of the tie rule. */
static void tfg_grid_pentagon(testutil_rng *g, geom_point v[5], int size) {
  for (;;) {
    double cx = 0, cy = 0;
    for (int i = 0; i < 5; i++) {
      v[i].x = (double)(testutil_next(g) % (uint64_t)size);
      v[i].y = (double)(testutil_next(g) % (uint64_t)size);
      cx += v[i].x / 5;
      cy += v[i].y / 5;
    }
    for (int i = 1; i < 5; i++)
      for (int j = i; j > 0 && atan2(v[j].y - cy, v[j].x - cx) < atan2(v[j - 1].y - cy, v[j - 1].x - cx); j--) {
        geom_point t = v[j]; v[j] = v[j - 1]; v[j - 1] = t;
      }
    int ok = 1;
    for (int i = 0; i < 5; i++)
      if (geom_orient(v[i], v[(i + 1) % 5], v[(i + 2) % 5]) <= 0) ok = 0;
    if (ok) return;
  }
}

static int tfg_same_point(geom_point a, geom_point b) {
  return a.x == b.x && a.y == b.y;
}

/* Is triangle t made of exactly the points a, b, c? */
static int tfg_tri_is(const geom_tri *t, geom_point a, geom_point b, geom_point c) {
  geom_point want[3] = {a, b, c};
  int used[3] = {0, 0, 0};
  for (int i = 0; i < 3; i++) {
    int found = 0;
    for (int k = 0; k < 3 && !found; k++)
      if (!used[k] && tfg_same_point(t->v[k], want[i])) used[k] = found = 1;
    if (!found) return 0;
  }
  return 1;
}

static void test_triangle_indexing(void **state) {
  (void)state;
  geom_point v[5] = {{0, 0}, {7, 0}, {6, 2}, {4, 3}, {2, 2}};
  flipgraph_pentagon p;
  flipgraph_prepare(&p, v);
  int seen[10] = {0};
  for (int i = 0; i < 5; i++)
    for (int j = 0; j < 5; j++)
      for (int k = 0; k < 5; k++) {
        int t = flipgraph_tri_index(i, j, k);
        if (i == j || j == k || i == k) {
          assert_int_equal(t, -1);
          continue;
        }
        assert_true(t >= 0 && t < 10);
        assert_true(tfg_tri_is(&p.tri[t], v[i], v[j], v[k]));
        seen[t] = 1;
      }
  for (int t = 0; t < 10; t++) assert_true(seen[t]);
  /* Indices are taken mod 5. */
  assert_int_equal(flipgraph_tri_index(5, 6, 7), flipgraph_tri_index(0, 1, 2));
  assert_int_equal(flipgraph_tri_index(-1, 0, 1), flipgraph_tri_index(4, 0, 1));
  for (int t = 0; t < FLIPGRAPH_NTYPES; t++)
    assert_int_equal(strlen(flipgraph_type_name((flipgraph_type)t)), (size_t)(t == 3 ? 2 : t == 4 ? 1 : t + 1));
  assert_string_equal(flipgraph_type_name(FLIPGRAPH_IV), "IV");
}

/* Decisions by hand: every type from its definition. */
static void test_graph_from_decisions(void **state) {
  (void)state;
  flipgraph g;
  /* All AC: every arrow goes from T_{j-1} to T_{j+1}, round the cycle. */
  rule_choice all_ac[5] = {RULE_AC, RULE_AC, RULE_AC, RULE_AC, RULE_AC};
  flipgraph_from_decisions(all_ac, -1, &g);
  assert_int_equal(g.type, FLIPGRAPH_IV);
  assert_int_equal(g.nsinks, 0);
  /* Exhaustively over all 3^5 decision vectors: structure invariants. */
  for (int code = 0; code < 243; code++) {
    rule_choice dec[5];
    int either = 0;
    for (int j = 0, c = code; j < 5; j++, c /= 3) {
      dec[j] = (rule_choice)(c % 3);
      either |= dec[j] == RULE_EITHER;
    }
    flipgraph_from_decisions(dec, 0, &g);
    for (int j = 0; j < 5; j++) assert_int_equal(g.dec[j], dec[j]);
    if (either) {
      assert_int_equal(g.type, FLIPGRAPH_V);
      continue;
    }
    /* Count sinks by following the arrows: the edge of Q_j joins
    ** T_{j+1} (preferred when AC) and T_{j-1}. */
    int out[5] = {0};
    for (int j = 0; j < 5; j++) out[dec[j] == RULE_AC ? (j + 4) % 5 : (j + 1) % 5]++;
    int ns = 0;
    for (int i = 0; i < 5; i++) ns += out[i] == 0;
    assert_int_equal(g.nsinks, ns);
    assert_int_equal(g.type == FLIPGRAPH_IV, ns == 0);
    assert_int_equal(g.type == FLIPGRAPH_III, ns == 2);
    if (ns == 2) assert_true(g.sink[0] < g.sink[1]);
    assert_int_equal(g.delaunay, g.type == FLIPGRAPH_I && g.sink[0] == 0);
    if (ns != 1) continue;
    /* One sink: the source (no arrow in) sits 2 steps from it round the
    ** cycle T0 T2 T4 T1 T3 for type I, next to it for type II. */
    static const int cyc[5] = {0, 2, 4, 1, 3};
    int in[5] = {0}, pos[5];
    for (int k = 0; k < 5; k++) pos[cyc[k]] = k;
    for (int j = 0; j < 5; j++) in[dec[j] == RULE_AC ? (j + 1) % 5 : (j + 4) % 5]++;
    int src = -1;
    for (int i = 0; i < 5; i++)
      if (in[i] == 0) src = i;
    assert_true(src >= 0);
    int d = abs(pos[src] - pos[g.sink[0]]);
    if (d > 2) d = 5 - d;
    assert_int_equal(g.type, d == 2 ? FLIPGRAPH_I : FLIPGRAPH_II);
  }
}

/* The spec's definition of locality, applied literally: the single sink
** T_i is local when, for every vertex v, every diagonal of T_i not incident
** to v that is a diagonal of Q_v is the one the rule chose for Q_v (a
** diagonal of T_i that is a side of Q_v is there anyway).  Then inserting v
** into the LOT of the other four only adds edges at v. */
static int tfg_sink_is_local(const rule_choice dec[5], int i) {
  const int diag[2][2] = {{i, (i + 2) % 5}, {i, (i + 3) % 5}};
  for (int v = 0; v < 5; v++)
    for (int d = 0; d < 2; d++) {
      int a = diag[d][0], b = diag[d][1];
      if (a == v || b == v) continue;
      int ac = (a == (v + 1) % 5 && b == (v + 3) % 5) || (b == (v + 1) % 5 && a == (v + 3) % 5);
      int bd = (a == (v + 2) % 5 && b == (v + 4) % 5) || (b == (v + 2) % 5 && a == (v + 4) % 5);
      if ((ac && dec[v] != RULE_AC) || (bd && dec[v] != RULE_BD)) return 0;
    }
  return 1;
}

/* The spec reduces locality to the source's distance from the sink; check
** that reduction against the definition on every one-sink decision vector. */
static void test_type_one_is_local(void **state) {
  (void)state;
  int ones = 0;
  for (int code = 0; code < 32; code++) {
    rule_choice dec[5];
    for (int j = 0; j < 5; j++) dec[j] = (code >> j) & 1 ? RULE_BD : RULE_AC;
    flipgraph g;
    flipgraph_from_decisions(dec, -1, &g);
    if (g.nsinks != 1) continue;
    ones++;
    assert_int_equal(tfg_sink_is_local(dec, g.sink[0]), g.type == FLIPGRAPH_I);
  }
  assert_int_equal(ones, 20);   /* 2^5 - 2 with no sink - 10 with two */
}

/* Figure 3.3: P_1 = sum of the two triangles' perimeters = the quad's
** perimeter + 2 * diagonal, so it picks the shorter diagonal.  Diagonal
** lengths: v0v2 = sqrt 40 = 6.32, v0v3 = 5, v1v3 = sqrt 18 = 4.24,
** v1v4 = sqrt 29 = 5.39, v2v4 = 4.  So Q0 (v1v3 vs v2v4) -> BD, Q1 (v2v4 vs
** v3v0) -> AC, Q2 (v3v0 vs v4v1) -> AC, Q3 (v4v1 vs v0v2) -> AC, Q4 (v0v2 vs
** v1v3) -> BD; sinks T3 = {v3v0, v3v1} (total 9.24, the global optimum) and
** T4 = {v4v1, v4v2} (9.39, a local optimum: flipping either diagonal only
** lengthens it). */
static void test_figure_3_3(void **state) {
  (void)state;
  geom_point v[5] = {{0, 0}, {7, 0}, {6, 2}, {4, 3}, {2, 2}};
  flipgraph_pentagon p;
  flipgraph_prepare(&p, v);
  rule r;
  char err[256];
  assert_int_equal(rule_parse("P_1", &r, err, sizeof err), 0);
  flipgraph g;
  flipgraph_classify(&p, &r, TFG_EPS, &g);
  rule_choice want[5] = {RULE_BD, RULE_AC, RULE_AC, RULE_AC, RULE_BD};
  for (int j = 0; j < 5; j++) assert_int_equal(g.dec[j], want[j]);
  assert_int_equal(g.type, FLIPGRAPH_III);
  assert_int_equal(g.nsinks, 2);
  assert_int_equal(g.sink[0], 3);
  assert_int_equal(g.sink[1], 4);
  assert_int_equal(g.delaunay, 0);
  /* Brute force: a fan is locally optimal under "shorter diagonal" when
  ** for each of its two diagonals the crossing diagonal of the quad they
  ** share is not shorter. */
  int nlocal = 0;
  for (int i = 0; i < 5; i++) {
    int local = 1;
    for (int k = 2; k <= 3; k++) {
      /* Diagonal v_i v_{i+k}; the other diagonal of T_i is v_i v_{i+5-k}.
      ** Flipping v_i v_{i+k} inside the quad v_i, v_{i+k-1}, v_{i+k},
      ** v_{i+k+1} (the two triangles on it) gives v_{i+k-1} v_{i+k+1}. */
      double here = geom_dist(v[i], v[(i + k) % 5]);
      double there = geom_dist(v[(i + k - 1) % 5], v[(i + k + 1) % 5]);
      if (there < here) local = 0;
    }
    if (local) {
      assert_true(i == 3 || i == 4);
      nlocal++;
    }
  }
  assert_int_equal(nlocal, 2);
}

/* The fan T_d whose three triangles have empty circumcircles. */
static int tfg_brute_delaunay(const geom_point v[5]) {
  int found = -1;
  for (int i = 0; i < 5; i++) {
    int tris[3][3] = {{i, i + 1, i + 2}, {i, i + 2, i + 3}, {i, i + 3, i + 4}};
    int ok = 1;
    for (int t = 0; t < 3 && ok; t++)
      for (int o = 0; o < 5 && ok; o++) {
        int a = tris[t][0] % 5, b = tris[t][1] % 5, c = tris[t][2] % 5;
        if (o == a || o == b || o == c) continue;
        if (geom_incircle(v[a], v[b], v[c], v[o]) >= 0) ok = 0;
      }
    if (ok) {
      assert_int_equal(found, -1);   /* at most one fan is strictly Delaunay */
      found = i;
    }
  }
  return found;
}

static void test_dt_always_type_one(void **state) {
  (void)state;
  rule dt = rule_delaunay();
  for (uint64_t i = 0; i < 20000; i++) {
    geom_point v[5];
    sampler_pentagon(7, i, v);
    flipgraph_pentagon p;
    flipgraph_prepare(&p, v);
    flipgraph g;
    flipgraph_classify(&p, &dt, TFG_EPS, &g);
    assert_int_equal(g.type, FLIPGRAPH_I);
    assert_int_equal(g.delaunay, 1);
    assert_int_equal(g.sink[0], p.delaunay_sink);
    assert_int_equal(p.delaunay_sink, tfg_brute_delaunay(v));
  }
  /* Four cocircular points (a square) and a fifth outside: the Delaunay
  ** triangulation is not unique, DT says EITHER on the square. */
  geom_point sq[5] = {{0, 0}, {1, 0}, {1, 1}, {0.5, 2}, {0, 1}};
  flipgraph_pentagon p;
  flipgraph_prepare(&p, sq);
  flipgraph g;
  flipgraph_classify(&p, &dt, TFG_EPS, &g);
  assert_int_equal(g.type, FLIPGRAPH_V);
  assert_int_equal(g.dec[3], RULE_EITHER);   /* Q3 = v4 v0 v1 v2 is the square */
  assert_int_equal(p.delaunay_sink, -1);
  assert_int_equal(g.delaunay, 0);
}

/* The fast path against flipgraph_classify on one pentagon, all rules; and
** flipgraph_classify against rule_eval on the quad points when deep. */
static void tfg_check_pentagon(const flipgraph_plan *pl, const rule *rules, int n,
                               const geom_point v[5], int deep, double eps) {
  flipgraph_pentagon p;
  flipgraph_prepare(&p, v);
  flipgraph fast[TFG_MAXRULES];
  flipgraph_plan_run(pl, &p, fast);
  for (int r = 0; r < n; r++) {
    flipgraph g;
    flipgraph_classify(&p, &rules[r], eps, &g);
    for (int j = 0; j < 5; j++) {
      if (fast[r].dec[j] != g.dec[j]) {
        print_error("rule %s, Q%d: fast %s, classify %s at (%.17g,%.17g) (%.17g,%.17g) "
                    "(%.17g,%.17g) (%.17g,%.17g) (%.17g,%.17g)\n", rules[r].name, j,
                    rule_choice_str(fast[r].dec[j]), rule_choice_str(g.dec[j]),
                    v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y, v[3].x, v[3].y,
                    v[4].x, v[4].y);
        fail();
      }
      if (deep) {
        geom_point q[4];
        for (int k = 0; k < 4; k++) q[k] = v[(j + 1 + k) % 5];
        rule re = rules[r];
        rule_set_tie_eps(&re, eps);
        assert_int_equal(rule_eval(&re, q, NULL, NULL), g.dec[j]);
      }
    }
    assert_int_equal(fast[r].type, g.type);
    assert_int_equal(fast[r].nsinks, g.nsinks);
    assert_int_equal(fast[r].sink[0], g.sink[0]);
    assert_int_equal(fast[r].sink[1], g.sink[1]);
    assert_int_equal(fast[r].delaunay, g.delaunay);
  }
}

static void test_fast_path_equals_rule_eval(void **state) {
  (void)state;
  rule rules[TFG_MAXRULES];
  int n = tfg_all_rules(rules);
  assert_true(n >= 120);
  flipgraph_plan *pl = flipgraph_plan_new(rules, n, TFG_EPS);
  assert_non_null(pl);
  geom_point v[5];
  for (uint64_t i = 0; i < 10000; i++) {
    sampler_pentagon(11, i, v);
    tfg_check_pentagon(pl, rules, n, v, i < 1000, TFG_EPS);
  }
  /* Integer grids: exact ties (A_1 always, Pinf and Rinf often) and
  ** cocircular quads. */
  testutil_rng g = {12345};
  int ties = 0;
  for (int i = 0; i < 3000; i++) {
    tfg_grid_pentagon(&g, v, i < 1500 ? 5 : 12);
    tfg_check_pentagon(pl, rules, n, v, i < 600, TFG_EPS);
    flipgraph_pentagon p;
    flipgraph_prepare(&p, v);
    ties += p.delaunay_sink < 0;
  }
  assert_true(ties > 0);   /* the grid really produced cocircular quads */
  /* A regular pentagon, scaled and shifted. */
  for (int k = 0; k < 5; k++)
    v[k] = (geom_point){3 + 2 * cos(2 * M_PI * k / 5), -1 + 2 * sin(2 * M_PI * k / 5)};
  tfg_check_pentagon(pl, rules, n, v, 1, TFG_EPS);
  flipgraph_plan_free(pl);
  /* Coarse tie tolerances make near-ties (the relative test) common, so
  ** that branch is exercised too; tie_eps = 0 leaves exact equality only. */
  const double eps[] = {0, 1e-9, 1e-4, 1e-2, 0.05};
  for (size_t e = 0; e < sizeof eps / sizeof eps[0]; e++) {
    pl = flipgraph_plan_new(rules, n, eps[e]);
    assert_non_null(pl);
    for (uint64_t i = 0; i < 2000; i++) {
      sampler_pentagon(13 + e, i, v);
      tfg_check_pentagon(pl, rules, n, v, i < 100, eps[e]);
    }
    flipgraph_plan_free(pl);
  }
}

/* Extreme measures take quadvec's exact fallbacks; the vector and the
** portable engines tally the same. */
static void test_extremes_and_engines(void **state) {
  (void)state;
  int ids[3];
  assert_int_equal(testutil_extreme_measures(ids), 0);
  rule rules[TFG_MAXRULES];
  int n = tfg_all_rules(rules);
  const double eps[] = {TFG_EPS, 0, 1e-4};
  geom_point v[5];
  for (int scalar = 0; scalar < 2; scalar++)
    for (size_t e = 0; e < sizeof eps / sizeof eps[0]; e++) {
      flipgraph_plan *pl = flipgraph_plan_new(rules, n, eps[e]);
      assert_non_null(pl);
      flipgraph_use_portable(scalar);
      for (uint64_t i = 0; i < 1500; i++) {
        sampler_pentagon(17 + e, i, v);
        tfg_check_pentagon(pl, rules, n, v, i < 50, eps[e]);
      }
      flipgraph_use_portable(0);
      flipgraph_plan_free(pl);
    }
  static flipgraph_counts vec[TFG_MAXRULES], sca[TFG_MAXRULES];
  memset(vec, 0, sizeof vec);
  memset(sca, 0, sizeof sca);
  assert_int_equal(flipgraph_tally(rules, n, 5, 0, 20000, TFG_EPS, 2, vec, NULL, NULL), 0);
  flipgraph_use_portable(1);
  assert_int_equal(flipgraph_tally(rules, n, 5, 0, 20000, TFG_EPS, 2, sca, NULL, NULL), 0);
  flipgraph_use_portable(0);
  assert_memory_equal(vec, sca, (size_t)n * sizeof vec[0]);
  measure_unregister_user();
}

/* flipgraph_tally equals a plain loop over flipgraph_classify. */
static void test_tally_equals_loop(void **state) {
  (void)state;
  rule rules[TFG_MAXRULES];
  int n = tfg_all_rules(rules);
  const uint64_t seed = 99, first = 500, count = 3000;
  flipgraph_counts tally[TFG_MAXRULES], loop[TFG_MAXRULES];
  memset(tally, 0, sizeof tally);
  memset(loop, 0, sizeof loop);
  assert_int_equal(flipgraph_tally(rules, n, seed, first, count, TFG_EPS, 2, tally, NULL, NULL), 0);
  for (uint64_t i = first; i < first + count; i++) {
    geom_point v[5];
    sampler_pentagon(seed, i, v);
    flipgraph_pentagon p;
    flipgraph_prepare(&p, v);
    for (int r = 0; r < n; r++) {
      flipgraph g;
      flipgraph_classify(&p, &rules[r], TFG_EPS, &g);
      loop[r].samples++;
      loop[r].type[g.type]++;
      loop[r].dt += (uint64_t)g.delaunay;
    }
  }
  for (int r = 0; r < n; r++) {
    assert_int_equal(tally[r].samples, count);
    assert_memory_equal(&tally[r], &loop[r], sizeof tally[r]);
  }
  /* Bad input: an unknown measure. */
  rule bad = rules[0];
  bad.measure = 1000;
  assert_int_equal(flipgraph_tally(&bad, 1, seed, 0, 10, TFG_EPS, 1, tally, NULL, NULL), -1);
  assert_null(flipgraph_plan_new(&bad, 1, TFG_EPS));
  assert_int_equal(flipgraph_tally(rules, 1, seed, UINT64_MAX, 10, TFG_EPS, 1, tally, NULL, NULL), -1);
}

/* flipgraph_classify_n is flipgraph_prepare + flipgraph_classify on every
** pentagon, with any thread count; a clockwise pentagon gets the graph of
** its renumbering v0, v4, v3, v2, v1; a pentagon that is not convex stops
** the batch at its index with geom_polygon_check's error and vertex. */
static void test_classify_n(void **state) {
  (void)state;
  rule rules[TFG_MAXRULES];
  int n = tfg_all_rules(rules);
  enum { M = 700 };
  geom_point *v = malloc(5 * M * sizeof *v);
  flipgraph *g = malloc((size_t)M * (size_t)n * sizeof *g);
  assert_non_null(v);
  assert_non_null(g);
  for (int threads = 1; threads <= 2; threads++) {
    for (int i = 0; i < M; i++) {
      sampler_pentagon(17, (uint64_t)i, v + 5 * i);
      if (i % 2) {
        geom_point t = v[5 * i + 1];
        v[5 * i + 1] = v[5 * i + 4], v[5 * i + 4] = t;
        t = v[5 * i + 2], v[5 * i + 2] = v[5 * i + 3], v[5 * i + 3] = t;
      }
    }
    geom_polyerr e;
    size_t bad;
    assert_int_equal(flipgraph_classify_n(v, M, rules, n, TFG_EPS, threads, g, &e, &bad), M);
    for (int i = 0; i < M; i++) {
      geom_point w[5];
      sampler_pentagon(17, (uint64_t)i, w);
      flipgraph_pentagon p;
      flipgraph_prepare(&p, w);
      for (int r = 0; r < n; r++) {
        flipgraph want;
        flipgraph_classify(&p, &rules[r], TFG_EPS, &want);
        assert_memory_equal(&want, &g[(size_t)i * (size_t)n + (size_t)r], sizeof want);
      }
    }
  }
  v[5 * 3 + 2] = v[5 * 3 + 1];
  geom_polyerr e;
  size_t bad;
  assert_int_equal(flipgraph_classify_n(v, M, rules, n, TFG_EPS, 2, g, &e, &bad), 3);
  assert_int_equal(e, GEOM_DUPLICATE);
  free(v);
  free(g);
}

/* The per-sample hook sees every pentagon once, on a thread number below
** the thread count, with the graphs flipgraph_classify gives; its per-thread
** counts add up to the tally's. */
#define TFG_HOOK_THREADS 2
typedef struct tfg_hook {
  int nrules, bad;
  uint64_t first, count;
  unsigned char *seen;
  flipgraph_counts c[TFG_HOOK_THREADS][TFG_MAXRULES];
  const rule *rules;
} tfg_hook;

static void tfg_each(void *ctx, int thread, uint64_t i, const flipgraph_pentagon *p,
                     const flipgraph *g) {
  tfg_hook *h = ctx;
  if (thread < 0 || thread >= TFG_HOOK_THREADS || i < h->first || i >= h->first + h->count) {
    h->bad = 1;
    return;
  }
  h->seen[i - h->first]++;
  for (int r = 0; r < h->nrules; r++) {
    flipgraph want;
    flipgraph_classify(p, &h->rules[r], TFG_EPS, &want);
    if (want.type != g[r].type || want.delaunay != g[r].delaunay) h->bad = 1;
    h->c[thread][r].samples++;
    h->c[thread][r].type[g[r].type]++;
    h->c[thread][r].dt += (uint64_t)g[r].delaunay;
  }
}

static void test_tally_hook(void **state) {
  (void)state;
  rule rules[TFG_MAXRULES];
  int n = tfg_all_rules(rules);
  if (n > 12) n = 12;
  static tfg_hook h;
  memset(&h, 0, sizeof h);
  h.nrules = n;
  h.first = 70;
  h.count = 5000;
  h.rules = rules;
  h.seen = calloc(h.count, 1);
  flipgraph_counts out[TFG_MAXRULES];
  memset(out, 0, sizeof out);
  flipgraph_run run = {7, h.first, h.count, TFG_EPS, TFG_HOOK_THREADS, NULL, NULL, tfg_each, &h, NULL};
  assert_int_equal(flipgraph_tally_run(rules, n, &run, out), 0);
  assert_int_equal(h.bad, 0);
  for (uint64_t i = 0; i < h.count; i++) assert_int_equal(h.seen[i], 1);
  for (int r = 0; r < n; r++) {
    flipgraph_counts sum = {0};
    for (int t = 0; t < TFG_HOOK_THREADS; t++) {
      sum.samples += h.c[t][r].samples;
      for (int y = 0; y < FLIPGRAPH_NTYPES; y++) sum.type[y] += h.c[t][r].type[y];
      sum.dt += h.c[t][r].dt;
    }
    assert_memory_equal(&sum, &out[r], sizeof sum);
  }
  free(h.seen);
}

/* Theorem 1 of the thesis: no triangle-based rule has a type IV pentagon.
** And types I, II, III and V each occur under some triangle rule. */
static void test_types_reached(void **state) {
  (void)state;
  rule rules[TFG_MAXRULES];
  int n = tfg_all_rules(rules);
  flipgraph_counts c[TFG_MAXRULES];
  memset(c, 0, sizeof c);
  assert_int_equal(flipgraph_tally(rules, n, 2024, 0, 50000, TFG_EPS, 0, c, NULL, NULL), 0);
  uint64_t total[FLIPGRAPH_NTYPES] = {0};
  for (int r = 0; r < n; r++) {
    if (rules[r].kind == RULE_TRIANGLE && c[r].type[FLIPGRAPH_IV] != 0) {
      print_error("rule %s gave %llu type IV graphs\n", rules[r].name,
                  (unsigned long long)c[r].type[FLIPGRAPH_IV]);
      fail();
    }
    for (int t = 0; t < FLIPGRAPH_NTYPES; t++) total[t] += c[r].type[t];
  }
  assert_true(total[FLIPGRAPH_I] > 0);
  assert_true(total[FLIPGRAPH_II] > 0);
  assert_true(total[FLIPGRAPH_III] > 0);
  assert_true(total[FLIPGRAPH_V] > 0);
  /* Integer grids too (ties everywhere): still never type IV. */
  flipgraph_plan *pl = flipgraph_plan_new(rules, n, TFG_EPS);
  testutil_rng g = {777};
  for (int i = 0; i < 3000; i++) {
    geom_point v[5];
    tfg_grid_pentagon(&g, v, 8);
    flipgraph_pentagon p;
    flipgraph_prepare(&p, v);
    flipgraph out[TFG_MAXRULES];
    flipgraph_plan_run(pl, &p, out);
    for (int r = 0; r < n; r++) assert_int_not_equal(out[r].type, FLIPGRAPH_IV);
  }
  flipgraph_plan_free(pl);
}

/* A whole-quadrilateral rule that goes round the cycle.  Directions are
** taken mod 180 degrees; the rule prefers the diagonal that lies less than
** 90 degrees anticlockwise of the other.  It names neither diagonal first
** (swapping them maps delta to 180 - delta and the answer with it), and it
** is rotation invariant, so on a regular pentagon -- where turning by 72
** degrees carries Q_j onto Q_{j+1} with AC onto AC -- all five decisions
** agree: all AC or all BD, i.e. no sink (type IV).  Near-regular
** pentagons keep that. */
static rule_choice tfg_cyclic_rule(const geom_point q[4], void *ctx) {
  (void)ctx;
  double tac = atan2(q[2].y - q[0].y, q[2].x - q[0].x);
  double tbd = atan2(q[3].y - q[1].y, q[3].x - q[1].x);
  double delta = fmod(tac - tbd + 4 * M_PI, M_PI);
  if (delta == 0 || delta == M_PI / 2) return RULE_EITHER;
  return delta < M_PI / 2 ? RULE_AC : RULE_BD;
}

static void test_type_four_by_quad_rule(void **state) {
  (void)state;
  rule_quad q = {"cyclic-test", "prefers the diagonal < 90 deg anticlockwise of the other",
                 tfg_cyclic_rule, NULL};
  int id = rule_quad_register(&q);
  assert_true(id > 0);
  rule r;
  char err[256];
  assert_int_equal(rule_parse("cyclic-test", &r, err, sizeof err), 0);
  assert_int_equal(r.kind, RULE_QUAD);
  geom_point v[5];
  for (int k = 0; k < 5; k++) v[k] = (geom_point){cos(2 * M_PI * k / 5 + 0.1), sin(2 * M_PI * k / 5 + 0.1)};
  flipgraph_pentagon p;
  flipgraph_prepare(&p, v);
  flipgraph g;
  flipgraph_classify(&p, &r, TFG_EPS, &g);
  assert_int_equal(g.type, FLIPGRAPH_IV);
  assert_int_equal(g.nsinks, 0);
  /* On random pentagons it happens too, and the tally agrees with itself
  ** for one and two threads. */
  flipgraph_counts c1, c2;
  memset(&c1, 0, sizeof c1);
  memset(&c2, 0, sizeof c2);
  assert_int_equal(flipgraph_tally(&r, 1, 5, 0, 20000, TFG_EPS, 1, &c1, NULL, NULL), 0);
  assert_int_equal(flipgraph_tally(&r, 1, 5, 0, 20000, TFG_EPS, 2, &c2, NULL, NULL), 0);
  assert_memory_equal(&c1, &c2, sizeof c1);
  assert_true(c1.type[FLIPGRAPH_IV] > 0);
  rule_quad_unregister_user();
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_triangle_indexing),
    cmocka_unit_test(test_graph_from_decisions),
    cmocka_unit_test(test_type_one_is_local),
    cmocka_unit_test(test_figure_3_3),
    cmocka_unit_test(test_dt_always_type_one),
    cmocka_unit_test(test_fast_path_equals_rule_eval),
    cmocka_unit_test(test_tally_equals_loop),
    cmocka_unit_test(test_classify_n),
    cmocka_unit_test(test_extremes_and_engines),
    cmocka_unit_test(test_tally_hook),
    cmocka_unit_test(test_types_reached),
    cmocka_unit_test(test_type_four_by_quad_rule),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
