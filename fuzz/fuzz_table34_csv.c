/*
** fuzz_table34_csv.c: the table34 CSV reader that `merge` sums shards with,
** and the summing itself (a file merged with itself).
*/
#include "fuzz_support.h"
#include "report.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const char *path = fuzz_path(data, size);
  report_row *rows = NULL;
  int n = 0;
  char err[512];
  if (report_csv_read(path, &rows, &n, err, sizeof err) == 0) {
    report_row *again = NULL;
    int m = 0;
    if (report_csv_read(path, &again, &m, err, sizeof err) != 0 || m != n) abort();
    (void)report_rows_add(rows, n, again, m, "fuzz", err, sizeof err);
    free(again);
    free(rows);
  } else if (err[0] == '\0') {
    abort();   /* a refusal always says why (cli_error makes it one line) */
  }
  return 0;
}
