/*
** cmd_table34.c: `fliplab table34` (placeholder until its issue lands).
*/
#include "cli/cli.h"

int cli_cmd_table34(int argc, char **argv) {
  (void)argc;
  (void)argv;
  return cli_error("table34", "not built yet");
}
