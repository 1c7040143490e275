/*
** bench_got_points.c: the GOT of a point set end to end (got_points_solve,
** got/got_points.c): the exact minimum-weight triangulation (P_1) of uniform
** random points in the unit square, then another sum rule at the largest n its
** skeleton takes; wall and CPU seconds (median of REPS runs where given), seconds
** per stage, candidate and certain edges (and their share of the 3n - h - 3 edges
** of a triangulation), faces left and the largest, the certified verdict, and the
** process's peak resident memory so far (getrusage: rows run in the order given, so a
** row's figure is its own peak when sizes ascend).  The load average is printed: on a
** shared machine wall times grow with it.
** Usage: bench_got_points [--reps R] [--threads T] [--rule RULE N] [--dt] [N ...]
**        (default: 10000 100000 1000000 for P_1, medians of 3 below 10^6, 1 at 10^6;
**        then a_2 at 200 points).  --dt: the rules whose GOT is Delaunay instead, R_1 and
**        -r_1 (skeleton delaunay: lot's exact Delaunay triangulation, certified; default
**        sizes 100000 1000000), then both on the 316 x 316 integer grid, whose every
**        square is a cocircular cell: a tied face.  All runs go through study_got_points,
**        as the program's; "dt s" is the Delaunay triangulation's time, "cand s" the
**        certificate's (delaunay) or the candidate search's (lmt).
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include "benchutil.h"
#include "got.h"
#include "study.h"

#define BENCH_MAXN 16

static rule bench_rule(const char *name) {
  rule r;
  char err[256];
  if (rule_parse(name, &r, err, sizeof err) != 0) {
    fprintf(stderr, "bench_got_points: %s\n", err);
    exit(2);
  }
  return r;
}

/* n uniform points (seed 1), or the side x side integer grid when side > 0. */
static geom_point *bench_points(size_t n, size_t side) {
  geom_point *p = malloc(n * sizeof *p);
  if (p == NULL) exit(1);
  if (side == 0) sampler_points(SAMPLER_UNIFORM, 1, n, p);
  for (size_t i = 0; side > 0 && i < n; i++) p[i] = (geom_point){(double)(i % side),
                                                                  (double)(i / side)};
  return p;
}

/* One size: REPS runs, the median's figures printed as one row. */
static void bench_row(const rule *r, size_t n, size_t side, int reps, int threads) {
  geom_point *p = bench_points(n, side);
  got_result res[5];
  bench_time t[5];
  char err[512];
  got_options o = {threads, RULE_DEFAULT_TIE_EPS};
  for (int k = 0; k < reps; k++) {
    double w = bench_wall(), c = bench_cpu();
    if (study_got_points(p, n, r, &o, GOT_SKELETON_AUTO, &res[k], err, sizeof err) != 0) {
      printf("%-8s %9zu  failed: %s\n", rule_name(r), n, err);
      free(p);
      return;
    }
    t[k] = (bench_time){bench_wall() - w, bench_cpu() - c};
    res[k].seconds = t[k].wall;
  }
  int m = 0;                 /* the run of median wall time */
  for (int k = 0; k < reps; k++) {
    int below = 0;
    for (int j = 0; j < reps; j++) below += t[j].wall < t[k].wall;
    if (below == reps / 2) m = k;
  }
  const got_result *g = &res[m];
  size_t tedges = n - 1 + g->ntri;
  struct rusage ru;
  double peak = getrusage(RUSAGE_SELF, &ru) == 0 ? (double)ru.ru_maxrss / 1024 : NAN;
  printf("%-8s %9zu%s %4d %9.2f %9.2f %6.2f %8.2f %8.2f %7.3f %7.3f %10zu %6.2f%% %8zu %7zu "
         "%7.0f %s\n",
         rule_name(r), n, side ? "g" : " ", reps, t[m].wall, t[m].cpu, g->seconds_delaunay,
         g->seconds_candidates, g->seconds_lmt, g->seconds_faces, g->seconds_solve,
         g->candidates,
         100.0 * (double)g->certain / (double)tedges, g->faces_left, g->largest_face, peak,
         g->cert_unique ? "unique" : "tie not excluded");
  fflush(stdout);             /* a row at a time: the large sizes take minutes */
  for (int k = 0; k < reps; k++) got_result_free(&res[k]);
  free(p);
}

int main(int argc, char **argv) {
  size_t ns[BENCH_MAXN] = {10000, 100000, 1000000};
  int nn = 3, reps = 0, threads = 0, given = 0, dt = 0;
  const char *other = "a_2";
  size_t other_n = 200;
  for (int i = 1; i < argc; i++) {
    if (strcmp(argv[i], "--reps") == 0 && i + 1 < argc) reps = atoi(argv[++i]);
    else if (strcmp(argv[i], "--threads") == 0 && i + 1 < argc) threads = atoi(argv[++i]);
    else if (strcmp(argv[i], "--dt") == 0) dt = 1;
    else if (strcmp(argv[i], "--rule") == 0 && i + 2 < argc)
      other = argv[++i], other_n = (size_t)strtoull(argv[++i], NULL, 10);
    else if (nn < BENCH_MAXN || !given) {
      if (!given) nn = 0, given = 1;       /* sizes given: they replace the defaults */
      ns[nn++] = strtoull(argv[i], NULL, 10);
    }
  }
  if (reps < 0 || reps > 5) reps = 5;
  if (dt && !given) nn = 2, ns[0] = 100000, ns[1] = 1000000;
  printf("# bench_got_points: uniform points (seed 1; n g: the integer grid), skeleton auto, "
         "threads %d (0: all); load %.2f\n", threads, bench_load());
  printf("%-8s %10s %4s %9s %9s %6s %8s %8s %7s %7s %10s %7s %8s %7s %7s %s\n", "rule", "n",
         "reps", "wall s", "cpu s", "dt s", "cand s", "lmt s", "faces s", "solve s",
         "candidates", "certain", "faces>3", "largest", "peak MB", "certified");
  const char *names[2] = {"P_1", other};
  if (dt) names[0] = "R_1", names[1] = "-r_1";
  for (int k = 0; k < (dt ? 2 : 1); k++) {
    rule r = bench_rule(names[k]);
    for (int i = 0; i < nn; i++)
      bench_row(&r, ns[i], 0, reps ? reps : ns[i] < 1000000 ? 3 : 1, threads);
    if (dt) bench_row(&r, 316 * 316, 316, reps ? reps : 3, threads);
  }
  rule ro = bench_rule(other);
  if (!dt) bench_row(&ro, other_n, 0, reps ? reps : 3, threads);
  printf("# load at the end %.2f\n", bench_load());
  return 0;
}
