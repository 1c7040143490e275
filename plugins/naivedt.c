/*
** naivedt.c: example plugin: the Delaunay rule decided by a naive
** double-precision in-circle determinant, as a whole-quadrilateral rule
** named "naiveDT".  It is the experiment of the thesis's section 7.5:
** "Delaunay triangulation algorithms sometimes fail because computations
** are inexact ... the approximated DT flip rule is not systematic and
** local."  No filter, no exact fallback: the textbook 4x4 determinant
**
**     | ax ay ax^2+ay^2 1 |
**     | bx by bx^2+by^2 1 |
**     | cx cy cx^2+cy^2 1 |   > 0  when D is inside circle ABC (ABC anticlockwise)
**     | dx dy dx^2+dy^2 1 |
**
** expanded along its last column in raw coordinates, so its rounding error
** grows with the coordinates' magnitude rather than with the points'
** spread.  On near-cocircular points far from the origin (points on a
** circle, a rotated grid) its sign is noise, and `fliplab lot` can meet a
** flip sequence that returns to an earlier triangulation: it reports a
** cycle (or, for very long ones, an exhausted flip budget) and stops.
** Use it only to watch that happen; fliplab's own DT is exact.
*/
#include <fliplab/plugin.h>

/* The 3x3 determinant of rows (x, y, x^2 + y^2) of three points. */
static double naivedt_det3(fliplab_plugin_point p, fliplab_plugin_point q, fliplab_plugin_point r) {
  double lp = p.x * p.x + p.y * p.y, lq = q.x * q.x + q.y * q.y, lr = r.x * r.x + r.y * r.y;
  return p.x * (q.y * lr - lq * r.y) - p.y * (q.x * lr - lq * r.x) + lp * (q.x * r.y - q.y * r.x);
}

static int naivedt_fn(const fliplab_plugin_point q[4]) {
  /* Laplace expansion along the column of ones. */
  double det = -naivedt_det3(q[1], q[2], q[3]) + naivedt_det3(q[0], q[2], q[3])
             - naivedt_det3(q[0], q[1], q[3]) + naivedt_det3(q[0], q[1], q[2]);
  if (det > 0) return FLIPLAB_PLUGIN_BD;     /* D inside circle ABC: BD is Delaunay */
  if (det < 0) return FLIPLAB_PLUGIN_AC;
  return FLIPLAB_PLUGIN_EITHER;
}

static const fliplab_plugin_rule naivedt_rules[] = {
  {"naiveDT", "Delaunay by a naive floating-point in-circle determinant (thesis 7.5; inexact)",
   naivedt_fn},
};

static const fliplab_plugin naivedt_plugin = {
  FLIPLAB_PLUGIN_ABI, "naivedt", "thesis section 7.5: an inexact Delaunay rule", 0, 0, 1,
  naivedt_rules,
};

const fliplab_plugin *fliplab_plugin_entry(void) {
  return &naivedt_plugin;
}
