/*
** fuzz_pentagon_csv.c: the pentagon CSV reader (`sample` writes it,
** `classify` reads it).  Whatever it accepts must be strictly convex and
** anticlockwise, within the supported scale.
*/
#include <math.h>
#include "fuzz_support.h"
#include "geom.h"
#include "report.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  FILE *in = fuzz_stream(data, size);
  if (in == NULL) return 0;
  geom_point *v = NULL;
  size_t n = 0, rev = 0;
  char err[512];
  if (report_pentagon_read(in, "fuzz", &v, &n, &rev, err, sizeof err) == 0) {
    for (size_t i = 0; i < n; i++) {
      geom_point p[5];
      memcpy(p, v + 5 * i, sizeof p);
      size_t bad;
      int r;
      if (geom_polygon_check(p, 5, &bad, &r) != GEOM_OK || r) abort();
    }
    free(v);
  } else if (err[0] == '\0') {
    abort();   /* a refusal always says why (cli_error makes it one line) */
  }
  fclose(in);
  return 0;
}
