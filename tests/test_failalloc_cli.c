/*
** test_failalloc_cli.c: every allocation failure on the commands' main
** paths is a clean failure.  In a build with -DFLIPLAB_FAILALLOC=ON (made by
** scripts/test together with ASan) the program fails its K-th allocation
** when FLIPLAB_FAILALLOC=K (cli/failalloc.c).  For each command below and
** every K up to the number of allocations the command makes, the run must
** either succeed with exactly the output of an undisturbed run, or fail
** with status 1 or 2 and ONE line saying "out of memory" - no crash, no
** sanitizer report (leaks included: ASan checks at exit), no other message
** (an allocation failure must not pass for bad input), no temporary file
** left and no old output changed.
** In an ordinary build the program makes no such promise to the test: skipped.
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
#include <unistd.h>

#include "testutil.h"

#define TF_CAP (1 << 18)
#define TF_MAXK 400          /* allocations tried per command at most */
static char tf_out[TF_CAP], tf_err[TF_CAP], tf_want[TF_CAP];
static char tf_dir[512];

/* The commands; %1$s is the test directory (inputs made by tf_setup). */
static const char *const tf_cmds[] = {
  "flip R_inf 0 0 1 0 1 1 0 1",
  "sample --count 3 --out %1$s/out.csv",
  "table34 --samples 5 --format csv --out %1$s/out.csv --plot %1$s/plot.svg",
  "table34 --samples 5 --measures R,P",
  "merge %1$s/s1.csv %1$s/s2.csv --out %1$s/out.csv --plot %1$s/plot.svg",
  "merge %1$s/s1.csv %1$s/s2.csv --format text",
  "classify --input %1$s/pent.csv --rule R_inf --rule DT --out %1$s/out.csv",
  "got --rule P_1 --random 7 --csv %1$s/out.csv --svg %1$s/plot.svg --compare DT",
  "got --rule R_inf --polygon %1$s/poly.csv",
  "flipgraph --rule R_1 --points %1$s/poly.csv --memory 64K",
  "got --rule P_1 --random 6 --sampler star",
  "rule R_inf --samples 40 --quads 40",
  "--define 'q = a*b' table34 --measures q --samples 5 --format csv",
  "--define 'q = a*b' got --rule q_1 --random 6",
  "lot --rule ES:hexagon --random 30 --out %1$s/out.csv --cdf %1$s/cdf.csv",
  /* the weighted rule: a redundant site, so two rounds */
  "lot --rule WDT --points %1$s/wpts.csv --weights %1$s/w.csv --check --out %1$s/out.csv",
  "flipgraph --rule WDT --points %1$s/wpts.csv --weights %1$s/w.csv",
};

static int tf_setup(void **state) {
  (void)state;
  char cmd[1400];
  testutil_tmppath(tf_dir, sizeof tf_dir, "failalloc");
  snprintf(cmd, sizeof cmd, "rm -rf %s && mkdir -p %s", tf_dir, tf_dir);
  if (system(cmd) != 0) return -1;
  snprintf(cmd, sizeof cmd, "%s/poly.csv", tf_dir);
  testutil_write_file(cmd, "x,y\n0,0\n2,0\n3,1\n2,2.5\n0,2\n");
  snprintf(cmd, sizeof cmd, "%s/wpts.csv", tf_dir);
  testutil_write_file(cmd, "0,0\n4,0\n4,4\n0,4\n2,2\n1,3\n3,1\n");
  snprintf(cmd, sizeof cmd, "%s/w.csv", tf_dir);
  testutil_write_file(cmd, "0\n0\n0\n0\n-9\n1\n0.5\n");
  if (testutil_runf(NULL, 0, tf_err, TF_CAP, "sample --count 3 --out %s/pent.csv", tf_dir) ||
      testutil_runf(NULL, 0, tf_err, TF_CAP,
                    "table34 --samples 9 --measures R --shard 1/2 --format csv --out %s/s1.csv",
                    tf_dir) ||
      testutil_runf(NULL, 0, tf_err, TF_CAP,
                    "table34 --samples 9 --measures R --shard 2/2 --format csv --out %s/s2.csv",
                    tf_dir))
    return -1;
  return 0;
}

static int tf_teardown(void **state) {
  (void)state;
  char cmd[1200];
  snprintf(cmd, sizeof cmd, "rm -rf %s", tf_dir);
  return system(cmd) == 0 ? 0 : -1;
}

/* Drop the lines that measure time (got's "time: ..."), which differ
** between any two runs. */
static void tf_strip_time(char *s) {
  char *p = s, *w = s;
  while (*p) {
    char *nl = strchr(p, '\n');
    size_t len = nl ? (size_t)(nl - p) + 1 : strlen(p);
    if (strncmp(p, "time: ", 6) != 0) {
      memmove(w, p, len);
      w += len;
    }
    p += len;
  }
  *w = '\0';
}

/* The number of allocations of one run (0 when the build cannot fail them). */
static unsigned long tf_count(const char *args) {
  setenv("FLIPLAB_FAILALLOC_COUNT", "1", 1);
  testutil_run(args, tf_out, TF_CAP, tf_err, TF_CAP);
  unsetenv("FLIPLAB_FAILALLOC_COUNT");
  const char *c = strstr(tf_err, "failalloc: ");
  return c != NULL ? strtoul(c + 11, NULL, 10) : 0;
}

static void tf_no_temp(const char *args, unsigned long k) {
  DIR *d = opendir(tf_dir);
  assert_non_null(d);
  struct dirent *e;
  while ((e = readdir(d)) != NULL)
    if (e->d_name[0] == '.' && strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0) {
      closedir(d);
      fail_msg("'%s' K=%lu left '%s'", args, k, e->d_name);
    }
  closedir(d);
}

static void test_every_allocation(void **state) {
  (void)state;
  char probe[64];
  snprintf(probe, sizeof probe, "table34 --samples 1");
  if (tf_count(probe) == 0) skip();          /* not a FLIPLAB_FAILALLOC build */
  /* Sanitizer reports must not pass for our exit status 1. */
  setenv("ASAN_OPTIONS", "detect_leaks=1:exitcode=86", 1);
  setenv("UBSAN_OPTIONS", "halt_on_error=1:exitcode=87", 1);
  unsigned long runs = 0;
  for (size_t c = 0; c < sizeof tf_cmds / sizeof tf_cmds[0]; c++) {
    char args[2048];
    snprintf(args, sizeof args, tf_cmds[c], tf_dir);
    unsigned long n = tf_count(args);
    assert_int_equal(testutil_run(args, tf_want, TF_CAP, tf_err, TF_CAP), 0);
    tf_strip_time(tf_want);
    if (n > TF_MAXK) n = TF_MAXK;
    for (unsigned long k = 1; k <= n; k++) {
      char kk[32];
      snprintf(kk, sizeof kk, "%lu", k);
      setenv("FLIPLAB_FAILALLOC", kk, 1);
      int st = testutil_run(args, tf_out, TF_CAP, tf_err, TF_CAP);
      unsetenv("FLIPLAB_FAILALLOC");
      runs++;
      if (st == 0) {
        tf_strip_time(tf_out);
        if (strcmp(tf_out, tf_want) != 0 || tf_err[0] != '\0')
          fail_msg("'%s' K=%lu: success with other output (stderr '%.300s')", args, k, tf_err);
      } else if ((st != 1 && st != 2) || !testutil_one_line(tf_err) ||
                 strstr(tf_err, "out of memory") == NULL) {
        fail_msg("'%s' K=%lu: exit %d, stderr '%.600s'", args, k, st, tf_err);
      }
      tf_no_temp(args, k);
    }
  }
  print_message("%lu runs with a failed allocation\n", runs);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_every_allocation),
  };
  return cmocka_run_group_tests(tests, tf_setup, tf_teardown);
}
