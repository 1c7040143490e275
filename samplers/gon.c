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
   "n iid uniform points of the region conditioned on convex position (weighted)", 1, ALL},
  {"naive", sampler_gon_naive, "O(n / P(convex)), n <= 10",
   "n iid uniform points of the region conditioned on convex position", 0, ALL},
  {"iteration", sampler_gon_iteration, "O(h log n)",
   "uniform points of the region until their hull has n vertices", 0, ALL},
  {"valtr", sampler_gon_valtr, "O(n log n)",
   "n iid uniform points of the square conditioned on convex position", 0, SQ},
  {"vector", sampler_gon_vector, "O(n log n)",
   "edge vectors' x and y components uniform in the ball of {sum = 0}", 0, 0},
  {"circle", sampler_gon_circle, "O(n log n)", "n uniform angles on the unit circle", 0, 0},
};
#undef ALL
#undef SQ
const size_t sampler_gons_count = sizeof sampler_gons / sizeof sampler_gons[0];

const sampler_gon *sampler_gon_find(const char *s) {
  for (size_t k = 0; k < sampler_gons_count; k++)
    if (strcmp(s, sampler_gons[k].name) == 0) return &sampler_gons[k];
  return NULL;
}

const char *sampler_gon_names(void) {
  static char buf[512];
  if (buf[0] == '\0') {
    size_t len = 0;
    for (size_t k = 0; k < sampler_gons_count && len + 40 < sizeof buf; k++)
      len += (size_t)snprintf(buf + len, sizeof buf - len, "%s%s", k ? ", " : "",
                              sampler_gons[k].name);
  }
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
  else if (s->draw == sampler_gon_naive && n > SAMPLER_NAIVE_MAX)
    snprintf(err, errlen, "sampler naive takes n up to %d (it draws about 1 / P(convex) "
             "points a polygon); use rejection or valtr", SAMPLER_NAIVE_MAX);
  else
    return 0;
  return -1;
}

int sampler_gon_draw(const sampler_gon *s, const sampler_gon_params *p, uint64_t seed,
                     uint64_t index, size_t n, geom_point *out, sampler_gon_info *info) {
  *info = (sampler_gon_info){0};
  if (n < 3 || (unsigned)p->region >= SAMPLER_REGION_COUNT) return -1;
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
