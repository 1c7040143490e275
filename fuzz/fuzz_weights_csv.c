/*
** fuzz_weights_csv.c: the weight-file reader of `lot --rule WDT --weights`
** (report_weights_read).  The first byte sets the point count (1 to 256),
** the rest is the file.  Whatever it accepts must be exactly that many
** weights, each within the weight contract of geom.h; a refusal always
** says why, in one line.
*/
#include "fuzz_support.h"
#include "geom.h"
#include "report.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  size_t np = 1 + (size ? data[0] : 0);
  const char *path = fuzz_path(size ? data + 1 : data, size ? size - 1 : 0);
  double *w = NULL;
  char err[512];
  if (report_weights_read(path, np, &w, err, sizeof err) == 0) {
    for (size_t k = 0; k < np; k++)
      if (geom_weight_check(w[k]) != GEOM_COORD_OK) abort();
    free(w);
  } else if (err[0] == '\0' || strchr(err, '\n') != NULL) {
    abort();
  }
  return 0;
}
