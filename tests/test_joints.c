/*
** test_joints.c: the algebra of the six joints (thesis table 3.3) on seeded
** random values of both sign domains: the l_p formulas and the sign
** convention, commutativity (bit-exact), associativity (to rounding),
** monotonicity, the identity element, infinite inputs, and the keys
** (strictly increasing, invertible, turning f into +, min or max), and
** verdicts from enclosures (joint_compare_bounds) against joint_compare;
** and the power means l_p made through the table: names, decisions on
** random quadrilaterals against sums of p-th powers in long double, the
** algebra, the split form and the keys.
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

#include "joint.h"
#include "measure.h"
#include "rule.h"
#include "testutil.h"

#define TJOINT_SAMPLES 200000

/* A value of the domain of sign s: magnitudes spread over 1e-3 .. 1e3,
** with exact zeros now and then (measures such as a-c reach 0). */
static double tjoint_value(testutil_rng *g, int s) {
  double u = testutil_uniform(g);
  double m = u < 0.03 ? 0.0 : testutil_uniform(g) * pow(10.0, 6 * testutil_uniform(g) - 3);
  return s * m;
}

/* The l_p joints of table 3.3 for x, y >= 0, written independently. */
static double tjoint_ref(joint_id j, double x, double y) {
  switch (j) {
  case JOINT_MIN: return fmin(x, y);
  case JOINT_HARMONIC: return (x == 0 || y == 0) ? 0 : 1 / (1 / x + 1 / y);
  case JOINT_PRODUCT: return x * y;
  case JOINT_SUM: return x + y;
  case JOINT_RSS: return sqrt(x * x + y * y);
  default: return fmax(x, y);
  }
}

static int tjoint_is_finite_p(joint_id j) {
  return j != JOINT_MIN && j != JOINT_MAX;
}

static void tjoint_fail(const char *what, joint_id j, int s, double x, double y, double got, double want) {
  print_error("%s: joint %s s=%d x=%.17g y=%.17g: got %.17g want %.17g\n", what,
              joint_get(j)->name, s, x, y, got, want);
}

static void test_table(void **state) {
  (void)state;
  static const char *const names[JOINT_COUNT] = {"-inf", "-1", "0", "1", "2", "inf"};
  static const joint_keyop ops[JOINT_COUNT] = {JOINT_KEY_MIN, JOINT_KEY_ADD, JOINT_KEY_ADD,
                                               JOINT_KEY_ADD, JOINT_KEY_ADD, JOINT_KEY_MAX};
  for (int j = 0; j < JOINT_COUNT; j++) {
    const joint *J = joint_get((joint_id)j);
    assert_non_null(J);
    assert_string_equal(J->name, names[j]);
    assert_int_equal(joint_find(names[j]), j);
    assert_int_equal(J->needs_sign, tjoint_is_finite_p((joint_id)j));
    assert_int_equal(J->keyop, ops[j]);
    assert_true(J->symbol && J->symbol[0] && J->desc && J->desc[0]);
  }
  assert_int_equal(joint_find("3x"), -1);
  assert_int_equal(joint_find(""), -1);
  assert_int_equal(joint_find("Inf"), -1);
  assert_int_equal(joint_find("--2"), -1);
}

/* Formula and sign convention: for s = +1 the l_p formula (to ~4 ulps: an
** implementation may use x*y/(x+y) or hypot); for s = -1 the finite-p
** joints are exactly -f(|x|, |y|) and min / max are used as they are. */
static void test_formula_and_sign(void **state) {
  (void)state;
  testutil_rng g = {1};
  for (int n = 0; n < TJOINT_SAMPLES; n++) {
    for (int s = -1; s <= 1; s += 2) {
      double x = tjoint_value(&g, s), y = tjoint_value(&g, s);
      for (int jj = 0; jj < JOINT_COUNT; jj++) {
        joint_id j = (joint_id)jj;
        double got = joint_apply(j, s, x, y), want;
        if (s == 1) {
          want = tjoint_ref(j, x, y);
          if (!(fabs(got - want) <= 1e-15 * fabs(want))) {
            tjoint_fail("formula", j, s, x, y, got, want);
            fail();
          }
          assert_true(got >= 0);
        } else {
          want = tjoint_is_finite_p(j) ? -joint_apply(j, 1, fabs(x), fabs(y))
                                       : (j == JOINT_MIN ? fmin(x, y) : fmax(x, y));
          if (got != want) {
            tjoint_fail("sign convention", j, s, x, y, got, want);
            fail();
          }
          assert_true(got <= 0);
        }
      }
    }
  }
}

/* Commutativity must be bit-exact: the flip rules' independence of the
** first vertex relies on it (rule.h). */
static void test_commutative(void **state) {
  (void)state;
  testutil_rng g = {2};
  for (int n = 0; n < TJOINT_SAMPLES; n++)
    for (int s = -1; s <= 1; s += 2) {
      double x = tjoint_value(&g, s), y = tjoint_value(&g, s);
      for (int j = 0; j < JOINT_COUNT; j++) {
        double f1 = joint_apply((joint_id)j, s, x, y), f2 = joint_apply((joint_id)j, s, y, x);
        if (memcmp(&f1, &f2, sizeof f1) != 0) {
          tjoint_fail("commutative", (joint_id)j, s, x, y, f1, f2);
          fail();
        }
      }
    }
}

/* Associativity holds only to rounding: (x+y)+z and x+(y+z) round
** different intermediate sums.  With all operands of one sign no
** cancellation occurs, every operation (1/x, +, *, x^2, sqrt) adds a
** relative error <= 2^-53, and each side takes at most ~8 of them: the two
** agree to ~2e-15 relative.  1e-12 leaves a wide margin; min and max are
** exact. */
static void test_associative(void **state) {
  (void)state;
  testutil_rng g = {3};
  for (int n = 0; n < TJOINT_SAMPLES; n++)
    for (int s = -1; s <= 1; s += 2) {
      double x = tjoint_value(&g, s), y = tjoint_value(&g, s), z = tjoint_value(&g, s);
      for (int jj = 0; jj < JOINT_COUNT; jj++) {
        joint_id j = (joint_id)jj;
        double l = joint_apply(j, s, joint_apply(j, s, x, y), z);
        double r = joint_apply(j, s, x, joint_apply(j, s, y, z));
        double tol = tjoint_is_finite_p(j) ? 1e-12 * fabs(l) : 0;
        if (!(fabs(l - r) <= tol)) {
          print_error("associative: joint %s s=%d x=%.17g y=%.17g z=%.17g: %.17g vs %.17g\n",
                      joint_get(j)->name, s, x, y, z, l, r);
          fail();
        }
      }
    }
}

/* x <= y implies f(x, z) <= f(y, z): also in floating point, since each
** step is a monotone function followed by (monotone) rounding.  Half the
** pairs are adjacent doubles to probe that. */
static void test_monotone(void **state) {
  (void)state;
  testutil_rng g = {4};
  for (int n = 0; n < TJOINT_SAMPLES; n++)
    for (int s = -1; s <= 1; s += 2) {
      double x = tjoint_value(&g, s), y = (n & 1) && x != 0 ? nextafter(x, s * INFINITY) : tjoint_value(&g, s);
      double z = tjoint_value(&g, s);
      if (y < x) { double t = x; x = y; y = t; }
      for (int jj = 0; jj < JOINT_COUNT; jj++) {
        joint_id j = (joint_id)jj;
        double fx = joint_apply(j, s, x, z), fy = joint_apply(j, s, y, z);
        if (!(fx <= fy)) {
          print_error("monotone: joint %s s=%d x=%.17g <= y=%.17g, z=%.17g: f %.17g > %.17g\n",
                      joint_get(j)->name, s, x, y, z, fx, fy);
          fail();
        }
      }
    }
}

/* f(e, x) == x == f(x, e) exactly for every x of the domain (0 included):
** the GOT programme uses e for "no triangle yet". */
static void test_identity(void **state) {
  (void)state;
  testutil_rng g = {5};
  int failures = 0;
  for (int s = -1; s <= 1; s += 2)
    for (int jj = 0; jj < JOINT_COUNT; jj++) {
      joint_id j = (joint_id)jj;
      double e = joint_identity(j, s);
      assert_false(isnan(e));
      int bad = 0;
      for (int n = 0; n < TJOINT_SAMPLES / 10; n++) {
        double x = n == 0 ? 0.0 : tjoint_value(&g, s);
        double l = joint_apply(j, s, e, x), r = joint_apply(j, s, x, e);
        if (l != x || r != x) {
          if (bad++ < 3) tjoint_fail("identity", j, s, e, x, l, x);
        }
      }
      if (bad) {
        print_error("identity fails for joint %s s=%d on %d of %d values\n", joint_get(j)->name, s,
                    bad, TJOINT_SAMPLES / 10);
        failures++;
      }
      /* the identity's key is the key-space identity */
      double k = joint_key(j, s, e);
      if (k != joint_key_identity(j)) {
        print_error("joint %s s=%d: key(identity %.17g) = %.17g, key identity %.17g\n",
                    joint_get(j)->name, s, e, k, joint_key_identity(j));
        failures++;
      }
    }
  assert_int_equal(failures, 0);
}

/* b/(c-a) is -inf on an exactly equilateral triangle: a joint of the <= 0
** domain must give the limit, never NaN. */
static void test_infinite_inputs(void **state) {
  (void)state;
  const double ys[] = {-0.5, -3.0, -INFINITY};
  for (size_t i = 0; i < sizeof ys / sizeof ys[0]; i++) {
    double y = ys[i];
    for (int jj = 0; jj < JOINT_COUNT; jj++) {
      joint_id j = (joint_id)jj;
      double f = joint_apply(j, -1, -INFINITY, y), f2 = joint_apply(j, -1, y, -INFINITY);
      double want = j == JOINT_MAX ? y : j == JOINT_HARMONIC ? y : -INFINITY;
      if (isnan(f) || !(fabs(f - want) <= 1e-15 * fabs(want) || f == want) || f != f2) {
        tjoint_fail("infinite input", j, -1, -INFINITY, y, f, want);
        fail();
      }
    }
  }
}

/* Keys: phi strictly increasing (for values that differ by more than the
** key's own rounding: log or 1/x of adjacent doubles may round together,
** so adjacent pairs are only required non-decreasing), unkey inverting it,
** and phi(f(x, y)) = phi(x) (+) phi(y) to rounding. */
static void test_keys(void **state) {
  (void)state;
  testutil_rng g = {6};
  for (int n = 0; n < TJOINT_SAMPLES; n++)
    for (int s = -1; s <= 1; s += 2) {
      double x = tjoint_value(&g, s);
      double y = (n & 3) == 0 && x != 0 ? nextafter(x, s * INFINITY) : tjoint_value(&g, s);
      if (y < x) { double t = x; x = y; y = t; }
      for (int jj = 0; jj < JOINT_COUNT; jj++) {
        joint_id j = (joint_id)jj;
        const joint *J = joint_get(j);
        double kx = joint_key(j, s, x), ky = joint_key(j, s, y);
        assert_false(isnan(kx) || isnan(ky));
        int strict = y - x > 1e-9 * fmax(fabs(x), fabs(y));
        if (strict ? !(kx < ky) : !(kx <= ky)) {
          print_error("key not increasing: joint %s s=%d x=%.17g y=%.17g keys %.17g %.17g\n",
                      J->name, s, x, y, kx, ky);
          fail();
        }
        double ux = joint_unkey(j, s, kx);
        if (!(fabs(ux - x) <= 1e-12 * fabs(x))) {
          tjoint_fail("unkey(key(x))", j, s, x, kx, ux, x);
          fail();
        }
        double kf = joint_key(j, s, joint_apply(j, s, x, y));
        double kc = joint_key_combine(J->keyop, kx, ky);
        int ok = isinf(kc) ? kf == kc
                           : fabs(kf - kc) <= 1e-12 * (1 + fabs(kx) + fabs(ky));
        if (!ok) {
          print_error("key(f(x,y)) %.17g vs combine(key x, key y) %.17g: joint %s s=%d x=%.17g y=%.17g\n",
                      kf, kc, J->name, s, x, y);
          fail();
        }
      }
    }
}

/* joint_compare decides as joint_compare_values on joint_apply's values,
** for the joints it evaluates plainly (every one but l_0 and l_2, whose
** split form has its own tests): on random values of both sign domains,
** with zeros of both signs, infinities and near-ties at the tolerance. */
static double tjoint_hard(testutil_rng *g, int s) {
  static const double special[] = {0.0, -0.0, INFINITY, 1.0, 0x1p-1000, 0x1p1000};
  double u = testutil_uniform(g);
  if (u < 0.2) return s * special[testutil_next(g) % 6];
  return tjoint_value(g, s);
}

static void test_compare_plain(void **state) {
  (void)state;
  static const double eps[] = {0.0, 1e-12, 1e-6};
  testutil_rng g = {4711};
  long bad = 0;
  for (int j = 0; j < JOINT_COUNT; j++) {
    if (j == JOINT_PRODUCT || j == JOINT_RSS) continue;
    for (int k = 0; k < TJOINT_SAMPLES; k++) {
      int s = k % 2 ? -1 : 1;
      double x1 = tjoint_hard(&g, s), y1 = tjoint_hard(&g, s), x2, y2;
      if (k % 3 == 0) {   /* a near-tie: the same pair, one value nudged */
        x2 = y1;
        y2 = x1 * (1 + 1e-12 * (testutil_uniform(&g) - 0.5));
      } else {
        x2 = tjoint_hard(&g, s);
        y2 = tjoint_hard(&g, s);
      }
      for (int e = 0; e < 3; e++) {
        int want = joint_compare_values(joint_apply(j, s, x1, y1), joint_apply(j, s, x2, y2), eps[e]);
        int got = joint_compare(j, s, x1, y1, x2, y2, eps[e]);
        if (got != want && bad++ < 5)
          print_error("joint %s s=%d (%a, %a) vs (%a, %a) eps %g: %d, expected %d\n",
                      joint_get(j)->name, s, x1, y1, x2, y2, eps[e], got, want);
      }
    }
  }
  assert_int_equal(bad, 0);
}

/* ---- joint_compare_bounds: verdicts from enclosures ---- */

static const double tjoint_eps[] = {0, 1e-12, 1e-9, 1e-3, 0.5, 1};

/* The k-th sample of the box lo..hi: its 16 corners, then points drawn
** per coordinate from the ends, their neighbours inside and the interior. */
static void tjoint_sample(testutil_rng *g, int k, const double lo[4], const double hi[4],
                          double x[4]) {
  for (int i = 0; i < 4; i++) {
    if (k < 16) {
      x[i] = (k >> i) & 1 ? hi[i] : lo[i];
      continue;
    }
    double u = testutil_uniform(g);
    x[i] = u < 0.25 ? lo[i] : u < 0.5 ? hi[i] : u < 0.6 ? nextafter(lo[i], hi[i])
         : u < 0.7 ? nextafter(hi[i], lo[i]) : lo[i] + testutil_uniform(g) * (hi[i] - lo[i]);
    if (x[i] < lo[i] || x[i] > hi[i]) x[i] = lo[i];
  }
}

/* A certified verdict must be joint_compare's on every sampled point of
** the box; returns 1 when the verdict was certified. */
static int tjoint_check_box(testutil_rng *g, joint_id j, int s, const double lo[4],
                            const double hi[4], double eps) {
  joint_verdict v = joint_compare_bounds(j, s, lo, hi, eps);
  if (v == JOINT_UNSURE) return 0;
  for (int k = 0; k < 48; k++) {
    double x[4];
    tjoint_sample(g, k, lo, hi, x);
    int c = joint_compare(j, s, x[0], x[1], x[2], x[3], eps);
    if ((v == JOINT_LESS) != (c < 0)) {
      print_error("joint %s s=%d eps=%g: verdict %s but joint_compare(%.17g, %.17g, %.17g, "
                  "%.17g) = %d; box [%.17g %.17g] [%.17g %.17g] [%.17g %.17g] [%.17g %.17g]\n",
                  joint_get(j)->name, s, eps, v == JOINT_LESS ? "less" : "not less", x[0], x[1],
                  x[2], x[3], c, lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], lo[3], hi[3]);
      fail();
    }
  }
  return 1;
}

/* Values of the second pair whose joint is the first pair's times
** (1 + r) (near a tie when |r| is near eps), or equal to it (r = 0,
** the pair swapped or rebuilt). */
static void tjoint_near_pair(testutil_rng *g, joint_id j, int s, double x1, double y1, double r,
                             double *x2, double *y2) {
  double A = joint_apply(j, s, x1, y1), B = A * (1 + r), f = testutil_uniform(g);
  if (j == JOINT_SUM) {
    *y2 = f * B;
    *x2 = B - *y2;
  } else if ((j == JOINT_MIN) == (s > 0)) {   /* B is the smaller one */
    *x2 = B;
    *y2 = B * (s > 0 ? 1 + f : 1 - f / 2);
  } else {
    *x2 = B;
    *y2 = B * (s > 0 ? f : 1 - f / 2 + 0.5);
  }
  if (testutil_next(g) & 1) {
    double t = *x2;
    *x2 = *y2;
    *y2 = t;
  }
}

/* Half-widths of the enclosures: none (exact values), an ulp, the LOT's
** 1e-6, relative or absolute, and wide. */
static double tjoint_width(testutil_rng *g, double v) {
  switch (testutil_next(g) % 6) {
    case 0: return 0;
    case 1: return fabs(nextafter(v, INFINITY) - v);
    case 2: return 1e-6 * fabs(v);
    case 3: return 1e-6;
    case 4: return 1e-12 * fabs(v);
    default: return 1e-3 * fabs(v);
  }
}

/* For min, max and sum, on random values, on near ties at the tolerance
** (the joint of the second pair eps (1 +- 1e-6), eps, eps (1 +- few
** ulps) away from the first's, or equal), at scales 2^-1000 .. 2^1000
** (eps max(|A|, |B|) underflows, sums overflow), with exact values and
** with enclosures of several widths: every certified verdict is
** joint_compare's at every corner and at sampled points.  Most generic
** cases are certified; the other joints are never. */
static void test_compare_bounds(void **state) {
  (void)state;
  testutil_rng g = {7};
  static const double near[] = {1, 1 + 1e-6, 1 - 1e-6, 1 + 0x1p-50, 1 - 0x1p-50, 0};
  long cases = 0, decided = 0, exact_cases = 0, exact_decided = 0;
  for (int n = 0; n < 60000; n++)
    for (int s = -1; s <= 1; s += 2)
      for (int jj = 0; jj < JOINT_COUNT; jj++) {
        joint_id j = (joint_id)jj;
        double eps = tjoint_eps[testutil_next(&g) % 6], v[4];
        double scale = ldexp(1.0, (int)(testutil_next(&g) % 2001) - 1000);
        v[0] = tjoint_value(&g, s) * scale;
        v[1] = tjoint_value(&g, s) * scale;
        int kind = (int)(testutil_next(&g) % 4);
        if (kind == 0) {
          v[2] = tjoint_value(&g, s) * scale;
          v[3] = tjoint_value(&g, s) * scale;
        } else {
          double r = near[testutil_next(&g) % 6] * (testutil_next(&g) & 1 ? eps : -eps);
          tjoint_near_pair(&g, j, s, v[0], v[1], kind == 3 ? 0 : r, &v[2], &v[3]);
        }
        double lo[4], hi[4];
        int exact = testutil_next(&g) % 3 == 0;
        for (int i = 0; i < 4; i++) {
          double w = exact ? 0 : tjoint_width(&g, v[i]);
          lo[i] = v[i] - w;
          hi[i] = v[i] + w;
        }
        int d = tjoint_check_box(&g, j, s, lo, hi, eps);
        if (!joint_has_bounds(j)) {
          assert_int_equal(d, 0);
          continue;
        }
        cases += kind == 0;
        decided += kind == 0 && d;
        exact_cases += kind == 0 && exact;
        exact_decided += kind == 0 && exact && d;
      }
  print_message("compare_bounds: %ld of %ld generic cases certified (%ld of %ld exact)\n",
                decided, cases, exact_decided, exact_cases);
  assert_true(decided > cases / 2);
  assert_true(exact_decided > 0.98 * exact_cases);
}

/* ---- the power means ------------------------------------------------------ */

static const char *const tjoint_powers[] = {"3", "-2", "0.5", "-0.5", "7"};

/* Names: the built-in p map to the built-in rows, one row per other p,
** canonical names, and refusals (-1: no joint name; -2: a p refused). */
static void test_power_names(void **state) {
  (void)state;
  char err[256];
  assert_int_equal(joint_find("1.0"), JOINT_SUM);
  assert_int_equal(joint_find("+1"), JOINT_SUM);
  assert_int_equal(joint_find("2.00"), JOINT_RSS);
  assert_int_equal(joint_find("-1e0"), JOINT_HARMONIC);
  assert_int_equal(joint_find("0.0"), JOINT_PRODUCT);
  assert_int_equal(joint_find("-0"), JOINT_PRODUCT);
  int j3 = joint_find("3");
  assert_true(j3 >= JOINT_COUNT && j3 < JOINT_CAPACITY && j3 < joint_count());
  assert_int_equal(joint_find("3.0"), j3);
  assert_int_equal(joint_find("30e-1"), j3);
  const joint *J = joint_get((joint_id)j3);
  assert_string_equal(J->name, "3");
  assert_string_equal(J->symbol, "l_3");
  assert_true(J->needs_sign && J->keyop == JOINT_KEY_ADD && J->key == JOINT_SHAPE_POWER);
  assert_true(J->vec == JOINT_VEC_NONE && J->split && !J->bounds && J->p == 3);
  assert_string_equal(joint_get((joint_id)joint_find("1e20"))->name, "1e+20");
  assert_string_equal(joint_get((joint_id)joint_find("0.10000000000000001"))->name, "0.1");
  assert_string_equal(joint_get((joint_id)joint_find("-.5"))->name, "-0.5");
  static const char *const bad[] = {"", "x", "nan", "NaN", "Infinity", "0x3", "3 ", " 3", "1e",
                                    ".", "+", "1..2", "1-2", "3x", "1,2"};
  for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
    assert_int_equal(joint_parse(bad[k], err, sizeof err), -1);
    assert_true(strstr(err, "unknown joint") != NULL && strchr(err, '\n') == NULL);
  }
  static const char *const refused[] = {"1e400", "1e-400", "0.001", "-0.0019",
                                        "0.1234567890123456"};
  for (size_t k = 0; k < sizeof refused / sizeof *refused; k++) {
    assert_int_equal(joint_parse(refused[k], err, sizeof err), -2);
    assert_non_null(strstr(err, refused[k]));
  }
  /* P_1.0 is P_1, name and all. */
  rule a, b;
  assert_int_equal(rule_parse("P_1.0", &a, err, sizeof err), 0);
  assert_int_equal(rule_parse("P_1", &b, err, sizeof err), 0);
  assert_int_equal(a.joint, JOINT_SUM);
  assert_string_equal(a.name, "P_1");
  assert_int_equal(rule_parse("P_3.000", &a, err, sizeof err), 0);
  assert_string_equal(a.name, "P_3");
  assert_int_equal(rule_parse("P_0.0001", &a, err, sizeof err), -1);
  assert_non_null(strstr(err, "P_0.0001"));
}

/* (|x|^p + |y|^p)^(1/p) in long double, and the decision as the rule
** states it (0 when the two values are within 1e-9 of each other). */
static int tjoint_brute(double p, int s, double x1, double y1, double x2, double y2) {
  long double pl = p;
  long double fa = powl(powl(fabsl((long double)x1), pl) + powl(fabsl((long double)y1), pl), 1 / pl);
  long double fb = powl(powl(fabsl((long double)x2), pl) + powl(fabsl((long double)y2), pl), 1 / pl);
  if (fabsl(fa - fb) <= 1e-9L * (fa > fb ? fa : fb)) return 0;
  int lt = fa < fb;                     /* magnitudes; values <= 0 are -f */
  return (s > 0 ? lt : !lt) ? -1 : 1;
}

/* Decisions on random convex quadrilaterals, for a measure >= 0 (P, R)
** and one <= 0 (-alpha), against the brute force away from ties; and the
** rule_eval path (the rule verbs) gives the same decisions. */
static void test_power_decisions(void **state) {
  (void)state;
  static const int ms[] = {MEASURE_P, MEASURE_R, MEASURE_NEG_ALPHA};
  testutil_rng g = {20261202};
  long checked = 0, total = 0;
  for (size_t k = 0; k < sizeof tjoint_powers / sizeof *tjoint_powers; k++) {
    joint_id j = (joint_id)joint_find(tjoint_powers[k]);
    double p = joint_get(j)->p;
    for (size_t mi = 0; mi < sizeof ms / sizeof *ms; mi++) {
      const measure *M = measure_get(ms[mi]);
      rule r;
      char err[256];
      assert_int_equal(rule_triangle(ms[mi], j, &r, err, sizeof err), 0);
      for (int n = 0; n < 4000; n++) {
        geom_point q[4];
        geom_tri t[4];
        testutil_convex_quad(&g, q);
        testutil_quad_tris(q, t);
        double v[4];
        for (int i = 0; i < 4; i++) v[i] = measure_eval(ms[mi], &t[i]);
        int want = tjoint_brute(p, M->sign, v[0], v[1], v[2], v[3]);
        int got = joint_compare(j, M->sign, v[0], v[1], v[2], v[3], 1e-12);
        rule_choice d = rule_eval_tris(&r, &t[0], &t[1], &t[2], &t[3], NULL, NULL);
        assert_int_equal(d, got < 0 ? RULE_AC : got > 0 ? RULE_BD : RULE_EITHER);
        total++;
        if (want == 0) continue;
        checked++;
        if (got != want)
          fail_msg("p = %g, measure %s: %.17g %.17g | %.17g %.17g: got %d want %d", p, M->name,
                   v[0], v[1], v[2], v[3], got, want);
      }
    }
  }
  print_message("power means: %ld of %ld decisions checked against long double\n", checked,
                total);
  assert_true(checked > 0.99 * total);
}

/* The algebra: exact commutativity, the identity, monotonicity, the
** formula to a few ulps, values where x^p itself overflows, the split
** form equal to the plain value scaled, and the keys. */
static void test_power_algebra(void **state) {
  (void)state;
  testutil_rng g = {77};
  for (size_t k = 0; k < sizeof tjoint_powers / sizeof *tjoint_powers; k++) {
    joint_id j = (joint_id)joint_find(tjoint_powers[k]);
    double p = joint_get(j)->p;
    for (int n = 0; n < 20000; n++) {
      int s = n & 1 ? 1 : -1;
      double x = tjoint_value(&g, s), y = tjoint_value(&g, s), z = tjoint_value(&g, s);
      double f = joint_apply(j, s, x, y);
      assert_true(f == joint_apply(j, s, y, x) || (isnan(f) && isnan(joint_apply(j, s, y, x))));
      assert_true(joint_apply(j, s, joint_identity(j, s), x) == x);
      if (s * x >= s * z) assert_true(s * joint_apply(j, s, x, y) >= s * joint_apply(j, s, z, y));
      if (x != 0 && y != 0) {
        double want = s * pow(pow(fabs(x), p) + pow(fabs(y), p), 1 / p);
        TESTUTIL_NEAR(f, want, 1e-13, 0);
        int e;
        double m = joint_apply_split(j, s, x, y, &e);
        assert_true(ldexp(m, e) == f);
        double kk = joint_key(j, s, x) + joint_key(j, s, y);
        TESTUTIL_NEAR(joint_key(j, s, f), kk, 1e-12, 0);
        TESTUTIL_NEAR(joint_unkey(j, s, joint_key(j, s, x)), x, 1e-14, 0);
        assert_true(joint_key(j, s, x) < joint_key(j, s, x * (s > 0 ? 1.5 : 0.5)) ||
                    (s < 0 && x == 0));
      }
    }
    /* 1e300^7 overflows, the mean does not: 1e300 * 2^(1/p) (p > 0). */
    double big = joint_apply(j, 1, 1e300, 1e300);
    assert_true(isfinite(big));
    TESTUTIL_NEAR(big, 1e300 * pow(2, 1 / p), 1e-14, 0);
    int e;
    double m = joint_apply_split(j, 1, 1e300, 1e-300, &e);
    assert_true(isfinite(m) && m > 0);
    /* ... and a comparison beyond the doubles still decides, in split form. */
    if (p > 0) assert_int_equal(joint_compare(j, 1, DBL_MAX, DBL_MAX, DBL_MAX, DBL_MAX / 2, 1e-12), 1);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
    cmocka_unit_test(test_table),
    cmocka_unit_test(test_formula_and_sign),
    cmocka_unit_test(test_commutative),
    cmocka_unit_test(test_associative),
    cmocka_unit_test(test_monotone),
    cmocka_unit_test(test_identity),
    cmocka_unit_test(test_infinite_inputs),
    cmocka_unit_test(test_keys),
    cmocka_unit_test(test_compare_plain),
    cmocka_unit_test(test_compare_bounds),
    cmocka_unit_test(test_power_names),
    cmocka_unit_test(test_power_decisions),
    cmocka_unit_test(test_power_algebra),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
