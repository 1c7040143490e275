/*
** cmd_merge.c: `fliplab merge` (placeholder until its issue lands).
*/
#include "cli/cli.h"

int cli_cmd_merge(int argc, char **argv) {
  (void)argc;
  (void)argv;
  return cli_error("merge", "not built yet");
}
