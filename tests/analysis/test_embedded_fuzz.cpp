// The embedding catalog against the dynamic check (no soundness bug; every
// rejected rule confirmed except those whose terms are equal on every map,
// derived by hand in the catalog's notes), and Theorems 2/4 on random
// embedded rules.
#include <algorithm>
#include <fstream>
#include <numeric>
#include <optional>
#include <random>
#include <set>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "checkers/embedding_conditions.hpp"
#include "checkers/embedding_consistency.hpp"
#include "checkers/map_validity.hpp"
#include "checkers/rule_conditions.hpp"
#include "analysis/embedded_fuzz.hpp"
#include "io/catalog.hpp"
#include "rewriting/application.hpp"
#include "core/input_error.hpp"
#include "io/mesh_io.hpp"
#include "core/orbit.hpp"
#include "rewriting/term_eval.hpp"
#include "generators/mesh_map.hpp"
#include "generators/random_embedding.hpp"
#include "generators/random_maps.hpp"
#include "generators/random_rules.hpp"
#include "tests/embedding_support.hpp"

namespace dartcheck {
namespace {

using namespace testing_support;

TEST(EmbeddingCatalog, StaticVerdictsMatchTheRecordedOnes) {
  ASSERT_EQ(embedding_catalog().rules.size(), 33u);
  for (const auto& r : embedding_catalog().rules) {
    ASSERT_TRUE(r.terms) << r.rule.name();
    ASSERT_TRUE(r.expected_failures) << r.rule.name();
    auto want = *r.expected_failures;
    std::sort(want.begin(), want.end());
    EXPECT_EQ(static_failures_of(r), want) << r.rule.name();
  }
}

TEST(EmbeddingCatalog, FuzzConfirmsEveryRejectionExceptEqualTerms) {
  // Rejected rules whose two terms are equal on every map (hand
  // derivations in the catalog's notes): the static conditions are only
  // sufficient, so no map can break them. (triangulation-jerboa-col was
  // one until the check learned that alpha2 commutes with the word-0 loop.)
  const std::set<std::string> equal_terms = {"fig17b-vertex-insertion/two-terms", "fig19b-triangulation-col/equal-terms", "exploded-view/two-nodes"};
  analysis::FuzzOptions o;
  o.seed = 3;
  o.runs = 2000;
  o.max_darts = 64;
  std::size_t confirmed = 0, consistent = 0;
  for (const auto& r : embedding_catalog().rules) {
    const auto report = analysis::fuzz_embedded_rule(r, {}, o);
    ASSERT_NE(report.verdict, analysis::FuzzClass::soundness_bug) << r.rule.name() << ": " << report.counterexample->embedding_failures.front();
    if (static_failures_of(r).empty()) {
      EXPECT_GT(report.applications, 100u) << r.rule.name() << " " << report.reason;
      ++consistent;
    } else if (equal_terms.contains(r.rule.name())) {
      EXPECT_EQ(report.verdict, analysis::FuzzClass::unconfirmed) << r.rule.name();
    } else {
      EXPECT_EQ(report.verdict, analysis::FuzzClass::confirmed) << r.rule.name() << ": " << report.reason;
      ++confirmed;
    }
  }
  EXPECT_EQ(consistent, 15u);
  EXPECT_EQ(confirmed, 15u);
}

// --- Theorems 2 and 4 on random embedded rules ---------------------------

TEST(EmbeddingTheorems, RulesThatPassTheConditionsNeverBreakAMap) {
  // Theorem 2 (direct) and Theorem 4 (extended): a topologically consistent
  // rule whose terms pass A, B (direct), C and label yields an embedded
  // G-map from every embedded G-map. Terms are drawn from a small pool so
  // that both verdicts are frequent.
  std::mt19937 rng(11);
  const Model model = Model::gmap(2);
  const std::vector<EmbeddingSignature> pos = {signatures[0]};
  std::size_t passed = 0, rejected_confirmed = 0, tried = 0;
  analysis::FuzzOptions o;
  o.seed = 5;
  o.runs = 150;
  o.max_darts = 32;
  for (int round = 0; round < 4000 && passed < 60; ++round) {
    Rule topo = random_combinatorial_rule(rng, model, model);
    const auto verdict = check_rule(topo, {});
    if (std::any_of(verdict.conditions.begin(), verdict.conditions.end(), [](const ConditionVerdict& c) { return !c.holds; })) continue;
    RuleTerms terms;
    terms.embeddings = pos;
    terms.instantiation = rng() % 2 ? Instantiation::direct : Instantiation::extended;
    TermScope scope;
    scope.model = &model;
    scope.embeddings = &terms.embeddings;
    scope.variables = topo.left().names();
    const auto& ln = topo.left().names();
    auto pool = [&]() {
      switch (rng() % 3) {
        case 0:
          return fmt::format("point2({}, 0)", rng() % 2);
        case 1:
          return fmt::format("{}.pos", ln[rng() % ln.size()]);
        default:
          return fmt::format("midpoint({}.pos, {}.pos)", ln[rng() % ln.size()], ln[rng() % ln.size()]);
      }
    };
    for (const auto& n : topo.left().names())
      if (rng() % 2) {
        Term t = parse_term(fmt::format("{}.pos", n));
        check_term(t, scope);
        terms.left.push_back({n, "pos", t, "", 0, 0});
      }
    for (const auto& n : topo.right().names())
      if (rng() % 3) {
        Term t = parse_term(pool());
        check_term(t, scope);
        terms.right.push_back({n, "pos", t, "", 0, 0});
      }
    const Operation entry{topo, {}, std::nullopt, {}, {}, terms};
    const bool holds = failing_names(check_term_conditions(topo, {}, terms)).empty();
    const auto report = analysis::fuzz_embedded_rule(entry, {}, o);
    ++tried;
    if (holds) {
      ASSERT_NE(report.verdict, analysis::FuzzClass::soundness_bug) << "round " << round << ": " << report.counterexample->embedding_failures.front();
      passed += report.applications > 0;
    } else {
      rejected_confirmed += report.verdict == analysis::FuzzClass::confirmed;
    }
  }
  EXPECT_GE(passed, 20u) << tried << " rules tried";
  EXPECT_GE(rejected_confirmed, 20u) << "the dynamic check must be able to fail";
}

}  // namespace
}  // namespace dartcheck
