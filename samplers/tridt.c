/*
** tridt.c: the triangulation method (thesis section 6.6): a uniformly
** random triangulation of the convex n-gon, realised as a strictly convex
** polygon whose Delaunay triangulation it is (Dillencourt's construction,
** in the thesis's O(n) form).
**
** The triangulation.  Triangulations of the n-gon with vertices 0..n-1 are
** in bijection with binary trees of n - 2 internal nodes: the root is the
** triangle on the side (0, n-1), and the triangle (i, k, j) (i < k < j) has
** the sub-polygons i..k and k..j as its left and right subtrees.  A binary
** tree is its preorder word, +1 for a node and -1 for a leaf; by the cycle
** lemma each of the C(2m+1, m) words of m (+1)s and m + 1 (-1)s has exactly
** one rotation that is a tree's word (all proper prefix sums >= 0; the cut
** is after the first minimum of the prefix sums), and the 2m + 1 rotations
** are distinct.  So a uniformly shuffled word (Fisher-Yates), rotated, is a
** uniform tree, and a uniform triangulation: every one of the Catalan
** number C_{n-2} triangulations equally likely.  O(n).
**
** The angles (6.6.1 and 6.6.2).  Angles are integers in units where s units
** make a straight angle.  They realise the triangulation as a Delaunay one
** when (1) the angles at each vertex sum to less than s (convex), (2) the
** two angles facing each interior edge sum to less than s (locally
** Delaunay), (3) every angle is positive and (4) each triangle's sum is s.
** Start with the root at (1, 1, 1), s = 3; a triangle added across the
** edge AB of a triangle ABD whose corner D has value z gets z + 1 at A and
** B and s - z - 1 at its apex, s grows by z + 1, and every corner opposite
** (w.r.t. the new triangle) implicitly grows by z + 1 too.  The O(n) form
** never performs those increments: it walks round the dual tree (the tree
** above) twice, keeping a current triangle whose three values are right;
** the only value of another triangle that may be stale is its corner
** opposite the edge leading to the current triangle, and it is recomputed
** from s and the two others when the walk enters that triangle across that
** edge.  The first walk adds every triangle, the second corrects every
** stale corner once s is final.  s grows like n^1.5 on uniform trees
** (about 2^17 at n = 2000); beyond 2^53 the values would no longer be
** exact doubles, so such a draw is refused.
**
** The polygon.  Directions of edges are integers modulo 2s too, so they are
** exact: the root's side runs from p_0 = (0, 0) to p_{n-1} = (1, 0); in a
** triangle (i, k, j) the edge i -> k turns clockwise from i -> j by the
** angle at i, and k -> j turns anticlockwise from i -> j by the angle at j;
** lengths follow the law of sines.  Only cos, sin and the lengths round:
** each vertex is placed from its parent triangle's two vertices, so a
** vertex at depth d of the dual tree carries some d rounding errors of
** relative size 2^-53 of the coordinates, while the smallest angles are
** pi / s and the smallest edges far shorter.  Past some n the rounding
** therefore spoils convexity or the Delaunay property; every draw is
** checked exactly (geom_polygon_check, and geom_incircle strictly negative
** across each of the n - 3 interior edges: a strictly convex polygon whose
** triangulation is locally Delaunay with no cocircular quadrilateral has it
** as its unique Delaunay triangulation) and refused (-1) when the check
** fails, rather than drawn again, which would bias the law towards the
** triangulations that doubles realise (docs/sampling.md has the figures).
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "sampler.h"

#define TRIDT_PI 3.14159265358979323846
#define TRIDT_SMAX 0x1p53   /* values and s stay exact doubles and uint64 below it */

/* One triangle (i, k, j), i < k < j, of the dual tree in preorder. */
typedef struct tridt_node {
  uint32_t v[3];           /* i, k, j */
  uint32_t child[2];       /* across (i, k) and (k, j); UINT32_MAX for a polygon side */
  uint32_t parent;         /* UINT32_MAX at the root */
  uint64_t a[3];           /* the angles at i, k, j in units, s a straight angle */
} tridt_node;

#define TRIDT_NONE UINT32_MAX

/* A uniform tree word of m nodes into w[0 .. 2m]: shuffle, then rotate
** after the first minimum of the prefix sums (the cycle lemma).  O(m). */
static void tridt_word(sampler_rng *g, size_t m, signed char *w, signed char *tmp) {
  size_t len = 2 * m + 1, cut = 0;
  for (size_t i = 0; i < len; i++) tmp[i] = i < m ? 1 : -1;
  for (size_t i = len - 1; i > 0; i--) {
    size_t j = (size_t)sampler_below(g, i + 1);
    signed char t = tmp[i];
    tmp[i] = tmp[j];
    tmp[j] = t;
  }
  long sum = 0, low = 0;
  for (size_t i = 0; i < len; i++) {
    sum += tmp[i];
    if (sum < low) low = sum, cut = i + 1;
  }
  for (size_t i = 0; i < len; i++) w[i] = tmp[(cut + i) % len];
}

/* The nodes of the tree of word w (m nodes, preorder): each node's i is the
** first polygon side of its subtree, k the end of its left subtree, j the
** end of its right one; the sides are the leaves (c, c + 1) in order.  An
** explicit stack of the nodes whose subtrees are open.  O(m). */
static void tridt_parse(const signed char *w, size_t m, tridt_node *t, uint32_t *stack,
                        unsigned char *side) {
  size_t top = 0, next = 0;
  uint32_t c = 0;
  for (size_t pos = 0; pos < 2 * m + 1; pos++) {
    if (w[pos] > 0) {
      tridt_node *x = &t[next];
      memset(x, 0, sizeof *x);
      x->v[0] = c;
      x->child[0] = x->child[1] = TRIDT_NONE;
      x->parent = top ? stack[top - 1] : TRIDT_NONE;
      if (top) t[stack[top - 1]].child[side[top - 1]] = (uint32_t)next;
      stack[top] = (uint32_t)next++;
      side[top++] = 0;
      continue;
    }
    c++;   /* the side (c - 1, c) closes; so may the subtrees it ends */
    while (top && side[top - 1] == 1) t[stack[--top]].v[2] = c;
    if (top) {
      t[stack[top - 1]].v[1] = c;
      side[top - 1] = 1;
    }
  }
}

/* Enter node x from its parent across the parent's edge on side d (0: (i, k),
** 1: (k, j)), whose facing corner in the parent is j or i.  Returns -1 when
** s would leave the exact range. */
static int tridt_enter_child(tridt_node *t, uint32_t x, int d, uint64_t *s) {
  uint64_t *a = t[x].a;
  const uint64_t *pa = t[t[x].parent].a;
  if (a[0] != 0) {
    a[1] = *s - a[0] - a[2];   /* the corner facing the edge just crossed */
    return 0;
  }
  uint64_t z = pa[d == 0 ? 2 : 0];
  if ((double)*s + (double)z + 1 >= TRIDT_SMAX) return -1;
  a[0] = a[2] = z + 1;
  a[1] = *s - z - 1;
  *s += z + 1;
  return 0;
}

/* One walk round the outer face of the dual tree from the root, back to
** it: each edge crossed twice, O(m). */
static int tridt_walk(tridt_node *t, uint64_t *s) {
  uint32_t cur = 0, from = TRIDT_NONE;
  for (;;) {
    const tridt_node *x = &t[cur];
    uint32_t nx;
    if (from == x->parent) nx = x->child[0] != TRIDT_NONE ? x->child[0] : x->child[1];
    else nx = from == x->child[0] ? x->child[1] : TRIDT_NONE;
    if (nx == TRIDT_NONE) nx = x->parent;   /* back up */
    if (nx == TRIDT_NONE) return 0;         /* back at the root from its last child */
    if (nx == x->parent) {
      tridt_node *p = &t[nx];
      int d = p->child[0] == cur ? 0 : 1;   /* recompute the corner facing that edge */
      if (d == 0) p->a[2] = *s - p->a[0] - p->a[1];
      else p->a[0] = *s - p->a[1] - p->a[2];
    } else if (tridt_enter_child(t, nx, nx == x->child[0] ? 0 : 1, s) != 0) {
      return -1;
    }
    from = cur;
    cur = nx;
  }
}

/* The angles of every triangle (section 6.6.2): two walks.  *s gets the
** straight angle. */
static int tridt_angles(tridt_node *t, uint64_t *s) {
  *s = 3;
  t[0].a[0] = t[0].a[1] = t[0].a[2] = 1;
  for (int pass = 0; pass < 2; pass++)
    if (tridt_walk(t, s) != 0) return -1;
  return 0;
}

/* sin(pi a / s) for 0 < a < s, from the nearer of a and s - a so that small
** angles keep their relative accuracy. */
static double tridt_sin(uint64_t a, uint64_t s) {
  uint64_t m = a < s - a ? a : s - a;
  return sin(TRIDT_PI * ((double)m / (double)s));
}

static geom_point tridt_step(geom_point p, double len, uint64_t dir, uint64_t s) {
  double f = TRIDT_PI * ((double)dir / (double)s);   /* dir < 2s */
  return (geom_point){p.x + len * cos(f), p.y + len * sin(f)};
}

/* The vertices by trigonometry, the nodes in preorder (parents first).
** dir[x], len[x]: the direction (units mod 2s) and length of x's edge i -> j. */
static void tridt_place(const tridt_node *t, size_t m, uint64_t s, geom_point *p, uint64_t *dir,
                        double *len) {
  p[t[0].v[0]] = (geom_point){0, 0};
  p[t[0].v[2]] = (geom_point){1, 0};
  dir[0] = 0;
  len[0] = 1;
  for (size_t x = 0; x < m; x++) {
    const uint64_t *a = t[x].a;
    uint64_t dl = (dir[x] + 2 * s - a[0]) % (2 * s), dr = (dir[x] + a[2]) % (2 * s);
    double sk = tridt_sin(a[1], s);
    double ll = len[x] * tridt_sin(a[2], s) / sk, lr = len[x] * tridt_sin(a[0], s) / sk;
    p[t[x].v[1]] = tridt_step(p[t[x].v[0]], ll, dl, s);
    if (t[x].child[0] != TRIDT_NONE) dir[t[x].child[0]] = dl, len[t[x].child[0]] = ll;
    if (t[x].child[1] != TRIDT_NONE) dir[t[x].child[1]] = dr, len[t[x].child[1]] = lr;
  }
}

/* 1 when every interior edge is strictly locally Delaunay (exact). */
static int tridt_delaunay(const tridt_node *t, size_t m, const geom_point *p) {
  for (size_t x = 0; x < m; x++)
    for (int d = 0; d < 2; d++) {
      uint32_t c = t[x].child[d];
      if (c == TRIDT_NONE) continue;
      const uint32_t *v = t[x].v;
      if (geom_incircle(p[v[0]], p[v[1]], p[v[2]], p[t[c].v[1]]) >= 0) return 0;
    }
  return 1;
}

/* The work space of one draw: one allocation. */
typedef struct tridt_work {
  tridt_node *t;
  uint64_t *dir;
  double *len;
  uint32_t *stack;
  signed char *w, *tmp;
  unsigned char *side;
} tridt_work;

static void *tridt_alloc(tridt_work *k, size_t m) {
  size_t len = 2 * m + 1;
  size_t bytes = m * (sizeof *k->t + sizeof *k->dir + sizeof *k->len + sizeof *k->stack + 1)
               + 2 * len;
  char *b = malloc(bytes);
  if (b == NULL) return NULL;
  k->t = (tridt_node *)b;
  k->dir = (uint64_t *)(k->t + m);
  k->len = (double *)(k->dir + m);
  k->stack = (uint32_t *)(k->len + m);
  k->w = (signed char *)(k->stack + m);
  k->tmp = k->w + len;
  k->side = (unsigned char *)(k->tmp + len);
  return b;
}

/* The drawn triangles, renumbered from the output's first vertex. */
static void tridt_triangles(const tridt_node *t, size_t m, size_t n, size_t first, uint32_t *tri) {
  for (size_t x = 0; x < m; x++)
    for (int c = 0; c < 3; c++) tri[3 * x + c] = (uint32_t)((t[x].v[c] + n - first) % n);
}

/* O(n): the word, the tree, two walks, the placement, the exact checks. */
int sampler_gon_tridt(sampler_rng *g, size_t n, geom_point *out, uint32_t *tri,
                      sampler_gon_info *info) {
  if (info != NULL) *info = (sampler_gon_info){0, 0, 0};
  if (n < 3 || n > UINT32_MAX / 2) return -1;
  size_t m = n - 2, first = 0;
  tridt_work k;
  void *block = tridt_alloc(&k, m);
  if (block == NULL) return SAMPLER_ENOMEM;
  tridt_word(g, m, k.w, k.tmp);
  tridt_parse(k.w, m, k.t, k.stack, k.side);
  uint64_t s;
  int rc = tridt_angles(k.t, &s);
  if (rc == 0) {
    tridt_place(k.t, m, s, out, k.dir, k.len);
    rc = tridt_delaunay(k.t, m, out) ? sampler_gon_canon(out, n, &first) : -1;
  }
  if (rc == 0 && tri != NULL) tridt_triangles(k.t, m, n, first, tri);
  if (info != NULL) info->draws = 2 * m;
  free(block);
  return rc;
}

int sampler_gon_triangulation(sampler_rng *g, size_t n, const sampler_gon_params *p,
                              geom_point *out, sampler_gon_info *info) {
  (void)p;
  return sampler_gon_tridt(g, n, out, NULL, info);
}
