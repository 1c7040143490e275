/*
** test_paradigms_cli.c: `fliplab paradigms` as a user runs it: --list
** names every algorithm of the registry; a small matrix writes a CSV whose
** columns are every count per site and growth exponent, whose counts are
** the library's for the same points (sampler_points, paradigm_run
** recomputed here) and whose growth exponents are the least-squares slopes
** of its own totals; a refused rule is a row saying why, in the CSV and on
** stdout; the plot is well-formed; every bad option is one line on stderr,
** exit status 2, and no output file.
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
#include <unistd.h>

#include "paradigm.h"
#include "sampler.h"
#include "splitmix.h"
#include "testutil.h"

static char tpl_out[1 << 17], tpl_err[4096];

static void test_list(void **state) {
  (void)state;
  assert_int_equal(testutil_run("paradigms --list", tpl_out, sizeof tpl_out, tpl_err,
                                sizeof tpl_err), 0);
  for (size_t i = 0; i < paradigm_count(); i++) {
    char row[128];
    snprintf(row, sizeof row, "| %s | %s | %s |", paradigm_get(i)->name,
             paradigm_get(i)->paradigm, paradigm_get(i)->section);
    if (strstr(tpl_out, row) == NULL) fail_msg("--list has no row '%s'", row);
  }
}

/* Field k (0-based) of the CSV line s, unquoted fields only, into buf. */
static const char *tpl_field(const char *s, int k, char *buf, size_t len) {
  for (int i = 0; i < k; i++) {
    s = strchr(s, ',');
    assert_non_null(s);
    s++;
  }
  size_t n = strcspn(s, ",\n");
  snprintf(buf, len, "%.*s", (int)n, s);
  return buf;
}

/* The column named `name` in the header line h. */
static int tpl_column(const char *h, const char *name) {
  char buf[64];
  for (int k = 0; k < 64; k++)
    if (strcmp(tpl_field(h, k, buf, sizeof buf), name) == 0) return k;
  fail_msg("no column %s", name);
  return -1;
}

/* The line of the CSV for algorithm a, rule r, family f and size n. */
static const char *tpl_line(const char *csv, const char *a, const char *r, const char *f,
                            unsigned n) {
  char key[128];
  snprintf(key, sizeof key, "\n%s,", a);
  for (const char *s = strstr(csv, key); s != NULL; s = strstr(s + 1, key)) {
    char want[160], buf[64];
    snprintf(want, sizeof want, "%s|%s|%u", r, f, n);
    char got[160];
    snprintf(got, sizeof got, "%s|", tpl_field(s + 1, 3, buf, sizeof buf));
    strcat(got, tpl_field(s + 1, 4, buf, sizeof buf));
    strcat(got, "|");
    strcat(got, tpl_field(s + 1, 5, buf, sizeof buf));
    if (strcmp(got, want) == 0) return s + 1;
  }
  fail_msg("no row %s %s %s %u", a, r, f, n);
  return NULL;
}

/* Count k of algorithm a on family f's n points (seed 4), recomputed. */
static uint64_t tpl_count(const char *a, sampler_points_kind f, size_t n, int k) {
  geom_point *p = malloc(n * sizeof *p);
  assert_non_null(p);
  sampler_points(f, 4, n, p);
  rule r = rule_delaunay();
  paradigm_input in = {.p = p, .n = n, .r = &r, .problem = PARADIGM_DELAUNAY, .seed = 4,
                       .threads = 1};
  paradigm_result res;
  char err[256];
  if (paradigm_run(paradigm_find(a), &in, &res, err, sizeof err) != 0) fail_msg("%s", err);
  uint64_t v = res.ops.v[k];
  paradigm_result_free(&res);
  free(p);
  return v;
}

static void test_matrix(void **state) {
  (void)state;
  char csv[512], svg[512];
  testutil_tmppath(csv, sizeof csv, "paradigms.csv");
  testutil_tmppath(svg, sizeof svg, "paradigms.svg");
  assert_int_equal(testutil_runf(tpl_out, sizeof tpl_out, tpl_err, sizeof tpl_err,
                                 "paradigms --algorithms incremental,watson,convex-flip --rules "
                                 "DT,ES:square --families uniform,dups --sizes 300,1200 --runs 1 "
                                 "--seed 4 --csv %s --svg %s --measure incircle", csv, svg), 0);
  char *t = testutil_read_file(csv);
  assert_non_null(t);
  assert_int_equal(testutil_count(t, "\n"), 1 + 3 * 2 * 2 * 2);
  for (int k = 0; k < OPS_COUNT; k++) {
    char name[64];
    snprintf(name, sizeof name, "%s_per_site", ops_name(k));
    tpl_column(t, name);
    snprintf(name, sizeof name, "growth_%s", ops_name(k));
    tpl_column(t, name);
  }
  int ci = tpl_column(t, "incircle_per_site"), gi = tpl_column(t, "growth_incircle");
  int st = tpl_column(t, "status");
  char buf[256];
  double v[2];
  unsigned sizes[2] = {300, 1200};
  for (int s = 0; s < 2; s++) {
    const char *line = tpl_line(t, "incremental", "DT", "dups", sizes[s]);
    v[s] = atof(tpl_field(line, ci, buf, sizeof buf)) * sizes[s];
    assert_int_equal((uint64_t)llround(v[s]), tpl_count("incremental", SAMPLER_DUPS, sizes[s],
                                                        OPS_INCIRCLE));
    assert_string_equal(tpl_field(line, st, buf, sizeof buf), "ok");
  }
  const char *line = tpl_line(t, "incremental", "DT", "dups", 300);
  double slope = log(v[1] / v[0]) / log(4.0);
  TESTUTIL_NEAR(atof(tpl_field(line, gi, buf, sizeof buf)), slope, 1e-9, 1e-9);
  /* watson serves ES:square (its triangles equal incremental's: the matrix
  ** stops at a disagreement); a row for convex polygons refuses point sets. */
  line = tpl_line(t, "watson", "ES:square", "uniform", 1200);
  assert_string_equal(tpl_field(line, st, buf, sizeof buf), "ok");
  line = tpl_line(t, "convex-flip", "ES:square", "uniform", 1200);
  assert_true(strstr(line, "refused: algorithm convex-flip does not solve the delaunay") != NULL);
  assert_non_null(strstr(tpl_out, "| convex-flip | flip | ES:square | uniform | refused: "));
  free(t);
  char *g = testutil_read_file(svg);
  assert_non_null(g);
  assert_non_null(strstr(g, "<svg"));
  assert_non_null(strstr(g, "</svg>"));
  assert_int_equal(testutil_count(g, "<polyline"), 3);
  free(g);
}

/* The constrained problem recomputed: family f's n points (seed 5), up to
** n/4 segments from the segments' stream; the incremental row's triangles.
** Every segment through no other point is an edge of them (the meaning of
** a constrained triangulation). */
static size_t tpl_constrained(sampler_points_kind f, size_t n) {
  geom_point *p = malloc(n * sizeof *p);
  uint32_t *seg = malloc(2 * (n / 4 + 1) * sizeof *seg);
  assert_true(p != NULL && seg != NULL);
  sampler_points(f, 5, n, p);
  sampler_rng g;
  sampler_seed(&g, 5, GEOM_STREAM_SEGMENTS);
  size_t m;
  assert_int_equal(sampler_segments(&g, p, n, n / 4, seg, &m), 0);
  assert_true(m > 0);
  rule r = rule_delaunay();
  paradigm_input in = {.p = p, .n = n, .r = &r, .problem = PARADIGM_CONSTRAINED, .seed = 5,
                       .threads = 1, .segments = seg, .nsegments = m};
  paradigm_result res;
  char err[256];
  if (paradigm_run(paradigm_find("incremental"), &in, &res, err, sizeof err) != 0)
    fail_msg("%s", err);
  for (size_t k = 0; k < m; k++) {
    uint32_t a = seg[2 * k], b = seg[2 * k + 1];
    int through = 0, edge = 0;
    for (size_t i = 0; i < n; i++) {   /* p[i] strictly between p[a] and p[b] */
      double dot = (p[i].x - p[a].x) * (p[i].x - p[b].x) + (p[i].y - p[a].y) * (p[i].y - p[b].y);
      through |= i != a && i != b && geom_orient(p[a], p[b], p[i]) == 0 && dot < 0;
    }
    for (size_t t = 0; t < res.ntri && !through; t++)
      for (int e = 0; e < 3; e++) {
        uint32_t u = res.tri[3 * t + e], v = res.tri[3 * t + (e + 1) % 3];
        edge |= (u == a && v == b) || (u == b && v == a);
      }
    if (!through && !edge) fail_msg("segment %zu (%u, %u) is no edge", k, a, b);
  }
  size_t t = res.ntri;
  paradigm_result_free(&res);
  free(p), free(seg);
  return t;
}

/* --problem: the constrained problem's rows agree (the matrix compares
** them) and their triangles are the recomputed ones; a polygon's rows,
** simple or convex, make n - 2 triangles each; the problem is named in the
** CSV and on stdout; a row that does not serve the problem says so. */
static void test_problems(void **state) {
  (void)state;
  char csv[512], buf[256];
  testutil_tmppath(csv, sizeof csv, "problems.csv");
  static const struct {
    const char *problem, *args, *row, *family;
    int kind;   /* the constrained points' sampler_points_kind, -1 for a polygon */
  } run[] = {
    {"constrained", "incremental,flip,select-constrained,sweep --families uniform,lines",
     "select-constrained", "lines", SAMPLER_LINES},
    {"constrained", "incremental,flip,select-constrained --families uniform",
     "flip", "uniform", SAMPLER_UNIFORM},
    {"polygon", "incremental,flip,select-constrained,watson --families star,monotone",
     "flip", "monotone", -1},
    {"convex", "convex-divide,convex-random,convex-flip,incremental --families valtr,vector",
     "convex-divide", "vector", -1},
  };
  for (size_t i = 0; i < sizeof run / sizeof *run; i++) {
    if (testutil_runf(tpl_out, sizeof tpl_out, tpl_err, sizeof tpl_err, "paradigms --problem "
                      "%s --algorithms %s --sizes 200,600 --runs 1 --seed 5 --csv %s",
                      run[i].problem, run[i].args, csv) != 0)
      fail_msg("%s: %s", run[i].args, tpl_err);
    char head[96];
    snprintf(head, sizeof head, "# fliplab paradigms: %s problem", run[i].problem);
    assert_non_null(strstr(tpl_out, head));
    char *t = testutil_read_file(csv);
    assert_non_null(t);
    int tr = tpl_column(t, "triangles"), pr = tpl_column(t, "problem");
    int st = tpl_column(t, "status");
    for (unsigned n = 200; n <= 600; n += 400) {
      const char *line = tpl_line(t, run[i].row, "DT", run[i].family, n);
      size_t want = run[i].kind < 0 ? n - 2 : tpl_constrained(run[i].kind, n);
      assert_int_equal(strtoull(tpl_field(line, tr, buf, sizeof buf), NULL, 10), want);
      assert_string_equal(tpl_field(line, st, buf, sizeof buf), "ok");
      assert_string_equal(tpl_field(line, pr, buf, sizeof buf), run[i].problem);
    }
    if (i != 1) assert_non_null(strstr(t, "refused: algorithm"));
    free(t);
  }
}

static void test_errors(void **state) {
  (void)state;
  char csv[512];
  testutil_tmppath(csv, sizeof csv, "bad.csv");
  static const char *const bad[] = {
    "--algorithms nope", "--algorithms watson,watson", "--families nope",
    "--families uniform,uniform", "--sizes 2", "--sizes 100,x", "--sizes 1e9", "--runs 0",
    "--runs 100", "--rules NOPE", "--rules ''", "--sizes 100,", "--measure nope", "--seed -1",
    "--bogus", "--svg x.csv",
    "--sizes 1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17", "--problem nope", "--problem",
    "--problem convex --families uniform", "--problem polygon --families valtr",
    "--problem delaunay --families star", "--problem convex --families naive",
    "--problem convex --families rejection",
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    unlink(csv);
    int rc = testutil_runf(tpl_out, sizeof tpl_out, tpl_err, sizeof tpl_err,
                           "paradigms --sizes 100 --runs 1 --csv %s %s", csv, bad[i]);
    if (rc != 2 || !testutil_one_line(tpl_err)) fail_msg("'%s': status %d, '%s'", bad[i], rc,
                                                         tpl_err);
    assert_int_equal(access(csv, F_OK), -1);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_list),
    cmocka_unit_test(test_matrix),
    cmocka_unit_test(test_problems),
    cmocka_unit_test(test_errors),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
