/*
** joint.h: joint functions (thesis table 3.3; docs/joints.md).
**
** A joint combines two badness values: min, harmonic, product, sum,
** root-sum-square, max (the l_p "norms" for p = -inf, -1, 0, 1, 2, inf).
** For measures with values <= 0 the four finite-p joints are applied to
** |x|, |y| and the result negated; min and max are used as they are.
**
** Every joint also has a "key": a strictly increasing map phi of the
** measure's domain with phi(f(x, y)) = phi(x) (+) phi(y), where (+) is
** addition for the finite-p joints and min / max for the others.  The GOT
** dynamic programme works with keys so that long chains neither overflow
** (products of thousands of values) nor pay a sqrt per step.
*/
#ifndef FLIPLAB_JOINT_H
#define FLIPLAB_JOINT_H

typedef enum joint_id {
  JOINT_MIN,       /* l_-inf */
  JOINT_HARMONIC,  /* l_-1 */
  JOINT_PRODUCT,   /* l_0 */
  JOINT_SUM,       /* l_1 */
  JOINT_RSS,       /* l_2 */
  JOINT_MAX,       /* l_inf */
  JOINT_COUNT
} joint_id;

/* How keys combine. */
typedef enum joint_keyop { JOINT_KEY_ADD, JOINT_KEY_MIN, JOINT_KEY_MAX } joint_keyop;

typedef struct joint {
  const char *name;     /* command-line suffix: "-inf", "-1", "0", "1", "2", "inf" */
  const char *symbol;   /* "l_-inf" ... */
  const char *desc;
  int needs_sign;       /* 1 if the measure must keep one sign */
  joint_keyop keyop;
  const char *word;     /* one word for tables: "min", "harmonic", ... */
  const char *colour;   /* its colour in pictures (Okabe-Ito, colour-blind safe) */
} joint;

const joint *joint_get(joint_id j);
int joint_find(const char *name);   /* -1 if unknown */

/* f(x, y) for a measure of sign s (+1: values >= 0, -1: values <= 0). */
double joint_apply(joint_id j, int s, double x, double y);
/* The identity e with f(e, x) = x for every x of the domain of sign s. */
double joint_identity(joint_id j, int s);

/* Keys: phi, its inverse, and the identity in key space. */
double joint_key(joint_id j, int s, double x);
double joint_unkey(joint_id j, int s, double k);
double joint_key_identity(joint_id j);
static inline double joint_key_combine(joint_keyop op, double k1, double k2) {
  return op == JOINT_KEY_ADD ? k1 + k2
       : op == JOINT_KEY_MIN ? (k1 < k2 ? k1 : k2)
                             : (k1 > k2 ? k1 : k2);
}

#endif
