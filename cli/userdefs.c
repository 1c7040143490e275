/*
** userdefs.c: the global options --define and --plugin.
**
** They may appear anywhere on the command line, any number of times, and
** are handled in order before the command runs: --define 'NAME = EXPR'
** (or 'NAME >= 0 : EXPR', 'NAME <= 0 : EXPR') registers a formula measure,
** --plugin FILE.so loads a plugin.  Both are removed from argv so the
** commands never see them.
**
** Bad values met while a command runs are recorded by formula.c; commands
** should check formula_check_errors after their run and fail with the
** message.  As a backstop for any command that does not, an exit handler
** turns a recorded bad value into a one-line error and exit status 1, so
** counts built on a NaN are never reported as a success.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "formula.h"
#include "cli.h"
#include "plugin_loader.h"

#define CLI_ECHO_MAX 60   /* characters of a definition repeated in its error */

static void cli_userdefs_atexit(void) {
  char msg[1024];
  if (formula_check_errors(msg, sizeof msg)) {
    fflush(NULL);
    cli_error(NULL, "%s", msg);
    _exit(1);
  }
}

int cli_userdefs_failed(const char *cmd) {
  char msg[1024];
  if (!formula_check_errors(msg, sizeof msg)) return 0;
  cli_error(cmd, "%s", msg);
  formula_clear_errors();
  return 1;
}

/* "--define VALUE" or "--define=VALUE": the option's value, or NULL when
** argv[*i] is not this option.  *missing is set when the value is absent. */
static const char *cli_userdefs_value(const char *opt, int argc, char **argv, int *i,
                                      int *missing) {
  size_t n = strlen(opt);
  if (strncmp(argv[*i], opt, n) != 0) return NULL;
  if (argv[*i][n] == '=') return argv[*i] + n + 1;
  if (argv[*i][n] != '\0') return NULL;
  if (*i + 1 >= argc) {
    *missing = 1;
    return NULL;
  }
  return argv[++*i];
}

int cli_userdefs_take(int *argc, char **argv) {
  static int hooked;
  int out = 1;
  char err[1024];
  for (int i = 1; i < *argc; i++) {
    int missing = 0;
    const char *def = cli_userdefs_value("--define", *argc, argv, &i, &missing);
    const char *plug = def || missing ? NULL : cli_userdefs_value("--plugin", *argc, argv, &i, &missing);
    if (missing) {
      fprintf(stderr, "fliplab: option %s needs a value\n", argv[i]);
      return 2;
    }
    if (def != NULL) {
      if (formula_define(def, err, sizeof err) < 0) {
        /* Echo at most CLI_ECHO_MAX characters of the definition. */
        cli_error(NULL, "--define '%.*s%s': %s", CLI_ECHO_MAX, def,
                  strlen(def) > CLI_ECHO_MAX ? "..." : "", err);
        return 2;
      }
    } else if (plug != NULL) {
      if (plugin_load(plug, err, sizeof err) != 0) {
        cli_error(NULL, "--plugin: %s", err);
        return 2;
      }
    } else {
      argv[out++] = argv[i];
      continue;
    }
    if (!hooked) {
      atexit(cli_userdefs_atexit);
      hooked = 1;
    }
  }
  argv[out] = NULL;
  *argc = out;
  return 0;
}
