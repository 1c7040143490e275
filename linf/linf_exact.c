/*
** linf_exact.c: what needs GMP rationals: the orientation of d + 1 points
** in R^d, and a circumcube's centre, radius and distances as exact decimal
** text (every double is a dyadic rational, and so is every half-sum).
*/
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "linf.h"

/* Gaussian elimination over the rationals: the sign of det(a), a an m x m
** matrix of rationals (overwritten).  O(m^3) rational operations. */
static int linf_det_sign(mpq_t *a, int m) {
  int sign = 1;
  mpq_t t;
  mpq_init(t);
  for (int c = 0; c < m && sign != 0; c++) {
    int p = c;
    while (p < m && mpq_sgn(a[p * m + c]) == 0) p++;
    if (p == m) {
      sign = 0;
      break;
    }
    if (p != c) {
      for (int j = 0; j < m; j++) mpq_swap(a[p * m + j], a[c * m + j]);
      sign = -sign;
    }
    sign *= mpq_sgn(a[c * m + c]);
    for (int r = c + 1; r < m; r++) {
      if (mpq_sgn(a[r * m + c]) == 0) continue;
      mpq_div(t, a[r * m + c], a[c * m + c]);
      for (int j = c; j < m; j++) {
        mpq_t prod;
        mpq_init(prod);
        mpq_mul(prod, t, a[c * m + j]);
        mpq_sub(a[r * m + j], a[r * m + j], prod);
        mpq_clear(prod);
      }
    }
  }
  mpq_clear(t);
  return sign;
}

int linf_orient(const double *pts, int d) {
  mpq_t a[LINF_DIM_MAX * LINF_DIM_MAX], x;
  mpq_init(x);
  for (int r = 0; r < d; r++)
    for (int c = 0; c < d; c++) {
      mpq_init(a[r * d + c]);
      mpq_set_d(a[r * d + c], pts[(r + 1) * d + c]);
      mpq_set_d(x, pts[c]);
      mpq_sub(a[r * d + c], a[r * d + c], x);
    }
  int s = linf_det_sign(a, d);
  for (int i = 0; i < d * d; i++) mpq_clear(a[i]);
  mpq_clear(x);
  return s;
}

/* A dyadic rational as exact decimal text: v = num / 2^k = num 5^k / 10^k. */
static void linf_decimal(const mpq_t v, char *buf, size_t len) {
  mpz_t num;
  mpz_init(num);
  unsigned long k = mpz_scan1(mpq_denref(v), 0);
  mpz_ui_pow_ui(num, 5, k);
  mpz_mul(num, num, mpq_numref(v));
  char *s = mpz_get_str(NULL, 10, num);
  int neg = s[0] == '-';
  char *digits = s + neg;
  size_t nd = strlen(digits);
  /* the integer part, then the k decimals without their trailing zeros */
  size_t ipart = nd > k ? nd - k : 0, used = 0;
  char out[1200];
  if (neg) out[used++] = '-';
  if (ipart == 0) out[used++] = '0';
  for (size_t i = 0; i < ipart && used < sizeof out - 4; i++) out[used++] = digits[i];
  size_t last = nd;
  while (last > ipart && digits[last - 1] == '0') last--;
  if (last > ipart) {
    out[used++] = '.';
    for (size_t z = nd; z < k && used < sizeof out - 4; z++) out[used++] = '0';
    for (size_t i = ipart; i < last && used < sizeof out - 4; i++) out[used++] = digits[i];
  }
  out[used] = 0;
  free(s);
  mpz_clear(num);
  if (len == 0) return;
  snprintf(buf, len, "%s", out);
  if (strlen(out) >= len && len > 4) memcpy(buf + len - 4, "...", 4);
}

/* r = (top - bottom) / 2 and c_i = face_i -+ r, exactly. */
static void linf_cube_exact(const linf_cube *c, mpq_t r, mpq_t *centre) {
  mpq_t b;
  mpq_init(b);
  mpq_set_d(r, c->top);
  mpq_set_d(b, c->bottom);
  mpq_sub(r, r, b);
  mpq_div_2exp(r, r, 1);
  for (int i = 0; i < c->d; i++) {
    mpq_set_d(centre[i], c->face[i]);
    if (c->side[i] >= 0) mpq_sub(centre[i], centre[i], r);
    else mpq_add(centre[i], centre[i], r);
  }
  mpq_clear(b);
}

void linf_cube_centre(const linf_cube *c, char *buf, size_t len) {
  mpq_t r, centre[LINF_DIM_MAX];
  mpq_init(r);
  for (int i = 0; i < c->d; i++) mpq_init(centre[i]);
  linf_cube_exact(c, r, centre);
  size_t used = 0;
  char one[1200];
  for (int i = 0; i < c->d && used + 1 < len; i++) {
    linf_decimal(centre[i], one, sizeof one);
    int w = snprintf(buf + used, len - used, "%s%s%s", i ? ", " : "(", one,
                     i + 1 == c->d ? ")" : "");
    used += w > 0 ? (size_t)w : 0;
  }
  if (used >= len && len > 4) memcpy(buf + len - 4, "...", 4);
  for (int i = 0; i < c->d; i++) mpq_clear(centre[i]);
  mpq_clear(r);
}

void linf_cube_distance(const linf_cube *c, const double *q, char *buf, size_t len) {
  mpq_t r, x, best, centre[LINF_DIM_MAX];
  mpq_inits(r, x, best, NULL);
  for (int i = 0; i < c->d; i++) mpq_init(centre[i]);
  linf_cube_exact(c, r, centre);
  if (q == NULL) mpq_set(best, r);
  for (int i = 0; q != NULL && i < c->d; i++) {
    mpq_set_d(x, q[i]);
    mpq_sub(x, x, centre[i]);
    mpq_abs(x, x);
    if (mpq_cmp(x, best) > 0) mpq_set(best, x);
  }
  linf_decimal(best, buf, len);
  for (int i = 0; i < c->d; i++) mpq_clear(centre[i]);
  mpq_clears(r, x, best, NULL);
}
