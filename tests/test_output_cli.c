/*
** test_output_cli.c: no lost data, no ignored write error (cli/output.c).
** Every command's standard output and every output option on a full device
** (/dev/full) give exit status 1 and one line naming what could not be
** written; a failing run (bad value of a user formula, unwritable second
** output, bad input) leaves the previous file byte-identical, keeps its
** mode and leaves no temporary file behind; a successful run replaces it;
** two outputs naming one file (also spelled differently, or through a
** symlink) are refused; a command may overwrite its own input.
*/
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "testutil.h"

#define TO_CAP (1 << 16)
static char to_out[TO_CAP], to_err[TO_CAP];
static char to_dir[512];            /* this test's own directory */
static char to_pent[600], to_csv[600], to_good[600];

#define TO_PRECIOUS "precious,content\n1,2\n"

static void to_path(char *buf, size_t len, const char *name) {
  snprintf(buf, len, "%s/%s", to_dir, name);
}

static void to_one_line(const char *what) {
  if (!testutil_one_line(to_err)) fail_msg("%s: stderr should be one line: '%s'", what, to_err);
}

/* No ".NAME.XXXXXX" left in the test directory. */
static void to_no_temp(const char *what) {
  DIR *d = opendir(to_dir);
  assert_non_null(d);
  struct dirent *e;
  while ((e = readdir(d)) != NULL)
    if (e->d_name[0] == '.' && strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0) {
      closedir(d);
      fail_msg("%s: temporary file '%s' left behind", what, e->d_name);
    }
  closedir(d);
}

static int to_setup(void **state) {
  (void)state;
  char cmd[1200];
  testutil_tmppath(to_dir, sizeof to_dir, "outputs");
  snprintf(cmd, sizeof cmd, "rm -rf %s && mkdir -p %s", to_dir, to_dir);
  if (system(cmd) != 0) return -1;
  to_path(to_pent, sizeof to_pent, "pent.csv");
  to_path(to_csv, sizeof to_csv, "counts.csv");
  to_path(to_good, sizeof to_good, "good.csv");
  if (testutil_runf(NULL, 0, to_err, TO_CAP, "sample --count 6 --out %s", to_pent) != 0) return -1;
  if (testutil_runf(NULL, 0, to_err, TO_CAP, "table34 --samples 30 --format csv --out %s",
                    to_csv) != 0)
    return -1;
  return 0;
}

static int to_teardown(void **state) {
  (void)state;
  char cmd[1200];
  snprintf(cmd, sizeof cmd, "rm -rf %s", to_dir);
  return system(cmd) == 0 ? 0 : -1;
}

/* Every command with standard output on a full device. */
static void test_stdout_full(void **state) {
  (void)state;
  const char *cmds[] = {
    "list", "--help", "--version", "list --help", "flip R_inf 0 0 1 0 1 1 0 1",
    "sample --count 5", "table34 --samples 20", "table34 --samples 20 --format csv",
    "classify --input %s", "got --rule P_1 --random 8", "rule R_inf --samples 200",
    "merge %s",
  };
  for (size_t i = 0; i < sizeof cmds / sizeof cmds[0]; i++) {
    char args[2048];
    snprintf(args, sizeof args, cmds[i], strstr(cmds[i], "merge") ? to_csv : to_pent);
    int st = testutil_run_to(args, "/dev/full", to_err, TO_CAP);
    if (st != 1) fail_msg("'%s' > /dev/full: exit %d (want 1), stderr '%s'", args, st, to_err);
    to_one_line(args);
    assert_non_null(strstr(to_err, "standard output"));
  }
}

/* Every output option on a full device. */
static void test_option_full(void **state) {
  (void)state;
  const char *cmds[] = {
    "sample --count 5 --out /dev/full",
    "table34 --samples 20 --out /dev/full",
    "table34 --samples 20 --format csv --out " "%s" "/t.csv --plot /dev/full",
    "merge " "%s" "/counts.csv --out /dev/full",
    "merge " "%s" "/counts.csv --out " "%s" "/m.csv --plot /dev/full",
    "classify --input " "%s" "/pent.csv --out /dev/full",
    "got --rule P_1 --random 8 --csv /dev/full",
    "got --rule P_1 --random 8 --svg /dev/full",
  };
  for (size_t i = 0; i < sizeof cmds / sizeof cmds[0]; i++) {
    char args[2048];
    snprintf(args, sizeof args, cmds[i], to_dir, to_dir);
    int st = testutil_run(args, to_out, TO_CAP, to_err, TO_CAP);
    if (st != 1) fail_msg("'%s': exit %d (want 1), stderr '%s'", args, st, to_err);
    to_one_line(args);
    assert_non_null(strstr(to_err, "cannot write '/dev/full'"));
    to_no_temp(args);
  }
}

/* A failing run leaves the old file byte-identical, mode kept, no temp. */
static void test_failing_run_keeps_file(void **state) {
  (void)state;
  /* sqrt(x1) passes the definition's sample triangles but is NaN on the
  ** unit-disc pentagons (x1 < 0): the run itself fails. */
  const char *cmds[] = {
    "table34 --samples 30 --out %s --plot /nonexistent-dir/x.svg",
    "--define 'q = sqrt(x1)' table34 --measures q --samples 30 --out %s",
    "--define 'q = sqrt(x1)' table34 --measures q --samples 30 --format csv --out %s",
    "--define 'q = sqrt(x1)' classify --rule q_1 --input PENT --out %s",
    "table34 --samples 30 --out %s --plot /dev/full",
    "got --rule P_1 --random 8 --csv %s --svg /dev/full",
    "merge PENT --out %s",
    "classify --input %s --out %s",
  };
  for (size_t i = 0; i < sizeof cmds / sizeof cmds[0]; i++) {
    char fmt[1024], args[4096];
    const char *p = strstr(cmds[i], "PENT");
    if (p != NULL)
      snprintf(fmt, sizeof fmt, "%.*s%s%s", (int)(p - cmds[i]), cmds[i], to_pent, p + 4);
    else
      snprintf(fmt, sizeof fmt, "%s", cmds[i]);
    snprintf(args, sizeof args, fmt, to_good, to_good);
    testutil_write_file(to_good, TO_PRECIOUS);
    assert_int_equal(chmod(to_good, 0640), 0);
    int st = testutil_run(args, to_out, TO_CAP, to_err, TO_CAP);
    if (st == 0) fail_msg("'%s' should fail", args);
    to_one_line(args);
    char *now = testutil_read_file(to_good);
    assert_non_null(now);
    if (strcmp(now, TO_PRECIOUS) != 0) fail_msg("'%s' changed the old file: '%.200s'", args, now);
    free(now);
    struct stat st_;
    assert_int_equal(stat(to_good, &st_), 0);
    assert_int_equal(st_.st_mode & 0777, 0640);
    to_no_temp(args);
  }
}

/* Success replaces the file (through a symlink: the file it names), keeps
** an existing file's mode, and may overwrite the command's own input. */
static void test_success_replaces(void **state) {
  (void)state;
  char link[600], copy[600], other[600];
  testutil_write_file(to_good, TO_PRECIOUS);
  assert_int_equal(chmod(to_good, 0640), 0);
  assert_int_equal(testutil_runf(to_out, TO_CAP, to_err, TO_CAP,
                                 "sample --count 4 --seed 7 --out %s", to_good), 0);
  assert_int_equal(testutil_runf(to_out, TO_CAP, to_err, TO_CAP, "sample --count 4 --seed 7"),
                   0);
  char *now = testutil_read_file(to_good);
  assert_string_equal(now, to_out);
  free(now);
  struct stat st;
  assert_int_equal(stat(to_good, &st), 0);
  assert_int_equal(st.st_mode & 0777, 0640);

  to_path(link, sizeof link, "link.csv");
  unlink(link);
  assert_int_equal(symlink(to_good, link), 0);
  assert_int_equal(testutil_runf(NULL, 0, to_err, TO_CAP, "sample --count 2 --out %s", link), 0);
  struct stat lst;
  assert_int_equal(lstat(link, &lst), 0);
  assert_true(S_ISLNK(lst.st_mode));
  assert_int_equal(testutil_runf(to_out, TO_CAP, to_err, TO_CAP, "sample --count 2"), 0);
  now = testutil_read_file(to_good);
  assert_string_equal(now, to_out);
  free(now);
  unlink(link);

  /* classify in place equals classify to another file. */
  to_path(copy, sizeof copy, "copy.csv");
  to_path(other, sizeof other, "other.csv");
  now = testutil_read_file(to_pent);
  testutil_write_file(copy, now);
  free(now);
  assert_int_equal(testutil_runf(NULL, 0, to_err, TO_CAP,
                                 "classify --rule DT --input %s --out %s", copy, other), 0);
  assert_int_equal(testutil_runf(NULL, 0, to_err, TO_CAP,
                                 "classify --rule DT --input %s --out %s", copy, copy), 0);
  char *a = testutil_read_file(copy), *b = testutil_read_file(other);
  assert_string_equal(a, b);
  free(a);
  free(b);
  unlink(copy);
  unlink(other);
  to_no_temp("success");
}

/* Two outputs naming one file: refused before anything runs. */
static void test_same_file_twice(void **state) {
  (void)state;
  /* A name without a format's extension, acceptable to both outputs (a
  ** .csv name for an SVG output is refused for its extension first). */
  char link[600], same[600];
  to_path(link, sizeof link, "alias.out");
  to_path(same, sizeof same, "same.out");
  testutil_write_file(same, TO_PRECIOUS);
  unlink(link);
  assert_int_equal(symlink(same, link), 0);
  const char *fmts[] = {
    "table34 --samples 10 --out %s --plot %s",
    "merge COUNTS --out %s --plot %s",
    "got --rule P_1 --random 6 --csv %s --svg %s",
  };
  for (size_t i = 0; i < sizeof fmts / sizeof fmts[0]; i++)
    for (int spelling = 0; spelling < 3; spelling++) {
      char fmt[1024], second[700], args[4096];
      const char *p = strstr(fmts[i], "COUNTS");
      if (p != NULL)
        snprintf(fmt, sizeof fmt, "%.*s%s%s", (int)(p - fmts[i]), fmts[i], to_csv, p + 6);
      else
        snprintf(fmt, sizeof fmt, "%s", fmts[i]);
      if (spelling == 0) snprintf(second, sizeof second, "%s", same);
      else if (spelling == 1) snprintf(second, sizeof second, "%s/./same.out", to_dir);
      else snprintf(second, sizeof second, "%s", link);
      snprintf(args, sizeof args, fmt, same, second);
      int st = testutil_run(args, to_out, TO_CAP, to_err, TO_CAP);
      if (st != 2) fail_msg("'%s': exit %d (want 2), '%s'", args, st, to_err);
      to_one_line(args);
      assert_non_null(strstr(to_err, "two outputs"));
      char *now = testutil_read_file(same);
      assert_string_equal(now, TO_PRECIOUS);
      free(now);
    }
  /* Both to standard output. */
  int st = testutil_runf(to_out, TO_CAP, to_err, TO_CAP, "table34 --samples 10 --out - --plot -");
  assert_int_equal(st, 2);
  to_one_line("two stdout");
  unlink(link);
  unlink(same);
  to_no_temp("same file");
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_stdout_full),
    cmocka_unit_test(test_option_full),
    cmocka_unit_test(test_failing_run_keeps_file),
    cmocka_unit_test(test_success_replaces),
    cmocka_unit_test(test_same_file_twice),
  };
  return cmocka_run_group_tests(tests, to_setup, to_teardown);
}
