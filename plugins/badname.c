/*
** badname.c: a deliberately broken plugin for the tests: its rule's name
** holds a newline, which would split `list` and the lot header, and must
** be refused like a measure name (docs/plugins.md).
*/
#include <fliplab/plugin.h>

static int badname_fn(const fliplab_plugin_point q[4]) {
  (void)q;
  return FLIPLAB_PLUGIN_AC;
}

static const fliplab_plugin_rule badname_rules[] = {{"bad\nname", "always AC", badname_fn}};

static const fliplab_plugin badname_plugin = {
  FLIPLAB_PLUGIN_ABI, "badname", "a rule name with a newline", 0, 0, 1, badname_rules,
};

const fliplab_plugin *fliplab_plugin_entry(void) {
  return &badname_plugin;
}
