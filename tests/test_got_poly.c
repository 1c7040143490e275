/*
** test_got_poly.c: GOT of simple (non-convex) polygons: exact validation,
** the valid diagonals against an independent O(n^3) oracle, the masked
** programme against brute force over every triangulation (every measure and
** joint), and convex input giving the convex path's results bit for bit.
*/
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "geom.h"
#include "measure.h"
#include "joint.h"
#include "rule.h"
#include "got.h"
#include "got_internal.h"
#include "sampler.h"
#include "testutil.h"

#define TP_MAXN 12
#define TP_REL 1e-9

/* ---- validation ---- */

static geom_polyerr tp_check(const double *xy, size_t n, size_t *b1, size_t *b2, int *rev) {
  geom_point p[32];
  for (size_t i = 0; i < n; i++) p[i] = (geom_point){xy[2 * i], xy[2 * i + 1]};
  return geom_simple_polygon_check(p, n, b1, b2, rev);
}

static void test_validation(void **state) {
  (void)state;
  size_t b1, b2;
  int rev;
  const double square[] = {0, 0, 1, 0, 1, 1, 0, 1};
  assert_int_equal(tp_check(square, 4, &b1, &b2, &rev), GEOM_OK);
  assert_int_equal(rev, 0);
  const double cw[] = {0, 0, 0, 1, 1, 1, 1, 0};
  assert_int_equal(tp_check(cw, 4, &b1, &b2, &rev), GEOM_OK);
  assert_int_equal(rev, 1);
  /* bow tie: edges 0 (0-1) and 2 (2-3) cross */
  const double bow[] = {0, 0, 1, 1, 1, 0, 0, 1};
  assert_int_equal(tp_check(bow, 4, &b1, &b2, &rev), GEOM_CROSSING);
  assert_int_equal(b1, 0);
  assert_int_equal(b2, 2);
  /* vertex 4 touches edge 1-2 (x = 2) without crossing */
  const double touch[] = {0, 0, 2, 0, 2, 2, 1, 2, 2, 1, 0, 2};
  assert_int_equal(tp_check(touch, 6, &b1, &b2, &rev), GEOM_CROSSING);
  assert_true((b1 == 1 && (b2 == 3 || b2 == 4)));
  /* repeated vertex */
  const double rep[] = {0, 0, 2, 0, 1, 1, 2, 2, 1, 1, 0, 2};
  assert_int_equal(tp_check(rep, 6, &b1, &b2, &rev), GEOM_DUPLICATE);
  /* a spike folding back onto its own edge, and a flat triangle */
  const double spike[] = {0, 0, 2, 0, 1, 0, 1, 1};
  assert_int_equal(tp_check(spike, 4, &b1, &b2, &rev), GEOM_CROSSING);
  const double flat[] = {0, 0, 1, 1, 2, 2};
  assert_int_equal(tp_check(flat, 3, &b1, &b2, &rev), GEOM_CROSSING);
  /* collinear consecutive vertices are fine */
  const double run[] = {0, 0, 1, 0, 2, 0, 3, 0, 3, 1, 0, 1};
  assert_int_equal(tp_check(run, 6, &b1, &b2, &rev), GEOM_OK);
  /* overlapping non-adjacent collinear edges */
  const double overlap[] = {0, 0, 4, 0, 4, 2, 3, 2, 3, 0, 1, 0, 1, 2, 0, 2};
  assert_int_equal(tp_check(overlap, 8, &b1, &b2, &rev), GEOM_CROSSING);
  assert_int_equal(b1, 0);
}

/* ---- the oracle for valid diagonals: O(n) exact tests per pair ---- */

static int tp_between(geom_point a, geom_point b, geom_point c) {
  double lx = fmin(a.x, b.x), hx = fmax(a.x, b.x), ly = fmin(a.y, b.y), hy = fmax(a.y, b.y);
  return c.x >= lx && c.x <= hx && c.y >= ly && c.y <= hy;
}

/* Direction p_j leaves p_i into its open interior cone (anticlockwise). */
static int tp_in_cone(const geom_point *p, size_t n, size_t i, size_t j) {
  geom_point a = p[i], nx = p[(i + 1) % n], pv = p[(i + n - 1) % n], d = p[j];
  if (geom_orient(pv, a, nx) > 0) return geom_orient(a, nx, d) > 0 && geom_orient(a, d, pv) > 0;
  return !(geom_orient(a, pv, d) >= 0 && geom_orient(a, d, nx) >= 0);
}

static int tp_valid(const geom_point *p, size_t n, size_t i, size_t j) {
  if (i == j) return 0;
  if ((i + 1) % n == j || (j + 1) % n == i) return 1;
  if (!tp_in_cone(p, n, i, j)) return 0;
  for (size_t k = 0; k < n; k++)
    if (k != i && k != j && geom_orient(p[i], p[j], p[k]) == 0 && tp_between(p[i], p[j], p[k]))
      return 0;
  for (size_t e = 0; e < n; e++) {
    size_t f = (e + 1) % n;
    if (e == i || e == j || f == i || f == j) continue;
    if (geom_segments_meet(p[i], p[j], p[e], p[f])) return 0;
  }
  return 1;
}

static void tp_check_diagonals(const geom_point *p, size_t n, int threads) {
  unsigned char *V = malloc(n * n);
  assert_int_equal(got_valid_diagonals(p, n, V, threads), 0);
  for (size_t i = 0; i < n; i++)
    for (size_t j = 0; j < n; j++)
      if (V[i * n + j] != tp_valid(p, n, i, j))
        fail_msg("n=%zu: diagonal %zu-%zu: sweep %d, oracle %d", n, i, j, V[i * n + j],
                 tp_valid(p, n, i, j));
  free(V);
}

/* Random polygons on a small integer grid: star-shaped around the centre
** from points sorted by angle, kept when exactly simple.  Lots of collinear
** triples, equal directions and grazing contacts. */
static size_t tp_grid_polygon(testutil_rng *g, size_t want, geom_point *p) {
  for (;;) {
    size_t n = 0;
    while (n < want) {
      geom_point q = {(double)(testutil_next(g) % 9) - 4, (double)(testutil_next(g) % 9) - 4};
      if (q.x == 0 && q.y == 0) continue;
      p[n++] = q;
    }
    for (size_t a = 1; a < n; a++)       /* insertion sort by atan2 (ties by radius) */
      for (size_t b = a; b > 0; b--) {
        double ta = atan2(p[b].y, p[b].x), tb = atan2(p[b - 1].y, p[b - 1].x);
        if (ta < tb || (ta == tb && hypot(p[b].x, p[b].y) < hypot(p[b - 1].x, p[b - 1].y))) {
          geom_point t = p[b];
          p[b] = p[b - 1];
          p[b - 1] = t;
        }
      }
    geom_point c[TP_MAXN * 4];
    memcpy(c, p, n * sizeof *p);
    int rev;
    if (geom_simple_polygon_check(c, n, NULL, NULL, &rev) == GEOM_OK) {
      memcpy(p, c, n * sizeof *p);
      return n;
    }
  }
}

/* Arbitrary simple polygons: random points untangled by 2-opt moves (a
** crossing pair of edges is replaced by the two other ways of joining
** their ends, which shortens the tour), on a coarse grid so that
** collinear triples occur, or with random coordinates.  Not star-shaped in
** general: spirals and lobes that wrap around a reflex vertex appear. */
static size_t tp_twoopt_polygon(testutil_rng *g, size_t n, int grid, geom_point *p) {
  for (;;) {
    for (size_t i = 0; i < n; i++)
      p[i] = grid ? (geom_point){(double)(testutil_next(g) % 13), (double)(testutil_next(g) % 13)}
                  : (geom_point){testutil_uniform(g), testutil_uniform(g)};
    int moved = 1;
    for (int it = 0; it < 2000 && moved; it++) {
      moved = 0;
      for (size_t e = 0; e < n && !moved; e++)
        for (size_t f = e + 2; f < n && !moved; f++) {
          if (e == 0 && f == n - 1) continue;
          if (geom_segments_meet(p[e], p[e + 1], p[f], p[(f + 1) % n])) {
            for (size_t a = e + 1, b = f; a < b; a++, b--) {   /* reverse e+1..f */
              geom_point tmp = p[a];
              p[a] = p[b];
              p[b] = tmp;
            }
            moved = 1;
          }
        }
    }
    geom_point c[64];
    memcpy(c, p, n * sizeof *p);
    int rev;
    if (geom_simple_polygon_check(c, n, NULL, NULL, &rev) == GEOM_OK) {
      memcpy(p, c, n * sizeof *p);
      return n;
    }
  }
}

static void test_diagonals_twoopt(void **state) {
  (void)state;
  testutil_rng g = {4242};
  geom_point p[64];
  for (int t = 0; t < testutil_reps(300); t++) {
    size_t n = 5 + (size_t)t % 20;
    tp_twoopt_polygon(&g, n, t % 2, p);
    tp_check_diagonals(p, n, 1);
  }
}

static void test_diagonals_oracle(void **state) {
  (void)state;
  testutil_rng g = {12345};
  geom_point p[64];
  for (int t = 0; t < 300; t++) {
    size_t n = tp_grid_polygon(&g, 4 + (size_t)t % 12, p);
    tp_check_diagonals(p, n, 1 + t % 2);
  }
  sampler_rng s;
  sampler_seed(&s, 7, 1);
  for (int t = 0; t < 20; t++) {
    assert_int_equal(sampler_star(&s, 40, p), 0);
    tp_check_diagonals(p, 40, 2);
    assert_int_equal(sampler_monotone(&s, 40, p), 0);
    tp_check_diagonals(p, 40, 2);
  }
}

/* Hand-made cases: a diagonal grazing a reflex vertex, one along an edge
** line, one outside; a polygon with a single triangulation. */
static void test_diagonals_hand(void **state) {
  (void)state;
  /* 0:(0,0) 1:(4,0) 2:(4,4) 3:(2,2) reflex 4:(0,4).  0-2 passes through
  ** the reflex vertex 3 (grazing): invalid; 1-4 crosses outside (through
  ** the notch): invalid; 1-3 and 0-3 valid. */
  geom_point a[5] = {{0, 0}, {4, 0}, {4, 4}, {2, 2}, {0, 4}};
  unsigned char V[25];
  assert_int_equal(got_valid_diagonals(a, 5, V, 1), 0);
  assert_int_equal(V[0 * 5 + 2], 0);
  assert_int_equal(V[1 * 5 + 4], 0);
  assert_int_equal(V[1 * 5 + 3], 1);
  assert_int_equal(V[0 * 5 + 3], 1);
  /* collinear run along the bottom: 0-2 runs along edges 0-1, 1-2 */
  geom_point b[5] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {0, 1}};
  assert_int_equal(got_valid_diagonals(b, 5, V, 1), 0);
  assert_int_equal(V[0 * 5 + 2], 0);
  assert_int_equal(V[1 * 5 + 3], 1);
  assert_int_equal(V[1 * 5 + 4], 1);
  tp_check_diagonals(a, 5, 1);
  tp_check_diagonals(b, 5, 1);
}

/* ---- brute force over every triangulation ---- */

typedef struct tp_bf {
  const geom_point *p;
  size_t n;
  int measure, sign;
  joint_id joint;
  unsigned char V[TP_MAXN * TP_MAXN];
} tp_bf;

/* All totals of the triangulations of chain (i, j) into out (count back). */
static size_t tp_totals(const tp_bf *b, size_t i, size_t j, double *out, size_t cap) {
  size_t m = 0;
  for (size_t k = i + 1; k < j; k++) {
    if (!b->V[i * b->n + k] || !b->V[k * b->n + j]) continue;
    geom_tri t;
    geom_tri_make(&t, b->p[i], b->p[k], b->p[j]);
    double tk = measure_eval(b->measure, &t);
    double *L = malloc(cap * sizeof *L), *R = malloc(cap * sizeof *R);
    size_t nl = k > i + 1 ? tp_totals(b, i, k, L, cap) : 1, nr = j > k + 1 ? tp_totals(b, k, j, R, cap) : 1;
    for (size_t x = 0; x < nl; x++)
      for (size_t y = 0; y < nr; y++) {
        double v = tk;
        if (k > i + 1) v = joint_apply(b->joint, b->sign, L[x], v);
        if (j > k + 1) v = joint_apply(b->joint, b->sign, v, R[y]);
        assert_true(m < cap);
        out[m++] = v;
      }
    free(L);
    free(R);
  }
  return m;
}

static int tp_cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* Same triangles, same badness bits (fields: the struct has padding). */
static int tp_same_tris(const got_result *a, const got_result *b) {
  if (a->ntri != b->ntri) return 0;
  for (size_t q = 0; q < a->ntri; q++) {
    const got_triangle *x = &a->tri[q], *y = &b->tri[q];
    if (x->i != y->i || x->k != y->k || x->j != y->j ||
        memcmp(&x->badness, &y->badness, sizeof x->badness) != 0)
      return 0;
  }
  return 1;
}

static int tp_close(double a, double b, double scale) {
  return a == b || fabs(a - b) <= TP_REL * scale;
}

static void tp_check_bf(const geom_point *p, size_t n, int m, joint_id jt) {
  rule r;
  char err[256];
  if (rule_triangle(m, jt, &r, err, sizeof err) != 0) return;   /* sign-incompatible */
  tp_bf *b = calloc(1, sizeof *b);
  b->p = p;
  b->n = n;
  b->measure = m;
  b->joint = jt;
  b->sign = (int)measure_get(m)->sign;
  assert_int_equal(got_valid_diagonals(p, n, b->V, 1), 0);
  size_t cap = 20000;
  double *v = malloc(cap * sizeof *v);
  size_t cnt = tp_totals(b, 0, n - 1, v, cap);
  assert_true(cnt >= 1);
  qsort(v, cnt, sizeof *v, tp_cmp);
  got_result res;
  got_options o = {1, RULE_DEFAULT_TIE_EPS};
  if (got_solve(p, n, &r, &o, &res, err, sizeof err) != 0) fail_msg("got_solve: %s", err);
  double best = v[0];
  if (!tp_close(res.total, best, fabs(best)))
    fail_msg("%s n=%zu: DP %.17g, brute force %.17g", r.name, n, res.total, best);
  double again = res.tri[0].badness;
  for (size_t q = 1; q < res.ntri; q++) again = joint_apply(jt, b->sign, again, res.tri[q].badness);
  if (!tp_close(again, best, fabs(best)))
    fail_msg("%s n=%zu: DP triangles total %.17g, optimum %.17g", r.name, n, again, best);
  for (size_t q = 0; q < res.ntri; q++) {   /* every triangle uses valid sides */
    size_t i = (size_t)res.tri[q].i, k = (size_t)res.tri[q].k, j = (size_t)res.tri[q].j;
    assert_true(b->V[i * n + k] && b->V[k * n + j] && b->V[i * n + j]);
  }
  assert_int_equal(res.has_runner_up, cnt > 1);
  if (cnt > 1) {
    double second = v[1], scale = fmax(fabs(best), fabs(second));
    double gap_bf = second - best, gap = res.total2 - res.total;
    if (!(tp_close(gap, gap_bf, scale) || (isinf(gap_bf) && isinf(gap))))
      fail_msg("%s n=%zu: runner-up gap DP %.17g, brute force %.17g (best %.17g)", r.name, n,
               gap, gap_bf, best);
  }
  got_result_free(&res);
  free(v);
  free(b);
}

static void tp_check_all_rules(const geom_point *p, size_t n) {
  for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++)
    for (int j = 0; j < JOINT_COUNT; j++) tp_check_bf(p, n, m, (joint_id)j);
}

static void test_brute_force_star(void **state) {
  (void)state;
  sampler_rng s;
  sampler_seed(&s, 99, 2);
  geom_point p[TP_MAXN];
  for (size_t n = 4; n <= 10; n++)
    for (int t = 0; t < (n <= 8 ? 3 : 1); t++) {
      assert_int_equal(t % 2 ? sampler_monotone(&s, n, p) : sampler_star(&s, n, p), 0);
      tp_check_all_rules(p, n);
    }
}

static void test_brute_force_hand(void **state) {
  (void)state;
  /* reflex notch, a collinear run, and a comb with one triangulation */
  geom_point a[5] = {{0, 0}, {4, 0}, {4, 4}, {2, 2}, {0, 4}};
  geom_point b[7] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 2}, {1.5, 0.5}, {0, 2}};
  geom_point c[6] = {{0, 0}, {6, 0}, {5, 1}, {4, 0.2}, {3, 1}, {2, 0.2}};
  tp_check_all_rules(a, 5);
  tp_check_all_rules(b, 7);
  tp_check_all_rules(c, 6);
  testutil_rng g = {777};
  geom_point q[64];
  for (int t = 0; t < testutil_reps(20); t++) {
    size_t n = tp_grid_polygon(&g, 5 + (size_t)t % 5, q);
    tp_check_all_rules(q, n);
  }
}

/* A polygon whose only triangulation is forced: a collinear run of four
** vertices under an apex.  Every chord between two vertices of the run
** passes through another one, so only the fan from the apex remains (and
** no zero-area triangle may appear). */
static void test_single_triangulation(void **state) {
  (void)state;
  geom_point p[5] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {1.5, 1}};
  unsigned char V[25];
  assert_int_equal(got_valid_diagonals(p, 5, V, 1), 0);
  size_t diag = 0;
  for (size_t i = 0; i < 5; i++)
    for (size_t j = i + 2; j < 5; j++) diag += V[i * 5 + j] && !(i == 0 && j == 4);
  assert_int_equal(diag, 2);   /* n - 3: the triangulation is forced */
  assert_int_equal(V[1 * 5 + 4], 1);
  assert_int_equal(V[2 * 5 + 4], 1);
  rule r;
  char err[256];
  assert_int_equal(rule_parse("P_1", &r, err, sizeof err), 0);
  got_result res;
  got_options o = {1, RULE_DEFAULT_TIE_EPS};
  assert_int_equal(got_solve(p, 5, &r, &o, &res, err, sizeof err), 0);
  assert_false(res.has_runner_up);
  got_result_free(&res);
  for (size_t q = 0; q < res.ntri; q++) assert_true(res.tri[q].badness == res.tri[q].badness);
  tp_check_all_rules(p, 5);
}

/* ---- convex input: the masked programme gives the convex path's results
** bit for bit (convex input itself always takes the convex path) ---- */

static void test_convex_identical(void **state) {
  (void)state;
  sampler_rng s;
  sampler_seed(&s, 5, 3);
  geom_point p[60];
  for (int t = 0; t < 3; t++) {
    size_t n = 20 + 20 * (size_t)t;
    assert_int_equal(sampler_vector(&s, n, p), 0);
    for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++)
      for (int j = 0; j < JOINT_COUNT; j++) {
        rule r;
        char err[256];
        if (rule_triangle(m, (joint_id)j, &r, err, sizeof err) != 0) continue;
        got_result a, b;
        got_options o1 = {1, RULE_DEFAULT_TIE_EPS}, o2 = {2, RULE_DEFAULT_TIE_EPS};
        assert_int_equal(got_solve(p, n, &r, &o1, &a, err, sizeof err), 0);
        assert_int_equal(got_solve_ex(p, n, &r, &o2, 1, &b, err, sizeof err), 0);
        assert_false(a.simple);
        assert_true(b.simple);
        if (!tp_same_tris(&a, &b))
          fail_msg("%s n=%zu: convex and masked differ: %.17g %.17g", r.name, n, a.key, b.key);
        assert_true(a.key == b.key || (isnan(a.key) && isnan(b.key)));
        assert_true(a.key2 == b.key2 || (isnan(a.key2) && isnan(b.key2)));
        got_result_free(&a);
        got_result_free(&b);
      }
  }
}

/* Threads: the masked path is bit-identical too. */
static void test_simple_threads(void **state) {
  (void)state;
  sampler_rng s;
  sampler_seed(&s, 11, 4);
  geom_point p[200];
  assert_int_equal(sampler_star(&s, 200, p), 0);
  const char *rules[] = {"P_1", "sigma_2", "R_inf", "-alpha_-inf", "lambda_0"};
  for (size_t q = 0; q < sizeof rules / sizeof *rules; q++) {
    rule r;
    char err[256];
    assert_int_equal(rule_parse(rules[q], &r, err, sizeof err), 0);
    got_result a, b;
    got_options o1 = {1, RULE_DEFAULT_TIE_EPS}, o2 = {2, RULE_DEFAULT_TIE_EPS};
    assert_int_equal(got_solve(p, 200, &r, &o1, &a, err, sizeof err), 0);
    assert_int_equal(got_solve(p, 200, &r, &o2, &b, err, sizeof err), 0);
    assert_true(a.simple);
    if (a.key != b.key || !tp_same_tris(&a, &b))
      fail_msg("%s: threads 1 and 2 differ: %.17g %.17g", rules[q], a.key, b.key);
    assert_true(a.key == b.key);
    assert_true(a.key2 == b.key2);
    got_result_free(&a);
    got_result_free(&b);
  }
}

static void test_solve_refuses(void **state) {
  (void)state;
  geom_point bow[4] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  geom_point cw[4] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  rule r;
  char err[256];
  assert_int_equal(rule_parse("P_1", &r, err, sizeof err), 0);
  got_result res;
  assert_int_equal(got_solve(bow, 4, &r, NULL, &res, err, sizeof err), -1);
  assert_non_null(strstr(err, "edges 0-1 and 2-3"));
  assert_int_equal(got_solve(cw, 4, &r, NULL, &res, err, sizeof err), -1);
  assert_non_null(strstr(err, "clockwise"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_validation),
    cmocka_unit_test(test_diagonals_hand),
    cmocka_unit_test(test_diagonals_oracle),
    cmocka_unit_test(test_diagonals_twoopt),
    cmocka_unit_test(test_single_triangulation),
    cmocka_unit_test(test_brute_force_hand),
    cmocka_unit_test(test_brute_force_star),
    cmocka_unit_test(test_convex_identical),
    cmocka_unit_test(test_simple_threads),
    cmocka_unit_test(test_solve_refuses),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
