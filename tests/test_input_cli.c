/*
** test_input_cli.c: hostile input gets one short line, never a crash or a
** silent wrong answer (issue 10, items 1, 7, 8).
**   - the muParser crash reproducer (a 2,100-character bad token) and a
**     20,000-character formula: refused, the echo cut short;
**   - a name over the limit, 1e400 and 1e-400 inside a formula: refused;
**   - numbers that overflow or underflow a double in every reader (classify
**     pentagons, got polygons): "out of range", never read as 0 or inf;
**   - a UTF-8 byte order mark: skipped by every reader;
**   - classify's geometry errors name the row and the vertex, as got's do;
**   - a quoted newline echoed in a message keeps it one line;
**   - classify with stdout output writes nothing when a row is bad, and
**     its output does not depend on the input being a file or a pipe;
**   - a NUL byte inside a number (issue 17) is refused by every reader
**     (lot points, got polygons, classify pentagons, merge of table34 and
**     census shards), as the same field with the NUL left out is;
**   - option values are read whole by the same parser: ' 5' and 1e-400 are
**     no counts, 1.5e1 is one, a subnormal tolerance is too small.
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
#include <sys/stat.h>
#include <unistd.h>

#include "testutil.h"

#define TI_CAP (1 << 20)
static char ti_out[TI_CAP], ti_err[TI_CAP];
#define TI_RUN(...) testutil_runf(ti_out, TI_CAP, ti_err, TI_CAP, __VA_ARGS__)

/* The last run failed with status st, one line of at most maxlen bytes
** containing want. */
static void ti_refused(int got, int st, const char *want, size_t maxlen) {
  if (got != st) fail_msg("exit %d (want %d): %.300s", got, st, ti_err);
  if (!testutil_one_line(ti_err)) fail_msg("not one line: %.300s", ti_err);
  if (strstr(ti_err, want) == NULL) fail_msg("'%.300s' lacks '%s'", ti_err, want);
  if (strlen(ti_err) > maxlen) fail_msg("message of %zu bytes: %.300s", strlen(ti_err), ti_err);
}

static void test_formula_input(void **state) {
  (void)state;
  static char args[25000];
  /* The reproducer: `--define "q = a+####...#"` (2,100 #) aborted in muParser. */
  int n = snprintf(args, sizeof args, "--define 'q = a+");
  memset(args + n, '#', 2100);
  snprintf(args + n + 2100, sizeof args - (size_t)n - 2100, "' list");
  ti_refused(testutil_run(args, ti_out, TI_CAP, ti_err, TI_CAP), 2, "at most 1024", 300);
  /* Under the limit: muParser's own message, its token cut. */
  snprintf(args + n + 1000, sizeof args - (size_t)n - 1000, "' list");
  ti_refused(testutil_run(args, ti_out, TI_CAP, ti_err, TI_CAP), 2, "syntax error", 400);
  /* 7,000 characters of a valid-looking formula (the run helper takes 8 KB;
  ** the issue used 20,000): not echoed whole. */
  n = snprintf(args, sizeof args, "--define 'q = a");
  for (int k = 0; k < 3500; k++) n += snprintf(args + n, sizeof args - (size_t)n, "+b");
  snprintf(args + n, sizeof args - (size_t)n, "' list");
  ti_refused(testutil_run(args, ti_out, TI_CAP, ti_err, TI_CAP), 2, "at most 1024", 300);

  ti_refused(TI_RUN("--define 'averyveryveryveryverylongnamethatistoolong = a' list"), 2,
             "at most 31", 300);
  ti_refused(TI_RUN("--define 'q = 1e400*a' list"), 2, "'1e400' at position 4 is out of range",
             300);
  ti_refused(TI_RUN("--define 'q = a + 1e-400' list"), 2, "out of range", 300);
}

static void ti_file(char *path, size_t len, const char *name, const char *text) {
  assert_int_equal(system("mkdir -p " FLIPLAB_BUILD_DIR "/testtmp"), 0);
  testutil_tmppath(path, len, name);
  testutil_write_file(path, text);
}

#define TI_PENT "0,0,1,0,1.5,0.5,1,1,0,1\n"

static void test_numbers_out_of_range(void **state) {
  (void)state;
  char p[512];
  static const struct { const char *row, *want; } rows[] = {
    {"0,0,1,0,1e-400,0.5,1,1,0,1\n", "x3 '1e-400' is out of range"},
    {"0,0,1,0,1.5,0.5,1,1,0,1e400\n", "y5 '1e400' is out of range"},
    {"0,0,1,0,1.5,-1e-310,1,1,0,1\n", "y3 '-1e-310' is out of range"},   /* subnormal */
    {"0,0,1,0,1.5,0.5,1,inf,0,1\n", "not finite"},
  };
  for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
    ti_file(p, sizeof p, "range.csv", rows[i].row);
    ti_refused(TI_RUN("classify --input %s", p), 2, rows[i].want, 300);
    assert_non_null(strstr(ti_err, "line 1"));
  }
  ti_file(p, sizeof p, "poly.csv", "0,0\n1,0\n1e-400,1\n");
  ti_refused(TI_RUN("got --rule P_1 --polygon %s", p), 2, "line 3: x '1e-400' is out of range",
             300);
  ti_file(p, sizeof p, "poly.csv", "0,0\n1,0\n1,1e999\n");
  ti_refused(TI_RUN("got --rule P_1 --polygon %s", p), 2, "out of range", 300);
  unlink(p);
}

/* Option values are read whole by geom/'s number parser (cli/util.c): a
** count with blanks around it, or written as a real that underflows to 0,
** is refused rather than read as a nearby number; sizes in scientific
** notation still work; a tolerance below the normal doubles is too small. */
static void test_option_numbers(void **state) {
  (void)state;
  ti_refused(TI_RUN("sample --count 2 --first ' 5'"), 2, "--first expects a non-negative "
             "integer, got ' 5'", 300);
  ti_refused(TI_RUN("sample --count 2 --first 1e-400"), 2, "got '1e-400'", 300);
  ti_refused(TI_RUN("sample --count 2 --first 0x10"), 2, "got '0x10'", 300);
  ti_refused(TI_RUN("sample --count 2.5"), 2, "got '2.5'", 300);
  ti_refused(TI_RUN("sample --count 2e13"), 2, "--count 2e13 is out of range [1, 1000000000000]",
             300);
  assert_int_equal(TI_RUN("sample --count 2e0 --first 1.5e1 --no-header"), 0);
  assert_int_equal(testutil_count(ti_out, "\n"), 2);
  ti_refused(TI_RUN("table34 --samples 10 --tie-eps 1e-310"), 2, "too small in magnitude", 300);
  ti_refused(TI_RUN("table34 --samples 10 --tie-eps 1e999"), 2, "expects a finite number", 300);
}

/* Write n bytes (NULs included) to a file of the test directory. */
static void ti_bytes(char *path, size_t len, const char *name, const char *bytes, size_t n) {
  ti_file(path, len, name, "");
  FILE *f = fopen(path, "wb");
  assert_non_null(f);
  assert_int_equal(fwrite(bytes, 1, n, f), n);
  assert_int_equal(fclose(f), 0);
}

/* text with a NUL byte inserted after the first occurrence of `after` at
** or past byte `from` (the data rows), written to a file. */
static void ti_nul_after(char *path, size_t len, const char *name, const char *text,
                         size_t from, const char *after) {
  const char *at = strstr(text + from, after);
  assert_non_null(at);
  size_t k = (size_t)(at - text) + strlen(after), n = strlen(text);
  char *b = malloc(n + 1);
  assert_non_null(b);
  memcpy(b, text, k);
  b[k] = '\0';
  memcpy(b + k + 1, text + k, n - k);
  ti_bytes(path, len, name, b, n + 1);
  free(b);
}

static void test_nul_in_field(void **state) {
  (void)state;
  char p[512], q[512];
  static const char pts[] = "x,y\n0,0\n1,0\n0.5\0garbage,0.8\n";
  ti_bytes(p, sizeof p, "nul.csv", pts, sizeof pts - 1);
  /* the field shown whole, its NUL as '?' (the points reader shows fields
  ** as the segments and weights readers do: report_pairs_shown) */
  ti_refused(TI_RUN("lot --rule DT --points %s", p), 2, "line 4: x '0.5?garbage' is not a number",
             300);
  ti_refused(TI_RUN("got --rule P_1 --polygon %s", p), 2,
             "line 4: x '0.5?garbage' is not a number", 300);
  static const char pent[] = "0,0,1,0,1.5\0001,0.5,1,1,0,1\n";
  ti_bytes(p, sizeof p, "nul.csv", pent, sizeof pent - 1);
  ti_refused(TI_RUN("classify --input %s", p), 2, "x3 '1.5' is not a number", 300);
  /* merge: a count with a NUL and a digit after it ("20\0" "7" read as 20). */
  ti_file(q, sizeof q, "shard.csv", "");
  assert_int_equal(TI_RUN("table34 --samples 20 --format csv --out %s", q), 0);
  char *csv = testutil_read_file(q);
  ti_nul_after(p, sizeof p, "nul.csv", csv, (size_t)(strchr(csv, '\n') - csv), ",20");
  ti_refused(TI_RUN("merge %s", p), 2, "samples '20' is not a count", 300);
  /* A name: "DT" then a NUL and junk would read as DT. */
  ti_nul_after(p, sizeof p, "nul.csv", csv, (size_t)(strchr(csv, '\n') - csv), ",,DT");
  ti_refused(TI_RUN("merge %s", p), 2, "rule 'DT' has a NUL byte inside", 300);
  free(csv);
  assert_int_equal(TI_RUN("census --sites 5 --samples 20 --format csv --out %s", q), 0);
  csv = testutil_read_file(q);
  ti_nul_after(p, sizeof p, "nul.csv", csv, (size_t)(strchr(csv, '\n') - csv), ",20");
  ti_refused(TI_RUN("merge %s", p), 2, "is not a count", 300);
  free(csv);
  unlink(p);
  unlink(q);
}

/* A BOM changes nothing: same output as without it. */
static void test_bom(void **state) {
  (void)state;
  char plain[512], bom[512];
  static char want[TI_CAP];
  const char *bytes = "\xEF\xBB\xBF";
  const char *pent = "x1,y1,x2,y2,x3,y3,x4,y4,x5,y5\n" TI_PENT;
  char text[256];
  for (int header = 0; header < 2; header++) {
    const char *body = header ? pent : TI_PENT;
    ti_file(plain, sizeof plain, "plain.csv", body);
    snprintf(text, sizeof text, "%s%s", bytes, body);
    ti_file(bom, sizeof bom, "bom.csv", text);
    assert_int_equal(TI_RUN("classify --rule DT --input %s", plain), 0);
    memcpy(want, ti_out, strlen(ti_out) + 1);
    if (TI_RUN("classify --rule DT --input %s", bom) != 0) fail_msg("BOM refused: %s", ti_err);
    assert_string_equal(ti_out, want);
  }
  ti_file(plain, sizeof plain, "plain.csv", "x,y\n0,0\n1,0\n0,1\n");
  ti_file(bom, sizeof bom, "bom.csv", "\xEF\xBB\xBFx,y\n0,0\n1,0\n0,1\n");
  assert_int_equal(TI_RUN("got --rule P_1 --polygon %s", plain), 0);
  const char *tri = strstr(ti_out, "triangles:");
  assert_non_null(tri);
  memcpy(want, tri, strlen(tri) + 1);
  assert_int_equal(TI_RUN("got --rule P_1 --polygon %s", bom), 0);
  assert_non_null(strstr(ti_out, want));
  /* merge: a counts CSV saved with a BOM. */
  assert_int_equal(TI_RUN("table34 --samples 20 --format csv --out %s", plain), 0);
  char *csv = testutil_read_file(plain);
  char *with = malloc(strlen(csv) + 4);
  sprintf(with, "%s%s", bytes, csv);
  testutil_write_file(bom, with);
  assert_int_equal(TI_RUN("merge %s", bom), 0);
  assert_string_equal(ti_out, csv);
  free(csv);
  free(with);
  unlink(plain);
  unlink(bom);
}

/* Row and vertex in every geometry error; one line whatever is echoed. */
static void test_classify_names_vertex(void **state) {
  (void)state;
  char p[512];
  static const struct { const char *row, *want; } rows[] = {
    {"0,0,2,0,1,0.5,2,2,0,2\n", "line 2: point 3 (x3,y3): polygon is not convex"},
    {"0,0,1e60,0,1.5,0.5,1,1,0,1\n", "line 2: x2 '1e60' is out of range"},
    {"0,0,1,0,1.5,0.5,1,1,1,0\n", "line 2: point"},
    {"0,0,1,0,1.5,0.5,1,1,0,\"1\n2\"\n", "line 2: y5 '1?2' is not a number"},
  };
  for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
    char text[256];
    snprintf(text, sizeof text, "%s%s", TI_PENT, rows[i].row);
    ti_file(p, sizeof p, "vertex.csv", text);
    ti_refused(TI_RUN("classify --input %s", p), 2, rows[i].want, 300);
    assert_string_equal(ti_out, "");                   /* stdout: nothing before the check */
  }
  unlink(p);
}

/* Streaming from a pipe gives the same rows as from a file. */
static void test_classify_pipe(void **state) {
  (void)state;
  char p[512];
  static char want[TI_CAP];
  testutil_tmppath(p, sizeof p, "pipe.csv");
  assert_int_equal(TI_RUN("sample --count 300 --seed 4 --out %s", p), 0);
  assert_int_equal(TI_RUN("classify --rule R_inf --rule DT --input %s", p), 0);
  memcpy(want, ti_out, strlen(ti_out) + 1);
  char fifo[512], cmd[1200];
  testutil_tmppath(fifo, sizeof fifo, "pipe.fifo");
  unlink(fifo);
  assert_int_equal(mkfifo(fifo, 0600), 0);
  snprintf(cmd, sizeof cmd, "cat %s > %s &", p, fifo);
  assert_int_equal(system(cmd), 0);
  assert_int_equal(TI_RUN("classify --rule R_inf --rule DT --input %s", fifo), 0);
  assert_string_equal(ti_out, want);
  unlink(fifo);
  assert_int_equal(testutil_count(ti_out, "\n"), 1 + 600);
  unlink(p);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_formula_input),
    cmocka_unit_test(test_numbers_out_of_range),
    cmocka_unit_test(test_option_numbers),
    cmocka_unit_test(test_nul_in_field),
    cmocka_unit_test(test_bom),
    cmocka_unit_test(test_classify_names_vertex),
    cmocka_unit_test(test_classify_pipe),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
