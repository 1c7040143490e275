/*
** test_got_cert.c: the certified verdict of `got` (got/got_cert.c).
**
** Exact ties (a square and a regular hexagon with exactly symmetric
** coordinates, under P_1 and other rules) must give "tie not excluded";
** well-separated random polygons "unique optimum"; and on small polygons
** the enclosures must hold against exact values: GMP rationals (mpq) for
** the rational measures (Pinf, Rinf, -A and their square and reciprocal
** keys), MPFR at 400 bits for the irrational ones (lengths, angles, sigma^2;
** a 400-bit evaluation is within 2^-390 relative, far below any bound
** tested).  For every triangulation T of the polygon: the returned one's
** exact key lies in [key - cert_err, key + cert_err], and every other's is
** at least key2 - cert_err2.  The same for the faces of a point set
** (got_face_solve, got/got_face.c): convex polygons with points inside,
** every triangulation enumerated (siteflip), exact totals in GMP rationals.
*/
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <gmp.h>
#include <mpfr.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "geom.h"
#include "measure.h"
#include "joint.h"
#include "rule.h"
#include "got.h"
#include "got_face.h"
#include "sampler.h"
#include "siteflip.h"

#define TC_PREC 400
#define TC_MAXN 9
#define TC_MAXT 2000

static void tc_solve(const geom_point *p, size_t n, const char *rname, got_result *res) {
  rule r;
  char err[256];
  assert_int_equal(rule_parse(rname, &r, err, sizeof err), 0);
  got_options o = {1, RULE_DEFAULT_TIE_EPS};
  if (got_solve(p, n, &r, &o, res, err, sizeof err) != 0) fail_msg("%s: %s", rname, err);
}

/* ---- verdicts ---- */

static void tc_expect(const geom_point *p, size_t n, const char *rname, int unique) {
  got_result res;
  tc_solve(p, n, rname, &res);
  if (res.cert_unique != unique)
    fail_msg("%s n=%zu: certified unique %d (gap %.3g, bound %.3g), want %d", rname, n,
             res.cert_unique, res.cert_gap, res.cert_bound, unique);
  got_result_free(&res);
}

static void test_exact_ties(void **state) {
  (void)state;
  geom_point sq[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const char *rules[] = {"P_1", "P_2", "P_inf", "a_1", "sigma_2", "gamma_inf", "-alpha_-inf",
                         "Pinf_1", "-A_1", "abc_1", "R_inf", "P_0"};
  for (size_t q = 0; q < sizeof rules / sizeof *rules; q++) tc_expect(sq, 4, rules[q], 0);
  /* regular hexagon, exactly symmetric under x -> -x and y -> -y; the two
  ** inner-triangle triangulations (P_1's optimum) are mirror images */
  double h = sqrt(3.0) / 2;
  geom_point hex[6] = {{1, 0}, {0.5, h}, {-0.5, h}, {-1, 0}, {-0.5, -h}, {0.5, -h}};
  for (size_t q = 0; q < sizeof rules / sizeof *rules; q++) tc_expect(hex, 6, rules[q], 0);
  got_result res;
  tc_solve(hex, 6, "P_1", &res);
  assert_true(res.cert_gap == 0 || res.cert_gap <= res.cert_bound);
  got_result_free(&res);
}

static void test_separated_unique(void **state) {
  (void)state;
  sampler_rng s;
  sampler_seed(&s, 3, 9);
  geom_point p[300];
  for (int t = 0; t < 4; t++) {
    size_t n = 100 + 50 * (size_t)t;
    assert_int_equal(t % 2 ? sampler_vector(&s, n, p) : sampler_star(&s, n, p), 0);
    tc_expect(p, n, "P_1", 1);
    tc_expect(p, n, "sigma_2", 1);
    tc_expect(p, n, "P_2", 1);
    /* no error model: never "unique", whatever the gap */
    tc_expect(p, n, "lambda_1", 0);
    tc_expect(p, n, "P_0", 0);
  }
}

/* ---- enclosures against exact values ---- */

typedef struct tc_tri { int i, k, j; } tc_tri;

typedef struct tc_all {
  size_t count, len;
  tc_tri *t;            /* count lists of len triangles */
} tc_all;

/* Every triangulation of chain (i, j) over the valid diagonals V. */
static tc_all tc_enum(const unsigned char *V, size_t n, size_t i, size_t j) {
  tc_all out = {0, j - i - 1, NULL};
  if (j - i < 2) {
    out.count = 1;
    return out;
  }
  out.t = malloc(TC_MAXT * out.len * sizeof *out.t);
  for (size_t k = i + 1; k < j; k++) {
    if (!V[i * n + k] || !V[k * n + j]) continue;
    tc_all L = tc_enum(V, n, i, k), R = tc_enum(V, n, k, j);
    for (size_t x = 0; x < L.count; x++)
      for (size_t y = 0; y < R.count; y++) {
        assert_true(out.count < TC_MAXT);
        tc_tri *d = out.t + out.count * out.len;
        d[0] = (tc_tri){(int)i, (int)k, (int)j};
        if (L.len) memcpy(d + 1, L.t + x * L.len, L.len * sizeof *d);
        if (R.len) memcpy(d + 1 + L.len, R.t + y * R.len, R.len * sizeof *d);
        out.count++;
      }
    free(L.t);
    free(R.t);
  }
  return out;
}

/* Exact rational badness for Pinf, Rinf, -A; 0 on success, -1 otherwise. */
static int tc_value_q(int m, geom_point a, geom_point b, geom_point c, mpq_t v) {
  mpq_t x[3], y[3], t, u;
  geom_point P[3] = {a, b, c};
  for (int q = 0; q < 3; q++) {
    mpq_init(x[q]);
    mpq_init(y[q]);
    mpq_set_d(x[q], P[q].x);
    mpq_set_d(y[q], P[q].y);
  }
  mpq_init(t);
  mpq_init(u);
  int rc = 0;
  if (m == MEASURE_PINF || m == MEASURE_RINF) {
    mpq_t *X[2] = {x, y};
    mpq_t r[2];
    for (int d = 0; d < 2; d++) {
      mpq_init(r[d]);
      int lo = 0, hi = 0;
      for (int q = 1; q < 3; q++) {
        if (mpq_cmp(X[d][q], X[d][lo]) < 0) lo = q;
        if (mpq_cmp(X[d][q], X[d][hi]) > 0) hi = q;
      }
      mpq_sub(r[d], X[d][hi], X[d][lo]);
    }
    if (m == MEASURE_PINF) {
      mpq_add(v, r[0], r[1]);
      mpq_set_ui(t, 2, 1);
      mpq_mul(v, v, t);
    } else {
      mpq_set(v, mpq_cmp(r[0], r[1]) > 0 ? r[0] : r[1]);
      mpq_set_ui(t, 1, 2);
      mpq_mul(v, v, t);
    }
    mpq_clear(r[0]);
    mpq_clear(r[1]);
  } else if (m == MEASURE_NEG_AREA) {   /* -|cross| / 2 */
    mpq_sub(t, x[1], x[0]);
    mpq_sub(u, y[2], y[0]);
    mpq_mul(v, t, u);
    mpq_sub(t, y[1], y[0]);
    mpq_sub(u, x[2], x[0]);
    mpq_mul(t, t, u);
    mpq_sub(v, v, t);
    mpq_abs(v, v);
    mpq_set_si(t, -1, 2);
    mpq_mul(v, v, t);
  } else {
    rc = -1;
  }
  for (int q = 0; q < 3; q++) {
    mpq_clear(x[q]);
    mpq_clear(y[q]);
  }
  mpq_clear(t);
  mpq_clear(u);
  return rc;
}

/* High-precision badness for the length and angle measures. */
static int tc_value_f(int m, geom_point a, geom_point b, geom_point c, mpfr_t v) {
  geom_point P[3] = {a, b, c};
  mpfr_t L[3], th[3], dx, dy, t;
  mpfr_inits2(TC_PREC, dx, dy, t, (mpfr_ptr)0);
  for (int q = 0; q < 3; q++) {
    mpfr_inits2(TC_PREC, L[q], th[q], (mpfr_ptr)0);
    geom_point s = P[(q + 1) % 3], e = P[(q + 2) % 3];   /* side opposite q */
    mpfr_set_d(dx, e.x, MPFR_RNDN);
    mpfr_sub_d(dx, dx, s.x, MPFR_RNDN);
    mpfr_set_d(dy, e.y, MPFR_RNDN);
    mpfr_sub_d(dy, dy, s.y, MPFR_RNDN);
    mpfr_hypot(L[q], dx, dy, MPFR_RNDN);
  }
  for (int q = 0; q < 3; q++) {   /* angle at q: law of cosines */
    mpfr_t num;
    mpfr_init2(num, TC_PREC);
    mpfr_sqr(num, L[(q + 1) % 3], MPFR_RNDN);
    mpfr_sqr(t, L[(q + 2) % 3], MPFR_RNDN);
    mpfr_add(num, num, t, MPFR_RNDN);
    mpfr_sqr(t, L[q], MPFR_RNDN);
    mpfr_sub(num, num, t, MPFR_RNDN);
    mpfr_mul(t, L[(q + 1) % 3], L[(q + 2) % 3], MPFR_RNDN);
    mpfr_mul_ui(t, t, 2, MPFR_RNDN);
    mpfr_div(num, num, t, MPFR_RNDN);
    mpfr_acos(th[q], num, MPFR_RNDN);
    mpfr_clear(num);
  }
  /* sort lengths and angles ascending */
  for (int x = 0; x < 3; x++)
    for (int y = x + 1; y < 3; y++) {
      if (mpfr_cmp(L[y], L[x]) < 0) mpfr_swap(L[x], L[y]);
      if (mpfr_cmp(th[y], th[x]) < 0) mpfr_swap(th[x], th[y]);
    }
  int rc = 0;
  switch (m) {
    case MEASURE_A: mpfr_set(v, L[2], MPFR_RNDN); break;
    case MEASURE_NEG_C: mpfr_neg(v, L[0], MPFR_RNDN); break;
    case MEASURE_P: mpfr_add(v, L[0], L[1], MPFR_RNDN); mpfr_add(v, v, L[2], MPFR_RNDN); break;
    case MEASURE_ABC: mpfr_mul(v, L[0], L[1], MPFR_RNDN); mpfr_mul(v, v, L[2], MPFR_RNDN); break;
    case MEASURE_NEG_C_OVER_A: mpfr_div(v, L[0], L[2], MPFR_RNDN); mpfr_neg(v, v, MPFR_RNDN); break;
    case MEASURE_NEG_C_OVER_P:
      mpfr_add(t, L[0], L[1], MPFR_RNDN);
      mpfr_add(t, t, L[2], MPFR_RNDN);
      mpfr_div(v, L[0], t, MPFR_RNDN);
      mpfr_neg(v, v, MPFR_RNDN);
      break;
    case MEASURE_A_MINUS_C: mpfr_sub(v, L[2], L[0], MPFR_RNDN); break;
    case MEASURE_NEG_ALPHA: mpfr_neg(v, th[0], MPFR_RNDN); break;
    case MEASURE_BETA: mpfr_set(v, th[1], MPFR_RNDN); break;
    case MEASURE_GAMMA: mpfr_set(v, th[2], MPFR_RNDN); break;
    case MEASURE_SIGMA: {      /* sigma^2: the l_2 key */
      mpfr_t p3;
      mpfr_init2(p3, TC_PREC);
      mpfr_const_pi(p3, MPFR_RNDN);
      mpfr_div_ui(p3, p3, 3, MPFR_RNDN);
      mpfr_set_ui(v, 0, MPFR_RNDN);
      for (int q = 0; q < 3; q++) {
        mpfr_sub(t, th[q], p3, MPFR_RNDN);
        mpfr_sqr(t, t, MPFR_RNDN);
        mpfr_add(v, v, t, MPFR_RNDN);
      }
      mpfr_div_ui(v, v, 3, MPFR_RNDN);
      mpfr_clear(p3);
      break;
    }
    default: rc = -1;
  }
  for (int q = 0; q < 3; q++) mpfr_clears(L[q], th[q], (mpfr_ptr)0);
  mpfr_clears(dx, dy, t, (mpfr_ptr)0);
  return rc;
}

/* The exact key total of one triangulation (as mpfr at TC_PREC; for the
** rational measures computed in mpq first, then converted: comparisons
** below are made in mpq for those). */
typedef struct tc_ctx {
  const geom_point *p;
  int m, sign;
  joint_id jt;
  joint_keyop op;
  int rational;
} tc_ctx;

/* key(b) for the joint: identity, square (sign kept) or -1/b. */
static void tc_key_q(const tc_ctx *c, mpq_t b) {
  if (c->jt == JOINT_RSS) {
    int neg = mpq_sgn(b) < 0;
    mpq_mul(b, b, b);
    if (neg) mpq_neg(b, b);
  } else if (c->jt == JOINT_HARMONIC) {
    mpq_inv(b, b);
    mpq_neg(b, b);
  }
}

static void tc_key_f(const tc_ctx *c, mpfr_t b) {
  if (c->m == MEASURE_SIGMA) return;   /* tc_value_f gave sigma^2 */
  if (c->jt == JOINT_RSS) {
    int neg = mpfr_sgn(b) < 0;
    mpfr_sqr(b, b, MPFR_RNDN);
    if (neg) mpfr_neg(b, b, MPFR_RNDN);
  } else if (c->jt == JOINT_HARMONIC) {
    mpfr_ui_div(b, 1, b, MPFR_RNDN);
    mpfr_neg(b, b, MPFR_RNDN);
  }
}

static void tc_total_q(const tc_ctx *c, const tc_tri *t, size_t len, mpq_t tot) {
  mpq_t v;
  mpq_init(v);
  for (size_t q = 0; q < len; q++) {
    assert_int_equal(tc_value_q(c->m, c->p[t[q].i], c->p[t[q].k], c->p[t[q].j], v), 0);
    tc_key_q(c, v);
    if (q == 0) mpq_set(tot, v);
    else if (c->op == JOINT_KEY_ADD) mpq_add(tot, tot, v);
    else if ((c->op == JOINT_KEY_MIN) == (mpq_cmp(v, tot) < 0)) mpq_set(tot, v);
  }
  mpq_clear(v);
}

static void tc_total_f(const tc_ctx *c, const tc_tri *t, size_t len, mpfr_t tot) {
  mpfr_t v;
  mpfr_init2(v, TC_PREC);
  for (size_t q = 0; q < len; q++) {
    assert_int_equal(tc_value_f(c->m, c->p[t[q].i], c->p[t[q].k], c->p[t[q].j], v), 0);
    tc_key_f(c, v);
    if (q == 0) mpfr_set(tot, v, MPFR_RNDN);
    else if (c->op == JOINT_KEY_ADD) mpfr_add(tot, tot, v, MPFR_RNDN);
    else if ((c->op == JOINT_KEY_MIN) == (mpfr_cmp(v, tot) < 0)) mpfr_set(tot, v, MPFR_RNDN);
  }
  mpfr_clear(v);
}

/* sign of exact total - x (x a double). */
static int tc_cmp_total(const tc_ctx *c, const tc_tri *t, size_t len, double x) {
  if (c->rational) {
    mpq_t tot, d;
    mpq_inits(tot, d, NULL);
    tc_total_q(c, t, len, tot);
    mpq_set_d(d, x);
    int s = mpq_cmp(tot, d);
    mpq_clears(tot, d, NULL);
    return s;
  }
  mpfr_t tot;
  mpfr_init2(tot, TC_PREC);
  tc_total_f(c, t, len, tot);
  int s = mpfr_cmp_d(tot, x);
  mpfr_clear(tot);
  return s;
}

static int tc_same(const tc_tri *t, size_t len, const got_result *res) {
  for (size_t q = 0; q < len; q++) {
    int found = 0;
    for (size_t r = 0; r < res->ntri && !found; r++)
      found = res->tri[r].i == t[q].i && res->tri[r].k == t[q].k && res->tri[r].j == t[q].j;
    if (!found) return 0;
  }
  return 1;
}

static void tc_check_enclosure(const geom_point *p, size_t n, int m, joint_id jt, size_t *checked) {
  rule r;
  char err[256];
  if (rule_triangle(m, jt, &r, err, sizeof err) != 0) return;
  got_result res;
  got_options o = {1, RULE_DEFAULT_TIE_EPS};
  assert_int_equal(got_solve(p, n, &r, &o, &res, err, sizeof err), 0);
  if (!isfinite(res.cert_err)) {
    got_result_free(&res);
    return;
  }
  tc_ctx c = {p, m, (int)measure_get(m)->sign, jt, joint_get(jt)->keyop, 0};
  mpq_t probe;
  mpq_init(probe);
  c.rational = tc_value_q(m, p[0], p[1], p[2], probe) == 0;
  mpq_clear(probe);
  if (m == MEASURE_SIGMA && jt != JOINT_RSS) fail_msg("sigma certified with %s", r.name);
  unsigned char *V = malloc(n * n);
  assert_int_equal(got_valid_diagonals(p, n, V, 1), 0);
  tc_all all = tc_enum(V, n, 0, n - 1);
  size_t mine = 0;
  for (size_t x = 0; x < all.count; x++) {
    const tc_tri *t = all.t + x * all.len;
    if (tc_same(t, all.len, &res)) {
      mine++;
      if (tc_cmp_total(&c, t, all.len, res.key - res.cert_err) < 0 ||
          tc_cmp_total(&c, t, all.len, res.key + res.cert_err) > 0)
        fail_msg("%s n=%zu: exact optimum outside [%.17g +- %.3g]", r.name, n, res.key,
                 res.cert_err);
    } else if (res.has_runner_up && tc_cmp_total(&c, t, all.len, res.key2 - res.cert_err2) < 0) {
      fail_msg("%s n=%zu: a triangulation's exact key is below key2 - err2 = %.17g", r.name, n,
               res.key2 - res.cert_err2);
    }
  }
  assert_int_equal(mine, 1);
  (*checked)++;
  free(all.t);
  free(V);
  got_result_free(&res);
}

static void test_enclosures(void **state) {
  (void)state;
  sampler_rng s;
  sampler_seed(&s, 21, 5);
  geom_point p[TC_MAXN];
  size_t checked = 0;
  for (int t = 0; t < 6; t++) {
    size_t n = 5 + (size_t)t % 4;
    int rc = t % 3 == 0 ? sampler_vector(&s, n, p) : t % 3 == 1 ? sampler_star(&s, n, p)
                                                              : sampler_monotone(&s, n, p);
    assert_int_equal(rc, 0);
    for (int m = 0; m < MEASURE_BUILTIN_COUNT; m++)
      for (int j = 0; j < JOINT_COUNT; j++) tc_check_enclosure(p, n, m, (joint_id)j, &checked);
  }
  /* every certified family was exercised: 13 measures with error models */
  assert_true(checked >= 6 * 20);
}

/* ---- faces of point sets (got_face_solve) ---- */

/* The exact total of node u of g (or of the triangles tri[0..3m) when g is
** NULL) in mpq, for a rational measure m. */
static void tc_face_total(const geom_point *p, const siteflip_graph *g, int u,
                          const uint32_t *tri, size_t nt, int m, mpq_t sum) {
  mpq_t v;
  mpq_init(v);
  mpq_set_ui(sum, 0, 1);
  size_t count = g ? (size_t)g->per : nt;
  for (size_t t = 0; t < count; t++) {
    const unsigned char *tv = g ? g->tri_v[g->node_tri[(size_t)u * (size_t)g->per + t]] : NULL;
    uint32_t a = g ? tv[0] : tri[3 * t], b = g ? tv[1] : tri[3 * t + 1];
    uint32_t c = g ? tv[2] : tri[3 * t + 2];
    assert_int_equal(tc_value_q(m, p[a], p[b], p[c], v), 0);
    mpq_add(sum, sum, v);
  }
  mpq_clear(v);
}

/* 1 when node u holds every edge of the triangles tri[0..3nt). */
static int tc_face_is(const siteflip_graph *g, int u, const uint32_t *tri, size_t nt) {
  for (size_t t = 0; t < nt; t++)
    for (int e = 0; e < 3; e++)
      if (!siteflip_has_edge(g, u, (int)tri[3 * t + e], (int)tri[3 * t + (e + 1) % 3]))
        return 0;
  return 1;
}

/* x + s y in mpq, exactly, against v: the sign of v - (x + s y). */
static int tc_cmp_bound(const mpq_t v, double x, double y, int s) {
  mpq_t b, t;
  mpq_inits(b, t, NULL);
  mpq_set_d(b, x);
  mpq_set_d(t, y);
  if (s > 0) mpq_add(b, b, t);
  else mpq_sub(b, b, t);
  int c = mpq_cmp(v, b);
  mpq_clears(b, t, NULL);
  return c;
}

/* The face's enclosures under rule rname against every triangulation. */
static void tc_face_check(const geom_point *p, size_t n, size_t k, const siteflip_graph *g,
                          const char *rname) {
  uint32_t walk[TC_MAXN], inner[TC_MAXN], edge[TC_MAXN * TC_MAXN];
  size_t ne = 0, len = k;
  for (uint32_t i = 0; i < n; i++) {
    if (i < k) walk[i] = i;
    else inner[i - k] = i;
    for (uint32_t j = i + 1; j < n; j++) edge[2 * ne] = i, edge[2 * ne++ + 1] = j;
  }
  got_face_in in = {p, 1, &len, walk, inner, n - k, edge, ne};
  rule r;
  char err[256];
  got_face_out o;
  assert_int_equal(rule_parse(rname, &r, err, sizeof err), 0);
  if (got_face_solve(&in, &r, &o, err, sizeof err) != 0) fail_msg("%s", err);
  assert_true(isfinite(o.err) && isfinite(o.err2));
  mpq_t T;
  mpq_init(T);
  tc_face_total(p, NULL, 0, o.tri, o.ntri, rule_measure(&r), T);
  assert_true(tc_cmp_bound(T, o.key, o.err, -1) >= 0 && tc_cmp_bound(T, o.key, o.err, 1) <= 0);
  for (int u = 0; u < g->nnodes; u++) {
    if (tc_face_is(g, u, o.tri, o.ntri)) continue;
    tc_face_total(p, g, u, NULL, 0, rule_measure(&r), T);
    assert_true(tc_cmp_bound(T, o.key2, o.err2, -1) >= 0);
  }
  mpq_clear(T);
  got_face_out_free(&o);
}

static void test_face_enclosures(void **state) {
  (void)state;
  sampler_rng s;
  sampler_seed(&s, 38, 3);
  geom_point p[TC_MAXN];
  int faces = 0;
  while (faces < 40) {
    size_t k = 4 + (size_t)faces % 3, n = k + 1 + (size_t)faces % 3;
    assert_int_equal(sampler_circle(&s, k, p), 0);
    for (size_t i = k; i < n; i++)
      p[i] = (geom_point){0.6 * sampler_uniform(&s) - 0.3, 0.6 * sampler_uniform(&s) - 0.3};
    int inside = 1;
    for (size_t i = k; i < n; i++)
      for (size_t e = 0; e < k; e++) inside &= geom_orient(p[e], p[(e + 1) % k], p[i]) > 0;
    char err[256];
    siteflip_graph *g = inside ? siteflip_build(p, (int)n, err, sizeof err) : NULL;
    if (g == NULL) continue;
    tc_face_check(p, n, k, g, "Pinf_1");
    tc_face_check(p, n, k, g, "-A_1");
    siteflip_free(g);
    faces++;
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_exact_ties),
    cmocka_unit_test(test_separated_unique),
    cmocka_unit_test(test_enclosures),
    cmocka_unit_test(test_face_enclosures),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
