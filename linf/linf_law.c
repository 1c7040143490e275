/*
** linf_law.c: theorem 14 of the thesis (the most l_inf circumcubes of
** non-degenerate d + 1 points, and a configuration that attains it), and
** the exact law of the circumcube count of d + 1 random points.
*/
#include <string.h>
#include "linf.h"

int linf_bound(int d) {
  return 1 << ((d - 1) / 2);
}

/* The thesis's R^5 example, generalised: p_0 and p_1 the far pair on
** coordinate 0 (0 and 4, every other coordinate 1); then pairs of points
** on pairs of coordinates (0, 0) and (2, 2), each pair with two choices
** of faces; for even d one point left, the only minimum of the last
** coordinate, whose maximum p_1 holds (2). */
void linf_extremal(int d, double *pts) {
  for (int j = 0; j <= d; j++)
    for (int i = 0; i < d; i++) pts[j * d + i] = 1;
  pts[0] = 0;
  pts[d] = 4;
  int j = 2, i = 1;
  for (; i + 1 < d; i += 2, j += 2) {
    pts[j * d + i] = pts[j * d + i + 1] = 0;
    pts[(j + 1) * d + i] = pts[(j + 1) * d + i + 1] = 2;
  }
  if (i < d) {
    pts[j * d + i] = 0;
    pts[d + i] = 2;
  }
}

/* One representative of a rank pattern: coordinate 0 of extent 4, its
** maximum point 0 and minimum point 1; coordinate i of extent 2, its
** maximum point mx[i] and minimum point mn[i]; every other value 0. */
static void linf_law_points(int d, const int *mx, const int *mn, double *pts) {
  memset(pts, 0, (size_t)(d + 1) * (size_t)d * sizeof *pts);
  pts[0] = 2;
  pts[d] = -2;
  for (int i = 1; i < d; i++) {
    pts[mx[i] * d + i] = 1;
    pts[mn[i] * d + i] = -1;
  }
}

/* The points of d + 1 independent points with independent continuous
** coordinates are exchangeable, and so are the coordinates: the maximum
** and the minimum of each coordinate are a uniform ordered pair of
** distinct points, independent of the extents (the ranks of a sample are
** independent of its order statistics), and the coordinate of largest
** extent is uniform.  Fixing it to coordinate 0 with maximum 0 and minimum
** 1 loses nothing by symmetry, and the count depends on nothing else
** (linf.h): so the law is the count over the (d (d + 1))^{d-1} patterns of
** the other coordinates, each computed by linf_circumcubes on a
** representative. */
uint64_t linf_rank_law(int d, uint64_t *law) {
  memset(law, 0, (LINF_CUBES_MAX + 1) * sizeof *law);
  if (d < LINF_DIM_MIN || d > 5) return 0;
  int n = d + 1, pairs = n * (n - 1), code[LINF_DIM_MAX] = {0};
  int mx[LINF_DIM_MAX] = {0}, mn[LINF_DIM_MAX] = {0};
  double pts[(LINF_DIM_MAX + 1) * LINF_DIM_MAX];
  linf_cube cubes[LINF_CUBES_MAX];
  uint64_t total = 0;
  for (;;) {
    for (int i = 1; i < d; i++) {
      mx[i] = code[i] / (n - 1);
      mn[i] = code[i] % (n - 1);
      mn[i] += mn[i] >= mx[i];
    }
    linf_law_points(d, mx, mn, pts);
    int c = linf_circumcubes(pts, d, cubes);
    law[c < 0 ? 0 : c]++;   /* never infinite: each extreme is unique */
    total++;
    int i = 1;
    while (i < d && ++code[i] == pairs) code[i++] = 0;
    if (i == d) return total;
  }
}
