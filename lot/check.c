/*
** check.c: checks of a triangulation given as a list of triangles, sharing
** nothing with the algorithms that made it: the structure (anticlockwise
** triangles, each edge in one or two triangles with opposite directions,
** Euler's count), local optimality of every interior edge decided afresh
** (rule_eval on the quadrilateral's own points; DT by the exact empty-circle
** test), the comparison of two triangulations, and each triangle's badness.
*/
#include <math.h>
#include <stdlib.h>
#include "lot.h"
#include "measure.h"

typedef struct lot_dedge {
  uint64_t key;         /* min << 32 | max */
  uint32_t t;           /* triangle */
  uint8_t e;            /* edge e of t: from tri[3t+e] to tri[3t+(e+1)%3] */
} lot_dedge;

static int lot_dedge_cmp(const void *x, const void *y) {
  const lot_dedge *a = x, *b = y;
  if (a->key != b->key) return a->key < b->key ? -1 : 1;
  return a->t < b->t ? -1 : a->t > b->t;
}

static uint64_t lot_ukey(uint32_t u, uint32_t v) {
  return u < v ? (uint64_t)u << 32 | v : (uint64_t)v << 32 | u;
}

static int lot_strictly_convex(const geom_point q[4]) {
  for (int i = 0; i < 4; i++)
    if (geom_orient(q[i], q[(i + 1) % 4], q[(i + 2) % 4]) <= 0) return 0;
  return 1;
}

/* The interior edge u -> v of triangle (u, v, a), v -> u of (v, u, d). */
static void lot_check_edge(const geom_point *p, uint32_t u, uint32_t v, uint32_t a,
                           uint32_t d, const rule *r, lot_check_result *out) {
  const geom_point q[4] = {p[u], p[d], p[v], p[a]};   /* anticlockwise; diagonal q0 q2 */
  int convex = lot_strictly_convex(q);
  out->decided += convex;
  int bad;
  if (rule_is_delaunay(r))
    bad = geom_incircle(p[u], p[v], p[a], p[d]) > 0;   /* d strictly inside circle uva */
  else
    bad = convex && rule_eval(r, q, NULL, NULL) == RULE_BD;
  if (bad && out->not_optimal++ == 0) {
    out->bad_edge[0] = u < v ? u : v;
    out->bad_edge[1] = u < v ? v : u;
  }
}

int lot_check(const geom_point *p, size_t n, const uint32_t *tri, size_t ntri,
              const rule *r, lot_check_result *out) {
  *out = (lot_check_result){0};
  lot_dedge *e = malloc(3 * ntri * sizeof *e);
  unsigned char *used = calloc(n ? n : 1, 1);
  if (e == NULL || used == NULL) {
    free(e);
    free(used);
    return -1;
  }
  int valid = 1;
  for (size_t t = 0; t < ntri; t++) {
    const uint32_t *v = tri + 3 * t;
    if (v[0] >= n || v[1] >= n || v[2] >= n) {
      valid = 0;
      continue;
    }
    if (geom_orient(p[v[0]], p[v[1]], p[v[2]]) <= 0) valid = 0;
    for (int i = 0; i < 3; i++) {
      used[v[i]] = 1;
      e[3 * t + i] = (lot_dedge){lot_ukey(v[i], v[(i + 1) % 3]), (uint32_t)t, (uint8_t)i};
    }
  }
  qsort(e, 3 * ntri, sizeof *e, lot_dedge_cmp);
  for (size_t i = 0; i < 3 * ntri && valid;) {
    size_t j = i;
    while (j < 3 * ntri && e[j].key == e[i].key) j++;
    if (j - i == 1) out->boundary_edges++;
    else if (j - i > 2) valid = 0;
    else {
      const uint32_t *t1 = tri + 3 * e[i].t, *t2 = tri + 3 * e[i + 1].t;
      uint32_t u = t1[e[i].e], v = t1[(e[i].e + 1) % 3], a = t1[(e[i].e + 2) % 3];
      uint32_t u2 = t2[e[i + 1].e], d = t2[(e[i + 1].e + 2) % 3];
      if (u2 != v) valid = 0;   /* the same direction in both: inconsistent */
      else {
        out->interior_edges++;
        lot_check_edge(p, u, v, a, d, r, out);
      }
    }
    i = j;
  }
  size_t vertices = 0;
  for (size_t i = 0; i < n; i++) vertices += used[i];
  if (valid && ntri + out->boundary_edges + 2 != 2 * vertices) valid = 0;
  out->valid = valid;
  free(e);
  free(used);
  return 0;
}

static int lot_u64_cmp(const void *x, const void *y) {
  uint64_t a = *(const uint64_t *)x, b = *(const uint64_t *)y;
  return a < b ? -1 : a > b;
}

/* Sorted distinct undirected edges of a list. */
static uint64_t *lot_edge_keys(const uint32_t *t, size_t nt, size_t *nk) {
  uint64_t *k = malloc((3 * nt + 1) * sizeof *k);
  if (k == NULL) return NULL;
  for (size_t i = 0; i < nt; i++)
    for (int j = 0; j < 3; j++) k[3 * i + j] = lot_ukey(t[3 * i + j], t[3 * i + (j + 1) % 3]);
  qsort(k, 3 * nt, sizeof *k, lot_u64_cmp);
  size_t w = 0;
  for (size_t i = 0; i < 3 * nt; i++)
    if (w == 0 || k[w - 1] != k[i]) k[w++] = k[i];
  *nk = w;
  return k;
}

typedef struct lot_tkey {
  uint32_t v[3];        /* ascending */
} lot_tkey;

static int lot_tkey_cmp(const void *x, const void *y) {
  const lot_tkey *a = x, *b = y;
  for (int i = 0; i < 3; i++)
    if (a->v[i] != b->v[i]) return a->v[i] < b->v[i] ? -1 : 1;
  return 0;
}

/* Sorted triangles as ascending vertex triples. */
static lot_tkey *lot_tri_keys(const uint32_t *t, size_t nt) {
  lot_tkey *k = malloc((nt + 1) * sizeof *k);
  if (k == NULL) return NULL;
  for (size_t i = 0; i < nt; i++) {
    uint32_t a = t[3 * i], b = t[3 * i + 1], c = t[3 * i + 2], s;
    if (a > b) { s = a; a = b; b = s; }
    if (b > c) { s = b; b = c; c = s; }
    if (a > b) { s = a; a = b; b = s; }
    k[i] = (lot_tkey){{a, b, c}};
  }
  qsort(k, nt, sizeof *k, lot_tkey_cmp);
  return k;
}

static size_t lot_common_edges(const uint64_t *a, size_t na, const uint64_t *b, size_t nb) {
  size_t i = 0, j = 0, c = 0;
  while (i < na && j < nb) {
    if (a[i] == b[j]) { c++; i++; j++; }
    else if (a[i] < b[j]) i++;
    else j++;
  }
  return c;
}

static size_t lot_common_tris(const lot_tkey *a, size_t na, const lot_tkey *b, size_t nb) {
  size_t i = 0, j = 0, c = 0;
  while (i < na && j < nb) {
    int r = lot_tkey_cmp(&a[i], &b[j]);
    if (r == 0) { c++; i++; j++; }
    else if (r < 0) i++;
    else j++;
  }
  return c;
}

int lot_compare(const uint32_t *a, size_t na, const uint32_t *b, size_t nb, lot_diff *out) {
  *out = (lot_diff){0};
  size_t ea, eb;
  uint64_t *ka = lot_edge_keys(a, na, &ea), *kb = lot_edge_keys(b, nb, &eb);
  lot_tkey *sa = lot_tri_keys(a, na), *sb = lot_tri_keys(b, nb);
  int rc = -1;
  if (ka && kb && sa && sb) {
    out->edges_a = ea;
    out->edges_b = eb;
    out->edges_common = lot_common_edges(ka, ea, kb, eb);
    out->triangles_a = na;
    out->triangles_b = nb;
    out->triangles_common = lot_common_tris(sa, na, sb, nb);
    rc = 0;
  }
  free(ka);
  free(kb);
  free(sa);
  free(sb);
  return rc;
}

/* Directed edges bucketed by their first vertex (a counting sort), each
** slot holding the edge's head and its triangle, so that the twin of
** u -> v is found by a scan of the few contiguous slots of the edges
** leaving v. */
int lot_neighbors(const uint32_t *tri, size_t ntri, size_t n, int32_t *nb) {
  size_t *start = calloc(n + 1, sizeof *start);
  uint64_t *slot = malloc((ntri ? 3 * ntri : 1) * sizeof *slot);   /* head << 32 | t */
  if (start == NULL || slot == NULL) {
    free(start);
    free(slot);
    return -1;
  }
  for (size_t c = 0; c < 3 * ntri; c++) start[tri[c] + 1]++;
  for (size_t v = 0; v < n; v++) start[v + 1] += start[v];
  for (size_t c = 0; c < 3 * ntri; c++) {
    uint64_t head = tri[c - c % 3 + (c % 3 + 1) % 3];
    slot[start[tri[c]]++] = head << 32 | (uint64_t)(c / 3);
  }
  for (size_t v = n; v > 0; v--) start[v] = start[v - 1];   /* back to the starts */
  start[0] = 0;
  for (size_t c = 0; c < 3 * ntri; c++) {
    /* corner c = 3t + k: the edge opposite it runs u -> v; its twin is v -> u */
    size_t t = c / 3, k = c % 3;
    uint32_t u = tri[3 * t + (k + 1) % 3], v = tri[3 * t + (k + 2) % 3];
    nb[c] = -1;
    for (size_t s = start[v]; s < start[v + 1]; s++)
      if ((uint32_t)(slot[s] >> 32) == u) {
        nb[c] = (int32_t)(uint32_t)slot[s];
        break;
      }
  }
  free(start);
  free(slot);
  return 0;
}

void lot_get_badness(const geom_point *p, const uint32_t *tri, size_t ntri, const rule *r,
                     double *out) {
  for (size_t t = 0; t < ntri; t++) {
    if (!rule_is_triangle(r)) {
      out[t] = NAN;
      continue;
    }
    geom_tri g;
    geom_tri_make(&g, p[tri[3 * t]], p[tri[3 * t + 1]], p[tri[3 * t + 2]]);
    out[t] = measure_eval(rule_measure(r), &g);
  }
}
