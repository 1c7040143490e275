/*
** cmd_linf.c: `fliplab linf`: the thesis's section 4.2 on l_inf
** circumcubes in R^d (studies/linf_study.c, studies/linf_mc.c): an
** example with each of its claims computed exactly, or the Monte Carlo of
** the circumcube count of random points with 99% Wilson intervals and the
** exact law.
*/
#include <stdio.h>
#include <string.h>
#include "cli.h"
#include "study.h"
#include "study_linf.h"

#define CMD "linf"

typedef struct cli_linf_opts {
  int example, montecarlo;
  uint64_t dim, trials, seed, threads;
} cli_linf_opts;

static const char *const cli_linf_example_names[] = {"3d", "pseudo", "r5", "facet", NULL};

#define T cli_linf_opts
static const cli_option cli_linf_table[] = {
  {.name = "--example", .arg = "E", .dflt = "none",
   .help = "3d (locally but not globally Delaunay), pseudo (two circumcubes),\n"
           "                     r5 (theorem 14's bound attained), facet (a facet of three\n"
           "                     Delaunay tetrahedra)",
   .kind = CLI_CHOICE, .off = CLI_AT(T, example, int), .names = cli_linf_example_names,
   .idef = -1, .bad = "unknown example '%s' (valid: 3d, pseudo, r5, facet)"},
  CLI_OPT_FLAG("--montecarlo", "d + 1 points uniform in the unit cube: how many circumcubes", T,
               montecarlo),
  {.name = "--dim", .arg = "D", .help = "the dimension of --montecarlo", .kind = CLI_U64,
   .off = CLI_AT(T, dim, uint64_t), .lo = LINF_DIM_MIN, .hi = LINF_DIM_MAX, .def = 5,
   .bad = "--dim: %s is out of range (the dimension must be 2 .. 8)"},
  {.name = "--trials", .arg = "N", .help = "configurations drawn", .kind = CLI_U64,
   .off = CLI_AT(T, trials, uint64_t), .lo = 1, .hi = STUDY_LINF_TRIALS_MAX, .def = 50000,
   .bad = "--trials: %s is out of range (1 .. 2^40 configurations)"},
  CLI_OPT_SEED("the random points", T, seed),
  CLI_OPT_THREADS("threads (the counts are the same for any)", T, threads),
};
#undef T

static const cli_spec cli_linf_spec = {
  CMD, "usage: fliplab linf --example E | --montecarlo [--dim D] [--trials N] [--seed S]",
  "The l_inf circumballs (axis-parallel circumcubes) of d + 1 points in R^d,\n"
  "exactly (the thesis's section 4.2; docs/linf.md).  --example prints an\n"
  "example's cells, their circumcubes and every point's distance from each\n"
  "centre, then each claim as computed: is it a triangulation, locally and\n"
  "globally Delaunay, which simplices are Delaunay (brute force and the\n"
  "selection algorithm).  --montecarlo counts the circumcubes of random\n"
  "points: each count's share with its 99% Wilson interval, beside the\n"
  "exact law (d <= 5) and theorem 14's bound.\n",
  cli_linf_table, CLI_NOPTS(cli_linf_table), NULL};

/* A simplex's or a facet's letters. */
static const char *cli_linf_name(const study_linf_report *r, const study_linf_cell *x) {
  static char name[LINF_DIM_MAX + 2];
  study_linf_key_name(r->ex, linf_row_key(x->v, r->ex->d + 1), r->ex->d + 1, name);
  return name;
}

static const char *cli_linf_facet(const study_linf_report *r, uint64_t key) {
  static char name[LINF_DIM_MAX + 2];
  study_linf_key_name(r->ex, key, r->ex->d, name);
  return name;
}

static void cli_linf_set(const study_linf_report *r, uint64_t set) {
  for (size_t c = 0; c < r->npool; c++)
    if (set >> c & 1) printf(" %s", cli_linf_name(r, &r->pool[c]));
  printf(set ? "\n" : " none\n");
}

static void cli_linf_cube(const study_linf_report *r, const study_linf_cell *x, int b) {
  char text[512];
  linf_cube_centre(&x->cube[b], text, sizeof text);
  printf("%-8s %-24s", cli_linf_name(r, x), text);
  linf_cube_distance(&x->cube[b], NULL, text, sizeof text);
  printf(" %-8s", text);
  for (size_t q = 0; q < r->ex->n; q++) {
    linf_cube_distance(&x->cube[b], r->ex->pts + q * r->ex->d, text, sizeof text);
    printf(" %4s", text);
  }
  printf("  %-5s  %s\n", x->empty[b] ? "yes" : "no", x->local[b] ? "yes" : "no");
}

/* The cells, each circumcube with every point's distance from its centre. */
static void cli_linf_cells(const study_linf_report *r) {
  if (r->cells == 0) return;
  printf("%-8s %-24s %-8s", "cell", "centre", "radius");
  for (size_t q = 0; q < r->ex->n; q++) printf(" %4c", r->ex->labels[q]);
  printf("  empty  local\n");
  for (size_t c = 0; c < r->npool; c++) {
    const study_linf_cell *x = &r->pool[c];
    if (!(r->cells >> c & 1)) continue;
    if (x->ncubes == LINF_INFINITE) printf("%-8s infinitely many\n", cli_linf_name(r, x));
    if (x->ncubes == 0) printf("%-8s no circumcube\n", cli_linf_name(r, x));
    for (int b = 0; b < x->ncubes; b++) cli_linf_cube(r, x, b);
  }
}

static void cli_linf_claims(const study_linf_report *r) {
  if (r->cells & (r->cells - 1)) {
    printf("the cells triangulate the points: %s%s%s\n", r->tiling ? "yes" : "no (",
           r->tiling ? "" : r->why, r->tiling ? "" : ")");
    printf("locally Delaunay (a circumcube without the neighbours' far vertices): %s\n",
           r->locally ? "yes" : "no");
    printf("Delaunay (a circumcube with no point inside): %s\n", r->globally ? "yes" : "no");
  }
  size_t solid = 0;
  for (size_t c = 0; c < r->npool; c++) solid += !r->pool[c].flat;
  if (solid == 0) {
    printf("the points lie in one hyperplane: they span no simplex\n");
    return;
  }
  printf("l_inf Delaunay simplices (brute force):");
  cli_linf_set(r, r->delaunay);
  printf("selection algorithm (4.2.2): %zu simplices; %llu facets, %llu cube tests, largest "
         "candidate set %llu\n", r->selected.n, (unsigned long long)r->st.facets,
         (unsigned long long)r->st.cube_tests, (unsigned long long)r->st.largest_set);
  printf("the Delaunay simplices triangulate the points: %s%s%s\n", r->del_tiling ? "yes" : "no (",
         r->del_tiling ? "" : r->del_why, r->del_tiling ? "" : ")");
  printf("hull facets %zu, with no Delaunay simplex %zu; facets inside the hull with a "
         "Delaunay simplex on one side only %zu\n", r->hull_facets, r->bare_facets,
         r->open_facets);
  printf("the most Delaunay simplices on one facet: %d (%s), %d of them on one side\n",
         r->crowded, cli_linf_facet(r, r->crowded_at), r->crowded_side);
  if (!r->searched) return;
  printf("triangulations of the points %llu: locally Delaunay %llu, Delaunay %llu\n",
         (unsigned long long)r->tilings, (unsigned long long)r->tilings_local,
         (unsigned long long)r->tilings_global);
  for (size_t k = 0; k < r->nlocal_only; k++) {
    printf("locally but not globally Delaunay:");
    cli_linf_set(r, r->local_only[k]);
  }
}

static int cli_linf_example(const study_linf_example *ex) {
  study_linf_report r;
  int rc = study_linf_examine(ex, &r);
  if (rc == 0) {
    printf("# fliplab linf --example %s: %s\n", ex->name, ex->what);
    for (size_t q = 0; q < ex->n; q++) {
      printf("%c (", ex->labels[q]);
      for (int i = 0; i < ex->d; i++) printf("%s%.17g", i ? ", " : "", ex->pts[q * ex->d + i]);
      printf(")%s", q + 1 < ex->n ? "  " : "\n");
    }
    cli_linf_cells(&r);
    cli_linf_claims(&r);
  }
  study_linf_report_free(&r);
  return rc == 0 ? 0 : (cli_error(CMD, "out of memory"), 1);
}

static void cli_linf_mc_print(const study_linf_mc *mc) {
  printf("# fliplab linf --montecarlo: %d points uniform in [0,1)^%d, %llu trials, seed %llu\n",
         mc->d + 1, mc->d, (unsigned long long)mc->trials, (unsigned long long)mc->seed);
  printf("%-6s %10s %9s   %-22s %s\n", "cubes", "trials", "percent", "99% Wilson interval",
         mc->law_total ? "exact law (percent)" : "");
  int most = 0;
  for (int k = 0; k <= LINF_CUBES_MAX; k++) {
    uint64_t law = mc->law_total ? mc->law[k] : 0;
    if (mc->count[k] == 0 && law == 0) continue;
    if (mc->count[k] > 0) most = k;
    double lo, hi;
    study_wilson_z(mc->count[k], mc->trials, STUDY_Z99, &lo, &hi);
    char iv[48];
    snprintf(iv, sizeof iv, "[%.4f, %.4f]", lo, hi);
    printf("%-6d %10llu %9.4f   %-22s", k, (unsigned long long)mc->count[k],
           100.0 * (double)mc->count[k] / (double)mc->trials, iv);
    if (mc->law_total)
      printf(" %.4f (%llu/%llu)", 100.0 * (double)law / (double)mc->law_total,
             (unsigned long long)law, (unsigned long long)mc->law_total);
    printf("\n");
  }
  if (mc->infinite) printf("infinitely many: %llu trials\n", (unsigned long long)mc->infinite);
  printf("most circumcubes seen %d; theorem 14's bound 2^floor((d-1)/2) = %d\n", most,
         linf_bound(mc->d));
}

int cli_cmd_linf(int argc, char **argv) {
  cli_linf_opts o;
  uint64_t given = 0;
  int st = cli_options_parse(&cli_linf_spec, argc, argv, &o, &given);
  if (st != 0) return st == 1 ? 0 : st;
  if ((o.example >= 0) == (o.montecarlo != 0))
    return cli_error(CMD, "give one of --example E and --montecarlo");
  static const char *const mc_only[] = {"--dim", "--trials", "--seed", "--threads"};
  for (size_t i = 0; o.example >= 0 && i < sizeof mc_only / sizeof *mc_only; i++)
    if (cli_option_given(&cli_linf_spec, given, mc_only[i]))
      return cli_error(CMD, "%s goes with --montecarlo, not --example", mc_only[i]);
  if (o.example >= 0) return cli_linf_example(&study_linf_examples[o.example]);
  study_linf_mc mc;
  char err[200];
  if (study_linf_montecarlo((int)o.dim, o.trials, o.seed, (int)o.threads, &mc, err,
                            sizeof err) != 0)
    return cli_error(CMD, "%s", err);
  cli_linf_mc_print(&mc);
  return 0;
}
