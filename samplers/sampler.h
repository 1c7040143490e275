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
** Random convex n-gons of every method of chapter 6, by name: the section
** "random convex n-gons" below.  The methods and the streams:
** docs/sampling.md.
*/
#ifndef FLIPLAB_SAMPLER_H
#define FLIPLAB_SAMPLER_H

#include <stddef.h>
#include <stdint.h>
#include "geom.h"
#include "splitmix.h"   /* the registry of streams every sampler_seed names */

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

/* Other pentagon samplers for `table34 --sampler` (docs/sampling.md), each
** drawing pentagon `index` from the stream (seed, index), strictly convex,
** anticlockwise from the lexicographically smallest vertex:
**   iteration  sampler_pentagon (the thesis's, the default)
**   vector     sampler_vector with n = 5
**   circle     sampler_circle with n = 5
**   disc-hull  five points uniform in the unit disc, all five drawn again
**              until each is a vertex of their convex hull (exact test)
** draw returns 0, or SAMPLER_ENOMEM. */
typedef int (*sampler_pentagon_fn)(uint64_t seed, uint64_t index, geom_point v[5]);
typedef struct sampler_pentagons {
  const char *name;
  sampler_pentagon_fn draw;
} sampler_pentagons;
#define SAMPLER_PENTAGONS_COUNT 4
extern const sampler_pentagons sampler_pentagons_table[SAMPLER_PENTAGONS_COUNT];
/* The entry named s, or NULL. */
const sampler_pentagons *sampler_pentagons_find(const char *s);

/* Quadrilateral number `index` of the stream `seed`: four points uniform
** in the unit disc in strictly convex position, anticlockwise (the
** Delaunay-equivalence check of `fliplab rule`, and the tests). */
void sampler_quad(uint64_t seed, uint64_t index, geom_point q[4]);

/* The iteration method for convex n-gons, 3 <= n < SAMPLER_HULL_MAX:
** sample `index` of stream `seed`, anticlockwise from the lexicographically
** smallest vertex.  For n = 5 it is sampler_pentagon, draw for draw. */
#define SAMPLER_HULL_MAX 17   /* the census's 16 sites (SITEFLIP_MAX_SITES) */
void sampler_convex(uint64_t seed, uint64_t index, int n, geom_point *v);

/* Site sets for the census (samplers/sites.c).  SAMPLER_SITES_CONVEX is
** sampler_convex; the others draw n independent points (uniform in the unit
** disc, uniform in the square [-1, 1)^2, standard normal), redrawing the
** whole set from the same stream in the (measure-zero) event of two equal
** points or all points on one line.  Sample i depends only on (seed, i). */
typedef enum sampler_sites_kind {
  SAMPLER_SITES_CONVEX, SAMPLER_SITES_DISC, SAMPLER_SITES_SQUARE, SAMPLER_SITES_NORMAL,
  SAMPLER_SITES_COUNT
} sampler_sites_kind;
const char *sampler_sites_name(int kind);       /* "convex", ... ; NULL if unknown */
int sampler_sites_find(const char *name);       /* -1 if unknown */
/* 0, or -1 for an unknown kind or n out of [3, SAMPLER_HULL_MAX). */
int sampler_sites(int kind, uint64_t seed, uint64_t index, int n, geom_point *out);

/* Convex n-gons, anticlockwise, strictly convex, n >= 3.  0 on success,
** SAMPLER_ENOMEM when memory ran out, -1 when no strictly convex n-gon
** came out in floating point. */
#define SAMPLER_ENOMEM (-2)
int sampler_vector(sampler_rng *g, size_t n, geom_point *out);
int sampler_circle(sampler_rng *g, size_t n, geom_point *out);

/* Simple (generally non-convex) n-gons, anticlockwise, checked exactly
** (samplers/simplepoly.c): star-shaped from sorted random angles and radii,
** or x-monotone from random points split by the line through the extreme
** two.  0 on success, SAMPLER_ENOMEM when memory ran out, -1 when 100
** draws all failed the check. */
int sampler_star(sampler_rng *g, size_t n, geom_point *out);
int sampler_monotone(sampler_rng *g, size_t n, geom_point *out);

/* Point sets for triangulations (samplers/points.c), by name:
**   uniform   the unit square [0, 1)^2
**   normal    standard normal coordinates
**   disc      the unit disc
**   grid      the integer grid points (i mod s, i div s), s = ceil(sqrt(n)),
**             i = 0 .. n-1: every unit square's corners are cocircular
**   parabola  (i, i^2) for i = n, n-1, ..., 1 in that order (theorem 6's
**             worst case for the incremental algorithm)
**   circle    random angles on the unit circle (cocircular up to rounding)
**   clustered SAMPLER_CLUSTER_COUNT Gaussian clusters: centres uniform in
**             the unit square, each point in a cluster drawn uniformly, offset
**             by independent normals of deviation SAMPLER_CLUSTER_SIGMA
**   jittered  the grid's points, each coordinate moved by an independent
**             uniform offset in [-SAMPLER_JITTER, SAMPLER_JITTER)
**   lines     exact integer points on L = SAMPLER_LINE_COUNT random lines:
**             point i on line i mod L, at m = ceil(n / L) points a line; line k is
**             a_k + t d_k with a_k uniform in [-64m, 64m)^2 and d_k uniform
**             in [-8, 8]^2 minus (0, 0), all integers; point i's t is
**             16 (i div L) + r - 8m with r uniform in [0, 16) (distinct and
**             increasing along the line); all coordinates are integers of
**             magnitude at most 128 m, so collinearity is exact.  A draw
**             with all points on one line (small n) is replaced by the next
**             draw of the stream.
**   dups      duplicate-heavy: a pool of m = max(3, ceil(n / 4)) points (the
**             uniform family's first m, or all n when n < 3), then n - m
**             copies of pool points drawn uniformly: each pool point is
**             repeated 1 + Binomial(n - m, 1 / m) times (mean about 4)
** The same (kind, seed, n) always gives the same points, bit for bit. */
typedef enum sampler_points_kind {
  SAMPLER_UNIFORM, SAMPLER_NORMAL, SAMPLER_DISC, SAMPLER_GRID, SAMPLER_PARABOLA,
  SAMPLER_CIRCLE, SAMPLER_CLUSTERED, SAMPLER_JITTERED, SAMPLER_LINES, SAMPLER_DUPS,
  SAMPLER_POINTS_COUNT
} sampler_points_kind;
#define SAMPLER_CLUSTER_COUNT 20
#define SAMPLER_CLUSTER_SIGMA 0.01
#define SAMPLER_JITTER 0x1p-10
#define SAMPLER_LINE_COUNT 8
#define SAMPLER_DUPS_SHARE 4   /* n points, n / 4 distinct */

/* The kind named s, or -1; the names, comma-separated, for messages. */
int sampler_points_find(const char *s);
const char *sampler_points_name(sampler_points_kind k);
extern const char sampler_points_names[];

void sampler_points(sampler_points_kind k, uint64_t seed, size_t n, geom_point *out);

/* ---- planar straight-line graphs (samplers/pslg.c, docs/sampling.md) ----
** Inputs of constrained triangulations.  In each, two segments meet only at
** points of the graph (an end point of one of them), decided exactly. */

/* A polygon with holes: an outer ring of nouter vertices (anticlockwise,
** star-shaped from the origin, radii in [0.75, 1]) and nholes rings of m
** vertices each (radius about 0.3 / sqrt(nholes), at most 0.2, centres in
** the disc of radius 0.6), each hole strictly inside the outer ring, their
** bounding boxes pairwise disjoint; out->hole[h] is hole h's centre,
** strictly inside it.  Points: the outer ring, then each hole's; segments:
** every ring's edges.  0, SAMPLER_ENOMEM, or -1 (nouter or m below 3, more
** than SAMPLER_PSLG_MAX_HOLES holes, or the holes did not fit). */
#define SAMPLER_PSLG_MAX_HOLES 100000
int sampler_pslg_holes(sampler_rng *g, size_t nouter, size_t nholes, size_t m, geom_pslg *out);

/* Up to m non-crossing segments on the points p[0..n): their bounding box
** cut into c x c cells, c = ceil(sqrt(min(m, n / 4))) (so about n / c^2 >=
** 4 points a cell, and some 3n / 4 candidates); in each cell, the segments from
** its first point (input order) to each other point of the cell (equal
** points and a second point in the same direction skipped, exactly); m of
** those drawn uniformly.  Cells are disjoint convex sets, so segments of
** two cells never meet; segments of one cell share only their first point.
** A segment may pass through another point of its cell (which splits it).
** seg gets 2 indices per segment, *got how many (fewer than m when there
** are fewer candidates).  0 or SAMPLER_ENOMEM. */
int sampler_segments(sampler_rng *g, const geom_point *p, size_t n, size_t m, uint32_t *seg,
                     size_t *got);

/* The first n points, row by row, of a square grid turned by atan(4/3):
** (i, j) -> (3i - 4j, 4i + 3j), exact integers (so rows are exactly
** collinear, and unit squares exactly cocircular); segments along its
** lines: each piece between row neighbours is chosen with probability 1/2,
** a run of chosen pieces being one segment through the points between;
** each piece between column neighbours is a segment with probability 1/2.
** 0, SAMPLER_ENOMEM, or -1 (n below 3 or above SAMPLER_PSLG_MAX_GRID). */
#define SAMPLER_PSLG_MAX_GRID 0x3fffffffu
int sampler_pslg_grid(sampler_rng *g, size_t n, geom_pslg *out);

/* ---- random convex n-gons, chapter 6 (samplers/gon.c, docs/sampling.md) ----
**
** Every method of the thesis's chapter 6 (and Valtr's direct one) behind
** one signature, and a registry of them by name.  The regions the points of
** the point-based methods are drawn from: the unit square [0, 1]^2, the
** unit disc (centre 0, radius 1), the triangle (0, 0), (1, 0), (0, 1). */
typedef enum sampler_region {
  SAMPLER_REGION_SQUARE, SAMPLER_REGION_DISC, SAMPLER_REGION_TRIANGLE, SAMPLER_REGION_COUNT
} sampler_region;

typedef struct sampler_gon_params {
  sampler_region region;
  int law;              /* a method's variant, e.g. the bounce law; 0 = default */
  const char *inner;    /* the dual's inner method, NULL = default */
} sampler_gon_params;

typedef struct sampler_gon_info {
  double log_weight;      /* ln of the bias-correcting weight (0 when unweighted) */
  uint64_t hull_changes;  /* h of the iteration method, else 0 */
  uint64_t draws;         /* random points drawn or events processed */
} sampler_gon_info;

/* out: n vertices, strictly convex (checked exactly), anticlockwise from the
** lexicographically smallest; returns 0, SAMPLER_ENOMEM, or -1 with no
** polygon (e.g. n beyond what doubles can realise). */
typedef int (*sampler_gon_fn)(sampler_rng *g, size_t n, const sampler_gon_params *p,
                              geom_point *out, sampler_gon_info *info);

/* The registry: name, function, cost, law (one line each, for help and
** docs), whether the output carries a weight, the regions it takes (a bit
** mask of 1 << sampler_region; 0: it draws no points from one), the
** largest n it takes (0: any; beyond, its cost explodes), how many laws
** p->law selects among (1: only law 0), and whether it takes an inner
** method p->inner (the dual: then the inner method's laws apply). */
typedef struct sampler_gon {
  const char *name;
  sampler_gon_fn draw;
  const char *cost, *law;
  int weighted;
  unsigned regions;
  size_t nmax;
  int laws, inner;
} sampler_gon;
extern const sampler_gon sampler_gons[];
extern const size_t sampler_gons_count;
/* The entry named s, or NULL; the names, comma-separated, for messages
** (a static string built on the first call: make that call before starting
** threads that may make it too). */
const sampler_gon *sampler_gon_find(const char *s);
const char *sampler_gon_names(void);
/* The region named s ("square", "disc", "triangle"), or -1; its name. */
int sampler_region_find(const char *s);
const char *sampler_region_name(int r);
extern const char sampler_region_names[];

/* Can sampler `name` draw n-gons in region (-1: none given, which means
** the square for the samplers that take one; vector and circle take none)?
** 0, or -1 with a one-line message (unknown sampler, region, n below 3 or
** beyond naive rejection's 10). */
int sampler_gon_check(const char *name, int region, size_t n, char *err, size_t errlen);
/* Does sampler `name` (known) take law `law` and inner method `inner`
** (NULL: none given) for n-gons?  An inner method is a registry row that draws no
** points from a region, carries no weight and takes no inner method
** itself; sampler_gon_inner finds it (NULL: "vector"), else NULL.  0, or
** -1 with a one-line message naming the law or inner method. */
int sampler_gon_check_variant(const char *name, int law, const char *inner, size_t n,
                              char *err, size_t errlen);
const sampler_gon *sampler_gon_inner(const char *inner);

/* Polygon `index` of stream `seed` from s (its own stream, GEOM_STREAM_SAMPLE
** (index): any thread count gives the same polygons): s->draw, then the
** exact check that out is strictly convex and anticlockwise (-1 if not).
** 0, SAMPLER_ENOMEM, or -1 (n < 3 or above s->nmax, a region s does not
** take, or s failed). */
int sampler_gon_draw(const sampler_gon *s, const sampler_gon_params *p, uint64_t seed,
                     uint64_t index, size_t n, geom_point *out, sampler_gon_info *info);

/* The methods (each a sampler_gon_fn; docs/sampling.md gives the laws):
**   rejection   6.2: n iid points of the region conditioned on convex
**               position, drawn point by point in the acceptance regions
**               with the weight exp(log_weight); O(n log n)
**   naive       n iid points drawn again until in convex position (exact,
**               unweighted; affordable for small n only)
**   iteration   6.3: points of the region until their hull has n vertices,
**               drawing only outside the hull; O(h log n) for h hull changes
**   valtr       Valtr's direct uniform convex n-gon in the square: the law
**               of rejection in the square, unweighted; O(n log n) */
int sampler_gon_rejection(sampler_rng *g, size_t n, const sampler_gon_params *p,
                          geom_point *out, sampler_gon_info *info);
int sampler_gon_naive(sampler_rng *g, size_t n, const sampler_gon_params *p, geom_point *out,
                      sampler_gon_info *info);
int sampler_gon_iteration(sampler_rng *g, size_t n, const sampler_gon_params *p,
                          geom_point *out, sampler_gon_info *info);
int sampler_gon_valtr(sampler_rng *g, size_t n, const sampler_gon_params *p, geom_point *out,
                      sampler_gon_info *info);

/* ---- random convex n-gons, chapter 6: bounce, triangulation, dual, prior
** art (samplers/bounce.c, tridt.c, dual.c, priorart.c; docs/sampling.md).
** Each is a sampler_gon_fn: out gets n vertices, strictly convex (checked
** exactly), anticlockwise from the lexicographically smallest; 0,
** SAMPLER_ENOMEM, or -1 with no polygon. */

/* Check p[0..n) exactly (geom_polygon_check: strictly convex, anticlockwise,
** within the coordinate contract) and rotate it in place to start at its
** lexicographically smallest vertex, whose old index goes to *first (if not
** NULL).  0, or -1 (p then unspecified). */
int sampler_gon_canon(geom_point *p, size_t n, size_t *first);
/* An integer uniform in [0, k), k >= 1 (exactly: no modulo bias). */
uint64_t sampler_below(sampler_rng *g, uint64_t k);

/* Triangulation (section 6.6): a uniformly random triangulation of the
** n-gon realised so that it is the polygon's exact Delaunay triangulation.
** tri (if not NULL) gets its n - 2 triangles, 3 indices into out each,
** anticlockwise; the drawn labelling's vertex 0 is the output vertex at
** the origin.  -1 when doubles do not realise the drawn triangulation (the
** exact check failed: from n of about 1.5 x 10^6 on, docs/sampling.md) or
** n < 3.  O(n).  sampler_gon_triangulation: the same as a sampler_gon_fn. */
int sampler_gon_tridt(sampler_rng *g, size_t n, geom_point *out, uint32_t *tri,
                      sampler_gon_info *info);
int sampler_gon_triangulation(sampler_rng *g, size_t n, const sampler_gon_params *p,
                              geom_point *out, sampler_gon_info *info);
/* Bounce (section 6.5): the regular n-gon, velocities uniform in the unit
** disc, 2n bounce events by p->law (0: the bounced velocity redrawn; 1:
** reflected); info->draws counts the events.  -1 when rounding spoilt the
** output 64 times running, for n < 3 or another law.  O(n log n). */
int sampler_gon_bounce(sampler_rng *g, size_t n, const sampler_gon_params *p, geom_point *out,
                       sampler_gon_info *info);
/* Dual (section 6.7): the polar dual, about the mean of its vertices, of
** the polygon of the method p->inner (sampler_gon_inner: "vector" when
** NULL; also "circle", "triangulation", "bounce", "geobench", "angles",
** "dual-rejection"), drawn
** again when rounding spoils the dual (at most 10 times).  -1 for an
** unknown inner method.  sampler_gon_polar: the polar dual of a strictly
** convex anticlockwise p about the mean of its vertices, n vertices for n
** edges, checked like every output (0 or -1). */
int sampler_gon_dual(sampler_rng *g, size_t n, const sampler_gon_params *p, geom_point *out,
                     sampler_gon_info *info);
int sampler_gon_polar(const geom_point *p, size_t n, geom_point *out);
/* Dual Rejection: n half-planes x . u < r (u a uniform direction, r uniform
** on (0, 1]) until their intersection has n sides; -1 after
** SAMPLER_DUALREJ_DRAWS half-planes.  info->draws counts them.  The
** registry takes n up to SAMPLER_DUALREJ_NMAX (9 x 10^5 half-planes a
** 10-gon, docs/sampling.md). */
#define SAMPLER_DUALREJ_DRAWS 100000000ull
#define SAMPLER_DUALREJ_NMAX 10
int sampler_gon_dualrej(sampler_rng *g, size_t n, const sampler_gon_params *p, geom_point *out,
                        sampler_gon_info *info);
/* The prior art (section 6.1): XYZ GeoBench's n radius moves of a cyclic
** polygon (about 1/e of the corners never move), and Roussille and
** Dufour's random turning angles with closing edge lengths (whose later
** turns shrink below what doubles hold: -1 from n of about 60 on). */
int sampler_gon_geobench(sampler_rng *g, size_t n, const sampler_gon_params *p, geom_point *out,
                         sampler_gon_info *info);
int sampler_gon_angles(sampler_rng *g, size_t n, const sampler_gon_params *p, geom_point *out,
                       sampler_gon_info *info);

#endif
