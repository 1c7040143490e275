/*
** bench_got_face.c: the exact solver for a point set's faces
** (got/got_face.c): regions visited and wall time for random faces of 10
** to 40 boundary vertices (star-shaped polygons, sampler_star) with 0 to 5
** points inside (drawn in the polygon's kernel near the centre), every
** segment allowed (the worst case: a skeleton's faces allow fewer), under
** P_1 and -alpha_1.  Medians over FACES faces per row of the regions, the
** wall time and the CPU time (one thread: on a shared machine the wall
** time grows with the load average, printed, and the CPU time less).
** Usage: bench_got_face [--quick] (at most 30 vertices, 3 inner points).
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "benchutil.h"
#include "got_face.h"
#include "sampler.h"

#define FACES 5
#define MAXV 48

typedef struct bench_face {
  geom_point p[MAXV];
  size_t nb, ninner, nedges;
  size_t len;
  uint32_t walk[MAXV], inner[MAXV], edge[MAXV * MAXV];
} bench_face;

/* 1 when q is strictly left of every edge of the polygon (its kernel). */
static int bench_in_kernel(const geom_point *p, size_t n, geom_point q) {
  for (size_t i = 0; i < n; i++)
    if (geom_orient(p[i], p[(i + 1) % n], q) <= 0) return 0;
  return 1;
}

static void bench_make(sampler_rng *g, size_t nb, size_t k, bench_face *f) {
  if (sampler_star(g, nb, f->p) != 0) {
    fprintf(stderr, "bench_got_face: no star-shaped %zu-gon\n", nb);
    exit(1);
  }
  f->nb = nb, f->ninner = 0, f->len = nb;
  for (size_t i = 0; i < nb; i++) f->walk[i] = (uint32_t)i;
  while (f->ninner < k) {
    geom_point q = {0.3 * sampler_uniform(g) - 0.15, 0.3 * sampler_uniform(g) - 0.15};
    if (!bench_in_kernel(f->p, nb, q)) continue;
    f->p[nb + f->ninner] = q;
    f->inner[f->ninner] = (uint32_t)(nb + f->ninner);
    f->ninner++;
  }
  f->nedges = 0;
  for (uint32_t i = 0; i < nb + k; i++)
    for (uint32_t j = i + 1; j < nb + k; j++)
      f->edge[2 * f->nedges] = i, f->edge[2 * f->nedges++ + 1] = j;
}

static void bench_row(sampler_rng *g, size_t nb, size_t k, const rule *r) {
  double t[FACES], cpu[FACES], st[FACES];
  for (int q = 0; q < FACES; q++) {
    bench_face f;
    bench_make(g, nb, k, &f);
    got_face_in in = {f.p, 1, &f.len, f.walk, f.inner, f.ninner, f.edge, f.nedges};
    got_face_out o;
    char err[256];
    double c0 = bench_cpu(), t0 = bench_wall();
    if (got_face_solve(&in, r, &o, err, sizeof err) != 0) {
      fprintf(stderr, "bench_got_face: %s\n", err);
      exit(1);
    }
    t[q] = bench_wall() - t0;
    cpu[q] = bench_cpu() - c0;
    st[q] = (double)o.states;
    got_face_out_free(&o);
  }
  printf("%-9s %9zu %6zu %12.0f %12.4f %12.4f\n", rule_name(r), nb, k, bench_median(st, FACES),
         bench_median(t, FACES), bench_median(cpu, FACES));
}

int main(int argc, char **argv) {
  int quick = argc > 1 && strcmp(argv[1], "--quick") == 0;
  const char *names[] = {"P_1", "-alpha_1"};
  const size_t nbs[] = {10, 20, 30, 40}, ks[] = {0, 1, 2, 3, 5};
  printf("# bench_got_face: load average %.2f; medians of %d faces per row\n", bench_load(),
         FACES);
  printf("%-9s %9s %6s %12s %12s %12s\n", "rule", "vertices", "inner", "regions", "seconds",
         "cpu-seconds");
  for (size_t q = 0; q < 2; q++) {
    rule r;
    char err[256];
    if (rule_parse(names[q], &r, err, sizeof err) != 0) return 1;
    sampler_rng g;
    sampler_seed(&g, 38, 0);
    for (size_t a = 0; a < 4; a++)
      for (size_t b = 0; b < 5; b++)
        if (!quick || (nbs[a] <= 30 && ks[b] <= 3)) bench_row(&g, nbs[a], ks[b], &r);
  }
  return 0;
}
