// Theorems 4-6 (002 Sec. 7-9) on real maps. The theorems speak of pattern
// graphs; what a user needs is their consequence on hosts: a rule scheme
// whose conditions I_S, O_S and C_S all hold turns every valid G-map or
// O-map into a valid one, at every hook where it applies (Theorems 4-6 with
// Lemma 3: the pattern graph of a valid map satisfies I_P, O_P and C_P).
//
// The schemes are random mutations of the catalog's consistent schemes
// (drop an arc, add an arc, change a word, change a dimension, retarget an
// arc): close to valid, so both verdicts occur. Each one is applied at
// every dart of random valid maps of its model (up to a few hundred
// darts). Soundness: a scheme judged consistent never yields an invalid
// map nor a refusal for an H that needs two i-arcs at a dart. For schemes
// that fail only the cycle condition the test reports how often a real
// counterexample turns up: Theorem 6 is sufficient, not necessary.
//
// DARTCHECK_SCHEME_MUTANTS (default 1000 per model) sets the count.
#include <cstdlib>
#include <random>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "checkers/map_validity.hpp"
#include "checkers/rule_conditions.hpp"
#include "io/catalog.hpp"
#include "rewriting/application.hpp"
#include "generators/random_maps.hpp"

using namespace dartcheck;

namespace {

struct ArcSpec {
  std::string source, target;
  int dim;
  ConjWord word;
};
struct SchemeSpec {
  std::vector<std::string> left_nodes, right_nodes;
  std::vector<ArcSpec> left, right;
  std::vector<std::string> hooks;
};

SchemeSpec spec_of(const CatalogRule& r) {
  SchemeSpec s;
  auto side = [](const TopoGraph& g, const std::vector<ConjWord>& w, std::vector<std::string>& nodes, std::vector<ArcSpec>& arcs) {
    nodes = g.names();
    for (ArcId e = 0; e < g.arc_count(); ++e) arcs.push_back({g.name(g.arc(e).source), g.name(g.arc(e).target), g.arc(e).label, w[e]});
  };
  side(r.rule.left(), r.words.left, s.left_nodes, s.left);
  side(r.rule.right(), r.words.right, s.right_nodes, s.right);
  for (NodeId h : r.rule.hooks()) s.hooks.push_back(r.rule.left().name(h));
  return s;
}

// The scheme of a spec, or nullopt if the Rule constructor rejects it (a
// mutation that disconnected L from its hook).
std::optional<std::pair<Rule, ArcWords>> build(const SchemeSpec& s, const Model& model) {
  ArcWords words;
  words.scheme = true;
  auto side = [&](const std::vector<std::string>& nodes, const std::vector<ArcSpec>& arcs, std::vector<ConjWord>& w) {
    TopoGraph g;
    for (const auto& n : nodes) g.add_node(n);
    for (const auto& a : arcs) {
      g.add_arc(*g.find(a.source), *g.find(a.target), a.dim);
      w.push_back(a.word);
    }
    return g;
  };
  TopoGraph l = side(s.left_nodes, s.left, words.left), r = side(s.right_nodes, s.right, words.right);
  try {
    return std::pair{Rule("mutant", model, std::move(l), std::move(r), s.hooks, words.left, words.right), words};
  } catch (const ValueError&) {
    return std::nullopt;
  }
}

// One random mutation; mostly on R, which is where operations go wrong.
void mutate(SchemeSpec& s, const Model& model, const std::vector<ConjWord>& pool, std::mt19937& rng) {
  auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  const bool on_left = pick(5) == 0 && !s.left.empty();
  auto& arcs = on_left ? s.left : s.right;
  auto& nodes = on_left ? s.left_nodes : s.right_nodes;
  const int dim = model.dims[pick(model.dims.size())];
  switch (pick(5)) {
    case 0:
      if (!arcs.empty()) arcs.erase(arcs.begin() + static_cast<long>(pick(arcs.size())));
      break;
    case 1:
      arcs.push_back({nodes[pick(nodes.size())], nodes[pick(nodes.size())], dim, pool[pick(pool.size())]});
      break;
    case 2:
      if (!arcs.empty()) arcs[pick(arcs.size())].word = pool[pick(pool.size())];
      break;
    case 3:
      if (!arcs.empty()) arcs[pick(arcs.size())].dim = dim;
      break;
    default:
      if (!arcs.empty()) arcs[pick(arcs.size())].target = nodes[pick(nodes.size())];
  }
}

// A random valid map of the model from a recipe drawn with `rng`.
Map random_host(const Model& model, std::mt19937& rng) {
  return build_random_map(model, draw_recipe(rng, std::uniform_int_distribution<std::uint32_t>(2, 24)(rng), model.dimension()));
}

struct Tally {
  std::size_t mutants = 0, rejected = 0, consistent = 0, applications = 0, unsound = 0;
  std::size_t cycle_only = 0, cycle_only_broken = 0, other_failing = 0, other_failing_broken = 0;
};

std::size_t mutant_count() {
  if (const char* v = std::getenv("DARTCHECK_SCHEME_MUTANTS")) return static_cast<std::size_t>(std::strtoull(v, nullptr, 10));
  return 1000;
}

Tally run_model(const std::string& model_name, const std::vector<std::string>& bases, std::uint32_t seed) {
  static const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  std::mt19937 rng(seed);
  Tally t;
  const Model model = *Model::by_name(model_name);
  std::vector<Map> hosts;
  for (int k = 0; k < 6; ++k) hosts.push_back(random_host(model, rng));
  for (std::size_t m = 0; m < mutant_count(); ++m) {
    const CatalogRule& base = *catalog.find_rule(bases[m % bases.size()]);
    SchemeSpec spec = spec_of(base);
    // The pool of words: those of the scheme, ε and every single letter.
    std::vector<ConjWord> pool{ConjWord{}};
    for (const auto& a : spec.right) pool.push_back(a.word);
    for (Dim d : model.dims) pool.push_back(ConjWord::of_dims({d}));
    const int steps = 1 + static_cast<int>(rng() % 2);
    for (int k = 0; k < steps; ++k) mutate(spec, model, pool, rng);
    ++t.mutants;
    auto scheme = build(spec, model);
    if (!scheme) {
      ++t.rejected;
      continue;
    }
    const auto& [rule, words] = *scheme;
    const RuleVerdict verdict = check_rule(rule, words);
    bool cycle_fails = false, other_fails = false;
    for (const auto& c : verdict.conditions)
      if (!c.holds) (c.condition == RuleCondition::cycle ? cycle_fails : other_fails) = true;
    bool broken = false;
    const Operation op{rule, words, {}, {}, {}, {}};
    Applier applier(op);
    for (const Map& host : hosts) {
      for (Dart hook = 0; hook < host.size(); hook += 1 + static_cast<Dart>(host.size() / 24)) {
        Map h = host;
        const auto out = applier.apply(h, std::span(&hook, 1));
        if (out.refusal == Refusal::not_representable) {
          broken = true;
          if (verdict.consistent()) ++t.unsound;
          continue;
        }
        if (!out.ok()) continue;
        ++t.applications;
        if (!check_map(h).valid()) {
          broken = true;
          if (verdict.consistent()) {
            ++t.unsound;
            ADD_FAILURE() << "a consistent mutant of " << base.rule.name() << " produced an invalid " << model_name << " at dart " << hook;
          }
        }
      }
    }
    if (verdict.consistent()) {
      ++t.consistent;
    } else if (cycle_fails && !other_fails) {
      ++t.cycle_only;
      t.cycle_only_broken += broken;
    } else {
      ++t.other_failing;
      t.other_failing_broken += broken;
    }
  }
  fmt::print(
      "{}: {} mutants ({} rejected by the Rule constructor), {} consistent ({} applications in all), "
      "{} fail only C: {} broke a host; {} fail I/dangling/O: {} broke a host; unsound: {}\n",
      model_name, t.mutants, t.rejected, t.consistent, t.applications, t.cycle_only, t.cycle_only_broken, t.other_failing, t.other_failing_broken,
      t.unsound);
  return t;
}

void expect_sound(const Tally& t) {
  EXPECT_EQ(t.unsound, 0u);
  // The mutants must exercise both sides, or the test proves nothing.
  EXPECT_GT(t.consistent, t.mutants / 20);
  EXPECT_GT(t.applications, 0u);
}

}  // namespace

TEST(SchemeTheorems, ConsistentSchemesPreserve2Gmaps) {
  expect_sound(run_model("2-gmap", {"quad-subdivision-gmap", "cone-extrusion-gmap", "edge-rounding-gmap", "insert-vertex-jerboa"}, 11));
}
TEST(SchemeTheorems, ConsistentSchemesPreserve2Omaps) {
  expect_sound(run_model("2-omap", {"quad-subdivision-omap", "cone-extrusion-omap", "edge-rounding-omap"}, 12));
}
TEST(SchemeTheorems, ConsistentSchemesPreserve3Gmaps) { expect_sound(run_model("3-gmap", {"face-extrusion-gmap"}, 13)); }
TEST(SchemeTheorems, ConsistentSchemesPreserve3Omaps) { expect_sound(run_model("3-omap", {"face-extrusion-omap"}, 14)); }
