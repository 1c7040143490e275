/*
** cmd_rule.c: `fliplab rule` (placeholder until its issue lands).
*/
#include "cli/cli.h"

int cli_cmd_rule(int argc, char **argv) {
  (void)argc;
  (void)argv;
  return cli_error("rule", "not built yet");
}
