/*
** shape.c: making shapes (parsing, named shapes, their checks and tables,
** the variant each one is, chosen once) and the public decision verbs,
** which call the shape's variant.  The decisions themselves are in the
** variants' files (shape_polygon.c, shape_square.c, shape_hex.c,
** shape_ellipse.c), the exact predicates in shape_arith.c;
** docs/emptyshape.md has the definitions and the special-position rule.
*/
#include <math.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "geom.h"
#include "shape.h"
#include "shape_internal.h"

/* ---- shapes and their variants ------------------------------------------ */

/* Shapes made so far: each one's serial number, which no other shape of
** the process shares (the exact signs kept per thread are keyed by it). */
static atomic_ulong shape_made;

/* A shape of kind kind and n vertices (none: an ellipse), its private part
** empty but for its serial number: NULL out of memory. */
static shape *shape_new(shape_kind kind, int n) {
  shape *k = calloc(1, sizeof *k);
  if (k == NULL) return NULL;
  k->kind = kind;
  k->n = n;
  k->impl = calloc(1, sizeof *k->impl);
  if (k->impl != NULL) k->impl->serial = atomic_fetch_add(&shape_made, 1) + 1;
  if (n > 0 && k->impl != NULL) {
    k->v = calloc((size_t)n, sizeof *k->v);
    k->impl->half = calloc((size_t)n, 1);
  }
  if (k->impl == NULL || (n > 0 && (k->v == NULL || k->impl->half == NULL))) {
    shape_free(k);
    return NULL;
  }
  return k;
}

void shape_free(shape *k) {
  if (k == NULL) return;
  if (k->impl != NULL) {
    shape_quick_free(k);
    shape_memo_free(k);
    shape_hex_free(k);
    free(k->impl->half);
    free(k->impl);
  }
  free(k->v);
  free(k);
}

/* K's variant v and with it its decisions: the one choice of them, made
** when K is made. */
static void shape_impl_set(shape *k, shape_variant v) {
  const shape_ops *ops = NULL;
  switch (v) {
  case SHAPE_V_POLYGON: ops = &shape_ops_polygon; break;
  case SHAPE_V_SQUARE: ops = &shape_ops_square; break;
  case SHAPE_V_DIAMOND: ops = &shape_ops_diamond; break;
  case SHAPE_V_HEXAGON: ops = &shape_ops_hexagon; break;
  case SHAPE_V_ELLIPSE: ops = &shape_ops_ellipse; break;
  }
  k->impl->variant = v;
  k->impl->ops = ops;
}

/* ---- parsing ------------------------------------------------------------ */

/* Numbers separated by ',' or blanks (a run of blanks, or blanks around
** one ','), none missing: 0 and *count, or -1 with err set. */
static int shape_numbers(const char *s, size_t len, double *out, int max, int *count,
                         char *err, size_t errlen) {
  size_t i = 0;
  int n = 0;
  for (;;) {
    double x = 0;
    size_t used = 0;
    geom_numerr e = geom_number_scan(s + i, len - i, &x, &used);
    if (used == 0 || n == max || e != GEOM_NUM_OK) {
      if (n == max) snprintf(err, errlen, "too many numbers in '%.*s'", (int)len, s);
      else snprintf(err, errlen, "'%.*s' %s", (int)len, s,
                    used == 0 ? "is missing a number" : geom_numerr_str(e));
      return -1;
    }
    out[n++] = x;
    i += used;
    size_t j = i;
    while (j < len && (s[j] == ' ' || s[j] == '\t')) j++;
    int comma = j < len && s[j] == ',';
    if (comma) j++;
    while (j < len && (s[j] == ' ' || s[j] == '\t')) j++;
    if (j == len && !comma) break;
    if (j == i) {
      snprintf(err, errlen, "'%.*s' is not a list of numbers", (int)len, s);
      return -1;
    }
    i = j;
  }
  *count = n;
  return 0;
}

/* Edge j's half-turn class relative to edge 0 (shape_support's search):
** 0 when its direction is turned by an angle in [0, pi) from edge 0's,
** else 1.  Exact; only edge 0 itself is parallel to edge 0 with the same
** direction (strict convexity), so a zero cross product means pi. */
static void shape_halves(shape *k) {
  for (int j = 0; j < k->n; j++) {
    shape_args g = {.K = k, .e = {0}, .p = {k->v[j], k->v[(j + 1) % k->n]}};
    k->impl->half[j] = j > 0 && shape_sign(SHAPE_PROG_CROSS, &g) <= 0;
  }
}

/* The polygon of n vertices p (copied), checked: strictly convex, within
** the coordinate contract (so the predicates' bound holds), anticlockwise
** (a clockwise list is reversed, keeping its first vertex); then its
** tables, and its variant: a square or a hexagon with a decision of its
** own (shape_square_is, shape_diamond_is, shape_hex_build), else the
** general polygon. */
static shape *shape_polygon(const geom_point *p, int n, const char *spec, char *err,
                            size_t errlen) {
  shape *k = shape_new(SHAPE_POLYGON, n);
  if (k == NULL) {
    snprintf(err, errlen, "shape '%.60s': out of memory", spec);
    return NULL;
  }
  memcpy(k->v, p, (size_t)n * sizeof *p);
  size_t bad = 0;
  int reversed = 0;
  geom_polyerr e = n < 3 ? GEOM_TOO_FEW : geom_polygon_check(k->v, (size_t)n, &bad, &reversed);
  if (e != GEOM_OK) {
    if (e == GEOM_TOO_FEW)
      snprintf(err, errlen, "shape '%.60s': %s", spec, geom_polyerr_str(e));
    else
      snprintf(err, errlen, "shape '%.60s': vertex %zu: %s", spec, bad + 1, geom_polyerr_str(e));
    shape_free(k);
    return NULL;
  }
  shape_halves(k);
  k->impl->moderate = shape_xp_moderate(k);   /* before the tables: memo reads it */
  if (shape_hex_build(k) != 0 || shape_memo_build(k) != 0 || shape_quick_build(k) != 0) {
    snprintf(err, errlen, "shape '%.60s': out of memory", spec);
    shape_free(k);
    return NULL;
  }
  shape_variant v = SHAPE_V_POLYGON;
  if (shape_square_is(k)) v = SHAPE_V_SQUARE;
  if (shape_diamond_is(k)) v = SHAPE_V_DIAMOND;
  if (k->impl->hexa != NULL) v = SHAPE_V_HEXAGON;
  shape_impl_set(k, v);
  return k;
}

/* "poly:X Y;X Y;...": vertices separated by ';'. */
static shape *shape_parse_poly(const char *spec, const char *s, char *err, size_t errlen) {
  geom_point *p = malloc(SHAPE_MAX_VERTICES * sizeof *p);
  if (p == NULL) {
    snprintf(err, errlen, "shape '%.60s': out of memory", spec);
    return NULL;
  }
  int n = 0;
  shape *k = NULL;
  for (const char *q = s;; n++) {
    const char *semi = strchr(q, ';');
    size_t len = semi ? (size_t)(semi - q) : strlen(q);
    double xy[2];
    int got = 0;
    char why[200] = "";
    if (n == SHAPE_MAX_VERTICES) {
      snprintf(err, errlen, "shape '%.60s': more than %d vertices", spec, SHAPE_MAX_VERTICES);
      goto done;
    }
    if (shape_numbers(q, len, xy, 2, &got, why, sizeof why) != 0 || got != 2) {
      snprintf(err, errlen, "shape '%.60s': vertex %d: %s", spec, n + 1,
               got == 1 ? "needs two coordinates" : why);
      goto done;
    }
    p[n] = (geom_point){xy[0], xy[1]};
    if (semi == NULL) break;
    q = semi + 1;
  }
  k = shape_polygon(p, n + 1, spec, err, errlen);
done:
  free(p);
  return k;
}

/* ngon:K: vertex j at (cos 2 pi j / K, sin 2 pi j / K), each coordinate
** rounded to the nearest multiple of 2^-20 (halves away from zero): the
** shape is those doubles, the same on every platform unless the libm
** result lies within an ulp of a rounding boundary (none does for the
** named shapes; tests/test_shape.c pins their coordinates). */
static shape *shape_ngon(int K, const char *spec, char *err, size_t errlen) {
  geom_point p[SHAPE_NGON_MAX];
  const double pi = 3.14159265358979323846;
  for (int j = 0; j < K; j++) {
    double a = 2 * pi * j / K;
    p[j] = (geom_point){round(cos(a) * 0x1p20) * 0x1p-20, round(sin(a) * 0x1p20) * 0x1p-20};
  }
  return shape_polygon(p, K, spec, err, errlen);
}

typedef struct shape_named {
  const char *name;
  int n;                 /* vertices, or 0 for an ngon of ngon vertices */
  int ngon;
  geom_point v[4];
} shape_named;

static const shape_named shape_names[] = {
  {"square", 4, 0, {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}},   /* the L_inf ball */
  {"diamond", 4, 0, {{1, 0}, {0, 1}, {-1, 0}, {0, -1}}},    /* the L_1 ball */
  {"triangle", 3, 0, {{0, 0}, {1, 0}, {0, 1}}},            /* X Y Z of the thesis */
  {"hexagon", 0, 6, {{0, 0}}},
  {"octagon", 0, 8, {{0, 0}}},
};

/* "ellipse:A B[ THETA]": semi-axis A along direction THETA (radians), B
** across.  The form Q = R diag(1/A^2, 1/B^2) R^T is rounded to doubles
** once, here: the shape is {x : x^T Q x <= 1} for those doubles.  A and B
** must lie in [2^-20, 2^20], so that the entries stay within [2^-100,
** 2^100] (the predicates' bound); an off-diagonal entry below 2^-60 times
** the largest is set to 0 (an axis-aligned ellipse stays exactly one). */
static shape *shape_parse_ellipse(const char *spec, const char *s, char *err, size_t errlen) {
  double x[3] = {0, 0, 0};
  int n = 0;
  char why[200];
  if (shape_numbers(s, strlen(s), x, 3, &n, why, sizeof why) != 0 || n < 2) {
    snprintf(err, errlen, "shape '%.60s': %s", spec,
             n == 1 ? "expects ellipse:A B[ THETA]" : why);
    return NULL;
  }
  if (!(x[0] >= 0x1p-20 && x[0] <= 0x1p20 && x[1] >= 0x1p-20 && x[1] <= 0x1p20)) {
    snprintf(err, errlen, "shape '%.60s': the semi-axes must lie between 2^-20 and 2^20", spec);
    return NULL;
  }
  shape *k = shape_new(SHAPE_ELLIPSE, 0);
  if (k == NULL) {
    snprintf(err, errlen, "shape '%.60s': out of memory", spec);
    return NULL;
  }
  shape_impl_set(k, SHAPE_V_ELLIPSE);
  double c = cos(x[2]), sn = sin(x[2]), ia = 1 / (x[0] * x[0]), ib = 1 / (x[1] * x[1]);
  k->q11 = ia * c * c + ib * sn * sn;
  k->q22 = ia * sn * sn + ib * c * c;
  k->q12 = (ia - ib) * c * sn;
  if (fabs(k->q12) < 0x1p-60 * fmax(k->q11, k->q22)) k->q12 = 0;
  if (fabs(k->q11) < 0x1p-60 * k->q22) k->q11 = 0;
  if (fabs(k->q22) < 0x1p-60 * k->q11) k->q22 = 0;
  if (!(k->q11 > 0 && k->q22 > 0 && k->q11 * k->q22 > k->q12 * k->q12 * (1 + 0x1p-40))) {
    snprintf(err, errlen, "shape '%.60s': the ellipse is too flat", spec);
    shape_free(k);
    return NULL;
  }
  k->impl->moderate = shape_xp_moderate(k);
  return k;
}

static shape *shape_parse_named(const char *spec, char *err, size_t errlen) {
  for (size_t i = 0; i < sizeof shape_names / sizeof shape_names[0]; i++) {
    const shape_named *s = &shape_names[i];
    if (strcmp(spec, s->name) != 0) continue;
    return s->n ? shape_polygon(s->v, s->n, spec, err, errlen)
                : shape_ngon(s->ngon, spec, err, errlen);
  }
  snprintf(err, errlen,
           "unknown shape '%.60s': expected square, diamond, triangle, hexagon, octagon, "
           "ngon:K, poly:X Y;X Y;... or ellipse:A B[ THETA]", spec);
  return NULL;
}

int shape_parse(const char *spec, shape **out, char *err, size_t errlen) {
  shape *k = NULL;
  if (strncmp(spec, "poly:", 5) == 0) {
    k = shape_parse_poly(spec, spec + 5, err, errlen);
  } else if (strncmp(spec, "ellipse:", 8) == 0) {
    k = shape_parse_ellipse(spec, spec + 8, err, errlen);
  } else if (strncmp(spec, "ngon:", 5) == 0) {
    uint64_t K = 0;
    if (geom_count_parse(spec + 5, strlen(spec + 5), &K) != 0 || K < 3 || K > SHAPE_NGON_MAX)
      snprintf(err, errlen, "shape '%.60s': ngon:K needs a whole K from 3 to %d", spec,
               SHAPE_NGON_MAX);
    else
      k = shape_ngon((int)K, spec, err, errlen);
  } else {
    k = shape_parse_named(spec, err, errlen);
  }
  if (k == NULL) return -1;
  *out = k;
  return 0;
}

/* ---- the decision verbs ---------------------------------------------------
**
** The public verbs call K's variant (shape_impl_set), each in its file:
** the general polygon's (shape_polygon.c), the square's (shape_square.c),
** the hexagon's (shape_hex.c) and the ellipse's (shape_ellipse.c). */

shape_choice shape_decide(const shape *k, geom_point a, geom_point b, geom_point c, geom_point d,
                          shape_trace *tr) {
  if (tr) *tr = (shape_trace){.corner = -1, .contact = {-1, -1, -1}};
  if (!geom_point_finite(a) || !geom_point_finite(b) || !geom_point_finite(c) ||
      !geom_point_finite(d))
    return SHAPE_EITHER;
  return k->impl->ops->decide(k, a, b, c, d, tr);
}

/* Sites in the coordinate contract are finite and 0 or of magnitude at
** least 1e-30 > 2^-100, all that shape_quick_ready checks of them. */
shape_choice shape_decide_valid(const shape *k, geom_point a, geom_point b, geom_point c,
                                geom_point d) {
  return k->impl->ops->decide_hinted(k, a, b, c, d, NULL);
}

shape_choice shape_decide_hinted(const shape *k, geom_point a, geom_point b, geom_point c,
                                 geom_point d, shape_hint *h) {
  return k->impl->ops->decide_hinted(k, a, b, c, d, h);
}

int shape_wants_hints(const shape *k) {
  return k->impl->ops->wants_hints(k);
}
