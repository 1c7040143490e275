/*
** bench_triavg.c: the enumeration of every triangulation (studies/trienum.c)
** against a plain recursive enumerator that rebuilds each triangulation's
** sums from its diagonals (the peer), and the closed forms at large n.
**   bench_triavg [N_ENUM ...]    (default 12 14 16)
** Prints, per n: triangulations, the median CPU seconds of 5 runs (3 at
** n >= 16) and ns per triangulation of the enumerator with every vertex's
** degree histogram, of its fast path (two vertices: study_avg_new's) and of
** the peer, the peer's time over each of the two, and whether the totals
** agree; then the closed forms' time at n = 10^3,
** 10^4, 10^5 and the fitted exponent (O(n^2) word operations expected).
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "benchutil.h"
#include "triavg_internal.h"

/* ---- the peer ---------------------------------------------------------------- */

typedef struct bench_peer {
  int nv, cut, npend, ndiag;
  int pend[2 * STUDY_ENUM_VMAX], diag[2 * STUDY_ENUM_VMAX];
  study_enum_totals *t;
} bench_peer;

static void bench_peer_leaf(bench_peer *p) {
  uint64_t s[3] = {0, 0, 0}, t[3];
  uint8_t deg[STUDY_ENUM_VMAX] = {0};
  for (int q = 0; q < p->ndiag; q++) {
    int i = p->diag[2 * q], j = p->diag[2 * q + 1];
    study_diag_terms((uint32_t)i, (uint32_t)j, (uint32_t)p->nv, (uint32_t)p->cut, t);
    for (int r = 0; r < 3; r++) s[r] += t[r];
    deg[i]++, deg[j]++;
  }
  p->t->count++;
  p->t->tc += s[0] + (uint64_t)(p->nv - 2);
  p->t->cross += s[1];
  p->t->len += s[2];
  for (int v = 0; v < p->nv; v++) p->t->hist[v][deg[v]]++;
}

/* Take the last pending piece p_a .. p_b, try each apex, recurse. */
static void bench_peer_rec(bench_peer *p) {
  if (p->npend == 0) {
    bench_peer_leaf(p);
    return;
  }
  p->npend--;
  int a = p->pend[2 * p->npend], b = p->pend[2 * p->npend + 1];
  for (int k = a + 1; k < b; k++) {
    int np = p->npend, nd = p->ndiag;
    int sides[2][2] = {{a, k}, {k, b}};
    for (int s = 0; s < 2; s++)
      if (sides[s][1] - sides[s][0] >= 2) {
        p->diag[2 * p->ndiag] = sides[s][0], p->diag[2 * p->ndiag + 1] = sides[s][1];
        p->ndiag++;
        p->pend[2 * p->npend] = sides[s][0], p->pend[2 * p->npend + 1] = sides[s][1];
        p->npend++;
      }
    bench_peer_rec(p);
    p->npend = np;
    p->ndiag = nd;
  }
  p->pend[2 * p->npend] = a, p->pend[2 * p->npend + 1] = b;
  p->npend++;
}

static void bench_peer_run(int n, study_enum_totals *t) {
  bench_peer p = {.nv = n + 2, .cut = n / 2, .npend = 1, .t = t};
  memset(t, 0, sizeof *t);
  p.pend[0] = 0, p.pend[1] = n + 1;
  bench_peer_rec(&p);
}

/* ---- timing ---------------------------------------------------------------- */

/* mode 0: the enumerator with every vertex's degree histogram (the peer's
** work); 1: its fast path (p_n and p_{n+1} only, what study_avg_new runs);
** 2: the peer. */
static bench_time bench_enum(int n, int runs, int mode, study_enum_totals *t) {
  bench_time tt[5];
  for (int r = 0; r < runs; r++) {
    double w = bench_wall(), c = bench_cpu();
    if (mode == 2) bench_peer_run(n, t);
    else study_enum_run(n, mode == 0, t);
    tt[r] = (bench_time){bench_wall() - w, bench_cpu() - c};
  }
  return bench_median_time(tt, runs);
}

static double bench_closed(int n) {
  double v[3];
  char err[256];
  for (int r = 0; r < 3; r++) {
    double c = bench_cpu();
    study_avg *a = study_avg_new(n, 0, err, sizeof err);
    if (!a) {
      fprintf(stderr, "bench_triavg: %s\n", err);
      exit(1);
    }
    study_avg_delete(a);
    v[r] = bench_cpu() - c;
  }
  return bench_median(v, 3);
}

int main(int argc, char **argv) {
  int ns[8] = {12, 14, 16}, nn = 3;
  if (argc > 1) nn = 0;
  for (int i = 1; i < argc && nn < 8; i++) {
    ns[nn] = atoi(argv[i]);
    if (ns[nn] < 1 || ns[nn] > STUDY_AVG_ENUM_NMAX) {
      fprintf(stderr, "bench_triavg: n '%s' outside 1..%d\n", argv[i], STUDY_AVG_ENUM_NMAX);
      return 2;
    }
    nn++;
  }
  printf("load %.2f; cpu seconds, medians; ns per triangulation in brackets\n"
         "%4s %12s %16s %16s %16s %6s %6s %6s\n", bench_load(), "n", "triangs", "every vertex",
         "fast path", "peer", "ratio", "ratio", "agree");
  static study_enum_totals a, b, f;
  for (int i = 0; i < nn; i++) {
    int runs = ns[i] >= 16 ? 3 : 5;
    bench_time te = bench_enum(ns[i], runs, 0, &a), tf = bench_enum(ns[i], runs, 1, &f);
    bench_time tp = bench_enum(ns[i], runs, 2, &b);
    int agree = a.count == b.count && a.tc == b.tc && a.cross == b.cross && a.len == b.len &&
                memcmp(a.hist, b.hist, sizeof a.hist) == 0 && f.tc == a.tc;
    double k = 1e9 / (double)a.count;
    printf("%4d %12llu %7.3f (%5.1f) %7.3f (%5.1f) %7.3f (%5.1f) %6.2f %6.2f %6s\n", ns[i],
           (unsigned long long)a.count, te.cpu, te.cpu * k, tf.cpu, tf.cpu * k, tp.cpu,
           tp.cpu * k, tp.cpu / te.cpu, tp.cpu / tf.cpu, agree ? "yes" : "NO");
  }
  double c3 = bench_closed(1000), c4 = bench_closed(10000), c5 = bench_closed(100000);
  printf("closed forms, cpu s (median of 3): n=1e3 %.4f, n=1e4 %.3f, n=1e5 %.2f; "
         "exponent 1e4..1e5 %.2f\n", c3, c4, c5, log10(c5 / c4));
  return 0;
}
