/*
** report_internal.h: what the files of reports/ share and nobody else
** needs: the SVG kit (reports/svg.c: text, view fit, colour scale, the
** frames and arrows of the flip-graph pictures) and the CSV helpers of the
** writers and readers.  Not installed; report.h is the public face.
*/
#ifndef FLIPLAB_REPORT_INTERNAL_H
#define FLIPLAB_REPORT_INTERNAL_H

#include <stddef.h>
#include <stdio.h>
#include "fliplab_config.h"
#include "report.h"

/* ---- CSV (reports/csvio.c, reports/census.c) ---- */

/* Write one CSV field, quoted through libcsv only when it contains a comma,
** quote, CR, LF, or leading/trailing blanks (which a reader would trim). */
FLIPLAB_INTERNAL int report_csv_field(FILE *f, const char *s);

/* The columns of a counts CSV (report.h) and the writer of the ten plus
** the run columns (report_write's CSV with m->run). */
#define REPORT_CSV_NCOLS 16
FLIPLAB_INTERNAL const char *const report_csv_header[REPORT_CSV_NCOLS];
FLIPLAB_INTERNAL int report_csv_write_run(FILE *f, const report_row *rows, int nrows,
                                          const report_run *run);

/* The columns of a census CSV (report.h), and the most rows one may hold:
** every measure with every joint, and every quadrilateral rule. */
#define REPORT_CENSUS_NCOLS 14
#define REPORT_CENSUS_MAX_ROWS (MEASURE_MAX * JOINT_COUNT + RULE_QUAD_MAX)
FLIPLAB_INTERNAL const char *const report_census_header[REPORT_CENSUS_NCOLS];

/* ---- files of two-field rows (reports/csv_pairs.c) ---- */

/* A file of rows "a,b" (or "a" when fields is 1; 0 means 2) with an
** optional header line naming the columns (head), one row parsed by row
** into size bytes (at most 16);
** what names the rows in messages ("points").  row returns 0, or -1 with
** its one-line message in r->err.  The reader's own messages name the file
** and line: a wrong field count, no rows, memory. */
typedef struct report_pairs report_pairs;
struct report_pairs {
  const char *path, *what, *head[2];
  int fields;           /* 1 or 2 (0: 2) */
  size_t size;
  int (*row)(const report_pairs *r, char **f, const size_t *len, unsigned long long line,
             void *out);
  const void *ctx;      /* the row parser's */
  char *err;
  size_t errlen;
};
/* At most 40 bytes of a field for a message, control bytes (a quoted
** field may hold line breaks) shown as '?', so the message stays one line. */
FLIPLAB_INTERNAL void report_pairs_shown(const char *f, size_t len, char out[41]);
/* 0 with the rows in *rows and their 1-based lines in *lines (when lines
** is not NULL; free both), or -1 (nothing to free). */
FLIPLAB_INTERNAL int report_pairs_read(const report_pairs *r, void **rows, uint64_t **lines,
                                       size_t *n);

/* ---- the counts table of both CSV kinds (reports/counts.c) ---- */

/* An integer column: CSV column col (-1: not a column of its own but a
** sum the kind reads from a mean), the uint64_t at offset off of a row,
** and how two shards' values combine. */
typedef enum report_addop { REPORT_ADD_SUM, REPORT_ADD_MAX } report_addop;
typedef struct report_countcol {
  int col;
  size_t off;
  report_addop op;
} report_countcol;

/* A consistency rule of a row, as the error message states it. */
typedef struct report_countcheck {
  const char *rule;
  int (*holds)(const void *row);
} report_countcheck;

/* A CSV kind: its header, its integer columns (counts[0] is `samples`, the
** same on every row of a file), its checks, and the kind's own parts: the
** other fields of a record (names, means, run columns; 0, or -1 with the
** message in the reader's err) and whether two rows are the same rule
** (0, or -1 with a message naming `what` and row i + 1). */
typedef struct report_tableread report_tableread;
typedef struct report_table {
  const char *const *header;
  size_t row_size;
  int max_rows;
  const report_countcol *counts;
  int ncounts;
  const report_countcheck *checks;
  int nchecks;
  const int *names;            /* the text columns (rule, measure, ...), NUL-free */
  int nnames;
  int (*fields)(report_tableread *r, char **f, void *row, unsigned long long line);
  int (*same)(const void *a, const void *b, int i, const char *what, char *err, size_t errlen);
} report_table;

/* A reader of one file of a kind: the rows so far (malloc'ed), the
** record's field lengths, and the kind's own state (ctx). */
struct report_tableread {
  const report_table *t;
  const char *name;
  int ncols;                /* fields per record, from the header */
  char *rows;
  int n, cap;
  const size_t *len;
  void *ctx;
  char *err;
  size_t errlen;
};

/* One record after the header: field count, row bound, no NUL byte in a
** text column (a C string would cut the name short), the integer
** columns, the kind's fields, the checks, the sample count; the row is
** appended.  0, or -1 with "FILE line N: ..." in r->err. */
FLIPLAB_INTERNAL int report_table_record(report_tableread *r, char **f, const size_t *len,
                                         int nf, uint64_t line);
/* acc[i] += add[i] over the integer columns (sums overflow-checked, maxima
** kept) after t->same on every row; -1 with a message naming `what`. */
FLIPLAB_INTERNAL int report_table_add(const report_table *t, void *acc, int nacc,
                                      const void *add, int nadd, const char *what, char *err,
                                      size_t errlen);
/* The integer columns of a row as fields (num[col], field[col] set). */
FLIPLAB_INTERNAL void report_table_format(const report_table *t, const void *row,
                                          char num[][32], const char **field);

/* ---- text (reports/svg.c) ---- */

/* Write s as SVG/XML text: & < > " ' escaped (element text or an attribute
** value with either quote).  0, or -1 on a write error. */
FLIPLAB_INTERNAL int report_xml_text(FILE *f, const char *s);

/* A <text> line at (x, y) of the given font size, escaped. */
FLIPLAB_INTERNAL void report_svg_text(FILE *f, double x, double y, int size, const char *s);

/* Caption lines (separated by '\n') as monospace text from (x, y) down,
** REPORT_SVG_LINE px apart, escaped; and how many lines a caption has (0
** for NULL or ""), for the picture's height. */
#define REPORT_SVG_LINE 17.0
FLIPLAB_INTERNAL void report_svg_caption(FILE *f, double x, double y, const char *caption);
FLIPLAB_INTERNAL int report_svg_caption_lines(const char *caption);

/* ---- view fit (reports/svg.c) ---- */

/* The bounding box of n >= 1 points, and the scale that makes its larger
** side `size` px (1 when the points coincide). */
typedef struct report_svg_box {
  double minx, miny, maxx, maxy;
} report_svg_box;
FLIPLAB_INTERNAL report_svg_box report_svg_bbox(const geom_point *p, size_t n);
FLIPLAB_INTERNAL double report_svg_fit_scale(const report_svg_box *b, double size);

/* ---- the badness colour scale of shaded drawings (got, lot) ---- */

/* (report_svg_colour, the scale itself, is public: report.h.) */
/* 20 swatches from lo to hi, labelled, left edge at x0, top at y. */
FLIPLAB_INTERNAL void report_svg_colour_legend(FILE *f, double x0, double y, double lo,
                                               double hi);

/* ---- log-log line plots (reports/svg.c: cpdt, paradigms) ---- */

/* A 640 x 480 canvas, a 380 px square plot with whole decades on both
** axes (log10 ranges), a line per series with its legend entry at the
** right (eight colours, cycled). */
typedef struct report_loglog { double x0, x1, y0, y1; } report_loglog;
/* The decades around x in [xlo, xhi], y in [ylo, yhi] (positive; none:
** xhi == 0, one decade from 1). */
FLIPLAB_INTERNAL report_loglog report_loglog_range(double xlo, double xhi, double ylo,
                                                   double yhi);
FLIPLAB_INTERNAL void report_loglog_frame(FILE *f, const report_loglog *a, const char *title,
                                          const char *xlabel, const char *ylabel);
/* Series `slot`: the line through (x[i], y[i]), i < k (positive), its
** markers, and its legend entry. */
FLIPLAB_INTERNAL void report_loglog_series(FILE *f, const report_loglog *a, const double *x,
                                           const double *y, size_t k, int slot,
                                           const char *label);

/* ---- directed flip graphs (svg_flipgraph.c, svg_siteflip.c) ---- */

/* The XML declaration, the <svg> element of w x h px, the arrowhead marker
** and the white background. */
FLIPLAB_INTERNAL void report_svg_graph_open(FILE *f, double w, double h);

/* The flip between the frames (side `box`) centred at a and b: an arrow
** from a to b, or a dashed line when `either`, cut `pad` px outside both
** frames; nothing when the frames leave no room. */
FLIPLAB_INTERNAL void report_svg_flip(FILE *f, double box, double pad, double width, double ax,
                                      double ay, double bx, double by, int either);

/* A triangulation's frame and tags in a flip graph: sinks in a thick green
** frame, sources in a dashed red one, the others thin grey; the name T<k>
** below, the role above, "DT" in the lower right corner.  One style; the
** two pictures differ only in sizes. */
typedef enum report_svg_role {
  REPORT_SVG_PLAIN, REPORT_SVG_SINK, REPORT_SVG_SOURCE
} report_svg_role;
typedef struct report_svg_node_style {
  double box, rx;                  /* frame side, corner radius */
  double sink_width, source_width; /* frame strokes */
  const char *source_dash;         /* a source frame's dash pattern */
  int name_size, name_bold;        /* the name T<k> ... */
  double name_gap;                 /* ... this far below the frame's centre line + box/2 */
  int role_size;                   /* the role label's font size */
  double tag_gap;                  /* role above / DT inside the frame, px */
} report_svg_node_style;
FLIPLAB_INTERNAL void report_svg_node_frame(FILE *f, const report_svg_node_style *st, double cx,
                                            double cy, report_svg_role role);
FLIPLAB_INTERNAL void report_svg_node_tags(FILE *f, const report_svg_node_style *st, double cx,
                                           double cy, int name, report_svg_role role, int dt);

#endif
