/*
** plugin.c: the plugin loader: dlopen a shared object, check its ABI
** version and names, and register its measures and quadrilateral rules.
**
** The plugin's structs are not fliplab's: measures see a
** fliplab_plugin_tri copied from the geom_tri (19 doubles, a few ns, and
** geom_tri may change without breaking plugins), rules see
** fliplab_plugin_point copies.  Plugins stay loaded until exit: the
** registries point into them.
*/
#include <dlfcn.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "formula.h"
#include "measure.h"
#include "plugin.h"
#include "plugin_loader.h"
#include "rule.h"

#define PLUGIN_MAX 16
#define PLUGIN_ITEMS_MAX 32     /* measures or rules per plugin */

static int plugin_n;

/* The ABI's sign constants are the registry's, so a promise converts by cast. */
_Static_assert((int)FLIPLAB_PLUGIN_NONPOS == (int)MEASURE_NONPOS && (int)FLIPLAB_PLUGIN_ANYSIGN == (int)MEASURE_ANYSIGN
               && (int)FLIPLAB_PLUGIN_NONNEG == (int)MEASURE_NONNEG, "plugin sign constants");

static double plugin_measure_fn(const geom_tri *t, void *ctx) {
  const fliplab_plugin_measure *m = ctx;
  fliplab_plugin_tri p = {
    .v = {{t->v[0].x, t->v[0].y}, {t->v[1].x, t->v[1].y}, {t->v[2].x, t->v[2].y}},
    .a = t->a, .b = t->b, .c = t->c,
    .alpha = t->alpha, .beta = t->beta, .gamma = t->gamma,
    .A = t->area, .P = t->P, .R = t->R, .r = t->r, .h = t->h, .rx = t->rx, .ry = t->ry,
  };
  return formula_check_value(m->name, t, m->fn(&p), (measure_sign)m->sign, 1);
}

static rule_choice plugin_rule_fn(const geom_point q[4], void *ctx) {
  const fliplab_plugin_rule *r = ctx;
  fliplab_plugin_point p[4];
  for (int i = 0; i < 4; i++) p[i] = (fliplab_plugin_point){q[i].x, q[i].y};
  int d = r->fn(p);
  if (d == FLIPLAB_PLUGIN_AC) return RULE_AC;
  if (d == FLIPLAB_PLUGIN_BD) return RULE_BD;
  if (d != FLIPLAB_PLUGIN_EITHER) {
    char msg[512];
    snprintf(msg, sizeof msg,
             "rule '%s' returned %d (not AC=0, BD=1 or EITHER=2) on the quadrilateral "
             "(%.17g, %.17g), (%.17g, %.17g), (%.17g, %.17g), (%.17g, %.17g)",
             r->name, d, q[0].x, q[0].y, q[1].x, q[1].y, q[2].x, q[2].y, q[3].x, q[3].y);
    formula_note_message(msg);
  }
  return RULE_EITHER;
}

/* Quadrilateral-rule names follow the measure-name alphabet (no '_', so
** "NAME" can never be read as MEASURE_JOINT; nothing that splits a line
** of `list` or a CSV row) and must be new. */
static int plugin_check_rule_name(const char *name, char *err, size_t errlen) {
  if (measure_check_name("rule", name, err, errlen) != 0) return -1;
  for (int i = 0; i < rule_quad_count(); i++)
    if (strcmp(rule_quad_get(i)->name, name) == 0) {
      snprintf(err, errlen, "rule '%s' already exists", name);
      return -1;
    }
  return 0;
}

/* Everything a plugin declares is checked before anything is registered,
** so a bad plugin leaves the registries as they were. */
static int plugin_validate(const fliplab_plugin *pl, char *err, size_t errlen) {
  char why[300];
  if (pl->nmeasures < 0 || pl->nmeasures > PLUGIN_ITEMS_MAX || pl->nrules < 0 ||
      pl->nrules > PLUGIN_ITEMS_MAX || (pl->nmeasures > 0 && pl->measures == NULL) ||
      (pl->nrules > 0 && pl->rules == NULL)) {
    snprintf(err, errlen, "declares %d measures and %d rules (0-%d of each, arrays non-NULL)",
             pl->nmeasures, pl->nrules, PLUGIN_ITEMS_MAX);
    return -1;
  }
  if (pl->nmeasures + pl->nrules == 0) {
    snprintf(err, errlen, "declares no measure and no rule");
    return -1;
  }
  if (measure_count() + pl->nmeasures > MEASURE_MAX ||
      rule_quad_count() + pl->nrules > RULE_QUAD_MAX) {
    snprintf(err, errlen, "too many measures or rules loaded (at most %d and %d)", MEASURE_MAX,
             RULE_QUAD_MAX);
    return -1;
  }
  for (int i = 0; i < pl->nmeasures; i++) {
    const fliplab_plugin_measure *m = &pl->measures[i];
    if (m->name == NULL || m->fn == NULL) {
      snprintf(err, errlen, "measure %d has no name or no function", i);
      return -1;
    }
    if (m->sign < -1 || m->sign > 1) {
      snprintf(err, errlen, "measure '%s' has sign %d (expected -1, 0 or 1)", m->name, m->sign);
      return -1;
    }
    if (formula_check_name(m->name, why, sizeof why) != 0) {
      snprintf(err, errlen, "%s", why);
      return -1;
    }
    for (int k = 0; k < i; k++)
      if (strcmp(pl->measures[k].name, m->name) == 0) {
        snprintf(err, errlen, "declares measure '%s' twice", m->name);
        return -1;
      }
  }
  for (int i = 0; i < pl->nrules; i++) {
    const fliplab_plugin_rule *r = &pl->rules[i];
    if (r->name == NULL || r->fn == NULL) {
      snprintf(err, errlen, "rule %d has no name or no function", i);
      return -1;
    }
    if (plugin_check_rule_name(r->name, why, sizeof why) != 0) {
      snprintf(err, errlen, "%s", why);
      return -1;
    }
    for (int k = 0; k < i; k++)
      if (strcmp(pl->rules[k].name, r->name) == 0) {
        snprintf(err, errlen, "declares rule '%s' twice", r->name);
        return -1;
      }
  }
  return 0;
}

static void plugin_register(const fliplab_plugin *pl) {
  for (int i = 0; i < pl->nmeasures; i++) {
    const fliplab_plugin_measure *m = &pl->measures[i];
    measure M = {m->name, m->name, m->desc ? m->desc : "plugin measure",
                 (measure_sign)m->sign, plugin_measure_fn, (void *)m};
    measure_register(&M);
  }
  for (int i = 0; i < pl->nrules; i++) {
    const fliplab_plugin_rule *r = &pl->rules[i];
    rule_quad Q = {r->name, r->desc ? r->desc : "plugin rule", plugin_rule_fn, (void *)r};
    rule_quad_register(&Q);
  }
}

/* dlerror() text may span a path and a reason but is one line; keep it. */
int plugin_load(const char *path, char *err, size_t errlen) {
  char file[4096], why[400];
  if (plugin_n >= PLUGIN_MAX) {
    snprintf(err, errlen, "too many plugins (at most %d)", PLUGIN_MAX);
    return -1;
  }
  /* dlopen searches the library path for a name without '/'; a user
  ** naming a file means that file. */
  snprintf(file, sizeof file, "%s%s", strchr(path, '/') ? "" : "./", path);
  if (access(file, R_OK) != 0) {
    snprintf(err, errlen, "cannot open '%s': %s", path, strerror(errno));
    return -1;
  }
  dlerror();
  void *h = dlopen(file, RTLD_NOW | RTLD_LOCAL);
  if (h == NULL) {
    const char *e = dlerror();
    snprintf(err, errlen, "cannot load '%s': %s", path, e ? e : "unknown dlopen error");
    return -1;
  }
  fliplab_plugin_entry_fn entry;
  void *sym = dlsym(h, FLIPLAB_PLUGIN_ENTRY);
  /* POSIX blesses this conversion of dlsym's result; memcpy keeps
  ** -Wpedantic quiet about object-to-function pointer casts. */
  memcpy(&entry, &sym, sizeof entry);
  if (sym == NULL) {
    snprintf(err, errlen, "'%s' does not export %s() (is it a fliplab plugin?)", path,
             FLIPLAB_PLUGIN_ENTRY);
    dlclose(h);
    return -1;
  }
  const fliplab_plugin *pl = entry();
  if (pl == NULL) {
    snprintf(err, errlen, "'%s': %s() returned NULL", path, FLIPLAB_PLUGIN_ENTRY);
    dlclose(h);
    return -1;
  }
  if (pl->abi != FLIPLAB_PLUGIN_ABI) {
    snprintf(err, errlen,
             "'%s' was built for plugin ABI %d, this fliplab speaks ABI %d "
             "(rebuild it against this fliplab's fliplab/plugin.h)",
             path, pl->abi, FLIPLAB_PLUGIN_ABI);
    dlclose(h);
    return -1;
  }
  if (plugin_validate(pl, why, sizeof why) != 0) {
    snprintf(err, errlen, "plugin '%s' (%s): %s", pl->name ? pl->name : "?", path, why);
    dlclose(h);
    return -1;
  }
  plugin_register(pl);
  plugin_n++;
  return 0;
}

int plugin_count(void) {
  return plugin_n;
}
