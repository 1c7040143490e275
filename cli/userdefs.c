/*
** userdefs.c: the global options --define and --plugin (placeholder until
** user-defined measures land: it refuses them).
*/
#include <string.h>
#include "cli/cli.h"

int cli_userdefs_take(int *argc, char **argv) {
  for (int i = 1; i < *argc; i++)
    if (strcmp(argv[i], "--define") == 0 || strcmp(argv[i], "--plugin") == 0)
      return cli_error("main", "%s is not supported yet", argv[i]);
  return 0;
}
