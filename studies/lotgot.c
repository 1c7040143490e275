/*
** lotgot.c: a LOT against the GOT of the same polygon (docs/lot.md): the
** polygon rebuilt from the input (the hull of points in strictly convex
** position, or the one closed ring a constrained run's segments form), its
** GOT, and the relation theory demands: the LOT totals at least the GOT's,
** and for the rules whose GOT is the CDT (rule_got_is_cdt) the constrained
** LOT, their CDT, has the GOT's triangles.
*/
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "study.h"

#define STUDY_NEED_RING "the GOT comparison needs a simple polygon: segments forming one " \
                        "closed ring through every point"

/* err's one line; returns -1. */
static int study_err(char *err, size_t errlen, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  if (err != NULL && errlen > 0) vsnprintf(err, errlen, fmt, ap);
  va_end(ap);
  return -1;
}

/* The degrees of the points on the segments into deg, their two neighbours
** into nb[2 v], nb[2 v + 1]: 0, or -1 unless every point is on exactly two. */
static int study_ring_degrees(const geom_pslg *in, uint32_t *deg, uint32_t *nb, char *err,
                              size_t errlen) {
  size_t n = in->npts;
  memset(deg, 0, n * sizeof *deg);
  for (size_t k = 0; k < 2 * n; k++) {
    uint32_t v = in->seg[k], w = in->seg[k ^ 1];
    if (v >= n || w >= n)
      return study_err(err, errlen, "%s (segment %zu names a point beyond the %zu given)",
                       STUDY_NEED_RING, k / 2, n);
    if (deg[v] == 2)
      return study_err(err, errlen, "%s (point %u is on more than 2 segments)", STUDY_NEED_RING,
                       v);
    nb[2 * v + deg[v]++] = w;
  }
  for (size_t v = 0; v < n; v++)
    if (deg[v] != 2)
      return study_err(err, errlen, "%s (point %zu is on %u segment)", STUDY_NEED_RING, v,
                       deg[v]);
  return 0;
}

/* The segments as one closed ring through all n points: ring[] the points
** in ring order from point 0 (nb: 2 n scratch).  O(n).  0, or -1 with err. */
static int study_ring(const geom_pslg *in, uint32_t *ring, uint32_t *nb, char *err,
                      size_t errlen) {
  size_t n = in->npts;
  if (in->nholes)
    return study_err(err, errlen, "%s, no holes (%zu given)", STUDY_NEED_RING, in->nholes);
  if (in->nseg != n || n < 3)
    return study_err(err, errlen, "%s (%zu segments, %zu points)", STUDY_NEED_RING, in->nseg, n);
  if (study_ring_degrees(in, ring, nb, err, errlen) != 0) return -1;
  ring[0] = 0;
  ring[1] = nb[0];
  for (size_t i = 2; i < n; i++) {
    uint32_t cur = ring[i - 1], prev = ring[i - 2];
    ring[i] = nb[2 * cur] == prev ? nb[2 * cur + 1] : nb[2 * cur];
    if (ring[i] == 0)
      return study_err(err, errlen, "%s (they form more than one ring)", STUDY_NEED_RING);
  }
  return 0;
}

/* The ring's polygon into poly, anticlockwise, and map[v]: its vertex v's
** input point.  0, or -1 with err. */
static int study_ring_polygon(const geom_pslg *in, size_t ntri, geom_point *poly, uint32_t *map,
                              char *err, size_t errlen) {
  size_t n = in->npts, b1, b2;
  int rev = 0;
  uint32_t *ring = malloc(n * sizeof *ring), *nb = malloc(2 * n * sizeof *nb);
  int rc = ring && nb ? study_ring(in, ring, nb, err, errlen)
                      : study_err(err, errlen, "out of memory");
  if (rc == 0 && ntri + 2 != n)
    rc = study_err(err, errlen, "the GOT comparison needs the LOT to triangulate the polygon: "
                   "it has %zu triangles, the polygon's triangulations %zu (is keep-hull "
                   "keeping the outside?)", ntri, n - 2);
  for (size_t i = 0; rc == 0 && i < n; i++) poly[i] = in->pts[ring[i]];
  geom_polyerr pe = rc == 0 ? geom_simple_polygon_check(poly, n, &b1, &b2, &rev) : GEOM_OK;
  if (rc == 0 && pe != GEOM_OK)
    rc = study_err(err, errlen, "the GOT comparison: the ring of segments is not a simple "
                   "polygon: %s", geom_polyerr_str(pe));
  for (size_t v = 0; rc == 0 && v < n; v++) map[v] = ring[rev ? (n - v) % n : v];
  free(ring);
  free(nb);
  return rc;
}

/* The hull's polygon (every distinct point a corner: by Euler's relation
** the LOT of n distinct points with h on the hull has 2n - h - 2
** triangles, h - 2 exactly when n = h) and map[v]. */
static int study_hull_polygon(const geom_point *p, const uint32_t *hull, size_t h, size_t ntri,
                              geom_point *poly, uint32_t *map, char *err, size_t errlen) {
  size_t bad;
  int rev = 0;
  for (size_t i = 0; i < h; i++) poly[i] = p[hull[i]];
  if (h < 3 || ntri + 2 != h || geom_polygon_check(poly, h, &bad, &rev) != GEOM_OK)
    return study_err(err, errlen, "the GOT comparison needs points in strictly convex position "
                     "(%zu of %zu distinct points are hull corners)", h, (ntri + h + 2) / 2);
  for (size_t v = 0; v < h; v++) map[v] = hull[rev ? (h - v) % h : v];
  return 0;
}

/* The relation of the LOT's total (c->lot_key) with the GOT's, and of their
** triangles (c->diff): equal within the sum of the certified error bounds,
** or without one within the rule's tie tolerance. */
static void study_got_relation(const rule *r, study_gotcheck *c) {
  const got_result *g = &c->got;
  double key = c->lot_key, bound = g->cert_err + got_cert_err_of(g, key);
  c->lot_total = rule_unkey(r, key);
  got_format_total(g, key, c->lot_text, sizeof c->lot_text);
  got_format_total(g, g->key, c->got_text, sizeof c->got_text);
  c->rel = rule_gap(r, key, g->key);
  c->certified = isfinite(bound);
  c->uncertified = c->certified ? NULL : g->cert_why ? g->cert_why
                                                     : "no forward error bound for the LOT's total";
  c->equal = key == g->key || (c->certified ? fabs(key - g->key) <= bound
                                            : c->rel <= rule_tie_eps(r));
  c->below = !c->equal && key < g->key;
  c->same = c->diff.triangles_common == c->diff.triangles_a &&
            c->diff.triangles_a == c->diff.triangles_b;
  c->got_is_cdt = rule_got_is_cdt(r);
  c->failed = c->below || (c->got_is_cdt && !c->same && !c->equal);
}

/* The GOT of poly[0..n-1] (map: its vertices' input points) into c, its
** triangles as input points, compared with the LOT's. */
static int study_got_of(const geom_point *poly, const uint32_t *map, const geom_pslg *in,
                        const uint32_t *tri, size_t ntri, const rule *r, int threads,
                        study_gotcheck *c, char *err, size_t errlen) {
  char why[512];
  got_options go = {threads, rule_tie_eps(r)};
  double *bad = malloc((ntri + 1) * sizeof *bad);
  c->tri = malloc(3 * c->n * sizeof *c->tri);
  int rc = bad && c->tri ? 0 : study_err(err, errlen, "out of memory");
  if (rc == 0 && got_check_memory(c->n, rule_measure(r), why, sizeof why) != 0)
    rc = study_err(err, errlen, "the GOT comparison: %s", why);
  if (rc == 0 && got_solve(poly, c->n, r, &go, &c->got, err, errlen) != 0) rc = -1;
  for (size_t t = 0; rc == 0 && t < c->got.ntri; t++) {
    c->tri[3 * t] = map[c->got.tri[t].i];
    c->tri[3 * t + 1] = map[c->got.tri[t].k];
    c->tri[3 * t + 2] = map[c->got.tri[t].j];
  }
  if (rc == 0 && lot_compare(tri, ntri, c->tri, c->got.ntri, &c->diff) != 0)
    rc = study_err(err, errlen, "out of memory");
  if (rc == 0) {
    lot_get_badness(in->pts, tri, ntri, r, bad);
    c->lot_key = rule_total_key(r, bad, ntri);
    study_got_relation(r, c);
  }
  free(bad);
  return rc;
}

int study_lot_got(const geom_pslg *in, const uint32_t *hull, size_t nhull, const uint32_t *tri,
                  size_t ntri, const rule *r, int threads, study_gotcheck *out, char *err,
                  size_t errlen) {
  memset(out, 0, sizeof *out);
  if (!rule_is_triangle(r))
    return study_err(err, errlen, "the GOT comparison needs a triangle-based rule "
                     "(MEASURE_JOINT), not '%s'", rule_name(r));
  out->ring = in->nseg > 0 || in->nholes > 0;
  out->n = out->ring ? in->npts : nhull;
  geom_point *poly = malloc((out->n + 1) * sizeof *poly);
  uint32_t *map = malloc((out->n + 1) * sizeof *map);
  int rc = poly && map ? 0 : study_err(err, errlen, "out of memory");
  if (rc == 0)
    rc = out->ring ? study_ring_polygon(in, ntri, poly, map, err, errlen)
                   : study_hull_polygon(in->pts, hull, nhull, ntri, poly, map, err, errlen);
  if (rc == 0) rc = study_got_of(poly, map, in, tri, ntri, r, threads, out, err, errlen);
  free(poly);
  free(map);
  if (rc != 0) study_gotcheck_free(out);
  return rc;
}

void study_gotcheck_free(study_gotcheck *c) {
  got_result_free(&c->got);
  free(c->tri);
  c->tri = NULL;
}
