/*
** cmd_flip.c: `fliplab flip RULE x1 y1 x2 y2 x3 y3 x4 y4`: decide one
** convex quadrilateral ABCD with a rule.
*/
#include <math.h>
#include <string.h>
#include "cli.h"
#include "rule.h"

typedef struct cli_flip_opts {
  double tie_eps;
  const char *pos[9];     /* RULE and the 8 coordinates */
  int npos;
} cli_flip_opts;

static const cli_option cli_flip_table[] = {
  CLI_OPT_TIE_EPS("relative tolerance under which the two joint values tie", 1, cli_flip_opts,
                  tie_eps),
};

/* A leading '-' is a rule or a negative number, never an option here. */
static int cli_flip_positional(const char *cmd, const char *arg, void *dst) {
  cli_flip_opts *o = dst;
  if (strncmp(arg, "--", 2) == 0 && strlen(arg) > 2)
    return cli_unknown_option(cmd, arg, cli_flip_table, CLI_NOPTS(cli_flip_table));
  if (o->npos == 9) return cli_error(cmd, "too many arguments: expected RULE and 8 coordinates");
  o->pos[o->npos++] = arg;
  return 0;
}

static const cli_spec cli_flip_spec = {
  "flip", "usage: fliplab flip RULE x1 y1 x2 y2 x3 y3 x4 y4 [options]",
  "Decides which diagonal of the convex quadrilateral ABCD the rule prefers:\n"
  "AC (A=(x1,y1) to C=(x3,y3)), BD, or either (a tie within the tie tolerance,\n"
  "relative).  For a triangle-based rule MEASURE_JOINT both joint values are\n"
  "printed: f(AC) = f(b(ABC), b(ACD)), f(BD) = f(b(ABD), b(BCD)).\n"
  "The quadrilateral must be strictly convex; clockwise input is accepted and\n"
  "relabelled A, D, C, B (anticlockwise, same diagonals), which is noted.\n"
  "Rules, measures, joints and ties: docs/rules.md, docs/measures.md, docs/joints.md.\n",
  cli_flip_table, CLI_NOPTS(cli_flip_table), cli_flip_positional};

int cli_cmd_flip(int argc, char **argv) {
  cli_flip_opts o = {0};
  int st = cli_options_parse(&cli_flip_spec, argc, argv, &o, NULL);
  if (st != 0) return st == 1 ? 0 : st;
  const char *const *pos = o.pos;
  int npos = o.npos;
  if (npos != 9)
    return cli_error("flip", "expected RULE and 8 coordinates (x1 y1 ... x4 y4), got %d argument%s",
                     npos, npos == 1 ? "" : "s");
  rule r;
  if (cli_parse_rule("flip", pos[0], &r) != 0) return 2;
  rule_set_tie_eps(&r, o.tie_eps);
  geom_point q[4];
  static const char *const coord[8] = {"x1", "y1", "x2", "y2", "x3", "y3", "x4", "y4"};
  for (int k = 0; k < 8; k++) {
    double v = 0;
    geom_coorderr ce = geom_coord_parse(pos[1 + k], &v);   /* the coordinate contract */
    if (ce != GEOM_COORD_OK)
      return cli_error("flip", "%s '%.40s' %s", coord[k], pos[1 + k], geom_coorderr_str(ce));
    if (k % 2 == 0) q[k / 2].x = v;
    else q[k / 2].y = v;
  }
  size_t bad;
  int reversed;
  geom_polyerr e = geom_polygon_check(q, 4, &bad, &reversed);
  if (e != GEOM_OK)
    return cli_error("flip", "quadrilateral vertex %c (%s %s): %s", "ABCD"[bad],
                     pos[1 + 2 * bad], pos[2 + 2 * bad], geom_polyerr_str(e));
  double ac, bd;
  rule_choice c = rule_eval(&r, q, &ac, &bd);
  /* Decided fully before anything is printed: a bad value of a user
  ** measure or a plugin rule's bad answer fails the command, no result. */
  if (cli_userdefs_failed("flip")) return 1;
  printf("rule      %s\n", rule_name(&r));
  if (reversed) printf("note      clockwise input relabelled A, D, C, B (same diagonals)\n");
  printf("decision  %s\n", rule_choice_str(c));
  if (rule_is_triangle(&r)) {
    printf("f(AC)     %.17g\n", ac);
    printf("f(BD)     %.17g\n", bd);
    printf("tie-eps   %g\n", o.tie_eps);
  }
  return 0;
}
