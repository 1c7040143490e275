/*
** measure.c: the measure registry and the 23 built-in measures of
** ../shared/spec/measures.md (thesis table 3.2).
**
** Angles are in radians.  Every joint is positively homogeneous, so the
** unit never changes a decision; sigma's 60 degrees is pi/3 here.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "badness/measure.h"

static double measure_neg_alpha(const geom_tri *t, void *ctx) { (void)ctx; return -t->alpha; }
static double measure_beta(const geom_tri *t, void *ctx) { (void)ctx; return t->beta; }
static double measure_gamma(const geom_tri *t, void *ctx) { (void)ctx; return t->gamma; }
static double measure_a(const geom_tri *t, void *ctx) { (void)ctx; return t->a; }
static double measure_neg_c(const geom_tri *t, void *ctx) { (void)ctx; return -t->c; }
static double measure_p(const geom_tri *t, void *ctx) { (void)ctx; return t->P; }
static double measure_abc(const geom_tri *t, void *ctx) { (void)ctx; return t->a * t->b * t->c; }
static double measure_neg_area(const geom_tri *t, void *ctx) { (void)ctx; return -t->area; }
static double measure_circumradius(const geom_tri *t, void *ctx) { (void)ctx; return t->R; }
static double measure_neg_inradius(const geom_tri *t, void *ctx) { (void)ctx; return -t->r; }
static double measure_neg_h(const geom_tri *t, void *ctx) { (void)ctx; return -t->h; }
static double measure_neg_r_over_R(const geom_tri *t, void *ctx) { (void)ctx; return -(t->r / t->R); }
static double measure_neg_r2_over_A(const geom_tri *t, void *ctx) {
  (void)ctx;
  return -4.0 * t->area / (t->P * t->P);
}
static double measure_neg_c_over_a(const geom_tri *t, void *ctx) { (void)ctx; return -(t->c / t->a); }
static double measure_neg_c_over_P(const geom_tri *t, void *ctx) { (void)ctx; return -(t->c / t->P); }
static double measure_a_minus_c(const geom_tri *t, void *ctx) { (void)ctx; return t->a - t->c; }

/* b/(c-a) written as -(b/(a-c)): the same value for a > c, and for an
** equilateral triangle a - c is +0, giving the spec's -inf (b/(c-a) would
** divide by +0 and give +inf). */
static double measure_b_over_c_minus_a(const geom_tri *t, void *ctx) {
  (void)ctx;
  return -(t->b / (t->a - t->c));
}

static double measure_lambda(const geom_tri *t, void *ctx) {
  (void)ctx;
  return t->a * t->a / (2.0 * t->area);
}

/* Eccentricity d = R - s, s the signed distance from the circumcentre to the
** longest side (positive inside).  That distance is R cos(gamma), gamma being
** the angle opposite the longest side, so d = R (1 - cos gamma); cos gamma
** comes from the law of cosines (gamma >= 60 deg, so no cancellation). */
static double measure_d(const geom_tri *t, void *ctx) {
  (void)ctx;
  double cosg = (t->b * t->b + t->c * t->c - t->a * t->a) / (2.0 * t->b * t->c);
  return t->R * (1.0 - cosg);
}

static double measure_sigma(const geom_tri *t, void *ctx) {
  (void)ctx;
  const double third = M_PI / 3.0;
  double da = t->alpha - third, db = t->beta - third, dg = t->gamma - third;
  return sqrt((da * da + db * db + dg * dg) / 3.0);
}

static double measure_pinf(const geom_tri *t, void *ctx) { (void)ctx; return 2.0 * (t->rx + t->ry); }
static double measure_rinf(const geom_tri *t, void *ctx) { (void)ctx; return 0.5 * fmax(t->rx, t->ry); }

/* Appendix C: the largest inscribed axis-parallel square has radius
** A / (range x + range y) = 2A / Pinf. */
static double measure_neg_rinf(const geom_tri *t, void *ctx) {
  (void)ctx;
  return -t->area / (t->rx + t->ry);
}

#define NEG MEASURE_NONPOS
#define POS MEASURE_NONNEG
static measure measure_registry[MEASURE_MAX] = {
  [MEASURE_NEG_ALPHA] = {"-alpha", "-α", "smallest angle", NEG, measure_neg_alpha, NULL},
  [MEASURE_BETA] = {"beta", "β", "median angle", POS, measure_beta, NULL},
  [MEASURE_GAMMA] = {"gamma", "γ", "largest angle", POS, measure_gamma, NULL},
  [MEASURE_A] = {"a", "a", "length of the longest side", POS, measure_a, NULL},
  [MEASURE_NEG_C] = {"-c", "-c", "length of the shortest side", NEG, measure_neg_c, NULL},
  [MEASURE_P] = {"P", "P", "perimeter a+b+c", POS, measure_p, NULL},
  [MEASURE_ABC] = {"abc", "abc", "product of the sides", POS, measure_abc, NULL},
  [MEASURE_NEG_AREA] = {"-A", "-A", "area", NEG, measure_neg_area, NULL},
  [MEASURE_R] = {"R", "R", "circumradius abc/(4A)", POS, measure_circumradius, NULL},
  [MEASURE_NEG_R] = {"-r", "-r", "inradius 2A/P", NEG, measure_neg_inradius, NULL},
  [MEASURE_NEG_H] = {"-a'", "-a'", "shortest altitude 2A/a", NEG, measure_neg_h, NULL},
  [MEASURE_NEG_R_OVER_R] = {"-r/R", "-r/R", "inradius over circumradius", NEG, measure_neg_r_over_R, NULL},
  [MEASURE_NEG_R2_OVER_A] = {"-r2/A", "-r²/A", "incircle area over area (up to pi): 4A/P^2", NEG, measure_neg_r2_over_A, NULL},
  [MEASURE_NEG_C_OVER_A] = {"-c/a", "-c/a", "shortest over longest side", NEG, measure_neg_c_over_a, NULL},
  [MEASURE_NEG_C_OVER_P] = {"-c/P", "-c/P", "share of the perimeter in the shortest side", NEG, measure_neg_c_over_P, NULL},
  [MEASURE_A_MINUS_C] = {"a-c", "a-c", "longest minus shortest side", POS, measure_a_minus_c, NULL},
  [MEASURE_B_OVER_C_MINUS_A] = {"b/(c-a)", "b/(c-a)", "median side over (c-a); -inf for equilateral", NEG, measure_b_over_c_minus_a, NULL},
  [MEASURE_LAMBDA] = {"lambda", "λ", "aspect ratio a/a' = a^2/(2A)", POS, measure_lambda, NULL},
  [MEASURE_D] = {"d", "d", "eccentricity R(1 - cos gamma) (project's reading of the OCR)", POS, measure_d, NULL},
  [MEASURE_SIGMA] = {"sigma", "σ", "standard deviation of the angles", POS, measure_sigma, NULL},
  [MEASURE_PINF] = {"Pinf", "P∞", "l_inf perimeter 2(rx+ry)", POS, measure_pinf, NULL},
  [MEASURE_RINF] = {"Rinf", "R∞", "smallest enclosing axis-parallel square: max(rx,ry)/2", POS, measure_rinf, NULL},
  [MEASURE_NEG_RINF] = {"-rinf", "-r∞", "largest inscribed axis-parallel square: A/(rx+ry)", NEG, measure_neg_rinf, NULL},
};
#undef NEG
#undef POS

static int measure_registered = MEASURE_BUILTIN_COUNT;

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
