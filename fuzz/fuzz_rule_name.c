/*
** fuzz_rule_name.c: the rule-name grammar (rule_parse, rule_name_split,
** rule_name_join) on any string: power-mean joints (P_3, R_-0.5), measure
** names with signs and slashes, DT.  An accepted rule prints a canonical
** name that parses back to the same rule; a refused one has a message
** (which may echo the name's bytes: the program's cli_error makes it one
** line).
*/
#include "fuzz_support.h"
#include "rule.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  char *s = fuzz_string(data, size > 128 ? 128 : size);
  rule r, back;
  char err[4096] = "";
  if (rule_parse(s, &r, err, sizeof err) == 0) {
    char again[4096] = "";
    if (rule_parse(rule_name(&r), &back, again, sizeof again) != 0) abort();
    if (strcmp(rule_name(&back), rule_name(&r)) != 0) abort();
    if (rule_is_triangle(&r) != rule_is_triangle(&back)) abort();
    if (rule_is_triangle(&r) &&
        (rule_measure(&r) != rule_measure(&back) || rule_joint(&r) != rule_joint(&back)))
      abort();
  } else if (err[0] == '\0') {
    abort();
  }
  free(s);
  return 0;
}
