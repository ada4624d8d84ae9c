// Round trip (000 App. A read backwards): let S be a consistent
// Jerboa-style scheme whose L is complete (every node has every dimension,
// as a relabeling or an explicit arc) and G a connected map on which S's
// instantiated L at hook dart v covers every dart. If the hook orbit
// G<o>(v) has no loop and no two of its dimensions link the same pair of
// darts (so the example decides every label), then folding
// κ(G, S applied to G at v) from v gives S back up to node names.
//
// Subjects: every such scheme of the bundled catalogs and of
// ../shared/jerboa-samples/JerboaRebuilt2.jme (3-G-maps), on random
// connected maps. DARTCHECK_INFERENCE_RUNS sets the number of maps (100).
#include <cstdlib>
#include <iostream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "checkers/rule_conditions.hpp"
#include "generators/random_maps.hpp"
#include "tests/map_recipe_gen.hpp"
#include "inference_support.hpp"

namespace dartcheck::inference::test {
namespace {

int runs() {
  const char* env = std::getenv("DARTCHECK_INFERENCE_RUNS");
  return env ? std::atoi(env) : 100;
}

// Every node of L has every dimension: in its label or as an explicit arc.
bool complete_left(const Operation& op) {
  const auto& g = op.rule.left();
  for (NodeId v = 0; v < g.node_count(); ++v) {
    DimSet dims = 0;
    for (const auto& j : op.jerboa->left[v])
      if (j) dims |= dim_bit(*j);
    for (ArcId e = 0; e < g.arc_count(); ++e)
      if (g.arc(e).source == v && arc_word(op.words.left, e).empty()) dims |= dim_bit(g.arc(e).label);
    if (dims != op.rule.model().dim_set()) return false;
  }
  return true;
}

std::vector<const Operation*> subjects() {
  static std::vector<Catalog> catalogs;
  if (catalogs.empty())
    for (const char* f : {"/catalogs/seed-operations.yaml", "/catalogs/embedding-operations.yaml", "/catalogs/event-operations.yaml",
                          "/../shared/jerboa-samples/JerboaRebuilt2.jme"})
      catalogs.push_back(read_catalog(std::string(DARTCHECK_SOURCE_DIR) + f));
  std::vector<const Operation*> out;
  for (const auto& c : catalogs)
    for (const auto& r : c.rules)
      if (r.jerboa && r.rule.hooks().size() == 1 && has_random_generator(r.rule.model()) && complete_left(r) &&
          check_rule(r.rule, r.words).consistent() && canonical_form(r))
        out.push_back(&r);
  return out;
}

// The example decides every label: no loop and no doubled link in G<o>(v).
bool decisive(const Map& g, const std::vector<Dim>& orbit, Dart v) {
  for (Dart b : orbit_darts(g, orbit, v))
    for (std::size_t p = 0; p < orbit.size(); ++p) {
      if (g.link(orbit[p], b) == b) return false;
      for (std::size_t q = 0; q < orbit.size(); ++q)
        if (p != q && g.link(orbit[p], b) == g.link(orbit[q], b)) return false;
    }
  // Nor any other dimension: a j-link doubling an i-link of the orbit would
  // be a second relabeling candidate.
  for (Dart b : orbit_darts(g, orbit, v))
    for (Dim j : g.model().dims)
      for (Dim i : orbit)
        if (i != j && g.link(i, b) == g.link(j, b)) return false;
  return true;
}

enum class Outcome { round_trip, not_covering, not_decisive, refused };

// One case; fails the test on a round trip that does not hold.
Outcome check_case(const Operation& op, const Map& random, Dart hook) {
  Dart v = 0;
  const Map g = component(random, hook, &v);
  const Dart hooks[] = {v};
  auto match = Applier(op).match(g, hooks);
  if (!match.ok()) return Outcome::refused;
  if (match.value->pattern->darts[0].size() * op.rule.left().node_count() != g.size()) return Outcome::not_covering;
  std::vector<Dim> dims;
  for (const auto& d : op.jerboa->parameter) dims.push_back(*d);
  if (!decisive(g, dims, v)) return Outcome::not_decisive;
  Map h = g;
  auto derived = Applier(op).apply(h, hooks);
  if (!derived.ok()) return Outcome::refused;
  // κ: the preserved darts keep their place (renumbered when H is compacted).
  KappaSpec kappa;
  std::vector<Dart> renumbered(g.size());
  for (Dart x = 0; x < g.size(); ++x) renumbered[x] = x;
  for (const auto& [from, to] : derived.value->moved)
    if (from < g.size()) renumbered[from] = to;
  for (NodeId x = 0; x < op.rule.left().node_count(); ++x)
    if (op.rule.to_right(x) != no_node)
      for (Dart d : match.value->match[x]) kappa.pairs.emplace_back(d, renumbered[d]);
  const auto graph = make_kappa_graph(g, h, kappa);
  InferOptions o;
  o.start = v;
  const auto attempts = infer(graph, dims, o);
  const Attempt& a = attempts.at(0);
  const std::string what = fmt::format("{} on a {}-dart map at {}: ", op.rule.name(), g.size(), v);
  if (!a.inferred()) {
    const std::string why = a.failure ? a.failure->text : !a.ill_formed.empty() ? "ill-formed" : a.verification ? a.verification->why : a.not_a_rule;
    ADD_FAILURE() << what << why;
    RC_FAIL(what + why);
  }
  if (canonical_form(a.rule->operation) != canonical_form(op)) {
    ADD_FAILURE() << what << *canonical_form(a.rule->operation) << " != " << *canonical_form(op);
    RC_FAIL(what + "a different scheme");
  }
  return Outcome::round_trip;
}

RC_GTEST_PROP(InferenceRoundTrip, CatalogSchemesOnRandomMaps, ()) {
  static const auto subs = subjects();
  const auto recipe = *gen_map_recipe(1, 5);
  std::size_t trips = 0;
  for (const Operation* op : subs) {
    const Map g = build_random_map(op->rule.model(), recipe);
    for (Dart d = 0; d < g.size(); d += 7) trips += check_case(*op, g, d) == Outcome::round_trip;
  }
  RC_CLASSIFY(trips > 0, "round trips");
}

// The property is not vacuous: the subjects include the catalogs'
// surface schemes, and each round-trips on closed shapes (every link
// non-loop) where its L covers the map.
TEST(InferenceRoundTrip, SubjectsRoundTripOnClosedShapes) {
  const auto subs = subjects();
  std::vector<std::string> names;
  for (const auto* op : subs) names.push_back(op->rule.name());
  for (const char* expected : {"quad-subdivision-jerboa", "edge-rounding-gmap"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected << " is not a subject";
  std::size_t trips = 0;
  for (const auto* op : subs) {
    const int n = op->rule.model().dimension();
    for (const char* s : {"cube", "tetrahedron", "prism:5"}) {
      Map g = build_shape(Model::gmap(n), parse_shape(s));
      for (Dart d = 0; d < g.size(); d += 5) trips += check_case(*op, g, d) == Outcome::round_trip;
      if (::testing::Test::HasFailure()) return;
    }
  }
  EXPECT_GE(trips, 20u);
  std::cerr << "subjects " << subs.size() << " (" << fmt::format("{}", fmt::join(names, ", ")) << "), shape round trips " << trips << "\n";
  int random_trips = 0;
  std::mt19937 rng(11);
  for (int k = 0; k < runs(); ++k) {
    for (const auto* op : subs) {
      const Map g = build_random_map(op->rule.model(), draw_recipe(rng, 1 + static_cast<std::uint32_t>(k % 5), op->rule.model().dimension()));
      for (Dart d = 0; d < g.size(); d += 3) random_trips += check_case(*op, g, d) == Outcome::round_trip;
      if (::testing::Test::HasFailure()) return;
    }
  }
  RecordProperty("random_round_trips", random_trips);
  std::cerr << "random round trips " << random_trips << "\n";
  EXPECT_GT(random_trips, 0);
}

}  // namespace
}  // namespace dartcheck::inference::test
