/*
** got_points.c: the GOT of a point set for a sum rule (got.h, "point sets"; docs/got.md,
** "Point sets").
**
** Why it is exact.  For a rule whose joint's keys add, a triangulation's total key is the
** sum of its triangles' keys, and a flip changes it by the difference of the two pairs'
** keys, which is what the rule decides by: so no flip improves a GOT strictly, every GOT
** is a LOT, and the skeleton's CERTAIN edges (in every LOT: got_skel.h) are in every GOT.
** The certain edges cut the hull into faces; a triangulation containing them is a union
** of triangulations of the faces, its total the sum of theirs, so the optimum is the union
** of the faces' optima and the runner-up among such triangulations differs from the
** optimum in exactly one face.  Every GOT contains the skeleton, so the GOT is unique iff
** every face's optimum is.
**
** Steps and costs (n points, E certain edges, F faces):
**   validation (sort: O(n log n)); the skeleton (got_skel_build, got_skel_delaunay on a
**   caller's Delaunay triangulation for the rules of rule_got_cdt_theorem, or got_skel_all in
**   O(n^3)); the planar graph of the certain edges: neighbours in exact angular order
**   (O(sum deg^2), insertion sorts of short lists), its closed walks (O(E)), components
**   (union-find), each component not holding the hull and each isolated point located in
**   the innermost bounded walk around it (a uniform grid of walk boxes, exact winding
**   numbers); the POSSIBLE edges sent to the face on both their ends' wedges (O(sum deg));
**   then each face solved independently (OpenMP, faces of GOT_POINTS_BIG points and more
**   one after the other with every thread inside got_solve) and combined in face order,
**   so the result is bit-identical for any thread count.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "measure.h"
#include "got_internal.h"
#include "geom_key_internal.h"
#include "got_skel.h"
#include "got_face.h"

/* Faces with at least this many boundary and inner points are solved one at a time with
** all threads inside (got_solve's own OpenMP); the others in parallel, one thread each. */
#define GOT_POINTS_BIG 256

/* Bytes per point beyond the skeleton's edges: the graph, walks, faces, triangles. */
#define GOT_POINTS_BYTES_PER_POINT 400

typedef struct got_pt {
  double x, y;
  size_t row;
} got_pt;

static int got_pt_cmp(const void *a, const void *b) {
  const got_pt *u = a, *v = b;
  if (u->x != v->x) return u->x < v->x ? -1 : 1;
  if (u->y != v->y) return u->y < v->y ? -1 : 1;
  return u->row < v->row ? -1 : u->row > v->row;
}

static int got_points_err(char *err, size_t errlen, const char *what) {
  snprintf(err, errlen, "%s", what);
  return -1;
}

/* Two equal points, naming both rows; 0 when all are distinct.  O(n log n). */
static int got_points_distinct(const geom_point *p, size_t n, char *err, size_t errlen) {
  got_pt *s = malloc(n * sizeof *s);
  if (s == NULL) return got_points_err(err, errlen, "out of memory");
  for (size_t i = 0; i < n; i++) s[i] = (got_pt){p[i].x, p[i].y, i};
  qsort(s, n, sizeof *s, got_pt_cmp);
  int rc = 0;
  for (size_t i = 1; i < n && rc == 0; i++)
    if (s[i].x == s[i - 1].x && s[i].y == s[i - 1].y) {
      snprintf(err, errlen, "points %zu and %zu (0-based rows) are equal (%.17g, %.17g): "
               "a point set's GOT needs distinct points", s[i - 1].row, s[i].row, s[i].x,
               s[i].y);
      rc = -1;
    }
  free(s);
  return rc;
}

int got_points_check(const geom_point *p, size_t n, const rule *r, char *err, size_t errlen) {
  if (!rule_is_triangle(r) || joint_get(rule_joint(r))->keyop != JOINT_KEY_ADD) {
    snprintf(err, errlen, "rule %s is not a sum rule: a point set's GOT needs a measure and a "
             "joint whose keys add (l_1, l_2, l_0, l_-1 or a power mean l_p, e.g. P_1), as "
             "the skeleton's argument does", rule_name(r));
    return -1;
  }
  if (n < 3) {
    snprintf(err, errlen, "a point set's GOT needs at least 3 points, got %zu", n);
    return -1;
  }
  if (n > INT32_MAX) {
    snprintf(err, errlen, "%zu points are too many (at most %d)", n, INT32_MAX);
    return -1;
  }
  for (size_t i = 0; i < n; i++) {
    geom_coorderr e = geom_coord_check(p[i].x);
    if (e == GEOM_COORD_OK) e = geom_coord_check(p[i].y);
    if (e != GEOM_COORD_OK) {
      snprintf(err, errlen, "point %zu (0-based row): a coordinate %s", i, geom_coorderr_str(e));
      return -1;
    }
  }
  if (got_points_distinct(p, n, err, errlen) != 0) return -1;
  for (size_t c = 2; c < n; c++)
    if (geom_orient(p[0], p[1], p[c]) != 0) return 0;
  return got_points_err(err, errlen, "the points are all collinear: they have no "
                        "triangulation");
}

size_t got_points_memory_needed(size_t n) {
  return n > SIZE_MAX / 1024 ? SIZE_MAX : n * GOT_POINTS_BYTES_PER_POINT;
}

int got_points_check_memory(size_t n, char *err, size_t errlen) {
  size_t need = got_points_memory_needed(n), have = got_phys_memory() / 4 * 3;
  if (need <= have && n <= INT32_MAX) return 0;
  snprintf(err, errlen, "%zu points need about %.3g GB, more than the %.2f GB allowed (3/4 "
           "of physical memory)", n, (double)n * GOT_POINTS_BYTES_PER_POINT / 1e9, have / 1e9);
  return -1;
}

static const char *const got_skeleton_names[] = {"auto", "all", "lmt", "delaunay"};
#define GOT_NSKELETONS (sizeof got_skeleton_names / sizeof *got_skeleton_names)

const char *got_skeleton_name(got_skeleton s) {
  return (unsigned)s < GOT_NSKELETONS ? got_skeleton_names[s] : "?";
}

int got_skeleton_find(const char *name) {
  for (int i = 0; i < (int)GOT_NSKELETONS; i++)
    if (name != NULL && strcmp(name, got_skeleton_names[i]) == 0) return i;
  return -1;
}

/* ---- the planar graph of the certain edges ---- */

typedef struct got_graph {
  const geom_point *p;
  size_t n;
  size_t *off;          /* n + 1: neighbours of v are adj[off[v] .. off[v+1]) */
  uint32_t *adj;        /* in anticlockwise order from the direction (1, 0) */
  uint32_t *walk_of;    /* per half-edge v -> adj[h]: its closed walk */
  size_t nwalks;
  size_t *woff;         /* walk w: wv[woff[w] .. woff[w+1]) (tails of its half-edges) */
  uint32_t *wv;
  uint32_t *comp;       /* per vertex: its component's root (union-find) */
  unsigned char *outer; /* per walk: 1 when it is its component's outer walk */
  int32_t *face_of;     /* per walk: its face (-1: the unbounded one) */
  int32_t *loc;         /* per vertex: the face an isolated vertex or a component lies in */
  size_t nfaces;
  uint32_t *face_walk;  /* per face: its bounded walk */
} got_graph;

static void got_graph_free(got_graph *g) {
  free(g->off), free(g->adj), free(g->walk_of), free(g->woff), free(g->wv);
  free(g->comp), free(g->outer), free(g->face_of), free(g->loc), free(g->face_walk);
}

/* Which half of the directions around v holds a: 0 for angles in [0, pi), 1 for [pi,
** 2 pi).  Exact: it only compares coordinates. */
static int got_half(geom_point v, geom_point a) {
  return a.y < v.y || (a.y == v.y && a.x < v.x);
}

/* Is the direction v -> a strictly before v -> b, anticlockwise from (1, 0)? */
static int got_angle_less(geom_point v, geom_point a, geom_point b) {
  int ha = got_half(v, a), hb = got_half(v, b);
  if (ha != hb) return ha < hb;
  return geom_orient(v, a, b) > 0;
}

/* Sort each vertex's neighbours by angle: insertion sorts (degrees are small). */
static void got_graph_sort(got_graph *g) {
  for (size_t v = 0; v < g->n; v++) {
    uint32_t *a = g->adj + g->off[v];
    size_t d = g->off[v + 1] - g->off[v];
    for (size_t i = 1; i < d; i++) {
      uint32_t x = a[i];
      size_t j = i;
      for (; j > 0 && got_angle_less(g->p[v], g->p[x], g->p[a[j - 1]]); j--) a[j] = a[j - 1];
      a[j] = x;
    }
  }
}

static uint32_t got_find(uint32_t *c, uint32_t v) {
  while (c[v] != v) v = c[v] = c[c[v]];
  return v;
}

/* The certain edges' adjacency (both directions) and components. */
static int got_graph_adj(got_graph *g, const got_skel *s) {
  size_t n = g->n;
  g->off = calloc(n + 1, sizeof *g->off);
  g->comp = malloc(n * sizeof *g->comp);
  if (g->off == NULL || g->comp == NULL) return -1;
  for (size_t v = 0; v < n; v++) g->comp[v] = (uint32_t)v;
  for (size_t e = 0; e < s->nedges; e++)
    if (s->state[e] == GOT_EDGE_CERTAIN) {
      uint32_t a = s->edge[2 * e], b = s->edge[2 * e + 1];
      g->off[a + 1]++, g->off[b + 1]++;
      uint32_t ra = got_find(g->comp, a), rb = got_find(g->comp, b);
      if (ra != rb) g->comp[ra > rb ? ra : rb] = ra < rb ? ra : rb;
    }
  for (size_t v = 0; v < n; v++) g->off[v + 1] += g->off[v];
  g->adj = malloc((g->off[n] + 1) * sizeof *g->adj);
  size_t *fill = malloc((n + 1) * sizeof *fill);
  if (g->adj == NULL || fill == NULL) {
    free(fill);
    return -1;
  }
  memcpy(fill, g->off, n * sizeof *fill);
  for (size_t e = 0; e < s->nedges; e++)
    if (s->state[e] == GOT_EDGE_CERTAIN) {
      uint32_t a = s->edge[2 * e], b = s->edge[2 * e + 1];
      g->adj[fill[a]++] = b;
      g->adj[fill[b]++] = a;
    }
  free(fill);
  for (size_t v = 0; v < n; v++) g->comp[v] = got_find(g->comp, (uint32_t)v);
  got_graph_sort(g);
  return 0;
}

/* The position of w in v's neighbours (present by construction). */
static size_t got_graph_pos(const got_graph *g, uint32_t v, uint32_t w) {
  size_t h = g->off[v];
  while (g->adj[h] != w) h++;
  return h;
}

/* The half-edge after v -> w on the walk with its face on the left: w -> x, x the
** neighbour of w just before v in anticlockwise order. */
static size_t got_graph_next(const got_graph *g, uint32_t v, size_t h) {
  uint32_t w = g->adj[h];
  size_t t = got_graph_pos(g, w, v), d = g->off[w + 1] - g->off[w];
  return t == g->off[w] ? g->off[w] + d - 1 : t - 1;
}

/* The tail of half-edge h (a binary search over off). */
static uint32_t got_graph_tail(const got_graph *g, size_t h) {
  size_t lo = 0, hi = g->n;
  while (hi - lo > 1) {
    size_t mid = lo + (hi - lo) / 2;
    if (g->off[mid] <= h) lo = mid;
    else hi = mid;
  }
  return (uint32_t)lo;
}

/* Every closed walk, in half-edge order.  O(E log n). */
static int got_graph_walks(got_graph *g) {
  size_t H = g->off[g->n];
  g->walk_of = malloc((H + 1) * sizeof *g->walk_of);
  g->woff = malloc((H + 2) * sizeof *g->woff);
  g->wv = malloc((H + 1) * sizeof *g->wv);
  if (g->walk_of == NULL || g->woff == NULL || g->wv == NULL) return -1;
  for (size_t h = 0; h < H; h++) g->walk_of[h] = UINT32_MAX;
  size_t len = 0;
  g->nwalks = 0;
  for (size_t h0 = 0; h0 < H; h0++) {
    if (g->walk_of[h0] != UINT32_MAX) continue;
    g->woff[g->nwalks] = len;
    uint32_t v = got_graph_tail(g, h0);
    for (size_t h = h0; g->walk_of[h] == UINT32_MAX;) {
      g->walk_of[h] = (uint32_t)g->nwalks;
      g->wv[len++] = v;
      uint32_t w = g->adj[h];
      h = got_graph_next(g, v, h);
      v = w;
    }
    g->nwalks++;
  }
  g->woff[g->nwalks] = len;
  return 0;
}

/* Is q inside the closed walk w (winding number non-zero)?  q is on none of its edges
** (a vertex of another component).  Exact: geom_orient and coordinate comparisons. */
static int got_graph_inside(const got_graph *g, size_t w, geom_point q) {
  const geom_point *p = g->p;
  size_t a = g->woff[w], b = g->woff[w + 1];
  long wn = 0;
  for (size_t i = a; i < b; i++) {
    geom_point u = p[g->wv[i]], v = p[g->wv[i + 1 < b ? i + 1 : a]];
    if (u.y <= q.y) {
      if (v.y > q.y && geom_orient(u, v, q) > 0) wn++;
    } else if (v.y <= q.y && geom_orient(u, v, q) < 0) {
      wn--;
    }
  }
  return wn != 0;
}

/* Each component's outer walk: at its lexicographically smallest vertex m the outer
** face holds the direction (-1, 0), which lies anticlockwise after the last neighbour of
** m in the upper half (or the last of all).  minv[root]: that vertex.  Then the faces:
** every other walk, in walk order. */
static int got_graph_faces(got_graph *g, uint32_t *minv) {
  const geom_point *p = g->p;
  for (size_t v = 0; v < g->n; v++) minv[v] = UINT32_MAX;
  for (size_t v = 0; v < g->n; v++) {
    uint32_t c = g->comp[v], m = minv[c];
    if (m == UINT32_MAX || p[v].x < p[m].x || (p[v].x == p[m].x && p[v].y < p[m].y))
      minv[c] = (uint32_t)v;
  }
  g->outer = calloc(g->nwalks + 1, 1);
  g->face_of = malloc((g->nwalks + 1) * sizeof *g->face_of);
  g->face_walk = malloc((g->nwalks + 1) * sizeof *g->face_walk);
  g->loc = malloc(g->n * sizeof *g->loc);
  if (!g->outer || !g->face_of || !g->face_walk || !g->loc) return -1;
  for (size_t v = 0; v < g->n; v++) {
    g->loc[v] = -1;
    if (g->comp[v] != v || g->off[v + 1] == g->off[v]) continue;
    uint32_t m = minv[v];
    size_t h = g->off[m + 1] - 1;
    for (size_t k = g->off[m]; k < g->off[m + 1]; k++)
      if (!got_half(p[m], p[g->adj[k]])) h = k;
    g->outer[g->walk_of[h]] = 1;
  }
  g->nfaces = 0;
  for (size_t w = 0; w < g->nwalks; w++) {
    g->face_of[w] = g->outer[w] ? -1 : (int32_t)g->nfaces;
    if (!g->outer[w]) g->face_walk[g->nfaces++] = (uint32_t)w;
  }
  return 0;
}

/* A uniform grid of the bounded walks' boxes, for point location. */
typedef struct got_grid {
  double x0, y0, sx, sy;
  size_t G;
  size_t *off;          /* G * G + 1 */
  uint32_t *face;
} got_grid;

static size_t got_grid_cell(double v, double v0, double s, size_t G) {
  double c = floor((v - v0) * s);
  return c <= 0 ? 0 : c >= (double)(G - 1) ? G - 1 : (size_t)c;
}

/* The box of face f's walk into cells [cx0, cx1] x [cy0, cy1]. */
static void got_grid_box(const got_graph *g, const got_grid *gr, size_t f, size_t c[4]) {
  size_t w = g->face_walk[f];
  double bx0 = INFINITY, bx1 = -INFINITY, by0 = INFINITY, by1 = -INFINITY;
  for (size_t i = g->woff[w]; i < g->woff[w + 1]; i++) {
    geom_point q = g->p[g->wv[i]];
    bx0 = fmin(bx0, q.x), bx1 = fmax(bx1, q.x), by0 = fmin(by0, q.y), by1 = fmax(by1, q.y);
  }
  c[0] = got_grid_cell(bx0, gr->x0, gr->sx, gr->G);
  c[1] = got_grid_cell(bx1, gr->x0, gr->sx, gr->G);
  c[2] = got_grid_cell(by0, gr->y0, gr->sy, gr->G);
  c[3] = got_grid_cell(by1, gr->y0, gr->sy, gr->G);
}

/* Register every face in the cells its box meets (two passes: count, fill). */
static int got_grid_make(const got_graph *g, got_grid *gr) {
  double x1 = -INFINITY, y1 = -INFINITY;
  gr->x0 = gr->y0 = INFINITY;
  for (size_t v = 0; v < g->n; v++) {
    gr->x0 = fmin(gr->x0, g->p[v].x), x1 = fmax(x1, g->p[v].x);
    gr->y0 = fmin(gr->y0, g->p[v].y), y1 = fmax(y1, g->p[v].y);
  }
  gr->G = 1;
  while (gr->G < 2048 && gr->G * gr->G < g->nfaces) gr->G *= 2;
  gr->sx = x1 > gr->x0 ? (double)gr->G / (x1 - gr->x0) : 0;
  gr->sy = y1 > gr->y0 ? (double)gr->G / (y1 - gr->y0) : 0;
  gr->off = calloc(gr->G * gr->G + 1, sizeof *gr->off);
  if (gr->off == NULL) return -1;
  for (int pass = 0; pass < 2; pass++) {
    for (size_t f = 0; f < g->nfaces; f++) {
      size_t c[4];
      got_grid_box(g, gr, f, c);
      for (size_t cy = c[2]; cy <= c[3]; cy++)
        for (size_t cx = c[0]; cx <= c[1]; cx++) {
          size_t k = cy * gr->G + cx;
          if (pass == 0) gr->off[k + 1]++;
          else gr->face[gr->off[k]++] = (uint32_t)f;
        }
    }
    if (pass == 0) {
      for (size_t k = 0; k < gr->G * gr->G; k++) gr->off[k + 1] += gr->off[k];
      gr->face = malloc((gr->off[gr->G * gr->G] + 1) * sizeof *gr->face);
      if (gr->face == NULL) return -1;
    }
  }
  for (size_t k = gr->G * gr->G; k > 0; k--) gr->off[k] = gr->off[k - 1];
  gr->off[0] = 0;
  return 0;
}

/* The innermost bounded walk of another component around q (vertex v): a face holding
** q that lies inside the best so far replaces it.  -1 when none (cannot happen for a
** point inside the hull). */
static int32_t got_grid_locate(const got_graph *g, const got_grid *gr, const uint32_t *minv,
                               uint32_t v) {
  geom_point q = g->p[v];
  size_t k = got_grid_cell(q.y, gr->y0, gr->sy, gr->G) * gr->G +
             got_grid_cell(q.x, gr->x0, gr->sx, gr->G);
  int32_t best = -1;
  for (size_t i = gr->off[k]; i < gr->off[k + 1]; i++) {
    uint32_t f = gr->face[i], w = g->face_walk[f];
    if (g->comp[g->wv[g->woff[w]]] == g->comp[v] || !got_graph_inside(g, w, q)) continue;
    uint32_t rep = minv[g->comp[g->wv[g->woff[w]]]];
    if (best < 0 || got_graph_inside(g, g->face_walk[best], g->p[rep])) best = (int32_t)f;
  }
  return best;
}

/* Locate every component but the hull's (through its smallest vertex) and every isolated
** point; the outer walks of those components become holes of their faces. */
static int got_graph_locate(got_graph *g, const uint32_t *minv, uint32_t hull) {
  got_grid gr = {0};
  int need = 0;
  for (size_t v = 0; v < g->n && !need; v++) need = g->comp[v] == v && v != hull;
  if (need && got_grid_make(g, &gr) != 0) {
    free(gr.off), free(gr.face);
    return -1;
  }
  for (size_t v = 0; v < g->n; v++)
    if (g->comp[v] == v && v != hull) g->loc[v] = got_grid_locate(g, &gr, minv, minv[v]);
  for (size_t w = 0; w < g->nwalks; w++)
    if (g->outer[w] && g->comp[g->wv[g->woff[w]]] != hull)
      g->face_of[w] = g->loc[g->comp[g->wv[g->woff[w]]]];
  free(gr.off), free(gr.face);
  return 0;
}

/* The face of the wedge at v that holds the direction v -> t: the walk of v -> w, w the
** last neighbour not after t anticlockwise (the last of all when none).  -2 when t lies
** on a certain edge's ray (the edge v t is that certain edge). */
static int32_t got_graph_face_at(const got_graph *g, uint32_t v, uint32_t t) {
  const geom_point *p = g->p;
  size_t a = g->off[v], b = g->off[v + 1], h = b - 1;
  if (a == b) return g->loc[v];
  for (size_t k = a; k < b; k++)
    if (!got_angle_less(p[v], p[t], p[g->adj[k]])) h = k;
  uint32_t w = g->adj[h];
  if (got_half(p[v], p[w]) == got_half(p[v], p[t]) && geom_orient(p[v], p[w], p[t]) == 0)
    return -2;
  return g->face_of[g->walk_of[h]];
}

/* What each face holds besides its walk: holes (walks), isolated points, POSSIBLE edges;
** each a CSR by face; tri_off: where each face's triangles go (Euler: the walks' lengths
** plus twice the inner points and the holes, minus 2). */
typedef struct got_faces {
  size_t *hoff, *ioff, *eoff, *tri_off;
  uint32_t *hole, *inner, *edge;
} got_faces;

static void got_faces_free(got_faces *fc) {
  free(fc->hoff), free(fc->ioff), free(fc->eoff), free(fc->tri_off);
  free(fc->hole), free(fc->inner), free(fc->edge);
}

/* The face of item i for the three kinds (0 holes, 1 inner points, 2 edges); -1 none. */
static int32_t got_faces_of(const got_graph *g, const got_skel *s, int kind, size_t i) {
  if (kind == 0)
    return g->outer[i] && g->face_of[i] >= 0 ? g->face_of[i] : -1;
  if (kind == 1)
    return g->off[i] == g->off[i + 1] ? g->loc[i] : -1;
  if (s->state[i] == GOT_EDGE_CERTAIN) return -1;
  uint32_t a = s->edge[2 * i], b = s->edge[2 * i + 1];
  int32_t fa = got_graph_face_at(g, a, b), fb = got_graph_face_at(g, b, a);
  return fa == fb ? fa : -1;    /* ends in different faces: it crosses a certain edge */
}

/* One CSR: off[F + 1], items (per = 1 index, or 2 for edges). */
static int got_faces_csr(const got_graph *g, const got_skel *s, int kind, size_t **off,
                         uint32_t **item) {
  size_t F = g->nfaces, m = kind == 0 ? g->nwalks : kind == 1 ? g->n : s->nedges;
  size_t per = kind == 2 ? 2 : 1;
  *off = calloc(F + 2, sizeof **off);
  if (*off == NULL) return -1;
  for (size_t i = 0; i < m; i++) {
    int32_t f = got_faces_of(g, s, kind, i);
    if (f >= 0) (*off)[f + 2]++;
  }
  for (size_t f = 0; f < F; f++) (*off)[f + 2] += (*off)[f + 1];
  *item = malloc((per * (*off)[F + 1] + 1) * sizeof **item);
  if (*item == NULL) return -1;
  for (size_t i = 0; i < m; i++) {
    int32_t f = got_faces_of(g, s, kind, i);
    if (f < 0) continue;
    size_t at = (*off)[f + 1]++;
    if (kind == 2) (*item)[2 * at] = s->edge[2 * i], (*item)[2 * at + 1] = s->edge[2 * i + 1];
    else (*item)[at] = (uint32_t)i;
  }
  return 0;
}

static size_t got_walk_len(const got_graph *g, size_t w) {
  return g->woff[w + 1] - g->woff[w];
}

static int got_faces_make(const got_graph *g, const got_skel *s, got_faces *fc) {
  if (got_faces_csr(g, s, 0, &fc->hoff, &fc->hole) != 0 ||
      got_faces_csr(g, s, 1, &fc->ioff, &fc->inner) != 0 ||
      got_faces_csr(g, s, 2, &fc->eoff, &fc->edge) != 0)
    return -1;
  fc->tri_off = malloc((g->nfaces + 1) * sizeof *fc->tri_off);
  if (fc->tri_off == NULL) return -1;
  fc->tri_off[0] = 0;
  for (size_t f = 0; f < g->nfaces; f++) {
    size_t t = got_walk_len(g, g->face_walk[f]);
    for (size_t k = fc->hoff[f]; k < fc->hoff[f + 1]; k++) t += got_walk_len(g, fc->hole[k]) + 2;
    t += 2 * (fc->ioff[f + 1] - fc->ioff[f]);
    fc->tri_off[f + 1] = fc->tri_off[f] + t - 2;
  }
  return 0;
}

/* Points of face f: its walks' vertices (with repeats) and its inner points. */
static size_t got_face_size(const got_graph *g, const got_faces *fc, size_t f) {
  size_t t = got_walk_len(g, g->face_walk[f]) + fc->ioff[f + 1] - fc->ioff[f];
  for (size_t k = fc->hoff[f]; k < fc->hoff[f + 1]; k++) t += got_walk_len(g, fc->hole[k]);
  return t;
}

/* An empty face bounded by one walk without a repeated vertex: a simple polygon. */
static int got_face_is_polygon(const got_graph *g, const got_faces *fc, size_t f,
                               uint32_t *stamp) {
  if (fc->hoff[f + 1] != fc->hoff[f] || fc->ioff[f + 1] != fc->ioff[f]) return 0;
  size_t w = g->face_walk[f];
  int simple = 1;
  for (size_t i = g->woff[w]; i < g->woff[w + 1]; i++) {
    simple &= stamp[g->wv[i]] != (uint32_t)f + 1;
    stamp[g->wv[i]] = (uint32_t)f + 1;
  }
  return simple;
}

/* ---- solving the faces ---- */

/* One face's answer (got_face_out's certificate, got_result's for polygons). */
typedef struct got_face_res {
  double key, key2, err, err2;
  int has2, unique;
  const char *why;
  size_t states;
} got_face_res;

/* A triangle of point indices, ascending, with its badness. */
static got_triangle got_points_tri(const geom_point *p, const rule *r, uint32_t a, uint32_t b,
                                   uint32_t c, double badness) {
  uint32_t t;
  if (a > b) t = a, a = b, b = t;
  if (b > c) t = b, b = c, c = t;
  if (a > b) t = a, a = b, b = t;
  if (isnan(badness)) {
    geom_tri tr;
    geom_tri_make(&tr, p[a], p[b], p[c]);
    badness = measure_eval(rule_measure(r), &tr);
  }
  return (got_triangle){(int)a, (int)b, (int)c, badness};
}

/* An empty simple face: got_solve on its walk (anticlockwise), triangles mapped back. */
static int got_face_polygon(const got_graph *g, size_t f, const rule *r, const got_options *o,
                            got_face_res *fr, got_triangle *tri, char *err, size_t errlen) {
  size_t w = g->face_walk[f], L = got_walk_len(g, w);
  const uint32_t *v = g->wv + g->woff[w];
  geom_point *poly = malloc(L * sizeof *poly);
  got_result res;
  if (poly == NULL) return got_points_err(err, errlen, "out of memory");
  for (size_t i = 0; i < L; i++) poly[i] = g->p[v[i]];
  int rc = got_solve(poly, L, r, o, &res, err, errlen);
  free(poly);
  if (rc != 0) return -1;
  for (size_t q = 0; q < res.ntri; q++)
    tri[q] = got_points_tri(g->p, r, v[res.tri[q].i], v[res.tri[q].k], v[res.tri[q].j],
                            res.tri[q].badness);
  *fr = (got_face_res){res.key, res.key2, res.cert_err, res.cert_err2, res.has_runner_up,
                       res.cert_unique, res.cert_why, 0};
  got_result_free(&res);
  return 0;
}

/* Any other face: its walks (the bounded one first, then the holes), inner points and
** POSSIBLE edges to got_face_solve. */
static int got_face_general(const got_graph *g, const got_faces *fc, size_t f, const rule *r,
                            got_face_res *fr, got_triangle *tri, size_t ntri, char *err,
                            size_t errlen) {
  size_t nw = 1 + fc->hoff[f + 1] - fc->hoff[f], total = 0;
  size_t *len = malloc(nw * sizeof *len);
  uint32_t *walk = malloc((got_face_size(g, fc, f) + 1) * sizeof *walk);
  got_face_out out = {0};
  int rc = len && walk ? 0 : got_points_err(err, errlen, "out of memory");
  for (size_t k = 0; rc == 0 && k < nw; k++) {
    size_t w = k == 0 ? g->face_walk[f] : fc->hole[fc->hoff[f] + k - 1];
    len[k] = got_walk_len(g, w);
    memcpy(walk + total, g->wv + g->woff[w], len[k] * sizeof *walk);
    total += len[k];
  }
  got_face_in in = {g->p, nw, len, walk, fc->inner + fc->ioff[f], fc->ioff[f + 1] - fc->ioff[f],
                    fc->edge + 2 * fc->eoff[f], fc->eoff[f + 1] - fc->eoff[f]};
  if (rc == 0) rc = got_face_solve(&in, r, &out, err, errlen);
  if (rc == 0 && out.ntri != ntri) {
    snprintf(err, errlen, "internal error: face %zu has %zu triangles, Euler's relation says "
             "%zu", f, out.ntri, ntri);
    rc = -1;
  }
  for (size_t q = 0; rc == 0 && q < ntri; q++)
    tri[q] = got_points_tri(g->p, r, out.tri[3 * q], out.tri[3 * q + 1], out.tri[3 * q + 2],
                            NAN);
  if (rc == 0)
    *fr = (got_face_res){out.key, out.key2, out.err, out.err2, out.has_runner_up, out.unique,
                         out.unique || isfinite(out.err + out.err2) ? NULL
                         : "no forward error bound for this face", out.states};
  got_face_out_free(&out);
  free(len);
  free(walk);
  return rc;
}

/* The faces' solver state shared by the threads. */
typedef struct got_solver {
  const got_graph *g;
  const got_faces *fc;
  const rule *r;
  const unsigned char *polygon;   /* per face: an empty simple polygon */
  got_face_res *res;
  got_triangle *tri;
  double tie_eps;
  long long fail;                 /* the first face that failed, or -1 */
  char *err;
  size_t errlen;
} got_solver;

static void got_solver_face(got_solver *S, size_t f, int threads) {
  char e[512];
  got_options o = {threads, S->tie_eps};
  size_t t0 = S->fc->tri_off[f], nt = S->fc->tri_off[f + 1] - t0;
  int rc = S->polygon[f]
               ? got_face_polygon(S->g, f, S->r, &o, &S->res[f], S->tri + t0, e, sizeof e)
               : got_face_general(S->g, S->fc, f, S->r, &S->res[f], S->tri + t0, nt, e,
                                  sizeof e);
  if (rc == 0) return;
#pragma omp critical(got_points_fail)
  if (S->fail < 0 || (long long)f < S->fail) {
    S->fail = (long long)f;
    snprintf(S->err, S->errlen, "%s", e);
  }
}

/* Big faces one by one with every thread, then the others in parallel. */
static void got_solver_run(got_solver *S, int threads) {
  size_t F = S->g->nfaces;
  for (size_t f = 0; f < F; f++)
    if (got_face_size(S->g, S->fc, f) >= GOT_POINTS_BIG) got_solver_face(S, f, threads);
  long long nf = (long long)F;
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads)
  for (long long f = 0; f < nf; f++)
    if (got_face_size(S->g, S->fc, (size_t)f) < GOT_POINTS_BIG)
      got_solver_face(S, (size_t)f, 1);
}

/* ---- the answer ---- */

/* The face closest to a tie (least certified margin; an uncertified face first) into
** res's certificate, and the runner-up: the optimum with the one face changed whose
** runner-up costs least.  The total's bound: the faces' bounds plus the rounding of
** their sum (Higham's gamma_{F-1} times the sum of |keys|, as got_cert.c). */
static void got_points_certify(got_result *out, const got_solver *S, size_t F) {
  double key = 0, err = 0, sabs = 0, d2 = INFINITY, margin = INFINITY;
  long long best = -1, worst = -1;
  int all = 1;
  for (size_t f = 0; f < F; f++) {
    const got_face_res *fr = &S->res[f];
    key += fr->key, err += fr->err, sabs += fabs(fr->key);
    out->face_states += fr->states;
    if (!fr->has2) continue;
    double d = fr->key2 - fr->key, m = fr->unique ? d - (fr->err + fr->err2) : -INFINITY;
    if (best < 0 || d < d2) best = (long long)f, d2 = d;
    if (worst < 0 || m < margin) worst = (long long)f, margin = m;
    all &= fr->unique;
  }
  double gam = (double)F * 0x1p-53 / (1 - (double)F * 0x1p-53);
  out->key = key;
  out->cert_err = (err + gam * sabs) * (1 + 0x1p-40);
  out->cert_unique = all;
  out->has_runner_up = best >= 0;
  out->key2 = best >= 0 ? key + d2 : INFINITY;
  out->cert_gap = out->cert_bound = out->cert_err2 = INFINITY;
  if (worst >= 0) {
    const got_face_res *fw = &S->res[worst];
    out->cert_gap = fw->key2 - fw->key;
    out->cert_bound = fw->err + fw->err2;
    out->cert_err2 = fw->err2;
    out->cert_why = all ? NULL : fw->why;
  }
}

static int got_tri_cmp(const void *a, const void *b) {
  const got_triangle *u = a, *v = b;
  if (u->i != v->i) return u->i < v->i ? -1 : 1;
  if (u->k != v->k) return u->k < v->k ? -1 : 1;
  return (u->j > v->j) - (u->j < v->j);
}

/* A triangle's vertex i, got_tri_cmp's first key (below n): its bucket. */
static uint32_t got_tri_first(const void *x) {
  return (uint32_t)((const got_triangle *)x)->i;
}

/* Totals, gaps and the triangles (sorted) into out. */
static void got_points_fill(got_result *out, got_solver *S, size_t F, const rule *r) {
  got_points_certify(out, S, F);
  out->measure = rule_measure(r);
  out->joint = rule_joint(r);
  out->sign = rule_sign(r);
  out->total = rule_unkey(r, out->key);
  out->tie_eps = S->tie_eps;
  out->cert_rho = out->cert_alpha = NAN;
  if (out->has_runner_up) {
    out->total2 = rule_unkey(r, out->key2);
    out->gap = out->total2 - out->total;
    out->rel_gap = rule_gap(r, out->key, out->key2);
    out->unique = !(out->rel_gap <= out->tie_eps);
  } else {
    out->total2 = out->gap = out->rel_gap = INFINITY;
    out->unique = 1;
  }
  out->ntri = S->fc->tri_off[F];
  out->tri = S->tri;
  S->tri = NULL;
  /* O(n + triangles) by geom_bucket_sort: qsort was a serial second at 10^6 points */
  if (geom_bucket_sort(out->tri, out->ntri, sizeof *out->tri, (uint32_t)(S->g->n - 1),
                       got_tri_first, got_tri_cmp) != 0)
    qsort(out->tri, out->ntri, sizeof *out->tri, got_tri_cmp);
}

/* The skeleton that runs: DELAUNAY for AUTO when a theorem makes the rule's GOT Delaunay
** (rule_got_cdt_theorem: an observation is no ground for a certified answer) and a
** triangulation is given, LMT for AUTO otherwise; -1 with err for DELAUNAY where it does not
** apply. */
#define GOT_DT_RULES "R_1, R_2, R_0, R_-1, -r_1, abc_1"   /* rule_got_cdt_theorem's */

static int got_points_which(got_skeleton sk, const rule *r, const uint32_t *dt, char *err,
                            size_t errlen) {
  int cdt = rule_got_cdt_theorem(r) > 0;
  if (sk == GOT_SKELETON_AUTO) return cdt && dt != NULL ? GOT_SKELETON_DELAUNAY : GOT_SKELETON_LMT;
  if (sk != GOT_SKELETON_DELAUNAY || (cdt && dt != NULL)) return (int)sk;
  if (rule_got_is_cdt(r) && !cdt)
    snprintf(err, errlen, "skeleton delaunay: that rule %s's GOT is Delaunay is observed on "
             "samples (table 3.4), not proven, so it cannot certify (the skeleton applies to "
             GOT_DT_RULES ")", rule_name(r));
  else if (!cdt)
    snprintf(err, errlen, "skeleton delaunay: rule %s's GOT need not be a Delaunay "
             "triangulation (it applies to " GOT_DT_RULES ")", rule_name(r));
  else
    snprintf(err, errlen, "skeleton delaunay: no Delaunay triangulation was given");
  return -1;
}

/* The skeleton asked for (got_points_which's). */
static int got_points_skeleton(const geom_point *p, size_t n, const rule *r, int threads,
                               got_skeleton sk, const uint32_t *dt, size_t ndt, got_skel *s,
                               char *err, size_t errlen) {
  switch (sk) {
    case GOT_SKELETON_ALL: return got_skel_all(p, n, s, err, errlen);
    case GOT_SKELETON_DELAUNAY: return got_skel_delaunay(p, n, dt, ndt, s, err, errlen);
    case GOT_SKELETON_AUTO:
    case GOT_SKELETON_LMT: break;
  }
  return got_skel_build(p, n, r, threads, s, err, errlen);
}

/* The planar graph of the certain edges, its faces and what each holds. */
static int got_points_faces(got_graph *g, const got_skel *s, got_faces *fc) {
  uint32_t *minv = malloc(g->n * sizeof *minv);
  int rc = minv != NULL && got_graph_adj(g, s) == 0 && got_graph_walks(g) == 0 &&
           got_graph_faces(g, minv) == 0 ? 0 : -1;
  uint32_t hull = 0;
  for (size_t v = 1; rc == 0 && v < g->n; v++)
    if (g->p[v].x < g->p[hull].x || (g->p[v].x == g->p[hull].x && g->p[v].y < g->p[hull].y))
      hull = (uint32_t)v;
  if (rc == 0) rc = got_graph_locate(g, minv, g->comp[hull]);
  if (rc == 0) rc = got_faces_make(g, s, fc);
  free(minv);
  return rc;
}

/* Statistics of the skeleton and the faces. */
static void got_points_stats(got_result *out, const got_skel *s, const got_graph *g,
                             const got_faces *fc, const unsigned char *polygon) {
  out->candidates = s->candidates;
  out->edges = s->nedges;
  out->rounds = s->rounds;
  for (size_t e = 0; e < s->nedges; e++) out->certain += s->state[e] == GOT_EDGE_CERTAIN;
  out->faces = g->nfaces;
  for (size_t f = 0; f < g->nfaces; f++) {
    size_t z = got_face_size(g, fc, f);
    out->faces_left += z > 3;
    out->faces_general += !polygon[f];
    if (z > out->largest_face) out->largest_face = z;
  }
  out->seconds_candidates = s->seconds_candidates;
  out->seconds_lmt = s->seconds_lmt;
}

/* Faces, then each solved, then the answer; 0 or -1 with err. */
static int got_points_run(const geom_point *p, size_t n, const rule *r, int threads,
                          double tie_eps, const got_skel *s, got_result *out, char *err,
                          size_t errlen) {
  double t0 = omp_get_wtime();
  got_graph g = {.p = p, .n = n};
  got_faces fc = {0};
  got_solver S = {&g, &fc, r, NULL, NULL, NULL, tie_eps, -1, err, errlen};
  unsigned char *polygon = NULL;
  uint32_t *stamp = calloc(n, sizeof *stamp);
  int rc = stamp && got_points_faces(&g, s, &fc) == 0 ? 0 : -1;
  if (rc == 0) {
    polygon = malloc(g.nfaces + 1);
    S.res = calloc(g.nfaces + 1, sizeof *S.res);
    S.tri = malloc((fc.tri_off[g.nfaces] + 1) * sizeof *S.tri);
    rc = polygon && S.res && S.tri ? 0 : -1;
  }
  if (rc != 0) got_points_err(err, errlen, "out of memory for the faces");
  for (size_t f = 0; rc == 0 && f < g.nfaces; f++)
    polygon[f] = (unsigned char)got_face_is_polygon(&g, &fc, f, stamp);
  S.polygon = polygon;
  out->seconds_faces = omp_get_wtime() - t0;
  if (rc == 0) {
    got_points_stats(out, s, &g, &fc, polygon);
    got_solver_run(&S, threads);
    rc = S.fail >= 0 ? -1 : 0;
  }
  if (rc == 0) got_points_fill(out, &S, g.nfaces, r);
  out->seconds_solve = omp_get_wtime() - t0 - out->seconds_faces;
  got_graph_free(&g);
  got_faces_free(&fc);
  free(stamp), free(polygon), free(S.res), free(S.tri);
  return rc;
}

int got_points_solve(const geom_point *p, size_t n, const rule *r, const got_options *opt,
                     got_skeleton skeleton, got_result *out, char *err, size_t errlen) {
  return got_points_solve_dt(p, n, r, opt, skeleton, NULL, 0, out, err, errlen);
}

int got_points_solve_dt(const geom_point *p, size_t n, const rule *r, const got_options *opt,
                        got_skeleton skeleton, const uint32_t *dt, size_t ndt, got_result *out,
                        char *err, size_t errlen) {
  memset(out, 0, sizeof *out);
  if (got_points_check(p, n, r, err, errlen) != 0) return -1;
  return got_points_solve_checked(p, n, r, opt, skeleton, dt, ndt, out, err, errlen);
}

int got_points_solve_checked(const geom_point *p, size_t n, const rule *r,
                             const got_options *opt, got_skeleton skeleton, const uint32_t *dt,
                             size_t ndt, got_result *out, char *err, size_t errlen) {
  memset(out, 0, sizeof *out);
  if (opt != NULL && geom_threads_check(opt->threads, err, errlen) != 0) return -1;
  if ((unsigned)skeleton >= GOT_NSKELETONS)
    return got_points_err(err, errlen, "skeleton: expected auto, all, lmt or delaunay");
  if (got_points_check_memory(n, err, errlen) != 0) return -1;
  int sk = got_points_which(skeleton, r, dt, err, errlen);
  if (sk < 0) return -1;
  int threads = geom_threads_clamp(opt ? opt->threads : 0, omp_get_max_threads());
  double t0 = omp_get_wtime();
  got_skel s;
  if (got_points_skeleton(p, n, r, threads, (got_skeleton)sk, dt, ndt, &s, err, errlen) != 0) {
    got_skel_free(&s);
    return -1;
  }
  int rc = got_points_run(p, n, r, threads, opt ? opt->tie_eps : RULE_DEFAULT_TIE_EPS, &s,
                          out, err, errlen);
  got_skel_free(&s);
  /* the error model of keys summed from measure_eval (a LOT's total, say): got_cert_err_of */
  const char *why;
  if (rc == 0 && got_cert_model(p, n, r, &out->cert_rho, &out->cert_alpha, &why) != 0)
    out->cert_rho = out->cert_alpha = NAN;
  out->n = n;
  out->points = 1;
  out->skeleton = sk;
  out->threads = threads;
  out->seconds = omp_get_wtime() - t0;
  if (rc != 0) got_result_free(out);
  return rc;
}
