/*
** poly.c: Triangle's .poly files (report_poly_read, report_poly_write):
** vertices, segments and hole points of a planar straight-line graph, the
** input of `fliplab lot --poly` and the output of `fliplab sample --format
** poly`.  The format and what fliplab makes of it: docs/formats.md.
**
** The reader is strict where Triangle is lenient about what a mistake looks
** like: every line has exactly its fields, every count is honoured (a file
** that ends early or goes on after the last section is refused), vertices
** are numbered consecutively from 0 or 1 as the first one says, segment
** endpoints name existing vertices, coordinates (vertices, holes, regions)
** honour the contract of geom.h, other reals go through the same number
** parser.  Every refusal is one line, "FILE line N: problem".
**
** Lines are read with getline, so a line of any length is read whole; a
** token is a span (pointer and length) into it, and the number parsers
** read spans, so a NUL byte inside a token makes it no number.
*/
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"

typedef struct report_poly_tok {
  const char *s;
  size_t len;
} report_poly_tok;

typedef struct report_poly_reader {
  FILE *in;
  const char *path;
  char *buf;
  size_t bufcap;
  uint64_t line;              /* of the last line read */
  report_poly_tok *tok;
  size_t ntok, tokcap;
  char *err;
  size_t errlen;
} report_poly_reader;

#define REPORT_POLY_MAX_ATTRS 1000   /* per vertex: far beyond any real file */

/* Room for one more token. */
static int report_poly_tok_grow(report_poly_reader *r) {
  if (r->ntok < r->tokcap) return 0;
  size_t cap = r->tokcap ? 2 * r->tokcap : 16;
  report_poly_tok *t = realloc(r->tok, cap * sizeof *t);
  if (t == NULL) return -1;
  r->tok = t;
  r->tokcap = cap;
  return 0;
}

static int report_poly_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

/* The next line with at least one token (blank lines and everything from
** '#' to the end of a line are comments): 1 (its tokens in r->tok), 0 at
** the end of the file, -1 with err set on a read error or no memory. */
static int report_poly_next(report_poly_reader *r) {
  for (;;) {
    errno = 0;
    ssize_t got = getline(&r->buf, &r->bufcap, r->in);
    if (got < 0) {
      if (ferror(r->in) || errno == ENOMEM) {
        snprintf(r->err, r->errlen, "%s line %llu: %s", r->path,
                 (unsigned long long)r->line + 1, errno == ENOMEM ? "out of memory"
                                                                  : "read error");
        return -1;
      }
      return 0;
    }
    r->line++;
    size_t n = (size_t)got, i = 0;
    r->ntok = 0;
    while (i < n && r->buf[i] != '#') {
      if (report_poly_blank(r->buf[i])) {
        i++;
        continue;
      }
      size_t j = i;
      while (j < n && !report_poly_blank(r->buf[j]) && r->buf[j] != '#') j++;
      if (report_poly_tok_grow(r) != 0) {
        snprintf(r->err, r->errlen, "%s line %llu: out of memory", r->path,
                 (unsigned long long)r->line);
        return -1;
      }
      r->tok[r->ntok++] = (report_poly_tok){r->buf + i, j - i};
      i = j;
    }
    if (r->ntok > 0) return 1;
  }
}

/* "FILE line N: " then the message; always -1. */
static int report_poly_fail(report_poly_reader *r, const char *what, const char *detail) {
  snprintf(r->err, r->errlen, "%s line %llu: %s%s", r->path, (unsigned long long)r->line,
           what, detail ? detail : "");
  return -1;
}

/* The next line, which must exist (`what` names it in the message). */
static int report_poly_need(report_poly_reader *r, const char *what) {
  int k = report_poly_next(r);
  if (k != 0) return k;
  snprintf(r->err, r->errlen, "%s line %llu: the file ends before %s (truncated, or a count "
           "is too large)", r->path, (unsigned long long)(r->line ? r->line : 1), what);
  return -1;
}

/* Token k as a count (digits only), at most max; -1 with err naming it. */
static int report_poly_count(report_poly_reader *r, size_t k, const char *what, uint64_t max,
                             uint64_t *out) {
  const report_poly_tok *t = &r->tok[k];
  char msg[200];
  if (geom_count_parse(t->s, t->len, out) != 0) {
    snprintf(msg, sizeof msg, "%s '%.*s' is not a non-negative integer", what,
             (int)(t->len > 40 ? 40 : t->len), t->s);
    return report_poly_fail(r, msg, NULL);
  }
  if (*out > max) {
    snprintf(msg, sizeof msg, "%s %llu is too large (at most %llu)", what,
             (unsigned long long)*out, (unsigned long long)max);
    return report_poly_fail(r, msg, NULL);
  }
  return 0;
}

/* Token k as a boundary marker: an integer, optionally signed (ignored). */
static int report_poly_marker(report_poly_reader *r, size_t k) {
  const report_poly_tok *t = &r->tok[k];
  size_t skip = t->len > 1 && (t->s[0] == '-' || t->s[0] == '+');
  uint64_t v;
  if (geom_count_parse(t->s + skip, t->len - skip, &v) == 0) return 0;
  char msg[120];
  snprintf(msg, sizeof msg, "boundary marker '%.*s' is not an integer",
           (int)(t->len > 40 ? 40 : t->len), t->s);
  return report_poly_fail(r, msg, NULL);
}

/* Token k as a coordinate under the contract (coord: 1) or as any real. */
static int report_poly_real(report_poly_reader *r, size_t k, const char *what, int coord,
                            double *out) {
  const report_poly_tok *t = &r->tok[k];
  char msg[200];
  int len = (int)(t->len > 40 ? 40 : t->len);
  if (coord) {
    geom_coorderr e = geom_coord_parse_n(t->s, t->len, out);
    if (e == GEOM_COORD_OK) return 0;
    snprintf(msg, sizeof msg, "%s '%.*s' %s", what, len, t->s, geom_coorderr_str(e));
  } else {
    geom_numerr e = geom_number_parse(t->s, t->len, out);
    if (e == GEOM_NUM_OK) return 0;
    snprintf(msg, sizeof msg, "%s '%.*s' %s", what, len, t->s, geom_numerr_str(e));
  }
  return report_poly_fail(r, msg, NULL);
}

/* The line has between lo and hi tokens. */
static int report_poly_fields(report_poly_reader *r, size_t lo, size_t hi, const char *what) {
  if (r->ntok >= lo && r->ntok <= hi) return 0;
  char msg[200];
  if (lo == hi)
    snprintf(msg, sizeof msg, "%s: expected %zu fields, got %zu", what, lo, r->ntok);
  else
    snprintf(msg, sizeof msg, "%s: expected %zu to %zu fields, got %zu", what, lo, hi, r->ntok);
  return report_poly_fail(r, msg, NULL);
}

/* Room for n + 1 elements of `size` bytes in *p (capacity *cap). */
static int report_poly_grow(void **p, size_t *cap, size_t n, size_t size) {
  if (n < *cap) return 0;
  size_t c = *cap ? 2 * *cap : 64;
  void *q = realloc(*p, c * size);
  if (q == NULL) return -1;
  *p = q;
  *cap = c;
  return 0;
}

/* The first line: #vertices [dimension [#attributes [#markers]]], the
** missing ones defaulting as in Triangle (2, 0, 0). */
static int report_poly_header(report_poly_reader *r, uint64_t *nv, uint64_t *attrs,
                              uint64_t *marks) {
  uint64_t dim = 2;
  *attrs = *marks = 0;
  if (report_poly_need(r, "the first line '#vertices 2 #attributes #boundary-markers'") < 0 ||
      report_poly_fields(r, 1, 4, "first line '#vertices 2 #attributes #boundary-markers'") ||
      report_poly_count(r, 0, "vertex count", LOT_MAX_POINTS, nv) ||
      (r->ntok > 1 && report_poly_count(r, 1, "dimension", UINT64_MAX, &dim)) ||
      (r->ntok > 2 && report_poly_count(r, 2, "attribute count", REPORT_POLY_MAX_ATTRS, attrs)) ||
      (r->ntok > 3 && report_poly_count(r, 3, "boundary marker count", 1, marks)))
    return -1;
  if (dim != 2) {
    char msg[80];
    snprintf(msg, sizeof msg, "dimension %llu: only 2 is supported", (unsigned long long)dim);
    return report_poly_fail(r, msg, NULL);
  }
  if (*nv == 0)
    return report_poly_fail(r, "0 vertices, which in Triangle means a separate .node file; "
                            "fliplab reads only the vertices listed in the .poly file", NULL);
  if (*nv < 3) return report_poly_fail(r, "fewer than 3 vertices", NULL);
  return 0;
}

/* The vertex number of vertex i: the first one sets the base (0 or 1),
** the others follow it consecutively. */
static int report_poly_vertex_id(report_poly_reader *r, uint64_t i, report_poly *out) {
  uint64_t id;
  if (report_poly_count(r, 0, "vertex number", UINT64_MAX, &id) != 0) return -1;
  char msg[160];
  if (i == 0 && id > 1) {
    snprintf(msg, sizeof msg, "the first vertex is numbered %llu; vertices are numbered from "
             "0 or 1", (unsigned long long)id);
    return report_poly_fail(r, msg, NULL);
  }
  if (i == 0) out->first = (int)id;
  if (id != (uint64_t)out->first + i) {
    snprintf(msg, sizeof msg, "vertex number %llu, expected %llu (vertices are numbered "
             "consecutively)", (unsigned long long)id,
             (unsigned long long)((uint64_t)out->first + i));
    return report_poly_fail(r, msg, NULL);
  }
  return 0;
}

static int report_poly_vertices(report_poly_reader *r, report_poly *out) {
  uint64_t nv, attrs, marks;
  if (report_poly_header(r, &nv, &attrs, &marks) != 0) return -1;
  out->attributes = (size_t)attrs;
  out->markers = marks != 0;
  size_t cap = 0;
  for (uint64_t i = 0; i < nv; i++) {
    double xy[2], a;
    if (report_poly_need(r, "the last vertex") < 0 ||
        report_poly_fields(r, 3 + attrs + marks, 3 + attrs + marks,
                           "vertex line 'i x y [attributes] [marker]'") ||
        report_poly_vertex_id(r, i, out) || report_poly_real(r, 1, "x", 1, &xy[0]) ||
        report_poly_real(r, 2, "y", 1, &xy[1]))
      return -1;
    for (size_t k = 0; k < attrs; k++)
      if (report_poly_real(r, 3 + k, "attribute", 0, &a) != 0) return -1;
    if (marks && report_poly_marker(r, 3 + attrs) != 0) return -1;
    if (report_poly_grow((void **)&out->g.pts, &cap, out->g.npts, sizeof *out->g.pts) != 0)
      return report_poly_fail(r, "out of memory", NULL);
    out->g.pts[out->g.npts++] = (geom_point){xy[0], xy[1]};
  }
  return 0;
}

/* Endpoint k of a segment, as a 0-based vertex index. */
static int report_poly_endpoint(report_poly_reader *r, size_t k, const report_poly *out,
                                uint32_t *v) {
  uint64_t id;
  if (report_poly_count(r, k, "segment endpoint", UINT64_MAX, &id) != 0) return -1;
  uint64_t lo = (uint64_t)out->first, hi = lo + out->g.npts - 1;
  if (id < lo || id > hi) {
    char msg[160];
    snprintf(msg, sizeof msg, "segment endpoint %llu is not a vertex (the vertices are %llu "
             "to %llu)", (unsigned long long)id, (unsigned long long)lo, (unsigned long long)hi);
    return report_poly_fail(r, msg, NULL);
  }
  *v = (uint32_t)(id - lo);
  return 0;
}

static int report_poly_segments(report_poly_reader *r, report_poly *out) {
  uint64_t ns, marks = 0, id;
  if (report_poly_need(r, "the segment count line '#segments #boundary-markers'") < 0 ||
      report_poly_fields(r, 1, 2, "segment count line '#segments #boundary-markers'") ||
      report_poly_count(r, 0, "segment count", UINT32_MAX, &ns) ||
      (r->ntok > 1 && report_poly_count(r, 1, "boundary marker count", 1, &marks)))
    return -1;
  out->markers |= marks != 0;
  size_t cap = 0, lcap = 0;
  for (uint64_t i = 0; i < ns; i++) {
    uint32_t a, b;
    if (report_poly_need(r, "the last segment") < 0 ||
        report_poly_fields(r, 3 + marks, 3 + marks, "segment line 'i a b [marker]'") ||
        report_poly_count(r, 0, "segment number", UINT64_MAX, &id) ||
        report_poly_endpoint(r, 1, out, &a) || report_poly_endpoint(r, 2, out, &b) ||
        (marks && report_poly_marker(r, 3) != 0))
      return -1;
    if (a == b) return report_poly_fail(r, "the segment joins a vertex to itself", NULL);
    if (report_poly_grow((void **)&out->g.seg, &cap, out->g.nseg, 2 * sizeof *out->g.seg) ||
        report_poly_grow((void **)&out->seg_line, &lcap, out->g.nseg, sizeof *out->seg_line))
      return report_poly_fail(r, "out of memory", NULL);
    out->g.seg[2 * out->g.nseg] = a;
    out->g.seg[2 * out->g.nseg + 1] = b;
    out->seg_line[out->g.nseg++] = r->line;
  }
  return 0;
}

static int report_poly_holes(report_poly_reader *r, report_poly *out) {
  uint64_t nh, id;
  if (report_poly_need(r, "the hole count line '#holes'") < 0 ||
      report_poly_fields(r, 1, 1, "hole count line '#holes'") ||
      report_poly_count(r, 0, "hole count", UINT32_MAX, &nh))
    return -1;
  size_t cap = 0;
  for (uint64_t i = 0; i < nh; i++) {
    double xy[2];
    if (report_poly_need(r, "the last hole") < 0 ||
        report_poly_fields(r, 3, 3, "hole line 'i x y'") ||
        report_poly_count(r, 0, "hole number", UINT64_MAX, &id) ||
        report_poly_real(r, 1, "hole x", 1, &xy[0]) || report_poly_real(r, 2, "hole y", 1, &xy[1]))
      return -1;
    if (report_poly_grow((void **)&out->g.hole, &cap, out->g.nholes, sizeof *out->g.hole) != 0)
      return report_poly_fail(r, "out of memory", NULL);
    out->g.hole[out->g.nholes++] = (geom_point){xy[0], xy[1]};
  }
  return 0;
}

/* The optional last section: regional attributes and area constraints,
** checked and counted, not kept (fliplab has no use for them). */
static int report_poly_regions(report_poly_reader *r, report_poly *out) {
  uint64_t nr, id;
  int k = report_poly_next(r);
  if (k <= 0) return k;
  if (report_poly_fields(r, 1, 1, "region count line '#regions'") ||
      report_poly_count(r, 0, "region count", UINT32_MAX, &nr))
    return -1;
  for (uint64_t i = 0; i < nr; i++) {
    double v;
    if (report_poly_need(r, "the last region") < 0 ||
        report_poly_fields(r, 4, 5, "region line 'i x y attribute [maximum-area]'") ||
        report_poly_count(r, 0, "region number", UINT64_MAX, &id) ||
        report_poly_real(r, 1, "region x", 1, &v) || report_poly_real(r, 2, "region y", 1, &v) ||
        report_poly_real(r, 3, "regional attribute", 0, &v) ||
        (r->ntok > 4 && report_poly_real(r, 4, "maximum area", 0, &v)))
      return -1;
    out->regions++;
  }
  k = report_poly_next(r);
  if (k < 0) return -1;
  if (k > 0)
    return report_poly_fail(r, "more lines than the counts announce (after the regions)", NULL);
  return 0;
}

void report_poly_free(report_poly *p) {
  geom_pslg_free(&p->g);
  free(p->seg_line);
  memset(p, 0, sizeof *p);
}

int report_poly_read(const char *path, report_poly *out, char *err, size_t errlen) {
  memset(out, 0, sizeof *out);
  FILE *f = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
  if (f == NULL) {
    snprintf(err, errlen, "cannot read '%s': %s", path, strerror(errno));
    return -1;
  }
  report_poly_reader r = {.in = f, .path = path, .err = err, .errlen = errlen};
  err[0] = '\0';
  int rc = report_poly_vertices(&r, out) || report_poly_segments(&r, out) ||
           report_poly_holes(&r, out) || report_poly_regions(&r, out) ? -1 : 0;
  if (f != stdin) fclose(f);
  free(r.buf);
  free(r.tok);
  if (rc != 0) {
    if (err[0] == '\0') snprintf(err, errlen, "%s: cannot be read", path);
    report_poly_free(out);
  }
  return rc;
}

/* One "%.17g" coordinate pair after a label; the fprintf result is
** checked once, by ferror, when the file is closed (cli_close_out). */
int report_poly_write(FILE *f, const geom_pslg *p) {
  fprintf(f, "# fliplab: %zu vertices, %zu segments, %zu holes (Triangle's .poly format)\n",
          p->npts, p->nseg, p->nholes);
  fprintf(f, "%zu 2 0 0\n", p->npts);
  for (size_t i = 0; i < p->npts; i++)
    fprintf(f, "%zu %.17g %.17g\n", i, p->pts[i].x, p->pts[i].y);
  fprintf(f, "%zu 0\n", p->nseg);
  for (size_t i = 0; i < p->nseg; i++)
    fprintf(f, "%zu %u %u\n", i, p->seg[2 * i], p->seg[2 * i + 1]);
  fprintf(f, "%zu\n", p->nholes);
  for (size_t i = 0; i < p->nholes; i++)
    fprintf(f, "%zu %.17g %.17g\n", i, p->hole[i].x, p->hole[i].y);
  return ferror(f) ? -1 : 0;
}
