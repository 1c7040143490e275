/*
** triavg.c: the closed forms of chapter 5's averages over all
** triangulations of a convex polygon, as exact GMP rationals, and the same
** averages from an enumeration (trienum.c), side by side in one study_avg.
** Each formula's derivation is in docs/averages.md; the tests compare every
** one with the enumeration and with a second route.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "triavg_internal.h"

struct study_avg {
  int n, enumerated;
  mpq_t closed[STUDY_AVG_COUNT], enumv[STUDY_AVG_COUNT];
  study_enum_totals tot;                     /* the (n+2)-gon's enumeration */
  uint64_t prefix_deg[STUDY_ENUM_VMAX];      /* [m]: sum over the (m+2)-gon's */
  uint64_t prefix_count[STUDY_ENUM_VMAX];    /* triangulations of the last vertex's degree */
};

/* ---- sums over Catalan pairs ---------------------------------------------- */

static void study_catalan(mpz_t out, unsigned long n) {
  mpz_bin_uiui(out, 2 * n, n);
  mpz_divexact_ui(out, out, n + 1);
}

/* out = sum_{m=1}^{n-1} w(m, n) C_m C_{n-m}.  P_m = C_m C_{n-m} goes to
** P_{m+1} = P_m (2m+1)(n-m+1) / ((m+2)(2n-2m-1)), an exact division (both
** sides are integers), so the cost is O(n) steps on O(n)-bit numbers:
** O(n^2) word operations, and O(n) space where an array of the Catalan
** numbers would take O(n^2) bits. */
static void study_catalan_pairs(mpz_t out, int n, unsigned long (*w)(unsigned long m,
                                                                      unsigned long n)) {
  mpz_t p;
  mpz_init(p);
  mpz_set_ui(out, 0);
  unsigned long nn = (unsigned long)n;
  if (nn >= 2) study_catalan(p, nn - 1);                /* P_1 = C_{n-1} */
  for (unsigned long m = 1; m + 1 <= nn; m++) {
    mpz_addmul_ui(out, p, w(m, nn));
    if (m + 2 > nn) break;
    mpz_mul_ui(p, p, (2 * m + 1) * (nn - m + 1));
    mpz_divexact_ui(p, p, (m + 2) * (2 * nn - 2 * m - 1));
  }
  mpz_clear(p);
}

/* out = sum / C_n (divided by `extra` too). */
static void study_over_catalan(mpq_t out, const mpz_t sum, int n, unsigned long extra) {
  mpz_t c;
  mpz_init(c);
  study_catalan(c, (unsigned long)n);
  mpz_mul_ui(c, c, extra);
  mpq_set_num(out, sum);
  mpq_set_den(out, c);
  mpq_canonicalize(out);
  mpz_clear(c);
}

/* The crossing weight: diagonals p_i p_j with j - i - 1 = m that cross the
** cut after p_k, k = floor(n/2): min(m, n-m) + 1 of them. */
static unsigned long study_w_cross(unsigned long m, unsigned long n) {
  return (m < n - m ? m : n - m) + 1;
}

/* T_c's weight: n+1-m diagonals with j - i - 1 = m, each scanning m. */
static unsigned long study_w_tc(unsigned long m, unsigned long n) {
  return (n + 1 - m) * m;
}

/* L's weight: n+1-m chords with j - i - 1 = m, index length
** min(m+1, n+1-m). */
static unsigned long study_w_len(unsigned long m, unsigned long n) {
  return (n + 1 - m) * (m + 1 < n + 1 - m ? m + 1 : n + 1 - m);
}

/* ---- the closed forms ------------------------------------------------------ */

/* T_c(n) = 4^n / C_n - (2n+1) (the generating-function solution). */
static void study_closed_tc(int n, mpq_t out) {
  mpz_t four;
  mpz_init(four);
  mpz_setbit(four, 2 * (unsigned long)n);
  study_over_catalan(out, four, n, 1);
  mpq_t s;
  mpq_init(s);
  mpq_set_ui(s, 2 * (unsigned long)n + 1, 1);
  mpq_sub(out, out, s);
  mpq_clear(s);
  mpz_clear(four);
}

/* The balanced split: n + sum_{i=1}^{n} floor(log2 i)
** = n + (n+1)k - 2^{k+1} + 2, k = floor(log2 n). */
static void study_closed_tc_min(int n, mpq_t out) {
  unsigned long k = 0, nn = (unsigned long)n;
  while ((2UL << k) <= nn) k++;
  mpq_set_ui(out, nn + (nn + 1) * k + 2 - (2UL << k), 1);
}

/* The path: n + (n-1) + ... + 1. */
static void study_closed_tc_max(int n, mpq_t out) {
  mpq_set_ui(out, (unsigned long)n * ((unsigned long)n + 1) / 2, 1);
}

static void study_closed_cross(int n, mpq_t out) {
  mpz_t s;
  mpz_init(s);
  study_catalan_pairs(s, n, study_w_cross);
  study_over_catalan(out, s, n, 1);
  mpz_clear(s);
}

/* L_a = (n+2) A / (2(n-1)): the N rotations of the cut cross a chord of
** index length s exactly 2s times. */
static void study_closed_la(int n, mpq_t out) {
  mpq_t f;
  mpq_init(f);
  study_closed_cross(n, out);
  mpq_set_ui(f, (unsigned long)n + 2, 2 * ((unsigned long)n - 1));
  mpq_canonicalize(f);
  mpq_mul(out, out, f);
  mpq_clear(f);
}

/* The fullest dual tree from its centroid: 1, 3, 6, ..., 3 2^{k-1} nodes at
** depths 0..k and n + 2 - 3 2^k at depth k+1, with 3 2^k <= n + 2. */
static void study_closed_lmin(int n, mpq_t out) {
  unsigned long k = 0, nn = (unsigned long)n;
  while (3 * (2UL << k) <= nn + 2) k++;
  unsigned long p = 3UL << k;                            /* 3 2^k */
  unsigned long depth = p * k + 3 - p + (k + 1) * (nn + 2 - p);
  mpq_set_ui(out, nn - 1 + depth, nn - 1);
  mpq_canonicalize(out);
}

/* The path: its edges split off 1 .. n-1 triangles, sum of min(t, n-t) =
** floor(n^2/4). */
static void study_closed_lmax(int n, mpq_t out) {
  unsigned long nn = (unsigned long)n;
  mpq_set_ui(out, nn - 1 + nn * nn / 4, nn - 1);
  mpq_canonicalize(out);
}

/* 2(n-1) diagonal ends over n+2 vertices. */
static void study_closed_degree(int n, mpq_t out) {
  mpq_set_ui(out, 2 * ((unsigned long)n - 1), (unsigned long)n + 2);
  mpq_canonicalize(out);
}

/* p / q = sum_{i=a}^{b-1} 1/i by binary splitting: O(M(n log n) log n)
** where adding n fractions one by one would cost O(n^2) gcds. */
static void study_harmonic_split(mpz_t p, mpz_t q, unsigned long a, unsigned long b) {
  if (b - a == 1) {
    mpz_set_ui(p, 1);
    mpz_set_ui(q, a);
    return;
  }
  mpz_t p2, q2;
  mpz_inits(p2, q2, NULL);
  unsigned long mid = a + (b - a) / 2;
  study_harmonic_split(p, q, a, mid);
  study_harmonic_split(p2, q2, mid, b);
  mpz_mul(p, p, q2);
  mpz_addmul(p, p2, q);
  mpz_mul(q, q, q2);
  mpz_clears(p2, q2, NULL);
}

/* T_i(n) = sum_{i=1}^{n} 2(i-1)/(i+2) = 2n - 6 H_{n+2} + 9. */
static void study_closed_ti(int n, mpq_t out) {
  mpz_t p, q;
  mpz_inits(p, q, NULL);
  study_harmonic_split(p, q, 1, (unsigned long)n + 3);
  mpq_set_num(out, p);
  mpq_set_den(out, q);
  mpq_canonicalize(out);
  mpz_mul_si(p, mpq_numref(out), -6);
  mpz_set(q, mpq_denref(out));
  mpz_addmul_ui(p, q, 2 * (unsigned long)n + 9);
  mpq_set_num(out, p);
  mpq_canonicalize(out);
  mpz_clears(p, q, NULL);
}

/* ---- the enumerated averages ----------------------------------------------- */

static void study_enum_ratio(mpq_t out, uint64_t num, uint64_t den) {
  mpz_t a, b;
  mpz_inits(a, b, NULL);
  mpz_import(a, 1, -1, sizeof num, 0, 0, &num);
  mpz_import(b, 1, -1, sizeof den, 0, 0, &den);
  mpq_set_num(out, a);
  mpq_set_den(out, b);
  mpq_canonicalize(out);
  mpz_clears(a, b, NULL);
}

static uint64_t study_deg_sum(const uint64_t *hist, int nv) {
  uint64_t s = 0;
  for (int d = 0; d < nv; d++) s += (uint64_t)d * hist[d];
  return s;
}

static void study_enum_tc(const study_avg *a, mpq_t o) {
  study_enum_ratio(o, a->tot.tc, a->tot.count);
}
static void study_enum_tc_min(const study_avg *a, mpq_t o) {
  study_enum_ratio(o, a->tot.tc_min, 1);
}
static void study_enum_tc_max(const study_avg *a, mpq_t o) {
  study_enum_ratio(o, a->tot.tc_max, 1);
}
static void study_enum_cross(const study_avg *a, mpq_t o) {
  study_enum_ratio(o, a->tot.cross, a->tot.count);
}
static void study_enum_la(const study_avg *a, mpq_t o) {
  study_enum_ratio(o, a->tot.len, a->tot.count * (uint64_t)(a->n - 1));
}
static void study_enum_lmin(const study_avg *a, mpq_t o) {
  study_enum_ratio(o, a->tot.len_min, (uint64_t)(a->n - 1));
}
static void study_enum_lmax(const study_avg *a, mpq_t o) {
  study_enum_ratio(o, a->tot.len_max, (uint64_t)(a->n - 1));
}
static void study_enum_degree(const study_avg *a, mpq_t o) {
  study_enum_ratio(o, study_deg_sum(a->tot.hist[a->n], a->n + 2), a->tot.count);
}

/* T_i: the newest vertex's mean degree in every prefix polygon, summed. */
static void study_enum_ti(const study_avg *a, mpq_t o) {
  mpq_t t;
  mpq_init(t);
  mpq_set_ui(o, 0, 1);
  for (int m = 1; m <= a->n; m++) {
    study_enum_ratio(t, a->prefix_deg[m], a->prefix_count[m]);
    mpq_add(o, o, t);
  }
  mpq_clear(t);
}

/* ---- the table of quantities ----------------------------------------------- */

typedef struct study_avg_row {
  const char *name, *about;
  int nmin;                                      /* the least n it exists at */
  void (*closed)(int n, mpq_t out);
  void (*enumerated)(const study_avg *a, mpq_t out);
} study_avg_row;

static const study_avg_row study_avg_rows[STUDY_AVG_COUNT] = {
  {"Tc", "mean vertices scanned, circumcircle algorithm on the newest side", 1,
   study_closed_tc, study_enum_tc},
  {"Tc_min", "least vertices scanned over the triangulations", 1, study_closed_tc_min,
   study_enum_tc_min},
  {"Tc_max", "most vertices scanned over the triangulations", 1, study_closed_tc_max,
   study_enum_tc_max},
  {"A", "mean diagonals crossing the cut after p_floor(n/2)", 1, study_closed_cross,
   study_enum_cross},
  {"La", "mean of L(D), the mean index length of D's diagonals", 2, study_closed_la,
   study_enum_la},
  {"Lmin", "least L(D) over the triangulations", 2, study_closed_lmin, study_enum_lmin},
  {"Lmax", "greatest L(D) over the triangulations", 2, study_closed_lmax, study_enum_lmax},
  {"deg", "mean interior degree of a vertex", 1, study_closed_degree, study_enum_degree},
  {"Ti", "mean flips, incremental algorithm in input order", 1, study_closed_ti,
   study_enum_ti},
};

const char *study_avg_name(int i) {
  return i >= 0 && i < STUDY_AVG_COUNT ? study_avg_rows[i].name : NULL;
}

const char *study_avg_about(int i) {
  return i >= 0 && i < STUDY_AVG_COUNT ? study_avg_rows[i].about : NULL;
}

void study_avg_closed(int kind, int n, mpq_t out) {
  study_avg_rows[kind].closed(n, out);
}

/* ---- the study ------------------------------------------------------------- */

/* Cost: each closed form O(n^2) word operations at most; the enumeration
** C_1 + ... + C_n triangulations, O(n) each. */
study_avg *study_avg_new(int n, int enumerate, char *err, size_t errcap) {
  if (n < 1 || n > STUDY_AVG_NMAX) {
    snprintf(err, errcap, "n = %d is outside 1..%d (the (n+2)-gon)", n, STUDY_AVG_NMAX);
    return NULL;
  }
  if (enumerate && n > STUDY_AVG_ENUM_NMAX) {
    snprintf(err, errcap, "n = %d: enumeration goes up to n = %d (C_%d = 477638700 "
             "triangulations)", n, STUDY_AVG_ENUM_NMAX, STUDY_AVG_ENUM_NMAX);
    return NULL;
  }
  study_avg *a = calloc(1, sizeof *a);
  if (!a) {
    snprintf(err, errcap, "out of memory");
    return NULL;
  }
  a->n = n;
  a->enumerated = enumerate != 0;
  for (int k = 0; k < STUDY_AVG_COUNT; k++) {
    mpq_inits(a->closed[k], a->enumv[k], NULL);
    if (n >= study_avg_rows[k].nmin) study_avg_rows[k].closed(n, a->closed[k]);
  }
  if (!a->enumerated) return a;
  for (int m = 1; m <= n; m++) {
    study_enum_run(m, 0, &a->tot);
    a->prefix_deg[m] = study_deg_sum(a->tot.hist[m + 1], m + 2);
    a->prefix_count[m] = a->tot.count;
  }
  for (int k = 0; k < STUDY_AVG_COUNT; k++)
    if (n >= study_avg_rows[k].nmin) study_avg_rows[k].enumerated(a, a->enumv[k]);
  return a;
}

void study_avg_delete(study_avg *a) {
  if (!a) return;
  for (int k = 0; k < STUDY_AVG_COUNT; k++) mpq_clears(a->closed[k], a->enumv[k], NULL);
  free(a);
}

int study_avg_value(const study_avg *a, int kind, int enumerated, mpq_t out) {
  if (kind < 0 || kind >= STUDY_AVG_COUNT || a->n < study_avg_rows[kind].nmin ||
      (enumerated && !a->enumerated))
    return 0;
  mpq_set(out, enumerated ? a->enumv[kind] : a->closed[kind]);
  return 1;
}

/* Copy GMP's text of a value into buf as snprintf would, and free it. */
static size_t study_avg_put(char *s, char *buf, size_t cap) {
  size_t len = strlen(s);
  if (cap) {
    size_t k = len < cap - 1 ? len : cap - 1;
    memcpy(buf, s, k);
    buf[k] = 0;
  }
  void (*freefn)(void *, size_t);
  mp_get_memory_functions(NULL, NULL, &freefn);
  freefn(s, len + 1);
  return len;
}

size_t study_avg_text(const study_avg *a, int kind, int enumerated, int hex, char *buf,
                      size_t cap) {
  mpq_t q;
  mpq_init(q);
  size_t len = 0;
  if (cap) buf[0] = 0;
  if (study_avg_value(a, kind, enumerated, q))
    len = study_avg_put(mpq_get_str(NULL, hex ? 16 : 10, q), buf, cap);
  mpq_clear(q);
  return len;
}

double study_avg_double(const study_avg *a, int kind, int enumerated) {
  mpq_t q;
  mpq_init(q);
  double d = study_avg_value(a, kind, enumerated, q) ? mpq_get_d(q) : NAN;
  mpq_clear(q);
  return d;
}

/* ---- degree counts ------------------------------------------------------------ */

/* G^d_n = C(2n-3-d, n-2) - C(2n-3-d, n) for n >= 2 (G^0_1 = 1: the
** triangle), the solution of G^d_n = G^{d+1}_n + G^{d-1}_{n-1}, G^n_n = 0. */
void study_avg_degcount(int n, int d, mpz_t out) {
  if (n == 1) {
    mpz_set_ui(out, d == 0);
    return;
  }
  mpz_t b;
  mpz_init(b);
  unsigned long top = 2 * (unsigned long)n - 3 - (unsigned long)d;
  mpz_bin_uiui(out, top, (unsigned long)n - 2);
  mpz_bin_uiui(b, top, (unsigned long)n);
  mpz_sub(out, out, b);
  mpz_clear(b);
}

size_t study_avg_degcount_text(const study_avg *a, int d, int enumerated, int hex, char *buf,
                               size_t cap) {
  if (cap) buf[0] = 0;
  if (d < 0 || d >= a->n || (enumerated && !a->enumerated)) return 0;
  mpz_t g;
  mpz_init(g);
  if (enumerated) {
    uint64_t v = a->tot.hist[a->n][d];
    mpz_import(g, 1, -1, sizeof v, 0, 0, &v);
  } else {
    study_avg_degcount(a->n, d, g);
  }
  size_t len = study_avg_put(mpz_get_str(NULL, hex ? 16 : 10, g), buf, cap);
  mpz_clear(g);
  return len;
}

/* ---- second routes, for the tests ------------------------------------------ */

/* T_c = n + (1/C_n) sum over diagonals of the vertices their pieces hold. */
void study_avg_tc_by_chords(int n, mpq_t out) {
  mpz_t s;
  mpz_init(s);
  study_catalan_pairs(s, n, study_w_tc);
  study_over_catalan(out, s, n, 1);
  mpq_t t;
  mpq_init(t);
  mpq_set_ui(t, (unsigned long)n, 1);
  mpq_add(out, out, t);
  mpq_clears(t, NULL);
  mpz_clear(s);
}

/* L_a = sum over chords of index length times frequency, over (n-1) C_n. */
void study_avg_la_by_chords(int n, mpq_t out) {
  mpz_t s;
  mpz_init(s);
  study_catalan_pairs(s, n, study_w_len);
  study_over_catalan(out, s, n, (unsigned long)n - 1);
  mpz_clear(s);
}

/* T_i as the sum of 2(i-1)/(i+2), one fraction at a time. */
void study_avg_ti_by_sum(int n, mpq_t out) {
  mpq_t t;
  mpq_init(t);
  mpq_set_ui(out, 0, 1);
  for (unsigned long i = 1; i <= (unsigned long)n; i++) {
    mpq_set_ui(t, 2 * (i - 1), i + 2);
    mpq_canonicalize(t);
    mpq_add(out, out, t);
  }
  mpq_clear(t);
}
