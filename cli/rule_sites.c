/*
** rule_sites.c: the verdicts of `fliplab rule` beyond convex pentagons.
** Convex pentagons cannot show every failure (thesis section 3.5: -R_1 is
** type I on every pentagon yet has two LOTs on a square with a site
** inside, figure 3.8), so each rule also runs the census on other site
** sets, by default five-site disc sets (most have an interior site) and
** convex hexagons (section 7.3's next step), and the first set with two
** or more sinks is printed as a witness that `fliplab flipgraph` reads
** back bit for bit.  The census and the witness are the library's
** (study_sites); this file parses --sites and words them.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "report.h"
#include "rule.h"
#include "sampler.h"
#include "siteflip.h"
#include "study.h"

#define CLI_SITES_MAX 8

typedef struct cli_site_spec {
  int sampler, n;
} cli_site_spec;

/* "disc:5,convex:6" (or "none") into specs; count, or -1 after the error. */
static int cli_sites_parse(const char *s, cli_site_spec *spec) {
  if (strcmp(s, "none") == 0) return 0;
  int k = 0;
  for (const char *p = s;;) {
    const char *comma = strchr(p, ','), *colon = strchr(p, ':');
    size_t len = comma ? (size_t)(comma - p) : strlen(p);
    char name[32];
    if (colon == NULL || colon > p + len || (size_t)(colon - p) >= sizeof name || k == CLI_SITES_MAX)
      return cli_error("rule", "--sites expects SAMPLER:N,... (e.g. disc:5,convex:6) or none, "
                               "got '%s'", s), -1;
    memcpy(name, p, (size_t)(colon - p));
    name[colon - p] = '\0';
    char num[16];
    size_t nl = len - (size_t)(colon - p) - 1;
    if (nl == 0 || nl >= sizeof num)
      return cli_error("rule", "--sites: '%.*s' needs a site count", (int)len, p), -1;
    memcpy(num, colon + 1, nl);
    num[nl] = '\0';
    uint64_t n;
    if ((spec[k].sampler = sampler_sites_find(name)) < 0)
      return cli_error("rule", "--sites: unknown sampler '%s' (valid: convex, disc, square, "
                               "normal)", name), -1;
    if (cli_parse_u64("rule", "--sites N", num, 3, SITEFLIP_MAX_SITES, &n) != 0) return -1;
    spec[k++].n = (int)n;
    if (comma == NULL) break;
    p = comma + 1;
  }
  return k;
}

int cli_rule_sites_check(const char *spec) {
  cli_site_spec s[CLI_SITES_MAX];
  return cli_sites_parse(spec, s) < 0 ? 2 : 0;
}

/* "convex hexagons", "five-site disc sets", "9-site normal sets". */
static void cli_sites_words(char *buf, size_t len, const cli_site_spec *s) {
  static const char *const gon[] = {"", "", "", "triangles", "quadrilaterals", "pentagons",
                                    "hexagons", "heptagons", "octagons", "nonagons",
                                    "decagons", "11-gons", "12-gons", "13-gons", "14-gons",
                                    "15-gons", "16-gons"};
  static const char *const num[] = {"", "", "", "three", "four", "five", "six", "seven",
                                    "eight", "nine", "ten", "eleven", "twelve", "thirteen",
                                    "fourteen", "fifteen", "sixteen"};
  _Static_assert(sizeof gon / sizeof *gon == SITEFLIP_MAX_SITES + 1, "a name per site count");
  _Static_assert(sizeof num / sizeof *num == SITEFLIP_MAX_SITES + 1, "a name per site count");
  if (s->sampler == SAMPLER_SITES_CONVEX) snprintf(buf, len, "convex %s", gon[s->n]);
  else snprintf(buf, len, "%s-site %s sets", num[s->n], sampler_sites_name(s->sampler));
}

/* The witness: its sites in one line, and with --svg-dir its CSV (for
** `fliplab flipgraph --points`) and its directed flip graph. */
static int cli_sites_witness(const rule *r, const cli_site_spec *s, int64_t idx,
                             const geom_point *p, double tie_eps, const char *svg_dir) {
  printf("    witness: set #%lld:", (long long)idx);
  for (int i = 0; i < s->n; i++) printf(" %.17g,%.17g", p[i].x, p[i].y);
  printf("\n");
  if (svg_dir == NULL) return 0;
  char base[4096], path[4200];
  snprintf(base, sizeof base, "%s/%s-%s%d-%lld", svg_dir, r->name, sampler_sites_name(s->sampler),
           s->n, (long long)idx);
  for (char *c = base + strlen(svg_dir) + 1; *c; c++)
    if (*c == '/') *c = '_';   /* a rule name like -r/R_1 */
  snprintf(path, sizeof path, "%s.csv", base);
  FILE *f = cli_open_out("rule", path);
  if (f == NULL) return 1;
  fprintf(f, "x,y\n");
  for (int i = 0; i < s->n; i++) fprintf(f, "%.17g,%.17g\n", p[i].x, p[i].y);
  if (cli_close_out(f) != 0) return 1;
  printf("      csv: %s (fliplab flipgraph --rule %s --points %s)\n", path, r->name, path);
  char err[256];
  siteflip_graph *g = siteflip_build(p, s->n, err, sizeof err);
  rule_choice *dec = g ? malloc(((size_t)g->nquads + 1) * sizeof *dec) : NULL;
  siteflip_result res;
  int rc = 1;
  if (dec != NULL && siteflip_direct(g, r, tie_eps, dec, NULL, &res) == 0 &&
      g->nnodes <= REPORT_SITEFLIP_SVG_MAX) {
    snprintf(path, sizeof path, "%s.svg", base);
    if ((f = cli_open_out("rule", path)) != NULL) {
      char cap[RULE_NAME_MAX + 128];
      snprintf(cap, sizeof cap, "rule %s: %d triangulations, %d sinks (set #%lld)", r->name,
               g->nnodes, res.nsinks, (long long)idx);
      report_siteflip_svg(f, g, dec, cap);
      rc = cli_close_out(f) != 0;
      if (rc == 0) printf("      svg: %s\n", path);
    }
  } else if (dec != NULL) {
    rc = 0;   /* too many triangulations to draw */
  }
  free(dec);
  siteflip_free(g);
  return rc;
}

static int cli_sites_one(const rule *r, const cli_site_spec *s, uint64_t samples, uint64_t seed,
                         double tie_eps, int threads, const char *svg_dir) {
  study_sitecheck c;
  char err[256], what[64];
  if (study_sites(r, s->sampler, s->n, seed, samples, tie_eps, threads, &c, err, sizeof err) != 0)
    return cli_error("rule", "%s", err), 1;
  cli_sites_words(what, sizeof what, s);
  unsigned long long m = c.counts.samples, tie = c.counts.tie, none = c.counts.no_sink;
  if (!c.systematic) {
    printf("  verdict: not systematic: %llu %s with two or more LOTs among %llu %s%s\n",
           (unsigned long long)c.counts.multi_sink, strchr(what, ' ') + 1, m, what,
           s->sampler != SAMPLER_SITES_CONVEX && s->n == 5 ? " (figure 3.8's kind)" : "");
    if (c.has_witness && cli_sites_witness(r, s, (int64_t)c.witness, c.sites, tie_eps, svg_dir))
      return 1;
  } else {
    printf("  verdict: no counterexample to systematicity in %llu %s%s (no set with two LOTs)\n",
           (unsigned long long)c.decided, what, tie ? " without a tie" : "");
  }
  if (none > 0)
    printf("  verdict: no LOT at all on %llu of the %llu %s (no sink)\n", none, m, what);
  if (tie > 0) printf("  verdict: returns either on %llu of the %llu %s\n", tie, m, what);
  return 0;
}

int cli_rule_sites(const rule *r, const char *spec, uint64_t samples, uint64_t seed,
                   double tie_eps, int threads, const char *svg_dir) {
  cli_site_spec s[CLI_SITES_MAX];
  int k = cli_sites_parse(spec, s);
  if (k < 0) return 2;
  for (int i = 0; i < k; i++)
    if (cli_sites_one(r, &s[i], samples, seed, tie_eps, threads, svg_dir) != 0) return 1;
  return 0;
}
