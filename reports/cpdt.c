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

/* Canvas, plot area (pixels); one colour per algorithm. */
enum { CP_W = 640, CP_H = 480, CP_X0 = 70, CP_Y0 = 40, CP_PW = 380, CP_PH = 380 };
static const char *const report_cpdt_colours[] = {
  "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf",
};

typedef struct cp_axes { double x0, x1, y0, y1; } cp_axes;   /* log10 ranges */

static double cp_px(const cp_axes *a, double n) {
  return CP_X0 + (log10(n) - a->x0) / (a->x1 - a->x0) * CP_PW;
}
static double cp_py(const cp_axes *a, double v) {
  return CP_Y0 + CP_PH - (log10(v) - a->y0) / (a->y1 - a->y0) * CP_PH;
}

/* Whole decades round every positive mean. */
static cp_axes cp_range(const study_cpdt_cell *cells, size_t ncells, int count) {
  double nlo = INFINITY, nhi = 0, vlo = INFINITY, vhi = 0;
  for (size_t i = 0; i < ncells; i++) {
    double v = cells[i].mean[count], n = (double)cells[i].n;
    if (!(v > 0)) continue;
    nlo = fmin(nlo, n), nhi = fmax(nhi, n), vlo = fmin(vlo, v), vhi = fmax(vhi, v);
  }
  if (nhi == 0) return (cp_axes){0, 1, 0, 1};
  cp_axes a = {floor(log10(nlo)), ceil(log10(nhi)), floor(log10(vlo)), ceil(log10(vhi))};
  if (a.x1 <= a.x0) a.x1 = a.x0 + 1;
  if (a.y1 <= a.y0) a.y1 = a.y0 + 1;
  return a;
}

static void cp_frame(FILE *f, const cp_axes *a, const char *title, const char *ylabel) {
  fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
             "font-family=\"sans-serif\">\n"
             "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n", CP_W, CP_H);
  fprintf(f, "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" "
             "stroke=\"black\"/>\n", CP_X0, CP_Y0, CP_PW, CP_PH);
  char lab[32];
  for (double e = a->x0; e <= a->x1; e++) {
    double x = CP_X0 + (e - a->x0) / (a->x1 - a->x0) * CP_PW;
    snprintf(lab, sizeof lab, "1e%g", e);
    fprintf(f, "<line x1=\"%.2f\" y1=\"%d\" x2=\"%.2f\" y2=\"%d\" stroke=\"#ccc\"/>\n", x, CP_Y0,
            x, CP_Y0 + CP_PH);
    report_svg_text(f, x - 12, CP_Y0 + CP_PH + 16, 11, lab);
  }
  for (double e = a->y0; e <= a->y1; e++) {
    double y = CP_Y0 + CP_PH - (e - a->y0) / (a->y1 - a->y0) * CP_PH;
    snprintf(lab, sizeof lab, "1e%g", e);
    fprintf(f, "<line x1=\"%d\" y1=\"%.2f\" x2=\"%d\" y2=\"%.2f\" stroke=\"#ccc\"/>\n", CP_X0, y,
            CP_X0 + CP_PW, y);
    report_svg_text(f, CP_X0 - 40, y + 4, 11, lab);
  }
  report_svg_text(f, CP_X0, 24, 14, title);
  report_svg_text(f, CP_X0 + CP_PW / 2 - 60, CP_H - 12, 12, "vertices n (log scale)");
  report_svg_text(f, CP_X0 + CP_PW + 16, CP_Y0 + 8, 12, ylabel);
}

/* One algorithm's line, markers and legend entry (slope). */
static void cp_series(FILE *f, const cp_axes *a, const study_cpdt_cell *cells, size_t ncells,
                      int algorithm, int count, int slot) {
  const char *col = report_cpdt_colours[slot % 8];
  fprintf(f, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\" points=\"", col);
  for (size_t i = 0; i < ncells; i++)
    if (cells[i].algorithm == algorithm && cells[i].mean[count] > 0)
      fprintf(f, "%.2f,%.2f ", cp_px(a, (double)cells[i].n), cp_py(a, cells[i].mean[count]));
  fprintf(f, "\"/>\n");
  for (size_t i = 0; i < ncells; i++)
    if (cells[i].algorithm == algorithm && cells[i].mean[count] > 0)
      fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"3\" fill=\"%s\"/>\n",
              cp_px(a, (double)cells[i].n), cp_py(a, cells[i].mean[count]), col);
  double y = CP_Y0 + 40 + 20 * slot, s = study_cpdt_slope(cells, ncells, algorithm, count);
  char lab[64];
  snprintf(lab, sizeof lab, isnan(s) ? "%s" : "%s  slope %.2f", cpdt_algorithm_name(algorithm), s);
  fprintf(f, "<rect x=\"%d\" y=\"%.2f\" width=\"12\" height=\"4\" fill=\"%s\"/>\n",
          CP_X0 + CP_PW + 16, y - 4, col);
  report_svg_text(f, CP_X0 + CP_PW + 34, y, 11, lab);
}

int report_cpdt_svg(FILE *f, const char *title, const study_cpdt_cell *cells, size_t ncells,
                    const int *algorithms, size_t nalgorithms, int count) {
  if (count < 0 || count >= STUDY_CPDT_NCOUNTS) return -1;
  cp_axes a = cp_range(cells, ncells, count);
  char ylabel[64];
  snprintf(ylabel, sizeof ylabel, "mean %s (log scale)", study_cpdt_count_name(count));
  cp_frame(f, &a, title, ylabel);
  for (size_t k = 0; k < nalgorithms; k++)
    cp_series(f, &a, cells, ncells, algorithms[k], count, (int)k);
  fprintf(f, "</svg>\n");
  return ferror(f) ? -1 : 0;
}
