/*
** rule.h: flip rules.
**
** A flip rule picks a diagonal of a convex quadrilateral ABCD (anticlockwise):
** RULE_AC, RULE_BD or RULE_EITHER.  A rule is either triangle-based, b_f
** (a registry measure b and a joint f, compared with the tie tolerance of
** docs/rules.md), or a whole-quadrilateral rule: the
** exact Delaunay rule DT, or one registered at run time (plugins).
**
** Independence of the first vertex, bit for bit: triangle quantities are
** computed from canonically ordered vertices (geom_tri_make) and every joint
** is exactly commutative in floating point, so b_f sees the same four
** numbers for ABCD and BCDA; DT is exact; quadrilateral rules are called on
** the rotation of ABCD that starts at its lexicographically smallest vertex.
*/
#ifndef FLIPLAB_RULE_H
#define FLIPLAB_RULE_H

#include <stddef.h>
#include "geom.h"
#include "joint.h"

typedef enum rule_choice { RULE_AC = 0, RULE_BD = 1, RULE_EITHER = 2 } rule_choice;

typedef enum rule_kind { RULE_TRIANGLE, RULE_QUAD } rule_kind;

/* A whole-quadrilateral rule; q is anticlockwise and strictly convex. */
typedef rule_choice (*rule_quad_fn)(const geom_point q[4], void *ctx);

typedef struct rule_quad {
  const char *name;     /* e.g. "DT" */
  const char *desc;
  rule_quad_fn fn;
  void *ctx;
} rule_quad;

/* A rule is read through the verbs below (rule_is_triangle, rule_measure,
** rule_decide, rule_total_key, rule_gap...), never field by field: what a
** rule means lives here.  The tie tolerance is part of the rule. */
/* A rule's name has at most RULE_NAME_MAX - 1 bytes: room for an
** empty-shape rule's polygon of two dozen vertices written at full
** precision ("ES:poly:0.80901699437494745 0.58778525229247314;..."). */
#define RULE_NAME_MAX 1024

typedef struct rule {
  rule_kind kind;
  int measure;          /* RULE_TRIANGLE: registry id */
  joint_id joint;       /* RULE_TRIANGLE */
  int sign;             /* RULE_TRIANGLE: the measure's sign (measure.h), kept for the hot paths */
  int quad;             /* RULE_QUAD: quadrilateral-rule registry id */
  double tie_eps;       /* relative tie tolerance (docs/rules.md) */
  char name[RULE_NAME_MAX];   /* canonical name, e.g. "-alpha_inf", "DT" */
} rule;

#define RULE_DEFAULT_TIE_EPS 1e-12
#define RULE_QUAD_MAX 32
#define RULE_DT 0       /* quadrilateral-rule registry id of DT */
#define RULE_WDT 1      /* ... and of WDT, the weighted Delaunay rule */

/* Build rules.  rule_parse accepts "DT", a registered quadrilateral rule's
** name, or MEASURE_JOINT ("R_inf", "-c_-inf", "-r2/A_0").  On failure it
** returns -1 and writes a one-line message (naming the valid choices) to err. */
int rule_parse(const char *name, rule *out, char *err, size_t errlen);
/* An empty-shape rule "ES:SPEC" (SPEC a shape spec of shapes/shape.h,
** docs/emptyshape.md), registered as a quadrilateral rule on first use;
** rule_parse calls it for every name starting "ES:" not yet registered. */
int rule_shape_make(const char *name, rule *out, char *err, size_t errlen);
/* 1 when r is an empty-shape rule (made by rule_shape_make). */
int rule_is_shape(const rule *r);
/* The shape of an empty-shape rule, parsed once when the rule is made and
** owned by it (it lives as long as the process: never free it), or NULL
** for every other rule: the one way to a rule's shape. */
const struct shape *rule_shape(const rule *r);

/* The one grammar of rule names: a triangle-based rule is MEASURE_JOINT,
** split at the last '_' (measure names may contain '-', '/' and '\'', a
** joint name never contains '_').  rule_name_split copies the measure part
** into measure[mlen] and returns the joint part (a pointer into name), or
** NULL when name has no '_' after its first character or the measure part
** does not fit.  rule_name_join writes "MEASURE_JOINT" into buf[len] and
** returns what snprintf does; rule_name_is tells whether rule is that name. */
const char *rule_name_split(const char *name, char *measure, size_t mlen);
int rule_name_join(char *buf, size_t len, const char *measure, const char *joint);
int rule_name_is(const char *rule, const char *measure, const char *joint);
int rule_triangle(int measure, joint_id j, rule *out, char *err, size_t errlen);
rule rule_delaunay(void);

/* Quadrilateral-rule registry (DT is id RULE_DT). */
int rule_quad_register(const rule_quad *q);   /* new id, or -1 */
/* Mark quadrilateral rule id as systematic and acyclic as DT is (the
** empty-shape rules, docs/emptyshape.md): the same diagonal whatever
** rotation of the quadrilateral it is given, a unique LOT that incremental
** insertion reaches by flipping the new point's link only, and no flip
** cycle; lot/ then takes DT's path (rule_is_systematic).  Unmarked rules
** (plugins): lot re-examines every changed edge and watches for cycles. */
void rule_quad_set_systematic(int id);
int rule_quad_count(void);
const rule_quad *rule_quad_get(int id);
void rule_quad_unregister_user(void);

/* Compare two joint values with the spec's tie tolerance:
** RULE_EITHER when |ac - bd| <= eps * max(|ac|, |bd|) or ac == bd
** (equal infinities included); a finite and an infinite value never tie. */
rule_choice rule_compare(double ac, double bd, double tie_eps);

/* Decide a convex anticlockwise quadrilateral with the rule's tie
** tolerance.  For triangle-based rules *ac and *bd (may be NULL) receive
** f(b(ABC), b(ACD)) and f(b(ABD), b(BCD)). */
rule_choice rule_eval(const rule *r, const geom_point q[4], double *ac, double *bd);

/* The same from the four triangles already made (the hot path of classify):
** t_abc, t_acd for diagonal AC, t_abd, t_bcd for BD. */
rule_choice rule_eval_tris(const rule *r, const geom_tri *t_abc, const geom_tri *t_acd,
                           const geom_tri *t_abd, const geom_tri *t_bcd, double *ac, double *bd);

/* The same from the four triangles' badness values (a triangulation that
** keeps each triangle's measure, as lot/ does): the decision of
** rule_eval_tris bit for bit, since a triangle's measure depends only on the
** triangle (geom_tri_make's canonical order). */
rule_choice rule_eval_badness(const rule *r, double b_abc, double b_acd, double b_abd,
                              double b_bcd, double *ac, double *bd);

/* rule_eval on m quadrilaterals q[4i .. 4i+3] at once (python/'s vectorised
** decisions): out[i] is RULE_AC (diagonal q[4i] q[4i+2]), RULE_BD or
** RULE_EITHER, or -1 when the quadrilateral is not strictly convex and
** anticlockwise (exact orientations), which no rule decides; ac and bd (may
** be NULL) receive rule_eval's joint values (NaN when undecided or for a
** quadrilateral rule). */
void rule_eval_quads(const rule *r, const geom_point *q, size_t m, signed char *out,
                     double *ac, double *bd);

/* Per-site weights reaching a rule.  WDT, the weighted Delaunay rule of a
** regular triangulation (docs/rules.md), reads a weight per site: w[i] is
** q[i]'s, and the rule keeps the diagonal of the lower convex hull of the
** sites lifted to (x, y, x^2 + y^2 - w) (rule_power_eval, exact).  Every
** other rule ignores weights; WDT without them (w == NULL, or an engine
** that has none: classify's pentagons, the census) reads every weight as
** 0, where it is DT exactly.  rule_wants_weights: 1 for WDT. */
rule_choice rule_eval_weighted(const rule *r, const geom_point q[4], const double w[4],
                               double *ac, double *bd);
rule_choice rule_power_eval(geom_point a, geom_point b, geom_point c, geom_point d,
                            const double w[4]);

/* DT on ABCD directly: exact, so no canonical rotation is needed. */
rule_choice rule_delaunay_eval(geom_point a, geom_point b, geom_point c, geom_point d);

const char *rule_choice_str(rule_choice c);   /* "AC", "BD", "either" */

/* Every triangle-based rule name "m_j" for the given measures, in table order
** (joint-major, as table 3.4), appended to out; returns how many. */
int rule_list_triangle(const int *measures, int nmeasures, rule *out, int cap);

/* ---- what a rule is ----------------------------------------------------
** Inline: lot/ and the census ask these on their hot paths. */
static inline int rule_is_triangle(const rule *r) { return r->kind == RULE_TRIANGLE; }
static inline int rule_is_delaunay(const rule *r) {
  return r->kind == RULE_QUAD && r->quad == RULE_DT;
}
static inline int rule_wants_weights(const rule *r) {
  return r->kind == RULE_QUAD && r->quad == RULE_WDT;
}
/* DT, or a quadrilateral rule registered as systematic (rule_quad). */
int rule_is_systematic(const rule *r);
/* The measure's registry id (-1 for a quadrilateral rule), its sign, the joint. */
static inline int rule_measure(const rule *r) { return r->kind == RULE_TRIANGLE ? r->measure : -1; }
static inline int rule_sign(const rule *r) { return r->sign; }
static inline joint_id rule_joint(const rule *r) { return r->joint; }
/* The quadrilateral rule (NULL for a triangle-based rule). */
const rule_quad *rule_quad_of(const rule *r);
static inline const char *rule_name(const rule *r) { return r->name; }
/* The two parts of a triangle-based rule's name ("" for a quadrilateral
** rule), as report rows and CSV columns give them. */
const char *rule_measure_name(const rule *r);
const char *rule_joint_name(const rule *r);
static inline double rule_tie_eps(const rule *r) { return r->tie_eps; }
static inline void rule_set_tie_eps(rule *r, double tie_eps) { r->tie_eps = tie_eps; }

/* ---- deciding from badness values ---------------------------------------
** rule_decide: a triangle-based rule's decision between the pair (x1, y1)
** of the triangles on diagonal AC and (x2, y2) on BD, decided in split
** form with the rule's tolerance (joint_compare); rule_eval_badness bit
** for bit.  rule_decide_bounds: the same certified from enclosures
** lo[k] <= value k <= hi[k], in the order x1, y1, x2, y2 (JOINT_LESS:
** certainly AC; joint_compare_bounds). */
static inline rule_choice rule_decide(const rule *r, double x1, double y1, double x2, double y2) {
  int c = joint_compare(r->joint, r->sign, x1, y1, x2, y2, r->tie_eps);
  return c < 0 ? RULE_AC : c > 0 ? RULE_BD : RULE_EITHER;
}
static inline joint_verdict rule_decide_bounds(const rule *r, const double lo[4],
                                               const double hi[4]) {
  return joint_compare_bounds(r->joint, r->sign, lo, hi, r->tie_eps);
}

/* ---- totals of a triangulation ------------------------------------------
** A triangulation's total is its badness values combined by the rule's
** joint.  Totals are carried as keys (joint.h: phi(f(x, y)) = phi(x) (+)
** phi(y)), which neither overflow nor pay a root per value: rule_key of one
** value, rule_key_add of two keys, rule_total_key of n values (from the
** identity, in the order given), rule_unkey back to badness units. */
static inline double rule_key(const rule *r, double b) { return joint_key(r->joint, r->sign, b); }
static inline double rule_unkey(const rule *r, double k) {
  return joint_unkey(r->joint, r->sign, k);
}
static inline double rule_key_add(const rule *r, double k1, double k2) {
  return joint_key_combine(joint_get(r->joint)->keyop, k1, k2);
}
double rule_key_identity(const rule *r);
double rule_total_key(const rule *r, const double *bad, size_t n);

/* The relative gap between two totals given as keys: |T1 - T2| / max(|T1|,
** |T2|), the one formula for every joint (docs/rules.md).  0 for equal
** keys (equal infinities included) or a NaN; 1 when one total is infinite
** and the other not; for l_0 computed in log space, -expm1(-|K1 - K2|),
** so that products beyond the range of a double still have a gap. */
double rule_gap(const rule *r, double key1, double key2);

/* ---- what a rule's GOT is ----------------------------------------------
** 1 when the rule's GOT of every simple polygon in general position is the
** polygon's constrained Delaunay triangulation (R_1, R_2, R_0, R_-1, -r_1,
** abc_1 by theorems 3, 16 and 18 of appendix A; -r/R_1 and -r2/A_0 as table
** 3.4 observes them on its samples, unproven; docs/lot.md), so that its
** constrained LOT, the CDT, must have the GOT's triangles; else 0. */
int rule_got_is_cdt(const rule *r);
/* The theorem of appendix A proving that r decides every strictly convex
** quadrilateral as DT does, strictly off the circle (3, 16 or 18), or 0:
** what a certified answer may rest on (got's skeleton `delaunay`). */
int rule_got_cdt_theorem(const rule *r);

#endif
