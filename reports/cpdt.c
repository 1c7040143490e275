/*
** cpdt.c: the files of `fliplab cpdt`: the experiment's CSV table and its
** log-log plots with fitted slopes (thesis figures 5.4-5.13), hand-written
** SVG.
*/
#include <math.h>
#include <stdio.h>
#include "report_internal.h"

int report_cpdt_csv(FILE *f, const char *sampler, uint64_t trials, const study_cpdt_cell *cells,
                    size_t ncells) {
  enum { NF = 4 + 2 * STUDY_CPDT_NCOUNTS };
  char buf[NF][48], half[STUDY_CPDT_NCOUNTS][48];
  const char *fld[NF] = {"sampler", "n", "algorithm", "trials"};
  for (int k = 0; k < STUDY_CPDT_NCOUNTS; k++) {
    snprintf(half[k], sizeof half[k], "%s_half", study_cpdt_count_name(k));
    fld[4 + 2 * k] = study_cpdt_count_name(k);
    fld[5 + 2 * k] = half[k];
  }
  int rc = report_csv_row(f, fld, NF);
  for (size_t i = 0; i < ncells && rc == 0; i++) {
    const study_cpdt_cell *c = &cells[i];
    fld[0] = sampler;
    snprintf(buf[1], sizeof buf[1], "%llu", (unsigned long long)c->n);
    fld[1] = buf[1];
    fld[2] = cpdt_algorithm_name(c->algorithm);
    snprintf(buf[3], sizeof buf[3], "%llu", (unsigned long long)trials);
    fld[3] = buf[3];
    for (int k = 0; k < STUDY_CPDT_NCOUNTS; k++) {
      snprintf(buf[4 + 2 * k], sizeof buf[0], "%.10g", c->mean[k]);
      snprintf(buf[5 + 2 * k], sizeof buf[0], "%.10g", c->half[k]);
      fld[4 + 2 * k] = buf[4 + 2 * k];
      fld[5 + 2 * k] = buf[5 + 2 * k];
    }
    rc = report_csv_row(f, fld, NF);
  }
  return rc;
}

/* Whole decades round every positive mean. */
static report_loglog cp_range(const study_cpdt_cell *cells, size_t ncells, int count) {
  double nlo = INFINITY, nhi = 0, vlo = INFINITY, vhi = 0;
  for (size_t i = 0; i < ncells; i++) {
    double v = cells[i].mean[count], n = (double)cells[i].n;
    if (!(v > 0)) continue;
    nlo = fmin(nlo, n), nhi = fmax(nhi, n), vlo = fmin(vlo, v), vhi = fmax(vhi, v);
  }
  return report_loglog_range(nlo, nhi, vlo, vhi);
}

/* One algorithm's line, markers and legend entry (slope). */
static void cp_series(FILE *f, const report_loglog *a, const study_cpdt_cell *cells,
                      size_t ncells, int algorithm, int count, int slot) {
  double x[64], y[64];
  size_t k = 0;
  for (size_t i = 0; i < ncells && k < 64; i++)
    if (cells[i].algorithm == algorithm && cells[i].mean[count] > 0)
      x[k] = (double)cells[i].n, y[k++] = cells[i].mean[count];
  double s = study_cpdt_slope(cells, ncells, algorithm, count);
  char lab[64];
  snprintf(lab, sizeof lab, isnan(s) ? "%s" : "%s  slope %.2f", cpdt_algorithm_name(algorithm), s);
  report_loglog_series(f, a, x, y, k, slot, lab);
}

int report_cpdt_svg(FILE *f, const char *title, const study_cpdt_cell *cells, size_t ncells,
                    const int *algorithms, size_t nalgorithms, int count) {
  if (count < 0 || count >= STUDY_CPDT_NCOUNTS) return -1;
  report_loglog a = cp_range(cells, ncells, count);
  char ylabel[64];
  snprintf(ylabel, sizeof ylabel, "mean %s (log scale)", study_cpdt_count_name(count));
  report_loglog_frame(f, &a, title, "vertices n (log scale)", ylabel);
  for (size_t k = 0; k < nalgorithms; k++)
    cp_series(f, &a, cells, ncells, algorithms[k], count, (int)k);
  fprintf(f, "</svg>\n");
  return ferror(f) ? -1 : 0;
}
