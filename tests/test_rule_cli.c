/*
** test_rule_cli.c: `fliplab rule`, --define and --plugin through the program.
**
** The printed numbers are checked against the library (counts from
** flipgraph_tally, witnesses re-classified from their printed coordinates,
** the lowest-index claim by brute force), not against remembered output.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "measure.h"
#include "flipgraph.h"
#include "rule.h"
#include "sampler.h"
#include "testutil.h"

#define OUTCAP (1 << 20)
#define PLUGINS FLIPLAB_BUILD_DIR "/plugins/"

static char out[OUTCAP], err[OUTCAP];

/* Run `fliplab printf(FMT, ...)` into out and err. */
#define RUN(...) testutil_runf(out, sizeof out, err, sizeof err, __VA_ARGS__)

/* The count and the percentage printed on the "  LABEL  count ..." line of
** the block of rule `name`. */
static unsigned long long count_of(const char *text, const char *name, const char *label) {
  char head[128], key[32];
  snprintf(head, sizeof head, "rule %s:", name);
  const char *b = strstr(text, head);
  if (b == NULL) fail_msg("no block for rule %s in:\n%s", name, text);
  snprintf(key, sizeof key, "\n  %-5s ", label);
  const char *l = strstr(b, key);
  if (l == NULL) fail_msg("no line %s for rule %s", label, name);
  return strtoull(l + strlen(key), NULL, 10);
}

static const char *block_of(const char *text, const char *name) {
  char head[128];
  snprintf(head, sizeof head, "rule %s:", name);
  const char *b = strstr(text, head);
  if (b == NULL) fail_msg("no block for rule %s", name);
  return b;
}

/* --define q = a*b*c: the same counts as the built-in abc for all six
** joints, via table34 --measures (CSV) and via rule. */
static void test_formula_equals_builtin(void **state) {
  (void)state;
  int rc = RUN("--define 'q = a*b*c' table34 --measures q,abc --samples 5000 --format csv");
  if (rc != 0) fail_msg("table34 exit %d: %s", rc, err);
  static const char *const joints[] = {"-inf", "-1", "0", "1", "2", "inf"};
  for (int j = 0; j < 6; j++) {
    char kq[64], ka[64];
    snprintf(kq, sizeof kq, "\nq,%s,q_%s,", joints[j], joints[j]);
    snprintf(ka, sizeof ka, "\nabc,%s,abc_%s,", joints[j], joints[j]);
    const char *lq = strstr(out, kq), *la = strstr(out, ka);
    if (lq == NULL || la == NULL) fail_msg("rows for joint %s missing:\n%s", joints[j], out);
    lq += strlen(kq);
    la += strlen(ka);
    size_t nq = strcspn(lq, "\n"), na = strcspn(la, "\n");
    assert_int_equal(nq, na);
    assert_memory_equal(lq, la, nq);
  }
  assert_int_equal(RUN("--define 'q = a*b*c' rule q_0 abc_0 --samples 5000 --quads 1000"), 0);
  static const char *const labels[] = {"I", "II", "III", "IV", "V", "DT"};
  for (int k = 0; k < 6; k++)
    assert_int_equal(count_of(out, "q_0", labels[k]), count_of(out, "abc_0", labels[k]));
}

/* -2*A/P with joint 1 is -r_1, Delaunay-equivalent (thesis theorem 16). */
static void test_inradius_is_delaunay(void **state) {
  (void)state;
  assert_int_equal(RUN("--define 'rr = -2*A/P' rule rr_1 --samples 20000 --quads 50000"), 0);
  assert_int_equal(count_of(out, "rr_1", "DT"), 20000);
  assert_int_equal(count_of(out, "rr_1", "I"), 20000);
  const char *b = block_of(out, "rr_1");
  assert_non_null(strstr(b, "50000 random convex quadrilaterals: 0 disagreements"));
  assert_non_null(strstr(b, "agrees with Delaunay on all 20000 pentagons"));
  assert_null(strstr(out, "proved"));
  /* And the counts are those of the library. */
  rule r;
  char e[2048];
  assert_int_equal(rule_parse("-r_1", &r, e, sizeof e), 0);
  flipgraph_counts c;
  memset(&c, 0, sizeof c);
  assert_int_equal(flipgraph_tally(&r, 1, 1, 0, 20000, RULE_DEFAULT_TIE_EPS, 2, &c, NULL, NULL), 0);
  assert_int_equal(c.dt, 20000);
}

/* Parse every witness line "type T #IDX: pentagon x,y,...; decisions D;
** sinks ..." of a block. */
typedef struct witness {
  char type[8];
  unsigned long long idx;
  geom_point v[5];
  char dec[6];
  int nsinks, sink[2];
} witness;

static int witnesses(const char *block, witness *w, int cap) {
  int n = 0;
  const char *end = strstr(block + 1, "\nrule ");
  for (const char *l = strstr(block, "    type "); l && (!end || l < end) && n < cap;
       l = strstr(l + 1, "    type ")) {
    witness *x = &w[n];
    int used = 0;
    if (sscanf(l, "    type %7s #%llu: pentagon %n", x->type, &x->idx, &used) != 2 || used == 0)
      fail_msg("bad witness line: %.200s", l);
    const char *p = l + used;
    for (int i = 0; i < 5; i++) {
      char *q;
      x->v[i].x = strtod(p, &q);
      p = q + 1;
      x->v[i].y = strtod(p, &q);
      p = q + 1;
    }
    assert_int_equal(sscanf(p, " decisions %5s", x->dec), 1);
    const char *s = strstr(p, "sinks");
    assert_non_null(s);
    s += 5;
    x->nsinks = 0;
    int len = 0;
    while (x->nsinks < 2 && sscanf(s, " T%d%n", &x->sink[x->nsinks], &len) == 1) {
      x->nsinks++;
      s += len;
    }
    n++;
  }
  return n;
}

/* gamma as a formula: type III witnesses whose graphs, re-classified from
** the printed coordinates under the built-in gamma_inf, have two sinks;
** and they are the lowest sample indices of type III. */
static void test_gamma_witnesses(void **state) {
  (void)state;
  assert_int_equal(RUN("--define 'g = gamma' rule g_inf --samples 3000 --quads 2000 --witnesses 3"), 0);
  const char *b = block_of(out, "g_inf");
  assert_non_null(strstr(b, "verdict: not systematic:"));
  witness w[16];
  int n = witnesses(b, w, 16);
  rule r;
  char e[2048];
  assert_int_equal(rule_parse("gamma_inf", &r, e, sizeof e), 0);
  int n3 = 0;
  unsigned long long idx3[3];
  for (int k = 0; k < n; k++) {
    flipgraph_pentagon p;
    flipgraph g;
    flipgraph_prepare(&p, w[k].v);
    flipgraph_classify(&p, &r, RULE_DEFAULT_TIE_EPS, &g);
    assert_string_equal(flipgraph_type_name(g.type), w[k].type);
    for (int j = 0; j < 5; j++)
      assert_int_equal(w[k].dec[j], g.dec[j] == RULE_AC ? 'A' : g.dec[j] == RULE_BD ? 'B' : 'E');
    if (g.type == FLIPGRAPH_III) {
      assert_int_equal(g.nsinks, 2);
      assert_int_equal(w[k].nsinks, 2);
      assert_int_equal(w[k].sink[0], g.sink[0]);
      assert_int_equal(w[k].sink[1], g.sink[1]);
      idx3[n3++] = w[k].idx;
    }
  }
  assert_int_equal(n3, 3);
  /* Brute force: the first three type-III samples of the stream. */
  int found = 0;
  for (unsigned long long i = 0; found < 3; i++) {
    geom_point v[5];
    flipgraph_pentagon p;
    flipgraph g;
    sampler_pentagon(1, i, v);
    flipgraph_prepare(&p, v);
    flipgraph_classify(&p, &r, RULE_DEFAULT_TIE_EPS, &g);
    if (g.type == FLIPGRAPH_III) assert_int_equal(idx3[found++], i);
  }
}

/* Same output whatever the thread count, plugins included. */
static void test_thread_independent(void **state) {
  (void)state;
  static char first[OUTCAP];
  const char *args =
    "--plugin " PLUGINS "rule109.so --plugin " PLUGINS "rule156.so --define 'g = gamma' "
    "rule rule109 rule156 P2/A_2 g_inf --samples 20000 --quads 20000 --witnesses 2 --threads %d";
  assert_int_equal(RUN(args, 1), 0);
  memcpy(first, out, sizeof out);
  assert_int_equal(RUN(args, 2), 0);
  assert_string_equal(first, out);
  assert_int_equal(count_of(out, "rule109", "I") + count_of(out, "rule109", "II") +
                   count_of(out, "rule109", "III") + count_of(out, "rule109", "IV") +
                   count_of(out, "rule109", "V"), 20000);
}

static void test_svg(void **state) {
  (void)state;
  char dir[512], cmd[1024];
  testutil_tmppath(dir, sizeof dir, "svg");
  assert_int_equal(
    RUN("--define 'g = gamma' rule g_inf --samples 500 --quads 0 --witnesses 1 --svg-dir %s", dir), 0);
  const char *s = strstr(out, "svg: ");
  assert_non_null(s);
  char path[1024];
  assert_int_equal(sscanf(s, "svg: %1023s", path), 1);
  char *svg = testutil_read_file(path);
  assert_non_null(svg);
  assert_non_null(strstr(svg, "<svg"));
  assert_non_null(strstr(svg, "</svg>"));
  assert_non_null(strstr(svg, ">sink<"));
  assert_non_null(strstr(svg, "marker-end"));
  assert_non_null(strstr(svg, "rule g_inf"));
  free(svg);
  snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
  assert_int_equal(system(cmd), 0);
}

/* Every refusal: exit status 2 (usage/input) or 1 (bad value during the
** run), exactly one line on stderr naming the problem, no crash. */
static void refused(const char *args, int status, const char *want) {
  int rc = RUN("%s", args);
  if (rc != status) fail_msg("'%s': exit %d, expected %d; stderr: %s", args, rc, status, err);
  if (!testutil_one_line(err)) fail_msg("'%s': stderr is not one line: %s", args, err);
  if (strstr(err, want) == NULL) fail_msg("'%s': stderr lacks '%s': %s", args, want, err);
}

static void test_refusals(void **state) {
  (void)state;
  refused("--define 'q = a*' rule q_1", 2, "syntax error at position 6");
  refused("--define 'q = (a+b' list", 2, "syntax error at position");
  refused("--define 'q = a*foo' rule q_1", 2, "unknown variable 'foo'");
  refused("--define 'abc = a' list", 2, "already exists");
  refused("--define 'q = a' --define 'q = b' list", 2, "already exists");
  refused("--define", 2, "needs a value");
  refused("--plugin " PLUGINS "nothere.so rule DT", 2, "No such file");
  refused("--plugin " PLUGINS "badabi.so rule DT", 2, "ABI");
  refused("--plugin " PLUGINS "noentry.so rule DT", 2, "fliplab_plugin_entry");
  refused("--plugin " PLUGINS "badname.so list", 2, "has the byte 0x0a");
  refused("--plugin " PLUGINS "rule109.so --plugin " PLUGINS "rule109.so list", 2, "already exists");
  refused("--define 'z = a - 1' rule z_1", 2, "both signs");
  refused("rule nosuch_1", 2, "unknown measure");
  refused("rule DT --samples 0", 2, "--samples");
  refused("rule DT --witnesses 1000", 2, "--witnesses");
  /* NaN during a run: named with its triangle, exit 1, no counts. */
  refused("--define 'u = sqrt(x1)' rule u_1 --samples 2000 --quads 0", 1, "not finite");
  assert_null(strstr(out, "type"));
  /* A command that does not check itself is caught on exit. */
  refused("--define 'u = sqrt(x1)' flip u_1 -1 0 0 -1 1 0 0 1", 1, "measure 'u'");
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_formula_equals_builtin),
    cmocka_unit_test(test_inradius_is_delaunay),
    cmocka_unit_test(test_gamma_witnesses),
    cmocka_unit_test(test_thread_independent),
    cmocka_unit_test(test_svg),
    cmocka_unit_test(test_refusals),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
