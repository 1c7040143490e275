/*
** test_measures.c: the 23 badness measures of spec/measures.md on
** hand-computed triangles (equilateral, 3-4-5, a sliver, a rotated 3-4-5),
** the appendix C l_inf measures against a brute-force largest inscribed
** square, independent recomputation on random triangles, signs, and the
** measure registry, and the cheap enclosures of the angle measures
** (measure_bounds) on a stress set of triangles.  Angles are in radians
** (sigma uses pi/3).
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

#include "measure.h"
#include "geom.h"
#include "testutil.h"

/* The measure NAME on triangle t, looked up by its command-line name. */
static double tmeas_val(const char *name, const geom_tri *t) {
  int id = measure_find(name);
  if (id < 0) {
    print_error("measure '%s' not found\n", name);
    fail();
  }
  return measure_eval(id, t);
}

typedef struct tmeas_expect {
  const char *name;
  double want, rel, abs;
} tmeas_expect;

static void tmeas_check_table(const char *tri, const geom_tri *t, const tmeas_expect *e, size_t n,
                              const char *file, int line) {
  for (size_t i = 0; i < n; i++) {
    char what[128];
    snprintf(what, sizeof what, "%s on %s", e[i].name, tri);
    testutil_near(tmeas_val(e[i].name, t), e[i].want, e[i].rel, e[i].abs, what, file, line);
  }
}
#define TMEAS_CHECK(tri, t, e) tmeas_check_table(tri, t, e, sizeof e / sizeof e[0], __FILE__, __LINE__)

static geom_point tmeas_pt(double x, double y) {
  geom_point p = {x, y};
  return p;
}

/* ---- registry ---- */

static const char *const tmeas_names[MEASURE_BUILTIN_COUNT] = {
  "-alpha", "beta", "gamma", "a", "-c", "P", "abc", "-A", "R", "-r", "-a'", "-r/R", "-r2/A",
  "-c/a", "-c/P", "a-c", "b/(c-a)", "lambda", "d", "sigma", "Pinf", "Rinf", "-rinf"};
static const measure_sign tmeas_signs[MEASURE_BUILTIN_COUNT] = {
  MEASURE_NONPOS, MEASURE_NONNEG, MEASURE_NONNEG, MEASURE_NONNEG, MEASURE_NONPOS,
  MEASURE_NONNEG, MEASURE_NONNEG, MEASURE_NONPOS, MEASURE_NONNEG, MEASURE_NONPOS,
  MEASURE_NONPOS, MEASURE_NONPOS, MEASURE_NONPOS, MEASURE_NONPOS, MEASURE_NONPOS,
  MEASURE_NONNEG, MEASURE_NONPOS, MEASURE_NONNEG, MEASURE_NONNEG, MEASURE_NONNEG,
  MEASURE_NONNEG, MEASURE_NONNEG, MEASURE_NONPOS};

static void test_registry(void **state) {
  (void)state;
  assert_int_equal(measure_count(), MEASURE_BUILTIN_COUNT);
  assert_int_equal(MEASURE_BUILTIN_COUNT, 23);
  for (int i = 0; i < MEASURE_BUILTIN_COUNT; i++) {
    const measure *m = measure_get(i);
    assert_non_null(m);
    assert_string_equal(m->name, tmeas_names[i]);
    assert_int_equal(measure_find(tmeas_names[i]), i);
    assert_int_equal(m->sign, tmeas_signs[i]);
    assert_non_null(m->fn);
    assert_true(m->symbol != NULL && m->symbol[0] != '\0');
    assert_true(m->desc != NULL && m->desc[0] != '\0' && strchr(m->desc, '\n') == NULL);
  }
  assert_int_equal(measure_find("R"), MEASURE_R);
  assert_int_equal(measure_find("-rinf"), MEASURE_NEG_RINF);
  assert_int_equal(measure_find("b/(c-a)"), MEASURE_B_OVER_C_MINUS_A);
  assert_int_equal(measure_find("foo"), -1);
  assert_int_equal(measure_find(""), -1);
  assert_int_equal(measure_find("r"), -1);   /* only "-r" exists */

  /* table 3.4's columns, in the thesis's order */
  static const char *const t34[MEASURE_TABLE34_COUNT] = {
    "R", "-alpha", "gamma", "-a'", "-A", "-r", "P", "a", "-c", "-r/R", "-r2/A", "lambda",
    "-c/a", "abc", "-c/P", "a-c", "b/(c-a)", "Rinf", "Pinf", "-rinf"};
  for (int i = 0; i < MEASURE_TABLE34_COUNT; i++)
    assert_int_equal(measure_table34[i], measure_find(t34[i]));

  char buf[4096];
  measure_names(buf, sizeof buf);
  for (int i = 0; i < MEASURE_BUILTIN_COUNT; i++) assert_non_null(strstr(buf, tmeas_names[i]));
  char small[10];
  memset(small, 'x', sizeof small);
  measure_names(small, sizeof small);          /* must truncate, not overflow */
  assert_true(memchr(small, '\0', sizeof small) != NULL);
}

static double tmeas_twice_area(const geom_tri *t, void *ctx) {
  (void)ctx;
  return 2 * t->area;
}

static void test_register_user(void **state) {
  (void)state;
  measure m = {"tests2area", "2A", "twice the area (test)", MEASURE_NONNEG, tmeas_twice_area, NULL};
  int id = measure_register(&m);
  assert_int_equal(id, MEASURE_BUILTIN_COUNT);
  assert_int_equal(measure_count(), MEASURE_BUILTIN_COUNT + 1);
  assert_int_equal(measure_find("tests2area"), id);
  geom_tri t;
  geom_tri_make(&t, tmeas_pt(0, 0), tmeas_pt(4, 0), tmeas_pt(0, 3));
  assert_true(measure_eval(id, &t) == 12);
  assert_int_equal(measure_register(&m), -1);         /* name taken */
  measure dup = m;
  dup.name = "R";
  assert_int_equal(measure_register(&dup), -1);       /* a built-in's name */
  measure_unregister_user();
  assert_int_equal(measure_count(), MEASURE_BUILTIN_COUNT);
  assert_int_equal(measure_find("tests2area"), -1);
}

/* ---- hand-computed triangles ---- */

/* Equilateral, side 2: (0,0), (2,0), (1, sqrt3); s3 = sqrt 3.
** angles pi/3; a = b = c = 2; A = sqrt3; P = 6; abc = 8; R = 8/(4 sqrt3) =
** 2/sqrt3; r = 2A/P = 1/sqrt3; a' = 2A/a = sqrt3; r/R = 1/2;
** r^2/A = 4A/P^2 = 4 sqrt3/36 = sqrt3/9; c/a = 1; c/P = 1/3; a - c = 0;
** b/(c-a) = 2/0 -> -inf (c - a is 0 or a few ulps below 0 in floating
** point: checked separately); lambda = a^2/(2A) = 4/(2 sqrt3) = 2/sqrt3;
** d = R(1 - cos 60deg) = R/2 = 1/sqrt3; sigma = 0; rx = 2, ry = sqrt3,
** Pinf = 2(2 + sqrt3), Rinf = max(2, sqrt3)/2 = 1, -rinf = -sqrt3/(2 + sqrt3). */
static void test_equilateral(void **state) {
  (void)state;
  double s3 = sqrt(3.0), pi = M_PI;
  geom_tri t;
  geom_tri_make(&t, tmeas_pt(0, 0), tmeas_pt(2, 0), tmeas_pt(1, s3));
  const tmeas_expect e[] = {
    {"-alpha", -pi / 3, 1e-13, 0}, {"beta", pi / 3, 1e-13, 0}, {"gamma", pi / 3, 1e-13, 0},
    {"a", 2, 1e-15, 0}, {"-c", -2, 1e-15, 0}, {"P", 6, 1e-15, 0}, {"abc", 8, 1e-14, 0},
    {"-A", -s3, 1e-15, 0}, {"R", 2 / s3, 1e-14, 0}, {"-r", -1 / s3, 1e-14, 0},
    {"-a'", -s3, 1e-14, 0}, {"-r/R", -0.5, 1e-14, 0}, {"-r2/A", -s3 / 9, 1e-14, 0},
    {"-c/a", -1, 1e-15, 0}, {"-c/P", -1.0 / 3, 1e-15, 0}, {"a-c", 0, 0, 1e-14},
    {"lambda", 2 / s3, 1e-14, 0}, {"d", 1 / s3, 1e-12, 0}, {"sigma", 0, 0, 1e-12},
    {"Pinf", 2 * (2 + s3), 1e-15, 0}, {"Rinf", 1, 1e-15, 0}, {"-rinf", -s3 / (2 + s3), 1e-14, 0},
  };
  TMEAS_CHECK("equilateral side 2", &t, e);
  double v = tmeas_val("b/(c-a)", &t);
  if (!(v < -1e12)) {   /* -inf, or b / (a few ulps) */
    print_error("b/(c-a) on equilateral = %.17g, want -inf or < -1e12\n", v);
    fail();
  }
}

/* Equilateral of side 1 in another position: (0.5, sqrt3/2), (0,0), (1,0);
** every length halves: a = 1, A = sqrt3/4, R = 1/sqrt3, -r = -1/(2 sqrt3),
** -a' = -sqrt3/2; scale-free ones unchanged; Pinf = 2(1 + sqrt3/2),
** Rinf = 1/2, -rinf = -(sqrt3/4)/(1 + sqrt3/2). */
static void test_equilateral_unit(void **state) {
  (void)state;
  double s3 = sqrt(3.0), h = s3 / 2, pi = M_PI;
  geom_tri t;
  geom_tri_make(&t, tmeas_pt(0.5, h), tmeas_pt(0, 0), tmeas_pt(1, 0));
  const tmeas_expect e[] = {
    {"-alpha", -pi / 3, 1e-13, 0}, {"gamma", pi / 3, 1e-13, 0}, {"a", 1, 1e-15, 0},
    {"-A", -s3 / 4, 1e-15, 0}, {"R", 1 / s3, 1e-14, 0}, {"-r", -1 / (2 * s3), 1e-14, 0},
    {"-a'", -h, 1e-14, 0}, {"-r/R", -0.5, 1e-14, 0}, {"-r2/A", -s3 / 9, 1e-14, 0},
    {"abc", 1, 1e-14, 0}, {"lambda", 2 / s3, 1e-14, 0}, {"d", 1 / (2 * s3), 1e-12, 0},
    {"Pinf", 2 * (1 + h), 1e-15, 0}, {"Rinf", 0.5, 1e-15, 0},
    {"-rinf", -(s3 / 4) / (1 + h), 1e-14, 0},
  };
  TMEAS_CHECK("equilateral side 1", &t, e);
}

/* 3-4-5: (0,0), (4,0), (0,3).  a = 5, b = 4, c = 3; alpha = atan2(3,4)
** = 0.6435..., beta = atan2(4,3) = 0.9273..., gamma = pi/2; A = 6, P = 12,
** abc = 60, R = 60/24 = 2.5, r = 12/12 = 1, a' = 12/5 = 2.4,
** r/R = 0.4 (= 8*36/(12*60)), r^2/A = 4*6/144 = 1/6, c/a = 0.6, c/P = 0.25,
** a - c = 2, b/(c-a) = 4/(3-5) = -2, lambda = 25/12, d = R(1 - cos 90deg)
** = 2.5 (the circumcentre is the midpoint of the hypotenuse: s = 0),
** sigma = sqrt(((alpha-pi/3)^2 + (beta-pi/3)^2 + (pi/6)^2)/3) = 0.38794...;
** rx = 4, ry = 3: Pinf = 14, Rinf = 2, -rinf = -6/7. */
static void test_345(void **state) {
  (void)state;
  double pi = M_PI, al = atan2(3, 4), be = atan2(4, 3);
  double sg = sqrt(((al - pi / 3) * (al - pi / 3) + (be - pi / 3) * (be - pi / 3) + (pi / 6) * (pi / 6)) / 3);
  geom_tri t;
  geom_tri_make(&t, tmeas_pt(0, 3), tmeas_pt(0, 0), tmeas_pt(4, 0));
  const tmeas_expect e[] = {
    {"-alpha", -al, 1e-13, 0}, {"beta", be, 1e-13, 0}, {"gamma", pi / 2, 1e-13, 0},
    {"a", 5, 1e-15, 0}, {"-c", -3, 1e-15, 0}, {"P", 12, 1e-15, 0}, {"abc", 60, 1e-15, 0},
    {"-A", -6, 1e-15, 0}, {"R", 2.5, 1e-15, 0}, {"-r", -1, 1e-15, 0}, {"-a'", -2.4, 1e-15, 0},
    {"-r/R", -0.4, 1e-14, 0}, {"-r2/A", -1.0 / 6, 1e-14, 0}, {"-c/a", -0.6, 1e-15, 0},
    {"-c/P", -0.25, 1e-15, 0}, {"a-c", 2, 1e-15, 0}, {"b/(c-a)", -2, 1e-15, 0},
    {"lambda", 25.0 / 12, 1e-14, 0}, {"d", 2.5, 1e-13, 0}, {"sigma", sg, 1e-12, 0},
    {"Pinf", 14, 0, 0}, {"Rinf", 2, 0, 0}, {"-rinf", -6.0 / 7, 1e-15, 0},
  };
  TMEAS_CHECK("3-4-5", &t, e);
  testutil_near(sg, 0.38794, 0, 1e-5, "sigma(3-4-5) hand value", __FILE__, __LINE__);
}

/* Sliver (0,0), (1,0), (0.5, 1e-3); s = sqrt(0.25 + 1e-6), th = atan(2e-3).
** a = 1, b = c = s; alpha = beta = th, gamma = pi - 2 th; A = 5e-4;
** P = 1 + 2s; abc = s^2 = 0.250001; R = 0.250001/0.002 = 125.0005;
** r = 1e-3/P; a' = 1e-3; r/R = r/125.0005; r^2/A = 4A/P^2 = 2e-3/P^2;
** c/a = s; c/P = s/P; a - c = 1 - s; b/(c-a) = s/(s-1); lambda = 1/1e-3 =
** 1000; d: the circumcentre is (0.5, k) with 0.25 + k^2 = (1e-3 - k)^2,
** k = (1e-6 - 0.25)/2e-3 = -124.9995, on the far side of the longest side
** (s = -124.9995) so d = R - s = 125.0005 + 124.9995 = 250;
** sigma = sqrt((2(th - pi/3)^2 + (2pi/3 - 2th)^2)/3) = sqrt2 (pi/3 - th);
** rx = 1, ry = 1e-3: Pinf = 2.002, Rinf = 0.5, -rinf = -5e-4/1.001. */
static void test_sliver(void **state) {
  (void)state;
  double pi = M_PI, s = sqrt(0.25 + 1e-6), th = atan(2e-3), P = 1 + 2 * s;
  geom_tri t;
  geom_tri_make(&t, tmeas_pt(1, 0), tmeas_pt(0.5, 1e-3), tmeas_pt(0, 0));
  const tmeas_expect e[] = {
    {"-alpha", -th, 1e-11, 0}, {"beta", th, 1e-11, 0}, {"gamma", pi - 2 * th, 1e-13, 0},
    {"a", 1, 1e-15, 0}, {"-c", -s, 1e-15, 0}, {"P", P, 1e-15, 0}, {"abc", 0.250001, 1e-14, 0},
    {"-A", -5e-4, 1e-12, 0}, {"R", 125.0005, 1e-12, 0}, {"-r", -1e-3 / P, 1e-12, 0},
    {"-a'", -1e-3, 1e-12, 0}, {"-r/R", -(1e-3 / P) / 125.0005, 1e-12, 0},
    {"-r2/A", -2e-3 / (P * P), 1e-12, 0}, {"-c/a", -s, 1e-15, 0}, {"-c/P", -s / P, 1e-15, 0},
    {"a-c", 1 - s, 1e-13, 0}, {"b/(c-a)", s / (s - 1), 1e-13, 0}, {"lambda", 1000, 1e-12, 0},
    {"d", 250, 1e-11, 0}, {"sigma", sqrt(2.0) * (pi / 3 - th), 1e-12, 0},
    {"Pinf", 2.002, 1e-15, 0}, {"Rinf", 0.5, 0, 0}, {"-rinf", -5e-4 / 1.001, 1e-12, 0},
  };
  TMEAS_CHECK("sliver", &t, e);
}

/* The 3-4-5 triangle rotated by 30 degrees about the origin:
** (0,0), (4,0) -> (4 cos30, 4 sin30) = (2 sqrt3, 2),
** (0,3) -> (-3 sin30, 3 cos30) = (-1.5, 1.5 sqrt3).
** rx = 2 sqrt3 + 1.5 = 4.964..., ry = 1.5 sqrt3 = 2.598...;
** Pinf = 2(rx + ry) = 3 + 7 sqrt3 = 15.124..., Rinf = rx/2 = sqrt3 + 0.75,
** -rinf = -A/(rx + ry) = -6/(1.5 + 3.5 sqrt3) = -0.7934...
** Every other measure is rotation invariant: equal to the unrotated ones. */
static void test_rotated_345(void **state) {
  (void)state;
  double s3 = sqrt(3.0);
  geom_tri t, u;
  geom_tri_make(&t, tmeas_pt(0, 0), tmeas_pt(2 * s3, 2), tmeas_pt(-1.5, 1.5 * s3));
  geom_tri_make(&u, tmeas_pt(0, 0), tmeas_pt(4, 0), tmeas_pt(0, 3));
  const tmeas_expect e[] = {
    {"Pinf", 3 + 7 * s3, 1e-15, 0}, {"Rinf", s3 + 0.75, 1e-15, 0},
    {"-rinf", -6 / (1.5 + 3.5 * s3), 1e-14, 0},
  };
  TMEAS_CHECK("rotated 3-4-5", &t, e);
  testutil_near(tmeas_val("-rinf", &t), -0.79342, 0, 1e-5, "-rinf rotated hand value", __FILE__, __LINE__);
  for (int i = 0; i < MEASURE_PINF; i++) {
    char what[64];
    snprintf(what, sizeof what, "%s rotated vs unrotated", tmeas_names[i]);
    testutil_near(measure_eval(i, &t), measure_eval(i, &u), 1e-13, 1e-14, what, __FILE__, __LINE__);
  }
}

/* The largest axis-parallel square inside a triangle, by linear
** programming: maximise s over squares [x, x+s] x [y, y+s]; for an edge
** with outward normal n and offset n.p_i, the square's farthest point
** gives n.(x,y) + s (max(nx,0) + max(ny,0)) <= n.p_i.  The optimum touches
** all three sides (appendix C), so solve the 3x3 system by Cramer's rule.
** Returns the half-side ("radius"), which appendix C calls r_inf. */
static double tmeas_inscribed_square(geom_point p0, geom_point p1, geom_point p2) {
  geom_point p[3] = {p0, p1, p2};
  double cr = (p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x);
  if (cr < 0) { p[1] = p2; p[2] = p1; }
  double m[3][4];
  for (int i = 0; i < 3; i++) {
    geom_point a = p[i], b = p[(i + 1) % 3];
    double nx = b.y - a.y, ny = -(b.x - a.x);   /* outward for anticlockwise */
    m[i][0] = nx;
    m[i][1] = ny;
    m[i][2] = fmax(nx, 0) + fmax(ny, 0);
    m[i][3] = nx * a.x + ny * a.y;
  }
  double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  double dets = m[0][0] * (m[1][1] * m[2][3] - m[1][3] * m[2][1]) -
                m[0][1] * (m[1][0] * m[2][3] - m[1][3] * m[2][0]) +
                m[0][3] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return dets / det / 2;
}

/* Appendix C's formula r_inf = A/(range x + range y), e.g. (0,0), (1,3),
** (4,4): A = |1*4 - 3*4|/2 = 4, rx = ry = 4, r_inf = 4/8 = 1/2: the unit
** square [1,2] x [2,3] touches y = 3x at (1,3), y = x at (2,2) and lies
** below y = 3 + (x-1)/3 (3.33 at x = 2); also checked against the LP. */
static void test_rinf_appendix_c(void **state) {
  (void)state;
  geom_tri t;
  geom_point p0 = tmeas_pt(0, 0), p1 = tmeas_pt(1, 3), p2 = tmeas_pt(4, 4);
  geom_tri_make(&t, p0, p1, p2);
  testutil_near(tmeas_val("-rinf", &t), -0.5, 1e-15, 0, "-rinf (0,0),(1,3),(4,4)", __FILE__, __LINE__);
  testutil_near(tmeas_inscribed_square(p0, p1, p2), 0.5, 1e-14, 0, "LP square", __FILE__, __LINE__);
  testutil_near(tmeas_val("Pinf", &t), 16, 0, 0, "Pinf (0,0),(1,3),(4,4)", __FILE__, __LINE__);
  testutil_near(tmeas_val("Rinf", &t), 2, 0, 0, "Rinf (0,0),(1,3),(4,4)", __FILE__, __LINE__);
  /* right isosceles (0,0), (1,0), (0,1): the square [0,1/2]^2, r_inf = 1/4 */
  geom_tri_make(&t, tmeas_pt(0, 1), tmeas_pt(0, 0), tmeas_pt(1, 0));
  testutil_near(tmeas_val("-rinf", &t), -0.25, 1e-15, 0, "-rinf right isosceles", __FILE__, __LINE__);

  testutil_rng g = {99};
  for (int n = 0; n < 20000; n++) {
    geom_point q[3];
    for (int k = 0; k < 3; k++) q[k] = tmeas_pt(2 * testutil_uniform(&g) - 1, 2 * testutil_uniform(&g) - 1);
    double cr = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x);
    if (fabs(cr) < 1e-3) continue;   /* keep the LP well conditioned */
    geom_tri_make(&t, q[0], q[1], q[2]);
    testutil_near(-tmeas_val("-rinf", &t), tmeas_inscribed_square(q[0], q[1], q[2]), 1e-9, 0,
               "-rinf vs largest inscribed square", __FILE__, __LINE__);
  }
}

/* Random triangles: each measure against an independent computation from
** the coordinates, and its declared sign. */
static void test_random_independent(void **state) {
  (void)state;
  testutil_rng g = {2024};
  double pi = M_PI;
  int done = 0;
  while (done < 20000) {
    geom_point p[3];
    for (int k = 0; k < 3; k++) p[k] = tmeas_pt(4 * testutil_uniform(&g) - 2, 4 * testutil_uniform(&g) - 2);
    double cr = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x);
    if (fabs(cr) < 1e-4) continue;
    done++;
    /* sides with their opposite vertex, sorted descending */
    double s[3];
    int opp[3];
    for (int i = 0; i < 3; i++) {
      s[i] = hypot(p[(i + 1) % 3].x - p[(i + 2) % 3].x, p[(i + 1) % 3].y - p[(i + 2) % 3].y);
      opp[i] = i;
    }
    for (int i = 0; i < 3; i++)
      for (int j = i + 1; j < 3; j++)
        if (s[j] > s[i]) {
          double x = s[i]; s[i] = s[j]; s[j] = x;
          int o = opp[i]; opp[i] = opp[j]; opp[j] = o;
        }
    double a = s[0], b = s[1], c = s[2], A = fabs(cr) / 2, P = a + b + c;
    double ang[3];   /* ang[i] opposite s[i] */
    for (int i = 0; i < 3; i++)
      ang[i] = atan2(4 * A, s[(i + 1) % 3] * s[(i + 1) % 3] + s[(i + 2) % 3] * s[(i + 2) % 3] - s[i] * s[i]);
    double R = a * b * c / (4 * A), r = 2 * A / P;
    /* d = R - (signed distance from the circumcentre to the longest side,
    ** positive on the side of the opposite vertex) */
    geom_point u = p[(opp[0] + 1) % 3], v = p[(opp[0] + 2) % 3], w = p[opp[0]];
    double bx = v.x - u.x, by = v.y - u.y, cx = w.x - u.x, cy = w.y - u.y;
    double D = 2 * (bx * cy - by * cx);
    double ox = (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / D;
    double oy = (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / D;
    double side_w = bx * cy - by * cx, side_o = bx * oy - by * ox;   /* signed, times |uv| */
    double dist = (side_o * (side_w > 0 ? 1 : -1)) / hypot(bx, by);
    double dd = R - dist;
    double sig = 0;
    for (int i = 0; i < 3; i++) sig += (ang[i] - pi / 3) * (ang[i] - pi / 3);
    sig = sqrt(sig / 3);
    double xmin = fmin(p[0].x, fmin(p[1].x, p[2].x)), xmax = fmax(p[0].x, fmax(p[1].x, p[2].x));
    double ymin = fmin(p[0].y, fmin(p[1].y, p[2].y)), ymax = fmax(p[0].y, fmax(p[1].y, p[2].y));
    double rx = xmax - xmin, ry = ymax - ymin;
    const double want[MEASURE_BUILTIN_COUNT] = {
      -ang[2], ang[1], ang[0], a, -c, P, a * b * c, -A, R, -r, -2 * A / a, -r / R, -4 * A / (P * P),
      -c / a, -c / P, a - c, b / (c - a), a * a / (2 * A), dd, sig, 2 * (rx + ry),
      fmax(rx, ry) / 2, -A / (rx + ry)};
    geom_tri t;
    geom_tri_make(&t, p[0], p[1], p[2]);
    for (int i = 0; i < MEASURE_BUILTIN_COUNT; i++) {
      double got = measure_eval(i, &t);
      /* 1e-9: areas from a different base vertex differ by eps*side^2/A
      ** <= 1e-12 here; b/(c-a) near isosceles a = c amplifies it */
      double rel = i == MEASURE_B_OVER_C_MINUS_A ? 1e-6 : 1e-9;
      if (!(fabs(got - want[i]) <= rel * fabs(want[i]) + 1e-12)) {
        print_error("%s on (%.17g,%.17g) (%.17g,%.17g) (%.17g,%.17g): got %.17g want %.17g\n",
                    tmeas_names[i], p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y, got, want[i]);
        fail();
      }
      if (tmeas_signs[i] == MEASURE_NONNEG) assert_true(got >= 0);
      if (tmeas_signs[i] == MEASURE_NONPOS) assert_true(got <= 0);
    }
  }
}

/* ---- measure_bounds: the LOT cache's enclosures ---- */

/* A point inside the contract: x clamped to [1e-30, 1e30] in magnitude. */
static double tmeas_clamp(double x) {
  double m = fabs(x);
  return m == 0 ? 0 : m < 1e-30 ? copysign(1e-30, x) : m > 1e30 ? copysign(1e30, x) : x;
}

static double tmeas_ulps(double x, int k) {
  for (; k > 0; k--) x = nextafter(x, INFINITY);
  for (; k < 0; k++) x = nextafter(x, -INFINITY);
  return x;
}

/* One triangle of the stress set: kind 0 uniform, 1 a needle (one side
** 1e-9 of the others), 2 flat (apex 1e-9 off a side, also outside it),
** 3 nearly equilateral, 4 nearly isosceles with a right angle, 5 flat to a
** few ulps, 6 two vertices a few ulps apart (the two long sides equal to
** rounding, the angles at their ends anything summing to pi), 7
** isosceles (base angles equal, the apex anything); then scaled by
** 2^-95 .. 2^95 and shifted. */
static void tmeas_stress_tri(testutil_rng *g, int kind, geom_point v[3]) {
  double u[6];
  for (int i = 0; i < 6; i++) u[i] = testutil_uniform(g);
  switch (kind) {
    case 0:
      for (int i = 0; i < 3; i++) v[i] = (geom_point){u[2 * i], u[2 * i + 1]};
      break;
    case 1:
      v[0] = (geom_point){u[0], u[1]};
      v[1] = (geom_point){u[0] + 1e-9 * (u[2] - 0.5), u[1] + 1e-9 * (u[3] - 0.5)};
      v[2] = (geom_point){u[4], u[5]};
      break;
    case 2: case 5: {
      double t = 3 * u[2] - 1, off = kind == 2 ? 1e-9 * (u[3] - 0.5) : 0;
      v[0] = (geom_point){u[0], u[1]};
      v[1] = (geom_point){u[4], u[5]};
      v[2] = (geom_point){u[0] + t * (u[4] - u[0]) - off * (u[5] - u[1]),
                          u[1] + t * (u[5] - u[1]) + off * (u[4] - u[0])};
      if (kind == 5) v[2].y = nextafter(nextafter(v[2].y, 2), 2);
      break;
    }
    case 3: {
      double e = 1e-7 * (u[0] - 0.5);
      v[0] = (geom_point){0, 0};
      v[1] = (geom_point){1, e};
      v[2] = (geom_point){0.5 + e * u[1], sqrt(0.75) - e * u[2]};
      break;
    }
    case 4:
      v[0] = (geom_point){0, 0};
      v[1] = (geom_point){1, 0};
      v[2] = (geom_point){1e-9 * (u[0] - 0.5), 1 + 1e-9 * (u[1] - 0.5)};
      break;
    case 6:
      v[0] = (geom_point){u[0], u[1]};
      v[1] = (geom_point){tmeas_ulps(u[0], (int)(u[2] * 7) - 3), tmeas_ulps(u[1], (int)(u[3] * 7) - 3)};
      v[2] = (geom_point){u[4] + 1, u[5]};
      break;
    default:
      v[0] = (geom_point){0, 0};
      v[1] = (geom_point){2 * u[0], 0};
      v[2] = (geom_point){u[0], 3 * u[1]};
      break;
  }
  if (kind == 6 && (testutil_next(g) & 1)) return;   /* unscaled: the ulps stay apart */
  double scale = ldexp(1.0, (int)(testutil_next(g) % 191) - 95), sx = 2 * u[3] - 1, sy = 2 * u[4] - 1;
  for (int i = 0; i < 3; i++)
    v[i] = (geom_point){tmeas_clamp(scale * (v[i].x + sx)), tmeas_clamp(scale * (v[i].y + sy))};
}

/* One triangle, one angle measure, every vertex order: the enclosure holds
** the very double measure_eval gives and is at most `width` wide; the
** measure's floor is below it.  Returns how many orders had no enclosure. */
static int tmeas_check_bounds(int id, const geom_point v[3], double width, long *bad) {
  geom_tri t;
  geom_tri_make(&t, v[0], v[1], v[2]);
  double x = measure_eval(id, &t);
  int none = 0;
  if (!(measure_floor(id) <= x) && (*bad)++ < 5)
    print_error("%s = %.17g below its floor %.17g\n", measure_get(id)->name, x, measure_floor(id));
  for (int o = 0; o < 6; o++) {
    double lo, hi;
    const int *o3 = testutil_perm3[o];
    if (!measure_bounds(id, v[o3[0]], v[o3[1]], v[o3[2]], &lo, &hi)) {
      none++;
      continue;
    }
    if (!(lo <= x && x <= hi && hi - lo <= width) && (*bad)++ < 5)
      print_error("%s of (%a,%a) (%a,%a) (%a,%a): [%.17g, %.17g], value %.17g\n",
                  measure_get(id)->name, v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y, lo, hi, x);
  }
  return none;
}

/* For the four angle measures, measure_bounds encloses the very double
** measure_eval gives, in every vertex order, within 1e-5; no enclosure
** only for triangles whose area needs the exact path.  The other measures
** have none.  The two vertices 1e-17 apart of geom.c's example: gamma (135
** degrees) is enclosed although the sides round to the same length. */
static void test_bounds(void **state) {
  (void)state;
  static const int ids[] = {MEASURE_NEG_ALPHA, MEASURE_BETA, MEASURE_GAMMA, MEASURE_SIGMA};
  testutil_rng g = {777};
  long checked = 0, none = 0, bad = 0;
  for (int it = 0; it < 160000; it++) {
    geom_point v[3];
    tmeas_stress_tri(&g, it % 8, v);
    if (geom_orient(v[0], v[1], v[2]) == 0) continue;
    for (size_t k = 0; k < sizeof ids / sizeof ids[0]; k++) {
      none += tmeas_check_bounds(ids[k], v, 1e-5, &bad);
      checked += 6;
    }
  }
  print_message("bounds: %ld checked, %ld without (flat), %ld wrong\n", checked, none, bad);
  assert_int_equal(bad, 0);
  assert_true(none > 0 && none < checked / 2);
  geom_point ex[3] = {{0, 0}, {1e-17, 1e-17}, {1, 0}};
  for (size_t k = 0; k < sizeof ids / sizeof ids[0]; k++)
    assert_int_equal(tmeas_check_bounds(ids[k], ex, 1e-5, &bad), 0);
  assert_int_equal(bad, 0);
  geom_point a = {0, 0}, b = {1, 0}, c = {0, 1};
  double lo, hi;
  for (int id = 0; id < measure_count(); id++)
    if (!measure_has_bounds(id)) assert_int_equal(measure_bounds(id, a, b, c, &lo, &hi), 0);
}

/* measure_points(id) is measure_eval on geom_tri_make, bit for bit, in
** every vertex order: on the stress set, and on triangles with signed
** zeros, coincident and collinear vertices (the sort-free and origin-only
** paths of geom_tri_fill_values must agree with the canonical sort there
** too).  Two NaN results count as equal. */
static int tmeas_points_agree(int id, const geom_point v[3]) {
  geom_tri t;
  geom_tri_make(&t, v[0], v[1], v[2]);
  double x = measure_eval(id, &t);
  for (int o = 0; o < 6; o++) {
    const int *o3 = testutil_perm3[o];
    double y = measure_points(id)(v[o3[0]], v[o3[1]], v[o3[2]]);
    if (!(isnan(x) && isnan(y)) && memcmp(&x, &y, sizeof x) != 0) {
      print_error("%s of (%a,%a) (%a,%a) (%a,%a) order %d: %a, expected %a\n",
                  measure_get(id)->name, v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y, o, y, x);
      return 0;
    }
  }
  return 1;
}

static void test_points_kernels(void **state) {
  (void)state;
  static const geom_point special[][3] = {
    {{0, 0}, {-0.0, 1}, {1, -0.0}}, {{-0.0, -0.0}, {0, 0}, {1, 1}}, {{0, 0}, {0, 0}, {0, 0}},
    {{0, 0}, {-0.0, 0}, {0, -0.0}}, {{1, 2}, {1, 2}, {3, 5}}, {{0, 0}, {1, 1}, {2, 2}},
    {{0, 1}, {0, 2}, {0, 3}}, {{-0.0, 1}, {0, 2}, {-0.0, 3}}, {{1e-30, 0}, {0, 1e-30}, {0, 0}},
  };
  testutil_rng g = {4242};
  long bad = 0, n = 0;
  for (int id = 0; id < MEASURE_BUILTIN_COUNT; id++) {
    assert_non_null(measure_points(id));
    for (size_t s = 0; s < sizeof special / sizeof special[0]; s++, n++)
      bad += !tmeas_points_agree(id, special[s]);
    for (int it = 0; it < 6000; it++, n++) {
      geom_point v[3];
      tmeas_stress_tri(&g, it % 6, v);
      bad += !tmeas_points_agree(id, v);
    }
  }
  print_message("measure_points: %ld triangles x 6 orders, %ld differing\n", n, bad);
  assert_int_equal(bad, 0);
  assert_null(measure_points(MEASURE_BUILTIN_COUNT));
  assert_null(measure_points(-1));
}

/* geom_angle_rank_bounds encloses alpha, beta and gamma as geom_tri_make
** computes them, in every vertex order, within 1e-5, on the stress set:
** one angle where the sides are told apart, all three for the isosceles
** and near-isosceles kinds (3, 4, 6, 7) where they may not be. */
static void test_angle_rank_bounds(void **state) {
  (void)state;
  testutil_rng g = {778};
  long checked = 0, bad = 0;
  for (int it = 0; it < 80000; it++) {
    geom_point v[3];
    tmeas_stress_tri(&g, it % 8, v);
    if (geom_orient(v[0], v[1], v[2]) == 0) continue;
    geom_tri t;
    geom_tri_make(&t, v[0], v[1], v[2]);
    const double want[3] = {t.alpha, t.beta, t.gamma};
    for (int k = 0; k < 3; k++)
      for (int o = 0; o < 6; o++) {
        double l, h;
        const int *o3 = testutil_perm3[o];
        if (!geom_angle_rank_bounds(v[o3[0]], v[o3[1]], v[o3[2]], k, &l, &h))
          continue;
        checked++;
        if (!(l <= want[k] && want[k] <= h && h - l < 1e-5) && bad++ < 5)
          print_error("angle %d of (%a,%a) (%a,%a) (%a,%a): [%.17g, %.17g], value %.17g\n", k,
                      v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y, l, h, want[k]);
      }
  }
  print_message("ranked angles: %ld enclosures, %ld wrong\n", checked, bad);
  assert_int_equal(bad, 0);
  assert_true(checked > 500000);
}

/* measure_floor is below every value of its measure, on the stress set
** and on near-equilateral triangles, where the bounded ratios (-r/R, -c/P,
** -r2/A) come closest to their floors: lot_prefers_exact rules flips out
** from it. */
static void test_floors(void **state) {
  (void)state;
  testutil_rng g = {31337};
  long bad = 0, tight = 0;
  for (int it = 0; it < 120000; it++) {
    geom_point v[3];
    if (it % 2) {
      tmeas_stress_tri(&g, it % 7, v);
    } else {   /* equilateral to within 1e-k, k = 0..16, at any scale */
      double e = pow(10, -(double)(testutil_next(&g) % 17)), s = ldexp(1, (int)(testutil_next(&g) % 181) - 90);
      v[0] = (geom_point){0, 0};
      v[1] = (geom_point){s, s * e * (testutil_uniform(&g) - 0.5)};
      v[2] = (geom_point){s * (0.5 + e * (testutil_uniform(&g) - 0.5)), s * sqrt(0.75)};
    }
    if (geom_orient(v[0], v[1], v[2]) == 0) continue;
    geom_tri t;
    geom_tri_make(&t, v[0], v[1], v[2]);
    for (int id = 0; id < MEASURE_BUILTIN_COUNT; id++) {
      double x = measure_eval(id, &t), f = measure_floor(id);
      if (!(f <= x) && bad++ < 5)
        print_error("%s = %.17g below its floor %.17g\n", measure_get(id)->name, x, f);
      tight += isfinite(f) && f < 0 && x - f < 1e-6 * fabs(f);
    }
  }
  print_message("floors: %ld values within 1e-6 of a floor, %ld below\n", tight, bad);
  assert_int_equal(bad, 0);
  assert_true(tight > 1000);   /* the near-equilateral triangles reach the floors */
}

/* A dense sweep of one angle through (0, pi) at several scales: the
** enclosures of geom_angle_bounds hold the angles geom_tri_make computes
** (this probes the atan polynomial on a fine grid of arguments). */
static void test_angle_bounds_sweep(void **state) {
  (void)state;
  long wrong = 0, n = 0;
  for (int s = -90; s <= 90; s += 30)
    for (int i = 1; i < 200000; i++) {
      double th = M_PI * i / 200000.0, sc = ldexp(1.0, s);
      geom_point v[3] = {{0, 0}, {sc, 0}, {0.75 * sc * cos(th), 0.75 * sc * sin(th)}};
      double lo[3], hi[3];
      if (!geom_angle_bounds(v[0], v[1], v[2], lo, hi)) continue;
      geom_tri t;
      geom_tri_make(&t, v[0], v[1], v[2]);
      n++;
      if (!(geom_min3(lo[0], lo[1], lo[2]) <= t.alpha && t.alpha <= geom_min3(hi[0], hi[1], hi[2])
            && geom_mid3(lo[0], lo[1], lo[2]) <= t.beta && t.beta <= geom_mid3(hi[0], hi[1], hi[2])
            && geom_max3(lo[0], lo[1], lo[2]) <= t.gamma && t.gamma <= geom_max3(hi[0], hi[1], hi[2]))
          && wrong++ < 5)
        print_error("angle %.17g at scale 2^%d: not enclosed\n", th, s);
    }
  print_message("angle sweep: %ld triangles, %ld not enclosed\n", n, wrong);
  assert_int_equal(wrong, 0);
  assert_true(n > 1000000);
}

/* measure_eval_tris is measure_eval on geom_tri_make's triangle, bit for
** bit, for every measure, whatever the vertex order (random triangles and
** a flat one: the same inf or NaN).  More triangles than the threshold of
** the threaded loop, so that path is the one compared. */
static void test_eval_tris(void **state) {
  (void)state;
  enum { M = 30000 };
  geom_point *v = malloc(3 * M * sizeof *v);
  double *out = malloc(M * sizeof *out);
  assert_non_null(v);
  assert_non_null(out);
  uint64_t s = 12345;
  for (int i = 0; i < 3 * M; i++) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    v[i].x = (double)(s >> 11) * 0x1p-53 - 0.5;
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    v[i].y = (double)(s >> 11) * 0x1p-53 - 0.5;
  }
  v[3] = (geom_point){0, 0}, v[4] = (geom_point){1, 1}, v[5] = (geom_point){2, 2};
  for (int id = 0; id < measure_count(); id++) {
    measure_eval_tris(id, v, M, out);
    for (int i = 0; i < M; i++) {
      geom_tri t;
      geom_tri_make(&t, v[3 * i + 2], v[3 * i], v[3 * i + 1]);
      double want = measure_eval(id, &t);
      if (!(out[i] == want || (isnan(out[i]) && isnan(want))) ||
          (out[i] == 0 && signbit(out[i]) != signbit(want)))
        fail_msg("measure %s, triangle %d: %.17g, measure_eval %.17g", measure_get(id)->name, i,
                 out[i], want);
    }
  }
  free(v);
  free(out);
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_registry),
    cmocka_unit_test(test_register_user),
    cmocka_unit_test(test_equilateral),
    cmocka_unit_test(test_equilateral_unit),
    cmocka_unit_test(test_345),
    cmocka_unit_test(test_sliver),
    cmocka_unit_test(test_rotated_345),
    cmocka_unit_test(test_rinf_appendix_c),
    cmocka_unit_test(test_random_independent),
    cmocka_unit_test(test_points_kernels),
    cmocka_unit_test(test_floors),
    cmocka_unit_test(test_bounds),
    cmocka_unit_test(test_angle_rank_bounds),
    cmocka_unit_test(test_eval_tris),
    cmocka_unit_test(test_angle_bounds_sweep),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
