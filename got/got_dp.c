/*
** got_dp.c: the GOT dynamic programme (thesis Algorithm 1) in key space.
**
** Table.  One n x n array M of keys: M[i][j] = B(i, j) for i < j, mirrored
** to M[j][i], so that for a cell (i, j) both B(i, k) (row i) and B(k, j)
** (row j of the mirror) are read contiguously in k.  The argmin k of each
** cell sits in a packed upper triangle of int32.  Cells with j = i + 1 (the
** empty chain, the joint's identity) are never written nor read: the k = i+1
** term of a cell has no left part and the k = j-1 term no right part, and
** both are peeled off the loop.
**
** Order.  The upper triangle is cut into T x T tiles.  Tile (I, J) needs
** only tiles (I, K) with K <= J and (K, J) with K >= I, so the tiles of one
** tile-diagonal J - I = D are independent once all D' < D are done: they
** are shared among the threads (one implicit barrier per D).  Inside a tile,
** rows go bottom-up and columns left to right, which satisfies the tile's
** own dependencies.  Each cell reads rows i and j over k in (i, j); the T
** cells of a tile row share row i and the T cells of a tile column share
** row j, so each row fetched from memory is used about T times.
**
** Each cell is computed entirely by one thread, in the same order, so the
** result is bit-identical whatever the thread count.  Ties: a candidate
** replaces the best only when strictly smaller, so the smallest k wins.
*/
#define _POSIX_C_SOURCE 200809L
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <omp.h>
#include "measure.h"
#include "got_internal.h"

#define GOT_TILE 32

/* How a measure value becomes a key: the bulk form of the key shape the
** joint table gives (joint.h), for measures of sign s (0 and +1 take the
** form for values >= 0, as joint_key does). */
got_keyfn got_keyfn_of(joint_shape sh, int s) {
  switch (sh) {
    case JOINT_SHAPE_SAME: return GOT_KEY_IDENT;
    case JOINT_SHAPE_SQUARE: return s >= 0 ? GOT_KEY_SQ : GOT_KEY_NEGSQ;
    case JOINT_SHAPE_NEGRECIP: return GOT_KEY_NEGRECIP;   /* -(-1/-x) is -1/x bit for bit */
    case JOINT_SHAPE_LOG: return s >= 0 ? GOT_KEY_LOG : GOT_KEY_NEGLOGNEG;
    case JOINT_SHAPE_POWER: return GOT_KEY_POWER;
  }
  return GOT_KEY_POWER;
}

typedef struct got_dp {
  size_t n;
  got_pairs *pd;
  joint_id joint;
  int sign;
  joint_keyop op;
  got_keyfn keyfn;
  double p;             /* the joint's exponent (GOT_KEY_POWER) */
  double *M;            /* n x n keys, mirrored */
  int32_t *K;           /* packed upper triangle: argmin k */
  const unsigned char *V;   /* simple polygons: n x n, 1 = edge or valid diagonal;
                               NULL for convex ones (everything valid) */
} got_dp;

static inline size_t got_kidx(size_t n, size_t i, size_t j) {
  return i * n - i * (i + 1) / 2 + (j - i - 1);
}

/* Turn m measure values into keys, in place. */
GOT_CLONES static void got_keys(const got_dp *dp, double *t, size_t m) {
  switch (dp->keyfn) {
    case GOT_KEY_IDENT: return;
    case GOT_KEY_SQ: for (size_t q = 0; q < m; q++) t[q] = t[q] * t[q]; return;
    case GOT_KEY_NEGSQ: for (size_t q = 0; q < m; q++) t[q] = -(t[q] * t[q]); return;
    case GOT_KEY_NEGRECIP: for (size_t q = 0; q < m; q++) t[q] = -1 / t[q]; return;
    case GOT_KEY_LOG: got_log_inplace(t, m, 1.0); return;
    case GOT_KEY_NEGLOGNEG: got_log_inplace(t, m, -1.0); return;
    case GOT_KEY_FROM_SQ_IDENT: return;
    case GOT_KEY_FROM_SQ_HALFLOG:
      got_log_inplace(t, m, 1.0);
      for (size_t q = 0; q < m; q++) t[q] *= 0.5;
      return;
    case GOT_KEY_POWER:
      for (size_t q = 0; q < m; q++) t[q] = joint_key_shape(JOINT_SHAPE_POWER, dp->p, dp->sign, t[q]);
      return;
  }
}

/* Keys of the triangles (i, k, j) for k in (i, j) into t[0 .. j-i-2]. */
static void got_tri_keys(const got_dp *dp, size_t i, size_t j, double *t) {
  got_pairs_eval(dp->pd, i, j, i + 1, j, t);
  got_keys(dp, t, j - i - 1);
}

#define GOT_ADD(a, b) ((a) + (b))
#define GOT_MIN(a, b) ((a) < (b) ? (a) : (b))
#define GOT_MAX(a, b) ((a) > (b) ? (a) : (b))

/* One cell, for one key operation.  NaN candidates (only from degenerate
** triangles) never win: they fail the strict comparison. */
#define GOT_CELL(name, COMB) \
  static void name(got_dp *dp, size_t i, size_t j, double *t) { \
    const size_t n = dp->n, d = j - i; \
    got_tri_keys(dp, i, j, t); \
    double best = t[0]; \
    size_t bk = i + 1; \
    if (d > 2) { \
      const double *Bi = dp->M + i * n, *Bj = dp->M + j * n; \
      best = INFINITY; \
      double c = COMB(t[0], Bj[i + 1]);              /* k = i+1: no left part */ \
      if (c < best) best = c; \
      const double *tk = t - (i + 1); \
      for (size_t k = i + 2; k + 1 < j; k++) { \
        c = COMB(COMB(Bi[k], tk[k]), Bj[k]); \
        if (c < best) { best = c; bk = k; } \
      } \
      c = COMB(Bi[j - 1], t[d - 2]);                 /* k = j-1: no right part */ \
      if (c < best) { best = c; bk = j - 1; } \
    } \
    dp->M[i * n + j] = best; \
    dp->M[j * n + i] = best; \
    dp->K[got_kidx(n, i, j)] = (int32_t)bk; \
  }

GOT_CELL(got_cell_add, GOT_ADD)
GOT_CELL(got_cell_min, GOT_MIN)
GOT_CELL(got_cell_max, GOT_MAX)

/* Simple polygons.  Split k is allowed when (i, k) and (k, j) are edges or
** valid diagonals; cell (i, j) exists only when (i, j) is one (every chain
** cut off by a valid diagonal is a simple polygon, so it has at least one
** allowed split).  The triangle keys are computed for runs of allowed k
** only: a disallowed k may make a degenerate triangle, which a user
** measure should never see.  Same candidate expressions and the same
** smallest-k tie rule as GOT_CELL. */
static size_t got_tri_keys_masked(const got_dp *dp, size_t i, size_t j, double *t) {
  const size_t n = dp->n;
  const unsigned char *Vi = dp->V + i * n, *Vj = dp->V + j * n;
  size_t count = 0;
  for (size_t k = i + 1; k < j;) {
    if (!(Vi[k] & Vj[k])) { k++; continue; }
    size_t k1 = k + 1;
    while (k1 < j && (Vi[k1] & Vj[k1])) k1++;
    got_pairs_eval(dp->pd, i, j, k, k1, t + (k - i - 1));
    got_keys(dp, t + (k - i - 1), k1 - k);
    count += k1 - k;
    k = k1;
  }
  return count;
}

#define GOT_CELLM(name, COMB) \
  static void name(got_dp *dp, size_t i, size_t j, double *t) { \
    const size_t n = dp->n; \
    const unsigned char *Vi = dp->V + i * n, *Vj = dp->V + j * n; \
    if (!Vi[j]) return; \
    got_tri_keys_masked(dp, i, j, t); \
    const double *Bi = dp->M + i * n, *Bj = dp->M + j * n, *tk = t - (i + 1); \
    double best = INFINITY; \
    size_t bk = 0; \
    for (size_t k = i + 1; k < j; k++) { \
      if (!(Vi[k] & Vj[k])) continue; \
      double c = k == i + 1 ? (k + 1 == j ? tk[k] : COMB(tk[k], Bj[k])) \
               : k + 1 == j ? COMB(Bi[k], tk[k]) : COMB(COMB(Bi[k], tk[k]), Bj[k]); \
      if (bk == 0) bk = k; \
      if (c < best) { best = c; bk = k; } \
    } \
    dp->M[i * n + j] = best; \
    dp->M[j * n + i] = best; \
    dp->K[got_kidx(n, i, j)] = (int32_t)bk; \
  }

GOT_CELLM(got_cellm_add, GOT_ADD)
GOT_CELLM(got_cellm_min, GOT_MIN)
GOT_CELLM(got_cellm_max, GOT_MAX)

typedef void (*got_cell_fn)(got_dp *dp, size_t i, size_t j, double *t);

static got_cell_fn got_cell_pick(const got_dp *dp) {
  static const got_cell_fn fn[2][3] = {
    {got_cell_add, got_cell_min, got_cell_max},
    {got_cellm_add, got_cellm_min, got_cellm_max}};
  int o = dp->op == JOINT_KEY_ADD ? 0 : dp->op == JOINT_KEY_MIN ? 1 : 2;
  return fn[dp->V != NULL][o];
}

static void got_run(got_dp *dp, int threads, double *tmp) {
  const size_t n = dp->n, T = GOT_TILE, nb = (n + T - 1) / T;
  got_cell_fn cell = got_cell_pick(dp);
#pragma omp parallel num_threads(threads)
  {
    double *t = tmp + (size_t)omp_get_thread_num() * n;
    for (size_t D = 0; D < nb; D++) {
      long ntiles = (long)(nb - D);
#pragma omp for schedule(dynamic, 1)
      for (long I = 0; I < ntiles; I++) {
        size_t J = (size_t)I + D;
        size_t i0 = (size_t)I * T, i1 = i0 + T < n ? i0 + T : n;
        size_t j0 = J * T, j1 = j0 + T < n ? j0 + T : n;
        for (size_t i = i1; i-- > i0;)
          for (size_t j = j0 > i + 2 ? j0 : i + 2; j < j1; j++) cell(dp, i, j, t);
      }
    }
  }
}

/* ---- runner-up along the optimal tree ---- */

static inline double got_comb(joint_keyop op, double a, double b) {
  return op == JOINT_KEY_ADD ? GOT_ADD(a, b) : op == JOINT_KEY_MIN ? GOT_MIN(a, b)
                                                                    : GOT_MAX(a, b);
}

/* The candidate of split k in cell (i, j) given the triangle key tk and
** (optionally) replacement values for the left and right parts; the same
** expression, in the same order, as GOT_CELL. */
static double got_cand(const got_dp *dp, size_t i, size_t k, size_t j, double tk,
                       const double *left, const double *right) {
  const size_t n = dp->n;
  int hasl = k > i + 1, hasr = k + 1 < j;
  double l = left ? *left : dp->M[i * n + k], r = right ? *right : dp->M[j * n + k];
  if (!hasl && !hasr) return tk;
  if (!hasl) return got_comb(dp->op, tk, r);
  if (!hasr) return got_comb(dp->op, l, tk);
  return got_comb(dp->op, got_comb(dp->op, l, tk), r);
}

typedef struct got_node {
  size_t i, k, j;
  long left, right;     /* child cells (chains of length >= 2), or -1 */
  int has2;
  double second;
} got_node;

/* Backtrack from (0, n-1) in pre-order; children get larger indices. */
static int got_backtrack(const got_dp *dp, got_node *node) {
  const size_t n = dp->n;
  typedef struct { size_t i, j; long parent; int side; } item;
  item *stack = malloc(n * sizeof *stack);
  if (stack == NULL) return -1;
  size_t sp = 0, count = 0;
  stack[sp++] = (item){0, n - 1, -1, 0};
  while (sp > 0) {
    item it = stack[--sp];
    size_t k = (size_t)dp->K[got_kidx(n, it.i, it.j)];
    long me = (long)count++;
    node[me] = (got_node){it.i, k, it.j, -1, -1, 0, 0};
    if (it.parent >= 0) {
      if (it.side == 0) node[it.parent].left = me;
      else node[it.parent].right = me;
    }
    if (it.j - k >= 2) stack[sp++] = (item){k, it.j, me, 1};
    if (k - it.i >= 2) stack[sp++] = (item){it.i, k, me, 0};
  }
  free(stack);
  return 0;
}

/* second(i, j) = min( min over k != k* of candidate(k),
**                     candidate(k*) with second(left), with second(right) ).
** Every triangulation other than the best uses either another k at the
** root or, at k*, a non-best triangulation of one side, and the second
** smallest of a monotone combination of two independent sets is reached by
** replacing exactly one part by its second smallest. */
static void got_runner_up(const got_dp *dp, got_node *node, size_t count, double *t) {
  for (size_t q = count; q-- > 0;) {
    got_node *c = &node[q];
    size_t i = c->i, j = c->j;
    double best2 = INFINITY;
    int has = 0;
    const unsigned char *Vi = dp->V ? dp->V + i * dp->n : NULL, *Vj = Vi ? dp->V + j * dp->n : NULL;
    if (Vi) got_tri_keys_masked(dp, i, j, t);
    else got_tri_keys(dp, i, j, t);
    for (size_t k = i + 1; k < j; k++) {
      if (k == c->k || (Vi && !(Vi[k] & Vj[k]))) continue;
      double v = got_cand(dp, i, k, j, t[k - i - 1], NULL, NULL);
      if (!has || v < best2) best2 = v;
      has = 1;
    }
    double tk = t[c->k - i - 1];
    if (c->left >= 0 && node[c->left].has2) {
      double v = got_cand(dp, i, c->k, j, tk, &node[c->left].second, NULL);
      if (!has || v < best2) best2 = v;
      has = 1;
    }
    if (c->right >= 0 && node[c->right].has2) {
      double v = got_cand(dp, i, c->k, j, tk, NULL, &node[c->right].second);
      if (!has || v < best2) best2 = v;
      has = 1;
    }
    c->has2 = has;
    c->second = best2;
  }
}

/* ---- memory ---- */

size_t got_memory_needed(size_t n, int measure) {
  if (n > ((size_t)1 << 26)) return SIZE_MAX;   /* n^2 * 40 would overflow */
  size_t tables = 1 + (size_t)got_kernel_tables(measure);
  return n * n * sizeof(double) * tables          /* keys + pair tables */
       + n * (n - 1) / 2 * sizeof(int32_t)        /* argmin */
       + n * n                                    /* valid diagonals (simple polygons) */
       + n * (sizeof(got_node) + 64);             /* backtracking, buffers */
}

size_t got_phys_memory(void) {
  long pages = sysconf(_SC_PHYS_PAGES), psize = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || psize <= 0) return (size_t)8 << 30;   /* assume 8 GiB */
  return (size_t)pages * (size_t)psize;
}

int got_check_memory(size_t n, int measure, char *err, size_t errlen) {
  size_t need = got_memory_needed(n, measure), have = got_phys_memory() / 4 * 3;
  if (n <= INT32_MAX && need <= have) return 0;
  if (need == SIZE_MAX)
    snprintf(err, errlen, "n = %zu is far too large: the O(n^2) tables would need "
             "more than %.3g TB", n, (double)n * (double)n * 20 / 1e12);
  else
    snprintf(err, errlen, "n = %zu needs %.2f GB of tables (Theta(n^2)), more than the "
             "%.2f GB allowed (3/4 of physical memory)", n, need / 1e9, have / 1e9);
  return -1;
}

/* ---- results ---- */

void got_format_total(const got_result *res, double key, char *buf, size_t len) {
  double v = joint_unkey(res->joint, res->sign, key);
  int tiny = v == 0 || !isfinite(v) || fabs(v) < DBL_MIN;
  if (joint_get(res->joint)->key == JOINT_SHAPE_LOG && tiny && isfinite(key)) {
    /* key = ln|B| for values >= 0, -ln|B| for values <= 0 */
    if (res->sign >= 0) snprintf(buf, len, "exp(%.17g)", key);
    else snprintf(buf, len, "-exp(%.17g)", -key);
    return;
  }
  snprintf(buf, len, "%.17g", v);
}

void got_result_free(got_result *res) {
  if (res == NULL) return;
  free(res->tri);
  res->tri = NULL;
  res->ntri = 0;
}

/* ---- got_solve, step by step ---- */

/* The rule and the size: a triangle-based rule, n >= 3, tables that fit. */
static int got_solve_check(size_t n, const rule *r, char *err, size_t errlen) {
  if (!rule_is_triangle(r)) {
    snprintf(err, errlen, "rule %s is not triangle-based: GOT needs a measure and a "
             "joint (MEASURE_JOINT, e.g. R_inf)", r->name);
    return -1;
  }
  if (n < 3) {
    snprintf(err, errlen, "a polygon needs at least 3 vertices, got %zu", n);
    return -1;
  }
  return got_check_memory(n, rule_measure(r), err, errlen);
}

/* Convex (strictly, anticlockwise) polygons take the unmasked fast path;
** anything else must be a simple anticlockwise polygon, whose valid
** diagonals go into *V.  Both tests are exact. */
static int got_solve_shape(const geom_point *p, size_t n, int threads, int force_mask,
                           unsigned char **V, char *err, size_t errlen) {
  *V = NULL;
  geom_point *q = malloc(n * sizeof *q);
  if (q == NULL) goto oom;
  memcpy(q, p, n * sizeof *q);
  size_t bad = 0, bad2 = 0;
  int rev = 0;
  geom_polyerr e = geom_polygon_check(q, n, &bad, &rev);
  if (e == GEOM_OK && !rev && !force_mask) {
    free(q);
    return 0;
  }
  memcpy(q, p, n * sizeof *q);
  e = geom_simple_polygon_check(q, n, &bad, &bad2, &rev);
  free(q);
  if (e == GEOM_CROSSING) {
    snprintf(err, errlen, "polygon is not simple: edges %zu-%zu and %zu-%zu meet", bad,
             (bad + 1) % n, bad2, (bad2 + 1) % n);
    return -1;
  }
  if (e != GEOM_OK || rev) {
    snprintf(err, errlen, "vertex %zu: %s", bad,
             e != GEOM_OK ? geom_polyerr_str(e) : "polygon is clockwise (need anticlockwise)");
    return -1;
  }
  *V = malloc(n * n);
  if (*V == NULL || got_valid_diagonals(p, n, *V, threads) != 0) goto oom;
  return 0;
oom:
  free(*V);                   /* the table may be there when its filling failed */
  *V = NULL;
  snprintf(err, errlen, "out of memory for the diagonals of n = %zu", n);
  return -1;
}

/* Keys and kernels for the rule (sigma-type measures hand out b^2). */
static int got_dp_init(got_dp *dp, const geom_point *p, size_t n, const rule *r, int threads) {
  const measure *m = measure_get(rule_measure(r));
  dp->n = n;
  dp->joint = rule_joint(r);
  dp->sign = (int)m->sign;
  const joint *J = joint_get(rule_joint(r));
  dp->op = J->keyop;
  dp->p = J->p;
  dp->keyfn = got_keyfn_of(J->key, dp->sign);
  if (got_measure_has_square(rule_measure(r)) && dp->sign > 0 &&
      (dp->keyfn == GOT_KEY_SQ || dp->keyfn == GOT_KEY_LOG)) {
    dp->keyfn = dp->keyfn == GOT_KEY_SQ ? GOT_KEY_FROM_SQ_IDENT : GOT_KEY_FROM_SQ_HALFLOG;
    dp->pd = got_pairs_new_sq(p, n, rule_measure(r), threads);
  } else {
    dp->pd = got_pairs_new(p, n, rule_measure(r), threads);
  }
  dp->M = malloc(n * n * sizeof *dp->M);
  dp->K = malloc((n * (n - 1) / 2) * sizeof *dp->K);
  return dp->pd && dp->M && dp->K ? 0 : -1;
}

static void got_dp_free(got_dp *dp) {
  got_pairs_free(dp->pd);
  free(dp->M);
  free(dp->K);
}

/* Totals, runner-up, gap and the triangles (badness from measure_eval). */
static void got_result_fill(got_result *out, const got_dp *dp, const got_node *node,
                            const geom_point *p, const rule *r, const got_options *opt) {
  const size_t n = dp->n, count = n - 2;
  out->n = n;
  out->measure = rule_measure(r);
  out->joint = rule_joint(r);
  out->sign = dp->sign;
  out->key = dp->M[n - 1];
  out->total = joint_unkey(rule_joint(r), dp->sign, out->key);
  out->has_runner_up = node[0].has2;
  out->tie_eps = opt ? opt->tie_eps : RULE_DEFAULT_TIE_EPS;
  if (out->has_runner_up) {
    out->key2 = node[0].second;
    out->total2 = joint_unkey(rule_joint(r), dp->sign, out->key2);
    out->gap = out->total2 - out->total;
    out->rel_gap = rule_gap(r, out->key, out->key2);
    out->unique = !(out->rel_gap <= out->tie_eps);
  } else {
    out->key2 = out->total2 = INFINITY;
    out->gap = out->rel_gap = INFINITY;
    out->unique = 1;
  }
  for (size_t q = 0; q < count; q++) {
    geom_tri t;
    geom_tri_make(&t, p[node[q].i], p[node[q].k], p[node[q].j]);
    out->tri[q] = (got_triangle){(int)node[q].i, (int)node[q].k, (int)node[q].j,
                                 measure_eval(rule_measure(r), &t)};
  }
  out->ntri = count;
  out->simple = dp->V != NULL;
}

int got_solve(const geom_point *p, size_t n, const rule *r, const got_options *opt,
              got_result *out, char *err, size_t errlen) {
  return got_solve_ex(p, n, r, opt, 0, out, err, errlen);
}

int got_solve_ex(const geom_point *p, size_t n, const rule *r, const got_options *opt,
                 int force_mask, got_result *out, char *err, size_t errlen) {
  memset(out, 0, sizeof *out);
  if (got_solve_check(n, r, err, errlen) != 0) return -1;
  if (opt != NULL && geom_threads_check(opt->threads, err, errlen) != 0) return -1;
  int threads = geom_threads_clamp(opt ? opt->threads : 0, omp_get_max_threads());
  double t0 = omp_get_wtime();
  got_dp dp = {0};
  unsigned char *V = NULL;
  if (got_solve_shape(p, n, threads, force_mask, &V, err, errlen) != 0) return -1;
  dp.V = V;
  int rc = got_dp_init(&dp, p, n, r, threads);
  double *tmp = malloc((size_t)threads * n * sizeof *tmp);
  got_node *node = malloc(n * sizeof *node);
  out->tri = malloc(n * sizeof *out->tri);
  if (rc != 0 || tmp == NULL || node == NULL || out->tri == NULL) {
    snprintf(err, errlen, "out of memory for n = %zu (%.2f GB)", n,
             got_memory_needed(n, rule_measure(r)) / 1e9);
    rc = -1;
    goto done;
  }
  got_run(&dp, threads, tmp);
  if (got_backtrack(&dp, node) != 0) {
    snprintf(err, errlen, "out of memory while backtracking");
    rc = -1;
    goto done;
  }
  got_runner_up(&dp, node, n - 2, tmp);
  got_result_fill(out, &dp, node, p, r, opt);
  got_certify(out, p, n, dp.keyfn, dp.op);
  out->threads = threads;
  out->seconds = omp_get_wtime() - t0;
done:
  if (rc != 0) got_result_free(out);
  got_dp_free(&dp);
  free(V);
  free(tmp);
  free(node);
  return rc;
}
