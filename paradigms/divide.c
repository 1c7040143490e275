/*
** divide.c: Guibas and Stolfi's divide and conquer for the Delaunay
** triangulation (section 2.6.1), with vertical cuts ("dc-vertical") and with
** cuts alternating between vertical and horizontal (Dwyer: "dc-alternating").
**
** The sites are halved recursively by lines; each pair of triangulated
** halves is merged along the edges that cross the line, from the lower
** common tangent upwards: a candidate neighbour of either end of the
** present cross edge is kept while the next neighbour lies outside the
** circle through the cross edge and it, and the circle through the cross
** edge and the left candidate decides which end moves.  Every in-circle test
** is lot's (paradigm_inshape's perturbation: never 0 for four sites not on a
** line), so the result is lot's Delaunay triangulation exactly, ties
** included.  A vertical cut splits by the lexicographic order (x, y), a
** horizontal one by (y, -x), the lexicographic order of the frame turned a
** quarter clockwise, in which the same merge runs unchanged (orientation
** does not depend on the frame); only "leftmost" and "rightmost", the ends
** the merge starts and ends from, are found by a walk along the hulls in
** the frame of the cut.  There is no sort: each cut partitions its piece at
** a sampled median (below).
**
** The mesh is paradigm_half's (paradigm_internal.h: origin rings, Guibas
** and Stolfi's splice).  The top two levels of the recursion are fixed: four subtrees,
** each allocating edges from its own slice of the array, their counts kept
** apart and added in a fixed order, so that one thread and two (OpenMP
** tasks, the halves side by side) do the same operations and make the same
** mesh, edge for edge.
**
** Every empty-shape rule ES:SHAPE too (section 2.6.6): with the rounding
** shapes of docs/emptyshape.md every triangle has one region through its
** corners and the regions through two sites are nested on each side of
** their line, oppositely, as circles are; the rule's triangulation is the
** one whose regions are empty, and it covers the convex hull.  That is all
** the merge uses: an edge of the whole with both ends in one half is an
** edge of the half (its region is empty there too), the lower common
** tangent is a hull edge of the whole, so an edge of it (the bottom
** support-hull edge is the hull edge: the rounding shapes close the gap
** that 2.6.6 warns of), and the candidate of a cross edge is the least
** site above it in the pencil's order, paradigm_beats (dc_inside).  No half
** is disconnected: its edges left in the whole bound a polygon (pinched at
** most) between its part of the hull and the cross edges' ends, every site
** of it inside, and each merge step keeps its books.  The tests compare
** every shape with lot on thousands of sets, grids and cocircular ones
** included.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "paradigm_internal.h"
#include "splitmix.h"

#define DC_NONE 0xffffffffu
#define DC_TOP 2          /* levels of the recursion run as tasks: 4 subtrees */
#define DC_NODES 7        /* nodes of those levels, heap-numbered */
#define DC_MAX_POINTS ((DC_NONE - 1) / 6)   /* 3n edges, 6n half-edges below DC_NONE */

/* Subtrees that run side by side write their pools (and counts) at every
** edge made or deleted, so each sits on lines of its own, two cache lines
** wide (the adjacent-line prefetcher fetches pairs).  Packed, 24 bytes
** apart, the pools of nodes 3, 4 and 5 shared lines, and the two cores
** passed them back and forth at every edge (false sharing). */
#define DC_LINE 128

/* A slice of the edge array: a free list, fresh slots [used, end), and the
** slice to take from when both are empty (the subtrees a merge joins). */
typedef struct dc_pool {
  _Alignas(DC_LINE) uint32_t free;
  uint32_t base, used, end;
  struct dc_pool *more;
} dc_pool;

typedef struct dc_counts {
  _Alignas(DC_LINE) ops_counts c;
} dc_counts;

/* A triangulated subset: ccw hull edge out of its leftmost site, cw hull
** edge out of its rightmost (Guibas and Stolfi's ldo and rdo). */
typedef struct dc_hull {
  uint32_t l, r;
} dc_hull;

typedef struct dc_run {
  geom_point *s;          /* the sites, in the order of the cuts */
  uint32_t *id;           /* their input indices */
  geom_point *ts;         /* the cuts' scratch */
  uint32_t *tid;
  void *block;            /* s, ts and tid, 36 bytes a site: the triangles' array later */
  const geom_point *sb[3];   /* s, ts and the input: each cut moves a piece from */
  const uint32_t *ib[3];     /* one to s or ts (dc_to); the input's indices are k */
  paradigm_half *h;
  const rule *r;
  int es;                 /* an empty-shape rule: the merge asks paradigm_beats */
  int alternating;
  int threads;
  int failed;             /* an edge slice ran out: a bug, reported, never a crash */
  dc_pool pool[DC_NODES];
  ops_counts *count[DC_NODES];   /* NULL when not counting */
} dc_run;

static uint32_t dc_alloc(dc_run *R, dc_pool *p) {
  for (; p != NULL; p = p->more) {
    if (p->free != DC_NONE) {
      uint32_t e = p->free;
      p->free = R->h[2 * e].next;
      return e;
    }
    if (p->used < p->end) return p->used++;
  }
  R->failed = 1;
  return 0;
}

static uint32_t dc_make_edge(dc_run *R, dc_pool *p, ops_counts *c, uint32_t a, uint32_t b) {
  uint32_t e = 2 * dc_alloc(R, p);
  paradigm_half *h = R->h;
  h[e].org = a, h[e].next = h[e].prev = e;
  h[e + 1].org = b, h[e + 1].next = h[e + 1].prev = e + 1;
  ops_add(c, OPS_EDGES_MADE, 1);
  return e;
}

/* A new edge from Dest(a) to Org(b), a's left face split off by it. */
static uint32_t dc_connect(dc_run *R, dc_pool *p, ops_counts *c, uint32_t a, uint32_t b) {
  uint32_t e = dc_make_edge(R, p, c, paradigm_he_dest(R->h, a), R->h[b].org);
  paradigm_he_splice(R->h, e, paradigm_he_lnext(R->h, a));
  paradigm_he_splice(R->h, e ^ 1, b);
  return e;
}

static void dc_delete(dc_run *R, dc_pool *p, ops_counts *c, uint32_t e) {
  paradigm_half *h = R->h;
  paradigm_he_splice(h, e, h[e].prev);
  paradigm_he_splice(h, e ^ 1, h[e ^ 1].prev);
  h[e].org = h[e ^ 1].org = DC_NONE;
  h[e & ~1u].next = p->free;
  p->free = e >> 1;
  ops_add(c, OPS_EDGES_DELETED, 1);
}

/* Two or three sites, lexicographically sorted. */
static dc_hull dc_base(dc_run *R, dc_pool *p, ops_counts *c, uint32_t lo, uint32_t n) {
  uint32_t a = dc_make_edge(R, p, c, lo, lo + 1);
  if (n == 2) return (dc_hull){a, a ^ 1};
  uint32_t b = dc_make_edge(R, p, c, lo + 1, lo + 2);
  paradigm_he_splice(R->h, a ^ 1, b);
  int o = ops_orient(c, R->s[lo], R->s[lo + 1], R->s[lo + 2]);
  if (o > 0) {
    dc_connect(R, p, c, b, a);
    return (dc_hull){a, b ^ 1};
  }
  if (o < 0) {
    uint32_t t = dc_connect(R, p, c, b, a);
    return (dc_hull){t ^ 1, t};
  }
  return (dc_hull){a, b ^ 1};
}

/* Site x strictly right of the directed edge e (to its left: swap). */
static inline int dc_right_of(const dc_run *R, ops_counts *c, uint32_t x, uint32_t e) {
  return ops_orient(c, R->s[x], R->s[paradigm_he_dest(R->h, e)], R->s[R->h[e].org]) > 0;
}

static inline int dc_left_of(const dc_run *R, ops_counts *c, uint32_t x, uint32_t e) {
  return ops_orient(c, R->s[x], R->s[R->h[e].org], R->s[paradigm_he_dest(R->h, e)]) > 0;
}

/* lot's in-circle test: d strictly inside the circle through a, b, d
** (anticlockwise), the zeros settled by paradigm_inshape's perturbation. */
static inline int dc_incircle(const dc_run *R, ops_counts *c, uint32_t a, uint32_t b,
                              uint32_t d, uint32_t e) {
  const geom_point *s = R->s;
  int v = ops_incircle(c, s[a], s[b], s[d], s[e]);
  return (v != 0 ? v : paradigm_inshape(R->r, NULL, s[a], s[b], s[d], s[e])) > 0;
}

/* Does site d lie strictly inside the rule's region through the cross
** edge a -> b and x (x strictly left of it)?  DT: lot's in-circle test,
** valid for d anywhere.  ES: the order of paradigm_beats, which needs d
** strictly left of ab too; a site on or below the line of ab is outside.
** That is no loss: the cross edge is an edge of the result, so the region
** of its triangle above it, the least of the pencil above ab, is empty;
** x's region is larger above and so smaller below, and holds no site
** there either. */
static inline int dc_inside(const dc_run *R, ops_counts *c, uint32_t a, uint32_t b,
                            uint32_t x, uint32_t d) {
  const geom_point *s = R->s;
  if (!R->es) return dc_incircle(R, c, a, b, x, d);
  return ops_orient(c, s[a], s[b], s[d]) > 0 && paradigm_beats(R->r, c, s[a], s[b], s[x], s[d]);
}

/* The left (right) candidate: the first neighbour of basel's left (right)
** end, anticlockwise (clockwise) from basel and above it, whose circle
** with basel holds no next neighbour; edges in the way are deleted.
** DC_NONE when no neighbour lies above.  When the next neighbour is
** basel's other end, the four sites are three and the candidate stays.
** Inline: each side gets its own copy. */
static inline uint32_t dc_candidate(dc_run *R, dc_pool *p, ops_counts *c, uint32_t basel,
                                    int right) {
  paradigm_half *h = R->h;
  uint32_t bo = h[basel].org, bd = paradigm_he_dest(h, basel), stop = right ? bd : bo;
  uint32_t e = right ? h[basel].prev : h[basel ^ 1].next;
  if (!dc_right_of(R, c, paradigm_he_dest(h, e), basel)) return DC_NONE;
  for (int deleted = 0;; deleted = 1) {
    uint32_t t = right ? h[e].prev : h[e].next, far = paradigm_he_dest(h, t);
    if (far == stop || !dc_inside(R, c, bd, bo, paradigm_he_dest(h, e), far))
      return !deleted || dc_right_of(R, c, paradigm_he_dest(h, e), basel) ? e : DC_NONE;
    dc_delete(R, p, c, e);
    e = t;
  }
}

/* Both candidates above the cross edge (lc out of its left end, rc out of
** its right end): does the right one lie inside the region through the
** cross edge and the left one?  Both strictly above it: for ES,
** paradigm_beats needs no more. */
static inline int dc_right_wins(const dc_run *R, ops_counts *c, uint32_t lc, uint32_t rc) {
  const paradigm_half *h = R->h;
  const geom_point *s = R->s;
  uint32_t l = paradigm_he_dest(h, lc), bd = h[lc].org, bo = h[rc].org, r = paradigm_he_dest(h, rc);
  if (!R->es) return dc_incircle(R, c, l, bd, bo, r);
  return paradigm_beats(R->r, c, s[bd], s[bo], s[l], s[r]);
}

/* Merge left (ldo, ldi: cw hull edge out of its rightmost site) and right
** (rdi: ccw hull edge out of its leftmost site, rdo).  O(sites of both):
** each step adds or deletes an edge. */
static dc_hull dc_merge(dc_run *R, dc_pool *p, ops_counts *c, uint32_t ldo, uint32_t ldi,
                        uint32_t rdi, uint32_t rdo) {
  paradigm_half *h = R->h;
  for (;;) {   /* the lower common tangent */
    if (dc_left_of(R, c, h[rdi].org, ldi)) ldi = paradigm_he_lnext(h, ldi);
    else if (dc_right_of(R, c, h[ldi].org, rdi)) rdi = paradigm_he_rprev(h, rdi);
    else break;
  }
  uint32_t basel = dc_connect(R, p, c, rdi ^ 1, ldi);
  if (h[ldi].org == h[ldo].org) ldo = basel ^ 1;
  if (h[rdi].org == h[rdo].org) rdo = basel;
  for (;;) {
    uint32_t lc = dc_candidate(R, p, c, basel, 0), rc = dc_candidate(R, p, c, basel, 1);
    if (lc == DC_NONE && rc == DC_NONE) break;
    if (lc == DC_NONE || (rc != DC_NONE && dc_right_wins(R, c, lc, rc)))
      basel = dc_connect(R, p, c, rc, basel ^ 1);
    else
      basel = dc_connect(R, p, c, basel ^ 1, lc ^ 1);
  }
  return (dc_hull){ldo, rdo};
}

/* The ccw hull edge out of the first (last) site of the frame. */
static uint32_t dc_extreme(const dc_run *R, uint32_t e, int frame, int last) {
  return paradigm_he_extreme(R->h, R->s, e, frame, last);
}

/* Merge two halves split by the cut of frame 1 (horizontal): find their
** ends in that frame, merge, and give back the ends in frame 0. */
static dc_hull dc_merge_across(dc_run *R, dc_pool *p, ops_counts *c, dc_hull a, dc_hull b,
                               int frame) {
  if (frame == 0) return dc_merge(R, p, c, a.l, a.r, b.l, b.r);
  uint32_t ldo = dc_extreme(R, a.l, 1, 0), ldi = R->h[dc_extreme(R, a.l, 1, 1)].prev;
  uint32_t rdi = dc_extreme(R, b.l, 1, 0), rdo = R->h[dc_extreme(R, b.l, 1, 1)].prev;
  dc_hull m = dc_merge(R, p, c, ldo, ldi, rdi, rdo);
  return (dc_hull){dc_extreme(R, m.l, 0, 0), R->h[dc_extreme(R, m.l, 0, 1)].prev};
}

/* ---- the cuts: no sort.  A piece [lo, hi) is split by the order of its
** cut's frame at a pivot: any pivot that leaves each side two sites gives
** the same triangulation (every split is by a line); a balanced one keeps
** the recursion O(log n) deep and, with alternating cuts, the pieces
** square, which makes the merges cheap.  The pivot is the median of a
** sample, or the exact median when the sample's leaves a side under an
** eighth.  Pieces under DC_SORTED sites are sorted lexicographically once
** and then halved in the middle by vertical cuts, as Guibas and Stolfi's
** sorted sites are. ---- */

#define DC_SMALL 11       /* sites sampled for a pivot in the smallest pieces */
#define DC_SORTED 24      /* smaller pieces are sorted, then take vertical cuts only */
#define DC_CHUNKS 8       /* a wide cut's partition: fixed chunks, run as tasks ... */
#define DC_WIDE 16384     /* ... in pieces of this many sites or more */

/* Sites sampled for a pivot, by piece size.  The median of s samples sits
** at a rank of m (1/2 +- 1/(2 sqrt(s + 2))) (one standard deviation), so 63
** samples leave the sides 46:54 or worse as often as not; the top cuts,
** whose halves are the threads' shares, take 4,095 (+- 0.8%).  The cost,
** s random reads and an O(s) selection, stays under 1% of the pass. */
static const struct { uint32_t from, sample; } dc_samples[] = {
  {(uint32_t)1 << 18, 4095}, {64 * 63, 63}, {0, DC_SMALL}};

static void dc_sift(geom_point *a, uint32_t i, uint32_t n, int frame) {
  for (uint32_t k; (k = 2 * i + 1) < n; i = k) {
    if (k + 1 < n && paradigm_frame_before(a[k], a[k + 1], frame)) k++;
    if (!paradigm_frame_before(a[i], a[k], frame)) return;
    geom_point t = a[i];
    a[i] = a[k], a[k] = t;
  }
}

/* Heapsort: the selection's way out when its pivots keep failing, so that
** no input makes it quadratic.  O(n log n). */
static void dc_heapsort(geom_point *a, uint32_t n, int frame) {
  for (uint32_t i = n / 2; i-- > 0;) dc_sift(a, i, n, frame);
  for (uint32_t m = n; m-- > 1;) {
    geom_point t = a[0];
    a[0] = a[m], a[m] = t;
    dc_sift(a, 0, m, frame);
  }
}

/* The element of rank k of a[0..n) in the frame's order: Hoare's selection
** with pseudo-random pivots, O(n) expected; after 2 log2 n + 16 rounds, a
** heapsort.  The sites are distinct, so the ranks are too. */
static geom_point dc_select(geom_point *a, uint32_t n, uint32_t k, int frame) {
  uint64_t g = n;
  uint32_t lo = 0, hi = n;
  int budget = 16;
  for (uint32_t m = n; m > 1; m >>= 1) budget += 2;
  while (hi - lo > 1) {
    if (budget-- == 0) {
      dc_heapsort(a + lo, hi - lo, frame);
      return a[k];
    }
    uint32_t q = lo + (uint32_t)(geom_splitmix64(&g) % (hi - lo)), i = lo, j = hi - 1;
    geom_point piv = a[q], t;
    a[q] = a[j], a[j] = piv;
    while (i < j) {
      if (paradigm_frame_before(a[i], piv, frame)) i++;
      else t = a[i], a[i] = a[--j], a[j] = t;
    }
    a[hi - 1] = a[i], a[i] = piv;
    if (k == i) return piv;
    if (k < i) hi = i;
    else lo = i + 1;
  }
  return a[lo];
}

/* Where a piece's sites are: in the sites' array, the scratch or the
** input (the first cut's), or sorted in the sites' array. */
enum { DC_IN_S, DC_IN_T, DC_IN_P, DC_SORTED_S };

/* Where a cut moves a piece from buffer w: the scratch, or back. */
static inline geom_point *dc_to(const dc_run *R, int w) {
  return w == DC_IN_T ? R->s : R->ts;
}

static inline uint32_t *dc_to_id(const dc_run *R, int w) {
  return w == DC_IN_T ? R->id : R->tid;
}

/* The pivot of [lo, hi): the median of a sample drawn by a generator
** seeded with the range (so the same whatever the threads), or the exact
** median.  Uses the range's slice of the scratch. */
static geom_point dc_pivot(dc_run *R, uint32_t lo, uint32_t hi, int frame, int exact, int w) {
  uint32_t m = hi - lo;
  const geom_point *s = R->sb[w];
  geom_point *t = dc_to(R, w) + lo;
  if (exact || m <= 2 * DC_SMALL) {
    memcpy(t, s + lo, (size_t)m * sizeof *t);
    return dc_select(t, m, m / 2, frame);
  }
  size_t row = 0;
  while (m < dc_samples[row].from) row++;   /* the last row's is 0 */
  uint32_t size = dc_samples[row].sample;
  uint64_t g = (uint64_t)lo << 32 | hi;
  for (uint32_t k = 0; k < size; k++) t[k] = s[lo + geom_splitmix64(&g) % m];
  return dc_select(t, size, size / 2, frame);
}

/* Partition [lo, hi) of buffer w by piv into the other buffer's slice of
** the piece that starts at base: the sites before it at a, a + 1, ... and
** the others at b - 1, b - 2, ... (the back).  Returns the last a.  Without
** branches: a conditional move picks the slot.  Inline, so that each frame
** gets its own loop. */
static inline uint32_t dc_partition_in(dc_run *R, uint32_t base, uint32_t lo, uint32_t hi,
                                       geom_point piv, int frame, int w, uint32_t a,
                                       uint32_t b) {
  const geom_point *s = R->sb[w];
  const uint32_t *id = R->ib[w];
  geom_point *t = dc_to(R, w) + base;
  uint32_t *tid = dc_to_id(R, w) + base;
  for (uint32_t k = lo; k < hi; k++) {
    geom_point v = s[k];
    uint32_t low = (uint32_t)paradigm_frame_before(v, piv, frame), at = low ? a : b - 1;
    t[at] = v, tid[at] = id ? id[k] : k;
    a += low, b -= 1 - low;
  }
  return a;
}

/* The sites of [lo, hi) of buffer w before piv. */
static inline uint32_t dc_count_in(const dc_run *R, uint32_t lo, uint32_t hi, geom_point piv,
                                   int frame, int w) {
  const geom_point *s = R->sb[w];
  uint32_t a = 0;
  for (uint32_t k = lo; k < hi; k++) a += (uint32_t)paradigm_frame_before(s[k], piv, frame);
  return a;
}

/* A wide cut (the top one, when threads share the work): DC_CHUNKS
** chunks counted, then each written from where the chunks before it end,
** as tasks.  Chunk j's sites before piv go after those of chunks 0 .. j-1,
** its others before theirs from the back, so the result is the one pass's,
** site for site, whatever the threads.  Two passes, each split. */
static uint32_t dc_partition_wide(dc_run *R, uint32_t lo, uint32_t hi, geom_point piv,
                                  int frame, int w) {
  uint32_t c[DC_CHUNKS + 1], low[DC_CHUNKS + 1] = {0};
  for (int j = 0; j <= DC_CHUNKS; j++)
    c[j] = lo + (uint32_t)((uint64_t)(hi - lo) * (uint64_t)j / DC_CHUNKS);
  for (int j = 0; j < DC_CHUNKS; j++) {
#pragma omp task shared(c, low)
    low[j + 1] = frame ? dc_count_in(R, c[j], c[j + 1], piv, 1, w)
                       : dc_count_in(R, c[j], c[j + 1], piv, 0, w);
  }
#pragma omp taskwait
  for (int j = 0; j < DC_CHUNKS; j++) low[j + 1] += low[j];
  for (int j = 0; j < DC_CHUNKS; j++) {
    uint32_t a = low[j], b = hi - c[j] + low[j];   /* (hi - lo) - (c[j] - lo - low[j]) */
#pragma omp task shared(c)
    if (frame) dc_partition_in(R, lo, c[j], c[j + 1], piv, 1, w, a, b);
    else dc_partition_in(R, lo, c[j], c[j + 1], piv, 0, w, a, b);
  }
#pragma omp taskwait
  return low[DC_CHUNKS];
}

/* Partition [lo, hi) of buffer w by piv (wide: in chunks, as tasks). */
static uint32_t dc_partition(dc_run *R, uint32_t lo, uint32_t hi, geom_point piv, int frame,
                             int w, int wide) {
  if (wide) return dc_partition_wide(R, lo, hi, piv, frame, w);
  return frame ? dc_partition_in(R, lo, lo, hi, piv, 1, w, 0, hi - lo)
               : dc_partition_in(R, lo, lo, hi, piv, 0, w, 0, hi - lo);
}

/* Split [lo, hi) (at least DC_SORTED sites, in buffer w) in the frame's
** order into the other buffer; returns where the second side starts.
** O(hi - lo) expected: one pass with the sample's pivot, redone with the
** exact median when a side is under an eighth (buffer w is untouched). */
static uint32_t dc_split(dc_run *R, uint32_t lo, uint32_t hi, int frame, int w, int wide) {
  uint32_t m = hi - lo, a;
  for (int exact = 0; exact < 2; exact++) {
    geom_point piv = dc_pivot(R, lo, hi, frame, exact, w);
    a = dc_partition(R, lo, hi, piv, frame, w, wide);
    if (a >= m / 8 + 2 && m - a >= m / 8 + 2) break;
  }
  return lo + a;
}

/* Bring [lo, hi) from buffer w to the sites' array and sort it
** lexicographically, by insertion: small pieces only. */
static void dc_sort_small(dc_run *R, uint32_t lo, uint32_t hi, int w) {
  geom_point *s = R->s;
  uint32_t *id = R->id;
  for (uint32_t k = lo; k < hi && w != DC_IN_S; k++)
    s[k] = R->sb[w][k], id[k] = R->ib[w] ? R->ib[w][k] : k;
  for (uint32_t k = lo + 1; k < hi; k++) {
    geom_point v = s[k];
    uint32_t i = id[k], j = k;
    for (; j > lo && paradigm_frame_before(v, s[j - 1], 0); j--)
      s[j] = s[j - 1], id[j] = id[j - 1];
    s[j] = v, id[j] = i;
  }
}


/* The cut of piece [lo, hi) at depth `depth`: its frame into *frame, the
** state of its sides into *state, where it splits returned.  Each cut moves
** the sites to the other buffer; small pieces come back and are sorted. */
static uint32_t dc_cut(dc_run *R, uint32_t lo, uint32_t hi, int depth, int *state,
                       int *frame) {
  /* The top cut runs before the threads split: its partition is shared. */
  int wide = depth == 0 && R->threads > 1 && hi - lo >= DC_WIDE;
  if (*state != DC_SORTED_S && hi - lo < DC_SORTED) {
    dc_sort_small(R, lo, hi, *state);
    *state = DC_SORTED_S;
  }
  *frame = *state != DC_SORTED_S && R->alternating ? depth & 1 : 0;
  if (*state == DC_SORTED_S) return lo + (hi - lo) / 2;
  uint32_t mid = dc_split(R, lo, hi, *frame, *state, wide);
  *state = *state == DC_IN_T ? DC_IN_S : DC_IN_T;
  return mid;
}

/* Sites [lo, hi) at recursion depth `depth`: T(n) = 2 T(n/2) + merge. */
static dc_hull dc_recurse(dc_run *R, dc_pool *p, ops_counts *c, uint32_t lo, uint32_t hi,
                          int depth, int state) {
  int frame;
  if (hi - lo <= 3 && state != DC_SORTED_S) dc_sort_small(R, lo, hi, state);
  if (hi - lo <= 3) return dc_base(R, p, c, lo, hi - lo);
  uint32_t mid = dc_cut(R, lo, hi, depth, &state, &frame);
  dc_hull a = dc_recurse(R, p, c, lo, mid, depth + 1, state);
  dc_hull b = dc_recurse(R, p, c, mid, hi, depth + 1, state);
  return dc_merge_across(R, p, c, a, b, frame);
}

/* The fixed top levels: node k (heap order) covers [lo, hi); its subtrees
** run as tasks.  Returns the chain of edge slices it used in *first and
** *tail. */
static dc_hull dc_top(dc_run *R, uint32_t lo, uint32_t hi, int depth, int k, int state,
                      dc_pool **first, dc_pool **tail) {
  if (depth == DC_TOP || hi - lo < DC_SORTED) {
    dc_pool *p = &R->pool[k];
    *p = (dc_pool){DC_NONE, 3 * lo, 3 * lo, 3 * hi, NULL};
    *first = *tail = p;
    return dc_recurse(R, p, R->count[k], lo, hi, depth, state);
  }
  int frame;
  uint32_t mid = dc_cut(R, lo, hi, depth, &state, &frame);
  dc_pool *f1, *t1, *f2, *t2;
  dc_hull a, b;
#pragma omp task shared(a, f1, t1) if (R->threads > 1)
  a = dc_top(R, lo, mid, depth + 1, 2 * k + 1, state, &f1, &t1);
  b = dc_top(R, mid, hi, depth + 1, 2 * k + 2, state, &f2, &t2);
#pragma omp taskwait
  t1->more = f2;
  *first = f1, *tail = t2;
  return dc_merge_across(R, f1, R->count[k], a, b, frame);
}

/* ---- the run ---- */

/* The faces of pool p's half-edges, in input indices, into the t slots of
** tri from slot `at` on (back: from slot at - 1 down): the face left of
** half-edge a is Org(a), Dest(a), Org(c) with c = Lprev(a) = Sym(Onext(a)),
** and it is written from its smallest half-edge (a < b = Lnext(a) and
** a < c); the outer face is skipped by the mark DC_OUTER on the origins of
** its half-edges.  a holds c, its twin b and Dest(a), so the test reads
** no other half-edge: one random read a face, Org(c), prefetched a few
** half-edges ahead for every live half-edge (measured: a third faster
** than prefetching only the faces to write, whose lines the others
** share).  A face past the array's ends is counted, not written (a broken
** mesh: the caller's count check fails).  Returns the number of faces. */
#define DC_OUTER 0x80000000u   /* origins are below DC_MAX_POINTS < 2^31 */
#define DC_AHEAD 16

static size_t dc_faces(const dc_run *R, const dc_pool *p, uint32_t *tri, size_t t, size_t at,
                       int back) {
  const paradigm_half *h = R->h;
  const uint32_t *id = R->id;
  size_t k = 0;
  uint32_t end = 2 * p->used;
  for (uint32_t a = 2 * p->base; a < end; a++) {
    uint32_t f = a + DC_AHEAD;
    if (f < end && !(h[f].org & DC_OUTER)) __builtin_prefetch(&h[h[f].next ^ 1]);
    uint32_t o = h[a].org, c = h[a].next ^ 1;
    if ((o & DC_OUTER) || h[a ^ 1].prev < a || c < a) continue;   /* deleted, outer */
    size_t slot = back ? at - 1 - k : at + k;
    k++;
    if (back ? k > at : slot >= t) continue;
    tri[3 * slot] = id[o];
    tri[3 * slot + 1] = id[h[a ^ 1].org & ~DC_OUTER];
    tri[3 * slot + 2] = id[h[c].org & ~DC_OUTER];
  }
  return k;
}

/* The triangles of the mesh, 2n - 2 - h of them (h on the hull), into an
** array of that size from both ends: the first half of the pools' faces
** from the front, in pool order, the second half's from the back, in
** reverse (the pools read by two threads, the same array whatever the
** threads: no scratch, no copy).  The array is the block of the sites
** and the cuts' scratch, dead by now (36 bytes a site hold the 12 a
** triangle, under 24 a site), cut to size: no fresh memory to fault in
** and zero.  O(n). */
static int dc_triangles(dc_run *R, const dc_pool *first, dc_hull top, uint32_t n,
                        paradigm_output *out) {
  uint32_t e0 = top.l ^ 1, e = e0, hull = 0;
  do {
    hull++;
    R->h[e].org |= DC_OUTER;
    e = paradigm_he_lnext(R->h, e);
  } while (e != e0);
  const dc_pool *pool[DC_NODES];
  int np = 0;
  for (const dc_pool *p = first; p != NULL && np < DC_NODES; p = p->more) pool[np++] = p;
  size_t t = 2 * (size_t)n - 2 - hull, got[2] = {0, 0};
  out->tri = R->block;
#pragma omp parallel for schedule(static, 1) num_threads(2) if (R->threads > 1)
  for (int f = 0; f < 2; f++)   /* front 0: pools 0 .. np/2 - 1; front 1: np - 1 down */
    for (int k = f ? np - 1 : 0; f ? k >= np / 2 : k < np / 2; k += f ? -1 : 1)
      got[f] += dc_faces(R, pool[k], out->tri, t, f ? t - got[f] : got[f], f);
  void *fit = realloc(R->block, 3 * (t ? t : 1) * sizeof *out->tri);   /* shrinks */
  out->tri = fit != NULL ? fit : R->block;
  R->block = NULL;
  out->ntri = t;
  return got[0] + got[1] == t ? 0 : -2;
}

/* Merge and triangulate the sites s (in the order of the cuts). */
static int dc_mesh(dc_run *R, uint32_t n, ops_counts *c, paradigm_output *out, char *err,
                   size_t errlen) {
  dc_counts part[DC_NODES];
  memset(part, 0, sizeof part);
  for (int k = 0; k < DC_NODES; k++) R->count[k] = c ? &part[k].c : NULL;
  size_t bytes = 3 * (size_t)n * 2 * sizeof *R->h;
  R->h = malloc(bytes);
  if (R->h == NULL) {
    snprintf(err, errlen, "out of memory for the mesh of %u points", n);
    return -1;
  }
  ops_memory(c, (int64_t)bytes);
  dc_pool *first = NULL, *tail = NULL;
  dc_hull top;
  if (R->threads > 1) {
#pragma omp parallel num_threads(R->threads < 4 ? R->threads : 4)
#pragma omp single
    top = dc_top(R, 0, n, 0, 0, DC_IN_P, &first, &tail);
  } else {
    top = dc_top(R, 0, n, 0, 0, DC_IN_P, &first, &tail);
  }
  for (int k = 0; k < DC_NODES && c != NULL; k++) ops_merge(c, &part[k].c);
  int rc = R->failed ? -2 : dc_triangles(R, first, top, n, out);
  free(R->h);
  ops_memory(c, -(int64_t)bytes);
  if (rc == -2) snprintf(err, errlen, "divide and conquer: the mesh of %u points is not a "
                         "triangulation (a bug: please report it)", n);
  return rc == 0 ? 0 : -1;
}

/* The sites, s[k] = p[id[k]] (in input order to begin with: the cuts
** permute them), and the scratch of the cuts, s, ts and tid in one block
** (dc_triangles writes the triangles there).  0, or -1 (out of memory). */
static int dc_sites(const paradigm_input *in, ops_counts *c, dc_run *R) {
  uint32_t n = (uint32_t)in->n;
  R->id = malloc((size_t)n * sizeof *R->id);
  R->block = malloc((size_t)(n ? n : 1) * (2 * sizeof *R->s + sizeof *R->tid));
  ops_memory(c, (int64_t)n * 40);
  if (R->id == NULL || R->block == NULL) return -1;
  R->s = R->block;
  R->ts = R->s + n;
  R->tid = (uint32_t *)(R->ts + n);
  R->sb[0] = R->s, R->sb[1] = R->ts, R->sb[2] = in->p;
  R->ib[0] = R->id, R->ib[1] = R->tid, R->ib[2] = NULL;
  return 0;
}

/* Both rows, counting into c (NULL: not counting).  Cost: the cuts, one
** partition pass a level, O(n) expected per level and O(n log n) in all
** (they take the place of the sort, which costs about as much); log n
** levels of merges, each O(n) at worst (T(n) = 2 T(n/2) + O(n) = O(n log
** n)).  On uniform sites the vertical cuts' merges run along the long axis
** of thin strips, Theta(n) each, so Theta(n log n); alternating cuts keep
** the pieces square, a merge of m sites crosses O(sqrt m) edges, and the
** merges cost O(n) expected in all (Dwyer shows O(n log log n) for his
** variant).  Memory: 72 bytes a site for the mesh (3n edges of 24 bytes),
** 40 for the sites and the scratch of the cuts, 36 of which then hold the
** triangles. */
int paradigm_divide(const paradigm_input *in, int alternating, ops_counts *c,
                    paradigm_output *out, char *err, size_t errlen) {
  if (in->n > DC_MAX_POINTS) {
    snprintf(err, errlen, "divide and conquer: %zu points, at most %u", in->n,
             (unsigned)DC_MAX_POINTS);
    return -1;
  }
  uint32_t n = (uint32_t)in->n;
  /* Threads pay only past a few thousand sites (a team costs microseconds). */
  dc_run R = {.r = in->r, .es = rule_shape(in->r) != NULL, .alternating = alternating,
              .threads = n < 4096 ? 1 : in->threads};
  int rc = dc_sites(in, c, &R);
  if (rc != 0) snprintf(err, errlen, "out of memory for the sites of %u points", n);
  else rc = dc_mesh(&R, n, c, out, err, errlen);
  free(R.block), free(R.id);
  ops_memory(c, -(int64_t)n * 40);
  return rc;
}

int paradigm_dc_vertical(const paradigm_input *in, paradigm_output *out, char *err,
                         size_t errlen) {
  return paradigm_divide(in, 0, &out->ops, out, err, errlen);
}

int paradigm_dc_alternating(const paradigm_input *in, paradigm_output *out, char *err,
                            size_t errlen) {
  return paradigm_divide(in, 1, &out->ops, out, err, errlen);
}
