/*
** test_table34_cli.c: `fliplab table34` and `fliplab merge` from the
** outside: the CSV header and one row per rule (the registry's table order,
** then DT); counts consistent and agreeing with the theorems (R_f, DT,
** -alpha_inf always Delaunay; no type IV); bit-identical output for 1 and
** 2 threads; shards merged back byte for byte; text and Markdown layout;
** the scatter plot; and one-line errors with exit status 2 for bad input.
*/
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "measure.h"
#include "rule.h"
#include "joint.h"
#include "report.h"
#include "testutil.h"

#define TT_CAP (1 << 20)
#define TT_HEADER \
  "measure,joint,rule,samples,type_I,type_II,type_III,type_IV,type_V,dt,seed,tie_eps,first,end,total,rules\n"

static char tt_out[TT_CAP], tt_err[TT_CAP];

/* Run `fliplab printf(FMT, ...)` into tt_out and tt_err. */
#define TT_RUN(...) testutil_runf(tt_out, TT_CAP, tt_err, TT_CAP, __VA_ARGS__)

static void tt_path(char *buf, size_t len, const char *name) {
  assert_int_equal(system("mkdir -p " FLIPLAB_BUILD_DIR "/testtmp"), 0);
  testutil_tmppath(buf, len, name);
}

/* Read a counts CSV from the program's stdout through the library reader. */
static int tt_read_counts(const char *text, report_row **rows) {
  char path[512], err[256];
  int n = 0;
  tt_path(path, sizeof path, "counts.csv");
  FILE *f = fopen(path, "wb");
  fputs(text, f);
  fclose(f);
  if (report_csv_read(path, rows, &n, err, sizeof err) != 0) fail_msg("%s", err);
  unlink(path);
  return n;
}

/* stderr is exactly one line. */
static void tt_one_line(void) {
  if (!testutil_one_line(tt_err))
    fail_msg("stderr should be one line: '%s'", tt_err);
}

static const report_row *tt_find(const report_row *rows, int n, const char *rule) {
  for (int i = 0; i < n; i++)
    if (strcmp(rows[i].rule, rule) == 0) return &rows[i];
  fail_msg("rule %s missing", rule);
  return NULL;
}

/* Header, rows in rule_list_triangle's order then DT, and the theorems. */
static void test_csv_rows(void **state) {
  (void)state;
  assert_int_equal(TT_RUN("table34 --samples 1500 --seed 3 --format csv"), 0);
  assert_int_equal(strncmp(tt_out, TT_HEADER, strlen(TT_HEADER)), 0);
  report_row *rows = NULL;
  int n = tt_read_counts(tt_out, &rows);
  rule want[MEASURE_TABLE34_COUNT * JOINT_COUNT];
  int nwant = rule_list_triangle(measure_table34, MEASURE_TABLE34_COUNT, want, 200);
  assert_int_equal(nwant, 120);
  assert_int_equal(n, 121);
  for (int i = 0; i < nwant; i++) {
    assert_string_equal(rows[i].rule, want[i].name);
    assert_string_equal(rows[i].measure, measure_get(want[i].measure)->name);
    assert_string_equal(rows[i].joint, joint_get(want[i].joint)->name);
  }
  assert_string_equal(rows[120].rule, "DT");
  assert_string_equal(rows[120].measure, "");
  for (int i = 0; i < n; i++) {
    assert_int_equal(rows[i].c.samples, 1500);   /* the reader checked the sums */
    assert_int_equal(rows[i].c.type[FLIPGRAPH_IV], 0);   /* theorem 1 */
  }
  /* DT is type I with itself as sink; so is every rule that equals DT on
  ** every convex quadrilateral (R_f: theorem 3, -alpha_inf: theorem 17). */
  static const char *const always_dt[] = {"DT", "R_-inf", "R_-1", "R_0", "R_1", "R_2",
                                          "R_inf", "-alpha_inf"};
  for (size_t k = 0; k < sizeof always_dt / sizeof always_dt[0]; k++) {
    const report_row *r = tt_find(rows, n, always_dt[k]);
    assert_int_equal(r->c.type[FLIPGRAPH_I], 1500);
    assert_int_equal(r->c.dt, 1500);
  }
  /* -A_1 always ties (the two triangulations of a quadrilateral have the
  ** same area), the thesis's first type-V remark. */
  assert_int_equal(tt_find(rows, n, "-A_1")->c.type[FLIPGRAPH_V], 1500);
  free(rows);
}

/* Same seed: the same bytes whatever the thread count. */
static void test_threads_identical(void **state) {
  (void)state;
  assert_int_equal(TT_RUN("table34 --samples 3000 --seed 11 --format csv --threads 1"), 0);
  char *one = strdup(tt_out);
  assert_int_equal(TT_RUN("table34 --samples 3000 --seed 11 --format csv --threads 2"), 0);
  assert_string_equal(one, tt_out);
  free(one);
}

/* Shards 1/4 .. 4/4 (uneven: 2003 is odd) merge into the unsharded CSV. */
static void test_shards_merge(void **state) {
  (void)state;
  char full[512], shard[4][512], merged[512];
  tt_path(full, sizeof full, "full.csv");
  tt_path(merged, sizeof merged, "merged.csv");
  assert_int_equal(TT_RUN("table34 --samples 2003 --seed 9 --format csv --out %s", full), 0);
  uint64_t total = 0;
  for (int k = 0; k < 4; k++) {
    char name[32];
    snprintf(name, sizeof name, "shard%d.csv", k + 1);
    tt_path(shard[k], sizeof shard[k], name);
    assert_int_equal(TT_RUN("table34 --samples 2003 --seed 9 --format csv --shard %d/4 --out %s",
                            k + 1, shard[k]), 0);
    char *s = testutil_read_file(shard[k]);
    report_row *rows = NULL;
    tt_read_counts(s, &rows);
    /* floor(k S / 4) boundaries: 500, 501, 501, 501 */
    uint64_t lo = (uint64_t)k * 2003 / 4, hi = (uint64_t)(k + 1) * 2003 / 4;
    assert_int_equal(rows[0].c.samples, hi - lo);
    total += rows[0].c.samples;
    free(rows);
    free(s);
  }
  assert_int_equal(total, 2003);
  assert_int_equal(TT_RUN("merge %s %s %s %s --out %s", shard[0], shard[1], shard[2], shard[3],
                          merged), 0);
  char *a = testutil_read_file(full), *b = testutil_read_file(merged);
  assert_non_null(a);
  assert_non_null(b);
  assert_string_equal(a, b);
  /* Any order of the shards sums to the same. */
  assert_int_equal(TT_RUN("merge %s %s %s %s", shard[3], shard[1], shard[0], shard[2]), 0);
  assert_string_equal(tt_out, a);
  free(a);
  free(b);

  /* A shard of other rules, or a non-table CSV: refused with the file named. */
  char other[512];
  tt_path(other, sizeof other, "other.csv");
  assert_int_equal(TT_RUN("table34 --samples 100 --measures R,-alpha --format csv --out %s",
                          other), 0);
  assert_int_equal(TT_RUN("merge %s %s", shard[0], other), 2);
  assert_non_null(strstr(tt_err, other));
  FILE *f = fopen(other, "wb");
  fputs("measure,joint,rule,samples,I,II,III,IV,V,dt\nR,-inf,R_-inf,1,1,0,0,0,0,1\n", f);
  fclose(f);
  assert_int_equal(TT_RUN("merge %s %s", shard[0], other), 2);
  assert_non_null(strstr(tt_err, other));
  assert_non_null(strstr(tt_err, "line 1"));
  tt_one_line();
  f = fopen(other, "wb");
  fputs("measure,joint,rule,samples,type_I,type_II,type_III,type_IV,type_V,dt\n"
        "R,-inf,R_-inf,1,1,0,0,0,0,1\nR,-1,R_-1,1,1,0,0\n", f);
  fclose(f);
  assert_int_equal(TT_RUN("merge %s", other), 2);
  assert_non_null(strstr(tt_err, "line 3"));
  tt_one_line();
  for (int k = 0; k < 4; k++) unlink(shard[k]);
  unlink(full);
  unlink(merged);
  unlink(other);
}

/* Text and Markdown: the header facts, all 20 measures, six joint blocks. */
static void test_text_md(void **state) {
  (void)state;
  static const char *const joints[6] = {"l_-inf ", "l_-1 ", "l_0 ", "l_1 ", "l_2 ", "l_inf "};
  for (int md = 0; md < 2; md++) {
    assert_int_equal(TT_RUN("table34 --samples 400 --seed 2 --tie-eps 1e-10 --format %s",
                            md ? "md" : "text"), 0);
    assert_non_null(strstr(tt_out, "samples: 400"));
    assert_non_null(strstr(tt_out, "seed: 2"));
    assert_non_null(strstr(tt_out, "tie tolerance: 1e-10"));
    assert_non_null(strstr(tt_out, "iteration method, unit disc"));
    assert_non_null(strstr(tt_out, FLIPLAB_VERSION));
    for (int i = 0; i < MEASURE_TABLE34_COUNT; i++) {
      char key[80];
      snprintf(key, sizeof key, md ? "`%s`" : " %s", measure_get(measure_table34[i])->name);
      if (strstr(tt_out, key) == NULL) fail_msg("measure %s missing", key);
    }
    /* The thesis's layout: one block per joint, all 20 measures side by side. */
    for (int j = 0; j < 6; j++) assert_int_equal(testutil_count(tt_out, joints[j]), 1);
    assert_null(strstr(tt_out, "Measures 1-"));
    assert_non_null(strstr(tt_out, "Type V"));
    assert_non_null(strstr(tt_out, "-A_1"));
    assert_non_null(strstr(tt_out, "Type IV (no sink): none"));
  }
  /* --columns 10 splits the text into two groups of ten measures. */
  assert_int_equal(TT_RUN("table34 --samples 400 --seed 2 --columns 10"), 0);
  for (int j = 0; j < 6; j++) assert_int_equal(testutil_count(tt_out, joints[j]), 2);
  assert_non_null(strstr(tt_out, "Measures 1-10 of 20"));
  assert_non_null(strstr(tt_out, "Measures 11-20 of 20"));
}

/* --measures: a list, and "all" (every registered measure). */
static void test_measures_option(void **state) {
  (void)state;
  report_row *rows = NULL;
  assert_int_equal(TT_RUN("table34 --samples 50 --measures R,-alpha --format csv"), 0);
  assert_int_equal(tt_read_counts(tt_out, &rows), 2 * 6 + 1);
  free(rows);
  assert_int_equal(TT_RUN("table34 --samples 50 --measures all --format csv"), 0);
  int n = tt_read_counts(tt_out, &rows);
  int ids[MEASURE_MAX], nm = measure_count();
  for (int i = 0; i < nm; i++) ids[i] = i;
  rule all[MEASURE_MAX * JOINT_COUNT];
  assert_int_equal(n, rule_list_triangle(ids, nm, all, MEASURE_MAX * JOINT_COUNT) + 1);
  free(rows);
  assert_int_equal(TT_RUN("table34 --samples 50 --measures R,nosuch"), 2);
  assert_non_null(strstr(tt_err, "nosuch"));
}

/* --rules: the rules as given, counted as in the --measures run; refused
** beside --measures. */
static void test_rules_option(void **state) {
  (void)state;
  report_row *rows = NULL, *all = NULL;
  assert_int_equal(TT_RUN("table34 --samples 300 --seed 3 --rules 'R_1, -alpha_inf,DT' "
                          "--format csv"), 0);
  assert_int_equal(tt_read_counts(tt_out, &rows), 3);
  assert_string_equal(rows[0].rule, "R_1");
  assert_string_equal(rows[1].rule, "-alpha_inf");
  assert_string_equal(rows[2].rule, "DT");
  assert_int_equal(TT_RUN("table34 --samples 300 --seed 3 --measures R,-alpha --format csv"), 0);
  int n = tt_read_counts(tt_out, &all);
  for (int i = 0; i < 3; i++) {
    const report_row *w = tt_find(all, n, rows[i].rule);
    assert_non_null(w);
    assert_memory_equal(&w->c, &rows[i].c, sizeof w->c);
  }
  free(rows);
  free(all);
  assert_int_equal(TT_RUN("table34 --samples 10 --rules R_1 --measures R"), 2);
  tt_one_line();
  assert_int_equal(TT_RUN("table34 --samples 10 --rules R_1,nosuch_1"), 2);
  tt_one_line();
  assert_non_null(strstr(tt_err, "nosuch"));
}

/* s with the five XML specials escaped, as every SVG of fliplab writes
** text (an independent spelling: reports/svg.c is what is tested). */
static void tt_xml(char *buf, size_t len, const char *s) {
  static const char *const special = "&<>\"'";
  static const char *const entity[] = {"&amp;", "&lt;", "&gt;", "&quot;", "&apos;"};
  size_t n = 0;
  buf[0] = '\0';
  for (; *s && n + 7 < len; s++) {
    const char *e = strchr(special, *s);
    if (e != NULL) n += (size_t)snprintf(buf + n, len - n, "%s", entity[e - special]);
    else buf[n++] = *s, buf[n] = '\0';
  }
}

/* The plot names every rule without type V in a hover title, and no other. */
static void test_plot(void **state) {
  (void)state;
  char svg[512];
  tt_path(svg, sizeof svg, "plot.svg");
  assert_int_equal(TT_RUN("table34 --samples 300 --format csv --plot %s", svg), 0);
  report_row *rows = NULL;
  int n = tt_read_counts(tt_out, &rows);
  char *s = testutil_read_file(svg);
  assert_non_null(s);
  assert_non_null(strstr(s, "<svg"));
  assert_non_null(strstr(s, "</svg>"));
  for (int i = 0; i < n; i++) {
    char a[300], b[300], name[256];   /* room for the name and its suffix */
    tt_xml(name, sizeof name, rows[i].rule);   /* the name as the SVG spells it */
    snprintf(a, sizeof a, ">%s: type I", name);
    snprintf(b, sizeof b, "\n%s: type I", name);
    int named = strstr(s, a) != NULL || strstr(s, b) != NULL;
    if (named != (rows[i].c.type[FLIPGRAPH_V] == 0))
      fail_msg("rule %s: named %d, type V %llu", rows[i].rule, named,
               (unsigned long long)rows[i].c.type[FLIPGRAPH_V]);
  }
  free(s);
  free(rows);
  unlink(svg);
}

/* --help exits 0; bad values and unknown options: one line, status 2. */
/* Sizes in scientific notation mean the same integer: --samples 1.5e3
** gives the same bytes as --samples 1500. */
static void test_scientific_sizes(void **state) {
  (void)state;
  assert_int_equal(TT_RUN("table34 --samples 1500 --seed 3 --format csv"), 0);
  char *plain = strdup(tt_out);
  assert_int_equal(TT_RUN("table34 --samples 1.5e3 --seed 3 --format csv"), 0);
  assert_string_equal(plain, tt_out);
  free(plain);
}

static void test_usage_errors(void **state) {
  (void)state;
  static const char *const helps[] = {"table34 --help", "merge --help", "sample --help",
                                      "classify --help"};
  for (size_t i = 0; i < sizeof helps / sizeof helps[0]; i++) {
    assert_int_equal(TT_RUN("%s", helps[i]), 0);
    assert_non_null(strstr(tt_out, "usage: fliplab"));
  }
  static const char *const bad[] = {
    "table34 --samples 0", "table34 --samples 1000000000001", "table34 --samples -5",
    "table34 --samples 1.5", "table34 --threads 0", "table34 --threads 1025",
    "table34 --shard 5/4", "table34 --shard 0/4", "table34 --shard 2", "table34 --shard a/b",
    "table34 --format xml", "table34 --tie-eps nan", "table34 --tie-eps -1",
    "table34 --bogus", "table34 --columns 0", "table34 --seed", "table34 --measures ,", "merge",
    "merge --bogus x.csv", "merge /nonexistent/x.csv", "sample --count 0", "sample --what",
    "classify", "classify --input /nonexistent.csv", "classify --rule nosuch --input x",
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    int st = TT_RUN("%s", bad[i]);
    if (st != 2 || !testutil_one_line(tt_err) || strncmp(tt_err, "fliplab ", 8) != 0)
      fail_msg("'%s': status %d, stderr '%s' (want 2 and one line)", bad[i], st, tt_err);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_csv_rows),
    cmocka_unit_test(test_threads_identical),
    cmocka_unit_test(test_shards_merge),
    cmocka_unit_test(test_text_md),
    cmocka_unit_test(test_measures_option),
    cmocka_unit_test(test_rules_option),
    cmocka_unit_test(test_plot),
    cmocka_unit_test(test_scientific_sizes),
    cmocka_unit_test(test_usage_errors),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
