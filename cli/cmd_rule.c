/*
** cmd_rule.c: `fliplab rule`: test flip rules on random pentagons and
** quadrilaterals, and say honestly what the evidence shows.
**
** Per rule: the counts of flip-graph types I-V with 95% Wilson intervals,
** the agreement with Delaunay, verdicts ("not systematic: N
** counterexamples", never "proved"), a Delaunay-equivalence check on random
** convex quadrilaterals, and witness pentagons for every non-type-I outcome.
**
** Determinism.  Pentagon i is sampler_pentagon(seed, i) and quadrilateral i
** comes from its own generator stream, so every count is independent of
** the thread count.  Witnesses are the lowest sample indices of each
** outcome: samples are cut into chunks; each chunk, scanned in ascending
** order, keeps its own first K; chunks are merged in index order.  The
** first K of the merged sequence are the lowest K overall, whichever
** thread ran which chunk.
*/
#include <errno.h>
#include <math.h>
#include <omp.h>
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

#define CLI_RULE_MAX 64
#define CLI_RULE_CHUNK 1024           /* samples per scheduling unit */
#define CLI_RULE_BLOCK 64             /* chunks merged at a time */
#define CLI_RULE_WITNESS_MAX 100
#define CLI_RULE_QUAD_SALT 0x51A7C0DE5EEDF00Dull

/* Witness slots: types II, III, IV, V (type I needs none). */
#define CLI_RULE_WTYPES 4

typedef struct cli_rule_opts {
  uint64_t samples, seed, witnesses, quads, threads;
  double tie_eps;
  const char *svg_dir;
} cli_rule_opts;

typedef struct cli_rule_found {
  int n;
  uint64_t idx[CLI_RULE_WITNESS_MAX];
} cli_rule_found;

typedef struct cli_rule_quadcheck {
  uint64_t tested, disagree, ties, cocircular;
  uint64_t first;                     /* lowest disagreeing index, or UINT64_MAX */
} cli_rule_quadcheck;

static void cli_rule_usage(FILE *f) {
  fprintf(f,
          "usage: fliplab rule RULE... [--samples N] [--seed S] [--witnesses K] [--svg-dir DIR]\n"
          "                    [--quads M] [--tie-eps E] [--threads T]\n\n"
          "Tests each flip rule (MEASURE_JOINT, DT, or a plugin's rule) on N random convex\n"
          "pentagons (iteration method, default 100000) and M random convex quadrilaterals\n"
          "(default 100000): types I-V with 95%% Wilson intervals, agreement with Delaunay,\n"
          "verdicts, and up to K (default 3) witness pentagons per non-type-I outcome (lowest\n"
          "sample indices; the same for any --threads).  --svg-dir draws each witness's\n"
          "directed flip graph (thesis figure 3.7).  User measures: fliplab --define 'q = a*b*c'\n"
          "rule q_1; plugins: fliplab --plugin FILE.so rule NAME.\n");
}

/* ---- statistics ----------------------------------------------------------- */

/* 95% Wilson score interval of k successes in n, in percent. */
static void cli_rule_wilson(uint64_t k, uint64_t n, double *lo, double *hi) {
  if (n == 0) {
    *lo = 0;
    *hi = 100;
    return;
  }
  const double z = 1.959963984540054;
  double nn = (double)n, p = (double)k / nn, z2 = z * z;
  double den = 1 + z2 / nn;
  double centre = (p + z2 / (2 * nn)) / den;
  double half = z * sqrt(p * (1 - p) / nn + z2 / (4 * nn * nn)) / den;
  *lo = 100 * fmax(0, centre - half);
  *hi = 100 * fmin(1, centre + half);
}

static void cli_rule_pct_line(const char *label, uint64_t k, uint64_t n, const char *note) {
  double lo, hi;
  cli_rule_wilson(k, n, &lo, &hi);
  printf("  %-5s %10llu  %8.3f%%  [%.3f, %.3f]%s%s\n", label, (unsigned long long)k,
         n ? 100.0 * (double)k / (double)n : 0.0, lo, hi, note ? "  " : "", note ? note : "");
}

/* ---- pentagons: counts and witnesses ------------------------------------ */

static int cli_rule_wslot(flipgraph_type t) {
  return t == FLIPGRAPH_I ? -1 : (int)t - 1;
}

/* One chunk [lo, hi): counts into c[nrules], first K witnesses into
** w[nrules][CLI_RULE_WTYPES]. */
static void cli_rule_chunk(const flipgraph_plan *pl, int nrules, uint64_t seed, uint64_t lo,
                           uint64_t hi, int k, flipgraph_counts *c, cli_rule_found *w,
                           flipgraph *g) {
  geom_point v[5];
  flipgraph_pentagon p;
  for (uint64_t i = lo; i < hi; i++) {
    sampler_pentagon(seed, i, v);
    flipgraph_prepare(&p, v);
    flipgraph_plan_run(pl, &p, g);
    for (int r = 0; r < nrules; r++) {
      c[r].samples++;
      c[r].type[g[r].type]++;
      c[r].dt += g[r].delaunay;
      int s = cli_rule_wslot(g[r].type);
      if (s >= 0) {
        cli_rule_found *f = &w[r * CLI_RULE_WTYPES + s];
        if (f->n < k) f->idx[f->n++] = i;
      }
    }
  }
}

static int cli_rule_pentagons(const rule *rules, int nrules, const cli_rule_opts *o,
                              flipgraph_counts *counts, cli_rule_found *found) {
  flipgraph_plan *pl = flipgraph_plan_new(rules, nrules, o->tie_eps);
  if (pl == NULL) return -1;
  int k = (int)o->witnesses, threads = o->threads ? (int)o->threads : omp_get_max_threads();
  size_t per = (size_t)nrules * CLI_RULE_WTYPES;
  cli_rule_found *bw = calloc(CLI_RULE_BLOCK * per, sizeof *bw);
  flipgraph_counts *bc = calloc((size_t)CLI_RULE_BLOCK * (size_t)nrules, sizeof *bc);
  flipgraph *scratch = malloc((size_t)threads * (size_t)nrules * sizeof *scratch);
  if (bw == NULL || bc == NULL || scratch == NULL) {
    free(bw);
    free(bc);
    free(scratch);
    flipgraph_plan_free(pl);
    return -1;
  }
  cli_progress prog;
  cli_progress_start(&prog, "rule");
  uint64_t nchunks = (o->samples + CLI_RULE_CHUNK - 1) / CLI_RULE_CHUNK;
  for (uint64_t b0 = 0; b0 < nchunks; b0 += CLI_RULE_BLOCK) {
    int nb = (int)(nchunks - b0 < CLI_RULE_BLOCK ? nchunks - b0 : CLI_RULE_BLOCK);
    memset(bw, 0, (size_t)nb * per * sizeof *bw);
    memset(bc, 0, (size_t)nb * (size_t)nrules * sizeof *bc);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int q = 0; q < nb; q++) {
      uint64_t lo = (b0 + (uint64_t)q) * CLI_RULE_CHUNK;
      uint64_t hi = lo + CLI_RULE_CHUNK < o->samples ? lo + CLI_RULE_CHUNK : o->samples;
      cli_rule_chunk(pl, nrules, o->seed, lo, hi, k, bc + (size_t)q * (size_t)nrules,
                     bw + (size_t)q * per, scratch + (size_t)omp_get_thread_num() * (size_t)nrules);
    }
    /* Merge in chunk order: counts add, witnesses keep the first K. */
    for (int q = 0; q < nb; q++)
      for (int r = 0; r < nrules; r++) {
        const flipgraph_counts *c = &bc[(size_t)q * (size_t)nrules + (size_t)r];
        counts[r].samples += c->samples;
        for (int t = 0; t < FLIPGRAPH_NTYPES; t++) counts[r].type[t] += c->type[t];
        counts[r].dt += c->dt;
        for (int s = 0; s < CLI_RULE_WTYPES; s++) {
          const cli_rule_found *src = &bw[(size_t)q * per + (size_t)r * CLI_RULE_WTYPES + (size_t)s];
          cli_rule_found *dst = &found[(size_t)r * CLI_RULE_WTYPES + (size_t)s];
          for (int i = 0; i < src->n && dst->n < k; i++) dst->idx[dst->n++] = src->idx[i];
        }
      }
    uint64_t done = (b0 + (uint64_t)nb) * CLI_RULE_CHUNK;
    cli_progress_update(done < o->samples ? done : o->samples, o->samples, &prog);
  }
  cli_progress_finish(&prog);
  free(bw);
  free(bc);
  free(scratch);
  flipgraph_plan_free(pl);
  return 0;
}

/* ---- quadrilaterals: Delaunay equivalence ------------------------------- */

/* Quadrilateral i: four points uniform in the unit disc, drawn again until
** they are in strictly convex position, ordered anticlockwise from the one
** with the smallest angle about their centroid. */
static void cli_rule_quad(uint64_t seed, uint64_t i, geom_point q[4]) {
  sampler_rng g;
  sampler_seed(&g, seed ^ CLI_RULE_QUAD_SALT, i);
  for (;;) {
    double ang[4], cx = 0, cy = 0;
    for (int k = 0; k < 4; k++) {
      double x, y;
      do {
        x = 2 * sampler_uniform(&g) - 1;
        y = 2 * sampler_uniform(&g) - 1;
      } while (x * x + y * y >= 1);
      q[k] = (geom_point){x, y};
      cx += x / 4;
      cy += y / 4;
    }
    for (int k = 0; k < 4; k++) ang[k] = atan2(q[k].y - cy, q[k].x - cx);
    for (int a = 1; a < 4; a++)
      for (int b = a; b > 0 && ang[b] < ang[b - 1]; b--) {
        double t = ang[b];
        ang[b] = ang[b - 1];
        ang[b - 1] = t;
        geom_point p = q[b];
        q[b] = q[b - 1];
        q[b - 1] = p;
      }
    int ok = 1;
    for (int k = 0; k < 4; k++) ok &= geom_orient(q[k], q[(k + 1) % 4], q[(k + 2) % 4]) > 0;
    if (ok) return;
  }
}

static void cli_rule_quads(const rule *r, const cli_rule_opts *o, cli_rule_quadcheck *out) {
  rule dt = rule_delaunay();
  uint64_t dis = 0, ties = 0, coc = 0, first = UINT64_MAX;
  int threads = o->threads ? (int)o->threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 4096) num_threads(threads) \
    reduction(+ : dis, ties, coc) reduction(min : first)
  for (uint64_t i = 0; i < o->quads; i++) {
    geom_point q[4];
    cli_rule_quad(o->seed, i, q);
    rule_choice d = rule_eval(&dt, q, o->tie_eps, NULL, NULL);
    if (d == RULE_EITHER) {
      coc++;
      continue;
    }
    rule_choice c = rule_eval(r, q, o->tie_eps, NULL, NULL);
    if (c == RULE_EITHER) {
      ties++;
    } else if (c != d) {
      dis++;
      if (i < first) first = i;
    }
  }
  *out = (cli_rule_quadcheck){o->quads, dis, ties, coc, first};
}

/* ---- printing --------------------------------------------------------------- */

static void cli_rule_describe(const rule *r) {
  if (r->kind == RULE_QUAD) {
    printf("rule %s: quadrilateral rule: %s\n", r->name, rule_quad_get(r->quad)->desc);
    return;
  }
  const measure *m = measure_get(r->measure);
  const char *expr = formula_expr(r->measure);
  printf("rule %s: measure %s (%s%s), joint %s (%s)\n", r->name, m->name,
         expr ? "formula " : "", expr ? expr : m->desc, joint_get(r->joint)->name,
         joint_get(r->joint)->symbol);
}

/* A type-V pentagon says nothing about systematicity or locality, so the
** "no counterexample" claims count only the pentagons of types I-IV. */
/* "1 pentagon", "2 pentagons". */
static const char *cli_rule_s(unsigned long long n) {
  return n == 1 ? "" : "s";
}

static void cli_rule_verdicts(const rule *r, const flipgraph_counts *c) {
  unsigned long long n = c->samples;
  unsigned long long t2 = c->type[FLIPGRAPH_II], t3 = c->type[FLIPGRAPH_III];
  unsigned long long t4 = c->type[FLIPGRAPH_IV], t5 = c->type[FLIPGRAPH_V];
  unsigned long long decided = n - t5;
  const char *of = t5 ? " of types I-IV" : "";
  if (t3) printf("  verdict: not systematic: %llu counterexample%s (type III, two LOTs)\n", t3,
                 cli_rule_s(t3));
  else printf("  verdict: no counterexample to systematicity in %llu pentagons%s (no type III)\n",
              decided, of);
  if (t2) printf("  verdict: not local: %llu counterexample%s (type II)\n", t2, cli_rule_s(t2));
  else printf("  verdict: no counterexample to locality in %llu pentagons%s (no type II)\n",
              decided, of);
  if (t4 && r->kind == RULE_TRIANGLE)
    printf("  verdict: BUG: %llu pentagons without a sink (type IV), impossible for a "
           "triangle-based rule (thesis theorem 1)\n", t4);
  else if (t4)
    printf("  verdict: no LOT exists on %llu pentagon%s (type IV, no sink)\n", t4, cli_rule_s(t4));
  if (t5)
    printf("  verdict: returns either on %llu pentagon%s (type V): ties within tie_eps, which a "
           "good rule hits with probability zero\n", t5, cli_rule_s(t5));
  if (n > 0 && c->dt == n)
    printf("  verdict: agrees with Delaunay on all %llu pentagons\n", n);
}

static void cli_rule_quad_report(const rule *r, const cli_rule_opts *o,
                                 const cli_rule_quadcheck *qc) {
  if (o->quads == 0) return;
  printf("  Delaunay equivalence on %llu random convex quadrilaterals: %llu disagreements, "
         "%llu ties (either), %llu cocircular skipped\n",
         (unsigned long long)qc->tested, (unsigned long long)qc->disagree,
         (unsigned long long)qc->ties, (unsigned long long)qc->cocircular);
  if (qc->disagree == 0 && qc->ties == 0) {
    printf("  verdict: no counterexample to Delaunay equivalence in %llu quadrilaterals\n",
           (unsigned long long)(qc->tested - qc->cocircular));
    return;
  }
  if (qc->disagree == 0) {
    printf("  verdict: not Delaunay-equivalent: either on %llu quadrilaterals where Delaunay "
           "decides (no opposite choice on the other %llu)\n",
           (unsigned long long)qc->ties,
           (unsigned long long)(qc->tested - qc->cocircular - qc->ties));
    return;
  }
  geom_point q[4];
  cli_rule_quad(o->seed, qc->first, q);
  double ac, bd;
  rule dt = rule_delaunay();
  rule_choice c = rule_eval(r, q, o->tie_eps, &ac, &bd);
  rule_choice d = rule_eval(&dt, q, o->tie_eps, NULL, NULL);
  printf("  verdict: not Delaunay-equivalent; first disagreement, quadrilateral #%llu "
         "ABCD = %.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g: rule %s, DT %s",
         (unsigned long long)qc->first, q[0].x, q[0].y, q[1].x, q[1].y, q[2].x, q[2].y, q[3].x,
         q[3].y, rule_choice_str(c), rule_choice_str(d));
  if (r->kind == RULE_TRIANGLE) printf(" (F_AC = %.17g, F_BD = %.17g)", ac, bd);
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
  char cap[1024];
  snprintf(cap, sizeof cap,
           "rule %s: type %s, pentagon #%llu of seed %llu (tie_eps %g)\n"
           "v0 = (%.17g, %.17g)   v1 = (%.17g, %.17g)\n"
           "v2 = (%.17g, %.17g)   v3 = (%.17g, %.17g)\n"
           "v4 = (%.17g, %.17g)\n"
           "arrows point to the preferred triangulation; T_i = fan at v_i",
           r->name, flipgraph_type_name(g->type), (unsigned long long)idx,
           (unsigned long long)o->seed, o->tie_eps, p->v[0].x, p->v[0].y, p->v[1].x, p->v[1].y,
           p->v[2].x, p->v[2].y, p->v[3].x, p->v[3].y, p->v[4].x, p->v[4].y);
  report_flipgraph_svg(f, p, g, cap);
  return cli_close_out(f) != 0 ? 1 : 0;
}

/* Witnesses are re-derived from their index with the one-rule reference
** path (flipgraph_classify), which must agree with the fast plan. */
static int cli_rule_witnesses(const rule *r, const cli_rule_opts *o, const cli_rule_found *w) {
  int any = 0;
  for (int s = 0; s < CLI_RULE_WTYPES; s++) any |= w[s].n > 0;
  if (!any || o->witnesses == 0) return 0;
  printf("  witnesses (lowest sample indices; decisions of Q0..Q4, A = diagonal v_{j+1}v_{j+3} "
         "of Q_j, B = v_{j+2}v_{j+4}, E = either; sinks T_i = fan at v_i):\n");
  for (int s = 0; s < CLI_RULE_WTYPES; s++)
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

static void cli_rule_print(const rule *r, const cli_rule_opts *o, const flipgraph_counts *c) {
  static const char *const note[FLIPGRAPH_NTYPES] = {
    "one sink, systematic and local here", "one sink, not local", "two sinks, not systematic",
    "no sink", "either returned"};
  cli_rule_describe(r);
  printf("  %llu pentagons (iteration method, seed %llu), tie_eps %g; 95%% Wilson intervals\n",
         (unsigned long long)c->samples, (unsigned long long)o->seed, o->tie_eps);
  printf("  %-5s %10s  %9s  %s\n", "type", "count", "percent", "95% interval");
  for (int t = 0; t < FLIPGRAPH_NTYPES; t++)
    cli_rule_pct_line(flipgraph_type_name((flipgraph_type)t), c->type[t], c->samples, note[t]);
  cli_rule_pct_line("DT", c->dt, c->samples, "type I with sink = Delaunay triangulation");
}

/* ---- the command ------------------------------------------------------------- */

static int cli_rule_parse(int argc, char **argv, cli_rule_opts *o, rule *rules, int *nrules) {
  *o = (cli_rule_opts){100000, 1, 3, 100000, 0, RULE_DEFAULT_TIE_EPS, NULL};
  *nrules = 0;
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i], *v;
    if (strncmp(a, "--", 2) != 0 || strcmp(a, "--") == 0) {
      char err[4096];
      if (*nrules >= CLI_RULE_MAX) return cli_error("rule", "at most %d rules", CLI_RULE_MAX);
      if (rule_parse(a, &rules[*nrules], err, sizeof err) != 0) return cli_error("rule", "%s", err);
      (*nrules)++;
      continue;
    }
    if ((v = cli_optarg("rule", argc, argv, &i)) == NULL) return 2;
    if (strcmp(a, "--samples") == 0) {
      if (cli_parse_u64("rule", a, v, 1, 1ull << 40, &o->samples)) return 2;
    } else if (strcmp(a, "--seed") == 0) {
      if (cli_parse_u64("rule", a, v, 0, UINT64_MAX, &o->seed)) return 2;
    } else if (strcmp(a, "--witnesses") == 0) {
      if (cli_parse_u64("rule", a, v, 0, CLI_RULE_WITNESS_MAX, &o->witnesses)) return 2;
    } else if (strcmp(a, "--quads") == 0) {
      if (cli_parse_u64("rule", a, v, 0, 1ull << 40, &o->quads)) return 2;
    } else if (strcmp(a, "--threads") == 0) {
      if (cli_parse_u64("rule", a, v, 0, 1024, &o->threads)) return 2;
    } else if (strcmp(a, "--tie-eps") == 0) {
      if (cli_parse_double("rule", a, v, 0, 1e-3, &o->tie_eps)) return 2;
    } else if (strcmp(a, "--svg-dir") == 0) {
      o->svg_dir = v;
    } else {
      return cli_error("rule", "unknown option '%s' (try: fliplab rule --help)", a);
    }
  }
  if (*nrules == 0) return cli_error("rule", "no rule given (try: fliplab rule --help)");
  return 0;
}

int cli_cmd_rule(int argc, char **argv) {
  for (int i = 1; i < argc; i++)
    if (cli_is_help(argv[i])) {
      cli_rule_usage(stdout);
      return 0;
    }
  static rule rules[CLI_RULE_MAX];
  cli_rule_opts o;
  int nrules, rc = cli_rule_parse(argc, argv, &o, rules, &nrules);
  if (rc != 0) return rc;
  if (o.svg_dir != NULL && mkdir(o.svg_dir, 0777) != 0 && errno != EEXIST)
    return cli_error("rule", "cannot create --svg-dir '%s': %s", o.svg_dir, strerror(errno));

  flipgraph_counts *counts = calloc((size_t)nrules, sizeof *counts);
  cli_rule_found *found = calloc((size_t)nrules * CLI_RULE_WTYPES, sizeof *found);
  cli_rule_quadcheck *qc = calloc((size_t)nrules, sizeof *qc);
  if (counts == NULL || found == NULL || qc == NULL ||
      cli_rule_pentagons(rules, nrules, &o, counts, found) != 0) {
    free(counts);
    free(found);
    free(qc);
    fprintf(stderr, "fliplab rule: out of memory\n");
    return 1;
  }
  for (int r = 0; r < nrules; r++) cli_rule_quads(&rules[r], &o, &qc[r]);
  if (cli_userdefs_failed("rule")) {
    rc = 1;
    goto out;
  }
  for (int r = 0; r < nrules && rc == 0; r++) {
    if (r > 0) printf("\n");
    cli_rule_print(&rules[r], &o, &counts[r]);
    cli_rule_verdicts(&rules[r], &counts[r]);
    cli_rule_quad_report(&rules[r], &o, &qc[r]);
    rc = cli_rule_witnesses(&rules[r], &o, &found[(size_t)r * CLI_RULE_WTYPES]);
  }
  if (rc == 0 && cli_userdefs_failed("rule")) rc = 1;
out:
  fflush(stdout);
  free(counts);
  free(found);
  free(qc);
  return rc;
}
