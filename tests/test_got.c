/*
** test_got.c: the GOT dynamic programme (got/) against independent checks.
**
** - Kernels: every built-in measure's pair-data kernel agrees with
**   measure_eval(geom_tri_make(...)) on every triangle of random polygons
**   (relative 1e-12; angles are differences of edge directions, so angle
**   measures get 1e-13 rad absolute on top); the bulk log agrees with libm.
** - Brute force: for random convex polygons with n <= 10, every
**   triangulation (Catalan(n-2)) is enumerated and its total combined with
**   joint_apply on measure_eval values; for all 23 measures x 6 joints the
**   DP's optimum and its runner-up gap equal the brute force's smallest
**   and second smallest totals.  Tolerance: relative 1e-9, because the DP
**   sums keys (logs for l_0, squares for l_2) from kernel values that
**   differ from measure_eval in the last bits, while the brute force
**   combines measure_eval values directly; a wrong choice of triangles
**   would be off by far more on these polygons.
** - Known optima: GOT(P_1) is the minimum-weight triangulation (sum of
**   perimeters = polygon perimeter + twice the diagonals), on polygons
**   whose minimum is derived by hand below.
** - Delaunay: for the DT-equivalent rules with strictly monotone joints
**   the GOT is the (exact) Delaunay triangulation of random polygons in
**   general position; for -alpha_inf and R_inf the Delaunay triangulation
**   attains the optimal value.
** - Rotating the first vertex or reversing the polygon keeps the optimum;
**   the result does not depend on the thread count (bit for bit); sizes
**   beyond memory and quadrilateral rules are refused with a message.
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
#include "got.h"
#include "got_internal.h"
#include "sampler.h"
#include "testutil.h"

#define TGOT_REL 1e-9

static void tgot_polygon(uint64_t seed, size_t n, geom_point *p) {
  sampler_rng g;
  sampler_seed(&g, seed, 77);
  assert_int_equal(sampler_vector(&g, n, p), 0);
}

static rule tgot_rule(int m, joint_id j) {
  rule r;
  char err[256];
  assert_int_equal(rule_triangle(m, j, &r, err, sizeof err), 0);
  return r;
}

static void tgot_solve(const geom_point *p, size_t n, const rule *r, int threads, got_result *res) {
  char err[256];
  got_options o = {threads, RULE_DEFAULT_TIE_EPS};
  if (got_solve(p, n, r, &o, res, err, sizeof err) != 0) fail_msg("got_solve: %s", err);
}

static int tgot_close(double a, double b, double scale) {
  if (a == b) return 1;
  return fabs(a - b) <= TGOT_REL * scale;
}

/* ---- kernels ---- */

static int tgot_is_angle(int m) {
  return m == MEASURE_NEG_ALPHA || m == MEASURE_BETA || m == MEASURE_GAMMA || m == MEASURE_SIGMA;
}

static void test_kernels_match_measure_eval(void **state) {
  (void)state;
  enum { N = 14 };
  geom_point p[N];
  double out[N];
  double worst = 0;
  for (int poly = 0; poly < 6; poly++) {
    sampler_rng g;
    sampler_seed(&g, 100 + (uint64_t)poly, 1);
    if (poly % 2) assert_int_equal(sampler_circle(&g, N, p), 0);
    else assert_int_equal(sampler_vector(&g, N, p), 0);
    for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++) {
      assert_true(got_measure_has_kernel(m));
      got_pairs *pd = got_pairs_new(p, N, m, 1);
      assert_non_null(pd);
      for (size_t i = 0; i < N; i++)
        for (size_t j = i + 2; j < N; j++) {
          got_pairs_eval(pd, i, j, i + 1, j, out);
          for (size_t k = i + 1; k < j; k++) {
            geom_tri t;
            geom_tri_make(&t, p[i], p[k], p[j]);
            double want = measure_eval(m, &t), got = out[k - i - 1];
            double tol = 1e-12 * fabs(want) + (tgot_is_angle(m) ? 1e-13 : 0);
            if (!(fabs(got - want) <= tol))
              fail_msg("measure %s triangle (%zu,%zu,%zu): kernel %.17g, measure_eval %.17g",
                       measure_get(m)->name, i, k, j, got, want);
            if (want != 0 && fabs(got - want) / fabs(want) > worst)
              worst = fabs(got - want) / fabs(want);
          }
        }
      got_pairs_free(pd);
    }
  }
  print_message("worst relative kernel difference: %.3g\n", worst);
}

static void test_bulk_log(void **state) {
  (void)state;
  testutil_rng g = {42};
  enum { M = 4096 };
  static double x[M], y[M];
  for (int q = 0; q < M; q++)
    x[q] = y[q] = (testutil_uniform(&g) + 0.5) * pow(2.0, (double)(testutil_next(&g) % 2000) - 1000.0);
  x[0] = y[0] = 1.0;
  x[1] = y[1] = nextafter(1.0, 2.0);
  got_log_inplace(y, M, 1.0);
  for (int q = 0; q < M; q++) {
    double want = log(x[q]);
    assert_true(fabs(y[q] - want) <= 2 * 2.2e-16 * fabs(want) + 1e-300);
    y[q] = -x[q];
  }
  got_log_inplace(y, M, -1.0);
  for (int q = 0; q < M; q++) assert_true(y[q] == -(-log(x[q]) * -1.0) || fabs(y[q] + log(x[q])) <= 2 * 2.2e-16 * fabs(log(x[q])));
  double s[4] = {0.0, INFINITY, -1.0, 0x1p-1070};
  got_log_inplace(s, 4, 1.0);
  assert_true(s[0] == -INFINITY && s[1] == INFINITY && isnan(s[2]) && s[3] == log(0x1p-1070));
}

/* ---- brute force ---- */

typedef struct tgot_list { double *v; size_t n; } tgot_list;

typedef struct tgot_bf {
  const geom_point *p;
  size_t n;
  int measure, sign;
  joint_id joint;
  double tri[12][12][12];
  tgot_list memo[12][12];
} tgot_bf;

/* All totals of the triangulations of the chain i..j (j - i >= 2). */
static const tgot_list *tgot_bf_values(tgot_bf *b, size_t i, size_t j) {
  tgot_list *L = &b->memo[i][j];
  if (L->v) return L;
  size_t cap = 1;
  for (size_t k = i + 1; k < j; k++) {
    size_t a = k - i >= 2 ? tgot_bf_values(b, i, k)->n : 1;
    size_t c = j - k >= 2 ? tgot_bf_values(b, k, j)->n : 1;
    cap += a * c;
  }
  L->v = malloc(cap * sizeof *L->v);
  for (size_t k = i + 1; k < j; k++) {
    double t = b->tri[i][k][j];
    const tgot_list *A = k - i >= 2 ? tgot_bf_values(b, i, k) : NULL;
    const tgot_list *C = j - k >= 2 ? tgot_bf_values(b, k, j) : NULL;
    size_t na = A ? A->n : 1, nc = C ? C->n : 1;
    for (size_t x = 0; x < na; x++)
      for (size_t y = 0; y < nc; y++) {
        double v = t;   /* the empty chain contributes nothing: no identity needed */
        if (A) v = joint_apply(b->joint, b->sign, A->v[x], v);
        if (C) v = joint_apply(b->joint, b->sign, v, C->v[y]);
        L->v[L->n++] = v;
      }
  }
  return L;
}

static int tgot_cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return x < y ? -1 : x > y;
}

static long long tgot_catalan(int m) {
  long long c = 1;
  for (int q = 0; q < m; q++) c = c * 2 * (2 * q + 1) / (q + 2);
  return c;
}

/* Check one rule on one polygon against brute force. */
static void tgot_check_bf(const geom_point *p, size_t n, int m, joint_id jt) {
  tgot_bf *b = calloc(1, sizeof *b);
  b->p = p;
  b->n = n;
  b->measure = m;
  b->joint = jt;
  b->sign = (int)measure_get(m)->sign;
  for (size_t i = 0; i < n; i++)
    for (size_t k = i + 1; k < n; k++)
      for (size_t j = k + 1; j < n; j++) {
        geom_tri t;
        geom_tri_make(&t, p[i], p[k], p[j]);
        b->tri[i][k][j] = measure_eval(m, &t);
      }
  const tgot_list *all = tgot_bf_values(b, 0, n - 1);
  assert_int_equal((long long)all->n, tgot_catalan((int)n - 2));
  double *v = malloc(all->n * sizeof *v);
  memcpy(v, all->v, all->n * sizeof *v);
  qsort(v, all->n, sizeof *v, tgot_cmp);
  double best = v[0], second = all->n > 1 ? v[1] : NAN;

  rule r = tgot_rule(m, jt);
  got_result res;
  tgot_solve(p, n, &r, 1, &res);
  double scale = fmax(fabs(best), fabs(second));
  if (!tgot_close(res.total, best, fabs(best)))
    fail_msg("%s n=%zu: DP %.17g, brute force %.17g", r.name, n, res.total, best);
  /* the triangles returned reach that value (recomputed with measure_eval) */
  double again = res.tri[0].badness;
  for (size_t q = 1; q < res.ntri; q++) again = joint_apply(jt, b->sign, again, res.tri[q].badness);
  if (!tgot_close(again, best, fabs(best)))
    fail_msg("%s n=%zu: DP triangles total %.17g, optimum %.17g", r.name, n, again, best);
  if (n > 3) {
    assert_true(res.has_runner_up);
    double gap_bf = second - best, gap = res.total2 - res.total;
    if (!(fabs(gap - gap_bf) <= TGOT_REL * scale || gap == gap_bf))
      fail_msg("%s n=%zu: runner-up gap DP %.17g, brute force %.17g (best %.17g)", r.name, n,
               gap, gap_bf, best);
    /* uniqueness as the tie rule says, away from the tolerance's edge */
    if (gap_bf > 1e-6 * scale) assert_true(res.unique);
    if (gap_bf == 0) assert_false(res.unique);
  }
  got_result_free(&res);
  free(v);
  for (size_t i = 0; i < 12; i++)
    for (size_t j = 0; j < 12; j++) free(b->memo[i][j].v);
  free(b);
}

static void test_brute_force_all_rules(void **state) {
  (void)state;
  geom_point p[10];
  for (size_t n = 3; n <= 10; n++) {
    int polys = n <= 8 ? 3 : 1;
    for (int s = 0; s < polys; s++) {
      tgot_polygon(1000 * n + (uint64_t)s, n, p);
      for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++)
        for (int j = 0; j < JOINT_COUNT; j++) tgot_check_bf(p, n, m, (joint_id)j);
    }
  }
}

/* The circle sampler: all cocircular, ties everywhere for the R rules. */
static void test_brute_force_circle(void **state) {
  (void)state;
  geom_point p[9];
  sampler_rng g;
  sampler_seed(&g, 5, 5);
  assert_int_equal(sampler_circle(&g, 9, p), 0);
  for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++)
    for (int j = 0; j < JOINT_COUNT; j++) tgot_check_bf(p, 9, m, (joint_id)j);
}

/* ---- known minimum-weight triangulations ---- */

static double tgot_perimeter(const geom_point *p, size_t n) {
  double s = 0;
  for (size_t q = 0; q < n; q++) s += geom_dist(p[q], p[(q + 1) % n]);
  return s;
}

static void tgot_check_p1(const geom_point *p, size_t n, double diagonals) {
  rule r = tgot_rule(MEASURE_P, JOINT_SUM);
  got_result res;
  tgot_solve(p, n, &r, 1, &res);
  double want = tgot_perimeter(p, n) + 2 * diagonals;
  assert_true(fabs(res.total - want) <= 1e-12 * want);
  assert_true(res.unique);
  got_result_free(&res);
}

static void test_p1_minimum_weight(void **state) {
  (void)state;
  /* A long thin hexagon, h = 0.05:
  **   p0 (0,0), p1 (1,-h), p2 (3,-h), p3 (4,0), p4 (2.8,h), p5 (1.1,h).
  ** Every diagonal at p0 (to p2, p3, p4) or at p3 (to p0, p1, p5) is
  ** longer than 2.7, while a triangulation avoiding them has the ears
  ** p5 p0 p1 and p2 p3 p4, hence the rungs p1p5 and p2p4 (about 2h each),
  ** plus a diagonal of the quadrilateral p1 p2 p4 p5: p1p4 = |(1.8, 2h)|
  ** beats p2p5 = |(1.9, 2h)|.  Its three diagonals total about 2.0 < 2.7,
  ** so the minimum is perimeter + 2 (|p1p5| + |p2p4| + |p1p4|). */
  const double h = 0.05;
  geom_point hex[6] = {{0, 0}, {1, -h}, {3, -h}, {4, 0}, {2.8, h}, {1.1, h}};
  tgot_check_p1(hex, 6, geom_dist(hex[1], hex[5]) + geom_dist(hex[2], hex[4]) +
                        geom_dist(hex[1], hex[4]));

  /* A regular hexagon (unit circumradius) with vertices 1, 3, 5 pushed
  ** out by 1%.  In the regular hexagon a triangulation has 3 diagonals,
  ** each short (sqrt 3) or long (2); only the two "inner triangles" 0-2-4
  ** and 1-3-5 use three short ones (3 sqrt 3 = 5.196 against at least
  ** 2 sqrt 3 + 2 = 5.464).  Pushing 1, 3, 5 out lengthens 1-3-5 and leaves
  ** 0-2-4 alone, and moves every total by O(1%), less than the 0.27 gap:
  ** the minimum is perimeter + 2 * 3 sqrt 3 exactly (in real arithmetic). */
  geom_point reg[6];
  for (int q = 0; q < 6; q++) {
    double a = q * M_PI / 3, s = q % 2 ? 1.01 : 1.0;
    reg[q] = (geom_point){s * cos(a), s * sin(a)};
  }
  tgot_check_p1(reg, 6, geom_dist(reg[0], reg[2]) + geom_dist(reg[2], reg[4]) +
                        geom_dist(reg[4], reg[0]));

  /* A quadrilateral: the shorter diagonal (the thesis's P_1 flip rule). */
  geom_point quad[4] = {{0, 0}, {10, 0}, {9, 1}, {2, 1}};
  tgot_check_p1(quad, 4, fmin(geom_dist(quad[0], quad[2]), geom_dist(quad[1], quad[3])));
}

/* ---- Delaunay ---- */

static double tgot_total(const got_triangle *t, size_t ntri, const geom_point *p, int m,
                         joint_id jt) {
  int s = (int)measure_get(m)->sign;
  double v = 0;
  for (size_t q = 0; q < ntri; q++) {
    geom_tri tr;
    geom_tri_make(&tr, p[t[q].i], p[t[q].k], p[t[q].j]);
    double b = measure_eval(m, &tr);
    v = q ? joint_apply(jt, s, v, b) : b;
  }
  return v;
}

static void test_delaunay_rules(void **state) {
  (void)state;
  static const struct { int m; joint_id j; } eq[] = {
    {MEASURE_R, JOINT_SUM}, {MEASURE_R, JOINT_RSS}, {MEASURE_R, JOINT_PRODUCT},
    {MEASURE_R, JOINT_HARMONIC}, {MEASURE_NEG_R, JOINT_SUM}, {MEASURE_ABC, JOINT_SUM},
    {MEASURE_NEG_R_OVER_R, JOINT_SUM}, {MEASURE_NEG_R2_OVER_A, JOINT_PRODUCT},
  };
  enum { N = 40 };
  geom_point p[N];
  got_triangle dt[N];
  for (int s = 0; s < 8; s++) {
    size_t n = s < 4 ? 12 : N;
    tgot_polygon(500 + (uint64_t)s, n, p);
    int unique = 0;
    assert_int_equal(got_delaunay(p, n, dt, &unique), 0);
    assert_true(unique);
    /* empty circumcircles, exactly */
    for (size_t q = 0; q + 2 < n; q++)
      for (size_t v = 0; v < n; v++)
        assert_true(geom_incircle(p[dt[q].i], p[dt[q].k], p[dt[q].j], p[v]) <= 0);
    for (size_t e = 0; e < sizeof eq / sizeof eq[0]; e++) {
      rule r = tgot_rule(eq[e].m, eq[e].j);
      got_result res;
      tgot_solve(p, n, &r, 2, &res);
      got_diff d;
      assert_int_equal(got_compare(res.tri, dt, n, &d), 0);
      if (d.triangles_common != n - 2 || d.diagonals_differ != 0)
        fail_msg("GOT(%s) differs from DT on %zu of %zu diagonals (n = %zu)", r.name,
                 d.diagonals_differ, d.diagonals, n);
      got_result_free(&res);
    }
    static const struct { int m; joint_id j; } val[] = {
      {MEASURE_NEG_ALPHA, JOINT_MAX}, {MEASURE_R, JOINT_MAX}};
    for (size_t e = 0; e < 2; e++) {
      rule r = tgot_rule(val[e].m, val[e].j);
      got_result res;
      tgot_solve(p, n, &r, 1, &res);
      double vdt = tgot_total(dt, n - 2, p, val[e].m, val[e].j);
      if (!tgot_close(vdt, res.total, fabs(res.total)))
        fail_msg("%s: DT value %.17g, GOT %.17g", r.name, vdt, res.total);
      got_result_free(&res);
    }
  }
}

/* Cocircular integer points (radius 5): exact ties, DT not unique. */
static void test_delaunay_cocircular(void **state) {
  (void)state;
  geom_point p[8] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-4, 3}, {-5, 0}, {-3, -4}, {4, -3}};
  got_triangle dt[8];
  int unique = 1;
  assert_int_equal(got_delaunay(p, 8, dt, &unique), 0);
  assert_false(unique);
  for (size_t q = 0; q < 6; q++)
    for (size_t v = 0; v < 8; v++)
      assert_true(geom_incircle(p[dt[q].i], p[dt[q].k], p[dt[q].j], p[v]) <= 0);
  got_diff d;
  assert_int_equal(got_compare(dt, dt, 8, &d), 0);
  assert_int_equal(d.triangles_common, 6);
  assert_int_equal(d.diagonals_differ, 0);
}

/* ---- invariance, determinism, limits ---- */

static void test_rotation_reversal(void **state) {
  (void)state;
  enum { N = 13 };
  geom_point p[N], q[N];
  tgot_polygon(77, N, p);
  for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++)
    for (int j = 0; j < JOINT_COUNT; j++) {
      rule r = tgot_rule(m, (joint_id)j);
      got_result base, other;
      tgot_solve(p, N, &r, 1, &base);
      for (int variant = 0; variant < 3; variant++) {
        size_t rot = variant == 0 ? 5 : variant == 1 ? 11 : 3;
        for (size_t v = 0; v < N; v++) q[v] = p[(v + rot) % N];
        if (variant == 2) {   /* reversed: clockwise, normalised as the CLI does */
          for (size_t v = 0; v < N; v++) q[v] = p[(N - v + rot) % N];
          int rev = 0;
          assert_int_equal(geom_polygon_check(q, N, NULL, &rev), GEOM_OK);
          assert_true(rev);
        }
        tgot_solve(q, N, &r, 1, &other);
        if (!tgot_close(base.total, other.total, fabs(base.total)))
          fail_msg("%s variant %d: %.17g vs %.17g", r.name, variant, base.total, other.total);
        got_result_free(&other);
      }
      got_result_free(&base);
    }
}

static void test_threads_bit_identical(void **state) {
  (void)state;
  enum { N = 300 };
  static geom_point p[N];
  tgot_polygon(9, N, p);
  static const char *const names[] = {"P_1", "sigma_2", "abc_0", "-alpha_inf", "R_-1", "-c_-inf"};
  for (size_t e = 0; e < sizeof names / sizeof names[0]; e++) {
    rule r;
    char err[256];
    assert_int_equal(rule_parse(names[e], &r, err, sizeof err), 0);
    got_result a, b;
    tgot_solve(p, N, &r, 1, &a);
    tgot_solve(p, N, &r, 2, &b);
    assert_memory_equal(&a.key, &b.key, sizeof a.key);
    assert_memory_equal(&a.key2, &b.key2, sizeof a.key2);
    assert_int_equal(a.ntri, b.ntri);
    for (size_t q = 0; q < a.ntri; q++) {
      assert_true(a.tri[q].i == b.tri[q].i && a.tri[q].k == b.tri[q].k && a.tri[q].j == b.tri[q].j);
      assert_memory_equal(&a.tri[q].badness, &b.tri[q].badness, sizeof(double));
    }
    got_result_free(&a);
    got_result_free(&b);
  }
}

static void test_limits(void **state) {
  (void)state;
  char err[256];
  assert_int_equal(got_check_memory(1000, MEASURE_P, err, sizeof err), 0);
  assert_int_equal(got_check_memory((size_t)1 << 22, MEASURE_P, err, sizeof err), -1);
  assert_non_null(strstr(err, "GB"));
  assert_int_equal(got_check_memory(1000000000, MEASURE_P, err, sizeof err), -1);
  assert_non_null(strstr(err, "too large"));
  assert_true(got_memory_needed(2000, MEASURE_SIGMA) > got_memory_needed(2000, MEASURE_NEG_AREA));
  /* at least its Theta(n^2) tables: keys and pair tables, argmin, and the
  ** n^2-byte table of valid diagonals of a simple polygon (once left out) */
  for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++) {
    size_t n = 1000, k = 1 + (size_t)got_kernel_tables(m);
    assert_true(got_memory_needed(n, m) >= n * n * 8 * k + n * (n - 1) / 2 * 4 + n * n);
  }

  geom_point p[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  rule dt = rule_delaunay();
  got_result res;
  got_options o = {1, RULE_DEFAULT_TIE_EPS};
  assert_int_equal(got_solve(p, 4, &dt, &o, &res, err, sizeof err), -1);
  assert_non_null(strstr(err, "triangle-based"));
  rule r = tgot_rule(MEASURE_P, JOINT_SUM);
  assert_int_equal(got_solve(p, 2, &r, &o, &res, err, sizeof err), -1);
  /* n = 3: one triangle, no runner-up */
  assert_int_equal(got_solve(p, 3, &r, &o, &res, err, sizeof err), 0);
  assert_int_equal(res.ntri, 1);
  assert_false(res.has_runner_up);
  assert_true(res.unique);
  got_result_free(&res);
  /* the unit square: both diagonals equal, P_1 ties exactly */
  assert_int_equal(got_solve(p, 4, &r, &o, &res, err, sizeof err), 0);
  assert_false(res.unique);
  got_result_free(&res);
}

/* A user measure (no kernel) goes through measure_eval: same optimum as the
** built-in it copies, on several threads (measure functions are reentrant
** by contract), bit-identical to one thread. */
static double tgot_user_p(const geom_tri *t, void *ctx) {
  (void)ctx;
  return t->a + t->b + t->c;
}

static void test_user_measure_fallback(void **state) {
  (void)state;
  measure um = {"tgot_userP", "uP", "perimeter again", MEASURE_NONNEG, tgot_user_p, NULL};
  int id = measure_register(&um);
  assert_true(id >= MEASURE_BUILTIN_COUNT);
  assert_false(got_measure_has_kernel(id));
  geom_point p[60];
  tgot_polygon(4, 60, p);
  rule ru = tgot_rule(id, JOINT_SUM), rb = tgot_rule(MEASURE_P, JOINT_SUM);
  got_result a, a1, b;
  tgot_solve(p, 60, &ru, 2, &a);
  tgot_solve(p, 60, &ru, 1, &a1);
  tgot_solve(p, 60, &rb, 2, &b);
  assert_true(tgot_close(a.total, b.total, b.total));
  assert_int_equal(a.threads, 2);
  assert_memory_equal(&a.key, &a1.key, sizeof a.key);
  assert_int_equal(a.ntri, a1.ntri);
  for (size_t q = 0; q < a.ntri; q++) {   /* field by field: the struct has padding */
    assert_int_equal(a.tri[q].i, a1.tri[q].i);
    assert_int_equal(a.tri[q].k, a1.tri[q].k);
    assert_int_equal(a.tri[q].j, a1.tri[q].j);
    assert_memory_equal(&a.tri[q].badness, &a1.tri[q].badness, sizeof(double));
  }
  got_result_free(&a);
  got_result_free(&a1);
  got_result_free(&b);
  measure_unregister_user();
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_kernels_match_measure_eval),
    cmocka_unit_test(test_bulk_log),
    cmocka_unit_test(test_brute_force_all_rules),
    cmocka_unit_test(test_brute_force_circle),
    cmocka_unit_test(test_p1_minimum_weight),
    cmocka_unit_test(test_delaunay_rules),
    cmocka_unit_test(test_delaunay_cocircular),
    cmocka_unit_test(test_rotation_reversal),
    cmocka_unit_test(test_threads_bit_identical),
    cmocka_unit_test(test_limits),
    cmocka_unit_test(test_user_measure_fallback),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
