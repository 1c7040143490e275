/*
** cpdt.c: the convex-polygon Delaunay workbench's table of algorithms, its
** input check, the exact incircle test every algorithm decides with, and the
** measures of a result (index length, the circumcircle algorithm's cost).
*/
#include <stdlib.h>
#include <string.h>
#include "cpdt_internal.h"
#include "geom_field_internal.h"
#include "predicates.h"
#include "splitmix.h"

typedef struct cpdt_entry {
  const char *name, *about;
  int (*run)(cpdt_run *r);
} cpdt_entry;

static const cpdt_entry cpdt_table[CPDT_ALGORITHM_COUNT] = {
  [CPDT_CIRCUM] = {"circum", "circumcircle algorithm, newest side (5.4.1)", cpdt_circum},
  [CPDT_CIRCUM_RANDOM] = {"circum-random", "circumcircle algorithm, random side",
                          cpdt_circum_random},
  [CPDT_CIRCUM_WALK] = {"circum-walk", "circumcircle algorithm in O(1) extra space",
                        cpdt_circum_walk},
  [CPDT_DIVIDE] = {"divide", "divide and conquer (5.4.2)", cpdt_divide},
  [CPDT_INCREMENTAL] = {"incremental", "incremental, input order (5.4.3)", cpdt_incremental},
  [CPDT_RANDOM] = {"random", "incremental, random order (Chew)", cpdt_random_incremental},
  [CPDT_FLIP] = {"flip", "fan from vertex 0, then Lawson's flips", cpdt_flip},
  [CPDT_CORNERS] = {"corners", "corners cut, smallest circle first (2.5.4)", cpdt_corners},
};

const char *cpdt_algorithm_name(int a) {
  return a >= 0 && a < CPDT_ALGORITHM_COUNT ? cpdt_table[a].name : NULL;
}

const char *cpdt_algorithm_about(int a) {
  return a >= 0 && a < CPDT_ALGORITHM_COUNT ? cpdt_table[a].about : NULL;
}

int cpdt_algorithm_find(const char *name) {
  for (int a = 0; name != NULL && a < CPDT_ALGORITHM_COUNT; a++)
    if (strcmp(name, cpdt_table[a].name) == 0) return a;
  return -1;
}

/* geom_polygon_check on a copy: it would reverse a clockwise polygon, which
** here is an error (vertex numbers are the caller's). */
int cpdt_check(const geom_point *p, size_t n, size_t *bad) {
  size_t dummy;
  if (bad == NULL) bad = &dummy;
  *bad = 0;
  if (n > CPDT_MAX_N) return CPDT_TOO_MANY;
  geom_point *q = malloc((n > 0 ? n : 1) * sizeof *q);
  if (q == NULL) return -2;
  if (n > 0) memcpy(q, p, n * sizeof *q);
  int reversed = 0;
  int e = (int)geom_polygon_check(q, n, bad, &reversed);
  free(q);
  if (e == GEOM_OK && reversed) return CPDT_CLOCKWISE;
  if (e != GEOM_OK && reversed && *bad > 0) *bad = n - *bad;   /* back to the caller's rows */
  return e;
}

const char *cpdt_check_str(int err) {
  if (err == CPDT_CLOCKWISE) return "the polygon is clockwise (give it anticlockwise)";
  if (err == CPDT_TOO_MANY) return "too many vertices (at most 2^29)";
  if (err == -2) return "out of memory";
  return geom_polyerr_str((geom_polyerr)err);
}

/* Exact, with lot's tie-break: the symbolic lift z = x^2 + y^2 + eps^(N - rank)
** (docs/lot.md).  The determinant is linear in the z column, so its perturbed
** value is det + the sum over the four points of eps^(N - rank) times the
** point's cofactor: for a, b, c, d those are orient(b,c,d), -orient(a,c,d),
** orient(a,b,d) and -orient(a,b,c).  When det = 0 the greatest point's
** term decides; in convex position no three are collinear, so it is not 0. */
int cpdt_incircle(cpdt_run *r, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  const geom_point *p = r->p;
  r->c->incircle++;
  int s = geom_incircle(p[a], p[b], p[c], p[d]);
  if (s != 0) return s;
  uint32_t v[4] = {a, b, c, d};
  int g = 0;
  for (int i = 1; i < 4; i++)
    if (geom_lexless(p[v[g]], p[v[i]])) g = i;
  if (g == 3) return -1;   /* -orient(a, b, c), a b c anticlockwise */
  r->c->orient++;
  static const int other[3][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}};
  int o = geom_orient(p[v[other[g][0]]], p[v[other[g][1]]], p[v[other[g][2]]]);
  return g == 1 ? -o : o;
}

void cpdt_emit(cpdt_run *r, uint32_t a, uint32_t b, uint32_t c) {
  uint32_t t;
  if (a > b) { t = a; a = b; b = t; }
  if (b > c) { t = b; b = c; c = t; }
  if (a > b) { t = a; a = b; b = t; }
  uint32_t *o = r->tri + 3 * (size_t)(b - 1);
  o[0] = a;
  o[1] = b;
  o[2] = c;
}

uint32_t cpdt_random(cpdt_run *r, uint32_t m) {
  return (uint32_t)(geom_unit53(geom_splitmix64(&r->rng)) * m);
}

void cpdt_memory(cpdt_run *r, uint64_t bytes) {
  r->c->memory += bytes;
}

int cpdt_triangulate(const geom_point *p, size_t n, int algorithm, uint64_t seed,
                     uint32_t *tri, cpdt_counts *counts) {
  cpdt_counts local;
  if (counts == NULL) counts = &local;
  memset(counts, 0, sizeof *counts);
  if (algorithm < 0 || algorithm >= CPDT_ALGORITHM_COUNT || n < 3 || n > CPDT_MAX_N) return -1;
  cpdt_run r = {p, n, counts, seed ^ GEOM_STREAM_CPDT, tri};
  int rc = cpdt_table[algorithm].run(&r);
  if (rc == 0) counts->index_length = cpdt_index_length(tri, n);
  return rc;
}

/* Index length of i < j: min(j - i, n - j + i); 1 for a polygon side. */
static size_t cpdt_len(size_t i, size_t j, size_t n) {
  size_t d = j - i;
  return d < n - d ? d : n - d;
}

double cpdt_index_length(const uint32_t *tri, size_t n) {
  if (n <= 3) return 0;
  uint64_t sum = 0;
  for (size_t t = 0; t + 2 < n; t++) {
    const uint32_t *v = tri + 3 * t;
    size_t l[3] = {cpdt_len(v[0], v[1], n), cpdt_len(v[1], v[2], n), cpdt_len(v[0], v[2], n)};
    for (int e = 0; e < 3; e++)
      if (l[e] > 1) sum += l[e];   /* each diagonal is counted by its two triangles */
  }
  return (double)sum / (2.0 * (double)(n - 3));
}

uint64_t cpdt_circum_cost(const uint32_t *tri, size_t n) {
  uint64_t sum = 0;
  for (size_t t = 0; t + 2 < n; t++) sum += tri[3 * t + 2] - tri[3 * t] - 1;
  return sum;
}

/* ---- the counts by name ---- */

#define F(M, T) GEOM_FIELD(cpdt_counts, M, GEOM_FIELD_##T)
static const geom_field cpdt_counts_fields[] = {
  F(scanned, U64), F(incircle, U64), F(orient, U64), F(flips, U64), F(merges, U64),
  F(cross_sum, U64), F(cross_max, U64), F(added, U64), F(deleted, U64), F(depth, U64),
  F(memory, U64), F(index_length, DOUBLE)};
#undef F
#define CPDT_NFIELDS (sizeof cpdt_counts_fields / sizeof *cpdt_counts_fields)

cpdt_counts *cpdt_counts_new(void) { return calloc(1, sizeof(cpdt_counts)); }

void cpdt_counts_delete(cpdt_counts *c) { free(c); }

const char *cpdt_counts_field(size_t i) {
  return i < CPDT_NFIELDS ? cpdt_counts_fields[i].name : NULL;
}

int cpdt_counts_get_u64(const cpdt_counts *c, const char *name, uint64_t *out) {
  return geom_field_u64(c, geom_field_find(cpdt_counts_fields, CPDT_NFIELDS, name), 0, out);
}

int cpdt_counts_get_double(const cpdt_counts *c, const char *name, double *out) {
  const geom_field *f = geom_field_find(cpdt_counts_fields, CPDT_NFIELDS, name);
  uint64_t u;
  if (geom_field_double(c, f, out) == 0) return 0;
  if (geom_field_u64(c, f, 0, &u) != 0) return -1;
  *out = (double)u;
  return 0;
}
