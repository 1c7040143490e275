/*
** cli.h: the fliplab program's commands and their shared helpers.
**
** Each command lives in cli/cmd_NAME.c as cli_cmd_NAME(argc, argv), where
** argv[0] is the command's name.  A command returns the process exit status;
** errors are one line on stderr ("fliplab NAME: ..."), exit status 2 for
** bad usage or input and 1 for a failure while running.
*/
#ifndef FLIPLAB_CLI_H
#define FLIPLAB_CLI_H

#include <stdint.h>
#include <stdio.h>
#include "fliplab_config.h"

int cli_cmd_list(int argc, char **argv);
int cli_cmd_flip(int argc, char **argv);
int cli_cmd_sample(int argc, char **argv);
int cli_cmd_table34(int argc, char **argv);
int cli_cmd_merge(int argc, char **argv);
int cli_cmd_classify(int argc, char **argv);
int cli_cmd_got(int argc, char **argv);
int cli_cmd_rule(int argc, char **argv);
int cli_cmd_lot(int argc, char **argv);
int cli_cmd_flipgraph(int argc, char **argv);
int cli_cmd_census(int argc, char **argv);

/* Print "fliplab CMD: message" ("fliplab: message" when cmd is NULL) on
** stderr, as one line of at most about 1000 bytes (control characters
** shown as '?'); returns 2 (usage/input error). */
int cli_error(const char *cmd, const char *fmt, ...) FLIPLAB_PRINTF(2, 3);

/* Strict number parsing of option values: the whole string, finite, in
** range, read by geom/'s one number parser (geom_count_parse; sizes may be
** written 1e6; geom_number_scan for reals).  On failure they print the
** one-line error naming the option and return -1. */
int cli_parse_u64(const char *cmd, const char *opt, const char *s,
                  uint64_t lo, uint64_t hi, uint64_t *out);
int cli_parse_double(const char *cmd, const char *opt, const char *s,
                     double lo, double hi, double *out);

/* The value of an option "--name VALUE" at argv[*i]; advances *i.
** NULL (after printing the error) when the value is missing. */
const char *cli_optarg(const char *cmd, int argc, char **argv, int *i);

/* Is opt one of the help spellings? */
int cli_is_help(const char *opt);

/* ---- help and "did you mean" (cli/hint.c) ---- */

/* One option of a command: its help line lists it with its default. */
typedef struct cli_option {
  const char *name;   /* "--samples" */
  const char *arg;    /* "N", or NULL for a flag */
  const char *dflt;   /* the default as help shows it, or NULL (flags, required) */
  const char *help;   /* one short line */
} cli_option;
#define CLI_NOPTS(table) (sizeof(table) / sizeof((table)[0]))

/* "usage", a blank line, "about" (ends with '\n'), then every option. */
void cli_help(FILE *f, const char *usage, const char *about, const cli_option *o, size_t n);
const cli_option *cli_option_find(const char *name, const cli_option *o, size_t n);
/* "unknown option '--sed': did you mean '--seed'?"; returns 2. */
int cli_unknown_option(const char *cmd, const char *opt, const cli_option *o, size_t n);
int cli_unknown_command(const char *name, const char *const *names, size_t n);

/* Edit distance (with swaps), and the closest of names[] to s, or NULL when
** none is close (see cli/hint.c; "alpha" finds "-alpha"). */
size_t cli_edit_distance(const char *a, const char *b);
const char *cli_closest(const char *s, const char *const *names, size_t n);
const char *cli_closest_measure(const char *s);

/* rule_parse with a useful error: "did you mean", or how to define an
** unknown measure.  0, or 2 after printing the one-line error. */
struct rule;
int cli_parse_rule(const char *cmd, const char *name, struct rule *out);
/* A comma-separated list of rules ("R_1,P_1,DT") appended to out[*n..cap-1]. */
int cli_parse_rule_list(const char *cmd, const char *list, struct rule *out, int *n, int cap);

/* Output names: 2 (after the error) when path's extension names another
** known format than want ("svg", "csv"): `--plot fig.png` is refused rather
** than filled with SVG.  No extension, an unknown one, or "-" is accepted. */
int cli_check_out_ext(const char *cmd, const char *opt, const char *path, const char *want);
/* The table format a file name asks for: "csv", "md", "text" (.txt), or NULL. */
const char *cli_format_of_path(const char *path);
/* Table columns of `per` characters that fit beside `fixed` ones on the
** terminal; 0 (no limit) when stdout is not a terminal. */
uint64_t cli_terminal_columns(int fixed, int per);

/* Global options usable before or after any command: --define 'NAME = EXPR'
** and --plugin FILE.so.  cli_userdefs_take removes them from argv (updating
** *argc) after registering what they define; returns 0, or 2 after an error. */
int cli_userdefs_take(int *argc, char **argv);
/* After a run: if a user measure produced a bad value (NaN, infinite, wrong
** sign), print it as cmd's one-line error and return 1; else 0. */
int cli_userdefs_failed(const char *cmd);

/* A progress bar on stderr for long runs.  It appears only when stderr is
** a terminal and the run has lasted about a second, so quick runs, pipes,
** logs and tests never see it (cli/progress.c). */
typedef struct cli_progress {
  int enabled;          /* stderr is a terminal */
  int shown;            /* the bar has been drawn (needs erasing) */
  double t0;            /* start, seconds */
  double last;          /* last redraw, seconds */
  const char *label;
} cli_progress;

void cli_progress_start(cli_progress *p, const char *label);
/* A census_progress_fn: ctx is the cli_progress. */
void cli_progress_update(uint64_t done, uint64_t total, void *ctx);
void cli_progress_finish(cli_progress *p);

/* `fliplab rule` beyond pentagons (cli/rule_sites.c): the census of each
** site set of spec ("disc:5,convex:6", or "none") under r, a verdict line
** each and the first witness with two or more LOTs (its CSV and SVG into
** svg_dir when not NULL).  cli_rule_sites_check validates spec (0 or 2). */
struct rule;
int cli_rule_sites_check(const char *spec);
int cli_rule_sites(const struct rule *r, const char *spec, uint64_t samples, uint64_t seed,
                   double tie_eps, int threads, const char *svg_dir);

/* --measures: "table34" (the thesis's twenty, its order), "all" (those,
** then the other registered measures) or NAME,NAME,...: registry ids into
** ids[MEASURE_MAX]; the count, or -1 after a one-line error. */
int cli_measure_list(const char *cmd, const char *s, int *ids);
/* --shard K/N: 1 <= K <= N <= 10^6; 0, or -1 after a one-line error. */
int cli_parse_shard(const char *cmd, const char *s, uint64_t *k, uint64_t *n);

/* Output files (cli/output.c).  cli_open_out(cmd, FILE) returns a stream
** for FILE ("-" or NULL: stdout) that really writes a temporary file in
** FILE's directory; FILE itself is replaced (renamed over) only when the
** whole command succeeds, by cli_outputs_finish, which main() calls with
** the command's exit status.  So a failing run leaves every old file
** byte-identical and no partial file behind.  Devices (/dev/full, FIFOs)
** are written directly.  NULL after printing the one-line error (cannot
** create, or FILE already named by another output of this run).
** cli_close_out flushes and closes (stdout: flushes), checking every write;
** on failure it prints "fliplab CMD: cannot write 'FILE': REASON" once and
** returns -1 (the caller just returns 1).  cli_abort_out discards an output:
** its old file stays.  cli_outputs_finish returns the final status: 1 when
** status was 0 but some output or stdout could not be written/renamed. */
FILE *cli_open_out(const char *cmd, const char *path);
int cli_close_out(FILE *f);
/* cli_close_out for a stream a writer returning wrc (0 or -1) just filled:
** 1 after the one-line error (the stream's, or "out of memory" when the
** writer failed with the stream intact), else 0.  NULL f: 0. */
int cli_finish_out(const char *cmd, FILE *f, int wrc);
void cli_abort_out(FILE *f);
int cli_outputs_finish(const char *cmd, int status);

#endif
