/*
** fuzz_coord.c: the coordinate contract's reader (geom_coord_parse), used by
** every coordinate reader.  An accepted value is a coordinate of the
** contract and reads back bit for bit from its %.17g form; a refused one
** leaves the output untouched.
*/
#include <math.h>
#include "fuzz_support.h"
#include "geom.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  char *s = fuzz_string(data, size > 256 ? 256 : size);
  double x = 12345.0;
  geom_coorderr e = geom_coord_parse(s, &x);
  if (e == GEOM_COORD_OK) {
    if (geom_coord_check(x) != GEOM_COORD_OK) abort();
    char buf[64];
    double y = 0;
    snprintf(buf, sizeof buf, "%.17g", x);
    if (geom_coord_parse(buf, &y) != GEOM_COORD_OK || y != x) abort();
  } else if (x != 12345.0 || geom_coorderr_str(e)[0] == '\0') {
    abort();
  }
  free(s);
  return 0;
}
