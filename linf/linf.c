/*
** linf.c: the l_inf circumcubes of d + 1 points by the characterisation of
** linf.h (the thesis's proof of theorem 14 made an algorithm), and the
** exact point-in-cube test.
*/
#include "linf.h"
#include "geom_exact_internal.h"

/* The sign of a - b + c - e, exactly.  Every coordinate of the contract
** (geom.h) is below 2^100 in magnitude, so no partial sum overflows; then
** each two-sum of the expansion is error-free (an addition's rounding error
** is representable even among subnormals), and the sign of a nonoverlapping
** expansion is the sign of its largest component.  No filter: four terms
** cost four two-sums. */
static int linf_sign4(double a, double b, double c, double e) {
  double h1[2], h2[3], h3[4];
  int n1 = geom_grow_expansion(1, &a, -b, h1);
  int n2 = geom_grow_expansion(n1, h1, c, h2);
  int n3 = geom_grow_expansion(n2, h2, -e, h3);
  double top = h3[n3 - 1];
  return (top > 0) - (top < 0);
}

/* What the circumcubes of d + 1 points depend on: each coordinate's largest
** and smallest value and the points attaining them (bit masks), the
** coordinate k of largest extent, and the coordinates of that extent. */
typedef struct linf_frame {
  int d;
  unsigned all, max_at[LINF_DIM_MAX], min_at[LINF_DIM_MAX], forced;
  double hi[LINF_DIM_MAX], lo[LINF_DIM_MAX];
  int k;
} linf_frame;

static void linf_frame_make(const double *pts, int d, linf_frame *f) {
  f->d = d;
  f->all = (1u << (d + 1)) - 1;
  for (int i = 0; i < d; i++) {
    f->hi[i] = f->lo[i] = pts[i];
    for (int j = 1; j <= d; j++) {
      double x = pts[j * d + i];
      if (x > f->hi[i]) f->hi[i] = x;
      if (x < f->lo[i]) f->lo[i] = x;
    }
    f->max_at[i] = f->min_at[i] = 0;
    for (int j = 0; j <= d; j++) {
      if (pts[j * d + i] == f->hi[i]) f->max_at[i] |= 1u << j;
      if (pts[j * d + i] == f->lo[i]) f->min_at[i] |= 1u << j;
    }
  }
  f->k = 0;
  for (int i = 1; i < d; i++)   /* extent i - extent k = hi_i - lo_i + lo_k - hi_k */
    if (linf_sign4(f->hi[i], f->lo[i], f->lo[f->k], f->hi[f->k]) > 0) f->k = i;
  f->forced = 0;
  for (int i = 0; i < d; i++)
    if (linf_sign4(f->hi[i], f->lo[i], f->lo[f->k], f->hi[f->k]) == 0) f->forced |= 1u << i;
}

/* Do one face per coordinate cover every point, without the forced
** coordinates' second faces?  Then every radius above D/2 has a
** circumcube (each coordinate's interval is wider than its extent and can
** put the chosen face at the chosen extreme).  Cost O(2^d d). */
static int linf_cover_above(const linf_frame *f) {
  for (unsigned s = 0; s < 1u << f->d; s++) {
    unsigned cover = 0;
    for (int i = 0; i < f->d; i++) cover |= (s >> i & 1) ? f->min_at[i] : f->max_at[i];
    if (cover == f->all) return 1;
  }
  return 0;
}

/* The choice s (bit t: the t-th unforced coordinate takes its min face)
** as the faces' masks part[t]; returns the points covered with the forced
** coordinates' base. */
static unsigned linf_choice(const linf_frame *f, const int *u, int nu, unsigned s,
                            unsigned base, unsigned *part) {
  unsigned cover = base;
  for (int t = 0; t < nu; t++) {
    part[t] = (s >> t & 1) ? f->min_at[u[t]] : f->max_at[u[t]];
    cover |= part[t];
  }
  return cover;
}

/* Could coordinate t of a cover slide (the others cover every point)? */
static int linf_slack(const linf_frame *f, const unsigned *part, int nu, unsigned base) {
  for (int t = 0; t < nu; t++) {
    unsigned cover = base;
    for (int w = 0; w < nu; w++)
      if (w != t) cover |= part[w];
    if (cover == f->all) return 1;
  }
  return 0;
}

static void linf_cube_make(const linf_frame *f, unsigned s, linf_cube *c) {
  c->d = f->d;
  c->top = f->hi[f->k];
  c->bottom = f->lo[f->k];
  for (int i = 0, t = 0; i < f->d; i++) {
    if (f->forced >> i & 1) {
      c->side[i] = 0;
      c->face[i] = f->hi[i];
    } else {
      int low = s >> t++ & 1;
      c->side[i] = (signed char)(low ? -1 : 1);
      c->face[i] = low ? f->lo[i] : f->hi[i];
    }
  }
}

int linf_circumcubes(const double *pts, int d, linf_cube *out) {
  linf_frame f;
  linf_frame_make(pts, d, &f);
  if (linf_cover_above(&f)) return LINF_INFINITE;
  int u[LINF_DIM_MAX], nu = 0;
  unsigned base = 0, part[LINF_DIM_MAX];
  for (int i = 0; i < d; i++) {
    if (f.forced >> i & 1) base |= f.max_at[i] | f.min_at[i];
    else u[nu++] = i;
  }
  int count = 0;
  for (unsigned s = 0; s < 1u << nu; s++) {
    if (linf_choice(&f, u, nu, s, base, part) != f.all) continue;
    if (linf_slack(&f, part, nu, base)) return LINF_INFINITE;
    linf_cube_make(&f, s, &out[count++]);
  }
  return count;
}

int linf_cube_side(const linf_cube *c, const double *q) {
  int on = 0;
  for (int i = 0; i < c->d; i++) {
    double x = q[i], face = c->face[i];
    /* near: q against the face that holds points; far: against the face
    ** at distance D = top - bottom beyond it, inside the cube */
    int near, far;
    if (c->side[i] >= 0) {
      near = (face > x) - (face < x);
      far = linf_sign4(x, face, c->top, c->bottom);   /* x - (face - D) */
    } else {
      near = (x > face) - (x < face);
      far = -linf_sign4(x, face, c->bottom, c->top);  /* (face + D) - x */
    }
    if (near < 0 || far < 0) return 1;
    on |= near == 0 || far == 0;
  }
  return on ? 0 : -1;
}
