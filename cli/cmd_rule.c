/*
** cmd_rule.c: `fliplab rule`: test flip rules on random pentagons and
** quadrilaterals, and say honestly what the evidence shows.
**
** Per rule: the counts of flip-graph types I-V with 95% Wilson intervals,
** the agreement with Delaunay, verdicts ("not systematic: N
** counterexamples", never "proved"), a Delaunay-equivalence check on random
** convex quadrilaterals, and witness pentagons for every non-type-I outcome.
** The studies behind them are the library's (studies/study.h: the same
** numbers Python's verdicts() returns); this file parses the options and
** words what they found.  Pentagon i is sampler_pentagon(seed, i) and
** quadrilateral i is sampler_quad(seed, i): no output depends on --threads.
*/
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "formula.h"
#include "measure.h"
#include "flipgraph.h"
#include "cli.h"
#include "rule.h"
#include "sampler.h"
#include "report.h"
#include "study.h"

#define CLI_RULE_MAX 64

typedef struct cli_rule_opts {
  uint64_t samples, seed, witnesses, quads, threads;
  double tie_eps;
  const char *svg_dir;
  const char *sites;          /* site sets beyond pentagons (cli/rule_sites.c) */
  uint64_t site_samples;
  cli_rules rules;            /* the arguments */
} cli_rule_opts;

#define T cli_rule_opts
static const cli_option cli_rule_opts_help[] = {
  CLI_OPT_U64("--samples", "N", "random convex pentagons (iteration method), at most 2^40", T,
              samples, 1, 1ull << 40, 100000),
  CLI_OPT_SEED("sampler seed: pentagon i is table34's pentagon i of seed S", T, seed),
  CLI_OPT_U64("--witnesses", "K", "witness pentagons printed per non-type-I outcome, at most 100",
              T, witnesses, 0, STUDY_WITNESS_MAX, 3),
  CLI_OPT_STRING("--svg-dir", "DIR", "none", "draw each witness's directed flip graph into DIR",
                 T, svg_dir),
  CLI_OPT_U64("--quads", "M", "random convex quadrilaterals for the Delaunay-equivalence check",
              T, quads, 0, 1ull << 40, 100000),
  CLI_OPT_TIE_EPS("relative tie tolerance of the rules, at most 1e-3", 1e-3, T, tie_eps),
  CLI_OPT_THREADS("threads; no output depends on T", T, threads),
  {.name = "--sites", .arg = "LIST", .sdef = "disc:5,convex:6",
   .help = "also census these site sets (SAMPLER:N, or none): a verdict\n"
           "                     and a witness set each (docs/sitesets.md)",
   .kind = CLI_STRING, .off = CLI_AT(T, sites, const char *), .check = cli_rule_sites_check},
  CLI_OPT_U64("--site-samples", "S", "site sets per --sites entry", T, site_samples, 1,
              1ull << 40, 20000),
};
#undef T

/* RULE...: rules, also comma lists; "--" too (no rule, said so). */
static int cli_rule_positional(const char *cmd, const char *arg, void *dst) {
  if (strncmp(arg, "--", 2) == 0 && strcmp(arg, "--") != 0)
    return cli_unknown_option(cmd, arg, cli_rule_opts_help, CLI_NOPTS(cli_rule_opts_help));
  return cli_rules_add(cmd, arg, &((cli_rule_opts *)dst)->rules);
}

static const cli_spec cli_rule_spec = {
  "rule", "usage: fliplab rule RULE... [options]",
  "Tests each flip rule (MEASURE_JOINT, DT, or a plugin's rule; several may be given,\n"
  "also as a comma list) on random convex pentagons and quadrilaterals: flip-graph\n"
  "types I-V with 95% Wilson intervals, agreement with Delaunay, verdicts, and the\n"
  "witness pentagons of the lowest sample indices (the same for any --threads).\n"
  "User measures: fliplab --define 'q = a*b*c' rule q_1; plugins: fliplab --plugin\n"
  "FILE.so rule NAME.  Types and verdicts: docs/classification.md.\n",
  cli_rule_opts_help, CLI_NOPTS(cli_rule_opts_help), cli_rule_positional};

/* ---- printing --------------------------------------------------------------- */

static void cli_rule_pct_line(const char *label, uint64_t k, uint64_t n, double lo, double hi,
                              const char *note) {
  printf("  %-5s %10llu  %8.3f%%  [%.3f, %.3f]%s%s\n", label, (unsigned long long)k,
         n ? 100.0 * (double)k / (double)n : 0.0, lo, hi, note ? "  " : "", note ? note : "");
}

static void cli_rule_describe(const rule *r) {
  if (!rule_is_triangle(r)) {
    printf("rule %s: quadrilateral rule: %s\n", rule_name(r), rule_quad_of(r)->desc);
    return;
  }
  const measure *m = measure_get(rule_measure(r));
  const char *expr = formula_expr(rule_measure(r));
  printf("rule %s: measure %s (%s%s), joint %s (%s)\n", rule_name(r), m->name,
         expr ? "formula " : "", expr ? expr : m->desc, rule_joint_name(r),
         joint_get(rule_joint(r))->symbol);
}

/* "1 pentagon", "2 pentagons". */
static const char *cli_rule_s(unsigned long long n) {
  return n == 1 ? "" : "s";
}

/* The "no counterexample" claims count the pentagons of types I-IV only
** (v->decided): a type-V pentagon says nothing either way. */
static void cli_rule_verdicts(const study_verdict *v) {
  const flipgraph_counts *c = &v->counts;
  unsigned long long n = c->samples;
  unsigned long long t2 = c->type[FLIPGRAPH_II], t3 = c->type[FLIPGRAPH_III];
  unsigned long long t4 = c->type[FLIPGRAPH_IV], t5 = c->type[FLIPGRAPH_V];
  unsigned long long decided = v->decided;
  const char *of = t5 ? " of types I-IV" : "";
  if (!v->systematic)
    printf("  verdict: not systematic: %llu counterexample%s (type III, two LOTs)\n", t3,
           cli_rule_s(t3));
  else
    printf("  verdict: no counterexample to systematicity in %llu pentagons%s (no type III)\n",
           decided, of);
  if (!v->local)
    printf("  verdict: not local: %llu counterexample%s (type II)\n", t2, cli_rule_s(t2));
  else
    printf("  verdict: no counterexample to locality in %llu pentagons%s (no type II)\n",
           decided, of);
  if (v->sink_bug)
    printf("  verdict: BUG: %llu pentagons without a sink (type IV), impossible for a "
           "triangle-based rule (thesis theorem 1)\n", t4);
  else if (t4)
    printf("  verdict: no LOT exists on %llu pentagon%s (type IV, no sink)\n", t4, cli_rule_s(t4));
  if (t5)
    printf("  verdict: returns either on %llu pentagon%s (type V): ties within tie_eps, which a "
           "good rule hits with probability zero\n", t5, cli_rule_s(t5));
  if (v->always_delaunay)
    printf("  verdict: agrees with Delaunay on all %llu pentagons\n", n);
}

static void cli_rule_quad_report(const rule *r, const study_quadcheck *qc) {
  const geom_point *q = qc->q;
  if (qc->tested == 0) return;
  printf("  Delaunay equivalence on %llu random convex quadrilaterals: %llu disagreements, "
         "%llu ties (either), %llu cocircular skipped\n",
         (unsigned long long)qc->tested, (unsigned long long)qc->disagree,
         (unsigned long long)qc->ties, (unsigned long long)qc->cocircular);
  if (qc->equivalent) {
    printf("  verdict: no counterexample to Delaunay equivalence in %llu quadrilaterals\n",
           (unsigned long long)qc->decided);
    return;
  }
  if (qc->disagree == 0) {
    printf("  verdict: not Delaunay-equivalent: either on %llu quadrilaterals where Delaunay "
           "decides (no opposite choice on the other %llu)\n",
           (unsigned long long)qc->ties, (unsigned long long)(qc->decided - qc->ties));
    return;
  }
  printf("  verdict: not Delaunay-equivalent; first disagreement, quadrilateral #%llu "
         "ABCD = %.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g: rule %s, DT %s",
         (unsigned long long)qc->first, q[0].x, q[0].y, q[1].x, q[1].y, q[2].x, q[2].y, q[3].x, q[3].y,
         rule_choice_str(qc->choice), rule_choice_str(qc->dt));
  if (rule_is_triangle(r)) printf(" (F_AC = %.17g, F_BD = %.17g)", qc->ac, qc->bd);
  printf("\n");
}

static char cli_rule_letter(rule_choice c) {
  return c == RULE_AC ? 'A' : c == RULE_BD ? 'B' : 'E';
}

/* File names keep letters, digits, '-', '.', '_'; anything else becomes '~'. */
static void cli_rule_svg_path(char *buf, size_t len, const char *dir, const char *rname,
                              flipgraph_type t, uint64_t idx) {
  char safe[96];
  size_t n = 0;
  for (const char *s = rname; *s && n + 1 < sizeof safe; s++) {
    char c = *s;
    int ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
             c == '-' || c == '.' || c == '_';
    safe[n++] = ok ? c : '~';
  }
  safe[n] = '\0';
  snprintf(buf, len, "%s/%s-%llu-%s.svg", dir, flipgraph_type_name(t), (unsigned long long)idx,
           safe);
}

static int cli_rule_svg(const char *path, const rule *r, const cli_rule_opts *o, uint64_t idx,
                        const flipgraph_pentagon *p, const flipgraph *g) {
  FILE *f = cli_open_out("rule", path);
  if (f == NULL) return 2;
  char cap[RULE_NAME_MAX + 512];
  snprintf(cap, sizeof cap,
           "rule %s: type %s, pentagon #%llu of seed %llu (tie_eps %g)\n"
           "v0 = (%.17g, %.17g)   v1 = (%.17g, %.17g)\n"
           "v2 = (%.17g, %.17g)   v3 = (%.17g, %.17g)\n"
           "v4 = (%.17g, %.17g)\n"
           "arrows point to the preferred triangulation; T_i = fan at v_i",
           r->name, flipgraph_type_name(g->type), (unsigned long long)idx,
           (unsigned long long)o->seed, o->tie_eps, p->v[0].x, p->v[0].y, p->v[1].x, p->v[1].y,
           p->v[2].x, p->v[2].y, p->v[3].x, p->v[3].y, p->v[4].x, p->v[4].y);
  return cli_finish_out("rule", f, report_flipgraph_svg(f, p, g, cap));
}

/* Witnesses are re-derived from their index with the one-rule reference
** path (flipgraph_classify), which must agree with the fast plan. */
static int cli_rule_witnesses(const rule *r, const cli_rule_opts *o,
                              const study_witnesses *w) {
  int any = 0;
  for (int s = FLIPGRAPH_II; s < FLIPGRAPH_NTYPES; s++) any |= w[s].n > 0;
  if (!any || o->witnesses == 0) return 0;
  printf("  witnesses (lowest sample indices; decisions of Q0..Q4, A = diagonal v_{j+1}v_{j+3} "
         "of Q_j, B = v_{j+2}v_{j+4}, E = either; sinks T_i = fan at v_i):\n");
  for (int s = FLIPGRAPH_II; s < FLIPGRAPH_NTYPES; s++)
    for (int k = 0; k < w[s].n; k++) {
      geom_point v[5];
      flipgraph_pentagon p;
      flipgraph g;
      sampler_pentagon(o->seed, w[s].idx[k], v);
      flipgraph_prepare(&p, v);
      flipgraph_classify(&p, r, o->tie_eps, &g);
      printf("    type %-3s #%llu: pentagon", flipgraph_type_name(g.type),
             (unsigned long long)w[s].idx[k]);
      for (int i = 0; i < 5; i++) printf("%s%.17g,%.17g", i ? "," : " ", v[i].x, v[i].y);
      printf("; decisions ");
      for (int j = 0; j < 5; j++) putchar(cli_rule_letter(g.dec[j]));
      printf("; sinks");
      if (g.type == FLIPGRAPH_V) printf(" - (either)");
      else if (g.nsinks == 0) printf(" none");
      for (int i = 0; i < g.nsinks; i++) printf(" T%d", g.sink[i]);
      if (p.delaunay_sink >= 0) printf("; Delaunay T%d", p.delaunay_sink);
      printf("\n");
      if (o->svg_dir != NULL) {
        char path[4096];
        cli_rule_svg_path(path, sizeof path, o->svg_dir, r->name, g.type, w[s].idx[k]);
        if (cli_rule_svg(path, r, o, w[s].idx[k], &p, &g) != 0) return 1;
        printf("      svg: %s\n", path);
      }
    }
  return 0;
}

static void cli_rule_print(const rule *r, const cli_rule_opts *o, const study_verdict *v) {
  static const char *const note[FLIPGRAPH_NTYPES] = {
    "one sink, systematic and local here", "one sink, not local", "two sinks, not systematic",
    "no sink", "either returned"};
  const flipgraph_counts *c = &v->counts;
  cli_rule_describe(r);
  printf("  %llu pentagons (iteration method, seed %llu), tie_eps %g; 95%% Wilson intervals\n",
         (unsigned long long)c->samples, (unsigned long long)o->seed, o->tie_eps);
  printf("  %-5s %10s  %9s  %s\n", "type", "count", "percent", "95% interval");
  for (int t = 0; t < FLIPGRAPH_NTYPES; t++)
    cli_rule_pct_line(flipgraph_type_name((flipgraph_type)t), c->type[t], c->samples, v->lo[t],
                      v->hi[t], note[t]);
  cli_rule_pct_line("DT", c->dt, c->samples, v->lo[STUDY_ROW_DT], v->hi[STUDY_ROW_DT],
                    "type I with sink = Delaunay triangulation");
}

/* ---- the command ------------------------------------------------------------- */

/* 0, 1 after --help, 2 after an error. */
static int cli_rule_parse(int argc, char **argv, cli_rule_opts *o) {
  int st = cli_options_parse(&cli_rule_spec, argc, argv, o, NULL);
  if (st != 0) return st;
  if (o->rules.n == 0) return cli_error("rule", "no rule given (try: fliplab rule --help)");
  return 0;
}

/* The studies of every rule: pentagons (one tally for all rules, with a
** progress bar) and quadrilaterals.  0, or 1 after the one-line error. */
static int cli_rule_study(const rule *rules, int nrules, const cli_rule_opts *o,
                          study_verdict *v, study_quadcheck *qc) {
  char err[256];
  cli_progress prog;
  cli_progress_start(&prog, "rule");
  flipgraph_run run = {o->seed, 0, o->samples, o->tie_eps, (int)o->threads, cli_progress_update,
                       &prog, NULL, NULL, NULL};
  int rc = study_pentagons(rules, nrules, &run, (int)o->witnesses, v);
  cli_progress_finish(&prog);
  if (rc != 0) return fprintf(stderr, "fliplab rule: out of memory\n"), 1;
  for (int r = 0; r < nrules; r++)
    if (study_quads(&rules[r], o->seed, o->quads, (int)o->threads, &qc[r], err, sizeof err) != 0)
      return cli_error("rule", "%s", err), 1;
  return 0;
}

int cli_cmd_rule(int argc, char **argv) {
  static rule rules[CLI_RULE_MAX];
  cli_rule_opts o = {.rules = {rules, 0, CLI_RULE_MAX}};
  int rc = cli_rule_parse(argc, argv, &o), nrules = o.rules.n;
  if (rc == 1) return 0;
  if (rc != 0) return rc;
  for (int r = 0; r < nrules; r++) rule_set_tie_eps(&rules[r], o.tie_eps);
  if (o.svg_dir != NULL && mkdir(o.svg_dir, 0777) != 0 && errno != EEXIST)
    return cli_error("rule", "cannot create --svg-dir '%s': %s", o.svg_dir, strerror(errno));

  study_verdict *v = calloc((size_t)nrules, sizeof *v);
  study_quadcheck *qc = calloc((size_t)nrules, sizeof *qc);
  if (v == NULL || qc == NULL) rc = (fprintf(stderr, "fliplab rule: out of memory\n"), 1);
  else rc = cli_rule_study(rules, nrules, &o, v, qc);
  if (rc == 0 && cli_userdefs_failed("rule")) rc = 1;
  for (int r = 0; r < nrules && rc == 0; r++) {
    if (r > 0) printf("\n");
    cli_rule_print(&rules[r], &o, &v[r]);
    cli_rule_verdicts(&v[r]);
    cli_rule_quad_report(&rules[r], &qc[r]);
    rc = cli_rule_sites(&rules[r], o.sites, o.site_samples, o.seed, o.tie_eps, (int)o.threads,
                        o.svg_dir);
    if (rc == 0) rc = cli_rule_witnesses(&rules[r], &o, v[r].witness);
  }
  if (rc == 0 && cli_userdefs_failed("rule")) rc = 1;
  fflush(stdout);
  free(v);
  free(qc);
  return rc;
}
