/*
** points.c: point sets for `fliplab lot` (sampler.h lists them): random
** ones drawn from one generator stream of the seed, the structured sets of
** the thesis's worst cases and degenerate inputs, and the input families of
** the benchmarks (clusters, a jittered grid, points on few lines, many
** duplicates).  One table row a family: its name and the function that
** fills the n points from the stream.
*/
#include <math.h>
#include <string.h>
#include "sampler.h"

#define SAMPLER_POINTS_2PI 6.28318530717958647693

/* n points of one family from the stream g (already seeded). */
typedef void (*sampler_points_fill)(sampler_rng *g, size_t n, geom_point *out);

/* The side of the square grid that holds n points: ceil(sqrt(n)). */
static size_t sampler_points_side(size_t n) {
  size_t side = (size_t)ceil(sqrt((double)n));
  while (side * side < n) side++;
  return side;
}

/* A uniform integer in [0, k), k >= 1: the draw modulo k (the bias, below
** k / 2^64, is far below anything a test or a benchmark could see). */
static int64_t sampler_points_int(sampler_rng *g, uint64_t k) {
  return (int64_t)(sampler_next(g) % k);
}

static void sampler_fill_uniform(sampler_rng *g, size_t n, geom_point *out) {
  for (size_t i = 0; i < n; i++) {
    double x = sampler_uniform(g);
    out[i] = (geom_point){x, sampler_uniform(g)};
  }
}

static void sampler_fill_normal(sampler_rng *g, size_t n, geom_point *out) {
  for (size_t i = 0; i < n; i++) {
    double x = sampler_normal(g);
    out[i] = (geom_point){x, sampler_normal(g)};
  }
}

static void sampler_fill_disc(sampler_rng *g, size_t n, geom_point *out) {
  for (size_t i = 0; i < n; i++) out[i] = sampler_disc(g);
}

static void sampler_fill_grid(sampler_rng *g, size_t n, geom_point *out) {
  (void)g;
  size_t side = sampler_points_side(n);
  for (size_t i = 0; i < n; i++) out[i] = (geom_point){(double)(i % side), (double)(i / side)};
}

static void sampler_fill_parabola(sampler_rng *g, size_t n, geom_point *out) {
  (void)g;
  for (size_t i = 0; i < n; i++) {
    double x = (double)(n - i);
    out[i] = (geom_point){x, x * x};
  }
}

static void sampler_fill_circle(sampler_rng *g, size_t n, geom_point *out) {
  for (size_t i = 0; i < n; i++) {
    double th = SAMPLER_POINTS_2PI * sampler_uniform(g);
    out[i] = (geom_point){cos(th), sin(th)};
  }
}

/* The centres first (x then y, uniform in the unit square), then for each
** point its cluster floor(K u) and two normal deviates scaled by sigma. */
static void sampler_fill_clustered(sampler_rng *g, size_t n, geom_point *out) {
  geom_point c[SAMPLER_CLUSTER_COUNT];
  sampler_fill_uniform(g, SAMPLER_CLUSTER_COUNT, c);
  for (size_t i = 0; i < n; i++) {
    geom_point m = c[(int)(SAMPLER_CLUSTER_COUNT * sampler_uniform(g))];
    double dx = SAMPLER_CLUSTER_SIGMA * sampler_normal(g);
    out[i] = (geom_point){m.x + dx, m.y + SAMPLER_CLUSTER_SIGMA * sampler_normal(g)};
  }
}

/* The grid's points, each coordinate moved by (2u - 1) J: 2u - 1 and the
** product by the power of two J are exact, the sum is rounded once. */
static void sampler_fill_jittered(sampler_rng *g, size_t n, geom_point *out) {
  sampler_fill_grid(g, n, out);
  for (size_t i = 0; i < n; i++) {
    double dx = (2 * sampler_uniform(g) - 1) * SAMPLER_JITTER;
    out[i].x += dx;
    out[i].y += (2 * sampler_uniform(g) - 1) * SAMPLER_JITTER;
  }
}

/* One draw of the lines family (sampler.h): every product and sum is an
** integer below 2^7 m in magnitude, exact in a double for any n that fits
** in memory, so the points of a line are exactly collinear. */
static void sampler_lines_draw(sampler_rng *g, size_t n, geom_point *out) {
  int64_t m = (int64_t)((n + SAMPLER_LINE_COUNT - 1) / SAMPLER_LINE_COUNT);
  int64_t a[SAMPLER_LINE_COUNT][4];   /* anchor x, y; direction x, y */
  for (int k = 0; k < SAMPLER_LINE_COUNT; k++) {
    a[k][0] = sampler_points_int(g, (uint64_t)(128 * m)) - 64 * m;
    a[k][1] = sampler_points_int(g, (uint64_t)(128 * m)) - 64 * m;
    do {
      a[k][2] = sampler_points_int(g, 17) - 8;
      a[k][3] = sampler_points_int(g, 17) - 8;
    } while (a[k][2] == 0 && a[k][3] == 0);
  }
  for (size_t i = 0; i < n; i++) {
    const int64_t *l = a[i % SAMPLER_LINE_COUNT];
    int64_t t = 16 * (int64_t)(i / SAMPLER_LINE_COUNT) + sampler_points_int(g, 16) - 8 * m;
    out[i] = (geom_point){(double)(l[0] + t * l[2]), (double)(l[1] + t * l[3])};
  }
}

/* 1 when the n points are all on one line (or all equal), exactly. */
static int sampler_points_collinear(const geom_point *p, size_t n) {
  size_t j = 1;
  while (j < n && p[j].x == p[0].x && p[j].y == p[0].y) j++;
  for (size_t i = j + 1; i < n; i++)
    if (geom_orient(p[0], p[j], p[i]) != 0) return 0;
  return 1;
}

/* Small sets of integer points can fall on one line (three points, each on
** its own line, about one draw in a hundred): such a draw is replaced by
** the next one of the stream, so that every set of three or more points
** can be triangulated. */
static void sampler_fill_lines(sampler_rng *g, size_t n, geom_point *out) {
  do sampler_lines_draw(g, n, out);
  while (n >= 3 && sampler_points_collinear(out, n));
}

/* The pool (the uniform family's first m points), then copies of pool
** points drawn uniformly. */
static void sampler_fill_dups(sampler_rng *g, size_t n, geom_point *out) {
  size_t m = (n + SAMPLER_DUPS_SHARE - 1) / SAMPLER_DUPS_SHARE;
  if (m < 3) m = n < 3 ? n : 3;
  sampler_fill_uniform(g, m, out);
  for (size_t i = m; i < n; i++) out[i] = out[sampler_points_int(g, m)];
}

static const struct sampler_points_row {
  const char *name;
  sampler_points_fill fill;
} sampler_points_table[SAMPLER_POINTS_COUNT] = {
  {"uniform", sampler_fill_uniform},     {"normal", sampler_fill_normal},
  {"disc", sampler_fill_disc},           {"grid", sampler_fill_grid},
  {"parabola", sampler_fill_parabola},   {"circle", sampler_fill_circle},
  {"clustered", sampler_fill_clustered}, {"jittered", sampler_fill_jittered},
  {"lines", sampler_fill_lines},         {"dups", sampler_fill_dups}};

const char sampler_points_names[] =
  "uniform, normal, disc, grid, parabola, circle, clustered, jittered, lines, dups";

int sampler_points_find(const char *s) {
  for (int k = 0; k < SAMPLER_POINTS_COUNT; k++)
    if (strcmp(s, sampler_points_table[k].name) == 0) return k;
  return -1;
}

const char *sampler_points_name(sampler_points_kind k) {
  return sampler_points_table[k].name;
}

/* Cost: O(n) draws and arithmetic for every family (lines: O(n) more per
** redrawn set, which happens only for small n). */
void sampler_points(sampler_points_kind k, uint64_t seed, size_t n, geom_point *out) {
  sampler_rng g;
  sampler_seed(&g, seed, GEOM_STREAM_POINTS);
  sampler_points_table[k].fill(&g, n, out);
}
