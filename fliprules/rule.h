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

typedef struct rule {
  rule_kind kind;
  int measure;          /* RULE_TRIANGLE: registry id */
  joint_id joint;       /* RULE_TRIANGLE */
  int quad;             /* RULE_QUAD: quadrilateral-rule registry id */
  char name[80];        /* canonical name, e.g. "-alpha_inf", "DT" */
} rule;

#define RULE_DEFAULT_TIE_EPS 1e-12
#define RULE_QUAD_MAX 32
#define RULE_DT 0       /* quadrilateral-rule registry id of DT */

/* Build rules.  rule_parse accepts "DT", a registered quadrilateral rule's
** name, or MEASURE_JOINT ("R_inf", "-c_-inf", "-r2/A_0").  On failure it
** returns -1 and writes a one-line message (naming the valid choices) to err. */
int rule_parse(const char *name, rule *out, char *err, size_t errlen);

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
int rule_quad_count(void);
const rule_quad *rule_quad_get(int id);
void rule_quad_unregister_user(void);

/* Compare two joint values with the spec's tie tolerance:
** RULE_EITHER when |ac - bd| <= eps * max(|ac|, |bd|) or ac == bd
** (equal infinities included); a finite and an infinite value never tie. */
rule_choice rule_compare(double ac, double bd, double tie_eps);

/* Decide a convex anticlockwise quadrilateral.  For triangle-based rules
** *ac and *bd (may be NULL) receive f(b(ABC), b(ACD)) and f(b(ABD), b(BCD)). */
rule_choice rule_eval(const rule *r, const geom_point q[4], double tie_eps,
                      double *ac, double *bd);

/* The same from the four triangles already made (the hot path of classify):
** t_abc, t_acd for diagonal AC, t_abd, t_bcd for BD. */
rule_choice rule_eval_tris(const rule *r, const geom_tri *t_abc, const geom_tri *t_acd,
                           const geom_tri *t_abd, const geom_tri *t_bcd,
                           double tie_eps, double *ac, double *bd);

/* The same from the four triangles' badness values (a triangulation that
** keeps each triangle's measure, as lot/ does): the decision of
** rule_eval_tris bit for bit, since a triangle's measure depends only on the
** triangle (geom_tri_make's canonical order). */
rule_choice rule_eval_badness(const rule *r, double b_abc, double b_acd, double b_abd,
                              double b_bcd, double tie_eps, double *ac, double *bd);

/* DT on ABCD directly: exact, so no canonical rotation is needed. */
rule_choice rule_delaunay_eval(geom_point a, geom_point b, geom_point c, geom_point d);

const char *rule_choice_str(rule_choice c);   /* "AC", "BD", "either" */

/* Every triangle-based rule name "m_j" for the given measures, in table order
** (joint-major, as table 3.4), appended to out; returns how many. */
int rule_list_triangle(const int *measures, int nmeasures, rule *out, int cap);

#endif
