/*
** cmd_classify.c: `fliplab classify`: the directed flip graph of every
** pentagon of a CSV file under every chosen rule, one output row per
** (pentagon, rule):
**
**   id,rule,decisions,type,sink,dt
**
** id is the pentagon's row number (1-based, header excluded); decisions
** are five letters for Q_0..Q_4: A = diagonal v_{j+1}v_{j+3}, B = diagonal
** v_{j+2}v_{j+4}, E = either (a tie); type is I..V; sink lists the sinks'
** fan indices (T_i = the fan at v_i), space-separated when there are two
** (type III), empty when there is none (types IV and V); dt is 1 for type I with the
** Delaunay triangulation as sink.  Vertices are numbered v0..v4 in input
** order after a clockwise pentagon has been reversed by geom_polygon_check,
** which keeps the first vertex: (p1, p2, p3, p4, p5) becomes
** v0..v4 = (p1, p5, p4, p3, p2).
*/
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "measure.h"
#include "flipgraph.h"
#include "cli.h"
#include "rule.h"
#include "joint.h"
#include "report.h"

#define CMD "classify"
#define CLI_MAX_RULES 1024

static const char cli_classify_usage[] =
  "usage: fliplab classify --input FILE.csv [--rule R ...] [--tie-eps E] [--out FILE.csv]\n"
  "Classify the directed flip graph of every pentagon of FILE.csv under every rule.\n"
  "Input: rows x1,y1,...,x5,y5 (the header line x1,y1,...,y5 is optional), either\n"
  "orientation: a clockwise row p1..p5 is renumbered v0..v4 = p1,p5,p4,p3,p2.\n"
  "Output: id,rule,decisions,type,sink,dt per pentagon and rule, where id is the\n"
  "pentagon's row (1-based, header excluded); decisions = five letters for Q_0..Q_4\n"
  "(A = diagonal v_{j+1}v_{j+3}, B = v_{j+2}v_{j+4}, E = either); type I..V;\n"
  "sink = i for the fan T_i (two, space-separated, for type III; empty for IV, V);\n"
  "dt = 1 if type I with the Delaunay triangulation as sink.\n\n"
  "  --input FILE   pentagons ('-' for standard input)\n"
  "  --rule R       a rule (repeatable), e.g. R_inf, -alpha_inf, DT;\n"
  "                 default: the 120 rules of table 3.4, then DT\n"
  "  --tie-eps E    tie tolerance (default 1e-12)\n"
  "  --out FILE     output file (default: stdout)\n";

static void cli_classify_row(FILE *out, size_t id, const rule *r, const flipgraph *g) {
  static const char letter[3] = {'A', 'B', 'E'};   /* RULE_AC, RULE_BD, RULE_EITHER */
  char dec[6];
  for (int j = 0; j < 5; j++) dec[j] = letter[g->dec[j]];
  dec[5] = '\0';
  fprintf(out, "%zu,", id);
  report_csv_field(out, r->name);
  fprintf(out, ",%s,%s,", dec, flipgraph_type_name(g->type));
  for (int s = 0; s < g->nsinks && s < 2; s++) fprintf(out, s ? " %d" : "%d", g->sink[s]);
  fprintf(out, ",%d\n", g->delaunay ? 1 : 0);
}

int cli_cmd_classify(int argc, char **argv) {
  const char *inpath = NULL, *outpath = NULL;
  double eps = RULE_DEFAULT_TIE_EPS;
  rule *rules = malloc(CLI_MAX_RULES * sizeof *rules);
  int nrules = 0, rc = 2;
  geom_point *v = NULL;
  FILE *in = NULL, *out = NULL;
  if (rules == NULL) return cli_error(CMD, "out of memory");
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i], *val;
    char err[1024];
    if (cli_is_help(a)) {
      fputs(cli_classify_usage, stdout);
      rc = 0;
      goto done;
    }
    if (strcmp(a, "--input") == 0) {
      if ((inpath = cli_optarg(CMD, argc, argv, &i)) == NULL) goto done;
    } else if (strcmp(a, "--out") == 0) {
      if ((outpath = cli_optarg(CMD, argc, argv, &i)) == NULL) goto done;
    } else if (strcmp(a, "--tie-eps") == 0) {
      if ((val = cli_optarg(CMD, argc, argv, &i)) == NULL ||
          cli_parse_double(CMD, a, val, 0, 1, &eps) != 0)
        goto done;
    } else if (strcmp(a, "--rule") == 0) {
      if ((val = cli_optarg(CMD, argc, argv, &i)) == NULL) goto done;
      if (nrules == CLI_MAX_RULES) {
        cli_error(CMD, "at most %d rules", CLI_MAX_RULES);
        goto done;
      }
      if (rule_parse(val, &rules[nrules], err, sizeof err) != 0) {
        cli_error(CMD, "%s", err);
        goto done;
      }
      nrules++;
    } else {
      cli_error(CMD, "unknown option '%s' (try: fliplab classify --help)", a);
      goto done;
    }
  }
  if (inpath == NULL) {
    cli_error(CMD, "--input FILE.csv is required (try: fliplab classify --help)");
    goto done;
  }
  if (nrules == 0) {
    nrules = rule_list_triangle(measure_table34, MEASURE_TABLE34_COUNT, rules,
                                CLI_MAX_RULES - 1);
    rules[nrules++] = rule_delaunay();
  }

  /* Read and check every row before writing anything. */
  in = strcmp(inpath, "-") == 0 ? stdin : fopen(inpath, "rb");
  if (in == NULL) {
    cli_error(CMD, "cannot read '%s': %s", inpath, strerror(errno));
    goto done;
  }
  size_t n = 0;
  char err[512];
  if (report_pentagon_read(in, inpath, &v, &n, NULL, err, sizeof err) != 0) {
    cli_error(CMD, "%s", err);
    goto done;
  }
  if ((out = cli_open_out(CMD, outpath)) == NULL) goto done;
  fputs("id,rule,decisions,type,sink,dt\n", out);
  cli_progress prog;
  cli_progress_start(&prog, "classify");
  for (size_t k = 0; k < n; k++) {
    flipgraph_pentagon p;
    flipgraph_prepare(&p, v + 5 * k);
    for (int r = 0; r < nrules; r++) {
      flipgraph g;
      flipgraph_classify(&p, &rules[r], eps, &g);
      cli_classify_row(out, k + 1, &rules[r], &g);
    }
    if ((k & 1023) == 0) cli_progress_update(k, n, &prog);
  }
  cli_progress_finish(&prog);
  if (cli_userdefs_failed(CMD)) {
    rc = 1;
    goto done;
  }
  rc = cli_close_out(out) != 0 ? 1 : 0;
  out = NULL;
done:
  if (in != NULL && in != stdin) fclose(in);
  cli_abort_out(out);
  free(v);
  free(rules);
  return rc;
}
