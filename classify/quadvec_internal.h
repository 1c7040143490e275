/*
** quadvec_internal.h: the decisions of many triangle-based rules on many
** quadrilaterals at once, one vector lane per measure ("slot"), branch-free:
** the engine shared by the pentagon plans (flipgraph.c, a base-3 digit per
** quadrilateral) and the site-set census (sitecensus.c, a BD bit per
** quadrilateral).  The vector engine is inline here so that each caller
** compiles it with its own constants (the pentagon's five quadrilaterals
** and row stride fold into the loops) inside its own AVX2 clone; the
** portable engine and the exact fallback are in quadvec.c.  Not installed.
*/
#ifndef FLIPLAB_QUADVEC_INTERNAL_H
#define FLIPLAB_QUADVEC_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <string.h>
#include "fliplab_config.h"
#if FLIPLAB_HAVE_SSE2
#include <emmintrin.h>
#endif
#include "joint.h"

/* Slots are processed QUADVEC_LANES at a time: tables have a row stride
** that is a multiple of it, and at least QUADVEC_PAD(nslots). */
#define QUADVEC_LANES 4
#define QUADVEC_PAD(n) (((n) + QUADVEC_LANES - 1) / QUADVEC_LANES * QUADVEC_LANES)

/* Quadrilaterals per batch, at most (the census's BD bits fill a word). */
#define QUADVEC_MAX_QUADS 64

/* One batch: every quadrilateral of one site set (or pentagon) under every
** used joint and every slot.  Tables are [row][stride]; lanes from nslots
** up to QUADVEC_PAD(nslots) are padding: the caller keeps val and sign 1.0
** there (their results are never read).
**
** For each used joint j, slot s and quadrilateral q decided d (AC, BD or a
** tie), code[j][s] is the sum over q of bd_weight[q] (d = BD) or
** tie_weight[q] (tie), and tie[j][s] is non-zero iff some q is a tie.
** Pentagons take bd_weight 3^q and tie_weight 2 * 3^q (the decision code).
** Both NULL ask for BD bits (bit q set where q is decided BD; q < 64) and
** leave code[j][s] unspecified where tie[j][s] is set: the census, which
** counts a rule with a tie as a tie whatever its other decisions. */
typedef struct quadvec_batch {
  int nslots, stride, ntris, nquads;
  const ptrdiff_t (*qoff)[4];       /* row * stride of ABC, ACD (diagonal AC), ABD, BCD (BD) */
  const unsigned long long *bd_weight, *tie_weight;   /* per quadrilateral */
  const double *sign;               /* per slot: -1.0 for measures <= 0, else 1.0 */
  double tie_eps;
  const int *joint_used;            /* [JOINT_CAPACITY]: 0 skips the joint */
  const double *val;                /* [ntris][stride]: the measure of slot s on row t */
  double *mag, *h;                  /* scratch [ntris][stride] */
  long long *flags;                 /* scratch [stride] */
  unsigned long long *code;         /* out [JOINT_CAPACITY][stride] */
  long long *tie;                   /* out [JOINT_CAPACITY][stride] */
} quadvec_batch;

/* Flags of a slot (rewrite 5 below). */
#define QUADVEC_WIDE 1LL   /* a magnitude outside [2^-511, 2^511] (or NaN) */
#define QUADVEC_INF 2LL    /* a magnitude +inf */

/* The portable engine: the whole batch (quadvec.c). */
FLIPLAB_INTERNAL void quadvec_run_scalar(const quadvec_batch *b);

/* After the vector engine: the slots that rewrite 5 sends to joint_compare. */
FLIPLAB_INTERNAL void quadvec_fix_lanes(const quadvec_batch *b);

/* Whether the portable engine is in use: without generic vectors, built
** with -DQUADVEC_SCALAR, or after quadvec_use_scalar(1) (tests: both
** engines give the same bits; switch only while no batch runs). */
FLIPLAB_INTERNAL int quadvec_scalar_on(void);
FLIPLAB_INTERNAL void quadvec_use_scalar(int on);

#if FLIPLAB_HAVE_VECTORS && !defined(QUADVEC_SCALAR)
#define QUADVEC_VECTOR 1
#else
#define QUADVEC_VECTOR 0
#endif

/* h of rewrite 2 for the harmonic and l_2 forms (the joint table's vec). */
#define QUADVEC_H(v, x) ((v) == JOINT_VEC_HARMONIC ? 1.0 / (x) : (x) * (x))

/* ---- why the engine decides as rule_eval_tris does ----------------------
**
** The engine must decide exactly as rule_eval_tris does, bit for bit (the
** tests compare the two on every rule over many pentagons and site sets),
** while doing far less work.  Five rewrites make that possible; each is
** exact:
**
** 1. Sign.  joint_apply gives g(x, y) for min, max and measures >= 0, and
**    -g(-x, -y) for the four finite-p joints on measures <= 0 (g being the
**    joint on magnitudes).  Negation is exact, so g is computed here on the
**    magnitudes m = sign * x (multiplying by -1.0 is exact).  Comparing
**    -g_AC with -g_BD: equality, NaN and infinity tests are unchanged,
**    (-u) - (-v) rounds to exactly -(u - v) (round-to-nearest is
**    symmetric) so the tie test is unchanged, and -u < -v iff u > v, which
**    for non-tied, non-NaN values is !(u < v): the decision is flipped.
** 2. Shared per-triangle work.  g(x, y) = c(h(x), h(y)) with h(x) = 1/x,
**    c(a, b) = 1/(a + b) for the harmonic joint and h(x) = x*x,
**    c(a, b) = sqrt(a + b) for the root-sum-square: the same operations in
**    the same order as joint.c, so the same bits, but h runs once per
**    triangle instead of once per (triangle, quadrilateral) pair.  (joint.c
**    returns the other argument exactly when one harmonic argument is +inf;
**    1/(1/y) need not be y, so such slots go to rewrite 5's fallback.)
** 3. joint_compare_values inlined: fmax(|ac|, |bd|) is a plain maximum once
**    NaN has been sent to a tie; isinf(v) is |v| == inf, and "neither is
**    infinite" is "their larger magnitude is not".
** 4. A filter saves the final division (harmonic, f = 1/s) or square root
**    (l_2, f = sqrt(s)) of the sums s_AC, s_BD when their order alone
**    decides.  Let u = 2^-53, 0 <= tie_eps <= 1/8, K = 4 tie_eps + 2^-45,
**    both sums in [2^-1000, 2^1000] (so every quantity below is normal and
**    each rounded operation has relative error <= u) and, say, s_lo <
**    s_hi with fl(s_hi - s_lo) > K s_hi.  Then s_lo/s_hi < 1 - k, k =
**    K/(1 + u), and the exact values satisfy f_small/f_big < 1 - k/2
**    (sqrt(1 - k) <= 1 - k/2; for 1/s the ratio is < 1 - k itself).  After
**    rounding f_small/f_big < (1 - k/2)(1 + 3u), so fl(f_big - f_small) >
**    f_big (k/2 - 3u)(1 - u) > tie_eps f_big (1 + u) >= fl(tie_eps f_big):
**    no tie, and since correctly rounded 1/s and sqrt are monotone, f_AC <
**    f_BD iff s_AC > s_BD (harmonic) or s_AC < s_BD (l_2).  Equal sums
**    give equal f: a tie.  A vector with any other lane (near ties, zeros,
**    infinities, NaN, extreme magnitudes) takes the exact path.
** 5. Range.  The product and the root-sum-square joints can underflow or
**    overflow a double (joint.h), but not when every magnitude of the slot
**    lies in [2^-511, 2^511]: then every product, square and sum of two
**    squares is a normal double below 2^1023, and the plain evaluation is
**    the split one of joint_compare bit for bit.  A slot with a magnitude
**    outside (or 0, inf, NaN: rare, extreme triangles), and a harmonic slot
**    with a magnitude +inf (rewrite 2), is decided again by joint_compare,
**    one quadrilateral at a time (quadvec_fix_lanes).
**
** A joint of form JOINT_VEC_NONE (the table's power means) has no fast
** path: every slot of it is decided as in rewrite 5, by joint_compare.
**
** Values sit triangle-major (val[t][slot]) so that the loops over slots
** (all measures of one joint) run on contiguous memory.
*/

#if QUADVEC_VECTOR
/* GCC/Clang generic vectors: one lane per slot, 64-bit lanes throughout
** (doubles, and comparison masks of -1 / 0), no branches. */
#define QUADVEC_INLINE static inline __attribute__((always_inline))
typedef double quadvec_vd __attribute__((vector_size(8 * QUADVEC_LANES)));
typedef long long quadvec_vi __attribute__((vector_size(8 * QUADVEC_LANES)));
typedef unsigned long long quadvec_vu __attribute__((vector_size(8 * QUADVEC_LANES)));

/* Lane helpers are macros or take pointers: a vector passed by value would
** draw GCC's psABI note about 32-byte arguments without AVX. */
#define QUADVEC_VSEL(m, a, b) \
  ((quadvec_vd)(((m) & (quadvec_vi)(a)) | (~(m) & (quadvec_vi)(b))))
#define QUADVEC_VABS(x) ((quadvec_vd)((quadvec_vi)(x) & 0x7fffffffffffffffLL))

/* *out = the joint of form v on magnitudes of the lanes at pa and pb
** (after h). */
QUADVEC_INLINE void quadvec_vc(joint_vec v, const double *pa, const double *pb,
                               quadvec_vd *out) {
  quadvec_vd a, b, r;
  memcpy(&a, pa, sizeof a);
  memcpy(&b, pb, sizeof b);
  switch (v) {
    case JOINT_VEC_MIN: r = QUADVEC_VSEL(a < b, a, b); break;
    case JOINT_VEC_MAX: r = QUADVEC_VSEL(a > b, a, b); break;
    case JOINT_VEC_HARMONIC: r = 1.0 / (a + b); break;
    case JOINT_VEC_PRODUCT: r = a * b; break;
    case JOINT_VEC_RSS: {
      /* sqrt() must keep errno semantics, which stops GCC vectorising it;
      ** SSE2's sqrtpd is the same correctly rounded IEEE square root. */
      double x[QUADVEC_LANES];
      r = a + b;
      memcpy(x, &r, sizeof x);
#if FLIPLAB_HAVE_SSE2
      for (int k = 0; k < QUADVEC_LANES; k += 2)
        _mm_storeu_pd(&x[k], _mm_sqrt_pd(_mm_loadu_pd(&x[k])));
#else
      for (int k = 0; k < QUADVEC_LANES; k++) x[k] = sqrt(x[k]);
#endif
      memcpy(&r, x, sizeof r);
      break;
    }
    case JOINT_VEC_SUM:
    case JOINT_VEC_NONE:   /* never called: quadvec_joints_vector skips it */
      r = a + b;
      break;
  }
  *out = r;
}

/* quadvec_magnitudes, a vector at a time. */
QUADVEC_INLINE void quadvec_magnitudes_vector(const quadvec_batch *b) {
  const int nv = QUADVEC_PAD(b->nslots), st = b->stride;
  for (int s = 0; s < nv; s += QUADVEC_LANES) {
    quadvec_vd sign;
    quadvec_vi fl = {0};
    memcpy(&sign, &b->sign[s], sizeof sign);
    for (int t = 0; t < b->ntris; t++) {
      quadvec_vd v, m;
      memcpy(&v, &b->val[t * st + s], sizeof v);
      m = sign * v;
      memcpy(&b->mag[t * st + s], &m, sizeof m);
      fl |= ((~(m >= 0x1p-511) | ~(m <= 0x1p511)) & QUADVEC_WIDE) | ((m == INFINITY) & QUADVEC_INF);
    }
    memcpy(&b->flags[s], &fl, sizeof fl);
  }
}

/* Rewrite 4 on one quadrilateral: 1 (and *tie, *ac set) when every lane's
** sums decide, 0 to take the exact path. */
QUADVEC_INLINE int quadvec_filter(joint_vec v, const double *src, const ptrdiff_t *o, double k,
                                  quadvec_vi *tie, quadvec_vi *lt) {
  quadvec_vd a0, a1, b0, b1;
  memcpy(&a0, &src[o[0]], sizeof a0);
  memcpy(&a1, &src[o[1]], sizeof a1);
  memcpy(&b0, &src[o[2]], sizeof b0);
  memcpy(&b1, &src[o[3]], sizeof b1);
  quadvec_vd sa = a0 + a1, sb = b0 + b1;
  quadvec_vd hi = QUADVEC_VSEL(sa > sb, sa, sb), lo = QUADVEC_VSEL(sa > sb, sb, sa);
  quadvec_vi eq = sa == sb;
  quadvec_vi sure = eq | ((hi <= 0x1p1000) & (lo >= 0x1p-1000)
                          & (QUADVEC_VABS(sa - sb) > k * hi));
  /* All lanes sure: an AND across the four lanes by two swaps. */
  _Static_assert(QUADVEC_LANES == 4, "the swaps below are written for four lanes");
#if defined(__clang__) || __GNUC__ >= 12
  sure &= __builtin_shufflevector(sure, sure, 2, 3, 0, 1);
  sure &= __builtin_shufflevector(sure, sure, 1, 0, 3, 2);
  if (sure[0] == 0) return 0;
#else
  int all_sure = 1;
  for (int l = 0; l < QUADVEC_LANES; l++) all_sure &= sure[l] != 0;
  if (!all_sure) return 0;
#endif
  /* f_AC < f_BD iff s_AC > s_BD (harmonic: 1/s decreases) or s_AC < s_BD (l_2). */
  *tie = eq;
  *lt = v == JOINT_VEC_HARMONIC ? sa > sb : sa < sb;
  return 1;
}

/* Codes of every slot under joint j, of form v; see the comment at the top
** for why each step is joint_compare's arithmetic. */
QUADVEC_INLINE void quadvec_joint_vector(joint_vec v, int j, const quadvec_batch *b) {
  const int nv = QUADVEC_PAD(b->nslots), st = b->stride;
  const int finite_p = v != JOINT_VEC_MIN && v != JOINT_VEC_MAX;
  const int hj = v == JOINT_VEC_HARMONIC || v == JOINT_VEC_RSS;
  const int filter = hj && b->tie_eps >= 0 && b->tie_eps <= 0.125;
  const double eps = b->tie_eps, k = 4 * b->tie_eps + 0x1p-45;
  /* The per-triangle inputs: raw values for min and max, magnitudes for
  ** sum and product, h(magnitude) for the harmonic and l_2 joints. */
  const double *src = finite_p ? b->mag : b->val;
  if (hj) {
    for (int t = 0; t < b->ntris; t++)
      for (int s = 0; s < nv; s++) b->h[t * st + s] = QUADVEC_H(v, b->mag[t * st + s]);
    src = b->h;
  }
  for (int s = 0; s < nv; s += QUADVEC_LANES) {
    quadvec_vd sign;
    memcpy(&sign, &b->sign[s], sizeof sign);
    quadvec_vi negm = sign < 0.0;
    if (!finite_p) negm = (quadvec_vi){0};
    quadvec_vu code = {0};
    quadvec_vi tieacc = {0};
    quadvec_vu bit = code + 1;   /* bits mode: 2^q */
    for (int q = 0; q < b->nquads; q++) {
      const ptrdiff_t *o = b->qoff[q];
      quadvec_vi tie, lt;
      if (!(filter && quadvec_filter(v, src + s, o, k, &tie, &lt))) {
        quadvec_vd fa, fb;
        quadvec_vc(v, &src[s + o[0]], &src[s + o[1]], &fa);
        quadvec_vc(v, &src[s + o[2]], &src[s + o[3]], &fb);
        quadvec_vd aa = QUADVEC_VABS(fa), ab = QUADVEC_VABS(fb);
        quadvec_vd big = QUADVEC_VSEL(aa > ab, aa, ab);
        /* big != inf is |fa| != inf && |fb| != inf on lanes without NaN
        ** (a NaN lane is a tie anyway). */
        tie = (fa == fb) | (fa != fa) | (fb != fb)
            | ((big != INFINITY) & (QUADVEC_VABS(fa - fb) <= eps * big));
        lt = fa < fb;
      }
      quadvec_vi ac = lt ^ negm;
      if (b->bd_weight == NULL) {
        code |= (quadvec_vu)~ac & bit;
        bit += bit;
      } else {
        long long bw = (long long)b->bd_weight[q], tw = (long long)b->tie_weight[q];
        code += (quadvec_vu)((tie & tw) | (~tie & ~ac & bw));
      }
      tieacc |= tie;
    }
    memcpy(&b->code[j * st + s], &code, sizeof code);
    memcpy(&b->tie[j * st + s], &tieacc, sizeof tieacc);
  }
}

/* One specialised copy of the loops per form of the joint table; a joint
** without one is left to quadvec_fix_lanes. */
QUADVEC_INLINE void quadvec_joints_vector(int j, const quadvec_batch *b) {
  switch (joint_get((joint_id)j)->vec) {
    case JOINT_VEC_MIN: quadvec_joint_vector(JOINT_VEC_MIN, j, b); break;
    case JOINT_VEC_HARMONIC: quadvec_joint_vector(JOINT_VEC_HARMONIC, j, b); break;
    case JOINT_VEC_PRODUCT: quadvec_joint_vector(JOINT_VEC_PRODUCT, j, b); break;
    case JOINT_VEC_SUM: quadvec_joint_vector(JOINT_VEC_SUM, j, b); break;
    case JOINT_VEC_RSS: quadvec_joint_vector(JOINT_VEC_RSS, j, b); break;
    case JOINT_VEC_MAX: quadvec_joint_vector(JOINT_VEC_MAX, j, b); break;
    case JOINT_VEC_NONE: break;
  }
}

/* The whole batch: each caller calls this from its own function, cloned
** for AVX2 where the compiler can (FLIPLAB_HAVE_CLONES); every operation
** is an IEEE basic operation on doubles, so every clone gives the same
** bits, and so does the portable engine. */
QUADVEC_INLINE void quadvec_run(const quadvec_batch *b) {
  /* A private copy whose address never escapes: the caller's constants
  ** (row offsets, weights, counts) stay constants in the loops. */
  const quadvec_batch c = *b;
  if (quadvec_scalar_on()) {
    quadvec_run_scalar(b);
    return;
  }
  quadvec_magnitudes_vector(&c);
  for (int j = 0, nj = joint_count(); j < nj; j++)
    if (c.joint_used[j]) quadvec_joints_vector(j, &c);
  quadvec_fix_lanes(b);
}
#else
static inline void quadvec_run(const quadvec_batch *b) {
  quadvec_run_scalar(b);
}
#endif

#endif
