/*
** fuzz_quad_dt.c: a differential oracle for the scale contract.  Eight
** doubles make a quadrilateral; if the polygon check accepts it (strictly
** convex, every coordinate 0 or of magnitude in [1e-30, 1e30]), no rule
** that is always Delaunay (R with every joint, -alpha_inf, -r_1, abc_1,
** -r/R_1, -r2/A_0) may contradict the exact DT: it may tie (the spec's
** tolerance, near cocircular or flat shapes), never pick the other
** diagonal.  The vectorised pentagon engine is not involved here; the
** quadrilateral path (geom_tri_make, measures, joint_compare) is.
*/
#include <math.h>
#include "fuzz_support.h"
#include "geom.h"
#include "rule.h"

static const char *const fuzz_dt_rules[] = {
  "R_-inf", "R_-1", "R_0", "R_1", "R_2", "R_inf", "-alpha_inf", "-r_1", "abc_1",
  "-r/R_1", "-r2/A_0"};
#define FUZZ_NRULES (sizeof fuzz_dt_rules / sizeof fuzz_dt_rules[0])

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static rule rules[FUZZ_NRULES];
  static int ready;
  if (!ready) {
    char err[512];
    for (size_t i = 0; i < FUZZ_NRULES; i++)
      if (rule_parse(fuzz_dt_rules[i], &rules[i], err, sizeof err) != 0) abort();
    ready = 1;
  }
  if (size < sizeof(geom_point[4])) return 0;
  geom_point q[4];
  memcpy(q, data, sizeof q);
  size_t bad;
  int rev;
  if (geom_polygon_check(q, 4, &bad, &rev) != GEOM_OK) return 0;
  rule dt = rule_delaunay();
  rule_choice d = rule_eval(&dt, q, NULL, NULL);
  for (size_t i = 0; i < FUZZ_NRULES; i++) {
    double ac, bd;
    rule_choice c = rule_eval(&rules[i], q, &ac, &bd);
    if (c != RULE_EITHER && d != RULE_EITHER && c != d) {
      fprintf(stderr, "%s says %s, DT %s: (%.17g,%.17g) (%.17g,%.17g) (%.17g,%.17g) (%.17g,%.17g)"
              " values %.17g %.17g\n", fuzz_dt_rules[i], rule_choice_str(c), rule_choice_str(d),
              q[0].x, q[0].y, q[1].x, q[1].y, q[2].x, q[2].y, q[3].x, q[3].y, ac, bd);
      abort();
    }
  }
  return 0;
}
