/*
** test_scale.c: the coordinate contract of geom.h (every coordinate 0 or of
** magnitude in [1e-30, 1e30]) and what it promises: thin and tiny-scale
** quadrilaterals and pentagons anywhere inside it, in several orientations,
** get the exact Delaunay decision from every DT-equivalent rule; the
** product and root-sum-square joints decide where a double product would
** underflow or overflow; coordinates outside the contract are refused by
** every reader, never read as 0 or infinity.
**
** Shapes are built exactly: vertex coordinates are small integers times
** L = 2^p (lengths) and h = 2^q (heights), mapped by exact similarities
** (the eight symmetries of the square, and the integer rotations-with-scale
** [[a, -b], [b, a]] for (a, b) = (1, 1), (2, 1), (4, 3), exact while the
** shape is no thinner than 2^-40).  Every rule's decision and DT are
** invariant under similarities, and DT is exact, so each case has a
** certain answer.
*/
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "flipgraph.h"
#include "geom.h"
#include "joint.h"
#include "measure.h"
#include "rule.h"
#include "testutil.h"

/* The rules that always agree with Delaunay (thesis theorems 3, 16-18 and
** table 3.4; see test_delaunay_equiv.c). */
static const char *const tscale_dt_rules[] = {
  "R_-inf", "R_-1", "R_0", "R_1", "R_2", "R_inf", "-alpha_inf", "-r_1", "abc_1",
  "-r/R_1", "-r2/A_0"};
#define TSCALE_NRULES (int)(sizeof tscale_dt_rules / sizeof tscale_dt_rules[0])

/* Base shapes in units (X of L, Y of h), anticlockwise. */
typedef struct tscale_shape { const char *name; int n; int xy[5][2]; } tscale_shape;
static const tscale_shape tscale_shapes[] = {
  {"flat kite", 4, {{0, 0}, {3, -1}, {4, 0}, {1, 2}}},
  {"flat trapezoid", 4, {{0, 0}, {5, 0}, {3, 1}, {1, 1}}},
  {"flat lens", 4, {{0, 0}, {2, -1}, {7, 0}, {4, 3}}},
  {"flat pentagon", 5, {{0, 0}, {2, -1}, {6, -1}, {7, 0}, {3, 2}}},
  {"flat house", 5, {{0, 0}, {6, 0}, {6, 1}, {4, 3}, {1, 2}}},
};
#define TSCALE_NSHAPES (int)(sizeof tscale_shapes / sizeof tscale_shapes[0])

/* Similarity number k: 0..7 the symmetries of the square, 8.. rotations. */
#define TSCALE_NSIM 11
static geom_point tscale_map(int k, double x, double y) {
  static const int rot[3][2] = {{1, 1}, {2, 1}, {4, 3}};
  if (k >= 8) {
    double a = rot[k - 8][0], b = rot[k - 8][1];
    return (geom_point){a * x - b * y, b * x + a * y};
  }
  double u = k & 4 ? y : x, v = k & 4 ? x : y;
  return (geom_point){k & 1 ? -u : u, k & 2 ? -v : v};
}

/* The shape at lengths 2^p and heights 2^q under similarity k, translated
** by (tx, ty) (0, or a power of two that keeps every coordinate exact);
** anticlockwise after geom_polygon_check.  0 if it is not a valid polygon
** of the contract (which the grid below never produces). */
static int tscale_make(const tscale_shape *s, int p, int q, int k, double tx, geom_point *out) {
  double L = ldexp(1, p), h = ldexp(1, q);
  for (int i = 0; i < s->n; i++) {
    geom_point m = tscale_map(k, s->xy[i][0] * L, s->xy[i][1] * h);
    out[i] = (geom_point){m.x + tx, m.y};
    if (out[i].x - tx != m.x) return 0;   /* not exact */
  }
  size_t bad;
  int rev;
  return geom_polygon_check(out, (size_t)s->n, &bad, &rev) == GEOM_OK;
}

static rule tscale_rules[TSCALE_NRULES];

static void tscale_parse_rules(void) {
  for (int i = 0; i < TSCALE_NRULES; i++) {
    char err[4096];
    if (rule_parse(tscale_dt_rules[i], &tscale_rules[i], err, sizeof err) != 0) fail_msg("%s", err);
  }
}

/* A tie of abc_1 on a flat quadrilateral is the spec's tolerance at work
** (the four abc values of four nearly collinear points satisfy a Ptolemy
** identity up to O((h/L)^2)), not an underflow: both joint values are
** normal doubles, within tie_eps of each other, and with tie_eps = 0 the
** rule gives DT's answer whenever (h/L)^2 is far above rounding. */
static int tscale_abc_tie_ok(const rule *r, const geom_point q[4], rule_choice dt, int p, int q2) {
  double ac, bd;
  rule_choice c = rule_eval(r, q, &ac, &bd);
  if (c != RULE_EITHER) return 0;
  if (!(fabs(ac) >= DBL_MIN && fabs(bd) >= DBL_MIN && isfinite(ac) && isfinite(bd))) return 0;
  if (!(fabs(ac - bd) <= RULE_DEFAULT_TIE_EPS * fmax(fabs(ac), fabs(bd)))) return 0;
  rule exact = *r;
  rule_set_tie_eps(&exact, 0);
  if (p - q2 <= 20) return rule_eval(&exact, q, NULL, NULL) == dt;
  return 1;
}

/* Exponent grid: lengths 2^p from the top of the contract (coordinates up
** to 7 L < 1e30) to the bottom (2^-99 > 1e-30), heights from L down to the
** bottom of the contract. */
static const int tscale_p[] = {96, 60, 20, 0, -20, -60, -97};
static const int tscale_drop[] = {0, 3, 10, 20, 40, 52, 80, 120, 196};

static void test_thin_quads_and_pentagons(void **state) {
  (void)state;
  tscale_parse_rules();
  rule dt = rule_delaunay();
  flipgraph_plan *pl = flipgraph_plan_new(tscale_rules, TSCALE_NRULES, RULE_DEFAULT_TIE_EPS);
  assert_non_null(pl);
  int cases = 0, bad = 0, abc_ties = 0;
  for (int si = 0; si < TSCALE_NSHAPES; si++)
    for (size_t pi = 0; pi < sizeof tscale_p / sizeof tscale_p[0]; pi++)
      for (size_t di = 0; di < sizeof tscale_drop / sizeof tscale_drop[0]; di++)
        for (int k = 0; k < TSCALE_NSIM; k++)
          for (int t = 0; t < 2; t++) {
            const tscale_shape *s = &tscale_shapes[si];
            int p = tscale_p[pi], q = p - tscale_drop[di];
            if (q < -99 || (k >= 8 && tscale_drop[di] > 40)) continue;
            if (k >= 8 && p > 94) continue;               /* rotations scale by up to 5 */
            double tx = t ? ldexp(1, p + 4) : 0;          /* a translated copy */
            geom_point v[5];
            if (!tscale_make(s, p, q, k, tx, v)) continue;
            cases++;
            if (s->n == 4) {
              rule_choice d = rule_eval(&dt, v, NULL, NULL);
              for (int i = 0; i < TSCALE_NRULES; i++) {
                for (int rot = 0; rot < 4; rot++) {   /* any vertex called A */
                  geom_point r4[4] = {v[rot], v[(rot + 1) % 4], v[(rot + 2) % 4], v[(rot + 3) % 4]};
                  rule_choice want = rot & 1 ? (d == RULE_AC ? RULE_BD : RULE_AC) : d;
                  rule_choice c = rule_eval(&tscale_rules[i], r4, NULL, NULL);
                  if (c == want) continue;
                  if (strcmp(tscale_dt_rules[i], "abc_1") == 0
                      && tscale_abc_tie_ok(&tscale_rules[i], r4, want, p, q)) {
                    abc_ties++;
                    continue;
                  }
                  if (bad++ < 5)
                    print_error("%s, L = 2^%d, h = 2^%d, map %d, shift %d, A = vertex %d: %s "
                                "says %s, DT %s\n", s->name, p, q, k, t, rot, tscale_dt_rules[i],
                                rule_choice_str(c), rule_choice_str(want));
                }
              }
            } else {
              flipgraph_pentagon pent;
              flipgraph_prepare(&pent, v);
              flipgraph fast[TSCALE_NRULES];
              flipgraph_plan_run(pl, &pent, fast);
              if (pent.delaunay_sink < 0) bad++;
              for (int i = 0; i < TSCALE_NRULES; i++) {
                flipgraph one;
                flipgraph_classify(&pent, &tscale_rules[i], RULE_DEFAULT_TIE_EPS, &one);
                int ok = one.delaunay && fast[i].delaunay;
                if (!ok && strcmp(tscale_dt_rules[i], "abc_1") == 0 && one.type == FLIPGRAPH_V
                    && fast[i].type == FLIPGRAPH_V) {
                  /* every tied decision must be a tolerance tie of a quadrilateral */
                  ok = 1;
                  for (int j = 0; j < 5 && ok; j++) {
                    if (one.dec[j] != RULE_EITHER) continue;
                    geom_point q4[4];
                    for (int m = 0; m < 4; m++) q4[m] = v[(j + 1 + m) % 5];
                    rule_choice dq = rule_eval(&dt, q4, NULL, NULL);
                    ok = tscale_abc_tie_ok(&tscale_rules[i], q4, dq, p, q);
                  }
                  abc_ties += ok;
                }
                if (!ok && bad++ < 5)
                  print_error("%s, L = 2^%d, h = 2^%d, map %d, shift %d: %s gives type %s "
                              "(fast path %s), not Delaunay\n", s->name, p, q, k, t,
                              tscale_dt_rules[i], flipgraph_type_name(one.type),
                              flipgraph_type_name(fast[i].type));
              }
            }
          }
  flipgraph_plan_free(pl);
  print_message("%d thin shapes, %d abc_1 tolerance ties, %d disagreements\n", cases, abc_ties, bad);
  assert_true(cases > 1500);
  assert_true(abc_ties > 0);   /* the tie case is exercised */
  assert_int_equal(bad, 0);
}

/* Thin quadrilaterals in random directions: the coordinates are rounded,
** so the plain cross product of a thin triangle cancels and loses most of
** its digits (geom_twice_area recomputes it exactly).  Lengths 1, 1e20 and
** 1e-20, thinness 2^-20 .. 2^-48; every DT-equivalent rule must give DT's
** exact answer, or (abc_1 only) a tolerance tie of normal values. */
static void test_thin_random_directions(void **state) {
  (void)state;
  tscale_parse_rules();
  rule dt = rule_delaunay();
  testutil_rng g = {1994};
  int cases = 0, bad = 0;
  static const double scales[] = {1, 1e20, 1e-20};
  for (int n = 0; n < 20000; n++) {
    double th = 2 * M_PI * testutil_uniform(&g), L = scales[n % 3];
    double thin = ldexp(1, -20 - (int)(testutil_next(&g) % 29));
    double dx = cos(th), dy = sin(th);
    /* A flat lens or trapezoid: positions along the direction, offsets across. */
    double t[4] = {0, 0.2 + 0.6 * testutil_uniform(&g), 1, 0.2 + 0.6 * testutil_uniform(&g)};
    double o[4] = {0, -(0.5 + testutil_uniform(&g)), 0, 0.5 + testutil_uniform(&g)};
    if (n % 2) { t[1] = 1.3; t[2] = 0.9; o[1] = 0; o[2] = o[3]; }   /* a trapezoid */
    geom_point q[4];
    for (int k = 0; k < 4; k++)
      q[k] = (geom_point){L * (3 + t[k] * dx - o[k] * thin * dy), L * (3 + t[k] * dy + o[k] * thin * dx)};
    size_t badv;
    int rev;
    if (geom_polygon_check(q, 4, &badv, &rev) != GEOM_OK) continue;
    cases++;
    rule_choice d = rule_eval(&dt, q, NULL, NULL);
    for (int i = 0; i < TSCALE_NRULES; i++) {
      rule_choice c = rule_eval(&tscale_rules[i], q, NULL, NULL);
      if (c == d) continue;
      if (strcmp(tscale_dt_rules[i], "abc_1") == 0 && tscale_abc_tie_ok(&tscale_rules[i], q, d, 0, (int)log2(thin)))
        continue;
      if (bad++ < 5)
        print_error("direction %.17g, L %g, thinness %g: %s says %s, DT %s\n", th, L, thin,
                    tscale_dt_rules[i], rule_choice_str(c), rule_choice_str(d));
    }
  }
  print_message("%d thin quadrilaterals in random directions, %d disagreements\n", cases, bad);
  assert_true(cases > 15000);
  assert_int_equal(bad, 0);
}

/* Found by fuzz/fuzz_quad_dt: a flat triangle whose two longest sides round
** to the same double while their opposite angles are pi - 5e-20 and 5e-20.
** geom_tri_make took the tiny one for the largest and computed it as pi
** minus the others: 0, so -alpha_inf answered BD where DT says AC. */
static void test_flat_equal_sides(void **state) {
  (void)state;
  geom_point q[4] = {{0, 0}, {3.3103697155232625e-28, 0},
                     {6.1065542931650197e-09, 3.3103697155250992e-28},
                     {-0.00025941827334463596, 3.921736917071456e-28}};
  geom_tri t;
  geom_tri_make(&t, q[0], q[1], q[2]);
  assert_true(t.alpha > 0 && t.beta > 0);
  TESTUTIL_NEAR(t.alpha + t.beta + t.gamma, M_PI, 1e-15, 0);
  /* the angle at A: atan2(height, base), height 3.31e-28 over 6.1e-9 */
  TESTUTIL_NEAR(fmax(t.alpha, t.beta), atan2(3.3103697155250992e-28, 6.1065542931650197e-09), 1e-12, 0);
  tscale_parse_rules();
  rule dt = rule_delaunay();
  rule_choice d = rule_eval(&dt, q, NULL, NULL);
  for (int i = 0; i < TSCALE_NRULES; i++) {
    rule_choice c = rule_eval(&tscale_rules[i], q, NULL, NULL);
    if (c != RULE_EITHER && c != d) fail_msg("%s says %s, DT %s", tscale_dt_rules[i],
                                             rule_choice_str(c), rule_choice_str(d));
  }
}

/* The product and root-sum-square joints decide beyond the double range,
** as the exact values would, and agree bit for bit with the plain
** evaluation inside it. */
static void test_joint_split(void **state) {
  (void)state;
  double eps = RULE_DEFAULT_TIE_EPS;
  /* 1e-170 * 1e-170 underflows to 0 but 1e-170 * 3e-170 < 2e-170 * 2e-170. */
  assert_int_equal(joint_compare(JOINT_PRODUCT, 1, 1e-170, 3e-170, 2e-170, 2e-170, eps), -1);
  assert_int_equal(joint_compare(JOINT_PRODUCT, -1, -1e-170, -3e-170, -2e-170, -2e-170, eps), 1);
  assert_int_equal(joint_compare(JOINT_PRODUCT, 1, 1e200, 3e200, 2e200, 2e200, eps), -1);
  assert_int_equal(joint_compare(JOINT_PRODUCT, 1, 1e200, 4e200, 2e200, 2e200, eps), 0);
  assert_int_equal(joint_compare(JOINT_PRODUCT, 1, 0x1p-1000, 0x1p-1000, 0, 1, eps), 1);
  assert_int_equal(joint_compare(JOINT_PRODUCT, 1, 0, 1, 0x1p-1000, 0x1p-1000, eps), -1);
  assert_int_equal(joint_compare(JOINT_RSS, 1, 1e300, 1e300, 1e300, 2e300, eps), -1);
  assert_int_equal(joint_compare(JOINT_RSS, 1, 1e-300, 1e-300, 1e-300, 2e-300, eps), -1);
  assert_int_equal(joint_compare(JOINT_RSS, 1, 3e-300, 4e-300, 5e-300, 0, eps), 0);
  assert_int_equal(joint_compare(JOINT_PRODUCT, 1, NAN, 1, 1, 1, eps), 0);
  assert_int_equal(joint_compare(JOINT_PRODUCT, 1, INFINITY, 1, 1e300, 1e300, eps), 1);
  int e;
  double m = joint_apply_split(JOINT_PRODUCT, -1, -1e-200, -1e-200, &e);
  TESTUTIL_NEAR(log2(-m) + e, 2 * log2(1e-200), 1e-14, 0);
  /* Inside the range: the same decision as the plain values, always. */
  testutil_rng g = {77};
  int differ = 0;
  for (int n = 0; n < 200000; n++) {
    double v[4];
    for (int i = 0; i < 4; i++) v[i] = ldexp(0.5 + testutil_uniform(&g), (int)(testutil_next(&g) % 1000) - 500);
    if (n % 3 == 0) v[2] = v[0], v[3] = v[1] * (1 + 1e-13 * testutil_uniform(&g));
    for (int j = JOINT_PRODUCT; j <= JOINT_RSS; j += JOINT_RSS - JOINT_PRODUCT)
      for (int s = -1; s <= 1; s += 2) {
        double a = joint_apply((joint_id)j, s, s * v[0], s * v[1]);
        double b = joint_apply((joint_id)j, s, s * v[2], s * v[3]);
        if (!(fabs(a) >= DBL_MIN && fabs(b) >= DBL_MIN && isfinite(a) && isfinite(b))) continue;
        differ += joint_compare((joint_id)j, s, s * v[0], s * v[1], s * v[2], s * v[3], eps)
                  != joint_compare_values(a, b, eps);
      }
  }
  assert_int_equal(differ, 0);
}

/* Measures whose values lie far outside the double range of a product
** (area times 2^-1000, area times 2^700): the product and root-sum-square
** rules must decide exactly as on the area itself (scaling every value by
** one power of two changes no decision), in the vectorised engine, in
** flipgraph_classify and in rule_eval alike. */
static double tscale_area_lo(const geom_tri *t, void *ctx) { (void)ctx; return ldexp(t->area, -1000); }
static double tscale_area_hi(const geom_tri *t, void *ctx) { (void)ctx; return ldexp(t->area, 700); }
static double tscale_area(const geom_tri *t, void *ctx) { (void)ctx; return t->area; }

static void test_scaled_measures(void **state) {
  (void)state;
  measure ms[3] = {
    {"tscaleA", "A", "area", MEASURE_NONNEG, tscale_area, NULL},
    {"tscaleLo", "A 2^-1000", "area times 2^-1000", MEASURE_NONNEG, tscale_area_lo, NULL},
    {"tscaleHi", "A 2^700", "area times 2^700", MEASURE_NONNEG, tscale_area_hi, NULL}};
  int id[3];
  for (int i = 0; i < 3; i++) assert_true((id[i] = measure_register(&ms[i])) >= 0);
  rule rules[6];
  char err[256];
  for (int i = 0; i < 3; i++) {
    assert_int_equal(rule_triangle(id[i], JOINT_PRODUCT, &rules[i], err, sizeof err), 0);
    assert_int_equal(rule_triangle(id[i], JOINT_RSS, &rules[3 + i], err, sizeof err), 0);
  }
  flipgraph_plan *pl = flipgraph_plan_new(rules, 6, RULE_DEFAULT_TIE_EPS);
  assert_non_null(pl);
  testutil_rng g = {4242};
  int differ = 0, types = 0;
  for (int n = 0; n < 3000; n++) {
    geom_point v[5];
    for (int k = 0; k < 5; k++) {   /* a random convex pentagon: sorted angles on an ellipse */
      double a = 2 * M_PI * (k + testutil_uniform(&g) * 0.9) / 5;
      v[k] = (geom_point){cos(a) * (1 + testutil_uniform(&g) * 0.1), 0.3 * sin(a)};
    }
    size_t bad;
    int rev;
    if (geom_polygon_check(v, 5, &bad, &rev) != GEOM_OK) continue;
    flipgraph_pentagon p;
    flipgraph_prepare(&p, v);
    flipgraph fast[6], one;
    flipgraph_plan_run(pl, &p, fast);
    for (int i = 0; i < 6; i++) {
      flipgraph_classify(&p, &rules[i], RULE_DEFAULT_TIE_EPS, &one);
      int ref = i < 3 ? 0 : 3;
      differ += one.type != fast[ref].type || fast[i].type != fast[ref].type;
      for (int j = 0; j < 5; j++) differ += one.dec[j] != fast[ref].dec[j] || fast[i].dec[j] != fast[ref].dec[j];
    }
    types += fast[0].type == FLIPGRAPH_I;
  }
  flipgraph_plan_free(pl);
  measure_unregister_user();
  assert_true(types > 100);
  assert_int_equal(differ, 0);
}

/* The contract's reader, used by every coordinate reader. */
static void test_coord_parse(void **state) {
  (void)state;
  static const struct { const char *s; geom_coorderr e; } cases[] = {
    {"0", GEOM_COORD_OK}, {"-0", GEOM_COORD_OK}, {"1e-30", GEOM_COORD_OK},
    {"-1e30", GEOM_COORD_OK}, {" 2.5", GEOM_COORD_NOT_NUMBER}, {"0x1p-99", GEOM_COORD_OK},
    {"1e-400", GEOM_COORD_OUT_OF_RANGE}, {"1e400", GEOM_COORD_OUT_OF_RANGE},
    {"-1e400", GEOM_COORD_OUT_OF_RANGE}, {"4.9e-324", GEOM_COORD_OUT_OF_RANGE},
    {"1e-170", GEOM_COORD_OUT_OF_RANGE}, {"9.99e-31", GEOM_COORD_OUT_OF_RANGE}, {"1e-31", GEOM_COORD_OUT_OF_RANGE}, {"2e30", GEOM_COORD_OUT_OF_RANGE},
    {"1.0000001e30", GEOM_COORD_OUT_OF_RANGE}, {"0x1p-100", GEOM_COORD_OUT_OF_RANGE},
    {"nan", GEOM_COORD_NOT_FINITE}, {"-inf", GEOM_COORD_NOT_FINITE},
    {"", GEOM_COORD_NOT_NUMBER}, {"1,5", GEOM_COORD_NOT_NUMBER}, {"2 ", GEOM_COORD_NOT_NUMBER},
    {"x", GEOM_COORD_NOT_NUMBER}, {"1e", GEOM_COORD_NOT_NUMBER}};
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    double x = 12345;
    geom_coorderr e = geom_coord_parse(cases[i].s, &x);
    if (e != cases[i].e) fail_msg("'%s': got %d, want %d", cases[i].s, (int)e, (int)cases[i].e);
    if (e != GEOM_COORD_OK) assert_true(x == 12345);
    assert_true(testutil_one_line(geom_coorderr_str(e)) || strchr(geom_coorderr_str(e), '\n') == NULL);
  }
}

/* Every command that reads coordinates refuses one outside the contract
** with one line naming it, and exit status 2 or 1; none reads it as 0. */
static void test_readers_refuse(void **state) {
  (void)state;
  char out[4096], err[4096], path[512];
  int rc = testutil_runf(out, sizeof out, err, sizeof err, "flip -A_0 0 0 1 -1e-170 2 0 1 3e-170");
  assert_int_not_equal(rc, 0);
  assert_true(testutil_one_line(err));
  assert_non_null(strstr(err, "out of range"));
  /* inside the contract the same shape decides as the exact values do */
  rc = testutil_runf(out, sizeof out, err, sizeof err, "flip -A_0 0 0 1 -1e-30 2 0 1 3e-30");
  assert_int_equal(rc, 0);
  assert_non_null(strstr(out, "decision  BD"));

  testutil_tmppath(path, sizeof path, "scale_pent.csv");
  testutil_write_file(path, "0,0,1,0,1.5,1,0.5,1.7,-0.5,1e-400\n");
  rc = testutil_runf(out, sizeof out, err, sizeof err, "classify --input '%s'", path);
  assert_int_not_equal(rc, 0);
  assert_true(testutil_one_line(err));
  assert_non_null(strstr(err, "y5"));
  assert_non_null(strstr(err, "out of range"));

  testutil_tmppath(path, sizeof path, "scale_poly.csv");
  testutil_write_file(path, "x,y\n0,0\n1,0\n1,1e-400\n0,1\n");
  rc = testutil_runf(out, sizeof out, err, sizeof err, "got --rule R_1 --polygon '%s'", path);
  assert_int_not_equal(rc, 0);
  assert_true(testutil_one_line(err));
  assert_non_null(strstr(err, "line 4"));
  assert_non_null(strstr(err, "out of range"));
}

/* GOT at both ends of the contract: finite totals, no NaN triangle. */
static void test_got_extremes(void **state) {
  (void)state;
  char out[1 << 16], err[4096], path[512];
  testutil_tmppath(path, sizeof path, "scale_got.csv");
  /* A flat convex 8-gon with lengths near 1e29 and heights near 1e-30. */
  testutil_write_file(path, "x,y\n0,0\n2e29,-1e-30\n5e29,-2e-30\n7e29,-1e-30\n8e29,0\n"
                            "6e29,3e-30\n4e29,4e-30\n1e29,2e-30\n");
  static const char *const rules[] = {"R_2", "R_0", "-A_0", "-r/R_0", "-r/R_2", "abc_0",
                                      "lambda_2", "-r2/A_0", "-alpha_inf", "P_1", "sigma_2"};
  for (size_t i = 0; i < sizeof rules / sizeof rules[0]; i++) {
    int rc = testutil_runf(out, sizeof out, err, sizeof err, "got --rule %s --polygon '%s' "
                           "--print-triangles", rules[i], path);
    if (rc != 0) fail_msg("%s: exit %d: %s", rules[i], rc, err);
    const char *tot = strstr(out, "total badness: ");
    assert_non_null(tot);
    if (strstr(out, "nan") || strncmp(tot + 15, "inf", 3) == 0 || strncmp(tot + 15, "-inf", 4) == 0
        || strstr(out, " inf\n") || strstr(out, " -inf\n") || strncmp(tot + 15, "-0\n", 3) == 0
        || strncmp(tot + 15, "0\n", 2) == 0)
      fail_msg("%s: a non-finite or vanished value in:\n%s", rules[i], out);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_coord_parse),
    cmocka_unit_test(test_joint_split),
    cmocka_unit_test(test_scaled_measures),
    cmocka_unit_test(test_thin_quads_and_pentagons),
    cmocka_unit_test(test_thin_random_directions),
    cmocka_unit_test(test_flat_equal_sides),
    cmocka_unit_test(test_readers_refuse),
    cmocka_unit_test(test_got_extremes),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
