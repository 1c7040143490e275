/*
** fuzz_formula.c: the formula parser (`--define 'NAME = EXPR'`): defining,
** then evaluating the measure on a few triangles, then forgetting it.
*/
#include "formula.h"
#include "fuzz_support.h"
#include "measure.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  char *def = fuzz_string(data, size);
  char err[1024];
  int id = formula_define(def, err, sizeof err);
  if (id >= 0) {
    static const geom_point pts[][3] = {
      {{0, 0}, {1, 0}, {0, 1}}, {{0, 0}, {1e-3, 0}, {0.5, 1e-9}}, {{-1e6, 3}, {2e6, 1}, {0, 7e5}}};
    for (size_t k = 0; k < sizeof pts / sizeof pts[0]; k++) {
      geom_tri t;
      geom_tri_make(&t, pts[k][0], pts[k][1], pts[k][2]);
      (void)measure_eval(id, &t);
    }
  } else if (err[0] == '\0') {
    abort();   /* a refusal always says why (cli_error makes it one line) */
  }
  formula_clear_errors();
  measure_unregister_user();
  formula_reset();
  free(def);
  return 0;
}
