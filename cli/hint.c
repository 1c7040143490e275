/*
** hint.c: "did you mean" for every command: suggestions for mistyped
** commands, options (from the option tables' rows, cli/options.c), rules
** and measures.  One home: every command reports an unknown name through
** here.
**
** A suggestion is the candidate at the smallest edit distance (insertions,
** deletions, substitutions and swaps of neighbours, each costing one), if
** that distance is at most a third of the typed name's length (at least 1;
** names of one or two characters get none: "g" is no typo of "a").  Signs count for
** nothing: a measure typed with or without its leading '-' ("alpha" for
** "-alpha", "-gamma" for "gamma") is suggested whatever its length, since
** fliplab names "small is good" measures by their negation.
*/
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/ioctl.h>
#include <unistd.h>
#include "cli.h"
#include "joint.h"
#include "measure.h"
#include "rule.h"

#define CLI_HINT_MAXLEN 64    /* longer names get no suggestion */

/* Optimal string alignment distance (Damerau-Levenshtein without
** repeated edits of one substring), O(|a| |b|) with three rows. */
size_t cli_edit_distance(const char *a, const char *b) {
  size_t n = strlen(a), m = strlen(b);
  if (n > CLI_HINT_MAXLEN || m > CLI_HINT_MAXLEN) return (size_t)-1;
  size_t r0[CLI_HINT_MAXLEN + 1], r1[CLI_HINT_MAXLEN + 1], r2[CLI_HINT_MAXLEN + 1];
  size_t *pp = r0, *prev = r1, *cur = r2;
  for (size_t j = 0; j <= m; j++) prev[j] = j;
  for (size_t i = 1; i <= n; i++) {
    cur[0] = i;
    for (size_t j = 1; j <= m; j++) {
      size_t cost = a[i - 1] != b[j - 1];
      size_t d = prev[j] + 1;
      if (cur[j - 1] + 1 < d) d = cur[j - 1] + 1;
      if (prev[j - 1] + cost < d) d = prev[j - 1] + cost;
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] && pp[j - 2] + 1 < d)
        d = pp[j - 2] + 1;
      cur[j] = d;
    }
    size_t *t = pp;
    pp = prev;
    prev = cur;
    cur = t;
  }
  return prev[m];
}

/* s with its leading '-' removed, or added; into buf. */
static const char *cli_hint_flip_sign(const char *s, char *buf, size_t len) {
  snprintf(buf, len, s[0] == '-' ? "%s" : "-%s", s[0] == '-' ? s + 1 : s);
  return buf;
}

const char *cli_closest(const char *s, const char *const *names, size_t n) {
  char flipped[CLI_HINT_MAXLEN + 2];
  cli_hint_flip_sign(s, flipped, sizeof flipped);
  const char *best = NULL;
  size_t len = strlen(s), bestd = len < 3 ? 0 : len / 3 > 1 ? len / 3 : 1;
  for (size_t i = 0; i < n; i++) {
    if (names[i] == NULL || strcmp(names[i], s) == 0) continue;
    if (strcmp(names[i], flipped) == 0) return names[i];
    size_t d = bestd > 0 ? cli_edit_distance(s, names[i]) : (size_t)-1;
    if (d < bestd || (d == bestd && best == NULL)) {
      best = names[i];
      bestd = d;
    }
  }
  return best;
}

/* ---- options ---------------------------------------------------------------- */

int cli_unknown_option(const char *cmd, const char *opt, const cli_option *o, size_t n) {
  const char *names[64];
  size_t k = 0;
  for (size_t i = 0; i < n && k < 63; i++) names[k++] = o[i].name;
  names[k++] = "--help";
  const char *near = cli_closest(opt, names, k);
  if (near != NULL)
    return cli_error(cmd, "unknown option '%s': did you mean '%s'? (try: fliplab %s --help)",
                     opt, near, cmd);
  return cli_error(cmd, "unknown option '%s' (try: fliplab %s --help)", opt, cmd);
}

/* ---- rules and measures ------------------------------------------------------- */

/* Every measure's name, in registry order. */
static size_t cli_measure_names(const char **names, size_t cap) {
  size_t n = 0;
  for (int i = 0; i < measure_count() && n < cap; i++) names[n++] = measure_get(i)->name;
  return n;
}

const char *cli_closest_measure(const char *s) {
  const char *names[MEASURE_MAX];
  return cli_closest(s, names, cli_measure_names(names, MEASURE_MAX));
}

/* The closest rule name to s: a quadrilateral rule, or MEASURE_JOINT with
** each half corrected on its own; into buf.  0 if nothing is close. */
static int cli_closest_rule(const char *s, char *buf, size_t len) {
  const char *quads[64];
  size_t nq = 0;
  for (int i = 0; i < rule_quad_count() && nq < 64; i++) quads[nq++] = rule_quad_get(i)->name;
  char m[CLI_HINT_MAXLEN + 1];
  const char *js = rule_name_split(s, m, sizeof m);
  if (js == NULL) {
    const char *q = cli_closest(s, quads, nq);
    if (q != NULL) snprintf(buf, len, "%s", q);
    return q != NULL;
  }
  const char *joints[JOINT_COUNT];
  for (int j = 0; j < JOINT_COUNT; j++) joints[j] = joint_get((joint_id)j)->name;
  const char *mm = measure_find(m) >= 0 ? m : cli_closest_measure(m);
  const char *jj = joint_find(js) >= 0 ? js : cli_closest(js, joints, JOINT_COUNT);
  if (mm == NULL || jj == NULL) return 0;
  rule_name_join(buf, len, mm, jj);
  return 1;
}

/* name[0 .. len-1] without the blanks around it into buf (cap bytes): 0,
** or -1 when nothing is left or it does not fit. */
static int cli_rule_trim(const char *name, size_t len, char *buf, size_t cap) {
  while (len > 0 && (*name == ' ' || *name == '\t')) name++, len--;
  while (len > 0 && (name[len - 1] == ' ' || name[len - 1] == '\t')) len--;
  if (len == 0 || len >= cap) return -1;
  memcpy(buf, name, len);
  buf[len] = '\0';
  return 0;
}

/* One rule name, blanks around it ignored as in a list (so that --rule
** 'ES:square ' and --rules 'ES:square ,DT' agree). */
int cli_parse_rule(const char *cmd, const char *given, rule *out) {
  char err[4096], near[160], name[RULE_NAME_MAX];
  if (cli_rule_trim(given, strlen(given), name, sizeof name) != 0)
    return cli_error(cmd, "empty or too long rule name '%.60s' (at most %d characters)", given,
                     RULE_NAME_MAX - 1);
  if (rule_parse(name, out, err, sizeof err) == 0) return 0;
  if (cli_closest_rule(name, near, sizeof near) && strcmp(near, name) != 0) {
    rule tmp;
    char e2[512];
    if (rule_parse(near, &tmp, e2, sizeof e2) == 0)
      return cli_error(cmd, "unknown rule '%s': did you mean '%s'? (fliplab list shows every "
                       "measure and joint)", name, near);
  }
  char m[64];
  const char *js = rule_name_split(name, m, sizeof m);
  if (js != NULL && joint_find(js) >= 0) {
    if (measure_find(m) < 0)
      return cli_error(cmd, "unknown measure '%s' in rule '%s': not built in (fliplab list) and "
                       "not defined: fliplab --define '%s = EXPR' %s ... defines it (the "
                       "formula variables are in fliplab --help), --plugin FILE.so loads one",
                       m, name, m, cmd);
  }
  return cli_error(cmd, "%s", err);
}

/* Split "R_1,P_1, DT" at commas (blanks around names ignored) and parse
** each rule into out[*n...]; 0, or 2 after the error. */
int cli_parse_rule_list(const char *cmd, const char *list, rule *out, int *n, int cap) {
  const char *p = list;
  for (;;) {
    const char *comma = strchr(p, ',');
    size_t len = comma ? (size_t)(comma - p) : strlen(p);
    char name[RULE_NAME_MAX];
    if (cli_rule_trim(p, len, name, sizeof name) != 0)
      return cli_error(cmd, "empty or too long rule name in '%.200s'", list);
    if (*n >= cap) return cli_error(cmd, "at most %d rules", cap);
    if (cli_parse_rule(cmd, name, &out[*n]) != 0) return 2;
    (*n)++;
    if (comma == NULL) return 0;
    p = comma + 1;
  }
}

int cli_rule_list_new(const char *cmd, const char *list, rule **out) {
  int cap = 1, n = 0;
  for (const char *c = list; *c; c++) cap += *c == ',';
  if ((*out = malloc((size_t)cap * sizeof **out)) == NULL) return cli_error(cmd, "out of memory"), -1;
  if (cli_parse_rule_list(cmd, list, *out, &n, cap) != 0) {
    free(*out);
    return -1;
  }
  return n;
}

int cli_unknown_command(const char *name, const char *const *names, size_t n) {
  const char *near = cli_closest(name, names, n);
  if (near != NULL)
    fprintf(stderr, "fliplab: unknown command '%s': did you mean '%s'? (try: fliplab --help)\n",
            name, near);
  else
    fprintf(stderr, "fliplab: unknown command '%s' (try: fliplab --help)\n", name);
  return 2;
}

/* ---- output file names -------------------------------------------------------- */

/* Extensions of formats a user might expect; fliplab writes only some. */
static const char *const cli_known_ext[] = {
  "csv", "svg", "md", "txt", "png", "jpg", "jpeg", "pdf", "eps", "ps", "html", "json", "tsv",
  "poly", "node", "ele",
};

static const char *cli_ext(const char *path) {
  const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
  return dot != NULL && (slash == NULL || dot > slash + 1) ? dot + 1 : NULL;
}

static int cli_ext_is(const char *ext, const char *want) {
  return ext != NULL && strlen(ext) == strlen(want) && strncasecmp(ext, want, strlen(want)) == 0;
}

int cli_check_out_ext(const char *cmd, const char *opt, const char *path, const char *want) {
  const char *ext = cli_ext(path);
  if (strcmp(path, "-") == 0 || ext == NULL || cli_ext_is(ext, want)) return 0;
  for (size_t i = 0; i < sizeof cli_known_ext / sizeof cli_known_ext[0]; i++)
    if (cli_ext_is(ext, cli_known_ext[i]))
      return cli_error(cmd, "%s '%s': this output is %s, not .%s; name the file .%s", opt, path,
                       want, ext, want);
  return 0;
}

const char *cli_format_of_path(const char *path) {
  const char *ext = cli_ext(path);
  if (path == NULL || strcmp(path, "-") == 0 || ext == NULL) return NULL;
  if (cli_ext_is(ext, "csv")) return "csv";
  if (cli_ext_is(ext, "md")) return "md";
  if (cli_ext_is(ext, "txt")) return "text";
  return NULL;
}

/* ---- the terminal --------------------------------------------------------------- */

/* How many table columns of `per` characters fit beside a `fixed`-wide
** label when stdout is a terminal (its width: the window size, else
** $COLUMNS, else 80); 0 (no limit) when stdout is not a terminal, so
** pipes, files and tests get the thesis's one-block layout. */
uint64_t cli_terminal_columns(int fixed, int per) {
  if (!isatty(fileno(stdout))) return 0;
  int width = 0;
  struct winsize ws;
  if (ioctl(fileno(stdout), TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0) width = ws.ws_col;
  const char *env = getenv("COLUMNS");
  if (width == 0 && env != NULL) width = atoi(env);
  if (width <= 0) width = 80;
  int n = (width - fixed) / per;
  return n > 0 ? (uint64_t)n : 1;
}
