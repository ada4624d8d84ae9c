// Static vs dynamic event detection (004 Sec. 5), side by side in one run.
//
// For each scenario, one application G => H of a rule, then for every
// orbit type of the model: the dynamic log (every dart of G and H labeled
// with its orbit, events/event_log.hpp's oracle) against the instantiated log
// (the rule's orbits instantiated on the match; traversal only for
// incomplete rule orbits). Both logs are compared; the times are the
// median of --runs runs. Scenarios (2-G-maps; 004 used 3-G-maps in Jerboa):
//  - split: quad subdivision of the whole surface (the Jerboa scheme on
//    <0,1,2>) applied 8 times to the 48-dart cube, hooked on the last dart
//    (48 -> 3,145,728 darts); the log of the last application is timed;
//  - creation: face triangulation of one face of that 3,145,728-dart map
//    (new vertex, edges and faces);
//  - merge: deleting one interior edge of a 1024 x 1024 grid (two faces
//    merge; 8,388,608 darts).
// Usage: bench_events [--runs N] [--quick] (quick: 6 subdivisions, 256 x 256).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "events/event_log.hpp"
#include "generators/shapes.hpp"
#include "bench/median.hpp"
#include "io/catalog.hpp"

using namespace dartcheck;
using namespace dartcheck::events;
using Clock = std::chrono::steady_clock;

namespace {

using bench::median_ms;

void scenario(const char* name, const Operation& op, const Map& g, std::vector<Dart> hooks, int runs) {
  const EventRule view = *event_rule(op).rule;
  Map h = g;
  const auto start = Clock::now();
  auto traced = Applier(op).apply(h, hooks);
  const double apply_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  if (!traced.ok()) {
    fmt::print("{}: not applied: {}\n", name, traced.why);
    std::exit(1);
  }
  fmt::print("\n{}: {} at dart {}, {} -> {} darts, application {:.1f} ms\n\n", name, op.rule.name(), hooks[0], g.size(), h.size(), apply_ms);
  fmt::print("| orbit type | events | dynamic ms | instantiated ms | dynamic / instantiated |\n|---|---:|---:|---:|---:|\n");
  for (const OrbitKind& kind : all_orbit_kinds(op.rule.model())) {
    const KindEvents k = static_events(view, kind);
    EventLog dyn, inst;
    const double d = median_ms(runs, [&] { dyn = dynamic_log(g, h, op.rule, *traced.value, kind); });
    const double s = median_ms(runs, [&] { inst = instantiated_log(g, h, view, k, *traced.value); });
    if (dyn.events != inst.events) {
      fmt::print("{} {}: the logs differ\n", name, kind.str());
      std::exit(1);
    }
    fmt::print("| {} | {} | {:.2f} | {:.3f} | {:.0f}x |\n", kind.str(), dyn.events.size(), d, s, s > 0 ? d / s : 0.0);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5;
  bool quick = false;
  for (int k = 1; k < argc; ++k) {
    if (!std::strcmp(argv[k], "--runs") && k + 1 < argc)
      runs = std::max(1, std::atoi(argv[++k]));
    else if (!std::strcmp(argv[k], "--quick"))
      quick = true;
  }
  const Catalog seed = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  const Catalog ev = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/event-operations.yaml");
  const Operation& quad = *seed.find_rule("quad-subdivision-jerboa");
  Map g = build_shape(Model::gmap(2), {"cube", {}});
  const int steps = quick ? 6 : 8;
  for (int k = 0; k + 1 < steps; ++k) {
    Map next = g;
    const Dart last = static_cast<Dart>(g.size() - 1);
    if (!Applier(quad).apply(next, std::vector<Dart>{last}).ok()) return 1;
    g = std::move(next);
  }
  scenario("split", quad, g, {static_cast<Dart>(g.size() - 1)}, runs);
  Map big = g;
  Applier(quad).apply(big, std::vector<Dart>{static_cast<Dart>(g.size() - 1)});
  scenario("creation", *ev.find_rule("triangulate-face"), big, {static_cast<Dart>(big.size() - 1)}, runs);
  const int side = quick ? 256 : 1024;
  const Map grid = build_shape(Model::gmap(2), {"grid", {side, side}});
  Dart inner = 0;
  for (Dart d = static_cast<Dart>(grid.size() / 2); d < grid.size(); ++d)
    if (grid.link(2, d) != d) {
      inner = d;
      break;
    }
  scenario("merge", *ev.find_rule("delete-edge"), grid, {inner}, runs);
  return 0;
}
