/*
** main.c: the fliplab program: dispatch to a command.
*/
#include <stdio.h>
#include <string.h>
#include "cli.h"

typedef struct cli_command {
  const char *name;
  int (*run)(int argc, char **argv);
  const char *summary;
} cli_command;

static const cli_command cli_commands[] = {
  {"list",     cli_cmd_list,     "list the badness measures, joints and quadrilateral rules"},
  {"flip",     cli_cmd_flip,     "decide one convex quadrilateral with a rule"},
  {"sample",   cli_cmd_sample,   "write random convex pentagons to CSV"},
  {"table34",  cli_cmd_table34,  "regenerate the thesis's table 3.4 (flip-graph types)"},
  {"merge",    cli_cmd_merge,    "sum table34 CSV shards"},
  {"classify", cli_cmd_classify, "classify the directed flip graphs of given pentagons"},
  {"rule",     cli_cmd_rule,     "test a flip rule: types, intervals, verdicts, witnesses"},
  {"got",      cli_cmd_got,      "globally optimal triangulation of a simple polygon"},
  {"lot",      cli_cmd_lot,      "locally optimal triangulation of a point set, any rule"},
  {"flipgraph", cli_cmd_flipgraph, "every triangulation of a small site set, directed by a rule"},
  {"census",   cli_cmd_census,   "table 3.4 for any n: flip graphs of random site sets"},
  {"averages", cli_cmd_averages, "chapter 5's exact averages over all triangulations"},
  {"cpdt",     cli_cmd_cpdt,     "chapter 5: Delaunay triangulations of convex polygons, counted"},
  {"convex",   cli_cmd_convex,   "random convex n-gons (chapter 6): CSV, SVG, statistics"},
  {"linf",     cli_cmd_linf,     "section 4.2: l_inf circumcubes in R^d, exact; the examples"},
  {"paradigms", cli_cmd_paradigms, "chapter 2: every triangulation algorithm, timed and counted"},
};
#define CLI_NCOMMANDS (sizeof cli_commands / sizeof cli_commands[0])

static void cli_usage(FILE *out) {
  fprintf(out, "usage: fliplab [--define 'NAME = EXPR'] [--plugin FILE.so] COMMAND [options]\n"
               "       fliplab COMMAND --help | fliplab --version\n\ncommands:\n");
  for (size_t i = 0; i < CLI_NCOMMANDS; i++)
    fprintf(out, "  %-9s %s\n", cli_commands[i].name, cli_commands[i].summary);
  fprintf(out, "\nglobal options (before or after the command, repeatable):\n");
  cli_userdefs_help(out);
  fprintf(out, "\nRules are MEASURE_JOINT (e.g. P_1, -alpha_inf) or DT; fliplab list shows them.\n"
               "Definitions, formats and methods: docs/README.md in the source tree, installed\n"
               "as share/doc/fliplab/README.md.\n");
}

int main(int argc, char **argv) {
  if (cli_userdefs_take(&argc, argv) != 0) return 2;
  if (argc < 2) {
    cli_usage(stderr);
    return 2;
  }
  if (cli_is_help(argv[1])) {
    cli_usage(stdout);
    return cli_outputs_finish("help", 0);
  }
  if (strcmp(argv[1], "--version") == 0) {
    printf("fliplab %s\n", FLIPLAB_VERSION);
    return cli_outputs_finish("version", 0);
  }
  for (size_t i = 0; i < CLI_NCOMMANDS; i++)
    if (strcmp(argv[1], cli_commands[i].name) == 0) {
      /* Outputs reach their names only if the command succeeded, user
      ** measures included (cli/output.c). */
      int st = cli_commands[i].run(argc - 1, argv + 1);
      if (st == 0 && cli_userdefs_failed(cli_commands[i].name)) st = 1;
      return cli_outputs_finish(cli_commands[i].name, st);
    }
  const char *names[CLI_NCOMMANDS];
  for (size_t i = 0; i < CLI_NCOMMANDS; i++) names[i] = cli_commands[i].name;
  return cli_unknown_command(argv[1], names, CLI_NCOMMANDS);
}
