/*
** got_face.c: the optimal triangulations of one face of a point set's
** skeleton, exactly (got_face.h; docs/got.md, "Point sets: faces with
** points inside").  The faces the polygon programme cannot take: points
** inside, holes (other boundary components), edges walked twice.
**
** A memoised search over regions (an advancing front).  A region is a set
** of closed walks (the first one outer, face on the left) and the points
** strictly inside it.  Every triangulation of a region has exactly one
** triangle on the left of its pivot, the least half-edge a -> b of the
** outer walk; its apex c is an inner point, or one occurrence of a walk's
** vertex (the occurrence whose corner holds the triangle's corner at c).
** Removing the triangle leaves:
**   c inside:          the outer walk a c b ...;
**   c on a hole:       the outer walk a c (the hole from c round to c) c b ...;
**   c on the outer walk a b X c Y: two pieces, a c Y and c b X, a side
**                      that was a boundary edge cancelling with it (c -> a,
**                      b -> c), each piece keeping the holes and points its
**                      walk winds round (exact winding numbers);
** so best(region) = min over apexes of key(abc) + best(pieces), the pieces
** being independent.  Regions are memoised by a canonical code (each walk
** rotated to its least half-edge, holes ordered by it, points ascending),
** so the sub-polygons of a simple polygon are met once each: O(n^2) regions
** with O(n) apexes for a convex n-gon, O(n) exact tests per apex, O(n^4)
** in all; each inner point multiplies the regions by the ways it can be
** cut off, exponential in their number at worst.  The search refuses a
** face once it has visited GOT_FACE_MAX_STATES regions.
**
** A triangle a b c is accepted when it turns anticlockwise (geom_orient),
** its two new sides are allowed edges or the boundary edges they cancel,
** its corner at a, b and c lies in the region's corner at that occurrence,
** no walk vertex or inner point lies in it or on its sides, and no walk
** edge crosses its sides: all exact.  With the corners checked, a walk
** edge meeting the triangle must cross a side or end inside it.
**
** Runner-up.  Per region the least total and the least total of any other
** triangulation (the second smallest over apexes, or the best apex with one
** piece at its runner-up), the recurrence of got_dp.c for a monotone +.
** Ties go to the apex met first in the region's code (outer walk from the
** pivot on, then the holes, then the inner points; vertices numbered as
** got_face_number says, from the input's order): deterministic,
** single-threaded, and reentrant (no state outside the call), so a caller
** may solve several faces at once on its threads.  Keys are rule_key of
** measure_eval's value (through measure_points, bit for bit the same),
** added in the order key(abc) + best(first piece) + best(second piece);
** + rounded to nearest is monotone, so the optimum found is the floating
** total of the triangulation returned and the runner-up the least floating
** total of the others, and got_cert_err_sum bounds both (got_cert.c).
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "geom_mem_internal.h"
#include "geom_key_internal.h"
#include "measure.h"
#include "got_internal.h"
#include "got_face.h"

/* The regions a face may visit: each costs its code (4 bytes a vertex or
** point), an entry (48 bytes) and two to four hash slots of 8 bytes: for
** faces of 50 vertices about 300 MB at most.  Entry indices fit 32 bits. */
#define GOT_FACE_MAX_STATES ((size_t)1 << 20)

/* A region's code: [nw, npt, len[0..nw-1], walk vertices..., points...]. */
typedef struct got_face_view {
  uint32_t nw, npt;
  const uint32_t *len, *v, *pt;
  size_t nv;            /* vertices of all walks */
} got_face_view;

typedef struct got_face_entry {
  size_t off, len;      /* its code in the arena */
  uint64_t hash;
  double best, second;
  uint32_t choice;      /* position in the code of the best apex */
  unsigned char feasible, has2;
} got_face_entry;

typedef struct got_face_ctx {
  const geom_point *p;      /* the face's points by local number (got_face_number) */
  geom_point *lp;           /* ... owned */
  uint32_t *glob;           /* local number -> index in the caller's points */
  const rule *r;
  int measure;
  measure_points_fn fast;   /* the measure from three points, bit for bit (NULL: none) */
  uint64_t *edge;       /* allowed edges, lo << 32 | hi, ascending */
  size_t nedges;
  uint32_t *arena;
  size_t arena_len, arena_cap;
  got_face_entry *ent;
  size_t nent, ent_cap;
  uint64_t *slot;       /* hash slots: the hash's top 32 bits, entry index + 1 (0: free) */
  size_t nslot;
  size_t limit;
  int fail;             /* 1: too many regions; 2: out of memory */
} got_face_ctx;

/* The parts of a code, in place. */
static got_face_view got_face_view_of(const uint32_t *code) {
  got_face_view w;
  w.nw = code[0];
  w.npt = code[1];
  w.len = code + 2;
  w.v = w.len + w.nw;
  w.nv = 0;
  for (uint32_t k = 0; k < w.nw; k++) w.nv += w.len[k];
  w.pt = w.v + w.nv;
  return w;
}

static size_t got_face_code_len(const uint32_t *code) {
  got_face_view w = got_face_view_of(code);
  return 2 + w.nw + w.nv + w.npt;
}

/* The words mixed one by one, then the bits avalanched (MurmurHash3's
** finaliser): the slot index takes the low bits, the slot check the high. */
static uint64_t got_face_hash(const uint32_t *code, size_t len) {
  uint64_t h = 0x9e3779b97f4a7c15u;
  for (size_t i = 0; i < len; i++) {
    h ^= code[i];
    h *= 0xff51afd7ed558ccdu;
    h ^= h >> 32;
  }
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53u;
  return h ^ (h >> 33);
}

/* ---- canonical codes ------------------------------------------------ */

/* The rotation of walk w[0..n-1] starting at its least half-edge (each
** half-edge occurs once in a region, so the least is unique). */
static size_t got_face_walk_start(const uint32_t *w, size_t n) {
  size_t s = 0;
  for (size_t i = 1; i < n; i++) {
    uint32_t a = w[i], b = w[(i + 1) % n], sa = w[s], sb = w[(s + 1) % n];
    if (a < sa || (a == sa && b < sb)) s = i;
  }
  return s;
}

static int got_face_u32_cmp(const void *x, const void *y) {
  uint32_t a = *(const uint32_t *)x, b = *(const uint32_t *)y;
  return a < b ? -1 : a > b;
}

/* Holes sorted by their least half-edge: (first, second) of the rotated
** walk, packed, with the hole's index, start and rotation. */
typedef struct got_face_hole { uint64_t key; uint32_t k; size_t off, rot; } got_face_hole;

static int got_face_hole_cmp(const void *x, const void *y) {
  const got_face_hole *a = x, *b = y;
  return a->key < b->key ? -1 : a->key > b->key;
}

/* Write the canonical code of the region raw (same layout, any rotation
** and order) into out (as long as raw), with h room for its walks. */
static void got_face_canon(const uint32_t *raw, uint32_t *out, got_face_hole *h) {
  got_face_view w = got_face_view_of(raw);
  size_t off = 0;
  for (uint32_t k = 0; k < w.nw; k++) {
    const uint32_t *wk = w.v + off;
    size_t s = got_face_walk_start(wk, w.len[k]);
    h[k] = (got_face_hole){(uint64_t)wk[s] << 32 | wk[(s + 1) % w.len[k]], k, off, s};
    off += w.len[k];
  }
  if (w.nw > 2) qsort(h + 1, w.nw - 1, sizeof *h, got_face_hole_cmp);
  out[0] = w.nw, out[1] = w.npt;
  uint32_t *o = out + 2 + w.nw;
  for (uint32_t q = 0; q < w.nw; q++) {
    uint32_t n = w.len[h[q].k];
    const uint32_t *wk = w.v + h[q].off;
    out[2 + q] = n;
    for (uint32_t i = 0; i < n; i++) *o++ = wk[(h[q].rot + i) % n];
  }
  memcpy(o, w.pt, w.npt * sizeof *o);
  qsort(o, w.npt, sizeof *o, got_face_u32_cmp);
}

/* ---- exact geometry ------------------------------------------------- */

/* 1 when direction v -> x lies strictly inside the anticlockwise sweep
** from v -> q to v -> p (the region's corner at an occurrence of v with
** next q and previous p; q == p: a leaf, everything but that ray).  Two
** distinct points never lie on one ray from v here: allowed and boundary
** edges hold no third point. */
static int got_face_in_sector(const geom_point *P, uint32_t v, uint32_t q, uint32_t p,
                              uint32_t x) {
  if (x == q || x == p) return 0;   /* on a side: not strictly inside */
  geom_point V = P[v], Q = P[q], Pp = P[p], X = P[x];
  int t = geom_orient(V, Q, Pp);
  if (t > 0) return geom_orient(V, Q, X) > 0 && geom_orient(V, X, Pp) > 0;
  if (t < 0) return !(geom_orient(V, Pp, X) >= 0 && geom_orient(V, X, Q) >= 0);
  if (q == p) return 1;
  return geom_orient(V, Q, X) > 0;   /* a straight corner */
}

/* 1 when v -> y lies strictly inside the triangle corner from v -> x1
** anticlockwise to v -> x2 (less than pi). */
static int got_face_in_cone(const geom_point *P, uint32_t v, uint32_t x1, uint32_t x2,
                            uint32_t y) {
  if (y == x1 || y == x2) return 0;   /* (and no exact evaluation of a zero) */
  return geom_orient(P[v], P[x1], P[y]) > 0 && geom_orient(P[v], P[y], P[x2]) > 0;
}

/* 1 when the triangle's corner at v (from x1 to x2) lies in the region's
** corner at an occurrence of v with next q and previous p. */
static int got_face_corner_ok(const geom_point *P, uint32_t v, uint32_t q, uint32_t p,
                              uint32_t x1, uint32_t x2) {
  return (x1 == q || got_face_in_sector(P, v, q, p, x1)) &&
         (x2 == p || got_face_in_sector(P, v, q, p, x2)) &&
         !got_face_in_cone(P, v, x1, x2, q) && !got_face_in_cone(P, v, x1, x2, p);
}

/* The winding number of the closed walk w[0..n-1] round q (not on it):
** crossings of the rightward ray from q, signed (exact comparisons and
** orientations only). */
static int got_face_winding(const geom_point *P, const uint32_t *w, size_t n, geom_point q) {
  int wn = 0;
  for (size_t i = 0; i < n; i++) {
    geom_point u = P[w[i]], v = P[w[(i + 1) % n]];
    if (u.y <= q.y) {
      if (v.y > q.y && geom_orient(u, v, q) > 0) wn++;
    } else if (v.y <= q.y && geom_orient(u, v, q) < 0) {
      wn--;
    }
  }
  return wn;
}

static int got_face_allowed(const got_face_ctx *x, uint32_t u, uint32_t v) {
  uint64_t k = geom_edge_key(u, v);
  size_t lo = 0, hi = x->nedges;
  while (lo < hi) {
    size_t mid = lo + (hi - lo) / 2;
    if (x->edge[mid] < k) lo = mid + 1;
    else hi = mid;
  }
  return lo < x->nedges && x->edge[lo] == k;
}

/* ---- one step: the triangle on the pivot and what it leaves ---------- */

/* Where position rel (counted from the first walk vertex) lies: walk *k,
** its index *i there and the walk's first position *s; 0 for a point. */
static int got_face_locate(const got_face_view *w, size_t rel, uint32_t *k, size_t *i,
                           size_t *s) {
  if (rel >= w->nv) return 0;
  size_t off = 0;
  uint32_t q = 0;
  while (rel >= off + w->len[q]) off += w->len[q++];
  *k = q, *i = rel - off, *s = off;
  return 1;
}

/* 1 when no walk vertex or inner point other than a, b, c lies in the
** closed triangle a b c (anticlockwise) and no walk edge crosses a c or
** b c.  O(walk vertices + points); what lies outside the triangle's
** bounding box (exact comparisons) is skipped without an orientation. */
static int got_face_tri_empty(const got_face_ctx *x, const got_face_view *w, uint32_t a,
                              uint32_t b, uint32_t c) {
  const geom_point *P = x->p;
  geom_point A = P[a], B = P[b], C = P[c];
  double x0 = geom_min3(A.x, B.x, C.x), x1 = geom_max3(A.x, B.x, C.x);
  double y0 = geom_min3(A.y, B.y, C.y), y1 = geom_max3(A.y, B.y, C.y);
  for (size_t i = 0; i < w->nv + w->npt; i++) {
    uint32_t q = i < w->nv ? w->v[i] : w->pt[i - w->nv];
    geom_point Q = P[q];
    if (Q.x < x0 || Q.x > x1 || Q.y < y0 || Q.y > y1 || q == a || q == b || q == c) continue;
    if (geom_orient(A, B, Q) >= 0 && geom_orient(B, C, Q) >= 0 && geom_orient(C, A, Q) >= 0)
      return 0;
  }
  size_t off = 0;
  for (uint32_t k = 0; k < w->nw; k++) {
    const uint32_t *wk = w->v + off;
    for (size_t i = 0; i < w->len[k]; i++) {
      uint32_t u = wk[i], v = wk[(i + 1) % w->len[k]];
      geom_point U = P[u], V = P[v];
      if ((U.x < x0 && V.x < x0) || (U.x > x1 && V.x > x1) || (U.y < y0 && V.y < y0) ||
          (U.y > y1 && V.y > y1))
        continue;
      if (u != a && u != c && v != a && v != c && geom_segments_cross(A, C, U, V)) return 0;
      if (u != b && u != c && v != b && v != c && geom_segments_cross(B, C, U, V)) return 0;
    }
    off += w->len[k];
  }
  return 1;
}

/* 1 when position rel holds an apex of a triangle on the pivot a -> b
** (the outer walk's first half-edge) that lies in the region. */
static int got_face_apex_ok(const got_face_ctx *x, const got_face_view *w, size_t rel) {
  const geom_point *P = x->p;
  size_t L0 = w->len[0];
  uint32_t a = w->v[0], b = w->v[1], pa = w->v[L0 - 1], nb = w->v[2 % L0];
  uint32_t k, c, cn = 0, cp = 0;
  size_t i, s;
  int on = got_face_locate(w, rel, &k, &i, &s);
  if (on) {
    c = w->v[rel];
    cn = w->v[s + (i + 1) % w->len[k]];
    cp = w->v[s + (i + w->len[k] - 1) % w->len[k]];
  } else {
    c = w->pt[rel - w->nv];
  }
  if (c == a || c == b || geom_orient(P[a], P[b], P[c]) <= 0) return 0;
  if (!(on && cn == a) && !got_face_allowed(x, a, c)) return 0;
  if (!(on && cp == b) && !got_face_allowed(x, b, c)) return 0;
  if (!got_face_corner_ok(P, a, b, pa, b, c) || !got_face_corner_ok(P, b, nb, a, c, a))
    return 0;
  if (on && !got_face_corner_ok(P, c, cn, cp, a, b)) return 0;
  return got_face_tri_empty(x, w, a, b, c);
}

/* Write a raw region code: the outer walk o[0..lo-1], the holes k >= 1 of
** w with hsel[k] == want and the points i with psel[i] == want. */
static void got_face_write(uint32_t *out, const uint32_t *o, size_t lo, const got_face_view *w,
                           const unsigned char *hsel, const unsigned char *psel,
                           unsigned char want) {
  uint32_t nh = 0, np = 0;
  for (uint32_t k = 1; k < w->nw; k++) nh += hsel[k] == want;
  for (uint32_t i = 0; i < w->npt; i++) np += psel[i] == want;
  out[0] = 1 + nh, out[1] = np, out[2] = (uint32_t)lo;
  uint32_t *lens = out + 3, *v = out + 3 + nh;
  memcpy(v, o, lo * sizeof *v);
  v += lo;
  size_t off = w->len[0];
  for (uint32_t k = 1; k < w->nw; k++) {
    if (hsel[k] == want) {
      *lens++ = w->len[k];
      memcpy(v, w->v + off, w->len[k] * sizeof *v);
      v += w->len[k];
    }
    off += w->len[k];
  }
  for (uint32_t i = 0; i < w->npt; i++)
    if (psel[i] == want) *v++ = w->pt[i];
}

/* The outer walk after a triangle whose apex is inner or on hole k at its
** index i (first position s): a c b X, or a c (the hole from c) c b X. */
static size_t got_face_merge(const got_face_view *w, uint32_t c, int on, uint32_t k, size_t i,
                             size_t s, uint32_t *o) {
  size_t n = 0, L0 = w->len[0];
  o[n++] = w->v[0];
  o[n++] = c;
  if (on) {
    for (size_t t = 1; t < w->len[k]; t++) o[n++] = w->v[s + (i + t) % w->len[k]];
    o[n++] = c;
  }
  for (size_t t = 1; t < L0; t++) o[n++] = w->v[t];
  return n;
}

/* The two walks after a triangle whose apex is the outer walk's index j:
** a c Y into o1 and c b X into o2, cancelling a side that was a boundary
** edge (c -> a, b -> c); a walk of fewer than 3 vertices is dropped
** (length 0): it has no area. */
static void got_face_split(const got_face_view *w, size_t j, uint32_t *o1, size_t *l1,
                           uint32_t *o2, size_t *l2) {
  size_t L0 = w->len[0], ny = L0 - j - 1, nx = j - 2, n = 0;
  const uint32_t *Y = w->v + j + 1, *X = w->v + 2;
  uint32_t a = w->v[0], b = w->v[1], c = w->v[j];
  o1[n++] = a;
  if (ny > 0 && Y[0] == a) {
    for (size_t t = 1; t < ny; t++) o1[n++] = Y[t];
  } else if (ny > 0) {
    o1[n++] = c;
    for (size_t t = 0; t < ny; t++) o1[n++] = Y[t];
  }
  *l1 = n >= 3 ? n : 0;
  n = 0;
  if (nx > 0 && X[nx - 1] == b) {
    o2[n++] = b;
    for (size_t t = 0; t + 1 < nx; t++) o2[n++] = X[t];
  } else if (nx > 0) {
    o2[n++] = c, o2[n++] = b;
    for (size_t t = 0; t < nx; t++) o2[n++] = X[t];
  }
  *l2 = n >= 3 ? n : 0;
}

/* Scratch for one region's step: two raw and two canonical child codes of
** up to cap words each, an outer walk, and the holes' and points' pieces. */
typedef struct got_face_step {
  uint32_t *raw[2], *kid[2], *o1, *o2;
  unsigned char *hsel, *psel;
  got_face_hole *hole;
  size_t cap;
} got_face_step;

/* Scratch for the steps of region w (code of len words): a child's code is
** never longer (a merged hole repeats its apex but loses its length word; a
** point joining the walk leaves the points), with no more walks or points.
** 0, or -1 when out of memory. */
static int got_face_step_new(got_face_step *st, const got_face_view *w, size_t len) {
  st->cap = len + 8;
  st->hole = malloc((w->nw + 1) * sizeof *st->hole);
  uint32_t *m = malloc(6 * st->cap * sizeof *m + w->nw + w->npt + 2);
  if (m == NULL || st->hole == NULL) {
    free(m), free(st->hole);
    return -1;
  }
  st->raw[0] = m, st->raw[1] = m + st->cap, st->kid[0] = m + 2 * st->cap;
  st->kid[1] = m + 3 * st->cap, st->o1 = m + 4 * st->cap, st->o2 = m + 5 * st->cap;
  st->hsel = (unsigned char *)(m + 6 * st->cap);
  st->psel = st->hsel + w->nw + 1;
  return 0;
}

static void got_face_step_free(got_face_step *st) {
  free(st->raw[0]), free(st->hole);
}

/* Which of the two walks o1, o2 each hole and point lies in (0, 1). */
static void got_face_assign(const got_face_ctx *x, const got_face_view *w, got_face_step *st,
                            const uint32_t *o1, size_t l1) {
  size_t off = w->len[0];
  for (uint32_t k = 1; k < w->nw; k++) {
    st->hsel[k] = got_face_winding(x->p, o1, l1, x->p[w->v[off]]) == 0;
    off += w->len[k];
  }
  for (uint32_t i = 0; i < w->npt; i++)
    st->psel[i] = got_face_winding(x->p, o1, l1, x->p[w->pt[i]]) == 0;
}

/* The pieces left by the triangle on the pivot with apex at position rel,
** canonical, into st->kid[0..]; their number (0, 1, 2).  *c receives the
** apex. */
static int got_face_children(const got_face_ctx *x, const got_face_view *w, size_t rel,
                             got_face_step *st, uint32_t *c) {
  uint32_t k = 0;
  size_t i = 0, s = 0, l1, l2;
  int on = got_face_locate(w, rel, &k, &i, &s), n = 0;
  *c = on ? w->v[rel] : w->pt[rel - w->nv];
  memset(st->hsel, 0, w->nw + 1);
  memset(st->psel, 0, w->npt + 1);
  if (on && k == 0) {
    got_face_split(w, i, st->o1, &l1, st->o2, &l2);
    if (l1 > 0 && l2 > 0) got_face_assign(x, w, st, st->o1, l1);
    if (l1 > 0) got_face_write(st->raw[n++], st->o1, l1, w, st->hsel, st->psel, 0);
    if (l2 > 0) got_face_write(st->raw[n++], st->o2, l2, w, st->hsel, st->psel, l1 > 0);
  } else {
    if (on) st->hsel[k] = 1;
    else st->psel[rel - w->nv] = 1;
    l1 = got_face_merge(w, *c, on, k, i, s, st->o1);
    got_face_write(st->raw[n++], st->o1, l1, w, st->hsel, st->psel, 0);
  }
  for (int q = 0; q < n; q++) got_face_canon(st->raw[q], st->kid[q], st->hole);
  return n;
}

static double got_face_tri_key(const got_face_ctx *x, uint32_t a, uint32_t b, uint32_t c) {
  if (x->fast != NULL) return rule_key(x->r, x->fast(x->p[a], x->p[b], x->p[c]));
  geom_tri t;
  geom_tri_make(&t, x->p[a], x->p[b], x->p[c]);
  return rule_key(x->r, measure_eval(x->measure, &t));
}

/* ---- the memo --------------------------------------------------------- */

/* A slot holds the hash's top half beside the entry index, so that a probe
** rarely loads an entry it does not want. */
static uint64_t got_face_slot(uint64_t h, size_t e) {
  return (h & 0xffffffff00000000u) | (uint64_t)(e + 1);
}

static long got_face_lookup(const got_face_ctx *x, const uint32_t *code, size_t len,
                            uint64_t h) {
  if (x->nslot == 0) return -1;
  for (size_t q = h & (x->nslot - 1);; q = (q + 1) & (x->nslot - 1)) {
    uint64_t sl = x->slot[q];
    if (sl == 0) return -1;
    if ((sl ^ h) >> 32 != 0) continue;
    const got_face_entry *e = &x->ent[(uint32_t)sl - 1];
    if (e->hash == h && e->len == len && memcmp(x->arena + e->off, code, len * 4) == 0)
      return (long)((uint32_t)sl - 1);
  }
}

static void got_face_place(uint64_t *s, size_t ns, uint64_t h, size_t e) {
  size_t q = h & (ns - 1);
  while (s[q] != 0) q = (q + 1) & (ns - 1);
  s[q] = got_face_slot(h, e);
}

/* Rehash into twice the slots when half full. */
static int got_face_rehash(got_face_ctx *x) {
  if (2 * (x->nent + 1) <= x->nslot) return 0;
  size_t ns = x->nslot ? 2 * x->nslot : 1024;
  uint64_t *s = calloc(ns, sizeof *s);
  if (s == NULL) return -1;
  for (size_t e = 0; e < x->nent; e++) got_face_place(s, ns, x->ent[e].hash, e);
  free(x->slot);
  x->slot = s, x->nslot = ns;
  return 0;
}

/* Store a solved region; its index, or -1 when out of memory. */
static long got_face_insert(got_face_ctx *x, const uint32_t *code, size_t len, uint64_t h,
                            const got_face_entry *e) {
  if (geom_grow((void **)&x->arena, &x->arena_cap, x->arena_len + len, 4) != 0 ||
      geom_grow((void **)&x->ent, &x->ent_cap, x->nent + 1, sizeof *x->ent) != 0 ||
      got_face_rehash(x) != 0) {
    x->fail = 2;
    return -1;
  }
  memcpy(x->arena + x->arena_len, code, len * 4);
  got_face_entry *d = &x->ent[x->nent];
  *d = *e;
  d->off = x->arena_len, d->len = len, d->hash = h;
  x->arena_len += len;
  got_face_place(x->slot, x->nslot, h, x->nent);
  return (long)x->nent++;
}

/* ---- the search ------------------------------------------------------- */

static long got_face_solve_code(got_face_ctx *x, const uint32_t *code);

/* Fold one apex's total v (and the least total of its other
** triangulations, alt) into the region's best and runner-up. */
typedef struct got_face_other { double v; int has; } got_face_other;

static void got_face_other_add(got_face_other *o, double v) {
  o->v = o->has ? fmin(o->v, v) : v;
  o->has = 1;
}

static void got_face_fold(got_face_entry *e, got_face_other *other, double v, double alt,
                          int has_alt, uint32_t pos) {
  if (!e->feasible || v < e->best) {
    if (e->feasible) got_face_other_add(other, e->best);
    e->best = v, e->choice = pos, e->feasible = 1;
    e->second = alt, e->has2 = (unsigned char)has_alt;
  } else {
    got_face_other_add(other, v);
  }
}

/* The apex at position rel: its pieces solved, folded into e; -1 when the
** search fails. */
static int got_face_try(got_face_ctx *x, const got_face_view *w, size_t rel,
                        got_face_step *st, got_face_entry *e, got_face_other *other) {
  uint32_t c;
  int n = got_face_children(x, w, rel, st, &c);
  long ci[2] = {-1, -1};
  for (int q = 0; q < n; q++)
    if ((ci[q] = got_face_solve_code(x, st->kid[q])) < 0) return -1;
  double kt = got_face_tri_key(x, w->v[0], w->v[1], c), v = kt, alt = INFINITY;
  int has_alt = 0;
  for (int q = 0; q < n; q++)
    if (!x->ent[ci[q]].feasible) return 0;
  for (int q = 0; q < n; q++) v += x->ent[ci[q]].best;
  for (int q = 0; q < n; q++) {
    if (!x->ent[ci[q]].has2) continue;
    double t = kt;
    for (int u = 0; u < n; u++) t += u == q ? x->ent[ci[u]].second : x->ent[ci[u]].best;
    alt = fmin(alt, t), has_alt = 1;
  }
  got_face_fold(e, other, v, alt, has_alt, (uint32_t)(rel + 2 + w->nw));
  return 0;
}

/* The entry of region code (canonical), solving it when new; -1 when the
** search fails (x->fail). */
static long got_face_solve_code(got_face_ctx *x, const uint32_t *code) {
  size_t len = got_face_code_len(code);
  uint64_t h = got_face_hash(code, len);
  long idx = got_face_lookup(x, code, len, h);
  if (idx >= 0) return idx;
  if (x->nent >= x->limit) return x->fail = 1, -1;
  got_face_view w = got_face_view_of(code);
  got_face_step st;
  if (got_face_step_new(&st, &w, len) != 0) return x->fail = 2, -1;
  got_face_entry e = {0};
  got_face_other other = {0, 0};
  for (size_t rel = 2; rel < w.nv + w.npt; rel++) {
    if (!got_face_apex_ok(x, &w, rel)) continue;
    if (got_face_try(x, &w, rel, &st, &e, &other) != 0) {
      got_face_step_free(&st);
      return -1;
    }
  }
  got_face_step_free(&st);
  if (e.feasible && other.has) {
    e.second = e.has2 ? fmin(e.second, other.v) : other.v;
    e.has2 = 1;
  }
  return got_face_insert(x, code, len, h, &e);
}

/* The triangles of region idx's optimum into tri (3 each, room for cap), in
** the order the search met them; 0, -1 when out of memory, -2 past cap. */
static int got_face_backtrack(got_face_ctx *x, size_t idx, uint32_t *tri, size_t *ntri,
                              size_t cap) {
  const got_face_entry *e = &x->ent[idx];
  const uint32_t *code = x->arena + e->off;
  got_face_view w = got_face_view_of(code);
  got_face_step st;
  if (got_face_step_new(&st, &w, e->len) != 0) return -1;
  uint32_t c;
  int n = got_face_children(x, &w, e->choice - 2 - w.nw, &st, &c), rc = *ntri < cap ? 0 : -2;
  if (rc == 0) {
    tri[3 * *ntri] = w.v[0], tri[3 * *ntri + 1] = w.v[1], tri[3 * *ntri + 2] = c;
    ++*ntri;
  }
  for (int q = 0; q < n && rc == 0; q++) {
    size_t len = got_face_code_len(st.kid[q]);
    long ci = got_face_lookup(x, st.kid[q], len, got_face_hash(st.kid[q], len));
    rc = ci < 0 ? -1 : got_face_backtrack(x, (size_t)ci, tri, ntri, cap);
  }
  got_face_step_free(&st);
  return rc;
}

/* ---- the verbs ---------------------------------------------------------- */

/* The face's region code (raw) in a fresh array; NULL with a message. */
static uint32_t *got_face_root(const got_face_in *in, char *err, size_t errlen) {
  size_t nv = 0;
  if (in->nwalks == 0 || in->nwalks > UINT32_MAX / 4 || in->walk_len[0] < 3) {
    snprintf(err, errlen, "got_face_solve: the face needs an outer walk of 3 or more vertices");
    return NULL;
  }
  for (size_t k = 0; k < in->nwalks; k++) {
    if (in->walk_len[k] < 2) {
      snprintf(err, errlen, "got_face_solve: walk %zu has %zu vertex (a hole needs 2 or more)",
               k, in->walk_len[k]);
      return NULL;
    }
    nv += in->walk_len[k];
  }
  uint32_t *raw = malloc((2 + in->nwalks + nv + in->ninner) * sizeof *raw);
  if (raw == NULL) {
    snprintf(err, errlen, "got_face_solve: out of memory");
    return NULL;
  }
  raw[0] = (uint32_t)in->nwalks, raw[1] = (uint32_t)in->ninner;
  for (size_t k = 0; k < in->nwalks; k++) raw[2 + k] = (uint32_t)in->walk_len[k];
  memcpy(raw + 2 + in->nwalks, in->walk, nv * sizeof *raw);
  memcpy(raw + 2 + in->nwalks + nv, in->inner, in->ninner * sizeof *raw);
  return raw;
}

/* ---- local numbers -------------------------------------------------------
** The search numbers the face's vertices 0 .. V-1: the points inside first,
** in the order given, then the walks' vertices in order of first
** appearance.  Why: the pivot is the least half-edge, so the chords to the
** points inside are taken early and fewer regions arise (star-shaped
** 40-gons with 5 points inside: half the regions, bench_got_face), and the
** points are contiguous in memory.  Ties follow these numbers. */
typedef struct got_face_num { uint32_t g, pos; } got_face_num;

static int got_face_num_cmp(const void *x, const void *y) {
  const got_face_num *a = x, *b = y;
  if (a->g != b->g) return a->g < b->g ? -1 : 1;
  return a->pos < b->pos ? -1 : a->pos > b->pos;
}

/* The local number of global index g in map[0..V) (sorted by g, pos the
** local number); V when g is no vertex of the face. */
static uint32_t got_face_local(const got_face_num *map, uint32_t V, uint32_t g) {
  uint32_t lo = 0, hi = V;
  while (lo < hi) {
    uint32_t mid = lo + (hi - lo) / 2;
    if (map[mid].g < g) lo = mid + 1;
    else hi = mid;
  }
  return lo < V && map[lo].g == g ? map[lo].pos : V;
}

/* The distinct vertices of the occurrences a[0..m) (g the caller's index,
** pos the occurrence: points first, then walks), numbered by first
** occurrence into x->glob and x->lp; a becomes the map, sorted by g with
** pos the local number.  Their count V; a needs room for 2m entries. */
static uint32_t got_face_distinct(got_face_ctx *x, const geom_point *p, got_face_num *a,
                                  size_t m) {
  qsort(a, m, sizeof *a, got_face_num_cmp);
  uint32_t V = 0;
  for (size_t i = 0; i < m; i++)   /* each vertex's first occurrence */
    if (i == 0 || a[i].g != a[i - 1].g) a[V++] = a[i];
  got_face_num *b = a + V;         /* (first occurrence, place in a) */
  for (uint32_t i = 0; i < V; i++) b[i] = (got_face_num){a[i].pos, i};
  qsort(b, V, sizeof *b, got_face_num_cmp);
  for (uint32_t r = 0; r < V; r++) {
    got_face_num *v = &a[b[r].pos];
    x->glob[r] = v->g;
    x->lp[r] = p[v->g];
    v->pos = r;
  }
  return V;
}

/* Renumber the root code raw (walks, then points) and the allowed edges
** (x->edge: lo << 32 | hi, ascending; edges leaving the face dropped) in
** local numbers.  0, or -1 when out of memory. */
static int got_face_number(got_face_ctx *x, const got_face_in *in, uint32_t *raw) {
  got_face_view w = got_face_view_of(raw);
  size_t m = w.nv + w.npt;
  got_face_num *a = malloc(2 * (m + 1) * sizeof *a);
  x->glob = malloc((m + 1) * sizeof *x->glob);
  x->lp = malloc((m + 1) * sizeof *x->lp);
  x->edge = malloc((in->nedges + 1) * sizeof *x->edge);
  if (a == NULL || x->glob == NULL || x->lp == NULL || x->edge == NULL) {
    free(a);
    return -1;
  }
  uint32_t *occ = raw + 2 + w.nw;   /* walks, then points */
  for (size_t i = 0; i < m; i++) a[i] = (got_face_num){occ[i], (uint32_t)((i + w.npt) % m)};
  uint32_t V = got_face_distinct(x, in->p, a, m);
  for (size_t i = 0; i < m; i++) occ[i] = got_face_local(a, V, occ[i]);
  x->p = x->lp, x->nedges = 0;
  for (size_t e = 0; e < in->nedges; e++) {
    uint32_t u = got_face_local(a, V, in->edge[2 * e]);
    uint32_t v = got_face_local(a, V, in->edge[2 * e + 1]);
    if (u < V && v < V)
      x->edge[x->nedges++] = geom_edge_key(u, v);
  }
  qsort(x->edge, x->nedges, sizeof *x->edge, geom_u64_cmp);
  free(a);
  return 0;
}

/* 0 when r is a triangle-based rule whose keys add; else -1 and why. */
static int got_face_rule_ok(const rule *r, char *err, size_t errlen) {
  if (rule_is_triangle(r) && joint_get(rule_joint(r))->keyop == JOINT_KEY_ADD) return 0;
  snprintf(err, errlen, "got_face_solve: rule %s is not a sum rule (its keys must add: a "
           "measure with joint 1, 2, 0, -1 or a power mean)", rule_name(r));
  return -1;
}

/* The certified bounds of out->key and out->key2 for the face's points. */
static void got_face_certify(const got_face_in *in, const rule *r, size_t nv,
                             got_face_out *out) {
  double rho = NAN, alpha = NAN;
  const char *why;
  geom_point *q = malloc((nv + in->ninner + 1) * sizeof *q);
  if (q != NULL) {
    for (size_t i = 0; i < nv; i++) q[i] = in->p[in->walk[i]];
    for (size_t i = 0; i < in->ninner; i++) q[nv + i] = in->p[in->inner[i]];
    (void)got_cert_model(q, nv + in->ninner, r, &rho, &alpha, &why);
    free(q);
  }
  out->err = got_cert_err_sum(rho, alpha, out->ntri, out->key);
  out->err2 = out->has_runner_up ? got_cert_err_sum(rho, alpha, out->ntri, out->key2)
                                 : INFINITY;
  double gap = out->key2 - out->key, bound = out->err + out->err2;
  out->unique = !out->has_runner_up ||
                (isfinite(bound) && gap * (1 - 0x1p-50) > bound * (1 + 0x1p-50));
}

static void got_face_ctx_free(got_face_ctx *x) {
  free(x->edge), free(x->arena), free(x->ent), free(x->slot), free(x->glob), free(x->lp);
}

/* The search from the root code into out; 0, or -1 with a message. */
static int got_face_run(got_face_ctx *x, const got_face_in *in, size_t nv, uint32_t *root,
                        got_face_out *out, char *err, size_t errlen) {
  got_face_hole *h = malloc((in->nwalks + 1) * sizeof *h);
  long idx = -1;
  if (h != NULL) {
    got_face_canon(root, root + got_face_code_len(root), h);
    idx = got_face_solve_code(x, root + got_face_code_len(root));
    free(h);
  }
  out->states = x->nent;
  if (idx < 0 && x->fail == 1) {
    snprintf(err, errlen, "got_face_solve: a face of %zu boundary vertices and %zu inner "
             "points is too large for the exact search (more than %zu regions, the limit)",
             nv, in->ninner, x->limit);
    return -1;
  }
  if (idx >= 0 && !x->ent[idx].feasible) {
    snprintf(err, errlen, "got_face_solve: the face (%zu boundary vertices, %zu inner points) "
             "has no triangulation with its allowed edges", nv, in->ninner);
    return -1;
  }
  size_t m = nv + 2 * in->ninner + 2 * in->nwalks - 4;
  out->tri = idx >= 0 ? malloc(3 * (m + 1) * sizeof *out->tri) : NULL;
  int rc = out->tri == NULL ? -1
                            : got_face_backtrack(x, (size_t)idx, out->tri, &out->ntri, m);
  if (rc == -1) {
    snprintf(err, errlen, "got_face_solve: out of memory");
    return -1;
  }
  if (rc != 0 || out->ntri != m) {   /* walks bounding no face as described */
    snprintf(err, errlen, "got_face_solve: the face's walks are inconsistent (%zu triangles "
             "found, %zu expected from its vertices and points)", out->ntri, m);
    return -1;
  }
  out->key = x->ent[idx].best;
  out->has_runner_up = x->ent[idx].has2;
  out->key2 = out->has_runner_up ? x->ent[idx].second : INFINITY;
  return 0;
}

int got_face_solve_limit(const got_face_in *in, const rule *r, size_t max_states,
                         got_face_out *out, char *err, size_t errlen) {
  memset(out, 0, sizeof *out);
  if (got_face_rule_ok(r, err, errlen) != 0) return -1;
  uint32_t *raw = got_face_root(in, err, errlen);
  if (raw == NULL) return -1;
  got_face_ctx x = {0};
  x.r = r, x.measure = rule_measure(r), x.limit = max_states;
  x.fast = measure_points(x.measure);
  size_t nv = 0, len = got_face_code_len(raw);
  for (size_t k = 0; k < in->nwalks; k++) nv += in->walk_len[k];
  uint32_t *root = malloc(2 * len * sizeof *root);
  int rc = -1;
  if (root == NULL || got_face_number(&x, in, raw) != 0) {
    snprintf(err, errlen, "got_face_solve: out of memory");
  } else {
    memcpy(root, raw, len * sizeof *root);
    rc = got_face_run(&x, in, nv, root, out, err, errlen);
    for (size_t t = 0; rc == 0 && t < 3 * out->ntri; t++) out->tri[t] = x.glob[out->tri[t]];
  }
  if (rc == 0) got_face_certify(in, r, nv, out);
  else got_face_out_free(out);
  free(raw), free(root);
  got_face_ctx_free(&x);
  return rc;
}

int got_face_solve(const got_face_in *in, const rule *r, got_face_out *out, char *err,
                   size_t errlen) {
  return got_face_solve_limit(in, r, GOT_FACE_MAX_STATES, out, err, errlen);
}

void got_face_out_free(got_face_out *o) {
  free(o->tri);
  o->tri = NULL;
  o->ntri = 0;
}
