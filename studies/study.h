/*
** study.h: the lab's studies of a flip rule, as numbers (docs/classification.md,
** docs/lot.md).
**
** What `fliplab rule` and `fliplab lot --compare GOT` conclude is computed
** here, once, for every front end: the program and the Python package only
** parse their arguments and word or return what these calls fill in.
**   - study_pentagons: the flip-graph types of random convex pentagons, their
**     95% Wilson intervals, the verdicts (systematic: no type III; local: no
**     type II) and the witnesses of the lowest sample indices;
**   - study_quads: Delaunay equivalence on random convex quadrilaterals;
**   - study_sites: systematicity on other random site sets (the census);
**   - study_lot_got: a LOT's total against the GOT's of the same polygon
**     (strictly convex points, or segments forming one simple polygon), and
**     for the rules whose GOT is the CDT (rule_got_is_cdt) their triangles.
** Every count is the same for any thread count.  Random samples give
** evidence, not proof: a verdict is "no counterexample in N", never "proved".
**
** Front ends that read no C layout (python/) make the results with
** study_KIND_new and read them by the names of their fields
** (study_KIND_field, study_KIND_get_u64, ...), as lot_stats and got_result
** are read: one table per structure, geom/'s one reader.
*/
#ifndef FLIPLAB_STUDY_H
#define FLIPLAB_STUDY_H

#include <stddef.h>
#include <stdint.h>
#include "flipgraph.h"
#include "geom.h"
#include "got.h"
#include "lot.h"
#include "rule.h"
#include "siteflip.h"

/* ---- intervals ----------------------------------------------------------
** The 95% Wilson score interval of k successes in n, in percent, clipped
** to [0, 100] ([0, 100] when n == 0): it behaves at 0% and 100%, where
** the normal approximation does not.  Its half-width in percentage points
** (0 when n == 0), and the largest half-width over k for this n. */
void study_wilson(uint64_t k, uint64_t n, double *lo, double *hi);
/* The same at the level of the normal quantile z (2.5758293035489004:
** 99%, STUDY_Z99). */
#define STUDY_Z99 2.5758293035489004
void study_wilson_z(uint64_t k, uint64_t n, double z, double *lo, double *hi);
double study_wilson_halfwidth(uint64_t k, uint64_t n);
double study_wilson_max(uint64_t n);

/* ---- pentagons ---------------------------------------------------------- */

#define STUDY_WITNESS_MAX 100
/* The rows of a verdict's intervals: the five types, then DT. */
#define STUDY_ROW_DT FLIPGRAPH_NTYPES
#define STUDY_ROWS (FLIPGRAPH_NTYPES + 1)

/* The lowest sample indices of one outcome, ascending. */
typedef struct study_witnesses {
  int n;
  uint64_t idx[STUDY_WITNESS_MAX];
} study_witnesses;

/* A rule's verdicts on random convex pentagons.  A type-V pentagon (a tie)
** says nothing about systematicity or locality, so `decided` counts the
** pentagons of types I-IV, the ones a "no counterexample" claim rests on. */
typedef struct study_verdict {
  flipgraph_counts counts;
  double lo[STUDY_ROWS], hi[STUDY_ROWS];   /* 95% Wilson intervals, percent */
  uint64_t decided;        /* pentagons of types I-IV */
  int systematic;          /* no type III (two LOTs) */
  int local;               /* no type II */
  int sink_bug;            /* type IV under a triangle rule: impossible (thesis
                           ** theorem 1), so a bug; for another rule: no LOT */
  int always_delaunay;     /* every pentagon type I with the Delaunay sink */
  study_witnesses witness[FLIPGRAPH_NTYPES];   /* per type; none for type I */
} study_verdict;

/* The verdicts of counts c under rule r (witnesses untouched). */
void study_verdict_of(const rule *r, const flipgraph_counts *c, study_verdict *v);

/* Classify pentagons run->first .. +count of run->seed's stream
** (flipgraph_tally_run; its hook fields are this call's own and ignored)
** under every rule, keeping the lowest `witnesses` (0 .. STUDY_WITNESS_MAX)
** sample indices of each type but I, and fill out[0..nrules-1].  Each thread
** keeps its own lowest K per outcome and the lowest K of their union are the
** lowest K overall, so nothing depends on the thread count.  0, or -1 when
** the tally refuses (flipgraph_tally_run) or memory runs out. */
int study_pentagons(const rule *rules, int nrules, const flipgraph_run *run, int witnesses,
                    study_verdict *out);

/* ---- quadrilaterals: Delaunay equivalence ------------------------------- */

/* Rule r against DT on quadrilaterals 0 .. tested-1 of sampler_quad(seed):
** those where DT ties (four cocircular points) are skipped, a rule's tie
** where DT decides is counted apart from a disagreement. */
typedef struct study_quadcheck {
  uint64_t tested, disagree, ties, cocircular;
  uint64_t decided;        /* tested - cocircular: where DT decides */
  int equivalent;          /* no disagreement and no tie: no counterexample */
  uint64_t first;          /* the lowest disagreeing index (when disagree > 0) */
  geom_point q[4];         /* quadrilateral #first */
  rule_choice choice, dt;  /* the rule's and DT's decision on it */
  double ac, bd;           /* a triangle rule's joint values on it (else NaN) */
} study_quadcheck;

/* O(tested) rule evaluations, OpenMP over quadrilaterals.  threads: 0 for
** all cores or 1 .. GEOM_MAX_THREADS; 0, or -1 with err for another count. */
int study_quads(const rule *r, uint64_t seed, uint64_t tested, int threads,
                study_quadcheck *out, char *err, size_t errlen);

/* ---- other site sets ----------------------------------------------------
** Convex pentagons cannot show every failure (thesis section 3.5: -R_1 is
** type I on every pentagon, yet has two LOTs on a square with a site
** inside), so a study also runs the census of other site sets. */
typedef struct study_sitecheck {
  int sampler, n;          /* a sampler_sites_kind and its site count */
  siteflip_counts counts;
  uint64_t decided;        /* sets without a tie */
  int systematic;          /* no set with two or more sinks (LOTs) */
  int has_witness;         /* such a set was found again (when not systematic) */
  uint64_t witness;        /* the lowest such set's index */
  geom_point sites[SITEFLIP_MAX_SITES];   /* its sites */
} study_sitecheck;

/* The census of sets 0 .. samples-1 of sampler (n sites, seed) under r
** (siteflip_census; its cost and thread contract) and its first witness.
** 0, or -1 with err. */
int study_sites(const rule *r, int sampler, int n, uint64_t seed, uint64_t samples,
                double tie_eps, int threads, study_sitecheck *out, char *err, size_t errlen);

/* ---- a LOT against the GOT ----------------------------------------------
** The GOT is the least total over all triangulations of the polygon, so a
** triangle rule's LOT totals at least the GOT's.  Totals are compared as
** keys (rule_total_key): equal when within the sum of their certified error
** bounds (got_cert_err_of), where floating point cannot tell them apart;
** where no bound is known, within the rule's tie tolerance. */
typedef struct study_gotcheck {
  got_result got;          /* the polygon's GOT (freed by study_gotcheck_free) */
  int ring;                /* the polygon is a constrained run's ring of segments
                           ** (else the points' hull, in strictly convex position) */
  size_t n;                /* the polygon's vertices */
  uint32_t *tri;           /* the GOT's n - 2 triangles as input point indices */
  double lot_key;          /* the LOT's total as a key (the GOT's: got.key) */
  double lot_total;        /* in badness units (rule_unkey; the GOT's: got.total) */
  char lot_text[64], got_text[64];   /* both totals as got prints them */
  double rel;              /* relative difference of the totals (rule_gap) */
  int certified;           /* told by certified bounds (else by the tie tolerance) */
  const char *uncertified; /* why not (a static string), NULL when certified */
  int equal;               /* LOT total = GOT total */
  int below;               /* LOT total < GOT total: impossible, a failure */
  lot_diff diff;           /* the LOT's triangles (a) against the GOT's (b) */
  int same;                /* the same triangles */
  int got_is_cdt;          /* rule_got_is_cdt: the triangles must be the same */
  int failed;              /* below, or a CDT rule's other triangles with other totals */
} study_gotcheck;

/* The LOT tri[0..ntri-1] (anticlockwise triangles of input indices, as
** lot_get_triangles gives them) of in's points under the triangle rule r,
** against the GOT of its polygon: with segments or holes in `in`, the
** simple polygon its segments form (one closed ring through every point,
** no holes; the LOT must triangulate it); without, the points' hull
** (hull[0..nhull-1], lot_get_hull), which must be every distinct point, in
** strictly convex position.  Costs got_solve's Theta(n^3) and threads.
** 0, or -1 with a one-line err (out then needs no freeing). */
int study_lot_got(const geom_pslg *in, const uint32_t *hull, size_t nhull, const uint32_t *tri,
                  size_t ntri, const rule *r, int threads, study_gotcheck *out, char *err,
                  size_t errlen);
void study_gotcheck_free(study_gotcheck *c);

/* ---- how far local is from global: a point set's LOT against its GOT ----
** (studies/gotpoints.c; docs/got.md, "Point sets")  The LOT is the incremental one
** (lot_build's defaults: spatial order, the rule's tie tolerance); the GOT is
** got_points_solve's.  The gap is rule_gap(LOT, GOT), the project's one relative gap
** (|T1 - T2| / max(|T1|, |T2|)); the LOT is a GOT when the gap is within the rule's tie
** tolerance. */

/* The GOT of the point set p[0..n-1] (got_points_solve), the one entry the program, the
** package and the benchmarks call: for the rules whose GOT is a Delaunay triangulation by
** a theorem (rule_got_cdt_theorem) with the skeleton AUTO or DELAUNAY, lot's exact Delaunay
** triangulation is made first, once the points pass got_points_check, and handed to
** got_points_solve_checked, which certifies it (res->seconds_delaunay: its time, in
** res->seconds too); any other rule or skeleton goes to got_points_solve as it is.  0, or
** -1 with got's one-line err (or lot's). */
int study_got_points(const geom_point *p, size_t n, const rule *r, const got_options *opt,
                     got_skeleton sk, got_result *out, char *err, size_t errlen);

/* The total key of the LOT of p[0..n-1] under r: 0, or -1 with err. */
int study_lot_key(const geom_point *p, size_t n, const rule *r, double *key, char *err,
                  size_t errlen);

typedef struct study_gap_row {
  uint64_t sets;          /* point sets: set i is sampler_points(kind, seed + i, n) */
  double mean, lo, hi;    /* the mean gap and its 95% normal interval (1.96 s / sqrt(sets)) */
  double max;             /* the largest gap */
  uint64_t equal;         /* sets whose LOT is a GOT */
  double equal_lo, equal_hi;   /* the Wilson 95% interval of equal / sets, in percent */
  uint64_t certified;     /* sets whose GOT is certified unique */
  double seconds;
} study_gap_row;

/* The row of rule r over sets point sets of n points of sampler kind; sets in parallel
** (one thread each, threads in all), summed in set order: the same bits for any thread
** count.  0, or -1 with the first failing set's one-line err. */
int study_lot_got_gaps(const rule *r, int kind, size_t n, uint64_t sets, uint64_t seed,
                       int threads, got_skeleton sk, study_gap_row *out, char *err,
                       size_t errlen);

/* ---- results through verbs --------------------------------------------
** For callers that do not compile against this header (the Python
** package), as lot_stats and got_result are read (lot.h, got.h).
** study_KIND_new: a zeroed result on the heap (NULL when out of memory),
** study_KIND_delete frees it (a gotcheck's GOT too).  study_KIND_field(i):
** the name of its i-th field (NULL past the last).  study_KIND_get_u64:
** element i of an integer field (a count, an index, a flag 0 or 1, a
** rule_choice); study_KIND_get_double: a real field; study_gotcheck_get_text:
** lot_text, got_text or uncertified ("" for none); each 0, or -1 for a name
** that is no field of that type (or i outside it).  The arrays:
** study_verdict_interval, row r's interval (types I-V, then DT:
** STUDY_ROW_DT); study_verdict_witness, the k-th witness index of type t
** (-1 past the last); study_sitecheck_sites, the witness set into out (room
** for n sites; returns n, or 0 without a witness); study_gotcheck_triangles,
** the GOT's 3 (n - 2) vertex indices; study_gotcheck_got, the GOT itself
** (read by got.h's verbs). */
study_verdict *study_verdict_new(void);
void study_verdict_delete(study_verdict *v);
const char *study_verdict_field(size_t i);
int study_verdict_get_u64(const study_verdict *v, const char *name, size_t i, uint64_t *out);
int study_verdict_interval(const study_verdict *v, int row, double *lo, double *hi);
int64_t study_verdict_witness(const study_verdict *v, int t, int k);

study_quadcheck *study_quadcheck_new(void);
void study_quadcheck_delete(study_quadcheck *q);
const char *study_quadcheck_field(size_t i);
int study_quadcheck_get_u64(const study_quadcheck *q, const char *name, size_t i,
                            uint64_t *out);
int study_quadcheck_get_double(const study_quadcheck *q, const char *name, double *out);

study_sitecheck *study_sitecheck_new(void);
void study_sitecheck_delete(study_sitecheck *s);
const char *study_sitecheck_field(size_t i);
int study_sitecheck_get_u64(const study_sitecheck *s, const char *name, size_t i,
                            uint64_t *out);
int study_sitecheck_sites(const study_sitecheck *s, geom_point *out);

study_gotcheck *study_gotcheck_new(void);
void study_gotcheck_delete(study_gotcheck *c);
const char *study_gotcheck_field(size_t i);
int study_gotcheck_get_u64(const study_gotcheck *c, const char *name, size_t i, uint64_t *out);
int study_gotcheck_get_double(const study_gotcheck *c, const char *name, double *out);
const char *study_gotcheck_get_text(const study_gotcheck *c, const char *name);
const uint32_t *study_gotcheck_triangles(const study_gotcheck *c);
const got_result *study_gotcheck_got(const study_gotcheck *c);

/* ---- random convex polygons (studies/convex.c, docs/sampling.md) --------
** Per polygon: area, perimeter, the iteration method's hull changes h,
** unimodality (1 when from every vertex the distances to the others, round
** the boundary, rise then fall; NaN above STUDY_CONVEX_UNIMODAL_MAX
** vertices, the test being O(n^2)), and 1 when the minimum-area and the
** minimum-perimeter enclosing rectangles differ (rotating calipers, O(n)).
** Near-equal squared distances, areas and perimeters (relative 1e-12)
** count as equal. */
enum { STUDY_CONVEX_AREA, STUDY_CONVEX_PERIMETER, STUDY_CONVEX_H, STUDY_CONVEX_UNIMODAL,
       STUDY_CONVEX_RECT_DIFFER, STUDY_CONVEX_NSTATS };
#define STUDY_CONVEX_UNIMODAL_MAX 2000
extern const char *const study_convex_stat_names[STUDY_CONVEX_NSTATS];
void study_convex_measure(const geom_point *v, size_t n, uint64_t h,
                          double out[STUDY_CONVEX_NSTATS]);

/* Weighted means of the statistics over polygons added in index order, and
** 95% intervals (self-normalised importance sampling; studies/convex.c). */
typedef struct study_convex_acc {
  uint64_t count, missing[STUDY_CONVEX_NSTATS];
  double ref;                     /* the log weight the sums are relative to */
  double w, w2, wx[STUDY_CONVEX_NSTATS], w2x[STUDY_CONVEX_NSTATS], w2xx[STUDY_CONVEX_NSTATS];
} study_convex_acc;
void study_convex_acc_init(study_convex_acc *a);
void study_convex_acc_add(study_convex_acc *a, double log_weight,
                          const double x[STUDY_CONVEX_NSTATS]);
void study_convex_acc_mean(const study_convex_acc *a, int k, double *mean, double *half);
double study_convex_acc_ess(const study_convex_acc *a);
/* The same over arrays (count rows of STUDY_CONVEX_NSTATS statistics, their
** log weights, NULL: equal): means, half-widths, the effective sample size. */
void study_convex_summary(const double *stats, const double *log_weight, size_t count,
                          double *mean, double *half, double *ess);
/* Statistic k's name ("area", ...), NULL past the last (for front ends). */
const char *study_convex_stat_name(int k);

/* Polygons first .. first + count - 1 of a sampler (samplers/sampler.h's
** registry) on threads (0: all cores): polygon i into xy[i n .. i n + n),
** its log weight and h, and its STUDY_CONVEX_NSTATS statistics at stats[i
** STUDY_CONVEX_NSTATS ...] (study_convex_measure; these three may be
** NULL).  The same output for any
** thread count.  0; or the first failing polygon's code (-1, or
** SAMPLER_ENOMEM) with its index in *failed; -1 for an unknown sampler. */
typedef struct study_convex_run {
  const char *sampler;
  int region, law, threads;
  size_t n;
  uint64_t seed;
  const char *inner;   /* the dual's inner method, NULL = its default */
} study_convex_run;
int study_convex_draw(const study_convex_run *run, uint64_t first, uint64_t count,
                      geom_point *xy, double *log_weight, uint64_t *h, double *stats,
                      uint64_t *failed);

#endif
