/*
** measure.c: the measure registry and the 23 built-in measures of
** docs/measures.md (thesis table 3.2).
**
** Angles are in radians.  Every joint is positively homogeneous, so the
** unit never changes a decision; sigma's 60 degrees is pi/3 here.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "measure.h"
#include "geom_tri_internal.h"

/* The built-in measures, once: id, name, symbol, sign, description and the
** value as an expression of the triangle t.  The list generates both the
** registry's per-measure functions and measure_eval_all's straight-line
** evaluation of all of them (no indirect calls on the hot path).
**
** Notes on three entries:
** - b/(c-a) is written -(b/(a-c)): the same value for a > c, and for an
**   equilateral triangle a - c is +0, giving the spec's -inf (b/(c-a) would
**   divide by +0 and give +inf).
** - d = R - s, s the signed distance from the circumcentre to the longest
**   side (positive inside), which is R cos(gamma) with gamma the angle
**   opposite that side; cos(gamma) comes from the law of cosines (gamma >=
**   60 degrees, so no cancellation).
** - -rinf: appendix C's largest inscribed axis-parallel square has radius
**   A / (range x + range y) = 2A / Pinf. */
static int measure_registered = MEASURE_BUILTIN_COUNT;

#define MEASURE_LIST(X) \
  X(MEASURE_NEG_ALPHA, "-alpha", "-α", NEG, GEOM_F_ANGLES, "smallest angle", -t->alpha) \
  X(MEASURE_BETA, "beta", "β", POS, GEOM_F_ANGLES, "median angle", t->beta) \
  X(MEASURE_GAMMA, "gamma", "γ", POS, GEOM_F_ANGLES, "largest angle", t->gamma) \
  X(MEASURE_A, "a", "a", POS, GEOM_F_SIDES, "length of the longest side", t->a) \
  X(MEASURE_NEG_C, "-c", "-c", NEG, GEOM_F_SIDES, "length of the shortest side", -t->c) \
  X(MEASURE_P, "P", "P", POS, GEOM_F_PERIM, "perimeter a+b+c", t->P) \
  X(MEASURE_ABC, "abc", "abc", POS, GEOM_F_SIDES, "product of the sides", t->a * t->b * t->c) \
  X(MEASURE_NEG_AREA, "-A", "-A", NEG, GEOM_F_AREA, "area", -t->area) \
  X(MEASURE_R, "R", "R", POS, GEOM_F_CIRCUM, "circumradius abc/(4A)", t->R) \
  X(MEASURE_NEG_R, "-r", "-r", NEG, GEOM_F_INRADIUS, "inradius 2A/P", -t->r) \
  X(MEASURE_NEG_H, "-a'", "-a'", NEG, GEOM_F_HEIGHT, "shortest altitude a' = 2A/a", -t->h) \
  X(MEASURE_NEG_R_OVER_R, "-r/R", "-r/R", NEG, GEOM_F_CIRCUM | GEOM_F_INRADIUS, \
    "inradius over circumradius", -(t->r / t->R)) \
  X(MEASURE_NEG_R2_OVER_A, "-r2/A", "-r²/A", NEG, GEOM_F_AREA | GEOM_F_PERIM, \
    "incircle area over area, up to pi: 4A/P^2", -4.0 * t->area / (t->P * t->P)) \
  X(MEASURE_NEG_C_OVER_A, "-c/a", "-c/a", NEG, GEOM_F_SIDES, "shortest over longest side", \
    -(t->c / t->a)) \
  X(MEASURE_NEG_C_OVER_P, "-c/P", "-c/P", NEG, GEOM_F_SIDES | GEOM_F_PERIM, \
    "share of the perimeter in the shortest side", -(t->c / t->P)) \
  X(MEASURE_A_MINUS_C, "a-c", "a-c", POS, GEOM_F_SIDES, "longest minus shortest side", \
    t->a - t->c) \
  X(MEASURE_B_OVER_C_MINUS_A, "b/(c-a)", "b/(c-a)", NEG, GEOM_F_SIDES, \
    "median side over (c-a); -inf for equilateral", -(t->b / (t->a - t->c))) \
  X(MEASURE_LAMBDA, "lambda", "λ", POS, GEOM_F_SIDES | GEOM_F_AREA, \
    "aspect ratio a/a' = a^2/(2A)", t->a * t->a / (2.0 * t->area)) \
  X(MEASURE_D, "d", "d", POS, GEOM_F_SIDES | GEOM_F_CIRCUM, \
    "eccentricity R(1 - cos gamma) (project's reading of the OCR)", \
    t->R * (1.0 - (t->b * t->b + t->c * t->c - t->a * t->a) / (2.0 * t->b * t->c))) \
  X(MEASURE_SIGMA, "sigma", "σ", POS, GEOM_F_ANGLES, "standard deviation of the angles", \
    sqrt(((t->alpha - M_PI / 3) * (t->alpha - M_PI / 3) + (t->beta - M_PI / 3) * (t->beta - M_PI / 3) \
          + (t->gamma - M_PI / 3) * (t->gamma - M_PI / 3)) / 3.0)) \
  X(MEASURE_PINF, "Pinf", "P∞", POS, GEOM_F_RANGES, "l_inf perimeter 2(rx+ry)", \
    2.0 * (t->rx + t->ry)) \
  X(MEASURE_RINF, "Rinf", "R∞", POS, GEOM_F_RANGES, \
    "smallest enclosing axis-parallel square: max(rx,ry)/2", 0.5 * (t->rx > t->ry ? t->rx : t->ry)) \
  X(MEASURE_NEG_RINF, "-rinf", "-r∞", NEG, GEOM_F_AREA | GEOM_F_RANGES, \
    "largest inscribed axis-parallel square: A/(rx+ry)", -t->area / (t->rx + t->ry))

#define MEASURE_FN(id, name, sym, sign, fields, desc, expr) \
  static double measure_fn_##id(const geom_tri *t, void *ctx) { (void)ctx; return expr; }
MEASURE_LIST(MEASURE_FN)
#undef MEASURE_FN

/* The same expressions on a triangle made here, inline, with only the
** fields they read: geom_tri_fill_values with a constant mask, which the
** compiler specialises (the fields not read are never computed nor stored,
** and the sides-only measures skip the canonical sort, which cannot change
** them).  The same operations, so the same bits as measure_fn on
** geom_tri_make_fields for points without NaN (tests/test_measures.c checks
** it on stress triangles), without the calls. */
#define MEASURE_PTS(id, name, sym, sign, fields, desc, expr) \
  static double measure_pts_##id(geom_point p, geom_point q, geom_point r) { \
    geom_tri tri; \
    geom_tri_fill_values(&tri, p, q, r, fields); \
    const geom_tri *t = &tri; \
    return expr; \
  }
MEASURE_LIST(MEASURE_PTS)
#undef MEASURE_PTS

/* The same evaluation over a whole array, the loop inside each measure's
** own function so that the compiler inlines the expression into it (a call
** through measure_points per triangle costs as much as R itself).  Threads
** write disjoint slots and each value depends only on its own triangle, so
** the output is the same for any thread count. */
typedef void (*measure_batch_fn)(const geom_point *v, long long m, double *out);
#define MEASURE_BATCH(id, name, sym, sign, fields, desc, expr) \
  static void measure_batch_##id(const geom_point *v, long long m, double *out) { \
    _Pragma("omp parallel for schedule(static) if (m > 20000)") \
    for (long long i = 0; i < m; i++) out[i] = measure_pts_##id(v[3 * i], v[3 * i + 1], v[3 * i + 2]); \
  }
MEASURE_LIST(MEASURE_BATCH)
#undef MEASURE_BATCH

#define NEG MEASURE_NONPOS
#define POS MEASURE_NONNEG
#define MEASURE_ENTRY(id, name, sym, sign, fields, desc, expr) [id] = {name, sym, desc, sign, measure_fn_##id, NULL},
static measure measure_registry[MEASURE_MAX] = {MEASURE_LIST(MEASURE_ENTRY)};
#undef MEASURE_ENTRY
#undef NEG
#undef POS

void measure_eval_all(const geom_tri *t, double *out) {
#define MEASURE_VALUE(id, name, sym, sign, fields, desc, expr) out[id] = (expr);
  MEASURE_LIST(MEASURE_VALUE)
#undef MEASURE_VALUE
  for (int i = MEASURE_BUILTIN_COUNT; i < measure_registered; i++)
    out[i] = measure_registry[i].fn(t, measure_registry[i].ctx);
}

const int measure_table34[MEASURE_TABLE34_COUNT] = {
  MEASURE_R, MEASURE_NEG_ALPHA, MEASURE_GAMMA, MEASURE_NEG_H, MEASURE_NEG_AREA,
  MEASURE_NEG_R, MEASURE_P, MEASURE_A, MEASURE_NEG_C, MEASURE_NEG_R_OVER_R,
  MEASURE_NEG_R2_OVER_A, MEASURE_LAMBDA, MEASURE_NEG_C_OVER_A, MEASURE_ABC,
  MEASURE_NEG_C_OVER_P, MEASURE_A_MINUS_C, MEASURE_B_OVER_C_MINUS_A,
  MEASURE_RINF, MEASURE_PINF, MEASURE_NEG_RINF,
};

int measure_count(void) {
  return measure_registered;
}

const measure *measure_get(int id) {
  return id >= 0 && id < measure_registered ? &measure_registry[id] : NULL;
}

int measure_find(const char *name) {
  for (int i = 0; i < measure_registered; i++)
    if (strcmp(measure_registry[i].name, name) == 0) return i;
  return -1;
}

/* Registration happens while a command starts, before any thread runs, so
** the registry needs no lock. */
int measure_register(const measure *m) {
  if (measure_registered >= MEASURE_MAX || m->name == NULL || m->fn == NULL) return -1;
  if (measure_find(m->name) >= 0) return -1;
  measure_registry[measure_registered] = *m;
  return measure_registered++;
}

void measure_unregister_user(void) {
  measure_registered = MEASURE_BUILTIN_COUNT;
}

void measure_names(char *buf, size_t len) {
  size_t used = 0;
  if (len == 0) return;
  buf[0] = '\0';
  for (int i = 0; i < measure_registered && used < len; i++) {
    int n = snprintf(buf + used, len - used, "%s%s", i ? "," : "", measure_registry[i].name);
    if (n < 0) break;
    used += (size_t)n;
  }
}

/* ---- enclosures without atan2 (measure.h) ------------------------------ */

/* sigma(x) = |x - (t, t, t)| / sqrt 3 (Euclidean norm) over the three
** angles x, t = M_PI / 3 (the double measure_eval subtracts).  With each
** angle c_i in [lo_i, hi_i] and h >= every hi_i - lo_i, the triangle
** inequality gives |sigma(c) - sigma(lo)| <= |c - lo| / sqrt 3 <= h.  The
** value measure_eval computes is within 2 eps (relative) of sigma(c), the
** one computed here within 2 eps of sigma(lo) (a rounded difference,
** square, sum of positive terms, division and square root), and h is
** fl(hi - lo) made larger by 2^-40: the factors 1 -+ 2^-40 cover those
** errors and the roundings of the last lines.  One square root, the
** enclosure 2h, about 4e-6, wide. */
static void measure_sigma_bounds(const double lo[3], const double hi[3], double *slo,
                                 double *shi) {
  const double third = M_PI / 3;
  double s = 0, h = 0;
  for (int i = 0; i < 3; i++) {
    double d = lo[i] - third, w = hi[i] - lo[i];
    s += d * d;
    h = w > h ? w : h;
  }
  double sl = sqrt(s / 3.0);
  h *= 1 + 0x1p-40;
  double l = (sl * (1 - 0x1p-40) - h) * (1 - 0x1p-40);
  *slo = l > 0 ? l : 0;
  *shi = (sl * (1 + 0x1p-40) + h) * (1 + 0x1p-40);
}

/* The angle measures are alpha, beta, gamma themselves (negated for
** -alpha) or sigma of the three angles. */
int measure_bounds(int id, geom_point p, geom_point q, geom_point r, double *lo, double *hi) {
  double a[3], b[3], l, h;
  switch (id) {
    case MEASURE_NEG_ALPHA:
      if (!geom_angle_rank_bounds(p, q, r, 0, &l, &h)) return 0;
      *lo = -h;
      *hi = -l;
      return 1;
    case MEASURE_BETA:
      if (!geom_angle_rank_bounds(p, q, r, 1, &l, &h)) return 0;
      *lo = l > 0 ? l : 0;
      *hi = h;
      return 1;
    case MEASURE_GAMMA:
      return geom_angle_rank_bounds(p, q, r, 2, lo, hi);
    case MEASURE_SIGMA:
      if (!geom_angle_bounds(p, q, r, a, b)) return 0;
      measure_sigma_bounds(a, b, lo, hi);
      return 1;
    default:
      return 0;
  }
}

/* The angles geom_tri_fill computes are within 2^-35 of the exact ones
** (geom.c), and exact alpha <= pi/3 <= gamma: 1e-6 less covers the
** difference. */
/* Floors other than the sign's.  Each is a true bound of the exact
** quantity, moved out by far more than the rounding of the computed value
** can add: the angles by 1e-6 (their enclosures' slack, geom.c), the
** scale-free ratios by 1e-9 relative (the twice area is within 2^-40, the
** sides and the rest within a few eps).
**   -alpha >= -pi/3, gamma >= pi/3 (the angles sum to pi);
**   -r/R >= -1/2 (Euler: R >= 2r);
**   -c/a >= -1 exactly (c <= a, and c/a <= 1 rounds to at most 1);
**   -c/P >= -1/3 (P >= 3c);
**   -r2/A = -4A/P^2 >= -sqrt(3)/9 (of all triangles of a given perimeter
**   the equilateral one has the largest area). */
static const struct { int id; double floor; } measure_floors[] = {
  {MEASURE_NEG_ALPHA, -(M_PI / 3 + 1e-6)},
  {MEASURE_GAMMA, M_PI / 3 - 1e-6},
  {MEASURE_NEG_R_OVER_R, -0.5 * (1 + 1e-9)},
  {MEASURE_NEG_C_OVER_A, -1.0},
  {MEASURE_NEG_C_OVER_P, -(1 + 1e-9) / 3},
  {MEASURE_NEG_R2_OVER_A, -0.19245008972987526 * (1 + 1e-9)},   /* sqrt(3)/9 */
};

double measure_floor(int id) {
  for (size_t k = 0; k < sizeof measure_floors / sizeof measure_floors[0]; k++)
    if (measure_floors[k].id == id) return measure_floors[k].floor;
  return measure_get(id)->sign >= 0 ? 0 : -INFINITY;
}

int measure_has_bounds(int id) {
  return id == MEASURE_NEG_ALPHA || id == MEASURE_BETA || id == MEASURE_GAMMA ||
         id == MEASURE_SIGMA;
}

/* The geom_tri fields each built-in measure's expression reads, and its
** inline evaluation from three points. */
#define MEASURE_FIELDS(id, name, sym, sign, fields, desc, expr) [id] = fields,
static const unsigned measure_builtin_fields[MEASURE_BUILTIN_COUNT] = {
  MEASURE_LIST(MEASURE_FIELDS)
};
#undef MEASURE_FIELDS

#define MEASURE_PTS_ENTRY(id, name, sym, sign, fields, desc, expr) [id] = measure_pts_##id,
static const measure_points_fn measure_builtin_points[MEASURE_BUILTIN_COUNT] = {
  MEASURE_LIST(MEASURE_PTS_ENTRY)
};
#undef MEASURE_PTS_ENTRY

#define MEASURE_BATCH_ENTRY(id, name, sym, sign, fields, desc, expr) [id] = measure_batch_##id,
static const measure_batch_fn measure_builtin_batch[MEASURE_BUILTIN_COUNT] = {
  MEASURE_LIST(MEASURE_BATCH_ENTRY)
};
#undef MEASURE_BATCH_ENTRY

measure_points_fn measure_points(int id) {
  return id >= 0 && id < MEASURE_BUILTIN_COUNT ? measure_builtin_points[id] : NULL;
}

void measure_eval_tris(int id, const geom_point *v, size_t m, double *out) {
  long long mm = (long long)m;
  if (id >= 0 && id < MEASURE_BUILTIN_COUNT) {
    measure_builtin_batch[id](v, mm, out);
    return;
  }
  const measure *u = measure_get(id);
#pragma omp parallel for schedule(static) if (mm > 20000)
  for (long long i = 0; i < mm; i++) {
    geom_tri t;
    geom_tri_make(&t, v[3 * i], v[3 * i + 1], v[3 * i + 2]);
    out[i] = u->fn(&t, u->ctx);
  }
}

unsigned measure_fields(int id) {
  return id >= 0 && id < MEASURE_BUILTIN_COUNT ? measure_builtin_fields[id] : GEOM_F_ALL;
}

/* ---- user names -------------------------------------------------------- */

static int measure_name_char(int c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
         (c != '\0' && strchr("'/-.()+*^", c) != NULL);
}

/* A printable bad character is quoted with the name; any other byte (a
** newline, a tab) is named by its code and the name cut before it, so the
** message stays one line. */
int measure_check_name(const char *what, const char *name, char *err, size_t errlen) {
  size_t n = strlen(name);
  int letter = 0;
  if (n == 0) {
    snprintf(err, errlen, "the %s name is empty", what);
    return -1;
  }
  for (size_t i = 0; i < n; i++) {
    unsigned char c = (unsigned char)name[i];
    if (c < 0x20 || c >= 0x7f) {
      snprintf(err, errlen, "%s name '%.*s...' has the byte 0x%02x; use letters, digits and "
               "' / - . ( ) + * ^", what, (int)(i < 20 ? i : 20), name, c);
      return -1;
    }
  }
  if (n >= MEASURE_NAME_MAX) {
    snprintf(err, errlen, "%s name '%.20s...' is %zu characters long; at most %d", what, name,
             n, MEASURE_NAME_MAX - 1);
    return -1;
  }
  for (size_t i = 0; i < n; i++) {
    unsigned char c = (unsigned char)name[i];
    if (!measure_name_char(c)) {
      snprintf(err, errlen,
               "%s name '%s' has the character '%c'; use letters, digits and ' / - . ( ) + * ^ "
               "('_' separates measure and joint in rule names)", what, name, c);
      return -1;
    }
    letter |= (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
  }
  if (!letter) {
    snprintf(err, errlen, "%s name '%s' needs at least one letter", what, name);
    return -1;
  }
  return 0;
}
