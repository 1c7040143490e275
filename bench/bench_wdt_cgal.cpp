// bench_wdt_cgal.cpp: the weighted Delaunay rule WDT against CGAL's
// Regular_triangulation_2 (Exact_predicates_inexact_constructions_kernel)
// on the same weighted points, both timed in one process, and the two
// results compared triangle for triangle: the independent check of the
// regular triangulation the tests cannot run (CGAL is a benchmark
// dependency only).  Built only when CGAL is found.
//
//   bench_wdt_cgal N RUNS SEED SCALE
//
// N uniform points of the unit square (fliplab's sampler, SEED) with
// weights uniform in [0, SCALE / N) (SCALE 0: all equal, DT; about 1 makes
// a few percent of the sites redundant).  Prints the median wall time of
// each, their ratio, the sites each leaves out, and whether the triangles
// (as sorted index triples) and the sites left out are the same.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_2.h>
#include <CGAL/Regular_triangulation_vertex_base_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>
extern "C" {
#include "lot.h"
#include "sampler.h"
#include "splitmix.h"
}

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Regular_triangulation_vertex_base_2<K> Vb0;
typedef CGAL::Triangulation_vertex_base_with_info_2<unsigned, K, Vb0> Vb;
typedef CGAL::Regular_triangulation_face_base_2<K> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Regular_triangulation_2<K, Tds> RT;
typedef std::array<unsigned, 3> Tri;

static double bench_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

static double bench_median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// A triangle as lot_get_triangles writes it: anticlockwise from its smallest index.
static Tri bench_canon(unsigned a, unsigned b, unsigned c) {
  if (b < a && b < c) return {b, c, a};
  if (c < a && c < b) return {c, a, b};
  return {a, b, c};
}

// fliplab's WDT: triangles (sorted rows) and the sites left out.
static double bench_fliplab(const std::vector<geom_point> &p, const std::vector<double> &w,
                            std::vector<Tri> &tri, size_t &hidden, size_t &rounds) {
  rule r;
  char err[256];
  rule_parse("WDT", &r, err, sizeof err);
  lot_options o;
  lot_options_init(&o, &r);
  o.weights = w.data();
  double t0 = bench_now();
  lot *L;
  if (lot_build(&L, p.data(), p.size(), &o, err, sizeof err) != 0) {
    std::fprintf(stderr, "bench_wdt_cgal: %s\n", err);
    std::exit(1);
  }
  double t = bench_now() - t0;
  const lot_stats *st = lot_get_stats(L);
  std::vector<uint32_t> v(3 * st->triangles);
  lot_get_triangles(L, v.data());
  tri.resize(st->triangles);
  for (size_t k = 0; k < st->triangles; k++) tri[k] = {v[3 * k], v[3 * k + 1], v[3 * k + 2]};
  hidden = st->redundant;
  rounds = st->rounds;
  lot_free(L);
  return t;
}

// CGAL's regular triangulation of the same weighted points.
static double bench_cgal(const std::vector<geom_point> &p, const std::vector<double> &w,
                         std::vector<Tri> &tri, size_t &hidden) {
  std::vector<std::pair<K::Weighted_point_2, unsigned>> wp;
  wp.reserve(p.size());
  for (size_t i = 0; i < p.size(); i++)
    wp.emplace_back(K::Weighted_point_2(K::Point_2(p[i].x, p[i].y), w[i]), (unsigned)i);
  double t0 = bench_now();
  RT rt;
  rt.insert(wp.begin(), wp.end());
  double t = bench_now() - t0;
  tri.clear();
  for (auto f = rt.finite_faces_begin(); f != rt.finite_faces_end(); ++f)
    tri.push_back(bench_canon(f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()));
  std::sort(tri.begin(), tri.end());
  hidden = rt.number_of_hidden_vertices();
  return t;
}

int main(int argc, char **argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: bench_wdt_cgal N RUNS SEED SCALE\n");
    return 2;
  }
  size_t n = (size_t)std::strtod(argv[1], nullptr);
  int runs = std::atoi(argv[2]);
  uint64_t seed = std::strtoull(argv[3], nullptr, 10);
  double scale = std::strtod(argv[4], nullptr);
  std::vector<geom_point> p(n);
  std::vector<double> w(n);
  sampler_points(SAMPLER_UNIFORM, seed, n, p.data());
  uint64_t s = seed ^ 0x77656967687473ull;
  for (size_t i = 0; i < n; i++) w[i] = scale / (double)n * geom_unit53(geom_splitmix64(&s));
  std::vector<double> tf, tc;
  std::vector<Tri> a, b;
  size_t ha = 0, hb = 0, rounds = 0;
  for (int k = 0; k < runs; k++) {
    tf.push_back(bench_fliplab(p, w, a, ha, rounds));
    tc.push_back(bench_cgal(p, w, b, hb));
  }
  double mf = bench_median(tf), mc = bench_median(tc);
  std::printf("n %zu  weights in [0, %g)  runs %d\n", n, scale / (double)n, runs);
  std::printf("fliplab WDT      %.4f s  (%zu triangles, %zu sites left out, %zu rounds)\n", mf,
              a.size(), ha, rounds);
  std::printf("CGAL regular     %.4f s  (%zu triangles, %zu hidden)\n", mc, b.size(), hb);
  std::printf("ratio fliplab/CGAL %.2f\n", mf / mc);
  std::printf("same triangles: %s\n", a == b && ha == hb ? "yes" : "NO");
  return a == b && ha == hb ? 0 : 1;
}
