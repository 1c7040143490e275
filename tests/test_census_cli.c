/*
** test_census_cli.c: `fliplab flipgraph` and `fliplab census` as a user
** runs them: figure 3.8 with R_1 and with the formula -R (its SVG showing
** two sinks), GOT agreeing with `fliplab got` on convex polygons, census of
** convex pentagons agreeing with table34, the census CSV unchanged by the
** thread count and by shards merged with `fliplab merge`, bad input
** refused with one line.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sampler.h"
#include "testutil.h"

#define TCC_BUF 65536

static char tcc_out[TCC_BUF], tcc_err[TCC_BUF];

static void tcc_write_sites(const char *path, const geom_point *p, int n) {
  char text[4096];
  size_t k = (size_t)snprintf(text, sizeof text, "x,y\n");
  for (int i = 0; i < n; i++)
    k += (size_t)snprintf(text + k, sizeof text - k, "%.17g,%.17g\n", p[i].x, p[i].y);
  testutil_write_file(path, text);
}

static void test_figure_3_8_cli(void **state) {
  (void)state;
  char pts[512], svg[512];
  testutil_tmppath(pts, sizeof pts, "tcc_fig38.csv");
  testutil_tmppath(svg, sizeof svg, "tcc_fig38.svg");
  testutil_write_file(pts, "x,y\n0,0\n1,0\n1,1\n0,1\n0.45,0.4\n");
  assert_int_equal(testutil_runf(tcc_out, TCC_BUF, tcc_err, TCC_BUF,
                                 "flipgraph --rule R_1 --points %s", pts), 0);
  assert_non_null(strstr(tcc_out, "triangulations: 3\n"));
  assert_non_null(strstr(tcc_out, "flip edges: 2\n"));
  assert_non_null(strstr(tcc_out, "sinks: 1\n"));
  assert_non_null(strstr(tcc_out, "sink is DT: yes\n"));
  assert_non_null(strstr(tcc_out, "ties: no\n"));
  assert_non_null(strstr(tcc_out, "cycle: no\n"));
  assert_non_null(strstr(tcc_out, "GOT: "));
  assert_int_equal(testutil_runf(tcc_out, TCC_BUF, tcc_err, TCC_BUF,
                                 "--define 'negR = -R' flipgraph --rule negR_1 --points %s "
                                 "--svg %s", pts, svg), 0);
  assert_non_null(strstr(tcc_out, "sinks: 2\n"));
  assert_non_null(strstr(tcc_out, "sink is DT: -\n"));
  assert_int_equal(testutil_count(tcc_out, "  sink T"), 2);
  char *s = testutil_read_file(svg);
  assert_non_null(s);
  assert_int_equal(testutil_count(s, ">sink</text>"), 2);
  assert_int_equal(testutil_count(s, ">source</text>"), 1);
  assert_int_equal(testutil_count(s, ">DT</text>"), 1);
  free(s);
}

/* The GOT line of flipgraph against got's "total badness" line. */
static double tcc_value_after(const char *text, const char *key) {
  const char *p = strstr(text, key);
  if (p == NULL) fail_msg("no '%s' in: %s", key, text);
  return strtod(p + strlen(key), NULL);
}

static void test_got_agrees(void **state) {
  (void)state;
  static const char *const rules[] = {"R_1", "-alpha_inf", "P_2", "abc_0", "-r_-1", "a_inf",
                                      "lambda_-inf", "sigma_1"};
  char pts[512];
  testutil_tmppath(pts, sizeof pts, "tcc_convex.csv");
  for (int n = 5; n <= 9; n += 2)
    for (size_t r = 0; r < sizeof rules / sizeof rules[0]; r++) {
      geom_point p[9];
      sampler_convex(11, r, n, p);
      tcc_write_sites(pts, p, n);
      assert_int_equal(testutil_runf(tcc_out, TCC_BUF, tcc_err, TCC_BUF,
                                     "flipgraph --rule %s --points %s", rules[r], pts), 0);
      double mine = tcc_value_after(tcc_out, "GOT: ");
      assert_int_equal(testutil_runf(tcc_out, TCC_BUF, tcc_err, TCC_BUF,
                                     "got --rule %s --polygon %s --no-triangles", rules[r], pts), 0);
      double theirs = tcc_value_after(tcc_out, "total badness: ");
      TESTUTIL_NEAR(mine, theirs, 1e-12, 1e-300);
    }
}

/* Column col (0-based) of the CSV row whose third field is rule. */
static unsigned long long tcc_field(const char *csv, const char *rule, int col) {
  char key[128];
  snprintf(key, sizeof key, ",%s,", rule);
  for (const char *line = csv; line != NULL && *line; line = strchr(line, '\n') ? strchr(line, '\n') + 1 : NULL) {
    const char *p = strchr(line, ',');   /* the second comma precedes the third field */
    if (p != NULL) p = strchr(p + 1, ',');
    if (p == NULL || strncmp(p, key, strlen(key)) != 0) continue;
    const char *q = line;
    for (int k = 0; k < col; k++) q = strchr(q, ',') + 1;
    return strtoull(q, NULL, 10);
  }
  fail_msg("rule %s not in CSV", rule);
  return 0;
}

static void test_census_pentagons_cli(void **state) {
  (void)state;
  char *table = malloc(TCC_BUF), *census = malloc(TCC_BUF);
  assert_int_equal(testutil_run("table34 --samples 4000 --seed 9 --format csv --measures R,-alpha,P,gamma",
                                table, TCC_BUF, NULL, 0), 0);
  assert_int_equal(testutil_run("census --sites 5 --sampler convex --samples 4000 --seed 9 "
                                "--format csv --measures R,-alpha,P,gamma",
                                census, TCC_BUF, NULL, 0), 0);
  static const char *const rules[] = {"R_1", "-alpha_-inf", "-alpha_2", "P_inf", "gamma_0", "DT"};
  /* table34: measure,joint,rule,samples,type_I,type_II,type_III,type_IV,type_V,dt
  ** census:  measure,joint,rule,sites,sampler,samples,tie,no_sink,one_sink,multi_sink,... */
  unsigned long long multi = 0;
  for (size_t r = 0; r < sizeof rules / sizeof rules[0]; r++) {
    assert_int_equal(tcc_field(census, rules[r], 8),
                     tcc_field(table, rules[r], 4) + tcc_field(table, rules[r], 5));
    assert_int_equal(tcc_field(census, rules[r], 9), tcc_field(table, rules[r], 6));
    assert_int_equal(tcc_field(census, rules[r], 7), tcc_field(table, rules[r], 7));
    assert_int_equal(tcc_field(census, rules[r], 6), tcc_field(table, rules[r], 8));
    multi += tcc_field(census, rules[r], 9);
  }
  assert_true(multi > 0);
  free(table);
  free(census);
}

static void test_census_bytes(void **state) {
  (void)state;
  char whole[512], sh[3][512], merged[512];
  testutil_tmppath(whole, sizeof whole, "tcc_whole.csv");
  testutil_tmppath(merged, sizeof merged, "tcc_merged.csv");
  for (int k = 0; k < 3; k++) {
    char name[64];
    snprintf(name, sizeof name, "tcc_shard%d.csv", k + 1);
    testutil_tmppath(sh[k], sizeof sh[k], name);
  }
  static const char *const samplers[] = {"convex", "disc", "normal"};
  for (int s = 0; s < 3; s++) {
    const char *common = "census --sites 6 --samples 1500 --measures all --format csv";
    assert_int_equal(testutil_runf(NULL, 0, tcc_err, TCC_BUF, "%s --sampler %s --threads 1 --out %s",
                                   common, samplers[s], whole), 0);
    char *a = testutil_read_file(whole);
    assert_int_equal(testutil_runf(NULL, 0, tcc_err, TCC_BUF, "%s --sampler %s --threads 2 --out %s",
                                   common, samplers[s], whole), 0);
    char *b = testutil_read_file(whole);
    assert_string_equal(a, b);
    for (int k = 0; k < 3; k++)
      assert_int_equal(testutil_runf(NULL, 0, tcc_err, TCC_BUF, "%s --sampler %s --shard %d/3 --out %s",
                                     common, samplers[s], k + 1, sh[k]), 0);
    assert_int_equal(testutil_runf(NULL, 0, tcc_err, TCC_BUF, "merge %s %s %s --out %s", sh[0], sh[1],
                                   sh[2], merged), 0);
    char *m = testutil_read_file(merged);
    assert_string_equal(a, m);
    assert_true(testutil_count(a, "\n") > 120);
    free(a);
    free(b);
    free(m);
  }
}

static void tcc_refused(const char *args, const char *needle) {
  int rc = testutil_run(args, NULL, 0, tcc_err, TCC_BUF);
  if (rc != 2 || !testutil_one_line(tcc_err) || strstr(tcc_err, needle) == NULL)
    fail_msg("`fliplab %s`: exit %d, stderr '%s' (wanted one line with '%s')", args, rc, tcc_err,
             needle);
}

static void test_bad_input_cli(void **state) {
  (void)state;
  char dup[512], col[512], many[512], args[1200];
  testutil_tmppath(dup, sizeof dup, "tcc_dup.csv");
  testutil_tmppath(col, sizeof col, "tcc_col.csv");
  testutil_tmppath(many, sizeof many, "tcc_many.csv");
  testutil_write_file(dup, "x,y\n0,0\n1,0\n0,1\n1,0\n");
  testutil_write_file(col, "0,0\n1,1\n2,2\n3,3\n");
  char text[1024] = "x,y\n";
  for (int i = 0; i < 17; i++) snprintf(text + strlen(text), 40, "%d,%d\n", i, i * i);
  testutil_write_file(many, text);
  snprintf(args, sizeof args, "flipgraph --rule R_1 --points %s", dup);
  tcc_refused(args, "sites 2 and 4 are equal");
  snprintf(args, sizeof args, "flipgraph --rule R_1 --points %s", col);
  tcc_refused(args, "collinear");
  snprintf(args, sizeof args, "flipgraph --rule R_1 --points %s", many);
  tcc_refused(args, "at most 16 sites");
  snprintf(args, sizeof args, "flipgraph --rule Q_1 --points %s", dup);
  tcc_refused(args, "unknown measure 'Q'");
  tcc_refused("flipgraph --rule R_1", "--points");
  tcc_refused("census --sampler hexagonal", "unknown sampler 'hexagonal'");
  tcc_refused("census --sites 17", "3 to 16 sites");
  tcc_refused("census --sites 2", "3 to 16 sites");
  tcc_refused("census --sites x", "--sites expects a non-negative integer");   /* once */
  tcc_refused("census --samples 0", "--samples 0 is out of range");
  tcc_refused("census --rules R_1,nope_1", "unknown measure 'nope'");
  tcc_refused("census --shard 4/3", "--shard");
}

/* The 4 x 4 grid (16 sites, 46 456 triangulations) within the default
** budget; a tiny --memory stops with one line and exit 2, as does a census
** whose sets outgrow it; bad sizes are refused. */
static void test_memory_cli(void **state) {
  (void)state;
  char grid[512], args[1200];
  testutil_tmppath(grid, sizeof grid, "tcc_grid4.csv");
  char text[512] = "x,y\n";
  for (int i = 0; i < 16; i++) snprintf(text + strlen(text), 40, "%d,%d\n", i % 4, i / 4);
  testutil_write_file(grid, text);
  assert_int_equal(testutil_runf(tcc_out, TCC_BUF, tcc_err, TCC_BUF,
                                 "flipgraph --rule DT --points %s", grid), 0);
  assert_non_null(strstr(tcc_out, "sites: 16\n"));
  assert_non_null(strstr(tcc_out, "triangulations: 46456\n"));
  snprintf(args, sizeof args, "flipgraph --rule DT --points %s --memory 1M", grid);
  tcc_refused(args, "outgrows the memory budget of 1 MiB");
  assert_non_null(strstr(tcc_err, "triangulations found before it ran out"));
  tcc_refused("census --sites 14 --sampler disc --samples 4 --memory 64K",
              "set #0: the flip graph of 14 sites outgrows the memory budget of 64 KiB");
  tcc_refused("census --sites 6 --memory 0", "--memory 0 is out of range");
  tcc_refused("census --sites 6 --memory 2T", "--memory 2T is out of range");
  tcc_refused("census --sites 6 --memory 1.5G", "--memory expects a size");
  tcc_refused("census --sites 6 --memory G", "--memory expects a size");
  assert_int_equal(testutil_run("census --sites 5 --samples 10 --memory 64M", tcc_out, TCC_BUF,
                                tcc_err, TCC_BUF), 0);
}

/* fliplab rule catches -R_1 on five-site sets with a figure-3.8 witness
** that reads back into flipgraph with two sinks; R_1 passes. */
static void test_rule_catches_neg_R(void **state) {
  (void)state;
  char dir[512], args[2048];
  testutil_tmppath(dir, sizeof dir, "tcc_rule_svg");
  snprintf(args, sizeof args, "--define 'negR = -R' rule negR_1 --samples 2000 --quads 100 "
           "--site-samples 3000 --svg-dir %s", dir);
  assert_int_equal(testutil_run(args, tcc_out, TCC_BUF, tcc_err, TCC_BUF), 0);
  assert_non_null(strstr(tcc_out, "no counterexample to systematicity in 2000 pentagons"));
  assert_non_null(strstr(tcc_out, "five-site disc sets (figure 3.8's kind)"));
  const char *v = strstr(tcc_out, "verdict: not systematic: ");
  assert_non_null(v);
  assert_true(strtoull(v + strlen("verdict: not systematic: "), NULL, 10) > 0);
  /* the witness CSV and SVG */
  const char *csv = strstr(tcc_out, "      csv: ");
  assert_non_null(csv);
  char path[1024];
  assert_int_equal(sscanf(csv + 11, "%1023s", path), 1);
  char *flip = malloc(TCC_BUF);
  assert_int_equal(testutil_runf(flip, TCC_BUF, tcc_err, TCC_BUF,
                                 "--define 'negR = -R' flipgraph --rule negR_1 --points %s", path), 0);
  const char *k = strstr(flip, "sinks: ");
  assert_non_null(k);
  assert_true(atoi(k + 7) >= 2);
  assert_non_null(strstr(flip, "sites: 5\n"));
  /* the printed witness line and the CSV hold the same numbers */
  const char *w = strstr(tcc_out, "    witness: set #");
  assert_non_null(w);
  char *file = testutil_read_file(path);
  assert_non_null(file);
  const char *tok = strchr(w, ':') + 1;
  tok = strchr(tok, ':') + 1;   /* after "set #N:" */
  for (int i = 0; i < 5; i++) {
    char pt[128];
    assert_int_equal(sscanf(tok, " %127s", pt), 1);
    strcat(pt, "\n");
    assert_non_null(strstr(file, pt));
    tok = strchr(tok + 1, ' ');
    if (tok == NULL) break;
  }
  free(file);
  char svg[1100];
  snprintf(svg, sizeof svg, "%.*s.svg", (int)(strlen(path) - 4), path);
  char *s = testutil_read_file(svg);
  assert_non_null(s);
  assert_true(testutil_count(s, ">sink</text>") >= 2);
  free(s);
  free(flip);
  assert_int_equal(testutil_run("rule R_1 --samples 1000 --quads 100 --site-samples 1000",
                                tcc_out, TCC_BUF, tcc_err, TCC_BUF), 0);
  assert_non_null(strstr(tcc_out, "no counterexample to systematicity in 1000 five-site disc sets"));
  assert_non_null(strstr(tcc_out, "no counterexample to systematicity in 1000 convex hexagons"));
  tcc_refused("rule R_1 --sites disc:17", "--sites N");
  tcc_refused("rule R_1 --sites blob:5", "unknown sampler 'blob'");
}

static int tcc_setup(void **state) {
  (void)state;
  return testutil_run("--version", NULL, 0, NULL, 0) == 0 ? 0 : -1;   /* makes testtmp/ */
}

/* merge checks a census row's sinks as it checks its counts: mean_sinks
** 3 with max_sinks 2 cannot be (issue 17), nor can max_sinks 1 beside a
** multi-sink sample; the same row with mean_sinks 1.5 is merged. */
static void test_merge_census_sinks(void **state) {
  (void)state;
  char path[512];
  testutil_tmppath(path, sizeof path, "tcc_sinks.csv");
  static const char head[] = "measure,joint,rule,sites,sampler,samples,tie,no_sink,one_sink,"
                             "multi_sink,sink_dt,mean_sinks,max_sinks,mean_worst_gap\n";
  static const struct { const char *row; int ok; } rows[] = {
    {"R,1,R_1,5,convex,10,0,0,5,5,5,1.5,2,0\n", 1},
    {"R,1,R_1,5,convex,10,0,0,5,5,5,3,2,0\n", 0},     /* 30 sinks: at most 5 + 5 x 2 */
    {"R,1,R_1,5,convex,10,0,0,5,5,5,1.5,1,0\n", 0},   /* a multi-sink sample, max 1 */
    {"R,1,R_1,5,convex,10,0,0,5,5,5,1.2,2,0\n", 0},   /* 12 sinks: at least 5 + 5 x 2 */
    {"R,1,R_1,5,convex,10,0,10,0,0,0,0,0,\n", 1},
    {"R,1,R_1,5,convex,10,0,10,0,0,0,0,3,\n", 0},      /* no sink anywhere, max 3 */
  };
  char text[512];
  for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
    snprintf(text, sizeof text, "%s%s", head, rows[i].row);
    testutil_write_file(path, text);
    char args[700];
    snprintf(args, sizeof args, "merge %s", path);
    if (rows[i].ok) {
      int rc = testutil_run(args, tcc_out, TCC_BUF, tcc_err, TCC_BUF);
      if (rc != 0) fail_msg("row %zu refused: %s", i, tcc_err);
      assert_string_equal(tcc_out, text);
    } else {
      tcc_refused(args, "inconsistent counts");
    }
  }
  remove(path);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_figure_3_8_cli),
    cmocka_unit_test(test_got_agrees),
    cmocka_unit_test(test_census_pentagons_cli),
    cmocka_unit_test(test_census_bytes),
    cmocka_unit_test(test_bad_input_cli),
    cmocka_unit_test(test_memory_cli),
    cmocka_unit_test(test_rule_catches_neg_R),
    cmocka_unit_test(test_merge_census_sinks),
  };
  return cmocka_run_group_tests(tests, tcc_setup, NULL);
}
