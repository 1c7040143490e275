/*
** gon.c: the registry of random convex n-gon samplers (chapter 6,
** docs/sampling.md): one row per method, its cost and law in a line each,
** and the one entry point that seeds a polygon's own stream, draws and
** checks.  The older samplers (vector, circle; sampler_convex for the
** iteration at small n) are wrapped as they are, draw for draw.
*/
#include <stdio.h>
#include <string.h>
#include "gon_internal.h"

static const char *const sampler_region_list[SAMPLER_REGION_COUNT] = {"square", "disc",
                                                                      "triangle"};
const char sampler_region_names[] = "square, disc, triangle";

int sampler_region_find(const char *s) {
  for (int r = 0; r < SAMPLER_REGION_COUNT; r++)
    if (strcmp(s, sampler_region_list[r]) == 0) return r;
  return -1;
}

const char *sampler_region_name(int r) {
  return r >= 0 && r < SAMPLER_REGION_COUNT ? sampler_region_list[r] : NULL;
}

/* The largest n naive rejection takes: 10 points of the triangle are in
** convex position with probability about 1e-4 (Valtr), so about 1e5 points
** are drawn per polygon; at 12 it would be 1e7. */
#define SAMPLER_NAIVE_MAX 10

int sampler_gon_naive(sampler_rng *g, size_t n, const sampler_gon_params *p, geom_point *out,
                      sampler_gon_info *info) {
  if (n < 3 || n > SAMPLER_NAIVE_MAX) return -1;
  int m;
  do {
    m = 0;
    for (size_t k = 0; k < n; k++) m = sampler_hull_add(out, m, sampler_region_point(g, p->region));
    info->draws += n;
  } while ((size_t)m != n);
  sampler_lexfirst(out, n);
  return 0;
}

/* A polygon sampler of its own signature, its output rotated to start at
** the lexicographically smallest vertex (the draws are its own). */
static int sampler_gon_plain(int (*fn)(sampler_rng *, size_t, geom_point *), sampler_rng *g,
                             size_t n, geom_point *out) {
  int rc = fn(g, n, out);
  if (rc == 0) sampler_lexfirst(out, n);
  return rc;
}

static int sampler_gon_vector(sampler_rng *g, size_t n, const sampler_gon_params *p,
                              geom_point *out, sampler_gon_info *info) {
  (void)p;
  (void)info;
  return sampler_gon_plain(sampler_vector, g, n, out);
}

static int sampler_gon_circle(sampler_rng *g, size_t n, const sampler_gon_params *p,
                              geom_point *out, sampler_gon_info *info) {
  (void)p;
  (void)info;
  return sampler_gon_plain(sampler_circle, g, n, out);
}

#define ALL ((1u << SAMPLER_REGION_COUNT) - 1)
#define SQ (1u << SAMPLER_REGION_SQUARE)
const sampler_gon sampler_gons[] = {
  {"rejection", sampler_gon_rejection, "O(n log n)",
   "n iid uniform points of the region conditioned on convex position (weighted)", 1, ALL, 0, 1,
   0},
  {"naive", sampler_gon_naive, "O(n / P(convex)), n <= 10",
   "n iid uniform points of the region conditioned on convex position", 0, ALL,
   SAMPLER_NAIVE_MAX, 1, 0},
  {"iteration", sampler_gon_iteration, "O(h log n)",
   "uniform points of the region until their hull has n vertices", 0, ALL, 0, 2, 0},
  {"valtr", sampler_gon_valtr, "O(n log n)",
   "n iid uniform points of the square conditioned on convex position", 0, SQ, 0, 1, 0},
  {"vector", sampler_gon_vector, "O(n log n)",
   "edge vectors' x and y components uniform in the ball of {sum = 0}", 0, 0, 0, 1, 0},
  {"circle", sampler_gon_circle, "O(n log n)", "n uniform angles on the unit circle", 0, 0, 0,
   1, 0},
  {"triangulation", sampler_gon_triangulation, "O(n)",
   "a uniform triangulation of the n-gon, realised as its Delaunay triangulation", 0, 0, 0, 1,
   0},
  {"bounce", sampler_gon_bounce, "O(n log n)",
   "the regular n-gon after 2n bounce events (law 0: velocity redrawn, 1: reflected)", 0, 0, 0,
   2, 0},
  {"dual", sampler_gon_dual, "O(n) beyond the inner method",
   "the polar dual, about its vertex mean, of the inner method's polygon", 0, 0, 0, 1, 1},
  {"dual-rejection", sampler_gon_dualrej, "O(n log n / P(n sides)), n <= 10",
   "n uniform half-planes meeting the unit disc, drawn until they bound an n-gon", 0, 0,
   SAMPLER_DUALREJ_NMAX, 1, 0},
  {"geobench", sampler_gon_geobench, "O(n log n)",
   "n random radius moves of a polygon inscribed in the unit circle (XYZ GeoBench)", 0, 0, 0,
   1, 0},
  {"angles", sampler_gon_angles, "O(n), n <= about 50",
   "uniform feasible turning angles, edge lengths closing the polygon", 0, 0, 0, 1, 0},
};
#undef ALL
#undef SQ
const size_t sampler_gons_count = sizeof sampler_gons / sizeof sampler_gons[0];

const sampler_gon *sampler_gon_find(const char *s) {
  for (size_t k = 0; k < sampler_gons_count; k++)
    if (strcmp(s, sampler_gons[k].name) == 0) return &sampler_gons[k];
  return NULL;
}

/* The names of the registry's rows (only the inner methods when `inner`),
** comma-separated, into buf. */
static void sampler_gon_list(char *buf, size_t size, int inner) {
  size_t len = 0;
  buf[0] = '\0';
  for (size_t k = 0; k < sampler_gons_count && len + 40 < size; k++)
    if (!inner || sampler_gon_inner(sampler_gons[k].name) != NULL)
      len += (size_t)snprintf(buf + len, size - len, "%s%s", len ? ", " : "",
                              sampler_gons[k].name);
}

const char *sampler_gon_names(void) {
  static char buf[512];
  if (buf[0] == '\0') sampler_gon_list(buf, sizeof buf, 0);
  return buf;
}

int sampler_gon_check(const char *name, int region, size_t n, char *err, size_t errlen) {
  const sampler_gon *s = sampler_gon_find(name);
  if (s == NULL)
    snprintf(err, errlen, "unknown sampler '%s' (valid: %s)", name, sampler_gon_names());
  else if (s->regions == 0 && region >= 0)
    snprintf(err, errlen, "sampler %s draws no points from a region (give none)", name);
  else if (region >= SAMPLER_REGION_COUNT)
    snprintf(err, errlen, "region %d: valid are 0 .. %d (%s)", region, SAMPLER_REGION_COUNT - 1,
             sampler_region_names);
  else if (s->regions != 0 && region >= 0 && !(s->regions & (1u << region)))
    snprintf(err, errlen, "sampler %s does not draw in the %s (valid: square)", name,
             sampler_region_name(region));
  else if (n < 3)
    snprintf(err, errlen, "n = %zu: a polygon has at least 3 vertices", n);
  else if (s->nmax != 0 && n > s->nmax)
    snprintf(err, errlen, "sampler %s takes n up to %zu (its draws per polygon explode "
             "beyond; docs/sampling.md)", name, s->nmax);
  else
    return 0;
  return -1;
}

/* The inner methods: no region, no weight, no inner method of their own. */
const sampler_gon *sampler_gon_inner(const char *inner) {
  const sampler_gon *t = sampler_gon_find(inner != NULL ? inner : "vector");
  return t != NULL && t->regions == 0 && !t->weighted && !t->inner ? t : NULL;
}

int sampler_gon_check_variant(const char *name, int law, const char *inner, size_t n,
                              char *err, size_t errlen) {
  const sampler_gon *s = sampler_gon_find(name), *t = s;
  char list[256];
  sampler_gon_list(list, sizeof list, 1);
  if (s != NULL && s->inner) t = sampler_gon_inner(inner);
  if (s == NULL)
    snprintf(err, errlen, "unknown sampler '%s' (valid: %s)", name, sampler_gon_names());
  else if (inner != NULL && !s->inner)
    snprintf(err, errlen, "sampler %s takes no inner method (only dual does)", name);
  else if (t == NULL)
    snprintf(err, errlen, "unknown inner method '%s' (valid: %s)", inner, list);
  else if (t->nmax != 0 && n > t->nmax)
    snprintf(err, errlen, "inner method %s takes n up to %zu", t->name, t->nmax);
  else if (law < 0 || law >= t->laws)
    snprintf(err, errlen, "law %d: sampler %s takes laws 0 .. %d", law, t->name, t->laws - 1);
  else
    return 0;
  return -1;
}

int sampler_gon_draw(const sampler_gon *s, const sampler_gon_params *p, uint64_t seed,
                     uint64_t index, size_t n, geom_point *out, sampler_gon_info *info) {
  *info = (sampler_gon_info){0};
  if (n < 3 || (s->nmax != 0 && n > s->nmax) || (unsigned)p->region >= SAMPLER_REGION_COUNT)
    return -1;
  if (s->regions != 0 && !(s->regions & (1u << p->region))) return -1;
  sampler_rng g;
  sampler_seed(&g, seed, GEOM_STREAM_SAMPLE(index));
  int rc = s->draw(&g, n, p, out, info);
  if (rc != 0) return rc;
  size_t bad;
  int rev;
  if (geom_polygon_check(out, n, &bad, &rev) != GEOM_OK || rev) return -1;
  for (size_t k = 1; k < n; k++)
    if (geom_lexless(out[k], out[0])) return -1;
  return 0;
}
