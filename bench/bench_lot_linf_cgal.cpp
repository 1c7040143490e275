// bench_lot_linf_cgal.cpp: fliplab's empty-square triangulation against
// CGAL's L_inf Delaunay graph, on the same points in the same process.
//
//   bench_lot_linf_cgal [N [RUNS [SEED]]]        (defaults 100000, 3, 1)
//
// On N points of fliplab's "uniform" sampler (unit square):
//   1. fliplab: lot_build with the rule ES:square (the default incremental
//      algorithm: BRIO + Hilbert order, then flips to a LOT), as
//      `fliplab lot --rule ES:square --random N` runs it;
//   2. CGAL: Segment_Delaunay_graph_Linf_2 with the
//      Segment_Delaunay_graph_Linf_filtered_traits_2 of Simple_cartesian
//      <double> (Field_with_sqrt_tag), the points only, inserted through
//      insert_points (CGAL's spatial sort, then insertion with a hint).
// The two alternate run by run, so that both see the same machine load;
// printed: the median wall and CPU time of each, the median of the per-pair
// ratios fliplab / CGAL, the load average, and, as a check that the two
// compute the same graph, the edges of fliplab's convex-distance Delaunay
// graph (lot_cdf_extract, of the last run, not timed) against CGAL's finite
// edges.  Times
// cover the construction only, not sampling or the comparison.  Built only
// when CGAL is found (bench/CMakeLists.txt).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Segment_Delaunay_graph_Linf_2.h>
#include <CGAL/Segment_Delaunay_graph_Linf_filtered_traits_2.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <utility>
#include <vector>
extern "C" {
#include "benchutil.h"
#include "lot.h"
#include "rule.h"
#include "sampler.h"
#include "shape.h"
}

typedef CGAL::Simple_cartesian<double> CK;
typedef CGAL::Segment_Delaunay_graph_Linf_filtered_traits_2<CK, CGAL::Field_with_sqrt_tag> Gt;
typedef CGAL::Segment_Delaunay_graph_Linf_2<Gt> SDG;
typedef std::pair<uint32_t, uint32_t> Edge;

static Edge bench_edge(uint32_t a, uint32_t b) { return a < b ? Edge(a, b) : Edge(b, a); }

// One fliplab build: its triangles into tri when tri != nullptr.
static bench_time bench_fliplab(const std::vector<geom_point> &p, const rule &r,
                                std::vector<uint32_t> *tri) {
  lot_options o;
  lot_options_init(&o, &r);
  lot *L;
  char err[256];
  double c0 = bench_cpu(), t0 = bench_wall();
  if (lot_build(&L, p.data(), p.size(), &o, err, sizeof err) != 0) {
    std::fprintf(stderr, "bench_lot_linf_cgal: %s\n", err);
    std::exit(1);
  }
  bench_time t = {bench_wall() - t0, bench_cpu() - c0};
  if (tri != nullptr) {
    tri->resize(3 * lot_get_stats(L)->triangles);
    lot_get_triangles(L, tri->data());
  }
  lot_free(L);
  return t;
}

// One CGAL build (insert_points sorts its argument: a fresh copy, made
// before the clocks start); its finite edges into edges when not nullptr.
static bench_time bench_cgal(const std::vector<CK::Point_2> &pts,
                             const std::map<std::pair<double, double>, uint32_t> *index,
                             std::vector<Edge> *edges, size_t *faces) {
  std::vector<CK::Point_2> copy(pts);
  double c0 = bench_cpu(), t0 = bench_wall();
  SDG sdg;
  sdg.insert_points(copy);
  bench_time t = {bench_wall() - t0, bench_cpu() - c0};
  *faces = sdg.number_of_faces();
  if (edges != nullptr)
    for (SDG::Finite_edges_iterator e = sdg.finite_edges_begin(); e != sdg.finite_edges_end();
         ++e) {
      CK::Point_2 a = e->first->vertex(SDG::cw(e->second))->site().point();
      CK::Point_2 b = e->first->vertex(SDG::ccw(e->second))->site().point();
      edges->push_back(bench_edge(index->at({a.x(), a.y()}), index->at({b.x(), b.y()})));
    }
  return t;
}

// The edges of fliplab's convex-distance Delaunay graph of tri for the square.
static std::vector<Edge> bench_cdf_edges(const std::vector<geom_point> &p,
                                         const std::vector<uint32_t> &tri, size_t *dropped) {
  shape *k = nullptr;
  char err[256];
  lot_cdf g;
  if (shape_parse("square", &k, err, sizeof err) != 0 ||
      lot_cdf_extract(p.data(), tri.data(), tri.size() / 3, k, &g) != 0) {
    std::fprintf(stderr, "bench_lot_linf_cgal: the CDF graph failed\n");
    std::exit(1);
  }
  std::vector<Edge> e;
  for (size_t t = 0; t < g.triangles; t++)
    for (int s = 0; s < 3; s++)
      e.push_back(bench_edge(g.tri[3 * t + s], g.tri[3 * t + (s + 1) % 3]));
  for (size_t i = 0; i < g.edges; i++) e.push_back(bench_edge(g.edge[2 * i], g.edge[2 * i + 1]));
  *dropped = g.rounded;
  lot_cdf_free(&g);
  shape_free(k);
  return e;
}

static size_t bench_unique(std::vector<Edge> &e) {
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e.size();
}

// The check line: fliplab's CDF edges (from its triangles tri), CGAL's
// finite edges ce, and how many both have.
static void bench_compare(const std::vector<geom_point> &p, const std::vector<uint32_t> &tri,
                          std::vector<Edge> &ce, size_t faces) {
  size_t dropped;
  std::vector<Edge> fe = bench_cdf_edges(p, tri, &dropped);
  size_t nf = bench_unique(fe), nc = bench_unique(ce);
  std::vector<Edge> both;
  std::set_intersection(fe.begin(), fe.end(), ce.begin(), ce.end(), std::back_inserter(both));
  std::printf("check: fliplab ES:square %zu triangles (%zu dropped by the CDF graph), CDF graph "
              "%zu edges; CGAL %zu faces, %zu finite edges; %zu edges in both: %s\n",
              tri.size() / 3, dropped, nf, faces, nc, both.size(),
              both.size() == nf && nf == nc ? "the same graph" : "DIFFERENT");
}

int main(int argc, char **argv) {
  size_t n = argc > 1 ? (size_t)std::strtod(argv[1], nullptr) : 100000;
  int runs = argc > 2 ? std::atoi(argv[2]) : 3;
  unsigned long long seed = argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 1;
  if (argc > 4 || n < 3 || runs < 1 || runs > 16) {
    std::fprintf(stderr, "usage: bench_lot_linf_cgal [N >= 3 [RUNS 1..16 [SEED]]]\n");
    return 2;
  }
  std::vector<geom_point> p(n);
  sampler_points(SAMPLER_UNIFORM, seed, n, p.data());
  std::vector<CK::Point_2> pts;
  pts.reserve(n);
  for (const geom_point &q : p) pts.emplace_back(q.x, q.y);
  rule r;
  char err[256];
  if (rule_parse("ES:square", &r, err, sizeof err) != 0) {
    std::fprintf(stderr, "bench_lot_linf_cgal: %s\n", err);
    return 1;
  }
  std::printf("# bench_lot_linf_cgal: %zu uniform points (seed %llu), %d runs, load %.2f\n", n,
              seed, runs, bench_load());
  std::map<std::pair<double, double>, uint32_t> index;
  for (size_t i = 0; i < n; i++) index.emplace(std::make_pair(p[i].x, p[i].y), (uint32_t)i);
  bench_time f[16], c[16];
  double q[16], cq[16];
  size_t faces = 0;
  std::vector<uint32_t> tri;
  std::vector<Edge> ce;
  for (int k = 0; k < runs; k++) {   // the last run's outputs (taken off the clock) are checked
    int last = k == runs - 1;
    f[k] = bench_fliplab(p, r, last ? &tri : nullptr);
    c[k] = bench_cgal(pts, last ? &index : nullptr, last ? &ce : nullptr, &faces);
    q[k] = f[k].wall / c[k].wall;
    cq[k] = f[k].cpu / c[k].cpu;
    std::printf("run %d: fliplab %.3f s, CGAL %.3f s\n", k + 1, f[k].wall, c[k].wall);
    std::fflush(stdout);
  }
  bench_time fm = bench_median_time(f, runs), cm = bench_median_time(c, runs);
  std::printf("fliplab ES:square: %.3f s (cpu %.3f s)\n", fm.wall, fm.cpu);
  std::printf("CGAL L_inf SDG:    %.3f s (cpu %.3f s)\n", cm.wall, cm.cpu);
  std::printf("ratio fliplab / CGAL: %.2f (cpu %.2f), median of the %d pairs\n",
              bench_median(q, runs), bench_median(cq, runs), runs);
  bench_compare(p, tri, ce, faces);
  std::printf("load after: %.2f\n", bench_load());
  return 0;
}
