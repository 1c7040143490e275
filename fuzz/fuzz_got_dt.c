/*
** fuzz_got_dt.c: the Delaunay certificate of a point set's GOT (got/got_skel_dt.c, through
** got_points_solve_dt with the skeleton "delaunay") on triangle lists the fuzzer makes.  Byte
** 0 gives n (3 to 12), the next n bytes the points (x = b & 7, y = (b >> 3) & 7: an 8 x 8
** integer grid, full of collinear and cocircular quadruples), the rest triangles, three
** bytes each (an index b % (n + 1): sometimes a point beyond n).  Never a crash; a refusal
** is one line; an accepted list must be a Delaunay triangulation, so the R_1 total, which is
** the same for every Delaunay triangulation (a cocircular cell's triangles share its
** circumradius), equals that of lot's exact Delaunay triangulation.
*/
#include <math.h>
#include "fuzz_support.h"
#include "got.h"
#include "lot.h"

/* R_1's total key of lot's Delaunay triangulation of p. */
static double fuzz_dt_key(const geom_point *p, size_t n, const rule *r) {
  lot_options o;
  rule dt = rule_delaunay();
  lot_options_init(&o, &dt);
  lot *L = NULL;
  char err[256];
  if (lot_build(&L, p, n, &o, err, sizeof err) != 0) abort();
  size_t nt = lot_get_stats(L)->triangles;
  uint32_t tri[3 * 2 * 12];
  double bad[2 * 12];
  lot_get_triangles(L, tri);
  lot_get_badness(p, tri, nt, r, bad);
  lot_free(L);
  return rule_total_key(r, bad, nt);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static rule r;
  static int ready;
  char err[512] = "";
  if (!ready && rule_parse("R_1", &r, err, sizeof err) != 0) abort();
  ready = 1;
  if (size < 1) return 0;
  size_t n = 3 + data[0] % 10;
  if (size < 1 + n) return 0;
  geom_point p[12];
  for (size_t i = 0; i < n; i++) p[i] = (geom_point){data[1 + i] & 7, (data[1 + i] >> 3) & 7};
  size_t nt = (size - 1 - n) / 3;
  if (nt > 64) nt = 64;
  uint32_t tri[3 * 64 + 1];
  for (size_t k = 0; k < 3 * nt; k++) tri[k] = data[1 + n + k] % (n + 1);
  got_options o = {1, RULE_DEFAULT_TIE_EPS};
  got_result res;
  if (got_points_solve_dt(p, n, &r, &o, GOT_SKELETON_DELAUNAY, nt ? tri : NULL, nt, &res, err,
                          sizeof err) != 0) {
    if (err[0] == '\0' || strchr(err, '\n') != NULL) abort();
    return 0;
  }
  double k = fuzz_dt_key(p, n, &r);
  if (res.ntri != nt || !(fabs(res.key - k) <= 1e-9 * fabs(k))) {
    fprintf(stderr, "accepted %zu triangles (GOT %zu), total %.17g, Delaunay's %.17g\n", nt,
            res.ntri, res.key, k);
    abort();
  }
  got_result_free(&res);
  return 0;
}
