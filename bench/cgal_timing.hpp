// cgal_timing.hpp: the timing loop of the CGAL comparison programs that
// bench_lot and bench_cdt run (bench_lot_cgal.cpp, bench_cdt_cgal.cpp):
// RUNS builds of a fresh triangulation T by fill(T &), each timed in wall
// and process CPU time (the destructor outside the timed part), and the
// lines the C benches read back: "cgal_seconds S", "cgal_cpu_seconds C"
// (medians) and "cgal_faces F".
#ifndef FLIPLAB_BENCH_CGAL_TIMING_HPP
#define FLIPLAB_BENCH_CGAL_TIMING_HPP

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <vector>

template <class T, class Fill> int bench_cgal_time(int runs, Fill fill) {
  std::vector<double> t, c;
  size_t faces = 0;
  for (int k = 0; k < runs; k++) {
    timespec c0, c1;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c0);
    auto t0 = std::chrono::steady_clock::now();
    T tri;
    fill(tri);
    auto t1 = std::chrono::steady_clock::now();
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c1);
    t.push_back(std::chrono::duration<double>(t1 - t0).count());
    c.push_back((double)(c1.tv_sec - c0.tv_sec) + 1e-9 * (double)(c1.tv_nsec - c0.tv_nsec));
    faces = tri.number_of_faces();
  }
  std::sort(t.begin(), t.end());
  std::sort(c.begin(), c.end());
  std::printf("cgal_seconds %.6f\ncgal_cpu_seconds %.6f\ncgal_faces %zu\n", t[t.size() / 2],
              c[c.size() / 2], faces);
  return 0;
}

#endif
