/*
** fliplab/plugin.h: the public C ABI of fliplab plugins (version 1).
**
** A plugin is a shared object loaded with `fliplab --plugin FILE.so`.  It
** exports one function,
**
**     const fliplab_plugin *fliplab_plugin_entry(void);
**
** returning a description (static storage, valid until exit) of the badness
** measures and whole-quadrilateral flip rules it adds.  Once loaded, a
** measure NAME is usable wherever a built-in one is (rules NAME_JOINT, e.g.
** `table34 --measures NAME`, `classify --rule NAME_1`), and a quadrilateral
** rule by its name (`rule NAME`, `classify --rule NAME`).
**
** Build a plugin against this header only (no fliplab library needed):
**
**     cc -std=c11 -O2 -shared -fPIC $(pkg-config --cflags fliplab) my.c -o my.so -lm
**
** The full contract, with the examples of plugins/, is docs/plugins.md.
**
** Contract:
** - abi must be FLIPLAB_PLUGIN_ABI; fliplab refuses any other value.  The
**   number changes whenever a struct below changes layout or meaning.
** - Names: letters, digits and ' / - . ( ) + * ^, at least one letter, no
**   '_' (rule names split MEASURE_JOINT at the last '_'), at most 31
**   characters; they must not clash with a built-in or already loaded name.
** - Functions are called concurrently from several threads: they must be
**   reentrant (no unsynchronised global state) and must not keep pointers.
** - Measures: small is good.  sign promises the value domain (it decides
**   the joints' conventions): FLIPLAB_PLUGIN_NONNEG, _NONPOS or _ANYSIGN
**   (min and max joints only).  NaN, or a value outside the promised
**   domain, is reported as an error after the run; +-inf is accepted.
** - Quadrilateral rules get ABCD anticlockwise and strictly convex, starting
**   at the lexicographically smallest vertex (x, then y), and return
**   FLIPLAB_PLUGIN_AC, _BD or _EITHER.  They must not depend on the
**   starting vertex (F(ABCD) = F(BCDA) with AC and BD swapped); fliplab's
**   canonical start makes that hold bit for bit for any consistent rule.
*/
#ifndef FLIPLAB_PLUGIN_H
#define FLIPLAB_PLUGIN_H

#ifdef __cplusplus
extern "C" {
#endif

#define FLIPLAB_PLUGIN_ABI 1
#define FLIPLAB_PLUGIN_ENTRY "fliplab_plugin_entry"

typedef struct fliplab_plugin_point {
  double x, y;
} fliplab_plugin_point;

/* A triangle's quantities, computed once by fliplab from the vertices in
** canonical order (lexicographic), so that they do not depend on how the
** vertices were listed.  Angles in radians. */
typedef struct fliplab_plugin_tri {
  fliplab_plugin_point v[3];  /* vertices, lexicographic order */
  double a, b, c;             /* sides, a >= b >= c */
  double alpha, beta, gamma;  /* angles, alpha <= beta <= gamma; alpha opposite c */
  double A;                   /* area, > 0 */
  double P;                   /* perimeter */
  double R;                   /* circumradius */
  double r;                   /* inradius */
  double h;                   /* shortest altitude 2A/a */
  double rx, ry;              /* coordinate ranges of the vertices */
} fliplab_plugin_tri;

enum { FLIPLAB_PLUGIN_NONPOS = -1, FLIPLAB_PLUGIN_ANYSIGN = 0, FLIPLAB_PLUGIN_NONNEG = 1 };
enum { FLIPLAB_PLUGIN_AC = 0, FLIPLAB_PLUGIN_BD = 1, FLIPLAB_PLUGIN_EITHER = 2 };

typedef struct fliplab_plugin_measure {
  const char *name;
  const char *desc;           /* one line */
  int sign;                   /* FLIPLAB_PLUGIN_NONNEG, _NONPOS or _ANYSIGN */
  double (*fn)(const fliplab_plugin_tri *t);
} fliplab_plugin_measure;

typedef struct fliplab_plugin_rule {
  const char *name;
  const char *desc;           /* one line */
  int (*fn)(const fliplab_plugin_point q[4]);
} fliplab_plugin_rule;

typedef struct fliplab_plugin {
  int abi;                    /* FLIPLAB_PLUGIN_ABI */
  const char *name;           /* the plugin's name, for messages */
  const char *desc;
  int nmeasures;
  const fliplab_plugin_measure *measures;
  int nrules;
  const fliplab_plugin_rule *rules;
} fliplab_plugin;

typedef const fliplab_plugin *(*fliplab_plugin_entry_fn)(void);

/* Every plugin defines this (with default visibility). */
const fliplab_plugin *fliplab_plugin_entry(void);

#ifdef __cplusplus
}
#endif

#endif
