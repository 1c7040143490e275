/*
** test_table34_sampler.c: `fliplab table34 --sampler` and the pentagon
** samplers behind it (sampler_pentagons_table, flipgraph_run.sampler).
** Library: every sampler gives strictly convex anticlockwise pentagons
** starting at their lexicographically smallest vertex, a function of
** (seed, index) alone; the tally with a sampler equals a plain loop over
** flipgraph_classify of that sampler's pentagons.  Program: no --sampler
** and --sampler iteration give the same bytes; every sampler's CSV has
** consistent counts summing to --samples, DT always type I and Delaunay,
** the sampler column on every row, the same bytes for 1 and 2 threads;
** merge refuses such CSVs; an unknown sampler is a one-line error with a
** "did you mean".
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

#include "measure.h"
#include "rule.h"
#include "flipgraph.h"
#include "sampler.h"
#include "testutil.h"

#define TS_CAP (1 << 20)
#define TS_EPS RULE_DEFAULT_TIE_EPS
#define TS_MAXRULES (MEASURE_MAX * 6 + 1)

static char ts_out[TS_CAP], ts_err[TS_CAP];
#define TS_RUN(...) testutil_runf(ts_out, TS_CAP, ts_err, TS_CAP, __VA_ARGS__)

/* ---- library ------------------------------------------------------------- */

/* Strictly convex (every consecutive triple turns left, exactly), lex-first
** start, and the same pentagon when drawn again. */
static void test_samplers_convex(void **state) {
  (void)state;
  for (int k = 0; k < SAMPLER_PENTAGONS_COUNT; k++) {
    const sampler_pentagons *s = &sampler_pentagons_table[k];
    assert_ptr_equal(sampler_pentagons_find(s->name), s);
    for (uint64_t i = 0; i < 2000; i++) {
      geom_point v[5], w[5];
      assert_int_equal(s->draw(42, i, v), 0);
      for (int j = 0; j < 5; j++) {
        assert_true(geom_orient(v[j], v[(j + 1) % 5], v[(j + 2) % 5]) > 0);
        if (j > 0) assert_true(geom_lexless(v[0], v[j]));
      }
      assert_int_equal(s->draw(42, i, w), 0);
      assert_memory_equal(v, w, sizeof v);
    }
  }
  assert_null(sampler_pentagons_find("disc"));
  assert_null(sampler_pentagons_find(""));
}

/* p strictly inside triangle abc (exact)? */
static int ts_inside(geom_point p, geom_point a, geom_point b, geom_point c) {
  int o = geom_orient(a, b, c);
  return geom_orient(a, b, p) == o && geom_orient(b, c, p) == o && geom_orient(c, a, p) == o;
}

/* The first five disc points of stream (seed, i) in convex position: no
** point inside a triangle of the others (none is on a segment: continuous). */
static int ts_first_five_convex(uint64_t seed, uint64_t i) {
  sampler_rng g;
  geom_point p[5];
  sampler_seed(&g, seed, i);
  for (int k = 0; k < 5; k++) p[k] = sampler_disc(&g);
  for (int q = 0; q < 5; q++)
    for (int a = 0; a < 5; a++)
      for (int b = a + 1; b < 5; b++)
        for (int c = b + 1; c < 5; c++)
          if (q != a && q != b && q != c && ts_inside(p[q], p[a], p[b], p[c])) return 0;
  return 1;
}

/* iteration is sampler_pentagon; vector and circle draw other pentagons.
** disc-hull shares iteration's stream, so the two coincide exactly on the
** samples whose first five points are in convex position (docs/sampling.md). */
static void test_samplers_distinct(void **state) {
  (void)state;
  geom_point v[5], w[5];
  sampler_pentagon(7, 3, v);
  assert_int_equal(sampler_pentagons_find("iteration")->draw(7, 3, w), 0);
  assert_memory_equal(v, w, sizeof v);
  for (int k = 1; k < 3; k++) {
    assert_int_equal(sampler_pentagons_table[k].draw(7, 3, w), 0);
    assert_memory_not_equal(v, w, sizeof v);
  }
  int same = 0;
  for (uint64_t i = 0; i < 2000; i++) {
    sampler_pentagon(7, i, v);
    assert_int_equal(sampler_pentagons_find("disc-hull")->draw(7, i, w), 0);
    int eq = memcmp(v, w, sizeof v) == 0;
    assert_int_equal(eq, ts_first_five_convex(7, i));
    same += eq;
  }
  print_message("disc-hull = iteration on %d of 2000 samples\n", same);
  assert_true(same > 0 && same < 2000);
  /* disc-hull and iteration stay in the unit disc; circle is on it. */
  for (uint64_t i = 0; i < 500; i++) {
    assert_int_equal(sampler_pentagons_find("disc-hull")->draw(1, i, w), 0);
    for (int j = 0; j < 5; j++) assert_true(w[j].x * w[j].x + w[j].y * w[j].y < 1);
    assert_int_equal(sampler_pentagons_find("circle")->draw(1, i, w), 0);
    for (int j = 0; j < 5; j++)
      TESTUTIL_NEAR(w[j].x * w[j].x + w[j].y * w[j].y, 1.0, 0, 1e-15);
  }
}

/* The tally with run.sampler equals a plain loop over flipgraph_classify of
** that sampler's pentagons, for 1 and 2 threads. */
static void test_tally_with_sampler(void **state) {
  (void)state;
  static rule rules[TS_MAXRULES];
  int ids[MEASURE_MAX], nm = measure_count();
  for (int i = 0; i < nm; i++) ids[i] = i;
  int n = rule_list_triangle(ids, nm, rules, TS_MAXRULES - 1);
  rules[n++] = rule_delaunay();
  const uint64_t seed = 5, first = 100, count = 2500;
  for (int k = 1; k < SAMPLER_PENTAGONS_COUNT; k++) {
    const sampler_pentagons *s = &sampler_pentagons_table[k];
    static flipgraph_counts tally[2][TS_MAXRULES], loop[TS_MAXRULES];
    memset(tally, 0, sizeof tally);
    memset(loop, 0, sizeof loop);
    for (int t = 0; t < 2; t++) {
      flipgraph_run run = {.seed = seed, .first = first, .count = count, .tie_eps = TS_EPS,
                           .threads = t + 1, .sampler = s->draw};
      assert_int_equal(flipgraph_tally_run(rules, n, &run, tally[t]), 0);
    }
    for (uint64_t i = first; i < first + count; i++) {
      geom_point v[5];
      assert_int_equal(s->draw(seed, i, v), 0);
      flipgraph_pentagon p;
      flipgraph_prepare(&p, v);
      for (int r = 0; r < n; r++) {
        flipgraph g;
        flipgraph_classify(&p, &rules[r], TS_EPS, &g);
        loop[r].samples++;
        loop[r].type[g.type]++;
        loop[r].dt += (uint64_t)g.delaunay;
      }
    }
    for (int r = 0; r < n; r++) {
      assert_memory_equal(&tally[0][r], &loop[r], sizeof loop[r]);
      assert_memory_equal(&tally[1][r], &loop[r], sizeof loop[r]);
    }
    /* DT: one sink, the Delaunay triangulation (exact predicates). */
    assert_int_equal(loop[n - 1].dt, count);
  }
}

/* ---- program ------------------------------------------------------------- */

static void test_default_is_iteration(void **state) {
  (void)state;
  static const char *const fmt[] = {"csv", "text", "md"};
  for (int f = 0; f < 3; f++) {
    assert_int_equal(TS_RUN("table34 --samples 1500 --seed 4 --format %s", fmt[f]), 0);
    char *plain = strdup(ts_out);
    assert_int_equal(TS_RUN("table34 --samples 1500 --seed 4 --format %s --sampler iteration",
                            fmt[f]), 0);
    assert_string_equal(plain, ts_out);
    free(plain);
  }
  assert_null(strstr(ts_out, "sampler,"));
}

/* Field `col` (0-based) of a CSV line without quotes, as a number. */
static unsigned long long ts_field(const char *line, int col) {
  for (int c = 0; c < col; c++) line = strchr(line, ',') + 1;
  return strtoull(line, NULL, 10);
}

/* Every row: types sum to samples = S, dt <= type_I, last field the
** sampler; DT's row all type I and Delaunay; count rows. */
static int ts_check_csv(const char *csv, const char *name, unsigned long long S) {
  const char *line = strchr(csv, '\n');
  assert_non_null(line);
  assert_true(strncmp(line - 8, ",sampler", 8) == 0);
  int rows = 0;
  for (line++; *line; line = strchr(line, '\n') + 1, rows++) {
    const char *end = strchr(line, '\n');
    assert_non_null(end);
    size_t len = strlen(name);
    assert_true(end - line > (ptrdiff_t)len && line[end - line - len - 1] == ',');
    assert_memory_equal(end - len, name, len);
    unsigned long long sum = 0;
    for (int t = 0; t < 5; t++) sum += ts_field(line, 4 + t);
    assert_int_equal(ts_field(line, 3), S);
    assert_int_equal(sum, S);
    assert_true(ts_field(line, 9) <= ts_field(line, 4));
    assert_int_equal(ts_field(line, 7), 0);   /* no type IV (theorem 1) */
    if (strncmp(line, ",,DT,", 5) == 0) {
      assert_int_equal(ts_field(line, 4), S);
      assert_int_equal(ts_field(line, 9), S);
    }
  }
  return rows;
}

static void test_each_sampler_csv(void **state) {
  (void)state;
  static const char *const names[] = {"vector", "circle", "disc-hull"};
  for (int k = 0; k < 3; k++) {
    assert_int_equal(TS_RUN("table34 --samples 2100 --seed 3 --sampler %s --format csv "
                            "--threads 1", names[k]), 0);
    assert_int_equal(ts_check_csv(ts_out, names[k], 2100), 121);
    char *one = strdup(ts_out);
    assert_int_equal(TS_RUN("table34 --samples 2100 --seed 3 --sampler %s --format csv "
                            "--threads 2", names[k]), 0);
    assert_string_equal(one, ts_out);
    free(one);
    assert_int_equal(TS_RUN("table34 --samples 300 --sampler %s --measures R", names[k]), 0);
    char want[64];
    snprintf(want, sizeof want, "sampler: %s;", names[k]);
    assert_non_null(strstr(ts_out, want));
  }
}

/* A shard of a non-iteration run: merge refuses it, in one line. */
static void test_merge_refuses(void **state) {
  (void)state;
  char a[512], b[512];
  assert_int_equal(system("mkdir -p " FLIPLAB_BUILD_DIR "/testtmp"), 0);
  testutil_tmppath(a, sizeof a, "vec1.csv");
  testutil_tmppath(b, sizeof b, "vec2.csv");
  assert_int_equal(TS_RUN("table34 --samples 1000 --sampler vector --shard 1/2 --format csv "
                          "--measures R --out %s", a), 0);
  assert_int_equal(TS_RUN("table34 --samples 1000 --sampler vector --shard 2/2 --format csv "
                          "--measures R --out %s", b), 0);
  assert_int_equal(TS_RUN("merge %s %s", a, b), 2);
  assert_true(testutil_one_line(ts_err));
  assert_non_null(strstr(ts_err, "--sampler"));
  remove(a);
  remove(b);
}

static void test_bad_sampler(void **state) {
  (void)state;
  assert_int_equal(TS_RUN("table34 --sampler vectr"), 2);
  assert_true(testutil_one_line(ts_err));
  assert_non_null(strstr(ts_err, "did you mean 'vector'"));
  assert_int_equal(TS_RUN("table34 --sampler disc_hull"), 2);
  assert_non_null(strstr(ts_err, "did you mean 'disc-hull'"));
  assert_int_equal(TS_RUN("table34 --sampler qqqqqqqq"), 2);
  assert_true(testutil_one_line(ts_err));
  assert_non_null(strstr(ts_err, "iteration, vector, circle, disc-hull"));
  assert_int_equal(TS_RUN("table34 --sampler"), 2);
  assert_true(testutil_one_line(ts_err));
  assert_int_equal(TS_RUN("table34 --help"), 0);
  assert_non_null(strstr(ts_out, "--sampler"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_samplers_convex),
    cmocka_unit_test(test_samplers_distinct),
    cmocka_unit_test(test_tally_with_sampler),
    cmocka_unit_test(test_default_is_iteration),
    cmocka_unit_test(test_each_sampler_csv),
    cmocka_unit_test(test_merge_refuses),
    cmocka_unit_test(test_bad_sampler),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
