/*
** cmd_got.c: `fliplab got` (placeholder until its issue lands).
*/
#include "cli/cli.h"

int cli_cmd_got(int argc, char **argv) {
  (void)argc;
  (void)argv;
  return cli_error("got", "not built yet");
}
