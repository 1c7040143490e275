/*
** test_help_cli.c: what `--help` and the error hints promise.
**  - every command listed by `fliplab --help` has a `--help` that lists its
**    options, each option taking a value shows its default (or says it is
**    required), and every listed option is one the command accepts;
**  - the one option parser: every value option without its value is one
**    line naming it; the shared rows (--seed, --threads, --tie-eps) have
**    the same bounds, messages and defaults in every command, --tie-eps's
**    printed from RULE_DEFAULT_TIE_EPS;
**  - `fliplab --help` names every formula variable;
**  - "did you mean" for commands, options, rules and measures, including
**    the sign forms (alpha for -alpha), and a useful word for an undefined
**    measure;
**  - comma lists of rules, output extensions checked, the table format
**    taken from --out's name.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "formula.h"
#include "rule.h"
#include "testutil.h"

#define TH_CAP 65536
static char th_out[TH_CAP], th_err[TH_CAP];

static int th_run(const char *fmt, const char *a, const char *b) {
  char args[4096];
  if (strlen(a) + strlen(b) + strlen(fmt) >= 1024) fail_msg("arguments too long");
  snprintf(args, sizeof args, fmt, a, b);
  int st = testutil_run(args, th_out, TH_CAP, th_err, TH_CAP);
  if (st < 0 || st >= 128) fail_msg("fliplab %s: status %d (crash?)", args, st);
  return st;
}

/* stderr is one line and contains want. */
static void th_says(const char *args, int status, const char *want) {
  int st = testutil_run(args, th_out, TH_CAP, th_err, TH_CAP);
  if (st != status || !testutil_one_line(th_err) || strstr(th_err, want) == NULL)
    fail_msg("fliplab %s: exit %d (want %d), stderr '%s' lacks '%s'", args, st, status, th_err,
             want);
}

/* The commands, from the "commands:" block of fliplab --help. */
static int th_commands(char names[][32], int cap) {
  assert_int_equal(th_run("--help", "", ""), 0);
  char *p = strstr(th_out, "commands:\n");
  assert_non_null(p);
  p += strlen("commands:\n");
  int n = 0;
  while (strncmp(p, "  ", 2) == 0 && n < cap) {
    sscanf(p + 2, "%31s", names[n++]);
    p = strchr(p, '\n') + 1;
  }
  return n;
}

/* What one parser and its shared rows promise of a value option: its
** value missing is one line naming it; --tie-eps shows the rule library's
** default; --seed, --threads and --tie-eps have the same bounds and
** messages in every command. */
static void th_option_rows(const char *cmd, const char *name, const char *entry) {
  char want[2400];
  snprintf(want, sizeof want, "fliplab %s: option %s needs a value\n", cmd, name);
  if (th_run("%s %s", cmd, name) != 2 || strcmp(th_err, want) != 0)
    fail_msg("%s %s (no value): '%s', want '%s'", cmd, name, th_err, want);
  if (strcmp(name, "--tie-eps") == 0) {
    snprintf(want, sizeof want, "(default: %g)", RULE_DEFAULT_TIE_EPS);
    if (strstr(entry, want) == NULL) fail_msg("%s --tie-eps: '%s' lacks %s", cmd, entry, want);
    snprintf(want, sizeof want, "fliplab %s: --tie-eps -1 is out of range [0, ", cmd);
    if (th_run("%s --tie-eps -1", cmd, "") != 2 || strncmp(th_err, want, strlen(want)) != 0)
      fail_msg("%s --tie-eps -1: '%s'", cmd, th_err);
  }
  if (strcmp(name, "--threads") == 0) {
    snprintf(want, sizeof want, "fliplab %s: --threads 0 is out of range [1, 1024]\n", cmd);
    if (th_run("%s --threads 0", cmd, "") != 2 || strcmp(th_err, want) != 0)
      fail_msg("%s --threads 0: '%s', want '%s'", cmd, th_err, want);
    assert_non_null(strstr(entry, "(default: all cores)"));
  }
  if (strcmp(name, "--seed") == 0) {
    snprintf(want, sizeof want, "fliplab %s: --seed expects a non-negative integer, got "
             "'-1'\n", cmd);
    if (th_run("%s --seed -1", cmd, "") != 2 || strcmp(th_err, want) != 0)
      fail_msg("%s --seed -1: '%s', want '%s'", cmd, th_err, want);
    assert_non_null(strstr(entry, "(default: 1)"));
  }
}

static void test_command_help(void **state) {
  (void)state;
  char cmds[32][32];
  int nc = th_commands(cmds, 32);
  assert_true(nc >= 8);
  for (int c = 0; c < nc; c++) {
    assert_int_equal(th_run("%s --help", cmds[c], ""), 0);
    char help[TH_CAP];
    snprintf(help, sizeof help, "%s", th_out);
    char *opts = strstr(help, "\noptions:\n");
    if (opts == NULL) fail_msg("%s --help has no options section", cmds[c]);
    /* Entries start with "  --"; continuation lines with more blanks. */
    for (char *l = opts + 10; *l; ) {
      char *end = strchr(l, '\n');
      if (end == NULL) break;
      if (strncmp(l, "  --", 4) != 0) {
        l = end + 1;
        continue;
      }
      char name[64] = "", arg[64] = "";
      sscanf(l + 2, "%63s %63s", name, arg);
      /* The entry: up to the next option line. */
      char *next = end + 1;
      while (*next && strncmp(next, "  --", 4) != 0) next = strchr(next, '\n') ? strchr(next, '\n') + 1 : next + strlen(next);
      int takes_value = arg[0] >= 'A' && arg[0] <= 'Z';
      if (takes_value && strcmp(name, "--help") != 0) {
        char entry[2048];
        snprintf(entry, sizeof entry, "%.*s", (int)(next - l), l);
        if (strstr(entry, "(default: ") == NULL)
          fail_msg("%s --help: %s shows no default: %s", cmds[c], name, entry);
        th_option_rows(cmds[c], name, entry);
      }
      if (strcmp(name, "--help") != 0) {
        char unknown[96];
        snprintf(unknown, sizeof unknown, "unknown option '%s'", name);
        /* A trailing unknown option stops the command after parsing, before
        ** any work (the matrix of `paradigms` took seconds a value). */
        th_run("%s %s 1 --th-not-an-option", cmds[c], name);
        if (strstr(th_err, unknown) != NULL)
          fail_msg("%s refuses its own option %s: %s", cmds[c], name, th_err);
      }
      l = next;
    }
  }
}

static void test_formula_variables_in_help(void **state) {
  (void)state;
  assert_int_equal(th_run("--help", "", ""), 0);
  char vars[256];
  snprintf(vars, sizeof vars, "%s", formula_vars);
  for (char *t = strtok(vars, " ()"); t != NULL; t = strtok(NULL, " ()")) {
    if (strcmp(t, "and") == 0 || strcmp(t, "constant") == 0) continue;
    /* As a word: a blank before, no letter or digit after. */
    int found = 0;
    size_t tl = strlen(t);
    for (const char *p = strstr(th_out, t); p != NULL && !found; p = strstr(p + 1, t))
      found = p > th_out && p[-1] == ' ' && !isalnum((unsigned char)p[tl]);
    if (!found)
      fail_msg("fliplab --help does not name the formula variable '%s'", t);
  }
}

static void test_did_you_mean(void **state) {
  (void)state;
  th_says("tabel34", 2, "did you mean 'table34'?");
  th_says("flip alpha_inf 0 0 1 0 1 1 0 1", 2, "did you mean '-alpha_inf'?");
  th_says("flip -gamma_1 0 0 1 0 1 1 0 1", 2, "did you mean 'gamma_1'?");
  th_says("table34 --samples 10 --measures R,alpha", 2, "did you mean '-alpha'?");
  th_says("rule R_1 --sed 3", 2, "did you mean '--seed'?");
  th_says("table34 --sampels 10", 2, "did you mean '--samples'?");
  th_says("rule lamda_1 --samples 10", 2, "did you mean 'lambda_1'?");
  th_says("rule R_2x --samples 10", 2, "unknown joint");
  /* An undefined measure: how to define one. */
  th_says("rule g_inf --samples 10", 2, "--define 'g = EXPR'");
  /* Nothing close: no wild guess. */
  th_says("rule zzzzzz_1 --samples 10", 2, "unknown measure 'zzzzzz'");
  assert_null(strstr(th_err, "did you mean"));
}

static void test_rule_lists_and_names(void **state) {
  (void)state;
  assert_int_equal(system("mkdir -p " FLIPLAB_BUILD_DIR "/testtmp"), 0);
  assert_int_equal(th_run("rule R_1,P_1 --samples 200 --quads 10", "", ""), 0);
  assert_non_null(strstr(th_out, "rule R_1:"));
  assert_non_null(strstr(th_out, "rule P_1:"));
  th_says("rule R_1,,P_1 --samples 10", 2, "empty");
  /* Extensions: an SVG output never lands in a .png; nothing is written. */
  char png[512], md[512];
  snprintf(png, sizeof png, "%s/testtmp/help_fig.png", FLIPLAB_BUILD_DIR);
  snprintf(md, sizeof md, "%s/testtmp/help_table.md", FLIPLAB_BUILD_DIR);
  unlink(png);
  assert_int_equal(th_run("table34 --samples 10 --plot %s", png, ""), 2);
  assert_non_null(strstr(th_err, ".svg"));
  assert_int_equal(access(png, F_OK), -1);
  assert_int_equal(th_run("sample --count 2 --out %s", png, ""), 2);
  /* The format follows --out's extension, and must agree with --format. */
  assert_int_equal(th_run("table34 --samples 10 --out %s", md, ""), 0);
  char *s = testutil_read_file(md);
  assert_non_null(s);
  assert_non_null(strstr(s, "| joint | row |"));
  free(s);
  assert_int_equal(th_run("table34 --samples 10 --format csv --out %s", md, ""), 2);
  unlink(md);
}

/* Every input file may be '-' (standard input); a file given without its
** option is pointed to it. */
static void test_stdin_and_positional(void **state) {
  (void)state;
  char poly[512];
  snprintf(poly, sizeof poly, "%s/testtmp/help_poly.csv", FLIPLAB_BUILD_DIR);
  assert_int_equal(system("mkdir -p " FLIPLAB_BUILD_DIR "/testtmp"), 0);
  testutil_write_file(poly, "x,y\n0,0\n2,0\n3,1\n2,3\n0,2\n-1,1\n");
  assert_int_equal(th_run("got --rule P_1 --polygon %s", poly, ""), 0);
  static char want[TH_CAP];
  memcpy(want, th_out, TH_CAP);
  assert_int_equal(testutil_run_in(poly, "got --rule P_1 --polygon -", th_out, TH_CAP, th_err,
                                   TH_CAP), 0);
  /* The same answer: total and runner-up lines, and the triangles (the
  ** source's name and the time may differ). */
  const char *keys[] = {"total badness:", "runner-up:", "triangles:"};
  for (int k = 0; k < 3; k++) {
    const char *a = strstr(want, keys[k]), *b = strstr(th_out, keys[k]);
    assert_non_null(a);
    assert_non_null(b);
    size_t la = strcspn(a, "\n"), lb = strcspn(b, "\n");
    if (k == 2) la = strlen(a), lb = strlen(b);
    assert_int_equal(la, lb);
    assert_memory_equal(a, b, la);
  }
  th_says("classify p.csv", 2, "--input p.csv");
  unlink(poly);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_command_help),
    cmocka_unit_test(test_formula_variables_in_help),
    cmocka_unit_test(test_did_you_mean),
    cmocka_unit_test(test_rule_lists_and_names),
    cmocka_unit_test(test_stdin_and_positional),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
