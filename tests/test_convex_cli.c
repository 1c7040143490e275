/*
** test_convex_cli.c: `fliplab convex` as a user meets it:
**  - bad input is one line on stderr and exit status 2: an unknown sampler
**    or region, a region the sampler does not take, n and count out of
**    range, a bad seed, naive rejection past n = 10, an n the sampler cannot
**    realise in doubles, a law or inner method the sampler does not take;
**    and no output file is left behind;
**  - every sampler of the registry (each law, and the dual of several inner
**    methods): the CSV has n rows per polygon, each polygon strictly convex
**    (re-checked exactly from the printed digits, which read back bit for
**    bit), and is the same file for 1 and 2 threads;
**  - --stats prints every statistic; --svg writes one SVG with a panel each;
**    --stats-out has a row per polygon.
*/
#include <ctype.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "geom.h"
#include "sampler.h"
#include "testutil.h"

#define CAP (1 << 20)
static char out[CAP], err[CAP];

static void says(const char *args, const char *want) {
  int st = testutil_run(args, out, CAP, err, CAP);
  if (st != 2 || !testutil_one_line(err) || strstr(err, want) == NULL)
    fail_msg("fliplab %s: exit %d, stderr '%s' lacks '%s'", args, st, err, want);
}

static void test_errors(void **state) {
  (void)state;
  char path[512], args[1024];
  says("convex --sampler bogus", "unknown sampler 'bogus' (valid: rejection, naive");
  says("convex --region moon", "unknown region 'moon' (valid: square, disc, triangle)");
  says("convex --sampler valtr --region disc", "does not draw in the disc");
  says("convex --sampler vector --region disc", "draws no points from a region");
  says("convex --n 2", "--n 2 is out of range");
  says("convex --n 1e8", "out of range");
  says("convex --count 0", "--count 0 is out of range");
  says("convex --seed -1", "--seed");
  says("convex --sampler naive --n 11", "naive takes n up to 10");
  says("convex --law 1", "law 1: sampler rejection takes laws 0 .. 0");
  says("convex --sampler triangulation --law 1", "law 1: sampler triangulation takes laws 0");
  says("convex --sampler bounce --law 2", "--law 2 is out of range");
  says("convex --sampler dual --inner geobench --law 1", "law 1: sampler geobench takes");
  says("convex --sampler dual --inner moon", "unknown inner method 'moon' (valid: vector, "
       "circle, triangulation, bounce, dual-rejection, geobench, angles)");
  says("convex --sampler dual --inner dual", "unknown inner method 'dual'");
  says("convex --sampler dual --inner rejection", "unknown inner method 'rejection'");
  says("convex --sampler bounce --inner vector", "sampler bounce takes no inner method");
  says("convex --sampler dual-rejection --n 11", "dual-rejection takes n up to 10");
  says("convex --sampler dual --inner dual-rejection --n 11", "inner method dual-rejection "
       "takes n up to 10");
  says("convex --sampler angles --n 300", "could not realise a strictly convex 300-gon");
  testutil_tmppath(path, sizeof path, "convex_fail.csv");
  unlink(path);
  snprintf(args, sizeof args, "convex --sampler iteration --region square --n 3000 --count 1 "
           "--out %s", path);
  says(args, "could not realise a strictly convex 3000-gon");
  assert_true(access(path, F_OK) != 0);
}

/* Parse the CSV: every polygon has n rows, vertices in order, strictly
** convex; the number of polygons. */
static int check_csv(const char *text, size_t n) {
  const char *p = strchr(text, '\n');
  assert_non_null(p);
  static const char head[] = "polygon,vertex,x,y,log_weight,h\n";
  assert_int_equal(strncmp(text, head, strlen(head)), 0);
  geom_point v[64];
  int polys = 0;
  for (p++; *p;) {
    for (size_t j = 0; j < n; j++) {
      unsigned long long id, vtx, h;
      double lw;
      int len;
      assert_int_equal(sscanf(p, "%llu,%llu,%lf,%lf,%lf,%llu%n", &id, &vtx, &v[j].x, &v[j].y,
                              &lw, &h, &len), 6);
      assert_true(id == (unsigned long long)polys && vtx == j);
      p = strchr(p, '\n') + 1;
    }
    size_t bad;
    int rev;
    assert_int_equal(geom_polygon_check(v, n, &bad, &rev), GEOM_OK);
    assert_int_equal(rev, 0);
    polys++;
  }
  return polys;
}

static void test_csv_threads(void **state) {
  (void)state;
  static const char *const s[] = {"rejection --region disc", "iteration --region triangle",
                                  "valtr", "naive --region square", "triangulation",
                                  "bounce", "bounce --law 1", "dual",
                                  "dual --inner bounce --law 1", "dual --inner triangulation",
                                  "dual-rejection",
                                  "geobench", "angles", "vector", "circle"};
  for (size_t k = 0; k < sizeof s / sizeof s[0]; k++) {
    char args[256];
    snprintf(args, sizeof args, "convex --sampler %s --n 8 --count 40 --threads 1", s[k]);
    assert_int_equal(testutil_run(args, out, CAP, err, CAP), 0);
    assert_int_equal(check_csv(out, 8), 40);
    char *one = strdup(out);
    snprintf(args, sizeof args, "convex --sampler %s --n 8 --count 40 --threads 2", s[k]);
    assert_int_equal(testutil_run(args, out, CAP, err, CAP), 0);
    assert_string_equal(one, out);
    free(one);
  }
}

static void test_stats_svg(void **state) {
  (void)state;
  char svg[512], st[512];
  testutil_tmppath(svg, sizeof svg, "convex.svg");
  testutil_tmppath(st, sizeof st, "convex_stats.csv");
  assert_int_equal(testutil_runf(out, CAP, err, CAP, "convex --n 12 --count 30 --stats --svg %s "
                                 "--svg-count 3 --stats-out %s", svg, st), 0);
  static const char *const names[] = {"area", "perimeter", "h", "unimodal", "rect_differ",
                                      "effective sample size"};
  for (size_t k = 0; k < 6; k++) assert_non_null(strstr(out, names[k]));
  char *text = testutil_read_file(svg);
  assert_non_null(text);
  assert_int_equal(testutil_count(text, "<path fill="), 3);
  free(text);
  text = testutil_read_file(st);
  assert_non_null(text);
  assert_int_equal(testutil_count(text, "\n"), 31);
  static const char head[] = "polygon,log_weight,area,perimeter,h,unimodal,rect_differ\n";
  assert_int_equal(strncmp(text, head, strlen(head)), 0);
  free(text);
}

/* The words of the help row of option opt, as one space-separated string:
** its text up to the first parenthesis, or (paren) the text inside it. */
static void tcc_help_words(const char *help, const char *opt, int paren, char *out,
                           size_t cap) {
  const char *s = strstr(help, opt);
  assert_non_null(s);
  s += strlen(opt);
  while (*s == ' ' || isupper((unsigned char)*s)) s++;
  if (paren) s = strchr(s, '(') + 1;
  size_t k = 0;
  for (; *s && *s != '(' && *s != ')' && k + 1 < cap; s++)
    out[k++] = *s == ',' || *s == '\n' ? ' ' : *s;
  out[k] = '\0';
}

/* Does the space-separated list hold word w exactly once? */
static int tcc_listed(const char *list, const char *w) {
  int count = 0;
  char buf[1024];
  snprintf(buf, sizeof buf, "%s", list);
  for (char *t = strtok(buf, " "); t; t = strtok(NULL, " ")) count += strcmp(t, w) == 0;
  return count == 1;
}

/* The help names every sampler of the registry and no other (--inner: the
** inner methods, those that can serve the dual). */
static void test_help_lists_registry(void **state) {
  (void)state;
  static char out[16384], err[1024];
  assert_int_equal(testutil_run("convex --help", out, sizeof out, err, sizeof err), 0);
  char sam[1024], inner[1024];
  tcc_help_words(out, "--sampler", 0, sam, sizeof sam);
  tcc_help_words(out, "--inner", 1, inner, sizeof inner);
  size_t words = 0, inner_words = 0;
  for (size_t i = 0; i < sampler_gons_count; i++) {
    if (!tcc_listed(sam, sampler_gons[i].name))
      fail_msg("--sampler help lacks %s", sampler_gons[i].name);
    words++;
    if (sampler_gon_inner(sampler_gons[i].name) != NULL) {
      if (!tcc_listed(inner, sampler_gons[i].name))
        fail_msg("--inner help lacks %s", sampler_gons[i].name);
      inner_words++;
    }
  }
  size_t listed = 0, listed_inner = 0;
  for (char *t = strtok(sam, " "); t; t = strtok(NULL, " ")) listed++;
  for (char *t = strtok(inner, " "); t; t = strtok(NULL, " ")) listed_inner++;
  assert_int_equal(listed, words);
  assert_int_equal(listed_inner, inner_words);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_errors),
    cmocka_unit_test(test_csv_threads),
    cmocka_unit_test(test_stats_svg),
    cmocka_unit_test(test_help_lists_registry),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
