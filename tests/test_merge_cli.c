/*
** test_merge_cli.c: `fliplab merge` sums only what may be summed
** (docs/merge.md).  Shards of one run merge in any order into the unsharded
** CSV; each way of mixing runs or losing data is refused with one line naming
** the file: another seed, tie tolerance, sample count or measure list, a
** missing shard (gap), overlapping shards, a file cut at a row boundary, a
** rule that does not match its measure and joint, a duplicate row, the same
** file twice (also through another path or a link), a file without the run
** columns.  And the crash reproducer: tens of thousands of distinct rules
** (a signed overflow in the table layout, then SIGSEGV) is a one-line error.
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

#include "testutil.h"

#define TM_CAP (1 << 20)
static char tm_out[TM_CAP], tm_err[TM_CAP];
static char tm_dir[512];

#define TM_RUN(...) testutil_runf(tm_out, TM_CAP, tm_err, TM_CAP, __VA_ARGS__)

static void tm_path(char *buf, size_t len, const char *name) {
  snprintf(buf, len, "%s/%s", tm_dir, name);
}

/* A shard K/N of `table34 --samples S` with extra options, into NAME. */
static void tm_shard(const char *name, int k, int n, int samples, const char *extra) {
  char p[700];
  tm_path(p, sizeof p, name);
  if (TM_RUN("table34 --samples %d --shard %d/%d --format csv %s --out %s", samples, k, n,
             extra, p) != 0)
    fail_msg("table34 failed: %s", tm_err);
}

static int tm_setup(void **state) {
  (void)state;
  char cmd[1200];
  testutil_tmppath(tm_dir, sizeof tm_dir, "merge");
  snprintf(cmd, sizeof cmd, "rm -rf %s && mkdir -p %s", tm_dir, tm_dir);
  return system(cmd) == 0 ? 0 : -1;
}

static int tm_teardown(void **state) {
  (void)state;
  char cmd[1200];
  snprintf(cmd, sizeof cmd, "rm -rf %s", tm_dir);
  return system(cmd) == 0 ? 0 : -1;
}

/* merge FILES (names in tm_dir) must fail with one line containing want. */
static void tm_refused(const char *files, const char *want) {
  char args[4096] = "merge", *p = args + 5;
  char buf[1024];
  snprintf(buf, sizeof buf, "%s", files);
  for (char *tok = strtok(buf, " "); tok != NULL; tok = strtok(NULL, " ")) {
    if (strcmp(tok, "-") == 0) p += snprintf(p, sizeof args - (size_t)(p - args), " -");
    else p += snprintf(p, sizeof args - (size_t)(p - args), " %s/%s", tm_dir, tok);
  }
  int st = testutil_run(args, tm_out, TM_CAP, tm_err, TM_CAP);
  if (st != 2) fail_msg("merge %s: exit %d (want 2): %s", files, st, tm_err);
  if (!testutil_one_line(tm_err)) fail_msg("merge %s: not one line: %s", files, tm_err);
  if (strstr(tm_err, want) == NULL) fail_msg("merge %s: '%s' lacks '%s'", files, tm_err, want);
  assert_string_equal(tm_out, "");
}

/* Shards in any order, and partial contiguous merges merged again, give
** the unsharded CSV byte for byte. */
static void test_merge_ok(void **state) {
  (void)state;
  char full[700], part[700];
  for (int k = 1; k <= 4; k++) {
    char name[32];
    snprintf(name, sizeof name, "s%d.csv", k);
    tm_shard(name, k, 4, 301, "");
  }
  tm_path(full, sizeof full, "full.csv");
  assert_int_equal(TM_RUN("table34 --samples 301 --format csv --out %s", full), 0);
  char *want = testutil_read_file(full);
  assert_int_equal(TM_RUN("merge %s/s3.csv %s/s1.csv %s/s4.csv %s/s2.csv", tm_dir, tm_dir,
                          tm_dir, tm_dir), 0);
  assert_string_equal(tm_out, want);
  tm_path(part, sizeof part, "s12.csv");
  assert_int_equal(TM_RUN("merge %s/s1.csv %s/s2.csv --out %s", tm_dir, tm_dir, part), 0);
  assert_int_equal(TM_RUN("merge %s/s4.csv %s %s/s3.csv", tm_dir, part, tm_dir), 0);
  assert_string_equal(tm_out, want);
  free(want);
}

static void test_merge_refusals(void **state) {
  (void)state;
  char src[700], dst[700];
  tm_shard("a1.csv", 1, 3, 300, "");
  tm_shard("a2.csv", 2, 3, 300, "");
  tm_shard("a3.csv", 3, 3, 300, "");
  tm_shard("seed.csv", 2, 3, 300, "--seed 9");
  tm_shard("eps.csv", 2, 3, 300, "--tie-eps 1e-9");
  tm_shard("samples.csv", 2, 3, 303, "");
  tm_shard("measures.csv", 2, 3, 300, "--measures R,-alpha");
  tm_shard("over.csv", 2, 4, 300, "");
  tm_refused("a1.csv seed.csv a3.csv", "seed");
  tm_refused("a1.csv eps.csv a3.csv", "tie_eps");
  tm_refused("a1.csv samples.csv", "303 samples");
  tm_refused("a1.csv measures.csv", "--measures");
  tm_refused("a1.csv a3.csv", "missing");
  tm_refused("a1.csv a2.csv over.csv", "overlap");
  tm_refused("a1.csv a1.csv", "same file");

  /* The same file under another path, and through a symbolic link. */
  char other[1200];
  snprintf(other, sizeof other, "merge %s/a1.csv %s/.//a1.csv", tm_dir, tm_dir);
  assert_int_equal(testutil_run(other, tm_out, TM_CAP, tm_err, TM_CAP), 2);
  assert_non_null(strstr(tm_err, "same file"));
  tm_path(src, sizeof src, "a1.csv");
  tm_path(dst, sizeof dst, "link.csv");
  assert_int_equal(symlink(src, dst), 0);
  tm_refused("a1.csv a2.csv link.csv", "same file");

  /* Cut at a row boundary: the first 40 lines of a2.csv. */
  char *text = testutil_read_file(src), *p = text;
  for (int l = 0; l < 40; l++) p = strchr(p, '\n') + 1;
  *p = '\0';
  tm_path(dst, sizeof dst, "cut.csv");
  testutil_write_file(dst, text);
  tm_refused("cut.csv a2.csv a3.csv", "truncated");
  free(text);
}

/* Rows edited by hand: a rule renamed, a row repeated, the run columns gone. */
static void test_merge_bad_rows(void **state) {
  (void)state;
  char a1[700], dst[700];
  tm_shard("b1.csv", 1, 2, 200, "");
  tm_path(a1, sizeof a1, "b1.csv");
  char *text = testutil_read_file(a1);
  char *line2 = strchr(text, '\n') + 1, *line3 = strchr(line2, '\n') + 1;

  /* R_-inf relabelled R_1 (its measure and joint still say R, -inf). */
  char *mod = malloc(strlen(text) + 64);
  char *r = strstr(line2, "R_-inf");
  assert_non_null(r);
  sprintf(mod, "%.*sR_1%s", (int)(r - text), text, r + 6);
  tm_path(dst, sizeof dst, "relabel.csv");
  testutil_write_file(dst, mod);
  tm_refused("relabel.csv", "does not match");

  /* Row 2 again at the end (the row count no longer matches either). */
  sprintf(mod, "%s%.*s", text, (int)(line3 - line2), line2);
  tm_path(dst, sizeof dst, "dup.csv");
  testutil_write_file(dst, mod);
  tm_refused("dup.csv", "appears twice");

  /* The ten columns of old files: no run to check. */
  testutil_write_file(dst, "measure,joint,rule,samples,type_I,type_II,type_III,type_IV,type_V,dt\n"
                           "R,-inf,R_-inf,10,10,0,0,0,0,10\n");
  tm_refused("dup.csv", "no run columns");

  /* Run columns that contradict the counts. */
  testutil_write_file(dst, "measure,joint,rule,samples,type_I,type_II,type_III,type_IV,type_V,"
                           "dt,seed,tie_eps,first,end,total,rules\n"
                           "R,-inf,R_-inf,10,10,0,0,0,0,10,1,1e-12,0,11,100,1\n");
  tm_refused("dup.csv", "inconsistent run columns");
  free(mod);
  free(text);
}

/* Tens of thousands of distinct rules (the crash reproducer), a huge field,
** a record of thousands of fields: one-line errors, quickly. */
static void test_merge_bounds(void **state) {
  (void)state;
  char dst[700];
  tm_path(dst, sizeof dst, "many.csv");
  FILE *f = fopen(dst, "wb");
  assert_non_null(f);
  fputs("measure,joint,rule,samples,type_I,type_II,type_III,type_IV,type_V,dt\n", f);
  for (int i = 0; i < 30000; i++) fprintf(f, "m%d,%d,m%d_%d,10,10,0,0,0,0,10\n", i, i, i, i);
  assert_int_equal(fclose(f), 0);
  tm_refused("many.csv", "does not match");      /* joint "0".."29999": the first bad one */
  f = fopen(dst, "wb");
  fputs("measure,joint,rule,samples,type_I,type_II,type_III,type_IV,type_V,dt\n", f);
  for (int i = 0; i < 30000; i++) fprintf(f, "m%d,inf,m%d_inf,10,10,0,0,0,0,10\n", i, i);
  assert_int_equal(fclose(f), 0);
  tm_refused("many.csv", "more than");
  f = fopen(dst, "wb");
  fputs("measure,joint,rule,samples,type_I,type_II,type_III,type_IV,type_V,dt\nR", f);
  for (int i = 0; i < 100000; i++) fputc('x', f);
  fputs(",inf,R_inf,10,10,0,0,0,0,10\n", f);
  assert_int_equal(fclose(f), 0);
  tm_refused("many.csv", "longer than 4096 bytes");
  f = fopen(dst, "wb");
  fputs("measure,joint,rule,samples,type_I,type_II,type_III,type_IV,type_V,dt\n", f);
  for (int i = 0; i < 5000; i++) fputs("1,", f);
  fputs("1\n", f);
  assert_int_equal(fclose(f), 0);
  tm_refused("many.csv", "more than 256 fields");
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_merge_ok),
    cmocka_unit_test(test_merge_refusals),
    cmocka_unit_test(test_merge_bad_rows),
    cmocka_unit_test(test_merge_bounds),
  };
  return cmocka_run_group_tests(tests, tm_setup, tm_teardown);
}
