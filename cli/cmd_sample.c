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

static const cli_option cli_sample_opts[] = {
  {"--count", "N", "5000", "pentagons, at most 1e12"},
  {"--seed", "S", "1", "sampler seed: the pentagons of table34 --seed S"},
  {"--first", "I", "0", "start at sample index I"},
  {"--out", "FILE.csv", "stdout", "output file ('-': stdout)"},
  {"--no-header", NULL, NULL, "omit the header line x1,y1,...,x5,y5"},
};

static void cli_sample_usage(void) {
  cli_help(stdout, "usage: fliplab sample [options]",
           "Write random convex pentagons (iteration method, unit disc; anticlockwise) as\n"
           "CSV rows x1,y1,...,x5,y5 after a header line with those names (docs/formats.md).\n",
           cli_sample_opts, CLI_NOPTS(cli_sample_opts));
}

int cli_cmd_sample(int argc, char **argv) {
  uint64_t count = 5000, seed = 1, first = 0;
  const char *outpath = NULL;
  int header = 1;
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i], *v;
    if (cli_is_help(a)) {
      cli_sample_usage();
      return 0;
    }
    if (strcmp(a, "--count") == 0) {
      if ((v = cli_optarg(CMD, argc, argv, &i)) == NULL ||
          cli_parse_u64(CMD, a, v, 1, CLI_MAX_SAMPLES, &count) != 0)
        return 2;
    } else if (strcmp(a, "--seed") == 0) {
      if ((v = cli_optarg(CMD, argc, argv, &i)) == NULL ||
          cli_parse_u64(CMD, a, v, 0, UINT64_MAX, &seed) != 0)
        return 2;
    } else if (strcmp(a, "--first") == 0) {
      if ((v = cli_optarg(CMD, argc, argv, &i)) == NULL ||
          cli_parse_u64(CMD, a, v, 0, UINT64_MAX - CLI_MAX_SAMPLES, &first) != 0)
        return 2;
    } else if (strcmp(a, "--out") == 0) {
      if ((outpath = cli_optarg(CMD, argc, argv, &i)) == NULL ||
          cli_check_out_ext(CMD, a, outpath, "csv") != 0)
        return 2;
    } else if (strcmp(a, "--no-header") == 0) {
      header = 0;
    } else {
      return cli_unknown_option(CMD, a, cli_sample_opts, CLI_NOPTS(cli_sample_opts));
    }
  }
  FILE *out = cli_open_out(CMD, outpath);
  if (out == NULL) return 2;
  if (header) report_pentagon_header(out);
  int rc = 0;
  for (uint64_t k = 0; k < count && rc == 0; k++) {
    geom_point v[5];
    sampler_pentagon(seed, first + k, v);
    if (report_pentagon_write(out, v) != 0) rc = 1;
  }
  return cli_close_out(out) != 0 ? 1 : rc;
}
