/*
** study_linf.h: the thesis's experiments of section 4.2 on the l_inf
** circumcubes (linf/linf.h): its examples, each claim computed exactly,
** and the Monte Carlo of the circumcube count of random points with the
** exact law beside it (docs/linf.md).
*/
#ifndef FLIPLAB_STUDY_LINF_H
#define FLIPLAB_STUDY_LINF_H

#include <stddef.h>
#include <stdint.h>
#include "linf.h"

/* ---- the examples ---------------------------------------------------------
**   3d      section 4.2.1: A(6,6,2) B(10,4,8) C(0,2,6) D(2,12,0) E(4,8,10)
**           F(8,0,4) and the cells ACEF, ACDE, ABEF, BCEF, BCDF, "locally
**           Delaunay but not Delaunay"
**   pseudo  A(1,1,7) B(5,3,0) C(3,5,8) D(8,6,1), two circumcubes of radius 4
**   r5      theorem 14's R^5 configuration with 4 circumcubes
**   facet   six points with a facet of three Delaunay tetrahedra, two on one
**           side (the end of section 4.2.1: the circumcubes through a
**           facet do not nest); no cells */
#define STUDY_LINF_CELLS_MAX 8
typedef struct study_linf_example {
  const char *name, *what;
  int d;
  size_t n;
  const char *labels;        /* one letter per point */
  const double *pts;         /* n rows of d */
  const char *const *cells;  /* NULL-terminated, each d + 1 letters */
} study_linf_example;

extern const study_linf_example study_linf_examples[];
#define STUDY_LINF_EXAMPLES 4
/* The example named s, or NULL. */
const study_linf_example *study_linf_example_find(const char *s);
/* The m point labels of a row key (linf_row_key) into name (m + 1 bytes). */
void study_linf_key_name(const study_linf_example *ex, uint64_t key, int m, char *name);

/* A simplex of an example's points (flat: in one hyperplane): its
** circumcubes (ncubes may be LINF_INFINITE), which have no point strictly
** inside (empty[b]) and, within a triangulation, which have no far vertex
** of a neighbouring simplex strictly inside (local[b]); nempty, nlocal:
** how many. */
typedef struct study_linf_cell {
  unsigned char v[LINF_DIM_MAX + 1];
  int flat, ncubes, nempty, nlocal;
  linf_cube cube[LINF_CUBES_MAX];
  unsigned char empty[LINF_CUBES_MAX], local[LINF_CUBES_MAX];
} study_linf_cell;

/* What the exact computation finds of an example.  Sets of simplices are
** bit masks over pool, every (d+1)-subset of the points in lexicographic
** order (at most 64); a flat one is in no triangulation and not Delaunay.
**   cells        the example's cells; tiling: 1 when they triangulate the
**                hull (why: else the reason); locally: every cell has a
**                local cube; globally: an empty one
**   delaunay     every l_inf Delaunay simplex (linf_delaunay_brute);
**                del_tiling, del_why: do they triangulate the hull
**   selected     what the selection algorithm finds, its counts in st
**   hull_facets  the hull's facets, bare: those no Delaunay simplex has;
**   open_facets  facets inside the hull with a Delaunay simplex on one
**                side only (the walls of what the Delaunay simplices miss)
**   crowded      the most Delaunay simplices on one facet (crowded_side:
**                the most on one side of it; crowded_at: the first such
**                facet, linf_row_key)
**   tilings      every triangulation of the points (when the pool has at
**                most STUDY_LINF_SEARCH_MAX simplices; searched 0 else),
**                how many are locally Delaunay, how many Delaunay, and the
**                first STUDY_LINF_LIST_MAX locally but not globally
**                Delaunay ones */
#define STUDY_LINF_SEARCH_MAX 18
#define STUDY_LINF_LIST_MAX 8
typedef struct study_linf_report {
  const study_linf_example *ex;
  size_t npool;
  study_linf_cell *pool;
  uint64_t cells, delaunay;
  int tiling, locally, globally, del_tiling;
  char why[160], del_why[160];
  linf_simplices selected;
  linf_select_stats st;
  size_t hull_facets, bare_facets, open_facets;
  int crowded, crowded_side;
  uint64_t crowded_at;
  int searched;
  uint64_t tilings, tilings_local, tilings_global;
  uint64_t local_only[STUDY_LINF_LIST_MAX];
  size_t nlocal_only;
  struct study_linf_facet *facets;   /* the pool's facets (private) */
} study_linf_report;

/* 0, or -1 when memory ran out; study_linf_report_free after either. */
int study_linf_examine(const study_linf_example *ex, study_linf_report *r);
void study_linf_report_free(study_linf_report *r);
/* Does the set (a mask over r's pool) triangulate the points: is every
** point a vertex, and do the simplices tile the hull?  Each facet of
** a simplex must be a hull facet of that one simplex, or a facet of two on
** opposite sides: then the simplices cover each point of the hull once
** (the covering degree does not change across a shared facet and is 1
** beside the hull's boundary).  1, or 0 with why (may be NULL). */
int study_linf_triangulates(const study_linf_report *r, uint64_t set, char *why, size_t len);
/* Is the set locally Delaunay: each simplex has a
** circumcube with no far vertex of a neighbour strictly inside?  Writes
** each simplex's local flags. */
int study_linf_locally(study_linf_report *r, uint64_t set);

/* ---- the Monte Carlo ------------------------------------------------------
** d + 1 points uniform in [0, 1)^d (d x (d + 1) doubles of 53 random bits,
** point by point, from the stream GEOM_STREAM_SAMPLE(t) of trial t), and
** the number of their circumcubes; count[k] trials with k of them,
** infinite those with infinitely many (probability 0).  Beside them the
** exact law (linf_rank_law; law_total 0 when d > 5).  Any thread count
** (0: all cores) gives the same counts.  0, or -1 with the reason in err. */
typedef struct study_linf_mc {
  int d;
  uint64_t trials, seed;
  uint64_t count[LINF_CUBES_MAX + 1], infinite;
  uint64_t law[LINF_CUBES_MAX + 1], law_total;
} study_linf_mc;

#define STUDY_LINF_TRIALS_MAX ((uint64_t)1 << 40)
int study_linf_montecarlo(int d, uint64_t trials, uint64_t seed, int threads, study_linf_mc *mc,
                          char *err, size_t errlen);

#endif
