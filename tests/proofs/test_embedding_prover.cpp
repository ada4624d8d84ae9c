// The solver on embeddings (proofs/embedding_prover) against independent
// answers: the hand derivations the embedding catalog records (which
// failures are false alarms, which break a map), the library's own
// application (every arithmetic counterexample is replayed by
// the Applier + check_embedding), and brute force: every host up to K
// darts with values drawn from a small domain and as random dyadic reals,
// applied by the library.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include <fmt/format.h>

#include "analysis/embedded_fuzz.hpp"
#include "analysis/rule_result.hpp"
#include "checkers/embedding_consistency.hpp"
#include "checkers/host_search.hpp"
#include "generators/random_rules.hpp"
#include "io/catalog.hpp"
#include "proofs/embedding_prover.hpp"
#include "rewriting/application.hpp"
#include "rewriting/term_functions.hpp"

using namespace dartcheck;
using namespace dartcheck::proofs;

namespace {

const Catalog& embedding_catalog() {
  static const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/embedding-operations.yaml");
  return c;
}

const CatalogRule& rule_named(const std::string& name) {
  for (const auto& e : embedding_catalog().rules)
    if (e.rule.name() == name) return e;
  throw std::runtime_error("no rule " + name);
}

const EmbeddingAnswer& answer(const EmbeddingProof& p, const std::string& embedding, Reading r) {
  for (const auto& a : p.answers)
    if (a.embedding == embedding && a.reading == r) return a;
  throw std::runtime_error("no answer for " + embedding);
}

EmbeddingProveOptions at(std::size_t k) {
  EmbeddingProveOptions o;
  o.max_darts = k;
  return o;
}

}  // namespace

// Every rule of the embedding catalog at K = |L| + 4: no answer contradicts
// Theorems 2 and 4 (a counterexample where the conditions hold), every
// arithmetic counterexample is replayed by the library, and each answer
// is decided (no `unknown`).
TEST(ProveEmbeddings, CatalogAnswersAreDecidedAndReplayed) {
  for (const auto& e : embedding_catalog().rules) {
    const EmbeddingProof p = prove_embeddings(e, at(e.rule.left().node_count() + 4));
    ASSERT_FALSE(p.answers.empty()) << e.rule.name();
    for (const auto& a : p.answers) {
      EXPECT_FALSE(a.disagree) << e.rule.name() << " " << a.condition() << ": " << a.note;
      EXPECT_NE(a.status, EmbeddingAnswer::Status::unknown) << e.rule.name() << ": " << a.why;
      if (a.status == EmbeddingAnswer::Status::counterexample && a.reading == Reading::arithmetic) {
        EXPECT_TRUE(a.replayed) << e.rule.name() << ": " << a.replay;
      }
      // A syntactic pass is a theorem: no counterexample in either reading.
      if (a.static_failures.empty()) {
        EXPECT_EQ(a.status, EmbeddingAnswer::Status::none) << e.rule.name() << " " << a.why;
      }
    }
  }
}

// The catalog's hand notes: these variants fail a syntactic condition
// while their two terms are equal on every map (fig17b's j, l are i, k's
// 2-neighbours at the same vertices; Fig. 19b's equal terms; the exploded
// view's two nodes of one 2-orbit), so neither reading finds a host.
TEST(ProveEmbeddings, FalseAlarmsOfTheCatalogHaveNoHost) {
  for (const auto& [name, embedding] : {std::pair{"fig17b-vertex-insertion/two-terms", "pos"},
                                        std::pair{"fig19b-triangulation-col/equal-terms", "col"}, std::pair{"exploded-view/two-nodes", "exp_pos"}}) {
    const Operation& e = rule_named(name);
    const EmbeddingProof p = prove_embeddings(e, at(e.rule.left().node_count() + 4));
    for (Reading r : {Reading::uninterpreted, Reading::arithmetic}) {
      const auto& a = answer(p, embedding, r);
      EXPECT_FALSE(a.static_failures.empty()) << name;
      EXPECT_EQ(a.status, EmbeddingAnswer::Status::none) << name << " " << name_of(r) << ": " << a.why;
      EXPECT_NE(a.note.find("false alarm"), std::string::npos) << a.note;
    }
  }
  // Triangulation with Jerboa's collects of colors: A(col) holds once the
  // neighbour read commutes with the loop (docs/jerboa-expressions.md),
  // and the solver agrees that no host breaks it.
  const Operation& col = rule_named("triangulation-jerboa-col");
  const EmbeddingProof p = prove_embeddings(col, at(5));
  for (Reading r : {Reading::uninterpreted, Reading::arithmetic}) EXPECT_EQ(answer(p, "col", r).status, EmbeddingAnswer::Status::none);
}

// triangulation-all-faces-pos/corner-copy gives each new vertex the
// position of its corner in the face: on the smallest face of 2 darts
// (one edge, vertices 0 and 1 at different positions) the centre vertex
// gets both, so the answer is a counterexample on 2 darts that the library
// replays, naming two values of one pos-orbit.
TEST(ProveEmbeddings, CornerCopyBreaksOnTwoDartsAndReplays) {
  const EmbeddingProof p = prove_embeddings(rule_named("triangulation-all-faces-pos/corner-copy"), at(5));
  const auto& a = answer(p, "pos", Reading::arithmetic);
  ASSERT_EQ(a.status, EmbeddingAnswer::Status::counterexample);
  EXPECT_EQ(a.darts, 2U);
  EXPECT_TRUE(a.replayed) << a.replay;
  EXPECT_NE(a.replay.find("has 2 values"), std::string::npos) << a.replay;
  EXPECT_EQ(answer(p, "pos", Reading::uninterpreted).status, EmbeddingAnswer::Status::counterexample);
}

namespace {

// A random embedded DPO rule on 2-gmaps: R's nodes labeled with vertex
// positions read from L (a node's own, a neighbour's, midpoints, centers
// of a collect, a translation) or left unlabeled.
Operation random_embedded_rule(std::mt19937& rng) {
  const Model model = Model::gmap(2);
  Operation op{random_combinatorial_rule(rng, model, model), {}, std::nullopt, {}, {}, std::nullopt};
  RuleTerms terms;
  terms.embeddings.push_back({"pos", ValueType::point2, {1, 2}});
  const auto names = op.rule.left().names();
  TermScope scope;
  scope.model = &op.rule.model();
  scope.embeddings = &terms.embeddings;
  scope.variables = names;
  auto node = [&] { return names[std::uniform_int_distribution<std::size_t>(0, names.size() - 1)(rng)]; };
  auto draw = [&]() -> std::string {
    switch (std::uniform_int_distribution<int>(0, 6)(rng)) {
      case 0:
        return fmt::format("{}.pos", node());
      case 1:
        return fmt::format("{}.alpha{}.pos", node(), std::uniform_int_distribution<int>(0, 2)(rng));
      case 2:
        return fmt::format("midpoint({}.pos, {}.pos)", node(), node());
      case 3:
        return fmt::format("center(pos<0,1>({}))", node());
      case 4:
        return fmt::format("{}.pos + vector2(1, 0)", node());
      case 5:
        return "point2(0.5, 0)";
      default:
        return fmt::format("center(pos<0>({}))", node());
    }
  };
  const TopoGraph& R = op.rule.right();
  for (NodeId y = 0; y < R.node_count(); ++y) {
    if (std::uniform_int_distribution<int>(0, 4)(rng) == 0) continue;  // unlabeled
    Term t = parse_term(draw());
    check_term(t, scope);
    terms.right.push_back({R.name(y), "pos", std::move(t), {}, 0, 0});
  }
  op.terms = std::move(terms);
  return op;
}

// The smallest host (in darts, up to k) on which the library's application
// breaks pos, over every host containing L with values from `domain`
// (each orbit's coordinates drawn `draws` times), or 0.
std::size_t brute_force(const Operation& op, std::size_t k, const std::vector<double>& domain, int draws, std::mt19937& rng) {
  const Rule& rule = op.rule;
  std::vector<Dart> hooks(rule.hooks().begin(), rule.hooks().end());
  for (std::size_t n = rule.left().node_count(); n <= k; ++n) {
    bool broke = false;
    for_each_small_map(
        rule.model(), n,
        [&](const std::vector<std::vector<NodeId>>& sigma) {
          Map g(rule.model(), n);
          for (std::size_t d = 0; d < rule.model().dims.size(); ++d)
            for (Dart x = 0; x < n; ++x) g.set_link(rule.model().dims[d], x, sigma[d][x]);
          for (int t = 0; t < draws && !broke; ++t) {
            EmbeddedMap host(g);
            const std::size_t e = host.add_embedding(op.terms->embeddings[0]);
            std::uniform_int_distribution<std::size_t> pick(0, domain.size() - 1);
            for (Dart x = 0; x < n; ++x)
              if (!host.embeddings[e].value(x)) host.label_orbit(e, x, Value::coords(ValueType::point2, {domain[pick(rng)], domain[pick(rng)], 0}));
            auto r = Applier(op).apply(host, hooks, false);
            if (!r.ok()) break;  // refused whatever the values
            broke = !check_embedding(host.map, host.embeddings[e], true).consistent();
          }
          return !broke;
        },
        2'000'000, &rule.left());
    if (broke) return n;
  }
  return 0;
}

}  // namespace

// Property (completeness and soundness of the search up to K): on random
// embedded rules, whenever the library's application breaks pos on some
// host of n <= K darts with some values, both readings report a
// counterexample on at most n darts (an uninterpreted break is implied by
// a concrete one; the arithmetic reading is exact on these terms), and
// every arithmetic counterexample replays. A `none` where brute force
// breaks would be a false proof.
TEST(ProveEmbeddings, RandomRulesMatchBruteForceUpToK) {
  std::mt19937 rng(61);
  int rules = 0, breaks = 0, nones = 0;
  for (int k = 0; k < 240; ++k) {
    const Operation op = random_embedded_rule(rng);
    const std::size_t K = op.rule.left().node_count() + 2;
    const EmbeddingProof p = prove_embeddings(op, at(K));
    if (p.applications == 0) continue;
    ++rules;
    const std::size_t small = brute_force(op, K, {0, 1}, 3, rng);
    const std::size_t dyadic = brute_force(op, K, {-2, -1.5, -0.25, 0, 0.75, 1, 3.5}, 3, rng);
    const std::size_t found = small == 0 ? dyadic : dyadic == 0 ? small : std::min(small, dyadic);
    breaks += found > 0;
    for (Reading r : {Reading::uninterpreted, Reading::arithmetic}) {
      const auto& a = answer(p, "pos", r);
      EXPECT_FALSE(a.disagree) << k << " " << a.note;
      ASSERT_NE(a.status, EmbeddingAnswer::Status::unknown) << a.why;
      nones += a.status == EmbeddingAnswer::Status::none;
      if (found > 0) {
        EXPECT_EQ(a.status, EmbeddingAnswer::Status::counterexample) << "rule " << k << " (" << name_of(r) << "): brute force breaks at " << found;
        if (a.status == EmbeddingAnswer::Status::counterexample) {
          EXPECT_LE(a.darts, found) << k;
        }
      }
      if (a.status == EmbeddingAnswer::Status::counterexample && r == Reading::arithmetic) {
        EXPECT_TRUE(a.replayed) << k << ": " << a.replay;
      }
    }
  }
  // Not vacuous: rules apply, some break and some do not.
  std::printf("%d rules applied, %d broken by brute force, %d answers none\n", rules, breaks, nones);
  EXPECT_GT(rules, 150);
  EXPECT_GT(breaks, 40);
  EXPECT_GT(nones, 40);
}

// A planted fault (R's values read as fresh unknowns) gives counterexamples
// that the library does not reproduce: each is reported as a DISAGREE.
TEST(ProveEmbeddings, PlantedFaultIsCaughtByTheReplay) {
  EmbeddingProveOptions o = at(6);
  o.fault = EmbeddingProveOptions::Fault::fresh_writes;
  int disagreements = 0;
  for (const char* name : {"fig17b-vertex-insertion", "fig12b-vertex-insertion", "triangulation-jerboa-pos", "fig19b-triangulation-col"}) {
    const EmbeddingProof p = prove_embeddings(rule_named(name), o);
    for (const auto& a : p.answers) disagreements += a.disagree;
  }
  EXPECT_EQ(disagreements, 8);  // each rule's conditions hold: both readings
}

// The two readings differ where only the algebra makes two terms equal
// (tests/data/embedding-readings.yaml): midpoint(a, b) and center{a, b} are
// one point in real arithmetic (a + b over 2 either way), so the
// arithmetic reading finds no host, while some interpretation of the two
// symbols tells them apart on the smallest corner; shifting one of them by
// (0, 1) breaks in both readings, and the arithmetic host replays.
TEST(ProveEmbeddings, ReadingsDifferWhereOnlyTheAlgebraAgrees) {
  const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/tests/data/embedding-readings.yaml");
  ASSERT_EQ(c.rules.size(), 3U);
  const EmbeddingProof same = prove_embeddings(c.rules[0], at(6));
  EXPECT_EQ(answer(same, "pos", Reading::uninterpreted).status, EmbeddingAnswer::Status::counterexample);
  EXPECT_EQ(answer(same, "pos", Reading::arithmetic).status, EmbeddingAnswer::Status::none);
  const EmbeddingProof shifted = prove_embeddings(c.rules[1], at(6));
  EXPECT_EQ(answer(shifted, "pos", Reading::uninterpreted).status, EmbeddingAnswer::Status::counterexample);
  const auto& a = answer(shifted, "pos", Reading::arithmetic);
  EXPECT_EQ(a.status, EmbeddingAnswer::Status::counterexample);
  EXPECT_TRUE(a.replayed) << a.replay;
  // A shift by 1e-05, a literal whose shortest text has an exponent.
  const EmbeddingProof tiny = prove_embeddings(c.rules[2], at(6));
  const auto& t = answer(tiny, "pos", Reading::arithmetic);
  EXPECT_EQ(t.status, EmbeddingAnswer::Status::counterexample) << t.why;
  EXPECT_TRUE(t.replayed) << t.replay;
}

// Item 4's second cross-check, with a planted fault: a solver that never
// asks Z3 answers `none` up to K = 8 darts for fig17a's two terms, which
// fuzz breaks on a 4-dart host; the rule's result must then contradict
// itself (a DISAGREE, exit 3), and without the fault it must not.
TEST(ProveEmbeddings, FuzzBreakWithinKContradictsASolverNone) {
  const auto& entry = rule_named("fig17a-translation/two-terms");
  analysis::FuzzOptions fo;
  fo.runs = 2000;
  const analysis::FuzzReport report = analysis::fuzz_embedded_rule(entry, {}, fo);
  ASSERT_TRUE(report.counterexample);
  ASSERT_LE(report.counterexample->host.size(), 8U);
  for (const bool faulty : {false, true}) {
    analysis::RuleResult r = analysis::analyse_static(embedding_catalog(), entry, 0);
    analysis::add_fuzz(r, report, fo.seed, "", "");
    proofs::RuleProof p;
    EmbeddingProveOptions o = at(8);
    if (faulty) o.fault = EmbeddingProveOptions::Fault::no_breaks;
    p.embedding = prove_embeddings(entry, o);
    analysis::add_proof(r, std::move(p), {}, {});
    EXPECT_EQ(!r.solver_fuzz_contradiction().empty(), faulty) << r.solver_fuzz_contradiction();
    EXPECT_EQ(r.unsound(), faulty);
  }
}
