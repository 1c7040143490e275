/*
** got_diag.c: the valid diagonals of a simple polygon, exactly, by one
** rotational visibility sweep per vertex: O(n log n) per vertex, O(n^2 log n)
** in all, every decision an exact geom_orient.
**
** A diagonal (i, j) is valid when the open segment p_i p_j lies in the open
** interior of the polygon: it leaves p_i into the interior cone of p_i and
** meets the boundary nowhere but at its two ends (a vertex on it, even a
** grazed reflex vertex, makes it invalid).  Those two conditions suffice:
** an open segment that starts inside and never meets the boundary stays
** inside, and then it also arrives at p_j from inside.
**
** Sweep around a = p_i (anticlockwise polygon).  Directions are ordered by
** their angle from the ray a -> p_{i+1}, exactly (a half-plane bit from
** geom_orient, then geom_orient within a half); the interior cone at a is
** the open range of angles up to that of p_{i-1}.  Every other vertex
** falls in an angle group (equal directions), ordered by distance inside
** the group.  An edge not incident to a and not collinear with a covers the
** open range of directions between its two endpoints (less than pi).  In
** each group, in angle order: the edges ending there leave the active set,
** the nearest vertex of the group is tested, the edges starting there
** enter.  The nearest vertex p_j of a group inside the cone is visible iff
** the active edge nearest to a does not separate a from p_j: an edge that
** only touches the ray at its end touches it at a vertex of the group,
** which is then nearer than p_j (invalid anyway) or beyond it (harmless).
**
** Active edges all cross the current ray and do not cross each other, so
** their order along the ray is a total order that does not change while
** they stay active.  It is decided without the ray: if f lies (weakly) on
** one side of the line of e, e is nearer iff a is on the other side;
** otherwise f straddles e's line, so e lies on one side of f's line and the
** same test runs the other way.  An indexed binary heap keeps the nearest
** edge on top, O(log n) per insertion or removal, comparing only edges that
** are active together.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "got_internal.h"

typedef struct got_sweep {
  const geom_point *p;
  size_t n, i;
  geom_point a, ref;   /* apex and the point defining angle 0 */
  size_t *ord, *tmp;   /* other vertices in angle order, merge buffer */
  double *key;         /* per vertex: approximate angle (sorting only) */
  unsigned char *half; /* per vertex: 0 for angles in [0, pi), 1 for [pi, 2pi) */
  size_t *grp;         /* per vertex: its angle group */
  size_t *heap, *pos;  /* active edges (named by first vertex), positions + 1 */
  size_t nheap;
  size_t *start, *end, *sidx, *eidx;   /* edges per group, CSR */
  size_t *egs, *ege;   /* per edge: groups of its first and last direction */
  unsigned char *ef;   /* per edge: GOT_EV_* */
} got_sweep;

enum { GOT_EV_INIT = 1, GOT_EV_START = 2, GOT_EV_END = 4 };

/* Half of the direction a -> v relative to a -> ref, exactly. */
static unsigned char got_half(geom_point a, geom_point ref, geom_point v) {
  int o = geom_orient(a, ref, v);
  if (o != 0) return o < 0;
  /* collinear: same direction as ref iff the coordinate signs agree */
  int sx = (v.x > a.x) - (v.x < a.x), sy = (v.y > a.y) - (v.y < a.y);
  int rx = (ref.x > a.x) - (ref.x < a.x), ry = (ref.y > a.y) - (ref.y < a.y);
  return !(sx == rx && sy == ry);
}

/* Angle comparison: -1, 0 (same direction), +1. */
static int got_angle_cmp(const got_sweep *s, size_t u, size_t v) {
  if (s->half[u] != s->half[v]) return s->half[u] < s->half[v] ? -1 : 1;
  return -geom_orient(s->a, s->p[u], s->p[v]);
}

/* Along one direction from a, the nearer point has the coordinate nearer
** to a's; exact (no subtraction). */
static int got_nearer(geom_point a, geom_point u, geom_point v) {
  if (u.x != v.x) return u.x > a.x ? u.x < v.x : u.x > v.x;
  return u.y > a.y ? u.y < v.y : u.y > v.y;
}

static int got_vertex_cmp(const got_sweep *s, size_t u, size_t v) {
  int c = got_angle_cmp(s, u, v);
  if (c != 0) return c;
  return got_nearer(s->a, s->p[u], s->p[v]) ? -1 : 1;
}

/* Angle order in two passes.  First a merge sort on approximate angles
** (atan2, relative to the reference ray, in [0, 2 pi)); then insertion sort
** with the exact comparator, which sorts any input correctly and costs
** O(m + inversions): rounding only misplaces near-equal directions (and
** perhaps a direction next to angle 0 that wrapped to 2 pi), so the exact
** pass does little work, while correctness never depends on atan2. */
static void got_sort(got_sweep *s, size_t *x, size_t m) {
  const double r0 = atan2(s->ref.y - s->a.y, s->ref.x - s->a.x);
  for (size_t q = 0; q < m; q++) {
    geom_point v = s->p[x[q]];
    double t = atan2(v.y - s->a.y, v.x - s->a.x) - r0;
    s->key[x[q]] = t < 0 ? t + 6.28318530717958647693 : t;
  }
  for (size_t w = 1; w < m; w *= 2) {
    for (size_t lo = 0; lo < m; lo += 2 * w) {
      size_t mid = lo + w < m ? lo + w : m, hi = lo + 2 * w < m ? lo + 2 * w : m;
      size_t l = lo, r = mid, o = lo;
      while (l < mid && r < hi) s->tmp[o++] = s->key[x[r]] < s->key[x[l]] ? x[r++] : x[l++];
      while (l < mid) s->tmp[o++] = x[l++];
      while (r < hi) s->tmp[o++] = x[r++];
    }
    memcpy(x, s->tmp, m * sizeof *x);
  }
  for (size_t q = 1; q < m; q++) {
    size_t v = x[q], b = q;
    while (b > 0 && got_vertex_cmp(s, v, x[b - 1]) < 0) {
      x[b] = x[b - 1];
      b--;
    }
    x[b] = v;
  }
}

/* geom_orient of (p_u, p_v, p_w), 0 without arithmetic when w is u or v:
** adjacent edges share a vertex, and an exactly zero determinant always
** misses the filter and would cost an exact evaluation. */
static int got_orient3(const got_sweep *s, size_t u, size_t v, size_t w) {
  if (w == u || w == v) return 0;
  return geom_orient(s->p[u], s->p[v], s->p[w]);
}

/* Is edge e nearer to a than edge f (both active)? */
static int got_edge_nearer(const got_sweep *s, size_t e, size_t f) {
  const size_t n = s->n, e2 = (e + 1) % n, f2 = (f + 1) % n;
  int o1 = got_orient3(s, e, e2, f), o2 = got_orient3(s, e, e2, f2);
  if (o1 * o2 >= 0 && (o1 | o2) != 0)
    return geom_orient(s->p[e], s->p[e2], s->a) != (o1 != 0 ? o1 : o2);
  int o3 = got_orient3(s, f, f2, e), o4 = got_orient3(s, f, f2, e2);
  if ((o3 | o4) == 0) return e < f;     /* collinear: cannot both be active */
  return geom_orient(s->p[f], s->p[f2], s->a) == (o3 != 0 ? o3 : o4);
}

static void got_heap_set(got_sweep *s, size_t q, size_t e) {
  s->heap[q] = e;
  s->pos[e] = q + 1;
}

static void got_heap_up(got_sweep *s, size_t q) {
  size_t e = s->heap[q];
  while (q > 0 && got_edge_nearer(s, e, s->heap[(q - 1) / 2])) {
    got_heap_set(s, q, s->heap[(q - 1) / 2]);
    q = (q - 1) / 2;
  }
  got_heap_set(s, q, e);
}

static void got_heap_down(got_sweep *s, size_t q) {
  size_t e = s->heap[q];
  for (;;) {
    size_t c = 2 * q + 1;
    if (c >= s->nheap) break;
    if (c + 1 < s->nheap && got_edge_nearer(s, s->heap[c + 1], s->heap[c])) c++;
    if (!got_edge_nearer(s, s->heap[c], e)) break;
    got_heap_set(s, q, s->heap[c]);
    q = c;
  }
  got_heap_set(s, q, e);
}

static void got_heap_push(got_sweep *s, size_t e) {
  got_heap_set(s, s->nheap++, e);
  got_heap_up(s, s->nheap - 1);
}

static void got_heap_remove(got_sweep *s, size_t e) {
  if (s->pos[e] == 0) return;
  size_t q = s->pos[e] - 1, last = s->heap[--s->nheap];
  s->pos[e] = 0;
  if (q == s->nheap) return;
  got_heap_set(s, q, last);
  got_heap_up(s, q);
  got_heap_down(s, s->pos[last] - 1);
}

/* Angle groups of the sorted vertices; returns the number of groups. */
static size_t got_groups(got_sweep *s, size_t m) {
  size_t g = 0;
  for (size_t q = 0; q < m; q++) {
    if (q > 0 && got_angle_cmp(s, s->ord[q - 1], s->ord[q]) != 0) g++;
    s->grp[s->ord[q]] = g;
  }
  return g + 1;
}

/* Edge events per group (CSR: start[g]..start[g+1] in sidx, likewise end
** in eidx); edges active at angle 0+ go straight into the heap.  Edge s -> e
** (anticlockwise around a, less than pi) covers the open range of angles
** from s's to e's.  When that range passes through angle 0 it has two
** pieces inside the cone: (0, e), active from the start and leaving at e,
** and (s, end of the cone), entering at s and never leaving.  A piece that
** holds no query group (a group strictly inside it and below gend) can
** never be the nearest edge at a query, so it is left out: from a boundary
** vertex most edges of a spiky polygon subtend no other vertex, and the heap
** stays small. */
static void got_events(got_sweep *s, size_t ng, size_t gend) {
  const size_t n = s->n, i = s->i;
  memset(s->start, 0, (ng + 1) * sizeof *s->start);
  memset(s->end, 0, (ng + 1) * sizeof *s->end);
  for (size_t e = 0; e < n; e++) {             /* classify once, count */
    size_t u = e, v = (e + 1) % n;
    s->ef[e] = 0;
    if (u == i || v == i) continue;
    int o = geom_orient(s->a, s->p[u], s->p[v]);
    if (o == 0) continue;
    size_t gs = o > 0 ? s->grp[u] : s->grp[v], ge = o > 0 ? s->grp[v] : s->grp[u];
    size_t hi = ge < gend ? ge : gend;
    s->egs[e] = gs;
    s->ege[e] = ge;
    if (gs < ge) {                             /* one piece (gs, ge) */
      if (gs + 1 < hi) s->ef[e] = GOT_EV_START | GOT_EV_END;
    } else {                                   /* wraps: (0, ge) and (gs, end) */
      if (1 < hi) s->ef[e] |= GOT_EV_INIT | GOT_EV_END;
      if (gs + 1 < gend) s->ef[e] |= GOT_EV_START;
    }
    if (s->ef[e] & GOT_EV_INIT) got_heap_push(s, e);
    if (s->ef[e] & GOT_EV_START) s->start[gs + 1]++;
    if (s->ef[e] & GOT_EV_END) s->end[ge + 1]++;
  }
  for (size_t g = 0; g < ng; g++) {
    s->start[g + 1] += s->start[g];
    s->end[g + 1] += s->end[g];
  }
  for (size_t e = 0; e < n; e++) {             /* fill */
    if (s->ef[e] & GOT_EV_START) s->sidx[s->start[s->egs[e]]++] = e;
    if (s->ef[e] & GOT_EV_END) s->eidx[s->end[s->ege[e]]++] = e;
  }
  /* the fill advanced each group's offset to the next group's: shift back */
  memmove(s->start + 1, s->start, ng * sizeof *s->start);
  memmove(s->end + 1, s->end, ng * sizeof *s->end);
  s->start[0] = s->end[0] = 0;
}

/* Row i of the visibility table: V[i*n + j] = 1 for valid diagonals. */
static void got_sweep_vertex(got_sweep *s, size_t i, unsigned char *row) {
  const size_t n = s->n;
  s->i = i;
  s->a = s->p[i];
  s->ref = s->p[(i + 1) % n];
  size_t m = 0;
  for (size_t v = 0; v < n; v++)
    if (v != i) {
      s->half[v] = got_half(s->a, s->ref, s->p[v]);
      s->ord[m++] = v;
    }
  got_sort(s, s->ord, m);
  size_t ng = got_groups(s, m), gend = s->grp[(i + n - 1) % n];
  s->nheap = 0;
  for (size_t e = 0; e < n; e++) s->pos[e] = 0;
  got_events(s, ng, gend);
  size_t q = 0;
  while (q < m && s->grp[s->ord[q]] == 0) q++;
  if (s->start[1] > s->start[0])
    for (size_t t = s->start[0]; t < s->start[1]; t++) got_heap_push(s, s->sidx[t]);
  for (size_t g = 1; g < gend; g++) {
    for (size_t t = s->end[g]; t < s->end[g + 1]; t++) got_heap_remove(s, s->eidx[t]);
    size_t j = s->ord[q];                       /* nearest vertex of group g */
    int ok = 1;
    if (s->nheap > 0) {
      size_t e = s->heap[0];
      geom_point e1 = s->p[e], e2 = s->p[(e + 1) % n];
      ok = geom_orient(e1, e2, s->p[j]) == geom_orient(e1, e2, s->a);
    }
    row[j] = (unsigned char)ok;
    while (q < m && s->grp[s->ord[q]] == g) q++;
    for (size_t t = s->start[g]; t < s->start[g + 1]; t++) got_heap_push(s, s->sidx[t]);
  }
}

int got_valid_diagonals(const geom_point *p, size_t n, unsigned char *V, int threads) {
  memset(V, 0, n * n);
  int fail = 0;
  threads = geom_threads_clamp(threads, 1);
#pragma omp parallel num_threads(threads) reduction(| : fail)
  {
    got_sweep s = {0};
    s.p = p;
    s.n = n;
    s.ord = malloc(n * sizeof *s.ord);
    s.tmp = malloc(n * sizeof *s.tmp);
    s.key = malloc(n * sizeof *s.key);
    s.half = malloc(n);
    s.grp = malloc(n * sizeof *s.grp);
    s.heap = malloc(n * sizeof *s.heap);
    s.pos = malloc(n * sizeof *s.pos);
    s.start = malloc((n + 1) * sizeof *s.start);
    s.end = malloc((n + 1) * sizeof *s.end);
    s.sidx = malloc(n * sizeof *s.sidx);
    s.eidx = malloc(n * sizeof *s.eidx);
    s.egs = malloc(n * sizeof *s.egs);
    s.ege = malloc(n * sizeof *s.ege);
    s.ef = malloc(n);
    int ok = s.ord && s.tmp && s.key && s.half && s.grp && s.heap && s.pos && s.start && s.end &&
             s.sidx && s.eidx && s.egs && s.ege && s.ef;
    fail |= !ok;
    long ln = (long)n;
#pragma omp for schedule(dynamic, 8)
    for (long li = 0; li < ln; li++)
      if (ok) got_sweep_vertex(&s, (size_t)li, V + (size_t)li * n);
    free(s.ord); free(s.tmp); free(s.key); free(s.half); free(s.grp); free(s.heap); free(s.pos);
    free(s.start); free(s.end); free(s.sidx); free(s.eidx);
    free(s.egs); free(s.ege); free(s.ef);
  }
  if (fail) return -1;
  /* Symmetric in exact arithmetic; keep a pair only if both sweeps agree,
  ** and mark the polygon's edges (usable as triangle sides). */
  for (size_t i = 0; i < n; i++)
    for (size_t j = i + 1; j < n; j++) {
      unsigned char v = V[i * n + j] & V[j * n + i];
      V[i * n + j] = V[j * n + i] = v;
    }
  for (size_t i = 0; i < n; i++) V[i * n + (i + 1) % n] = V[((i + 1) % n) * n + i] = 1;
  return 0;
}
