/*
** report.h: what fliplab prints about flip-graph counts: table 3.4 as
** text, Markdown or CSV, the CSV reader that `merge` sums shards with, the
** type-I-against-DT scatter plot (thesis figure 3.9), the pentagon CSV
** files that `sample` writes and `classify` reads, one pentagon's directed
** flip graph as a picture (thesis figure 3.7), and the input and output of
** `fliplab got` (polygon CSV, triangles as CSV, the SVG of a GOT).
**
** Every file format: docs/formats.md.
**
** A report works from rows of names and counts, not from rule structs, so a
** table merged from CSV shards prints exactly like one computed here.
** Every CSV byte goes through libcsv: fields are quoted by csv_fwrite when
** (and only when) they need it, files are read with csv_parse.
*/
#ifndef FLIPLAB_REPORT_H
#define FLIPLAB_REPORT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "flipgraph.h"
#include "geom.h"
#include "got.h"
#include "lot.h"
#include "siteflip.h"
#include "study_cpdt.h"
#include "study_paradigms.h"

/* One rule's outcome.  measure and joint are empty for a whole-quadrilateral
** rule such as DT; joint is the command-line suffix ("-inf" ... "inf"). */
typedef struct report_row {
  char measure[64];
  char joint[JOINT_NAME_MAX];
  char rule[RULE_NAME_MAX];
  flipgraph_counts c;
} report_row;

/* A counts CSV's record of its run (the run columns, see below). */
typedef struct report_run {
  int known;              /* the file has the run columns */
  uint64_t seed;
  double tie_eps;
  uint64_t first, end;    /* sample range [first, end) counted */
  uint64_t total;         /* the run's samples (--samples) */
  uint64_t rules;         /* rows of the file */
  const char *sampler;    /* table34 --sampler other than iteration: written as a
                          ** 17th column `sampler`, which merge refuses; else NULL */
} report_run;

/* What the table header says about the run.  Fields a merged CSV does not
** record (seed, tie tolerance) are marked absent. */
typedef struct report_meta {
  uint64_t samples;       /* pentagons behind every percentage */
  int has_seed;
  uint64_t seed;
  int has_tie_eps;
  double tie_eps;
  uint64_t shard_k, shard_n;          /* shard_n == 0: not a shard */
  uint64_t shard_first, shard_total;  /* sample range of the shard */
  const char *sampler;    /* NULL: "iteration method, unit disc" */
  const char *note;       /* extra header line, or NULL */
  int text_columns;       /* text: at most this many measures per block; 0 = all (thesis layout) */
  const report_run *run;  /* CSV: the run columns merge checks; NULL: the ten only */
} report_meta;

typedef enum report_format { REPORT_TEXT, REPORT_MD, REPORT_CSV } report_format;

/* "text", "md" (or "markdown"), "csv"; -1 if unknown. */
int report_format_parse(const char *s, report_format *out);

/* Fill a row from a rule's registry names. */
void report_row_from_rule(report_row *row, const rule *r, const flipgraph_counts *c);

/* Write the rows in the chosen format; 0, or -1 on a write error. */
int report_write(FILE *f, report_format fmt, const report_meta *m,
                 const report_row *rows, int nrows);

/* Table 3.4's layout: per joint a block DT / I / II / III over the measures
** (columns in order of first appearance), then the type-V and type-IV
** lines.  Text splits more than `maxcols` columns into balanced groups;
** maxcols <= 0 keeps them all in one block, as the thesis prints them. */
int report_table_text(FILE *f, const report_meta *m, const report_row *rows,
                      int nrows, int maxcols);
int report_table_md(FILE *f, const report_meta *m, const report_row *rows, int nrows);

/* Number of type-IV counts among triangle rules (rows with a measure):
** theorem 1 says it must be 0. */
uint64_t report_type_iv(const report_row *rows, int nrows);

/* CSV of counts:
**   measure,joint,rule,samples,type_I,type_II,type_III,type_IV,type_V,dt
** one row per rule in the given order, DT (measure, joint empty) included,
** then (report_csv_write_run; what `merge` checks, docs/merge.md) the run
** on every row:  seed,tie_eps,first,end,total,rules
** = sampler seed, tie tolerance (%.17g), the sample range [first, end) the
** counts cover out of the run's total samples, and the file's row count
** (a file cut at a row boundary is caught by it).  report_write writes the
** run columns when m->run is set. */
int report_csv_write(FILE *f, const report_row *rows, int nrows);   /* the ten columns */
/* One CSV record: the n fields, each quoted through libcsv only when it
** needs it (a comma, quote, CR, LF, or leading/trailing blanks), separated
** by commas, ended by LF; every CSV writer of reports/ writes through it.
** 0, or -1 once the stream has an error. */
int report_csv_row(FILE *f, const char *const *fields, int n);

/* Read a counts CSV written by report_csv_write.  Checks the header, the
** field counts, the numbers and their consistency (types sum to samples,
** dt <= type_I, one sample count per file).  On error returns -1 with a
** one-line message naming the file and row in err.  *rows is malloc'ed. */
int report_csv_read(const char *path, report_row **rows, int *nrows,
                    char *err, size_t errlen);
/* The same from a stream (name is used in messages).  Also refuses: more
** than a registry's worth of rules, a field over 4096 bytes, a joint that
** is not one of the six, a rule that is not MEASURE_JOINT, a rule twice;
** with the run columns, rows that disagree on them and a row count other
** than `rules`.  *run (may be NULL) gets the run columns (known = 0 when the
** file has only the ten). */
int report_counts_read(FILE *in, const char *name, report_row **rows, int *nrows,
                       report_run *run, char *err, size_t errlen);

/* acc += add, after checking both list the same rules in the same order;
** -1 with a message (naming `what`) on a mismatch or an overflow. */
int report_rows_add(report_row *acc, int nacc, const report_row *add, int nadd,
                    const char *what, char *err, size_t errlen);

/* Generic CSV records through libcsv.  fn gets each non-empty record
** (every field NUL-terminated, and its length in bytes, which tells a field
** with a NUL byte inside from a shorter one: numbers are read with the
** geom_ parsers, which take it) with its 1-based line number; a non-zero return stops the walk and is
** returned.  Lines count LF terminators, so quoted newlines shift them.
** A leading UTF-8 byte order mark is skipped; a record of more than 256
** fields or a field of more than 4096 bytes is an error ("line N: ..."). */
typedef int (*report_record_fn)(char **fields, const size_t *len, int nfields, uint64_t line,
                                void *ctx);
int report_csv_each(FILE *in, report_record_fn fn, void *ctx, char *err, size_t errlen);
/* report_csv_each over the file at path ("-": standard input): 0, or -1
** with err "cannot read 'PATH': why", fn's own message (fn writes err and
** leaves it empty otherwise) or the parse error after the path. */
int report_csv_file(const char *path, report_record_fn fn, void *ctx, char *err, size_t errlen);

/* Pentagon files: a header x1,y1,...,x5,y5 then one pentagon per row, each
** coordinate printed with %.17g so it reads back bit for bit. */
int report_pentagon_header(FILE *f);
int report_pentagon_write(FILE *f, const geom_point v[5]);

/* Read pentagons (the header line is optional; any orientation; a
** clockwise pentagon is reversed by geom_polygon_check).  *v is malloc'ed
** (5 points per pentagon); *reversed counts the reversed ones.  On a bad
** row: -1 and "FILE line N: problem" in err. */
int report_pentagon_read(FILE *in, const char *name, geom_point **v, size_t *count,
                         size_t *reversed, char *err, size_t errlen);
/* Streaming: fn gets each checked pentagon (anticlockwise), its 1-based id
** (header excluded), its line and whether it was reversed; a non-zero
** return stops the walk and is returned.  Constant memory in the rows. */
typedef int (*report_pentagon_fn)(const geom_point v[5], uint64_t id, uint64_t line,
                                  int reversed, void *ctx);
int report_pentagon_each(FILE *in, const char *name, report_pentagon_fn fn, void *ctx,
                         char *err, size_t errlen);

/* Figure 3.9: type-I % (x) against DT % (y) for every rule that produced
** no type-V graph; colour by joint, one <title> per point. */
int report_scatter_svg(FILE *f, const report_meta *m, const report_row *rows, int nrows);

/* ---- one directed flip graph (reports/svg_flipgraph.c) ---- */

/* The five triangulations of p drawn as small pictures around the cycle
** T0 - T2 - T4 - T1 - T3, an arrow on each cycle edge pointing to the
** triangulation the rule prefers (a dashed undirected line for EITHER),
** sinks in a thick green frame, sources in a dashed red one, the Delaunay
** triangulation tagged "DT".  caption: lines separated by '\n' (rule, type,
** coordinates...), drawn below.  0, or -1 on a write error. */
int report_flipgraph_svg(FILE *f, const flipgraph_pentagon *p, const flipgraph *g,
                         const char *caption);

/* ---- flip graphs of small site sets (reports/svg_siteflip.c) ---- */

/* The directed flip graph of a site set: a small drawing of every
** triangulation in columns by flip distance from triangulation 1, an arrow
** on each flip towards the preferred one (dashed line for `either`),
** sinks in a thick green frame, sources in a dashed red one, the Delaunay
** triangulation tagged "DT".  At most REPORT_SITEFLIP_SVG_MAX nodes
** (returns -2 and writes nothing above); 0, or -1 on a write error. */
#define REPORT_SITEFLIP_SVG_MAX 64
int report_siteflip_svg(FILE *f, const siteflip_graph *g, const rule_choice *dec,
                        const char *caption);

/* ---- the census of site sets (reports/census.c) ---- */

/* One rule's census.  measure and joint empty for whole-quadrilateral
** rules (which have no GOT, so no gap). */
typedef struct report_census_row {
  char measure[64];
  char joint[JOINT_NAME_MAX];
  char rule[RULE_NAME_MAX];
  int sites;
  char sampler[16];
  siteflip_counts c;
} report_census_row;

typedef struct report_census_meta {
  int has_seed;
  uint64_t seed;
  int has_tie_eps;
  double tie_eps;
  uint64_t shard_k, shard_n;        /* shard_n == 0: not a shard */
} report_census_meta;

void report_census_row_from_rule(report_census_row *row, const rule *r, int sites,
                                 const char *sampler, const siteflip_counts *c);

/* CSV, one row per rule:
**   measure,joint,rule,sites,sampler,samples,tie,no_sink,one_sink,
**   multi_sink,sink_dt,mean_sinks,max_sinks,mean_worst_gap
** mean_sinks = sinks / (samples - tie); mean_worst_gap = the mean over the
** samples with a sink of the worst sink's relative gap to the GOT (empty
** for rules that are not triangle-based, and both empty with no sample to
** average).  Both read back into exact integer sums (docs/sitesets.md). */
int report_census_write(FILE *f, report_format fmt, const report_census_meta *m,
                        const report_census_row *rows, int nrows);

/* Read a census CSV from in (named path in errors): header, field counts,
** numbers, consistency; every error one line naming the line.  *rows
** malloc'ed; 0 or -1. */
int report_census_read(FILE *in, const char *path, report_census_row **rows, int *nrows,
                       char *err, size_t errlen);
/* acc += add after checking the same rules, sites and sampler in order. */
int report_census_add(report_census_row *acc, int nacc, const report_census_row *add,
                      int nadd, const char *what, char *err, size_t errlen);

/* ---- the badness colour scale of shaded drawings (got, lot; reports/svg.c) ----
** f in [0, 1] (clamped; NaN as 0): light yellow = good to dark red = bad,
** as "#rrggbb"; a drawing maps its smallest finite badness to 0 and its
** largest to 1.  Public so that python/'s matplotlib pictures use the same
** scale as the SVGs. */
void report_svg_colour(double f, char *buf, size_t len);

/* ---- point files (reports/csv_points.c) ---- */

/* Read points from CSV (path "-": standard input): rows "x,y", an optional
** header line "x,y", every coordinate under the contract of
** geom_coord_parse.  Errors are one line naming the file and line: a wrong
** field count, a coordinate that is not a number or out of range, no points
** at all.  *lines (when lines is not NULL) receives each point's 1-based
** file line.  0 on success (free *out and *lines), -1 on error.  The
** caller checks what its input must be (a simple polygon, a site set). */
int report_points_read(const char *path, geom_point **out, uint64_t **lines, size_t *n,
                       char *err, size_t errlen);

/* ---- segment files (reports/csv_segments.c) ---- */

/* Read segments from CSV (path "-": standard input): rows "i,j" of 0-based
** indices into a point set of npoints points (the rows of its file), an
** optional header line "i,j".  Errors are one line naming the file and
** line: a wrong field count, an index that is not a non-negative integer
** (negative ones said so), an index >= npoints, i == j, no segments at all.
** *seg gets 2 indices per segment in file order, *lines (when lines is not
** NULL) each segment's 1-based file line.  0 on success (free *seg and
** *lines), -1 on error.  Crossings and overlaps are lot_build's to judge. */
int report_segments_read(const char *path, size_t npoints, uint32_t **seg, uint64_t **lines,
                         size_t *nseg, char *err, size_t errlen);

/* ---- weight files (reports/csv_weights.c) ---- */

/* Read per-site weights from CSV (path "-": standard input): one row "w"
** per row of the points file (npoints of them), an optional header line
** "w".  Errors are one line naming the file and line: a wrong field count,
** a weight that is not a number or outside the weight contract of geom.h
** (geom_weight_check), or, naming the file, a count other than npoints.
** 0 with *w (free it), or -1. */
int report_weights_read(const char *path, size_t npoints, double **w, char *err,
                        size_t errlen);

/* ---- Triangle's .poly files (reports/poly.c) ---- */

/* A planar straight-line graph: vertices, segments (pairs of 0-based
** vertex indices), hole points.  What the file had beyond that is counted,
** not kept: per-vertex attributes, regional attribute / area lines. */
typedef struct report_poly {
  geom_pslg g;            /* segment endpoints 0-based and different */
  uint64_t *seg_line;     /* each segment's 1-based file line */
  size_t attributes;      /* attributes per vertex in the file (ignored) */
  size_t regions;         /* regional attribute / area constraint lines (ignored) */
  int markers;            /* the file has boundary markers (vertices or segments; ignored) */
  int first;              /* the file numbers its vertices from 0 or 1 */
} report_poly;

/* Read a .poly file (path "-": standard input), strictly (docs/formats.md):
** exact field counts per line, consecutive vertex numbers from 0 or 1,
** endpoints that name vertices, no segment from a vertex to itself,
** coordinates (vertices, holes, regions) under the contract of geom.h, no
** line beyond the last section, '#' comments anywhere.  A first line
** announcing 0 vertices (a separate .node file) is refused.  Errors are one
** line, "FILE line N: problem".  0 (free with report_poly_free), or -1. */
int report_poly_read(const char *path, report_poly *out, char *err, size_t errlen);
void report_poly_free(report_poly *p);
/* Write g in the same format (vertices numbered from 0, no attributes or
** markers, coordinates with %.17g so they read back bit for bit); 0, or -1
** once the stream has an error. */
int report_poly_write(FILE *f, const geom_pslg *g);

/* ---- fliplab got (reports/csv_got.c, reports/svg_got.c) ---- */

/* Read a polygon from CSV (path "-": standard input): one vertex per row
** "x,y", an optional header line "x,y".  The polygon is validated (geom_polygon_check) and made
** anticlockwise; *reversed is 1 when the input was clockwise (it is
** reversed keeping vertex 0: vertex v is then input vertex (n - v) mod n).
** Errors are one line, "FILE line N: problem", naming the offending row.
** 0 on success (free *out), -1 on error. */
int report_got_read_polygon(const char *path, geom_point **out, size_t *n, int *reversed,
                            char *err, size_t errlen);

/* Triangles as CSV: header "i,j,k,badness", one row per triangle, vertex
** indices ascending.  map[v] (may be NULL) renumbers vertices, e.g. back
** to the input's order.  Rows go through report_csv_row (libcsv). */
int report_got_csv(FILE *f, const got_triangle *t, size_t ntri, const size_t *map);

typedef struct report_got_svg_opts {
  int shade;            /* fill triangles by badness (light = good, dark = bad) */
  const char *title;    /* one line above the picture, or NULL */
  const size_t *labels; /* vertex numbers to print (n <= 60), e.g. the input's
                           rows; NULL: 0..n-1 */
  const got_triangle *overlay;  /* another triangulation of the polygon (e.g. DT), or NULL: */
  size_t noverlay;              /* its diagonals missing from t are drawn dashed red on top */
  const char *overlay_name;     /* its name in the legend, e.g. "DT" */
} report_got_svg_opts;

/* The polygon (any simple one), its triangulation and (small) vertices,
** scaled to about 1000 px with thin strokes so that n = 1000 stays
** readable; vertex numbers up to n = 60. */
int report_got_svg(FILE *f, const geom_point *p, size_t n, const got_triangle *t,
                   size_t ntri, const report_got_svg_opts *o);

/* ---- fliplab lot (reports/csv_lot.c, reports/svg_lot.c) ---- */


/* Triangles as CSV, the shape of report_got_csv: header "i,j,k,badness",
** one row per triangle, vertices anticlockwise (as given), badness empty
** when NaN (DT and quadrilateral rules). */
int report_lot_csv(FILE *f, const uint32_t *tri, size_t ntri, const double *badness);

/* The convex-distance Delaunay graph as CSV (`lot --cdf`): header "i,j,k",
** a row per kept triangle (as given), then a row per extra edge with k
** empty (docs/formats.md). */
int report_lot_cdf_csv(FILE *f, const lot_cdf *g);

/* One triangulation to draw: triangles (indices into the points), their
** badness for shading (may be NULL), a caption, (may be NULL) a
** convex-distance Delaunay graph drawn over it in bold, and the constrained
** edges (2 point indices each; nseg == 0: none) drawn over it in a thick
** dark stroke. */
typedef struct report_lot_panel {
  const uint32_t *tri;
  size_t ntri;
  const double *badness;
  const char *caption;
  const lot_cdf *cdf;
  const uint32_t *seg;
  size_t nseg;
} report_lot_panel;

/* The panels side by side (e.g. a LOT and the Delaunay triangulation of
** the same points), each scaled to about 600 px; beyond three panels, in
** rows of the smallest square grid, about 400 px each; edges as hairlines,
** points as dots; with shade, triangles filled by badness on one scale
** shared by all panels.  0, or -1 on a write error. */
int report_lot_svg(FILE *f, const geom_point *p, size_t n, const report_lot_panel *panels,
                   int npanels, int shade, const char *title);

/* ---- fliplab cpdt (reports/cpdt.c) ----
** The experiment's table: a row per size and algorithm (sampler, n,
** algorithm, trials, then each quantity of study_cpdt_count_name and its
** interval's half-width NAME_half), %.10g.  The log-log plot of one quantity's
** means against n, a line per algorithm, its fitted slope in the legend
** (study_cpdt_slope).  0, or -1 on a write error. */
int report_cpdt_csv(FILE *f, const char *sampler, uint64_t trials, const study_cpdt_cell *cells,
                    size_t ncells);
int report_cpdt_svg(FILE *f, const char *title, const study_cpdt_cell *cells, size_t ncells,
                    const int *algorithms, size_t nalgorithms, int count);
/* ---- fliplab paradigms (reports/paradigms.c) ----
** Table 2.4 anew.  The CSV: a row per cell of study_paradigms_run
** (algorithm, paradigm, section, rule, family, n, distinct, triangles,
** status "ok" or "refused: <reason>", seconds, each count per site
** NAME_per_site, then the growth exponents growth_seconds and
** growth_NAME of the cell's (algorithm, rule, family), empty when there
** is none).  The Markdown table: a row per (algorithm, rule, family), the
** median time of each size in ms, the time's growth exponent, and the
** counts per site at the largest size; a refused row says why.  The SVG:
** count k per site (k = OPS_COUNT: the time) against n on log axes, a
** line per algorithm for the run's first rule and family, its slope in
** the legend.  0, or -1 on a write error. */
int report_paradigms_csv(FILE *f, const study_paradigms_plan *pl,
                         const study_paradigms_cell *cells);
int report_paradigms_md(FILE *f, const study_paradigms_plan *pl,
                        const study_paradigms_cell *cells);
int report_paradigms_svg(FILE *f, const char *title, const study_paradigms_plan *pl,
                         const study_paradigms_cell *cells, int k);

/* ---- random convex polygons (reports/svg_convex.c) ---- */

/* count polygons of n vertices each (xy[k n .. k n + n)), panels in rows
** of four at one common scale, titled with index[k] and, when log_weight
** is not NULL, the log weight.  0, or -1 once the stream has an error. */
int report_convex_svg(FILE *f, const geom_point *xy, size_t n, size_t count,
                      const uint64_t *index, const double *log_weight);

#endif
