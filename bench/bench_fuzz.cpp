// Fuzzing throughput (issue 4): applications plus full validity checks per
// second, per core, on random valid maps of 50-200 darts.
//  - ApplyAndCheck: the inner step of `dartcheck fuzz` alone: copy the
//    host, apply the rule at one dart (by one Applier
//    kept across applications, as the engine does), check every dart of H. The target
//    is 100,000 per second for quad subdivision on 2-G-maps of ~100 darts.
//  - FuzzRule: the whole engine (random recipes, every dart as hook,
//    refusals included), enumeration off, hosts up to the given size.
#include <benchmark/benchmark.h>

#include <random>

#include "checkers/map_validity.hpp"
#include "analysis/fuzz.hpp"
#include "io/catalog.hpp"
#include "rewriting/application.hpp"
#include "generators/random_maps.hpp"

using namespace dartcheck;

namespace {

const Catalog& catalog() {
  static const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  return c;
}

// 64 random valid maps of the rule's model with darts in [lo, hi].
std::vector<Map> hosts(const Model& model, std::size_t lo, std::size_t hi) {
  std::mt19937 rng(7);
  std::vector<Map> out;
  while (out.size() < 64) {
    Map g = build_random_map(model, draw_recipe(rng, static_cast<std::uint32_t>(hi / 7), model.dimension()));
    if (g.size() >= lo && g.size() <= hi) out.push_back(std::move(g));
  }
  return out;
}

void ApplyAndCheck(benchmark::State& state, const char* rule_name) {
  const CatalogRule& r = *catalog().find_rule(rule_name);
  const auto lo = static_cast<std::size_t>(state.range(0)), hi = lo + lo / 5;
  const auto maps = hosts(r.rule.model(), lo, hi);
  Map scratch = maps[0];
  // As the fuzz engine does: one Applier per rule, its tables reused by
  // every application.
  Applier rewriter(r);
  std::size_t k = 0, applied = 0, darts = 0;
  for (auto _ : state) {
    const Map& g = maps[k % maps.size()];
    const Dart hook = static_cast<Dart>((k / maps.size()) % g.size());
    ++k;
    scratch = g;
    auto d = rewriter.apply(scratch, std::span(&hook, 1));
    const bool ok = d.ok();
    if (ok) rewriter.recycle(std::move(*d.value));
    if (ok) {
      ++applied;
      darts += scratch.size();
      benchmark::DoNotOptimize(check_map(scratch).valid());
    }
  }
  state.counters["applications/s"] = benchmark::Counter(static_cast<double>(applied), benchmark::Counter::kIsRate);
  state.counters["attempts/s"] = benchmark::Counter(static_cast<double>(k), benchmark::Counter::kIsRate);
  state.counters["H darts"] = applied ? static_cast<double>(darts) / static_cast<double>(applied) : 0;
}

void FuzzRule(benchmark::State& state, const char* rule_name) {
  const CatalogRule& r = *catalog().find_rule(rule_name);
  analysis::FuzzOptions o;
  o.runs = 20'000;
  o.max_darts = static_cast<std::size_t>(state.range(0));
  o.exhaustive_hosts = 0;
  o.event_checks = 0;  // the topological loop alone, as before events/ existed
  std::size_t applications = 0;
  for (auto _ : state) {
    ++o.seed;
    const auto report = analysis::fuzz_rule(r, {}, o);
    applications += report.applications;
  }
  state.counters["applications/s"] = benchmark::Counter(static_cast<double>(applications), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK_CAPTURE(ApplyAndCheck, quad_subdivision_gmap, "quad-subdivision-gmap")->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(ApplyAndCheck, insert_vertex_sewn_edge, "insert-vertex-sewn-edge")->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(ApplyAndCheck, face_extrusion_omap, "face-extrusion-omap")->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(FuzzRule, quad_subdivision_gmap, "quad-subdivision-gmap")->Arg(128)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(FuzzRule, insert_vertex_sewn_edge, "insert-vertex-sewn-edge")->Arg(128)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
