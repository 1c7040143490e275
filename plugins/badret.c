/*
** badret.c: a deliberately broken plugin for the tests: its rule "badret"
** returns 7, which is neither AC, BD nor EITHER; a command that meets it
** must fail with a one-line error and print no result.
*/
#include <fliplab/plugin.h>

static int badret_fn(const fliplab_plugin_point q[4]) {
  (void)q;
  return 7;
}

static const fliplab_plugin_rule badret_rules[] = {{"badret", "returns 7", badret_fn}};

static const fliplab_plugin badret_plugin = {
  FLIPLAB_PLUGIN_ABI, "badret", "a rule with a bad return value", 0, 0, 1, badret_rules,
};

const fliplab_plugin *fliplab_plugin_entry(void) {
  return &badret_plugin;
}
