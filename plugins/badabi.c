/*
** badabi.c: a deliberately broken plugin for the tests: it reports an ABI
** version fliplab does not speak, and must be refused with a one-line error.
*/
#include <fliplab/plugin.h>

static int badabi_fn(const fliplab_plugin_point q[4]) {
  (void)q;
  return FLIPLAB_PLUGIN_AC;
}

static const fliplab_plugin_rule badabi_rules[] = {{"badabi", "always AC", badabi_fn}};

static const fliplab_plugin badabi_plugin = {
  FLIPLAB_PLUGIN_ABI + 41, "badabi", "wrong ABI version", 0, 0, 1, badabi_rules,
};

const fliplab_plugin *fliplab_plugin_entry(void) {
  return &badabi_plugin;
}
