/*
** rule.c: building, naming and evaluating flip rules.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "measure.h"
#include "rule.h"

/* ---- the quadrilateral-rule registry ----------------------------------- */

/* DT: AC when D is strictly outside the circumcircle of ABC, BD when
** strictly inside, EITHER when the four points are cocircular (exactly). */
rule_choice rule_delaunay_eval(geom_point a, geom_point b, geom_point c, geom_point d) {
  int s = geom_incircle(a, b, c, d);
  return s < 0 ? RULE_AC : s > 0 ? RULE_BD : RULE_EITHER;
}

static rule_choice rule_dt(const geom_point q[4], void *ctx) {
  (void)ctx;
  return rule_delaunay_eval(q[0], q[1], q[2], q[3]);
}

/* WDT with per-site weights w (rule_eval_weighted): AC when D's lifted
** point (x^2 + y^2 - w) lies strictly above the plane through A's, B's and
** C's, BD when strictly below, EITHER on it (exactly, geom_power). */
rule_choice rule_power_eval(geom_point a, geom_point b, geom_point c, geom_point d,
                            const double w[4]) {
  int s = geom_power(a, b, c, d, w);
  return s < 0 ? RULE_AC : s > 0 ? RULE_BD : RULE_EITHER;
}

/* WDT where no weights reach it (every weight 0): the power test of equal
** weights is the incircle test, so DT's answer, exactly. */
static rule_choice rule_wdt(const geom_point q[4], void *ctx) {
  (void)ctx;
  return rule_delaunay_eval(q[0], q[1], q[2], q[3]);
}

static rule_quad rule_quads[RULE_QUAD_MAX] = {
  [RULE_DT] = {"DT", "Delaunay: the empty-circle diagonal (exact incircle test)", rule_dt, NULL},
  [RULE_WDT] = {"WDT", "weighted Delaunay (regular triangulation): the power test of "
                       "per-site weights (exact; without weights, DT)", rule_wdt, NULL},
};
#define RULE_BUILTIN_QUADS 2   /* DT, WDT: what rule_quad_unregister_user keeps */
static int rule_nquads = RULE_BUILTIN_QUADS;
static unsigned char rule_quad_systematic[RULE_QUAD_MAX] = {[RULE_DT] = 1, [RULE_WDT] = 1};

int rule_quad_register(const rule_quad *q) {
  if (rule_nquads >= RULE_QUAD_MAX || q->name == NULL || q->fn == NULL) return -1;
  for (int i = 0; i < rule_nquads; i++)
    if (strcmp(rule_quads[i].name, q->name) == 0) return -1;
  rule_quads[rule_nquads] = *q;
  rule_quad_systematic[rule_nquads] = 0;
  return rule_nquads++;
}

void rule_quad_set_systematic(int id) {
  if (id >= 0 && id < rule_nquads) rule_quad_systematic[id] = 1;
}

int rule_quad_count(void) {
  return rule_nquads;
}

const rule_quad *rule_quad_get(int id) {
  return id >= 0 && id < rule_nquads ? &rule_quads[id] : NULL;
}

void rule_quad_unregister_user(void) {
  rule_nquads = RULE_BUILTIN_QUADS;
}

/* ---- naming ------------------------------------------------------------ */

rule rule_delaunay(void) {
  rule r = {.kind = RULE_QUAD, .measure = -1, .joint = JOINT_MIN, .quad = RULE_DT,
            .tie_eps = RULE_DEFAULT_TIE_EPS};
  snprintf(r.name, sizeof r.name, "DT");
  return r;
}

int rule_triangle(int m, joint_id j, rule *out, char *err, size_t errlen) {
  const measure *M = measure_get(m);
  const joint *J = joint_get(j);
  if (M == NULL || J == NULL) {
    snprintf(err, errlen, "no such measure or joint (ids %d, %d)", m, (int)j);
    return -1;
  }
  if (J->needs_sign && M->sign == MEASURE_ANYSIGN) {
    snprintf(err, errlen,
             "rule %s_%s: measure '%s' takes both signs, so joint %s (which needs "
             "one sign) is undefined for it; use joint -inf or inf",
             M->name, J->name, M->name, J->name);
    return -1;
  }
  *out = (rule){.kind = RULE_TRIANGLE, .measure = m, .joint = j, .sign = (int)M->sign,
                .quad = -1, .tie_eps = RULE_DEFAULT_TIE_EPS};
  rule_name_join(out->name, sizeof out->name, M->name, J->name);
  return 0;
}

static void rule_valid_names(char *err, size_t errlen, const char *what) {
  char measures[2048];
  measure_names(measures, sizeof measures);
  size_t used = (size_t)snprintf(err, errlen, "%s: expected DT", what);
  for (int i = 1; i < rule_nquads && used < errlen; i++)
    used += (size_t)snprintf(err + used, errlen - used, ", %s", rule_quads[i].name);
  char joints[64];
  joint_names(joints, sizeof joints);
  if (used < errlen)
    snprintf(err + used, errlen - used,
             " or MEASURE_JOINT with MEASURE in {%s} and JOINT in {%s} or a real p "
             "(the power mean l_p)", measures, joints);
}

const char *rule_name_split(const char *name, char *measure, size_t mlen) {
  const char *us = strrchr(name, '_');
  if (us == NULL || us == name || (size_t)(us - name) >= mlen) return NULL;
  memcpy(measure, name, (size_t)(us - name));
  measure[us - name] = '\0';
  return us + 1;
}

int rule_name_join(char *buf, size_t len, const char *measure, const char *joint) {
  return snprintf(buf, len, "%s_%s", measure, joint);
}

int rule_name_is(const char *rule, const char *measure, const char *joint) {
  size_t n = strlen(measure);
  return strncmp(rule, measure, n) == 0 && rule[n] == '_' && strcmp(rule + n + 1, joint) == 0;
}

int rule_parse(const char *name, rule *out, char *err, size_t errlen) {
  char what[160];
  snprintf(what, sizeof what, "unknown rule '%.100s'", name);
  for (int i = 0; i < rule_nquads; i++)
    if (strcmp(rule_quads[i].name, name) == 0) {
      *out = (rule){.kind = RULE_QUAD, .measure = -1, .quad = i, .tie_eps = RULE_DEFAULT_TIE_EPS};
      snprintf(out->name, sizeof out->name, "%s", rule_quads[i].name);
      return 0;
    }
  if (strncmp(name, "ES:", 3) == 0) return rule_shape_make(name, out, err, errlen);
  char mname[64];
  const char *jname = strlen(name) < sizeof mname ? rule_name_split(name, mname, sizeof mname) : NULL;
  if (jname == NULL) {
    rule_valid_names(err, errlen, what);
    return -1;
  }
  char jerr[160];
  int m = measure_find(mname), j = joint_parse(jname, jerr, sizeof jerr);
  if (m >= 0 && j < -1) {   /* a p the table cannot take */
    snprintf(err, errlen, "rule '%.60s': %s", name, jerr);
    return -1;
  }
  if (m < 0 || j < 0) {
    if (m < 0) snprintf(what, sizeof what, "unknown measure '%.60s' in rule '%.60s'", mname, name);
    else snprintf(what, sizeof what, "unknown joint '%.30s' in rule '%.60s'", jname, name);
    rule_valid_names(err, errlen, what);
    return -1;
  }
  return rule_triangle(m, (joint_id)j, out, err, errlen);
}

int rule_list_triangle(const int *measures, int nmeasures, rule *out, int cap) {
  int n = 0;
  char err[256];
  for (int j = 0; j < JOINT_COUNT; j++)
    for (int i = 0; i < nmeasures; i++) {
      if (n >= cap) return n;
      if (rule_triangle(measures[i], (joint_id)j, &out[n], err, sizeof err) == 0) n++;
    }
  return n;
}

const char *rule_choice_str(rule_choice c) {
  static const char *const s[] = {"AC", "BD", "either"};
  return (unsigned)c < 3 ? s[c] : "?";
}

/* ---- evaluation -------------------------------------------------------- */

/* Ties follow the spec: relative difference within tie_eps, or equal values
** (equal infinities included).  A finite value never ties with an infinite
** one: inf - x = inf <= eps * inf would otherwise call it a tie.  NaN (a
** measure undefined on a degenerate triangle) gives EITHER, so it shows up
** as a type-V graph instead of a silent decision. */
static rule_choice rule_from_cmp(int c) {
  return c < 0 ? RULE_AC : c > 0 ? RULE_BD : RULE_EITHER;
}

rule_choice rule_compare(double ac, double bd, double tie_eps) {
  return rule_from_cmp(joint_compare_values(ac, bd, tie_eps));
}

rule_choice rule_eval_tris(const rule *r, const geom_tri *t_abc, const geom_tri *t_acd,
                           const geom_tri *t_abd, const geom_tri *t_bcd, double *ac, double *bd) {
  const measure *M = measure_get(r->measure);
  return rule_eval_badness(r, M->fn(t_abc, M->ctx), M->fn(t_acd, M->ctx), M->fn(t_abd, M->ctx),
                           M->fn(t_bcd, M->ctx), ac, bd);
}

rule_choice rule_eval_badness(const rule *r, double x1, double y1, double x2, double y2,
                              double *ac, double *bd) {
  if (ac) *ac = joint_apply(r->joint, r->sign, x1, y1);
  if (bd) *bd = joint_apply(r->joint, r->sign, x2, y2);
  /* Decided in split form: a product or root-sum-square that under- or
  ** overflows a double still decides (joint_compare). */
  return rule_decide(r, x1, y1, x2, y2);
}

/* Quadrilateral rules see the rotation of ABCD that starts at its
** lexicographically smallest vertex.  Rotating by one vertex renames the
** diagonals (AC of BCDA is BD of ABCD), so an odd rotation swaps the answer. */
static rule_choice rule_eval_quad(const rule_quad *Q, const geom_point q[4]) {
  int m = 0;
  for (int i = 1; i < 4; i++)
    if (geom_lexless(q[i], q[m])) m = i;
  geom_point c[4] = {q[m], q[(m + 1) % 4], q[(m + 2) % 4], q[(m + 3) % 4]};
  rule_choice d = Q->fn(c, Q->ctx);
  if ((m & 1) && d != RULE_EITHER) d = d == RULE_AC ? RULE_BD : RULE_AC;
  return d;
}

rule_choice rule_eval(const rule *r, const geom_point q[4], double *ac, double *bd) {
  if (r->kind == RULE_QUAD) {
    if (ac) *ac = NAN;
    if (bd) *bd = NAN;
    return rule_eval_quad(&rule_quads[r->quad], q);
  }
  geom_tri abc, acd, abd, bcd;
  geom_tri_make(&abc, q[0], q[1], q[2]);
  geom_tri_make(&acd, q[0], q[2], q[3]);
  geom_tri_make(&abd, q[0], q[1], q[3]);
  geom_tri_make(&bcd, q[1], q[2], q[3]);
  return rule_eval_tris(r, &abc, &acd, &abd, &bcd, ac, bd);
}

rule_choice rule_eval_weighted(const rule *r, const geom_point q[4], const double w[4],
                               double *ac, double *bd) {
  if (w == NULL || !rule_wants_weights(r)) return rule_eval(r, q, ac, bd);
  if (ac) *ac = NAN;
  if (bd) *bd = NAN;
  return rule_power_eval(q[0], q[1], q[2], q[3], w);   /* exact: no canonical rotation */
}

void rule_eval_quads(const rule *r, const geom_point *q, size_t m, signed char *out,
                     double *ac, double *bd) {
  for (size_t i = 0; i < m; i++) {
    const geom_point *c = q + 4 * i;
    int convex = 1;
    for (int k = 0; k < 4 && convex; k++)
      convex = geom_orient(c[k], c[(k + 1) % 4], c[(k + 2) % 4]) > 0;
    double x = NAN, y = NAN;
    out[i] = convex ? (signed char)rule_eval(r, c, &x, &y) : -1;
    if (ac) ac[i] = x;
    if (bd) bd[i] = y;
  }
}

const rule_quad *rule_quad_of(const rule *r) {
  return r->kind == RULE_QUAD ? rule_quad_get(r->quad) : NULL;
}

int rule_is_systematic(const rule *r) {
  return r->kind == RULE_QUAD && r->quad >= 0 && r->quad < rule_nquads &&
         rule_quad_systematic[r->quad];
}

const char *rule_measure_name(const rule *r) {
  return r->kind == RULE_TRIANGLE ? measure_get(r->measure)->name : "";
}

const char *rule_joint_name(const rule *r) {
  return r->kind == RULE_TRIANGLE ? joint_get(r->joint)->name : "";
}

/* ---- totals and gaps --------------------------------------------------- */

double rule_key_identity(const rule *r) {
  return joint_key_identity(r->joint);
}

double rule_total_key(const rule *r, const double *bad, size_t n) {
  joint_keyop op = joint_get(r->joint)->keyop;
  double k = joint_key_identity(r->joint);
  for (size_t t = 0; t < n; t++) k = joint_key_combine(op, k, rule_key(r, bad[t]));
  return k;
}

/* Why log space for l_0 (the joint table's log key): its key is ln|T| (sign -1: -ln|T|), so
** |T1 - T2| / max(|T1|, |T2|) = 1 - exp(-|K1 - K2|), whatever the sign,
** and a product of thousands of values that no double holds still has a
** gap.  For the other joints the totals are doubles: their difference
** over the larger magnitude, 1 when one of them is infinite. */
double rule_gap(const rule *r, double key1, double key2) {
  if (key1 == key2 || isnan(key1) || isnan(key2)) return 0;
  if (joint_get(r->joint)->key == JOINT_SHAPE_LOG) return -expm1(-fabs(key2 - key1));
  double t1 = rule_unkey(r, key1), t2 = rule_unkey(r, key2);
  double m = fmax(fabs(t1), fabs(t2)), d = fabs(t2 - t1);
  if (!isfinite(m) || !isfinite(d)) return 1;
  return m > 0 ? d / m : 0;
}

/* ---- what a rule's GOT is ---------------------------------------------- */

/* The triangle rules whose GOT of a simple polygon is its constrained
** Delaunay triangulation.  Each decides every convex quadrilateral as DT
** does (table 3.4, tests/test_delaunay_equiv.c) with a strictly monotone
** joint, so a flip that improves a quadrilateral's pair improves the
** polygon's total: a GOT is locally optimal, and the only triangulation of
** a polygon in general position that is locally optimal for DT is its CDT.
** `theorem` is the thesis's proof that the rule decides as DT does, strictly
** off the circle (appendix A: 3 for R with any joint, 16 for -r_1, 18 for
** abc_1); 0 for -r/R_1 and -r2/A_0, which table 3.4 reports as always
** Delaunay from its samples, with no proof.
** R_-inf, R_inf and -alpha_inf are DT-equivalent too, but a total that is
** a min or a max ignores all triangles but one, so their GOT need not be
** locally optimal (the CDT attains the optimum of R_inf and -alpha_inf
** without being the only optimum, tests/test_got.c). */
static const struct {
  int measure;
  joint_id joint;
  int theorem;
} rule_got_cdt[] = {
  {MEASURE_R, JOINT_SUM, 3},          {MEASURE_R, JOINT_RSS, 3},
  {MEASURE_R, JOINT_PRODUCT, 3},      {MEASURE_R, JOINT_HARMONIC, 3},
  {MEASURE_NEG_R, JOINT_SUM, 16},     {MEASURE_ABC, JOINT_SUM, 18},
  {MEASURE_NEG_R_OVER_R, JOINT_SUM, 0}, {MEASURE_NEG_R2_OVER_A, JOINT_PRODUCT, 0},
};

/* The row of rule_got_cdt for r, or -1. */
static int rule_got_cdt_row(const rule *r) {
  for (size_t k = 0; r->kind == RULE_TRIANGLE && k < sizeof rule_got_cdt / sizeof *rule_got_cdt;
       k++)
    if (r->measure == rule_got_cdt[k].measure && r->joint == rule_got_cdt[k].joint)
      return (int)k;
  return -1;
}

int rule_got_is_cdt(const rule *r) {
  return rule_got_cdt_row(r) >= 0;
}

int rule_got_cdt_theorem(const rule *r) {
  int k = rule_got_cdt_row(r);
  return k >= 0 ? rule_got_cdt[k].theorem : 0;
}
