// Validity check and vertex-orbit traversal on large quad grids, dartcheck
// against CGAL on the same maps, in one program (the only translation unit
// of this target that includes CGAL).
//
//   build/bench/bench_validity --benchmark_min_time=0.5
//
// Maps: 2-G-maps and 2-O-maps of about 1M and 8M darts, in builder order
// and with darts shuffled (a random permutation of the dart indices, and
// CGAL's darts created in that order). "stream" reads every link entry
// once: the memory-bandwidth floor of any check.
#include <CGAL/Combinatorial_map.h>
#include <CGAL/Generalized_map.h>
#include <algorithm>
#include <benchmark/benchmark.h>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <memory>
#include <numeric>
#include <random>

#include "checkers/map_validity.hpp"
#include "core/orbit.hpp"
#include "generators/shapes.hpp"

using namespace dartcheck;

namespace {

using GMap2 = CGAL::Generalized_map<2>;
using CMap2 = CGAL::Combinatorial_map<2>;

Map shuffled(const Map& m, std::uint64_t seed) {
  std::vector<Dart> perm(m.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), std::mt19937_64(seed));
  Map out(m.model(), m.size());
  for (Dim i : m.model().dims)
    for (Dart d = 0; d < m.size(); ++d) {
      const Dart e = m.link(i, d);
      out.set_link_raw(i, perm[d], e == no_dart ? no_dart : perm[e]);
      if (m.model().is_oriented(i)) {
        const Dart p = m.inverse_link(i, d);
        out.set_inverse_link_raw(i, perm[d], p == no_dart ? no_dart : perm[p]);
      }
    }
  return out;
}

std::unique_ptr<GMap2> to_cgal_gmap(const Map& m) {
  auto g = std::make_unique<GMap2>();
  std::vector<GMap2::Dart_handle> h(m.size());
  for (Dart d = 0; d < m.size(); ++d) h[d] = g->create_dart();
  for (Dim i = 0; i <= 2; ++i)
    for (Dart d = 0; d < m.size(); ++d)
      if (m.link(i, d) > d) g->basic_link_alpha(h[d], h[m.link(i, d)], static_cast<unsigned>(i));
  return g;
}

std::unique_ptr<CMap2> to_cgal_cmap(const Map& m) {
  auto c = std::make_unique<CMap2>();
  std::vector<CMap2::Dart_handle> h(m.size());
  for (Dart d = 0; d < m.size(); ++d) h[d] = c->create_dart();
  for (Dart d = 0; d < m.size(); ++d) {
    c->basic_link_beta_1(h[d], h[m.link(1, d)]);
    if (m.link(2, d) > d) c->basic_link_beta_for_involution<2>(h[d], h[m.link(2, d)]);
  }
  return c;
}

struct Case {
  std::string name;
  Map map;
  std::unique_ptr<GMap2> gmap;
  std::unique_ptr<CMap2> cmap;
};

// Grids sized for about 1M and 8M darts: 8rc darts in a 2-G-map,
// 4rc + 2(r+c) in a 2-O-map.
Case& get_case(const std::string& model, int millions, bool shuffle) {
  static std::map<std::string, std::unique_ptr<Case>> cache;
  const std::string key = model + std::to_string(millions) + (shuffle ? "s" : "");
  auto& slot = cache[key];
  if (!slot) {
    const bool g = model == "2-gmap";
    const int side = static_cast<int>(std::sqrt(millions * 1e6 / (g ? 8.0 : 4.0)));
    Map m = build_shape(*Model::by_name(model), {"grid", {side, side}});
    if (shuffle) m = shuffled(m, 42);
    slot = std::make_unique<Case>(Case{key, std::move(m), nullptr, nullptr});
    if (g)
      slot->gmap = to_cgal_gmap(slot->map);
    else
      slot->cmap = to_cgal_cmap(slot->map);
  }
  return *slot;
}

void counters(benchmark::State& s, const Map& m, double bytes_per_dart) {
  s.counters["darts"] = static_cast<double>(m.size());
  s.counters["bytes_per_dart"] = bytes_per_dart;
  s.counters["ns_per_dart"] =
      benchmark::Counter(static_cast<double>(m.size()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void register_all() {
  for (const char* model : {"2-gmap", "2-omap"})
    for (int millions : {1, 8})
      for (bool shuffle : {false, true}) {
        const std::string tag = fmt::format("{}/{}M/{}", model, millions, shuffle ? "shuffled" : "ordered");
        const bool g = std::string(model) == "2-gmap";
        // One thread (CGAL's is_valid is sequential) and two (the
        // machines' cores; check_map's default from 2^20 darts on).
        for (unsigned threads : {1U, 2U})
          benchmark::RegisterBenchmark(fmt::format("validity/dartcheck-{}t/{}", threads, tag).c_str(), [=](benchmark::State& s) {
            Case& c = get_case(model, millions, shuffle);
            for (auto _ : s) benchmark::DoNotOptimize(check_map(c.map, threads).valid());
            if (!check_map(c.map, threads).valid()) s.SkipWithError("map is not valid");
            counters(s, c.map, static_cast<double>(c.map.stride() * sizeof(Dart)));
          });
        benchmark::RegisterBenchmark(("validity/cgal/" + tag).c_str(), [=](benchmark::State& s) {
          Case& c = get_case(model, millions, shuffle);
          bool ok = true;
          for (auto _ : s) benchmark::DoNotOptimize(ok = g ? c.gmap->is_valid() : c.cmap->is_valid(false));
          if (!ok) s.SkipWithError("CGAL says invalid");
          counters(s, c.map, static_cast<double>(g ? sizeof(GMap2::Dart) : sizeof(CMap2::Dart)));
        });
        benchmark::RegisterBenchmark(("stream/" + tag).c_str(), [=](benchmark::State& s) {
          Case& c = get_case(model, millions, shuffle);
          for (auto _ : s) {
            std::uint64_t sum = 0;
            for (Dart x : c.map.raw()) sum += x;
            benchmark::DoNotOptimize(sum);
          }
          counters(s, c.map, static_cast<double>(c.map.stride() * sizeof(Dart)));
        });
        benchmark::RegisterBenchmark(("vertices/dartcheck/" + tag).c_str(), [=](benchmark::State& s) {
          Case& c = get_case(model, millions, shuffle);
          OrbitWalker w(c.map);
          const auto gens = cell_generators(c.map.model(), 0);
          std::size_t n = 0;
          for (auto _ : s) benchmark::DoNotOptimize(n = w.count_orbits(gens));
          s.counters["vertices"] = static_cast<double>(n);
          counters(s, c.map, static_cast<double>(c.map.stride() * sizeof(Dart)));
        });
        benchmark::RegisterBenchmark(("vertices/cgal/" + tag).c_str(), [=](benchmark::State& s) {
          Case& c = get_case(model, millions, shuffle);
          std::size_t n = 0;
          for (auto _ : s) benchmark::DoNotOptimize(n = g ? c.gmap->one_dart_per_cell<0>().size() : c.cmap->one_dart_per_cell<0>().size());
          s.counters["vertices"] = static_cast<double>(n);
          counters(s, c.map, static_cast<double>(g ? sizeof(GMap2::Dart) : sizeof(CMap2::Dart)));
        });
      }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
