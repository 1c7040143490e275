/*
** fuzz_points_csv.c: the point-file reader shared by `lot`, `flipgraph` and
** `got` (report_points_read).  Whatever it accepts must honour the
** coordinate contract, and every line number it returns must be a real line
** of the input, increasing; a refusal always says why.
*/
#include "fuzz_support.h"
#include "geom.h"
#include "report.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const char *path = fuzz_path(data, size);
  geom_point *p = NULL;
  uint64_t *line = NULL;
  size_t n = 0;
  char err[512];
  if (report_points_read(path, &p, &line, &n, err, sizeof err) == 0) {
    if (n == 0) abort();
    for (size_t i = 0; i < n; i++) {
      if (geom_coord_check(p[i].x) != GEOM_COORD_OK || geom_coord_check(p[i].y) != GEOM_COORD_OK)
        abort();
      if (line[i] < 1 || (i > 0 && line[i] <= line[i - 1])) abort();
    }
    free(p);
    free(line);
  } else if (err[0] == '\0') {
    abort();
  }
  return 0;
}
