/*
** test_cdt_cli.c: `fliplab lot` with constraints (--segments, --holes,
** --poly, --keep-hull) end to end.
**
** - without constraints nothing changes: no segments/holes lines, no bold
**   stroke in the SVG; with every hull edge as a segment the triangles are
**   those of the unconstrained run, byte for byte (DT and P_1);
** - a sampled polygon with holes read with --poly gives the same triangles
**   as its vertices, segments and holes given as three CSV files; every
**   segment survives (--check); the kept triangles number n - 2 + 2 H
**   (Euler's relation for a polygon with H holes whose vertices are all on
**   its boundaries); --keep-hull keeps 2 n - h - 2, the removed count is
**   the difference;
** - --compare DT on a constrained run compares with the CDT (all shared for
**   DT); --compare GOT on a sampled simple polygon: R_1 (whose GOT is the
**   CDT) gives equal triangles, P_1 a total >= GOT's, and the GOT total is
**   `got --polygon`'s on the same polygon;
** - multi-rule mode keeps the constraints for every rule (one segments line
**   and one check per rule, one bold stroke per panel);
** - every bad input named in issue 20 gets one line on stderr and a
**   non-zero exit: crossing segments (both named), an index out of range,
**   negative, not an integer, i == j, a wrong field count, a truncated
**   segment or .poly file, a .poly with wrong counts, a hole point on a
**   segment, clashing options, --compare GOT on what is no simple polygon.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "report.h"
#include "testutil.h"

#define TCDT_CAP (1 << 20)
static char tcdt_out[TCDT_CAP], tcdt_err[TCDT_CAP];

#define TCDT_RUN(...) \
  testutil_runf(tcdt_out, sizeof tcdt_out, tcdt_err, sizeof tcdt_err, __VA_ARGS__)

/* A path for a test file. */
static const char *tcdt_path(char buf[512], const char *name) {
  testutil_tmppath(buf, 512, name);
  return buf;
}

/* The number after `key` in the output (e.g. "triangles: "). */
static size_t tcdt_count(const char *out, const char *key) {
  const char *s = strstr(out, key);
  if (s == NULL) fail_msg("no '%s' in:\n%s", key, out);
  return (size_t)strtoull(s + strlen(key), NULL, 10);
}

/* A run that must fail: exit status 2, one line on stderr holding want. */
static void tcdt_refused(const char *want, const char *fmt, const char *a, const char *b,
                         const char *c) {
  int st = TCDT_RUN(fmt, a, b, c);
  if (st != 2 || !testutil_one_line(tcdt_err) || strstr(tcdt_err, want) == NULL)
    fail_msg("status %d, stderr '%s', wanted one line with '%s' (" "%s)", st, tcdt_err, want,
             fmt);
}

/* Write text to a test file; its path. */
static const char *tcdt_file(char buf[512], const char *name, const char *text) {
  tcdt_path(buf, name);
  testutil_write_file(buf, text);
  return buf;
}

/* Random points (uniform in the unit square) as a points file. */
static void tcdt_points(const char *path, uint64_t seed, size_t n) {
  testutil_rng g = {seed};
  FILE *f = fopen(path, "wb");
  assert_non_null(f);
  fputs("x,y\n", f);
  for (size_t i = 0; i < n; i++) {
    double x = testutil_uniform(&g), y = testutil_uniform(&g);
    fprintf(f, "%.17g,%.17g\n", x, y);
  }
  assert_int_equal(fclose(f), 0);
}

/* The triangles of an --out CSV (header skipped): 3 indices each. */
static size_t tcdt_triangles(const char *path, unsigned **tri) {
  char *text = testutil_read_file(path);
  assert_non_null(text);
  size_t cap = 1024, n = 0;
  *tri = malloc(3 * cap * sizeof **tri);
  for (char *s = strchr(text, '\n'); s && s[1]; s = strchr(s + 1, '\n')) {
    unsigned a, b, c;
    if (sscanf(s + 1, "%u,%u,%u", &a, &b, &c) != 3) continue;
    if (n == cap) *tri = realloc(*tri, 3 * (cap *= 2) * sizeof **tri);
    (*tri)[3 * n] = a;
    (*tri)[3 * n + 1] = b;
    (*tri)[3 * n + 2] = c;
    n++;
  }
  free(text);
  return n;
}

/* Write the boundary edges (edges of one triangle) of a triangle list as a
** segments file; their number. */
static size_t tcdt_hull_segments(const unsigned *tri, size_t nt, const char *path) {
  FILE *f = fopen(path, "wb");
  assert_non_null(f);
  fputs("i,j\n", f);
  size_t nb = 0;
  for (size_t t = 0; t < nt; t++)
    for (int e = 0; e < 3; e++) {
      unsigned a = tri[3 * t + e], b = tri[3 * t + (e + 1) % 3], twin = 0;
      for (size_t u = 0; u < nt && !twin; u++)
        for (int q = 0; q < 3; q++)
          twin |= tri[3 * u + q] == b && tri[3 * u + (q + 1) % 3] == a;
      if (!twin) {
        fprintf(f, "%u,%u\n", a, b);
        nb++;
      }
    }
  assert_int_equal(fclose(f), 0);
  return nb;
}

static void test_unconstrained_unchanged(void **state) {
  (void)state;
  char svg[512], pts[512], a[512], b[512], seg[512];
  tcdt_path(pts, "cdt_pts.csv");
  tcdt_points(pts, 7, 60);
  assert_int_equal(TCDT_RUN("lot --rule DT --points %s --svg %s --compare DT", pts,
                            tcdt_path(svg, "cdt_plain.svg")), 0);
  assert_null(strstr(tcdt_out, "segments:"));
  assert_null(strstr(tcdt_out, "holes:"));
  assert_null(strstr(tcdt_out, "constrained"));
  char *text = testutil_read_file(svg);
  assert_null(strstr(text, "#111111"));
  free(text);
  static const char *const rules[] = {"DT", "P_1"};
  for (int k = 0; k < 2; k++) {
    assert_int_equal(TCDT_RUN("lot --rule %s --points %s --out %s", rules[k], pts,
                              tcdt_path(a, "cdt_free.csv")), 0);
    unsigned *tri;
    size_t nt = tcdt_triangles(a, &tri);
    size_t nb = tcdt_hull_segments(tri, nt, tcdt_path(seg, "cdt_hull_seg.csv"));
    free(tri);
    assert_int_equal(TCDT_RUN("lot --rule %s --points %s --segments %s --out %s --check",
                              rules[k], pts, seg, tcdt_path(b, "cdt_hull.csv")), 0);
    size_t ns, nc, merged, split, gone;
    const char *line = strstr(tcdt_out, "\nsegments: ");
    assert_non_null(line);
    assert_int_equal(sscanf(line, "\nsegments: %zu (%zu constrained edges; %zu merged, %zu split, "
                            "%zu in removed", &ns, &nc, &merged, &split, &gone), 5);
    assert_true(ns == nb && nc == nb && merged == 0 && split == 0 && gone == 0);
    assert_non_null(strstr(tcdt_out, "check: ok: constrained"));
    char *x = testutil_read_file(a), *y = testutil_read_file(b);
    assert_string_equal(x, y);
    free(x);
    free(y);
  }
}

/* A sampled polygon with holes written by `fliplab sample`. */
static void tcdt_sample(const char *path, int holes, int points, int seed) {
  assert_int_equal(TCDT_RUN("sample --sampler holes --holes %d --hole-vertices 5 --points %d "
                            "--seed %d --out %s", holes, points, seed, path), 0);
}

/* The .poly file's graph as points, segments and holes files. */
static void tcdt_split_poly(const char *poly, const char *pts, const char *seg,
                            const char *hol, report_poly *pf) {
  char err[512];
  assert_int_equal(report_poly_read(poly, pf, err, sizeof err), 0);
  FILE *f = fopen(pts, "wb"), *g = fopen(seg, "wb"), *h = fopen(hol, "wb");
  assert_true(f && g && h);
  for (size_t i = 0; i < pf->g.npts; i++)
    fprintf(f, "%.17g,%.17g\n", pf->g.pts[i].x, pf->g.pts[i].y);
  for (size_t i = 0; i < pf->g.nseg; i++)
    fprintf(g, "%u,%u\n", pf->g.seg[2 * i], pf->g.seg[2 * i + 1]);
  for (size_t i = 0; i < pf->g.nholes; i++)
    fprintf(h, "%.17g,%.17g\n", pf->g.hole[i].x, pf->g.hole[i].y);
  assert_true(fclose(f) == 0 && fclose(g) == 0 && fclose(h) == 0);
}

static void test_poly_round_trip(void **state) {
  (void)state;
  char poly[512], pts[512], seg[512], hol[512], a[512], b[512];
  static const char *const rules[] = {"DT", "P_1", "-alpha_inf"};
  for (int s = 0; s < 3; s++) {
    tcdt_sample(tcdt_path(poly, "cdt_holes.poly"), 1 + s, 40, 11 + s);
    report_poly pf;
    tcdt_split_poly(poly, tcdt_path(pts, "cdt_rt_pts.csv"), tcdt_path(seg, "cdt_rt_seg.csv"),
                    tcdt_path(hol, "cdt_rt_hol.csv"), &pf);
    size_t n = pf.g.npts, nh = pf.g.nholes, ns = pf.g.nseg;
    report_poly_free(&pf);
    assert_int_equal(TCDT_RUN("lot --rule %s --poly %s --out %s --check", rules[s], poly,
                              tcdt_path(a, "cdt_rt_a.csv")), 0);
    assert_non_null(strstr(tcdt_out, "check: ok: constrained"));
    assert_int_equal(tcdt_count(tcdt_out, "segments: "), ns);
    assert_int_equal(tcdt_count(tcdt_out, "holes: "), nh);
    assert_int_equal(tcdt_count(tcdt_out, "\ntriangles: "), n - 2 + 2 * nh);
    char args[4096];
    snprintf(args, sizeof args, "lot --rule %s --points %s --segments %s --holes %s --out %s",
             rules[s], pts, seg, hol, tcdt_path(b, "cdt_rt_b.csv"));
    assert_int_equal(TCDT_RUN("%s", args), 0);
    char *x = testutil_read_file(a), *y = testutil_read_file(b);
    assert_string_equal(x, y);
    free(x);
    free(y);
    /* --keep-hull: the whole convex hull's triangulation, removed = the difference */
    assert_int_equal(TCDT_RUN("lot --rule %s --poly %s --keep-hull --check", rules[s], poly), 0);
    assert_non_null(strstr(tcdt_out, "check: ok: constrained"));
    assert_non_null(strstr(tcdt_out, "the hull kept"));
    size_t kept = tcdt_count(tcdt_out, "\ntriangles: "), h = tcdt_count(tcdt_out, "(hull ");
    size_t removed = tcdt_count(strstr(tcdt_out, "\nholes: "), "(");
    assert_int_equal(kept + removed, 2 * n - h - 2);
  }
}

static void test_compare_dt_and_list(void **state) {
  (void)state;
  char poly[512], svg[512];
  tcdt_sample(tcdt_path(poly, "cdt_cmp.poly"), 2, 30, 5);
  assert_int_equal(TCDT_RUN("lot --rule DT --poly %s --compare DT --svg %s", poly,
                            tcdt_path(svg, "cdt_cmp.svg")), 0);
  size_t nt = tcdt_count(tcdt_out, "\ntriangles: ");
  char want[200];
  snprintf(want, sizeof want, "%zu of %zu triangles shared with the exact constrained Delaunay",
           nt, nt);
  assert_non_null(strstr(tcdt_out, want));
  char *text = testutil_read_file(svg);
  assert_int_equal(testutil_count(text, "stroke=\"#111111\""), 2);   /* LOT and CDT panels */
  free(text);
  assert_int_equal(TCDT_RUN("lot --rule DT,P_1,sigma_1 --poly %s --check --svg %s", poly, svg),
                   0);
  assert_int_equal(testutil_count(tcdt_out, "\nsegments: "), 3);
  assert_int_equal(testutil_count(tcdt_out, "check: ok: constrained"), 3);
  text = testutil_read_file(svg);
  assert_int_equal(testutil_count(text, "stroke=\"#111111\""), 3);
  free(text);
}

/* What became of the segments: a point inside two of them splits both, a
** repeated one is merged; the CDT (unique here) is the same for every
** algorithm. */
static void test_counts_and_algorithms(void **state) {
  (void)state;
  char pts[512], seg[512], poly[512], a[512], b[512];
  tcdt_file(pts, "cdt_cnt.csv", "0,0\n2,0\n2,2\n0,2\n1,0\n");
  tcdt_file(seg, "cdt_cnt_seg.csv", "0,1\n1,2\n2,3\n3,0\n1,0\n");
  assert_int_equal(TCDT_RUN("lot --rule DT --points %s --segments %s --check", pts, seg), 0);
  assert_non_null(strstr(tcdt_out, "\nsegments: 5 (5 constrained edges; 1 merged, 2 split, 0 "
                                   "in removed regions)\n"));
  assert_non_null(strstr(tcdt_out, "check: ok: constrained"));
  assert_int_equal(tcdt_count(tcdt_out, "\ntriangles: "), 3);
  /* a square hole cut in two by its diagonal: the diagonal lies in removed regions */
  char hol[512];
  tcdt_file(pts, "cdt_rm.csv", "0,0\n4,0\n4,4\n0,4\n1,1\n3,1\n3,3\n1,3\n");
  tcdt_file(seg, "cdt_rm_seg.csv", "0,1\n1,2\n2,3\n3,0\n4,5\n5,6\n6,7\n7,4\n4,6\n");
  tcdt_file(hol, "cdt_rm_hol.csv", "2.5,1.5\n1.5,2.5\n");
  assert_int_equal(TCDT_RUN("lot --rule P_1 --points %s --segments %s --holes %s --check", pts,
                            seg, hol), 0);
  assert_non_null(strstr(tcdt_out, "\nsegments: 9 (8 constrained edges; 0 merged, 0 split, 1 "
                                   "in removed regions)\n"));
  assert_non_null(strstr(tcdt_out, "8 of 9 input segments are chains of edges"));
  assert_int_equal(tcdt_count(tcdt_out, "\ntriangles: "), 8 - 2 + 2);
  tcdt_sample(tcdt_path(poly, "cdt_alg.poly"), 3, 50, 8);
  assert_int_equal(TCDT_RUN("lot --rule DT --poly %s --out %s", poly, tcdt_path(a, "cdt_alg_a.csv")),
                   0);
  char *x = testutil_read_file(a);
  static const char *const alg[] = {"flip", "sweep"};
  for (int k = 0; k < 2; k++) {
    assert_int_equal(TCDT_RUN("lot --rule DT --poly %s --algorithm %s --check --out %s", poly,
                              alg[k], tcdt_path(b, "cdt_alg_b.csv")), 0);
    assert_non_null(strstr(tcdt_out, "check: ok: constrained"));
    char *y = testutil_read_file(b);
    assert_string_equal(x, y);
    free(y);
  }
  free(x);
}

/* The number after "GOT total " / "LOT total " in the compare line. */
static double tcdt_total(const char *out, const char *key) {
  const char *s = strstr(out, key);
  assert_non_null(s);
  return strtod(s + strlen(key), NULL);
}

static void test_compare_got(void **state) {
  (void)state;
  char poly[512], pts[512], seg[512], hol[512];
  for (int s = 0; s < 3; s++) {
    tcdt_sample(tcdt_path(poly, "cdt_got.poly"), 0, 14 + 4 * s, 30 + s);
    assert_int_equal(TCDT_RUN("lot --rule R_1 --poly %s --compare GOT", poly), 0);
    assert_non_null(strstr(tcdt_out, "LOT = GOT"));
    assert_non_null(strstr(tcdt_out, "equal triangles, as it must be"));
    assert_int_equal(TCDT_RUN("lot --rule P_1 --poly %s --compare GOT", poly), 0);
    assert_true(strstr(tcdt_out, "LOT = GOT") || strstr(tcdt_out, "LOT > GOT"));
    double lot = tcdt_total(tcdt_out, "LOT total "), got = tcdt_total(tcdt_out, "GOT total ");
    assert_true(lot >= got * (1 - 1e-12));
    /* the same GOT from `fliplab got` on the polygon (its segments are the ring 0..n-1) */
    report_poly pf;
    tcdt_split_poly(poly, tcdt_path(pts, "cdt_got_pts.csv"), tcdt_path(seg, "cdt_got_seg.csv"),
                    tcdt_path(hol, "cdt_got_hol.csv"), &pf);
    report_poly_free(&pf);
    assert_int_equal(TCDT_RUN("got --rule P_1 --polygon %s", pts), 0);
    TESTUTIL_NEAR(tcdt_total(tcdt_out, "total badness: "), got, 1e-12, 0);
  }
  tcdt_sample(poly, 1, 20, 3);
  tcdt_refused("no holes (1 given)", "lot --rule P_1 --poly %s --compare GOT%s%s", poly, "", "");
  tcdt_sample(poly, 0, 20, 3);
  tcdt_refused("keep-hull", "lot --rule P_1 --poly %s --compare GOT%s%s", poly, " --keep-hull",
               "");
}

static void test_bad_segments(void **state) {
  (void)state;
  char pts[512], s[512];
  tcdt_file(pts, "cdt_sq.csv", "x,y\n0,0\n1,0\n1,1\n0,1\n0.5,0.25\n");
  const char *fmt = "lot --rule DT --points %s --segments %s%s";
  tcdt_refused(" cross", fmt, pts, tcdt_file(s, "cdt_s1.csv", "0,2\n1,3\n"), "");
  assert_non_null(strstr(tcdt_err, "0 (0-2)"));   /* both named */
  assert_non_null(strstr(tcdt_err, "1 (1-3)"));
  tcdt_refused("line 2: j 5 is out of range (5 points)", fmt, pts,
               tcdt_file(s, "cdt_s2.csv", "0,1\n1,5\n"), "");
  tcdt_refused("line 1: i '-1' is negative", fmt, pts, tcdt_file(s, "cdt_s3.csv", "-1,2\n"), "");
  tcdt_refused("line 1: j '2.5' is not a non-negative integer", fmt, pts,
               tcdt_file(s, "cdt_s4.csv", "1,2.5\n"), "");
  tcdt_refused("line 2: both ends are point 3", fmt, pts,
               tcdt_file(s, "cdt_s5.csv", "i,j\n3,3\n"), "");
  tcdt_refused("line 1: expected 2 fields i,j, got 3", fmt, pts,
               tcdt_file(s, "cdt_s6.csv", "0,1,2\n"), "");
  tcdt_refused("line 2: j '' is not", fmt, pts, tcdt_file(s, "cdt_s7.csv", "0,1\n1,"), "");
  tcdt_refused("no segments", fmt, pts, tcdt_file(s, "cdt_s8.csv", "i,j\n"), "");
  tcdt_refused("cannot read", fmt, pts, "/nonexistent/seg.csv", "");
  char h[512];
  tcdt_file(s, "cdt_s9.csv", "0,1\n1,2\n2,3\n3,0\n");
  tcdt_refused("lies on segment", "lot --rule DT --points %s --segments %s --holes %s", pts, s,
               tcdt_file(h, "cdt_h1.csv", "0.5,0\n"));
  tcdt_refused("hole 0 (5, 5) is outside", "lot --rule DT --points %s --segments %s --holes %s",
               pts, s, tcdt_file(h, "cdt_h2.csv", "5,5\n"));
  tcdt_refused("--holes", "lot --rule DT --points %s --segments %s --holes %s", pts, s,
               tcdt_file(h, "cdt_h3.csv", "0.5\n"));
}

static void test_bad_poly_and_options(void **state) {
  (void)state;
  char p[512], pts[512];
  tcdt_file(pts, "cdt_opt.csv", "0,0\n1,0\n0,1\n");
  const char *fmt = "lot --rule DT --poly %s%s%s";
  tcdt_refused("line 4: the file ends before the last vertex", fmt,
               tcdt_file(p, "cdt_p1.poly", "4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n"), "", "");
  tcdt_refused("the file ends before the segment count line", fmt,
               tcdt_file(p, "cdt_p2.poly", "3 2 0 0\n0 0 0\n1 1 0\n2 1 1\n"), "", "");
  tcdt_refused("more lines than the counts announce", fmt,
               tcdt_file(p, "cdt_p3.poly", "3\n0 0 0\n1 1 0\n2 1 1\n1\n0 0 1\n0\n0\n5\n"), "",
               "");
  tcdt_refused("segment endpoint 3 is not a vertex", fmt,
               tcdt_file(p, "cdt_p4.poly", "3\n0 0 0\n1 1 0\n2 1 1\n1\n0 0 3\n0\n"), "", "");
  tcdt_file(p, "cdt_p5.poly", "3\n0 0 0\n1 1 0\n2 1 1\n3\n0 0 1\n1 1 2\n2 2 0\n0\n");
  tcdt_refused("--poly gives the points, segments and holes: not with --points", fmt, p,
               " --points ", pts);
  tcdt_refused("not with --random", fmt, p, " --random 10", "");
  tcdt_refused("not with --segments", fmt, p, " --segments ", pts);
  tcdt_refused("not with --holes", fmt, p, " --holes ", pts);
  tcdt_refused("--segments needs --points", "lot --rule DT --random 10 --segments %s%s%s", pts,
               "", "");
  tcdt_refused("--keep-hull applies to constrained runs", "lot --rule DT --points %s%s%s", pts,
               " --keep-hull", "");
  /* regions and attributes: a note, then the run */
  tcdt_file(p, "cdt_p6.poly", "3 2 1\n0 0 0 7\n1 1 0 7\n2 1 1 7\n3\n0 0 1\n1 1 2\n2 2 0\n0\n"
            "1\n0 0.5 0.2 1 0.1\n");
  assert_int_equal(TCDT_RUN("lot --rule DT --poly %s", p), 0);
  assert_true(testutil_one_line(tcdt_err));
  assert_non_null(strstr(tcdt_err, "note: "));
  assert_non_null(strstr(tcdt_err, "1 vertex attribute(s), 1 regional"));
  assert_null(strstr(tcdt_err, "markers"));
  tcdt_file(p, "cdt_p7.poly", "3 2 0 1\n0 0 0 1\n1 1 0 1\n2 1 1 1\n3\n0 0 1\n1 1 2\n2 2 0\n0\n");
  assert_int_equal(TCDT_RUN("lot --rule DT --poly %s", p), 0);
  assert_true(testutil_one_line(tcdt_err));
  assert_non_null(strstr(tcdt_err, "boundary markers"));
  tcdt_file(p, "cdt_p8.poly", "3\n0 0 0\n1 1 0\n2 1 1\n3 1\n0 0 1 5\n1 1 2 5\n2 2 0 5\n0\n");
  assert_int_equal(TCDT_RUN("lot --rule DT --poly %s", p), 0);
  assert_non_null(strstr(tcdt_err, "boundary markers"));
  tcdt_file(p, "cdt_p9.poly", "3\n0 0 0\n1 1 0\n2 1 1\n3\n0 0 1\n1 1 2\n2 2 0\n0\n");
  assert_int_equal(TCDT_RUN("lot --rule DT --poly %s", p), 0);
  assert_string_equal(tcdt_err, "");
  assert_int_equal(tcdt_count(tcdt_out, "\ntriangles: "), 1);
  /* --compare GOT: segments that are no single ring */
  tcdt_file(pts, "cdt_two.csv", "0,0\n1,0\n0,1\n-5,-5\n-6,-5\n-5,-6\n");
  char s[512];
  tcdt_refused("more than one ring", "lot --rule P_1 --points %s --segments %s%s", pts,
               tcdt_file(s, "cdt_two_seg.csv", "0,1\n1,2\n2,0\n3,4\n4,5\n5,3\n"),
               " --compare GOT --keep-hull");
  tcdt_refused("point 0 is on more than 2 segments", "lot --rule P_1 --points %s --segments %s%s",
               pts, tcdt_file(s, "cdt_deg3_seg.csv", "0,1\n1,2\n2,0\n0,3\n3,4\n4,5\n"),
               " --compare GOT");
  tcdt_refused("(5 segments, 6 points)", "lot --rule P_1 --points %s --segments %s%s", pts,
               tcdt_file(s, "cdt_path_seg.csv", "0,1\n1,2\n2,0\n3,4\n4,5\n"), " --compare GOT");
}

int main(void) {
  mkdir(FLIPLAB_BUILD_DIR "/testtmp", 0777);   /* testutil_tmppath's folder */
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_unconstrained_unchanged), cmocka_unit_test(test_poly_round_trip),
    cmocka_unit_test(test_compare_dt_and_list),     cmocka_unit_test(test_counts_and_algorithms),
    cmocka_unit_test(test_compare_got),
    cmocka_unit_test(test_bad_segments),            cmocka_unit_test(test_bad_poly_and_options),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
