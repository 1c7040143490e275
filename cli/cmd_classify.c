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
#include <sys/stat.h>
#include "measure.h"
#include "flipgraph.h"
#include "cli.h"
#include "rule.h"
#include "joint.h"
#include "report.h"

#define CMD "classify"
#define CLI_MAX_RULES 1024

typedef struct cli_classify_opts {
  const char *in, *out;
  double eps;
  cli_rules rules;
} cli_classify_opts;

#define T cli_classify_opts
static const cli_option cli_classify_opts_help[] = {
  CLI_OPT_STRING("--input", "FILE.csv", "required", "pentagons, one per row ('-': standard input)",
                 T, in),
  {.name = "--rule", .arg = "R", .dflt = "the 120 rules of table 3.4, then DT",
   .help = "rules, repeatable or a comma list: R_inf,-alpha_inf,DT", .kind = CLI_CALL,
   .off = CLI_AT(T, rules, cli_rules), .call = cli_option_rules},
  CLI_OPT_TIE_EPS("relative tie tolerance of the rules", 1, T, eps),
  CLI_OPT_OUT("FILE.csv", "stdout", "csv", "output file", T, out),
};
#undef T

/* The pentagons come with --input, not as arguments. */
static int cli_classify_positional(const char *cmd, const char *arg, void *dst) {
  (void)dst;
  if (strncmp(arg, "--", 2) == 0)
    return cli_unknown_option(cmd, arg, cli_classify_opts_help, CLI_NOPTS(cli_classify_opts_help));
  return cli_error(cmd, "unexpected argument '%s': the pentagons are read with --input %s", arg,
                   arg);
}

static const cli_spec cli_classify_spec = {
  CMD, "usage: fliplab classify --input FILE.csv [options]",
  "Classify the directed flip graph of every pentagon of FILE.csv under every rule.\n"
  "Input: rows x1,y1,...,x5,y5 (the header line x1,y1,...,y5 is optional), either\n"
  "orientation: a clockwise row p1..p5 is renumbered v0..v4 = p1,p5,p4,p3,p2.\n"
  "Output: id,rule,decisions,type,sink,dt per pentagon and rule, where id is the\n"
  "pentagon's row (1-based, header excluded); decisions = five letters for Q_0..Q_4\n"
  "(A = diagonal v_{j+1}v_{j+3}, B = v_{j+2}v_{j+4}, E = either); type I..V;\n"
  "sink = i for the fan T_i (two, space-separated, for type III; empty for IV, V);\n"
  "dt = 1 if type I with the Delaunay triangulation as sink (docs/formats.md).\n",
  cli_classify_opts_help, CLI_NOPTS(cli_classify_opts_help), cli_classify_positional};

static void cli_classify_row(FILE *out, size_t id, const rule *r, const flipgraph *g) {
  static const char letter[3] = {'A', 'B', 'E'};   /* RULE_AC, RULE_BD, RULE_EITHER */
  char dec[6];
  for (int j = 0; j < 5; j++) dec[j] = letter[g->dec[j]];
  dec[5] = '\0';
  char num[24], sink[24] = "";
  snprintf(num, sizeof num, "%zu", id);
  if (g->nsinks >= 1) snprintf(sink, sizeof sink, "%d", g->sink[0]);
  if (g->nsinks >= 2) snprintf(sink, sizeof sink, "%d %d", g->sink[0], g->sink[1]);
  const char *field[6] = {num, r->name, dec, flipgraph_type_name(g->type), sink,
                          g->delaunay ? "1" : "0"};
  report_csv_row(out, field, 6);
}

/* 0, 1 after --help, or 2 after a usage error (printed). */
static int cli_classify_parse(int argc, char **argv, cli_classify_opts *o) {
  int st = cli_options_parse(&cli_classify_spec, argc, argv, o, NULL);
  if (st != 0) return st;
  if (o->in == NULL)
    return cli_error(CMD, "--input FILE.csv is required (try: fliplab classify --help)");
  if (o->rules.n == 0) {
    o->rules.n = rule_list_triangle(measure_table34, MEASURE_TABLE34_COUNT, o->rules.r,
                                    CLI_MAX_RULES - 1);
    o->rules.r[o->rules.n++] = rule_delaunay();
  }
  return 0;
}

/* The streaming step: each pentagon, as it is read, classified under every
** rule and written; memory does not grow with the rows.  A failed write
** stops the run at once (the output will be discarded anyway). */
typedef struct cli_classify_run {
  const cli_classify_opts *o;
  FILE *in, *out;
  uint64_t size;           /* input bytes, for the progress bar (0: unknown) */
  cli_progress prog;
} cli_classify_run;

static int cli_classify_one(const geom_point v[5], uint64_t id, uint64_t line, int rev,
                            void *ctx) {
  cli_classify_run *run = ctx;
  const cli_classify_opts *o = run->o;
  (void)line;
  (void)rev;
  flipgraph_pentagon p;
  flipgraph_prepare(&p, v);
  for (int r = 0; r < o->rules.n; r++) {
    flipgraph g;
    flipgraph_classify(&p, &o->rules.r[r], o->eps, &g);
    cli_classify_row(run->out, (size_t)id, &o->rules.r[r], &g);
  }
  if ((id & 1023) == 0) {
    if (ferror(run->out)) return 1;
    long pos = run->size > 0 ? ftell(run->in) : -1;
    if (pos >= 0) cli_progress_update((uint64_t)pos, run->size, &run->prog);
  }
  return 0;
}

/* The held rows to standard output, once the run has succeeded; 1 when
** they could not be kept.  A failed write to standard output stops the
** copy and is reported by cli_close_out, as for any command. */
static int cli_classify_release(FILE *held, FILE *out) {
  char buf[1 << 14];
  size_t n;
  int bad = fflush(held) != 0 || ferror(held);
  rewind(held);
  while (!bad && (n = fread(buf, 1, sizeof buf, held)) > 0)
    if (fwrite(buf, 1, n, out) != n) break;
  bad |= ferror(held) != 0;
  fclose(held);
  if (bad) cli_error(CMD, "cannot keep the rows in a temporary file: %s", strerror(errno));
  return bad;
}

/* A failing run prints no row: a bad input row, a bad value of a user
** measure or a plugin rule's bad answer may come after many good rows.  A
** file output is discarded on failure (output.c); rows meant for standard
** output, which cannot be taken back, are held in a temporary file and
** released only when the whole input has been classified. */
static int cli_classify_stream(const cli_classify_opts *o, FILE *in, FILE *out) {
  FILE *w = out == stdout ? tmpfile() : out;
  if (w == NULL) return cli_error(CMD, "cannot make a temporary file: %s", strerror(errno));
  cli_classify_run run = {.o = o, .in = in, .out = w};
  struct stat st;
  char err[512];
  if (in != stdin && fstat(fileno(in), &st) == 0 && S_ISREG(st.st_mode))
    run.size = (uint64_t)st.st_size;
  static const char *const head[6] = {"id", "rule", "decisions", "type", "sink", "dt"};
  report_csv_row(w, head, 6);
  cli_progress_start(&run.prog, "classify");
  int rc = report_pentagon_each(in, o->in, cli_classify_one, &run, err, sizeof err);
  cli_progress_finish(&run.prog);
  /* Bad input (exit 2) or a bad value (1); else rc > 0: a write failed,
  ** which closing the output (or the held rows' check) reports. */
  int failed = rc < 0 ? cli_error(CMD, "%s", err) : cli_userdefs_failed(CMD);
  if (w != out) {
    if (failed) fclose(w);
    return failed ? failed : cli_classify_release(w, out) || cli_close_out(out) != 0;
  }
  return failed ? failed : cli_close_out(out) != 0 || rc > 0;
}

int cli_cmd_classify(int argc, char **argv) {
  cli_classify_opts o = {.rules = {malloc(CLI_MAX_RULES * sizeof(rule)), 0, CLI_MAX_RULES}};
  if (o.rules.r == NULL) return cli_error(CMD, "out of memory");
  int rc = cli_classify_parse(argc, argv, &o);
  FILE *in = NULL, *out = NULL;
  if (rc != 0) {
    free(o.rules.r);
    return rc == 1 ? 0 : rc;
  }
  in = strcmp(o.in, "-") == 0 ? stdin : fopen(o.in, "rb");
  if (in == NULL)
    rc = cli_error(CMD, "cannot read '%s': %s", o.in, strerror(errno));
  else if ((out = cli_open_out(CMD, o.out)) == NULL)
    rc = 2;
  else
    rc = cli_classify_stream(&o, in, out);
  /* On failure the output is discarded by cli_outputs_finish (main). */
  if (in != NULL && in != stdin) fclose(in);
  free(o.rules.r);
  return rc;
}
