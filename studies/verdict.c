/*
** verdict.c: a rule's verdicts on random convex pentagons: the flip-graph
** types of the classify engine (flipgraph_tally_run), their intervals, what
** they say about systematicity and locality, and the witnesses of the
** lowest sample indices, collected by the engine's per-sample hook.
*/
#include <stdlib.h>
#include <string.h>
#include "study.h"

void study_verdict_of(const rule *r, const flipgraph_counts *c, study_verdict *v) {
  uint64_t n = c->samples;
  v->counts = *c;
  for (int t = 0; t < STUDY_ROWS; t++)
    study_wilson(t == STUDY_ROW_DT ? c->dt : c->type[t], n, &v->lo[t], &v->hi[t]);
  v->decided = n - c->type[FLIPGRAPH_V];
  v->systematic = c->type[FLIPGRAPH_III] == 0;
  v->local = c->type[FLIPGRAPH_II] == 0;
  v->sink_bug = c->type[FLIPGRAPH_IV] > 0 && rule_is_triangle(r);
  v->always_delaunay = n > 0 && c->dt == n;
}

/* Keep the k lowest indices in f, ascending (insertion: k <= 100). */
static void study_keep(study_witnesses *f, int k, uint64_t idx) {
  if (f->n == k && (k == 0 || idx >= f->idx[k - 1])) return;
  int j = f->n < k ? f->n++ : k - 1;
  for (; j > 0 && f->idx[j - 1] > idx; j--) f->idx[j] = f->idx[j - 1];
  f->idx[j] = idx;
}

/* The hook's state: each thread's own witnesses, [thread][rule][type]. */
typedef struct study_hook {
  int nrules, k;
  study_witnesses *w;
} study_hook;

static void study_each(void *ctx, int thread, uint64_t index, const flipgraph_pentagon *p,
                       const flipgraph *g) {
  (void)p;
  study_hook *h = ctx;
  study_witnesses *mine = h->w + (size_t)thread * (size_t)h->nrules * FLIPGRAPH_NTYPES;
  for (int r = 0; r < h->nrules; r++)
    if (g[r].type != FLIPGRAPH_I) study_keep(&mine[r * FLIPGRAPH_NTYPES + g[r].type], h->k, index);
}

/* O(samples x rules) through the classify engine; the witnesses' merge is
** O(threads x rules x 5 x K^2) at most, K <= 100. */
int study_pentagons(const rule *rules, int nrules, const flipgraph_run *run, int witnesses,
                    study_verdict *out) {
  if (nrules < 0 || witnesses < 0 || witnesses > STUDY_WITNESS_MAX) return -1;
  int threads = flipgraph_tally_threads(run->threads, run->count);
  size_t per = (size_t)nrules * FLIPGRAPH_NTYPES;
  study_hook h = {nrules, witnesses, calloc((size_t)threads * per + 1, sizeof *h.w)};
  flipgraph_counts *c = calloc((size_t)nrules + 1, sizeof *c);
  flipgraph_run mine = *run;
  mine.each = study_each;
  mine.each_ctx = &h;
  int rc = h.w && c ? flipgraph_tally_run(rules, nrules, &mine, c) : -1;
  for (int r = 0; r < nrules && rc == 0; r++) {
    study_verdict *v = &out[r];
    memset(v->witness, 0, sizeof v->witness);
    for (int t = 0; t < threads; t++)
      for (int s = 0; s < FLIPGRAPH_NTYPES; s++) {
        const study_witnesses *src = &h.w[(size_t)t * per + (size_t)r * FLIPGRAPH_NTYPES + s];
        for (int i = 0; i < src->n; i++) study_keep(&v->witness[s], witnesses, src->idx[i]);
      }
    study_verdict_of(&rules[r], &c[r], v);
  }
  free(h.w);
  free(c);
  return rc;
}
