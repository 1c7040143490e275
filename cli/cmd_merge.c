/*
** cmd_merge.c: `fliplab merge`: sum table34 CSV shards (same rules in the
** same order) into one table.  The CSV output is written by the same code as
** table34's, so merging the shards 1/N .. N/N of a run reproduces the
** unsharded CSV byte for byte.
*/
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "measure.h"
#include "report.h"

#define CMD "merge"

static const char cli_merge_usage[] =
  "usage: fliplab merge A.csv B.csv ... [--out FILE] [--format csv|text|md] [--plot FILE.svg]\n"
  "Sum table34 CSV files (e.g. the shards of `fliplab table34 --shard K/N --format csv`).\n"
  "They must have the same header and the same rules in the same order.\n\n"
  "  --out FILE       write the merged table to FILE (default: stdout)\n"
  "  --format F       csv (default), text or md: the table as table34 prints it\n"
  "                   (the CSV records neither seed nor tie tolerance)\n"
  "  --columns C      text: at most C measures per block (default: all)\n"
  "  --plot FILE.svg  also draw type-I % against DT % (thesis figure 3.9)\n"
  "A file name '-' reads standard input.\n";

int cli_cmd_merge(int argc, char **argv) {
  const char *outpath = NULL, *plotpath = NULL;
  report_format fmt = REPORT_CSV;
  uint64_t columns = 0;
  const char **files = calloc((size_t)argc, sizeof *files);
  int nfiles = 0;
  if (files == NULL) return cli_error(CMD, "out of memory");
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i], *v;
    if (cli_is_help(a)) {
      fputs(cli_merge_usage, stdout);
      free(files);
      return 0;
    }
    if (strcmp(a, "--out") == 0 || strcmp(a, "--plot") == 0 || strcmp(a, "--format") == 0) {
      if ((v = cli_optarg(CMD, argc, argv, &i)) == NULL) goto usage;
      if (a[2] == 'o') outpath = v;
      else if (a[2] == 'p') plotpath = v;
      else if (report_format_parse(v, &fmt) != 0) {
        cli_error(CMD, "--format must be csv, text or md, got '%s'", v);
        goto usage;
      }
    } else if (strcmp(a, "--columns") == 0) {
      if ((v = cli_optarg(CMD, argc, argv, &i)) == NULL ||
          cli_parse_u64(CMD, a, v, 1, MEASURE_MAX, &columns) != 0)
        goto usage;
    } else if (a[0] == '-' && a[1] != '\0') {
      cli_error(CMD, "unknown option '%s' (try: fliplab merge --help)", a);
      goto usage;
    } else {
      files[nfiles++] = a;
    }
  }
  for (int a = 0; a < nfiles; a++)
    for (int b = 0; b < a; b++)
      if (strcmp(files[a], files[b]) == 0) {
        cli_error(CMD, "'%s' is given twice: its samples would count twice", files[a]);
        goto usage;
      }
  if (nfiles == 0) {
    cli_error(CMD, "no input files (try: fliplab merge --help)");
    goto usage;
  }

  report_row *acc = NULL, *add = NULL;
  int nacc = 0, nadd = 0, rc = 2;
  char err[512];
  if (report_csv_read(files[0], &acc, &nacc, err, sizeof err) != 0) {
    cli_error(CMD, "%s", err);
    goto done;
  }
  for (int k = 1; k < nfiles; k++) {
    if (report_csv_read(files[k], &add, &nadd, err, sizeof err) != 0 ||
        report_rows_add(acc, nacc, add, nadd, files[k], err, sizeof err) != 0) {
      cli_error(CMD, "%s", err);
      goto done;
    }
    free(add);
    add = NULL;
  }
  FILE *out = cli_open_out(CMD, outpath);
  if (out == NULL) goto done;
  char note[64];
  snprintf(note, sizeof note, "merged from %d CSV file%s", nfiles, nfiles > 1 ? "s" : "");
  report_meta meta = {.samples = acc[0].c.samples, .note = note, .text_columns = (int)columns};
  FILE *plot = NULL;
  if (plotpath != NULL && (plot = cli_open_out(CMD, plotpath)) == NULL) goto done;
  report_write(out, fmt, &meta, acc, nacc);
  if (plot != NULL) report_scatter_svg(plot, &meta, acc, nacc);
  rc = cli_close_out(out) != 0 || cli_close_out(plot) != 0 ? 1 : 0;
done:
  free(acc);
  free(add);
  free(files);
  return rc;
usage:
  free(files);
  return 2;
}
