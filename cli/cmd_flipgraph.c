/*
** cmd_flipgraph.c: `fliplab flipgraph`: every triangulation of one small
** site set (convex or not), its flip graph directed by a rule, and what
** that graph says: sinks (the LOTs), sources, ties, cycles, whether the
** sink is the Delaunay triangulation, the GOT by brute force.
*/
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "report.h"
#include "rule.h"
#include "siteflip.h"

#define CMD "flipgraph"

typedef struct cli_flipgraph_opts {
  const char *rule, *points, *svg, *out, *weights;
  double tie_eps;
  uint64_t memory;
} cli_flipgraph_opts;

#define T cli_flipgraph_opts
static const cli_option cli_flipgraph_help[] = {
  CLI_OPT_STRING("--rule", "RULE", "required",
                 "DT, a quadrilateral rule, or MEASURE_JOINT (e.g. R_1)", T, rule),
  CLI_OPT_STRING("--points", "FILE.csv", "required",
                 "the sites: CSV rows x,y (optional header x,y)", T, points),
  CLI_OPT_STRING("--weights", "W.csv", "none",
                 "with --rule WDT: a weight 'w' per site (rows of the\n"
                 "                     points file; optional header 'w')", T, weights),
  CLI_OPT_FILE("--svg", "FILE.svg", "none", "svg",
               "draw the directed flip graph (at most 64 triangulations)", T, svg),
  CLI_OPT_TIE_EPS("relative tie tolerance of the rule", 1, T, tie_eps),
  CLI_OPT_MEMORY("1G", SITEFLIP_MEMORY_DEFAULT,
                 "memory budget of the flip graph (K, M, G: KiB, MiB, GiB;\n"
                 "                     about 200 bytes per triangulation)", T, memory),
  CLI_OPT_OUT("FILE", "stdout", NULL, "write the report to FILE", T, out),
};
#undef T

static const cli_spec cli_flipgraph_spec = {
  CMD, "usage: fliplab flipgraph --rule RULE --points FILE.csv [options]",
  "Enumerate every triangulation of a set of 3 to 16 sites (any position, convex\n"
  "or not) whose flip graph fits --memory, direct the graph by RULE and report:\n"
  "triangulations, flip edges, sinks (the LOTs; triangles as 1-based site\n"
  "numbers), sources, ties, cycle, sink is DT, GOT (triangle-based rules, by\n"
  "brute force) and the worst sink's relative gap to it (docs/sitesets.md).\n",
  cli_flipgraph_help, CLI_NOPTS(cli_flipgraph_help), NULL};

/* 0, 1 after --help, 2 after an error. */
static int cli_flipgraph_parse(int argc, char **argv, cli_flipgraph_opts *o) {
  int st = cli_options_parse(&cli_flipgraph_spec, argc, argv, o, NULL);
  if (st != 0) return st;
  if (o->rule == NULL || o->points == NULL)
    return cli_error(CMD, "--rule and --points are required (try: fliplab flipgraph --help)");
  return 0;
}

/* --weights: a weight per site for WDT, into *w (NULL without the option). */
static int cli_flipgraph_weights(const cli_flipgraph_opts *o, const rule *r, size_t n,
                                 double **w) {
  char err[512];
  *w = NULL;
  if (o->weights == NULL) return 0;
  if (!rule_wants_weights(r))
    return cli_error(CMD, "--weights applies to the weighted Delaunay rule WDT, not %s",
                     rule_name(r));
  if (report_weights_read(o->weights, n, w, err, sizeof err) != 0)
    return cli_error(CMD, "--weights: %s", err);
  return 0;
}

static void cli_flipgraph_tris(FILE *f, const siteflip_graph *g, int u) {
  for (int t = 0; t < g->per; t++) {
    const unsigned char *v = g->tri_v[g->node_tri[(size_t)u * (size_t)g->per + t]];
    fprintf(f, " (%d,%d,%d)", v[0] + 1, v[1] + 1, v[2] + 1);
  }
  fputc('\n', f);
}

static void cli_flipgraph_report(FILE *f, const siteflip_graph *g, const rule *r,
                                 const siteflip_result *res, const int *sinks) {
  fprintf(f, "sites: %d\nrule: %s\ntriangulations: %d\nflip edges: %d\nquadrilaterals: %d\n",
          g->n, r->name, g->nnodes, g->nedges, g->nquads);
  fprintf(f, "sinks: %d\n", res->nsinks);
  for (int k = 0; k < res->nsinks; k++) {
    fprintf(f, "  sink T%d:", sinks[k] + 1);
    cli_flipgraph_tris(f, g, sinks[k]);
  }
  fprintf(f, "sources: %d\nties: %s\ncycle: %s\nsink is DT: %s\n", res->nsources,
          res->ties ? "yes" : "no", res->cycle ? "yes" : "no",
          res->sink_dt < 0 ? "-" : res->sink_dt ? "yes" : "no");
  if (g->delaunay >= 0) {
    fprintf(f, "  DT T%d:", g->delaunay + 1);
    cli_flipgraph_tris(f, g, g->delaunay);
  }
  if (res->has_got) {
    fprintf(f, "GOT: %.17g (T%d)\n", res->got_total, res->got_node + 1);
    fprintf(f, "worst LOT gap: %.6g (T%d)\n", res->worst_gap, res->worst_sink + 1);
  } else {
    fprintf(f, "GOT: - (%s is not triangle-based)\n", r->name);
  }
}

static int cli_flipgraph_svg(const char *path, const siteflip_graph *g, const rule *r,
                             const rule_choice *dec, const siteflip_result *res) {
  if (g->nnodes > REPORT_SITEFLIP_SVG_MAX) {
    fprintf(stderr, "fliplab flipgraph: note: %d triangulations are too many to draw "
                    "(at most %d); no SVG written\n", g->nnodes, REPORT_SITEFLIP_SVG_MAX);
    return 0;
  }
  FILE *f = cli_open_out(CMD, path);
  if (f == NULL) return 2;
  char cap[RULE_NAME_MAX + 256];
  snprintf(cap, sizeof cap, "rule %s: %d triangulations, %d sink%s, %d source%s%s%s", r->name,
           g->nnodes, res->nsinks, res->nsinks == 1 ? "" : "s", res->nsources,
           res->nsources == 1 ? "" : "s", res->ties ? ", ties" : "",
           res->cycle ? ", a directed cycle" : "");
  report_siteflip_svg(f, g, dec, cap);   /* a failed write: cli_close_out reports it */
  return cli_close_out(f) != 0 ? 1 : 0;
}

int cli_cmd_flipgraph(int argc, char **argv) {
  cli_flipgraph_opts o;
  int st = cli_flipgraph_parse(argc, argv, &o);
  if (st != 0) return st == 1 ? 0 : st;
  rule r;
  char err[4096];
  if (cli_parse_rule(CMD, o.rule, &r) != 0) return 2;
  geom_point *p;
  size_t n;
  if (report_points_read(o.points, &p, NULL, &n, err, sizeof err) != 0)
    return cli_error(CMD, "%s", err);
  double *w;
  if (cli_flipgraph_weights(&o, &r, n, &w) != 0) {
    free(p);
    return 2;
  }
  /* siteflip_check refuses more than 16 sites before reading any. */
  cli_progress prog;
  cli_progress_start(&prog, CMD " enumerating");
  prog.open = 1;
  siteflip_limits lim = {(size_t)o.memory, cli_progress_update, &prog};
  siteflip_graph *g = siteflip_build_within(p, n > 1000000 ? 1000000 : (int)n, &lim, NULL, err,
                                            sizeof err);
  cli_progress_finish(&prog);
  free(p);
  if (g == NULL) {
    free(w);
    return cli_error(CMD, "%s: %s", o.points, err);
  }
  rule_choice *dec = malloc(((size_t)g->nquads + 1) * sizeof *dec);
  int *sinks = malloc((size_t)g->nnodes * sizeof *sinks);
  siteflip_result res;
  int rc = 1;
  FILE *out = NULL;
  if (dec == NULL || sinks == NULL ||
      siteflip_direct_weighted(g, &r, w, o.tie_eps, dec, sinks, &res) != 0) {
    cli_error(CMD, "out of memory");
    goto done;
  }
  if (cli_userdefs_failed(CMD)) goto done;
  if ((out = cli_open_out(CMD, o.out)) == NULL) {
    rc = 2;
    goto done;
  }
  cli_flipgraph_report(out, g, &r, &res, sinks);
  rc = cli_close_out(out) != 0 ? 1 : 0;
  if (rc == 0 && o.svg != NULL) rc = cli_flipgraph_svg(o.svg, g, &r, dec, &res);
done:
  free(w);
  free(dec);
  free(sinks);
  siteflip_free(g);
  return rc;
}
