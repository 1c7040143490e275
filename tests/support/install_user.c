/*
** install_user.c: a program using the installed library (install_check.sh):
** the Delaunay-equivalent rule R_1 must agree with DT on a quadrilateral.
*/
#include <stdio.h>
#include <fliplab/rule.h>

int main(void) {
  geom_point q[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1.1}};
  rule r1, dt = rule_delaunay();
  char err[4096];
  if (rule_parse("R_1", &r1, err, sizeof err) != 0) return 1;
  rule_choice a = rule_eval(&r1, q, RULE_DEFAULT_TIE_EPS, NULL, NULL);
  rule_choice b = rule_eval(&dt, q, RULE_DEFAULT_TIE_EPS, NULL, NULL);
  printf("R_1 %s, DT %s\n", rule_choice_str(a), rule_choice_str(b));
  return a == b && a != RULE_EITHER ? 0 : 1;
}
