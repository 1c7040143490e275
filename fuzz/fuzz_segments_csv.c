/*
** fuzz_segments_csv.c: the segment-file reader of `lot --segments`
** (report_segments_read).  The first byte sets the point count (2 to 257),
** the rest is the file.  Whatever it accepts must be at least one segment
** of two different indices below the point count, each on a real line of
** the input, the lines increasing; a refusal always says why, in one line.
*/
#include "fuzz_support.h"
#include "geom.h"
#include "report.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  size_t np = 2 + (size ? data[0] : 0);
  const char *path = fuzz_path(size ? data + 1 : data, size ? size - 1 : 0);
  uint32_t *s = NULL;
  uint64_t *line = NULL;
  size_t n = 0;
  char err[512];
  if (report_segments_read(path, np, &s, &line, &n, err, sizeof err) == 0) {
    if (n == 0) abort();
    for (size_t k = 0; k < n; k++) {
      if (s[2 * k] >= np || s[2 * k + 1] >= np || s[2 * k] == s[2 * k + 1]) abort();
      if (line[k] < 1 || line[k] > size || (k > 0 && line[k] <= line[k - 1])) abort();
    }
    free(s);
    free(line);
  } else if (err[0] == '\0' || strchr(err, '\n') != NULL) {
    abort();
  }
  return 0;
}
