/*
** plugin_loader.h: loading plugins (fliplab/plugin.h) into the measure and
** quadrilateral-rule registries: the program's --plugin, and the Python
** package's fliplab.load_plugin (python/, through the shared library).
** Installed as <fliplab/plugin_loader.h>; a plugin itself needs only
** <fliplab/plugin.h>.
*/
#ifndef FLIPLAB_PLUGIN_LOADER_H
#define FLIPLAB_PLUGIN_LOADER_H

#include <stddef.h>

/* dlopen path (a bare file name means ./NAME, not a library search), check
** the ABI version and every name, then register the plugin's measures and
** quadrilateral rules, all or none.  0, or -1 with a one-line message. */
int plugin_load(const char *path, char *err, size_t errlen);

/* Number of plugins loaded. */
int plugin_count(void);

#endif
