/*
** shape_arith.c: the shape predicates (shape_internal.h) as programs over a
** register file that runs on doubles with an error bound, on exact
** floating-point expansions or on exact rationals, and the driver that
** runs the first and, when it cannot decide, the second when the inputs
** allow it, else the third.
*/
#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <gmp.h>
#include "fliplab_config.h"
#include "geom_exact_internal.h"
#include "shape_internal.h"

/* ---- why the double run's sign can be trusted -------------------------
**
** A program is a tree of +, -, * over inputs (doubles, exact).  Beside each
** value v it carries its "absolute twin" t, the same tree evaluated with
** every input replaced by its magnitude and every - by a +, and a rounding
** count k: 0 for an input, 1 for the difference of two inputs (read as one
** rounded leaf, twin |fl(x - y)|), max(k_a, k_b) + 1 for a sum or
** difference, k_a + k_b + 2 for a product.  With u = 2^-53 and
** gamma_k = k u / (1 - k u), induction over the tree gives, for the exact
** value x and the exact twin X,
**     |v - x| <= gamma_k X   and   t = X (1 + theta), |theta| <= gamma_k:
**   a sum:     |v_a + v_b - (x_a + x_b)| <= gamma_m (X_a + X_b), m = max k,
**              and one more rounding, (1 + u)(1 + gamma_m) <= 1 + gamma_{m+1};
**   a product: |v_a v_b - x_a x_b| <= ((1 + gamma_a)(1 + gamma_b) - 1) X_a X_b
**              <= gamma_{a+b} X_a X_b, then the rounding of the product, whose
**              error is u |v_a v_b| + eta with eta <= 2^-1075 the absolute
**              error of an underflowing product; counting the product as two
**              roundings absorbs eta whenever X_a X_b >= 2^-1022 (then
**              eta <= u X_a X_b).
** So X <= t / (1 - gamma_k), and |v - x| <= gamma_k / (1 - gamma_k) t
** = k u t / (1 - 2 k u) < fl((2k + 2) u t) (k < 2^20, one rounding of a
** product of doubles, (2k + 2) u exact): when |v| exceeds that bound, v has
** the sign of x.  A twin of 0 means every monomial is 0: the value is 0.
**
** Underflow: a product whose twin is below 2^-1000 (but whose factors'
** twins are not 0) poisons the run, which then goes to the exact path, so
** every product that the bound relies on has X_a X_b >= 2^-1000 (1 -
** gamma) > 2^-1022.  Sums of non-negative twins cannot lose the bound (a
** subnormal sum is exact).  Overflow makes v or t infinite or NaN; the
** comparison then fails and the exact path decides.  The coordinate
** contract of geom.h (and the shape checks of shape.c) keep every
** predicate far from both: inputs are 0 or in [2^-100, 2^100], degrees at
** most 8.
**
** The exact run repeats the program on exact registers, so every run is
** the same program: one place to get right.  Those registers are GMP
** rationals (every double is a rational; the pool of shape_mpq.c), or,
** first, floating-point expansions (the pool of shape_xp.c: +, - and *
** carried out exactly by the error-free transformations of
** geom_exact_internal.h), about ten times cheaper (the LOT of the
** 100 x 100 grid for ES:square took 0.24 s against 2.46 s on GMP alone),
** when no step can overflow or underflow.  That holds when every input (site coordinate,
** polygon vertex coordinate, ellipse form entry) is 0 or of magnitude in
** [2^-80, 2^80] (shape_xp_may): each leaf of a program (an input or the
** difference of two) is then a multiple of g = 2^-132 (the last bit of a
** double of magnitude at least 2^-80) of magnitude at most 2^81.  A
** program's terms are products of at most 8 leaves (the corner's rows
** (X Y, X, Y) with X, Y of degree 2), so every product the expansions
** form, and every component of every sum (two_sum and two_product keep
** multiples of their operands' granularities), is a multiple of g^8 =
** 2^-1056, above the smallest subnormal 2^-1074: nothing is lost below.
** Above, every value is at most 2^(8 * 81) times the number of terms (far
** below 2^300), so Dekker's split (which multiplies by 2^27 + 1) and every
** sum stay far below overflow.  A run that outgrows its pool gives up and
** GMP decides; geom_exact_gmp_only (the tests' reference mode) sends every
** exact run to GMP. */

/* A program's value: in the double run the value v, its twin t and its
** rounding count k (plain numbers: a double run inlines into straight-line
** code that keeps them in machine registers); in the exact run the index q
** of its rational in the pool. */
typedef struct shape_num {
  double v, t;
  int k, q;
} shape_num;

typedef struct shape_ar {
  int exact;               /* 0: the double run, 1: the exact run */
  int poison;              /* a product underflowed: the double run decides nothing */
  shape_mpq *P;            /* the registers (exact run on rationals) */
  shape_xp *X;             /* the registers (exact run on expansions), or NULL */
} shape_ar;

/* The exact runs by program and deciding stage. */
static atomic_ulong shape_exact_count[SHAPE_PROG_COUNT][GEOM_STAGE_COUNT];

unsigned long shape_exact_stage_calls(shape_prog p, geom_stage s) {
  return atomic_load_explicit(&shape_exact_count[p][s], memory_order_relaxed);
}

unsigned long shape_exact_calls(void) {
  unsigned long n = 0;
  for (int p = 0; p < SHAPE_PROG_COUNT; p++)
    for (int s = 0; s < GEOM_STAGE_COUNT; s++) n += shape_exact_stage_calls(p, s);
  return n;
}

/* The exact run's rational of value i, and a new register of it.  The
** programs are fixed trees far smaller than the pool (tests/test_shape.c
** runs every one). */
static inline mpq_ptr shape_q(const shape_ar *a, shape_num i) {
  return a->P->r[i.q];
}

static shape_num shape_reg(shape_ar *a) {
  shape_mpq_new(a->P);
  return (shape_num){.q = a->P->n - 1};
}

static FLIPLAB_ALWAYS_INLINE shape_num shape_in(shape_ar *a, double x) {
  if (!a->exact) return (shape_num){x, fabs(x), 0, 0};
  if (a->X) return (shape_num){.q = shape_xp_d(a->X, x)};
  shape_mpq_d(a->P, x);
  return (shape_num){.q = a->P->n - 1};
}

/* x - y of two inputs, one rounded leaf (the bound's argument). */
static FLIPLAB_ALWAYS_INLINE shape_num shape_dif(shape_ar *a, double x, double y) {
  if (!a->exact) return (shape_num){x - y, fabs(x - y), 1, 0};
  if (a->X) return (shape_num){.q = shape_xp_diff(a->X, x, y)};
  shape_mpq_diff(a->P, x, y);
  return (shape_num){.q = a->P->n - 1};
}

static FLIPLAB_ALWAYS_INLINE int shape_kmax(shape_num i, shape_num j) {
  return i.k > j.k ? i.k : j.k;
}

static FLIPLAB_ALWAYS_INLINE shape_num shape_add(shape_ar *a, shape_num i, shape_num j) {
  if (!a->exact) return (shape_num){i.v + j.v, i.t + j.t, shape_kmax(i, j) + 1, 0};
  if (a->X) return (shape_num){.q = shape_xp_add(a->X, i.q, j.q, 0)};
  shape_num r = shape_reg(a);
  mpq_add(shape_q(a, r), shape_q(a, i), shape_q(a, j));
  return r;
}

static FLIPLAB_ALWAYS_INLINE shape_num shape_sub(shape_ar *a, shape_num i, shape_num j) {
  if (!a->exact) return (shape_num){i.v - j.v, i.t + j.t, shape_kmax(i, j) + 1, 0};
  if (a->X) return (shape_num){.q = shape_xp_add(a->X, i.q, j.q, 1)};
  shape_num r = shape_reg(a);
  mpq_sub(shape_q(a, r), shape_q(a, i), shape_q(a, j));
  return r;
}

static FLIPLAB_ALWAYS_INLINE shape_num shape_neg(shape_ar *a, shape_num i) {
  if (!a->exact) return (shape_num){-i.v, i.t, i.k, 0};
  if (a->X) return (shape_num){.q = shape_xp_neg(a->X, i.q)};
  shape_num r = shape_reg(a);
  mpq_neg(shape_q(a, r), shape_q(a, i));
  return r;
}

static FLIPLAB_ALWAYS_INLINE shape_num shape_mul(shape_ar *a, shape_num i, shape_num j) {
  if (!a->exact) {
    shape_num r = {i.v * j.v, i.t * j.t, i.k + j.k + 2, 0};
    a->poison |= (r.t < 0x1p-1000) & (i.t != 0) & (j.t != 0);
    return r;
  }
  if (a->X) return (shape_num){.q = shape_xp_mul(a->X, i.q, j.q)};
  shape_num r = shape_reg(a);
  mpq_mul(shape_q(a, r), shape_q(a, i), shape_q(a, j));
  return r;
}

/* x_i y_j - x_j y_i style: a b - c d. */
static FLIPLAB_ALWAYS_INLINE shape_num shape_cross2(shape_ar *a, shape_num pa, shape_num pb,
                                                    shape_num pc, shape_num pd) {
  return shape_sub(a, shape_mul(a, pa, pb), shape_mul(a, pc, pd));
}

/* The double run's verdict on value r: its sign, or 2 (undecided). */
static FLIPLAB_ALWAYS_INLINE int shape_ar_filter(const shape_ar *a, shape_num r) {
  if (a->poison) return 2;
  if (r.t == 0) return 0;
  double bound = (2.0 * r.k + 2.0) * 0x1p-53 * r.t;
  if (r.v > bound) return 1;
  if (-r.v > bound) return -1;
  return 2;
}

/* ---- determinants of register matrices ------------------------------- */

/* m is row-major: m[3 * row + col]. */
static FLIPLAB_ALWAYS_INLINE shape_num shape_det3(shape_ar *a, const shape_num m[9]) {
  shape_num c0 = shape_cross2(a, m[4], m[8], m[5], m[7]);
  shape_num c1 = shape_cross2(a, m[3], m[8], m[5], m[6]);
  shape_num c2 = shape_cross2(a, m[3], m[7], m[4], m[6]);
  shape_num s = shape_sub(a, shape_mul(a, m[0], c0), shape_mul(a, m[1], c1));
  return shape_add(a, s, shape_mul(a, m[2], c2));
}

/* ---- polygon rows ------------------------------------------------------ */

/* Vertex i for i in [-n, 2n): every caller asks for an edge's ends or a
** corner's neighbours (a division per vertex was a tenth of the run). */
static FLIPLAB_ALWAYS_INLINE geom_point shape_vertex(const shape *K, int i) {
  return K->v[i < 0 ? i + K->n : i >= K->n ? i - K->n : i];
}

/* Edge e's direction (e_x, e_y) into r[0], r[1], and h = cross(k_e, k_{e+1})
** into r[2]. */
static FLIPLAB_ALWAYS_INLINE void shape_edge_regs(shape_ar *a, const shape *K, int e,
                                                  shape_num r[3]) {
  geom_point p = shape_vertex(K, e), q = shape_vertex(K, e + 1);
  r[0] = shape_dif(a, q.x, p.x);
  r[1] = shape_dif(a, q.y, p.y);
  r[2] = shape_cross2(a, shape_in(a, p.x), shape_in(a, q.y), shape_in(a, p.y), shape_in(a, q.x));
}

/* w = cross(p - o, e) = n.(p - o), n the outward normal (e_y, -e_x); its
** eps coefficient is e.(p - o) (the sites turned by -eps). */
static FLIPLAB_ALWAYS_INLINE shape_num shape_w(shape_ar *a, const shape_args *g, shape_num ex,
                                               shape_num ey, geom_point p) {
  shape_num dx = shape_dif(a, p.x, g->o.x), dy = shape_dif(a, p.y, g->o.y);
  if (g->deriv) return shape_add(a, shape_mul(a, ex, dx), shape_mul(a, ey, dy));
  return shape_cross2(a, dx, ey, dy, ex);
}

static FLIPLAB_ALWAYS_INLINE shape_num shape_p_cross(shape_ar *a, const shape_args *g) {
  geom_point p = shape_vertex(g->K, g->e[0]), q = shape_vertex(g->K, g->e[0] + 1);
  shape_num ex = shape_dif(a, q.x, p.x), ey = shape_dif(a, q.y, p.y);
  shape_num wx = shape_dif(a, g->p[1].x, g->p[0].x), wy = shape_dif(a, g->p[1].y, g->p[0].y);
  if (g->deriv) return shape_neg(a, shape_add(a, shape_mul(a, ex, wx), shape_mul(a, ey, wy)));
  return shape_cross2(a, ex, wy, ey, wx);
}

/* ---- shape-only 3x3 determinants -----------------------------------------
**
** det3h(i, j, k), the determinant of the rows (e_x, e_y, h) of three edges,
** depends on the shape alone.  Its double run (value, twin, rounding count
** and poison) is kept for every triple of a polygon of at most
** SHAPE_MEMO_MAX edges (shape_memo_build), and a double run reads the kept
** value instead of repeating the program: the very numbers the program
** would give, so the filter's argument and its verdicts are unchanged;
** but for a det3h that is exactly 0 (two rows of one edge, or three
** edges whose lines meet in a point), kept as the input 0 (twin 0, count
** 0: an exact leaf of the argument), so that a term w M of such an M adds
** nothing to a tree's twin.  On grids that matters: a slack of a site
** against the edge line of its own contact edge (a site pair parallel to
** an edge) is then a tree whose every other term has a kept 0, whose
** twin is 0 when the slack is 0, and the filter sees the exact 0 at once
** instead of sending it to the exact run.
** Their exact values are kept too, as expansions (for a shape whose
** coordinates the expansion run takes, shape_xp_moderate), and the
** expansion run reads those: det4's exact run then only forms its four
** products w M (the hexagon's LOT of the 316 x 316 grid took 0.92 s
** against 1.25 s when each run formed its M).  The run on rationals always
** computes. */

#define SHAPE_MEMO_MAX 16

typedef struct shape_memo_entry {
  shape_num x;
  int poison;
} shape_memo_entry;

struct shape_memo {
  int n;
  shape_memo_entry *cof;   /* [(i n + j) n + k] */
  double *xd;              /* the exact values: expansions, entry i at xd + xoff[i], */
  int *xoff, *xlen;        /* xlen[i] components; NULL when not kept */
  signed char *sgn;        /* the same index: the exact sign (shape_sign) */
  double *val, *twin;      /* the same index: cof's values and twins, flat (shape_memo_flat) */
  int kmax, poisoned;      /* the largest rounding count; 1 when some entry is poisoned */
};

static FLIPLAB_ALWAYS_INLINE shape_num shape_cof3_run(shape_ar *a, const shape *K, int i, int j,
                                                      int k) {
  shape_num m[9];
  shape_edge_regs(a, K, i, &m[0]);
  shape_edge_regs(a, K, j, &m[3]);
  shape_edge_regs(a, K, k, &m[6]);
  return shape_det3(a, m);
}

static FLIPLAB_ALWAYS_INLINE shape_num shape_cof3(shape_ar *a, const shape *K, int i, int j,
                                                  int k) {
  const struct shape_memo *mm = K->impl->memo;
  size_t n = mm != NULL ? (size_t)mm->n : 0, at = ((size_t)i * n + (size_t)j) * n + (size_t)k;
  if (a->exact && a->X && mm != NULL && mm->xd != NULL)
    return (shape_num){.q = shape_xp_put(a->X, mm->xd + mm->xoff[at], mm->xlen[at])};
  if (a->exact || mm == NULL) return shape_cof3_run(a, K, i, j, k);
  const shape_memo_entry *e = &mm->cof[at];
  a->poison |= e->poison;
  return e->x;
}

/* The exact det3h of every triple as expansions into mm (for a moderate
** K): 0, or -1 out of memory.  A run that outgrows its pool (never for
** shapes of a few dozen bits per coordinate) leaves none kept. */
static int shape_memo_exact(const shape *K, struct shape_memo *mm) {
  size_t cnt = (size_t)mm->n * (size_t)mm->n * (size_t)mm->n, used = 0, cap = 4 * cnt;
  mm->xoff = malloc(cnt * sizeof *mm->xoff);
  mm->xlen = malloc(cnt * sizeof *mm->xlen);
  mm->xd = malloc(cap * sizeof *mm->xd);
  if (mm->xoff == NULL || mm->xlen == NULL || mm->xd == NULL) return -1;
  shape_xp X;
  for (size_t at = 0; at < cnt; at++) {
    int i = (int)(at / ((size_t)mm->n * (size_t)mm->n));
    int j = (int)(at / (size_t)mm->n % (size_t)mm->n), k = (int)(at % (size_t)mm->n);
    shape_xp_init(&X);
    shape_ar a = {.exact = 1, .X = &X};
    int r = shape_cof3_run(&a, K, i, j, k).q;
    if (X.full) {
      free(mm->xd);
      mm->xd = NULL;
      return 0;
    }
    if (used + (size_t)X.len[r] > cap) {
      double *grown = realloc(mm->xd, 2 * cap * sizeof *grown);
      if (grown == NULL) return -1;
      mm->xd = grown;
      cap *= 2;
    }
    memcpy(mm->xd + used, X.d + X.off[r], (size_t)X.len[r] * sizeof *mm->xd);
    mm->xoff[at] = (int)used;
    mm->xlen[at] = X.len[r];
    used += (size_t)X.len[r];
  }
  return 0;
}

int shape_memo_build(shape *K) {
  int n = K->n;
  if (n > SHAPE_MEMO_MAX) return 0;
  struct shape_memo *mm = malloc(sizeof *mm);
  shape_memo_entry *cof = malloc((size_t)n * (size_t)n * (size_t)n * sizeof *cof);
  signed char *sgn = malloc((size_t)n * (size_t)n * (size_t)n);
  double *val = malloc((size_t)n * (size_t)n * (size_t)n * sizeof *val);
  double *twin = malloc((size_t)n * (size_t)n * (size_t)n * sizeof *twin);
  if (mm == NULL || cof == NULL || sgn == NULL || val == NULL || twin == NULL) {
    free(mm);
    free(cof);
    free(sgn);
    free(val);
    free(twin);
    return -1;
  }
  *mm = (struct shape_memo){.n = n, .cof = cof, .sgn = sgn, .val = val, .twin = twin};
  /* xd, xoff, xlen: NULL until shape_memo_exact */
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++)
      for (int k = 0; k < n; k++) {
        shape_ar a = {.exact = 0};
        shape_num x = shape_cof3_run(&a, K, i, j, k);
        size_t at = ((size_t)i * (size_t)n + (size_t)j) * (size_t)n + (size_t)k;
        shape_args g = {.K = K, .e = {i, j, k}};
        sgn[at] = (signed char)shape_sign(SHAPE_PROG_DET3H, &g);   /* memo is not yet set */
        if (sgn[at] == 0) x = (shape_num){0, 0, 0, 0}, a.poison = 0;   /* exact: an input 0 */
        cof[at] = (shape_memo_entry){x, a.poison};
        val[at] = x.v;
        twin[at] = x.t;
        mm->kmax = x.k > mm->kmax ? x.k : mm->kmax;
        mm->poisoned |= a.poison;
      }
  if (K->impl->moderate && shape_memo_exact(K, mm) != 0) {
    K->impl->memo = mm;   /* freed with what it holds */
    shape_memo_free(K);
    return -1;
  }
  K->impl->memo = mm;
  return 0;
}

int shape_memo_flat(const shape *K, shape_memo_flat_view *out) {
  const struct shape_memo *mm = K->impl->memo;
  if (mm == NULL || mm->poisoned) return -1;
  *out = (shape_memo_flat_view){mm->val, mm->twin, mm->sgn, mm->kmax};
  return 0;
}

void shape_memo_free(shape *K) {
  struct shape_memo *mm = K->impl->memo;
  if (mm == NULL) return;
  free(mm->cof);
  free(mm->xd);
  free(mm->xoff);
  free(mm->xlen);
  free(mm->sgn);
  free(mm->val);
  free(mm->twin);
  free(mm);
  K->impl->memo = NULL;
}

/* det3h of edges e[0..2]. */
static FLIPLAB_ALWAYS_INLINE shape_num shape_p_det3h(shape_ar *a, const shape_args *g) {
  return shape_cof3(a, g->K, g->e[0], g->e[1], g->e[2]);
}

static FLIPLAB_ALWAYS_INLINE shape_num shape_p_det3w(shape_ar *a, const shape_args *g) {
  shape_num m[9];
  for (int r = 0; r < 3; r++) {
    geom_point p = shape_vertex(g->K, g->e[r]), q = shape_vertex(g->K, g->e[r] + 1);
    m[3 * r] = shape_dif(a, q.x, p.x);
    m[3 * r + 1] = shape_dif(a, q.y, p.y);
    m[3 * r + 2] = shape_w(a, g, m[3 * r], m[3 * r + 1], g->p[r]);
  }
  return shape_det3(a, m);
}

/* det4 of the rows (e_x, e_y, h, w) expanded along its last column:
** -w_0 M_0 + w_1 M_1 - w_2 M_2 + w_3 M_3, M_r the det3h of the other three
** rows (in order), which are shape-only (kept, above).  The eps coefficient
** replaces the w column by its coefficients (det4 is linear in it). */
static FLIPLAB_ALWAYS_INLINE shape_num shape_p_det4(shape_ar *a, const shape_args *g) {
  static const int other[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  shape_num acc = {0, 0, 0, 0};
  for (int r = 0; r < 4; r++) {
    geom_point p = shape_vertex(g->K, g->e[r]), q = shape_vertex(g->K, g->e[r] + 1);
    shape_num ex = shape_dif(a, q.x, p.x), ey = shape_dif(a, q.y, p.y);
    shape_num w = shape_w(a, g, ex, ey, g->p[r]);
    const int *o = other[r];
    shape_num t = shape_mul(a, w, shape_cof3(a, g->K, g->e[o[0]], g->e[o[1]], g->e[o[2]]));
    acc = r == 0 ? shape_neg(a, t) : r % 2 ? shape_add(a, acc, t) : shape_sub(a, acc, t);
  }
  return acc;
}

/* ---- the rounding shape of a corner -------------------------------------
**
** Corner c with cone sides u = k_{c+1} - k_c and v = k_{c-1} - k_c
** (delta = cross(u, v) > 0: the polygon is anticlockwise).  The map
** x' = cross(p, v), y' = cross(u, p) is delta [u v]^-1: it sends u and v
** to the positive axes, scaled by delta > 0.  With X, Y the mapped
** differences p - o, the rows (X Y, X, Y) of p[0..2] give the 4x4
** determinant of rows (x'y', x', y', 1) of the three sites and o (the
** translation to o is a column operation).  Its eps coefficient: the
** sites turned by -eps change p - o = w by eps (w_y, -w_x), so X by
** eps w.v and Y by -eps u.w; the determinant's derivative is the sum of
** the three determinants with one column differentiated. */
static FLIPLAB_ALWAYS_INLINE void shape_corner_row(shape_ar *a, const shape_args *g, int r,
                                                   shape_num out[6]) {
  geom_point c = shape_vertex(g->K, g->corner);
  geom_point nx = shape_vertex(g->K, g->corner + 1), pv = shape_vertex(g->K, g->corner - 1);
  shape_num ux = shape_dif(a, nx.x, c.x), uy = shape_dif(a, nx.y, c.y);
  shape_num vx = shape_dif(a, pv.x, c.x), vy = shape_dif(a, pv.y, c.y);
  shape_num dx = shape_dif(a, g->p[r].x, g->o.x), dy = shape_dif(a, g->p[r].y, g->o.y);
  shape_num X = shape_cross2(a, dx, vy, dy, vx), Y = shape_cross2(a, ux, dy, uy, dx);
  out[0] = shape_mul(a, X, Y);
  out[1] = X;
  out[2] = Y;
  if (!g->deriv) return;
  shape_num X1 = shape_add(a, shape_mul(a, dx, vx), shape_mul(a, dy, vy));
  shape_num Y1 = shape_neg(a, shape_add(a, shape_mul(a, ux, dx), shape_mul(a, uy, dy)));
  out[3] = shape_add(a, shape_mul(a, X1, Y), shape_mul(a, X, Y1));
  out[4] = X1;
  out[5] = Y1;
}

static FLIPLAB_ALWAYS_INLINE shape_num shape_p_corner(shape_ar *a, const shape_args *g) {
  shape_num rows[3][6], m[9];
  for (int r = 0; r < 3; r++) shape_corner_row(a, g, r, rows[r]);
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) m[3 * r + c] = rows[r][c];
  if (!g->deriv) return shape_det3(a, m);
  shape_num acc = {0, 0, 0, 0};
  for (int col = 0; col < 3; col++) {
    shape_num d[9];
    for (int r = 0; r < 3; r++)
      for (int c = 0; c < 3; c++) d[3 * r + c] = c == col ? rows[r][3 + c] : rows[r][c];
    shape_num t = shape_det3(a, d);
    acc = col == 0 ? t : shape_add(a, acc, t);
  }
  return acc;
}

/* ---- the ellipse ------------------------------------------------------- */

/* Rows (x, y, Q(x, y)) of p[r] - o: positive when o is inside the ellipse
** homothet through p[0..2] (anticlockwise), as the incircle determinant. */
static FLIPLAB_ALWAYS_INLINE shape_num shape_p_ellipse(shape_ar *a, const shape_args *g) {
  shape_num m[9];
  shape_num q11 = shape_in(a, g->K->q11), q12 = shape_in(a, 2 * g->K->q12);
  shape_num q22 = shape_in(a, g->K->q22);
  for (int r = 0; r < 3; r++) {
    shape_num x = shape_dif(a, g->p[r].x, g->o.x), y = shape_dif(a, g->p[r].y, g->o.y);
    shape_num xx = shape_mul(a, shape_mul(a, q11, x), x);
    shape_num yy = shape_mul(a, shape_mul(a, q22, y), y);
    shape_num xy = shape_mul(a, shape_mul(a, q12, x), y);
    m[3 * r] = x;
    m[3 * r + 1] = y;
    m[3 * r + 2] = shape_add(a, shape_add(a, xx, xy), yy);
  }
  return shape_det3(a, m);
}

/* ---- running a program ----------------------------------------------- */

typedef shape_num (*shape_prog_fn)(shape_ar *a, const shape_args *g);

static shape_prog_fn const shape_progs[SHAPE_PROG_COUNT] = {
  [SHAPE_PROG_CROSS] = shape_p_cross,   [SHAPE_PROG_DET3H] = shape_p_det3h,
  [SHAPE_PROG_DET3W] = shape_p_det3w,   [SHAPE_PROG_DET4] = shape_p_det4,
  [SHAPE_PROG_CORNER] = shape_p_corner, [SHAPE_PROG_ELLIPSE] = shape_p_ellipse};

/* The double run of f: its sign, or 2.  Inlined with f a constant at each
** call of shape_filter_of, so the program becomes straight-line double
** code (the exact branches fold away, exact being 0). */
static FLIPLAB_ALWAYS_INLINE int shape_filter(shape_prog_fn f, const shape_args *g) {
  shape_ar a = {.exact = 0};
  shape_num r = f(&a, g);
  return shape_ar_filter(&a, r);
}

static int shape_filter_of(shape_prog p, const shape_args *g) {
  switch (p) {
  case SHAPE_PROG_CROSS: return shape_filter(shape_p_cross, g);
  case SHAPE_PROG_DET3H: return shape_filter(shape_p_det3h, g);
  case SHAPE_PROG_DET3W: return shape_filter(shape_p_det3w, g);
  case SHAPE_PROG_DET4: return shape_filter(shape_p_det4, g);
  case SHAPE_PROG_CORNER: return shape_filter(shape_p_corner, g);
  case SHAPE_PROG_ELLIPSE: return shape_filter(shape_p_ellipse, g);
  case SHAPE_PROG_COUNT: break;
  }
  return 2;
}

int shape_only_exact;   /* shape_set_exact_only (shape_internal.h) */

/* ---- the fast paths (shape_internal.h) ------------------------------
**
** No new bound: each is the double run of a program tree of the kind the
** argument at the top covers (+, -, * over inputs and differences of two
** inputs, with the same twin and rounding-count rules, filtered by
** shape_ar_filter), so a sign it returns is the exact sign.
** shape_fast_det4's tree is shape_p_det4's without the terms w_r M_r whose
** w_r has twin 0: such a w_r is exactly 0 (a twin of 0 means every
** monomial is 0), so the dropped terms add exactly 0 and the tree's exact
** value is det4's.  The fourth row's w is always such a term (its site is
** o: both differences are exactly 0), and so is a row whose site is o.
** A w computed once and read by several trees is the same double, twin
** and count each tree would compute (the double run is deterministic: no
** FMA, no fast-math), and its poison is carried into each.  A returned 0
** (twin 0) is passed on as 2: the caller's eps_sign then takes the
** perturbation's coefficient. */

int shape_fast_cross(const shape *K, int e, geom_point p, geom_point q) {
  if (shape_only_exact) return 2;
  shape_args g = {.K = K, .e = {e}, .p = {p, q}};
  int s = shape_filter(shape_p_cross, &g);
  return s == 0 ? 2 : s;
}

void shape_w3_prep(shape_w3 *w, const shape *K, const int e[3], const geom_point p[3],
                   geom_point o) {
  shape_args g = {.K = K, .o = o};
  shape_ar a = {.exact = 0};
  for (int r = 0; r < 3; r++) {
    if (p[r].x == o.x && p[r].y == o.y) {   /* both differences 0: w is exactly 0, twin 0 */
      w->v[r] = w->t[r] = 0;
      w->k[r] = 0;
      continue;
    }
    geom_point u = shape_vertex(K, e[r]), v = shape_vertex(K, e[r] + 1);
    shape_num x = shape_w(&a, &g, shape_dif(&a, v.x, u.x), shape_dif(&a, v.y, u.y), p[r]);
    w->v[r] = x.v;
    w->t[r] = x.t;
    w->k[r] = x.k;
  }
  w->poison = a.poison;
}

int shape_fast_det4(const shape_w3 *w, const shape *K, const int e[3], int m) {
  if (shape_only_exact) return 2;
  /* M_r, the det3h of the rows other than r among (e[0], e[1], e[2], m). */
  const int other[3][3] = {{e[1], e[2], m}, {e[0], e[2], m}, {e[0], e[1], m}};
  shape_ar a = {.exact = 0, .poison = w->poison};
  shape_num acc = {0, 0, 0, 0};
  int have = 0;
  for (int r = 0; r < 3; r++) {
    if (w->t[r] == 0) continue;
    shape_num wr = {w->v[r], w->t[r], w->k[r], 0};
    shape_num t = shape_mul(&a, wr, shape_cof3(&a, K, other[r][0], other[r][1], other[r][2]));
    if (!have) acc = r % 2 ? t : shape_neg(&a, t);
    else acc = r % 2 ? shape_add(&a, acc, t) : shape_sub(&a, acc, t);
    have = 1;
  }
  int s = have ? shape_ar_filter(&a, acc) : 2;
  return s == 0 ? 2 : s;
}

/* det3w expanded along its w column, w_0 M_0 - w_1 M_1 + w_2 M_2, M_r the
** cross product of the other two rows' edge directions (in order): a tree
** over the same inputs, so the argument at the top covers it. */
int shape_fast_det3w(const shape_w3 *w, const shape *K, const int e[3]) {
  if (shape_only_exact) return 2;
  const int other[3][2] = {{e[1], e[2]}, {e[0], e[2]}, {e[0], e[1]}};
  shape_ar a = {.exact = 0, .poison = w->poison};
  shape_num acc = {0, 0, 0, 0};
  int have = 0;
  for (int r = 0; r < 3; r++) {
    if (w->t[r] == 0) continue;
    geom_point u0 = shape_vertex(K, other[r][0]), u1 = shape_vertex(K, other[r][0] + 1);
    geom_point v0 = shape_vertex(K, other[r][1]), v1 = shape_vertex(K, other[r][1] + 1);
    shape_num m = shape_cross2(&a, shape_dif(&a, u1.x, u0.x), shape_dif(&a, v1.y, v0.y),
                               shape_dif(&a, u1.y, u0.y), shape_dif(&a, v1.x, v0.x));
    shape_num t = shape_mul(&a, (shape_num){w->v[r], w->t[r], w->k[r], 0}, m);
    if (!have) acc = r % 2 ? shape_neg(&a, t) : t;
    else acc = r % 2 ? shape_sub(&a, acc, t) : shape_add(&a, acc, t);
    have = 1;
  }
  int s = have ? shape_ar_filter(&a, acc) : 2;
  return s == 0 ? 2 : s;
}

int shape_det3h_sign(const shape *K, const int e[3]) {
  const struct shape_memo *mm = K->impl->memo;
  if (mm != NULL) {
    size_t n = (size_t)mm->n;
    return mm->sgn[((size_t)e[0] * n + (size_t)e[1]) * n + (size_t)e[2]];
  }
  shape_args g = {.K = K, .e = {e[0], e[1], e[2]}};
  return shape_sign(SHAPE_PROG_DET3H, &g);
}

/* The range of the expansion run's inputs (the argument at the top). */
static int shape_xp_in(double x) {
  return geom_moderate(x, 0x1p-80, 0x1p80);
}

int shape_xp_moderate(const shape *K) {
  int ok = 1;
  for (int i = 0; i < K->n; i++) ok &= shape_xp_in(K->v[i].x) & shape_xp_in(K->v[i].y);
  if (K->kind == SHAPE_ELLIPSE)
    ok &= shape_xp_in(K->q11) & shape_xp_in(2 * K->q12) & shape_xp_in(K->q22);
  return ok;
}

/* The expansion run may decide g: K and every site the program reads in
** range (unused sites are {0, 0}), and GMP not forced. */
static int shape_xp_may(const shape_args *g) {
  int ok = g->K->impl->moderate & shape_xp_in(g->o.x) & shape_xp_in(g->o.y);
  for (int r = 0; r < 4; r++) ok &= shape_xp_in(g->p[r].x) & shape_xp_in(g->p[r].y);
  return ok && !geom_exact_gmp_forced();
}

static void shape_exact_note(shape_prog p, geom_stage s) {
  atomic_fetch_add_explicit(&shape_exact_count[p][s], 1, memory_order_relaxed);
}

/* The key of g's exact sign among the signs kept per thread (shape_seen.c):
** the program, deriv, the corner, the edges and the differences of the
** rows the program reads (the others stay 0) to its origin (o, or p[0] for
** cross, which reads no o); 1, or 0 when some difference is not exact. */
static int shape_seen_key_of(shape_prog p, const shape_args *g, shape_seen_key *k) {
  static const int rows[SHAPE_PROG_COUNT] = {
    [SHAPE_PROG_CROSS] = 2, [SHAPE_PROG_DET3H] = 0,  [SHAPE_PROG_DET3W] = 3,
    [SHAPE_PROG_DET4] = 4,  [SHAPE_PROG_CORNER] = 3, [SHAPE_PROG_ELLIPSE] = 3};
  const int n[6] = {g->deriv, g->corner, g->e[0], g->e[1], g->e[2], g->e[3]};
  shape_seen_start(k, g->K, (int)p, n, 6);
  return shape_seen_diffs(k, g->p, rows[p], p == SHAPE_PROG_CROSS ? g->p[0] : g->o);
}

/* The exact run: the same program on expansions, or when they may not
** decide it, on rationals. */
static int shape_exact_run(shape_prog p, const shape_args *g) {
  if (shape_xp_may(g)) {
    shape_xp X;
    shape_xp_init(&X);
    shape_ar a = {.exact = 1, .X = &X};
    int r = shape_progs[p](&a, g).q;
    if (!X.full) {
      shape_exact_note(p, GEOM_STAGE_EXPANSION);
      return shape_xp_sign(&X, r);
    }
  }
  shape_exact_note(p, GEOM_STAGE_GMP);
  shape_mpq P;
  shape_mpq_init(&P);
  shape_ar a = {.exact = 1, .P = &P};
  return shape_mpq_done(&P, shape_q(&a, shape_progs[p](&a, g)));
}

/* The exact sign: kept from an earlier run of the same quantity
** (shape_seen.c), or run.  Every program is translation-invariant (it
** reads the sites as differences), so on a grid the same few quantities
** come back at many places. */
static FLIPLAB_COLD int shape_exact(shape_prog p, const shape_args *g) {
  shape_seen_key k;
  int s;
  if (!shape_seen_on() || !shape_seen_key_of(p, g, &k)) return shape_exact_run(p, g);
  if (shape_seen_find(&k, &s)) return s;
  s = shape_exact_run(p, g);
  shape_seen_keep(&k, s);
  return s;
}

int shape_exact_diff(double a, double b, double *d) {
  shape_mpq P;
  shape_mpq_init(&P);
  *d = a - b;
  mpq_ptr x = shape_mpq_diff(&P, a, b);
  mpq_sub(x, x, shape_mpq_d(&P, *d));
  return shape_mpq_done(&P, x) == 0;
}

void shape_set_exact_only(int on) {
  shape_only_exact = on;
}

int shape_sign(shape_prog p, const shape_args *g) {
  int s = shape_only_exact ? 2 : shape_filter_of(p, g);
  return s != 2 ? s : shape_exact(p, g);
}

int shape_eps_sign(shape_prog p, shape_args g, int *level) {
  g.deriv = 0;
  int s = shape_sign(p, &g);
  if (s == 0) {
    g.deriv = 1;
    s = shape_sign(p, &g);
  }
  if (level) *level = g.deriv + (s == 0);
  return s;
}
