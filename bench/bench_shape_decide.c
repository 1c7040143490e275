/*
** bench_shape_decide.c: the cost of one empty-shape decision, apart from the
** mesh.  The quadrilaterals an ES rule's incremental LOT of N uniform points
** asks about are recorded (through lot's decide hook, which answers with the
** same shape_decide_valid), then each rule's decisions and DT's incircle
** test are timed on them alone, in the order lot asked them: median ns per
** call of R runs.  A rule's LOT time over DT's (bench_lot) minus what this
** shows is the mesh work the decisions do not explain.
**
**   bench_shape_decide [N [R [RULES]]]   (defaults 1000000 5 ES:square,ES:hexagon)
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "benchutil.h"
#include "lot.h"
#include "predicates.h"
#include "rule.h"
#include "sampler.h"
#include "shape.h"

typedef struct bench_quads {
  const shape *k;
  geom_point *q;
  size_t n, cap;
} bench_quads;

static rule_choice bench_record(const geom_point q[4], rule_choice cur, void *ctx) {
  bench_quads *c = ctx;
  (void)cur;
  if (c->n < c->cap) memcpy(c->q + 4 * c->n++, q, 4 * sizeof *q);
  return (rule_choice)shape_decide_valid(c->k, q[0], q[1], q[2], q[3]);
}

/* Median ns per quadrilateral of R runs of shape_decide_valid (k) or of
** the incircle test (k NULL); the sink keeps the answers alive. */
static double bench_decide_ns(const bench_quads *c, const shape *k, int R) {
  double t[64];
  volatile long sink = 0;
  for (int r = 0; r < R; r++) {
    double t0 = bench_wall();
    for (size_t i = 0; i < c->n; i++) {
      const geom_point *q = c->q + 4 * i;
      sink += k ? (long)shape_decide_valid(k, q[0], q[1], q[2], q[3])
                 : geom_incircle_valid(q[0], q[1], q[3], q[2]);
    }
    t[r] = (bench_wall() - t0) / (double)c->n * 1e9;
  }
  (void)sink;
  return bench_median(t, R);
}

static int bench_one(const char *name, const geom_point *p, size_t n, int R) {
  char err[256];
  rule r;
  if (rule_parse(name, &r, err, sizeof err) != 0) {
    fprintf(stderr, "bench_shape_decide: %s\n", err);
    return 1;
  }
  if (rule_shape(&r) == NULL) {
    fprintf(stderr, "bench_shape_decide: %s: not an empty-shape (ES:) rule\n", name);
    return 1;
  }
  bench_quads c = {.k = rule_shape(&r), .cap = 24 * n};
  c.q = malloc(4 * c.cap * sizeof *c.q);
  lot_options o;
  lot_options_init(&o, &r);
  o.decide = bench_record;
  o.decide_ctx = &c;
  lot *L = NULL;
  if (c.q == NULL || lot_build(&L, p, n, &o, err, sizeof err) != 0) {
    fprintf(stderr, "bench_shape_decide: %s: %s\n", name, c.q ? err : "out of memory");
    free(c.q);
    return 1;
  }
  lot_free(L);
  double es = bench_decide_ns(&c, c.k, R), dt = bench_decide_ns(&c, NULL, R);
  printf("| %s | %zu | %.1f | %.1f | %.1f |\n", name, c.n, es, dt, es - dt);
  free(c.q);
  return 0;
}

int main(int argc, char **argv) {
  size_t n = argc > 1 ? strtoull(argv[1], NULL, 10) : 1000000;
  int R = argc > 2 ? atoi(argv[2]) : 5;
  const char *rules = argc > 3 ? argv[3] : "ES:square,ES:hexagon";
  if (n < 3 || n > 20000000 || R < 1 || R > 64) {
    fprintf(stderr, "bench_shape_decide: N must be 3..2e7 and R 1..64\n");
    return 2;
  }
  geom_point *p = malloc(n * sizeof *p);
  if (p == NULL) return 1;
  sampler_points(SAMPLER_UNIFORM, 1, n, p);
  printf("# bench_shape_decide: the decisions of each rule's LOT of %zu uniform points, median of %d\n"
         "(load average at start: %.2f)\n\n"
         "| rule | decisions | ns per decision | DT's incircle, same quads (ns) | difference (ns) |\n"
         "|---|---:|---:|---:|---:|\n", n, R, bench_load());
  int rc = 0;
  char *list = strdup(rules), *save = NULL;
  for (char *s = strtok_r(list, ",", &save); s && rc == 0; s = strtok_r(NULL, ",", &save))
    rc = bench_one(s, p, n, R);
  printf("(load average at end: %.2f)\n", bench_load());
  free(list);
  free(p);
  return rc;
}
