/*
** flipgraph.c: directed flip graphs of convex pentagons, one rule at a time
** (flipgraph_classify) and many rules over many sampled pentagons at once
** (flipgraph_plan_*, flipgraph_tally).
**
** Labels.  v0..v4 anticlockwise, fans T_i = {v_i v_{i+2}, v_i v_{i+3}}.
** Q_j = A B C D = v_{j+1} v_{j+2} v_{j+3} v_{j+4} decides the edge
** T_{j+1} - T_{j-1}: RULE_AC (diagonal v_{j+1}v_{j+3}, in T_{j+1}) points it
** at T_{j+1}, RULE_BD (diagonal v_{j+2}v_{j+4}, in T_{j-1}) at T_{j-1}.  So
** T_i has the two edges decided by Q_{i-1} (where it is the AC side) and
** Q_{i+1} (where it is the BD side): it is a sink when dec[i-1] = AC and
** dec[i+1] = BD, a source when dec[i-1] = BD and dec[i+1] = AC.  Around the
** cycle T0 - T2 - T4 - T1 - T3, T_i sits at position 3i mod 5.
**
** Decision codes.  Five decisions in {AC, BD, EITHER} = {0, 1, 2} pack into
** code = sum dec[j] 3^j < 243; a plan keeps a 243-entry table from code to
** graph, so the per-rule work of the hot loop is the ten joint values, five
** comparisons and one table look-up.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "flipgraph.h"
#include "measure.h"
#include "census_internal.h"
#include "sampler.h"

#define FLIPGRAPH_NCODES 243
#define FLIPGRAPH_CHUNK 1024      /* pentagons per scheduling unit of tally */

/* Triangle index of each 3-subset of {0..4}, by bit mask. */
static const signed char flipgraph_mask_tri[32] = {
  -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1, 1, -1, 3, 6, -1,
  -1, -1, -1, 2, -1, 4, 7, -1, -1, 5, 8, -1, 9, -1, -1, -1};

/* The four triangles of Q_j as {ABC, ACD, ABD, BCD}.  (test_flipgraph
** checks it: flipgraph_classify, which reads this table, must agree with
** rule_eval on the quadrilateral's own points for every rule.) */
#define FLIPGRAPH_QUADS(X) \
  X(6, 8, 7, 9), X(9, 4, 3, 5), X(5, 1, 8, 2), X(2, 7, 4, 0), X(0, 3, 1, 6)
#define FLIPGRAPH_ROWS(a, b, c, d) {a, b, c, d}
static const int flipgraph_quad_tri[5][4] = {FLIPGRAPH_QUADS(FLIPGRAPH_ROWS)};

int flipgraph_tri_index(int i, int j, int k) {
  i = ((i % 5) + 5) % 5;
  j = ((j % 5) + 5) % 5;
  k = ((k % 5) + 5) % 5;
  return flipgraph_mask_tri[(1 << i) | (1 << j) | (1 << k)];
}

static const char *const flipgraph_type_names[FLIPGRAPH_NTYPES] = {
  "I", "II", "III", "IV", "V"};

const char *flipgraph_type_name(flipgraph_type t) {
  return (unsigned)t < FLIPGRAPH_NTYPES ? flipgraph_type_names[t] : "?";
}

/* ---- graphs from decisions --------------------------------------------- */

static int flipgraph_cycle_distance(int i, int k) {
  int d = ((3 * i - 3 * k) % 5 + 5) % 5;
  return d < 5 - d ? d : 5 - d;
}

/* Type and sinks of five decisions; delaunay left to the caller. */
static void flipgraph_shape(const rule_choice dec[5], flipgraph *g) {
  int source = -1;
  g->nsinks = 0;
  g->sink[0] = g->sink[1] = -1;
  g->delaunay = 0;
  for (int j = 0; j < 5; j++) g->dec[j] = dec[j];
  for (int j = 0; j < 5; j++)
    if (dec[j] == RULE_EITHER) {
      g->type = FLIPGRAPH_V;
      return;
    }
  for (int i = 0; i < 5; i++) {
    rule_choice in = dec[(i + 4) % 5], out = dec[(i + 1) % 5];
    if (in == RULE_AC && out == RULE_BD) g->sink[g->nsinks++] = i;
    if (in == RULE_BD && out == RULE_AC) source = i;
  }
  if (g->nsinks == 0) g->type = FLIPGRAPH_IV;
  else if (g->nsinks == 2) g->type = FLIPGRAPH_III;
  else /* one sink, hence one source */
    g->type = flipgraph_cycle_distance(g->sink[0], source) == 2 ? FLIPGRAPH_I : FLIPGRAPH_II;
}

void flipgraph_from_decisions(const rule_choice dec[5], int delaunay_sink, flipgraph *out) {
  flipgraph_shape(dec, out);
  out->delaunay = out->type == FLIPGRAPH_I && delaunay_sink >= 0
               && out->sink[0] == delaunay_sink;
}

static int flipgraph_code(const rule_choice dec[5]) {
  return dec[0] + 3 * (dec[1] + 3 * (dec[2] + 3 * (dec[3] + 3 * dec[4])));
}

/* ---- DT and preparation ------------------------------------------------ */

/* DT on every Q_j (exact). */
static int flipgraph_dt_decisions(const geom_point v[5], rule_choice dec[5]) {
  for (int j = 0; j < 5; j++)
    dec[j] = rule_delaunay_eval(v[(j + 1) % 5], v[(j + 2) % 5], v[(j + 3) % 5], v[(j + 4) % 5]);
  return flipgraph_code(dec);
}

/* Prepare and return the DT decision code.  The Delaunay triangulation is
** DT's unique sink; it is unique unless some Q_j is cocircular (EITHER).
** (Without EITHER, DT's graph is always type I: thesis theorem 3.) */
static int flipgraph_prepare_code(flipgraph_pentagon *p, const geom_point v[5]) {
  static const unsigned char tri[10][3] = {
    {0, 1, 2}, {0, 1, 3}, {0, 1, 4}, {0, 2, 3}, {0, 2, 4},
    {0, 3, 4}, {1, 2, 3}, {1, 2, 4}, {1, 3, 4}, {2, 3, 4}};
  for (int k = 0; k < 5; k++) p->v[k] = v[k];
  for (int t = 0; t < 10; t++)
    geom_tri_make(&p->tri[t], v[tri[t][0]], v[tri[t][1]], v[tri[t][2]]);
  rule_choice dec[5];
  int code = flipgraph_dt_decisions(v, dec);
  flipgraph g;
  flipgraph_shape(dec, &g);
  p->delaunay_sink = g.type == FLIPGRAPH_I ? g.sink[0] : -1;
  return code;
}

void flipgraph_prepare(flipgraph_pentagon *p, const geom_point v[5]) {
  (void)flipgraph_prepare_code(p, v);
}

/* ---- one rule ------------------------------------------------------------ */

void flipgraph_classify(const flipgraph_pentagon *p, const rule *r, double tie_eps,
                        flipgraph *out) {
  rule_choice dec[5];
  rule re = *r;
  rule_set_tie_eps(&re, tie_eps);
  for (int j = 0; j < 5; j++) {
    if (!rule_is_triangle(&re)) {
      geom_point q[4];
      for (int k = 0; k < 4; k++) q[k] = p->v[(j + 1 + k) % 5];
      dec[j] = rule_eval(&re, q, NULL, NULL);
    } else {
      const int *t = flipgraph_quad_tri[j];
      dec[j] = rule_eval_tris(&re, &p->tri[t[0]], &p->tri[t[1]], &p->tri[t[2]],
                              &p->tri[t[3]], NULL, NULL);
    }
  }
  flipgraph_from_decisions(dec, p->delaunay_sink, out);
}

size_t flipgraph_classify_n(geom_point *v, size_t m, const rule *rules, int nrules,
                            double tie_eps, int threads, flipgraph *out, geom_polyerr *err,
                            size_t *bad) {
  for (size_t i = 0; i < m; i++)
    if ((*err = geom_polygon_check(v + 5 * i, 5, bad, NULL)) != GEOM_OK) return i;
  long long mm = (long long)m;
#pragma omp parallel for schedule(dynamic, 256) num_threads(flipgraph_tally_threads(threads, m))
  for (long long i = 0; i < mm; i++) {
    flipgraph_pentagon p;
    flipgraph_prepare(&p, v + 5 * i);
    for (int r = 0; r < nrules; r++)
      flipgraph_classify(&p, &rules[r], tie_eps, &out[(size_t)i * (size_t)nrules + (size_t)r]);
  }
  return m;
}

/* ---- plans: many rules per pentagon -------------------------------------- */

/* The shared plan (census_internal.h: rules checked, slots, joints) and
** what is the pentagon's own: the code tables. */
struct flipgraph_plan {
  int nrules;
  double tie_eps;
  rule *rules;                       /* copy, what cp points to */
  census_plan cp;
  flipgraph graph[FLIPGRAPH_NCODES]; /* code -> graph (delaunay unset) */
  unsigned char code_type[FLIPGRAPH_NCODES];   /* code -> type */
  signed char code_sink1[FLIPGRAPH_NCODES];    /* code -> sink if type I, else -2 */
};

void flipgraph_plan_free(flipgraph_plan *pl) {
  if (pl == NULL) return;
  census_plan_free(&pl->cp);
  free(pl->rules);
  free(pl);
}

flipgraph_plan *flipgraph_plan_new(const rule *rules, int nrules, double tie_eps) {
  if (nrules < 0 || (nrules > 0 && rules == NULL)) return NULL;
  flipgraph_plan *pl = calloc(1, sizeof *pl);
  if (pl == NULL) return NULL;
  pl->nrules = nrules;
  pl->tie_eps = tie_eps;
  pl->rules = malloc((nrules > 0 ? (size_t)nrules : 1) * sizeof *pl->rules);
  if (pl->rules == NULL) goto fail;
  if (nrules > 0) memcpy(pl->rules, rules, (size_t)nrules * sizeof *rules);
  if (census_plan_make(&pl->cp, pl->rules, nrules) != 0) goto fail;
  for (int code = 0; code < FLIPGRAPH_NCODES; code++) {
    rule_choice dec[5];
    for (int j = 0, c = code; j < 5; j++, c /= 3) dec[j] = (rule_choice)(c % 3);
    flipgraph_shape(dec, &pl->graph[code]);
    pl->code_type[code] = (unsigned char)pl->graph[code].type;
    pl->code_sink1[code] = (signed char)(pl->graph[code].type == FLIPGRAPH_I ? pl->graph[code].sink[0] : -2);
  }
  return pl;
fail:
  flipgraph_plan_free(pl);
  return NULL;
}

/* ---- the hot loop: every rule at once (quadvec.c) ------------------------ */

/* Weights of the decision code: 3^q for BD, 2 * 3^q for a tie. */
static const unsigned long long flipgraph_bd_weight[5] = {1, 3, 9, 27, 81};
static const unsigned long long flipgraph_tie_weight[5] = {2, 6, 18, 54, 162};

#define FLIPGRAPH_SLOTS CENSUS_SLOTS

typedef struct flipgraph_work {
  double val[10][FLIPGRAPH_SLOTS];   /* measure of slot s on triangle t */
  double mag[10][FLIPGRAPH_SLOTS];   /* scratch of quadvec_run */
  double h[10][FLIPGRAPH_SLOTS];
  long long flags[FLIPGRAPH_SLOTS];
  unsigned long long code[JOINT_CAPACITY][FLIPGRAPH_SLOTS];   /* decision codes */
  long long tie[JOINT_CAPACITY][FLIPGRAPH_SLOTS];
} flipgraph_work;

/* Padding lanes hold harmless values (never read back). */
static void flipgraph_work_init(flipgraph_work *w) {
  for (int t = 0; t < 10; t++)
    for (int s = 0; s < FLIPGRAPH_SLOTS; s++) w->val[t][s] = w->mag[t][s] = 1.0;
}

/* flipgraph_quad_tri as offsets into the rows of flipgraph_work. */
#define FLIPGRAPH_OFF(a, b, c, d) \
  {(a) * FLIPGRAPH_SLOTS, (b) * FLIPGRAPH_SLOTS, (c) * FLIPGRAPH_SLOTS, (d) * FLIPGRAPH_SLOTS}
static const ptrdiff_t flipgraph_quad_off[5][4] = {FLIPGRAPH_QUADS(FLIPGRAPH_OFF)};

/* Codes of every (joint, slot) in use.  The batch's constants (five
** quadrilaterals, rows, weights) fold into the inlined loops. */
#if FLIPLAB_HAVE_CLONES
__attribute__((target_clones("avx2", "default")))
#endif
static void flipgraph_all_codes(const flipgraph_plan *pl, flipgraph_work *w) {
  const census_plan *cp = &pl->cp;
  const quadvec_batch b = {cp->nslots, FLIPGRAPH_SLOTS, 10, 5, flipgraph_quad_off,
                     flipgraph_bd_weight, flipgraph_tie_weight, cp->slot_sign, pl->tie_eps,
                     cp->joint_used, &w->val[0][0], &w->mag[0][0], &w->h[0][0], w->flags,
                     &w->code[0][0], &w->tie[0][0]};
  quadvec_run(&b);
}

/* Decision codes of every rule of the plan for one prepared pentagon whose
** DT code is dt_code. */
static void flipgraph_plan_codes(const flipgraph_plan *pl, const flipgraph_pentagon *p,
                                 int dt_code, flipgraph_work *w, unsigned char *codes) {
  const census_plan *cp = &pl->cp;
  if (cp->eval_all_ok) {
    double all[MEASURE_MAX];
    for (int t = 0; t < 10; t++) {
      measure_eval_all(&p->tri[t], all);
      for (int s = 0; s < cp->nslots; s++) w->val[t][s] = all[cp->slot_measure[s]];
    }
  } else {
    for (int s = 0; s < cp->nslots; s++) {
      const measure *m = measure_get(cp->slot_measure[s]);
      for (int t = 0; t < 10; t++) w->val[t][s] = m->fn(&p->tri[t], m->ctx);
    }
  }
  flipgraph_all_codes(pl, w);
  for (int i = 0; i < pl->nrules; i++) {
    const census_item *it = &cp->item[i];
    if (it->kind == CENSUS_TRIANGLE) {
      codes[i] = (unsigned char)w->code[it->joint][it->slot];
    } else if (it->kind == CENSUS_DT) {
      codes[i] = (unsigned char)dt_code;
    } else {
      flipgraph g;
      flipgraph_classify(p, &pl->rules[i], pl->tie_eps, &g);
      codes[i] = (unsigned char)flipgraph_code(g.dec);
    }
  }
}

void flipgraph_plan_run(const flipgraph_plan *pl, const flipgraph_pentagon *p,
                        flipgraph *out) {
  unsigned char stackcodes[256], *codes = stackcodes;
  if (pl->nrules > 256 && (codes = malloc((size_t)pl->nrules)) == NULL) {
    /* Out of memory: fall back to one rule at a time. */
    for (int i = 0; i < pl->nrules; i++)
      flipgraph_classify(p, &pl->rules[i], pl->tie_eps, &out[i]);
    return;
  }
  rule_choice dec[5];
  flipgraph_work w;
  flipgraph_work_init(&w);
  int dt_code = pl->cp.ndt > 0 ? flipgraph_dt_decisions(p->v, dec) : 0;
  flipgraph_plan_codes(pl, p, dt_code, &w, codes);
  for (int i = 0; i < pl->nrules; i++) {
    out[i] = pl->graph[codes[i]];
    out[i].delaunay = out[i].type == FLIPGRAPH_I && p->delaunay_sink >= 0
                   && out[i].sink[0] == p->delaunay_sink;
  }
  if (codes != stackcodes) free(codes);
}

/* ---- tally --------------------------------------------------------------- */

/* A tally's state: per thread (census_loop's thread numbers) its counts,
** decision codes and (with a hook) graphs, rows of nr. */
typedef struct flipgraph_tallyctx {
  const flipgraph_plan *pl;
  const flipgraph_run *run;
  size_t nr;
  flipgraph_counts *all;
  unsigned char *codes;
  flipgraph *graphs;        /* when the run has a hook */
} flipgraph_tallyctx;

static void flipgraph_hook(const flipgraph_tallyctx *t, int thread, uint64_t i,
                           const flipgraph_pentagon *p) {
  const flipgraph_plan *pl = t->pl;
  const unsigned char *codes = t->codes + (size_t)thread * t->nr;
  flipgraph *graphs = t->graphs + (size_t)thread * t->nr;
  for (int r = 0; r < pl->nrules; r++) {
    flipgraph *g = &graphs[r];
    *g = pl->graph[codes[r]];
    g->delaunay = g->type == FLIPGRAPH_I && p->delaunay_sink >= 0
               && g->sink[0] == p->delaunay_sink;
  }
  t->run->each(t->run->each_ctx, thread, i, p, graphs);
}

/* One chunk (a census_range_fn): -1 when run->sampler runs out of memory. */
static int flipgraph_tally_range(void *ctx, int thread, uint64_t lo, uint64_t hi) {
  const flipgraph_tallyctx *t = ctx;
  const flipgraph_plan *pl = t->pl;
  const flipgraph_run *run = t->run;
  unsigned char *codes = t->codes + (size_t)thread * t->nr;
  flipgraph_counts *c = t->all + (size_t)thread * t->nr;
  flipgraph_pentagon p;
  flipgraph_work w;
  geom_point v[5];
  flipgraph_work_init(&w);
  for (uint64_t i = lo; i < hi; i++) {
    if (run->sampler == NULL) sampler_pentagon(run->seed, i, v);
    else if (run->sampler(run->seed, i, v) != 0) return -1;
    int dt_code = flipgraph_prepare_code(&p, v);
    flipgraph_plan_codes(pl, &p, dt_code, &w, codes);
    for (int r = 0; r < pl->nrules; r++) {
      int code = codes[r];
      c[r].type[pl->code_type[code]]++;
      c[r].dt += pl->code_sink1[code] == p.delaunay_sink;
    }
    if (run->each != NULL) flipgraph_hook(t, thread, i, &p);
  }
  for (int r = 0; r < pl->nrules; r++) c[r].samples += hi - lo;
  return 0;
}

int flipgraph_tally_threads(int threads, uint64_t count) {
  return census_threads(threads, count, FLIPGRAPH_CHUNK);
}

/* Per-thread sums, added in thread order (integers: any order gives the same). */
static void flipgraph_tally_sum(const flipgraph_counts *all, int threads, int nrules,
                                flipgraph_counts *out) {
  for (int t = 0; t < threads; t++)
    for (int r = 0; r < nrules; r++) {
      const flipgraph_counts *c = &all[(size_t)t * (size_t)nrules + (size_t)r];
      out[r].samples += c->samples;
      for (int y = 0; y < FLIPGRAPH_NTYPES; y++) out[r].type[y] += c->type[y];
      out[r].dt += c->dt;
    }
}

int flipgraph_tally_run(const rule *rules, int nrules, const flipgraph_run *run,
                        flipgraph_counts *out) {
  if (run->first + run->count < run->first || (nrules > 0 && out == NULL) ||
      geom_threads_check(run->threads, NULL, 0) != 0)
    return -1;
  flipgraph_plan *pl = flipgraph_plan_new(rules, nrules, run->tie_eps);
  if (pl == NULL) return -1;
  int threads = flipgraph_tally_threads(run->threads, run->count);
  size_t nr = nrules > 0 ? (size_t)nrules : 1, cells = (size_t)threads * nr;
  flipgraph_tallyctx t = {pl, run, nr, calloc(cells, sizeof *t.all), malloc(cells),
                          run->each ? malloc(cells * sizeof *t.graphs) : NULL};
  census_loop loop = {run->first, run->count, FLIPGRAPH_CHUNK, threads, flipgraph_tally_range,
                      &t, run->progress, run->progress_ctx};
  int rc = -1;
  if (t.all != NULL && t.codes != NULL && (run->each == NULL || t.graphs != NULL) &&
      census_loop_run(&loop) == 0) {
    flipgraph_tally_sum(t.all, threads, nrules, out);
    rc = 0;
  }
  free(t.all);
  free(t.codes);
  free(t.graphs);
  flipgraph_plan_free(pl);
  return rc;
}

int flipgraph_tally(const rule *rules, int nrules, uint64_t seed, uint64_t first,
                    uint64_t count, double tie_eps, int threads,
                    flipgraph_counts *out, census_progress_fn progress, void *ctx) {
  flipgraph_run run = {seed, first, count, tie_eps, threads, progress, ctx, NULL, NULL, NULL};
  return flipgraph_tally_run(rules, nrules, &run, out);
}

void flipgraph_use_portable(int on) {
  quadvec_use_scalar(on);
}
