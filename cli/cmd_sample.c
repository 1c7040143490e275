/*
** cmd_sample.c: `fliplab sample`: write random convex pentagons (the
** table-3.4 sampler) to CSV, one per row as x1,y1,...,x5,y5 after a header
** line of those names, with %.17g so that every coordinate reads back bit
** for bit.  Pentagon i of seed S is the one table34 classifies as sample i.
**
** With --sampler holes|segments|grid it writes one random planar
** straight-line graph instead (samplers/pslg.c), as a Triangle .poly file:
** a polygon with holes, non-crossing segments on a point set, or a rotated
** grid with segments along its lines, the inputs of constrained
** triangulations.
*/
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "sampler.h"
#include "report.h"

#define CMD "sample"
#define CLI_MAX_SAMPLES 1000000000000ull   /* 1e12 */

/* Indexed by --sampler. */
enum { CLI_SAMPLE_PENTAGON, CLI_SAMPLE_HOLES, CLI_SAMPLE_SEGMENTS, CLI_SAMPLE_GRID };
static const char *const cli_sample_samplers[] = {"pentagon", "holes", "segments", "grid", NULL};
static const char *const cli_sample_formats[] = {"csv", "poly", NULL};

typedef struct cli_sample_opts {
  uint64_t count, seed, first, points, holes, hole_vertices, segments;
  const char *out;
  int no_header, sampler, format, point_sampler;
} cli_sample_opts;

/* --point-sampler: a sampler_points_kind, SAMPLER_UNIFORM by default. */
static int cli_sample_points_kind(const char *cmd, const cli_option *o, const char *v,
                                  void *dst) {
  (void)o;
  int k = v != NULL ? sampler_points_find(v) : SAMPLER_UNIFORM;
  if (k < 0) return cli_error(cmd, "unknown point sampler '%s' (valid: %s)", v, sampler_points_names);
  *(int *)dst = k;
  return 0;
}

#define T cli_sample_opts
static const cli_option cli_sample_table[] = {
  {.name = "--sampler", .arg = "S",
   .help = "pentagon (convex pentagons, CSV); holes, segments, grid:\n"
           "                     one planar straight-line graph (.poly)",
   .kind = CLI_CHOICE, .off = CLI_AT(T, sampler, int), .names = cli_sample_samplers,
   .idef = CLI_SAMPLE_PENTAGON,
   .bad = "unknown sampler '%s' (valid: pentagon, holes, segments, grid)"},
  CLI_OPT_U64("--count", "N", "pentagons, at most 1e12", T, count, 1, CLI_MAX_SAMPLES, 5000),
  CLI_OPT_SEED("sampler seed: the pentagons of table34 --seed S", T, seed),
  CLI_OPT_U64("--first", "I", "start at sample index I", T, first, 0,
              UINT64_MAX - CLI_MAX_SAMPLES, 0),
  CLI_OPT_U64("--points", "N", "graphs: vertices of the outer polygon (holes), points\n"
              "                     (segments, grid)", T, points, 3, SAMPLER_PSLG_MAX_GRID, 1000),
  CLI_OPT_U64("--holes", "H", "holes: the number of holes", T, holes, 0, SAMPLER_PSLG_MAX_HOLES,
              10),
  CLI_OPT_U64("--hole-vertices", "M", "holes: vertices of each hole", T, hole_vertices, 3,
              100000, 6),
  CLI_OPT_U64("--segments", "M", "segments: how many (fewer when the points offer fewer)", T,
              segments, 1, 0xffffffffu, 100),
  {.name = "--point-sampler", .arg = "NAME", .dflt = "uniform",
   .help = "segments: the points, as lot --random's --sampler", .kind = CLI_CALL,
   .off = CLI_AT(T, point_sampler, int), .call = cli_sample_points_kind},
  {.name = "--format", .arg = "F", .dflt = "csv (pentagon), poly (graphs)",
   .help = "csv: pentagon rows; poly: Triangle's .poly file", .kind = CLI_CHOICE,
   .off = CLI_AT(T, format, int), .names = cli_sample_formats, .idef = -1,
   .bad = "unknown format '%s' (valid: csv, poly)"},
  CLI_OPT_OUT("FILE", "stdout", NULL, "output file ('-': stdout), .csv or .poly", T, out),
  CLI_OPT_FLAG("--no-header", "omit the header line x1,y1,...,x5,y5", T, no_header),
};
#undef T

static const cli_spec cli_sample_spec = {
  CMD, "usage: fliplab sample [options]",
  "Write random convex pentagons (iteration method, unit disc; anticlockwise) as\n"
  "CSV rows x1,y1,...,x5,y5 after a header line with those names, or with\n"
  "--sampler holes|segments|grid one random planar straight-line graph as a\n"
  "Triangle .poly file (docs/formats.md, docs/sampling.md).\n",
  cli_sample_table, CLI_NOPTS(cli_sample_table), NULL};

/* The options that belong to the other kind of sampler are refused. */
static int cli_sample_check(const cli_sample_opts *o, uint64_t given) {
  static const char *const pent[] = {"--count", "--first", "--no-header"};
  static const char *const graph[] = {"--points", "--holes", "--hole-vertices", "--segments",
                                      "--point-sampler"};
  static const int graph_of[] = {-1, CLI_SAMPLE_HOLES, CLI_SAMPLE_HOLES, CLI_SAMPLE_SEGMENTS,
                                 CLI_SAMPLE_SEGMENTS};
  int is_pent = o->sampler == CLI_SAMPLE_PENTAGON;
  for (size_t i = 0; i < sizeof pent / sizeof pent[0]; i++)
    if (!is_pent && cli_option_given(&cli_sample_spec, given, pent[i]))
      return cli_error(CMD, "%s applies to --sampler pentagon only", pent[i]);
  for (size_t i = 0; i < sizeof graph / sizeof graph[0]; i++)
    if (cli_option_given(&cli_sample_spec, given, graph[i]) &&
        (is_pent || (graph_of[i] >= 0 && graph_of[i] != o->sampler)))
      return cli_error(CMD, "%s does not apply to --sampler %s", graph[i],
                       cli_sample_samplers[o->sampler]);
  int want = is_pent ? 0 : 1;
  if (o->format >= 0 && o->format != want)
    return cli_error(CMD, "--sampler %s writes %s only", cli_sample_samplers[o->sampler],
                     is_pent ? "CSV (--format csv)" : "a .poly file (--format poly)");
  return o->out ? cli_check_out_ext(CMD, "--out", o->out, cli_sample_formats[want]) : 0;
}

/* The graph of a graph sampler; 0, or 2 after the error. */
static int cli_sample_graph(const cli_sample_opts *o, geom_pslg *g) {
  sampler_rng r;
  int rc;
  if (o->sampler == CLI_SAMPLE_SEGMENTS) {
    *g = (geom_pslg){0};
    g->npts = (size_t)o->points;
    g->pts = malloc(g->npts * sizeof *g->pts);
    g->seg = malloc(2 * (size_t)o->segments * sizeof *g->seg);
    if (g->pts == NULL || g->seg == NULL) {
      geom_pslg_free(g);
      return cli_error(CMD, "out of memory for %zu points", (size_t)o->points);
    }
    sampler_points((sampler_points_kind)o->point_sampler, o->seed, g->npts, g->pts);
    sampler_seed(&r, o->seed, GEOM_STREAM_SEGMENTS);
    rc = sampler_segments(&r, g->pts, g->npts, (size_t)o->segments, g->seg, &g->nseg);
  } else {
    sampler_seed(&r, o->seed, GEOM_STREAM_PSLG);
    rc = o->sampler == CLI_SAMPLE_GRID
             ? sampler_pslg_grid(&r, (size_t)o->points, g)
             : sampler_pslg_holes(&r, (size_t)o->points, (size_t)o->holes,
                                  (size_t)o->hole_vertices, g);
  }
  if (rc == SAMPLER_ENOMEM) {
    geom_pslg_free(g);
    return cli_error(CMD, "out of memory");
  }
  if (rc != 0)   /* only the holes sampler can fail otherwise */
    return cli_error(CMD, "%llu holes of %llu vertices did not fit inside the polygon in "
                     "%d draws; ask for fewer", (unsigned long long)o->holes,
                     (unsigned long long)o->hole_vertices, 100);
  if (o->sampler == CLI_SAMPLE_SEGMENTS && g->nseg < o->segments)
    fprintf(stderr, "fliplab sample: note: %zu of the %llu segments asked for (the points offer "
            "no more)\n", g->nseg, (unsigned long long)o->segments);
  return 0;
}

static int cli_sample_write_graph(const cli_sample_opts *o) {
  geom_pslg g;
  if (cli_sample_graph(o, &g) != 0) return 2;
  FILE *out = cli_open_out(CMD, o->out);
  int rc = out == NULL ? 2 : 0;
  if (out != NULL) {
    report_poly_write(out, &g);
    rc = cli_close_out(out) != 0;   /* it said why */
  }
  geom_pslg_free(&g);
  return rc;
}

int cli_cmd_sample(int argc, char **argv) {
  cli_sample_opts o;
  uint64_t given;
  int st = cli_options_parse(&cli_sample_spec, argc, argv, &o, &given);
  if (st != 0) return st == 1 ? 0 : st;
  if (cli_sample_check(&o, given) != 0) return 2;
  if (o.sampler != CLI_SAMPLE_PENTAGON) return cli_sample_write_graph(&o);
  FILE *out = cli_open_out(CMD, o.out);
  if (out == NULL) return 2;
  if (!o.no_header) report_pentagon_header(out);
  int rc = 0;
  for (uint64_t k = 0; k < o.count && rc == 0; k++) {
    geom_point v[5];
    sampler_pentagon(o.seed, o.first + k, v);
    if (report_pentagon_write(out, v) != 0) rc = 1;
  }
  return cli_close_out(out) != 0 ? 1 : rc;
}
