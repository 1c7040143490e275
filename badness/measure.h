/*
** measure.h: badness measures (thesis table 3.2).
**
** A measure scores a triangle; small is good.  Measures live in one
** registry: the 23 built-in ones of docs/measures.md first (their
** indices are the MEASURE_* constants below), then any that a user defines
** at run time (formula or plugin) through measure_register.  Everything else
** in fliplab refers to a measure by its registry index.
*/
#ifndef FLIPLAB_MEASURE_H
#define FLIPLAB_MEASURE_H

#include "geom.h"

/* Which values a measure takes; it decides the joints' sign convention. */
typedef enum measure_sign {
  MEASURE_NONPOS = -1,   /* values <= 0 (a good quantity, negated) */
  MEASURE_ANYSIGN = 0,   /* both signs: only the min and max joints apply */
  MEASURE_NONNEG = 1     /* values >= 0 */
} measure_sign;

/* Called from several threads at once (table engine, GOT): must be reentrant. */
typedef double (*measure_fn)(const geom_tri *t, void *ctx);

typedef struct measure {
  const char *name;     /* command-line name, e.g. "-alpha" */
  const char *symbol;   /* thesis symbol, e.g. "-α" */
  const char *desc;     /* one-line description */
  measure_sign sign;
  measure_fn fn;
  void *ctx;            /* passed to fn; NULL for built-ins */
} measure;

enum {
  MEASURE_NEG_ALPHA, MEASURE_BETA, MEASURE_GAMMA, MEASURE_A, MEASURE_NEG_C,
  MEASURE_P, MEASURE_ABC, MEASURE_NEG_AREA, MEASURE_R, MEASURE_NEG_R,
  MEASURE_NEG_H, MEASURE_NEG_R_OVER_R, MEASURE_NEG_R2_OVER_A,
  MEASURE_NEG_C_OVER_A, MEASURE_NEG_C_OVER_P, MEASURE_A_MINUS_C,
  MEASURE_B_OVER_C_MINUS_A, MEASURE_LAMBDA, MEASURE_D, MEASURE_SIGMA,
  MEASURE_PINF, MEASURE_RINF, MEASURE_NEG_RINF,
  MEASURE_BUILTIN_COUNT
};

#define MEASURE_MAX 64        /* registry capacity, built-ins included */
#define MEASURE_TABLE34_COUNT 20

/* Registry. */
int measure_count(void);
const measure *measure_get(int id);
int measure_find(const char *name);             /* -1 if unknown */

/* The alphabet of names users give, to measures (formulas, plugins) and to
** quadrilateral rules (plugins) alike (docs/plugins.md): 1 to
** MEASURE_NAME_MAX - 1 characters among letters, digits and ' / - . ( ) +
** * ^, at least one letter; no '_' (rule names split at the last '_'), no
** blank, ',' or control character (names go into CSV rows and one-line
** messages).  what ("measure", "rule") opens the message.  Whether the
** name is taken is the registry's to say.  0, or -1 with the reason. */
#define MEASURE_NAME_MAX 32
int measure_check_name(const char *what, const char *name, char *err, size_t errlen);
int measure_register(const measure *m);         /* new id, or -1 if full or taken */
void measure_unregister_user(void);             /* drop user measures (tests) */

/* Table 3.4's twenty columns, in the thesis's order, as registry ids. */
extern const int measure_table34[MEASURE_TABLE34_COUNT];

static inline double measure_eval(int id, const geom_tri *t) {
  const measure *m = measure_get(id);
  return m->fn(t, m->ctx);
}

/* The measure of m triangles at once (python/'s vectorised badness):
** out[i] = measure_eval(id, t) for t = geom_tri_make(v[3i], v[3i+1],
** v[3i+2]), bit for bit (a built-in through measure_points, a user measure
** through geom_tri_make).  A flat triangle gets what its quantities give
** (an infinite or NaN value, as measure_eval does).  id must be a measure.
** Large batches are split over OpenMP threads: every value depends on its
** triangle only, and measures are reentrant by contract. */
void measure_eval_tris(int id, const geom_point *v, size_t m, double *out);

/* Every registered measure of t into out[0 .. measure_count()-1]; the
** built-ins are evaluated inline, without a call each (hot paths). */
void measure_eval_all(const geom_tri *t, double *out);

/* The geom_tri fields measure id reads (an OR of GEOM_F_*; GEOM_F_ALL for
** a user measure, which may read any): geom_tri_make_fields with them
** gives the value measure_eval gives on geom_tri_make's triangle, bit for
** bit (tests/test_lot.c checks the table both ways). */
unsigned measure_fields(int id);

/* A built-in measure evaluated straight from three points, in any order:
** measure_eval(id, t) for t = geom_tri_make_fields(p, q, r,
** measure_fields(id)), bit for bit, at about half the cost (for hot loops:
** lot/).  NULL for a user measure. */
typedef double (*measure_points_fn)(geom_point p, geom_point q, geom_point r);
measure_points_fn measure_points(int id);

/* A cheap enclosure *lo <= measure_eval(id, t) <= *hi of the very double
** measure_eval gives for t made by geom_tri_make from p, q, r (in any
** order): 1, or 0 (*lo, *hi unset) where there is none.  The angle
** measures (-alpha, beta, gamma, sigma) have one, from geom_angle_bounds,
** without atan2, some 1e-6 wide (wider, up to trivial, for -alpha and
** gamma of near-isosceles triangles); the other measures
** (measure_has_bounds) and flat triangles have none.  For decisions that
** need the exact values only when the enclosures cannot decide (lot/lot.c). */
int measure_bounds(int id, geom_point p, geom_point q, geom_point r, double *lo, double *hi);
int measure_has_bounds(int id);
/* A lower bound on every value measure_eval(id, .) takes: 0 for measures
** of sign >= 0, -inf for the others, except the bounded ones: -alpha >=
** -pi/3 and gamma >= pi/3, -r/R >= -1/2, -c/a >= -1, -c/P >= -1/3, -r2/A
** >= -sqrt(3)/9 (each moved out a little for rounding; measure.c). */
double measure_floor(int id);

/* Write a comma-separated list of all measure names into buf. */
void measure_names(char *buf, size_t len);

#endif
