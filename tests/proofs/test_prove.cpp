// dartcheck prove against independent answers: the catalog's hand-derived
// verdicts, the static checker on random rules (002 Theorems 1-3 are
// "iff"), the library's own derivations (every solver counterexample is
// replayed by derive() and, on maps, by apply_rule + check_map), and a
// planted encoding fault that must not go unnoticed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include <fmt/format.h>

#include "checkers/host_search.hpp"
#include "analysis/fuzz.hpp"
#include "io/catalog.hpp"
#include "generators/random_rules.hpp"
#include "checkers/map_validity.hpp"
#include "proofs/rule_prover.hpp"
#include "proofs/word_congruence.hpp"

using namespace dartcheck;
using namespace dartcheck::proofs;

namespace {

int random_rule_count() {
  const char* env = std::getenv("DARTCHECK_PROVE_RULES");
  return env ? std::atoi(env) : 500;
}

const Catalog& seed_catalog() {
  static const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  return c;
}

// The dynamic checker's opinion on a map counterexample of the solver.
bool dynamic_failure(const Operation& entry, const ClassAnswer& a) {
  const Map host = host_map(entry.rule.model(), *a.host);
  std::vector<Dart> hooks(entry.rule.hooks().begin(), entry.rule.hooks().end());
  Map scratch(entry.rule.model());
  Refusal refusal = Refusal::none;
  return analysis::apply_and_check(entry, host, hooks, scratch, refusal).has_value();
}

std::string text(const TopoGraph& g) {
  std::string s;
  for (const auto& a : g.arcs()) s += fmt::format("{}-{}->{} ", g.name(a.source), a.label, g.name(a.target));
  return s;
}

}  // namespace

// On the seed catalog, at 8 darts: the solver agrees with every verdict
// recorded by hand; a rule recorded as consistent has no counterexample
// in either class; a rule recorded as failing has a counterexample on a
// map of its model for some recorded condition, which apply_rule plus
// check_map confirm, unless it fails a dangling condition (Fact 1: then
// no valid map admits a derivation at all, which the solver must find).
TEST(ProveSeedCatalog, AgreesWithHandVerdictsUpTo8Darts) {
  ProveOptions o;
  o.max_darts = 8;
  int dpo = 0;
  for (const auto& e : seed_catalog().rules) {
    if (e.words.scheme) continue;
    ++dpo;
    ASSERT_TRUE(e.expected_failures.has_value()) << e.rule.name();
    const RuleProof p = prove_rule(e, o);
    EXPECT_TRUE(p.out_of_scope.empty());
    EXPECT_EQ(p.count(Agreement::disagree), 0U) << e.rule.name();
    const auto& expected = *e.expected_failures;
    bool confirmed = false, dangling = false;
    for (const auto& f : expected) dangling = dangling || f.starts_with("dangling");
    for (const auto& c : p.constraints) {
      const bool recorded = std::find(expected.begin(), expected.end(), c.constraint.name()) != expected.end();
      if (expected.empty()) {
        EXPECT_EQ(c.model.status, Status::none) << e.rule.name() << " " << c.constraint.name();
        if (c.theorem) {
          EXPECT_EQ(c.theorem->status, Status::none) << e.rule.name() << " " << c.constraint.name();
        }
      }
      for (const ClassAnswer* a : {&c.model, c.theorem ? &*c.theorem : nullptr})
        if (a && a->status == Status::counterexample) {
          EXPECT_TRUE(a->replayed) << e.rule.name() << " " << c.constraint.name() << ": " << a->replay_failure;
        }
      if (c.model.status == Status::counterexample) {
        EXPECT_TRUE(dynamic_failure(e, c.model)) << e.rule.name() << " " << c.constraint.name();
        confirmed = confirmed || recorded;
      }
    }
    if (!expected.empty() && !dangling) {
      EXPECT_TRUE(confirmed) << e.rule.name() << ": no map counterexample for a recorded failure";
    }
    if (dangling) {
      for (const auto& c : p.constraints) EXPECT_EQ(c.model.status, Status::vacuous) << e.rule.name();
    }
  }
  EXPECT_GE(dpo, 30);
}

namespace {

struct Tally {
  int rules = 0, compared = 0, counterexamples = 0, disagreements = 0, unresolved = 0;
};

Tally random_agreement(const Model& model, std::uint32_t seed, int count, const ProveOptions& o, bool report) {
  std::mt19937 rng(seed);
  Tally t;
  for (int k = 0; k < count; ++k) {
    const Rule rule = k % 3 != 2 ? random_combinatorial_rule(rng, model, model) : random_rule(rng, model, model);
    Operation entry{rule, {}, std::nullopt, {}, {}, std::nullopt};
    const RuleProof p = prove_rule(entry, o);
    ++t.rules;
    for (const auto& c : p.constraints) {
      t.compared += c.agreement == Agreement::agree || c.agreement == Agreement::disagree;
      t.unresolved += c.agreement == Agreement::unresolved;
      if (c.model.status == Status::counterexample) {
        ++t.counterexamples;
        if (!dynamic_failure(entry, c.model)) {
          ++t.disagreements;
          if (report) ADD_FAILURE() << "map counterexample not confirmed by apply_rule + check_map: " << c.constraint.name();
        }
      }
      if (c.agreement == Agreement::disagree) {
        ++t.disagreements;
        if (report && t.disagreements <= 5)
          ADD_FAILURE() << c.constraint.name() << ": " << c.note << "\nL: " << text(rule.left()) << "\nR: " << text(rule.right())
                        << (c.theorem && c.theorem->host ? "\nG: " + text(c.theorem->host_graph) + "\nH: " + text(c.theorem->result_graph) : "");
      }
    }
  }
  std::cout << fmt::format(
      "{}: {} random rules, {} constraint answers compared with the static checker, {} map counterexamples, "
      "{} unresolved, {} disagreements (hosts up to {} darts)\n",
      model.name, t.rules, t.compared, t.counterexamples, t.unresolved, t.disagreements, o.max_darts);
  return t;
}

}  // namespace

// Theorems 1-3 are "if and only if": on random small DPO rules the
// solver's answer over each theorem's host class equals the static
// condition (where the theorem's premise holds), and every counterexample
// replays through derive() and, on maps, through apply_rule + check_map.
TEST(ProveRandomRules, SolverAgreesWithStaticChecker2Gmap) {
  ProveOptions o;
  o.max_darts = 7;
  const Tally t = random_agreement(Model::gmap(2), 11, random_rule_count() / 2, o, true);
  EXPECT_EQ(t.disagreements, 0);
  EXPECT_GT(t.compared, random_rule_count());
  EXPECT_GT(t.counterexamples, 20);
}

TEST(ProveRandomRules, SolverAgreesWithStaticChecker2Omap) {
  ProveOptions o;
  o.max_darts = 7;
  const Tally t = random_agreement(Model::omap(2), 12, random_rule_count() - random_rule_count() / 2, o, true);
  EXPECT_EQ(t.disagreements, 0);
  EXPECT_GT(t.compared, random_rule_count());
  EXPECT_GT(t.counterexamples, 20);
}

// A planted bug: the encoding without the dangling condition lets the
// solver delete darts that keep outside arcs. The cross-checks must catch
// it (a counterexample that does not replay, or a verdict that contradicts
// a theorem).
TEST(ProvePlantedBug, DroppedDanglingConditionIsDetected) {
  ProveOptions o;
  o.max_darts = 6;
  o.fault = EncodingFault::drop_dangling;
  const Tally t = random_agreement(Model::gmap(2), 13, 150, o, false);
  EXPECT_GT(t.disagreements, 0);
}

// The small-model bounds of docs/prove.md, against brute force: for
// D-combinatorial rules on D = {0,1}, the solver's answer on hosts of at
// most the bound (|L| darts for Theorem 1, 2|L| for Theorem 2) equals the
// answer of the exhaustive search (checkers/host_search) over every host
// of the class with up to |L| + 3 darts, which is past both bounds since
// |L| <= 3.
TEST(ProveSmallModelBound, Theorems1And2AgreeWithBruteForcePastTheBound) {
  Model two;
  two.name = "D={0,1}";
  two.dims = {0, 1};
  std::mt19937 rng(21);
  ProveOptions o;
  o.max_darts = 9;
  int compared = 0, violated = 0;
  for (int k = 0; k < 150; ++k) {
    Model cls = two;
    const bool theorem2 = k % 2 == 1;
    if (theorem2) cls.non_oriented = dim_bit(0);
    const Rule rule = random_combinatorial_rule(rng, cls, cls);
    if (!combinatorial(check_rule(rule))) continue;
    const HConstraint c{theorem2 ? RuleCondition::non_orientation : RuleCondition::incident_arcs, 0};
    const Operation entry{rule, {}, std::nullopt, {}, {}, std::nullopt};
    const RuleProof p = prove_rule(entry, o);
    const ConstraintProof* cp = nullptr;
    for (const auto& x : p.constraints)
      if (x.constraint == c) cp = &x;
    // The model of `rule` is cls itself: its constraints include c.
    ASSERT_NE(cp, nullptr);
    ASSERT_TRUE(cp->theorem.has_value());
    const ClassAnswer& a = *cp->theorem;
    const HostSearch hs = search_hosts(rule, cls, 3, [&](const Violation& v) {
      return v.i == 0 && (theorem2 ? v.constraint == Constraint::non_orientation
                                   : v.constraint == Constraint::incident_in || v.constraint == Constraint::incident_out);
    });
    if (!hs.matched) continue;
    ++compared;
    violated += hs.host.has_value();
    EXPECT_EQ(a.status == Status::counterexample, hs.host.has_value())
        << c.name() << " solver " << name_of(a.status) << " at bound " << a.bound << "\nL: " << text(rule.left()) << "\nR: " << text(rule.right());
    if (a.status == Status::none) {
      EXPECT_EQ(a.darts, a.bound);
      EXPECT_TRUE(a.proved_for_all());
    }
  }
  std::cout << fmt::format("{} rules compared with brute force, {} with a violation\n", compared, violated);
  EXPECT_GT(compared, 60);
  EXPECT_GT(violated, 5);
}

namespace {

// Every word over the model's letters (bars on oriented dimensions) up to
// `length` letters.
std::vector<ConjWord> all_words(const Model& m, std::size_t length) {
  std::vector<ConjWord> out{ConjWord{}};
  for (std::size_t from = 0; from < out.size(); ++from) {
    if (out[from].size() == length) continue;
    for (Dim d : m.dims)
      for (bool bar : {false, true}) {
        if (bar && !m.is_oriented(d)) continue;
        ConjWord w = out[from];
        w.push(d, bar);
        out.push_back(w);
      }
  }
  return out;
}

}  // namespace

// Lemma 3 (002 Sec. 9.2) and its converse, bounded: words that R_{N,E}
// rewrites to each other end at the same dart on every map (the solver
// finds no separating map up to 6 darts), and every pair it does not
// relate is separated by some map of at most 6 darts.
TEST(ProveWords, CongruenceAgreesWithRewritingOnShortWords) {
  for (const auto& [model, length] : {std::pair{Model::gmap(2), std::size_t{3}}, std::pair{Model::omap(2), std::size_t{2}}}) {
    ConjugateRewriting r(model);
    const auto words = all_words(model, length);
    int congruent = 0, separated = 0;
    for (std::size_t a = 0; a < words.size(); ++a)
      for (std::size_t b = a + 1; b < words.size(); ++b) {
        const bool same = r.congruent(words[a], words[b]);
        const auto s = separate_words(model, words[a], words[b], 6, 50'000'000);
        ASSERT_NE(s.answer, Answer::unknown);
        EXPECT_EQ(s.answer == Answer::unsat, same) << model.name << ": " << words[a].str() << " vs " << words[b].str();
        if (s.map) {
          EXPECT_NE(follow(*s.map, 0, words[a]), follow(*s.map, 0, words[b]));
          EXPECT_TRUE(check_map(*s.map).valid());
        }
        congruent += same;
        separated += s.answer == Answer::sat;
      }
    std::cout << fmt::format("{}: {} words, {} congruent pairs, {} separated\n", model.name, words.size(), congruent, separated);
    EXPECT_GT(congruent, 0);
  }
}
