/*
** rule109.c: example plugin: thesis table 3.1's rule [109] as a whole-
** quadrilateral rule named "rule109".
**
** The thesis: "Let I be the point where the diagonals of ABCD intersect.
** If AC is the shorter diagonal we select it provided 1/4 <= AI/IC <= 4."
** It leaves open what happens otherwise; a flip rule must not depend on
** which vertex is called A, so the definition here treats both diagonals
** alike.  Call a diagonal balanced when I splits it in a ratio between
** 1/4 and 4 (AI/IC for AC, BI/ID for BD).  Then:
**   1. the shorter diagonal, if it is balanced;
**   2. otherwise the longer one, if it is balanced;
**   3. otherwise (neither balanced) the shorter one;
**   equal lengths: the balanced one if exactly one is, else EITHER.
**
** Ratios without division or square roots: I lies on BD, so
** AI/IC = dist(A, BD)/dist(C, BD) = |BDA|/|BDC| (twice-areas, cross
** products); lengths are compared squared.
*/
#include <fliplab/plugin.h>

static double rule109_cross(fliplab_plugin_point o, fliplab_plugin_point a, fliplab_plugin_point b) {
  double c = (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  return c < 0 ? -c : c;
}

static double rule109_len2(fliplab_plugin_point p, fliplab_plugin_point q) {
  return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y);
}

/* 1/4 <= num/den <= 4 */
static int rule109_balanced(double num, double den) {
  return 4 * num >= den && num <= 4 * den;
}

static int rule109_fn(const fliplab_plugin_point q[4]) {
  double ac = rule109_len2(q[0], q[2]), bd = rule109_len2(q[1], q[3]);
  int ok_ac = rule109_balanced(rule109_cross(q[1], q[3], q[0]), rule109_cross(q[1], q[3], q[2]));
  int ok_bd = rule109_balanced(rule109_cross(q[0], q[2], q[1]), rule109_cross(q[0], q[2], q[3]));
  if (ac == bd)
    return ok_ac == ok_bd ? FLIPLAB_PLUGIN_EITHER : ok_ac ? FLIPLAB_PLUGIN_AC : FLIPLAB_PLUGIN_BD;
  int shorter = ac < bd ? FLIPLAB_PLUGIN_AC : FLIPLAB_PLUGIN_BD;
  int longer = 1 - shorter;
  int ok_short = shorter == FLIPLAB_PLUGIN_AC ? ok_ac : ok_bd;
  int ok_long = shorter == FLIPLAB_PLUGIN_AC ? ok_bd : ok_ac;
  if (ok_short) return shorter;
  if (ok_long) return longer;
  return shorter;
}

static const fliplab_plugin_rule rule109_rules[] = {
  {"rule109", "[109] shorter diagonal if I splits it within 1/4..4, else the other if balanced, else the shorter",
   rule109_fn},
};

static const fliplab_plugin rule109_plugin = {
  FLIPLAB_PLUGIN_ABI, "rule109", "thesis table 3.1, rule [109]", 0, 0, 1, rule109_rules,
};

const fliplab_plugin *fliplab_plugin_entry(void) {
  return &rule109_plugin;
}
