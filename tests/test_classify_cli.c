/*
** test_classify_cli.c: `fliplab sample` and `fliplab classify` from the
** outside.  sample writes the sampler's pentagons bit for bit; classify
** on them reproduces table34's counts for the same seed (two independent
** paths through the engine); every output row is consistent with the
** classification spec re-derived here from its decision letters; the
** result does not depend on orientation or on which vertex comes first
** (up to the documented renumbering); bad rows are refused by line number.
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

#include "sampler.h"
#include "report.h"
#include "testutil.h"

#define TC_CAP (1 << 20)
#define TC_N 600
#define TC_SEED 21

static char tc_out[TC_CAP], tc_err[TC_CAP];

/* Run `fliplab printf(FMT, ...)` into tc_out and tc_err. */
#define TC_RUN(...) testutil_runf(tc_out, TC_CAP, tc_err, TC_CAP, __VA_ARGS__)

static void tc_path(char *buf, size_t len, const char *name) {
  assert_int_equal(system("mkdir -p " FLIPLAB_BUILD_DIR "/testtmp"), 0);
  testutil_tmppath(buf, len, name);
}

/* One output row of classify. */
typedef struct tc_row {
  int id;
  char rule[96];
  char dec[8];
  int type;           /* 0..4 for I..V */
  int nsinks, sink[2];
  int dt;
} tc_row;

typedef struct tc_rows {
  tc_row *r;
  int n, cap;
  int header;
} tc_rows;

static int tc_type(const char *s) {
  static const char *const names[5] = {"I", "II", "III", "IV", "V"};
  for (int t = 0; t < 5; t++)
    if (strcmp(s, names[t]) == 0) return t;
  fail_msg("bad type '%s'", s);
  return -1;
}

static int tc_collect(char **f, const size_t *len, int nf, uint64_t line, void *ctx) {
  (void)len;
  tc_rows *rs = ctx;
  assert_int_equal(nf, 6);
  if (!rs->header) {
    rs->header = 1;
    const char *want[6] = {"id", "rule", "decisions", "type", "sink", "dt"};
    for (int i = 0; i < 6; i++) assert_string_equal(f[i], want[i]);
    return 0;
  }
  (void)line;
  if (rs->n == rs->cap) {
    rs->cap = rs->cap ? 2 * rs->cap : 4096;
    rs->r = realloc(rs->r, (size_t)rs->cap * sizeof *rs->r);
  }
  tc_row *r = &rs->r[rs->n++];
  memset(r, 0, sizeof *r);
  r->id = atoi(f[0]);
  snprintf(r->rule, sizeof r->rule, "%s", f[1]);
  assert_int_equal(strlen(f[2]), 5);
  strcpy(r->dec, f[2]);
  r->type = tc_type(f[3]);
  r->nsinks = sscanf(f[4], "%d %d", &r->sink[0], &r->sink[1]);
  if (r->nsinks < 0) r->nsinks = 0;
  r->dt = atoi(f[5]);
  return 0;
}

static tc_rows tc_read(const char *path) {
  tc_rows rs = {0};
  char err[256];
  FILE *f = fopen(path, "rb");
  assert_non_null(f);
  if (report_csv_each(f, tc_collect, &rs, err, sizeof err) != 0) fail_msg("%s", err);
  fclose(f);
  return rs;
}

/* The spec, from the decision letters alone: Q_j decides the edge
** T_{j+1} - T_{j-1}, A pointing it at T_{j+1}, B at T_{j-1}.  T_i is a sink
** when both its edges point at it; with one sink, type I iff the source
** is two steps from it on the cycle T0 T2 T4 T1 T3 (position 3i mod 5). */
static void tc_check_spec(const tc_row *r) {
  if (strchr(r->dec, 'E') != NULL) {
    assert_int_equal(r->type, 4);
    return;
  }
  int in[5] = {0}, out[5] = {0};
  for (int j = 0; j < 5; j++) {
    int to = r->dec[j] == 'A' ? (j + 1) % 5 : (j + 4) % 5;
    int from = r->dec[j] == 'A' ? (j + 4) % 5 : (j + 1) % 5;
    in[to]++;
    out[from]++;
  }
  int sinks[5], ns = 0, source = -1;
  for (int i = 0; i < 5; i++) {
    if (out[i] == 0) sinks[ns++] = i;
    if (in[i] == 0) source = i;
  }
  assert_int_equal(r->nsinks, ns);
  for (int s = 0; s < ns; s++) assert_int_equal(r->sink[s], sinks[s]);
  if (ns == 0) assert_int_equal(r->type, 3);
  else if (ns == 2) assert_int_equal(r->type, 2);
  else {
    int d = ((3 * sinks[0] - 3 * source) % 5 + 5) % 5;
    if (d > 5 - d) d = 5 - d;
    assert_int_equal(r->type, d == 2 ? 0 : 1);
  }
}

static char tc_pent[512], tc_cls[512];

static int tc_setup(void **state) {
  (void)state;
  tc_path(tc_pent, sizeof tc_pent, "pent.csv");
  tc_path(tc_cls, sizeof tc_cls, "cls.csv");
  if (TC_RUN("sample --count %d --seed %d --out %s", TC_N, TC_SEED, tc_pent) != 0) return -1;
  if (TC_RUN("classify --input %s --out %s", tc_pent, tc_cls) != 0) return -1;
  return 0;
}

static int tc_teardown(void **state) {
  (void)state;
  unlink(tc_pent);
  unlink(tc_cls);
  return 0;
}

/* sample writes sampler_pentagon(seed, i) exactly. */
static void test_sample_exact(void **state) {
  (void)state;
  FILE *f = fopen(tc_pent, "rb");
  char line[64];
  assert_non_null(fgets(line, sizeof line, f));
  assert_string_equal(line, "x1,y1,x2,y2,x3,y3,x4,y4,x5,y5\n");
  rewind(f);
  geom_point *v = NULL;
  size_t n = 0, rev = 0;
  char err[256];
  assert_int_equal(report_pentagon_read(f, "pent.csv", &v, &n, &rev, err, sizeof err), 0);
  fclose(f);
  assert_int_equal(n, TC_N);
  assert_int_equal(rev, 0);   /* the sampler's pentagons are anticlockwise */
  for (size_t i = 0; i < n; i++) {
    geom_point w[5];
    sampler_pentagon(TC_SEED, i, w);
    assert_memory_equal(v + 5 * i, w, sizeof w);
  }
  free(v);
}

/* Classified rows summed per rule = table34's CSV for the same seed. */
static void test_matches_table34(void **state) {
  (void)state;
  tc_rows rs = tc_read(tc_cls);
  assert_int_equal(TC_RUN("table34 --samples %d --seed %d --format csv", TC_N, TC_SEED), 0);
  char path[512], err[256];
  tc_path(path, sizeof path, "t34.csv");
  FILE *f = fopen(path, "wb");
  fputs(tc_out, f);
  fclose(f);
  report_row *t = NULL;
  int nt = 0;
  assert_int_equal(report_csv_read(path, &t, &nt, err, sizeof err), 0);
  unlink(path);
  assert_int_equal(nt, 121);
  assert_int_equal(rs.n, TC_N * nt);
  uint64_t (*sum)[6] = calloc((size_t)nt, sizeof *sum);
  for (int k = 0; k < rs.n; k++) {
    const tc_row *r = &rs.r[k];
    int rule = k % nt;
    assert_int_equal(r->id, k / nt + 1);
    assert_string_equal(r->rule, t[rule].rule);   /* same rules, same order */
    sum[rule][r->type]++;
    sum[rule][5] += (uint64_t)r->dt;
  }
  for (int i = 0; i < nt; i++) {
    for (int ty = 0; ty < 5; ty++)
      if (sum[i][ty] != t[i].c.type[ty])
        fail_msg("%s type %d: classify %llu, table34 %llu", t[i].rule, ty,
                 (unsigned long long)sum[i][ty], (unsigned long long)t[i].c.type[ty]);
    assert_int_equal(sum[i][5], t[i].c.dt);
  }
  free(sum);
  free(t);
  free(rs.r);
}

/* Each row agrees with the spec; dt = type I with DT's sink. */
static void test_rows_follow_spec(void **state) {
  (void)state;
  tc_rows rs = tc_read(tc_cls);
  const int nr = 121;
  for (int p = 0; p < TC_N; p++) {
    const tc_row *dt = &rs.r[p * nr + nr - 1];
    assert_string_equal(dt->rule, "DT");
    assert_int_equal(dt->type, 0);
    assert_int_equal(dt->dt, 1);
    for (int k = 0; k < nr; k++) {
      const tc_row *r = &rs.r[p * nr + k];
      tc_check_spec(r);
      assert_int_equal(r->dt, r->type == 0 && r->sink[0] == dt->sink[0]);
    }
  }
  free(rs.r);
}

/* Write the sampled pentagons with the vertices in the order perm[]. */
static void tc_write_permuted(const char *path, const int perm[5], int header) {
  FILE *f = fopen(path, "wb");
  if (header) report_pentagon_header(f);
  for (int i = 0; i < TC_N; i++) {
    geom_point v[5], w[5];
    sampler_pentagon(TC_SEED, (uint64_t)i, v);
    for (int k = 0; k < 5; k++) w[k] = v[perm[k]];
    report_pentagon_write(f, w);
  }
  fclose(f);
}

/* Clockwise p1 p5 p4 p3 p2 is reversed back to p1..p5: identical output.
** Fully reversed p5..p1 becomes p5 p1 p2 p3 p4, a rotation: the same types
** and dt, sinks shifted by one, decisions rotated by one. */
static void test_orientation(void **state) {
  (void)state;
  char in[512], out[512];
  tc_path(in, sizeof in, "cw.csv");
  tc_path(out, sizeof out, "cw_out.csv");
  static const int cw[5] = {0, 4, 3, 2, 1}, rev[5] = {4, 3, 2, 1, 0};
  tc_write_permuted(in, cw, 0);   /* and no header line */
  assert_int_equal(TC_RUN("classify --input %s --out %s", in, out), 0);
  char *a = testutil_read_file(tc_cls), *b = testutil_read_file(out);
  assert_string_equal(a, b);
  free(a);
  free(b);

  tc_write_permuted(in, rev, 1);
  assert_int_equal(TC_RUN("classify --input %s --out %s", in, out), 0);
  tc_rows x = tc_read(tc_cls), y = tc_read(out);
  assert_int_equal(x.n, y.n);
  for (int k = 0; k < x.n; k++) {
    const tc_row *r = &x.r[k], *s = &y.r[k];
    assert_string_equal(r->rule, s->rule);
    assert_int_equal(r->type, s->type);
    assert_int_equal(r->dt, s->dt);
    for (int j = 0; j < 5; j++) assert_int_equal(s->dec[j], r->dec[(j + 4) % 5]);
    assert_int_equal(r->nsinks, s->nsinks);
    int want[2] = {(r->sink[0] + 1) % 5, (r->sink[1] + 1) % 5};
    if (r->nsinks == 2 && want[0] > want[1]) {
      int t = want[0];
      want[0] = want[1];
      want[1] = t;
    }
    for (int i = 0; i < r->nsinks; i++) assert_int_equal(s->sink[i], want[i]);
  }
  free(x.r);
  free(y.r);
  unlink(in);
  unlink(out);
}

/* --rule picks rules in order; CRLF line ends and blank lines are fine. */
static void test_rules_and_input(void **state) {
  (void)state;
  char in[512];
  tc_path(in, sizeof in, "crlf.csv");
  FILE *f = fopen(in, "wb");
  fputs("x1,y1,x2,y2,x3,y3,x4,y4,x5,y5\r\n\r\n0,0,1,0,1.5,0.5,1,1.1,0,1.3\r\n"
        "0,0,1,0,1.5,0.5,1,1,0,1.2\r\n", f);
  fclose(f);
  assert_int_equal(TC_RUN("classify --rule R_inf --rule DT --rule -alpha_inf --input %s", in), 0);
  tc_rows rs = {0};
  FILE *m = tmpfile();
  fputs(tc_out, m);
  rewind(m);
  char err[256];
  assert_int_equal(report_csv_each(m, tc_collect, &rs, err, sizeof err), 0);
  fclose(m);
  assert_int_equal(rs.n, 6);
  static const char *const want[3] = {"R_inf", "DT", "-alpha_inf"};
  for (int k = 0; k < 6; k++) {
    assert_int_equal(rs.r[k].id, k / 3 + 1);
    assert_string_equal(rs.r[k].rule, want[k % 3]);
    /* All three are the Delaunay rule on convex quadrilaterals (theorems 3,
    ** 17), here on a pentagon with no four cocircular points. */
    assert_string_equal(rs.r[k].dec, rs.r[k / 3 * 3 + 1].dec);
  }
  free(rs.r);
  unlink(in);
}

/* Bad rows: status 2, one line naming the line number and the problem. */
static void test_bad_rows(void **state) {
  (void)state;
  static const struct { const char *row, *want; } bad[] = {
    {"0,0,1,0,1.5,0.5,1,1,0\n", "got 9 fields"},
    {"0,0,1,0,1.5,zero,1,1,0,1\n", "not a number"},
    {"0,0,1,0,1.5,0.5,1,nan,0,1\n", "not finite"},
    {"0,0,1,0,1.5,0.5,1,1,1,0\n", "duplicate"},
    {"0,0,1,0,2,0,1,1,0,1\n", "collinear"},
    {"0,0,2,0,1,0.5,2,2,0,2\n", "not convex"},
  };
  char in[512];
  tc_path(in, sizeof in, "bad.csv");
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    FILE *f = fopen(in, "wb");
    fputs("x1,y1,x2,y2,x3,y3,x4,y4,x5,y5\n0,0,1,0,1.5,0.5,1,1,0,1\n"
          "0,0,1,0,1.5,0.5,1,1,0,1.2\n", f);
    fputs(bad[i].row, f);
    fclose(f);
    int st = TC_RUN("classify --input %s", in);
    if (st != 2 || strstr(tc_err, "line 4") == NULL || strstr(tc_err, bad[i].want) == NULL ||
        !testutil_one_line(tc_err))
      fail_msg("row '%s': status %d, stderr '%s'", bad[i].row, st, tc_err);
    assert_string_equal(tc_out, "");   /* nothing written before the check */
  }
  unlink(in);
}

/* A failing classify writes no row to standard output: a user measure's
** NaN or a plugin rule's bad answer met after good rows, and a bad row on
** standard input (read once) after good ones. */
static void test_fails_quietly(void **state) {
  (void)state;
  int st = TC_RUN("--define 'q >= 0 : sqrt(1.6 - a)' classify --input %s --rule q_1", tc_pent);
  assert_int_equal(st, 1);
  assert_string_equal(tc_out, "");
  assert_non_null(strstr(tc_err, "not finite"));
  assert_true(testutil_one_line(tc_err));
  st = TC_RUN("--plugin " FLIPLAB_BUILD_DIR "/plugins/badret.so classify --input %s --rule badret",
              tc_pent);
  assert_int_equal(st, 1);
  assert_string_equal(tc_out, "");
  assert_non_null(strstr(tc_err, "returned 7"));
  char in[512];
  tc_path(in, sizeof in, "badstdin.csv");
  FILE *f = fopen(in, "wb");
  fputs("x1,y1,x2,y2,x3,y3,x4,y4,x5,y5\n0,0,1,0,1.5,0.5,1,1,0,1\n0,0,1,1\n", f);
  fclose(f);
  st = testutil_run_in(in, "classify --input -", tc_out, TC_CAP, tc_err, TC_CAP);
  assert_int_equal(st, 2);
  assert_string_equal(tc_out, "");
  assert_non_null(strstr(tc_err, "line 3"));
  st = testutil_run_in(tc_pent, "classify --input - --rule DT", tc_out, TC_CAP, tc_err, TC_CAP);
  assert_int_equal(st, 0);
  assert_non_null(strstr(tc_out, "id,rule,decisions,type,sink,dt\n1,DT,"));
  unlink(in);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_sample_exact),
    cmocka_unit_test(test_matches_table34),
    cmocka_unit_test(test_rows_follow_spec),
    cmocka_unit_test(test_orientation),
    cmocka_unit_test(test_rules_and_input),
    cmocka_unit_test(test_bad_rows),
    cmocka_unit_test(test_fails_quietly),
  };
  return cmocka_run_group_tests(tests, tc_setup, tc_teardown);
}
