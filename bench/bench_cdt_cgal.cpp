// bench_cdt_cgal.cpp: the comparison for bench_cdt: CGAL's
// Constrained_Delaunay_triangulation_2 (Exact_predicates_inexact_constructions
// kernel, Exact_predicates_tag: the segments never cross, so no intersection
// is constructed) on the same points (fliplab's "uniform" sampler, or the
// sampler named by SAMPLER) and the same segments (sampler_segments on the GEOM_STREAM_SEGMENTS stream), all
// inserted by insert_constraints (CGAL's spatial sort of the points, then
// the constraints).  Built only when CGAL is found; run by bench_cdt and
// bench_families.
//
//   bench_cdt_cgal N M RUNS SEED [SAMPLER]
//                                  prints "cgal_seconds S", "cgal_cpu_seconds C"
//                                  (medians) and the number of faces.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>
#include "cgal_timing.hpp"
extern "C" {
#include "sampler.h"
}

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Default, CGAL::Exact_predicates_tag> CDT;

int main(int argc, char **argv) {
  int kind = argc == 6 ? sampler_points_find(argv[5]) : SAMPLER_UNIFORM;
  if ((argc != 5 && argc != 6) || kind < 0) {
    std::fprintf(stderr, "usage: bench_cdt_cgal N M RUNS SEED [SAMPLER]\n");
    return 2;
  }
  size_t n = (size_t)std::strtod(argv[1], nullptr), m = (size_t)std::strtod(argv[2], nullptr);
  int runs = std::atoi(argv[3]);
  unsigned long long seed = std::strtoull(argv[4], nullptr, 10);
  std::vector<geom_point> gp(n);
  std::vector<uint32_t> seg(2 * m + 2);
  size_t nseg = 0;
  sampler_points((sampler_points_kind)kind, seed, n, gp.data());
  sampler_rng g;
  sampler_seed(&g, seed, GEOM_STREAM_SEGMENTS);
  if (sampler_segments(&g, gp.data(), n, m, seg.data(), &nseg) != 0) return 1;
  std::vector<K::Point_2> pts;
  pts.reserve(n);
  for (const geom_point &q : gp) pts.emplace_back(q.x, q.y);
  std::vector<std::pair<std::size_t, std::size_t>> idx;
  for (size_t k = 0; k < nseg; k++) idx.emplace_back(seg[2 * k], seg[2 * k + 1]);
  return bench_cgal_time<CDT>(runs, [&](CDT &cdt) {
    cdt.insert_constraints(pts.begin(), pts.end(), idx.begin(), idx.end());
  });
}
