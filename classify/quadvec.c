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
static void quadvec_lane(joint_id j, const quadvec_batch *b, int s) {
  const int st = b->stride, sign = b->sign[s] < 0 ? -1 : 1;
  unsigned long long code = 0;
  long long tie = 0;
  for (int q = 0; q < b->nquads; q++) {
    const ptrdiff_t *o = b->qoff[q];
    int c = joint_compare(j, sign, b->val[o[0] + s], b->val[o[1] + s], b->val[o[2] + s],
                          b->val[o[3] + s], b->tie_eps);
    if (b->bd_weight == NULL) code |= (unsigned long long)(c > 0) << q;
    else code += c < 0 ? 0 : c > 0 ? b->bd_weight[q] : b->tie_weight[q];
    tie |= c == 0;
  }
  b->code[j * st + s] = code;
  b->tie[j * st + s] = tie;
}

static int quadvec_needs_lane(joint_id j, long long flags) {
  if (j == JOINT_PRODUCT || j == JOINT_RSS) return (flags & QUADVEC_WIDE) != 0;
  return j == JOINT_HARMONIC && (flags & QUADVEC_INF);
}


/* ---- the portable engine ------------------------------------------------- */

static void quadvec_joint_scalar(joint_id j, const quadvec_batch *b) {
  const int st = b->stride, finite_p = j != JOINT_MIN && j != JOINT_MAX;
  const int hj = j == JOINT_HARMONIC || j == JOINT_RSS;
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
        a0 = QUADVEC_H(j, a0);
        a1 = QUADVEC_H(j, a1);
        b0 = QUADVEC_H(j, b0);
        b1 = QUADVEC_H(j, b1);
      }
      switch (j) {
        case JOINT_MIN: fa = a0 < a1 ? a0 : a1; fb = b0 < b1 ? b0 : b1; break;
        case JOINT_MAX: fa = a0 > a1 ? a0 : a1; fb = b0 > b1 ? b0 : b1; break;
        case JOINT_HARMONIC: fa = 1.0 / (a0 + a1); fb = 1.0 / (b0 + b1); break;
        case JOINT_PRODUCT: fa = a0 * a1; fb = b0 * b1; break;
        case JOINT_RSS: fa = sqrt(a0 + a1); fb = sqrt(b0 + b1); break;
        default: fa = a0 + a1; fb = b0 + b1; break;
      }
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
  for (int j = 0; j < JOINT_COUNT; j++)
    if (b->joint_used[j]) quadvec_joint_scalar((joint_id)j, b);
  quadvec_fix_lanes(b);
}

void quadvec_fix_lanes(const quadvec_batch *b) {
  long long any = 0;
  for (int s = 0; s < b->nslots; s++) any |= b->flags[s];
  if (any == 0) return;
  for (int j = 0; j < JOINT_COUNT; j++)
    if (b->joint_used[j])
      for (int s = 0; s < b->nslots; s++)
        if (quadvec_needs_lane((joint_id)j, b->flags[s])) quadvec_lane((joint_id)j, b, s);
}
