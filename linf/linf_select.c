/*
** linf_select.c: the selection algorithm of the thesis's section 4.2.2 for
** the l_inf Delaunay simplices of a small set in R^d.
**
** From a facet (d points), every other point is offered in turn as a
** candidate, with its circumcubes through the facet.  The circumcubes
** through a facet do not nest under l_inf (section 4.2.1), so one
** candidate is not enough: the algorithm keeps a set.  A new point first
** kills every candidate circumcube it lies strictly inside (a candidate
** dies with its last cube), then joins the set if one of its own cubes
** holds no candidate strictly inside.  A second pass tests every surviving
** cube against every point; the survivors are exactly the Delaunay
** simplices on the facet (a point is refused or killed only by a witness
** strictly inside its cube).  A traversal over facets, with a set of the
** facets seen and a stack, starts from every hull facet (the thesis starts
** from one hull facet by gift wrapping, and rounds the cube's corners so
** that every simplex is reachable; here the hull facets come from a
** search, and what is not reachable from the hull is not found).
*/
#include <stdlib.h>
#include <string.h>
#include "linf_internal.h"

typedef struct linf_cand {
  int nc;
  linf_cube cube[LINF_CUBES_MAX];
} linf_cand;

/* A set of row keys (facets and simplices, told apart by a tag bit), open
** addressing, at most half full. */
typedef struct linf_keyset {
  uint64_t *k;
  size_t cap, n;
} linf_keyset;

typedef struct linf_sel {
  const double *pts;
  size_t n;
  int d;
  linf_cand *slot;         /* slot q: point q's live cubes as a candidate */
  int *live, nlive;        /* the candidate set */
  linf_select_stats *st;
  linf_keyset seen;
  unsigned char *stack;    /* facets to search, d indices each */
  size_t sn, scap;
  linf_simplices *out;
} linf_sel;

#define LINF_TAG_SIMPLEX ((uint64_t)1 << 62)

/* 1 if key is new (now in the set), 0 if present, -1 out of memory. */
static int linf_keyset_add(linf_keyset *s, uint64_t key) {
  if (2 * (s->n + 1) > s->cap) {
    size_t cap = s->cap ? 2 * s->cap : 1024;
    uint64_t *k = calloc(cap, sizeof *k);
    if (k == NULL) return -1;
    for (size_t i = 0; i < s->cap; i++) {
      if (s->k[i] == 0) continue;
      size_t h = (size_t)(s->k[i] * 0x9e3779b97f4a7c15ull >> 20) & (cap - 1);
      while (k[h] != 0) h = (h + 1) & (cap - 1);
      k[h] = s->k[i];
    }
    free(s->k);
    s->k = k;
    s->cap = cap;
  }
  uint64_t stored = key + 1;   /* 0 marks an empty slot */
  size_t h = (size_t)(stored * 0x9e3779b97f4a7c15ull >> 20) & (s->cap - 1);
  while (s->k[h] != 0) {
    if (s->k[h] == stored) return 0;
    h = (h + 1) & (s->cap - 1);
  }
  s->k[h] = stored;
  s->n++;
  return 1;
}

/* Mark facet f seen; push it to search if it was not.  0 or -1 (memory). */
static int linf_sel_push(linf_sel *s, const unsigned char *f) {
  int fresh = linf_keyset_add(&s->seen, linf_row_key(f, s->d));
  if (fresh <= 0) return fresh;
  if (s->sn == s->scap) {
    size_t cap = s->scap ? 2 * s->scap : 64;
    unsigned char *ns = realloc(s->stack, cap * (size_t)s->d);
    if (ns == NULL) return -1;
    s->stack = ns;
    s->scap = cap;
  }
  memcpy(s->stack + s->sn++ * (size_t)s->d, f, (size_t)s->d);
  return 0;
}

/* Point q against every candidate's cubes: those with q strictly inside
** die, and a candidate with none left. */
static void linf_sel_kill(linf_sel *s, size_t q) {
  const double *x = s->pts + q * (size_t)s->d;
  for (int a = 0; a < s->nlive;) {
    linf_cand *c = &s->slot[s->live[a]];
    for (int b = 0; b < c->nc;) {
      s->st->cube_tests++;
      if (linf_cube_side(&c->cube[b], x) == -1) c->cube[b] = c->cube[--c->nc];
      else b++;
    }
    if (c->nc == 0) s->live[a] = s->live[--s->nlive];
    else a++;
  }
}

/* Offer q on facet f: its circumcubes with f, less those holding a
** candidate strictly inside; it joins the set if any is left. */
static void linf_sel_offer(linf_sel *s, const unsigned char *f, size_t q) {
  int d = s->d;
  double rows[(LINF_DIM_MAX + 1) * LINF_DIM_MAX] = {0};
  linf_gather(s->pts, d, f, d, rows);
  memcpy(rows + d * d, s->pts + q * (size_t)d, (size_t)d * sizeof *rows);
  if (linf_orient(rows, d) == 0) return;
  linf_cand *c = &s->slot[q];
  c->nc = linf_circumcubes(rows, d, c->cube);
  if (c->nc == LINF_INFINITE) {
    s->st->degenerate++;
    return;
  }
  for (int b = 0; b < c->nc;) {
    int a = 0;
    for (; a < s->nlive; a++) {
      s->st->cube_tests++;
      if (linf_cube_side(&c->cube[b], s->pts + (size_t)s->live[a] * d) == -1) break;
    }
    if (a < s->nlive) c->cube[b] = c->cube[--c->nc];
    else b++;
  }
  if (c->nc == 0) return;
  s->live[s->nlive++] = (int)q;
  if ((uint64_t)s->nlive > s->st->largest_set) s->st->largest_set = (uint64_t)s->nlive;
}

/* A Delaunay simplex f + q: listed once, and its facets pushed. */
static int linf_sel_found(linf_sel *s, const unsigned char *f, int q) {
  int d = s->d, j = 0;
  unsigned char v[LINF_DIM_MAX + 1], g[LINF_DIM_MAX];
  for (int i = 0; i < d; i++) {
    if (j == i && q < f[i]) v[j++] = (unsigned char)q;
    v[j++] = f[i];
  }
  if (j == d) v[j++] = (unsigned char)q;
  int fresh = linf_keyset_add(&s->seen, linf_row_key(v, d + 1) | LINF_TAG_SIMPLEX);
  if (fresh <= 0) return fresh;
  if (linf_simplices_push(s->out, v) != 0) return -1;
  for (int drop = 0; drop <= d; drop++) {
    for (int i = 0, w = 0; i <= d; i++)
      if (i != drop) g[w++] = v[i];
    if (linf_sel_push(s, g) != 0) return -1;
  }
  return 0;
}

/* The Delaunay simplices on facet f: two passes over the points.  Cost
** O(c s n) cube tests (c: the most circumcubes of d + 1 points, s: the
** largest candidate set) and n orientations. */
static int linf_sel_facet(linf_sel *s, const unsigned char *f) {
  unsigned char in[LINF_POINTS_MAX] = {0};
  for (int i = 0; i < s->d; i++) in[f[i]] = 1;
  s->st->facets++;
  s->nlive = 0;
  for (size_t q = 0; q < s->n; q++) {
    if (in[q]) continue;
    linf_sel_kill(s, q);
    linf_sel_offer(s, f, q);
  }
  for (size_t q = 0; q < s->n; q++)
    if (!in[q]) linf_sel_kill(s, q);
  for (int a = 0; a < s->nlive; a++)
    if (linf_sel_found(s, f, s->live[a]) != 0) return -1;
  return 0;
}

/* n orientations. */
int linf_hull_facet(const double *pts, size_t n, int d, const unsigned char *f) {
  int pos = 0, neg = 0;
  double rows[(LINF_DIM_MAX + 1) * LINF_DIM_MAX] = {0};
  linf_gather(pts, d, f, d, rows);
  for (size_t q = 0; q < n && !(pos && neg); q++) {
    memcpy(rows + d * d, pts + q * (size_t)d, (size_t)d * sizeof *rows);
    int o = linf_orient(rows, d);
    pos |= o > 0;
    neg |= o < 0;
  }
  return pos != neg;
}

/* The first subset of d indices, 0 .. d - 1 (a table: gcc 12 with -march=native warned,
** wrongly, that a loop writing f[0 .. d-1] overflowed it). */
_Static_assert(LINF_DIM_MAX == 8, "linf_first_subset lists 0 .. LINF_DIM_MAX - 1");
static const unsigned char linf_first_subset[LINF_DIM_MAX] = {0, 1, 2, 3, 4, 5, 6, 7};

static int linf_sel_run(linf_sel *s) {
  unsigned char f[LINF_DIM_MAX], cur[LINF_DIM_MAX];
  memcpy(f, linf_first_subset, sizeof f);
  do {   /* the hull facets by search: C(n, d) facets, n orientations each */
    if (!linf_hull_facet(s->pts, s->n, s->d, f)) continue;
    s->st->hull_facets++;
    if (linf_sel_push(s, f) != 0) return -1;
  } while (linf_next_subset(f, s->d, s->n));
  while (s->sn > 0) {
    memcpy(cur, s->stack + --s->sn * (size_t)s->d, (size_t)s->d);
    if (linf_sel_facet(s, cur) != 0) return -1;
  }
  return linf_simplices_sort(s->out);
}

/* Cost: the hull search O(n^{d+1}) orientations, then O(c s n) cube tests
** per facet reached, every facet of every simplex found (section 4.2.2:
** O(n k f d c) for k simplices and a cube of f = 2d faces). */
int linf_delaunay_select(const double *pts, size_t n, int d, linf_simplices *out,
                         linf_select_stats *st) {
  linf_sel s = {.pts = pts, .n = n, .d = d, .st = st, .out = out};
  memset(st, 0, sizeof *st);
  linf_simplices_init(out, d);
  if (d < LINF_DIM_MIN || d > LINF_DIM_MAX || n > LINF_POINTS_MAX) return -1;
  if (n < (size_t)d + 1) return 0;
  s.slot = malloc(n * sizeof *s.slot);
  s.live = malloc(n * sizeof *s.live);
  int rc = s.slot && s.live ? linf_sel_run(&s) : -1;
  free(s.slot);
  free(s.live);
  free(s.seen.k);
  free(s.stack);
  return rc;
}
