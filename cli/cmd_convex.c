/*
** cmd_convex.c: `fliplab convex`: random convex n-gons from any sampler of
** the registry (samplers/gon.c; thesis chapter 6, docs/sampling.md): their
** vertices as CSV (one row per vertex: polygon, vertex, x, y, log_weight,
** h, with %.17g so that coordinates read back bit for bit), an SVG sheet of
** the first few, and with --stats the weighted means of the per-polygon
** statistics with 95% intervals (studies/convex.c).  Polygon i of seed S is
** drawn from its own stream: the output does not depend on --threads.
** Polygons are drawn in batches of about 2^22 vertices, so memory stays
** bounded whatever the count.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "report.h"
#include "sampler.h"
#include "study.h"

#define CMD "convex"
#define CLI_CONVEX_MAX_N 10000000ull       /* 1e7 vertices: 160 MB a polygon */
#define CLI_CONVEX_MAX_COUNT 1000000000ull
#define CLI_CONVEX_BATCH ((size_t)1 << 22)  /* vertices per batch */
#define CLI_CONVEX_SVG_MAX 16

typedef struct cli_convex_opts {
  uint64_t n, count, seed, first, threads, svg_count, law;
  const char *sampler, *inner, *out, *svg, *stats_out;
  int region, stats;
} cli_convex_opts;

static int cli_convex_region(const char *cmd, const cli_option *o, const char *v, void *dst) {
  (void)o;
  int r = v != NULL ? sampler_region_find(v) : SAMPLER_REGION_SQUARE;
  if (r < 0) return cli_error(cmd, "unknown region '%s' (valid: %s)", v, sampler_region_names);
  *(int *)dst = r;
  return 0;
}

#define T cli_convex_opts
static const cli_option cli_convex_table[] = {
  {.name = "--sampler", .arg = "S",
   .help = "rejection, naive, iteration, valtr, vector, circle, triangulation,\n"
           "                     bounce, dual, dual-rejection, geobench, angles\n"
           "                     (docs/sampling.md)",
   .kind = CLI_STRING, .off = CLI_AT(T, sampler, const char *), .sdef = "rejection"},
  {.name = "--region", .arg = "R", .dflt = "square",
   .help = "square [0,1]^2, disc (unit), triangle (0,0),(1,0),(0,1)", .kind = CLI_CALL,
   .off = CLI_AT(T, region, int), .call = cli_convex_region},
  CLI_OPT_U64("--n", "N", "vertices of each polygon, 3 .. 1e7", T, n, 3, CLI_CONVEX_MAX_N, 10),
  CLI_OPT_U64("--count", "C", "polygons, at most 1e9", T, count, 1, CLI_CONVEX_MAX_COUNT, 1000),
  CLI_OPT_SEED("seed: polygon i is drawn from stream (S, i)", T, seed),
  CLI_OPT_U64("--first", "I", "start at polygon index I", T, first, 0,
              UINT64_MAX - CLI_CONVEX_MAX_COUNT, 0),
  CLI_OPT_U64("--law", "L", "the sampler's variant (iteration: 1 = the exterior-region\n"
              "                     path also for the disc below 17; bounce: 0 = velocity\n"
              "                     redrawn, 1 = reflected)", T, law, 0, 1, 0),
  CLI_OPT_STRING("--inner", "M", "vector", "dual: the inner method (vector, circle,\n"
                 "                     triangulation, bounce, dual-rejection, geobench, angles)",
                 T, inner),
  CLI_OPT_THREADS("threads; the output does not depend on T", T, threads),
  CLI_OPT_OUT("FILE", "stdout unless --stats", "csv",
              "vertices as CSV: polygon,vertex,x,y,log_weight,h", T, out),
  CLI_OPT_FILE("--svg", "FILE", "none", "svg", "an SVG sheet of the first --svg-count polygons",
               T, svg),
  CLI_OPT_U64("--svg-count", "K", "polygons in the SVG, 1 .. 16", T, svg_count, 1,
              CLI_CONVEX_SVG_MAX, 4),
  CLI_OPT_FLAG("--stats", "print weighted means and 95% intervals of area, perimeter,\n"
               "                     h, unimodal, rect_differ", T, stats),
  CLI_OPT_FILE("--stats-out", "FILE", "none", "csv", "per-polygon statistics as CSV", T,
               stats_out),
};
#undef T

static const cli_spec cli_convex_spec = {
  CMD, "usage: fliplab convex [options]",
  "Write random convex n-gons (thesis chapter 6) from a sampler: strictly convex,\n"
  "anticlockwise from the lexicographically smallest vertex, as CSV rows\n"
  "polygon,vertex,x,y,log_weight,h; an SVG of a few; with --stats their weighted\n"
  "mean area, perimeter, hull changes h, unimodality and whether the minimum-area\n"
  "and minimum-perimeter enclosing rectangles differ (docs/sampling.md).\n",
  cli_convex_table, CLI_NOPTS(cli_convex_table), NULL};

/* The sampler and its region (sampler_gon_check's words); 0, or 2 after
** the one-line error. */
static int cli_convex_check(const cli_convex_opts *o, uint64_t given, const sampler_gon **s) {
  char err[512];
  int region = cli_option_given(&cli_convex_spec, given, "--region") ? o->region : -1;
  *s = sampler_gon_find(o->sampler);
  if (sampler_gon_check(o->sampler, region, (size_t)o->n, err, sizeof err) != 0)
    return cli_error(CMD, "%s", err);
  if (sampler_gon_check_variant(o->sampler, (int)o->law, o->inner, (size_t)o->n, err,
                                sizeof err) != 0)
    return cli_error(CMD, "%s", err);
  if (o->svg != NULL && o->n > 100000)
    return cli_error(CMD, "--svg draws polygons of at most 100000 vertices (--n %llu)",
                     (unsigned long long)o->n);
  return 0;
}

/* Where a batch goes. */
typedef struct cli_convex_sink {
  FILE *csv, *stats_csv;
  study_convex_acc acc;
  geom_point *svg_xy;
  uint64_t svg_index[CLI_CONVEX_SVG_MAX];
  double svg_lw[CLI_CONVEX_SVG_MAX];
  size_t svg_have;
} cli_convex_sink;

static void cli_convex_rows(const cli_convex_opts *o, cli_convex_sink *k, uint64_t id,
                            const geom_point *v, double lw, uint64_t h, const double *st) {
  size_t n = (size_t)o->n;
  if (k->csv != NULL)
    for (size_t j = 0; j < n; j++)
      fprintf(k->csv, "%llu,%zu,%.17g,%.17g,%.17g,%llu\n", (unsigned long long)id, j, v[j].x,
              v[j].y, lw, (unsigned long long)h);
  if (k->stats_csv != NULL) {
    fprintf(k->stats_csv, "%llu,%.17g", (unsigned long long)id, lw);
    for (int s = 0; s < STUDY_CONVEX_NSTATS; s++)
      fprintf(k->stats_csv, isnan(st[s]) ? ",nan" : ",%.17g", st[s]);
    fputc('\n', k->stats_csv);
  }
  if (o->stats) study_convex_acc_add(&k->acc, lw, st);
  if (k->svg_xy != NULL && k->svg_have < (size_t)o->svg_count) {
    memcpy(k->svg_xy + k->svg_have * n, v, n * sizeof *v);
    k->svg_index[k->svg_have] = id;
    k->svg_lw[k->svg_have++] = lw;
  }
}

/* Draw every batch into the sink; 0, or 1 (memory) or 2 (n too large for
** the sampler) after the one-line error. */
static int cli_convex_batches(const cli_convex_opts *o, cli_convex_sink *k) {
  size_t n = (size_t)o->n, b = CLI_CONVEX_BATCH / n;
  if (b < 1) b = 1;
  if (b > o->count) b = (size_t)o->count;
  geom_point *xy = malloc(b * n * sizeof *xy);
  double *lw = malloc(b * sizeof *lw), *st = malloc(b * STUDY_CONVEX_NSTATS * sizeof *st);
  uint64_t *h = malloc(b * sizeof *h), failed = 0;
  int want = o->stats || k->stats_csv != NULL, rc = xy && lw && st && h ? 0 : SAMPLER_ENOMEM;
  study_convex_run run = {o->sampler, o->region, (int)o->law, (int)o->threads, n, o->seed,
                          o->inner};
  for (uint64_t done = 0; done < o->count && rc == 0; done += b) {
    size_t m = o->count - done < b ? (size_t)(o->count - done) : b;
    rc = study_convex_draw(&run, o->first + done, m, xy, lw, h, want ? st : NULL, &failed);
    for (size_t i = 0; i < m && rc == 0; i++)
      cli_convex_rows(o, k, o->first + done + i, xy + i * n, lw[i], h[i],
                      st + i * STUDY_CONVEX_NSTATS);
  }
  free(xy);
  free(lw);
  free(st);
  free(h);
  if (rc == SAMPLER_ENOMEM)
    return cli_error(CMD, "out of memory for polygons of %zu vertices", n) - 1;
  if (rc != 0)   /* n beyond the sampler's reach in doubles: a request to change */
    return cli_error(CMD, "polygon %llu: --sampler %s could not realise a strictly convex "
                     "%zu-gon in doubles (its regions became too thin); ask for a smaller --n",
                     (unsigned long long)failed, o->sampler, n);
  return 0;
}

/* The weighted means, one statistic a line. */
static void cli_convex_print_stats(const cli_convex_opts *o, const sampler_gon *s,
                                   const study_convex_acc *a) {
  printf("sampler: %s%s, region: %s, n: %llu, polygons: %llu from %llu, seed: %llu\n",
         o->sampler, s->weighted ? " (weighted)" : "",
         s->regions ? sampler_region_name(o->region) : "none", (unsigned long long)o->n,
         (unsigned long long)o->count, (unsigned long long)o->first,
         (unsigned long long)o->seed);
  printf("effective sample size: %.6g of %llu\n", study_convex_acc_ess(a),
         (unsigned long long)a->count);
  printf("%-12s %-16s %s\n", "statistic", "mean", "95% half-width");
  for (int k = 0; k < STUDY_CONVEX_NSTATS; k++) {
    double m, hw;
    study_convex_acc_mean(a, k, &m, &hw);
    if (isnan(m))
      printf("%-12s %-16s %s\n", study_convex_stat_names[k], "-", "-");
    else
      printf("%-12s %-16.8g %.3g\n", study_convex_stat_names[k], m, hw);
  }
}

static int cli_convex_open(const cli_convex_opts *o, cli_convex_sink *k) {
  int csv = o->out != NULL || (!o->stats && o->stats_out == NULL && o->svg == NULL);
  if (csv && (k->csv = cli_open_out(CMD, o->out)) == NULL) return 2;
  if (k->csv != NULL) fprintf(k->csv, "polygon,vertex,x,y,log_weight,h\n");
  if (o->stats_out != NULL) {
    if ((k->stats_csv = cli_open_out(CMD, o->stats_out)) == NULL) return 2;
    fprintf(k->stats_csv, "polygon,log_weight");
    for (int s = 0; s < STUDY_CONVEX_NSTATS; s++)
      fprintf(k->stats_csv, ",%s", study_convex_stat_names[s]);
    fputc('\n', k->stats_csv);
  }
  if (o->svg != NULL) {
    k->svg_xy = malloc((size_t)o->svg_count * (size_t)o->n * sizeof *k->svg_xy);
    if (k->svg_xy == NULL) return cli_error(CMD, "out of memory for the SVG") - 1;
  }
  return 0;
}

static int cli_convex_svg(const cli_convex_opts *o, const sampler_gon *s,
                          const cli_convex_sink *k) {
  FILE *f = cli_open_out(CMD, o->svg);
  if (f == NULL) return 2;
  int wrc = report_convex_svg(f, k->svg_xy, (size_t)o->n, k->svg_have, k->svg_index,
                              s->weighted ? k->svg_lw : NULL);
  return cli_finish_out(CMD, f, wrc);
}

int cli_cmd_convex(int argc, char **argv) {
  cli_convex_opts o;
  uint64_t given;
  const sampler_gon *s;
  int st = cli_options_parse(&cli_convex_spec, argc, argv, &o, &given);
  if (st != 0) return st == 1 ? 0 : st;
  if (cli_convex_check(&o, given, &s) != 0) return 2;
  cli_convex_sink k = {0};
  study_convex_acc_init(&k.acc);
  int rc = cli_convex_open(&o, &k);
  if (rc == 0) rc = cli_convex_batches(&o, &k);
  if (rc == 0 && o.svg != NULL) rc = cli_convex_svg(&o, s, &k);
  if (rc == 0 && o.stats) cli_convex_print_stats(&o, s, &k.acc);
  if (k.csv != NULL && cli_close_out(k.csv) != 0 && rc == 0) rc = 1;
  if (k.stats_csv != NULL && cli_close_out(k.stats_csv) != 0 && rc == 0) rc = 1;
  free(k.svg_xy);
  return rc;
}
