/*
** shape_mpq.c: the pool of GMP rationals that every exact run of shapes/
** takes its registers from (shape_internal.h): the predicates' programs,
** the sweep's keys, the tables' exactness checks.  Every double is a
** rational, so each value below is exact.
*/
#include <stdlib.h>
#include "shape_internal.h"

void shape_mpq_init(shape_mpq *P) {
  P->n = 0;
  mpq_init(P->s);
}

void shape_mpq_clear(shape_mpq *P) {
  for (int i = 0; i < P->n; i++) mpq_clear(P->r[i]);
  mpq_clear(P->s);
  P->n = 0;
}

int shape_mpq_done(shape_mpq *P, mpq_srcptr x) {
  int s = mpq_sgn(x);
  shape_mpq_clear(P);
  return s;
}

mpq_ptr shape_mpq_new(shape_mpq *P) {
  if (P->n >= SHAPE_MPQ_MAX) abort();
  mpq_ptr x = P->r[P->n++];
  mpq_init(x);
  return x;
}

mpq_ptr shape_mpq_d(shape_mpq *P, double a) {
  mpq_ptr x = shape_mpq_new(P);
  mpq_set_d(x, a);
  return x;
}

mpq_ptr shape_mpq_diff(shape_mpq *P, double a, double b) {
  mpq_ptr x = shape_mpq_d(P, a);
  mpq_set_d(P->s, b);
  mpq_sub(x, x, P->s);
  return x;
}

mpq_ptr shape_mpq_cross(shape_mpq *P, mpq_srcptr a, mpq_srcptr b, mpq_srcptr c, mpq_srcptr d) {
  mpq_ptr x = shape_mpq_new(P);
  mpq_mul(x, a, b);
  mpq_mul(P->s, c, d);
  mpq_sub(x, x, P->s);
  return x;
}
