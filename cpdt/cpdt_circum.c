/*
** cpdt_circum.c: the circumcircle algorithm (thesis 5.4.1) in its three
** forms: the newest-side recursion, a random side of each piece, and the
** walk round the dual tree in O(1) extra space.
**
** The Delaunay triangle on a Delaunay edge a b has as apex the vertex k of
** the chain on one side for which no other vertex of that chain lies inside
** circle a b k.  Round the axis through the lifted a and b, the planes
** through each lifted chain vertex are totally ordered (lot's tie-break
** lifts the points generically: cpdt_incircle), so one pass that keeps the
** best candidate finds the apex: m replaces k when m is inside circle a b k.
*/
#include <stdlib.h>
#include <string.h>
#include "cpdt_internal.h"

/* The apex on side (a, b) among the vertices v[0..m-1], anticlockwise from
** b round to a (a b v[i] anticlockwise): m - 1 incircle tests. */
static uint32_t cpdt_scan(cpdt_run *r, uint32_t a, uint32_t b, const uint32_t *v, size_t m) {
  uint32_t k = v[0];
  r->c->scanned += m;
  for (size_t i = 1; i < m; i++)
    if (cpdt_incircle(r, a, b, k, v[i]) > 0) k = v[i];
  return k;
}

/* The same over the index range lo .. hi (inclusive, no wrap; a b lo
** anticlockwise: pass a piece's side as (b, a)), k the best so far or
** CPDT_NONE. */
static uint32_t cpdt_scan_range(cpdt_run *r, uint32_t a, uint32_t b, uint32_t lo, uint32_t hi,
                                uint32_t k) {
  for (uint32_t i = lo; i <= hi && i != CPDT_NONE; i++)
    if (k == CPDT_NONE) k = i;
    else if (cpdt_incircle(r, a, b, k, i) > 0) k = i;
  return k;
}

/* Cost: the scan of a piece of m vertices looks at m - 2 of them, so the
** total T(n) obeys T(m+1) = m+1 + T(k) + T(m-k) on the result: n^2/2 when
** every apex is next to an end, O(n log n) when it halves, and on average
** over all triangulations 4^m / C_m - (2m + 1) = Theta(n^1.5) (5.4.1).
** Space: a stack of the pieces waiting, up to n - 3. */
int cpdt_circum(cpdt_run *r) {
  typedef struct { uint32_t a, b; } piece;
  size_t n = r->n, sp = 0;
  piece *stack = malloc(n * sizeof *stack);
  if (stack == NULL) return -2;
  cpdt_memory(r, n * sizeof *stack);
  stack[sp++] = (piece){0, (uint32_t)n - 1};
  while (sp > 0) {
    if (sp > r->c->depth) r->c->depth = sp;
    piece c = stack[--sp];
    r->c->scanned += c.b - c.a - 1;
    uint32_t k = cpdt_scan_range(r, c.b, c.a, c.a + 1, c.b - 1, CPDT_NONE);
    cpdt_emit(r, c.a, k, c.b);
    if (c.b - k >= 2) stack[sp++] = (piece){k, c.b};   /* the newest sides */
    if (k - c.a >= 2) stack[sp++] = (piece){c.a, k};
  }
  free(stack);
  return 0;
}

/* Piece q[0..m-1] (anticlockwise) split by triangle q[s] q[s+1] q[k]: the
** pieces q[s+1 .. k] and q[k .. s] (cyclically) written to out; their
** sizes into sz[0..1]. */
static void cpdt_split(const uint32_t *q, size_t m, size_t s, size_t k, uint32_t *out,
                       size_t sz[2]) {
  size_t o = 0;
  for (size_t i = (s + 1) % m;; i = (i + 1) % m) {
    out[o++] = q[i];
    if (i == k) break;
  }
  sz[0] = o;
  for (size_t i = k;; i = (i + 1) % m) {
    out[o++] = q[i];
    if (i == s) break;
  }
  sz[1] = o - sz[0];
}

/* Cost: the scans as above, on a side drawn uniformly among the piece's m
** sides; splitting copies the piece, O(m) like its scan.  Space: the pieces
** waiting share their ends, at most 2n words, plus n for a split. */
int cpdt_circum_random(cpdt_run *r) {
  size_t n = r->n, top = 0, sp = 0;
  uint32_t *buf = malloc((2 * n + 4) * sizeof *buf), *tmp = malloc((n + 2) * sizeof *tmp);
  size_t *len = malloc(n * sizeof *len);
  if (buf == NULL || tmp == NULL || len == NULL) {
    free(buf), free(tmp), free(len);
    return -2;
  }
  cpdt_memory(r, (3 * n + 6) * sizeof *buf + n * sizeof *len);
  for (size_t i = 0; i < n; i++) buf[i] = (uint32_t)i;
  top = len[sp++] = n;
  while (sp > 0) {
    if (sp > r->c->depth) r->c->depth = sp;
    size_t m = len[--sp];
    uint32_t *q = buf + top - m;
    size_t s = cpdt_random(r, (uint32_t)m), sz[2];
    for (size_t i = 0; i + 2 < m; i++) tmp[i] = q[(s + 2 + i) % m];
    uint32_t a = q[s], b = q[(s + 1) % m], k = cpdt_scan(r, a, b, tmp, m - 2);
    cpdt_emit(r, a, b, k);
    size_t ki = (s + 2) % m;
    while (q[ki] != k) ki = (ki + 1) % m;
    cpdt_split(q, m, s, ki, tmp, sz);
    top -= m;
    for (int h = 0; h < 2; h++)
      if (sz[h] >= 3) {
        memcpy(buf + top, tmp + (h ? sz[0] : 0), sz[h] * sizeof *buf);
        top += sz[h];
        len[sp++] = sz[h];
      }
  }
  free(buf), free(tmp), free(len);
  return 0;
}

/* The apex of the triangle beyond Delaunay edge a < b: the vertices outside
** a .. b, anticlockwise from b + 1 round to a - 1. */
static uint32_t cpdt_scan_outside(cpdt_run *r, uint32_t a, uint32_t b) {
  r->c->scanned += r->n - (b - a + 1);
  uint32_t k = cpdt_scan_range(r, a, b, b + 1, (uint32_t)r->n - 1, CPDT_NONE);
  return a > 0 ? cpdt_scan_range(r, a, b, 0, a - 1, k) : k;
}

/* Up from the finished piece a .. b to the next piece to enter, written to
** *a, *b: 0, or 1 when the walk is back at the root. */
static int cpdt_walk_up(cpdt_run *r, uint32_t *a, uint32_t *b) {
  uint32_t last = (uint32_t)r->n - 1;
  while (*a != 0 || *b != last) {
    uint32_t c = cpdt_scan_outside(r, *a, *b);
    if (c < *a) {
      *a = c;          /* we were the right piece of c .. b: it is finished */
    } else if (c - *b >= 2) {
      *a = *b;         /* the left piece of a .. c: its right piece is next */
      *b = c;
      return 0;
    } else {
      *b = c;          /* the right piece is a side: a .. c is finished */
    }
  }
  return 1;
}

/* Cost: pieces are entered as the newest-side recursion enters them (its
** scans, above), in the same order, and left by finding the triangle beyond
** the piece's side: a scan of the n - m vertices outside a piece of m.  No
** stack: the state is the piece a .. b alone, O(1) words, so the price of
** the space is the upward scans, Theta(n^2) in all (most pieces are small,
** so most upward scans see nearly n vertices); the thesis's "a factor of 2"
** counts the downward scans only. */
int cpdt_circum_walk(cpdt_run *r) {
  uint32_t a = 0, b = (uint32_t)r->n - 1;
  r->c->depth = 1;
  for (;;) {
    r->c->scanned += b - a - 1;
    uint32_t k = cpdt_scan_range(r, b, a, a + 1, b - 1, CPDT_NONE);
    cpdt_emit(r, a, k, b);
    if (k - a >= 2) b = k;
    else if (b - k >= 2) a = k;
    else if (cpdt_walk_up(r, &a, &b)) return 0;
  }
}
