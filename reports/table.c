/*
** table.c: table 3.4 as text or Markdown, in the thesis's layout: one block
** per joint with the rows DT, I, II, III, one column per measure, then the
** rules that produced type-V graphs and a check that none produced type IV.
** Percentages are of all samples (the thesis's convention).
*/
#include <stdlib.h>
#include <string.h>
#include "measure.h"
#include "joint.h"
#include "report_internal.h"
#include "study.h"


/* The four rows of a joint block: label and which count they show. */
enum { REPORT_ROW_DT = -1 };
static const struct { const char *label; int type; } report_blockrows[] = {
  {"DT", REPORT_ROW_DT}, {"I", FLIPGRAPH_I}, {"II", FLIPGRAPH_II}, {"III", FLIPGRAPH_III},
};
#define REPORT_NBLOCKROWS 4

int report_format_parse(const char *s, report_format *out) {
  static const struct { const char *name; report_format f; } names[] = {
    {"text", REPORT_TEXT}, {"md", REPORT_MD}, {"markdown", REPORT_MD}, {"csv", REPORT_CSV},
  };
  for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
    if (strcmp(s, names[i].name) == 0) {
      *out = names[i].f;
      return 0;
    }
  return -1;
}

void report_row_from_rule(report_row *row, const rule *r, const flipgraph_counts *c) {
  memset(row, 0, sizeof *row);
  snprintf(row->measure, sizeof row->measure, "%s", rule_measure_name(r));
  snprintf(row->joint, sizeof row->joint, "%s", rule_joint_name(r));
  snprintf(row->rule, sizeof row->rule, "%s", rule_name(r));
  if (c != NULL) row->c = *c;
}

uint64_t report_type_iv(const report_row *rows, int nrows) {
  uint64_t n = 0;
  for (int i = 0; i < nrows; i++)
    if (rows[i].measure[0] != '\0') n += rows[i].c.type[FLIPGRAPH_IV];
  return n;
}

/* ------------------------------------------------------------- layout */

/* Which row fills each (joint block, measure column) cell. */
typedef struct report_layout {
  int ncols;
  const char **col;        /* measure names, order of first appearance */
  int nblocks;
  const char **block;      /* joint names present, table order, then unknown ones */
  int *cell;               /* [block * ncols + col] = row index or -1 */
  int decimals;
  uint64_t samples;
} report_layout;

static int report_find(const char **list, int n, const char *s) {
  for (int i = 0; i < n; i++)
    if (strcmp(list[i], s) == 0) return i;
  return -1;
}

static int report_layout_make(report_layout *L, const report_meta *m,
                              const report_row *rows, int nrows) {
  memset(L, 0, sizeof *L);
  size_t cap = (size_t)(nrows > 0 ? nrows : 1);
  L->col = malloc(cap * sizeof *L->col);
  L->block = malloc((cap + JOINT_COUNT) * sizeof *L->block);
  if (L->col == NULL || L->block == NULL) return -1;
  for (int j = 0; j < joint_count(); j++)
    for (int i = 0; i < nrows; i++)
      if (rows[i].measure[0] && strcmp(rows[i].joint, joint_get((joint_id)j)->name) == 0) {
        L->block[L->nblocks++] = joint_get((joint_id)j)->name;
        break;
      }
  for (int i = 0; i < nrows; i++) {
    if (rows[i].measure[0] == '\0') continue;
    if (report_find(L->col, L->ncols, rows[i].measure) < 0) L->col[L->ncols++] = rows[i].measure;
    if (report_find(L->block, L->nblocks, rows[i].joint) < 0) L->block[L->nblocks++] = rows[i].joint;
  }
  /* Sizes in size_t: blocks x columns overflowed an int on a crafted CSV
  ** of tens of thousands of rules (readers now cap the rules, too). */
  size_t ncell = (size_t)L->nblocks * (size_t)L->ncols;
  L->cell = malloc((ncell + 1) * sizeof *L->cell);
  if (L->cell == NULL) return -1;
  for (size_t k = 0; k < ncell; k++) L->cell[k] = -1;
  for (int i = 0; i < nrows; i++) {
    if (rows[i].measure[0] == '\0') continue;
    int b = report_find(L->block, L->nblocks, rows[i].joint);
    int c = report_find(L->col, L->ncols, rows[i].measure);
    size_t k = (size_t)b * (size_t)L->ncols + (size_t)c;
    if (L->cell[k] < 0) L->cell[k] = i;
  }
  L->samples = m->samples;
  /* Two decimals resolve 1e-4 of the samples; from a million samples on the
  ** Wilson half-width falls below 0.1 points and a third decimal carries
  ** information. */
  L->decimals = m->samples >= 1000000 ? 3 : 2;
  return 0;
}

static void report_layout_free(report_layout *L) {
  free(L->col);
  free(L->block);
  free(L->cell);
}

static void report_pct(char *buf, size_t len, const report_layout *L, uint64_t k) {
  if (L->samples == 0) snprintf(buf, len, "-");
  else snprintf(buf, len, "%.*f", L->decimals, 100.0 * (double)k / (double)L->samples);
}

static void report_cell(char *buf, size_t len, const report_layout *L,
                        const report_row *rows, int b, int c, int type) {
  int i = L->cell[(size_t)b * (size_t)L->ncols + (size_t)c];
  if (i < 0) {
    snprintf(buf, len, "-");
    return;
  }
  report_pct(buf, len, L, type == REPORT_ROW_DT ? rows[i].c.dt : rows[i].c.type[type]);
}

/* The joint's word for the block label (joints/ owns it). */
static const char *report_joint_word(const char *name) {
  int j = joint_find(name);
  return j >= 0 ? joint_get((joint_id)j)->word : "user";
}

/* ------------------------------------------------------------- header */

static void report_header_lines(FILE *f, const report_meta *m, int md) {
  const char *sep = md ? "  \n" : "\n";
  fprintf(f, "samples: %llu", (unsigned long long)m->samples);
  if (m->has_seed) fprintf(f, ", seed: %llu", (unsigned long long)m->seed);
  if (m->has_tie_eps) fprintf(f, ", tie tolerance: %g", m->tie_eps);
  fprintf(f, "%s", sep);
  fprintf(f, "sampler: %s; fliplab %s%s",
          m->sampler ? m->sampler : "iteration method, unit disc", FLIPLAB_VERSION, sep);
  if (m->shard_n > 0)
    fprintf(f, "shard %llu/%llu: samples [%llu, %llu) of %llu%s",
            (unsigned long long)m->shard_k, (unsigned long long)m->shard_n,
            (unsigned long long)m->shard_first,
            (unsigned long long)(m->shard_first + m->samples),
            (unsigned long long)m->shard_total, sep);
  if (m->note) fprintf(f, "%s%s", m->note, sep);
  fprintf(f, "Percentages of all samples (95%% Wilson half-width at most %.2f points).%s"
             "Row DT: type I with the Delaunay triangulation as sink.\n",
          study_wilson_max(m->samples), sep);
}

/* ------------------------------------------------------------- footer */

/* Whole-quadrilateral rules (DT), type V and type IV: the lines under the table. */
static void report_footer(FILE *f, const report_layout *L, const report_row *rows,
                          int nrows, int md) {
  char p[5][32], dt[32];
  const char *q = md ? "`" : "";
  for (int i = 0; i < nrows; i++) {
    if (rows[i].measure[0] != '\0') continue;
    for (int t = 0; t < FLIPGRAPH_NTYPES; t++) report_pct(p[t], sizeof p[t], L, rows[i].c.type[t]);
    report_pct(dt, sizeof dt, L, rows[i].c.dt);
    fprintf(f, "\nRule %s%s%s: I %s, II %s, III %s, IV %s, V %s; sink = Delaunay %s\n", q, rows[i].rule, q, p[0], p[1], p[2], p[3], p[4], dt);
  }
  fprintf(f, "\nType V (a tie in some quadrilateral), %% of samples:");
  int any = 0, col = 51;
  for (int i = 0; i < nrows; i++) {
    if (rows[i].c.type[FLIPGRAPH_V] == 0) continue;
    char buf[160], pct[32];
    report_pct(pct, sizeof pct, L, rows[i].c.type[FLIPGRAPH_V]);
    int n = snprintf(buf, sizeof buf, "%s%s%s %s", q, rows[i].rule, q, pct);
    if (any) fputc(',', f);
    if (!md && col + n + 2 > 78) {
      fprintf(f, "\n ");
      col = 1;
    }
    fprintf(f, " %s", buf);
    col += n + 2;
    any = 1;
  }
  fprintf(f, "%s\n", any ? "" : " none");
  uint64_t iv = report_type_iv(rows, nrows);
  if (iv == 0) {
    fprintf(f, "%sType IV (no sink): none among the triangle-based rules, as theorem 1 requires.\n",
            md ? "\n" : "");
    return;
  }
  fprintf(f, "%s*** TYPE IV (no sink) FOUND: %llu graphs from triangle-based rules, which "
             "theorem 1 rules out: a bug. Rules:",
          md ? "\n" : "", (unsigned long long)iv);
  for (int i = 0; i < nrows; i++)
    if (rows[i].measure[0] && rows[i].c.type[FLIPGRAPH_IV] > 0)
      fprintf(f, " %s%s%s (%llu)", q, rows[i].rule, q,
              (unsigned long long)rows[i].c.type[FLIPGRAPH_IV]);
  fprintf(f, " ***\n");
}

/* ------------------------------------------------------------- text */

/* A column fits its name and "100.00", two blanks apart. */
static int report_col_width(const report_layout *L, int c) {
  int w = (int)strlen(L->col[c]), pw = 4 + L->decimals;
  return (w > pw ? w : pw) + 2;
}

static void report_text_group(FILE *f, const report_layout *L, const report_row *rows,
                              int c0, int c1) {
  char buf[64];
  int lw = 6;   /* the label column fits "l_NAME" and "(word)" */
  for (int b = 0; b < L->nblocks; b++) {
    int n = (int)strlen(L->block[b]) + 2, w = (int)strlen(report_joint_word(L->block[b])) + 2;
    if (n > lw) lw = n;
    if (w > lw) lw = w;
  }
  fprintf(f, "%-*s %-4s", lw, "joint", "row");
  for (int c = c0; c < c1; c++) fprintf(f, "%*s", report_col_width(L, c), L->col[c]);
  fputc('\n', f);
  for (int b = 0; b < L->nblocks; b++) {
    for (int r = 0; r < REPORT_NBLOCKROWS; r++) {
      char label[48] = "";
      if (r == 0) snprintf(label, sizeof label, "l_%s", L->block[b]);
      else if (r == 1) snprintf(label, sizeof label, "(%s)", report_joint_word(L->block[b]));
      fprintf(f, "%-*s %-4s", lw, label, report_blockrows[r].label);
      for (int c = c0; c < c1; c++) {
        report_cell(buf, sizeof buf, L, rows, b, c, report_blockrows[r].type);
        fprintf(f, "%*s", report_col_width(L, c), buf);
      }
      fputc('\n', f);
    }
    if (b + 1 < L->nblocks) fputc('\n', f);
  }
}

int report_table_text(FILE *f, const report_meta *m, const report_row *rows,
                      int nrows, int maxcols) {
  report_layout L;
  if (report_layout_make(&L, m, rows, nrows) != 0) {
    report_layout_free(&L);
    return -1;
  }
  if (maxcols <= 0 || maxcols > L.ncols) maxcols = L.ncols;
  fprintf(f, "Table 3.4: %% of flip graphs of each type\n");
  report_header_lines(f, m, 0);
  /* Balanced groups: 20 columns -> 10 + 10, 23 -> 8 + 8 + 7. */
  int ngroups = L.ncols > 0 ? (L.ncols + maxcols - 1) / maxcols : 0;
  int per = ngroups > 0 ? (L.ncols + ngroups - 1) / ngroups : 0;
  for (int g = 0; g < ngroups; g++) {
    int c0 = g * per, c1 = c0 + per < L.ncols ? c0 + per : L.ncols;
    fputc('\n', f);
    if (ngroups > 1)
      fprintf(f, "Measures %d-%d of %d\n", c0 + 1, c1, L.ncols);
    report_text_group(f, &L, rows, c0, c1);
  }
  report_footer(f, &L, rows, nrows, 0);
  report_layout_free(&L);
  return ferror(f) ? -1 : 0;
}

/* ------------------------------------------------------------- Markdown */

/* A measure name as a code span; '|' would end the cell even inside one. */
static void report_md_name(FILE *f, const char *s) {
  fputc('`', f);
  for (; *s; s++) {
    if (*s == '|') fputc('\\', f);
    fputc(*s, f);
  }
  fputc('`', f);
}

int report_table_md(FILE *f, const report_meta *m, const report_row *rows, int nrows) {
  report_layout L;
  char buf[64];
  if (report_layout_make(&L, m, rows, nrows) != 0) {
    report_layout_free(&L);
    return -1;
  }
  fprintf(f, "### Table 3.4: %% of flip graphs of each type\n\n");
  report_header_lines(f, m, 1);
  fprintf(f, "\n| joint | row |");
  for (int c = 0; c < L.ncols; c++) {
    fputc(' ', f);
    report_md_name(f, L.col[c]);
    fprintf(f, " |");
  }
  fprintf(f, "\n|:--|:--|");
  for (int c = 0; c < L.ncols; c++) fprintf(f, "--:|");
  fputc('\n', f);
  for (int b = 0; b < L.nblocks; b++)
    for (int r = 0; r < REPORT_NBLOCKROWS; r++) {
      if (r == 0) fprintf(f, "| l_%s (%s) |", L.block[b], report_joint_word(L.block[b]));
      else fprintf(f, "| |");
      fprintf(f, " %s |", report_blockrows[r].label);
      for (int c = 0; c < L.ncols; c++) {
        report_cell(buf, sizeof buf, &L, rows, b, c, report_blockrows[r].type);
        fprintf(f, " %s |", buf);
      }
      fputc('\n', f);
    }
  report_footer(f, &L, rows, nrows, 1);
  report_layout_free(&L);
  return ferror(f) ? -1 : 0;
}

int report_write(FILE *f, report_format fmt, const report_meta *m,
                 const report_row *rows, int nrows) {
  switch (fmt) {
  case REPORT_CSV: return report_csv_write_run(f, rows, nrows, m->run);
  case REPORT_MD: return report_table_md(f, m, rows, nrows);
  case REPORT_TEXT: break;
  }
  return report_table_text(f, m, rows, nrows, m->text_columns);
}
