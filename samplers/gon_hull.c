/*
** gon_hull.c: rejection (thesis section 6.2) and iteration (6.3) in
** O(log n) per point, on one structure: the hull as a doubly linked list of
** vertices (edge v runs from vertex v to its successor), and a tree of
** partial sums over the edges' region masses.
**
** The tree.  The thesis keeps the regions' masses in the leaves of a
** balanced tree in hull order and splits a leaf when a point is inserted.
** Selection by descent needs no particular leaf order, so here leaf k is
** the region of the edge that starts at vertex slot k: a new vertex takes a
** free slot (a new leaf, or one a deleted vertex gave back), its edge's
** region is that leaf, and its neighbours' regions are updated in place.
** The tree is a complete binary tree over a power-of-two number of leaves,
** each inner node the sum of its two children, recomputed from them (never
** updated by differences, so rounding cannot drift): perfectly balanced by
** construction with no rotations.  Setting a leaf and selecting a leaf
** (descend with u * total: left if below the left child's sum, else right
** with the left sum taken off) cost O(log n) each.
**
** Rejection: start from three points of the domain; then draw each next
** point in the acceptance regions (right of exactly one edge: right of edge
** v, left of the lines of the two edges beside it; thesis figure 6.2): pick
** a region by its mass, draw uniformly in it, test exactly, insert.  One
** insertion changes the regions of the new vertex's two edges and of the
** two edges beside them: four leaves, O(log n).  The weight is the product
** of the total masses A (the root) at each step: n independent uniform
** points, conditioned on convex position, have the density prod_k 1[p_k in
** the acceptance region of p_1..p_{k-1}], the sampler's is prod 1[...] / A_k,
** so weighting by prod A_k gives weighted statistics of exactly that law.
** Total O(n log n).
**
** Iteration: the exterior of the hull is cut into one region per edge,
** right of edge v and left of the line of the edge before it (thesis figure
** 6.5: the first edge, anticlockwise, that the point sees); a point drawn
** there by mass is a uniform point of the domain outside the hull, the next
** point of the naive method that changes the hull.  Its visible chain is
** deleted (each deletion charged to the vertex's creation) and three leaves
** change.  O(h log n) for h hull changes.  For the disc and n below
** SAMPLER_HULL_MAX the registry keeps sampler_convex's own loop, draw for
** draw (the census's and table 3.4's polygons); law 1 asks for the general
** path there too (the tests compare the two).
*/
#include <math.h>
#include <stdlib.h>
#include "gon_internal.h"

typedef struct sampler_hull {
  geom_point *p;
  size_t *nxt, *prv, *freed;
  double *sum;            /* the tree: sum[1] the root, leaves at sum[cap + k] */
  size_t cap, slots, nfree, live;
} sampler_hull;

static void sampler_hull_free(sampler_hull *h) {
  free(h->p);
  free(h->nxt);
  free(h->prv);
  free(h->freed);
  free(h->sum);
}

static int sampler_hull_init(sampler_hull *h, size_t n) {
  *h = (sampler_hull){0};
  h->cap = 1;
  while (h->cap < n) h->cap *= 2;
  h->p = malloc(n * sizeof *h->p);
  h->nxt = malloc(n * sizeof *h->nxt);
  h->prv = malloc(n * sizeof *h->prv);
  h->freed = malloc(n * sizeof *h->freed);
  h->sum = calloc(2 * h->cap, sizeof *h->sum);
  if (h->p && h->nxt && h->prv && h->freed && h->sum) return 0;
  sampler_hull_free(h);
  return SAMPLER_ENOMEM;
}

static void sampler_tree_set(sampler_hull *h, size_t k, double w) {
  size_t j = h->cap + k;
  h->sum[j] = w;
  for (j /= 2; j >= 1; j /= 2) h->sum[j] = h->sum[2 * j] + h->sum[2 * j + 1];
}

/* The leaf whose partial-sum interval holds u, 0 <= u < sum[1]. */
static size_t sampler_tree_select(const sampler_hull *h, double u) {
  size_t j = 1;
  while (j < h->cap) {
    if (u < h->sum[2 * j]) {
      j = 2 * j;
    } else {
      u -= h->sum[2 * j];
      j = 2 * j + 1;
    }
  }
  return j - h->cap;
}

static size_t sampler_hull_slot(sampler_hull *h, geom_point p) {
  size_t s = h->nfree > 0 ? h->freed[--h->nfree] : h->slots++;
  h->p[s] = p;
  h->live++;
  return s;
}

static void sampler_hull_link(sampler_hull *h, size_t a, size_t b) {
  h->nxt[a] = b;
  h->prv[b] = a;
}

/* The region of edge v (v -> nxt v) into c, and its mass: acceptance
** (both neighbours' lines) or exterior (the previous one's). */
static double sampler_hull_clip(const sampler_hull *h, sampler_region r, size_t v, int accept,
                                sampler_clip *c) {
  size_t w = h->nxt[v];
  geom_point a = h->p[v], b = h->p[w];
  geom_point left[2][2] = {{h->p[h->prv[v]], a}, {b, h->p[h->nxt[w]]}};
  return sampler_region_mass(r, a, b, (const geom_point (*)[2])left, accept ? 2 : 1, c);
}

static void sampler_hull_update(sampler_hull *h, sampler_region r, size_t v, int accept) {
  sampler_clip c;
  sampler_tree_set(h, v, sampler_hull_clip(h, r, v, accept, &c));
}

/* Three points of the domain, not on one line (exact), anticlockwise, as
** slots 0, 1, 2; their regions.  Points drawn again on a degenerate draw. */
static void sampler_hull_start(sampler_hull *h, sampler_rng *g, sampler_region r, int accept,
                               uint64_t *draws) {
  geom_point q[3];
  int o;
  do {
    for (int k = 0; k < 3; k++) q[k] = sampler_region_point(g, r);
    *draws += 3;
  } while ((o = geom_orient(q[0], q[1], q[2])) == 0);
  if (o < 0) {
    geom_point t = q[1];
    q[1] = q[2];
    q[2] = t;
  }
  for (int k = 0; k < 3; k++) (void)sampler_hull_slot(h, q[k]);
  for (size_t k = 0; k < 3; k++) sampler_hull_link(h, k, (k + 1) % 3);
  for (size_t k = 0; k < 3; k++) sampler_hull_update(h, r, k, accept);
}

#define SAMPLER_STEP_TRIES 1000

/* One point in the region of a leaf chosen by mass, inside the region
** exactly: strictly right of edge v, strictly left of the previous edge's
** line, and (accept) of the next one's.  0, or -1 when rounding made every
** try fail (regions too thin for doubles). */
static int sampler_hull_draw(sampler_hull *h, sampler_rng *g, sampler_region r, int accept,
                             size_t *v, geom_point *p, uint64_t *draws) {
  for (int t = 0; t < SAMPLER_STEP_TRIES; t++) {
    size_t k = sampler_tree_select(h, sampler_uniform(g) * h->sum[1]);
    if (k >= h->slots || !(h->sum[h->cap + k] > 0)) continue;
    size_t w = h->nxt[k];
    geom_point a = h->p[k], b = h->p[w];
    sampler_clip c;
    (void)sampler_hull_clip(h, r, k, accept, &c);
    if (sampler_region_draw(g, r, &c, p, draws) != 0) return -1;
    if (geom_orient(a, b, *p) < 0 && geom_orient(h->p[h->prv[k]], a, *p) > 0 &&
        (!accept || geom_orient(b, h->p[h->nxt[w]], *p) > 0)) {
      *v = k;
      return 0;
    }
  }
  return -1;
}

/* out = the hull (v one of its vertices) from its lexicographically
** smallest vertex. */
static void sampler_hull_out(const sampler_hull *h, size_t v, geom_point *out) {
  for (size_t k = 0; k < h->live; k++, v = h->nxt[v]) out[k] = h->p[v];
  sampler_lexfirst(out, h->live);
}

int sampler_gon_rejection(sampler_rng *g, size_t n, const sampler_gon_params *prm,
                          geom_point *out, sampler_gon_info *info) {
  sampler_hull h;
  sampler_region r = prm->region;
  if (n < 3 || sampler_hull_init(&h, n) != 0) return n < 3 ? -1 : SAMPLER_ENOMEM;
  sampler_hull_start(&h, g, r, 1, &info->draws);
  int rc = 0;
  while (h.live < n && rc == 0) {
    size_t v;
    geom_point p;
    if (!(h.sum[1] > 0) || sampler_hull_draw(&h, g, r, 1, &v, &p, &info->draws) != 0) {
      rc = -1;
      break;
    }
    info->log_weight += log(h.sum[1]);
    size_t w = h.nxt[v], s = sampler_hull_slot(&h, p);
    sampler_hull_link(&h, v, s);
    sampler_hull_link(&h, s, w);
    size_t touched[4] = {h.prv[v], v, s, w};
    for (int k = 0; k < 4; k++) sampler_hull_update(&h, r, touched[k], 1);
  }
  if (rc == 0) sampler_hull_out(&h, 0, out);
  sampler_hull_free(&h);
  return rc;
}

/* Insert p, seen first by edge v: delete the rest of its visible chain
** (edges with p right of or on their line), link v -> p -> w; the regions
** of the three edges that changed.  Returns p's slot. */
static size_t sampler_hull_iterate(sampler_hull *h, sampler_region r, size_t v, geom_point p) {
  size_t w = h->nxt[v];
  while (geom_orient(h->p[w], h->p[h->nxt[w]], p) <= 0) {
    size_t x = h->nxt[w];
    sampler_tree_set(h, w, 0);
    h->freed[h->nfree++] = w;
    h->live--;
    w = x;
  }
  size_t s = sampler_hull_slot(h, p);
  sampler_hull_link(h, v, s);
  sampler_hull_link(h, s, w);
  size_t touched[3] = {v, s, w};
  for (int k = 0; k < 3; k++) sampler_hull_update(h, r, touched[k], 0);
  return s;
}

static int sampler_gon_iterate_large(sampler_rng *g, size_t n, sampler_region r,
                                     geom_point *out, sampler_gon_info *info) {
  sampler_hull h;
  if (sampler_hull_init(&h, n + 1) != 0) return SAMPLER_ENOMEM;
  sampler_hull_start(&h, g, r, 0, &info->draws);
  info->hull_changes = 3;
  size_t last = 0;
  int rc = 0;
  while (h.live != n) {
    size_t v;
    geom_point p;
    if (!(h.sum[1] > 0) || sampler_hull_draw(&h, g, r, 0, &v, &p, &info->draws) != 0) {
      rc = -1;
      break;
    }
    last = sampler_hull_iterate(&h, r, v, p);
    info->hull_changes++;
  }
  if (rc == 0) sampler_hull_out(&h, last, out);
  sampler_hull_free(&h);
  return rc;
}

int sampler_gon_iteration(sampler_rng *g, size_t n, const sampler_gon_params *prm,
                          geom_point *out, sampler_gon_info *info) {
  if (n < 3) return -1;
  if (prm->region != SAMPLER_REGION_DISC || n >= SAMPLER_HULL_MAX || prm->law == 1)
    return sampler_gon_iterate_large(g, n, prm->region, out, info);
  sampler_convex_rng(g, (int)n, out, &info->hull_changes);
  return 0;
}
