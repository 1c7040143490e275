/*
** sites.c: random site sets for the census of flip graphs (`fliplab
** census`): convex n-gons by the thesis's iteration method, or n
** independent points from a disc, a square or a normal distribution.
*/
#include <string.h>
#include "sampler.h"

static const char *const sampler_sites_names[SAMPLER_SITES_COUNT] = {
  "convex", "disc", "square", "normal"};

const char *sampler_sites_name(int kind) {
  return kind >= 0 && kind < SAMPLER_SITES_COUNT ? sampler_sites_names[kind] : NULL;
}

int sampler_sites_find(const char *name) {
  for (int k = 0; k < SAMPLER_SITES_COUNT; k++)
    if (strcmp(name, sampler_sites_names[k]) == 0) return k;
  return -1;
}

static geom_point sampler_point(sampler_rng *g, int kind) {
  switch (kind) {
    case SAMPLER_SITES_DISC: return sampler_disc(g);
    case SAMPLER_SITES_SQUARE: {
      double x = 2 * sampler_uniform(g) - 1;
      return (geom_point){x, 2 * sampler_uniform(g) - 1};
    }
    default: {
      double x = sampler_normal(g);
      return (geom_point){x, sampler_normal(g)};
    }
  }
}

/* Two equal points, or all on one line (exact)? */
static int sampler_degenerate(const geom_point *p, int n) {
  for (int i = 0; i < n; i++)
    for (int j = 0; j < i; j++)
      if (p[i].x == p[j].x && p[i].y == p[j].y) return 1;
  for (int k = 2; k < n; k++)
    if (geom_orient(p[0], p[1], p[k]) != 0) return 0;
  return 1;
}

int sampler_sites(int kind, uint64_t seed, uint64_t index, int n, geom_point *out) {
  if (kind < 0 || kind >= SAMPLER_SITES_COUNT || n < 3 || n >= SAMPLER_HULL_MAX) return -1;
  if (kind == SAMPLER_SITES_CONVEX) {
    sampler_convex(seed, index, n, out);
    return 0;
  }
  sampler_rng g;
  sampler_seed(&g, seed, GEOM_STREAM_SAMPLE(index));
  do {
    for (int i = 0; i < n; i++) out[i] = sampler_point(&g, kind);
  } while (sampler_degenerate(out, n));
  return 0;
}
