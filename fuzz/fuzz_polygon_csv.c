/*
** fuzz_polygon_csv.c: the polygon CSV reader of `got` (one vertex x,y per
** row).  Whatever it accepts must pass the polygon check unchanged.
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
    size_t bad;
    int r;
    if (geom_polygon_check(p, n, &bad, &r) != GEOM_OK || r) abort();
    free(p);
  } else if (err[0] == '\0') {
    abort();   /* a refusal always says why (cli_error makes it one line) */
  }
  return 0;
}
