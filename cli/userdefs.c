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

/* --define VALUE: register the formula measure; 0, or 2 after the error. */
static int cli_userdefs_define(const char *cmd, const cli_option *o, const char *v, void *dst) {
  char err[1024];
  (void)o, (void)dst;
  if (v == NULL || formula_define(v, err, sizeof err) >= 0) return 0;
  /* Echo at most CLI_ECHO_MAX characters of the definition. */
  return cli_error(cmd, "--define '%.*s%s': %s", CLI_ECHO_MAX, v,
                   strlen(v) > CLI_ECHO_MAX ? "..." : "", err);
}

static int cli_userdefs_plugin(const char *cmd, const cli_option *o, const char *v, void *dst) {
  char err[1024];
  (void)o, (void)dst;
  if (v == NULL || plugin_load(v, err, sizeof err) == 0) return 0;
  return cli_error(cmd, "--plugin: %s", err);
}

/* The global options: rows of the kind every command's table has, here
** repeatable and read before the command (cli_userdefs_take). */
static const cli_option cli_userdefs_opts[] = {
  {.name = "--define", .arg = "'NAME = EXPR'", .kind = CLI_CALL, .call = cli_userdefs_define,
   .help = "a badness measure from a formula (muParser syntax);\n"
           "                          'NAME <= 0 : EXPR' or 'NAME >= 0 : EXPR' declares its sign.\n"
           "                          Variables, per triangle: a b c (sides, a >= b >= c),\n"
           "                          alpha beta gamma (angles in radians, ascending; alpha\n"
           "                          opposite c), A (area), P (perimeter), R (circumradius),\n"
           "                          r (inradius), h (shortest altitude), rx ry (coordinate\n"
           "                          ranges), x1 y1 x2 y2 x3 y3 (vertices, lexicographic),\n"
           "                          and the constant pi.  Small is good."},
  {.name = "--plugin", .arg = "FILE.so", .kind = CLI_CALL, .call = cli_userdefs_plugin,
   .help = "load measures and quadrilateral rules from a plugin"},
};
#define CLI_USERDEFS_NOPTS (sizeof cli_userdefs_opts / sizeof cli_userdefs_opts[0])

void cli_userdefs_help(FILE *f) {
  for (size_t k = 0; k < CLI_USERDEFS_NOPTS; k++) {
    char head[48];
    snprintf(head, sizeof head, "%s %s", cli_userdefs_opts[k].name, cli_userdefs_opts[k].arg);
    fprintf(f, "  %-22s  %s\n", head, cli_userdefs_opts[k].help);
  }
}

/* The global option at argv[*i] ("--define VALUE" or "--define=VALUE"),
** its value into *v (NULL when missing); NULL when argv[*i] is none. */
static const cli_option *cli_userdefs_match(int argc, char **argv, int *i, const char **v) {
  for (size_t k = 0; k < CLI_USERDEFS_NOPTS; k++) {
    const char *name = cli_userdefs_opts[k].name;
    size_t n = strlen(name);
    if (strncmp(argv[*i], name, n) != 0 || (argv[*i][n] != '=' && argv[*i][n] != '\0'))
      continue;
    *v = argv[*i][n] == '=' ? argv[*i] + n + 1 : *i + 1 < argc ? argv[++*i] : NULL;
    return &cli_userdefs_opts[k];
  }
  return NULL;
}

int cli_userdefs_take(int *argc, char **argv) {
  static int hooked;
  int out = 1;
  for (int i = 1; i < *argc; i++) {
    const char *v;
    const cli_option *o = cli_userdefs_match(*argc, argv, &i, &v);
    if (o == NULL) {
      argv[out++] = argv[i];
      continue;
    }
    if (v == NULL) return cli_error(NULL, "option %s needs a value", argv[i]);
    if (o->call(NULL, o, v, NULL) != 0) return 2;
    if (!hooked) {
      atexit(cli_userdefs_atexit);
      hooked = 1;
    }
  }
  argv[out] = NULL;
  *argc = out;
  return 0;
}
