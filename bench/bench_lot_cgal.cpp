// bench_lot_cgal.cpp: the comparison for bench_lot: CGAL's
// Delaunay_triangulation_2 with the Exact_predicates_inexact_constructions
// kernel on the same points (fliplab's "uniform" sampler, or the sampler
// named by SAMPLER, same seed), inserted as a range (CGAL's spatial sort +
// insertion).  Built only when CGAL is found; run by bench_lot and
// bench_grid.
//
//   bench_lot_cgal N RUNS SEED [SAMPLER]
//                                 prints "cgal_seconds S" (median wall time),
//                                 "cgal_cpu_seconds C" (median process CPU
//                                 time) and the number of faces.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include "cgal_timing.hpp"
extern "C" {
#include "sampler.h"
}

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Delaunay_triangulation_2<K> DT;

int main(int argc, char **argv) {
  int kind = argc == 5 ? sampler_points_find(argv[4]) : SAMPLER_UNIFORM;
  if ((argc != 4 && argc != 5) || kind < 0) {
    std::fprintf(stderr, "usage: bench_lot_cgal N RUNS SEED [SAMPLER]\n");
    return 2;
  }
  size_t n = (size_t)std::strtod(argv[1], nullptr);
  int runs = std::atoi(argv[2]);
  unsigned long long seed = std::strtoull(argv[3], nullptr, 10);
  std::vector<geom_point> gp(n);
  sampler_points((sampler_points_kind)kind, seed, n, gp.data());
  std::vector<K::Point_2> pts;
  pts.reserve(n);
  for (const geom_point &q : gp) pts.emplace_back(q.x, q.y);
  return bench_cgal_time<DT>(runs, [&](DT &dt) { dt.insert(pts.begin(), pts.end()); });
}
