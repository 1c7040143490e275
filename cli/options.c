/*
** options.c: the one option parser of every command, and its help.
**
** A command's options are a table of rows (cli.h): each states its kind,
** bounds, default and destination, so parsing is a walk over argv that
** finds the row and hands the value to the row's setter; the defaults are
** the same setters given no value; the help prints the rows, each default
** from the value it stores unless the row words it ("all cores"); the "did
** you mean" of an unknown option (cli/hint.c) searches the rows' names.
** The setters of the shared rows (--shard, --format, rule lists) are here.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "geom.h"
#include "report.h"
#include "rule.h"
#include "sampler.h"

int cli_is_help(const char *opt) {
  return strcmp(opt, "--help") == 0 || strcmp(opt, "-h") == 0 || strcmp(opt, "help") == 0;
}

/* ---- the setters of each kind (v NULL: the default) ------------------------ */

static int cli_set_flag(const char *cmd, const cli_option *o, const char *v, void *dst) {
  (void)cmd;
  *(int *)dst = v != NULL ? o->set : o->idef;
  return 0;
}

/* With .bad, a count outside [lo, hi] gets the row's own message (a
** non-number still the common one). */
static int cli_set_u64(const char *cmd, const cli_option *o, const char *v, void *dst) {
  uint64_t *p = dst;
  if (v == NULL) {
    *p = o->def;
    return 0;
  }
  if (o->bad == NULL) return cli_parse_u64(cmd, o->name, v, o->lo, o->hi, p) != 0 ? 2 : 0;
  if (cli_parse_u64(cmd, o->name, v, 0, UINT64_MAX, p) != 0) return 2;
  return *p >= o->lo && *p <= o->hi ? 0 : cli_error(cmd, o->bad, v);
}

static int cli_set_double(const char *cmd, const cli_option *o, const char *v, void *dst) {
  if (v == NULL) {
    *(double *)dst = o->ddef;
    return 0;
  }
  return cli_parse_double(cmd, o->name, v, o->dlo, o->dhi, dst) != 0 ? 2 : 0;
}

static int cli_set_string(const char *cmd, const cli_option *o, const char *v, void *dst) {
  if (v != NULL && o->ext != NULL && cli_check_out_ext(cmd, o->name, v, o->ext) != 0) return 2;
  if (v != NULL && o->check != NULL && o->check(v) != 0) return 2;
  *(const char **)dst = v != NULL ? v : o->sdef;
  return 0;
}

static int cli_choice_index(const cli_option *o, const char *v) {
  if (o->find != NULL) return o->find(v);
  for (int k = 0; o->names[k] != NULL; k++)
    if (strcmp(o->names[k], v) == 0) return k;
  return -1;
}

static int cli_set_choice(const char *cmd, const cli_option *o, const char *v, void *dst) {
  int k = v != NULL ? cli_choice_index(o, v) : o->idef;
  if (v != NULL && k < 0) return cli_error(cmd, o->bad, v);
  *(int *)dst = k;
  return 0;
}

static int cli_set_call(const char *cmd, const cli_option *o, const char *v, void *dst) {
  return o->call(cmd, o, v, dst);
}

static const cli_option_fn cli_setters[] = {
  [CLI_FLAG] = cli_set_flag,     [CLI_U64] = cli_set_u64,       [CLI_DOUBLE] = cli_set_double,
  [CLI_STRING] = cli_set_string, [CLI_CHOICE] = cli_set_choice, [CLI_CALL] = cli_set_call,
};

/* ---- the shared rows' setters ------------------------------------------------ */

int cli_option_shard(const char *cmd, const cli_option *o, const char *v, void *dst) {
  cli_shard *s = dst;
  (void)o;
  if (v == NULL) {
    *s = (cli_shard){0, 0};
    return 0;
  }
  return cli_parse_shard(cmd, v, &s->k, &s->n) != 0 ? 2 : 0;
}

/* "512M" -> 512 * 2^20: the digits (cli_parse_u64's), then one unit. */
int cli_option_memory(const char *cmd, const cli_option *o, const char *v, void *dst) {
  static const char units[] = "KMGT";
  if (v == NULL) {
    *(uint64_t *)dst = o->def;
    return 0;
  }
  char num[32];
  size_t len = strlen(v);
  const char *u = len > 0 ? strchr(units, v[len - 1]) : NULL;
  int shift = u != NULL && *u != '\0' ? 10 * (int)(u - units + 1) : 0;
  if (shift > 0) len--;
  uint64_t n, max = CLI_MEMORY_MAX >> shift;
  if (len == 0 || len >= sizeof num || strspn(v, "0123456789") != len)
    return cli_error(cmd, "--memory expects a size such as 1G, 512M or 65536 (bytes), got '%s'",
                     v);
  memcpy(num, v, len);
  num[len] = '\0';
  if (geom_count_parse(num, len, &n) != 0 || n < 1 || n > max)
    return cli_error(cmd, "--memory %s is out of range [1, 1T]", v);
  *(uint64_t *)dst = n << shift;
  return 0;
}

int cli_option_format(const char *cmd, const cli_option *o, const char *v, void *dst) {
  if (v == NULL) {
    *(report_format *)dst = (report_format)o->idef;
    return 0;
  }
  return report_format_parse(v, dst) == 0 ? 0 : cli_error(cmd, o->bad, v);
}

int cli_rules_add(const char *cmd, const char *list, cli_rules *rules) {
  return cli_parse_rule_list(cmd, list, rules->r, &rules->n, rules->cap);
}

int cli_option_points_sampler(const char *cmd, const cli_option *o, const char *v, void *dst) {
  int k = v != NULL ? sampler_points_find(v) : o->idef;
  if (k < 0 && v != NULL)
    return cli_error(cmd, "unknown sampler '%s' (valid: %s)", v, sampler_points_names);
  *(int *)dst = k;
  return 0;
}

int cli_points_get(const char *cmd, const char *path, uint64_t random, int kind, uint64_t seed,
                   int (*check)(size_t n, char *err, size_t errlen), struct geom_point **p,
                   size_t *n, char *desc, size_t desclen) {
  char err[512];
  if (path) {
    if (report_points_read(path, p, NULL, n, err, sizeof err) != 0)
      return cli_error(cmd, "%s", err);
    snprintf(desc, desclen, "%zu points from %s", *n, path);
    return 0;
  }
  *n = (size_t)random;
  if (check(*n, err, sizeof err) != 0) return cli_error(cmd, "--random: %s", err);
  *p = malloc(*n * sizeof **p);
  if (*p == NULL) return cli_error(cmd, "out of memory for %zu points", *n);
  sampler_points((sampler_points_kind)kind, seed, *n, *p);
  snprintf(desc, desclen, "%zu %s points (seed %llu)", *n,
           sampler_points_name((sampler_points_kind)kind), (unsigned long long)seed);
  return 0;
}

int cli_option_rules(const char *cmd, const cli_option *o, const char *v, void *dst) {
  (void)o;
  if (v == NULL) {
    ((cli_rules *)dst)->n = 0;
    return 0;
  }
  return cli_rules_add(cmd, v, dst);
}

/* ---- the parser ---------------------------------------------------------------- */

const cli_option *cli_option_find(const char *name, const cli_option *o, size_t n) {
  for (size_t i = 0; i < n; i++)
    if (strcmp(o[i].name, name) == 0) return &o[i];
  return NULL;
}

int cli_option_given(const cli_spec *s, uint64_t given, const char *name) {
  const cli_option *o = cli_option_find(name, s->opts, s->nopts);
  return o != NULL && (given >> (o - s->opts) & 1);
}

int cli_options_parse(const cli_spec *s, int argc, char **argv, void *dst, uint64_t *given) {
  char *base = dst;
  uint64_t seen = 0;
  for (size_t k = 0; k < s->nopts; k++)
    cli_setters[s->opts[k].kind](s->cmd, &s->opts[k], NULL, base + s->opts[k].off);
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i], *v = a;
    if (cli_is_help(a)) {
      cli_spec_help(s);
      return 1;
    }
    const cli_option *o = cli_option_find(a, s->opts, s->nopts);
    if (o == NULL && s->positional == NULL)
      return cli_unknown_option(s->cmd, a, s->opts, s->nopts);
    if (o == NULL) {
      if (s->positional(s->cmd, a, dst) != 0) return 2;
      continue;
    }
    if (o->arg != NULL && i + 1 >= argc) return cli_error(s->cmd, "option %s needs a value", a);
    if (o->arg != NULL) v = argv[++i];
    if (cli_setters[o->kind](s->cmd, o, v, base + o->off) != 0) return 2;
    if (o - s->opts < 64) seen |= (uint64_t)1 << (o - s->opts);   /* tables have fewer rows */
  }
  if (given != NULL) *given = seen;
  return 0;
}

/* ---- help ------------------------------------------------------------------------ */

/* The default as help shows it: the row's words, else its value; NULL
** for none (flags). */
static const char *cli_option_default(const cli_option *o, char *buf, size_t len) {
  if (o->dflt != NULL || o->arg == NULL) return o->dflt;
  switch (o->kind) {
  case CLI_U64:
    snprintf(buf, len, "%llu", (unsigned long long)o->def);
    return buf;
  case CLI_DOUBLE:
    snprintf(buf, len, "%g", o->ddef);
    return buf;
  case CLI_STRING:
    return o->sdef;
  case CLI_CHOICE:
    return o->names != NULL && o->idef >= 0 ? o->names[o->idef] : NULL;
  case CLI_FLAG:
  case CLI_CALL:
    break;
  }
  return NULL;
}

/* Each option on one line, name and argument in a column of 18; a default
** that would run the line past 80 characters goes on the next line. */
void cli_help(FILE *f, const char *usage, const char *about, const cli_option *o, size_t n) {
  fprintf(f, "%s\n\n%s\noptions:\n", usage, about);
  for (size_t i = 0; i < n; i++) {
    char head[48], buf[32];
    const char *dflt = cli_option_default(&o[i], buf, sizeof buf);
    snprintf(head, sizeof head, "%s%s%s", o[i].name, o[i].arg ? " " : "", o[i].arg ? o[i].arg : "");
    fprintf(f, "  %-18s %s", head, o[i].help);
    if (dflt != NULL) {
      const char *last = strrchr(o[i].help, '\n');
      size_t col = last ? strlen(last + 1) : 21 + strlen(o[i].help);
      if (col + strlen(dflt) + 12 > 80) fprintf(f, "\n%21s", "");
      else fputc(' ', f);
      fprintf(f, "(default: %s)", dflt);
    }
    fputc('\n', f);
  }
  fprintf(f, "  %-18s %s\n", "--help", "this help");
}

void cli_spec_help(const cli_spec *s) {
  cli_help(stdout, s->usage, s->about, s->opts, s->nopts);
}
