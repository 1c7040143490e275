/*
** sitecensus.c: the census of directed flip graphs over many random site
** sets and many rules (`fliplab census`), and the search for a witness.
**
** Per sample: draw the sites, get the flip graph (convex n-gons all share
** one shape, built once per thread and moved to each sample; other sets
** are enumerated afresh), evaluate every measure once per triangle, then
** per rule decide every quadrilateral once, find the sinks, and for
** triangle-based rules the worst sink's gap to the GOT.
**
** Decisions are rule_eval_tris's, bit for bit: the same measure values
** (measure_eval_all computes the registry's expressions), and in the
** packed loop the joint and comparison written out with the same IEEE
** operations in the same order as joint_apply (joint.c) and
** joint_compare_values; for the product and root-sum-square on slots with
** magnitudes outside [2^-511, 2^511] (where the plain evaluation could
** leave the normal range), joint_compare itself, in split form.  Inside
** that range every product, square and sum of squares is a normal double,
** so plain and split forms agree bit for bit.  The tests compare every
** rule's census with siteflip_direct sample by sample.
**
** Sinks.  With at most 64 quadrilaterals the decisions pack into one word
** (bit q = 1 for BD); node u is a sink iff (bits & qmask[u]) == want[u],
** where qmask[u] marks the quadrilaterals of u's flips and want[u] those
** where u holds BD.  Larger graphs walk the edge list.  Packed graphs are
** counted by entry of the decision bits (one per measure and joint), and
** the convex shape's masks come from per-byte tables (siteflip_cwork_tables).
**
** GOT shortcut.  A flip that a triangle rule strictly prefers never
** raises the total badness: the total is the joint over all triangles, the
** joint is non-decreasing in each argument, and the flip lowers the joint
** of the two triangles it replaces.  Flipping from a GOT as the rule says
** therefore stays at GOT's total and, the rule having no cycles (theorem
** 1), ends in a sink: some sink attains the GOT.  So with no tie, one sink
** means gap 0, and with several the GOT is the best sink; no other
** triangulation's total is needed.  (test_siteflip checks best sink = GOT
** against brute force and `got`; test_census that census and
** siteflip_direct agree sample by sample.)
**
** Thread and shard independence: each sample depends only on (seed, i),
** the counts are integers, and each sample's gap is rounded to a multiple
** of SITEFLIP_GAP_UNIT before it is added.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "siteflip_internal.h"
#include "measure.h"
#include "joint.h"
#include "census_internal.h"
#include "sampler.h"

#define SITEFLIP_CHUNK 256
_Static_assert(SITEFLIP_MAX_SITES < SAMPLER_HULL_MAX, "the samplers draw every site count");
#define SITEFLIP_SLOTS CENSUS_SLOTS

typedef struct siteflip_crule {
  int quad;              /* whole-quadrilateral rule */
  int dt;                /* the DT rule */
  int slot;
  int bit;               /* joint * nv + slot: the rule's entry of bits and tie */
  int next;              /* the next rule of the same entry (or quadrilateral rule), -1 */
  joint_id joint;
  int msign;             /* the measure's sign */
  joint_keyop keyop;     /* how keys of triangles combine */
  double key0;           /* the identity of keyop */
} siteflip_crule;

/* The shared plan (census_internal.h: rules checked, slots in measure
** order with their signs, joints in use) and what the site sets add. */
typedef struct siteflip_cplan {
  census_plan cp;
  const rule *rules;
  int nrules, nv, eval_all;           /* nv: slots padded to whole vectors */
  int nruns, run_slot[MEASURE_MAX], run_len[MEASURE_MAX];   /* slots of consecutive measures */
  siteflip_crule *cr;
  double eps;
  int nentries;                       /* joint_count() * nv */
  int entry_rule[JOINT_CAPACITY * SITEFLIP_SLOTS];   /* first rule of each entry, -1 */
  int first_quad;                     /* first quadrilateral rule, -1 */
  size_t memory;                      /* each set's flip graph budget (siteflip_limits) */
} siteflip_cplan;

typedef struct siteflip_cwork {
  siteflip_graph *shape;     /* convex: the one shape, moved to each sample */
  uint64_t *stab;            /* the shape's sink tables [nstab][256] (siteflip_cwork_tables) */
  int nstab;                 /* 0: none */
  uint64_t dtbits;           /* with tables: DT's BD bits, and whether some is a tie */
  int dttied;
  double *val, *mag, *h;     /* values, magnitudes, scratch: [triangle][nv] */
  size_t valcap, magcap, hcap;
  long long flags[SITEFLIP_SLOTS];
  unsigned long long bits[JOINT_CAPACITY * SITEFLIP_SLOTS];  /* [joint][nv]: BD decisions by quadrilateral */
  long long tie[JOINT_CAPACITY * SITEFLIP_SLOTS];            /* [joint][nv]: non-zero: some tie */
  ptrdiff_t qoff[QUADVEC_MAX_QUADS][4];   /* quadrilaterals' triangle rows, times nv */
  rule_choice *dec, *dtdec;          /* one rule's decisions; DT's */
  size_t deccap, dtcap;
  uint64_t *qmask, *want;
  /* Packed graphs (siteflip_count_entries), by entry of bits: sink
  ** masks, and the running counts of siteflip_flush. */
  uint64_t emask[JOINT_CAPACITY * SITEFLIP_SLOTS];
  uint64_t etie[JOINT_CAPACITY * SITEFLIP_SLOTS], eone[JOINT_CAPACITY * SITEFLIP_SLOTS];
  uint64_t edt[JOINT_CAPACITY * SITEFLIP_SLOTS];
  uint64_t eother[JOINT_CAPACITY * SITEFLIP_SLOTS];   /* 1: no sink or several, no tie */
  int emulti[JOINT_CAPACITY * SITEFLIP_SLOTS + 1];
  unsigned char *out;
  double *key;
  int *sinks;
  size_t nodecap;
  /* The first set this thread could not enumerate, -1; why; over budget? */
  int64_t fail_at;
  int fail_over;
  char fail_err[256];
} siteflip_cwork;

/* Runs of consecutive measures among the slots, which siteflip_values
** copies as blocks out of measure_eval_all. */
static void siteflip_cplan_runs(siteflip_cplan *pl) {
  const census_plan *cp = &pl->cp;
  for (int s = 0; s < cp->nslots; s++) {
    if (s > 0 && cp->slot_measure[s - 1] == cp->slot_measure[s] - 1) {
      pl->run_len[pl->nruns - 1]++;
    } else {
      pl->run_slot[pl->nruns] = s;
      pl->run_len[pl->nruns++] = 1;
    }
  }
}

/* The entries (joint, slot) of bits and tie, each with its chain of rules
** in rule order; the quadrilateral rules' chain. */
static void siteflip_cplan_chains(siteflip_cplan *pl) {
  pl->nentries = joint_count() * pl->nv;
  for (int e = 0; e < pl->nentries; e++) pl->entry_rule[e] = -1;
  pl->first_quad = -1;
  for (int i = pl->nrules - 1; i >= 0; i--) {
    siteflip_crule *c = &pl->cr[i];
    int *head = c->quad ? &pl->first_quad : &pl->entry_rule[c->bit = c->joint * pl->nv + c->slot];
    c->next = *head;
    *head = i;
  }
}

/* 0, -1 for a rule the plan cannot hold, -2 when memory ran out
** (siteflip_cplan_free after either). */
static int siteflip_cplan_make(siteflip_cplan *pl, const rule *rules, int nrules, double eps) {
  memset(pl, 0, sizeof *pl);
  pl->rules = rules;
  pl->nrules = nrules;
  pl->eps = eps;
  int rc = census_plan_make(&pl->cp, rules, nrules);
  if (rc != 0) return rc;
  if ((pl->cr = calloc((size_t)nrules + 1, sizeof *pl->cr)) == NULL) return -2;
  for (int i = 0; i < nrules; i++) {
    const rule *r = &rules[i];
    const census_item *it = &pl->cp.item[i];
    siteflip_crule *c = &pl->cr[i];
    c->quad = it->kind != CENSUS_TRIANGLE;
    c->dt = it->kind == CENSUS_DT;
    if (c->quad) continue;
    c->slot = it->slot;
    c->joint = it->joint;
    c->msign = rule_sign(r);
    c->keyop = joint_get(rule_joint(r))->keyop;
    c->key0 = rule_key_identity(r);
  }
  siteflip_cplan_runs(pl);
  pl->nv = QUADVEC_PAD(pl->cp.nslots);
  siteflip_cplan_chains(pl);
  /* measure_eval_all when it is cheaper than calls: many slots, and no
  ** unused user measure (maybe a slow formula) would run. */
  pl->eval_all = pl->cp.nslots > 4 && pl->cp.eval_all_ok;
  return 0;
}

static void siteflip_cplan_free(siteflip_cplan *pl) {
  free(pl->cr);
  census_plan_free(&pl->cp);
}

static void siteflip_cwork_free(siteflip_cwork *w) {
  siteflip_free(w->shape);
  free(w->stab);
  free(w->val);
  free(w->mag);
  free(w->h);
  free(w->dec);
  free(w->dtdec);
  free(w->qmask);
  free(w->want);
  free(w->out);
  free(w->key);
  free(w->sinks);
}

static int siteflip_grow(void **p, size_t *cap, size_t need, size_t size) {
  if (need <= *cap) return 0;
  void *q = realloc(*p, need * size);
  if (q == NULL) return -1;
  *p = q;
  *cap = need;
  return 0;
}

/* Room for g's values, decisions and per-node arrays. */
static int siteflip_cwork_fit(siteflip_cwork *w, const siteflip_graph *g,
                              const siteflip_cplan *pl) {
  const int nv = pl->nv;
  size_t vc = w->valcap, dc = w->deccap, nn = (size_t)g->nnodes + 1, nc = w->nodecap;
  size_t mc = w->magcap, hc = w->hcap, tc = w->dtcap, rows = (size_t)g->ntris * (size_t)(nv + 1);
  if (siteflip_grow((void **)&w->val, &vc, rows, sizeof *w->val) ||
      siteflip_grow((void **)&w->mag, &mc, rows, sizeof *w->mag) ||
      siteflip_grow((void **)&w->h, &hc, rows, sizeof *w->h) ||
      siteflip_grow((void **)&w->dec, &dc, (size_t)g->nquads + 1, sizeof *w->dec) ||
      siteflip_grow((void **)&w->dtdec, &tc, (size_t)g->nquads + 1, sizeof *w->dtdec))
    return -1;
  w->valcap = vc;
  w->magcap = mc;
  w->hcap = hc;
  w->deccap = dc;
  w->dtcap = tc;
  if (nn <= nc) return 0;
  size_t c1 = nc, c2 = nc, c3 = nc, c4 = nc, c5 = nc;
  if (siteflip_grow((void **)&w->qmask, &c1, nn, sizeof *w->qmask) ||
      siteflip_grow((void **)&w->want, &c2, nn, sizeof *w->want) ||
      siteflip_grow((void **)&w->out, &c3, nn, sizeof *w->out) ||
      siteflip_grow((void **)&w->key, &c4, nn, sizeof *w->key) ||
      siteflip_grow((void **)&w->sinks, &c5, nn, sizeof *w->sinks))
    return -1;
  w->nodecap = nn;
  return 0;
}

/* What depends on g's shape only: sink masks and quadrilateral rows. */
static void siteflip_cwork_masks(siteflip_cwork *w, const siteflip_graph *g, int nv) {
  if (g->nquads > 64) return;
  for (int q = 0; q < g->nquads; q++)
    for (int k = 0; k < 4; k++) w->qoff[q][k] = (ptrdiff_t)g->quad[q].tri[k] * nv;
  memset(w->qmask, 0, (size_t)g->nnodes * sizeof *w->qmask);
  memset(w->want, 0, (size_t)g->nnodes * sizeof *w->want);
  for (int e = 0; e < g->nedges; e++) {
    uint64_t b = 1ull << g->edge[e].quad;
    w->qmask[g->edge[e].ac] |= b;
    w->qmask[g->edge[e].bd] |= b;
    w->want[g->edge[e].bd] |= b;
  }
}

/* Sink tables for the convex shape, which every sample of a thread
** shares.  Node u is a sink iff (bits & qmask[u]) == want[u]; cut the
** bits into bytes b_c: u is a sink iff (b_c & qmask_c[u]) == want_c[u] for
** every c (the byte c of each), so the sink mask is the AND over c of
** stab[c][b_c], one load per byte instead of a test per node.  No tables
** (nstab = 0) when memory is short: the node loop does the same work. */
static void siteflip_cwork_tables(siteflip_cwork *w, const siteflip_graph *g) {
  w->nstab = 0;
  if (g->nquads > 64 || g->nnodes > 64) return;
  int nc = (g->nquads + 7) / 8;
  free(w->stab);
  if ((w->stab = malloc((size_t)nc * 256 * sizeof *w->stab)) == NULL) return;
  for (int c = 0; c < nc; c++)
    for (uint64_t x = 0; x < 256; x++) {
      uint64_t m = 0, bc = x << (8 * c), byte = 0xffull << (8 * c);
      for (int u = 0; u < g->nnodes; u++) m |= (uint64_t)((bc & w->qmask[u]) == (w->want[u] & byte)) << u;
      w->stab[c * 256 + x] = m;
    }
  w->nstab = nc;
}

/* The sink mask of decision bits b by the tables (nstab > 0). */
static uint64_t siteflip_table_mask(const siteflip_cwork *w, uint64_t b) {
  uint64_t m = w->stab[b & 255];
  for (int c = 1; c < w->nstab; c++) m &= w->stab[c * 256 + ((b >> (8 * c)) & 255)];
  return m;
}

/* ---- decisions -------------------------------------------------------------- */

/* Every quadrilateral of g under a triangle rule, as rule_eval_tris decides
** it (joint_compare); *bits as above (when nquads <= 64).  Returns 1 if
** some decision is `either`. */
static int siteflip_decide_tri(const siteflip_graph *g, const double *val, int ns,
                               const siteflip_crule *c, double eps, rule_choice *dec,
                               uint64_t *bits) {
  uint64_t b = 0;
  for (int q = 0; q < g->nquads; q++) {
    const int *t = g->quad[q].tri;
    int k = joint_compare(c->joint, c->msign, val[t[0] * ns + c->slot], val[t[1] * ns + c->slot],
                          val[t[2] * ns + c->slot], val[t[3] * ns + c->slot], eps);
    if (k == 0) return 1;
    dec[q] = k < 0 ? RULE_AC : RULE_BD;
    if (q < 64) b |= (uint64_t)(k > 0) << q;
  }
  *bits = b;
  return 0;
}

/* Rule i on every quadrilateral of g; DT's decisions are dtdec (the exact
** in-circle test gives rule_eval's answer whatever the vertex order). */
static int siteflip_decide(const siteflip_cplan *pl, int i, const siteflip_graph *g,
                           const double *val, const rule_choice *dtdec, rule_choice *dec,
                           uint64_t *bits) {
  const siteflip_crule *c = &pl->cr[i];
  if (c->quad) {
    uint64_t b = 0;
    for (int q = 0; q < g->nquads; q++) {
      const unsigned char *v = g->quad[q].v;
      geom_point pts[4] = {g->p[v[0]], g->p[v[1]], g->p[v[2]], g->p[v[3]]};
      dec[q] = c->dt ? dtdec[q] : rule_eval(&pl->rules[i], pts, NULL, NULL);
      if (dec[q] == RULE_EITHER) return 1;
      if (q < 64) b |= (uint64_t)(dec[q] == RULE_BD) << q;
    }
    *bits = b;
    return 0;
  }
  return siteflip_decide_tri(g, val, pl->nv, c, pl->eps, dec, bits);
}

/* Every triangle rule on a graph of at most 64 quadrilaterals: w->bits
** and w->tie (quadvec_internal.h), cloned for AVX2 where possible. */
#if FLIPLAB_HAVE_CLONES
__attribute__((target_clones("avx2", "default")))
#endif
static void siteflip_all_bits(const siteflip_cplan *pl, const siteflip_graph *g,
                              siteflip_cwork *w) {
  const quadvec_batch b = {pl->cp.nslots, pl->nv, g->ntris, g->nquads, (const ptrdiff_t (*)[4])w->qoff,
                           NULL, NULL, pl->cp.slot_sign, pl->eps,
                           pl->cp.joint_used, w->val, w->mag, w->h, w->flags, w->bits, w->tie};
  quadvec_run(&b);
}

/* ---- one sample ----------------------------------------------------------- */

/* Sinks from the decisions, walking the edges (graphs the masks cannot hold). */
static int siteflip_sinks(siteflip_cwork *w, const siteflip_graph *g, const rule_choice *dec) {
  int ns = 0;
  memset(w->out, 0, (size_t)g->nnodes);
  for (int e = 0; e < g->nedges; e++)
    w->out[dec[g->edge[e].quad] == RULE_AC ? g->edge[e].bd : g->edge[e].ac] = 1;
  for (int u = 0; u < g->nnodes; u++)
    if (!w->out[u]) w->sinks[ns++] = u;
  return ns;
}

/* Node masks of the sinks of every entry of w->bits (nquads and nnodes
** <= 64): node u is a sink iff (bits & qmask[u]) == want[u].  Node by
** node over all entries, branch-free, so the AVX2 clone handles four
** entries at a time. */
#if FLIPLAB_HAVE_CLONES
__attribute__((target_clones("avx2", "default")))
#endif
static void siteflip_sink_masks(siteflip_cwork *w, int nnodes, int nentries) {
  const unsigned long long *bits = w->bits;
  uint64_t *m = w->emask;
  for (int e = 0; e < nentries; e++) m[e] = 0;
  for (int u = 0; u < nnodes; u++) {
    const uint64_t qm = w->qmask[u], want = w->want[u];
    for (int e = 0; e < nentries; e++) m[e] |= (uint64_t)((bits[e] & qm) == want) << u;
  }
}

/* The running counts of every entry from its sink mask: a tie, or one
** sink (at the Delaunay node dtbit or not); the others, without a tie and
** with no sink or several, are listed in w->emulti for siteflip_tally.
** Branch-free but for the list, in its own loop. */
#if FLIPLAB_HAVE_CLONES
__attribute__((target_clones("avx2", "default")))
#endif
static int siteflip_entry_counts(siteflip_cwork *w, int nentries, uint64_t dtbit) {
  for (int e = 0; e < nentries; e++) {
    const uint64_t m = w->emask[e], tied = w->tie[e] != 0;
    const uint64_t one = (m != 0) & ((m & (m - 1)) == 0);
    w->etie[e] += tied;
    w->eone[e] += one & !tied;
    w->edt[e] += (m == dtbit) & !tied;
    w->eother[e] = !(one | tied);
  }
  int n = 0;
  for (int e = 0; e < nentries; e++) {
    w->emulti[n] = e;
    n += (int)w->eother[e];
  }
  return n;
}

/* siteflip_sink_masks by the tables of siteflip_cwork_tables. */
static void siteflip_sink_masks_tab(siteflip_cwork *w, int nentries) {
  const uint64_t *t0 = w->stab, *t1 = w->stab + 256;
  if (w->nstab == 2) {   /* 9 to 16 quadrilaterals: hexagons */
    for (int e = 0; e < nentries; e++) {
      const uint64_t b = w->bits[e];
      w->emask[e] = t0[b & 255] & t1[(b >> 8) & 255];
    }
    return;
  }
  for (int e = 0; e < nentries; e++) w->emask[e] = siteflip_table_mask(w, w->bits[e]);
}

static int siteflip_ctz(uint64_t m) {   /* m != 0 */
#if defined(__GNUC__)
  return __builtin_ctzll(m);
#else
  int n = 0;
  for (; !(m & 1); m >>= 1) n++;
  return n;
#endif
}

/* The least and greatest total in key space over the nsinks sinks (each
** siteflip_node_key's arithmetic, with the plan's values), for a joint of
** key shape sh and exponent p: called with a constant sh, so each shape
** gets its own loop with the key inline.  Plain comparisons pick the
** extremes: a NaN total is skipped as fmin and fmax would skip it. */
static inline void siteflip_sink_range(joint_shape sh, double p, const siteflip_cwork *w,
                                       const siteflip_graph *g, const double *v, int nv,
                                       const siteflip_crule *c, int nsinks, double *lo,
                                       double *hi) {
  const int per = g->per, ms = c->msign;
  const joint_keyop op = c->keyop;
  double best = INFINITY, worst = -INFINITY;
  for (int s = 0; s < nsinks; s++) {
    const int *t = g->node_tri + (size_t)w->sinks[s] * (size_t)per;
    double k = c->key0;
    if (op == JOINT_KEY_ADD)
      for (int f = 0; f < per; f++) k += joint_key_shape(sh, p, ms, v[t[f] * nv]);
    else
      for (int f = 0; f < per; f++) k = joint_key_combine(op, k, v[t[f] * nv]);
    best = k < best ? k : best;
    worst = k > worst ? k : worst;
  }
  *lo = best;
  *hi = worst;
}

/* llround(x) for 0 <= x < 2^52: the integer part is exact, and so is the
** fraction x - r, so rounding half away from zero is r + (frac >= 1/2). */
static uint64_t siteflip_round_units(double x) {
  uint64_t r = (uint64_t)x;
  return r + (x - (double)r >= 0.5);
}

/* The worst sink's gap, in units; see the GOT shortcut above.  The sign
** of a zero total cannot change the gap. */
static uint64_t siteflip_gap_units(const siteflip_cwork *w, const siteflip_graph *g,
                                   const double *val, int nv, const rule *r,
                                   const siteflip_crule *c, int nsinks) {
  if (nsinks == 1) return 0;
  const double *v = val + c->slot;
  double best = 0, worst = 0;
  const joint *J = joint_get(c->joint);
  const double p = J->p;
  switch (J->key) {
    case JOINT_SHAPE_SAME:
      siteflip_sink_range(JOINT_SHAPE_SAME, p, w, g, v, nv, c, nsinks, &best, &worst);
      break;
    case JOINT_SHAPE_NEGRECIP:
      siteflip_sink_range(JOINT_SHAPE_NEGRECIP, p, w, g, v, nv, c, nsinks, &best, &worst);
      break;
    case JOINT_SHAPE_LOG:
      siteflip_sink_range(JOINT_SHAPE_LOG, p, w, g, v, nv, c, nsinks, &best, &worst);
      break;
    case JOINT_SHAPE_SQUARE:
      siteflip_sink_range(JOINT_SHAPE_SQUARE, p, w, g, v, nv, c, nsinks, &best, &worst);
      break;
    case JOINT_SHAPE_POWER:
      siteflip_sink_range(JOINT_SHAPE_POWER, p, w, g, v, nv, c, nsinks, &best, &worst);
      break;
  }
  double gap = rule_gap(r, best, worst);
  if (!(gap > 0)) return 0;
  return siteflip_round_units((gap < 4.0 ? gap : 4.0) / SITEFLIP_GAP_UNIT);
}

/* Measure values, rows of nv with the padding lanes 1.0 (quadvec). */
static void siteflip_values(const siteflip_cplan *pl, const siteflip_graph *g, double *val) {
  double all[MEASURE_MAX];
  for (int t = 0; t < g->ntris; t++) {
    double *row = val + (size_t)t * (size_t)pl->nv;
    if (pl->eval_all) {
      measure_eval_all(&g->tri[t], all);
      for (int k = 0; k < pl->nruns; k++) {
        const int s0 = pl->run_slot[k], len = pl->run_len[k];
        const double *src = all + pl->cp.slot_measure[s0];
        for (int s = 0; s < len; s++) row[s0 + s] = src[s];
      }
    } else {
      for (int s = 0; s < pl->cp.nslots; s++)
        row[s] = measure_eval(pl->cp.slot_measure[s], &g->tri[t]);
    }
    for (int s = pl->cp.nslots; s < pl->nv; s++) row[s] = 1.0;
  }
}

/* Rule i's decisions: 1 if some quadrilateral is a tie, else 0 with the
** BD bits (packed graphs) or w->dec.  Triangle rules on packed graphs come
** from quadvec (siteflip_all_bits). */
static int siteflip_rule_bits(const siteflip_cplan *pl, siteflip_cwork *w,
                              const siteflip_graph *g, int i, uint64_t *bits) {
  const siteflip_crule *cr = &pl->cr[i];
  if (g->nquads <= 64 && !cr->quad) {
    *bits = w->bits[cr->bit];
    return w->tie[cr->bit] != 0;
  }
  *bits = 0;
  return siteflip_decide(pl, i, g, w->val, w->dtdec, w->dec, bits);
}

/* Adds one untied sample whose ns sinks are w->sinks[0..ns-1] to c, in
** the running form of siteflip_count: a one-sink sample counts in
** one_sink and sink_dt only. */
static void siteflip_tally(const siteflip_cplan *pl, const siteflip_cwork *w,
                           const siteflip_graph *g, int i, int ns, siteflip_counts *c) {
  if (ns == 1) {
    c->one_sink++;
    c->sink_dt += w->sinks[0] == g->delaunay;
    return;
  }
  c->sinks += (uint64_t)ns;
  if ((uint64_t)ns > c->max_sinks) c->max_sinks = (uint64_t)ns;
  if (ns == 0) c->no_sink++;
  else c->multi_sink++;
  if (ns > 1 && !pl->cr[i].quad)
    c->gap_units += siteflip_gap_units(w, g, w->val, pl->nv, &pl->rules[i], &pl->cr[i], ns);
}

/* Running counts of `samples` samples made whole: every sample counts in
** samples, and a one-sink sample's sink in sinks and max_sinks. */
static void siteflip_counts_finish(siteflip_counts *c, uint64_t samples) {
  c->samples += samples;
  c->sinks += c->one_sink;
  if (c->one_sink > 0 && c->max_sinks < 1) c->max_sinks = 1;
}

/* Sinks of packed decisions on a graph of more than 64 nodes. */
static int siteflip_sinks_packed(siteflip_cwork *w, const siteflip_graph *g, uint64_t bits) {
  int ns = 0;
  for (int u = 0; u < g->nnodes; u++)
    if ((bits & w->qmask[u]) == w->want[u]) w->sinks[ns++] = u;
  return ns;
}

/* Adds the entries' running counts to the triangle rules' and clears them. */
static void siteflip_flush(const siteflip_cplan *pl, siteflip_cwork *w, siteflip_counts *out) {
  for (int e = 0; e < pl->nentries; e++) {
    for (int i = pl->entry_rule[e]; i >= 0; i = pl->cr[i].next) {
      out[i].tie += w->etie[e];
      out[i].one_sink += w->eone[e];
      out[i].sink_dt += w->edt[e];
    }
    w->etie[e] = w->eone[e] = w->edt[e] = 0;
  }
}

/* Lists in w->sinks the nodes of sink mask m; returns their count. */
static int siteflip_mask_sinks(siteflip_cwork *w, uint64_t m) {
  int ns = 0;
  for (; m != 0; m &= m - 1) w->sinks[ns++] = siteflip_ctz(m);
  return ns;
}

/* siteflip_count on a graph of at most 64 quadrilaterals and nodes: the
** triangle rules by entry of w->bits (rules sharing a measure and a joint
** share one), in running form until siteflip_flush, except for the
** samples with no sink or several, tallied rule by rule. */
static void siteflip_count_entries(const siteflip_cplan *pl, siteflip_cwork *w,
                                   const siteflip_graph *g, siteflip_counts *out) {
  const uint64_t dtbit = g->delaunay >= 0 ? 1ull << g->delaunay : 0;
  if (g == w->shape && w->nstab > 0) siteflip_sink_masks_tab(w, pl->nentries);
  else siteflip_sink_masks(w, g->nnodes, pl->nentries);
  int nm = siteflip_entry_counts(w, pl->nentries, dtbit);
  for (int k = 0; k < nm; k++) {
    int e = w->emulti[k], ns = siteflip_mask_sinks(w, w->emask[e]);
    for (int i = pl->entry_rule[e]; i >= 0; i = pl->cr[i].next) siteflip_tally(pl, w, g, i, ns, &out[i]);
  }
  const int tables = g == w->shape && w->nstab > 0;
  for (int i = pl->first_quad; i >= 0; i = pl->cr[i].next) {
    uint64_t bits, m = 0;
    if (tables && pl->cr[i].dt) {   /* siteflip_sample's DT bits and sinks */
      if (w->dttied) {
        out[i].tie++;
        continue;
      }
      m = siteflip_table_mask(w, w->dtbits);
    } else {
      if (siteflip_rule_bits(pl, w, g, i, &bits)) {
        out[i].tie++;
        continue;
      }
      for (int u = 0; u < g->nnodes; u++) m |= (uint64_t)((bits & w->qmask[u]) == w->want[u]) << u;
    }
    siteflip_tally(pl, w, g, i, siteflip_mask_sinks(w, m), &out[i]);
  }
}

/* Adds g's sample to out[0 .. nrules-1] in running form (siteflip_tally;
** siteflip_flush, then siteflip_counts_finish complete the counts). */
static void siteflip_count(const siteflip_cplan *pl, siteflip_cwork *w, const siteflip_graph *g,
                           siteflip_counts *out) {
  siteflip_values(pl, g, w->val);
  int packed = g->nquads <= 64;
  if (packed) siteflip_all_bits(pl, g, w);
  if (packed && g->nnodes <= 64) {
    siteflip_count_entries(pl, w, g, out);
    return;
  }
  for (int i = 0; i < pl->nrules; i++) {
    uint64_t bits;
    if (siteflip_rule_bits(pl, w, g, i, &bits)) {
      out[i].tie++;
      continue;
    }
    /* Now, while w->dec holds rule i's decisions. */
    int ns = packed ? siteflip_sinks_packed(w, g, bits) : siteflip_sinks(w, g, w->dec);
    siteflip_tally(pl, w, g, i, ns, &out[i]);
  }
}

/* g->delaunay for the moved convex shape: with tables and no tie, the
** Delaunay node is DT's one sink (siteflip_delaunay_of's nodes no flip
** leaves are then exactly the sinks), found by the tables; DT's bits and
** tie kept for the DT rule. */
static void siteflip_dt_node(siteflip_cwork *w, siteflip_graph *g) {
  if (w->nstab == 0) {
    g->delaunay = siteflip_delaunay_of(g, w->dtdec);
    return;
  }
  uint64_t b = 0;
  int tied = 0;
  for (int q = 0; q < g->nquads; q++) {
    b |= (uint64_t)(w->dtdec[q] == RULE_BD) << q;
    tied |= w->dtdec[q] == RULE_EITHER;
  }
  w->dtbits = b;
  w->dttied = tied;
  uint64_t m = siteflip_table_mask(w, b);
  if (tied) g->delaunay = siteflip_delaunay_of(g, w->dtdec);
  else g->delaunay = m != 0 && (m & (m - 1)) == 0 ? siteflip_ctz(m) : -1;
}

/* The flip graph of sample i, ready for siteflip_count: the moved shape
** (convex: one shape per thread), or a new graph (*owned, to be freed).
** NULL when memory ran out. */
static siteflip_graph *siteflip_sample(const siteflip_cplan *pl, siteflip_cwork *w, int sampler,
                                       int n, uint64_t seed, uint64_t i, int *owned) {
  geom_point p[SITEFLIP_MAX_SITES];
  const siteflip_limits lim = {pl->memory, NULL, NULL};
  siteflip_graph *g;
  sampler_sites(sampler, seed, i, n, p);
  *owned = sampler != SAMPLER_SITES_CONVEX;
  w->fail_at = (int64_t)i;   /* until the graph is ready */
  if (*owned) {
    g = siteflip_build_within(p, n, &lim, &w->fail_over, w->fail_err, sizeof w->fail_err);
  } else {
    int fresh = w->shape == NULL;
    if (fresh && (w->shape = siteflip_build_within(p, n, &lim, &w->fail_over, w->fail_err,
                                                   sizeof w->fail_err)) == NULL)
      return NULL;
    g = w->shape;
    if (fresh && siteflip_cwork_fit(w, g, pl) == 0) {
      siteflip_cwork_masks(w, g, pl->nv);
      siteflip_cwork_tables(w, g);
    }
  }
  if (g == NULL || siteflip_cwork_fit(w, g, pl) != 0) {
    if (g != NULL) snprintf(w->fail_err, sizeof w->fail_err, "out of memory");
    if (*owned) siteflip_free(g);
    return NULL;
  }
  w->fail_at = -1;
  if (*owned) {
    siteflip_cwork_masks(w, g, pl->nv);
    if (pl->cp.ndt > 0) siteflip_dt_decisions(g, w->dtdec);
  } else {
    /* siteflip_move, keeping DT's decisions for the DT rule. */
    siteflip_move_tris(g, p);
    siteflip_dt_decisions(g, w->dtdec);
    siteflip_dt_node(w, g);
  }
  return g;
}

static int siteflip_range(const siteflip_cplan *pl, siteflip_cwork *w, int sampler, int n,
                          uint64_t seed, uint64_t lo, uint64_t hi, siteflip_counts *out) {
  for (uint64_t i = lo; i < hi; i++) {
    int owned;
    siteflip_graph *g = siteflip_sample(pl, w, sampler, n, seed, i, &owned);
    if (g == NULL) return -1;
    siteflip_count(pl, w, g, out);
    if (owned) siteflip_free(g);
  }
  siteflip_flush(pl, w, out);
  return 0;
}

static void siteflip_counts_add(siteflip_counts *a, const siteflip_counts *b) {
  a->samples += b->samples;
  a->tie += b->tie;
  a->no_sink += b->no_sink;
  a->one_sink += b->one_sink;
  a->multi_sink += b->multi_sink;
  a->sink_dt += b->sink_dt;
  a->sinks += b->sinks;
  if (b->max_sinks > a->max_sinks) a->max_sinks = b->max_sinks;
  a->gap_units += b->gap_units;
}

static int siteflip_census_args(int sampler, int n, uint64_t first, uint64_t count, char *err,
                                size_t errlen) {
  if (sampler_sites_name(sampler) == NULL) {
    snprintf(err, errlen, "unknown sampler %d", sampler);
    return -1;
  }
  if (n < 3 || n > SITEFLIP_MAX_SITES) {
    snprintf(err, errlen, "%d sites: the census takes 3 to %d", n, SITEFLIP_MAX_SITES);
    return -1;
  }
  if (first + count < first) {
    snprintf(err, errlen, "sample range overflows");
    return -1;
  }
  return 0;
}

/* A census's state: the plan, the sampler, and per thread (census_loop's
** thread numbers) its work space and its counts, rows of nr. */
typedef struct siteflip_censusctx {
  const siteflip_cplan *pl;
  int sampler, n;
  uint64_t seed;
  size_t nr;
  siteflip_cwork *work;
  siteflip_counts *all;
} siteflip_censusctx;

/* One chunk (a census_range_fn): -1 when memory ran out. */
static int siteflip_census_range(void *ctx, int thread, uint64_t lo, uint64_t hi) {
  const siteflip_censusctx *c = ctx;
  return siteflip_range(c->pl, &c->work[thread], c->sampler, c->n, c->seed, lo, hi,
                        c->all + (size_t)thread * c->nr);
}

/* The per-thread counts made whole and added to out, in thread order. */
static void siteflip_census_sum(const siteflip_censusctx *c, int threads, uint64_t count,
                                siteflip_counts *out) {
  for (size_t r = 0; r < (size_t)c->pl->nrules; r++) {
    siteflip_counts tot = {0};
    for (int t = 0; t < threads; t++) siteflip_counts_add(&tot, &c->all[(size_t)t * c->nr + r]);
    siteflip_counts_finish(&tot, count);
    siteflip_counts_add(&out[r], &tot);
  }
}

/* Why the census stopped: the earliest set a thread could not enumerate
** (with several threads, the first one some thread reached). */
static void siteflip_census_fail(const siteflip_censusctx *c, int threads, int *over, char *err,
                                 size_t errlen) {
  const siteflip_cwork *f = NULL;
  for (int t = 0; c->work != NULL && t < threads; t++)
    if (c->work[t].fail_at >= 0 && (f == NULL || c->work[t].fail_at < f->fail_at)) f = &c->work[t];
  if (f == NULL) {
    snprintf(err, errlen, "out of memory");
    return;
  }
  snprintf(err, errlen, "set #%lld: %s", (long long)f->fail_at, f->fail_err);
  if (over != NULL) *over = f->fail_over;
}

int siteflip_census(const rule *rules, int nrules, int sampler, int n, uint64_t seed,
                    uint64_t first, uint64_t count, double tie_eps, int threads,
                    size_t memory, siteflip_counts *out, census_progress_fn progress,
                    void *ctx, int *over, char *err, size_t errlen) {
  if (over != NULL) *over = 0;
  if (siteflip_census_args(sampler, n, first, count, err, errlen) != 0 ||
      geom_threads_check(threads, err, errlen) != 0)
    return -1;
  siteflip_cplan pl;
  int rc = siteflip_cplan_make(&pl, rules, nrules, tie_eps);
  if (rc != 0) {
    siteflip_cplan_free(&pl);
    snprintf(err, errlen, "%s", rc == -2 ? "out of memory" : "invalid rule list");
    return -1;
  }
  pl.memory = memory;
  threads = census_threads(threads, count, SITEFLIP_CHUNK);
  size_t nr = nrules > 0 ? (size_t)nrules : 1;
  siteflip_censusctx c = {&pl, sampler, n, seed, nr, calloc((size_t)threads, sizeof *c.work),
                          calloc((size_t)threads * nr, sizeof *c.all)};
  census_loop loop = {first, count, SITEFLIP_CHUNK, threads, siteflip_census_range, &c,
                      progress, ctx};
  rc = c.work != NULL && c.all != NULL ? 0 : -2;
  for (int t = 0; rc == 0 && t < threads; t++) c.work[t].fail_at = -1;
  if (rc == 0 && census_loop_run(&loop) != 0) rc = -1;
  if (rc == 0) siteflip_census_sum(&c, threads, count, out);
  if (rc == -1) siteflip_census_fail(&c, threads, over, err, errlen);
  if (rc == -2) snprintf(err, errlen, "out of memory");
  for (int t = 0; c.work != NULL && t < threads; t++) siteflip_cwork_free(&c.work[t]);
  free(c.work);
  free(c.all);
  siteflip_cplan_free(&pl);
  return rc != 0 ? -1 : 0;
}

int64_t siteflip_find_multi(const rule *r, int sampler, int n, uint64_t seed, uint64_t first,
                            uint64_t count, double tie_eps, geom_point *p) {
  char err[256];
  if (siteflip_census_args(sampler, n, first, count, err, sizeof err) != 0) return -1;
  siteflip_cplan pl;
  siteflip_cwork w;
  memset(&w, 0, sizeof w);
  int64_t found = -1;
  if (siteflip_cplan_make(&pl, r, 1, tie_eps) == 0)
    for (uint64_t i = first; i < first + count && found < 0; i++) {
      int owned;
      siteflip_graph *g = siteflip_sample(&pl, &w, sampler, n, seed, i, &owned);
      if (g == NULL) break;
      siteflip_counts c = {0};
      siteflip_count(&pl, &w, g, &c);
      siteflip_flush(&pl, &w, &c);
      if (c.multi_sink > 0) {
        found = (int64_t)i;
        memcpy(p, g->p, (size_t)n * sizeof *p);
      }
      if (owned) siteflip_free(g);
    }
  siteflip_cplan_free(&pl);
  siteflip_cwork_free(&w);
  return found;
}
