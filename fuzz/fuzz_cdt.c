/*
** fuzz_cdt.c: constrained triangulations on adversarial input.  The bytes
** make up to 40 points on a 16 x 16 grid (rows and columns collinear,
** squares cocircular: the special positions), segments between them, hole
** points at half-integers and a rule (DT, P_1, ES:square); lot_build must
** either refuse in one line or give a result that lot_check_constrained
** accepts from scratch (valid with holes, every unconstrained edge locally
** optimal, exactly the removed segments missing); for DT, the flip
** algorithm must give the same CDT as the incremental one, and without
** holes so must chapter 2's rows that build it otherwise (divide and
** conquer with both kinds of cut, the constrained sweep), or all refuse
** (but the sweep refuses segments that cross at a site, docs/paradigms.md).
*/
#include "fuzz_support.h"
#include "lot.h"
#include "paradigm.h"
#include "rule.h"

static const char *const fuzz_cdt_rules[] = {"DT", "P_1", "ES:square"};

/* 0 on a refusal, 1 on a result (its triangles in *tri, *ntri). */
static int fuzz_cdt_build(const geom_point *p, size_t n, const lot_options *o, uint32_t **tri,
                          size_t *ntri, lot_stats *st) {
  lot *L;
  char err[512];
  if (lot_build(&L, p, n, o, err, sizeof err) != 0) {
    if (err[0] == 0 || strchr(err, '\n') != NULL) abort();   /* one line, always */
    return 0;
  }
  *st = *lot_get_stats(L);
  *ntri = st->triangles;
  *tri = malloc((3 * *ntri + 1) * sizeof **tri);
  if (*tri == NULL) abort();
  lot_get_triangles(L, *tri);
  lot_free(L);
  return 1;
}

/* The rows "incremental", "dc-constrained" (parameters 0 and 1) and
** "sweep-constrained" on the points and segments: all refuse (on one
** line) or all give the same triangles. */
static void fuzz_cdt_rows(const geom_point *p, size_t n, const uint32_t *seg, size_t nseg,
                          const rule *r) {
  static const char *const row[] = {"incremental", "dc-constrained", "dc-constrained",
                                    "sweep-constrained"};
  paradigm_result res[4];
  int rc[4];
  for (int k = 0; k < 4; k++) {
    paradigm_input in = {.p = p, .n = n, .r = r, .problem = PARADIGM_CONSTRAINED,
                         .segments = seg, .nsegments = nseg, .threads = 1, .param = k == 2};
    char err[512];
    rc[k] = paradigm_run(paradigm_find(row[k]), &in, &res[k], err, sizeof err);
    if (rc[k] != 0 && (err[0] == 0 || strchr(err, '\n') != NULL)) abort();
    /* the sweep refuses segments crossing at a site, which lot splits there */
    if (k == 3 && rc[k] != 0 && rc[0] == 0 && strstr(err, " cross") != NULL) continue;
    if ((rc[k] != 0) != (rc[0] != 0)) abort();
    if (rc[k] == 0 && (res[k].ntri != res[0].ntri
                       || memcmp(res[k].tri, res[0].tri, 3 * res[0].ntri * sizeof *res[0].tri)))
      abort();
  }
  for (int k = 0; k < 4; k++)
    if (rc[k] == 0) paradigm_result_free(&res[k]);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static rule rules[3];
  static int ready;
  if (!ready) {
    char err[512];
    for (int i = 0; i < 3; i++)
      if (rule_parse(fuzz_cdt_rules[i], &rules[i], err, sizeof err) != 0) abort();
    ready = 1;
  }
  if (size < 4) return 0;
  size_t n = 3 + data[0] % 38, nseg = data[1] % 30, nholes = data[2] % 3;
  const rule *r = &rules[(data[3] & 0x7f) % 3];
  int keep = data[3] >> 7;
  data += 4;
  size -= 4;
  if (size < n + 2 * nseg + nholes) return 0;
  geom_point p[40], holes[3];
  uint32_t seg[60];
  for (size_t i = 0; i < n; i++) p[i] = (geom_point){data[i] & 15, data[i] >> 4};
  for (size_t k = 0; k < 2 * nseg; k++) seg[k] = data[n + k] % (n + 1);   /* n: out of range */
  for (size_t h = 0; h < nholes; h++)
    holes[h] = (geom_point){(data[n + 2 * nseg + h] & 15) + 0.5, (data[n + 2 * nseg + h] >> 4) + 0.5};
  lot_options o;
  lot_options_init(&o, r);
  o.segments = seg;
  o.nsegments = nseg;
  o.holes = holes;
  o.nholes = nholes;
  o.keep_hull = keep;
  uint32_t *tri = NULL, *tri2 = NULL;
  size_t ntri, ntri2;
  lot_stats st, st2;
  if (rule_is_delaunay(r) && nholes == 0) fuzz_cdt_rows(p, n, seg, nseg, r);
  if (!fuzz_cdt_build(p, n, &o, &tri, &ntri, &st)) return 0;
  lot_check_result c;
  if (lot_check_constrained(p, n, tri, ntri, seg, nseg, r, &c) != 0) abort();
  if (!c.valid || c.not_optimal != 0 || c.segments_missing != st.segments_removed) {
    fprintf(stderr, "valid %d not_optimal %zu (edge %u-%u) missing %zu removed %zu\n", c.valid, c.not_optimal, c.bad_edge[0], c.bad_edge[1], c.segments_missing, st.segments_removed);
    abort();
  }
  if (rule_is_delaunay(r)) {
    o.algorithm = LOT_FLIP;
    if (!fuzz_cdt_build(p, n, &o, &tri2, &ntri2, &st2)) abort();
    if (ntri2 != ntri || memcmp(tri, tri2, 3 * ntri * sizeof *tri) != 0) abort();
  }
  free(tri);
  free(tri2);
  return 0;
}
