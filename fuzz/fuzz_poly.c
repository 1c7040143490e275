/*
** fuzz_poly.c: Triangle's .poly reader (report_poly_read).  Whatever it
** accepts must be a graph fliplab can take: at least three vertices under
** the coordinate contract, segment endpoints that name two different
** vertices, hole points under the contract, segment lines increasing; and
** written back (report_poly_write) it must read back to the same graph,
** bit for bit.  A refusal always says why, in one line.
*/
#include "fuzz_support.h"
#include "geom.h"
#include "report.h"

static int fuzz_poly_valid(const report_poly *r) {
  const geom_pslg *p = &r->g;
  int ok = p->npts >= 3 && (r->first == 0 || r->first == 1);
  for (size_t i = 0; i < p->npts; i++)
    ok &= geom_coord_check(p->pts[i].x) == GEOM_COORD_OK &&
          geom_coord_check(p->pts[i].y) == GEOM_COORD_OK;
  for (size_t i = 0; i < p->nseg; i++)
    ok &= p->seg[2 * i] < p->npts && p->seg[2 * i + 1] < p->npts &&
          p->seg[2 * i] != p->seg[2 * i + 1] && (i == 0 || r->seg_line[i] > r->seg_line[i - 1]);
  for (size_t i = 0; i < p->nholes; i++)
    ok &= geom_coord_check(p->hole[i].x) == GEOM_COORD_OK &&
          geom_coord_check(p->hole[i].y) == GEOM_COORD_OK;
  return ok;
}

/* Written and read back: the same vertices, segments and holes. */
static void fuzz_poly_round_trip(const geom_pslg *p) {
  static char path[64];
  if (path[0] == '\0') snprintf(path, sizeof path, "/tmp/fliplab-fuzz-%ld.poly", (long)getpid());
  FILE *f = fopen(path, "wb");
  if (f == NULL || report_poly_write(f, p) != 0 || fclose(f) != 0) abort();
  report_poly r;
  char err[512];
  if (report_poly_read(path, &r, err, sizeof err) != 0) abort();
  const geom_pslg q = r.g;
  if (q.npts != p->npts || q.nseg != p->nseg || q.nholes != p->nholes || r.first != 0 ||
      memcmp(q.pts, p->pts, p->npts * sizeof *p->pts) != 0 ||
      (p->nseg && memcmp(q.seg, p->seg, 2 * p->nseg * sizeof *p->seg) != 0) ||
      (p->nholes && memcmp(q.hole, p->hole, p->nholes * sizeof *p->hole) != 0))
    abort();
  report_poly_free(&r);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const char *path = fuzz_path(data, size);
  report_poly p;
  char err[512];
  if (report_poly_read(path, &p, err, sizeof err) == 0) {
    if (!fuzz_poly_valid(&p)) abort();
    fuzz_poly_round_trip(&p.g);
    report_poly_free(&p);
  } else if (err[0] == '\0' || strchr(err, '\n') != NULL) {
    abort();
  }
  return 0;
}
