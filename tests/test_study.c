/*
** test_study.c: the studies of studies/study.h against independent
** computations.
**
** - Intervals: the Wilson interval's end points solve the score equation
**   that defines it, hold the proportion, stay in [0, 100].
** - Pentagons: counts, verdicts and witnesses equal a plain loop over the
**   same stream with the one-rule reference path (flipgraph_classify),
**   whatever the thread count; the verdicts follow from the counts by their
**   definitions (systematic: no type III; local: no type II; type IV a bug
**   only for a triangle rule).
** - Quadrilaterals: the Delaunay-equivalence counts equal a plain loop of
**   rule_eval against DT, the first disagreement is the lowest index.
** - Site sets: the census counts equal siteflip_census's, the witness is
**   the lowest set whose flip graph (built again) has two or more sinks.
** - LOT against GOT, by brute force over every triangulation of small
**   simple polygons (an independent diagonal test, O'Rourke's): for the
**   rules rule_got_is_cdt names the CDT is the optimum, and the study finds
**   it with equal triangles; for every other rule of the catalogue some
**   polygon has an optimum that is not the CDT alone (a counterexample to
**   the property); a LOT never totals below the GOT; convex position; every
**   refusal one line.
** - The field tables read each result's fields by name.
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
#include "sampler.h"
#include "study.h"
#include "testutil.h"

static rule ts_rule(const char *name) {
  rule r;
  char err[512];
  if (rule_parse(name, &r, err, sizeof err) != 0) fail_msg("%s: %s", name, err);
  return r;
}

/* ---- intervals ---------------------------------------------------------- */

/* The Wilson interval is {p : |k/n - p| <= z sqrt(p(1-p)/n)}: its end points
** solve the score equation with equality, unless clipped to [0, 100]. */
static void test_wilson(void **state) {
  (void)state;
  const double z = 1.959963984540054;
  static const uint64_t ns[] = {10, 137, 5000, 1000000};
  for (size_t a = 0; a < sizeof ns / sizeof ns[0]; a++) {
    uint64_t n = ns[a];
    for (uint64_t k = 0; k <= n; k += n / 7 + 1) {
      double ph = (double)k / (double)n, nn = (double)n, lo, hi;
      double centre = (ph + z * z / (2 * nn)) / (1 + z * z / nn);
      double h = study_wilson_halfwidth(k, n) / 100;
      for (int s = -1; s <= 1; s += 2) {
        double p = centre + s * h;
        double lhs = (ph - p) * (ph - p), rhs = z * z * p * (1 - p) / nn;
        assert_true(fabs(lhs - rhs) <= 1e-12 + 1e-9 * rhs);
      }
      assert_true(study_wilson_halfwidth(k, n) <= study_wilson_max(n) + 1e-12);
      study_wilson(k, n, &lo, &hi);
      assert_true(0 <= lo && lo <= 100 * ph + 1e-9 && 100 * ph <= hi + 1e-9 && hi <= 100);
    }
  }
  /* The familiar figure: 5000 samples, p = 1/2: about 1.39 points. */
  assert_true(fabs(study_wilson_max(5000) - 1.3853) < 1e-3);
  assert_true(study_wilson_max(0) == 0);
  double lo, hi;
  study_wilson(0, 0, &lo, &hi);
  assert_true(lo == 0 && hi == 100);
}

/* ---- pentagons ------------------------------------------------------------ */

/* The plain loop: counts and the first k indices of each type. */
static void ts_pentagons_loop(const rule *r, uint64_t seed, uint64_t n, int k,
                              flipgraph_counts *c, study_witnesses *w) {
  memset(c, 0, sizeof *c);
  memset(w, 0, FLIPGRAPH_NTYPES * sizeof *w);
  for (uint64_t i = 0; i < n; i++) {
    geom_point v[5];
    flipgraph_pentagon p;
    flipgraph g;
    sampler_pentagon(seed, i, v);
    flipgraph_prepare(&p, v);
    flipgraph_classify(&p, r, rule_tie_eps(r), &g);
    c->samples++;
    c->type[g.type]++;
    c->dt += (uint64_t)g.delaunay;
    if (g.type != FLIPGRAPH_I && w[g.type].n < k) w[g.type].idx[w[g.type].n++] = i;
  }
}

static void ts_check_verdict(const rule *r, const study_verdict *v, const flipgraph_counts *c) {
  assert_memory_equal(&v->counts, c, sizeof *c);
  assert_int_equal(v->systematic, c->type[FLIPGRAPH_III] == 0);
  assert_int_equal(v->local, c->type[FLIPGRAPH_II] == 0);
  assert_int_equal(v->decided, c->samples - c->type[FLIPGRAPH_V]);
  assert_int_equal(v->sink_bug, c->type[FLIPGRAPH_IV] > 0 && rule_is_triangle(r));
  assert_int_equal(v->always_delaunay, c->samples > 0 && c->dt == c->samples);
  for (int t = 0; t < STUDY_ROWS; t++) {
    uint64_t k = t == STUDY_ROW_DT ? c->dt : c->type[t];
    double p = c->samples ? 100.0 * (double)k / (double)c->samples : 50, lo, hi;
    study_wilson(k, c->samples, &lo, &hi);
    assert_true(v->lo[t] == lo && v->hi[t] == hi && lo <= p + 1e-9 && p <= hi + 1e-9);
  }
}

static void test_pentagons(void **state) {
  (void)state;
  static const char *const names[] = {"P_1", "-alpha_inf", "sigma_0", "-c_1", "Pinf_inf", "DT"};
  enum { NR = sizeof names / sizeof *names, K = 4 };
  rule r[NR];
  for (int i = 0; i < NR; i++) r[i] = ts_rule(names[i]);
  uint64_t n = (uint64_t)testutil_reps(4000);
  study_verdict v1[NR], v2[NR];
  memset(v1, 0, sizeof v1);
  memset(v2, 0, sizeof v2);
  flipgraph_run run = {7, 0, n, RULE_DEFAULT_TIE_EPS, 2, NULL, NULL, NULL, NULL, NULL};
  assert_int_equal(study_pentagons(r, NR, &run, K, v2), 0);
  run.threads = 1;
  assert_int_equal(study_pentagons(r, NR, &run, K, v1), 0);
  assert_memory_equal(v1, v2, sizeof v1);   /* no output depends on the threads */
  int seen[FLIPGRAPH_NTYPES] = {0};
  for (int i = 0; i < NR; i++) {
    flipgraph_counts c;
    study_witnesses w[FLIPGRAPH_NTYPES];
    ts_pentagons_loop(&r[i], 7, n, K, &c, w);
    ts_check_verdict(&r[i], &v1[i], &c);
    for (int t = 0; t < FLIPGRAPH_NTYPES; t++) {
      assert_int_equal(v1[i].witness[t].n, w[t].n);
      assert_memory_equal(v1[i].witness[t].idx, w[t].idx, (size_t)w[t].n * sizeof *w[t].idx);
      seen[t] += w[t].n > 0;
    }
  }
  for (int t = FLIPGRAPH_II; t < FLIPGRAPH_NTYPES; t++)
    if (t != FLIPGRAPH_IV) assert_true(seen[t] > 0);   /* the witnesses were tested */
  run.count = 0;
  assert_int_equal(study_pentagons(r, NR, &run, STUDY_WITNESS_MAX + 1, v1), -1);
  run.threads = GEOM_MAX_THREADS + 1;
  assert_int_equal(study_pentagons(r, NR, &run, K, v1), -1);
}

/* Type IV is a bug for a triangle rule (theorem 1), "no LOT" for another. */
static void test_verdict_of(void **state) {
  (void)state;
  rule p1 = ts_rule("P_1"), dt = ts_rule("DT");
  flipgraph_counts c = {10, {3, 0, 2, 1, 4}, 3};
  study_verdict v;
  study_verdict_of(&p1, &c, &v);
  assert_true(v.sink_bug && v.local && !v.systematic && v.decided == 6 && !v.always_delaunay);
  study_verdict_of(&dt, &c, &v);
  assert_false(v.sink_bug);
  c = (flipgraph_counts){5, {5, 0, 0, 0, 0}, 5};
  study_verdict_of(&dt, &c, &v);
  assert_true(v.always_delaunay && v.systematic && v.local && v.decided == 5);
  c = (flipgraph_counts){0, {0}, 0};
  study_verdict_of(&dt, &c, &v);
  assert_false(v.always_delaunay);
}

/* ---- quadrilaterals --------------------------------------------------------- */

static void test_quads(void **state) {
  (void)state;
  static const char *const names[] = {"P_1", "R_1", "-c_1", "DT", "-A_1"};
  rule dt = ts_rule("DT");
  uint64_t n = (uint64_t)testutil_reps(20000);
  for (size_t k = 0; k < sizeof names / sizeof *names; k++) {
    rule r = ts_rule(names[k]);
    study_quadcheck q1, q2;
    char err[256];
    assert_int_equal(study_quads(&r, 3, n, 1, &q1, err, sizeof err), 0);
    assert_int_equal(study_quads(&r, 3, n, 2, &q2, err, sizeof err), 0);
    assert_memory_equal(&q1, &q2, sizeof q1);
    uint64_t dis = 0, ties = 0, coc = 0;
    int64_t first = -1;   /* none yet */
    for (uint64_t i = 0; i < n; i++) {
      geom_point q[4];
      sampler_quad(3, i, q);
      rule_choice d = rule_eval(&dt, q, NULL, NULL), c = rule_eval(&r, q, NULL, NULL);
      coc += d == RULE_EITHER;
      ties += d != RULE_EITHER && c == RULE_EITHER;
      dis += d != RULE_EITHER && c != RULE_EITHER && c != d;
      if (first < 0 && d != RULE_EITHER && c != RULE_EITHER && c != d) first = (int64_t)i;
    }
    assert_true(q1.tested == n && q1.disagree == dis && q1.ties == ties);
    assert_true(q1.cocircular == coc && q1.decided == n - coc);
    assert_true(first < 0 ? q1.first == 0 : q1.first == (uint64_t)first);
    assert_int_equal(q1.equivalent, dis == 0 && ties == 0);
    if (first >= 0) {
      geom_point q[4];
      sampler_quad(3, (uint64_t)first, q);
      assert_memory_equal(q, q1.q, sizeof q);
      assert_true(q1.choice != q1.dt && q1.dt == rule_eval(&dt, q, NULL, NULL));
    }
  }
  rule r1 = ts_rule("R_1"), p1 = ts_rule("P_1");
  study_quadcheck q;
  char err[256];
  assert_int_equal(study_quads(&r1, 3, n, 0, &q, err, sizeof err), 0);
  assert_true(q.equivalent);   /* R_1 is DT-equivalent (table 3.4) */
  assert_int_equal(study_quads(&p1, 3, n, 0, &q, err, sizeof err), 0);
  assert_true(q.disagree > 0);
  assert_int_equal(study_quads(&p1, 3, n, -1, &q, err, sizeof err), -1);
  assert_true(strstr(err, "threads") != NULL);
}

/* ---- site sets ---------------------------------------------------------------- */

/* Two or more sinks in the flip graph of set i, built again. */
static int ts_multi(const rule *r, int sampler, int n, uint64_t i) {
  geom_point p[SITEFLIP_MAX_SITES];
  char err[256];
  assert_int_equal(sampler_sites(sampler, 4, i, n, p), 0);
  siteflip_graph *g = siteflip_build(p, n, err, sizeof err);
  assert_non_null(g);
  rule_choice *dec = malloc(((size_t)g->nquads + 1) * sizeof *dec);
  siteflip_result res;
  assert_int_equal(siteflip_direct(g, r, rule_tie_eps(r), dec, NULL, &res), 0);
  free(dec);
  siteflip_free(g);
  return !res.ties && res.nsinks >= 2;
}

static void test_sites(void **state) {
  (void)state;
  static const char *const names[] = {"P_1", "R_1", "-alpha_2"};
  uint64_t n = (uint64_t)testutil_reps(400);
  for (size_t k = 0; k < sizeof names / sizeof *names; k++) {
    rule r = ts_rule(names[k]);
    study_sitecheck s;
    siteflip_counts c = {0};
    char err[256];
    int disc = SAMPLER_SITES_DISC;
    assert_int_equal(study_sites(&r, disc, 5, 4, n, 1e-12, 2, &s, err, sizeof err), 0);
    assert_int_equal(siteflip_census(&r, 1, disc, 5, 4, 0, n, 1e-12, 1, 0, &c, NULL, NULL, NULL,
                                     err, sizeof err), 0);
    assert_memory_equal(&s.counts, &c, sizeof c);
    assert_true(s.decided == c.samples - c.tie && s.systematic == (c.multi_sink == 0));
    int64_t w = -1;
    for (uint64_t i = 0; i < n && w < 0; i++)
      if (ts_multi(&r, disc, 5, i)) w = (int64_t)i;
    assert_int_equal(s.has_witness, w >= 0);
    assert_int_equal(s.witness, w >= 0 ? (uint64_t)w : 0);
    if (w >= 0) {
      geom_point p[SITEFLIP_MAX_SITES];
      sampler_sites(disc, 4, (uint64_t)w, 5, p);
      assert_memory_equal(p, s.sites, 5 * sizeof *p);
    }
    assert_int_equal(study_sites(&r, disc, 99, 4, n, 1e-12, 2, &s, err, sizeof err), -1);
  }
}

/* ---- brute force: every triangulation of a small simple polygon ------------- */

#define TS_MAXN 10
#define TS_MAXT 1500   /* Catalan(8) = 1430 for n = 10 */

typedef struct ts_poly {
  int n;
  geom_point p[TS_MAXN];
  unsigned char ok[TS_MAXN][TS_MAXN];     /* an edge or a valid diagonal */
  int ntri;                               /* triangulations found */
  uint32_t (*tri)[3 * (TS_MAXN - 2)];     /* [ntri][3 (n - 2)] */
} ts_poly;

static int ts_left(geom_point a, geom_point b, geom_point c) { return geom_orient(a, b, c) > 0; }
static int ts_lefton(geom_point a, geom_point b, geom_point c) { return geom_orient(a, b, c) >= 0; }

/* O'Rourke's InCone: the diagonal (i, j) starts into the polygon at i. */
static int ts_incone(const ts_poly *P, int i, int j) {
  geom_point a = P->p[i], b = P->p[j];
  geom_point a0 = P->p[(i + P->n - 1) % P->n], a1 = P->p[(i + 1) % P->n];
  if (ts_lefton(a0, a, a1)) return ts_left(a, b, a0) && ts_left(b, a, a1);
  return !(ts_lefton(a, b, a1) && ts_lefton(b, a, a0));
}

/* (i, j) meets no edge it does not end on (touching counts as meeting). */
static int ts_clear(const ts_poly *P, int i, int j) {
  for (int e = 0; e < P->n; e++) {
    int f = (e + 1) % P->n;
    if (e == i || e == j || f == i || f == j) continue;
    geom_point a = P->p[i], b = P->p[j], c = P->p[e], d = P->p[f];
    int o1 = geom_orient(a, b, c), o2 = geom_orient(a, b, d);
    int o3 = geom_orient(c, d, a), o4 = geom_orient(c, d, b);
    if (o1 * o2 <= 0 && o3 * o4 <= 0) return 0;
  }
  return 1;
}

/* The pending chains (i, j) still to triangulate; cur holds the triangles. */
static void ts_enum(ts_poly *P, int (*todo)[2], int ntodo, uint32_t *cur, int ncur) {
  if (ntodo == 0) {
    assert_true(P->ntri < TS_MAXT);
    memcpy(P->tri[P->ntri++], cur, 3 * (size_t)ncur * sizeof *cur);
    return;
  }
  int i = todo[ntodo - 1][0], j = todo[ntodo - 1][1];
  for (int k = i + 1; k < j; k++) {
    if (!P->ok[i][k] || !P->ok[k][j]) continue;
    int more = ntodo - 1;
    if (k - i >= 2) todo[more][0] = i, todo[more][1] = k, more++;
    if (j - k >= 2) todo[more][0] = k, todo[more][1] = j, more++;
    cur[3 * ncur] = (uint32_t)i, cur[3 * ncur + 1] = (uint32_t)k, cur[3 * ncur + 2] = (uint32_t)j;
    ts_enum(P, todo, more, cur, ncur + 1);
    todo[ntodo - 1][0] = i, todo[ntodo - 1][1] = j;
  }
}

/* Every triangulation of p[0..n-1] (simple, anticlockwise) into P. */
static void ts_triangulations(ts_poly *P, const geom_point *p, int n) {
  P->n = n;
  memcpy(P->p, p, (size_t)n * sizeof *p);
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++)
      P->ok[i][j] = i != j && ((j - i + n) % n == 1 || (i - j + n) % n == 1 ||
                               (ts_incone(P, i, j) && ts_incone(P, j, i) && ts_clear(P, i, j)));
  P->ntri = 0;
  P->tri = malloc(TS_MAXT * sizeof *P->tri);
  int todo[TS_MAXN][2] = {{0, n - 1}};
  uint32_t cur[3 * TS_MAXN];
  ts_enum(P, todo, 1, cur, 0);
  P->tri = realloc(P->tri, (size_t)P->ntri * sizeof *P->tri);
}

/* A triangulation's total as a key, from measure_eval values. */
static double ts_key(const rule *r, const geom_point *p, const uint32_t *t, int ntri) {
  double bad[TS_MAXN];
  for (int q = 0; q < ntri; q++) {
    geom_tri tr;
    geom_tri_make(&tr, p[t[3 * q]], p[t[3 * q + 1]], p[t[3 * q + 2]]);
    bad[q] = measure_eval(rule_measure(r), &tr);
  }
  return rule_total_key(r, bad, (size_t)ntri);
}

/* The same triangles (any order of triangles and of their vertices)? */
static int ts_same(const uint32_t *a, const uint32_t *b, int ntri) {
  lot_diff d;
  assert_int_equal(lot_compare(a, (size_t)ntri, b, (size_t)ntri, &d), 0);
  return d.triangles_common == (size_t)ntri;
}

/* The CDT of the polygon p[0..n-1] (rule DT, its edges as segments). */
static void ts_cdt(const geom_point *p, int n, uint32_t *tri) {
  uint32_t seg[2 * TS_MAXN];
  for (int i = 0; i < n; i++) seg[2 * i] = (uint32_t)i, seg[2 * i + 1] = (uint32_t)((i + 1) % n);
  rule dt = rule_delaunay();
  lot_options o;
  lot_options_init(&o, &dt);
  o.segments = seg;
  o.nsegments = (size_t)n;
  lot *L;
  char err[256];
  if (lot_build(&L, p, (size_t)n, &o, err, sizeof err) != 0) fail_msg("%s", err);
  assert_int_equal(lot_get_stats(L)->triangles, (size_t)n - 2);
  lot_get_triangles(L, tri);
  lot_free(L);
}

/* Random simple polygons of 6 to 9 vertices (star-shaped, x-monotone),
** then (from TS_NPOLY on) random convex quadrilaterals, where a GOT is the
** rule's decision: one that disagrees with DT there is no CDT rule. */
#define TS_NPOLY 14
#define TS_NQUAD 300
static void ts_polygon(int s, geom_point *p, int *n) {
  sampler_rng g;
  sampler_seed(&g, 100 + (uint64_t)s, 7);
  *n = s < TS_NPOLY ? 6 + s % 4 : 4;
  if (s >= TS_NPOLY) sampler_quad(5, (uint64_t)s, p);
  else assert_int_equal(s % 2 ? sampler_star(&g, (size_t)*n, p)
                              : sampler_monotone(&g, (size_t)*n, p), 0);
}

static geom_pslg ts_ring(geom_point *p, int n, uint32_t *seg) {
  for (int i = 0; i < n; i++) seg[2 * i] = (uint32_t)i, seg[2 * i + 1] = (uint32_t)((i + 1) % n);
  return (geom_pslg){p, (size_t)n, seg, (size_t)n, NULL, 0};
}

/* ---- LOT against GOT ------------------------------------------------------ */

/* The rules whose GOT is the CDT: on every polygon the CDT's total is the
** one least by brute force (every other triangulation's is larger), and
** the study finds it: the same triangles, equal totals, nothing failed. */
static void ts_cdt_rule(const rule *r, const ts_poly *P, const uint32_t *cdt) {
  int m = P->n - 2;
  double kc = ts_key(r, P->p, cdt, m);
  for (int t = 0; t < P->ntri; t++) {
    double k = ts_key(r, P->p, P->tri[t], m);
    if (!(k > kc) && !ts_same(P->tri[t], cdt, m))
      fail_msg("%s: a triangulation totals %.17g, the CDT %.17g", rule_name(r), k, kc);
  }
  uint32_t seg[2 * TS_MAXN];
  geom_point p[TS_MAXN];
  memcpy(p, P->p, sizeof p);
  geom_pslg in = ts_ring(p, P->n, seg);
  study_gotcheck c;
  char err[512];
  if (study_lot_got(&in, NULL, 0, cdt, (size_t)m, r, 1, &c, err, sizeof err) != 0)
    fail_msg("%s", err);
  assert_true(c.ring && c.got_is_cdt && c.same && c.equal && !c.below && !c.failed);
  assert_true(ts_same(c.tri, cdt, m));
  study_gotcheck_free(&c);
}

/* A counterexample to "the GOT is the CDT" on this polygon: a triangulation
** other than the CDT totals below it or ties it. */
static int ts_counterexample(const rule *r, const ts_poly *P, const uint32_t *cdt) {
  int m = P->n - 2;
  double kc = ts_key(r, P->p, cdt, m);
  for (int t = 0; t < P->ntri; t++) {
    double k = ts_key(r, P->p, P->tri[t], m);
    if ((k <= kc || rule_gap(r, k, kc) <= 1e-9) && !ts_same(P->tri[t], cdt, m)) return 1;
  }
  return 0;
}

static void test_got_is_cdt(void **state) {
  (void)state;
  enum { NP = TS_NPOLY + TS_NQUAD };
  static ts_poly P[NP];
  static uint32_t cdt[NP][3 * TS_MAXN];
  for (int s = 0; s < NP; s++) {
    geom_point p[TS_MAXN];
    int n;
    ts_polygon(s, p, &n);
    ts_triangulations(&P[s], p, n);
    ts_cdt(p, n, cdt[s]);
    int found = 0;   /* the enumeration holds the CDT exactly once */
    for (int t = 0; t < P[s].ntri; t++) found += ts_same(P[s].tri[t], cdt[s], n - 2);
    assert_int_equal(found, 1);
  }
  int named = 0, others = 0;
  for (int m = 0; m < measure_count(); m++)
    for (int j = 0; j < JOINT_COUNT; j++) {
      rule r;
      char err[256];
      if (rule_triangle(m, (joint_id)j, &r, err, sizeof err) != 0) continue;
      int cdt_rule = rule_got_is_cdt(&r), any = 0;
      for (int s = 0; s < NP && !any; s++) {
        if (cdt_rule) ts_cdt_rule(&r, &P[s], cdt[s]);
        else any = ts_counterexample(&r, &P[s], cdt[s]);
      }
      if (!cdt_rule && !any) fail_msg("%s: no counterexample to 'its GOT is the CDT'", r.name);
      named += cdt_rule;
      others += !cdt_rule;
    }
  assert_int_equal(named, 8);   /* R_1, R_2, R_0, R_-1, -r_1, abc_1, -r/R_1, -r2/A_0 */
  assert_true(others > 100);
  rule dt = ts_rule("DT");
  assert_false(rule_got_is_cdt(&dt));
  for (int s = 0; s < NP; s++) free(P[s].tri);
}

/* A constrained LOT totals at least the GOT, which is the brute-force
** least total; the study's relation and triangle counts agree. */
static void test_lot_above_got(void **state) {
  (void)state;
  static const char *const names[] = {"P_1", "sigma_1", "a_2", "R_inf", "-alpha_inf", "P_0"};
  for (int s = 0; s < TS_NPOLY; s++) {
    geom_point p[TS_MAXN];
    uint32_t seg[2 * TS_MAXN], tri[3 * TS_MAXN];
    int n;
    ts_polygon(s, p, &n);
    ts_poly P;
    ts_triangulations(&P, p, n);
    geom_pslg in = ts_ring(p, n, seg);
    for (size_t k = 0; k < sizeof names / sizeof *names; k++) {
      rule r = ts_rule(names[k]);
      lot_options o;
      lot_options_init(&o, &r);
      o.segments = seg;
      o.nsegments = (size_t)n;
      lot *L;
      char err[512];
      assert_int_equal(lot_build(&L, p, (size_t)n, &o, err, sizeof err), 0);
      lot_get_triangles(L, tri);
      lot_free(L);
      double best = INFINITY;
      for (int t = 0; t < P.ntri; t++) best = fmin(best, ts_key(&r, p, P.tri[t], n - 2));
      study_gotcheck c;
      assert_int_equal(study_lot_got(&in, NULL, 0, tri, (size_t)n - 2, &r, 2, &c, err,
                                     sizeof err), 0);
      assert_true(c.got.key == best || rule_gap(&r, c.got.key, best) <= 1e-9);
      assert_true(c.lot_key >= best || rule_gap(&r, c.lot_key, best) <= 1e-9);
      assert_true(!c.below && !c.failed && !c.got_is_cdt);
      assert_int_equal(c.same, ts_same(tri, c.tri, n - 2));
      assert_true(c.equal || c.lot_key > c.got.key);
      assert_int_equal(c.diff.triangles_a, (size_t)n - 2);
      study_gotcheck_free(&c);
    }
    free(P.tri);
  }
}

/* In convex position the polygon is the hull; an interior point refuses. */
static void test_got_convex(void **state) {
  (void)state;
  geom_point p[9];
  sampler_convex(11, 0, 8, p);
  p[8] = (geom_point){(p[0].x + p[3].x + p[5].x) / 3, (p[0].y + p[3].y + p[5].y) / 3};
  rule r = ts_rule("P_1");
  for (size_t n = 8; n <= 9; n++) {
    lot_options o;
    lot_options_init(&o, &r);
    lot *L;
    char err[512];
    assert_int_equal(lot_build(&L, p, n, &o, err, sizeof err), 0);
    size_t ntri = lot_get_stats(L)->triangles, h = lot_get_stats(L)->hull;
    uint32_t tri[3 * 16], hull[16];
    lot_get_triangles(L, tri);
    lot_get_hull(L, hull);
    lot_free(L);
    geom_pslg in = {p, n, NULL, 0, NULL, 0};
    study_gotcheck c;
    int rc = study_lot_got(&in, hull, h, tri, ntri, &r, 1, &c, err, sizeof err);
    if (n == 9) {
      assert_int_equal(rc, -1);
      assert_true(testutil_one_line(strcat(err, "\n")) && strstr(err, "(8 of 9 distinct"));
      continue;
    }
    assert_int_equal(rc, 0);
    ts_poly P;
    ts_triangulations(&P, p, 8);
    assert_int_equal(P.ntri, 132);   /* Catalan(6) */
    double best = INFINITY;
    for (int t = 0; t < P.ntri; t++) best = fmin(best, ts_key(&r, p, P.tri[t], 6));
    assert_true(!c.ring && c.n == 8 && rule_gap(&r, c.got.key, best) <= 1e-9);
    assert_true(c.lot_key >= best || rule_gap(&r, c.lot_key, best) <= 1e-9);
    free(P.tri);
    study_gotcheck_free(&c);
  }
}

/* Each refusal: -1 and one line saying what is wrong. */
static void test_got_refusals(void **state) {
  (void)state;
  static geom_point p[6] = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}}, hole = {2, 2};
  static uint32_t square[] = {0, 1, 1, 2, 2, 3, 3, 0};
  static uint32_t two[] = {0, 1, 1, 4, 4, 0, 2, 3, 3, 5, 5, 2};
  static uint32_t deg3[] = {0, 1, 1, 2, 2, 0, 0, 3, 3, 4, 4, 5};
  static uint32_t beyond[] = {0, 1, 1, 2, 2, 3, 3, 9};
  static uint32_t bow[] = {0, 2, 2, 1, 1, 3, 3, 0};   /* a ring that crosses itself */
  static const struct {
    geom_pslg in;
    size_t ntri;
    const char *rule, *want;
  } cases[] = {
    {{p, 4, square, 4, NULL, 0}, 2, "DT", "triangle-based rule (MEASURE_JOINT), not 'DT'"},
    {{p, 4, square, 4, NULL, 0}, 3, "P_1",
     "it has 3 triangles, the polygon's triangulations 2 (is keep-hull"},
    {{p, 4, square, 4, &hole, 1}, 2, "P_1", "no holes (1 given)"},
    {{p, 6, square, 4, NULL, 0}, 4, "P_1", "(4 segments, 6 points)"},
    {{p, 6, two, 6, NULL, 0}, 4, "P_1", "(they form more than one ring)"},
    {{p, 6, deg3, 6, NULL, 0}, 4, "P_1", "(point 0 is on more than 2 segments)"},
    {{p, 4, beyond, 4, NULL, 0}, 2, "P_1", "(segment 3 names a point beyond the 4 given)"},
    {{p, 4, bow, 4, NULL, 0}, 2, "P_1", "the ring of segments is not a simple polygon"},
    {{p, 6, NULL, 0, NULL, 0}, 6, "P_1", "strictly convex position"},
  };
  for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
    rule r = ts_rule(cases[k].rule);
    uint32_t tri[3 * TS_MAXN] = {0};
    study_gotcheck c;
    char err[512];
    assert_int_equal(study_lot_got(&cases[k].in, NULL, 0, tri, cases[k].ntri, &r, 1, &c, err,
                                   sizeof err), -1);
    if (strstr(err, cases[k].want) == NULL || strchr(err, '\n') != NULL)
      fail_msg("expected '%s' in one line, got '%s'", cases[k].want, err);
  }
}

/* ---- results through verbs ------------------------------------------------- */

/* Names unique, and each readable as an integer, a real, or by a verb of
** its own (others: the names of those). */
static void ts_names(const char *(*field)(size_t), int (*get_u64)(const void *, const char *,
                     size_t, uint64_t *), int (*get_double)(const void *, const char *, double *),
                     const void *res, const char *const *others) {
  size_t i = 0;
  for (; field(i) != NULL; i++) {
    uint64_t u;
    double d;
    int other = 0;
    for (const char *const *o = others; *o != NULL; o++) other |= strcmp(*o, field(i)) == 0;
    int n = (get_u64(res, field(i), 0, &u) == 0) + (get_double && get_double(res, field(i), &d) == 0);
    if (n + other != 1) fail_msg("field %s: %d readers", field(i), n + other);
    for (size_t j = 0; j < i; j++) assert_string_not_equal(field(i), field(j));
  }
  assert_true(i > 5);
  uint64_t u;
  assert_int_equal(get_u64(res, "nothing", 0, &u), -1);
}

static int ts_v_u64(const void *r, const char *n, size_t i, uint64_t *o) {
  return study_verdict_get_u64(r, n, i, o);
}
static int ts_q_u64(const void *r, const char *n, size_t i, uint64_t *o) {
  return study_quadcheck_get_u64(r, n, i, o);
}
static int ts_q_double(const void *r, const char *n, double *o) {
  return study_quadcheck_get_double(r, n, o);
}
static int ts_s_u64(const void *r, const char *n, size_t i, uint64_t *o) {
  return study_sitecheck_get_u64(r, n, i, o);
}
static int ts_g_u64(const void *r, const char *n, size_t i, uint64_t *o) {
  return study_gotcheck_get_u64(r, n, i, o);
}
static int ts_g_double(const void *r, const char *n, double *o) {
  return study_gotcheck_get_double(r, n, o);
}

/* Element i of integer field n of r, read by get (which must have it). */
static uint64_t ts_u64(int (*get)(const void *, const char *, size_t, uint64_t *), const void *r,
                       const char *n, size_t i) {
  uint64_t u;
  if (get(r, n, i, &u) != 0) fail_msg("no integer field %s[%zu]", n, i);
  return u;
}

/* Every field by name equals its member. */
static void test_fields(void **state) {
  (void)state;
  study_verdict *v = study_verdict_new();
  v->counts = (flipgraph_counts){1000, {900, 40, 30, 0, 30}, 700};
  v->lo[STUDY_ROW_DT] = 68.5;
  v->hi[STUDY_ROW_DT] = 71.5;
  v->witness[FLIPGRAPH_III] = (study_witnesses){2, {5, 9}};
  v->decided = 970;
  v->local = 1;
  static const char *const vo[] = {"lo", "hi", "witness", NULL};
  ts_names(study_verdict_field, ts_v_u64, NULL, v, vo);
  uint64_t u;
  double lo, hi;
  assert_true(ts_u64(ts_v_u64, v, "type", 2) == 30);
  assert_true(ts_u64(ts_v_u64, v, "dt", 0) == 700);
  assert_true(ts_u64(ts_v_u64, v, "decided", 0) == 970);
  assert_true(ts_u64(ts_v_u64, v, "local", 0) == 1);
  assert_int_equal(study_verdict_get_u64(v, "type", 5, &u), -1);
  assert_int_equal(study_verdict_interval(v, STUDY_ROW_DT, &lo, &hi), 0);
  assert_true(lo == 68.5 && hi == 71.5 && study_verdict_interval(v, 6, &lo, &hi) == -1);
  assert_true(study_verdict_witness(v, FLIPGRAPH_III, 1) == 9);
  assert_true(study_verdict_witness(v, FLIPGRAPH_III, 2) == -1);
  assert_true(study_verdict_witness(v, 7, 0) == -1);
  study_verdict_delete(v);

  study_quadcheck *q = study_quadcheck_new();
  *q = (study_quadcheck){.tested = 9, .first = 4, .choice = RULE_BD, .ac = 0.25};
  static const char *const qo[] = {"q", NULL};
  ts_names(study_quadcheck_field, ts_q_u64, ts_q_double, q, qo);
  assert_true(ts_u64(ts_q_u64, q, "first", 0) == 4);
  assert_true(ts_u64(ts_q_u64, q, "choice", 0) == RULE_BD);
  assert_true(study_quadcheck_get_double(q, "ac", &lo) == 0 && lo == 0.25);
  study_quadcheck_delete(q);

  study_sitecheck *s = study_sitecheck_new();
  geom_point p[SITEFLIP_MAX_SITES];
  s->n = 5;
  s->counts.multi_sink = 12;
  static const char *const so[] = {"sites", NULL};
  ts_names(study_sitecheck_field, ts_s_u64, NULL, s, so);
  assert_true(ts_u64(ts_s_u64, s, "multi_sink", 0) == 12);
  assert_int_equal(study_sitecheck_sites(s, p), 0);   /* no witness */
  s->has_witness = 1;
  s->sites[4] = (geom_point){0.5, -2};
  assert_true(study_sitecheck_sites(s, p) == 5 && p[4].x == 0.5 && p[4].y == -2);
  study_sitecheck_delete(s);

  study_gotcheck *c = study_gotcheck_new();
  snprintf(c->lot_text, sizeof c->lot_text, "exp(1000)");
  c->got.key = -3.5;
  c->diff.triangles_common = 17;
  c->rel = 0.125;
  static const char *const go[] = {"got", "tri", "lot_text", "got_text", "uncertified", NULL};
  ts_names(study_gotcheck_field, ts_g_u64, ts_g_double, c, go);
  assert_true(ts_u64(ts_g_u64, c, "triangles_shared", 0) == 17);
  assert_true(study_gotcheck_get_double(c, "rel", &lo) == 0 && lo == 0.125);
  assert_true(got_result_get_double(study_gotcheck_got(c), "key", &lo) == 0 && lo == -3.5);
  assert_string_equal(study_gotcheck_get_text(c, "lot_text"), "exp(1000)");
  assert_string_equal(study_gotcheck_get_text(c, "uncertified"), "");
  assert_null(study_gotcheck_get_text(c, "rel"));
  assert_null(study_gotcheck_triangles(c));
  study_gotcheck_delete(c);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_wilson),        cmocka_unit_test(test_pentagons),
    cmocka_unit_test(test_verdict_of),    cmocka_unit_test(test_quads),
    cmocka_unit_test(test_sites),         cmocka_unit_test(test_got_is_cdt),
    cmocka_unit_test(test_lot_above_got), cmocka_unit_test(test_got_convex),
    cmocka_unit_test(test_got_refusals),  cmocka_unit_test(test_fields),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
