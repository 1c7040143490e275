/*
** cmd_averages.c: `fliplab averages --n N[..M]`: chapter 5's exact averages
** over all triangulations of the (n+2)-gon, each closed form as an exact
** rational and a decimal, and with --enumerate the averages found by
** enumerating every triangulation beside them with a match column
** (studies/triavg.h, docs/averages.md).
*/
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "geom.h"
#include "triavg.h"

#define CMD "averages"
#define CLI_AVG_MAX_VALUES 1000      /* values of n in one run */

typedef struct cli_avg_range { uint64_t lo, hi; } cli_avg_range;

typedef struct cli_avg_opts {
  cli_avg_range n;
  int enumerate, degrees;
  const char *out;
} cli_avg_opts;

/* --n N or N..M into a cli_avg_range. */
static int cli_avg_option_n(const char *cmd, const cli_option *o, const char *v, void *dst) {
  (void)o;
  cli_avg_range *r = dst;
  if (v == NULL) return r->lo = r->hi = 0, 0;
  const char *dots = strstr(v, "..");
  size_t len1 = dots ? (size_t)(dots - v) : strlen(v);
  const char *second = dots ? dots + 2 : v;
  if (len1 == 0 || geom_count_parse(v, len1, &r->lo) != 0 ||
      geom_count_parse(second, strlen(second), &r->hi) != 0)
    return cli_error(cmd, "--n expects N or N..M (whole numbers), got '%s'", v);
  if (r->lo < 1 || r->hi > STUDY_AVG_NMAX || r->lo > r->hi)
    return cli_error(cmd, "--n %s: need 1 <= N <= M <= %d (the (n+2)-gon)", v, STUDY_AVG_NMAX);
  if (r->hi - r->lo >= CLI_AVG_MAX_VALUES)
    return cli_error(cmd, "--n %s: at most %d values of n in one run", v, CLI_AVG_MAX_VALUES);
  return 0;
}

#define T cli_avg_opts
static const cli_option cli_avg_table[] = {
  {.name = "--n", .arg = "N[..M]", .dflt = "required",
   .help = "the (n+2)-gon, or every n from N to M (n <= 100000)", .kind = CLI_CALL,
   .off = CLI_AT(T, n, cli_avg_range), .call = cli_avg_option_n},
  CLI_OPT_FLAG("--enumerate", "also enumerate every triangulation (n <= 18) and compare", T,
               enumerate),
  CLI_OPT_FLAG("--degrees", "also the degree counts G^d_n, d = 0 .. n-1", T, degrees),
  CLI_OPT_OUT("FILE", "stdout", NULL, "write the tables to FILE", T, out),
};
#undef T

static const cli_spec cli_avg_spec = {
  CMD, "usage: fliplab averages --n N[..M] [--enumerate] [--degrees] [options]",
  "Chapter 5's averages over the C_n triangulations of the convex (n+2)-gon, each\n"
  "equally likely: each closed form as an exact rational and a decimal; with\n"
  "--enumerate the same average from every triangulation, and whether they match\n"
  "(exit 1 if any does not).  Quantities and derivations: docs/averages.md.\n",
  cli_avg_table, CLI_NOPTS(cli_avg_table), NULL};

/* The exact text of one value (closed form or enumerated), malloc'ed. */
static char *cli_avg_text(const study_avg *a, int kind, int d, int enumerated) {
  size_t len = kind >= 0 ? study_avg_text(a, kind, enumerated, 0, NULL, 0)
                         : study_avg_degcount_text(a, d, enumerated, 0, NULL, 0);
  char *s = malloc(len + 1);
  if (!s) return NULL;
  if (kind >= 0) study_avg_text(a, kind, enumerated, 0, s, len + 1);
  else study_avg_degcount_text(a, d, enumerated, 0, s, len + 1);
  return s;
}

/* One row: name, exact, decimal, and enumerated with match; 1 on a
** mismatch, -1 out of memory. */
static int cli_avg_row(FILE *f, const study_avg *a, int kind, int d, int enumerate,
                       int width) {
  char *c = cli_avg_text(a, kind, d, 0), *e = enumerate ? cli_avg_text(a, kind, d, 1) : NULL;
  if (!c || (enumerate && !e)) return free(c), free(e), -1;
  char name[32];
  if (kind >= 0) snprintf(name, sizeof name, "%s", study_avg_name(kind));
  else snprintf(name, sizeof name, "G^%d", d);
  int mismatch = enumerate && strcmp(c, e) != 0;
  char dec[32] = "";
  if (kind >= 0) snprintf(dec, sizeof dec, "%.12g", study_avg_double(a, kind, 0));
  fprintf(f, "  %-7s %-*s ", name, width, c);
  if (enumerate) fprintf(f, "%-18s %-*s %s\n", dec, width, e, mismatch ? "NO" : "yes");
  else fprintf(f, "%s\n", dec);
  free(c);
  free(e);
  return mismatch;
}

/* The widest exact text of the block (at least the header's). */
static int cli_avg_width(const study_avg *a, int n, int degrees) {
  size_t w = 10;
  for (int k = 0; k < STUDY_AVG_COUNT; k++) {
    size_t l = study_avg_text(a, k, 0, 0, NULL, 0);
    if (l > w) w = l;
  }
  for (int d = 0; degrees && d < n; d++) {
    size_t l = study_avg_degcount_text(a, d, 0, 0, NULL, 0);
    if (l > w) w = l;
  }
  return (int)w;
}

/* One n's block: 0, 1 after a mismatch (named on stderr), -1 on an error. */
static int cli_avg_block(FILE *f, int n, const cli_avg_opts *o) {
  char err[256];
  study_avg *a = study_avg_new(n, o->enumerate, err, sizeof err);
  if (!a) return cli_error(CMD, "%s", err), -1;
  int width = cli_avg_width(a, n, o->degrees), bad = 0, rc = 0;
  fprintf(f, "n = %d: the %d-gon\n  %-7s %-*s ", n, n + 2, "name", width, "exact");
  if (o->enumerate) fprintf(f, "%-18s %-*s %s\n", "decimal", width, "enumerated", "match");
  else fprintf(f, "decimal\n");
  for (int k = 0; k < STUDY_AVG_COUNT + (o->degrees ? n : 0) && rc >= 0; k++) {
    int kind = k < STUDY_AVG_COUNT ? k : -1, d = k - STUDY_AVG_COUNT;
    if (kind >= 0 && study_avg_text(a, kind, 0, 0, NULL, 0) == 0) continue;  /* L at n = 1 */
    rc = cli_avg_row(f, a, kind, d, o->enumerate, width);
    if (rc == 1 && !bad++)
      cli_error(CMD, "n = %d, %s: the closed form and the enumeration differ", n,
                kind >= 0 ? study_avg_name(kind) : "G");
  }
  study_avg_delete(a);
  if (rc < 0) return cli_error(CMD, "out of memory"), -1;
  return bad > 0;
}

int cli_cmd_averages(int argc, char **argv) {
  cli_avg_opts o;
  int st = cli_options_parse(&cli_avg_spec, argc, argv, &o, NULL);
  if (st != 0) return st == 1 ? 0 : st;
  if (o.n.lo == 0) return cli_error(CMD, "--n N[..M] is required");
  if (o.enumerate && o.n.hi > STUDY_AVG_ENUM_NMAX)
    return cli_error(CMD, "--enumerate: n goes up to %d (C_%d = 477638700 triangulations), "
                     "not %llu", STUDY_AVG_ENUM_NMAX, STUDY_AVG_ENUM_NMAX,
                     (unsigned long long)o.n.hi);
  FILE *f = cli_open_out(CMD, o.out);
  if (!f) return 2;
  int mismatch = 0;
  for (uint64_t n = o.n.lo; n <= o.n.hi; n++) {
    int r = cli_avg_block(f, (int)n, &o);
    if (r < 0) return cli_abort_out(f), 1;
    mismatch |= r;
    if (n < o.n.hi) fprintf(f, "\n");
  }
  if (cli_close_out(f) != 0) return 1;
  return mismatch ? 1 : 0;
}
