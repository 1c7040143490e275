/*
** fuzz_number.c: the one number parser (geom_number_parse, geom_number_scan,
** geom_count_parse) on raw byte spans, NUL bytes included.  An accepted real
** is finite and normal (or 0) and reads back bit for bit from its %.17g
** form; a span with a NUL byte inside is never a number; a scan's prefix is
** never longer than the span; an accepted count prints back as the span.
*/
#include <math.h>
#include <inttypes.h>
#include "fuzz_support.h"
#include "geom.h"

static void fuzz_number_real(const char *s, size_t len) {
  double x = 12345.0;
  geom_numerr e = geom_number_parse(s, len, &x);
  if (e != GEOM_NUM_OK) {
    if (geom_numerr_str(e)[0] == '\0') abort();
    return;
  }
  if (!isfinite(x) || (x != 0 && fabs(x) < 0x1p-1022)) abort();
  if (memchr(s, '\0', len) != NULL) abort();
  char buf[64];
  double y = 0;
  int n = snprintf(buf, sizeof buf, "%.17g", x);
  if (geom_number_parse(buf, (size_t)n, &y) != GEOM_NUM_OK || y != x) abort();
}

static void fuzz_number_scan(const char *s, size_t len) {
  double x = 0;
  size_t used = 99999;
  geom_numerr e = geom_number_scan(s, len, &x, &used);
  if (used > len) abort();
  if (e == GEOM_NUM_NOT_NUMBER && used != 0) abort();
}

static void fuzz_number_count(const char *s, size_t len) {
  uint64_t v = 0;
  if (geom_count_parse(s, len, &v) != 0) return;
  char buf[32];
  int n = snprintf(buf, sizeof buf, "%" PRIu64, v);
  /* Digits only: the span is the number, possibly with leading zeros. */
  size_t z = 0;
  while (z + 1 < len && s[z] == '0') z++;
  if ((size_t)n != len - z || memcmp(buf, s + z, (size_t)n) != 0) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  size_t len = size > 512 ? 512 : size;
  char *s = malloc(len ? len : 1);
  if (s == NULL) abort();
  if (len) memcpy(s, data, len);   /* not NUL-terminated: the verbs take a length */
  fuzz_number_real(s, len);
  fuzz_number_scan(s, len);
  fuzz_number_count(s, len);
  free(s);
  return 0;
}
