/*
** rule156.c: example plugin: thesis table 3.1's rule [156] as a whole-
** quadrilateral rule named "rule156", plus one measure, "P2/A".
**
** Rule [156]: "Choose the shorter diagonal provided that the minimum angle
** is above some threshold."  Here the threshold is fixed at 30 degrees and
** the minimum angle is that of the two triangles the diagonal makes:
**   1. the shorter diagonal, if its minimum angle is >= 30 degrees;
**   2. otherwise the diagonal whose minimum angle is larger (max-min angle,
**      i.e. the Delaunay choice), the shorter one if the minima are equal;
**   equal lengths: the larger minimum angle, EITHER if those are equal too.
** Both diagonals are treated alike, so the rule does not depend on which
** vertex is called A.
**
** Measure "P2/A": perimeter^2 / area, the "sliveriness" of table 3.1
** ([282-284]); >= 0, 12 sqrt(3) for the equilateral triangle.
*/
#include <math.h>
#include <fliplab/plugin.h>

#define RULE156_THRESHOLD 0.52359877559829887   /* 30 degrees = pi/6 */

/* Angle at o between the edges to u and w, accurate for small angles. */
static double rule156_angle(fliplab_plugin_point o, fliplab_plugin_point u, fliplab_plugin_point w) {
  double ux = u.x - o.x, uy = u.y - o.y, wx = w.x - o.x, wy = w.y - o.y;
  return atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy);
}

static double rule156_min_angle(fliplab_plugin_point p, fliplab_plugin_point q, fliplab_plugin_point r) {
  double a = rule156_angle(p, q, r), b = rule156_angle(q, r, p), c = rule156_angle(r, p, q);
  return fmin(a, fmin(b, c));
}

static double rule156_len2(fliplab_plugin_point p, fliplab_plugin_point q) {
  return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y);
}

static int rule156_fn(const fliplab_plugin_point q[4]) {
  double ac = rule156_len2(q[0], q[2]), bd = rule156_len2(q[1], q[3]);
  double min_ac = fmin(rule156_min_angle(q[0], q[1], q[2]), rule156_min_angle(q[0], q[2], q[3]));
  double min_bd = fmin(rule156_min_angle(q[0], q[1], q[3]), rule156_min_angle(q[1], q[2], q[3]));
  int by_angle = min_ac > min_bd ? FLIPLAB_PLUGIN_AC
               : min_bd > min_ac ? FLIPLAB_PLUGIN_BD : FLIPLAB_PLUGIN_EITHER;
  if (ac == bd) return by_angle;
  int shorter = ac < bd ? FLIPLAB_PLUGIN_AC : FLIPLAB_PLUGIN_BD;
  double min_short = shorter == FLIPLAB_PLUGIN_AC ? min_ac : min_bd;
  if (min_short >= RULE156_THRESHOLD) return shorter;
  return by_angle == FLIPLAB_PLUGIN_EITHER ? shorter : by_angle;
}

static double rule156_p2_over_a(const fliplab_plugin_tri *t) {
  return t->P * t->P / t->A;
}

static const fliplab_plugin_rule rule156_rules[] = {
  {"rule156", "[156] shorter diagonal if its minimum angle is >= 30 deg, else the larger minimum angle",
   rule156_fn},
};

static const fliplab_plugin_measure rule156_measures[] = {
  {"P2/A", "perimeter^2/area (sliveriness)", FLIPLAB_PLUGIN_NONNEG, rule156_p2_over_a},
};

static const fliplab_plugin rule156_plugin = {
  FLIPLAB_PLUGIN_ABI, "rule156", "thesis table 3.1, rule [156], and the measure P2/A",
  1, rule156_measures, 1, rule156_rules,
};

const fliplab_plugin *fliplab_plugin_entry(void) {
  return &rule156_plugin;
}
