/*
** cmd_sample.c: `fliplab sample`: write random convex pentagons (the
** table-3.4 sampler) to CSV, one per row as x1,y1,...,x5,y5 after a header
** line of those names, with %.17g so that every coordinate reads back bit
** for bit.  Pentagon i of seed S is the one table34 classifies as sample i.
*/
#include <string.h>
#include "cli.h"
#include "sampler.h"
#include "report.h"

#define CMD "sample"
#define CLI_MAX_SAMPLES 1000000000000ull   /* 1e12 */

typedef struct cli_sample_opts {
  uint64_t count, seed, first;
  const char *out;
  int no_header;
} cli_sample_opts;

#define T cli_sample_opts
static const cli_option cli_sample_table[] = {
  CLI_OPT_U64("--count", "N", "pentagons, at most 1e12", T, count, 1, CLI_MAX_SAMPLES, 5000),
  CLI_OPT_SEED("sampler seed: the pentagons of table34 --seed S", T, seed),
  CLI_OPT_U64("--first", "I", "start at sample index I", T, first, 0,
              UINT64_MAX - CLI_MAX_SAMPLES, 0),
  CLI_OPT_OUT("FILE.csv", "stdout", "csv", "output file ('-': stdout)", T, out),
  CLI_OPT_FLAG("--no-header", "omit the header line x1,y1,...,x5,y5", T, no_header),
};
#undef T

static const cli_spec cli_sample_spec = {
  CMD, "usage: fliplab sample [options]",
  "Write random convex pentagons (iteration method, unit disc; anticlockwise) as\n"
  "CSV rows x1,y1,...,x5,y5 after a header line with those names (docs/formats.md).\n",
  cli_sample_table, CLI_NOPTS(cli_sample_table), NULL};

int cli_cmd_sample(int argc, char **argv) {
  cli_sample_opts o;
  int st = cli_options_parse(&cli_sample_spec, argc, argv, &o, NULL);
  if (st != 0) return st == 1 ? 0 : st;
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
