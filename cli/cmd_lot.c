/*
** cmd_lot.c: `fliplab lot`: a locally optimal triangulation of a point set
** for any rule (built-in, formula or plugin) by the incremental or the
** flip algorithm (DT and empty-shape rules also by the sweepline
** algorithm); prints the counts, the status (converged, cycle, budget
** exhausted) and the time; optionally re-checks local optimality from
** scratch, compares with the Delaunay triangulation or (convex position)
** the GOT, and writes the triangles as CSV and an SVG.  --rule A,B,...
** builds one LOT per rule of the same points: a block of lines each, and
** one SVG panel each.  Constrained runs (--segments, --holes, --poly):
** segments that must stay edges and hole points, through lot_options; the
** CDT or constrained LOT gets its own count lines, check, comparisons and
** drawn segments, and a run without them prints what it always did.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "lot.h"
#include "measure.h"
#include "report.h"
#include "sampler.h"
#include "shape.h"
#include "study.h"

#define CMD "lot"
#define CLI_LOT_MAX_N 1000000000000ull   /* parse bound; memory decides the real one */

/* One rule's triangles and their badness (a panel of a list's SVG). */
typedef struct cli_lot_tri {
  uint32_t *tri;
  double *bad;
  size_t ntri;
  uint32_t *con;        /* constrained edges in the result (2 each) */
  size_t ncon;
  uint32_t *red;        /* a weighted run's redundant sites */
  size_t nred;
} cli_lot_tri;

typedef struct cli_lot_args {
  const char *rule, *points, *out, *svg, *cdf, *segments, *holes, *poly, *weights;
  int sampler, algorithm, order, compare;   /* compare: 0 DT, 1 GOT, -1 none */
  uint64_t random, seed, max_flips, threads;
  double tie_eps;
  int check, shade, keep_hull;
} cli_lot_args;

/* Indexed by lot_algorithm and lot_order. */
static const char *const cli_lot_algorithms[] = {"incremental", "flip", "sweep", NULL};
static const char *const cli_lot_order_name[] = {"spatial", "input", "random", NULL};
static const char *const cli_lot_compares[] = {"DT", "GOT", NULL};

#define T cli_lot_args
static const cli_option cli_lot_opts[] = {
  CLI_OPT_STRING("--rule", "RULE,...", "required",
                 "DT, WDT, MEASURE_JOINT (e.g. P_1, -alpha_inf), ES:SHAPE, a\n"
                 "                     --define'd measure with a joint, or a --plugin\n"
                 "                     quadrilateral rule; a comma list builds one LOT per\n"
                 "                     rule (lines per rule, --svg one panel each; not\n"
                 "                     with --out, --cdf, --shade)",
                 T, rule),
  CLI_OPT_STRING("--points", "FILE.csv", "none: give --points or --random",
                 "CSV, one point 'x,y' per row (optional header 'x,y');\n"
                 "                     output indices are the file's rows, 0-based", T, points),
  CLI_OPT_STRING("--segments", "S.csv", "none",
                 "with --points: segments 'i,j' (0-based rows of the\n"
                 "                     points file) that must be edges: the constrained\n"
                 "                     LOT (the CDT for DT; docs/lot.md)", T, segments),
  CLI_OPT_STRING("--holes", "H.csv", "none",
                 "hole points 'x,y': the triangles reachable from one\n"
                 "                     without crossing a segment are removed", T, holes),
  CLI_OPT_STRING("--poly", "FILE.poly", "none",
                 "Triangle's .poly file: points, segments and holes\n"
                 "                     (instead of --points, --random, --segments, --holes)",
                 T, poly),
  CLI_OPT_STRING("--weights", "W.csv", "none",
                 "with --rule WDT and --points: a weight 'w' per row of\n"
                 "                     the points file (optional header 'w'): the regular\n"
                 "                     triangulation; redundant sites are named and left\n"
                 "                     out (docs/lot.md)", T, weights),
  CLI_OPT_FLAG("--keep-hull", "with segments: keep the triangles outside the outermost\n"
               "                     segment-bounded region (default: removed)", T, keep_hull),
  {.name = "--random", .arg = "N", .dflt = "none", .help = "N random points from --sampler",
   .kind = CLI_U64, .off = CLI_AT(T, random, uint64_t), .lo = 3, .hi = CLI_LOT_MAX_N},
  {.name = "--sampler", .arg = "NAME", .dflt = "uniform",
   .help = "uniform (unit square), normal, disc, grid (integer grid,\n"
           "                     row by row), parabola ((i, i^2), i = N..1), circle,\n"
           "                     clustered, jittered, lines, dups (docs/sampling.md)",
   .kind = CLI_CALL, .off = CLI_AT(T, sampler, int), .idef = SAMPLER_UNIFORM,
   .call = cli_option_points_sampler},
  CLI_OPT_SEED("the sampler's and the random order's seed", T, seed),
  {.name = "--algorithm", .arg = "A",
   .help = "incremental: insert, then flip back to a LOT; flip: a\n"
           "                     sweep triangulation, then Lawson's flip algorithm;\n"
           "                     sweep (rule DT or ES:SHAPE): the sweepline algorithm",
   .kind = CLI_CHOICE, .off = CLI_AT(T, algorithm, int), .names = cli_lot_algorithms,
   .idef = LOT_INCREMENTAL, .bad = "unknown algorithm '%s' (valid: incremental, flip, sweep)"},
  {.name = "--order", .arg = "O",
   .help = "insertion order: spatial (BRIO rounds along a Hilbert\n"
           "                     curve), random, input",
   .kind = CLI_CHOICE, .off = CLI_AT(T, order, int), .names = cli_lot_order_name,
   .idef = LOT_ORDER_SPATIAL, .bad = "unknown order '%s' (valid: input, random, spatial)"},
  {.name = "--max-flips", .arg = "N", .dflt = "1000 n + 10^7",
   .help = "stop after N flips: status 'budget exhausted'", .kind = CLI_U64,
   .off = CLI_AT(T, max_flips, uint64_t), .lo = 1, .hi = UINT64_MAX},
  CLI_OPT_FLAG("--check", "re-verify local optimality of every interior edge from scratch", T,
               check),
  {.name = "--compare", .arg = "DT|GOT", .dflt = "none",
   .help = "DT: edges and triangles shared with the exact Delaunay\n"
           "                     triangulation (with segments: the CDT); GOT (convex\n"
           "                     position, or segments forming one simple polygon;\n"
           "                     triangle rule): the LOT's total against the GOT's",
   .kind = CLI_CHOICE, .off = CLI_AT(T, compare, int), .names = cli_lot_compares, .idef = -1,
   .bad = "unknown --compare '%s' (valid: DT, GOT)"},
  CLI_OPT_OUT("FILE.csv", "none", "csv",
              "write the triangles: i,j,k,badness (anticlockwise;\n"
              "                     badness empty for DT and quadrilateral rules)", T, out),
  CLI_OPT_FILE("--cdf", "FILE.csv", "none", "csv",
               "with --rule ES:SHAPE: write the convex-distance Delaunay\n"
               "                     graph: kept triangles i,j,k, then extra edges i,j,", T, cdf),
  CLI_OPT_FILE("--svg", "FILE.svg", "none", "svg",
               "draw the LOT (next to the DT with --compare DT; with\n"
               "                     --cdf, the CDF graph over it in bold; with a list\n"
               "                     of rules, one panel per rule, no other)", T, svg),
  CLI_OPT_FLAG("--shade", "with --svg: fill the triangles by badness (light = good)", T, shade),
  CLI_OPT_TIE_EPS("relative tolerance under which a triangle rule ties", 1, T, tie_eps),
  CLI_OPT_THREADS("OpenMP threads for --compare GOT; the LOT itself is\n"
                  "                     sequential and does not depend on T", T, threads),
};
#undef T

static const cli_spec cli_lot_spec = {
  CMD, "usage: fliplab lot --rule RULE[,RULE...] (--points FILE.csv | --random N |\n"
  "                       --poly FILE.poly) [options]",
  "A locally optimal triangulation LOT(RULE) of a planar point set: every interior\n"
  "edge of a strictly convex quadrilateral is the diagonal the rule keeps\n"
  "(docs/lot.md).  A list of rules builds one LOT per rule of the same points.\n"
  "Segments that must stay edges and hole points (--segments, --holes, --poly)\n"
  "give the constrained LOT (the CDT for DT).\n"
  "Exit status 0 (also for status cycle or budget exhausted), 1 when --check\n"
  "fails (or a constrained --compare GOT), 2 for bad usage or input.\n",
  cli_lot_opts, CLI_NOPTS(cli_lot_opts), NULL};

/* Where the points (and constraints) come from: --poly alone, or one of
** --points and --random with --segments (--points only) and --holes. */
static int cli_lot_parse_input(const cli_lot_args *a, uint64_t given) {
  int sampler = cli_option_given(&cli_lot_spec, given, "--sampler");
  if (a->poly) {
    const char *clash = a->points ? "--points" : a->random ? "--random" : sampler ? "--sampler"
                      : a->segments ? "--segments" : a->holes ? "--holes" : NULL;
    if (clash)
      return cli_error(CMD, "--poly gives the points, segments and holes: not with %s", clash);
    return 0;
  }
  if ((a->points != NULL) == (a->random != 0))
    return cli_error(CMD, "give exactly one of --points FILE.csv and --random N");
  if (sampler && a->points) return cli_error(CMD, "--sampler applies to --random only");
  if (a->segments && a->points == NULL)
    return cli_error(CMD, "--segments needs --points FILE.csv (its rows are the indices)");
  if (a->weights && a->points == NULL)
    return cli_error(CMD, "--weights needs --points FILE.csv (a weight per row)");
  if (a->keep_hull && a->segments == NULL && a->holes == NULL)
    return cli_error(CMD, "--keep-hull applies to constrained runs (--segments, --holes, "
                     "--poly)");
  return 0;
}

/* The options into a and o: 0, 1 after --help, 2 after an error. */
static int cli_lot_parse(int argc, char **argv, cli_lot_args *a, lot_options *o) {
  uint64_t given;
  int st = cli_options_parse(&cli_lot_spec, argc, argv, a, &given);
  if (st != 0) return st;
  if (a->rule == NULL) return cli_error(CMD, "--rule is required (e.g. --rule DT or --rule P_1)");
  if (cli_lot_parse_input(a, given) != 0) return 2;
  if (cli_option_given(&cli_lot_spec, given, "--algorithm")) o->algorithm = a->algorithm;
  if (cli_option_given(&cli_lot_spec, given, "--order")) {
    o->order = a->order;
    if (o->algorithm != LOT_INCREMENTAL)
      return cli_error(CMD, "--order applies to --algorithm incremental only");
  }
  if (a->shade && a->svg == NULL) return cli_error(CMD, "--shade needs --svg FILE");
  return 0;
}

/* --rule: one rule read whole (so "ES:ellipse:2,1" is one rule), else a
** comma list (cli_rule_list_new: shape numbers take blanks there); what
** draws or writes one triangulation refuses a list.  The count, or -1
** after the error. */
static int cli_lot_rules(const cli_lot_args *a, rule **r) {
  rule one;
  char err[512];
  int n = 1, list = strchr(a->rule, ',') != NULL;
  /* one parse of a name without a comma: cli_parse_rule says why, with
  ** hints (parsing it twice made a failure the first parse met, such as
  ** running out of memory, pass unsaid when the second did not) */
  if (list ? rule_parse(a->rule, &one, err, sizeof err) == 0
           : cli_parse_rule(CMD, a->rule, &one) == 0) {
    if ((*r = malloc(sizeof **r)) == NULL) return cli_error(CMD, "out of memory"), -1;
    **r = one;
  } else if (!list || (n = cli_rule_list_new(CMD, a->rule, r)) < 0) {
    return -1;
  }
  const char *one_only = a->out ? "--out" : a->cdf ? "--cdf" : a->shade ? "--shade" : NULL;
  if (n > 1 && one_only)
    cli_error(CMD, "%s takes one rule, not a list of %d (--rule '%s')", one_only, n, a->rule);
  else if (a->cdf && !rule_is_shape(&(*r)[0]))
    cli_error(CMD, "--cdf needs an empty-shape rule (--rule ES:SHAPE), not '%s'", a->rule);
  else if (a->cdf && (a->segments || a->holes || a->poly))
    cli_error(CMD, "--cdf takes an unconstrained run: the convex-distance Delaunay graph "
              "of a run with %s is not defined here (docs/emptyshape.md)",
              a->poly ? "--poly" : a->segments ? "--segments" : "--holes");
  else
    return n;
  free(*r);
  return -1;
}

/* The points, read or sampled; desc names them. */
static int cli_lot_points(const cli_lot_args *a, geom_point **p, size_t *n, char *desc,
                          size_t desclen) {
  return cli_points_get(CMD, a->points, a->random, a->sampler, a->seed, lot_check_memory, p, n,
                        desc, desclen);
}

/* --poly: the file's graph into *in (vertex attributes, boundary markers
** and regions carry nothing here: a one-line note says what was dropped). */
static int cli_lot_poly(const char *path, geom_pslg *in, char *desc, size_t desclen) {
  report_poly pf;
  char err[512];
  if (report_poly_read(path, &pf, err, sizeof err) != 0) return cli_error(CMD, "%s", err);
  if (pf.attributes || pf.regions || pf.markers)
    fprintf(stderr, "%s: note: %s: ignored: %zu vertex attribute(s), %zu regional "
            "attribute/area line(s)%s\n", CMD, path, pf.attributes, pf.regions,
            pf.markers ? ", boundary markers" : "");
  *in = pf.g;
  free(pf.seg_line);
  snprintf(desc, desclen, "%zu points, %zu segments and %zu holes from %s", in->npts,
           in->nseg, in->nholes, path);
  return 0;
}

/* The input: --poly, or the points with --segments and --holes; desc names
** them (as before when there are no constraints). */
static int cli_lot_input(const cli_lot_args *a, geom_pslg *in, char *desc, size_t desclen) {
  char err[512];
  memset(in, 0, sizeof *in);
  if (a->poly) return cli_lot_poly(a->poly, in, desc, desclen);
  if (cli_lot_points(a, &in->pts, &in->npts, desc, desclen) != 0) return 2;
  size_t len = strlen(desc);
  if (a->segments) {
    if (report_segments_read(a->segments, in->npts, &in->seg, NULL, &in->nseg, err,
                             sizeof err) != 0)
      return cli_error(CMD, "%s", err);
    snprintf(desc + len, desclen - len, ", %zu segments from %s", in->nseg, a->segments);
    len = strlen(desc);
  }
  if (a->holes) {
    if (report_points_read(a->holes, &in->hole, NULL, &in->nholes, err, sizeof err) != 0)
      return cli_error(CMD, "--holes: %s", err);
    snprintf(desc + len, desclen - len, ", %zu holes from %s", in->nholes, a->holes);
  }
  return 0;
}

/* --weights: a weight per point, into *w (NULL without the option). */
static int cli_lot_weights(const cli_lot_args *a, const geom_pslg *in, double **w, char *desc,
                           size_t desclen) {
  char err[512];
  *w = NULL;
  if (a->weights == NULL) return 0;
  if (report_weights_read(a->weights, in->npts, w, err, sizeof err) != 0)
    return cli_error(CMD, "--weights: %s", err);
  size_t len = strlen(desc);
  snprintf(desc + len, desclen - len, ", weights from %s", a->weights);
  return 0;
}

/* A weighted run's sites left out: their count, the rounds, the first few. */
static void cli_lot_redundant_line(const lot_stats *st, const cli_lot_tri *t) {
  printf("redundant: %zu site%s (power cells empty: no regular triangulation keeps them; "
         "%zu round%s)", t->nred, t->nred == 1 ? "" : "s", st->rounds,
         st->rounds == 1 ? "" : "s");
  for (size_t k = 0; k < t->nred && k < 20; k++) printf("%s %u", k ? "" : ":", t->red[k]);
  printf("%s\n", t->nred > 20 ? " ..." : "");
}

static void cli_lot_status(const lot_stats *st) {
  if (st->status == LOT_CONVERGED) {
    printf("status: converged\n");
  } else if (st->status == LOT_CYCLE) {
    printf("status: cycle of %llu flips (the triangulation repeated, confirmed exactly); "
           "quadrilaterals:", (unsigned long long)st->cycle_length);
    for (size_t q = 0; q < st->cycle_quads; q++)
      printf("%s %u %u %u %u", q ? ";" : "", st->cycle_quad[q][0], st->cycle_quad[q][1],
             st->cycle_quad[q][2], st->cycle_quad[q][3]);
    printf("%s\n", st->cycle_length > st->cycle_quads ? " ..." : "");
  } else {
    printf("status: budget exhausted after %llu flips (--max-flips %llu); the triangulation "
           "is not locally optimal\n",
           (unsigned long long)st->flips, (unsigned long long)st->max_flips);
  }
}

/* --check of a constrained run, beyond lot_check's: every input segment a
** chain of triangle edges except those with a piece in a removed region. */
static int cli_lot_check_segments(const lot_check_result *c, const geom_pslg *in,
                                  const lot_stats *st) {
  if (c->segments_missing == st->segments_removed) return 0;
  size_t k = c->missing_segment;
  printf("check: FAILED: %zu input segments are not chains of triangle edges, %zu expected (in "
         "removed regions); first: segment %zu (%u-%u)\n", c->segments_missing,
         st->segments_removed, k, c->segments_missing ? in->seg[2 * k] : 0,
         c->segments_missing ? in->seg[2 * k + 1] : 0);
  return 1;
}

/* --check: 0 when the triangulation is valid, every interior edge (but
** the segments' ones) is locally optimal, and no segment is lost. */
static int cli_lot_check(const geom_point *p, size_t n, const uint32_t *tri, size_t ntri,
                         const rule *r, const geom_pslg *in, const lot_options *o,
                         const lot_stats *st) {
  lot_check_result c;
  lot_tie_result tie = {0};   /* unconstrained runs only */
  int constrained = in->nseg || in->nholes;
  if ((constrained ? lot_check_constrained(p, n, tri, ntri, in->seg, in->nseg, r, &c)
       : o->weights ? lot_check_weighted(p, o->weights, n, tri, ntri, r, &c)
                    : lot_check_ties(p, n, tri, ntri, r, &c, &tie)) != 0) {
    cli_error(CMD, "--check: out of memory");   /* no verdict: said on stderr, exit 1 */
    return 1;
  }
  if (!c.valid) {
    printf("check: FAILED: not a valid triangulation\n");
    return 1;
  }
  if (constrained && cli_lot_check_segments(&c, in, st) != 0) return 1;
  if (c.not_optimal) {
    printf("check: FAILED: %zu of %zu interior edges not locally optimal (first %u-%u)\n",
           c.not_optimal, c.interior_edges, c.bad_edge[0], c.bad_edge[1]);
    return 1;
  }
  if (tie.not_tie_broken) {
    printf("check: FAILED: %zu of %zu tied interior edges not as the tie-break settles them "
           "(first %u-%u): not the rule's one tie-broken LOT\n", tie.not_tie_broken, tie.ties,
           tie.tie_edge[0], tie.tie_edge[1]);
    return 1;
  }
  char how[160];
  int len = snprintf(how, sizeof how, "%s", o->weights
                     ? "every one passes the exact power test (regular, convex or not)"
                     : rule_is_delaunay(r) ? "every one passes the exact empty-circle test"
                                           : "the rule keeps every one");
  if (tie.ties)   /* no ties, no words: the line stays as before */
    snprintf(how + len, sizeof how - (size_t)len, "; %zu ties, every one as the tie-break "
             "settles it", tie.ties);
  if (constrained)
    printf("check: ok: constrained, re-verified from scratch: %zu of %zu input segments are "
           "chains of edges (the other %zu lie in removed regions); %zu interior edges, %zu "
           "unconstrained in strictly convex quadrilaterals, %s\n",
           in->nseg - st->segments_removed, in->nseg, st->segments_removed, c.interior_edges,
           c.decided, how);
  else
    printf("check: ok: locally optimal, re-verified from scratch: %zu interior edges, %zu in "
           "strictly convex quadrilaterals, %s\n", c.interior_edges, c.decided, how);
  return 0;
}

/* --compare DT: the Delaunay triangulation of the same points (with the
** same segments and holes: the constrained one). */
static int cli_lot_compare_dt(const geom_point *p, size_t n, const lot_options *base,
                              const uint32_t *tri, size_t ntri, uint32_t **dt, size_t *ndt) {
  rule d = rule_delaunay();
  lot_options o;
  lot_options_init(&o, &d);
  o.seed = base->seed;
  o.segments = base->segments;
  o.nsegments = base->nsegments;
  o.holes = base->holes;
  o.nholes = base->nholes;
  o.keep_hull = base->keep_hull;
  lot *L;
  char err[512];
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) return cli_error(CMD, "%s", err);
  *ndt = lot_get_stats(L)->triangles;
  *dt = malloc(3 * *ndt * sizeof **dt);
  lot_diff df;
  if (*dt == NULL) {
    lot_free(L);
    return cli_error(CMD, "out of memory");
  }
  lot_get_triangles(L, *dt);
  lot_free(L);
  if (lot_compare(tri, ntri, *dt, *ndt, &df) != 0) return cli_error(CMD, "out of memory");
  printf("compare DT: %zu of %zu edges and %zu of %zu triangles shared with the exact "
         "%sDelaunay triangulation (%.2f%% of triangles)\n", df.edges_common, df.edges_a,
         df.triangles_common, df.triangles_a, o.nsegments || o.nholes ? "constrained " : "",
         100.0 * (double)df.triangles_common / (double)(df.triangles_a ? df.triangles_a : 1));
  return 0;
}

/* --compare GOT in convex position: the totals and their relation. */
static void cli_lot_got_line(const rule *r, const study_gotcheck *c) {
  printf("compare GOT: LOT total %s, GOT total %s: %s (relative difference %.3g, ", c->lot_text,
         c->got_text, c->equal ? "equal" : "NOT equal", c->rel);
  if (c->certified) printf("GOT computed to within rounding)\n");
  else printf("%s the tie tolerance %g; no certified bound: %s)\n", c->equal ? "within" : "beyond",
              rule_tie_eps(r), c->uncertified);
}

/* --compare GOT of a constrained run: the totals, the shared triangles and
** the relation theory demands (study_gotcheck's failed: a total below the
** GOT's, or a CDT rule's other triangles with another total). */
static void cli_lot_ring_line(const study_gotcheck *c) {
  printf("compare GOT: LOT total %s, GOT total %s: %s (relative difference %.3g%s); "
         "%zu of %zu triangles shared%s\n", c->lot_text, c->got_text,
         c->below ? "LOT < GOT: FAILED (no triangulation is below the GOT)"
                  : c->equal ? "LOT = GOT" : "LOT > GOT, as it may be",
         c->rel, c->certified ? ", GOT computed to within rounding" : ", within the tie tolerance",
         c->diff.triangles_common, c->diff.triangles_b,
         !c->got_is_cdt ? ""
         : c->same      ? "; the rule's GOT is the CDT: equal triangles, as it must be"
         : c->equal     ? "; equal totals, other triangles (a tie)"
                        : "; the rule's GOT is the CDT: FAILED, the triangles differ");
}

/* --compare GOT: the LOT against the GOT of its polygon (study_lot_got: the
** hull of points in convex position, or the ring of a constrained run's
** segments); *failed when a constrained run breaks the relation. */
static int cli_lot_compare_got(const geom_pslg *in, const lot *L, const rule *r,
                               const cli_lot_tri *t, const cli_lot_args *a, int *failed) {
  const lot_stats *st = lot_get_stats(L);
  uint32_t *hull = malloc((st->hull + 1) * sizeof *hull);
  study_gotcheck c;
  char err[512];
  if (hull == NULL) return cli_error(CMD, "out of memory");
  lot_get_hull(L, hull);
  int rc = study_lot_got(in, hull, st->hull, t->tri, t->ntri, r, (int)a->threads, &c, err,
                         sizeof err);
  free(hull);
  if (rc != 0) return cli_error(CMD, "%s", err);
  if (c.ring) cli_lot_ring_line(&c);
  else cli_lot_got_line(r, &c);
  if (c.ring && c.failed) *failed = 1;
  study_gotcheck_free(&c);
  return 0;
}

/* --cdf: the convex-distance Delaunay graph of the shape of --rule ES:SHAPE
** (the rule's own, rule_shape), its count line and its CSV. */
static int cli_lot_cdf(const cli_lot_args *a, const rule *r, const geom_point *p,
                       const uint32_t *tri, size_t ntri, lot_cdf *g) {
  if (lot_cdf_extract(p, tri, ntri, rule_shape(r), g) != 0)
    return cli_error(CMD, "out of memory");
  FILE *f = cli_open_out(CMD, a->cdf);
  if (f == NULL) return 2;
  printf("cdf: %zu triangles, %zu extra edges (%zu triangles dropped)\n", g->triangles,
         g->edges, g->rounded);
  report_lot_cdf_csv(f, g);
  return cli_close_out(f) != 0;   /* it said why */
}

static int cli_lot_svg(const cli_lot_args *a, const geom_point *p, size_t n,
                       const cli_lot_tri *t, const uint32_t *dt, size_t ndt, const rule *r,
                       const lot_cdf *g, int constrained) {
  FILE *f = cli_open_out(CMD, a->svg);
  if (f == NULL) return 2;
  char cap[2][RULE_NAME_MAX + 160], title[200];
  int len = snprintf(cap[0], sizeof cap[0], "LOT(%s): %zu triangles", r->name, t->ntri);
  if (g && len > 0 && (size_t)len < sizeof cap[0])
    snprintf(cap[0] + len, sizeof cap[0] - (size_t)len, "; CDF graph (bold): %zu triangles, "
             "%zu extra edges", g->triangles, g->edges);
  snprintf(cap[1], sizeof cap[1], "%s triangulation: %zu triangles",
           constrained ? "Constrained Delaunay" : "Delaunay", ndt);
  snprintf(title, sizeof title, "%zu points%s%s", n,
           constrained ? "; constrained edges in bold" : "",
           a->shade ? "; shaded by triangle badness" : "");
  report_lot_panel pn[2] = {{t->tri, t->ntri, t->bad, cap[0], g, t->con, t->ncon},
                            {dt, ndt, NULL, cap[1], NULL, t->con, t->ncon}};
  report_lot_svg(f, p, n, pn, dt ? 2 : 1, a->shade, title);
  return cli_close_out(f) != 0;
}

static int cli_lot_write(const cli_lot_args *a, const geom_point *p, size_t n,
                         const cli_lot_tri *t, const uint32_t *dt, size_t ndt, const rule *r,
                         int constrained) {
  lot_cdf g;
  memset(&g, 0, sizeof g);
  int rc = a->cdf ? cli_lot_cdf(a, r, p, t->tri, t->ntri, &g) : 0;
  if (rc == 0 && a->out) {
    FILE *f = cli_open_out(CMD, a->out);
    if (f == NULL) rc = 2;
    else {
      report_lot_csv(f, t->tri, t->ntri, t->bad);
      rc = cli_close_out(f) != 0;   /* it said why */
    }
  }
  if (rc == 0 && a->svg)
    rc = cli_lot_svg(a, p, n, t, dt, ndt, r, a->cdf ? &g : NULL, constrained);
  lot_cdf_free(&g);
  return rc;
}

/* A constrained run's count lines: what became of the segments and holes. */
static void cli_lot_constraint_lines(const lot_options *o, const lot_stats *st) {
  printf("segments: %zu (%zu constrained edges; %zu merged, %zu split, %zu in removed "
         "regions)\n", st->segments, st->constrained, st->segments_merged, st->segments_split,
         st->segments_removed);
  printf("holes: %zu (%zu triangles removed: in holes%s)\n", st->holes, st->removed,
         o->keep_hull ? "; the hull kept" : " and outside the outermost boundary");
}

/* The header, counts, status and time lines. */
static void cli_lot_summary(const rule *r, const char *desc, const lot_options *o,
                            const lot *L, const cli_lot_tri *t, double tie_eps) {
  const lot_stats *st = lot_get_stats(L);
  int restarted;
  size_t ties = lot_get_sweep_ties(L, &restarted);
  int flip = o->algorithm == LOT_FLIP, inc = o->algorithm == LOT_INCREMENTAL;
  printf("# fliplab lot: rule %s, %s, %s algorithm%s%s, tie-eps %.3g\n", r->name, desc,
         cli_lot_algorithms[o->algorithm], inc ? ", order " : "",
         inc ? cli_lot_order_name[o->order] : "", tie_eps);
  printf("points: %zu (hull %zu, duplicates %zu)\n", st->n, st->hull, st->duplicates);
  if (o->nsegments || o->nholes) cli_lot_constraint_lines(o, st);
  if (o->weights) cli_lot_redundant_line(st, t);
  printf("triangles: %zu\n", st->triangles);
  printf("flips: %llu\n", (unsigned long long)st->flips);
  if (ties > 0 || restarted)   /* a polygon's sweep met sites in special position */
    printf("sweep: %zu ties in special position (%s, then the %llu flips above with the "
           "tie-break)\n", ties, restarted
           ? "the polygon sweep's result was no triangulation: the Delaunay sweep's"
           : "decided by a fixed order", (unsigned long long)st->flips);
  cli_lot_status(st);
  printf(flip ? "time: %.4f s (initial triangulation %.4f s, flips %.4f s)\n"
         : inc ? "time: %.4f s (ordering %.4f s, insertion with flips %.4f s)\n"
               : "time: %.4f s (ordering %.4f s, sweep %.4f s)\n",
         st->seconds_init + st->seconds_flip, st->seconds_init, st->seconds_flip);
}

/* A list's --svg: one panel per rule (captions as for one rule), no DT
** panel of its own (list DT among the rules). */
static int cli_lot_svg_list(const char *path, const geom_point *p, size_t n, const char *desc,
                            const cli_lot_tri *t, const rule *r, int nr) {
  report_lot_panel *pn = calloc((size_t)nr, sizeof *pn);
  char (*cap)[RULE_NAME_MAX + 64] = calloc((size_t)nr, sizeof *cap);
  FILE *f = pn && cap ? cli_open_out(CMD, path) : NULL;
  int rc = 2;
  if (pn == NULL || cap == NULL) cli_error(CMD, "out of memory");
  if (f != NULL) {
    for (int k = 0; k < nr; k++) {
      snprintf(cap[k], sizeof cap[k], "LOT(%s): %zu triangles", rule_name(&r[k]), t[k].ntri);
      pn[k] = (report_lot_panel){t[k].tri, t[k].ntri, NULL, cap[k], NULL, t[k].con, t[k].ncon};
    }
    char title[1300];
    snprintf(title, sizeof title, "%s: one LOT per rule", desc);
    report_lot_svg(f, p, n, pn, nr, 0, title);
    rc = cli_close_out(f) != 0;   /* it said why */
  }
  free(pn);
  free(cap);
  return rc;
}

/* The LOT's triangles, badness, constrained edges and redundant sites into *t. */
static int cli_lot_take(const lot *L, const geom_point *p, const rule *r, cli_lot_tri *t) {
  const lot_stats *st = lot_get_stats(L);
  t->ntri = st->triangles;
  t->ncon = st->constrained;
  t->tri = malloc(3 * st->triangles * sizeof *t->tri);
  t->bad = malloc(st->triangles * sizeof *t->bad);
  t->con = malloc((2 * st->constrained + 1) * sizeof *t->con);
  t->red = malloc((st->redundant + 1) * sizeof *t->red);
  if (t->tri == NULL || t->bad == NULL || t->con == NULL || t->red == NULL)
    return cli_error(CMD, "out of memory");
  t->nred = lot_get_redundant(L, t->red);
  lot_get_triangles(L, t->tri);
  lot_get_badness(p, t->tri, t->ntri, r, t->bad);
  if (t->ncon) lot_get_constrained(L, t->con);
  return 0;
}

/* One rule's LOT of the input: its lines (summary, --check, --compare) and,
** for a single rule, its outputs; *t keeps the triangles (caller frees),
** *failed is set when --check or a constrained --compare GOT fails.  0, 1
** after a formula's error, 2 after another. */
static int cli_lot_one(const cli_lot_args *a, const lot_options *base, const rule *r,
                       const geom_pslg *in, const char *desc, int single, cli_lot_tri *t,
                       int *failed) {
  char err[512];
  lot_options o = *base;
  o.r = *r;
  uint32_t *dt = NULL;
  size_t ndt = 0;
  const geom_point *p = in->pts;
  size_t n = in->npts;
  int constrained = in->nseg || in->nholes;
  lot *L = NULL;
  int rc = 0;
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) return cli_error(CMD, "%s", err);
  if (cli_userdefs_failed(CMD)) {
    lot_free(L);
    return 1;
  }
  const lot_stats *st = lot_get_stats(L);
  if (cli_lot_take(L, p, r, t) != 0) {
    lot_free(L);
    return 2;
  }
  cli_lot_summary(r, desc, &o, L, t, a->tie_eps);
  if (a->check && cli_lot_check(p, n, t->tri, t->ntri, r, in, &o, st) != 0) *failed = 1;
  if (a->compare == 0) rc = cli_lot_compare_dt(p, n, &o, t->tri, t->ntri, &dt, &ndt);
  else if (a->compare == 1) rc = cli_lot_compare_got(in, L, r, t, a, failed);
  if (rc == 0 && single) rc = cli_lot_write(a, p, n, t, dt, ndt, r, constrained);
  lot_free(L);
  free(dt);
  return rc;
}

int cli_cmd_lot(int argc, char **argv) {
  cli_lot_args a;
  rule d = rule_delaunay(), *r = NULL;
  lot_options o;
  lot_options_init(&o, &d);
  int rc = cli_lot_parse(argc, argv, &a, &o), nr;
  if (rc != 0) return rc == 1 ? 0 : rc;
  if ((nr = cli_lot_rules(&a, &r)) < 0) return 2;
  for (int k = 0; k < nr; k++) rule_set_tie_eps(&r[k], a.tie_eps);
  o.seed = a.seed;
  o.max_flips = a.max_flips;
  o.tie_eps = a.tie_eps;

  geom_pslg in;
  memset(&in, 0, sizeof in);
  char desc[1200];
  cli_lot_tri *t = calloc((size_t)nr, sizeof *t);
  int failed = 0;
  if (t == NULL) rc = cli_error(CMD, "out of memory");
  else rc = cli_lot_input(&a, &in, desc, sizeof desc);
  double *w = NULL;
  if (rc == 0) rc = cli_lot_weights(&a, &in, &w, desc, sizeof desc);
  o.weights = w;
  o.segments = in.seg;
  o.nsegments = in.nseg;
  o.holes = in.hole;
  o.nholes = in.nholes;
  o.keep_hull = a.keep_hull;
  for (int k = 0; rc == 0 && k < nr; k++)
    rc = cli_lot_one(&a, &o, &r[k], &in, desc, nr == 1, &t[k], &failed);
  if (rc == 0 && nr > 1 && a.svg) rc = cli_lot_svg_list(a.svg, in.pts, in.npts, desc, t, r, nr);
  for (int k = 0; t && k < nr; k++) {
    free(t[k].tri);
    free(t[k].bad);
    free(t[k].con);
    free(t[k].red);
  }
  free(t);
  free(w);
  geom_pslg_free(&in);
  free(r);
  return rc == 0 && failed ? 1 : rc;
}
