/*
** weighted.c: the sites that the weighted Delaunay rule WDT leaves out.
**
** With per-site weights the rule keeps the lower convex hull of the sites
** lifted to (x, y, x^2 + y^2 - w).  A site whose lifted point lies above
** that hull is redundant: its power cell is empty and no triangulation
** that uses it is regular.  lot's flips keep every site a vertex, so they
** end at a LOT in which every strictly convex quadrilateral is regular,
** but around a redundant site the lifted surface may fold: an interior
** edge u-v of triangles (u, v, a) and (v, u, d) is concave when d's lifted
** point lies below the plane of u, v, a (geom_power > 0).  A LOT flips
** every such edge of a strictly convex quadrilateral, so a concave edge
** has a quadrilateral u d v a that is not strictly convex: one end, say u,
** lies in the closed triangle (a, d, v), and concavity says exactly that
** u's lifted point lies strictly above the plane of a, d and v.  That
** plane lies on or above the lower hull over the triangle, so u is above
** the hull: redundant, certified by three other sites and four exact
** tests.  Conversely a LOT with no concave edge is a locally convex
** lifted surface over the convex hull, hence convex, hence the lower
** hull: every site on it, the triangulation regular.
** lot_build (lot.c) therefore removes the certified sites and triangulates
** again, until no edge is concave; the sites removed are then exactly the
** redundant ones (none of them is a lower-hull vertex, so the lower hull
** of the rest is that of all).
*/
#include "mesh.h"
#include "weighted.h"

/* The end of the interior edge opposite corner c (triangle (a, b, c0), a
** at c, d beyond b-c0) that certifies itself redundant, as an input index
** (m->inp), or LOT_NONE when the edge is not concave.  Cost: one power
** test, two orientation tests for a concave edge. */
static uint32_t lot_weighted_edge(const lot_mesh *m, const double *w, uint32_t c) {
  uint32_t a = m->tv[c], b = m->tv[lot_next3(c)], c0 = m->tv[lot_prev3(c)];
  uint32_t d = m->tv[m->tn[c]];
  const uint32_t *in = m->inp;
  const double ww[4] = {w[in[a]], w[in[b]], w[in[c0]], w[in[d]]};
  const geom_point *p = m->p;
  if (geom_power(p[a], p[b], p[c0], p[d], ww) <= 0) return LOT_NONE;
  /* quadrilateral a b d c0, anticlockwise: b reflex (or flat) when a, b,
  ** d do not turn left; else c0, when d, c0, a do not */
  if (geom_orient(p[a], p[b], p[d]) <= 0) return in[b];
  if (geom_orient(p[d], p[c0], p[a]) <= 0) return in[c0];
  return LOT_NONE;   /* strictly convex: only an unfinished run leaves it */
}

size_t lot_weighted_hidden(const lot_mesh *m, const double *w, unsigned char *mark) {
  size_t found = 0;
  for (uint32_t c = 0; c < LOT_CORNER(m->nt, 0); c++) {
    if (lot_slot(c) == 3 || c > m->tn[c] || lot_is_ghost(m, lot_tri_of(c)) ||
        lot_is_ghost(m, lot_tri_of(m->tn[c])))
      continue;
    uint32_t s = lot_weighted_edge(m, w, c);
    if (s != LOT_NONE && !mark[s]) {
      mark[s] = 1;
      found++;
    }
  }
  return found;
}
