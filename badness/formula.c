/*
** formula.c: badness measures defined at run time by a muParser formula.
**
** muParser (C API, muParserDLL.h) compiles an expression to bytecode once
** and then evaluates it in tens of nanoseconds, reading its variables
** through pointers bound at definition time.  A parser keeps its evaluation
** stack inside itself, so one parser must never run on two threads at once:
** every thread gets its own parser per formula, created lazily the first
** time that thread evaluates the formula, found again through a
** thread-local table (one pointer load and a compare on the hot path).
** Each parser owns the array of doubles its variables point at; the measure
** function fills that array from the geom_tri and calls mupEval.
**
** Thread-local entries carry the formula's serial number, never reused, so a
** stale entry left behind by formula_reset (tests) is recognised and
** replaced rather than followed.
*/
#include <ctype.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <muParserDLL.h>
#include "formula.h"
#include "measure.h"
#include "splitmix.h"

/* ---- variables: one table drives binding, filling and messages ---------- */

enum {
  FV_A, FV_B, FV_C, FV_ALPHA, FV_BETA, FV_GAMMA, FV_AREA, FV_P, FV_R, FV_RIN,
  FV_H, FV_RX, FV_RY, FV_X1, FV_Y1, FV_X2, FV_Y2, FV_X3, FV_Y3, FV_COUNT
};

static const char *const formula_var_names[FV_COUNT] = {
  "a", "b", "c", "alpha", "beta", "gamma", "A", "P", "R", "r",
  "h", "rx", "ry", "x1", "y1", "x2", "y2", "x3", "y3",
};

const char formula_vars[] =
  "a b c alpha beta gamma A P R r h rx ry x1 y1 x2 y2 x3 y3 (and constant pi)";

static inline void formula_fill(double *v, const geom_tri *t) {
  v[FV_A] = t->a;
  v[FV_B] = t->b;
  v[FV_C] = t->c;
  v[FV_ALPHA] = t->alpha;
  v[FV_BETA] = t->beta;
  v[FV_GAMMA] = t->gamma;
  v[FV_AREA] = t->area;
  v[FV_P] = t->P;
  v[FV_R] = t->R;
  v[FV_RIN] = t->r;
  v[FV_H] = t->h;
  v[FV_RX] = t->rx;
  v[FV_RY] = t->ry;
  v[FV_X1] = t->v[0].x;
  v[FV_Y1] = t->v[0].y;
  v[FV_X2] = t->v[1].x;
  v[FV_Y2] = t->v[1].y;
  v[FV_X3] = t->v[2].x;
  v[FV_Y3] = t->v[2].y;
}

/* ---- formulas and their per-thread parsers ------------------------------ */

typedef struct formula_slot {
  muParserHandle_t parser;
  double var[FV_COUNT];
  struct formula_slot *next;      /* all slots of one formula (for freeing) */
} formula_slot;

typedef struct formula {
  char name[FORMULA_NAME_MAX];
  char *expr;
  char *desc;
  measure_sign sign;
  int declared;                   /* sign given by the user */
  int index;                      /* in formula_table and formula_tls */
  int measure_id;
  uint64_t serial;
  formula_slot *slots;
} formula;

typedef struct formula_tls_entry {
  uint64_t serial;
  formula_slot *slot;
} formula_tls_entry;

static formula *formula_table[FORMULA_MAX];
static int formula_n;
static uint64_t formula_next_serial = 1;
static pthread_mutex_t formula_lock = PTHREAD_MUTEX_INITIALIZER;
static _Thread_local formula_tls_entry formula_tls[FORMULA_MAX];

/* A fresh parser bound to a fresh variable array, expression set.  Called
** with formula_lock held: muParser's constructors are not documented as
** safe to run concurrently. */
/* Slots are written on every evaluation by their own thread: each gets
** whole cache lines, or two threads' variable arrays could share a line and
** every evaluation would bounce it between the cores (false sharing, which
** cancelled the second thread entirely before this). */
#define FORMULA_LINE 64

static formula_slot *formula_slot_new(const char *expr) {
  size_t size = (sizeof(formula_slot) + FORMULA_LINE - 1) / FORMULA_LINE * FORMULA_LINE;
  formula_slot *s = aligned_alloc(FORMULA_LINE, size);
  if (s == NULL) return NULL;
  memset(s, 0, size);
  s->parser = mupCreate(muBASETYPE_FLOAT);
  if (s->parser == NULL) {
    free(s);
    return NULL;
  }
  for (int i = 0; i < FV_COUNT; i++) mupDefineVar(s->parser, formula_var_names[i], &s->var[i]);
  mupDefineConst(s->parser, "pi", M_PI);
  mupSetExpr(s->parser, expr);
  return s;
}

static void formula_slot_free(formula_slot *s) {
  if (s == NULL) return;
  mupRelease(s->parser);
  free(s);
}

/* This thread's parser for f (slow path: first use on this thread).  The
** expression was checked at definition time, so compiling it again here
** cannot fail; the first evaluation compiles it to bytecode. */
static formula_slot *formula_slot_get(formula *f) {
  pthread_mutex_lock(&formula_lock);
  formula_slot *s = formula_slot_new(f->expr);
  if (s != NULL) {
    s->next = f->slots;
    f->slots = s;
    mupEval(s->parser);
    mupError(s->parser);
  }
  pthread_mutex_unlock(&formula_lock);
  if (s == NULL) return NULL;
  formula_tls[f->index] = (formula_tls_entry){f->serial, s};
  return s;
}

/* Out of memory for a parser: the value is NaN and the run fails with the
** reason (a library does not abort its caller). */
static double formula_eval_raw(formula *f, const geom_tri *t) {
  formula_tls_entry *e = &formula_tls[f->index];
  formula_slot *s = e->serial == f->serial ? e->slot : formula_slot_get(f);
  if (s == NULL) {
    char msg[128];
    snprintf(msg, sizeof msg, "measure '%s': out of memory creating a parser", f->name);
    formula_note_message(msg);
    return NAN;
  }
  formula_fill(s->var, t);
  return mupEval(s->parser);
}

/* The measure function.  The checks cost two compares; a bad value is
** recorded (not replaced) so that the run can be failed afterwards. */
static double formula_measure_fn(const geom_tri *t, void *ctx) {
  formula *f = ctx;
  return formula_check_value(f->name, t, formula_eval_raw(f, t), f->sign, 0);
}

/* ---- bad values ---------------------------------------------------------- */

static atomic_int formula_bad_seen;
static atomic_ulong formula_bad_more;
static char formula_bad_msg[640];

void formula_note_message(const char *msg) {
  if (atomic_exchange(&formula_bad_seen, 1)) {
    atomic_fetch_add(&formula_bad_more, 1);
    return;
  }
  snprintf(formula_bad_msg, sizeof formula_bad_msg, "%s", msg);
}

void formula_note_bad_value(const char *measure, const geom_tri *t, double v,
                            const char *why) {
  if (atomic_load(&formula_bad_seen)) {
    atomic_fetch_add(&formula_bad_more, 1);
    return;
  }
  char msg[sizeof formula_bad_msg];
  snprintf(msg, sizeof msg,
           "measure '%s': value %g %s on the triangle (%.17g, %.17g), (%.17g, %.17g), "
           "(%.17g, %.17g)",
           measure, v, why, t->v[0].x, t->v[0].y, t->v[1].x, t->v[1].y, t->v[2].x,
           t->v[2].y);
  formula_note_message(msg);
}

double formula_check_value(const char *measure, const geom_tri *t, double v, measure_sign sign,
                           int allow_inf) {
  if (isnan(v) || (!allow_inf && isinf(v)))
    formula_note_bad_value(measure, t, v, "is not finite");
  else if (sign == MEASURE_NONNEG && v < 0)
    formula_note_bad_value(measure, t, v, "is negative, outside the measure's sign domain >= 0");
  else if (sign == MEASURE_NONPOS && v > 0)
    formula_note_bad_value(measure, t, v, "is positive, outside the measure's sign domain <= 0");
  return v;
}

/* formula_bad_msg is written once, by the thread that won the exchange;
** callers read it after the parallel region has ended (a barrier). */
int formula_check_errors(char *msg, size_t len) {
  if (!atomic_load(&formula_bad_seen)) return 0;
  unsigned long more = atomic_load(&formula_bad_more);
  if (more > 0)
    snprintf(msg, len, "%s (and %lu more bad values)", formula_bad_msg, more);
  else
    snprintf(msg, len, "%s", formula_bad_msg);
  return 1;
}

void formula_clear_errors(void) {
  atomic_store(&formula_bad_more, 0);
  formula_bad_msg[0] = '\0';
  atomic_store(&formula_bad_seen, 0);
}

/* ---- parsing a definition ------------------------------------------------ */

int formula_check_name(const char *name, char *err, size_t errlen) {
  if (measure_check_name("measure", name, err, errlen) != 0) return -1;
  int id = measure_find(name);
  if (id >= 0) {
    snprintf(err, errlen, "measure '%s' already exists (%s)", name,
             id < MEASURE_BUILTIN_COUNT ? "a built-in measure" : "defined earlier");
    return -1;
  }
  return 0;
}

/* Split "NAME = EXPR" / "NAME >= 0 : EXPR" / "NAME <= 0 : EXPR".  *sign is
** 2 when undeclared.  *expr_at is the offset of EXPR in def. */
static int formula_split(const char *def, char *name, int *sign, size_t *expr_at,
                         char *err, size_t errlen) {
  const char *p = def;
  while (*p == ' ' || *p == '\t') p++;
  const char *n0 = p;
  while (*p != '\0' && *p != ' ' && *p != '\t' && *p != '=' && *p != '<' && *p != '>' && *p != ':') p++;
  size_t nlen = (size_t)(p - n0);
  if (nlen == 0) {
    snprintf(err, errlen, "expected NAME = EXPR (or NAME >= 0 : EXPR, NAME <= 0 : EXPR)");
    return -1;
  }
  if (nlen >= FORMULA_NAME_MAX) {
    snprintf(err, errlen, "measure name '%.20s...' is %zu characters long; at most %d",
             n0, nlen, FORMULA_NAME_MAX - 1);
    return -1;
  }
  memcpy(name, n0, nlen);
  name[nlen] = '\0';
  while (*p == ' ' || *p == '\t') p++;
  *sign = 2;
  if (p[0] == '=' && p[1] != '=') {
    p++;
  } else if ((p[0] == '<' || p[0] == '>') && p[1] == '=') {
    *sign = p[0] == '>' ? MEASURE_NONNEG : MEASURE_NONPOS;
    p += 2;
    while (*p == ' ' || *p == '\t') p++;
    if (*p != '0') goto bad;
    p++;
    while (*p == ' ' || *p == '\t') p++;
    if (*p != ':') goto bad;
    p++;
  } else {
    goto bad;
  }
  while (*p == ' ' || *p == '\t') p++;
  if (*p == '\0') {
    snprintf(err, errlen, "the expression after '%s' is empty", *sign == 2 ? "=" : ":");
    return -1;
  }
  *expr_at = (size_t)(p - def);
  return 0;
bad:
  snprintf(err, errlen,
           "expected NAME = EXPR, NAME >= 0 : EXPR or NAME <= 0 : EXPR after the name '%s'", name);
  return -1;
}

/* muParser's messages end in "at position N"; we print our own position
** (in the whole definition), so drop theirs. */
static void formula_strip_position(const char *msg, char *out, size_t len) {
  snprintf(out, len, "%s", msg);
  char *at = strstr(out, " at position ");
  if (at != NULL) {
    char *rest = at + strlen(" at position ");
    while (*rest >= '0' && *rest <= '9') rest++;
    memmove(at, rest, strlen(rest) + 1);
  }
  size_t n = strlen(out);
  while (n > 0 && (out[n - 1] == '.' || out[n - 1] == ' ')) out[--n] = '\0';
}

/* An '=' that is not part of ==, !=, <=, >= is muParser's assignment: it
** would let a formula overwrite its own inputs.  Returns its offset or -1. */
static long formula_find_assignment(const char *e) {
  for (size_t i = 0; e[i] != '\0'; i++) {
    if (e[i] != '=') continue;
    if (e[i + 1] == '=') {
      i++;
      continue;
    }
    if (i > 0 && strchr("<>!=", e[i - 1]) != NULL) continue;
    return (long)i;
  }
  return -1;
}

static void formula_syntax_error(formula_slot *s, const char *expr, size_t expr_at,
                                 char *err, size_t errlen) {
  char m[256];
  long pos = mupGetErrorPos(s->parser);
  long elen = (long)strlen(expr);
  if (pos < 0 || pos > elen) pos = elen;
  formula_strip_position(mupGetErrorMsg(s->parser), m, sizeof m);
  if (strlen(m) > 100) memcpy(m + 97, "...", 4);   /* muParser echoes the bad token */
  snprintf(err, errlen, "syntax error at position %ld: %s", (long)expr_at + pos, m);
}

/* Every numeric literal must be a double: muParser takes 1e400 for a name
** (then "unknown variable") and 1e-400 for 0.  A literal starts with a digit,
** or '.' and a digit, not inside a name.  0 or -1 with the message. */
static int formula_check_numbers(const char *e, size_t expr_at, char *err, size_t errlen) {
  for (size_t i = 0; e[i] != '\0'; i++) {
    int starts = (e[i] >= '0' && e[i] <= '9') || (e[i] == '.' && e[i + 1] >= '0' && e[i + 1] <= '9');
    int inside = i > 0 && (isalnum((unsigned char)e[i - 1]) || e[i - 1] == '_' || e[i - 1] == '.');
    if (!starts || inside) continue;
    double v = 0;
    size_t used = 0;
    geom_numerr ne = geom_number_scan(e + i, strlen(e + i), &v, &used);
    if (ne == GEOM_NUM_OUT_OF_RANGE) {
      snprintf(err, errlen, "number '%.*s' at position %zu is out of range (%s)",
               (int)(used < 40 ? used : 40), e + i, expr_at + i,
               fabs(v) > 1 ? "it overflows a double" : "it underflows a double to 0 or a subnormal");
      return -1;
    }
    if (used > 0) i += used - 1;
  }
  return 0;
}

/* Compile expr on a scratch parser: variables known, syntax right, exactly
** one value.  0 or -1 with the message. */
static int formula_compile_check(const char *def, const char *expr, size_t expr_at,
                                 char *err, size_t errlen) {
  long eq = formula_find_assignment(expr);
  if (eq >= 0) {
    snprintf(err, errlen, "assignment '=' at position %ld is not allowed in a measure",
             (long)expr_at + eq);
    return -1;
  }
  if (formula_check_numbers(expr, expr_at, err, errlen) != 0) return -1;
  formula_slot *s = formula_slot_new(expr);
  if (s == NULL) {
    snprintf(err, errlen, "out of memory");
    return -1;
  }
  int rc = 0;
  /* Listing the expression's variables also lists undefined ones (with a
  ** NULL address): that is how an unknown variable gets its own message.
  ** After an error here the parser must not be evaluated (muParser 2.3
  ** crashes), so a syntax error found while listing is reported at once. */
  int nv = mupGetExprVarNum(s->parser);
  if (mupError(s->parser)) {
    formula_syntax_error(s, expr, expr_at, err, errlen);
    rc = -1;
    goto out;
  }
  for (int i = 0; i < nv; i++) {
    const muChar_t *vn = NULL;
    muFloat_t *addr = NULL;
    mupGetExprVar(s->parser, (unsigned)i, &vn, &addr);
    if (addr == NULL) {
      const char *where = strstr(expr, vn);
      snprintf(err, errlen, "unknown variable '%s' at position %ld; the variables are %s", vn,
               where ? (long)(expr_at + (size_t)(where - expr)) : (long)expr_at, formula_vars);
      rc = -1;
      goto out;
    }
  }
  /* A fresh parser for the real compilation (the listing left its own
  ** state behind). */
  formula_slot_free(s);
  s = formula_slot_new(expr);
  if (s == NULL) {
    snprintf(err, errlen, "out of memory");
    return -1;
  }
  mupEval(s->parser);
  if (mupError(s->parser)) {
    formula_syntax_error(s, expr, expr_at, err, errlen);
    rc = -1;
    goto out;
  }
  int nres = 0;
  mupEvalMulti(s->parser, &nres);
  if (mupError(s->parser) || nres != 1) {
    snprintf(err, errlen, "the expression gives %d comma-separated values; a measure needs one", nres);
    rc = -1;
  }
out:
  (void)def;
  formula_slot_free(s);
  return rc;
}

/* ---- the sign domain from sample triangles ------------------------------ */

/* splitmix64: the sample triangles must be the same on every run. */
static double formula_rng_uniform(uint64_t *s) {
  return geom_unit53(geom_splitmix64(s));
}

#define FORMULA_SAMPLES 3000

/* Sample triangle k: a few special shapes, then triangles in the unit disc,
** then triangles scaled over six decades and moved up to 100 units from the
** origin (formulas may use coordinates), then slivers (heights down to
** 1e-6 of the base) and needles, rotated, scaled and moved likewise. */
static void formula_sample_tri(int k, uint64_t *rng, geom_tri *t) {
  static const geom_point special[4][3] = {
    {{0, 0}, {1, 0}, {0.5, 0.86602540378443864676}},   /* equilateral */
    {{0, 0}, {1, 0}, {0, 1}},                          /* right isosceles */
    {{0, 0}, {1, 0}, {0.5, 0.05}},                     /* flat isosceles */
    {{-3, -2}, {-1, -2.5}, {-2, 4}},                   /* negative coordinates */
  };
  if (k < 4) {
    geom_tri_make(t, special[k][0], special[k][1], special[k][2]);
    return;
  }
  geom_point p[3];
  double scale = 1, ox = 0, oy = 0;
  if (k < 1500) {
    for (int i = 0; i < 3; i++) {
      double u, v;
      do {
        u = formula_rng_uniform(rng);
        v = formula_rng_uniform(rng);
      } while (!geom_disc_accept(u, v, &p[i]));
    }
  } else {
    double u = 2 * formula_rng_uniform(rng) - 0.5;           /* apex position along the base */
    double hgt = pow(10, -6 + 5 * formula_rng_uniform(rng)); /* sliver height */
    if (k < 2200) {
      for (int i = 0; i < 3; i++)
        p[i] = (geom_point){formula_rng_uniform(rng), formula_rng_uniform(rng)};
    } else {
      p[0] = (geom_point){0, 0};
      p[1] = (geom_point){1, 0};
      p[2] = (geom_point){u, hgt};
    }
    double th = 2 * M_PI * formula_rng_uniform(rng), c = cos(th), s = sin(th);
    for (int i = 0; i < 3; i++) p[i] = (geom_point){c * p[i].x - s * p[i].y, s * p[i].x + c * p[i].y};
    scale = pow(10, -3 + 6 * formula_rng_uniform(rng));
    ox = 200 * formula_rng_uniform(rng) - 100;
    oy = 200 * formula_rng_uniform(rng) - 100;
  }
  for (int i = 0; i < 3; i++) p[i] = (geom_point){ox + scale * p[i].x, oy + scale * p[i].y};
  geom_tri_make(t, p[0], p[1], p[2]);
}

/* Evaluate on the samples: the inferred sign, or a check of the declared
** one.  Non-finite values on degenerate-looking samples are skipped (they
** will be reported if a run ever meets such a triangle). */
static int formula_sign_from_samples(formula *f, char *err, size_t errlen) {
  uint64_t rng = GEOM_STATE_FORMULA_SIGNS;
  int neg = 0, pos = 0, finite = 0;
  geom_tri bad_t;
  double bad_v = 0;
  for (int k = 0; k < FORMULA_SAMPLES; k++) {
    geom_tri t;
    formula_sample_tri(k, &rng, &t);
    if (!(t.area > 0)) continue;
    double v = formula_eval_raw(f, &t);
    if (!isfinite(v)) continue;
    finite++;
    if ((v < 0 && !neg) || (v > 0 && !pos)) {
      if ((v < 0 && f->declared && f->sign == MEASURE_NONNEG) ||
          (v > 0 && f->declared && f->sign == MEASURE_NONPOS)) {
        bad_t = t;
        bad_v = v;
      }
    }
    if (v < 0) neg = 1;
    if (v > 0) pos = 1;
  }
  if (finite == 0) {
    snprintf(err, errlen, "the expression is not finite on any of %d sample triangles",
             FORMULA_SAMPLES);
    return -1;
  }
  if (f->declared) {
    if ((f->sign == MEASURE_NONNEG && neg) || (f->sign == MEASURE_NONPOS && pos)) {
      snprintf(err, errlen,
               "declared %s 0 but the value is %g on the triangle (%.17g, %.17g), (%.17g, %.17g), "
               "(%.17g, %.17g)",
               f->sign == MEASURE_NONNEG ? ">=" : "<=", bad_v, bad_t.v[0].x, bad_t.v[0].y,
               bad_t.v[1].x, bad_t.v[1].y, bad_t.v[2].x, bad_t.v[2].y);
      return -1;
    }
    return 0;
  }
  f->sign = neg && pos ? MEASURE_ANYSIGN : neg ? MEASURE_NONPOS : MEASURE_NONNEG;
  return 0;
}

/* ---- defining ------------------------------------------------------------ */

static void formula_free(formula *f) {
  if (f == NULL) return;
  for (formula_slot *s = f->slots, *n; s != NULL; s = n) {
    n = s->next;
    formula_slot_free(s);
  }
  free(f->expr);
  free(f->desc);
  free(f);
}

int formula_define(const char *def, char *err, size_t errlen) {
  char name[FORMULA_NAME_MAX];
  int sign;
  size_t expr_at;
  size_t dlen = strlen(def);
  if (dlen > FORMULA_TEXT_MAX) {
    snprintf(err, errlen, "the definition is %zu characters long; at most %d are accepted",
             dlen, FORMULA_TEXT_MAX);
    return -1;
  }
  if (formula_split(def, name, &sign, &expr_at, err, errlen) != 0) return -1;
  if (formula_check_name(name, err, errlen) != 0) return -1;
  if (formula_n >= FORMULA_MAX || measure_count() >= MEASURE_MAX) {
    snprintf(err, errlen, "too many user measures (at most %d formulas, %d measures in all)",
             FORMULA_MAX, MEASURE_MAX);
    return -1;
  }
  const char *expr = def + expr_at;
  pthread_mutex_lock(&formula_lock);
  int rc = formula_compile_check(def, expr, expr_at, err, errlen);
  pthread_mutex_unlock(&formula_lock);
  if (rc != 0) return -1;

  formula *f = calloc(1, sizeof *f);
  if (f == NULL) goto oom;
  snprintf(f->name, sizeof f->name, "%s", name);
  f->expr = strdup(expr);
  size_t dl = strlen(expr) + 32;
  f->desc = malloc(dl);
  if (f->expr == NULL || f->desc == NULL) goto oom;
  snprintf(f->desc, dl, "formula: %s", expr);
  f->declared = sign != 2;
  f->sign = sign != 2 ? (measure_sign)sign : MEASURE_ANYSIGN;
  f->index = formula_n;
  f->serial = formula_next_serial++;
  if (formula_sign_from_samples(f, err, errlen) != 0) {
    formula_free(f);
    return -1;
  }
  measure m = {f->name, f->name, f->desc, f->sign, formula_measure_fn, f};
  f->measure_id = measure_register(&m);
  if (f->measure_id < 0) {
    snprintf(err, errlen, "cannot register measure '%s' (registry full or name taken)", name);
    formula_free(f);
    return -1;
  }
  formula_table[formula_n++] = f;
  return f->measure_id;
oom:
  formula_free(f);
  snprintf(err, errlen, "out of memory");
  return -1;
}

int formula_count(void) {
  return formula_n;
}

const char *formula_expr(int measure_id) {
  for (int i = 0; i < formula_n; i++)
    if (formula_table[i]->measure_id == measure_id) return formula_table[i]->expr;
  return NULL;
}

void formula_reset(void) {
  pthread_mutex_lock(&formula_lock);
  for (int i = 0; i < formula_n; i++) {
    formula_free(formula_table[i]);
    formula_table[i] = NULL;
  }
  formula_n = 0;
  pthread_mutex_unlock(&formula_lock);
  formula_clear_errors();
}
