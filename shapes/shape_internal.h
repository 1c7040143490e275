/*
** shape_internal.h: what a shape keeps beside its public fields (its
** variant, chosen once when it is made, with that variant's decisions and
** tables), and the filtered arithmetic behind the shape predicates
** (shape_arith.c): one program per predicate, run first on doubles with a
** proven error bound, then, when the bound cannot tell the sign, exactly:
** on floating-point expansions (from one pool, shape_xp.c) when the inputs
** allow it, else on GMP rationals (from another, shape_mpq.c).  Private to
** shapes/ (not installed).
*/
#ifndef FLIPLAB_SHAPE_INTERNAL_H
#define FLIPLAB_SHAPE_INTERNAL_H

#include <gmp.h>
#include <stdint.h>
#include "fliplab_config.h"
#include "predicates.h"   /* geom_stage */
#include "shape.h"

/* ---- variants -------------------------------------------------------------
**
** Every shape is one variant, each with a decision of its own, told apart
** once when the shape is made (shape.c, shape_impl_set, one exhaustive
** switch): an axis-parallel square (bounding boxes, shape_square.c), a
** square turned by pi/4 (the same in a turned frame, shape_square.c), an
** affinely regular hexagon (slabs, shape_hex.c), every other polygon
** (supports and homothets, shape_polygon.c) and an ellipse (one determinant,
** shape_ellipse.c).  A variant is its table of decisions, shape_ops; the public
** verbs call through it and test no flag. */
typedef enum shape_variant {
  SHAPE_V_POLYGON, SHAPE_V_SQUARE, SHAPE_V_DIAMOND, SHAPE_V_HEXAGON, SHAPE_V_ELLIPSE
} shape_variant;

/* A variant's answers to shape_decide (the sites finite, *tr cleared or tr
** NULL), shape_decide_hinted and shape_wants_hints.  The sites are passed
** as values, as the public verbs take them, so that those verbs jump
** straight into the variant's code. */
typedef struct shape_ops {
  shape_choice (*decide)(const shape *k, geom_point a, geom_point b, geom_point c, geom_point d,
                         shape_trace *tr);
  shape_choice (*decide_hinted)(const shape *k, geom_point a, geom_point b, geom_point c,
                                geom_point d, shape_hint *h);
  int (*wants_hints)(const shape *k);
} shape_ops;

FLIPLAB_INTERNAL const shape_ops shape_ops_polygon, shape_ops_square, shape_ops_diamond,
  shape_ops_hexagon, shape_ops_ellipse;

/* The private part of a shape (k->impl), owned by it.  A polygon's tables
** are built once it is checked; those it does not have stay NULL. */
struct shape_impl {
  shape_variant variant;
  const shape_ops *ops;
  unsigned char *half;       /* 1 for the edges turned by [pi, 2 pi) from edge 0 */
  struct shape_memo *memo;   /* shape-only determinants (shape_arith.c) */
  struct shape_quick *quick; /* the quick decision's table (shape_quick.c) */
  struct shape_hex *hexa;    /* an affinely regular hexagon's slabs (shape_hex.c) */
  int moderate;              /* every coordinate (form entry) in the expansions' range */
  uint64_t serial;           /* this shape's number: the n-th shape made (shape.c) */
};

static inline shape_variant shape_variant_of(const shape *k) {
  return k->impl->variant;
}

/* What a predicate reads: the shape, up to four rows (a polygon edge and a
** site each), the point o every site is taken relative to (the
** predicates are translation-invariant: differences to o keep the double
** run accurate), and whether the value or its perturbation coefficient is
** wanted (docs/emptyshape.md: the shape turned by an infinitesimal angle,
** computed as the sites turned the other way). */
typedef struct shape_args {
  const shape *K;
  int e[4];             /* polygon edges (edge i joins vertices i and i+1) */
  geom_point p[4];      /* the rows' sites */
  geom_point o;         /* the origin of the site differences */
  int corner;           /* SHAPE_PROG_CORNER: the corner's vertex */
  int deriv;            /* 0: the value; 1: the coefficient of eps */
} shape_args;

/* The predicates, each one program (shape_arith.c).  cross: cross(e_{e[0]},
** p[1] - p[0]) (deriv: -e.(p[1] - p[0]));
** det3h: rows (e_x, e_y, h) of edges e[0..2], h = cross(k_i, k_{i+1});
** det3w: rows (e_x, e_y, w) of (e[r], p[r]), w = cross(p - o, e) (deriv: e.(p - o));
** det4: rows (e_x, e_y, h, w) of (e[r], p[r]), r < 4;
** corner: the rounding-shape determinant of p[0..2] about o (shape_polygon.c);
** ellipse: rows (x, y, Q(x, y)) of p[r] - o, r < 3. */
typedef enum shape_prog {
  SHAPE_PROG_CROSS, SHAPE_PROG_DET3H, SHAPE_PROG_DET3W, SHAPE_PROG_DET4, SHAPE_PROG_CORNER,
  SHAPE_PROG_ELLIPSE, SHAPE_PROG_COUNT
} shape_prog;

/* The exact sign of a program's value (filter, then expansions, then GMP). */
FLIPLAB_INTERNAL int shape_sign(shape_prog p, const shape_args *g);
/* The sign under the perturbation: the value's sign, or when it is 0 the
** sign of the eps coefficient; *level (may be NULL) gets 0 or 1, or 2
** when both are 0. */
FLIPLAB_INTERNAL int shape_eps_sign(shape_prog p, shape_args g, int *level);

/* Tests: 1 makes every sign skip the double run and take the exact one
** (so a decision can be compared with its purely exact twin); 0 restores.
** The exact run's stage is the expansions' unless geom_exact_gmp_only
** (predicates.h) sends it to GMP. */
FLIPLAB_INTERNAL void shape_set_exact_only(int on);
FLIPLAB_INTERNAL int shape_only_exact;   /* the mode (shape_arith.c); read inline: */
static inline int shape_exact_only(void) {   /* every decision asks */
  return shape_only_exact;
}

/* The fast paths of the hot predicates (shape_arith.c): the double run
** alone, returning its sign, or 2 when it cannot tell a non-zero sign (or
** in the exact-only test mode); the caller then asks shape_eps_sign, so
** every answer is the exact one.  shape_fast_cross: SHAPE_PROG_CROSS of
** edge e and p, q.  shape_w3: the w values of three rows (e[r], p[r])
** relative to o, computed once; shape_fast_det4: SHAPE_PROG_DET4 of those
** rows and a fourth row (m, o), whose w is 0, from them;
** shape_fast_det3w: SHAPE_PROG_DET3W of the rows from them (o = p[0]).
** shape_det3h_sign: the exact sign of SHAPE_PROG_DET3H of edges e[0..2]
** (kept per shape, else computed). */
typedef struct shape_w3 {
  double v[3], t[3];    /* each w's double value and twin */
  int k[3];             /* and rounding count */
  int poison;
} shape_w3;

FLIPLAB_INTERNAL int shape_fast_cross(const shape *K, int e, geom_point p, geom_point q);
FLIPLAB_INTERNAL void shape_w3_prep(shape_w3 *w, const shape *K, const int e[3],
                                    const geom_point p[3], geom_point o);
FLIPLAB_INTERNAL int shape_fast_det4(const shape_w3 *w, const shape *K, const int e[3], int m);
FLIPLAB_INTERNAL int shape_fast_det3w(const shape_w3 *w, const shape *K, const int e[3]);
FLIPLAB_INTERNAL int shape_det3h_sign(const shape *K, const int e[3]);

/* The contact edges t (of A, B, C = p[0..2]) of the circumscribing
** homothet of the anticlockwise triangle p whose supports s_AB, s_BC, s_CA
** (sup) differ, and det3's sign; 0 when none is found (shape_polygon.c). */
FLIPLAB_INTERNAL int shape_contacts(const shape *k, const int sup[3], const geom_point p[3],
                                    int t[3]);

/* The number of edges in the cyclic range [from, to), from != to, both in [0, n). */
static inline int shape_range(const shape *k, int from, int to) {
  return to > from ? to - from : to - from + k->n;
}

/* The kept shape-only determinants of a polygon (shape_arith.c): built by
** shape.c once a polygon is checked (0, or -1 out of memory; none for an
** ellipse or more than SHAPE_MEMO_MAX edges), freed with the shape. */
FLIPLAB_INTERNAL int shape_memo_build(shape *k);
FLIPLAB_INTERNAL void shape_memo_free(shape *k);

/* The kept det3h double runs as flat arrays indexed (i n + j) n + k: the
** values, their twins, the exact signs, and kmax, the largest rounding
** count of any entry; 0, or -1 when none are kept or one is poisoned. */
typedef struct shape_memo_flat_view {
  const double *val, *twin;
  const signed char *sgn;
  int kmax;
} shape_memo_flat_view;

FLIPLAB_INTERNAL int shape_memo_flat(const shape *k, shape_memo_flat_view *out);

/* The quick polygon decision (shape_quick.c): the table of a polygon with
** kept determinants, built once it is checked (0, or -1 out of memory; none
** otherwise), freed with the shape. */
FLIPLAB_INTERNAL int shape_quick_build(shape *k);
FLIPLAB_INTERNAL void shape_quick_free(shape *k);
/* 1 when the quick path may be asked about the sites p[0..3]: k has a
** table, the exact-only test mode is off, and every coordinate is 0 or of
** magnitude at least 2^-100 (its underflow argument); else 0.  The three
** verbs below require it. */
FLIPLAB_INTERNAL int shape_quick_ready(const shape *k, const geom_point p[4]);
/* 1 when K has a quick table and the exact-only test mode is off: the
** part of shape_quick_ready that does not look at the sites. */
static inline int shape_quick_on(const shape *k) {
  return k->impl->quick != NULL && !shape_exact_only();
}
/* The support vertices s_AB, s_BC, s_CA of p[0..2] into sup: 0 when every
** sign they rest on is certain (they are then shape_support's), else -1. */
FLIPLAB_INTERNAL int shape_quick_supports(const shape *k, const geom_point p[3], int sup[3]);
/* The homothet decision of the anticlockwise quadrilateral p (supports sup,
** three different vertices): shape_decide's answer and the contact triple
** into t, or -1 when some sign is not certain (then nothing is known). */
FLIPLAB_INTERNAL int shape_quick_homothet(const shape *k, const int sup[3], const geom_point p[4],
                                          int t[3]);
/* shape_quick_homothet's answer when t is already known to be the
** contact triple of p[0..2] (no supports, no search), or -1. */
FLIPLAB_INTERNAL int shape_quick_at(const shape *k, const int t[3], const geom_point p[4]);
/* The certain sign of SHAPE_PROG_CORNER of corner c, p[0..2] about o = p[3]
** (shape_polygon.c's rounding-shape test), or 2. */
FLIPLAB_INTERNAL int shape_quick_corner(const shape *k, int c, const geom_point p[4]);

/* The exact runs of program p decided by stage s (GEOM_STAGE_EXPANSION or
** GEOM_STAGE_GMP) over the process; shape_exact_calls is their total. */
FLIPLAB_INTERNAL unsigned long shape_exact_stage_calls(shape_prog p, geom_stage s);

/* ---- answers asked again --------------------------------------------------
**
** Exact answers kept per thread (shape_seen.c, which has the argument),
** keyed by the shape's serial number, what was asked (a program, or
** SHAPE_SEEN_SUPPORT, SHAPE_SEEN_DECIDE, SHAPE_SEEN_WHOLE: a polygon's
** support, its general path's contact search and D's test, and its whole
** general path, shape_polygon.c), up to 7 small integers and the
** exact differences of up to 4 sites to an origin.  shape_seen_start
** clears a key and sets its shape, what and integers; shape_seen_diffs
** sets the differences of p[0..rows) to o, 1 when all are exact (else the
** key may not be used).  shape_seen_find: 1 and *v when the key's answer is
** kept; shape_seen_keep keeps it.  shape_seen_on: 0 in the tests'
** reference modes, which must compute everything.  shape_seen_hits: the
** answers of kind what found kept, over the process. */
#define SHAPE_SEEN_SUPPORT SHAPE_PROG_COUNT
#define SHAPE_SEEN_DECIDE (SHAPE_PROG_COUNT + 1)
#define SHAPE_SEEN_WHOLE (SHAPE_PROG_COUNT + 2)
#define SHAPE_SEEN_WHATS (SHAPE_PROG_COUNT + 3)
typedef struct shape_seen_key {
  uint64_t serial;
  int what, n[7];
  double d[8];
} shape_seen_key;
_Static_assert(sizeof(shape_seen_key) == 13 * 8, "a key has no padding (compared as bytes)");

FLIPLAB_INTERNAL int shape_seen_on(void);
FLIPLAB_INTERNAL void shape_seen_start(shape_seen_key *k, const shape *K, int what, const int *n,
                                       int cnt);
FLIPLAB_INTERNAL int shape_seen_diffs(shape_seen_key *k, const geom_point *p, int rows,
                                      geom_point o);
FLIPLAB_INTERNAL int shape_seen_find(const shape_seen_key *k, int *v);
FLIPLAB_INTERNAL void shape_seen_keep(const shape_seen_key *k, int v);
FLIPLAB_INTERNAL unsigned long shape_seen_hits(int what);

/* 1 when every coordinate of polygon K (every entry of an ellipse's form)
** lies in the expansion run's range (shape_arith.c): kept in K's moderate
** when K is made. */
FLIPLAB_INTERNAL int shape_xp_moderate(const shape *k);

/* 1 when a - b is a double, exactly (GMP: for building a shape's tables);
** *d = fl(a - b) either way. */
FLIPLAB_INTERNAL int shape_exact_diff(double a, double b, double *d);

/* The empty-square rule (shape_square.c): 1 when polygon K is an
** axis-parallel square (its rule is the L_inf one, whatever the size and
** position), else 0; and for such a K the decision of the anticlockwise
** quadrilateral p, SHAPE_AC or SHAPE_BD, or -1 when a comparison ties
** (special position, or D on the square): shape_decide's answer. */
FLIPLAB_INTERNAL int shape_square_is(const shape *k);
FLIPLAB_INTERNAL int shape_square_decide(const geom_point p[4]);
/* The same for a square turned by pi/4 (the diamond, the L_1 ball: its
** vertices' frames (x + y, y - x) exact and an axis-parallel square), on
** the sites' frames: -1 also when a site's frame is not exact. */
FLIPLAB_INTERNAL int shape_diamond_is(const shape *k);
FLIPLAB_INTERNAL int shape_diamond_decide(const geom_point p[4]);
/* The empty-hexagon rule of an affinely regular hexagon (shape_hex.c): for
** a polygon K that is one (a centrally symmetric hexagon with e1 = e0 + e2,
** every edge an exact difference of its vertices) its slabs into its
** hexa (0, or -1 out of memory; hexa stays NULL for any other polygon),
** freed with the shape.  For such a K the decision of the anticlockwise
** quadrilateral p, SHAPE_AC or SHAPE_BD, or -1 when a comparison is too
** close to call: shape_decide's answer, and what it found of the shape in
** *out (may be NULL) when it answers.  shape_hex_at: the same decision when
** t holds the contact edges of p[0..2] (a hint), or -1 when D's test is too
** close to call or t fits no homothet (then nothing is known). */
FLIPLAB_INTERNAL int shape_hex_build(shape *k);
FLIPLAB_INTERNAL void shape_hex_free(shape *k);
FLIPLAB_INTERNAL int shape_hex_decide(const shape *k, const geom_point p[4], shape_hint *out);
FLIPLAB_INTERNAL int shape_hex_at(const shape *k, const int t[3], const geom_point p[4]);

/* ---- the variants' decisions -------------------------------------------- */

/* The general polygon decision of the anticlockwise quadrilateral p
** (shape_polygon.c): quick when the quick path may be asked (shape_quick_ready, or
** shape_quick_on for sites in the coordinate contract), with a trace and a
** hint (each may be NULL). */
FLIPLAB_INTERNAL shape_choice shape_polygon_decide(const shape *k, const geom_point p[4],
                                                   int quick, shape_trace *tr, shape_hint *h);

/* shape_polygon_decide without a trace, its answers and hints kept per
** thread (shape_seen.c): the fallback of the variants with a decision of
** their own, where the general path runs only at ties (shape_polygon.c). */
FLIPLAB_INTERNAL shape_choice shape_polygon_kept(const shape *k, const geom_point p[4], int quick,
                                                 shape_hint *h);

/* The general path's decision of p when t is the contact triple of
** p[0..2] (a homothet's hint: no supports, no contact search), exact
** whatever the sites (shape_polygon.c). */
FLIPLAB_INTERNAL shape_choice shape_polygon_at(const shape *k, const int t[3],
                                               const geom_point p[4]);

/* A polygon variant's own decision, tried where the quick path may be
** asked: the answer (it may fill *h), or -1 for the general path; and its
** answer for a homothet's hint, the contact edges t of p[0..2], or -1. */
typedef int (*shape_own_fn)(const shape *k, const geom_point p[4], shape_hint *h);
typedef int (*shape_at_fn)(const shape *k, const int t[3], const geom_point p[4]);

/* shape_decide and shape_decide_hinted of a polygon variant whose own
** decisions are own and at (NULL: none), written once and inlined with
** them constant into each variant's table (shape_polygon.c, shape_square.c,
** shape_hex.c): an own answer is the general path's (their files have the
** arguments), so it is taken first; a homothet's hint (lot's commonest
** call) is tried before anything else, with the quick path's shape_quick_at
** after at, and when neither is certain the general path decides from the
** hint's triple (on a grid, where ties make the quick answers give up,
** that skips the supports and the contact search of most decisions); with
** no hint, the own decision, then the general path (its answers kept,
** shape_polygon_kept, when keep is set: for an own decision that gives up
** at ties only, so that the general path's configurations come back;
** the square's and the diamond's give up on staircases too, common on
** uniform sites, where keeping costs more than it saves). */
static FLIPLAB_ALWAYS_INLINE shape_choice shape_variant_decide(const shape *k,
                                                               const geom_point p[4],
                                                               shape_trace *tr, shape_own_fn own) {
  int quick = shape_quick_ready(k, p);
  int ans = quick && own != NULL && tr == NULL ? own(k, p, NULL) : -1;
  return ans >= 0 ? (shape_choice)ans : shape_polygon_decide(k, p, quick, tr, NULL);
}

static FLIPLAB_ALWAYS_INLINE shape_choice shape_variant_hinted(const shape *k,
                                                               const geom_point p[4],
                                                               shape_hint *h, shape_own_fn own,
                                                               shape_at_fn at, int keep) {
  int quick = shape_quick_on(k);
  if (quick && h != NULL && h->how == SHAPE_HINT_HOMOTHET) {
    const int t[3] = {h->e[0], h->e[1], h->e[2]};
    int ans = at != NULL ? at(k, t, p) : -1;
    if (ans < 0) ans = shape_quick_at(k, t, p);
    return ans >= 0 ? (shape_choice)ans : shape_polygon_at(k, t, p);
  }
  int ans = quick && own != NULL ? own(k, p, h) : -1;
  if (ans >= 0) return (shape_choice)ans;
  return keep ? shape_polygon_kept(k, p, quick, h) : shape_polygon_decide(k, p, quick, NULL, h);
}

/* The table shape_ops_NAME of a polygon variant whose own decisions are OWN
** and AT (NULL: none), whose shape_wants_hints is WANTS and whose general
** path's answers are kept when KEEP is 1: the two decisions above with
** OWN, AT and KEEP inlined, the sites taken as values. */
#define SHAPE_VARIANT_OPS(NAME, OWN, AT, WANTS, KEEP)                                          \
  static shape_choice shape_##NAME##_variant_decide(const shape *k, geom_point a, geom_point b, \
                                                    geom_point c, geom_point d,                 \
                                                    shape_trace *tr) {                          \
    const geom_point p[4] = {a, b, c, d};                                                       \
    return shape_variant_decide(k, p, tr, OWN);                                                 \
  }                                                                                             \
  static shape_choice shape_##NAME##_variant_hinted(const shape *k, geom_point a, geom_point b, \
                                                    geom_point c, geom_point d,                 \
                                                    shape_hint *h) {                            \
    const geom_point p[4] = {a, b, c, d};                                                       \
    return shape_variant_hinted(k, p, h, OWN, AT, KEEP);                                        \
  }                                                                                             \
  const shape_ops shape_ops_##NAME = {shape_##NAME##_variant_decide,                            \
                                      shape_##NAME##_variant_hinted, WANTS}

/* ---- exact expansions -----------------------------------------------------
**
** A pool of floating-point expansions (shape_xp.c): registers in one arena,
** register 0 the value 0.  The expansion run of shape_arith.c takes its
** registers here; a run that outgrows the arena or the register count
** marks the pool full, every later verb answers register 0, and the run's
** result is not read (GMP decides).  The verbs mirror the rationals' below:
** a double, an expansion of len components (copied), a - b of two
** doubles, i + j (i - j when neg), -i, i j, and the sign of register i. */
#define SHAPE_XP_REGS 320
#define SHAPE_XP_ROOM 4096
typedef struct shape_xp {
  int n, used;              /* registers handed out, arena doubles used */
  int full;                 /* 1: out of room; nothing computed since is exact */
  int off[SHAPE_XP_REGS], len[SHAPE_XP_REGS];
  double d[SHAPE_XP_ROOM];
} shape_xp;

FLIPLAB_INTERNAL void shape_xp_init(shape_xp *X);
FLIPLAB_INTERNAL int shape_xp_d(shape_xp *X, double a);
FLIPLAB_INTERNAL int shape_xp_put(shape_xp *X, const double *e, int len);
FLIPLAB_INTERNAL int shape_xp_diff(shape_xp *X, double a, double b);
FLIPLAB_INTERNAL int shape_xp_add(shape_xp *X, int i, int j, int neg);
FLIPLAB_INTERNAL int shape_xp_neg(shape_xp *X, int i);
FLIPLAB_INTERNAL int shape_xp_mul(shape_xp *X, int i, int j);
FLIPLAB_INTERNAL int shape_xp_sign(const shape_xp *X, int i);

/* ---- exact rationals ------------------------------------------------------
**
** A pool of GMP rationals (shape_mpq.c), each register initialised when it
** is first handed out and all cleared together: every exact run of shapes/
** takes its registers here, the predicates' programs (shape_arith.c), the
** sweep's keys (shape_sweep_*.c) and the tables' exactness checks.  The
** programs are fixed and far smaller than the pool, so running out is a bug
** (abort). */
#define SHAPE_MPQ_MAX 320
typedef struct shape_mpq {
  int n;                    /* registers handed out */
  mpq_t s;                  /* scratch of the verbs below */
  mpq_t r[SHAPE_MPQ_MAX];
} shape_mpq;

FLIPLAB_INTERNAL void shape_mpq_init(shape_mpq *P);
FLIPLAB_INTERNAL void shape_mpq_clear(shape_mpq *P);
/* The sign of x, a register of P, and P cleared: how an exact run ends. */
FLIPLAB_INTERNAL int shape_mpq_done(shape_mpq *P, mpq_srcptr x);
/* A new register (its value 0), a double, a - b of two doubles, a b - c d. */
FLIPLAB_INTERNAL mpq_ptr shape_mpq_new(shape_mpq *P);
FLIPLAB_INTERNAL mpq_ptr shape_mpq_d(shape_mpq *P, double a);
FLIPLAB_INTERNAL mpq_ptr shape_mpq_diff(shape_mpq *P, double a, double b);
FLIPLAB_INTERNAL mpq_ptr shape_mpq_cross(shape_mpq *P, mpq_srcptr a, mpq_srcptr b, mpq_srcptr c,
                                         mpq_srcptr d);

#endif
