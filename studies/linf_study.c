/*
** linf_study.c: the thesis's section 4.2 examples on l_inf circumcubes,
** every claim computed exactly: are the cells a triangulation, are they
** locally and globally Delaunay, which simplices are Delaunay, and which
** triangulations of the points are locally or globally Delaunay.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "study_linf.h"

static const double study_linf_3d[] = {6, 6, 2, 10, 4, 8, 0, 2, 6, 2, 12, 0, 4, 8, 10, 8, 0, 4};
static const char *const study_linf_3d_cells[] = {"ACEF", "ACDE", "ABEF", "BCEF", "BCDF",
                                                  NULL};
static const double study_linf_pseudo[] = {1, 1, 7, 5, 3, 0, 3, 5, 8, 8, 6, 1};
static const char *const study_linf_pseudo_cells[] = {"ABCD", NULL};
static const double study_linf_r5[] = {0, 1, 1, 1, 1, 4, 1, 1, 1, 1, 1, 0, 0, 1, 1,
                                       1, 2, 2, 1, 1, 1, 1, 1, 0, 0, 1, 1, 1, 2, 2};
static const char *const study_linf_r5_cells[] = {"ABCDEF", NULL};
/* Found by a search of random integer sets: facet DEF borders three
** Delaunay tetrahedra, two of them on one side. */
static const double study_linf_facet3[] = {5, 11, 12, 11, 4, 5, 0, 11, 0,
                                           8, 1,  7,  9,  10, 6, 4, 8, 11};
static const char *const study_linf_facet3_cells[] = {NULL};

const study_linf_example study_linf_examples[STUDY_LINF_EXAMPLES] = {
  {"3d", "section 4.2.1: locally Delaunay but not Delaunay", 3, 6, "ABCDEF", study_linf_3d,
   study_linf_3d_cells},
  {"pseudo", "section 4.2.1: a pseudo-degenerate tetrahedron", 3, 4, "ABCD", study_linf_pseudo,
   study_linf_pseudo_cells},
  {"r5", "theorem 14: the bound attained in R^5", 5, 6, "ABCDEF", study_linf_r5,
   study_linf_r5_cells},
  {"facet", "section 4.2.1: a facet of three Delaunay tetrahedra", 3, 6, "ABCDEF",
   study_linf_facet3, study_linf_facet3_cells},
};

const study_linf_example *study_linf_example_find(const char *s) {
  for (int i = 0; i < STUDY_LINF_EXAMPLES; i++)
    if (strcmp(s, study_linf_examples[i].name) == 0) return &study_linf_examples[i];
  return NULL;
}

/* A facet of a pool simplex: its key (linf_row_key), the simplex, the
** side its far vertex lies on (the orientation of the facet, in increasing
** order, then that vertex) and whether it is a facet of the hull. */
struct study_linf_facet {
  uint64_t key;
  size_t cell;
  int side, hull;
};
typedef struct study_linf_facet study_linf_facet;

static int study_linf_facet_cmp(const void *a, const void *b) {
  const study_linf_facet *x = a, *y = b;
  if (x->key != y->key) return (x->key > y->key) - (x->key < y->key);
  return (x->cell > y->cell) - (x->cell < y->cell);
}

static void study_linf_rows(const study_linf_example *ex, const unsigned char *v, int m,
                            double *rows) {
  for (int j = 0; j < m; j++)
    memcpy(rows + j * ex->d, ex->pts + (size_t)v[j] * ex->d, ex->d * sizeof *rows);
}

/* The d + 1 facets of pool simplex c into f. */
static void study_linf_facets(const study_linf_example *ex, const study_linf_cell *x, size_t c,
                              study_linf_facet *f) {
  int d = ex->d;
  double rows[(LINF_DIM_MAX + 1) * LINF_DIM_MAX];
  for (int drop = 0; drop <= d; drop++) {
    unsigned char g[LINF_DIM_MAX + 1];
    for (int i = 0, w = 0; i <= d; i++)
      if (i != drop) g[w++] = x->v[i];
    g[d] = x->v[drop];
    study_linf_rows(ex, g, d + 1, rows);
    f[drop] = (study_linf_facet){linf_row_key(g, d), c, linf_orient(rows, d),
                                 linf_hull_facet(ex->pts, ex->n, d, g)};
  }
}

void study_linf_key_name(const study_linf_example *ex, uint64_t key, int m, char *name) {
  for (int i = m - 1; i >= 0; i--, key >>= 6) name[i] = ex->labels[key & 63];
  name[m] = 0;
}

static uint64_t study_linf_vmask(const study_linf_cell *x, int d) {
  uint64_t m = 0;
  for (int j = 0; j <= d; j++) m |= (uint64_t)1 << x->v[j];
  return m;
}

/* O(k d log(k d)) for k simplices in the set. */
int study_linf_triangulates(const study_linf_report *r, uint64_t set, char *why, size_t len) {
  const study_linf_facet *all = r->facets;
  study_linf_facet f[64 * (LINF_DIM_MAX + 1)];
  size_t m = 0, w = (size_t)r->ex->d + 1;
  for (size_t c = 0; c < r->npool; c++)
    if (set >> c & 1) memcpy(f + m, all + c * w, w * sizeof *f), m += w;
  if (m == 0) return why ? (snprintf(why, len, "no simplices"), 0) : 0;
  uint64_t used = 0;
  for (size_t c = 0; c < r->npool; c++)
    if (set >> c & 1) {
      if (r->pool[c].flat) return why ? (snprintf(why, len, "a simplex is flat"), 0) : 0;
      used |= study_linf_vmask(&r->pool[c], r->ex->d);
    }
  if (used != ((uint64_t)1 << r->ex->n) - 1)
    return why ? (snprintf(why, len, "a point is no vertex"), 0) : 0;
  qsort(f, m, sizeof *f, study_linf_facet_cmp);
  for (size_t a = 0, b; a < m; a = b) {
    for (b = a + 1; b < m && f[b].key == f[a].key; b++) continue;
    if ((b - a == 1 && f[a].hull) || (b - a == 2 && f[a].side * f[a + 1].side < 0)) continue;
    if (why == NULL) return 0;
    char name[LINF_DIM_MAX + 2];
    study_linf_key_name(r->ex, f[a].key, r->ex->d, name);
    if (b - a == 1) snprintf(why, len, "facet %s is inside the hull, a simplex on one side", name);
    else if (b - a == 2) snprintf(why, len, "the two simplices on facet %s overlap", name);
    else snprintf(why, len, "facet %s belongs to %zu simplices", name, b - a);
    return 0;
  }
  return 1;
}

/* Which cubes of pool simplex c have none of the points of mask strictly
** inside (flags into clear); how many. */
static int study_linf_clear(const study_linf_report *r, size_t c, uint64_t mask,
                            unsigned char *clear) {
  const study_linf_cell *x = &r->pool[c];
  int k = 0;
  for (int b = 0; b < x->ncubes; b++) {
    size_t q = 0;
    for (; q < r->ex->n; q++)
      if ((mask >> q & 1) && linf_cube_side(&x->cube[b], r->ex->pts + q * r->ex->d) == -1) break;
    clear[b] = q == r->ex->n;
    k += clear[b];
  }
  return k;
}

int study_linf_locally(study_linf_report *r, uint64_t set) {
  int ok = 1, d = r->ex->d;
  for (size_t c = 0; c < r->npool; c++) {
    if (!(set >> c & 1)) continue;
    uint64_t mine = study_linf_vmask(&r->pool[c], d), far = 0;
    for (size_t o = 0; o < r->npool; o++) {
      uint64_t off = study_linf_vmask(&r->pool[o], d) & ~mine;
      if ((set >> o & 1) && o != c && off != 0 && (off & (off - 1)) == 0) far |= off;
    }
    r->pool[c].nlocal = study_linf_clear(r, c, far, r->pool[c].local);
    ok &= r->pool[c].nlocal > 0;
  }
  return ok;
}

/* Every (d+1)-subset with its circumcubes and its facets.
** 0, or -1 (memory, or more than 64 of them). */
static int study_linf_pool(study_linf_report *r) {
  study_linf_facet **facets = &r->facets;
  const study_linf_example *ex = r->ex;
  int d = ex->d;
  unsigned char c[LINF_DIM_MAX + 1];
  double rows[(LINF_DIM_MAX + 1) * LINF_DIM_MAX];
  r->pool = malloc(64 * sizeof *r->pool);
  *facets = malloc(64 * (size_t)(d + 1) * sizeof **facets);
  if (r->pool == NULL || *facets == NULL) return -1;
  for (int j = 0; j <= d; j++) c[j] = (unsigned char)j;
  do {
    if (r->npool == 64) return -1;
    study_linf_cell *x = &r->pool[r->npool];
    study_linf_rows(ex, c, d + 1, rows);
    x->flat = linf_orient(rows, d) == 0;
    memcpy(x->v, c, (size_t)d + 1);
    x->ncubes = linf_circumcubes(rows, d, x->cube);
    x->nlocal = 0;
    study_linf_facets(ex, x, r->npool, *facets + r->npool * (size_t)(d + 1));
    r->npool++;
    x->nempty = study_linf_clear(r, r->npool - 1, ((uint64_t)1 << ex->n) - 1, x->empty);
  } while (linf_next_subset(c, d + 1, ex->n));
  return 0;
}

/* A list of simplices (increasing indices) as a mask over the pool. */
static uint64_t study_linf_mask(const study_linf_report *r, const unsigned char *v, size_t k) {
  uint64_t m = 0;
  size_t w = (size_t)r->ex->d + 1;
  for (size_t i = 0; i < k; i++)
    for (size_t c = 0; c < r->npool; c++)
      if (memcmp(r->pool[c].v, v + i * w, w) == 0) m |= (uint64_t)1 << c;
  return m;
}

/* The example's cells, by their letters, as a mask over the pool. */
static uint64_t study_linf_cells(const study_linf_report *r) {
  const study_linf_example *ex = r->ex;
  uint64_t m = 0;
  for (size_t k = 0; ex->cells[k] != NULL; k++) {
    unsigned char v[LINF_DIM_MAX + 1];
    for (int j = 0; j <= ex->d; j++)
      v[j] = (unsigned char)(strchr(ex->labels, ex->cells[k][j]) - ex->labels);
    for (int j = 1; j <= ex->d; j++)   /* insertion sort of d + 1 indices */
      for (int i = j; i > 0 && v[i - 1] > v[i]; i--) {
        unsigned char t = v[i];
        v[i] = v[i - 1];
        v[i - 1] = t;
      }
    m |= study_linf_mask(r, v, 1);
  }
  return m;
}

/* The hull facets no Delaunay simplex has, the facets inside the hull
** with a Delaunay simplex on one side only, and the most on one facet. */
static void study_linf_walls(study_linf_report *r) {
  const study_linf_facet *all = r->facets;
  int d = r->ex->d;
  unsigned char g[LINF_DIM_MAX];
  size_t w = (size_t)d + 1;
  for (int j = 0; j < d; j++) g[j] = (unsigned char)j;
  do {
    uint64_t key = linf_row_key(g, d);
    int pos = 0, neg = 0;
    for (size_t i = 0; i < r->npool * w; i++)
      if (all[i].key == key && (r->delaunay >> all[i].cell & 1)) pos += all[i].side > 0,
                                                                   neg += all[i].side < 0;
    int hull = linf_hull_facet(r->ex->pts, r->ex->n, d, g);
    r->hull_facets += hull;
    r->bare_facets += hull && pos + neg == 0;
    r->open_facets += !hull && pos + neg == 1;
    if (pos + neg > r->crowded || (pos + neg == r->crowded && (pos > r->crowded_side ||
                                                               neg > r->crowded_side))) {
      r->crowded = pos + neg;
      r->crowded_side = pos > neg ? pos : neg;
      r->crowded_at = key;
    }
  } while (linf_next_subset(g, d, r->ex->n));
}

/* Every subset of the pool that triangulates the hull: locally Delaunay?
** Delaunay?  O(2^k k d log(k d)) for a pool of k simplices. */
static void study_linf_search(study_linf_report *r) {
  uint64_t solid = 0;
  int k = 0;
  for (size_t c = 0; c < r->npool; c++)
    if (!r->pool[c].flat) solid |= (uint64_t)1 << c, k++;
  if (k == 0 || k > STUDY_LINF_SEARCH_MAX) return;
  r->searched = 1;
  for (uint64_t set = solid; set != 0; set = (set - 1) & solid) {
    if (!study_linf_triangulates(r, set, NULL, 0)) continue;
    r->tilings++;
    int global = (set & ~r->delaunay) == 0, local = study_linf_locally(r, set);
    r->tilings_global += global;
    r->tilings_local += local;
    if (local && !global && r->nlocal_only < STUDY_LINF_LIST_MAX)
      r->local_only[r->nlocal_only++] = set;
  }
}

int study_linf_examine(const study_linf_example *ex, study_linf_report *r) {
  linf_simplices del;
  memset(r, 0, sizeof *r);
  r->ex = ex;
  linf_simplices_init(&r->selected, ex->d);
  if (study_linf_pool(r) != 0 || linf_delaunay_brute(ex->pts, ex->n, ex->d, &del, NULL) != 0)
    return -1;
  r->delaunay = study_linf_mask(r, del.v, del.n);
  linf_simplices_free(&del);
  if (linf_delaunay_select(ex->pts, ex->n, ex->d, &r->selected, &r->st) != 0) return -1;
  r->cells = study_linf_cells(r);
  r->tiling = study_linf_triangulates(r, r->cells, r->why, sizeof r->why);
  r->del_tiling = study_linf_triangulates(r, r->delaunay, r->del_why, sizeof r->del_why);
  study_linf_walls(r);
  study_linf_search(r);
  r->globally = r->cells != 0 && (r->cells & ~r->delaunay) == 0;
  r->locally = study_linf_locally(r, r->cells);
  return 0;
}

void study_linf_report_free(study_linf_report *r) {
  free(r->pool);
  free(r->facets);
  r->pool = NULL;
  r->facets = NULL;
  linf_simplices_free(&r->selected);
}
