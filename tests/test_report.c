/*
** test_report.c: the reports module on its own: CSV quoting and reading
** through libcsv (round trips, every malformed-input error naming its file
** and line), summing shards, the text / Markdown tables' layout, the
** scatter plot's points and the pentagon files (bit-exact round trip).
** (The Wilson interval the tables' header cites: test_study.c.)
*/
#define _POSIX_C_SOURCE 200809L
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

#include "report_internal.h"
#include "testutil.h"

/* The whole of a stream as a NUL-terminated string (caller frees). */
static char *trep_slurp(FILE *f) {
  fflush(f);
  long n = ftell(f);
  char *s = malloc((size_t)n + 1);
  rewind(f);
  size_t got = fread(s, 1, (size_t)n, f);
  s[got] = '\0';
  return s;
}

/* A consistent random row: the five types sum to samples, dt <= type I. */
static void trep_random_row(testutil_rng *g, report_row *r, const char *m, const char *j,
                            uint64_t samples) {
  memset(r, 0, sizeof *r);
  snprintf(r->measure, sizeof r->measure, "%s", m);
  snprintf(r->joint, sizeof r->joint, "%s", j);
  if (m[0]) snprintf(r->rule, sizeof r->rule, "%s_%s", m, j);
  else snprintf(r->rule, sizeof r->rule, "DT");
  r->c.samples = samples;
  uint64_t left = samples;
  for (int t = 0; t < FLIPGRAPH_V; t++) {
    uint64_t k = left ? testutil_next(g) % (left + 1) : 0;
    r->c.type[t] = k;
    left -= k;
  }
  r->c.type[FLIPGRAPH_V] = left;
  r->c.dt = r->c.type[FLIPGRAPH_I] ? testutil_next(g) % (r->c.type[FLIPGRAPH_I] + 1) : 0;
}

typedef struct trep_fields { int n; char f[16][64]; uint64_t line[16]; } trep_fields;

static int trep_collect(char **fields, const size_t *len, int nf, uint64_t line, void *ctx) {
  (void)len;
  trep_fields *t = ctx;
  for (int i = 0; i < nf && t->n < 16; i++) {
    snprintf(t->f[t->n], sizeof t->f[t->n], "%s", fields[i]);
    t->line[t->n++] = line;
  }
  return 0;
}

/* Fields that need quotes get them (and come back intact); others do not. */
static void test_csv_field_quoting(void **state) {
  (void)state;
  static const char *const in[] = {"-r2/A_0", "b/(c-a)_-1", "a,b", "say \"hi\"",
                                   " lead", "two\nlines", "-a'_inf", ""};
  static const int quoted[] = {0, 0, 1, 1, 1, 1, 0, 0};
  for (int i = 0; i < 8; i++) {
    FILE *f = tmpfile();
    assert_non_null(f);
    assert_int_equal(report_csv_field(f, in[i]), 0);
    char *s = trep_slurp(f);
    assert_int_equal(s[0] == '"', quoted[i]);
    if (!quoted[i]) assert_string_equal(s, in[i]);
    free(s);
    /* Round trip: a record "x,FIELD,y" reads back as three fields. */
    rewind(f);
    fputs("x,", f);
    report_csv_field(f, in[i]);
    fputs(",y\n", f);
    long end = ftell(f);
    assert_int_equal(ftruncate(fileno(f), end), 0);
    rewind(f);
    trep_fields t = {0};
    char err[128];
    assert_int_equal(report_csv_each(f, trep_collect, &t, err, sizeof err), 0);
    assert_int_equal(t.n, 3);
    assert_string_equal(t.f[1], in[i]);
    fclose(f);
  }
}

/* Blank lines are skipped, CRLF works, line numbers count LFs. */
static void test_csv_each_lines(void **state) {
  (void)state;
  FILE *f = tmpfile();
  fputs("a,b\r\n\r\nc,d\n\n\ne\n", f);
  rewind(f);
  trep_fields t = {0};
  char err[128];
  assert_int_equal(report_csv_each(f, trep_collect, &t, err, sizeof err), 0);
  assert_int_equal(t.n, 5);
  assert_string_equal(t.f[0], "a");
  assert_string_equal(t.f[2], "c");
  assert_int_equal(t.line[0], 1);
  assert_int_equal(t.line[2], 3);
  assert_string_equal(t.f[4], "e");
  assert_int_equal(t.line[4], 6);
  fclose(f);
  /* An unterminated quote is malformed, and the error names the line. */
  f = tmpfile();
  fputs("a,b\nc,\"d\n", f);
  rewind(f);
  memset(&t, 0, sizeof t);
  assert_int_not_equal(report_csv_each(f, trep_collect, &t, err, sizeof err), 0);
  assert_non_null(strstr(err, "line 2"));
  fclose(f);
}

static const char *const trep_joints[6] = {"-inf", "-1", "0", "1", "2", "inf"};

static int trep_make_rows(report_row *rows, uint64_t samples, uint64_t seed) {
  static const char *const m[3] = {"R", "-r2/A", "b/(c-a)"};
  testutil_rng g = {seed};
  int n = 0;
  for (int j = 0; j < 6; j++)
    for (int k = 0; k < 3; k++) trep_random_row(&g, &rows[n++], m[k], trep_joints[j], samples);
  trep_random_row(&g, &rows[n++], "", "", samples);
  return n;
}

/* report_csv_write then report_csv_read gives the rows back. */
static void test_csv_counts_roundtrip(void **state) {
  (void)state;
  report_row rows[19], *back = NULL;
  int n = trep_make_rows(rows, 5000, 42), nback = 0;
  char path[512], err[256];
  testutil_tmppath(path, sizeof path, "counts.csv");
  assert_int_equal(system("mkdir -p " FLIPLAB_BUILD_DIR "/testtmp"), 0);
  FILE *f = fopen(path, "wb");
  assert_int_equal(report_csv_write(f, rows, n), 0);
  fclose(f);
  assert_int_equal(report_csv_read(path, &back, &nback, err, sizeof err), 0);
  assert_int_equal(nback, n);
  for (int i = 0; i < n; i++) {
    assert_string_equal(back[i].measure, rows[i].measure);
    assert_string_equal(back[i].joint, rows[i].joint);
    assert_string_equal(back[i].rule, rows[i].rule);
    assert_memory_equal(&back[i].c, &rows[i].c, sizeof rows[i].c);
  }
  free(back);
  unlink(path);
}

/* Every malformed counts file: an error naming the file and the line. */
static void test_csv_counts_errors(void **state) {
  (void)state;
  static const char *const hdr =
    "measure,joint,rule,samples,type_I,type_II,type_III,type_IV,type_V,dt\n";
  static const struct { const char *body; const char *want; } cases[] = {
    {"measure,joint,rule,samples\n", "line 1"},
    {"", "empty"},
    {"HDR", "no rows"},
    {"HDRR,-inf,R_-inf,10,10,0,0,0,0,10\nR,-1,R_-1,10,10,0,0,0\n", "line 3"},
    {"HDRR,-inf,R_-inf,10,10,0,0,0,0,x\n", "line 2: dt 'x'"},
    {"HDRR,-inf,R_-inf,10,10,0,0,0,0,-1\n", "line 2"},
    {"HDRR,-inf,R_-inf,10,9,0,0,0,0,5\n", "inconsistent"},
    {"HDRR,-inf,R_-inf,10,5,5,0,0,0,6\n", "inconsistent"},
    {"HDRR,-inf,R_-inf,10,10,0,0,0,0,0\nR,-1,R_-1,11,11,0,0,0,0,0\n", "line 3: samples"},
    {"HDRR,-inf,R_-inf,99999999999999999999,0,0,0,0,0,0\n", "line 2"},
    {"HDRR,-inf,\"R_-inf,10,10,0,0,0,0,10\n", "line"},
  };
  char path[512], err[256], body[512];
  testutil_tmppath(path, sizeof path, "bad.csv");
  assert_int_equal(system("mkdir -p " FLIPLAB_BUILD_DIR "/testtmp"), 0);
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    const char *b = cases[i].body;
    if (strncmp(b, "HDR", 3) == 0) snprintf(body, sizeof body, "%s%s", hdr, b + 3);
    else snprintf(body, sizeof body, "%s", b);
    testutil_write_file(path, body);
    report_row *rows = NULL;
    int n = 0;
    err[0] = '\0';
    assert_int_equal(report_csv_read(path, &rows, &n, err, sizeof err), -1);
    if (strstr(err, cases[i].want) == NULL || strstr(err, path) == NULL)
      fail_msg("case %zu: error '%s' should name the file and '%s'", i, err, cases[i].want);
    assert_null(strchr(err, '\n'));
  }
  unlink(path);
}

static void test_rows_add(void **state) {
  (void)state;
  report_row a[19], b[19], sum[19];
  int n = trep_make_rows(a, 700, 1);
  trep_make_rows(b, 300, 2);
  memcpy(sum, a, sizeof a);
  char err[256];
  assert_int_equal(report_rows_add(sum, n, b, n, "b.csv", err, sizeof err), 0);
  for (int i = 0; i < n; i++) {
    assert_int_equal(sum[i].c.samples, 1000);
    for (int t = 0; t < FLIPGRAPH_NTYPES; t++)
      assert_int_equal(sum[i].c.type[t], a[i].c.type[t] + b[i].c.type[t]);
    assert_int_equal(sum[i].c.dt, a[i].c.dt + b[i].c.dt);
  }
  /* Different rules or a different number of them: refused, acc untouched. */
  memcpy(sum, a, sizeof a);
  strcpy(b[4].rule, "other");
  assert_int_equal(report_rows_add(sum, n, b, n, "b.csv", err, sizeof err), -1);
  assert_non_null(strstr(err, "b.csv"));
  assert_memory_equal(sum, a, sizeof a);
  assert_int_equal(report_rows_add(sum, n, b, n - 1, "b.csv", err, sizeof err), -1);
}

/* Text: every measure, every joint block with its four rows, the exact
** percentages, the type-V line listing exactly the rules with type V. */
static void test_text_table(void **state) {
  (void)state;
  report_row rows[19];
  int n = trep_make_rows(rows, 5000, 7);
  /* Every cell 24.68 % type I, 12.34 % DT; type V only in rows 2 and 9. */
  for (int i = 0; i < n; i++) {
    memset(rows[i].c.type, 0, sizeof rows[i].c.type);
    rows[i].c.type[FLIPGRAPH_I] = 1234;
    rows[i].c.type[FLIPGRAPH_II] = 5000 - 1234;
    rows[i].c.dt = 617;
  }
  rows[2].c.type[FLIPGRAPH_II] -= 50;
  rows[2].c.type[FLIPGRAPH_V] = 50;
  rows[9].c.type[FLIPGRAPH_II] -= 5000 - 1234;
  rows[9].c.type[FLIPGRAPH_V] = 5000 - 1234;
  report_meta m = {.samples = 5000, .has_seed = 1, .seed = 3, .has_tie_eps = 1, .tie_eps = 1e-12};
  FILE *f = tmpfile();
  assert_int_equal(report_table_text(f, &m, rows, n, 10), 0);
  char *s = trep_slurp(f);
  fclose(f);
  assert_non_null(strstr(s, "samples: 5000"));
  assert_non_null(strstr(s, "seed: 3"));
  assert_non_null(strstr(s, "tie tolerance: 1e-12"));
  assert_non_null(strstr(s, "iteration method, unit disc"));
  assert_non_null(strstr(s, "1.39 points"));
  for (int j = 0; j < 6; j++) {
    char label[16];
    snprintf(label, sizeof label, "l_%s ", trep_joints[j]);
    assert_int_equal(testutil_count(s, label), 1);
  }
  assert_true(testutil_count(s, " 24.68") >= 18);   /* 1234 / 5000 */
  assert_true(testutil_count(s, " 12.34") >= 18);   /* 617 / 5000 */
  assert_non_null(strstr(s, "-r2/A"));
  assert_non_null(strstr(s, "b/(c-a)"));
  const char *v = strstr(s, "Type V");
  assert_non_null(v);
  assert_non_null(strstr(v, rows[2].rule));
  assert_non_null(strstr(v, "1.00"));
  assert_non_null(strstr(v, rows[9].rule));
  assert_non_null(strstr(v, "75.32"));
  assert_null(strstr(v, rows[0].rule));
  assert_non_null(strstr(s, "Type IV (no sink): none"));
  free(s);

  /* A type-IV count among triangle rules is shouted. */
  rows[5].c.type[FLIPGRAPH_I] -= 3;
  rows[5].c.type[FLIPGRAPH_IV] = 3;
  assert_int_equal(report_type_iv(rows, n), 3);
  f = tmpfile();
  report_table_text(f, &m, rows, n, 10);
  s = trep_slurp(f);
  fclose(f);
  assert_non_null(strstr(s, "TYPE IV"));
  assert_non_null(strstr(s, rows[5].rule));
  free(s);
}

/* Column groups: 23 columns of at most 10 are 8 + 8 + 7. */
static void test_text_groups(void **state) {
  (void)state;
  report_row rows[23 * 6 + 1];
  int n = 0;
  testutil_rng g = {5};
  for (int j = 0; j < 6; j++)
    for (int k = 0; k < 23; k++) {
      char name[16];
      snprintf(name, sizeof name, "m%d", k);
      trep_random_row(&g, &rows[n++], name, trep_joints[j], 100);
    }
  trep_random_row(&g, &rows[n++], "", "", 100);
  report_meta m = {.samples = 100};
  FILE *f = tmpfile();
  report_table_text(f, &m, rows, n, 10);
  char *s = trep_slurp(f);
  fclose(f);
  assert_non_null(strstr(s, "Measures 1-8 of 23"));
  assert_non_null(strstr(s, "Measures 9-16 of 23"));
  assert_non_null(strstr(s, "Measures 17-23 of 23"));
  assert_int_equal(testutil_count(s, "l_-inf "), 3);
  free(s);
}

/* Markdown: a proper table (every row has as many cells as the header). */
static void test_md_table(void **state) {
  (void)state;
  report_row rows[19];
  int n = trep_make_rows(rows, 5000, 11);
  report_meta m = {.samples = 5000};
  FILE *f = tmpfile();
  assert_int_equal(report_table_md(f, &m, rows, n), 0);
  char *s = trep_slurp(f);
  fclose(f);
  int lines = 0;
  size_t bars = 0;
  for (char *line = strtok(s, "\n"); line; line = strtok(NULL, "\n")) {
    if (line[0] != '|') continue;
    size_t b = testutil_count(line, "|") - testutil_count(line, "\\|");
    if (lines == 0) bars = b;
    assert_int_equal(b, bars);
    lines++;
  }
  assert_int_equal(bars, 3 + 3);      /* joint, row, three measures */
  assert_int_equal(lines, 2 + 6 * 4); /* header, rule, 6 blocks of 4 */
  free(s);
}

/* The plot: one circle per distinct (type I, DT) point without type V,
** every such rule named in a title, type-V rules absent, names escaped. */
static void test_scatter(void **state) {
  (void)state;
  report_row rows[19];
  int n = trep_make_rows(rows, 1000, 13);
  for (int i = 0; i < n; i++) {
    memset(rows[i].c.type, 0, sizeof rows[i].c.type);
    rows[i].c.type[FLIPGRAPH_I] = 900 - 10 * (uint64_t)(i % 5);
    rows[i].c.type[FLIPGRAPH_II] = 1000 - rows[i].c.type[FLIPGRAPH_I];
    rows[i].c.dt = 800;
  }
  rows[3].c.type[FLIPGRAPH_II] -= 1;
  rows[3].c.type[FLIPGRAPH_V] = 1;
  strcpy(rows[7].rule, "a<b&c");
  report_meta m = {.samples = 1000};
  FILE *f = tmpfile();
  assert_int_equal(report_scatter_svg(f, &m, rows, n), 0);
  char *s = trep_slurp(f);
  fclose(f);
  assert_non_null(strstr(s, "<svg"));
  assert_non_null(strstr(s, "</svg>"));
  /* Five distinct type-I values, all with DT 800: five data circles. */
  assert_int_equal(testutil_count(s, "fill-opacity=\"0.8\""), 5);
  for (int i = 0; i < n; i++) {
    if (i == 3 || i == 7) continue;
    char key[RULE_NAME_MAX + 16];
    snprintf(key, sizeof key, "%s: type I", rows[i].rule);
    assert_non_null(strstr(s, key));
  }
  char key[RULE_NAME_MAX + 16];
  snprintf(key, sizeof key, ">%s: type I", rows[3].rule);
  assert_null(strstr(s, key));
  snprintf(key, sizeof key, "\n%s: type I", rows[3].rule);
  assert_null(strstr(s, key));
  assert_non_null(strstr(s, "a&lt;b&amp;c: type I"));
  assert_int_equal(testutil_count(s, "<title>"), testutil_count(s, "</title>"));
  free(s);
}

/* Figure 3.9's legend lists exactly the colours drawn: DT sharing its spot
** with R_1 is drawn white ("several joints"), so neither DT's black entry
** nor l_1's appears; l_-inf's point is drawn and its entry is there. */
static void test_scatter_legend(void **state) {
  (void)state;
  report_row rows[3];
  testutil_rng g = {5};
  trep_random_row(&g, &rows[0], "R", "1", 1000);
  trep_random_row(&g, &rows[1], "", "", 1000);
  trep_random_row(&g, &rows[2], "P", "-inf", 1000);
  for (int i = 0; i < 3; i++) {
    memset(rows[i].c.type, 0, sizeof rows[i].c.type);
    rows[i].c.type[FLIPGRAPH_I] = i < 2 ? 1000 : 700;
    rows[i].c.type[FLIPGRAPH_III] = 1000 - rows[i].c.type[FLIPGRAPH_I];
    rows[i].c.dt = i < 2 ? 1000 : 400;
  }
  report_meta m = {.samples = 1000};
  FILE *f = tmpfile();
  assert_int_equal(report_scatter_svg(f, &m, rows, 3), 0);
  char *s = trep_slurp(f);
  fclose(f);
  assert_non_null(strstr(s, ">several joints<"));
  assert_non_null(strstr(s, ">l_-inf (min)<"));
  assert_null(strstr(s, "quadrilateral rule"));
  assert_null(strstr(s, ">l_1 (sum)<"));
  /* Every legend colour is a drawn circle's: legend circles have r="5". */
  assert_int_equal(testutil_count(s, "r=\"5\""), 2);
  assert_int_equal(testutil_count(s, "fill=\"#FFFFFF\""), 2);   /* point + legend */
  free(s);
}

/* --compare DT's overlay: exactly the other triangulation's diagonals that
** the drawn one lacks, dashed red; none when the two are the same. */
static int trep_red_segments(const geom_point *p, size_t n, const got_triangle *t,
                             const got_triangle *other) {
  report_got_svg_opts o = {.overlay = other, .noverlay = n - 2, .overlay_name = "DT"};
  FILE *f = tmpfile();
  assert_int_equal(report_got_svg(f, p, n, t, n - 2, &o), 0);
  char *s = trep_slurp(f);
  fclose(f);
  char *red = strstr(s, "stroke=\"#d62728\"");
  assert_non_null(red);
  char *d = strstr(red, " d=\""), *end = strchr(d + 4, '"');
  int m = 0;
  for (char *c = d + 4; c < end; c++) m += *c == 'M';
  assert_non_null(strstr(end, "diagonals of DT not in this triangulation"));
  free(s);
  return m;
}

static void test_got_overlay(void **state) {
  (void)state;
  const geom_point hex[6] = {{0, 0}, {2, 0}, {3, 1}, {2, 3}, {0, 2}, {-1, 1}};
  /* Fans at vertex 0 and at vertex 1 share no diagonal; a mixed one shares one. */
  const got_triangle fan0[4] = {{0, 1, 2, 0}, {0, 2, 3, 0}, {0, 3, 4, 0}, {0, 4, 5, 0}};
  const got_triangle fan1[4] = {{1, 2, 3, 0}, {1, 3, 4, 0}, {1, 4, 5, 0}, {0, 1, 5, 0}};
  const got_triangle mix[4] = {{0, 1, 2, 0}, {0, 2, 5, 0}, {2, 3, 5, 0}, {3, 4, 5, 0}};
  assert_int_equal(trep_red_segments(hex, 6, fan0, fan1), 3);
  assert_int_equal(trep_red_segments(hex, 6, fan0, fan0), 0);
  assert_int_equal(trep_red_segments(hex, 6, fan0, mix), 2);   /* (2,5), (3,5) */
}

/* Pentagons: %.17g reads back bit for bit; clockwise rows are reversed
** keeping the first vertex; bad rows name their line and problem. */
static void test_pentagon_files(void **state) {
  (void)state;
  testutil_rng g = {99};
  geom_point want[40 * 5];
  FILE *f = tmpfile();
  report_pentagon_header(f);
  for (int k = 0; k < 40; k++) {
    /* A regular pentagon, randomly scaled, rotated and moved: convex. */
    double r = 0.1 + testutil_uniform(&g), a0 = 6.283 * testutil_uniform(&g);
    double cx = testutil_uniform(&g) - 0.5, cy = testutil_uniform(&g) - 0.5;
    for (int i = 0; i < 5; i++)
      want[5 * k + i] = (geom_point){cx + r * cos(a0 + 1.2566370614359172 * i),
                                     cy + r * sin(a0 + 1.2566370614359172 * i)};
    geom_point w[5];
    for (int i = 0; i < 5; i++) w[i] = want[5 * k + (k % 2 ? (5 - i) % 5 : i)];
    report_pentagon_write(f, w);
  }
  rewind(f);
  geom_point *v = NULL;
  size_t n = 0, rev = 0;
  char err[256];
  assert_int_equal(report_pentagon_read(f, "p.csv", &v, &n, &rev, err, sizeof err), 0);
  fclose(f);
  assert_int_equal(n, 40);
  assert_int_equal(rev, 20);
  assert_memory_equal(v, want, sizeof want);
  free(v);

  static const struct { const char *row; const char *want; } bad[] = {
    {"0,0,1,0,1,1,0,1\n", "got 8 fields"},
    {"0,0,1,0,1.5,0.5,1,1,abc,1\n", "x5 'abc' is not a number"},
    {"0,0,1,0,1.5,0.5,1,1,nan,1\n", "x5 'nan' is not finite"},
    {"0,0,1,0,1.5,0.5,1,1,0,inf\n", "y5 'inf' is not finite"},
    {"0,0,1,0,1.5,0.5,1,1,,1\n", "x5 '' is not a number"},
    {"0,0,1,0,1,0,1,1,0,1\n", "duplicate"},
    {"0,0,1,0,2,0,1,1,0,1\n", "collinear"},
    {"0,0,2,0,1,0.5,2,2,0,2\n", "not convex"},
    {"1,0,-0.809,0.588,0.309,-0.951,0.309,0.951,-0.809,-0.588\n", "not convex"},
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    f = tmpfile();
    fputs("x1,y1,x2,y2,x3,y3,x4,y4,x5,y5\n0,0,1,0,1.5,0.5,1,1,0,1\n\n", f);
    fputs(bad[i].row, f);
    rewind(f);
    v = NULL;
    err[0] = '\0';
    assert_int_equal(report_pentagon_read(f, "p.csv", &v, &n, NULL, err, sizeof err), -1);
    fclose(f);
    if (strstr(err, "p.csv line 4") == NULL || strstr(err, bad[i].want) == NULL)
      fail_msg("row %zu: error '%s' should say 'p.csv line 4' and '%s'", i, err, bad[i].want);
  }
  /* A header alone has no pentagons. */
  f = tmpfile();
  fputs("x1,y1,x2,y2,x3,y3,x4,y4,x5,y5\n", f);
  rewind(f);
  assert_int_equal(report_pentagon_read(f, "p.csv", &v, &n, NULL, err, sizeof err), -1);
  assert_non_null(strstr(err, "no pentagons"));
  fclose(f);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_csv_field_quoting),
    cmocka_unit_test(test_csv_each_lines),
    cmocka_unit_test(test_csv_counts_roundtrip),
    cmocka_unit_test(test_csv_counts_errors),
    cmocka_unit_test(test_rows_add),
    cmocka_unit_test(test_text_table),
    cmocka_unit_test(test_text_groups),
    cmocka_unit_test(test_md_table),
    cmocka_unit_test(test_scatter),
    cmocka_unit_test(test_scatter_legend),
    cmocka_unit_test(test_got_overlay),
    cmocka_unit_test(test_pentagon_files),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
