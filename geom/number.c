/*
** number.c: the one number parser of fliplab (geom.h): reals in strtod
** syntax and strict decimal counts, each read from a byte span of known
** length, so that a field with a NUL byte inside it (which a C string would
** silently cut short) is no number.  Every reader of numbers uses it: the
** coordinate contract (geom_coord_parse), the CSV readers of reports/ and
** the literals of badness formulas.
*/
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "geom.h"

/* Bytes strtod may consume: blanks before the number, then digits, signs,
** the point, exponents, hex digits, "inf", "infinity", "nan(...)".  strtod
** never reads past the first byte outside this set, so parsing a
** NUL-terminated copy of the longest such prefix gives what strtod would
** give on the span itself. */
static int geom_number_byte(unsigned char c) {
  return (c >= '0' && c <= '9') || ((c | 0x20) >= 'a' && (c | 0x20) <= 'z') || c == '.' ||
         c == '+' || c == '-' || c == '(' || c == ')' || c == '_' || c == ' ' || c == '\t' ||
         c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

geom_numerr geom_number_scan(const char *s, size_t len, double *out, size_t *used) {
  size_t n = 0;
  while (n < len && geom_number_byte((unsigned char)s[n])) n++;
  char small[128], *copy = n < sizeof small ? small : malloc(n + 1);
  if (copy == NULL) return GEOM_NUM_NO_MEMORY;
  memcpy(copy, s, n);
  copy[n] = '\0';
  char *end;
  errno = 0;
  double x = strtod(copy, &end);
  int range = errno == ERANGE;
  *used = (size_t)(end - copy);
  if (copy != small) free(copy);
  if (*used == 0) return GEOM_NUM_NOT_NUMBER;
  *out = x;
  /* ERANGE: beyond the doubles (strtod gives inf), or below the normal
  ** ones (then read as 0 or a subnormal, silently losing the value). */
  if (range || (x != 0 && isfinite(x) && fabs(x) < DBL_MIN)) return GEOM_NUM_OUT_OF_RANGE;
  if (!isfinite(x)) return GEOM_NUM_NOT_FINITE;
  return GEOM_NUM_OK;
}

geom_numerr geom_number_parse(const char *s, size_t len, double *out) {
  size_t used = 0;
  double x = 0;
  if (s == NULL || (len > 0 && (s[0] == ' ' || (s[0] >= '\t' && s[0] <= '\r'))))
    return GEOM_NUM_NOT_NUMBER;   /* strtod would skip it: no blank before a number */
  geom_numerr e = geom_number_scan(s, len, &x, &used);
  if (used != len) return GEOM_NUM_NOT_NUMBER;   /* something after it, a NUL byte */
  if (e == GEOM_NUM_OK) *out = x;
  return e;
}

int geom_count_parse(const char *s, size_t len, uint64_t *out) {
  uint64_t v = 0;
  if (s == NULL || len == 0) return -1;
  for (size_t i = 0; i < len; i++) {
    if (s[i] < '0' || s[i] > '9') return -1;
    unsigned d = (unsigned)(s[i] - '0');
    if (v > (UINT64_MAX - d) / 10) return -1;
    v = v * 10 + d;
  }
  *out = v;
  return 0;
}

const char *geom_numerr_str(geom_numerr e) {
  static const char *const msg[] = {
    [GEOM_NUM_OK] = "is a number",
    [GEOM_NUM_NOT_NUMBER] = "is not a number",
    [GEOM_NUM_NOT_FINITE] = "is not finite",
    [GEOM_NUM_OUT_OF_RANGE] = "is out of range",
    [GEOM_NUM_NO_MEMORY] = "could not be read (out of memory)",
  };
  return (unsigned)e < sizeof msg / sizeof msg[0] ? msg[e] : "is not a number";
}
