/*
** got_skel.c: the skeleton of a point set's GOT for a sum rule (got/got_skel.h; docs/got.md,
** "Point sets: the skeleton"): candidate edges, the LMT-skeleton loop, the certain edges.
** Files: the grid in got_skel_grid.c, the candidate edges (1) in got_skel_cand.c, the
** candidate triangles (2) in got_skel_tri.c, what they share in got_skel_internal.h; here
** the LMT loop, the certain edges, the hull and got_skel_build.
**
** 1. Candidates.  P_1 (the minimum-weight triangulation): the diamond test on a uniform grid
**    (skel_diamond_point: a ring search bounded by sectors, far rings read by the open
**    sectors' arcs, pairs tried on the points seen before the full test); every other sum
**    rule: every segment through no third point, for n <= GOT_SKEL_ALL_MAX (no exclusion
**    is proven for them).  P_1 works on the points renumbered in the grid's cell order
**    (skel_renumber), mapped back at the output.
** 2. Candidate triangles: every empty triangle whose three edges are candidates, found from
**    pairs of neighbours in the candidate graph, emptiness tested exactly on the grid.
** 3. LMT loop, in rounds: an edge that is not a hull edge stays only while some pair of live
**    candidate triangles, one on each side, makes it locally optimal (skel_witness); when it
**    goes, its triangles go, and the other edges of those triangles are examined again in
**    the next round.  Each round decides every queued edge against the state at its start,
**    so the result is the same whatever the thread count; the final set is the largest
**    fixed point whatever the order (removal is monotone).
** 4. Certain edges: live edges that cross no other live edge (a segment grid), and the hull.
**
** Soundness (docs/got.md has the argument): every GOT of a sum rule is weakly locally
** optimal, so its own triangles witness its edges in every round; an edge is removed only
** when the flip is certainly a strict improvement: exact squared lengths for P_1
** (geom_dist2_cmp), else the certified key error model of got_cert.c and the rule's own tie
** tolerance together.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "got_skel_internal.h"

/* Largest n for the rules without a candidate exclusion (all pairs are candidates). */
#define GOT_SKEL_ALL_MAX 200

static void skel_free_all(skel *s) {
  free(s->ev), free(s->off), free(s->nbr), free(s->nbe);
  free(s->te), free(s->bad), free(s->toff), free(s->tinc), free(s->tmid);
  free(s->ealive), free(s->hull), free(s->talive), free(s->wit), free(s->hpair);
  skel_grid_free(&s->g);
  free(s->orig), free(s->q);
}

/* ---- the LMT loop -------------------------------------------------------- */

/* 1 when flipping ab to cd certainly lowers the total (c left of ab, d right, the
** quadrilateral a d b c strictly convex); t1 = abc and t2 = abd are candidate triangles.
** SKEL_CERTIFIED: with keys k^ within rho |k^| + alpha of the exact keys (got_cert.c),
** D = (k1 + k2) - (k3 + k4) rounded three times is within 3.01 u S of the sum of the
** computed keys (S = sum |k^|), so the exact difference exceeds D - E with E = (rho +
** 3.01 u) S + 4 alpha: D > E proves it positive.  The rule's own decision must agree
** (a strict preference beyond its tie tolerance), so what the rule calls a tie is kept. */
static int skel_flip_better(const skel *s, uint32_t a, uint32_t b, uint32_t c, uint32_t d,
                            uint32_t t1, uint32_t t2) {
  const geom_point *p = s->p;
  switch (s->kind) {
    case SKEL_EXACT_LENGTH:
      return geom_dist2_cmp(p[c], p[d], p[a], p[b]) < 0;
    case SKEL_CERTIFIED: {
      double x1 = s->bad[t1], y1 = s->bad[t2];
      double x2 = s->mp(p[a], p[d], p[c]), y2 = s->mp(p[d], p[b], p[c]);
      double k1 = rule_key(s->r, x1), k2 = rule_key(s->r, y1);
      double k3 = rule_key(s->r, x2), k4 = rule_key(s->r, y2);
      double D = (k1 + k2) - (k3 + k4), S = fabs(k1) + fabs(k2) + fabs(k3) + fabs(k4);
      double E = ((s->rho + 3.01 * SKEL_U) * S + 4 * s->alpha) * (1 + 0x1p-40);
      return D > E && rule_decide(s->r, x1, y1, x2, y2) == RULE_BD;
    }
    case SKEL_NEVER:
      return 0;
  }
  return 0;
}

/* 1 when triangles t1 (third vertex c, left of ab) and t2 (d, right) keep edge e = ab:
** the quadrilateral is not strictly convex, or the flip is not certainly better. */
static int skel_pair_keeps(const skel *s, uint32_t e, uint32_t t1, uint32_t t2) {
  uint32_t a = s->ev[2 * e], b = s->ev[2 * e + 1];
  uint32_t c = skel_tri_sum(s, t1) - a - b, d = skel_tri_sum(s, t2) - a - b;
  const geom_point *p = s->p;
  if (geom_orient_valid(p[c], p[d], p[a]) * geom_orient_valid(p[c], p[d], p[b]) >= 0) return 1;
  return !skel_flip_better(s, a, b, c, d, t1, t2);
}

/* Has edge e a witness pair among the live triangles?  The last pair found is tried
** first; then every live left triangle against every live right one.  Cost: the product
** of the two counts at worst. */
static int skel_witness(skel *s, uint32_t e) {
  uint32_t *w = s->wit + 2 * e;
  if (w[0] != UINT32_MAX && s->talive[w[0]] && s->talive[w[1]]) return 1;
  for (uint32_t i = s->toff[e]; i < s->tmid[e]; i++) {
    uint32_t ti = s->tinc[i] >> 1;
    if (!s->talive[ti]) continue;
    for (uint32_t j = s->tmid[e]; j < s->toff[e + 1]; j++) {
      uint32_t tj = s->tinc[j] >> 1;
      if (s->talive[tj] && skel_pair_keeps(s, e, ti, tj)) {
        w[0] = ti, w[1] = tj;
        return 1;
      }
    }
  }
  return 0;
}

/* A round's removals, in three parallel sweeps over its losers (every !keep[i]), each
** reading only what no thread writes during it: the losers die; each live triangle of a
** loser flags its live edges that are no hull edges (the next round's queue, by
** skel_flagged: each once, ascending, whatever the thread count); the losers' triangles
** die.  The queue holds every edge the sequential removal in queue order would have
** queued, but those that die in the same round (they would be kept at once as dead), so
** the rounds decide the same edges.  Cost: the triangles of the losers. */
static void skel_remove_round(skel *s, const uint32_t *W, const unsigned char *keep,
                              long long nw, unsigned char *flag) {
#pragma omp parallel num_threads(s->threads) if (nw >= SKEL_BLOCK)
  {
#pragma omp for schedule(static)
    for (long long i = 0; i < nw; i++)
      if (!keep[i]) s->ealive[W[i]] = 0;
#pragma omp for schedule(dynamic, 256)
    for (long long i = 0; i < nw; i++)
      for (uint32_t j = s->toff[W[i]]; !keep[i] && j < s->toff[W[i] + 1]; j++) {
        uint32_t t = s->tinc[j] >> 1;
        for (int k = 0; k < 3 && s->talive[t]; k++) {
          uint32_t f = s->te[3 * t + k];
          if (s->ealive[f] && !s->hull[f]) {
#pragma omp atomic write
            flag[f] = 1;
          }
        }
      }
#pragma omp for schedule(dynamic, 256)
    for (long long i = 0; i < nw; i++)
      for (uint32_t j = s->toff[W[i]]; !keep[i] && j < s->toff[W[i] + 1]; j++) {
#pragma omp atomic write
        s->talive[s->tinc[j] >> 1] = 0;
      }
  }
}

/* The flagged edges into out, ascending, their flags cleared; their count.  Blocks of
** SKEL_FLAG_BLOCK edges counted in parallel, then written in parallel at their offsets.
** cnt: one entry per block.  O(m) per call. */
#define SKEL_FLAG_BLOCK 65536
static size_t skel_flagged(const skel *s, unsigned char *flag, uint32_t *out, size_t *cnt) {
  long long nb = (long long)(s->m / SKEL_FLAG_BLOCK + 1);
  size_t total = 0;
#pragma omp parallel for schedule(static) num_threads(s->threads) if (nb > 1)
  for (long long b = 0; b < nb; b++) {
    size_t e1 = (size_t)(b + 1) * SKEL_FLAG_BLOCK, c = 0;
    for (size_t e = (size_t)b * SKEL_FLAG_BLOCK; e < e1 && e < s->m; e++) c += flag[e];
    cnt[b] = c;
  }
  for (long long b = 0; b < nb; b++) {
    size_t c = cnt[b];
    cnt[b] = total, total += c;
  }
#pragma omp parallel for schedule(static) num_threads(s->threads) if (nb > 1)
  for (long long b = 0; b < nb; b++) {
    size_t e1 = (size_t)(b + 1) * SKEL_FLAG_BLOCK, k = cnt[b];
    for (size_t e = (size_t)b * SKEL_FLAG_BLOCK; e < e1 && e < s->m; e++)
      if (flag[e]) out[k++] = (uint32_t)e, flag[e] = 0;
  }
  return total;
}

/* The LMT loop in rounds (Jacobi: every queued edge is judged against the state at the
** start of its round, in parallel, then the losers are removed: skel_remove_round).  Cost
** per round: the witness searches of the queued edges, the triangles of the losers, and a
** sweep of the edges' flags. */
static int skel_lmt(skel *s, size_t *rounds) {
  uint32_t *W = malloc(s->m * sizeof *W + 1);
  unsigned char *keep = malloc(s->m + 1), *flag = calloc(s->m + 1, 1);
  size_t *cnt = malloc((s->m / SKEL_FLAG_BLOCK + 1) * sizeof *cnt);
  int fail = !W || !keep || !flag || !cnt;
  size_t nw = 0;
  for (size_t e = 0; !fail && e < s->m; e++)
    if (!s->hull[e]) W[nw++] = (uint32_t)e;
  *rounds = 0;
  while (!fail && nw > 0) {
    ++*rounds;
    long long nwl = (long long)nw;
#pragma omp parallel for schedule(dynamic, 256) num_threads(s->threads) if (nwl >= 256)
    for (long long i = 0; i < nwl; i++)
      keep[i] = skel_witness(s, W[i]);
    skel_remove_round(s, W, keep, nwl, flag);
    nw = skel_flagged(s, flag, W, cnt);
  }
  free(W), free(keep), free(flag), free(cnt);
  return fail ? -1 : 0;
}

/* ---- certain edges ------------------------------------------------------- */

typedef struct skel_cells { uint32_t *off, *list; uint32_t cur; int fill; } skel_cells;

/* Counts (fill = 0) or places (fill = 1) edge cur in a cell, from any thread: a cell's list
** comes in any order, which only changes which crossing is found first, not whether one is. */
static void skel_cells_visit(void *ctx, size_t cell) {
  skel_cells *c = ctx;
  uint32_t at;
  if (c->fill) {
#pragma omp atomic capture
    at = c->off[cell]++;
    c->list[at] = c->cur;
  } else {
#pragma omp atomic
    c->off[cell + 1]++;
  }
}

/* Every live edge's cells through skel_cells_visit, in parallel. */
static void skel_cells_all(const skel *s, skel_cells c) {
  long long m = (long long)s->m;
#pragma omp parallel for schedule(dynamic, 1024) num_threads(s->threads) firstprivate(c)
  for (long long e = 0; e < m; e++)
    if (s->ealive[e])
      c.cur = (uint32_t)e,
      skel_segment_cells(&s->g, s->p[s->ev[2 * e]], s->p[s->ev[2 * e + 1]], skel_cells_visit, &c);
}

/* 1 when segments e and f (no common endpoint) cross (exact). */
static int skel_cross(const skel *s, uint32_t e, uint32_t f) {
  const geom_point *p = s->p;
  uint32_t a = s->ev[2 * e], b = s->ev[2 * e + 1], c = s->ev[2 * f], d = s->ev[2 * f + 1];
  if (a == c || a == d || b == c || b == d) return 0;
  return geom_segments_cross_valid(p[a], p[b], p[c], p[d]);
}

typedef struct skel_probe {
  const skel *s;
  const uint32_t *start, *list;
  uint32_t e;
  int crossed;
} skel_probe;

static void skel_probe_visit(void *ctx, size_t cell) {
  skel_probe *q = ctx;
  for (uint32_t k = q->start[cell]; k < q->start[cell + 1] && !q->crossed; k++)
    q->crossed = q->list[k] != q->e && skel_cross(q->s, q->e, q->list[k]);
}

/* cert[e] = 1 for the live edges no other live edge crosses (hull edges included): two
** crossing segments share the cell of their crossing point, which both visit.  Cost:
** the cells of each edge, and the edges of those cells until a crossing is found. */
static int skel_certain(const skel *s, unsigned char *cert) {
  size_t cells = (size_t)s->g.nx * (size_t)s->g.ny;
  skel_cells c = {calloc(cells + 1, sizeof(uint32_t)), NULL, 0, 0};
  uint32_t *start = malloc((cells + 1) * sizeof *start);
  if (!c.off || !start) return free(c.off), free(start), -1;
  skel_cells_all(s, c);
  for (size_t k = 0; k < cells; k++) c.off[k + 1] += c.off[k];
  memcpy(start, c.off, (cells + 1) * sizeof *start);
  c.list = malloc((size_t)c.off[cells] * sizeof *c.list + 1);
  if (!c.list) return free(c.off), free(start), -1;
  c.fill = 1;
  skel_cells_all(s, c);
  long long m = (long long)s->m;
#pragma omp parallel for schedule(dynamic, 1024) num_threads(s->threads)
  for (long long e = 0; e < m; e++) {
    skel_probe q = {s, start, c.list, (uint32_t)e, 0};
    if (s->ealive[e] && !s->hull[e])
      skel_segment_cells(&s->g, s->p[s->ev[2 * e]], s->p[s->ev[2 * e + 1]], skel_probe_visit,
                         &q);
    cert[e] = s->ealive[e] && !q.crossed;
  }
  free(c.off), free(start), free(c.list);
  return 0;
}

/* ---- the convex hull ----------------------------------------------------- */

typedef struct skel_lexpt { geom_point p; uint32_t i; } skel_lexpt;

static int skel_cmp_lex(const void *x, const void *y) {
  geom_point a = ((const skel_lexpt *)x)->p, b = ((const skel_lexpt *)y)->p;
  return geom_lexless(a, b) ? -1 : geom_lexless(b, a);
}

/* One chain of the monotone-chain hull over the points in lexicographic order (dir +1:
** lower chain forwards; -1: upper chain backwards), keeping collinear boundary points
** (only strict right turns are popped); its consecutive pairs appended to s->hpair.
** O(n) after the sort. */
static void skel_hull_chain(skel *s, const skel_lexpt *o, uint32_t *st, int dir) {
  size_t k = 0;
  for (size_t j = 0; j < s->n; j++) {
    uint32_t v = o[dir > 0 ? j : s->n - 1 - j].i;
    while (k >= 2 && geom_orient(s->p[st[k - 2]], s->p[st[k - 1]], s->p[v]) < 0) k--;
    st[k++] = v;
  }
  for (size_t j = 0; j + 1 < k; j++) {
    s->hpair[2 * s->nh] = st[j] < st[j + 1] ? st[j] : st[j + 1];
    s->hpair[2 * s->nh++ + 1] = st[j] < st[j + 1] ? st[j + 1] : st[j];
  }
}

/* The hull's boundary pairs into s->hpair, and the input's check: 0, -1 out of memory,
** -2 two equal points (*bad, *bad2 their indices), -3 all points on a line. */
static int skel_hull(skel *s, size_t *bad, size_t *bad2) {
  skel_lexpt *o = malloc(s->n * sizeof *o);
  uint32_t *st = malloc(s->n * sizeof *st);
  s->hpair = malloc(4 * s->n * sizeof *s->hpair);
  if (!o || !st || !s->hpair) return free(o), free(st), -1;
  for (size_t i = 0; i < s->n; i++) o[i] = (skel_lexpt){s->p[i], (uint32_t)i};
  qsort(o, s->n, sizeof *o, skel_cmp_lex);
  int rc = 0;
  for (size_t i = 1; i < s->n && rc == 0; i++)
    if (o[i].p.x == o[i - 1].p.x && o[i].p.y == o[i - 1].p.y)
      rc = -2, *bad = o[i - 1].i < o[i].i ? o[i - 1].i : o[i].i, *bad2 = o[i - 1].i ^ o[i].i ^ *bad;
  size_t k = 1;
  while (rc == 0 && k + 1 < s->n && geom_orient(o[0].p, o[s->n - 1].p, o[k].p) == 0) k++;
  if (rc == 0 && geom_orient(o[0].p, o[s->n - 1].p, o[k].p) == 0) rc = -3;
  if (rc == 0) skel_hull_chain(s, o, st, 1), skel_hull_chain(s, o, st, -1);
  free(o), free(st);
  return rc;
}

/* hull[e] = 1 for the hull's boundary edges; -1 when out of memory or when one is no
** candidate (it always is: nothing lies beyond it, nor on it). */
static int skel_hull_mark(skel *s) {
  s->hull = calloc(s->m + 1, 1);
  if (!s->hull) return -1;
  for (size_t k = 0; k < s->nh; k++) {
    uint32_t e = skel_edge_find(s, s->hpair[2 * k], s->hpair[2 * k + 1]);
    if (e == UINT32_MAX) return -1;
    s->hull[e] = 1;
  }
  return 0;
}

/* ---- got_skel_build ------------------------------------------------------ */

/* The rule's flip decision, chosen once: 0, or -1 with a message for a rule that is no
** sum rule (a quadrilateral rule, or a joint whose keys combine by min or max). */
static int skel_decider(skel *s, const rule *r, char *err, size_t errlen) {
  const joint *J = rule_is_triangle(r) ? joint_get(rule_joint(r)) : NULL;
  if (J == NULL || J->keyop != JOINT_KEY_ADD) {
    snprintf(err, errlen, "got skeleton: rule %s is not a sum rule (the skeleton needs a "
             "triangle-based rule whose joint is l_p for a finite p)", rule_name(r));
    return -1;
  }
  const char *why;
  s->r = r;
  s->mp = measure_points(rule_measure(r));
  s->kind = SKEL_NEVER;
  if (rule_measure(r) == MEASURE_P && rule_joint(r) == JOINT_SUM)
    s->kind = SKEL_EXACT_LENGTH;
  else if (s->mp != NULL && got_cert_model(s->p, s->n, r, &s->rho, &s->alpha, &why) == 0)
    s->kind = SKEL_CERTIFIED;
  return 0;
}

/* The output's edges in ascending order (a, b): a counting sort by b, then a stable one
** by a.  O(n + m). */
static int skel_sort_edges(got_skel *o) {
  size_t m = o->nedges;
  uint32_t *e2 = malloc(2 * m * sizeof *e2 + 1), *cnt = malloc((o->n + 1) * sizeof *cnt);
  unsigned char *s2 = malloc(m + 1);
  if (!e2 || !cnt || !s2) return free(e2), free(cnt), free(s2), -1;
  for (int key = 1; key >= 0; key--) {
    memset(cnt, 0, (o->n + 1) * sizeof *cnt);
    for (size_t e = 0; e < m; e++) cnt[o->edge[2 * e + key] + 1]++;
    for (size_t v = 0; v < o->n; v++) cnt[v + 1] += cnt[v];
    for (size_t e = 0; e < m; e++) {
      uint32_t k = cnt[o->edge[2 * e + key]]++;
      e2[2 * k] = o->edge[2 * e], e2[2 * k + 1] = o->edge[2 * e + 1], s2[k] = o->state[e];
    }
    uint32_t *te = o->edge;
    unsigned char *ts = o->state;
    o->edge = e2, o->state = s2, e2 = te, s2 = ts;
  }
  free(e2), free(cnt), free(s2);
  return 0;
}

/* The live edges into out, in ascending order of input indices, with their states. */
static int skel_output(const skel *s, got_skel *out) {
  unsigned char *cert = malloc(s->m + 1);
  size_t k = 0, live = 0;
  if (!cert || skel_certain(s, cert) != 0) return free(cert), -1;
  for (size_t e = 0; e < s->m; e++) live += s->ealive[e];
  out->edge = malloc(2 * live * sizeof *out->edge + 1);
  out->state = malloc(live + 1);
  if (!out->edge || !out->state) return free(cert), -1;
  for (size_t e = 0; e < s->m; e++) {
    if (!s->ealive[e]) continue;
    uint32_t a = s->ev[2 * e], b = s->ev[2 * e + 1];
    if (s->orig) a = s->orig[a], b = s->orig[b];
    out->edge[2 * k] = a < b ? a : b, out->edge[2 * k + 1] = a < b ? b : a;
    out->state[k++] = cert[e] ? GOT_EDGE_CERTAIN : GOT_EDGE_POSSIBLE;
  }
  out->nedges = live;
  free(cert);
  return s->orig ? skel_sort_edges(out) : 0;
}

/* P_1: the points renumbered in the grid's cell order (rows of cells), so that the
** searches, the box scans and the loop read neighbours from nearby memory; s->orig maps
** back, and the hull's pairs are renumbered.  The grid then built on the renumbered points
** has the same cells, and holds point k at place k.  O(n).  (The other rules take at most
** GOT_SKEL_ALL_MAX points and keep the input's numbering: their flip decisions round the
** measures of triangles whose vertices come in index order.) */
static int skel_renumber(skel *s) {
  if (skel_grid_build(&s->g, s->p, s->n) != 0) return -1;
  s->orig = s->g.pt, s->q = s->g.gp, s->g.pt = NULL, s->g.gp = NULL;
  skel_grid_free(&s->g);
  memset(&s->g, 0, sizeof s->g);
  uint32_t *inv = malloc(s->n * sizeof *inv);
  if (!inv) return -1;
  for (size_t k = 0; k < s->n; k++) inv[s->orig[k]] = (uint32_t)k;
  for (size_t k = 0; k < s->nh; k++) {
    uint32_t a = inv[s->hpair[2 * k]], b = inv[s->hpair[2 * k + 1]];
    s->hpair[2 * k] = a < b ? a : b, s->hpair[2 * k + 1] = a < b ? b : a;
  }
  free(inv);
  s->p = s->q;
  return 0;
}

/* Candidates, triangles and the hull, with the time they took. */
static int skel_prepare(skel *s) {
  if ((s->kind == SKEL_EXACT_LENGTH && skel_renumber(s) != 0) ||
      skel_grid_build(&s->g, s->p, s->n) != 0 ||
      skel_candidates(s, s->kind == SKEL_EXACT_LENGTH) != 0)
    return -1;
  if (s->m >= UINT32_MAX / 4) return -1;
  s->ealive = malloc(s->m + 1);
  s->wit = malloc(2 * s->m * sizeof *s->wit + 1);
  if (!s->ealive || !s->wit) return -1;
  memset(s->ealive, 1, s->m);
  memset(s->wit, 0xff, 2 * s->m * sizeof *s->wit);
  if (skel_adjacency(s) != 0 || skel_hull_mark(s) != 0) return -1;
  return skel_triangles(s);
}

/* The checks of the arguments: 0, or -1 with the message.  The coordinates must obey the
** contract (geom_coord_check): the skeleton's hot orientations then skip the filter's test
** for tiny differences (geom_orient_valid): a tenth of the instructions at 10^4 points. */
static int skel_check(skel *s, const rule *r, int threads, char *err, size_t errlen) {
  size_t bad = 0, bad2 = 0;
  if (geom_threads_check(threads, err, errlen) != 0 || skel_decider(s, r, err, errlen) != 0)
    return -1;
  if (s->n < 3 || s->n > UINT32_MAX / 8) {
    snprintf(err, errlen, "got skeleton: %zu points (expected 3 to %u)", s->n, UINT32_MAX / 8);
    return -1;
  }
  if (s->kind != SKEL_EXACT_LENGTH && s->n > GOT_SKEL_ALL_MAX) {
    snprintf(err, errlen, "got skeleton: %zu points is too many for rule %s: every pair of "
             "points is a candidate for it (no exclusion test), so at most %d points",
             s->n, rule_name(r), GOT_SKEL_ALL_MAX);
    return -1;
  }
  for (size_t i = 0; i < s->n; i++) {
    geom_coorderr e = geom_coord_check(s->p[i].x);
    if (e == GEOM_COORD_OK) e = geom_coord_check(s->p[i].y);
    if (e != GEOM_COORD_OK) {
      snprintf(err, errlen, "got skeleton: point %zu (0-based): a coordinate %s", i,
               geom_coorderr_str(e));
      return -1;
    }
  }
  int rc = skel_hull(s, &bad, &bad2);
  if (rc == -2)
    snprintf(err, errlen, "got skeleton: points %zu and %zu are equal (0-based)", bad, bad2);
  else if (rc == -3)
    snprintf(err, errlen, "got skeleton: all %zu points lie on one line", s->n);
  else if (rc != 0)
    snprintf(err, errlen, "got skeleton: out of memory for %zu points", s->n);
  return rc == 0 ? 0 : -1;
}

int got_skel_build(const geom_point *p, size_t n, const rule *r, int threads, got_skel *out,
                   char *err, size_t errlen) {
  skel s = {.p = p, .n = n};
  memset(out, 0, sizeof *out);
  out->n = n;
  if (skel_check(&s, r, threads, err, errlen) != 0) return skel_free_all(&s), -1;
  s.threads = threads > 0 ? threads : omp_get_max_threads();
  double t0 = omp_get_wtime();
  int rc = skel_prepare(&s);
  double t1 = omp_get_wtime();
  out->candidates = s.m;
  if (rc == 0) rc = skel_lmt(&s, &out->rounds);
  if (rc == 0) rc = skel_output(&s, out);
  out->seconds_candidates = t1 - t0;
  out->seconds_lmt = omp_get_wtime() - t1;
  skel_free_all(&s);
  if (rc != 0) {
    got_skel_free(out);
    snprintf(err, errlen, "got skeleton: out of memory for %zu points", n);
  }
  return rc;
}

void got_skel_free(got_skel *s) {
  if (!s) return;
  free(s->edge);
  free(s->state);
  s->edge = NULL;
  s->state = NULL;
  s->nedges = 0;
}
