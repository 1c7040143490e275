/*
** formula.h: badness measures defined at run time by a formula.
**
** A definition reads "NAME = EXPR", "NAME >= 0 : EXPR" or "NAME <= 0 : EXPR"
** (the last two declare the sign domain; otherwise it is inferred from
** sample triangles).  EXPR is a muParser expression over the triangle's
** quantities (see formula_vars below), evaluated by one compiled muParser
** parser per thread, so a formula measure may be called from OpenMP threads
** like any built-in one.  formula_define registers the measure in the
** measure registry, after which NAME_JOINT names a rule everywhere.
**
** Bad values are never counted silently: a NaN or infinite value, or one
** outside the measure's sign domain, is recorded (the first one, with the
** triangle that produced it) and formula_check_errors reports it after the
** run.  Plugins record their bad values through the same mechanism.
*/
/* The variables, sign inference and bad-value policy: docs/measures.md. */
#ifndef FLIPLAB_FORMULA_H
#define FLIPLAB_FORMULA_H

#include <stddef.h>
#include "geom.h"
#include "measure.h"

#define FORMULA_MAX 32          /* formulas per process */
#define FORMULA_NAME_MAX MEASURE_NAME_MAX     /* longest NAME, terminator included */
/* Longest definition text.  muParser formats its error messages into a
** fixed buffer and overflows it (a crash, not an error) on a bad token of
** about 2,000 characters; refusing longer definitions up front keeps every
** token far below that.  A real measure is a line, not a page. */
#define FORMULA_TEXT_MAX 1024

/* The variables a formula may use, space-separated (for messages and help):
** a b c alpha beta gamma A P R r h rx ry x1 y1 x2 y2 x3 y3, and constant pi.
** (x1,y1), (x2,y2), (x3,y3) are the vertices in geom_tri's canonical order:
** lexicographic by x, then y. */
extern const char formula_vars[];

/* Parse and register a definition.  Returns the new measure's registry id,
** or -1 with a one-line message in err (syntax errors give the 0-based
** position in the whole definition text; unknown variables are named). */
int formula_define(const char *def, char *err, size_t errlen);

/* Is name acceptable for a user measure (measure_check_name's alphabet) and
** not taken?  0, or -1 with the reason in err. */
int formula_check_name(const char *name, char *err, size_t errlen);

/* Record a bad value of a user measure (thread-safe; only the first one is
** kept).  why: e.g. "is not finite", "is negative but the measure was
** declared >= 0". */
void formula_note_bad_value(const char *measure, const geom_tri *t, double v,
                            const char *why);
/* The one check of a user measure's value, formulas and plugins alike:
** NaN, an infinity unless allow_inf (plugins may return +-inf, formulas may
** not), or a value outside the sign domain is recorded with
** formula_note_bad_value.  Returns v. */
double formula_check_value(const char *measure, const geom_tri *t, double v, measure_sign sign,
                           int allow_inf);
/* The same for a problem described by a ready one-line message. */
void formula_note_message(const char *msg);

/* 0 if no bad value was recorded; otherwise 1 and a one-line message (the
** measure, the value, the triangle's vertices with %.17g) in msg. */
int formula_check_errors(char *msg, size_t len);
void formula_clear_errors(void);

/* Number of formulas defined, and the expression of a formula measure
** (NULL if the registry id is not a formula). */
int formula_count(void);
const char *formula_expr(int measure_id);

/* Free every formula (tests).  Call measure_unregister_user() first. */
void formula_reset(void);

#endif
