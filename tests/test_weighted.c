/*
** test_weighted.c: the weighted Delaunay rule WDT (regular triangulations)
** and its exact power test.
**
** Checks: geom_power is geom_incircle when the weights are equal and the
** exact determinant always (filter against GMP on random reals and on
** small integers, where it is often 0); lot with WDT and equal weights (or
** none) gives DT's triangles exactly; on small random weighted sets lot
** gives the lower hull of the lifted sites, found by brute force over all
** triples, and leaves out exactly the sites above that hull (the oracle:
** a site inside a triangle of three others whose lifted plane it lies
** above); on large sets every kept edge is regular (lot_check_weighted)
** and every site left out is certified by the triangle of the result
** that holds it; duplicates keep the heaviest; bad weights are refused.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lot.h"
#include "rule.h"
#include "sampler.h"
#include "siteflip.h"
#include "splitmix.h"
#include "testutil.h"

static rule twt_rule(const char *name) {
  rule r;
  char err[256];
  if (rule_parse(name, &r, err, sizeof err) != 0) fail_msg("%s: %s", name, err);
  return r;
}

static double twt_unit(uint64_t *s) {
  return geom_unit53(geom_splitmix64(s));
}

/* A triangulation's triangles sorted (lot_get_triangles sorts them). */
typedef struct twt_tri {
  uint32_t *t;
  size_t n;
  uint32_t *red;
  size_t nred;
} twt_tri;

static int twt_build(const char *name, const geom_point *p, size_t n, const double *w,
                     lot_algorithm a, twt_tri *out, char *err, size_t errlen) {
  rule r = twt_rule(name);
  lot_options o;
  lot_options_init(&o, &r);
  o.algorithm = a;
  o.weights = w;
  lot *L;
  if (lot_build(&L, p, n, &o, err, errlen) != 0) return -1;
  const lot_stats *st = lot_get_stats(L);
  assert_int_equal(st->status, LOT_CONVERGED);
  out->n = st->triangles;
  out->t = malloc(3 * (out->n + 1) * sizeof *out->t);
  out->red = malloc((n + 1) * sizeof *out->red);
  assert_non_null(out->t);
  assert_non_null(out->red);
  lot_get_triangles(L, out->t);
  out->nred = lot_get_redundant(L, out->red);
  assert_int_equal(out->nred, st->redundant);
  lot_free(L);
  return 0;
}

static void twt_free(twt_tri *t) {
  free(t->t);
  free(t->red);
}

static void test_power_is_incircle(void **state) {
  (void)state;
  uint64_t s = 11;
  for (int k = 0; k < testutil_reps(20000); k++) {
    geom_point q[4];
    int grid = k & 1;
    for (int i = 0; i < 4; i++)
      q[i] = grid ? (geom_point){(double)(geom_splitmix64(&s) % 5),
                                 (double)(geom_splitmix64(&s) % 5)}
                  : (geom_point){twt_unit(&s), twt_unit(&s)};
    double c = grid ? (double)(geom_splitmix64(&s) % 7) : twt_unit(&s) * 3;
    const double w[4] = {c, c, c, c};
    assert_int_equal(geom_power(q[0], q[1], q[2], q[3], w),
                     geom_incircle(q[0], q[1], q[2], q[3]));
  }
}

/* The filter never disagrees with the exact determinant: random reals,
** and small integers with small integer weights (many exact zeros). */
static void test_power_exact(void **state) {
  (void)state;
  uint64_t s = 12;
  int zeros = 0;
  for (int k = 0; k < testutil_reps(40000); k++) {
    geom_point q[4];
    double w[4];
    int ints = k % 3 != 0;
    for (int i = 0; i < 4; i++) {
      q[i] = ints ? (geom_point){(double)(geom_splitmix64(&s) % 4),
                                 (double)(geom_splitmix64(&s) % 4)}
                  : (geom_point){twt_unit(&s) * 1e3, twt_unit(&s) * 1e-3};
      w[i] = ints ? (double)(geom_splitmix64(&s) % 5) : twt_unit(&s) * 1e-2;
    }
    int e = geom_power_exact(q[0], q[1], q[2], q[3], w);
    zeros += e == 0;
    assert_int_equal(geom_power(q[0], q[1], q[2], q[3], w), e);
  }
  assert_true(zeros > 100);   /* the integer cases reach the exact zero */
}

/* WDT with equal weights, or with none, is DT: the same triangles. */
static void test_equal_weights_are_dt(void **state) {
  (void)state;
  enum { N = 400 };
  static geom_point p[N];
  static double w[N];
  char err[256];
  for (int kind = 0; kind < 3; kind++) {
    sampler_points(kind == 0 ? SAMPLER_UNIFORM : kind == 1 ? SAMPLER_GRID : SAMPLER_CIRCLE, 3,
                   N, p);
    for (int i = 0; i < N; i++) w[i] = 0.25;
    for (int a = 0; a < 2; a++) {
      lot_algorithm alg = a ? LOT_FLIP : LOT_INCREMENTAL;
      twt_tri dt, wd, wn;
      assert_int_equal(twt_build("DT", p, N, NULL, alg, &dt, err, sizeof err), 0);
      assert_int_equal(twt_build("WDT", p, N, w, alg, &wd, err, sizeof err), 0);
      assert_int_equal(twt_build("WDT", p, N, NULL, alg, &wn, err, sizeof err), 0);
      assert_int_equal(wd.n, dt.n);
      assert_int_equal(wn.n, dt.n);
      assert_memory_equal(wd.t, dt.t, 3 * dt.n * sizeof *dt.t);
      assert_memory_equal(wn.t, dt.t, 3 * dt.n * sizeof *dt.t);
      assert_int_equal(wd.nred, 0);
      twt_free(&dt);
      twt_free(&wd);
      twt_free(&wn);
    }
  }
}

/* Is p in the closed triangle a b c (anticlockwise)? */
static int twt_in(geom_point a, geom_point b, geom_point c, geom_point p) {
  return geom_orient(a, b, p) >= 0 && geom_orient(b, c, p) >= 0 && geom_orient(c, a, p) >= 0;
}

/* The oracle: site l is redundant when some triangle of three other sites
** holds it and its lifted point lies strictly above their plane. */
static int twt_redundant(const geom_point *p, const double *w, size_t n, size_t l) {
  for (size_t i = 0; i < n; i++)
    for (size_t j = 0; j < n; j++)
      for (size_t k = 0; k < n; k++) {
        if (i == l || j == l || k == l || geom_orient(p[i], p[j], p[k]) <= 0) continue;
        const double ww[4] = {w[i], w[j], w[k], w[l]};
        if (twt_in(p[i], p[j], p[k], p[l]) && geom_power(p[i], p[j], p[k], p[l], ww) < 0)
          return 1;
      }
  return 0;
}

/* The oracle's faces: anticlockwise triples of kept sites with every other
** kept site's lifted point strictly above their plane, as sorted rows
** starting at the smallest index (lot_get_triangles' form). */
static size_t twt_faces(const geom_point *p, const double *w, size_t n, const int *keep,
                        uint32_t *out) {
  size_t f = 0;
  for (uint32_t i = 0; i < n; i++)
    for (uint32_t j = i + 1; j < n; j++)
      for (uint32_t k = i + 1; k < n; k++) {
        if (j == k || !keep[i] || !keep[j] || !keep[k] || geom_orient(p[i], p[j], p[k]) <= 0)
          continue;
        int ok = 1;
        for (uint32_t l = 0; l < n && ok; l++) {
          const double ww[4] = {w[i], w[j], w[k], w[l]};
          ok = l == i || l == j || l == k || !keep[l] || geom_power(p[i], p[j], p[k], p[l], ww) < 0;
        }
        if (ok) {
          out[3 * f] = i, out[3 * f + 1] = j, out[3 * f + 2] = k;
          f++;
        }
      }
  return f;
}

static int twt_row_cmp(const void *x, const void *y) {
  const uint32_t *a = x, *b = y;
  for (int i = 0; i < 3; i++)
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  return 0;
}

/* Small random weighted sets against the brute-force lower hull. */
static void test_small_sets_against_lifting(void **state) {
  (void)state;
  uint64_t s = 13;
  char err[256];
  int with_redundant = 0;
  for (int rep = 0; rep < testutil_reps(400); rep++) {
    size_t n = 4 + geom_splitmix64(&s) % 9;
    geom_point p[12];
    double w[12];
    int keep[12];
    double scale = rep % 4 == 0 ? 0 : 0.05 * (double)(rep % 4);
    for (size_t i = 0; i < n; i++) {
      p[i] = (geom_point){twt_unit(&s), twt_unit(&s)};
      w[i] = scale * twt_unit(&s);
    }
    twt_tri got;
    for (int a = 0; a < 2; a++) {
      assert_int_equal(twt_build("WDT", p, n, w, a ? LOT_FLIP : LOT_INCREMENTAL, &got, err,
                                 sizeof err), 0);
      size_t nred = 0;
      for (size_t l = 0; l < n; l++) {
        keep[l] = !twt_redundant(p, w, n, l);
        if (!keep[l]) {
          assert_true(nred < got.nred);
          assert_int_equal(got.red[nred++], l);
        }
      }
      assert_int_equal(nred, got.nred);
      with_redundant += nred > 0;
      uint32_t faces[3 * 220];
      size_t nf = twt_faces(p, w, n, keep, faces);
      qsort(faces, nf, 3 * sizeof *faces, twt_row_cmp);
      assert_int_equal(nf, got.n);
      assert_memory_equal(faces, got.t, 3 * nf * sizeof *faces);
      twt_free(&got);
    }
  }
  assert_true(with_redundant > testutil_reps(400) / 10);
}

/* A large set: regular (lot_check_weighted), and each site left out lies
** in a triangle of the result whose lifted plane is strictly below it. */
static void test_large_set_certified(void **state) {
  (void)state;
  enum { N = 20000 };
  static geom_point p[N];
  static double w[N];
  uint64_t s = 14;
  sampler_points(SAMPLER_UNIFORM, 5, N, p);
  for (int i = 0; i < N; i++) w[i] = 3e-5 * twt_unit(&s);   /* spacing^2 about 5e-5 */
  twt_tri t;
  char err[256];
  assert_int_equal(twt_build("WDT", p, N, w, LOT_INCREMENTAL, &t, err, sizeof err), 0);
  rule r = twt_rule("WDT");
  lot_check_result c;
  assert_int_equal(lot_check_weighted(p, w, N, t.t, t.n, &r, &c), 0);
  assert_true(c.valid);
  assert_int_equal(c.not_optimal, 0);
  assert_true(t.nred > 0);
  for (size_t k = 0; k < t.nred; k++) {
    geom_point x = p[t.red[k]];
    int certified = 0;
    for (size_t f = 0; f < t.n && !certified; f++) {
      const uint32_t *v = t.t + 3 * f;
      const double ww[4] = {w[v[0]], w[v[1]], w[v[2]], w[t.red[k]]};
      certified = twt_in(p[v[0]], p[v[1]], p[v[2]], x) &&
                  geom_power(p[v[0]], p[v[1]], p[v[2]], x, ww) < 0;
    }
    if (!certified) fail_msg("site %u left out without a certificate", t.red[k]);
  }
  twt_free(&t);
}

static int twt_u32_cmp(const void *x, const void *y) {
  uint32_t a = *(const uint32_t *)x, b = *(const uint32_t *)y;
  return a < b ? -1 : a > b;
}

/* A triangle as the sorted triple of its sites, packed (sites < 2^10). */
static uint32_t twt_pack(uint32_t a, uint32_t b, uint32_t c) {
  uint32_t v[3] = {a, b, c};
  qsort(v, 3, sizeof *v, twt_u32_cmp);
  return v[0] << 20 | v[1] << 10 | v[2];
}

/* The flip graph of a small weighted site set directed by WDT: where lot
** leaves no site out, one sink, lot's regular triangulation; equal weights
** direct it as DT does.  (Where a site is redundant no triangulation of all
** the sites is regular, and the graph may have several sinks.) */
static void test_flip_graph(void **state) {
  (void)state;
  uint64_t s = 15;
  rule wdt = twt_rule("WDT"), dt = twt_rule("DT");
  char err[256];
  int unique = 0;
  for (int rep = 0; rep < testutil_reps(60); rep++) {
    geom_point p[8];
    double w[8], eq[8];
    for (int i = 0; i < 8; i++) {
      p[i] = (geom_point){twt_unit(&s), twt_unit(&s)};
      w[i] = 0.06 * twt_unit(&s);
      eq[i] = 0.5;
    }
    siteflip_graph *g = siteflip_build(p, 8, err, sizeof err);
    assert_non_null(g);
    size_t nq = (size_t)g->nquads;
    rule_choice *dec = malloc(nq * sizeof *dec), *ddt = malloc(nq * sizeof *ddt);
    int *sinks = malloc((size_t)g->nnodes * sizeof *sinks);
    siteflip_result res, rdt;
    assert_int_equal(siteflip_direct_weighted(g, &wdt, eq, 0, dec, NULL, &res), 0);
    assert_int_equal(siteflip_direct(g, &dt, 0, ddt, NULL, &rdt), 0);
    assert_memory_equal(dec, ddt, (size_t)g->nquads * sizeof *dec);
    assert_int_equal(siteflip_direct_weighted(g, &wdt, w, 0, dec, sinks, &res), 0);
    twt_tri t;
    assert_int_equal(twt_build("WDT", p, 8, w, LOT_INCREMENTAL, &t, err, sizeof err), 0);
    if (t.nred == 0) {
      assert_int_equal(res.nsinks, 1);
      assert_int_equal(g->per, (int)t.n);
      uint32_t a[32], b[32];
      for (int k = 0; k < g->per; k++) {
        const unsigned char *v = g->tri_v[g->node_tri[(size_t)sinks[0] * (size_t)g->per + k]];
        a[k] = twt_pack(v[0], v[1], v[2]);
        b[k] = twt_pack(t.t[3 * k], t.t[3 * k + 1], t.t[3 * k + 2]);
      }
      qsort(a, t.n, sizeof *a, twt_u32_cmp);
      qsort(b, t.n, sizeof *b, twt_u32_cmp);
      assert_memory_equal(a, b, t.n * sizeof *a);
      unique++;
    } else {
      assert_true(res.nsinks >= 1);   /* acyclic: the lifted surface only goes down */
    }
    twt_free(&t);
    free(dec);
    free(ddt);
    free(sinks);
    siteflip_free(g);
  }
  assert_true(unique > testutil_reps(60) / 4);
}

/* Exact duplicates: the heaviest represents them (the first on a tie). */
static void test_duplicates(void **state) {
  (void)state;
  const geom_point p[6] = {{0, 0}, {4, 0}, {2, 3}, {2, 1}, {2, 1}, {2, 1}};
  const double w[6] = {0, 0, 0, 0.5, 2, 2};
  twt_tri t;
  char err[256];
  assert_int_equal(twt_build("WDT", p, 6, w, LOT_INCREMENTAL, &t, err, sizeof err), 0);
  assert_int_equal(t.n, 3);   /* (2, 1) with weight 2 is below the plane of the hull */
  for (size_t i = 0; i < 9; i++) assert_true(t.t[i] != 3 && t.t[i] != 5);
  assert_int_equal(t.nred, 0);
  twt_free(&t);
  const double heavy[6] = {0, 0, 0, 0.5, -9, -9};   /* then (2,1) with 0.5, still inside */
  assert_int_equal(twt_build("WDT", p, 6, heavy, LOT_INCREMENTAL, &t, err, sizeof err), 0);
  assert_int_equal(t.n, 3);
  for (size_t i = 0; i < 9; i++) assert_true(t.t[i] != 4 && t.t[i] != 5);
  twt_free(&t);
}

/* Bad weights and uses of weights: one line each. */
static void test_refused(void **state) {
  (void)state;
  geom_point p[5] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.3, 0.4}};
  double w[5] = {0, 0, 0, 0, 0};
  twt_tri t;
  char err[256];
  assert_int_equal(twt_build("DT", p, 5, w, LOT_INCREMENTAL, &t, err, sizeof err), -1);
  assert_non_null(strstr(err, "weights apply to the weighted Delaunay rule WDT, not DT"));
  assert_int_equal(twt_build("WDT", p, 5, w, LOT_SWEEP, &t, err, sizeof err), -1);
  assert_non_null(strstr(err, "sweep"));
  const double bad[3] = {NAN, 1e61, 1e-70};
  const char *why[3] = {"not finite", "out of range", "out of range"};
  for (int k = 0; k < 3; k++) {
    w[2] = bad[k];
    assert_int_equal(twt_build("WDT", p, 5, w, LOT_INCREMENTAL, &t, err, sizeof err), -1);
    assert_non_null(strstr(err, "point 2: weight"));
    assert_non_null(strstr(err, why[k]));
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_power_is_incircle),
    cmocka_unit_test(test_power_exact),
    cmocka_unit_test(test_equal_weights_are_dt),
    cmocka_unit_test(test_small_sets_against_lifting),
    cmocka_unit_test(test_large_set_certified),
    cmocka_unit_test(test_flip_graph),
    cmocka_unit_test(test_duplicates),
    cmocka_unit_test(test_refused),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
