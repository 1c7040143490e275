/*
** util.c: helpers shared by the commands: errors, strict number parsing
** of option values through geom/'s one number parser (output files:
** output.c).
*/
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "geom.h"

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

/* Digits only (geom_count_parse); or, for sizes written in scientific
** notation (--samples 1e6, digits then 'e', 'E' or '.'), a real
** (geom_number_parse) that is an integer a double holds exactly. */
int cli_parse_u64(const char *cmd, const char *opt, const char *s,
                  uint64_t lo, uint64_t hi, uint64_t *out) {
  size_t len = s != NULL ? strlen(s) : 0;
  uint64_t v;
  double d;
  if (len == 0 || *s == '-' || *s == '+') goto bad;
  if (geom_count_parse(s, len, &v) != 0) {
    char next = s[strspn(s, "0123456789")];
    if (next == '\0' || strchr("eE.", next) == NULL ||
        geom_number_parse(s, len, &d) != GEOM_NUM_OK || !(d >= 0 && d <= 0x1p53) ||
        d != floor(d))
      goto bad;
    v = (uint64_t)d;
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

/* geom_number_scan tells an underflow (a value read as 0 or a subnormal:
** "too small to compute with") from an overflow (not finite). */
int cli_parse_double(const char *cmd, const char *opt, const char *s,
                     double lo, double hi, double *out) {
  size_t len = s != NULL ? strlen(s) : 0, used = 0;
  double v = 0;
  geom_numerr e = len > 0 ? geom_number_scan(s, len, &v, &used) : GEOM_NUM_NOT_NUMBER;
  if (used != len || e == GEOM_NUM_NOT_NUMBER || e == GEOM_NUM_NO_MEMORY) goto bad;
  if (e == GEOM_NUM_OUT_OF_RANGE && fabs(v) <= 1.0) {
    cli_error(cmd, "%s %s is too small in magnitude to compute with", opt, s);
    return -1;
  }
  if (e != GEOM_NUM_OK) goto bad;
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
