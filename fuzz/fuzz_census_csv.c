/*
** fuzz_census_csv.c: the census CSV reader that `merge` sums shards with.
** What it accepts must survive a round trip (written back as CSV and read
** again: the same rows, counts and exact sums) and merge with itself; a
** refusal always says why.
*/
#include "fuzz_support.h"
#include "report.h"

static void fuzz_census_roundtrip(const report_census_row *rows, int n) {
  char *buf = NULL;
  size_t len = 0;
  FILE *out = open_memstream(&buf, &len);
  if (out == NULL) abort();
  report_census_meta meta = {0};
  if (report_census_write(out, REPORT_CSV, &meta, rows, n) != 0) abort();
  if (fclose(out) != 0) abort();
  FILE *in = fuzz_stream((const uint8_t *)buf, len);
  report_census_row *again = NULL;
  int m = 0;
  char err[512];
  if (report_census_read(in, "roundtrip", &again, &m, err, sizeof err) != 0 || m != n) abort();
  fclose(in);
  for (int i = 0; i < n; i++)
    if (strcmp(again[i].rule, rows[i].rule) != 0 || again[i].sites != rows[i].sites
        || memcmp(&again[i].c, &rows[i].c, sizeof rows[i].c) != 0)
      abort();
  if (report_census_add(again, m, rows, n, "fuzz", err, sizeof err) != 0) abort();
  free(again);
  free(buf);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  FILE *in = fuzz_stream(data, size);
  if (in == NULL) return 0;
  report_census_row *rows = NULL;
  int n = 0;
  char err[512];
  if (report_census_read(in, "fuzz", &rows, &n, err, sizeof err) == 0) {
    fuzz_census_roundtrip(rows, n);
    free(rows);
  } else if (err[0] == '\0') {
    abort();
  }
  fclose(in);
  return 0;
}
