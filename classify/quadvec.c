/*
** quadvec.c: the portable engine of quadvec_internal.h (the same
** arithmetic as the vector engine, a slot at a time) and the exact
** fallback of rewrite 5; the proof that both decide as rule_eval_tris
** does is in quadvec_internal.h.
*/
#include <math.h>
#include "quadvec_internal.h"

static int quadvec_scalar = !QUADVEC_VECTOR;

void quadvec_use_scalar(int on) {
  quadvec_scalar = on || !QUADVEC_VECTOR;
}

int quadvec_scalar_on(void) {
  return quadvec_scalar;
}

/* Magnitudes (rewrite 1) and the flags of rewrite 5. */
static void quadvec_magnitudes(const quadvec_batch *b) {
  const int nv = QUADVEC_PAD(b->nslots), st = b->stride;
  for (int s = 0; s < nv; s++) b->flags[s] = 0;
  for (int t = 0; t < b->ntris; t++)
    for (int s = 0; s < nv; s++) {
      double m = b->sign[s] * b->val[t * st + s];
      b->mag[t * st + s] = m;
      b->flags[s] |= (!(m >= 0x1p-511) | !(m <= 0x1p511)) * QUADVEC_WIDE
                     | (m == INFINITY) * QUADVEC_INF;
    }
}

/* Rewrite 5: slot s under joint j, one joint_compare per quadrilateral. */
static void quadvec_lane(int j, const quadvec_batch *b, int s) {
  const int st = b->stride, sign = b->sign[s] < 0 ? -1 : 1;
  unsigned long long code = 0;
  long long tie = 0;
  for (int q = 0; q < b->nquads; q++) {
    const ptrdiff_t *o = b->qoff[q];
    int c = joint_compare((joint_id)j, sign, b->val[o[0] + s], b->val[o[1] + s], b->val[o[2] + s],
                          b->val[o[3] + s], b->tie_eps);
    if (b->bd_weight == NULL) code |= (unsigned long long)(c > 0) << q;
    else code += c < 0 ? 0 : c > 0 ? b->bd_weight[q] : b->tie_weight[q];
    tie |= c == 0;
  }
  b->code[j * st + s] = code;
  b->tie[j * st + s] = tie;
}

/* Whether a slot of these flags needs rewrite 5 under a joint of form v:
** always without a fast path. */
static int quadvec_needs_lane(joint_vec v, long long flags) {
  switch (v) {
    case JOINT_VEC_PRODUCT:
    case JOINT_VEC_RSS: return (flags & QUADVEC_WIDE) != 0;
    case JOINT_VEC_HARMONIC: return (flags & QUADVEC_INF) != 0;
    case JOINT_VEC_MIN:
    case JOINT_VEC_MAX:
    case JOINT_VEC_SUM: return 0;
    case JOINT_VEC_NONE: return 1;
  }
  return 1;
}


/* ---- the portable engine ------------------------------------------------- */

/* fa = the joint of form v on a0, a1 (after h), fb on b0, b1. */
static void quadvec_c(joint_vec v, double a0, double a1, double b0, double b1, double *fa,
                      double *fb) {
  switch (v) {
    case JOINT_VEC_MIN: *fa = a0 < a1 ? a0 : a1; *fb = b0 < b1 ? b0 : b1; return;
    case JOINT_VEC_MAX: *fa = a0 > a1 ? a0 : a1; *fb = b0 > b1 ? b0 : b1; return;
    case JOINT_VEC_HARMONIC: *fa = 1.0 / (a0 + a1); *fb = 1.0 / (b0 + b1); return;
    case JOINT_VEC_PRODUCT: *fa = a0 * a1; *fb = b0 * b1; return;
    case JOINT_VEC_RSS: *fa = sqrt(a0 + a1); *fb = sqrt(b0 + b1); return;
    case JOINT_VEC_SUM:
    case JOINT_VEC_NONE:   /* never called: quadvec_run_scalar skips it */
      break;
  }
  *fa = a0 + a1;
  *fb = b0 + b1;
}

static void quadvec_joint_scalar(int j, const quadvec_batch *b) {
  const joint_vec v = joint_get((joint_id)j)->vec;
  const int st = b->stride, finite_p = v != JOINT_VEC_MIN && v != JOINT_VEC_MAX;
  const int hj = v == JOINT_VEC_HARMONIC || v == JOINT_VEC_RSS;
  const double *src = finite_p ? b->mag : b->val;
  for (int s = 0; s < b->nslots; s++) {
    unsigned long long code = 0;
    long long tieacc = 0;
    int neg = finite_p && b->sign[s] < 0;
    for (int q = 0; q < b->nquads; q++) {
      const ptrdiff_t *o = b->qoff[q];
      double a0 = src[o[0] + s], a1 = src[o[1] + s], b0 = src[o[2] + s], b1 = src[o[3] + s];
      double fa, fb;
      if (hj) {
        a0 = QUADVEC_H(v, a0);
        a1 = QUADVEC_H(v, a1);
        b0 = QUADVEC_H(v, b0);
        b1 = QUADVEC_H(v, b1);
      }
      quadvec_c(v, a0, a1, b0, b1, &fa, &fb);
      double aa = fabs(fa), ab = fabs(fb), big = aa > ab ? aa : ab;
      int tie = fa == fb || isnan(fa) || isnan(fb)
             || (!isinf(fa) && !isinf(fb) && fabs(fa - fb) <= b->tie_eps * big);
      int ac = (fa < fb) != neg;
      if (b->bd_weight == NULL) code |= (unsigned long long)!ac << q;
      else code += tie ? b->tie_weight[q] : ac ? 0 : b->bd_weight[q];
      tieacc |= tie;
    }
    b->code[j * st + s] = code;
    b->tie[j * st + s] = tieacc;
  }
}

void quadvec_run_scalar(const quadvec_batch *b) {
  quadvec_magnitudes(b);
  for (int j = 0, nj = joint_count(); j < nj; j++)
    if (b->joint_used[j] && joint_get((joint_id)j)->vec != JOINT_VEC_NONE)
      quadvec_joint_scalar(j, b);
  quadvec_fix_lanes(b);
}

/* Without flags only the joints without a fast path need lanes. */
void quadvec_fix_lanes(const quadvec_batch *b) {
  long long any = 0;
  for (int s = 0; s < b->nslots; s++) any |= b->flags[s];
  for (int j = 0, nj = joint_count(); j < nj; j++) {
    if (!b->joint_used[j]) continue;
    joint_vec v = joint_get((joint_id)j)->vec;
    if (any == 0 && v != JOINT_VEC_NONE) continue;
    for (int s = 0; s < b->nslots; s++)
      if (quadvec_needs_lane(v, b->flags[s])) quadvec_lane(j, b, s);
  }
}
