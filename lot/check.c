/*
** check.c: checks of a triangulation given as a list of triangles, sharing
** nothing with the algorithms that made it: the structure (anticlockwise
** triangles, each edge in one or two triangles with opposite directions,
** Euler's count), local optimality of every interior edge decided afresh
** (rule_eval on the quadrilateral's own points; DT by the exact empty-circle
** test) and, for DT and the empty-shape rules, lot's tie-break on every
** tied edge, the comparison of two triangulations, and each triangle's badness.
*/
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "lot.h"
#include "measure.h"
#include "order.h"
#include "geom_key_internal.h"

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

static int lot_strictly_convex(const geom_point q[4]) {
  for (int i = 0; i < 4; i++)
    if (geom_orient(q[i], q[(i + 1) % 4], q[(i + 2) % 4]) <= 0) return 0;
  return 1;
}

/* Is p after q in the plane's lexicographic order (x, then y)? */
static int lot_lex_after(geom_point p, geom_point q) {
  return p.x > q.x || (p.x == q.x && p.y > q.y);
}

/* A tie at the strictly convex u d v a (diagonal u-v) against lot's
** tie-break (docs/lot.md, Ties): the greatest of the four vertices counts
** as outside, so the kept diagonal is the one not incident to it; 1 when
** the greatest is u or v.  Written from the rule's statement, not from the
** algorithms' code. */
static int lot_tie_wrong(const geom_point *p, uint32_t u, uint32_t v, uint32_t a, uint32_t d) {
  const uint32_t q[4] = {u, v, a, d};
  int g = 0;
  for (int i = 1; i < 4; i++)
    if (lot_lex_after(p[q[i]], p[q[g]])) g = i;
  return g < 2;
}

/* The interior edge u -> v of triangle (u, v, a), v -> u of (v, u, d).
** DT and the empty-shape rules have lot's tie-break: their ties (the four
** sites on one circle, one shape) are counted and checked against it.
** With weights w (WDT) every edge must be regular, convex or not. */
static void lot_check_edge(const geom_point *p, const double *w, uint32_t u, uint32_t v,
                           uint32_t a, uint32_t d, const rule *r, lot_check_result *out,
                           lot_tie_result *tr) {
  const geom_point q[4] = {p[u], p[d], p[v], p[a]};   /* anticlockwise; diagonal q0 q2 */
  int convex = lot_strictly_convex(q);
  out->decided += convex;
  int bad, tie;
  if (w != NULL && rule_wants_weights(r)) {
    const double ww[4] = {w[u], w[v], w[a], w[d]};
    int in = geom_power(p[u], p[v], p[a], p[d], ww);
    bad = in > 0;   /* d's lifted point below the plane of u, v, a */
    tie = 0;
  } else if (rule_is_delaunay(r)) {
    int in = geom_incircle(p[u], p[v], p[a], p[d]);
    bad = in > 0;   /* d strictly inside circle uva */
    tie = convex && in == 0;
  } else {
    rule_choice ch = convex ? rule_eval(r, q, NULL, NULL) : RULE_EITHER;
    bad = ch == RULE_BD;
    tie = convex && ch == RULE_EITHER && rule_is_shape(r);
  }
  if (bad && out->not_optimal++ == 0) {
    out->bad_edge[0] = u < v ? u : v;
    out->bad_edge[1] = u < v ? v : u;
  }
  if (!tie || tr == NULL) return;
  tr->ties++;
  if (lot_tie_wrong(p, u, v, a, d) && tr->not_tie_broken++ == 0) {
    tr->tie_edge[0] = u < v ? u : v;
    tr->tie_edge[1] = u < v ? v : u;
  }
}


/* The structure and local optimality of tri; the edges in skip (sorted
** geom_edge_key keys: constrained) are interior but not decided.  Sets
** out->valid for the structure alone; *vertices: the points used. */
static int lot_check_run(const geom_point *p, const double *w, size_t n, const uint32_t *tri,
                         size_t ntri, const rule *r, const uint64_t *skip, size_t nskip,
                         lot_check_result *out, lot_tie_result *tie, size_t *vertices) {
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
      e[3 * t + i] = (lot_dedge){geom_edge_key(v[i], v[(i + 1) % 3]), (uint32_t)t, (uint8_t)i};
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
        if (skip == NULL || bsearch(&e[i].key, skip, nskip, sizeof *skip, geom_u64_cmp) == NULL)
          lot_check_edge(p, w, u, v, a, d, r, out, tie);
      }
    }
    i = j;
  }
  *vertices = 0;
  for (size_t i = 0; i < n; i++) *vertices += used[i];
  out->valid = valid;
  free(e);
  free(used);
  return 0;
}

/* An unconstrained check, with weights w or none: structure, Euler's count
** over the vertices used, every interior edge. */
static int lot_check_all(const geom_point *p, const double *w, size_t n, const uint32_t *tri,
                         size_t ntri, const rule *r, lot_check_result *out,
                         lot_tie_result *tie) {
  *out = (lot_check_result){0};
  if (tie != NULL) *tie = (lot_tie_result){0};
  size_t vertices;
  if (lot_check_run(p, w, n, tri, ntri, r, NULL, 0, out, tie, &vertices) != 0) return -1;
  if (out->valid && ntri + out->boundary_edges + 2 != 2 * vertices) out->valid = 0;
  return 0;
}

int lot_check_ties(const geom_point *p, size_t n, const uint32_t *tri, size_t ntri,
                   const rule *r, lot_check_result *out, lot_tie_result *tie) {
  return lot_check_all(p, NULL, n, tri, ntri, r, out, tie);
}

int lot_check(const geom_point *p, size_t n, const uint32_t *tri, size_t ntri,
              const rule *r, lot_check_result *out) {
  return lot_check_ties(p, n, tri, ntri, r, out, NULL);
}

int lot_check_weighted(const geom_point *p, const double *w, size_t n, const uint32_t *tri,
                       size_t ntri, const rule *r, lot_check_result *out) {
  return lot_check_all(p, w, n, tri, ntri, r, out, NULL);
}

/* ---- constrained triangulations ---------------------------------------- */

/* Directed edges u -> v as u << 32 | v, sorted, with their triangles: the
** adjacency the constrained checks walk. */
typedef struct lot_darc {
  uint64_t key;
  uint32_t t, e;        /* edge e of triangle t */
} lot_darc;

static int lot_darc_cmp(const void *x, const void *y) {
  const lot_darc *a = x, *b = y;
  return a->key < b->key ? -1 : a->key > b->key;
}

static const lot_darc *lot_darc_find(const lot_darc *d, size_t nd, uint32_t u, uint32_t v) {
  lot_darc q = {(uint64_t)u << 32 | v, 0, 0};
  return bsearch(&q, d, nd, sizeof *d, lot_darc_cmp);
}

typedef struct lot_pkey {
  double x, y;
  uint32_t i;
} lot_pkey;

static int lot_pkey_cmp(const void *a, const void *b) {
  const lot_pkey *p = a, *q = b;
  if (p->x != q->x) return p->x < q->x ? -1 : 1;
  if (p->y != q->y) return p->y < q->y ? -1 : 1;
  return p->i < q->i ? -1 : p->i > q->i;
}

/* The first index of each point's coordinates (merged duplicates):
** first[i] == i for the first occurrence.  A sort by (x, y, index), so
** equal points are adjacent with the first occurrence leading. */
static int lot_first_copies(const geom_point *p, size_t n, uint32_t *first) {
  lot_pkey *k = malloc((n ? n : 1) * sizeof *k);
  if (k == NULL) return -1;
  for (size_t i = 0; i < n; i++) k[i] = (lot_pkey){p[i].x, p[i].y, (uint32_t)i};
  qsort(k, n, sizeof *k, lot_pkey_cmp);
  for (size_t i = 0; i < n; i++)
    first[k[i].i] = i > 0 && k[i].x == k[i - 1].x && k[i].y == k[i - 1].y ? first[k[i - 1].i] : k[i].i;
  free(k);
  return 0;
}

/* Walk segment u-v along the edges (adjacency adj: sorted u << 32 | v in
** both directions): each step to the neighbour that is v or lies on the
** segment strictly between the current vertex and v.  The chain's edges
** go to keys; returns 1 when the chain reaches v. */
static int lot_chain(const geom_point *p, const uint64_t *adj, size_t nadj, uint32_t u, uint32_t v,
                     uint64_t **keys, size_t *nk, size_t *cap) {
  uint32_t cur = u;
  for (size_t steps = 0; cur != v && steps <= nadj; steps++) {
    uint64_t lo = (uint64_t)cur << 32;
    size_t i = 0, j = nadj;
    while (i < j) {   /* the first arc leaving cur */
      size_t h = (i + j) / 2;
      if (adj[h] < lo) i = h + 1;
      else j = h;
    }
    uint32_t next = UINT32_MAX;
    for (; i < nadj && adj[i] >> 32 == cur && next == UINT32_MAX; i++) {
      uint32_t w = (uint32_t)adj[i];
      if (w == v || (geom_orient(p[u], p[v], p[w]) == 0 && geom_ahead(p[cur], p[v], p[w]) &&
                     geom_ahead(p[v], p[cur], p[w])))
        next = w;
    }
    if (next == UINT32_MAX) return 0;
    if (*nk == *cap) {
      size_t c = *cap ? 2 * *cap : 256;
      uint64_t *k = realloc(*keys, c * sizeof *k);
      if (k == NULL) return -1;
      *keys = k;
      *cap = c;
    }
    (*keys)[(*nk)++] = geom_edge_key(cur, next);
    cur = next;
  }
  return cur == v;
}

/* What V - E + T must be for triangles that form planar surfaces with
** holes.  Each component (C, by union-find over shared edges) of genus 0
** with b boundary loops has Euler characteristic 2 - b, when a vertex where
** several fans meet (two triangles touching at a corner only, a hole
** touching the outer boundary) counts once per fan: V counts it once, so
** the answer is 2C - L - (fans - V).  Loops: each boundary edge u -> v is
** followed by the next one from v, found by turning around v through the
** triangles (so within v's fan); L is the number of cycles.  A boundary
** vertex has one outgoing boundary edge per fan.  n: the point count. */
static long lot_euler_rhs(const uint32_t *tri, size_t ntri, size_t n, const lot_darc *d,
                          size_t nd) {
  uint32_t *parent = malloc((ntri ? ntri : 1) * sizeof *parent);
  uint8_t *seen = calloc(nd ? nd : 1, 1);
  uint32_t *out = calloc(n ? n : 1, sizeof *out);
  if (parent == NULL || seen == NULL || out == NULL) {
    free(parent);
    free(seen);
    free(out);
    return LONG_MIN;
  }
  long extra = 0;
  for (size_t t = 0; t < ntri; t++) parent[t] = (uint32_t)t;
  long comps = (long)ntri, loops = 0;
  for (size_t i = 0; i < nd; i++) {
    uint32_t u = (uint32_t)(d[i].key >> 32), v = (uint32_t)d[i].key;
    const lot_darc *tw = lot_darc_find(d, nd, v, u);
    if (tw != NULL) {
      uint32_t a = d[i].t, b = tw->t;
      while (parent[a] != a) a = parent[a] = parent[parent[a]];
      while (parent[b] != b) b = parent[b] = parent[parent[b]];
      if (a != b) { parent[a] = b; comps--; }
      continue;
    }
    if (out[u]++ > 0) extra++;   /* a further fan at u */
    if (seen[i]) continue;
    loops++;
    for (size_t j = i; !seen[j];) {   /* trace the loop of boundary edge j */
      seen[j] = 1;
      uint32_t t = d[j].t, e = d[j].e;
      for (;;) {   /* the edge of t leaving the head of edge e */
        uint32_t from = tri[3 * t + (e + 1) % 3], to = tri[3 * t + (e + 2) % 3];
        const lot_darc *x = lot_darc_find(d, nd, to, from);
        if (x == NULL) {
          j = (size_t)(lot_darc_find(d, nd, from, to) - d);
          break;
        }
        t = x->t;
        e = x->e;
      }
    }
  }
  free(parent);
  free(seen);
  free(out);
  return 2 * comps - loops - extra;
}

int lot_check_constrained(const geom_point *p, size_t n, const uint32_t *tri, size_t ntri,
                          const uint32_t *seg, size_t nseg, const rule *r,
                          lot_check_result *out) {
  *out = (lot_check_result){0};
  for (size_t t = 0; t < 3 * ntri; t++)
    if (tri[t] >= n) return 0;   /* not valid */
  lot_darc *d = malloc((3 * ntri + 1) * sizeof *d);
  uint64_t *adj = malloc((6 * ntri + 1) * sizeof *adj), *keys = NULL;
  uint32_t *first = malloc((n ? n : 1) * sizeof *first);
  size_t nk = 0, kcap = 0, nadj = 0, vertices;
  int rc = -1;
  if (d == NULL || adj == NULL || first == NULL || lot_first_copies(p, n, first) != 0) goto done;
  for (size_t t = 0; t < ntri; t++)
    for (uint32_t e = 0; e < 3; e++) {
      uint32_t u = tri[3 * t + e], v = tri[3 * t + (e + 1) % 3];
      d[3 * t + e] = (lot_darc){(uint64_t)u << 32 | v, (uint32_t)t, e};
      adj[nadj++] = (uint64_t)u << 32 | v;
      adj[nadj++] = (uint64_t)v << 32 | u;
    }
  qsort(d, 3 * ntri, sizeof *d, lot_darc_cmp);
  qsort(adj, nadj, sizeof *adj, geom_u64_cmp);
  for (size_t k = 0; k < nseg; k++) {
    uint32_t u = seg[2 * k], v = seg[2 * k + 1];
    int ok = u < n && v < n && first[u] != first[v];
    if (ok) ok = lot_chain(p, adj, nadj, first[u], first[v], &keys, &nk, &kcap);
    if (ok < 0) goto done;
    if (!ok && out->segments_missing++ == 0) out->missing_segment = k;
  }
  if (nk > 0) qsort(keys, nk, sizeof *keys, geom_u64_cmp);
  if (lot_check_run(p, NULL, n, tri, ntri, r, keys, nk, out, NULL, &vertices) != 0) goto done;
  long rhs = out->valid ? lot_euler_rhs(tri, ntri, n, d, 3 * ntri) : 0;
  if (rhs == LONG_MIN) goto done;
  long edges = (long)(out->interior_edges + out->boundary_edges);
  if (out->valid && (long)vertices - edges + (long)ntri != rhs) out->valid = 0;
  rc = 0;
done:
  free(d);
  free(adj);
  free(keys);
  free(first);
  return rc;
}

/* Bits of the largest vertex index of two lists (at least 1). */
static int lot_vertex_bits(const uint32_t *a, size_t na, const uint32_t *b, size_t nb) {
  uint32_t m = 1;
  for (size_t i = 0; i < 3 * na; i++) m |= a[i];
  for (size_t i = 0; i < 3 * nb; i++) m |= b[i];
  int bits = 0;
  while (bits < 32 && m >> bits) bits++;
  return bits;
}

/* Sorted distinct undirected edges of a list, u < v packed as u << vb | v
** (vb bits hold every vertex, so the order is u's then v's, the same for
** both lists): O(nt), a radix sort of 2 vb bits (a pass of LOT_RADIX_BITS
** bits for each digit not the same in every key); qsort past 2^32 keys. */
static uint64_t *lot_edge_keys(const uint32_t *t, size_t nt, int vb, size_t *nk) {
  uint64_t *k = malloc((3 * nt + 1) * sizeof *k);
  if (k == NULL) return NULL;
  for (size_t i = 0; i < nt; i++)
    for (int j = 0; j < 3; j++) {
      uint32_t u = t[3 * i + j], v = t[3 * i + (j + 1) % 3];
      k[3 * i + j] = u < v ? (uint64_t)u << vb | v : (uint64_t)v << vb | u;
    }
  if (3 * nt > UINT32_MAX) qsort(k, 3 * nt, sizeof *k, geom_u64_cmp);
  else if (lot_radix(k, NULL, (uint32_t)(3 * nt), 2 * vb) != 0) {
    free(k);
    return NULL;
  }
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

/* k[0..nt-1] in order: by the keys b << vb | c, then stably by a (two
** stable radix sorts of the indices, 3 vb bits: the order of (a, b, c)),
** O(nt); qsort past 2^32.  0, or -1 when out of memory. */
static int lot_tkey_sort(lot_tkey *k, size_t nt, int vb) {
  if (nt > UINT32_MAX) {
    qsort(k, nt, sizeof *k, lot_tkey_cmp);
    return 0;
  }
  uint64_t *key = malloc((nt + 1) * sizeof *key);
  uint32_t *idx = malloc((nt + 1) * sizeof *idx);
  lot_tkey *s = malloc((nt + 1) * sizeof *s);
  int rc = -1;
  if (key != NULL && idx != NULL && s != NULL) {
    for (size_t i = 0; i < nt; i++) {
      key[i] = (uint64_t)k[i].v[1] << vb | k[i].v[2];
      idx[i] = (uint32_t)i;
    }
    rc = lot_radix(key, idx, (uint32_t)nt, 2 * vb);
    for (size_t i = 0; rc == 0 && i < nt; i++) key[i] = k[idx[i]].v[0];
    if (rc == 0) rc = lot_radix(key, idx, (uint32_t)nt, vb);
    for (size_t i = 0; rc == 0 && i < nt; i++) s[i] = k[idx[i]];
    if (rc == 0) memcpy(k, s, nt * sizeof *k);
  }
  free(key);
  free(idx);
  free(s);
  return rc;
}

/* Sorted triangles as ascending vertex triples (lot_tkey_sort). */
static lot_tkey *lot_tri_keys(const uint32_t *t, size_t nt, int vb) {
  lot_tkey *k = malloc((nt + 1) * sizeof *k);
  if (k == NULL) return NULL;
  for (size_t i = 0; i < nt; i++) {
    uint32_t a = t[3 * i], b = t[3 * i + 1], c = t[3 * i + 2], s;
    if (a > b) { s = a; a = b; b = s; }
    if (b > c) { s = b; b = c; c = s; }
    if (a > b) { s = a; a = b; b = s; }
    k[i] = (lot_tkey){{a, b, c}};
  }
  if (lot_tkey_sort(k, nt, vb) != 0) {
    free(k);
    return NULL;
  }
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

/* Both lists' edges and triangles sorted (radix sorts of keys packed in the
** vertex indices' bits) and merged: O(na + nb).  10^5 points' LOT beside DT:
** about 40 ms, where qsort took 120 to 190 ms. */
int lot_compare(const uint32_t *a, size_t na, const uint32_t *b, size_t nb, lot_diff *out) {
  *out = (lot_diff){0};
  size_t ea, eb;
  int vb = lot_vertex_bits(a, na, b, nb);
  uint64_t *ka = lot_edge_keys(a, na, vb, &ea), *kb = lot_edge_keys(b, nb, vb, &eb);
  lot_tkey *sa = lot_tri_keys(a, na, vb), *sb = lot_tri_keys(b, nb, vb);
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
