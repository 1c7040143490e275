/*
** cdf.c: the convex-distance (CDF) Delaunay graph of a convex shape K, read
** off an empty-shape triangulation of K (thesis 4.1.2): the triangles whose
** circumscribing shape is a homothet of K, and the CDF-Delaunay edges that
** lie in no such triangle.  docs/emptyshape.md has the argument.
*/
#include <stdlib.h>
#include <string.h>

#include "lot.h"
#include "geom_key_internal.h"

/* Edge classes in the sort below. */
enum { LOT_CDF_CANDIDATE = 1, LOT_CDF_NONEDGE = 2, LOT_CDF_KEPT = 4 };

typedef struct lot_cdf_rec {
  uint64_t key;     /* smaller index << 32 | larger index */
  unsigned cls;
} lot_cdf_rec;

int lot_cdf_nonedge(const shape *k, geom_point a, geom_point b, geom_point c) {
  switch (k->kind) {
  case SHAPE_ELLIPSE: return -1;   /* smooth: every triangle has a homothet */
  case SHAPE_POLYGON: break;
  }
  int ab = shape_support(k, a, b), bc = shape_support(k, b, c), ca = shape_support(k, c, a);
  if (ab == bc) return 2;
  if (ab == ca) return 1;
  if (bc == ca) return 0;
  return -1;
}

static int lot_cdf_cmp(const void *x, const void *y) {
  uint64_t a = ((const lot_cdf_rec *)x)->key, b = ((const lot_cdf_rec *)y)->key;
  return a < b ? -1 : a > b;
}

/* Classify every triangle: kept ones are copied to out->tri, and each of the
** 3 ntri edge records says what its triangle makes of it. */
static void lot_cdf_classify(const geom_point *p, const uint32_t *tri, size_t ntri,
                             const shape *k, lot_cdf *out, lot_cdf_rec *rec) {
  for (size_t t = 0; t < ntri; t++) {
    const uint32_t *v = tri + 3 * t;
    int bad = lot_cdf_nonedge(k, p[v[0]], p[v[1]], p[v[2]]);
    if (bad < 0) {
      memcpy(out->tri + 3 * out->triangles++, v, 3 * sizeof *v);
    } else {
      out->rounded++;
    }
    for (int e = 0; e < 3; e++) {
      lot_cdf_rec *r = rec + 3 * t + (size_t)e;
      r->key = geom_edge_key(v[e], v[(e + 1) % 3]);
      r->cls = bad < 0 ? LOT_CDF_KEPT : bad == e ? LOT_CDF_NONEDGE : LOT_CDF_CANDIDATE;
    }
  }
}

/* Merge the records of each edge (one or two: an edge is in at most two
** triangles): an extra edge is a candidate of a dropped triangle that is no
** triangle's non-edge and in no kept triangle. */
static void lot_cdf_merge(lot_cdf_rec *rec, size_t nrec, lot_cdf *out) {
  qsort(rec, nrec, sizeof *rec, lot_cdf_cmp);
  for (size_t i = 0; i < nrec;) {
    size_t j = i;
    unsigned cls = 0;
    while (j < nrec && rec[j].key == rec[i].key) cls |= rec[j++].cls;
    if ((cls & LOT_CDF_KEPT) && (cls & LOT_CDF_NONEDGE)) out->conflicts++;
    if (cls == LOT_CDF_CANDIDATE) {
      out->edge[2 * out->edges] = (uint32_t)(rec[i].key >> 32);
      out->edge[2 * out->edges + 1] = (uint32_t)rec[i].key;
      out->edges++;
    }
    i = j;
  }
}

int lot_cdf_extract(const geom_point *p, const uint32_t *tri, size_t ntri, const shape *k,
                    lot_cdf *out) {
  memset(out, 0, sizeof *out);
  size_t nrec = 3 * ntri, room = nrec ? nrec : 1;
  lot_cdf_rec *rec = malloc(room * sizeof *rec);
  out->tri = malloc(room * sizeof *out->tri);
  out->edge = malloc(2 * room * sizeof *out->edge);
  if (!rec || !out->tri || !out->edge) {
    free(rec);
    lot_cdf_free(out);
    return -1;
  }
  lot_cdf_classify(p, tri, ntri, k, out, rec);
  lot_cdf_merge(rec, nrec, out);
  free(rec);
  return 0;
}

void lot_cdf_free(lot_cdf *c) {
  if (!c) return;
  free(c->tri);
  free(c->edge);
  memset(c, 0, sizeof *c);
}
