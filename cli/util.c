/*
** util.c: helpers shared by the commands: errors, strict number parsing,
** option values (output files: output.c).
*/
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"

/* The message is one line of bounded length whatever it echoes: control
** characters (a newline inside a quoted CSV field, a tab) become '?', and
** past CLI_ERROR_MAX bytes it is cut and ends in "...". */
#define CLI_ERROR_MAX 1000

int cli_error(const char *cmd, const char *fmt, ...) {
  char msg[CLI_ERROR_MAX + 1];
  va_list ap;
  va_start(ap, fmt);
  int n = vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  if (n < 0) msg[0] = '\0';
  if (n >= (int)sizeof msg) memcpy(msg + CLI_ERROR_MAX - 3, "...", 4);
  for (char *p = msg; *p; p++)
    if ((unsigned char)*p < 0x20 || *p == 0x7f) *p = '?';
  if (cmd != NULL) fprintf(stderr, "fliplab %s: %s\n", cmd, msg);
  else fprintf(stderr, "fliplab: %s\n", msg);
  return 2;
}

int cli_parse_u64(const char *cmd, const char *opt, const char *s,
                  uint64_t lo, uint64_t hi, uint64_t *out) {
  char *end;
  errno = 0;
  if (s == NULL || *s == '\0' || *s == '-' || *s == '+') goto bad;
  unsigned long long v = strtoull(s, &end, 10);
  if (errno == 0 && (*end == 'e' || *end == 'E' || *end == '.')) {
    /* Scientific notation for sizes (--samples 1e6): accepted when the
    ** value is an integer that a double holds exactly. */
    double d = strtod(s, &end);
    if (*end != '\0' || !(d >= 0 && d <= 0x1p53) || d != floor(d)) goto bad;
    v = (unsigned long long)d;
  } else if (errno != 0 || *end != '\0') {
    goto bad;
  }
  if (v < lo || v > hi) {
    cli_error(cmd, "%s %s is out of range [%llu, %llu]", opt, s,
              (unsigned long long)lo, (unsigned long long)hi);
    return -1;
  }
  *out = v;
  return 0;
bad:
  cli_error(cmd, "%s expects a non-negative integer, got '%s'", opt, s ? s : "");
  return -1;
}

int cli_parse_double(const char *cmd, const char *opt, const char *s,
                     double lo, double hi, double *out) {
  char *end;
  errno = 0;
  if (s == NULL || *s == '\0') goto bad;
  double v = strtod(s, &end);
  if (*end != '\0') goto bad;
  if (errno == ERANGE && fabs(v) <= 1.0) {
    cli_error(cmd, "%s %s is too small in magnitude to compute with", opt, s);
    return -1;
  }
  if (errno == ERANGE || !isfinite(v)) goto bad;
  if (v < lo || v > hi) {
    cli_error(cmd, "%s %s is out of range [%g, %g]", opt, s, lo, hi);
    return -1;
  }
  *out = v;
  return 0;
bad:
  cli_error(cmd, "%s expects a finite number, got '%s'", opt, s ? s : "");
  return -1;
}

const char *cli_optarg(const char *cmd, int argc, char **argv, int *i) {
  if (*i + 1 >= argc) {
    cli_error(cmd, "option %s needs a value", argv[*i]);
    return NULL;
  }
  *i += 1;
  return argv[*i];
}

int cli_is_help(const char *opt) {
  return strcmp(opt, "--help") == 0 || strcmp(opt, "-h") == 0 || strcmp(opt, "help") == 0;
}
