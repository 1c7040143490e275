/*
** points.c: point sets for `fliplab lot` (sampler.h lists them): random
** ones drawn from one generator stream of the seed, and the structured
** sets of the thesis's worst cases and degenerate inputs.
*/
#include <math.h>
#include <string.h>
#include "sampler.h"

#define SAMPLER_POINTS_2PI 6.28318530717958647693

static const char *const sampler_points_table[SAMPLER_POINTS_COUNT] = {
  "uniform", "normal", "disc", "grid", "parabola", "circle"};

const char sampler_points_names[] = "uniform, normal, disc, grid, parabola, circle";

int sampler_points_find(const char *s) {
  for (int k = 0; k < SAMPLER_POINTS_COUNT; k++)
    if (strcmp(s, sampler_points_table[k]) == 0) return k;
  return -1;
}

const char *sampler_points_name(sampler_points_kind k) {
  return sampler_points_table[k];
}

void sampler_points(sampler_points_kind k, uint64_t seed, size_t n, geom_point *out) {
  sampler_rng g;
  sampler_seed(&g, seed, GEOM_STREAM_POINTS);
  size_t side = (size_t)ceil(sqrt((double)n));
  while (side * side < n) side++;
  for (size_t i = 0; i < n; i++) {
    switch (k) {
    case SAMPLER_UNIFORM: {
      double x = sampler_uniform(&g);
      out[i] = (geom_point){x, sampler_uniform(&g)};
      break;
    }
    case SAMPLER_NORMAL: {
      double x = sampler_normal(&g);
      out[i] = (geom_point){x, sampler_normal(&g)};
      break;
    }
    case SAMPLER_DISC: out[i] = sampler_disc(&g); break;
    case SAMPLER_GRID: out[i] = (geom_point){(double)(i % side), (double)(i / side)}; break;
    case SAMPLER_PARABOLA: {
      double x = (double)(n - i);
      out[i] = (geom_point){x, x * x};
      break;
    }
    default: {
      double th = SAMPLER_POINTS_2PI * sampler_uniform(&g);
      out[i] = (geom_point){cos(th), sin(th)};
      break;
    }
    }
  }
}
