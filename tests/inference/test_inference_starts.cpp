// Starts that need no folding (000 Sec. 10.3, docs/inference.md).
//
// Theorem (re-rooting). Let the non-strict folding of κ(G, H) from a along
// <o> build an L node m labelled as the hook (o_p -> o_p at every position
// p). Then m's darts are the <o>-orbit of any of them, and the non-strict
// folding from a dart of m builds the same nodes (as sets of darts) with
// the same labels and arcs; so it succeeds with this scheme hooked at m
// when this folding succeeds, and fails when it fails. Why: the two
// indexings of m's darts (from a's folding, and by m's own orbit walk) are
// isomorphisms of the labelled orbit graph, so they differ by an
// automorphism π of it; every step of the folding (which relabeling holds
// on every dart, which d-links form a node, the arc checks) is invariant
// under π, and the blocks are forced by the links. If the folding from m
// succeeded, a's hook would be a node labelled as the hook of that
// folding (the path back from m rebuilds it with label <o>), and a's
// folding would succeed: so a failure is shared too.
//
// Checked here by brute force: `infer --all` skips those starts and stops
// a folding at a node of an earlier failed one; every skipped start and
// every attempt made, folded alone (a lone --start folds everything),
// must give the same outcome and, when it succeeds, the same nodes,
// labels and arcs. Examples: random maps with H = G (every orbit type),
// and random maps with H = a catalog scheme applied at a dart.
// DARTCHECK_INFERENCE_RUNS sets the number of maps per kind (100).
#include <cstdlib>
#include <random>
#include <set>
#include <tuple>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "checkers/rule_conditions.hpp"
#include "generators/polygon_soup.hpp"
#include "generators/random_maps.hpp"
#include "inference_support.hpp"

namespace dartcheck::inference::test {
namespace {

int runs() {
  const char* env = std::getenv("DARTCHECK_INFERENCE_RUNS");
  return env ? std::atoi(env) : 100;
}

// The scheme as a set of nodes (each named by its smallest dart of
// κ(G, H), so independent of the hook) with labels and arcs.
using NodeKey = std::tuple<Dart, bool, std::string>;
using ArcKey = std::tuple<Dart, Dart, Dim>;
std::pair<std::set<NodeKey>, std::set<ArcKey>> shape_of(const GraphScheme& s) {
  std::vector<Dart> least;
  std::set<NodeKey> nodes;
  for (const auto& n : s.nodes) {
    least.push_back(*std::min_element(n.darts.begin(), n.darts.end()));
    nodes.emplace(least.back(), n.after, orbit_type_str(n.label));
  }
  std::set<ArcKey> arcs;
  for (const auto& e : s.arcs) {
    const Dart a = least[static_cast<std::size_t>(e.a)], b = least[static_cast<std::size_t>(e.b)];
    arcs.emplace(std::min(a, b), std::max(a, b), e.d);
  }
  return {nodes, arcs};
}

std::string outcome(const Attempt& a) {
  if (a.failure) return "failure";
  if (!a.not_a_rule.empty()) return "not a rule";
  if (!a.ill_formed.empty()) return "ill-formed";
  if (a.does_nothing) return "does nothing";
  if (a.verification && !a.verification->holds) return "verification failed";
  return a.freed_undecided ? "inferred (freed)" : "inferred";
}

struct Tally {
  std::size_t skipped = 0, shared_failures = 0, cases = 0;
};

// One example and orbit type: --all against every start folded alone.
void compare(const KappaGraph& graph, const std::vector<Dim>& orbit, FoldOptions fold, const std::string& what, Tally& tally) {
  InferOptions all;
  all.fold = fold;
  all.all = true;
  const auto attempts = infer(graph, orbit, all);
  ++tally.cases;
  auto alone = [&](Dart start, const Attempt& expected, const char* role) {
    InferOptions o;
    o.fold = fold;
    o.start = start;
    const Attempt b = infer(graph, orbit, o).at(0);
    const std::string where = fmt::format("{}, {} start {} (attempt from {}): ", what, role, start, expected.start);
    ASSERT_EQ(outcome(b), outcome(expected)) << where << (b.failure ? b.failure->text : "") << " / "
                                             << (expected.failure ? expected.failure->text : "");
    ASSERT_EQ(b.scheme.has_value(), expected.scheme.has_value()) << where;
    if (b.scheme) {
      EXPECT_EQ(shape_of(*b.scheme), shape_of(*expected.scheme)) << where << "a different scheme";
      EXPECT_EQ(b.scheme->undecided.size(), expected.scheme->undecided.size()) << where;
    }
  };
  std::set<Dart> seen;
  for (const Attempt& a : attempts) {
    // Every attempt made is what its start gives alone (this covers the
    // foldings stopped at a node of an earlier failed one) ...
    alone(a.start, a, "attempted");
    tally.shared_failures += a.failure && a.failure->kind == FailureKind::shared;
    // ... and every skipped start gives what the attempt that built it gave.
    for (Dart s : a.same_starts) {
      EXPECT_TRUE(seen.insert(s).second) << what << ": start " << s << " skipped twice";
      alone(s, a, "skipped");
      ++tally.skipped;
    }
    if (::testing::Test::HasFatalFailure()) return;
  }
  if (fold.strict) {
    for (const Attempt& a : attempts) EXPECT_TRUE(a.same_starts.empty()) << what << ": strict folding skips nothing";
  }
}

std::vector<std::vector<Dim>> orbit_types(int n) {
  std::vector<std::vector<Dim>> out;
  for (unsigned mask = 1; mask < (1u << (n + 1)); ++mask) {
    std::vector<Dim> o;
    for (Dim d = 0; d <= n; ++d)
      if (mask & (1u << d)) o.push_back(d);
    out.push_back(o);
  }
  return out;
}

FoldOptions policy(int k) {
  FoldOptions f;
  f.undecided = k % 3 == 0 ? UndecidedPolicy::keep : k % 3 == 1 ? UndecidedPolicy::free : UndecidedPolicy::fail;
  f.strict = k % 7 == 6 && f.undecided == UndecidedPolicy::keep;
  return f;
}

// H = G, κ the identity: every orbit type of the model.
TEST(InferenceStarts, SkippedStartsFoldAsTheirAttemptOnUnchangedMaps) {
  std::mt19937 rng(23);
  Tally tally;
  for (int n : {2, 3}) {
    const Model m = Model::gmap(n);
    for (int k = 0; k < runs(); ++k) {
      const Map g = component(build_random_map(m, draw_recipe(rng, 1 + static_cast<std::uint32_t>(k % 6), n)), 0);
      KappaSpec identity;
      identity.identity = true;
      const auto graph = make_kappa_graph(g, g, identity);
      for (const auto& o : orbit_types(n)) {
        compare(graph, o, policy(k),
                fmt::format("{}-gmap run {} ({} darts), orbit {}", n, k, g.size(), orbit_type_str(OrbitType(o.begin(), o.end()))), tally);
        if (HasFatalFailure()) return;
      }
    }
  }
  // Not vacuous: starts were skipped and foldings stopped early.
  EXPECT_GT(tally.skipped, 0u);
  EXPECT_GT(tally.shared_failures, 0u);
  std::cerr << fmt::format("{} examples, {} skipped starts, {} shared failures\n", tally.cases, tally.skipped, tally.shared_failures);
}

// H = a catalog scheme applied to G at a dart, κ its preserved darts.
TEST(InferenceStarts, SkippedStartsFoldAsTheirAttemptOnApplications) {
  std::vector<const Operation*> subjects;
  for (const auto& r : seed_catalog().rules)
    if (r.jerboa && r.rule.hooks().size() == 1 && has_random_generator(r.rule.model()) && check_rule(r.rule, r.words).consistent())
      subjects.push_back(&r);
  ASSERT_GE(subjects.size(), 3u);
  std::mt19937 rng(29);
  Tally tally;
  for (int k = 0; k < runs(); ++k)
    for (const Operation* op : subjects) {
      const int n = op->rule.model().dimension();
      const Map g = component(build_random_map(op->rule.model(), draw_recipe(rng, 1 + static_cast<std::uint32_t>(k % 4), n)), 0);
      const Dart hook = static_cast<Dart>(rng() % g.size());
      const Dart hooks[] = {hook};
      auto match = Applier(*op).match(g, hooks);
      if (!match.ok()) continue;
      Map h = g;
      auto derived = Applier(*op).apply(h, hooks);
      if (!derived.ok()) continue;
      std::vector<Dart> renumbered(g.size());
      for (Dart x = 0; x < g.size(); ++x) renumbered[x] = x;
      for (const auto& [from, to] : derived.value->moved)
        if (from < g.size()) renumbered[from] = to;
      KappaSpec kappa;
      std::vector<bool> matched(g.size(), false);
      for (NodeId x = 0; x < op->rule.left().node_count(); ++x)
        for (Dart d : match.value->match[x]) {
          matched[d] = true;
          if (op->rule.to_right(x) != no_node) kappa.pairs.emplace_back(d, renumbered[d]);
        }
      // The darts the rule did not touch are preserved too.
      for (Dart d = 0; d < g.size(); ++d)
        if (!matched[d]) kappa.pairs.emplace_back(d, renumbered[d]);
      const auto graph = make_kappa_graph(g, h, kappa);
      for (const auto& o : orbit_types(n)) {
        compare(graph, o, policy(k),
                fmt::format("{} on a {}-dart map at {}, orbit {}", op->rule.name(), g.size(), hook, orbit_type_str(OrbitType(o.begin(), o.end()))),
                tally);
        if (HasFatalFailure()) return;
      }
    }
  EXPECT_GT(tally.skipped, 0u);
  std::cerr << fmt::format("{} examples, {} skipped starts, {} shared failures\n", tally.cases, tally.skipped, tally.shared_failures);
}

// A hand-derived case: a pillow (two squares sewn along 2 edge by edge) has
// 2 commuting with 0 and 1, so the second square is an L node labelled
// <0,1> of the folding from the first: one attempt, one skipped start.
TEST(InferenceStarts, ThePillowsSecondFaceIsTheFirstReRooted) {
  const Map g = build_surface(Model::gmap(2), {{0, 1, 2, 3}, {3, 2, 1, 0}});
  ASSERT_EQ(g.size(), 16u);
  KappaSpec identity;
  identity.identity = true;
  InferOptions all;
  all.all = true;
  const auto attempts = infer(make_kappa_graph(g, g, identity), {0, 1}, all);
  ASSERT_EQ(attempts.size(), 1u);
  EXPECT_EQ(attempts[0].same_starts.size(), 1u);
  EXPECT_TRUE(attempts[0].does_nothing);
}

}  // namespace
}  // namespace dartcheck::inference::test
