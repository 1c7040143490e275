/*
** fuzz_polygon_csv.c: the polygon CSV reader of `got` (one vertex x,y per
** row).  It accepts simple polygons (got/ handles non-convex ones), so
** whatever it accepts must pass geom_simple_polygon_check unchanged: already
** anticlockwise, nothing crossing.
*/
#include "fuzz_support.h"
#include "geom.h"
#include "report.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const char *path = fuzz_path(data, size);
  geom_point *p = NULL;
  size_t n = 0;
  int rev = 0;
  char err[512];
  if (report_got_read_polygon(path, &p, &n, &rev, err, sizeof err) == 0) {
    size_t bad, bad2;
    int r;
    if (geom_simple_polygon_check(p, n, &bad, &bad2, &r) != GEOM_OK || r) abort();
    free(p);
  } else if (err[0] == '\0') {
    abort();   /* a refusal always says why (cli_error makes it one line) */
  }
  return 0;
}
