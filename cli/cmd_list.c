/*
** cmd_list.c: `fliplab list`: the measures, joints and quadrilateral rules.
*/
#include <string.h>
#include "measure.h"
#include "cli.h"
#include "rule.h"
#include "joint.h"

static const char *cli_list_sign(measure_sign s) {
  return s == MEASURE_NONNEG ? ">= 0" : s == MEASURE_NONPOS ? "<= 0" : "any";
}

/* printf pads by bytes; thesis symbols are UTF-8, so widen the field by
** the number of continuation bytes to align by characters. */
static int cli_list_width(const char *s, int width) {
  for (; *s; s++)
    if (((unsigned char)*s & 0xC0) == 0x80) width++;
  return width;
}

static int cli_list_positional(const char *cmd, const char *arg, void *dst) {
  (void)dst;
  return cli_error(cmd, "unexpected argument '%s'", arg);
}

static const cli_spec cli_list_spec = {
  "list", "usage: fliplab list",
  "Lists the badness measures (name, thesis symbol, sign domain, meaning),\n"
  "the joint functions and the quadrilateral rules.  A triangle-based rule\n"
  "is named MEASURE_JOINT, e.g. R_inf, -alpha_inf, P_1, -r2/A_0.  Formulas and\n"
  "meanings: docs/measures.md, docs/joints.md, docs/rules.md.\n",
  NULL, 0, cli_list_positional};

int cli_cmd_list(int argc, char **argv) {
  int st = cli_options_parse(&cli_list_spec, argc, argv, NULL, NULL);
  if (st != 0) return st == 1 ? 0 : st;
  printf("Badness measures (%d; small is good, angles in radians):\n", measure_count());
  printf("  %-9s %-9s %-5s %s\n", "name", "symbol", "sign", "description");
  for (int m = 0; m < measure_count(); m++) {
    const measure *M = measure_get(m);
    printf("  %-9s %-*s %-5s %s%s\n", M->name, cli_list_width(M->symbol, 9), M->symbol,
           cli_list_sign(M->sign), M->desc,
           m >= MEASURE_BUILTIN_COUNT ? " (user-defined)" : "");
  }
  printf("\nJoint functions (%d):\n", JOINT_COUNT);
  printf("  %-5s %-7s %s\n", "name", "symbol", "f(x, y) for values >= 0");
  for (int j = 0; j < JOINT_COUNT; j++) {
    const joint *J = joint_get((joint_id)j);
    printf("  %-5s %-7s %s\n", J->name, J->symbol, J->desc);
  }
  printf("  For measures with values <= 0 the joints -1, 0, 1, 2 act on |x|, |y|\n"
         "  and the result is negated; -inf and inf are used as they are.\n");
  printf("\nQuadrilateral rules (%d):\n", rule_quad_count());
  for (int q = 0; q < rule_quad_count(); q++)
    printf("  %-9s %s\n", rule_quad_get(q)->name, rule_quad_get(q)->desc);
  return 0;
}
