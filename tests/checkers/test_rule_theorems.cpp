// 002 Theorems 1-3 are "if and only if": the static condition holds exactly
// when every derivation on every host of the theorem's class preserves the
// constraint. This test draws random small DPO rules and compares the
// static verdict with a brute-force semantic answer: every host of the
// class on the nodes of L plus up to `extra` more nodes, every match (by
// symmetry, the identity on L's nodes), derive, check the constraint on H.
//
// A rule whose L matches no host of the class is vacuously preserving; the
// theorems do not speak of such rules, so they are counted apart and not
// compared. Set DARTCHECK_BRUTE_RULES to raise the number of rules.
#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <numeric>
#include <random>

#include <fmt/format.h>

#include "checkers/graph_constraints.hpp"
#include "checkers/host_search.hpp"
#include "checkers/rule_conditions.hpp"
#include "rewriting/graph_derivation.hpp"
#include "generators/random_rules.hpp"

using namespace dartcheck;

namespace {

int rule_count() {
  const char* env = std::getenv("DARTCHECK_BRUTE_RULES");
  return env ? std::atoi(env) : 5000;
}

// D = {0, 1}; the theorems are stated for one dimension i = 0 (resp. the
// pair (0, 1)), and the other label makes matching and dangling non-trivial.
Model two_dims() {
  Model m;
  m.name = "D={0,1}";
  m.dims = {0, 1};
  m.non_oriented = dim_bit(0) | dim_bit(1);
  m.exchangeable = {{0, 1}};
  return m;
}

enum class Host { incident_0, combinatorial_o0, combinatorial_c01 };

// The host class of each theorem as a model: D-combinatorial graphs with
// O on N and C on E.
Model class_model(Host h) {
  Model m = two_dims();
  m.non_oriented = h == Host::combinatorial_o0 ? dim_bit(0) : 0;
  if (h != Host::combinatorial_c01) m.exchangeable.clear();
  return m;
}

bool in_class(Host h, const Perms& s) { return perms_in_model(class_model(h), s); }

// Every permutation of n nodes extending the partial map `fixed` (no_node
// = free), by backtracking.
void extensions(std::size_t n, const std::vector<NodeId>& fixed, const std::function<void(const std::vector<NodeId>&)>& f) {
  std::vector<NodeId> p(fixed);
  p.resize(n, no_node);
  std::vector<bool> used(n, false);
  for (NodeId v = 0; v < fixed.size(); ++v)
    if (fixed[v] != no_node) used[fixed[v]] = true;
  std::function<void(NodeId)> go = [&](NodeId v) {
    if (v == n) return f(p);
    if (v < fixed.size() && fixed[v] != no_node) return go(v + 1);
    for (NodeId w = 0; w < n; ++w) {
      if (used[w]) continue;
      used[w] = true;
      p[v] = w;
      go(v + 1);
      used[w] = false;
      p[v] = no_node;
    }
  };
  go(0);
}

struct Semantic {
  bool matched = false;   // some host of the class, some match satisfying dangling
  bool violated = false;  // some derived H breaks the constraint
  std::string counterexample;
};

bool constraint_holds(Host h, const TopoGraph& H) {
  std::vector<Violation> v;
  for (NodeId x = 0; x < H.node_count(); ++x) {
    switch (h) {
      case Host::incident_0:
        check_incidence(H, x, 0, false, v);
        if (!v.empty()) return false;
        break;
      case Host::combinatorial_o0:
        if (!non_oriented_at(H, x, 0)) return false;
        break;
      case Host::combinatorial_c01:
        if (!cycle_at(H, x, 0, 1)) return false;
        break;
    }
  }
  return true;
}

std::string graph_text(const TopoGraph& g) {
  std::string s;
  for (const auto& a : g.arcs()) s += fmt::format("{}-{}->{} ", g.name(a.source), a.label, g.name(a.target));
  return s;
}

Semantic brute_force(const Rule& rule, Host h, std::size_t extra) {
  Semantic out;
  const TopoGraph& L = rule.left();
  const std::size_t nl = L.node_count();
  // L's arcs of a label must form a partial injection, or no host with
  // unique arcs per label contains an injective image of them.
  Perms fixed{std::vector<NodeId>(nl, no_node), std::vector<NodeId>(nl, no_node)};
  const bool free_label1 = h == Host::incident_0;  // Theorem 1: hosts are any D-graphs satisfying I(0)
  for (const auto& a : L.arcs()) {
    if (free_label1 && a.label == 1) continue;
    auto& f = fixed[static_cast<std::size_t>(a.label)];
    if (f[a.source] != no_node) return out;
    for (NodeId v = 0; v < nl; ++v)
      if (f[v] == a.target) return out;
    f[a.source] = a.target;
  }
  for (std::size_t n = nl; n <= nl + extra; ++n) {
    auto try_host = [&](const Perms& s) {
      if (!in_class(h, s)) return;
      TopoGraph G;
      for (NodeId v = 0; v < n; ++v) G.add_node(v < nl ? L.name(v) : fmt::format("x{}", v));
      GraphMatch m{std::vector<NodeId>(nl), std::vector<ArcId>(L.arc_count())};
      std::iota(m.node.begin(), m.node.end(), 0);
      for (NodeId v = 0; v < n; ++v) G.add_arc(v, s[0][v], 0);  // arc v is v's 0-arc
      if (free_label1) {
        // Minimal hosts suffice for Theorem 1: extra 1-arcs leave I(0)
        // alone and can only break the dangling condition.
        for (ArcId e = 0; e < L.arc_count(); ++e)
          if (L.arc(e).label == 1) m.arc[e] = G.add_arc(L.arc(e).source, L.arc(e).target, 1);
      } else {
        for (NodeId v = 0; v < n; ++v) G.add_arc(v, s[1][v], 1);  // arc n + v is v's 1-arc
      }
      for (ArcId e = 0; e < L.arc_count(); ++e) {
        const auto& a = L.arc(e);
        if (a.label == 0)
          m.arc[e] = a.source;
        else if (!free_label1)
          m.arc[e] = static_cast<ArcId>(n + a.source);
      }
      if (!satisfies_dangling(rule, G, m)) return;
      out.matched = true;
      if (out.violated) return;
      const TopoGraph H = derive(rule, G, m);
      if (!constraint_holds(h, H)) {
        out.violated = true;
        out.counterexample = fmt::format("G: {}\nH: {}", graph_text(G), graph_text(H));
      }
    };
    auto fix = [&](std::size_t d) {
      std::vector<NodeId> f = fixed[d];
      f.resize(n, no_node);
      return f;
    };
    extensions(n, fix(0), [&](const std::vector<NodeId>& s0) {
      if (free_label1) return try_host(Perms{s0, s0});
      extensions(n, fix(1), [&](const std::vector<NodeId>& s1) { try_host(Perms{s0, s1}); });
    });
    if (out.violated) break;
  }
  return out;
}

// Theorems 2 and 3: the library's exhaustive host search over the class,
// counting only violations of the theorem's constraint.
Semantic search_semantic(const Rule& rule, Host h, std::size_t extra) {
  const Constraint c = h == Host::combinatorial_o0 ? Constraint::non_orientation : Constraint::cycle;
  const HostSearch hs = search_hosts(rule, class_model(h), extra, [c](const Violation& v) { return v.constraint == c; });
  Semantic out{hs.matched, hs.host.has_value(), ""};
  if (hs.host) out.counterexample = fmt::format("G: {}\nH: {}", graph_text(*hs.host), graph_text(*hs.result));
  return out;
}

bool combinatorial(const Rule& r) {
  for (Dim d : r.model().dims)
    if (!check_incident_arcs(r, d).holds || !check_dangling(r, d).holds) return false;
  return true;
}

struct Tally {
  int compared = 0, vacuous = 0, consistent = 0, disagreements = 0;
};

Tally agreement(Host h, std::uint32_t seed, std::size_t extra, const std::function<ConditionVerdict(const Rule&)>& check, bool need_combinatorial) {
  std::mt19937 rng(seed);
  const Model model = two_dims();
  Tally t;
  for (int attempts = 0; t.compared < rule_count() && attempts < 50 * rule_count(); ++attempts) {
    const Rule rule = need_combinatorial && attempts % 4 != 0
                          ? random_combinatorial_rule(rng, class_model(h), model)
                          : random_rule(rng, class_model(h == Host::incident_0 ? Host::combinatorial_o0 : h), model, h == Host::incident_0);
    if (need_combinatorial && !combinatorial(rule)) continue;
    const Semantic sem = h == Host::incident_0 ? brute_force(rule, h, extra) : search_semantic(rule, h, extra);
    if (!sem.matched) {
      ++t.vacuous;
      continue;
    }
    ++t.compared;
    const ConditionVerdict v = check(rule);
    t.consistent += v.holds;
    if (v.holds == sem.violated) {
      ++t.disagreements;
      ADD_FAILURE() << "static " << (v.holds ? "holds" : "fails") << ", brute force " << (sem.violated ? "violated" : "preserved")
                    << "\nL: " << graph_text(rule.left()) << "\nR: " << graph_text(rule.right()) << "\n"
                    << sem.counterexample << (v.witnesses.empty() ? "" : "\nwitness: " + v.witnesses[0].text);
      if (t.disagreements > 5) break;
    }
  }
  std::cout << fmt::format("{} rules compared ({} consistent), {} vacuous skipped, hosts up to |V_L| + {} nodes, {} disagreements\n", t.compared,
                           t.consistent, t.vacuous, extra, t.disagreements);
  return t;
}

}  // namespace

// Theorem 1: I_r(0)-weak iff every derivation on a D-graph satisfying I(0)
// yields H satisfying I(0).
TEST(Theorem1, WeakIncidentArcsIffPreservation) {
  const Tally t = agreement(
      Host::incident_0, 1, 2, [](const Rule& r) { return check_incident_arcs(r, 0); }, false);
  EXPECT_EQ(t.disagreements, 0);
  EXPECT_EQ(t.compared, rule_count());
}

// Theorem 2: for D-combinatorial rules, O_r(0) iff every derivation on a
// D-combinatorial graph satisfying O(0) yields H satisfying O(0).
TEST(Theorem2, NonOrientationIffPreservation) {
  const Tally t = agreement(
      Host::combinatorial_o0, 2, 3, [](const Rule& r) { return check_non_orientation(r, 0); }, true);
  EXPECT_EQ(t.disagreements, 0);
  EXPECT_EQ(t.compared, rule_count());
}

// Theorem 3: for D-combinatorial rules, C_r(0,1) iff every derivation on a
// D-combinatorial graph satisfying C(0,1) yields H satisfying C(0,1).
TEST(Theorem3, CycleConditionIffPreservation) {
  const Tally t = agreement(
      Host::combinatorial_c01, 3, 3, [](const Rule& r) { return check_cycle(r, 0, 1); }, true);
  EXPECT_EQ(t.disagreements, 0);
  EXPECT_EQ(t.compared, rule_count());
}

namespace {
struct ModelTally {
  int compared = 0, consistent = 0, unsound = 0, confirmed = 0, gap = 0, vacuous = 0;
};

// The question users ask: rules of a model against hosts that are maps of
// the model. Soundness (Theorems 1-3 together, 002 Sec. 10.1): a rule
// whose every condition holds never yields an invalid map. The converse
// fails per constraint: a rule may break C(0,2) per Theorem 3 and still
// preserve every G-map, because hosts that are G-maps are a smaller class.
ModelTally model_level(const Model& model, std::uint32_t seed, std::size_t extra) {
  std::mt19937 rng(seed);
  ModelTally t;
  for (int attempts = 0; t.compared < rule_count() && attempts < 50 * rule_count(); ++attempts) {
    const Rule rule = attempts % 4 != 0 ? random_combinatorial_rule(rng, model, model) : random_rule_for(rng, model);
    const HostSearch hs = search_hosts(rule, model, extra);
    if (!hs.matched) {
      ++t.vacuous;
      continue;
    }
    ++t.compared;
    const RuleVerdict v = check_rule(rule);
    const bool ok = v.consistent();
    t.consistent += ok;
    if (ok && hs.host) {
      ++t.unsound;
      ADD_FAILURE() << "SOUNDNESS: all conditions hold but a " << model.name << " host breaks\nL: " << graph_text(rule.left())
                    << "\nR: " << graph_text(rule.right()) << "\nG: " << graph_text(*hs.host) << "\nH: " << graph_text(*hs.result);
    }
    if (!ok) (hs.host ? t.confirmed : t.gap) += 1;
  }
  std::cout << fmt::format(
      "{}: {} rules ({} consistent, {} inconsistent and confirmed on a map, {} inconsistent with no model-level "
      "counterexample), {} vacuous skipped, hosts up to |V_L| + {} darts, {} soundness exceptions\n",
      model.name, t.compared, t.consistent, t.confirmed, t.gap, t.vacuous, extra, t.unsound);
  return t;
}
}  // namespace

TEST(ModelLevel, ConsistentRulesPreserve2Gmaps) {
  const ModelTally t = model_level(Model::gmap(2), 4, 3);
  EXPECT_EQ(t.unsound, 0);
  EXPECT_EQ(t.compared, rule_count());
}

TEST(ModelLevel, ConsistentRulesPreserve2Omaps) {
  const ModelTally t = model_level(Model::omap(2), 5, 3);
  EXPECT_EQ(t.unsound, 0);
  EXPECT_EQ(t.compared, rule_count());
}
