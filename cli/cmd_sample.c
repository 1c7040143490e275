/*
** cmd_sample.c: `fliplab sample` (placeholder until its issue lands).
*/
#include "cli/cli.h"

int cli_cmd_sample(int argc, char **argv) {
  (void)argc;
  (void)argv;
  return cli_error("sample", "not built yet");
}
