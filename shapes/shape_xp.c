/*
** shape_xp.c: the pool of floating-point expansions that the shape
** predicates' expansion run takes its registers from (shape_internal.h):
** the stage between the double run and GMP.  Each register is an
** expansion (geom_exact_internal.h: a sum of nonoverlapping doubles, kept
** exactly) in one arena; a run that would outgrow the arena is marked full
** and decides nothing (GMP then does).  Sums and products of more than two
** components are compressed (geom_expansion_compress): without it lengths
** multiply down a program's tree (a det3h of 53-bit coordinates grew to
** hundreds of components), with it they stay near what the value's bits
** need.  shape_arith.c has the argument for when the expansions are exact.
*/
#include <string.h>
#include "geom_exact_internal.h"
#include "shape_internal.h"

/* A register of len components at the arena's top (reserved by
** shape_xp_room), or register 0 (the value 0) when the pool is full. */
static int shape_xp_keep(shape_xp *X, int len) {
  if (X->full) return 0;
  X->off[X->n] = X->used;
  X->len[X->n] = len;
  X->used += len;
  return X->n++;
}

/* need doubles of room at the arena's top, or NULL (the pool is then full). */
static double *shape_xp_room(shape_xp *X, int need) {
  if (X->full || X->used + need > SHAPE_XP_ROOM || X->n == SHAPE_XP_REGS) {
    X->full = 1;
    return NULL;
  }
  return X->d + X->used;
}

void shape_xp_init(shape_xp *X) {
  X->n = X->used = X->full = 0;
  X->d[0] = 0;
  shape_xp_keep(X, 1);   /* register 0: the value 0 */
}

int shape_xp_d(shape_xp *X, double a) {
  double *h = shape_xp_room(X, 1);
  if (h == NULL) return 0;
  h[0] = a;
  return shape_xp_keep(X, 1);
}

int shape_xp_put(shape_xp *X, const double *e, int len) {
  double *h = shape_xp_room(X, len);
  if (h == NULL) return 0;
  memcpy(h, e, (size_t)len * sizeof *h);
  return shape_xp_keep(X, len);
}

/* a - b as its rounded value and that rounding's error (geom_two_diff). */
int shape_xp_diff(shape_xp *X, double a, double b) {
  double *h = shape_xp_room(X, 2), x, y;
  if (h == NULL) return 0;
  geom_two_diff(a, b, &x, &y);
  int k = 0;
  if (y != 0) h[k++] = y;
  h[k++] = x;
  return shape_xp_keep(X, k);
}

static int shape_xp_zero(const shape_xp *X, int i) {
  return X->len[i] == 1 && X->d[X->off[i]] == 0;
}

/* i + j, or i - j when neg: j's components negated into scratch above the
** result's room first.  Cost O(li + lj). */
int shape_xp_add(shape_xp *X, int i, int j, int neg) {
  int li = X->len[i], lj = X->len[j];
  double *h = shape_xp_room(X, 2 * (li + lj));
  if (h == NULL) return 0;
  const double *f = X->d + X->off[j];
  if (neg) {
    double *t = h + li + lj;
    for (int c = 0; c < lj; c++) t[c] = -f[c];
    f = t;
  }
  int k = geom_expansion_sum(li, X->d + X->off[i], lj, f, h);
  return shape_xp_keep(X, k > 2 ? geom_expansion_compress(k, h) : k);
}

int shape_xp_neg(shape_xp *X, int i) {
  int li = X->len[i];
  double *h = shape_xp_room(X, li);
  if (h == NULL) return 0;
  for (int c = 0; c < li; c++) h[c] = -X->d[X->off[i] + c];
  return shape_xp_keep(X, li);
}

/* i j: the longer operand scaled by each component of the shorter
** (geom_expansion_product, cost O(n m^2) with m the shorter length); a
** zero operand gives register 0 at once (the common case of a degenerate
** input: zero differences). */
int shape_xp_mul(shape_xp *X, int i, int j) {
  if (shape_xp_zero(X, i) || shape_xp_zero(X, j)) return 0;
  if (X->len[i] < X->len[j]) {
    int t = i;
    i = j;
    j = t;
  }
  int n = X->len[i], m = X->len[j];
  double *h = shape_xp_room(X, 2 * n * m + 2 * n + 2 * n * m);
  if (h == NULL) return 0;
  int k = geom_expansion_product(n, X->d + X->off[i], m, X->d + X->off[j], h, h + 2 * n * m);
  return shape_xp_keep(X, k > 2 ? geom_expansion_compress(k, h) : k);
}

int shape_xp_sign(const shape_xp *X, int i) {
  double top = X->d[X->off[i] + X->len[i] - 1];
  return (top > 0) - (top < 0);
}
