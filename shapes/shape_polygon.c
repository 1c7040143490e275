/*
** shape_polygon.c: the empty-shape decision of a convex polygon, the
** general polygon variant's (shape_internal.h) and every polygon variant's
** fallback: support points, circumscribing homothets, rounding shapes of
** corners, and the hints that remember them.  The quick path
** (shape_quick.c) answers first where its signs are certain; the exact
** predicates are in shape_arith.c; docs/emptyshape.md has the definitions
** and the special-position rule.
*/
#include <string.h>
#include "shape.h"
#include "shape_internal.h"

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
static int shape_support_run(const shape *k, geom_point p, geom_point q) {
  int hw = shape_cross_eps(k, 0, p, q) > 0 ? 0 : 1;
  int lo = 1, hi = k->n;   /* edge 0 is always before: its angle is 0 */
  while (lo < hi) {
    int mid = lo + (hi - lo) / 2;
    if (shape_before(k, mid, p, q, hw)) lo = mid + 1;
    else hi = mid;
  }
  return lo % k->n;
}

/* The support depends on K and Q - P alone, so on a grid, where a few
** short directions come back everywhere, it is kept per thread
** (shape_seen.c) under Q - P when that difference is exact. */
int shape_support(const shape *k, geom_point p, geom_point q) {
  shape_seen_key key;
  const geom_point pq[2] = {p, q};
  int v;
  if (!shape_seen_on()) return shape_support_run(k, p, q);
  shape_seen_start(&key, k, SHAPE_SEEN_SUPPORT, NULL, 0);
  if (!shape_seen_diffs(&key, pq, 2, p)) return shape_support_run(k, p, q);
  if (shape_seen_find(&key, &v)) return v;
  v = shape_support_run(k, p, q);
  shape_seen_keep(&key, v);
  return v;
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

/* The circumscribing homothet of A, B, C by the contact search, and D's
** test against it: the general path's slow end. */
static shape_choice shape_homothet_found(const shape *k, const int sup[3], const geom_point p[4],
                                         shape_trace *tr, shape_hint *h) {
  int t[3], d3 = shape_contacts(k, sup, p, t);
  if (d3 == 0) {
    if (tr) tr->failed = 1;
    return SHAPE_EITHER;
  }
  if (tr) memcpy(tr->contact, t, sizeof t);
  shape_hint_set(h, SHAPE_HINT_HOMOTHET, t, k->n);
  return shape_homothet_decide(k, t, d3, p, tr);
}

/* The same, kept per thread (shape_seen.c) under the differences B - A,
** C - A, D - A: the answer and the contact triple are functions of K and
** those alone (every sign the search and the test read is exact and
** translation-invariant, and so are the supports), so a grid's
** configurations, which come back everywhere, are searched once.  Kept as
** one int: the choice in bits 0-1, bit 2 set when a triple was found, its
** edges in bits 4-11, 12-19, 20-27 (at most 255 edges).  Asked only where
** the quick path gave up, so uniform sites pay nothing for it. */
static shape_choice shape_homothet_seen(const shape *k, const int sup[3], const geom_point p[4],
                                        shape_hint *h) {
  shape_seen_key key;
  shape_seen_start(&key, k, SHAPE_SEEN_DECIDE, NULL, 0);
  if (!shape_seen_diffs(&key, p, 4, p[0])) return shape_homothet_found(k, sup, p, NULL, h);
  int v;
  if (!shape_seen_find(&key, &v)) {
    shape_hint left = {0};
    shape_choice c = shape_homothet_found(k, sup, p, NULL, &left);
    v = (int)c | (left.how == SHAPE_HINT_HOMOTHET) << 2 | left.e[0] << 4 | left.e[1] << 12 |
        left.e[2] << 20;
    shape_seen_keep(&key, v);
  }
  const int t[3] = {v >> 4 & 255, v >> 12 & 255, v >> 20 & 255};
  if (v >> 2 & 1) shape_hint_set(h, SHAPE_HINT_HOMOTHET, t, k->n);
  return (shape_choice)(v & 3);
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
  if (tr == NULL && quick && k->n <= 255 && shape_seen_on())
    return shape_homothet_seen(k, sup, p, h);
  return shape_homothet_found(k, sup, p, tr, h);
}

/* A homothet's hint names the contact triple of A, B, C (shape.h: filled
** by a decision of the same K, A, B, C), so D's test needs only det3's
** sign and the arc. */
shape_choice shape_polygon_at(const shape *k, const int t[3], const geom_point p[4]) {
  return shape_homothet_decide(k, t, shape_det3h_sign(k, t), p, NULL);
}

/* The whole decision and the hint it leaves, kept per thread (as
** shape_homothet_seen keeps its end, under B - A, C - A, D - A): for the
** variants with a decision of their own, whose general path runs only
** where that gave up (the hexagon's, at a tie); there the supports and
** the quick path's attempts are skipped too.  Kept as one int: the choice in bits 0-1, the
** hint's how in bits 2-3, its edges in bits 4-11, 12-19, 20-27. */
shape_choice shape_polygon_kept(const shape *k, const geom_point p[4], int quick, shape_hint *h) {
  shape_seen_key key;
  if (!quick || k->n > 255 || !shape_seen_on()) return shape_polygon_decide(k, p, quick, NULL, h);
  shape_seen_start(&key, k, SHAPE_SEEN_WHOLE, NULL, 0);
  if (!shape_seen_diffs(&key, p, 4, p[0])) return shape_polygon_decide(k, p, quick, NULL, h);
  int v;
  if (!shape_seen_find(&key, &v)) {
    shape_hint left = h != NULL ? *h : (shape_hint){0};
    shape_choice c = shape_polygon_decide(k, p, quick, NULL, &left);
    v = (int)c | left.how << 2 | left.e[0] << 4 | left.e[1] << 12 | left.e[2] << 20;
    shape_seen_keep(&key, v);
  }
  if (h != NULL && (v >> 2 & 3) != SHAPE_HINT_NONE)
    *h = (shape_hint){(unsigned char)(v >> 2 & 3), {(unsigned char)(v >> 4),
                                                     (unsigned char)(v >> 12),
                                                     (unsigned char)(v >> 20)}};
  return (shape_choice)(v & 3);
}

/* ---- the general polygon's variant (shape_internal.h) -------------------- */

/* A hint holds edge and corner indices in bytes. */
static int shape_polygon_wants_hints(const shape *k) {
  return k->n <= 255;
}

SHAPE_VARIANT_OPS(polygon, NULL, NULL, shape_polygon_wants_hints, 0);
