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

#include <stddef.h>
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
int cli_cmd_averages(int argc, char **argv);
int cli_cmd_cpdt(int argc, char **argv);
int cli_cmd_convex(int argc, char **argv);
int cli_cmd_linf(int argc, char **argv);
int cli_cmd_paradigms(int argc, char **argv);

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

/* Is opt one of the help spellings (--help, -h, help)? */
int cli_is_help(const char *opt);

/* ---- option tables (cli/options.c) ------------------------------------------
**
** Each command describes its options in one table of rows: name, argument,
** help line, kind, bounds, default and destination (an offset into the
** command's options struct).  One parser (cli_options_parse) reads every
** command's arguments from its table, cli_help prints the table, and the
** "did you mean" of a mistyped option (cli/hint.c) searches its names. */
typedef enum cli_kind {
  CLI_FLAG,     /* no value: stores .set into an int (default .idef) */
  CLI_U64,      /* uint64_t in [lo, hi] (default .def); .bad: own out-of-range message */
  CLI_DOUBLE,   /* double in [dlo, dhi] (default .ddef) */
  CLI_STRING,   /* const char * (default .sdef); .ext: the output extension it must
                ** have ("csv", "svg"), .check: a validator printing its own error */
  CLI_CHOICE,   /* int: the index of the value in .names (NULL-terminated), or what
                ** .find says (-1: unknown); default .idef; .bad: the error, '%s' = value */
  CLI_CALL      /* .call reads the value (and writes the default when it is NULL) */
} cli_kind;

typedef struct cli_option cli_option;
/* A setter: v is the value (a flag's own name for a flag), or NULL to store
** the row's default; dst is the row's destination.  0, or 2 after the
** one-line error. */
typedef int (*cli_option_fn)(const char *cmd, const cli_option *o, const char *v, void *dst);

struct cli_option {
  const char *name;   /* "--samples" */
  const char *arg;    /* "N", or NULL for a flag */
  const char *dflt;   /* help's default when it is no value of the row ("all cores",
                      ** "required", "none"), else NULL: printed from the default */
  const char *help;   /* one short line; continuation lines indented by 21 */
  cli_kind kind;
  size_t off;         /* the destination: offset in the command's options struct */
  uint64_t lo, hi, def;
  double dlo, dhi, ddef;
  const char *sdef;
  int idef, set;
  const char *ext;
  int (*check)(const char *v);
  const char *const *names;
  int (*find)(const char *v);
  const char *bad;
  cli_option_fn call;
};
#define CLI_NOPTS(table) (sizeof(table) / sizeof((table)[0]))

/* offsetof(T, F), refused by the compiler unless field F has type `type`. */
#define CLI_AT(T, F, type) (offsetof(T, F) + 0 * sizeof(&((T *)0)->F == (type *)0))

#define CLI_OPT_FLAG(N, H, T, F) \
  {.name = N, .help = H, .kind = CLI_FLAG, .off = CLI_AT(T, F, int), .set = 1}
#define CLI_OPT_U64(N, A, H, T, F, LO, HI, DEF) \
  {.name = N, .arg = A, .help = H, .kind = CLI_U64, .off = CLI_AT(T, F, uint64_t), .lo = LO, \
   .hi = HI, .def = DEF}
#define CLI_OPT_STRING(N, A, D, H, T, F) \
  {.name = N, .arg = A, .dflt = D, .help = H, .kind = CLI_STRING, .off = CLI_AT(T, F, const char *)}
/* A file to write, with the extension it must have (NULL: any). */
#define CLI_OPT_FILE(N, A, D, EXT, H, T, F) \
  {.name = N, .arg = A, .dflt = D, .help = H, .kind = CLI_STRING, \
   .off = CLI_AT(T, F, const char *), .ext = EXT}

/* The rows every command shares. */
#define CLI_MAX_THREADS GEOM_MAX_THREADS
#define CLI_OPT_SEED(H, T, F) CLI_OPT_U64("--seed", "S", H, T, F, 0, UINT64_MAX, 1)
#define CLI_OPT_THREADS(H, T, F) \
  {.name = "--threads", .arg = "T", .dflt = "all cores", .help = H, .kind = CLI_U64, \
   .off = CLI_AT(T, F, uint64_t), .lo = 1, .hi = CLI_MAX_THREADS}
/* The rules' relative tie tolerance in [0, HI], RULE_DEFAULT_TIE_EPS unless given. */
#define CLI_OPT_TIE_EPS(H, HI, T, F) \
  {.name = "--tie-eps", .arg = "E", .help = H, .kind = CLI_DOUBLE, .off = CLI_AT(T, F, double), \
   .dlo = 0, .dhi = HI, .ddef = RULE_DEFAULT_TIE_EPS}
#define CLI_OPT_OUT(A, D, EXT, H, T, F) CLI_OPT_FILE("--out", A, D, EXT, H, T, F)
/* --shard K/N (cli_parse_shard) into a cli_shard, {0, 0} when not given. */
typedef struct cli_shard { uint64_t k, n; } cli_shard;
#define CLI_OPT_SHARD(H, T, F) \
  {.name = "--shard", .arg = "K/N", .dflt = "none", .help = H, .kind = CLI_CALL, \
   .off = CLI_AT(T, F, cli_shard), .call = cli_option_shard}
int cli_option_shard(const char *cmd, const cli_option *o, const char *v, void *dst);
/* --memory SIZE into a uint64_t of bytes: an integer with an optional
** binary unit K, M, G or T (KiB ...; "1G" = 2^30), at least 1 and at most
** CLI_MEMORY_MAX; the default is DEF bytes, shown as DFLT. */
#define CLI_MEMORY_MAX ((uint64_t)1 << 40)
#define CLI_OPT_MEMORY(DFLT, DEF, H, T, F) \
  {.name = "--memory", .arg = "SIZE", .dflt = DFLT, .help = H, .kind = CLI_CALL, \
   .off = CLI_AT(T, F, uint64_t), .def = DEF, .call = cli_option_memory}
int cli_option_memory(const char *cmd, const cli_option *o, const char *v, void *dst);
/* --format into a report_format (default DEF), BAD the error for an unknown one. */
#define CLI_OPT_FORMAT(D, H, DEF, BAD, T, F) \
  {.name = "--format", .arg = "F", .dflt = D, .help = H, .kind = CLI_CALL, \
   .off = CLI_AT(T, F, report_format), .idef = DEF, .bad = BAD, .call = cli_option_format}
int cli_option_format(const char *cmd, const cli_option *o, const char *v, void *dst);
/* A point sampler's name (samplers/sampler.h, sampler_points_find) into an int: its
** sampler_points_kind, o->idef when not given. */
int cli_option_points_sampler(const char *cmd, const cli_option *o, const char *v, void *dst);
/* The points of --points FILE.csv (path not NULL) or of --random N (sampler kind, seed),
** *p malloc'ed, desc naming them; check (lot_check_memory, got_points_check_memory)
** refuses a --random N that does not fit.  0, or 2 after the one-line error. */
struct geom_point;
int cli_points_get(const char *cmd, const char *path, uint64_t random, int kind, uint64_t seed,
                   int (*check)(size_t n, char *err, size_t errlen), struct geom_point **p,
                   size_t *n, char *desc, size_t desclen);
/* Rules, repeatable and comma lists (cli_parse_rule_list), appended to a
** cli_rules whose r and cap the command sets before parsing (n = 0 by
** default); cli_option_rules is the setter, cli_rules_add the same for a
** positional argument. */
struct rule;
typedef struct cli_rules { struct rule *r; int n, cap; } cli_rules;
int cli_option_rules(const char *cmd, const cli_option *o, const char *v, void *dst);
int cli_rules_add(const char *cmd, const char *list, cli_rules *rules);

/* A command: its name, help and table; positional handles an argument
** that is no option of the table (NULL: it is an unknown option). */
typedef struct cli_spec {
  const char *cmd, *usage, *about;
  const cli_option *opts;
  size_t nopts;
  int (*positional)(const char *cmd, const char *arg, void *dst);   /* 0, or 2 after the error */
} cli_spec;

/* Every row's default into dst, then argv[1..argc-1] in order: 0; 1 after
** printing the help (a help spelling where an option may stand); 2 after
** the one-line error.  *given (may be NULL): bit i set when row i was
** given.  cli_option_given: was the row named `name` given? */
int cli_options_parse(const cli_spec *s, int argc, char **argv, void *dst, uint64_t *given);
int cli_option_given(const cli_spec *s, uint64_t given, const char *name);

/* "usage", a blank line, "about" (ends with '\n'), then every option with
** its default; cli_spec_help prints a command's to stdout. */
void cli_help(FILE *f, const char *usage, const char *about, const cli_option *o, size_t n);
void cli_spec_help(const cli_spec *s);
const cli_option *cli_option_find(const char *name, const cli_option *o, size_t n);

/* ---- "did you mean" (cli/hint.c) ---- */

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
/* The same into a new array (*out, malloc'ed, one slot per comma-separated
** name): the count, or -1 after the error. */
int cli_rule_list_new(const char *cmd, const char *list, struct rule **out);

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
/* The global options' help lines (their table is in cli/userdefs.c). */
void cli_userdefs_help(FILE *f);
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
  int open;             /* the total grows as the run goes (set after start): no ETA */
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
