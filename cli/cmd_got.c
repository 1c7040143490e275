/*
** cmd_got.c: `fliplab got`: the globally optimal triangulation of a simple
** polygon (thesis Algorithm 1, over the valid diagonals when the polygon is
** not convex) for a triangle-based rule, from a CSV file or a random
** polygon; prints the total badness, whether the optimum is unique (the
** runner-up gap), the time, and the triangles; optionally writes them as
** CSV and draws an SVG, and compares a convex polygon's GOT with its
** Delaunay triangulation (as Nielson and Franke did).
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "measure.h"
#include "cli.h"
#include "got.h"
#include "sampler.h"
#include "report.h"
#include "study.h"

#define CMD "got"
#define CLI_GOT_MAX_N 1000000000000ull   /* parse bound; memory decides the real one */
#define CLI_GOT_PRINT_N 50               /* list triangles by default up to this n */

/* The --random samplers, by name; the first is the default. */
typedef struct cli_got_sampler {
  const char *name, *what;
  int (*fn)(sampler_rng *g, size_t n, geom_point *out);
} cli_got_sampler;

static const cli_got_sampler cli_got_samplers[] = {
  {"vector", "a strictly convex", sampler_vector},
  {"circle", "a strictly convex", sampler_circle},
  {"star", "a simple star-shaped", sampler_star},
  {"monotone", "a simple x-monotone", sampler_monotone},
};

static int cli_got_sampler_find(const char *name) {
  for (size_t q = 0; q < sizeof cli_got_samplers / sizeof *cli_got_samplers; q++)
    if (strcmp(name, cli_got_samplers[q].name) == 0) return (int)q;
  return -1;
}

typedef struct cli_got_args {
  const char *rule, *polygon, *csv, *svg;
  int sampler;          /* index in cli_got_samplers */
  int compare;          /* 0: --compare DT, -1: none */
  uint64_t random, seed, threads;
  double tie_eps;
  int shade, print;     /* print: -1 default, 0 no, 1 yes */
  /* point sets (cmd_got.c's second half) */
  const char *points;
  int distribution;     /* a sampler_points_kind, -1: none (a polygon) */
  int skeleton;         /* got_skeleton */
  int no_lot;
  uint64_t gap_table;   /* sets of the local-against-global table, 0: none */
} cli_got_args;

static const char *const cli_got_compares[] = {"DT", NULL};
static const char *const cli_got_skeletons[] = {"auto", "all", "lmt", "delaunay", NULL};

#define T cli_got_args
static const cli_option cli_got_opts[] = {
  CLI_OPT_STRING("--rule", "RULE", "required",
                 "triangle-based rule MEASURE_JOINT, e.g. P_1, R_inf, sigma_2", T, rule),
  CLI_OPT_STRING("--polygon", "FILE.csv", "none: give --polygon or --random",
                 "CSV, one vertex 'x,y' per row (optional header 'x,y'; '-':\n"
                 "                     standard input): any simple polygon (no repeated vertex,\n"
                 "                     no two edges crossing or touching; collinear vertices\n"
                 "                     allowed), either orientation (clockwise input is reversed\n"
                 "                     keeping vertex 0; printed indices are always the file's\n"
                 "                     rows, 0-based)", T, polygon),
  {.name = "--random", .arg = "N", .dflt = "none",
   .help = "a random N-gon, anticlockwise (see --sampler)", .kind = CLI_U64,
   .off = CLI_AT(T, random, uint64_t), .lo = 3, .hi = CLI_GOT_MAX_N},
  CLI_OPT_SEED("the random polygon's seed", T, seed),
  {.name = "--sampler", .arg = "NAME", .dflt = "vector",
   .help = "convex: vector (thesis 6.4) or circle (random angles on the\n"
           "                     unit circle: cocircular up to rounding); simple: star\n"
           "                     (sorted random angles, radii in [0.2, 1]) or monotone\n"
           "                     (x-monotone, from random points in the unit square)",
   .kind = CLI_CHOICE, .off = CLI_AT(T, sampler, int), .find = cli_got_sampler_find,
   .bad = "unknown sampler '%s' (valid: vector, circle, star, monotone)"},
  CLI_OPT_THREADS("OpenMP threads; results do not depend on T", T, threads),
  CLI_OPT_TIE_EPS("relative tolerance under which the runner-up ties", 1, T, tie_eps),
  CLI_OPT_FILE("--csv", "FILE.csv", "none", "csv",
               "write the triangles: i,j,k,badness (docs/formats.md)", T, csv),
  CLI_OPT_FILE("--svg", "FILE.svg", "none", "svg", "draw the polygon and its GOT", T, svg),
  CLI_OPT_FLAG("--shade", "with --svg: fill the triangles by badness (light = good)", T, shade),
  {.name = "--compare", .arg = "DT", .dflt = "none",
   .help = "diagonals and triangles shared with the Delaunay triangulation\n"
           "                     (convex polygons only)",
   .kind = CLI_CHOICE, .off = CLI_AT(T, compare, int), .names = cli_got_compares, .idef = -1,
   .bad = "--compare supports DT only, got '%s'"},
  {.name = "--print-triangles", .help = "list the triangles (the default when n <= 50)",
   .kind = CLI_FLAG, .off = CLI_AT(T, print, int), .set = 1, .idef = -1},
  {.name = "--no-triangles", .help = "do not list them (the default when n > 50)",
   .kind = CLI_FLAG, .off = CLI_AT(T, print, int), .set = 0, .idef = -1},
  CLI_OPT_STRING("--points", "FILE.csv", "none",
                 "a point set instead of a polygon: CSV 'x,y' per row (as lot\n"
                 "                     reads it), distinct points, not all collinear; a sum\n"
                 "                     rule (l_1, l_2, l_0, l_-1, l_p): docs/got.md \"Point sets\"",
                 T, points),
  {.name = "--distribution", .arg = "NAME", .dflt = "none",
   .help = "with --random N: N random points of a point sampler (lot's\n"
           "                     --sampler names: uniform, normal, disc, grid, ...) instead\n"
           "                     of a polygon",
   .kind = CLI_CALL, .off = CLI_AT(T, distribution, int), .idef = -1,
   .call = cli_option_points_sampler},
  {.name = "--skeleton", .arg = "S", .help = "point sets: lmt (the LMT-skeleton), all (every\n"
           "                     edge, tiny n), delaunay (the certified Delaunay\n"
           "                     subdivision: R_1, -r_1, abc_1, ...) or auto (delaunay\n"
           "                     where it applies, else lmt)",
   .kind = CLI_CHOICE, .off = CLI_AT(T, skeleton, int), .names = cli_got_skeletons,
   .idef = GOT_SKELETON_AUTO, .bad = "unknown skeleton '%s' (valid: auto, all, lmt, delaunay)"},
  CLI_OPT_FLAG("--no-lot", "point sets: skip the LOT's total and its gap to the GOT", T, no_lot),
  {.name = "--gap-table", .arg = "SETS", .dflt = "none",
   .help = "how far local is from global: for each rule of --rule\n"
           "                     R1,R2,..., the gap LOT - GOT over SETS sets of --random N\n"
           "                     points of --distribution (default uniform)",
   .kind = CLI_U64, .off = CLI_AT(T, gap_table, uint64_t), .lo = 1, .hi = 1000000000},
};
#undef T

static const cli_spec cli_got_spec = {
  CMD, "usage: fliplab got --rule RULE (--polygon FILE.csv | --random N) [options]\n"
  "       fliplab got --rule RULE (--points FILE.csv | --random N --distribution NAME)\n"
  "       fliplab got --gap-table SETS --random N --rule RULE,... [options]",
  "Globally optimal triangulation GOT(b_f) of a simple polygon (convex or not):\n"
  "the thesis's Algorithm 1 over the polygon's valid diagonals, Theta(n^3) time\n"
  "and Theta(n^2) memory, ties broken towards the smallest split vertex k; of a\n"
  "point set, for a sum rule: the skeleton's certain edges, then each face they\n"
  "leave solved exactly (docs/got.md).\n",
  cli_got_opts, CLI_NOPTS(cli_got_opts), NULL};

/* Point sets: --points FILE or --random N --distribution NAME (or --gap-table). */
static int cli_got_parse_points(cli_got_args *a, uint64_t given) {
  if (a->polygon)
    return cli_error(CMD, "--polygon gives a polygon: not with --points, --distribution or "
                     "--gap-table");
  if ((a->points != NULL) == (a->random != 0))
    return cli_error(CMD, "give exactly one of --points FILE.csv and --random N");
  if (a->points && a->distribution >= 0)
    return cli_error(CMD, "--distribution applies to --random only");
  if (cli_option_given(&cli_got_spec, given, "--sampler"))
    return cli_error(CMD, "--sampler names a polygon sampler: for random points give "
                     "--distribution NAME");
  if (a->compare >= 0)
    return cli_error(CMD, "--compare DT needs a convex polygon: a point set's statistics "
                     "compare the GOT with the LOT instead");
  if (a->gap_table && a->points)
    return cli_error(CMD, "--gap-table draws its own sets: give --random N, not --points");
  if (a->gap_table && (a->csv || a->svg || a->print == 1))
    return cli_error(CMD, "--gap-table prints a table: not with --csv, --svg or "
                     "--print-triangles");
  if (a->shade && a->svg == NULL) return cli_error(CMD, "--shade needs --svg FILE");
  if (a->distribution < 0) a->distribution = SAMPLER_UNIFORM;
  return 0;
}

/* 0, 1 after --help, 2 after an error. */
static int cli_got_parse(int argc, char **argv, cli_got_args *a) {
  uint64_t given;
  int st = cli_options_parse(&cli_got_spec, argc, argv, a, &given);
  if (st != 0) return st;
  if (a->rule == NULL) return cli_error(CMD, "--rule is required (e.g. --rule P_1)");
  if (a->points != NULL || a->distribution >= 0 || a->gap_table)
    return cli_got_parse_points(a, given);
  if (cli_option_given(&cli_got_spec, given, "--skeleton") || a->no_lot)
    return cli_error(CMD, "--skeleton and --no-lot apply to point sets (--points FILE.csv, "
                     "or --random N --distribution NAME)");
  if ((a->polygon != NULL) == (a->random != 0))
    return cli_error(CMD, "give exactly one of --polygon FILE.csv and --random N");
  if (cli_option_given(&cli_got_spec, given, "--sampler") && a->polygon)
    return cli_error(CMD, "--sampler applies to --random only");
  if (a->shade && a->svg == NULL) return cli_error(CMD, "--shade needs --svg FILE");
  return 0;
}

/* The polygon: read (map = file row of each vertex) or sampled. */
static int cli_got_polygon(const cli_got_args *a, const rule *r, geom_point **p, size_t *n,
                           size_t **map, char *desc, size_t desclen) {
  char err[512];
  if (a->polygon) {
    int rev = 0;
    if (report_got_read_polygon(a->polygon, p, n, &rev, err, sizeof err) != 0)
      return cli_error(CMD, "%s", err);
    if (got_check_memory(*n, rule_measure(r), err, sizeof err) != 0)
      return cli_error(CMD, "%s", err);
    *map = malloc(*n * sizeof **map);
    if (*map == NULL) return cli_error(CMD, "out of memory");
    for (size_t v = 0; v < *n; v++) (*map)[v] = rev ? (*n - v) % *n : v;
    snprintf(desc, desclen, "%s%s", a->polygon, rev ? " (clockwise: reversed keeping vertex 0)" : "");
    return 0;
  }
  *n = (size_t)a->random;
  if (got_check_memory(*n, rule_measure(r), err, sizeof err) != 0)
    return cli_error(CMD, "%s", err);
  *p = malloc(*n * sizeof **p);
  if (*p == NULL) return cli_error(CMD, "out of memory for %zu points", *n);
  sampler_rng g;
  sampler_seed(&g, a->seed, GEOM_STREAM_GOT_POLYGON);
  const cli_got_sampler *s = &cli_got_samplers[a->sampler];
  int src = s->fn(&g, *n, *p);
  if (src == SAMPLER_ENOMEM) return cli_error(CMD, "out of memory");
  if (src != 0)
    return cli_error(CMD, "the %s sampler could not make %s %zu-gon in floating point "
                     "(points too close); use a smaller N", s->name, s->what, *n);
  snprintf(desc, desclen, "random %zu-gon (%s sampler, seed %llu)", *n, s->name,
           (unsigned long long)a->seed);
  return 0;
}

static void cli_got_runner_up(const got_result *res) {
  char b[64];
  /* a point set's runner-up is over the triangulations holding the skeleton */
  const char *ru = res->points ? "runner-up (holding the skeleton)" : "runner-up";
  if (!res->has_runner_up) {
    printf("%s: none (%s): the optimum is unique\n", ru, res->points ? "every face is a "
           "triangle" : "a triangle has one triangulation");
    return;
  }
  got_format_total(res, res->key2, b, sizeof b);
  if (!res->unique)
    printf("%s: tie (relative gap %.3g <= tie-eps %.3g): the optimum is NOT unique\n", ru,
           res->rel_gap, res->tie_eps);
  else if (joint_get(res->joint)->key == JOINT_SHAPE_LOG &&
           !(fabs(res->gap) > 0 && isfinite(res->gap)))
    printf("%s: %s (relative gap %.6g): the optimum is unique\n", ru, b, res->rel_gap);
  else
    printf("%s: %s (gap %.6g, relative %.6g): the optimum is unique\n", ru, b, res->gap,
           res->rel_gap);
}

/* The certified verdict (got_cert.c): gap and bound in key units, which
** are the totals' units when the joint table names none. */
static void cli_got_certified(const got_result *res) {
  if (!res->has_runner_up) {
    printf("certified: unique optimum (the only triangulation%s)\n",
           res->points ? " holding the skeleton" : "");
    return;
  }
  const char *ku = joint_get(res->joint)->key_units;
  char units[80] = "";
  if (ku != NULL) snprintf(units, sizeof units, "; key units: %s", ku);
  if (res->cert_unique)
    printf("certified: unique optimum (gap %.3g > error bound %.3g%s)\n", res->cert_gap,
           res->cert_bound, units);
  else if (res->cert_why)
    printf("certified: tie not excluded (gap %.3g <= error bound inf: %s)\n", res->cert_gap,
           res->cert_why);
  else
    printf("certified: tie not excluded (gap %.3g <= error bound %.3g%s)\n", res->cert_gap,
           res->cert_bound, units);
}

/* 0, or 1 after the one-line error: a comparison that could not be made
** fails the run rather than print a line of "failed" with status 0. */
static int cli_got_compare(const geom_point *p, size_t n, const got_result *res) {
  got_triangle *dt = malloc(n * sizeof *dt);
  got_diff d;
  int unique = 1;
  if (dt == NULL || got_delaunay(p, n, dt, &unique) != 0 ||
      got_compare(res->tri, dt, n, &d) != 0) {
    free(dt);
    cli_error(CMD, "out of memory");
    return 1;
  }
  printf("compare DT: %zu of %zu diagonals differ; %zu of %zu triangles in common (%.2f%%)%s\n",
         d.diagonals_differ, d.diagonals, d.triangles_common, d.triangles,
         100.0 * (double)d.triangles_common / (double)d.triangles,
         unique ? "; the Delaunay triangulation is unique"
                : "; the Delaunay triangulation is NOT unique (4+ cocircular vertices): "
                  "compared with the one of smallest split vertices");
  free(dt);
  return 0;
}

/* Strictly convex (exact)?  --compare DT needs it. */
/* 1 convex, 0 not, -1 out of memory. */
static int cli_got_is_convex(const geom_point *p, size_t n) {
  geom_point *q = malloc(n * sizeof *q);
  if (q == NULL) return -1;
  memcpy(q, p, n * sizeof *q);
  int rev = 0, ok = geom_polygon_check(q, n, NULL, &rev) == GEOM_OK && !rev;
  free(q);
  return ok;
}

/* Help, options and the rule; 0 to go on, otherwise the exit code (-1:
** help printed, exit 0). */
static int cli_got_setup(int argc, char **argv, cli_got_args *a, rule *r) {
  memset(a, 0, sizeof *a);
  int rc = cli_got_parse(argc, argv, a);
  if (rc != 0) return rc == 1 ? -1 : rc;
  if (a->gap_table) return 0;                  /* a list of rules: cli_got_table */
  if (cli_parse_rule(CMD, a->rule, r) != 0) return 2;
  if (!rule_is_triangle(r))
    return cli_error(CMD, "rule %s is not triangle-based: GOT needs a measure and a joint "
                     "(MEASURE_JOINT, e.g. R_inf or P_1)", rule_name(r));
  return 0;
}

/* The header, total, runner-up and time lines. */
static void cli_got_summary(const cli_got_args *a, const rule *r, const got_result *res,
                            const char *desc, const char *tot) {
  const joint *jt = joint_get(rule_joint(r));
  printf("# fliplab got: rule %s (measure %s, joint %s), n = %zu, %s, tie-eps %.3g\n", rule_name(r),
         rule_measure_name(r), jt->symbol, res->n, desc, a->tie_eps);
  if (jt->key == JOINT_SHAPE_LOG)
    printf("total badness: %s (key %s = %.17g)\n", tot,
           res->sign >= 0 ? "ln B" : "-ln|B|", res->key);
  else
    printf("total badness: %s\n", tot);
  cli_got_runner_up(res);
  cli_got_certified(res);
  printf("time: %.4f s (%d thread%s)\n", res->seconds, res->threads,
         res->threads == 1 ? "" : "s");
}

static void cli_got_triangles(const cli_got_args *a, const got_result *res, const size_t *map) {
  int print = a->print < 0 ? res->n <= CLI_GOT_PRINT_N : a->print;
  printf("triangles: %zu%s\n", res->ntri, print ? " (i j k badness; 0-based vertices of the input)"
                                                : " (list them with --print-triangles)");
  if (!print) return;
  for (size_t q = 0; q < res->ntri; q++) {
    size_t v[3] = {(size_t)res->tri[q].i, (size_t)res->tri[q].k, (size_t)res->tri[q].j};
    for (int c = 0; c < 3 && map; c++) v[c] = map[v[c]];
    printf("%zu %zu %zu %.17g\n", v[0], v[1], v[2], res->tri[q].badness);
  }
}

/* --csv and --svg; 0 or the exit code (cli_close_out reports write errors). */
static int cli_got_outputs(const cli_got_args *a, const rule *r, const geom_point *p,
                           const got_result *res, const size_t *map, const char *tot) {
  if (a->csv) {
    FILE *f = cli_open_out(CMD, a->csv);
    if (f == NULL) return 2;
    if (cli_finish_out(CMD, f, report_got_csv(f, res->tri, res->ntri, map)) != 0) return 1;
  }
  if (a->svg) {
    FILE *f = cli_open_out(CMD, a->svg);
    if (f == NULL) return 2;
    char title[RULE_NAME_MAX + 256];
    snprintf(title, sizeof title, "GOT(%s), n = %zu, total %s%s%s", r->name, res->n, tot,
             a->shade ? "; shaded by triangle badness" : "",
             a->compare >= 0 ? "; dashed red: Delaunay diagonals not in the GOT" : "");
    report_got_svg_opts so = {.shade = a->shade, .title = title, .labels = map};
    /* --compare DT: the Delaunay diagonals the GOT lacks, dashed on top. */
    got_triangle *dt = a->compare >= 0 ? malloc(res->n * sizeof *dt) : NULL;
    int unique;
    if (a->compare >= 0 && dt == NULL) return cli_error(CMD, "out of memory");
    if (dt != NULL && got_delaunay(p, res->n, dt, &unique) == 0) {
      so.overlay = dt;
      so.noverlay = res->n - 2;
      so.overlay_name = "DT";
    }
    int w = report_got_svg(f, p, res->n, res->tri, res->ntri, &so);
    free(dt);
    if (cli_finish_out(CMD, f, w) != 0) return 1;
  }
  return 0;
}

/* ---- point sets ---- */

/* The points, read or sampled; desc names them. */
static int cli_got_points_in(const cli_got_args *a, geom_point **p, size_t *n, char *desc,
                             size_t desclen) {
  char err[512];
  if (cli_points_get(CMD, a->points, a->random, a->distribution, a->seed,
                     got_points_check_memory, p, n, desc, desclen) != 0)
    return 2;
  if (got_points_check_memory(*n, err, sizeof err) != 0) return cli_error(CMD, "%s", err);
  return 0;
}

/* The skeleton, faces and stages; the LOT's total and its gap to the GOT. */
static int cli_got_points_stats(const cli_got_args *a, const rule *r, const geom_point *p,
                                const got_result *res) {
  size_t tedges = res->n - 1 + res->ntri;     /* Euler: 3n - h - 3 = n - 1 + (2n - h - 2) */
  printf("skeleton: %s, %zu candidate edges, %zu kept, %zu certain (%.2f%% of the %zu edges "
         "of a triangulation), %zu rounds\n", got_skeleton_name((got_skeleton)res->skeleton),
         res->candidates, res->edges, res->certain, 100.0 * (double)res->certain /
         (double)tedges, tedges, res->rounds);
  printf("faces: %zu bounded, %zu left to solve (more than a triangle), %zu with points "
         "inside or not simple; the largest has %zu points; %zu search states\n", res->faces,
         res->faces_left, res->faces_general, res->largest_face, res->face_states);
  if (res->skeleton == GOT_SKELETON_DELAUNAY)
    printf("seconds: Delaunay triangulation %.4f, certificate and candidates %.4f, faces %.4f, "
           "solve %.4f\n", res->seconds_delaunay, res->seconds_candidates, res->seconds_faces,
           res->seconds_solve);
  else
    printf("seconds: candidates %.4f, skeleton loop %.4f, faces %.4f, solve %.4f\n",
           res->seconds_candidates, res->seconds_lmt, res->seconds_faces, res->seconds_solve);
  if (a->no_lot) return 0;
  char err[512], lt[64];
  double lk;
  if (study_lot_key(p, res->n, r, &lk, err, sizeof err) != 0) return cli_error(CMD, "%s", err);
  double gap = rule_gap(r, lk, res->key);
  got_format_total(res, lk, lt, sizeof lt);
  printf("LOT (incremental): total %s; relative gap LOT - GOT %.6g (%s)\n", lt, gap,
         gap <= rule_tie_eps(r) ? "the LOT is a GOT" : "the LOT is not a GOT");
  return 0;
}

/* --csv (got's) and --svg (the points, as lot draws them); 0 or the exit code. */
static int cli_got_points_out(const cli_got_args *a, const rule *r, const geom_point *p,
                              const got_result *res, const char *tot) {
  if (a->csv) {
    FILE *f = cli_open_out(CMD, a->csv);
    if (f == NULL) return 2;
    if (cli_finish_out(CMD, f, report_got_csv(f, res->tri, res->ntri, NULL)) != 0) return 1;
  }
  if (a->svg == NULL) return 0;
  uint32_t *tri = malloc((3 * res->ntri + 1) * sizeof *tri);
  double *bad = malloc((res->ntri + 1) * sizeof *bad);
  if (tri == NULL || bad == NULL) {
    free(tri), free(bad);
    return cli_error(CMD, "out of memory");
  }
  for (size_t q = 0; q < res->ntri; q++) {
    tri[3 * q] = (uint32_t)res->tri[q].i, tri[3 * q + 1] = (uint32_t)res->tri[q].k;
    tri[3 * q + 2] = (uint32_t)res->tri[q].j, bad[q] = res->tri[q].badness;
  }
  char title[RULE_NAME_MAX + 256];
  snprintf(title, sizeof title, "GOT(%s) of %zu points, total %s%s", rule_name(r), res->n,
           tot, a->shade ? "; shaded by triangle badness" : "");
  report_lot_panel panel = {.tri = tri, .ntri = res->ntri, .badness = bad};
  FILE *f = cli_open_out(CMD, a->svg);
  int rc = f == NULL ? 2 : cli_finish_out(CMD, f, report_lot_svg(f, p, res->n, &panel, 1,
                                                                   a->shade, title)) ? 1 : 0;
  free(tri), free(bad);
  return rc;
}

static int cli_got_points(const cli_got_args *a, const rule *r) {
  geom_point *p = NULL;
  size_t n = 0;
  char desc[700], err[512], tot[64];
  got_result res;
  memset(&res, 0, sizeof res);
  int rc = cli_got_points_in(a, &p, &n, desc, sizeof desc);
  got_options opt = {(int)a->threads, a->tie_eps};
  if (rc == 0 &&
      study_got_points(p, n, r, &opt, (got_skeleton)a->skeleton, &res, err, sizeof err) != 0)
    rc = cli_error(CMD, "%s", err);
  if (rc == 0 && cli_userdefs_failed(CMD)) rc = 1;
  if (rc == 0) {
    got_format_total(&res, res.key, tot, sizeof tot);
    snprintf(desc + strlen(desc), sizeof desc - strlen(desc), ", skeleton %s",
             got_skeleton_name((got_skeleton)a->skeleton));
    cli_got_summary(a, r, &res, desc, tot);
    rc = cli_got_points_stats(a, r, p, &res);
  }
  if (rc == 0) {
    cli_got_triangles(a, &res, NULL);
    rc = cli_got_points_out(a, r, p, &res, tot);
  }
  got_result_free(&res);
  free(p);
  return rc;
}

/* --gap-table: a row per rule. */
static int cli_got_table(const cli_got_args *a) {
  rule *rules = NULL;
  int nr = cli_rule_list_new(CMD, a->rule, &rules);
  if (nr < 0) return 2;
  char err[512];
  printf("# fliplab got --gap-table: how far local is from global: %llu sets of %llu %s "
         "points (seed %llu, set i: seed + i), skeleton %s\n", (unsigned long long)a->gap_table,
         (unsigned long long)a->random, sampler_points_name((sampler_points_kind)a->distribution),
         (unsigned long long)a->seed, got_skeleton_name((got_skeleton)a->skeleton));
  printf("# gap = (LOT - GOT) / max(LOT, GOT) in magnitude (rule_gap); LOT = GOT: gap <= the "
         "rule's tie-eps; 95%% intervals (normal for the mean, Wilson for the fraction)\n");
  printf("%-12s %12s %27s %12s %9s %19s %10s\n", "rule", "mean gap", "95% interval",
         "max gap", "LOT=GOT", "95% interval", "seconds");
  int rc = 0;
  for (int i = 0; i < nr && rc == 0; i++) {
    study_gap_row row;
    if (!rule_is_triangle(&rules[i]) || joint_get(rule_joint(&rules[i]))->keyop != JOINT_KEY_ADD)
      rc = cli_error(CMD, "rule %s is not a sum rule: the table needs joints whose keys add "
                     "(l_1, l_2, l_0, l_-1, l_p)", rule_name(&rules[i]));
    else if (study_lot_got_gaps(&rules[i], a->distribution, (size_t)a->random, a->gap_table,
                                a->seed, (int)a->threads, (got_skeleton)a->skeleton, &row, err,
                                sizeof err) != 0)
      rc = cli_error(CMD, "%s: %s", rule_name(&rules[i]), err);
    else
      printf("%-12s %12.4e [%11.4e, %11.4e] %12.4e %8.1f%% [%6.1f%%, %6.1f%%] %10.2f\n",
             rule_name(&rules[i]), row.mean, row.lo, row.hi, row.max,
             100.0 * (double)row.equal / (double)row.sets, row.equal_lo, row.equal_hi,
             row.seconds);
  }
  free(rules);
  return rc;
}

int cli_cmd_got(int argc, char **argv) {
  cli_got_args a;
  rule r;
  int rc = cli_got_setup(argc, argv, &a, &r);
  if (rc != 0) return rc < 0 ? 0 : rc;
  if (a.gap_table) return cli_got_table(&a);
  if (a.points != NULL || a.distribution >= 0) return cli_got_points(&a, &r);
  geom_point *p = NULL;
  size_t n = 0, *map = NULL;
  char desc[600], err[512];
  got_result res;
  memset(&res, 0, sizeof res);
  rc = cli_got_polygon(&a, &r, &p, &n, &map, desc, sizeof desc);
  if (rc != 0) goto done;
  int convex = a.compare >= 0 ? cli_got_is_convex(p, n) : 1;
  if (convex < 0) {
    rc = cli_error(CMD, "out of memory");
    goto done;
  }
  if (!convex) {
    rc = cli_error(CMD, "--compare DT needs a convex polygon (this one has reflex vertices)");
    goto done;
  }
  got_options opt = {(int)a.threads, a.tie_eps};
  if (got_solve(p, n, &r, &opt, &res, err, sizeof err) != 0) {
    rc = cli_error(CMD, "%s", err);
    goto done;
  }
  if (cli_userdefs_failed(CMD)) {
    rc = 1;
    goto done;
  }
  char tot[64];
  got_format_total(&res, res.key, tot, sizeof tot);
  cli_got_summary(&a, &r, &res, desc, tot);
  if (a.compare >= 0 && cli_got_compare(p, n, &res) != 0) {
    rc = 1;
    goto done;
  }
  cli_got_triangles(&a, &res, map);
  rc = cli_got_outputs(&a, &r, p, &res, map, tot);
done:
  got_result_free(&res);
  free(p);
  free(map);
  return rc;
}
