/*
** cmd_classify.c: `fliplab classify` (placeholder until its issue lands).
*/
#include "cli/cli.h"

int cli_cmd_classify(int argc, char **argv) {
  (void)argc;
  (void)argv;
  return cli_error("classify", "not built yet");
}
