/*
** gon_internal.h: what the convex n-gon samplers of samplers/ share and
** nobody else needs: the small-n iteration of pentagon.c behind the
** registry, the in-place rotation to the lexicographically smallest vertex
** (gonutil.c),
** and the regions' geometry (samplers/gon_region.c) that rejection and
** iteration (samplers/gon_hull.c) draw in.  Not installed.
*/
#ifndef FLIPLAB_GON_INTERNAL_H
#define FLIPLAB_GON_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "fliplab_config.h"
#include "sampler.h"

/* sampler_convex from a stream already seeded: draw for draw the same
** polygon; *changes (when not NULL) gains the number of draws that changed
** the hull. */
FLIPLAB_INTERNAL void sampler_convex_rng(sampler_rng *g, int n, geom_point *v,
                                         uint64_t *changes);
/* Add p to the strictly convex anticlockwise hull h[0..n-1], n <
** SAMPLER_HULL_MAX (exact); the new size. */
FLIPLAB_INTERNAL int sampler_hull_add(geom_point *h, int n, geom_point p);
/* v rotated in place to start at its lexicographically smallest vertex
** (samplers/gonutil.c); that vertex's old index. */
FLIPLAB_INTERNAL size_t sampler_lexfirst(geom_point *v, size_t n);

/* A convex polygon of a few vertices: a region clipped to the domain. */
#define SAMPLER_CLIP_MAX 24   /* a region has at most 9 vertices, its disc part 18 */
typedef struct sampler_clip {
  int n;
  geom_point v[SAMPLER_CLIP_MAX];
} sampler_clip;

/* The region right of the directed line a->b (strictly) and left of each
** of the nleft lines left[k][0]->left[k][1], within the domain r: its mass
** (probability under the uniform law of r) into *mass, and the polygon
** points are drawn in into *c (for the disc, a polygon around region and
** disc: points outside the disc are refused by sampler_region_draw). */
FLIPLAB_INTERNAL double sampler_region_mass(sampler_region r, geom_point a, geom_point b,
                                            const geom_point (*left)[2], int nleft,
                                            sampler_clip *c);
/* A point uniform in the region of c (three uniforms per try; for the disc,
** drawn again until inside it): 0, or -1 after `tries` failed draws.  Adds
** the points drawn to *draws. */
FLIPLAB_INTERNAL int sampler_region_draw(sampler_rng *g, sampler_region r, const sampler_clip *c,
                                         geom_point *p, uint64_t *draws);
/* A point uniform in the whole domain r. */
FLIPLAB_INTERNAL geom_point sampler_region_point(sampler_rng *g, sampler_region r);

#endif
