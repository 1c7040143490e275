/*
** test_segments_csv.c: the segment-file reader of `lot --segments`
** (reports/csv_segments.c).  A file with a header, blank lines, CRLF line
** ends, quoted fields and a byte order mark reads as the rows say, with the
** rows' lines; random segment lists written and read back are the same
** list; a file cut at any byte reads as the complete rows before the cut
** (plus the cut row when it still parses) or is refused in one line; every
** kind of bad row is refused with one line naming the file's line.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "report.h"
#include "testutil.h"

static void tseg_file(const char *name, const char *text, char *path, size_t len) {
  testutil_tmppath(path, len, name);
  testutil_write_file(path, text);
}

static void test_segments_layout(void **state) {
  (void)state;
  char path[512], err[512];
  tseg_file("seg_layout.csv", "\xEF\xBB\xBFi,j\r\n0,1\r\n\r\n\"2\", 3 \r\n3,0", path, sizeof path);
  uint32_t *s;
  uint64_t *line;
  size_t n;
  assert_int_equal(report_segments_read(path, 4, &s, &line, &n, err, sizeof err), 0);
  assert_int_equal(n, 3);
  static const uint32_t want[6] = {0, 1, 2, 3, 3, 0};
  static const uint64_t wline[3] = {2, 4, 5};
  for (int k = 0; k < 6; k++) assert_int_equal(s[k], want[k]);
  for (int k = 0; k < 3; k++) assert_int_equal(line[k], wline[k]);
  free(s);
  free(line);
}

/* Random lists, with and without a header, read back as written. */
static void test_segments_round_trip(void **state) {
  (void)state;
  testutil_rng g = {20};
  char path[512], err[512];
  testutil_tmppath(path, sizeof path, "seg_random.csv");
  for (int run = 0; run < 50; run++) {
    size_t np = 2 + testutil_next(&g) % 5000, ns = 1 + testutil_next(&g) % 300;
    uint32_t *w = malloc(2 * ns * sizeof *w);
    assert_non_null(w);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    if (run % 2) fputs("i,j\n", f);
    for (size_t k = 0; k < ns; k++) {
      w[2 * k] = (uint32_t)(testutil_next(&g) % np);
      do w[2 * k + 1] = (uint32_t)(testutil_next(&g) % np); while (w[2 * k + 1] == w[2 * k]);
      fprintf(f, "%u,%u\n", w[2 * k], w[2 * k + 1]);
    }
    assert_int_equal(fclose(f), 0);
    uint32_t *s;
    size_t n;
    assert_int_equal(report_segments_read(path, np, &s, NULL, &n, err, sizeof err), 0);
    assert_int_equal(n, ns);
    assert_memory_equal(s, w, 2 * ns * sizeof *w);
    free(s);
    free(w);
  }
}

/* Each prefix of a file: the complete rows before the cut (and the cut one
** when what is left of it still names two points), or one line. */
static void test_segments_truncated(void **state) {
  (void)state;
  static const char text[] = "i,j\n0,11\n12,3\n4,5\n";
  char path[512], err[512], buf[64];
  testutil_tmppath(path, sizeof path, "seg_cut.csv");
  for (size_t cut = 0; cut < sizeof text - 1; cut++) {
    memcpy(buf, text, cut);
    buf[cut] = '\0';
    testutil_write_file(path, buf);
    uint32_t *s;
    size_t n;
    int rc = report_segments_read(path, 13, &s, NULL, &n, err, sizeof err);
    if (rc != 0) {
      assert_true(testutil_one_line(err) || strchr(err, '\n') == NULL);
      assert_non_null(strstr(err, path));
      continue;
    }
    size_t complete = 0;
    for (size_t k = 4; k < cut; k++) complete += text[k] == '\n';
    assert_true(n == complete || n == complete + 1);
    free(s);
  }
}

static void tseg_refused(const char *text, size_t np, const char *want) {
  char path[512], err[512];
  tseg_file("seg_bad.csv", text, path, sizeof path);
  uint32_t *s = (uint32_t *)&s;
  size_t n = 7;
  if (report_segments_read(path, np, &s, NULL, &n, err, sizeof err) != -1)
    fail_msg("accepted: %s", text);
  assert_null(s);
  assert_int_equal(n, 0);
  assert_null(strchr(err, '\n'));
  if (strstr(err, want) == NULL) fail_msg("'%s' lacks '%s'", err, want);
}

static void test_segments_bad_input(void **state) {
  (void)state;
  tseg_refused("0,1\n1,x\n", 4, "line 2: j 'x' is not a non-negative integer");
  tseg_refused("0,1\n-1,2\n", 4, "line 2: i '-1' is negative");
  tseg_refused("0,4\n", 4, "line 1: j 4 is out of range (4 points)");
  tseg_refused("0,99999999999999999999\n", 4, "line 1: j '99999999999999999999' is not");
  tseg_refused("i,j\n2,2\n", 4, "line 2: both ends are point 2");
  tseg_refused("0,1,2\n", 4, "line 1: expected 2 fields i,j, got 3");
  tseg_refused("0,1\n\n3\n", 4, "line 3: expected 2 fields i,j, got 1");
  tseg_refused("0,\n", 4, "line 1: j '' is not a non-negative integer");
  tseg_refused("1.0,2\n", 4, "i '1.0' is not");
  tseg_refused("i,j\n", 4, "no segments");
  tseg_refused("", 4, "no segments");
  tseg_refused("0,1\n\"2,3\n", 4, "line");
  tseg_refused("\"0\n1\",2\n", 4, "i '0?1' is not");   /* a quoted line break: still one line */
  char err[512];
  uint32_t *s;
  size_t n;
  assert_int_equal(report_segments_read("/nonexistent/seg.csv", 4, &s, NULL, &n, err,
                                        sizeof err), -1);
  assert_non_null(strstr(err, "cannot read '/nonexistent/seg.csv'"));
}

int main(void) {
  mkdir(FLIPLAB_BUILD_DIR "/testtmp", 0777);   /* testutil_tmppath's folder */
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_segments_layout),    cmocka_unit_test(test_segments_round_trip),
    cmocka_unit_test(test_segments_truncated), cmocka_unit_test(test_segments_bad_input),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
