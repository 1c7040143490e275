/*
** test_triavg.c: chapter 5's closed forms (studies/triavg.h) against the
** enumeration of every triangulation, against second routes, recurrences and
** asymptotics, and the measures of one triangulation against the thesis's
** procedures done by hand.
**
** - Every closed form equals the average (least, greatest) by enumeration,
**   exactly, for n = 1 .. 14 (every triangulation of every polygon up to the
**   16-gon); G^d_n too, and every vertex's degree law is G's (symmetry).
** - The enumerator gives C_n distinct triangulations, each a valid one, and
**   its running sums equal study_tri_measure's on the same triangles, whose
**   T_c is the circumcircle recursion counted step by step and whose
**   crossing count is the geometric crossing of the cut; the N rotations of
**   the cut cross 2 len_sum diagonals in all, for every triangulation.
** - Second routes at larger n: T_c as a sum over chords, L_a as lengths
**   times frequencies, T_i as a sum of fractions; G's recurrence
**   G^d_n = G^{d+1}_n + G^{d-1}_{n-1}, its total C_n and mean degree.
** - Asymptotics at n = 1000, 4000: T_c = sqrt(pi) n^{3/2} - 2n +
**   (9/8) sqrt(pi n) - 1 + O(n^{-1/2}), A = 4 sqrt(n/pi) - 2 + O(n^{-1/2}).
** - Refusals: n out of range, enumeration too large, triangles that are no
**   triangulation: NULL or -1 with one line.
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

#include "testutil.h"
#include "triavg_internal.h"

#define TEST_ENUM_N 14

static study_avg *ta_new(int n, int enumerate) {
  char err[256];
  study_avg *a = study_avg_new(n, enumerate, err, sizeof err);
  if (!a) fail_msg("study_avg_new(%d): %s", n, err);
  return a;
}

static uint64_t ta_catalan(int n) {
  uint64_t c = 1;
  for (int i = 0; i < n; i++) c = c * 2 * (2 * (uint64_t)i + 1) / ((uint64_t)i + 2);
  return c;
}

/* ---- closed forms against enumeration ----------------------------------- */

static void test_closed_equals_enumeration(void **state) {
  (void)state;
  mpq_t c, e;
  mpq_inits(c, e, NULL);
  for (int n = 1; n <= TEST_ENUM_N; n++) {
    study_avg *a = ta_new(n, 1);
    for (int k = 0; k < STUDY_AVG_COUNT; k++) {
      int has = study_avg_value(a, k, 0, c);
      assert_int_equal(has, study_avg_value(a, k, 1, e));
      assert_int_equal(has, n >= 2 || (k != STUDY_AVG_LA && k != STUDY_AVG_LMIN &&
                                       k != STUDY_AVG_LMAX));
      if (has && !mpq_equal(c, e))
        fail_msg("n = %d, %s: closed %s, enumerated %s", n, study_avg_name(k),
                 mpq_get_str(NULL, 10, c), mpq_get_str(NULL, 10, e));
    }
    char g1[64], g2[64];
    for (int d = 0; d < n; d++) {
      study_avg_degcount_text(a, d, 0, 0, g1, sizeof g1);
      study_avg_degcount_text(a, d, 1, 0, g2, sizeof g2);
      assert_string_equal(g1, g2);
    }
    assert_int_equal(study_avg_degcount_text(a, n, 0, 0, g1, sizeof g1), 0);
    study_avg_delete(a);
  }
  mpq_clears(c, e, NULL);
}

/* Every vertex has the same degree law, G^d_n (the polygon's rotations). */
static void test_every_vertex_has_law_g(void **state) {
  (void)state;
  mpz_t g;
  mpz_init(g);
  for (int n = 1; n <= TEST_ENUM_N; n++) {
    study_enum_totals t;
    study_enum_run(n, 1, &t);
    assert_true(t.count == ta_catalan(n));
    for (int v = 0; v < n + 2; v++)
      for (int d = 0; d < n + 2; d++) {
        if (d < n) study_avg_degcount(n, d, g);
        else mpz_set_ui(g, 0);
        assert_true(mpz_cmp_ui(g, (unsigned long)t.hist[v][d]) == 0);
      }
  }
  mpz_clear(g);
}

/* ---- one triangulation at a time ---------------------------------------- */

/* The triangles of the enumerator's current triangulation: the triples of
** pairwise joined vertices (in a triangulated convex polygon every such
** triple is a face). */
static size_t ta_triangles(const study_trienum *e, int adj[][STUDY_ENUM_VMAX], uint32_t *tri) {
  int nv = e->nv;
  memset(adj, 0, sizeof(int[STUDY_ENUM_VMAX]) * STUDY_ENUM_VMAX);
  for (int v = 0; v < nv; v++) adj[v][(v + 1) % nv] = adj[(v + 1) % nv][v] = 1;
  for (int q = 0; q < e->ndiag; q++) {
    int i = e->diag[q][0], j = e->diag[q][1];
    if (adj[i][j]) fail_msg("diagonal %d %d twice", i, j);
    adj[i][j] = adj[j][i] = 1;
  }
  size_t nt = 0;
  for (int a = 0; a < nv; a++)
    for (int b = a + 1; b < nv; b++)
      for (int c = b + 1; c < nv; c++)
        if (adj[a][b] && adj[b][c] && adj[a][c]) {
          tri[3 * nt] = (uint32_t)c, tri[3 * nt + 1] = (uint32_t)a, tri[3 * nt + 2] = (uint32_t)b;
          nt++;
        }
  return nt;
}

/* The thesis's circumtri(a, b) with its scan counted: b - a - 1 vertices,
** then the two pieces. */
static uint64_t ta_circumtri(int adj[][STUDY_ENUM_VMAX], int a, int b) {
  if (b - a <= 1) return 0;
  for (int k = a + 1; k < b; k++)
    if (adj[a][k] && adj[k][b])
      return (uint64_t)(b - a - 1) + ta_circumtri(adj, a, k) + ta_circumtri(adj, k, b);
  fail_msg("no apex on %d %d", a, b);
  return 0;
}

/* Diagonals crossing the segment from the middle of side p_{N-1} p_0 to the
** middle of side p_k p_{k+1}, the polygon on the unit circle. */
static uint64_t ta_geometric_cross(int adj[][STUDY_ENUM_VMAX], int nv, int k) {
  double x[STUDY_ENUM_VMAX], y[STUDY_ENUM_VMAX];
  for (int v = 0; v < nv; v++) x[v] = cos(2 * M_PI * v / nv), y[v] = sin(2 * M_PI * v / nv);
  double ax = (x[nv - 1] + x[0]) / 2, ay = (y[nv - 1] + y[0]) / 2;
  double bx = (x[k] + x[k + 1]) / 2, by = (y[k] + y[k + 1]) / 2;
  uint64_t cross = 0;
  for (int i = 0; i < nv; i++)
    for (int j = i + 2; j < nv; j++) {
      if (!adj[i][j] || (i == 0 && j == nv - 1)) continue;
      double o1 = (bx - ax) * (y[i] - ay) - (by - ay) * (x[i] - ax);
      double o2 = (bx - ax) * (y[j] - ay) - (by - ay) * (x[j] - ax);
      double o3 = (x[j] - x[i]) * (ay - y[i]) - (y[j] - y[i]) * (ax - x[i]);
      double o4 = (x[j] - x[i]) * (by - y[i]) - (y[j] - y[i]) * (bx - x[i]);
      cross += (o1 * o2 < 0 && o3 * o4 < 0);
    }
  return cross;
}

static void ta_check_one(const study_trienum *e, int n) {
  int adj[STUDY_ENUM_VMAX][STUDY_ENUM_VMAX];
  uint32_t tri[3 * STUDY_ENUM_VMAX], deg[STUDY_ENUM_VMAX], rot[3 * STUDY_ENUM_VMAX];
  char err[256];
  int nv = n + 2;
  assert_int_equal(e->ndiag, n - 1);
  size_t nt = ta_triangles(e, adj, tri);
  assert_int_equal(nt, (size_t)n);
  study_tri_stats s;
  if (study_tri_measure(tri, nt, (uint32_t)nv, &s, deg, err, sizeof err) != 0)
    fail_msg("%s", err);
  assert_true(s.tc == e->sum[0] + (uint64_t)n);
  assert_true(s.tc == ta_circumtri(adj, 0, nv - 1));
  assert_true(s.cross == e->sum[1]);
  assert_true(s.cross == ta_geometric_cross(adj, nv, n / 2));
  assert_true(s.len_sum == e->sum[2]);
  for (int v = 0; v < nv; v++) assert_int_equal(deg[v], e->deg[v]);
  uint64_t all = 0;                      /* the cut turned round the polygon */
  for (int r = 0; r < nv; r++) {
    for (size_t q = 0; q < 3 * nt; q++) rot[q] = (tri[q] + (uint32_t)r) % (uint32_t)nv;
    study_tri_stats sr;
    assert_int_equal(study_tri_measure(rot, nt, (uint32_t)nv, &sr, NULL, err, sizeof err), 0);
    all += sr.cross;
  }
  assert_true(all == 2 * s.len_sum);
}

static void test_enumerator_against_measure(void **state) {
  (void)state;
  for (int n = 1; n <= 9; n++) {
    study_trienum e;
    uint64_t count = 0;
    study_trienum_start(&e, n);
    while (study_trienum_next(&e)) {
      ta_check_one(&e, n);
      count++;
    }
    assert_true(count == ta_catalan(n));
  }
}

/* Distinct: the diagonal sets, as bit masks over the pairs, never repeat. */
static int ta_cmp_u64(const void *x, const void *y) {
  uint64_t a = *(const uint64_t *)x, b = *(const uint64_t *)y;
  return a < b ? -1 : a > b;
}

static void test_enumerator_distinct(void **state) {
  (void)state;
  int n = 8, nv = n + 2;                  /* 45 pairs of 10 vertices: 64 bits */
  uint64_t *mask = malloc(ta_catalan(n) * sizeof *mask);
  size_t m = 0;
  study_trienum e;
  study_trienum_start(&e, n);
  while (study_trienum_next(&e)) {
    uint64_t b = 0;
    for (int q = 0; q < e.ndiag; q++) {
      int i = e.diag[q][0], j = e.diag[q][1];
      b |= UINT64_C(1) << (i * nv + j - (i + 1) * (i + 2) / 2);
    }
    mask[m++] = b;
  }
  qsort(mask, m, sizeof *mask, ta_cmp_u64);
  for (size_t q = 1; q < m; q++) assert_true(mask[q] != mask[q - 1]);
  free(mask);
}

/* ---- second routes, recurrences, asymptotics ----------------------------- */

static void test_second_routes(void **state) {
  (void)state;
  static const int ns[] = {1, 2, 3, 4, 5, 6, 7, 10, 17, 33, 64, 101, 500, 1500};
  mpq_t c, r;
  mpq_inits(c, r, NULL);
  for (size_t q = 0; q < sizeof ns / sizeof *ns; q++) {
    int n = ns[q];
    study_avg_closed(STUDY_AVG_TC, n, c);
    study_avg_tc_by_chords(n, r);
    assert_true(mpq_equal(c, r));
    study_avg_closed(STUDY_AVG_TI, n, c);
    study_avg_ti_by_sum(n, r);
    assert_true(mpq_equal(c, r));
    if (n < 2) continue;
    study_avg_closed(STUDY_AVG_LA, n, c);
    study_avg_la_by_chords(n, r);
    assert_true(mpq_equal(c, r));
  }
  mpq_clears(c, r, NULL);
}

/* G^d_n = G^{d+1}_n + G^{d-1}_{n-1} (G^{-1} = 0, G^n_n = 0); the G^d_n
** add up to C_n and give the mean degree 2(n-1)/(n+2). */
static void test_degcount_recurrence(void **state) {
  (void)state;
  mpz_t g, up, left, total, moment, cat;
  mpz_inits(g, up, left, total, moment, cat, NULL);
  for (int n = 2; n <= 150; n++) {
    mpz_set_ui(total, 0);
    mpz_set_ui(moment, 0);
    for (int d = 0; d < n; d++) {
      study_avg_degcount(n, d, g);
      assert_true(mpz_sgn(g) > 0);
      mpz_add(total, total, g);
      mpz_addmul_ui(moment, g, (unsigned long)d);
      if (d + 1 < n) study_avg_degcount(n, d + 1, up);
      else mpz_set_ui(up, 0);
      if (d >= 1) study_avg_degcount(n - 1, d - 1, left);
      else mpz_set_ui(left, 0);
      mpz_add(up, up, left);
      assert_true(mpz_cmp(g, up) == 0);
    }
    mpz_bin_uiui(cat, 2 * (unsigned long)n, (unsigned long)n);
    mpz_divexact_ui(cat, cat, (unsigned long)n + 1);
    assert_true(mpz_cmp(total, cat) == 0);
    mpz_mul_ui(moment, moment, (unsigned long)n + 2);     /* mean = 2(n-1)/(n+2) */
    mpz_mul_ui(cat, cat, 2 * ((unsigned long)n - 1));
    assert_true(mpz_cmp(moment, cat) == 0);
  }
  mpz_clears(g, up, left, total, moment, cat, NULL);
}

/* The expansions (docs/averages.md): 4^n / C_n = (n+1) sqrt(pi n)
** (1 + 1/(8n) + O(n^-2)), and A's sum as a Riemann sum of
** x^{-1/2} (1-x)^{-3/2} over [0, 1/2], whose integral is 2.  The remainders
** measured at n = 1000 and 4000 are 0.2354/sqrt(n) and 0.85/sqrt(n); the
** bounds allow a third more. */
static void test_asymptotics(void **state) {
  (void)state;
  static const int ns[] = {1000, 4000};
  for (size_t q = 0; q < 2; q++) {
    double n = ns[q], sp = sqrt(M_PI);
    study_avg *a = ta_new(ns[q], 0);
    double tc = study_avg_double(a, STUDY_AVG_TC, 0);
    double x = study_avg_double(a, STUDY_AVG_CROSS, 0);
    double tc_pred = sp * pow(n, 1.5) - 2 * n + 9.0 / 8 * sp * sqrt(n) - 1;
    assert_true(fabs(tc - tc_pred) < 0.32 / sqrt(n));
    assert_true(fabs(x - (4 * sqrt(n / M_PI) - 2)) < 1.15 / sqrt(n));
    assert_true(fabs(tc / (sp * pow(n, 1.5)) - 1) < 2.1 / sqrt(n));
    study_avg_delete(a);
  }
}

/* The values a reader can check by hand: the quadrilateral, the pentagon. */
static void test_small_values(void **state) {
  (void)state;
  static const struct { int n, kind; const char *text; } rows[] = {
    {1, STUDY_AVG_TC, "1"}, {2, STUDY_AVG_TC, "3"}, {3, STUDY_AVG_TC, "29/5"},
    {2, STUDY_AVG_CROSS, "1"}, {1, STUDY_AVG_TI, "0"}, {2, STUDY_AVG_TI, "1/2"},
    {2, STUDY_AVG_LA, "2"}, {4, STUDY_AVG_LMIN, "2"}, {5, STUDY_AVG_LMAX, "5/2"},
    {3, STUDY_AVG_DEGREE, "4/5"},
  };
  char buf[64];
  for (size_t q = 0; q < sizeof rows / sizeof *rows; q++) {
    study_avg *a = ta_new(rows[q].n, 0);
    size_t len = study_avg_text(a, rows[q].kind, 0, 0, buf, sizeof buf);
    assert_int_equal(len, strlen(rows[q].text));
    assert_string_equal(buf, rows[q].text);
    assert_int_equal(study_avg_text(a, rows[q].kind, 1, 0, buf, sizeof buf), 0);
    study_avg_delete(a);
  }
}

/* ---- refusals ------------------------------------------------------------- */

static void test_refusals(void **state) {
  (void)state;
  char err[256];
  static const int bad[][2] = {{0, 0}, {-3, 0}, {STUDY_AVG_NMAX + 1, 0},
                               {STUDY_AVG_ENUM_NMAX + 1, 1}};
  for (size_t q = 0; q < 4; q++) {
    err[0] = 0;
    assert_null(study_avg_new(bad[q][0], bad[q][1], err, sizeof err));
    assert_true(strlen(err) > 10 && !strchr(err, '\n'));
  }
  static const struct { uint32_t nv; size_t nt; uint32_t t[12]; const char *what; } tris[] = {
    {5, 3, {0, 1, 2, 0, 2, 3, 0, 3, 5}, "out of range"},
    {5, 3, {0, 1, 1, 0, 2, 3, 0, 3, 4}, "repeats"},
    {5, 2, {0, 1, 2, 0, 2, 4}, "3 triangles"},
    {5, 3, {0, 1, 2, 0, 2, 3, 1, 3, 4}, "no triangle"},
    {6, 4, {0, 1, 3, 1, 2, 3, 0, 2, 3, 3, 4, 5}, "both lie inside"},
    {6, 4, {0, 1, 2, 0, 2, 3, 1, 3, 4, 0, 4, 5}, "no triangle"},
  };
  for (size_t q = 0; q < sizeof tris / sizeof *tris; q++) {
    study_tri_stats s;
    err[0] = 0;
    assert_int_equal(study_tri_measure(tris[q].t, tris[q].nt, tris[q].nv, &s, NULL, err,
                                       sizeof err), -1);
    if (!strstr(err, tris[q].what)) fail_msg("case %zu: %s", q, err);
    assert_null(strchr(err, '\n'));
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_closed_equals_enumeration),
    cmocka_unit_test(test_every_vertex_has_law_g),
    cmocka_unit_test(test_enumerator_against_measure),
    cmocka_unit_test(test_enumerator_distinct),
    cmocka_unit_test(test_second_routes),
    cmocka_unit_test(test_degcount_recurrence),
    cmocka_unit_test(test_asymptotics),
    cmocka_unit_test(test_small_values),
    cmocka_unit_test(test_refusals),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
