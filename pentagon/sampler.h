/*
** sampler.h: random convex and simple polygons.
**
** sampler_pentagon is the thesis's iteration method (section 6.3): points
** uniform in the unit disc, one at a time, keeping their convex hull, until
** the hull has exactly five vertices.  Sample i depends only on (seed, i):
** its generator is seeded from a hash of the pair, so any thread count and
** any split into shards give bit-identical samples.
**
** sampler_quad draws random convex quadrilaterals the same way (points
** uniform in the unit disc, kept when in convex position).
**
** For large n: the vector method (section 6.4) and points on a circle.
** The methods and the streams: docs/sampling.md.
*/
#ifndef FLIPLAB_SAMPLER_H
#define FLIPLAB_SAMPLER_H

#include <stddef.h>
#include <stdint.h>
#include "geom.h"

/* A small fast generator (the state of one stream). */
typedef struct sampler_rng { uint64_t s[4]; } sampler_rng;

void sampler_seed(sampler_rng *g, uint64_t seed, uint64_t stream);
uint64_t sampler_next(sampler_rng *g);
double sampler_uniform(sampler_rng *g);   /* [0, 1), 53 random bits */
double sampler_normal(sampler_rng *g);

/* A point uniform in the open unit disc (rejection from [-1, 1)^2). */
geom_point sampler_disc(sampler_rng *g);

/* Pentagon number `index` of the stream `seed`, anticlockwise. */
void sampler_pentagon(uint64_t seed, uint64_t index, geom_point v[5]);

/* Quadrilateral number `index` of the stream `seed`: four points uniform
** in the unit disc in strictly convex position, anticlockwise (the
** Delaunay-equivalence check of `fliplab rule`, and the tests). */
void sampler_quad(uint64_t seed, uint64_t index, geom_point q[4]);

/* Convex n-gons, anticlockwise, strictly convex, n >= 3. 0 on success. */
int sampler_vector(sampler_rng *g, size_t n, geom_point *out);
int sampler_circle(sampler_rng *g, size_t n, geom_point *out);

/* Simple (generally non-convex) n-gons, anticlockwise, checked exactly
** (pentagon/simplepoly.c): star-shaped from sorted random angles and radii,
** or x-monotone from random points split by the line through the extreme
** two.  0 on success, -1 when 100 draws all failed the check. */
int sampler_star(sampler_rng *g, size_t n, geom_point *out);
int sampler_monotone(sampler_rng *g, size_t n, geom_point *out);

#endif
