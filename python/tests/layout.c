/*
** layout.c: the C layout of every public structure python/fliplab reads or
** fills, for test_layout.py: one line "STRUCT sizeof N" per structure and
** "STRUCT FIELD OFFSET SIZE" per field (FIELD a C member designator:
** lot_stats.cycle_quad, geom_tri.v[1].y).  The ctypes mirrors are checked
** against what the compiler made of the headers, not against a copy of
** them: a field added, moved or resized in a header fails the test.  So
** are the structures the package reaches through verbs instead (lot_options
** and got_options: a setter per field; lot_stats, lot_check_result and
** got_result: every field readable by its name).
*/
#include <stddef.h>
#include <stdio.h>
#include "geom.h"
#include "measure.h"
#include "joint.h"
#include "rule.h"
#include "sampler.h"
#include "lot.h"
#include "flipgraph.h"
#include "siteflip.h"
#include "got.h"
#include "report.h"
#include "study.h"
#include "paradigm.h"
#include "linf.h"
#include "study_linf.h"

#define Z(S) printf("%s sizeof %zu\n", #S, sizeof(S))
#define F(S, m) printf("%s %s %zu %zu\n", #S, #m, offsetof(S, m), sizeof(((S *)0)->m))

/* geom_tri's vertices one coordinate at a time (offsetof takes plain
** member names only in ISO C). */
static void layout_tri_vertices(void) {
  for (int k = 0; k < 3; k++) {
    size_t v = offsetof(geom_tri, v) + (size_t)k * sizeof(geom_point);
    printf("geom_tri v[%d].x %zu %zu\n", k, v + offsetof(geom_point, x), sizeof(double));
    printf("geom_tri v[%d].y %zu %zu\n", k, v + offsetof(geom_point, y), sizeof(double));
  }
}

static void layout_geom(void) {
  Z(geom_point); F(geom_point, x); F(geom_point, y);
  Z(geom_tri); layout_tri_vertices();
  F(geom_tri, a); F(geom_tri, b); F(geom_tri, c); F(geom_tri, alpha); F(geom_tri, beta);
  F(geom_tri, gamma); F(geom_tri, area); F(geom_tri, P); F(geom_tri, R); F(geom_tri, r);
  F(geom_tri, h); F(geom_tri, rx); F(geom_tri, ry);
  Z(geom_pslg); F(geom_pslg, pts); F(geom_pslg, npts); F(geom_pslg, seg); F(geom_pslg, nseg);
  F(geom_pslg, hole); F(geom_pslg, nholes);
}

static void layout_rules(void) {
  Z(measure); F(measure, name); F(measure, symbol); F(measure, desc); F(measure, sign);
  F(measure, fn); F(measure, ctx);
  Z(joint); F(joint, name);
  Z(rule_quad); F(rule_quad, name); F(rule_quad, desc); F(rule_quad, fn); F(rule_quad, ctx);
  Z(rule); F(rule, kind); F(rule, measure); F(rule, joint); F(rule, sign); F(rule, quad);
  F(rule, tie_eps); F(rule, name);
  Z(sampler_pentagons); F(sampler_pentagons, name); F(sampler_pentagons, draw);
  Z(sampler_rng); F(sampler_rng, s);
}

static void layout_lot(void) {
  Z(lot_options); F(lot_options, r); F(lot_options, algorithm); F(lot_options, order);
  F(lot_options, seed); F(lot_options, max_flips); F(lot_options, tie_eps);
  F(lot_options, decide); F(lot_options, decide_ctx); F(lot_options, segments);
  F(lot_options, nsegments); F(lot_options, holes); F(lot_options, nholes);
  F(lot_options, keep_hull); F(lot_options, weights);
  F(lot_options, ops);
  Z(lot_stats); F(lot_stats, n); F(lot_stats, distinct); F(lot_stats, duplicates);
  F(lot_stats, hull); F(lot_stats, triangles); F(lot_stats, flips); F(lot_stats, status);
  F(lot_stats, cycle_length); F(lot_stats, cycle_quads); F(lot_stats, cycle_quad);
  F(lot_stats, max_flips); F(lot_stats, seconds_init); F(lot_stats, seconds_flip);
  F(lot_stats, segments); F(lot_stats, constrained); F(lot_stats, segments_merged);
  F(lot_stats, segments_split); F(lot_stats, segments_removed); F(lot_stats, holes);
  F(lot_stats, removed); F(lot_stats, redundant); F(lot_stats, rounds);
  Z(lot_check_result); F(lot_check_result, interior_edges);
  F(lot_check_result, boundary_edges); F(lot_check_result, decided);
  F(lot_check_result, not_optimal); F(lot_check_result, bad_edge); F(lot_check_result, valid);
  F(lot_check_result, segments_missing); F(lot_check_result, missing_segment);
  Z(lot_cdf); F(lot_cdf, triangles); F(lot_cdf, tri); F(lot_cdf, edges); F(lot_cdf, edge);
  F(lot_cdf, rounded); F(lot_cdf, conflicts);
  Z(lot_diff); F(lot_diff, edges_a); F(lot_diff, edges_b); F(lot_diff, edges_common);
  F(lot_diff, triangles_a); F(lot_diff, triangles_b); F(lot_diff, triangles_common);
  Z(report_row); F(report_row, measure); F(report_row, joint); F(report_row, rule);
  F(report_row, c);
  Z(report_run); F(report_run, known); F(report_run, seed); F(report_run, tie_eps);
  F(report_run, first); F(report_run, end); F(report_run, total); F(report_run, rules);
  F(report_run, sampler);
  Z(report_meta); F(report_meta, samples); F(report_meta, has_seed); F(report_meta, seed);
  F(report_meta, has_tie_eps); F(report_meta, tie_eps); F(report_meta, shard_k);
  F(report_meta, shard_n); F(report_meta, shard_first); F(report_meta, shard_total);
  F(report_meta, sampler); F(report_meta, note); F(report_meta, text_columns);
  F(report_meta, run);
  Z(report_census_row); F(report_census_row, measure); F(report_census_row, joint);
  F(report_census_row, rule); F(report_census_row, sites); F(report_census_row, sampler);
  F(report_census_row, c);
  Z(report_census_meta); F(report_census_meta, has_seed); F(report_census_meta, seed);
  F(report_census_meta, has_tie_eps); F(report_census_meta, tie_eps);
  F(report_census_meta, shard_k); F(report_census_meta, shard_n);
  Z(report_poly); F(report_poly, g); F(report_poly, seg_line); F(report_poly, attributes);
  F(report_poly, regions); F(report_poly, markers); F(report_poly, first);
}

static void layout_census(void) {
  Z(flipgraph_counts); F(flipgraph_counts, samples); F(flipgraph_counts, type);
  F(flipgraph_counts, dt);
  Z(flipgraph); F(flipgraph, dec); F(flipgraph, type); F(flipgraph, nsinks); F(flipgraph, sink);
  F(flipgraph, delaunay);
  Z(flipgraph_run); F(flipgraph_run, seed); F(flipgraph_run, first); F(flipgraph_run, count);
  F(flipgraph_run, tie_eps); F(flipgraph_run, threads); F(flipgraph_run, progress);
  F(flipgraph_run, progress_ctx); F(flipgraph_run, each); F(flipgraph_run, each_ctx);
  F(flipgraph_run, sampler);
  Z(siteflip_counts); F(siteflip_counts, samples); F(siteflip_counts, tie);
  F(siteflip_counts, no_sink); F(siteflip_counts, one_sink); F(siteflip_counts, multi_sink);
  F(siteflip_counts, sink_dt); F(siteflip_counts, sinks); F(siteflip_counts, max_sinks);
  F(siteflip_counts, gap_units);
}

static void layout_siteflip(void) {
  Z(siteflip_quad); F(siteflip_quad, v); F(siteflip_quad, tri);
  Z(siteflip_edge); F(siteflip_edge, ac); F(siteflip_edge, bd); F(siteflip_edge, quad);
  Z(siteflip_graph); F(siteflip_graph, n); F(siteflip_graph, p); F(siteflip_graph, nnodes);
  F(siteflip_graph, node); F(siteflip_graph, per); F(siteflip_graph, node_tri);
  F(siteflip_graph, ntris); F(siteflip_graph, tri_v); F(siteflip_graph, tri);
  F(siteflip_graph, nquads); F(siteflip_graph, quad); F(siteflip_graph, nedges);
  F(siteflip_graph, edge); F(siteflip_graph, adj_off); F(siteflip_graph, adj);
  F(siteflip_graph, delaunay);
  Z(siteflip_result); F(siteflip_result, nsinks); F(siteflip_result, nsources);
  F(siteflip_result, ties); F(siteflip_result, cycle); F(siteflip_result, sink_dt);
  F(siteflip_result, has_got); F(siteflip_result, got_node); F(siteflip_result, got_total);
  F(siteflip_result, worst_sink); F(siteflip_result, worst_gap);
}

static void layout_got(void) {
  Z(got_options); F(got_options, threads); F(got_options, tie_eps);
  Z(got_result); F(got_result, n); F(got_result, measure); F(got_result, joint);
  F(got_result, sign); F(got_result, key); F(got_result, total); F(got_result, has_runner_up);
  F(got_result, key2); F(got_result, total2); F(got_result, gap); F(got_result, rel_gap);
  F(got_result, unique); F(got_result, tie_eps); F(got_result, tri); F(got_result, ntri);
  F(got_result, simple); F(got_result, cert_err); F(got_result, cert_err2);
  F(got_result, cert_gap); F(got_result, cert_bound); F(got_result, cert_unique);
  F(got_result, cert_why); F(got_result, cert_rho); F(got_result, cert_alpha);
  F(got_result, seconds); F(got_result, threads); F(got_result, points);
  F(got_result, skeleton); F(got_result, candidates); F(got_result, edges);
  F(got_result, certain); F(got_result, rounds); F(got_result, faces);
  F(got_result, faces_left); F(got_result, faces_general); F(got_result, largest_face);
  F(got_result, face_states); F(got_result, seconds_candidates); F(got_result, seconds_lmt);
  F(got_result, seconds_faces); F(got_result, seconds_solve); F(got_result, seconds_delaunay);
}

/* Chapter 2's registry and runner, section 4.2's cubes (_paradigms.py, _linf.py). */
static void layout_paradigms(void) {
  Z(ops_counts); F(ops_counts, v); F(ops_counts, bytes);
  Z(paradigm_algorithm); F(paradigm_algorithm, name); F(paradigm_algorithm, paradigm);
  F(paradigm_algorithm, section); F(paradigm_algorithm, problems); F(paradigm_algorithm, rules);
  F(paradigm_algorithm, refusal); F(paradigm_algorithm, cost); F(paradigm_algorithm, param);
  F(paradigm_algorithm, run);
  Z(paradigm_input); F(paradigm_input, p); F(paradigm_input, n); F(paradigm_input, r);
  F(paradigm_input, problem); F(paradigm_input, segments); F(paradigm_input, nsegments);
  F(paradigm_input, seed); F(paradigm_input, threads); F(paradigm_input, param);
  Z(paradigm_result); F(paradigm_result, tri); F(paradigm_result, ntri);
  F(paradigm_result, ops); F(paradigm_result, seconds); F(paradigm_result, distinct);
  Z(linf_cube); F(linf_cube, d); F(linf_cube, side); F(linf_cube, face); F(linf_cube, top);
  F(linf_cube, bottom);
  Z(linf_simplices); F(linf_simplices, d); F(linf_simplices, n); F(linf_simplices, cap);
  F(linf_simplices, v);
  Z(linf_select_stats); F(linf_select_stats, facets); F(linf_select_stats, hull_facets);
  F(linf_select_stats, cube_tests); F(linf_select_stats, largest_set);
  F(linf_select_stats, degenerate);
  Z(study_linf_mc); F(study_linf_mc, d); F(study_linf_mc, trials); F(study_linf_mc, seed);
  F(study_linf_mc, count); F(study_linf_mc, infinite); F(study_linf_mc, law);
  F(study_linf_mc, law_total);
}

int main(void) {
  layout_geom();
  layout_paradigms();
  layout_rules();
  layout_lot();
  layout_census();
  layout_siteflip();
  layout_got();
  Z(study_convex_run); F(study_convex_run, sampler); F(study_convex_run, region);
  F(study_convex_run, law); F(study_convex_run, threads); F(study_convex_run, n);
  F(study_convex_run, seed); F(study_convex_run, inner);
  return fflush(stdout) != 0 || ferror(stdout) ? 1 : 0;
}
