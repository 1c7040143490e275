// bench_lot_cgal.cpp: the comparison for bench_lot: CGAL's
// Delaunay_triangulation_2 with the Exact_predicates_inexact_constructions
// kernel on the same points (fliplab's "uniform" sampler, same seed),
// inserted as a range (CGAL's spatial sort + insertion).  Built only when
// CGAL is found; run by bench_lot.
//
//   bench_lot_cgal N RUNS SEED    prints "cgal_seconds S" (median wall time),
//                                 "cgal_cpu_seconds C" (median process CPU
//                                 time) and the number of faces.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <cstdlib>
#include <vector>
extern "C" {
#include "sampler.h"
}

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Delaunay_triangulation_2<K> DT;

int main(int argc, char **argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: bench_lot_cgal N RUNS SEED\n");
    return 2;
  }
  size_t n = (size_t)std::strtod(argv[1], nullptr);
  int runs = std::atoi(argv[2]);
  unsigned long long seed = std::strtoull(argv[3], nullptr, 10);
  std::vector<geom_point> gp(n);
  sampler_points(SAMPLER_UNIFORM, seed, n, gp.data());
  std::vector<K::Point_2> pts;
  pts.reserve(n);
  for (const geom_point &q : gp) pts.emplace_back(q.x, q.y);
  std::vector<double> t, c;
  size_t faces = 0;
  for (int k = 0; k < runs; k++) {
    timespec c0, c1;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c0);
    auto t0 = std::chrono::steady_clock::now();
    DT dt;
    dt.insert(pts.begin(), pts.end());
    auto t1 = std::chrono::steady_clock::now();
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c1);
    t.push_back(std::chrono::duration<double>(t1 - t0).count());
    c.push_back((double)(c1.tv_sec - c0.tv_sec) + 1e-9 * (double)(c1.tv_nsec - c0.tv_nsec));
    faces = dt.number_of_faces();
  }
  std::sort(t.begin(), t.end());
  std::sort(c.begin(), c.end());
  std::printf("cgal_seconds %.6f\ncgal_cpu_seconds %.6f\ncgal_faces %zu\n", t[t.size() / 2],
              c[c.size() / 2], faces);
  return 0;
}
