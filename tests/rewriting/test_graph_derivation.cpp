// DPO on small labeled graphs: 002 Example 1, and agreement with the
// dense-map engine on every application it performs.
#include <gtest/gtest.h>
#include <map>
#include <rapidcheck/gtest.h>

#include "io/catalog.hpp"
#include "rewriting/detail/derivation.hpp"
#include "rewriting/graph_derivation.hpp"
#include "io/map_io.hpp"
#include "generators/random_maps.hpp"
#include "tests/map_recipe_gen.hpp"

using namespace dartcheck;

namespace {
// Labels of Example 1 / Figure 1 as dimensions: i = 0, j = 1, k = 2, d = 3.
constexpr int i_ = 0, j_ = 1, k_ = 2, d_ = 3;

Model example_model() {
  Model m;
  m.name = "example-1";
  m.dims = {0, 1, 2, 3};
  return m;
}
}  // namespace

// 002 Example 1: "Relabeling an i-arc into a j-arc ... The rule has two nodes
// in its left-hand side, right-hand side, and interface, an arc with the
// label to be modified in L, the relabeled arc in R, and no arc in K. The
// rule application is obtained via the match sending the node a to the
// node v, the node b to the node x and the i-arc between a and b to the
// i-arc between v and x. The i-arc is relabeled by j." Figure 1's graph G
// is lost; it has nodes v, w, x, y, z and arcs labeled i, k, j, d, so G below
// has those plus a second i-arc (z -> w) that the match must not touch.
TEST(GraphDerivation, Example1Relabeling) {
  TopoGraph L, R, G;
  L.add_node("a"), L.add_node("b"), L.add_arc(0, 1, i_);
  R.add_node("a"), R.add_node("b"), R.add_arc(0, 1, j_);
  const Rule r("relabel", example_model(), L, R, {"a"});
  for (const char* n : {"v", "w", "x", "y", "z"}) G.add_node(n);
  enum : NodeId { v, w, x, y, z };
  G.add_arc(v, x, i_), G.add_arc(x, w, k_), G.add_arc(v, y, j_), G.add_arc(y, z, d_), G.add_arc(z, w, i_);

  const auto matches = all_matches(r.left(), G);
  ASSERT_EQ(matches.size(), 2u) << "the two i-arcs of G";
  const auto m = std::find_if(matches.begin(), matches.end(), [](const GraphMatch& g) { return g.node[0] == v; });
  ASSERT_NE(m, matches.end());
  EXPECT_EQ(m->node[1], x);
  EXPECT_TRUE(satisfies_dangling(r, G, *m)) << "no node is deleted";
  const TopoGraph H = derive(r, G, *m);
  // H: G with v -i-> x replaced by v -j-> x, everything else unchanged.
  EXPECT_EQ(H.names(), G.names());
  auto sorted = [](std::vector<Arc<int>> a) {
    std::sort(a.begin(), a.end(), [](auto& p, auto& q) { return std::tie(p.source, p.target, p.label) < std::tie(q.source, q.target, q.label); });
    return a;
  };
  EXPECT_EQ(sorted(H.arcs()), sorted({{v, x, j_}, {x, w, k_}, {v, y, j_}, {y, z, d_}, {z, w, i_}}));
}

TEST(GraphDerivation, DanglingConditionOnGraphs) {
  // Deleting b while G has another arc at b's image violates it.
  TopoGraph L, R, G;
  L.add_node("a"), L.add_node("b"), L.add_arc(0, 1, 0);
  R.add_node("a");
  const Rule r("drop-b", example_model(), L, R, {"a"});
  G.add_node("p"), G.add_node("q"), G.add_node("s");
  G.add_arc(0, 1, 0);
  EXPECT_TRUE(satisfies_dangling(r, G, all_matches(L, G).at(0)));
  G.add_arc(2, 1, 3);
  EXPECT_FALSE(satisfies_dangling(r, G, all_matches(L, G).at(0)));
}

// Two implementations of Def. 4: on every application the dense engine
// performs, the exhaustive graph engine with the same match yields the same
// H (nodes related by the dense comatch and renumbering).
RC_GTEST_PROP(GraphDerivation, AgreesWithDenseEngine, ()) {
  static const Catalog seed = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  const auto& entry = *rc::gen::elementOf(seed.rules);
  const Rule& rule = entry.rule;
  const Map host = build_random_map(rule.model(), *gen_map_recipe(1, 12));
  const TopoGraph G = to_graph(host);
  int applied = 0;
  for (Dart hook = 0; hook < host.size(); ++hook) {
    Map g = host;
    auto out = apply_rule(rule, g, std::span(&hook, 1));
    if (!out.ok()) continue;
    ++applied;
    RC_LOG() << rule.name() << " at " << hook << " on\n" << map_to_yaml(host) << "gives\n" << map_to_yaml(g);
    const Derivation& d = *out.value;
    // The same match on the graph: L arc x -i-> y goes to the i-arc of m(x).
    GraphMatch m{std::vector<NodeId>(d.match.node.begin(), d.match.node.end()), {}};
    for (const auto& a : rule.left().arcs()) {
      ArcId f = 0;
      while (!(G.arc(f).source == m.node[a.source] && G.arc(f).label == a.label)) ++f;
      m.arc.push_back(f);
    }
    RC_ASSERT(satisfies_dangling(rule, G, m));
    std::vector<NodeId> comatch;
    const TopoGraph H = derive(rule, G, m, &comatch);
    RC_ASSERT(H.node_count() == g.size());
    // Graph H node -> dense H dart: preserved darts by name (moved ones
    // renumbered), added nodes through the two comatches.
    std::map<Dart, Dart> moved(d.moved.begin(), d.moved.end());
    std::vector<Dart> to_dart(H.node_count(), no_dart);
    for (NodeId v = 0; v < H.node_count(); ++v) {
      if (auto it = std::find(comatch.begin(), comatch.end(), v); it != comatch.end()) {
        to_dart[v] = d.comatch[static_cast<std::size_t>(it - comatch.begin())];
      } else {
        const Dart old = static_cast<Dart>(std::stoul(H.name(v)));
        to_dart[v] = moved.count(old) ? moved[old] : old;
      }
    }
    std::vector<std::tuple<Dart, Dart, int>> from_graph, from_dense;
    for (const auto& a : H.arcs()) from_graph.emplace_back(to_dart[a.source], to_dart[a.target], a.label);
    const TopoGraph Hd = to_graph(g);
    for (const auto& a : Hd.arcs()) from_dense.emplace_back(a.source, a.target, a.label);
    std::sort(from_graph.begin(), from_graph.end());
    std::sort(from_dense.begin(), from_dense.end());
    RC_ASSERT(from_graph == from_dense);
  }
  RC_CLASSIFY(applied > 0, "applied somewhere");
}
