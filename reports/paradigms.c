/*
** paradigms.c: the files of `fliplab paradigms`, table 2.4 anew: the
** matrix as CSV, as a Markdown table, and one count against n as a
** log-log plot (study_paradigms.h).
*/
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "report_internal.h"
#include "paradigm.h"

/* The cell of (a, r, f, s), as study_paradigms.h lays them out. */
static const study_paradigms_cell *rp_cell(const study_paradigms_plan *pl,
                                           const study_paradigms_cell *cells, size_t a,
                                           size_t r, size_t f, size_t s) {
  return &cells[((a * pl->nrules + r) * pl->nfamilies + f) * pl->nsizes + s];
}

/* The fixed columns, the counts per site and growth exponents, the problem. */
enum { RP_FIXED = 10, RP_PROBLEM = RP_FIXED + 2 * OPS_COUNT + 1, RP_NF = RP_PROBLEM + 1 };

static int rp_header(FILE *f) {
  static const char *fixed[RP_FIXED] = {"algorithm", "paradigm", "section", "rule", "family",
                                        "n", "distinct", "triangles", "status", "seconds"};
  char names[2 * OPS_COUNT][40];
  const char *fld[RP_NF];
  memcpy(fld, fixed, sizeof fixed);
  for (int k = 0; k < OPS_COUNT; k++) {
    snprintf(names[k], sizeof names[k], "%s_per_site", ops_name(k));
    snprintf(names[OPS_COUNT + k], sizeof names[0], "growth_%s", ops_name(k));
    fld[RP_FIXED + k] = names[k];
    fld[RP_FIXED + OPS_COUNT + 1 + k] = names[OPS_COUNT + k];
  }
  fld[RP_FIXED + OPS_COUNT] = "growth_seconds";
  fld[RP_PROBLEM] = "problem";
  return report_csv_row(f, fld, RP_NF);
}

/* "%.10g", or empty for NaN. */
static const char *rp_num(char *buf, size_t len, double v) {
  if (isnan(v)) buf[0] = '\0';
  else snprintf(buf, len, "%.10g", v);
  return buf;
}

static int rp_row(FILE *f, const study_paradigms_plan *pl, const study_paradigms_cell *cells,
                  size_t a, size_t r, size_t fa, size_t s) {
  const study_paradigms_cell *c = rp_cell(pl, cells, a, r, fa, s);
  const paradigm_algorithm *alg = paradigm_get(c->algorithm);
  char buf[RP_NF][48], status[STUDY_PARADIGMS_WHY + 16];
  const char *fld[RP_NF] = {alg->name, alg->paradigm, alg->section, pl->rules[r].name,
                            study_paradigms_family_name(pl->problem, c->family)};
  snprintf(buf[5], sizeof buf[5], "%llu", (unsigned long long)c->n);
  snprintf(buf[6], sizeof buf[6], "%zu", c->distinct);
  snprintf(buf[7], sizeof buf[7], "%zu", c->triangles);
  snprintf(status, sizeof status, c->refused == 1 ? "refused: %s" : c->refused ? "failed: %s"
                                                                          : "ok", c->why);
  fld[5] = buf[5], fld[6] = buf[6], fld[7] = buf[7], fld[8] = status;
  fld[9] = rp_num(buf[9], sizeof buf[9], c->refused ? NAN : c->seconds);
  for (int k = 0; k <= OPS_COUNT; k++) {   /* k = OPS_COUNT: growth_seconds */
    int i = RP_FIXED + k, j = RP_FIXED + (k < OPS_COUNT ? OPS_COUNT + 1 + k : OPS_COUNT);
    if (k < OPS_COUNT) fld[i] = rp_num(buf[i], sizeof buf[i], c->refused ? NAN : c->per_site[k]);
    fld[j] = rp_num(buf[j], sizeof buf[j], study_paradigms_growth(pl, cells, a, r, fa, k));
  }
  fld[RP_PROBLEM] = paradigm_problem_name(pl->problem);
  return report_csv_row(f, fld, RP_NF);
}

int report_paradigms_csv(FILE *f, const study_paradigms_plan *pl,
                         const study_paradigms_cell *cells) {
  int rc = rp_header(f);
  for (size_t r = 0; r < pl->nrules; r++)
    for (size_t fa = 0; fa < pl->nfamilies; fa++)
      for (size_t a = 0; a < pl->nalgorithms; a++)
        for (size_t s = 0; s < pl->nsizes && rc == 0; s++) rc = rp_row(f, pl, cells, a, r, fa, s);
  return rc != 0 || ferror(f) ? -1 : 0;
}

/* The counts the Markdown table shows per site. */
static const ops_kind rp_md_counts[] = {OPS_ORIENT, OPS_INCIRCLE, OPS_INSHAPE, OPS_FLIPS,
                                        OPS_LOCATE, OPS_EVENTS};
#define RP_MD_N (sizeof rp_md_counts / sizeof rp_md_counts[0])

static void rp_md_head(FILE *f, const study_paradigms_plan *pl) {
  fprintf(f, "| algorithm | paradigm | rule | points |");
  for (size_t s = 0; s < pl->nsizes; s++)
    fprintf(f, " ms n=%llu |", (unsigned long long)pl->sizes[s]);
  fprintf(f, " growth |");
  for (size_t k = 0; k < RP_MD_N; k++) fprintf(f, " %s/site |", ops_name(rp_md_counts[k]));
  fprintf(f, "\n|---|---|---|---|");
  for (size_t s = 0; s < pl->nsizes + 1 + RP_MD_N; s++) fprintf(f, "---:|");
  fprintf(f, "\n");
}

static void rp_md_row(FILE *f, const study_paradigms_plan *pl, const study_paradigms_cell *cells,
                      size_t a, size_t r, size_t fa) {
  const study_paradigms_cell *last = rp_cell(pl, cells, a, r, fa, pl->nsizes - 1);
  const paradigm_algorithm *alg = paradigm_get(last->algorithm);
  fprintf(f, "| %s | %s | %s | %s |", alg->name, alg->paradigm, pl->rules[r].name,
          study_paradigms_family_name(pl->problem, last->family));
  const study_paradigms_cell *bad = NULL;   /* the first refused or failed size */
  for (size_t s = 0; s < pl->nsizes && bad == NULL; s++)
    if (rp_cell(pl, cells, a, r, fa, s)->refused) bad = rp_cell(pl, cells, a, r, fa, s);
  if (bad != NULL) {
    if (bad->refused == 1) fprintf(f, " refused: %s |", bad->why);
    else fprintf(f, " failed at n=%llu: %s |", (unsigned long long)bad->n, bad->why);
    for (size_t s = 1; s < pl->nsizes + 1 + RP_MD_N; s++) fprintf(f, " |");
    fprintf(f, "\n");
    return;
  }
  for (size_t s = 0; s < pl->nsizes; s++)
    fprintf(f, " %.3g |", 1e3 * rp_cell(pl, cells, a, r, fa, s)->seconds);
  double g = study_paradigms_growth(pl, cells, a, r, fa, OPS_COUNT);
  if (isnan(g)) fprintf(f, " - |");
  else fprintf(f, " %.2f |", g);
  for (size_t k = 0; k < RP_MD_N; k++) fprintf(f, " %.2f |", last->per_site[rp_md_counts[k]]);
  fprintf(f, "\n");
}

int report_paradigms_md(FILE *f, const study_paradigms_plan *pl,
                        const study_paradigms_cell *cells) {
  rp_md_head(f, pl);
  for (size_t r = 0; r < pl->nrules; r++)
    for (size_t fa = 0; fa < pl->nfamilies; fa++)
      for (size_t a = 0; a < pl->nalgorithms; a++) rp_md_row(f, pl, cells, a, r, fa);
  return ferror(f) ? -1 : 0;
}

/* The plotted value of a cell: count k per site, or the seconds. */
static double rp_value(const study_paradigms_cell *c, int k) {
  return c->refused ? 0 : k == OPS_COUNT ? c->seconds : c->per_site[k];
}

int report_paradigms_svg(FILE *f, const char *title, const study_paradigms_plan *pl,
                         const study_paradigms_cell *cells, int k) {
  if (k < 0 || k > OPS_COUNT || pl->nsizes > 64) return -1;
  double nlo = INFINITY, nhi = 0, vlo = INFINITY, vhi = 0;
  for (size_t a = 0; a < pl->nalgorithms; a++)
    for (size_t s = 0; s < pl->nsizes; s++) {
      const study_paradigms_cell *c = rp_cell(pl, cells, a, 0, 0, s);
      double v = rp_value(c, k), n = (double)c->n;
      if (v > 0) nlo = fmin(nlo, n), nhi = fmax(nhi, n), vlo = fmin(vlo, v), vhi = fmax(vhi, v);
    }
  report_loglog ax = report_loglog_range(nlo, nhi, vlo, vhi);
  char ylabel[64];
  snprintf(ylabel, sizeof ylabel, k == OPS_COUNT ? "seconds (log scale)"
                                                 : "%s per site (log scale)", ops_name(k));
  report_loglog_frame(f, &ax, title, "points n (log scale)", ylabel);
  for (size_t a = 0; a < pl->nalgorithms; a++) {
    double x[64], y[64];
    size_t m = 0;
    study_slope sl = {0};
    for (size_t s = 0; s < pl->nsizes; s++) {
      const study_paradigms_cell *c = rp_cell(pl, cells, a, 0, 0, s);
      if (rp_value(c, k) > 0) x[m] = (double)c->n, y[m++] = rp_value(c, k);
      if (rp_value(c, k) > 0) study_slope_add(&sl, (double)c->n, rp_value(c, k));
    }
    char lab[96];
    double g = study_slope_get(&sl);
    const char *name = paradigm_get(pl->algorithms[a])->name;
    snprintf(lab, sizeof lab, isnan(g) ? "%s" : "%s  slope %.2f", name, g);
    report_loglog_series(f, &ax, x, y, m, (int)a, lab);
  }
  fprintf(f, "</svg>\n");
  return ferror(f) ? -1 : 0;
}
