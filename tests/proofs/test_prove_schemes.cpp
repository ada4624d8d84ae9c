// dartcheck prove on rule schemes whose L is one hook node with loops
// (002 Sec. 10), against independent answers: the seed catalog's
// hand-derived verdicts, the dynamic checker (apply_scheme + check_map)
// on every map counterexample, and an exhaustive enumeration of small
// maps whose derived graphs are built here directly from the product of
// Def. 19, not by the library's scheme application.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include <fmt/format.h>

#include "checkers/graph_constraints.hpp"
#include "checkers/host_search.hpp"
#include "analysis/fuzz.hpp"
#include "io/catalog.hpp"
#include "proofs/rule_prover.hpp"
#include "proofs/detail/scheme_encoding.hpp"

using namespace dartcheck;
using namespace dartcheck::proofs;

namespace {

const Catalog& seed_catalog() {
  static const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  return c;
}

std::vector<const CatalogRule*> schemes_in_scope() {
  std::vector<const CatalogRule*> out;
  for (const auto& e : seed_catalog().rules)
    if (e.words.scheme && scheme_out_of_scope(e.rule).empty()) out.push_back(&e);
  return out;
}

// The constraints that the derived graph of the scheme at hook dart 0 of
// g breaks, from 002 Def. 19-20 read directly: P_v is the closure of the
// hook under the words and their conjugates, ι(L, P_v) must match (each
// loop (w,d) of L is the d-arc p -> p·w), be connected by L's words, and
// satisfy the dangling condition; H is g without the instances of L \ K
// plus those of R \ K. nullopt when the scheme does not apply.
std::optional<std::set<std::string>> broken_by_product(const CatalogRule& entry, const Map& g) {
  const Rule& s = entry.rule;
  const TopoGraph &L = s.left(), &R = s.right();
  const ConjugateRewriting rw(s.model());
  std::vector<ConjWord> gens, l_gens;
  for (const auto* ws : {&entry.words.left, &entry.words.right})
    for (const auto& w : *ws)
      for (const ConjWord& x : {w, rw.conjugate(w)}) {
        if (x.empty()) continue;
        if (std::find(gens.begin(), gens.end(), x) == gens.end()) gens.push_back(x);
        if (ws == &entry.words.left && std::find(l_gens.begin(), l_gens.end(), x) == l_gens.end()) l_gens.push_back(x);
      }
  auto closure = [&](const std::vector<ConjWord>& by) -> std::optional<std::vector<Dart>> {
    std::vector<Dart> p{0};
    for (std::size_t k = 0; k < p.size(); ++k)
      for (const auto& w : by) {
        const Dart t = follow(g, p[k], w);
        if (t == no_dart) return std::nullopt;
        if (std::find(p.begin(), p.end(), t) == p.end()) p.push_back(t);
      }
    return p;
  };
  const auto pattern = closure(gens);
  if (!pattern) return std::nullopt;
  const std::vector<Dart>& P = *pattern;
  const auto connected = closure(l_gens);
  if (!connected || connected->size() != P.size()) return std::nullopt;
  auto in_p = [&](Dart d) { return std::find(P.begin(), P.end(), d) != P.end(); };
  for (ArcId e = 0; e < L.arc_count(); ++e) {
    for (ArcId f = e + 1; f < L.arc_count(); ++f)
      if (L.arc(f).label == L.arc(e).label) return std::nullopt;  // two instances on one arc
    for (Dart p : P)
      if (g.link(L.arc(e).label, p) != follow(g, p, arc_word(entry.words.left, e))) return std::nullopt;
  }
  const bool kept = s.to_right(0) != no_node;
  if (!kept)
    for (Dim d : s.model().dims)
      if (L.out_arcs(0, d).empty())
        for (Dart x = 0; x < g.size(); ++x)
          if ((in_p(x) && g.link(d, x) != no_dart) || (g.link(d, x) != no_dart && in_p(g.link(d, x)))) return std::nullopt;

  TopoGraph h;
  std::map<std::pair<NodeId, Dart>, NodeId> node;  // (R node or no_node for the host, dart) -> node of H
  for (Dart x = 0; x < g.size(); ++x)
    if (kept || !in_p(x)) node[{no_node, x}] = h.add_node(fmt::format("{}", x));
  for (NodeId y = 0; y < R.node_count(); ++y)
    if (s.to_left(y) == no_node)
      for (Dart p : P) node[{y, p}] = h.add_node(fmt::format("{}@{}", R.name(y), p));
  auto at = [&](NodeId y, Dart p) { return s.to_left(y) == no_node ? node.at({y, p}) : node.at({no_node, p}); };
  for (Dim d : s.model().dims) {
    bool deleted = false;
    for (ArcId e = 0; e < L.arc_count(); ++e) deleted |= L.arc(e).label == d && !s.preserved_left_arc(e);
    for (Dart x = 0; x < g.size(); ++x)
      if ((kept || !in_p(x)) && g.link(d, x) != no_dart && !(deleted && in_p(x)))
        h.add_arc(node.at({no_node, x}), node.at({no_node, g.link(d, x)}), d);
  }
  for (ArcId e = 0; e < R.arc_count(); ++e) {
    if (s.preserved_right_arc(e)) continue;
    const auto& a = R.arc(e);
    for (Dart p : P) h.add_arc(at(a.source, p), at(a.target, follow(g, p, arc_word(entry.words.right, e))), a.label);
  }
  std::set<std::string> broken;
  for (const auto& v : check_graph(h, s.model()).violations) broken.insert(constraint_name(v));
  return broken;
}

}  // namespace

// The seed catalog at 6 darts: no answer contradicts the static checker;
// a scheme recorded as consistent has no counterexample among the maps;
// every map counterexample replays (derive() on the instantiated rule)
// and apply_scheme + check_map confirm it; a scheme recorded as failing
// I or C gets a map counterexample for a recorded failure. (Recorded
// O-only failures may have none: Theorem 5's pattern graphs are not the
// P_v of maps, fig21-scheme in the catalog.) Schemes out of scope are
// exactly those whose L has several nodes.
TEST(ProveSchemes, SeedCatalogAgreesWithHandVerdictsUpTo6Darts) {
  ProveOptions o;
  o.max_darts = 6;
  int in_scope = 0;
  for (const auto& e : seed_catalog().rules) {
    if (!e.words.scheme) continue;
    const RuleProof p = prove_rule(e, o);
    EXPECT_EQ(p.out_of_scope.empty(), e.rule.left().node_count() == 1) << e.rule.name();
    if (!p.out_of_scope.empty()) continue;
    ++in_scope;
    ASSERT_TRUE(e.expected_failures.has_value()) << e.rule.name();
    const auto& expected = *e.expected_failures;
    EXPECT_EQ(p.count(Agreement::disagree), 0U) << e.rule.name();
    bool confirmed = false, confirmable = false;
    for (const auto& f : expected) confirmable = confirmable || !f.starts_with("O(");
    for (const auto& c : p.constraints) {
      const bool recorded = std::find(expected.begin(), expected.end(), c.constraint.name()) != expected.end();
      if (expected.empty()) {
        EXPECT_EQ(c.model.status, Status::none) << e.rule.name() << " " << c.constraint.name();
      }
      if (c.model.status != Status::counterexample) continue;
      EXPECT_TRUE(c.model.replayed) << e.rule.name() << " " << c.constraint.name() << ": " << c.model.replay_failure;
      const Map host = host_map(e.rule.model(), *c.model.host);
      Map scratch(e.rule.model());
      Refusal refusal = Refusal::none;
      const Dart hook = 0;
      EXPECT_TRUE(analysis::apply_and_check(e, host, std::span(&hook, 1), scratch, refusal).has_value())
          << e.rule.name() << " " << c.constraint.name();
      confirmed = confirmed || recorded;
    }
    if (confirmable) {
      EXPECT_TRUE(confirmed) << e.rule.name() << ": no map counterexample for a recorded failure";
    }
  }
  EXPECT_GE(in_scope, 25);
}

// For every in-scope seed scheme and constraint: the solver's minimal
// counterexample size up to 4 darts equals the smallest map, over all
// maps of the model on 1..4 darts (hook at dart 0: the enumeration holds
// every labelling), whose directly built H breaks the constraint; and
// "none" exactly when no such map exists.
TEST(ProveSchemes, MinimalCounterexamplesMatchExhaustiveEnumeration) {
  constexpr std::size_t k = 4;
  ProveOptions o;
  o.max_darts = k;
  int compared = 0, counterexamples = 0;
  for (const CatalogRule* e : schemes_in_scope()) {
    const Model& model = e->rule.model();
    if (model.partial) continue;  // the enumeration builds closed maps only
    std::map<std::string, std::size_t> smallest;
    for (std::size_t n = 1; n <= k; ++n) {
      const std::size_t visited = for_each_small_map(model, n, [&](const std::vector<std::vector<NodeId>>& sigma) {
        Map g(model, n);
        for (std::size_t d = 0; d < model.dims.size(); ++d)
          for (Dart x = 0; x < n; ++x) g.set_link(model.dims[d], x, sigma[d][x]);
        const auto broken = broken_by_product(*e, g);
        if (!broken) return true;
        // O and C queries ask among the H satisfying I on the dimensions
        // they read.
        auto i_holds = [&](Dim d) { return d < 0 || !broken->contains(condition_name(RuleCondition::incident_arcs, d)); };
        for (const HConstraint& c : model_constraints(model)) {
          const bool premise = c.kind == RuleCondition::incident_arcs || c.kind == RuleCondition::no_loop || (i_holds(c.i) && i_holds(c.j));
          if (premise && broken->contains(c.name())) smallest.emplace(c.name(), n);
        }
        return true;
      });
      ASSERT_LT(visited, 2'000'000U) << "the enumeration was cut short";
    }
    const RuleProof p = prove_rule(*e, o);
    for (const auto& c : p.constraints) {
      ++compared;
      const auto it = smallest.find(c.constraint.name());
      if (it == smallest.end()) {
        EXPECT_EQ(c.model.status, Status::none) << e->rule.name() << " " << c.constraint.name() << ": no map up to " << k << " darts breaks it";
        continue;
      }
      ++counterexamples;
      EXPECT_EQ(c.model.status, Status::counterexample) << e->rule.name() << " " << c.constraint.name();
      EXPECT_EQ(c.model.darts, it->second) << e->rule.name() << " " << c.constraint.name();
      EXPECT_TRUE(c.model.minimal) << e->rule.name() << " " << c.constraint.name();
    }
  }
  EXPECT_GE(compared, 100);
  EXPECT_GE(counterexamples, 10);
}
