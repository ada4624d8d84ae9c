// Operation inference by folding (000): linear scaling and the paper's
// small examples.
//
// Scaling (000 Sec. 8.3: O(|G| + |H|)): quad tori of n x n quads (G, 8n²
// darts) and their quad subdivision (H, 32n² darts, applied by the
// catalog's Jerboa scheme), κ = identity. Timed: the folding alone, and
// the whole inference (folding, rule, static check of the rule, and the
// App. A verification that applies the rule to G and compares with H).
// ns per dart of κ(G, H) should be flat across sizes.
//
// Examples: the inferences of 000 Sec. 9 dartcheck reproduces (quad from
// the cube, Loop and Powell-Sabin from one triangle, sqrt3 from the
// tetrahedron, Doo-Sabin's third iteration from the cube, Menger and the
// (2,2,2)-Menger from a cube in 3-G-maps), whole inference with
// verification, for comparison with the paper's JVM figures (Powell-Sabin
// about 5 ms, Doo-Sabin 3 about 40 ms, (2,2,2)-Menger about 100 ms).
// Usage: bench_inference [--runs N] [--quick]
#include <algorithm>
#include <chrono>
#include <cstring>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include "generators/polygon_soup.hpp"
#include "generators/shapes.hpp"
#include "inference/infer.hpp"
#include "bench/median.hpp"
#include "io/catalog.hpp"
#include "rewriting/application.hpp"
#include "../tests/inference/polycube.hpp"

using namespace dartcheck;
using namespace dartcheck::inference;

namespace {

using bench::median_ms;

std::vector<Polygon> torus(std::uint32_t n) {
  std::vector<Polygon> f;
  auto v = [n](std::uint32_t i, std::uint32_t j) { return (i % n) * n + (j % n); };
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < n; ++j) f.push_back({v(i, j), v(i, j + 1), v(i + 1, j + 1), v(i + 1, j)});
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5;
  bool quick = false;
  for (int k = 1; k < argc; ++k) {
    if (!std::strcmp(argv[k], "--runs") && k + 1 < argc)
      runs = std::atoi(argv[++k]);
    else if (!std::strcmp(argv[k], "--quick"))
      quick = true;
  }
  const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  const Operation& quad = *catalog.find_rule("quad-subdivision-jerboa");
  const Model m = Model::gmap(2);
  const std::vector<Dim> orbit{0, 1, 2};

  fmt::print("scaling: quad subdivision of n x n quad tori, median of {} runs\n", runs);
  fmt::print("{:>6} {:>10} {:>10} {:>11} {:>10} {:>11} {:>10}\n", "n", "|G|", "|G|+|H|", "fold ms", "ns/dart", "infer ms", "ns/dart");
  std::vector<std::uint32_t> sizes{5, 16, 50, 160, 500};
  if (quick) sizes = {5, 16, 50};
  for (std::uint32_t n : sizes) {
    Map g = build_surface(m, torus(n));
    Map h = g;
    const Dart hook[] = {0};
    if (!Applier(quad).apply(h, hook).ok()) return 1;
    KappaSpec k;
    k.identity = true;
    const auto graph = make_kappa_graph(g, h, k);
    bool ok = true;
    const double fold_ms = median_ms(runs, [&] { ok &= fold(graph, orbit, 0).scheme.has_value(); });
    InferOptions o;
    o.start = 0;
    const double infer_ms = median_ms(runs, [&] { ok &= infer(graph, orbit, o).at(0).inferred(); });
    if (!ok) {
      fmt::print("n = {}: inference failed\n", n);
      return 1;
    }
    const double darts = static_cast<double>(graph.size());
    fmt::print("{:>6} {:>10} {:>10} {:>11.3f} {:>10.1f} {:>11.3f} {:>10.1f}\n", n, g.size(), graph.size(), fold_ms, fold_ms * 1e6 / darts, infer_ms,
               infer_ms * 1e6 / darts);
  }

  fmt::print("\n000 Sec. 9 examples: whole inference with verification, median of {} runs\n", std::max(runs, 21));
  struct Example {
    const char* name;
    std::vector<Polygon> faces;
    inference::test::Subdivided (*subdivide)(const std::vector<Polygon>&);
  };
  const std::vector<Example> examples{{"quad subdivision (cube, Fig. 13)", cube_faces(), inference::test::quad_subdivision},
                                      {"Loop (one triangle, Fig. 27)", {{0, 1, 2}}, inference::test::loop_subdivision},
                                      {"Powell-Sabin 6-split (one triangle, Fig. 29)", {{0, 1, 2}}, inference::test::powell_sabin},
                                      {"sqrt3 (tetrahedron, Fig. 31)", tetrahedron_faces(), inference::test::sqrt3}};
  auto time_example = [&](const char* name, const KappaGraph& graph, const std::vector<Dim>& o) {
    bool ok = true;
    const double ms = median_ms(std::max(runs, 21), [&] {
      const auto attempts = infer(graph, o, {});
      ok &= std::any_of(attempts.begin(), attempts.end(), [](const Attempt& a) { return a.inferred(); });
    });
    fmt::print("  {:<46} {:>6} darts  {:>9.4f} ms{}\n", name, graph.size(), ms, ok ? "" : "  FAILED");
    return ok;
  };
  for (const auto& e : examples) {
    const auto s = e.subdivide(e.faces);
    KappaSpec k;
    for (const auto& [b, a] : s.kappa) k.pairs.emplace_back(inference::test::soup_dart(e.faces, b), inference::test::soup_dart(s.faces, a));
    if (!time_example(e.name, make_kappa_graph(build_surface(m, e.faces), build_surface(m, s.faces), k), orbit)) return 1;
  }
  {
    using namespace inference::test;
    const auto s = iterate(iterate(doo_sabin(cube_faces()), doo_sabin), doo_sabin);
    KappaSpec k;
    for (const auto& [b, a] : s.kappa) k.pairs.emplace_back(soup_dart(cube_faces(), b), soup_dart(s.faces, a));
    if (!time_example("Doo-Sabin, 3rd iteration (cube, Fig. 32b)", make_kappa_graph(build_surface(m, cube_faces()), build_surface(m, s.faces), k),
                      orbit))
      return 1;
    const std::vector<std::array<std::uint32_t, 3>> one{{0, 0, 0}};
    for (const auto& [name, n, keep] :
         {std::tuple{"Menger (cube, Fig. 34)", 3u, &menger_local}, std::tuple{"(2,2,2)-Menger (cube, Fig. 35)", 5u, &menger222_local}}) {
      const auto fine = refine(one, 1, n, *keep);
      if (!time_example(name, make_kappa_graph(polycube(one, 1), polycube(fine, n), corner_kappa(one, 1, fine, n)), {0, 1, 2, 3})) return 1;
    }
  }

  // Every start (--all) on an n x n grid that does not change (G = H, κ =
  // identity), the case where each start folds a different scheme: <0,1>
  // fails at the first boundary face its rings reach; <2> from a boundary
  // dart gives a whole-grid rule (one node per dart) that does nothing.
  // One start with a whole-grid rule shows the rule's own cost (fold,
  // static check, verification) is linear. Skipped: starts whose orbit an
  // earlier folding built as a hook-labelled node (000 Sec. 10.3).
  auto unchanged = [](const Map& g) {  // κ(G, G) by the identity
    KappaSpec k;
    k.identity = true;
    return make_kappa_graph(g, g, k);
  };
  fmt::print("\ninfer --all on unchanged n x n grids (G = H, identity), median of {} runs\n", runs);
  fmt::print("{:>6} {:>6} {:>8} {:>9} {:>8} {:>11} {:>12}\n", "orbit", "n", "|G|", "attempts", "skipped", "ms", "ns/dart/att");
  std::vector<int> grid_sizes{10, 20, 40};
  if (quick) grid_sizes = {10, 20};
  for (const std::vector<Dim>& o : {std::vector<Dim>{0, 1}, std::vector<Dim>{2}})
    for (int n : grid_sizes) {
      const Map g = build_surface(m, grid_faces(n, n));
      const auto graph = unchanged(g);
      InferOptions all;
      all.all = true;
      all.keep_rejected = false;
      std::size_t attempts = 0, skipped = 0;
      const double ms = median_ms(runs, [&] {
        const auto out = infer(graph, o, all);
        attempts = out.size();
        skipped = 0;
        for (const auto& a : out) skipped += a.same_starts.size();
      });
      fmt::print("{:>6} {:>6} {:>8} {:>9} {:>8} {:>11.1f} {:>12.1f}\n", orbit_type_str(OrbitType(o.begin(), o.end())), n, g.size(), attempts, skipped,
                 ms, ms * 1e6 / static_cast<double>(graph.size()) / static_cast<double>(attempts));
    }
  fmt::print("\none start (--start 0) giving a whole-grid rule: orbit <2>, median of {} runs\n", runs);
  fmt::print("{:>6} {:>8} {:>8} {:>11} {:>10}\n", "n", "|G|", "|L|", "ms", "ns/dart");
  std::vector<int> rule_sizes{20, 40, 80, 160};
  if (quick) rule_sizes = {20, 40};
  for (int n : rule_sizes) {
    const Map g = build_surface(m, grid_faces(n, n));
    const auto graph = unchanged(g);
    InferOptions one;
    one.start = 0;
    std::size_t left = 0;
    const double ms = median_ms(runs, [&] {
      const auto a = infer(graph, {2}, one).at(0);
      left = a.rule ? a.rule->operation.rule.left().node_count() : 0;
    });
    if (left == 0) {
      fmt::print("n = {}: no rule folded from dart 0\n", n);
      return 1;
    }
    fmt::print("{:>6} {:>8} {:>8} {:>11.1f} {:>10.1f}\n", n, g.size(), left, ms, ms * 1e6 / static_cast<double>(graph.size()));
  }
  return 0;
}
