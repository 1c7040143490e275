/*
** shape.c: shapes (parsing, named shapes, the variant each one is, chosen
** once) and the empty-shape decision (support points, circumscribing
** homothets, rounding shapes, ellipses) of the general polygon and the
** ellipse.  The predicates themselves, exact, are in shape_arith.c;
** docs/emptyshape.md has the definitions and the special-position rule.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "geom.h"
#include "shape.h"
#include "shape_internal.h"

/* ---- shapes and their variants ------------------------------------------ */

/* A shape of kind kind and n vertices (none: an ellipse), its private part
** empty: NULL out of memory. */
static shape *shape_new(shape_kind kind, int n) {
  shape *k = calloc(1, sizeof *k);
  if (k == NULL) return NULL;
  k->kind = kind;
  k->n = n;
  k->impl = calloc(1, sizeof *k->impl);
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
** own (shape_square_is, shape_hex_build), else the general polygon. */
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
  if (shape_hex_build(k) != 0 || shape_memo_build(k) != 0 || shape_quick_build(k) != 0) {
    snprintf(err, errlen, "shape '%.60s': out of memory", spec);
    shape_free(k);
    return NULL;
  }
  shape_variant v = SHAPE_V_POLYGON;
  if (shape_square_is(k)) v = SHAPE_V_SQUARE;
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

/* ---- support points -------------------------------------------------------
**
** The special-position rule (docs/emptyshape.md): K is turned by an
** infinitesimal angle eps > 0 (the sites by -eps, which is the same for
** homothets), so that no edge of K is parallel to a pair of sites.  Every
** predicate is then read as its value, or when that is 0, the sign of its
** eps coefficient (shape_eps_sign).  For the support of PQ, cross(e_j,
** Q - P) becomes cross(e_j, Q - P) - eps e_j.(Q - P): an edge parallel to
** PQ counts as turned clockwise from it when it has PQ's direction. */

/* eps-sign of cross(e_j, q - p): the fast path, else the full one. */
static int shape_cross_eps(const shape *k, int j, geom_point p, geom_point q) {
  int s = shape_fast_cross(k, j, p, q);
  if (s != 2) return s;
  shape_args g = {.K = k, .e = {j}, .p = {p, q}};
  return shape_eps_sign(SHAPE_PROG_CROSS, g, NULL);
}

/* Is edge j's direction angularly before the (perturbed) direction of
** Q - P, angles measured anticlockwise from edge 0 in [0, 2 pi)?  hw is
** the half of Q - P (shape_halves). */
static int shape_before(const shape *k, int j, geom_point p, geom_point q, int hw) {
  const unsigned char *half = k->impl->half;
  if (half[j] != hw) return half[j] < hw;
  return shape_cross_eps(k, j, p, q) > 0;
}

/* The edges before Q - P form a prefix 0..s-1 of the edge list (edge
** directions turn monotonically): the support vertex is s, the start of
** the first edge not before Q - P, found by binary search (s = n: 0). */
int shape_support(const shape *k, geom_point p, geom_point q) {
  int hw = shape_cross_eps(k, 0, p, q) > 0 ? 0 : 1;
  int lo = 1, hi = k->n;   /* edge 0 is always before: its angle is 0 */
  while (lo < hi) {
    int mid = lo + (hi - lo) / 2;
    if (shape_before(k, mid, p, q, hw)) lo = mid + 1;
    else hi = mid;
  }
  return lo % k->n;
}

/* ---- the circumscribing homothet of a polygon ------------------------------
**
** H = t + sK has support value c_i = n_i.t + s h_i on edge i (n_i the outward
** normal (e_y, -e_x) of edge direction e_i, h_i = n_i.k_i = cross(k_i,
** k_{i+1})).  With A on edge i, B on edge j, C on edge k of H, (t, s) solves
** three linear equations of rows (n, h | n.P); for any edge m and point P,
** det4 of the rows (n, h, n.P) of (i, A), (j, B), (k, C), (m, P) is
** det3 (n.P - c_m), det3 that of the rows (n, h) of i, j, k.  Columns
** (e_x, e_y) instead of (n_x, n_y) give the same determinants, and the
** last column may be taken relative to any common origin (a column
** operation): SHAPE_PROG_DET4 and SHAPE_PROG_DET3H.  So
**   sign(c_m - n_m.P) = -sign(det4) sign(det3),
**   sign(s)            = sign(det3 of rows (n | n.P)) sign(det3).
** A triple is the circumscribing homothet's contact triple when det3 != 0,
** s > 0, and each of A, B, C lies within its edge: on the inner side of the
** two neighbouring edges (a point of edge line i inside the half-planes of
** edges i - 1 and i + 1 is on edge i).  Going anticlockwise around H, A's
** contact edge is in [s_CA, s_AB), B's in [s_AB, s_BC), C's in [s_BC, s_CA)
** (those are the edges whose outward normal has that vertex as the
** triangle's extreme point), so only those triples are tried. */

/* eps-sign of c_m - n_m.P for the contact triple t[3] of A, B, C = p[0..2];
** w holds the rows' w values relative to P (shape_w3_prep), which every
** edge m of the same P shares. */
static int shape_slack(const shape *k, const int t[3], const geom_point p[3], const shape_w3 *w,
                       int m, geom_point pm, int d3, int *level) {
  int s = shape_fast_det4(w, k, t, m);
  if (s != 2) {
    if (level) *level = 0;
    return -s * d3;
  }
  shape_args g = {.K = k, .e = {t[0], t[1], t[2], m}, .p = {p[0], p[1], p[2], pm}, .o = pm};
  return -shape_eps_sign(SHAPE_PROG_DET4, g, level) * d3;
}

/* The contact test of triple t: det3's sign when t is the contact triple,
** else 0.  On failure *viol gets a bit 2 r + (side > 0) for each point r
** found beyond its contact's neighbouring edge t[r] + side (0: no such
** hint, the triple solves to no homothet).
** A check against the neighbouring edge that is the next point's (or the
** previous point's) contact edge is settled without a determinant.  Say
** P's contact edge is i and the next point Q's is i + 1 (anticlockwise:
** A, B, C, A).  H's edge lines pass through their points, so P's slack on
** edge i + 1 is n.(Q - P) = cross(Q - P, e_{i+1}) and Q's on edge i is
** n.(P - Q) = cross(e_i, Q - P), exactly, and turning the sites by -eps
** changes both sides alike (the same vectors), so their eps-signs agree.
** Edge i is in P's range, before s_PQ, and edge i + 1 in Q's, from s_PQ:
** e_i lies clockwise of Q - P and e_{i+1} anticlockwise of it (parallel
** ones settled by eps as shape_before settles them), by less than pi (a
** range spans the exterior angle at its point).  Both crosses are
** eps-positive: the check would pass, so it sets no bit.
** The bits are tested in order
** and the test stops at the first one set in stop: a caller that acts on
** the first set bit of stop (or on any violation, stop = all) gets the
** answer all six would give. */
static int shape_contact_ok(const shape *k, const int t[3], const geom_point p[3], int stop,
                            int *viol) {
  shape_args g = {.K = k, .e = {t[0], t[1], t[2]}, .p = {p[0], p[1], p[2]}, .o = p[0]};
  *viol = 0;
  int d3 = shape_det3h_sign(k, t);
  if (d3 == 0) return 0;
  shape_w3 w;
  shape_w3_prep(&w, k, t, p, p[0]);   /* det3w's w values, and the slacks' of A */
  int s = shape_fast_det3w(&w, k, t);
  if (s == 2) s = shape_eps_sign(SHAPE_PROG_DET3W, g, NULL);
  if (s * d3 <= 0) return 0;
  for (int r = 0; r < 3; r++) {
    if (r > 0) shape_w3_prep(&w, k, t, p, p[r]);
    for (int side = -1; side <= 1; side += 2) {
      int bit = 1 << (2 * r + (side > 0)), m = (t[r] + side + k->n) % k->n;
      if (m == t[(r + 3 + side) % 3]) continue;   /* settled (above) */
      if (shape_slack(k, t, p, &w, m, p[r], d3, NULL) < 0) {
        *viol |= bit;
        if (stop & bit) return 0;
      }
    }
  }
  return *viol ? 0 : d3;
}

/* The contact triple by trying every triple of the ranges: det3's sign, or 0. */
static int shape_contacts_all(const shape *k, const int start[3], const int len[3],
                              const geom_point p[3], int t[3]) {
  int viol;
  for (int a = 0; a < len[0]; a++)
    for (int b = 0; b < len[1]; b++)
      for (int c = 0; c < len[2]; c++) {
        t[0] = (start[0] + a) % k->n;
        t[1] = (start[1] + b) % k->n;
        t[2] = (start[2] + c) % k->n;
        int d3 = shape_contact_ok(k, t, p, 63, &viol);
        if (d3 != 0) return d3;
      }
  return 0;
}

/* The contact triple (edge indices into t) and det3's sign, or 0.  A walk
** from the middles of the ranges moves a contact towards the neighbouring
** edge its point lies beyond; it only saves time (whatever triple passes
** shape_contact_ok is the circumscribing homothet's, and every passing
** triple gives the same homothet), so when it stalls, leaves a range or
** takes too long, every triple is tried. */
int shape_contacts(const shape *k, const int sup[3], const geom_point p[3], int t[3]) {
  /* sup = s_AB, s_BC, s_CA; A's range starts at s_CA, B's at s_AB, C's at s_BC. */
  int start[3] = {sup[2], sup[0], sup[1]}, len[3], off[3];
  for (int r = 0; r < 3; r++) {
    len[r] = shape_range(k, start[r], sup[r]);
    off[r] = len[r] / 2;
  }
  for (int step = 0; step < 2 * k->n + 8; step++) {
    int movable = 0;
    for (int bit = 0; bit < 6; bit++) {
      int r = bit / 2, dir = bit % 2 ? 1 : -1;
      movable |= (off[r] + dir >= 0 && off[r] + dir < len[r]) << bit;
    }
    for (int r = 0; r < 3; r++) t[r] = (start[r] + off[r]) % k->n;
    int viol, d3 = shape_contact_ok(k, t, p, movable, &viol), moved = 0;
    if (d3 != 0) return d3;
    for (int bit = 0; bit < 6 && !moved; bit++) {
      int r = bit / 2, dir = bit % 2 ? 1 : -1;
      if ((viol >> bit & 1) && (movable >> bit & 1)) {
        off[r] += dir;
        moved = 1;
      }
    }
    if (!moved) break;
  }
  return shape_contacts_all(k, start, len, p, t);
}

/* D beyond chord CA is inside H iff it is inside every edge of the arc of H
** from C's contact edge to A's (anticlockwise, through s_CA): together with
** the chord, those edges bound the part of H beyond CA. */
static shape_choice shape_homothet_decide(const shape *k, const int t[3], int d3,
                                          const geom_point p[4], shape_trace *tr) {
  int out = 0, on = 0, lv = 0;
  shape_w3 w;
  shape_w3_prep(&w, k, t, p, p[3]);
  for (int m = t[2];; m = (m + 1) % k->n) {
    int level = 0, s = shape_slack(k, t, p, &w, m, p[3], d3, &level);
    lv = level > lv ? level : lv;
    out |= s < 0;
    on |= s == 0;
    if (out || m == t[0]) break;
  }
  if (tr) tr->level = lv;
  return out ? SHAPE_AC : on ? SHAPE_EITHER : SHAPE_BD;
}

/* ---- corners and their rounding shapes -------------------------------------
**
** When two supports of ABC coincide at vertex c, no homothet of K passes
** through A, B and C; the circumscribing shape is c's rounding shape, the
** convex side of the hyperbola branch through A, B, C with asymptotes
** parallel to c's cone sides u, v.  Mapped so that u, v become the positive
** axes, the branch is (x - h_x)(y - h_y) = r with r > 0, x > h_x, and for
** f(x, y) = x y + alpha x + beta y + gamma vanishing at A, B, C, f(D) =
** -det4(rows (x y, x, y, 1) of A, B, C, D) / orient(A, B, C) in mapped
** coordinates: the region is f > 0, and orient(A, B, C) > 0 (the map has
** determinant delta > 0, ABC is anticlockwise).  So D is inside when the
** determinant (SHAPE_PROG_CORNER) is negative.  D lies beyond chord CA,
** away from the other branch (which lies on B's side of the chord), so the
** sign of f alone decides.  Cone sides are never antiparallel: a strictly
** convex polygon's corner has an angle strictly between 0 and pi. */
static shape_choice shape_corner_decide(const shape *k, int c, const geom_point p[4], int quick,
                                        shape_trace *tr) {
  shape_args g = {.K = k, .p = {p[0], p[1], p[2]}, .o = p[3], .corner = c};
  int level = 0, s = quick ? shape_quick_corner(k, c, p) : 2;
  if (s == 2) s = shape_eps_sign(SHAPE_PROG_CORNER, g, &level);
  if (tr) *tr = (shape_trace){.rounding = 1, .corner = c, .contact = {-1, -1, -1}, .level = level};
  return s < 0 ? SHAPE_BD : s > 0 ? SHAPE_AC : SHAPE_EITHER;
}

/* What a corner's hint knows: the same answer as finding the corner again,
** since the circumscribing shape of A, B, C depends on them alone; -1 for
** any other hint (a homothet's is tried in shape_decide_hinted, first, and
** needs the quick path). */
static int shape_hint_decide(const shape *k, const geom_point p[4], int quick,
                             const shape_hint *h) {
  if (h == NULL || h->how != SHAPE_HINT_CORNER) return -1;
  return (int)shape_corner_decide(k, h->e[0], p, quick, NULL);
}

static void shape_hint_set(shape_hint *h, int how, const int e[3], int n) {
  if (h == NULL || n > 255) return;
  *h = (shape_hint){.how = (unsigned char)how};
  for (int r = 0; r < (how == SHAPE_HINT_CORNER ? 1 : 3); r++) h->e[r] = (unsigned char)e[r];
}

static shape_choice shape_corner_hinted(const shape *k, int c, const geom_point p[4], int quick,
                                        shape_trace *tr, shape_hint *h) {
  shape_hint_set(h, SHAPE_HINT_CORNER, (const int[3]){c, 0, 0}, k->n);
  return shape_corner_decide(k, c, p, quick, tr);
}

/* The quick path (shape_quick.c) answers first where its signs are
** certain, with this path's answer (the argument is there). */
shape_choice shape_polygon_decide(const shape *k, const geom_point p[4], int quick,
                                  shape_trace *tr, shape_hint *h) {
  int sup[3], t[3], hinted = shape_hint_decide(k, p, quick, h);
  if (hinted >= 0) return (shape_choice)hinted;
  if (!quick || shape_quick_supports(k, p, sup) != 0) {
    sup[0] = shape_support(k, p[0], p[1]);
    sup[1] = shape_support(k, p[1], p[2]);
    sup[2] = shape_support(k, p[2], p[0]);
  }
  /* All three cannot coincide: the three directions span the plane
  ** positively, and a corner's normal cone is narrower than pi. */
  if (sup[0] == sup[1] || sup[0] == sup[2]) return shape_corner_hinted(k, sup[0], p, quick, tr, h);
  if (sup[1] == sup[2]) return shape_corner_hinted(k, sup[1], p, quick, tr, h);
  int ans = quick ? shape_quick_homothet(k, sup, p, t) : -1;
  if (ans >= 0) {
    if (tr) memcpy(tr->contact, t, sizeof t);
    shape_hint_set(h, SHAPE_HINT_HOMOTHET, t, k->n);
    return (shape_choice)ans;
  }
  int d3 = shape_contacts(k, sup, p, t);
  if (d3 == 0) {
    if (tr) tr->failed = 1;
    return SHAPE_EITHER;
  }
  if (tr) memcpy(tr->contact, t, sizeof t);
  shape_hint_set(h, SHAPE_HINT_HOMOTHET, t, k->n);
  return shape_homothet_decide(k, t, d3, p, tr);
}

/* The ellipse: D inside the ellipse homothet through A, B, C when the
** determinant is positive (as the incircle test: Q = L^T L with det L > 0
** maps the ellipse to the unit circle).  The boundary case answers either,
** as DT does for cocircular sites: a smooth shape has no support ties, and
** four sites on one ellipse are the rule's genuine ties. */
static shape_choice shape_ellipse_decide(const shape *k, const geom_point p[4], shape_trace *tr) {
  shape_args g = {.K = k, .p = {p[0], p[1], p[2]}, .o = p[3]};
  int s = shape_sign(SHAPE_PROG_ELLIPSE, &g);
  if (tr) tr->level = s == 0 ? 2 : 0;
  return s > 0 ? SHAPE_BD : s < 0 ? SHAPE_AC : SHAPE_EITHER;
}

/* ---- the variants' decisions ----------------------------------------------
**
** The public verbs call K's variant (shape_impl_set); the general polygon's
** and the ellipse's are here, the square's and the hexagon's with their
** decisions (shape_square.c, shape_hex.c). */

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

/* A hint holds edge and corner indices in bytes. */
static int shape_polygon_wants_hints(const shape *k) {
  return k->n <= 255;
}

SHAPE_VARIANT_OPS(polygon, NULL, NULL, shape_polygon_wants_hints);

static shape_choice shape_ellipse_variant_decide(const shape *k, geom_point a, geom_point b,
                                                 geom_point c, geom_point d, shape_trace *tr) {
  const geom_point p[4] = {a, b, c, d};
  return shape_ellipse_decide(k, p, tr);
}

/* An ellipse's decision is one determinant: nothing to hint. */
static shape_choice shape_ellipse_hinted(const shape *k, geom_point a, geom_point b,
                                         geom_point c, geom_point d, shape_hint *h) {
  (void)h;
  const geom_point p[4] = {a, b, c, d};
  return shape_ellipse_decide(k, p, NULL);
}

static int shape_ellipse_wants_hints(const shape *k) {
  (void)k;
  return 0;
}

const shape_ops shape_ops_ellipse = {shape_ellipse_variant_decide, shape_ellipse_hinted,
                                     shape_ellipse_wants_hints};
