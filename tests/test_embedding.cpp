// Embedded maps, terms and embedded rules (003): the term language, collect
// operators against a brute-force traversal, the catalog's verdicts, the
// dynamic cross-check (no soundness bug; every rejected rule confirmed
// except those whose terms are equal on every map, derived by hand in the
// catalog's notes), Theorems 2/4 on random embedded rules, and the
// position triangulation of a mesh against the mesh file's barycenters.
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
#include "cli/embedded_fuzz.hpp"
#include "core/catalog.hpp"
#include "core/embedded_application.hpp"
#include "core/input_error.hpp"
#include "core/mesh_io.hpp"
#include "core/orbit.hpp"
#include "core/term_eval.hpp"
#include "generators/mesh_map.hpp"
#include "generators/random_embedding.hpp"
#include "generators/random_maps.hpp"
#include "generators/random_rules.hpp"

namespace dartcheck {

// GoogleTest prints values as text, not bytes (found by argument-dependent
// lookup, so outside the anonymous namespace).
inline void PrintTo(const Value& v, std::ostream* os) { *os << v.str(); }

namespace {

const std::string catalog_file = std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/embedding-operations.yaml";
const std::vector<EmbeddingSignature> signatures = {{"pos", ValueType::point2, {1, 2}}, {"col", ValueType::color, {0, 1}}};

Term checked(const std::string& text, std::vector<std::string> vars = {"a", "b"}, const FunctionRegistry* f = nullptr) {
  static const Model model = Model::gmap(2);
  TermScope scope;
  scope.model = &model;
  scope.embeddings = &signatures;
  scope.variables = std::move(vars);
  scope.parameters["v"] = Value::coords(ValueType::vector2, {1, 0, 0});
  scope.functions = f;
  Term t = parse_term(text);
  check_term(t, scope);
  return t;
}

std::size_t error_offset(const std::string& text) {
  try {
    checked(text);
  } catch (const TermError& e) {
    return e.offset();
  }
  return std::string::npos;
}

TEST(Terms, CanonicalTextAndSyntacticEquality) {
  // Spacing and redundant parentheses do not matter; operands do.
  EXPECT_TRUE(checked("a.pos+v").same(checked("(a.pos) + v")));
  EXPECT_FALSE(checked("a.pos + v").same(checked("b.pos + v")));
  EXPECT_EQ(checked("midpoint(a.pos,b.pos)+ v").str(), "midpoint(a.pos, b.pos) + v");
  EXPECT_EQ(checked("col_<0,1,2>(a.alpha_2)").str(), "col<0,1,2>(a.alpha2)");
  // a - (b - c) keeps its parentheses, (a - b) - c needs none.
  EXPECT_EQ(parse_term("1 - (2 - 3)").str(), "1 - (2 - 3)");
  EXPECT_EQ(parse_term("(1 - 2) - 3").str(), "1 - 2 - 3");
  EXPECT_EQ(parse_term("2 * (1 + 3)").str(), "2 * (1 + 3)");
  // An integer stands for a real; the conversion is invisible.
  EXPECT_EQ(checked("point2(0, 1)").str(), "point2(0, 1)");
  EXPECT_TRUE(checked("point2(0, 1)").same(checked("point2(0,1)")));
  EXPECT_EQ(checked("a.pos").variables(), std::vector<std::string>{"a"});
  EXPECT_EQ(checked("midpoint(b.pos, a.alpha0.pos)").variables(), (std::vector<std::string>{"a", "b"}));
}

TEST(Terms, ErrorsNameTheOffendingToken) {
  EXPECT_EQ(error_offset("a.pos + * b"), 8u);          // '*' where a term starts
  EXPECT_EQ(error_offset("midpoint(a.pos, "), 16u);    // the end of the term
  EXPECT_EQ(error_offset("c.pos"), 0u);                // not a node of L
  EXPECT_EQ(error_offset("a.color"), 2u);              // no such embedding
  EXPECT_EQ(error_offset("a.alpha7.pos"), 2u);         // not a dimension of a 2-G-map
  EXPECT_EQ(error_offset("mix(a.col, a.pos)"), 0u);    // no profile color x point2
  EXPECT_EQ(error_offset("center(a.pos)"), 0u);        // center takes a multiset
  EXPECT_EQ(error_offset("a.pos $ b"), 6u);
  EXPECT_EQ(error_offset("pos<0,x>(a)"), 6u);
  try {
    checked("mix(a.col, a.pos)");
  } catch (const TermError& e) {
    EXPECT_NE(std::string(e.what()).find("mix : color x color -> color"), std::string::npos) << e.what();
  }
}

TEST(Terms, UserFunctionsRegisteredWithTheirProfile) {
  FunctionRegistry f = FunctionRegistry::builtin();
  f.add("scale", {Sort::of(ValueType::point2), Sort::of(ValueType::real)}, Sort::of(ValueType::point2), [](std::span<const Operand> a) {
    const Value& p = std::get<Value>(a[0]);
    const double s = std::get<Value>(a[1]).x[0];
    return Value::coords(ValueType::point2, {p.x[0] * s, p.x[1] * s, 0});
  });
  EmbeddedMap g(Map(Model::gmap(2), 1));
  for (Dim i : {0, 1, 2}) g.map.sew(i, 0, 0);
  g.add_embedding(signatures[0]);
  g.embeddings[0].set(0, Value::coords(ValueType::point2, {2, 3, 0}));
  const Term t = checked("scale(a.pos, 2) + v", {"a"}, &f);
  TermEvaluator ev(g);
  const std::vector<std::string> names{"a"};
  const std::vector<Dart> darts{0};
  EXPECT_EQ(ev.value(t, names, darts), Value::coords(ValueType::point2, {5, 6, 0}));  // (4, 6) + (1, 0)
  EXPECT_THROW(checked("scale(a.pos, 2)"), TermError);  // unknown to the built-in registry
}

// The multiset of pi<o'>(d) by brute force: the darts reachable from d
// through links in o' (a plain worklist over Map::link), split into
// classes joined by links in o ∩ o', one value per class.
std::multiset<std::string> brute_collect(const EmbeddedMap& g, const Embedding& e, const std::vector<Dim>& o2, Dart d) {
  std::vector<Dart> orbit{d};
  std::set<Dart> in{d};
  for (std::size_t k = 0; k < orbit.size(); ++k)
    for (Dim i : o2)
      if (const Dart n = g.map.link(i, orbit[k]); n != no_dart && in.insert(n).second) orbit.push_back(n);
  std::map<Dart, Dart> up;
  for (Dart x : orbit) up[x] = x;
  std::function<Dart(Dart)> root = [&](Dart x) { return up[x] == x ? x : up[x] = root(up[x]); };
  for (Dart x : orbit)
    for (Dim i : o2)
      if (std::find(e.signature.orbit.begin(), e.signature.orbit.end(), i) != e.signature.orbit.end()) up[root(x)] = root(g.map.link(i, x));
  std::multiset<std::string> r;
  for (Dart x : orbit)
    if (root(x) == x) r.insert(e.value(x)->str());
  return r;
}

TEST(Terms, CollectEqualsBruteForceOnRandomEmbeddedMaps) {
  // Def. 9: pi<o'>(v) = the labels of the quotient by pi of <o'>(v).
  std::mt19937 rng(7);
  const Model model = Model::gmap(2);
  std::size_t compared = 0;
  for (int round = 0; round < 200; ++round) {
    const EmbeddedMap g = embed_randomly(build_random_map(model, draw_recipe(rng, 1 + round % 6, 2)), signatures, rng);
    TermEvaluator ev(g);
    for (int k = 0; k < 5; ++k) {
      const Dart d = std::uniform_int_distribution<Dart>(0, static_cast<Dart>(g.map.size() - 1))(rng);
      std::vector<Dim> o2;
      for (Dim i : {0, 1, 2})
        if (rng() % 2) o2.push_back(i);
      for (const Embedding& e : g.embeddings) {
        Multiset m = ev.collect(e.signature.name, o2, d);
        std::multiset<std::string> got;
        for (const Value& v : m) got.insert(v.str());
        ASSERT_EQ(got, brute_collect(g, e, o2, d)) << e.signature.name << " at dart " << d;
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, 2000u);
}

TEST(Catalog, BadTermsAreReportedAtTheirToken) {
  const std::string file = ::testing::TempDir() + "bad-terms.yaml";
  std::ofstream(file) << "model: 2-gmap\n"
                         "embeddings: [{name: pos, type: point2, orbit: \"<1,2>\"}]\n"
                         "rules:\n"
                         "  - name: r\n"
                         "    hooks: [a]\n"
                         "    left: {nodes: [a]}\n"
                         "    right: {nodes: [a]}\n"
                         "    labels: {right: {a: {pos: \"a.pos + * 2\"}}}\n";
  try {
    read_catalog(file);
    FAIL() << "accepted a malformed term";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 8);
    EXPECT_EQ(e.column(), 40);  // the '*': the quote is column 31, the term starts at 32, offset 8
    EXPECT_NE(std::string(e.what()).find("'*'"), std::string::npos) << e.what();
  }
}

// --- The catalog against the dynamic check --------------------------------

const Catalog& catalog() {
  static const Catalog c = read_catalog(catalog_file);
  return c;
}

std::vector<std::string> static_failures_of(const CatalogRule& r) {
  std::vector<std::string> f;
  for (const auto& c : check_rule(r.rule, r.words).conditions)
    if (!c.holds) f.push_back(c.name());
  for (const auto& n : failing_names(check_term_conditions(r.rule, r.words, *r.terms))) f.push_back(n);
  std::sort(f.begin(), f.end());
  return f;
}

TEST(EmbeddingCatalog, StaticVerdictsMatchTheRecordedOnes) {
  ASSERT_EQ(catalog().rules.size(), 33u);
  for (const auto& r : catalog().rules) {
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
  // sufficient, so no map can break them.
  const std::set<std::string> equal_terms = {"fig17b-vertex-insertion/two-terms", "fig19b-triangulation-col/equal-terms",
                                             "triangulation-jerboa-col", "exploded-view/two-nodes"};
  cli::FuzzOptions o;
  o.seed = 3;
  o.runs = 2000;
  o.max_darts = 64;
  std::size_t confirmed = 0, consistent = 0;
  for (const auto& r : catalog().rules) {
    const auto report = cli::fuzz_embedded_rule(r, {}, o);
    ASSERT_NE(report.verdict, cli::FuzzClass::soundness_bug) << r.rule.name() << ": " << report.counterexample->embedding_failures.front();
    if (static_failures_of(r).empty()) {
      EXPECT_GT(report.applications, 100u) << r.rule.name() << " " << report.reason;
      ++consistent;
    } else if (equal_terms.contains(r.rule.name())) {
      EXPECT_EQ(report.verdict, cli::FuzzClass::unconfirmed) << r.rule.name();
    } else {
      EXPECT_EQ(report.verdict, cli::FuzzClass::confirmed) << r.rule.name() << ": " << report.reason;
      ++confirmed;
    }
  }
  EXPECT_EQ(consistent, 14u);
  EXPECT_EQ(confirmed, 15u);
}

// Every embedding's value at every dart (none: nullopt), to compare two
// maps whose value pools differ.
std::vector<std::vector<std::optional<Value>>> values_of(const EmbeddedMap& g) {
  std::vector<std::vector<std::optional<Value>>> out;
  for (const Embedding& e : g.embeddings) {
    out.emplace_back();
    for (Dart d = 0; d < g.map.size(); ++d) out.back().push_back(e.value(d) ? std::optional(*e.value(d)) : std::nullopt);
  }
  return out;
}

TEST(EmbeddedRewriter, OneEvaluationPerOrbitAndReuseWriteWhatFreshApplicationsWrite) {
  // 003 Thm 2 and 4: when a rule passes the conditions, the instances of
  // one orbit of the extended rule have one value, so evaluating one per
  // orbit (Evaluation::one_per_orbit) writes what evaluating every
  // instance writes. And a rewriter kept across applications on a
  // changing map (tables left empty, walkers grown) acts as fresh
  // applications do. Three applications in a row on random embedded maps.
  std::mt19937 rng(11);
  std::size_t compared = 0, rules = 0;
  for (const auto& r : catalog().rules) {
    if (!static_failures_of(r).empty()) continue;
    ++rules;
    for (int round = 0; round < 80; ++round) {
      EmbeddedMap fresh = embed_randomly(build_random_map(r.rule.model(), draw_recipe(rng, 1 + round % 8, 2)), catalog().signatures, rng);
      EmbeddedMap reused = fresh;
      EmbeddedRewriter rewriter(r.rule, r.words, *r.terms, reused, Evaluation::one_per_orbit);
      for (int step = 0; step < 3; ++step) {
        std::vector<Dart> hooks;
        for (std::size_t h = 0; h < r.rule.hooks().size(); ++h)
          hooks.push_back(std::uniform_int_distribution<Dart>(0, static_cast<Dart>(fresh.map.size() - 1))(rng));
        const auto a = apply_embedded(r.rule, r.words, *r.terms, fresh, hooks);
        const auto b = rewriter.apply(hooks);
        ASSERT_EQ(a.refusal, b.refusal) << r.rule.name() << ": " << a.why << " / " << b.why;
        if (!a.ok()) continue;
        ASSERT_TRUE(a.value->conflicts.empty()) << r.rule.name() << ": " << a.value->conflicts.front();
        ASSERT_EQ(fresh.map, reused.map) << r.rule.name();
        ASSERT_EQ(values_of(fresh), values_of(reused)) << r.rule.name();
        ASSERT_EQ(a.value->written.size(), b.value->written.size()) << r.rule.name();
        for (std::size_t k = 0; k < a.value->written.size(); ++k) ASSERT_EQ(a.value->written[k].value, b.value->written[k].value) << r.rule.name();
        ++compared;
      }
    }
  }
  EXPECT_EQ(rules, 14u);
  EXPECT_GT(compared, 300u);
}

TEST(EmbeddingCatalog, FaceStretchingOverlapsOnATriangle) {
  // Fig. 33-34: on a square the two opposite half-edges are four vertices;
  // on a triangle two of their ends are one vertex (Lemma 3).
  const CatalogRule& r = *catalog().find_rule("fig32-face-stretching");
  std::mt19937 rng(1);
  for (int n : {3, 4}) {
    Map m(Model::gmap(2), 2 * static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
      m.sew(0, 2 * k, 2 * k + 1);
      m.sew(1, 2 * k + 1, (2 * k + 2) % (2 * n));
    }
    for (Dart d = 0; d < m.size(); ++d) m.sew(2, d, d);
    EmbeddedMap g = embed_randomly(std::move(m), {signatures[0]}, rng);
    const std::vector<Dart> hooks{0, 4};  // edges 0 and 2
    const auto d = apply_embedded(r.rule, r.words, *r.terms, g, hooks);
    if (n == 3) {
      EXPECT_EQ(d.refusal, Refusal::overlap) << d.why;
    } else {
      ASSERT_TRUE(d.ok()) << d.why;
      EXPECT_TRUE(check_embedding(g.map, g.embeddings[0], true).consistent());
    }
  }
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
  cli::FuzzOptions o;
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
        case 0: return fmt::format("point2({}, 0)", rng() % 2);
        case 1: return fmt::format("{}.pos", ln[rng() % ln.size()]);
        default: return fmt::format("midpoint({}.pos, {}.pos)", ln[rng() % ln.size()], ln[rng() % ln.size()]);
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
    const CatalogRule entry{topo, "", {}, {}, std::nullopt, {}, {}, std::nullopt, {}, {}, terms};
    const bool holds = failing_names(check_term_conditions(topo, {}, terms)).empty();
    const auto report = cli::fuzz_embedded_rule(entry, {}, o);
    ++tried;
    if (holds) {
      ASSERT_NE(report.verdict, cli::FuzzClass::soundness_bug) << "round " << round << ": " << report.counterexample->embedding_failures.front();
      passed += report.applications > 0;
    } else {
      rejected_confirmed += report.verdict == cli::FuzzClass::confirmed;
    }
  }
  EXPECT_GE(passed, 20u) << tried << " rules tried";
  EXPECT_GE(rejected_confirmed, 20u) << "the dynamic check must be able to fail";
}

// --- Triangulation of a mesh ---------------------------------------------

TEST(EmbeddingApplication, TriangulatingAMeshPutsEachCentreAtItsFaceBarycenter) {
  const CatalogRule& r = *catalog().find_rule("triangulation-jerboa-pos");
  for (const char* file : {"unit-square.off", "cube.off"}) {
    const Mesh mesh = read_mesh(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/meshes/" + file);
    EmbeddedMap g = mesh_with_positions(Model::gmap(2), mesh, signatures[0]);
    // The first dart of face f is the sum of the sizes of the faces before
    // it, doubled (build_surface); triangulation adds darts at the end, so
    // these numbers survive.
    Dart first = 0;
    for (const auto& f : mesh.faces) {
      std::array<double, 2> centre{};
      for (auto v : f)
        for (std::size_t k = 0; k < 2; ++k) centre[k] += mesh.positions[v][k] / static_cast<double>(f.size());
      const std::vector<Dart> hook{first};
      const auto d = apply_embedded(r.rule, r.words, *r.terms, g, hook);
      ASSERT_TRUE(d.ok()) << d.why;
      std::size_t centres = 0;
      for (const auto& w : d.value->written) {
        if (w.node.rfind("n2@", 0) != 0) continue;
        EXPECT_NEAR(w.value.x[0], centre[0], 1e-12);
        EXPECT_NEAR(w.value.x[1], centre[1], 1e-12);
        ++centres;
      }
      EXPECT_EQ(centres, 2 * f.size());
      first += static_cast<Dart>(2 * f.size());
    }
    EXPECT_TRUE(check_map(g.map).valid());
    EXPECT_TRUE(check_embedding(g.map, g.embeddings[0], true).consistent());
    std::size_t triangles = 0;
    for (const auto& f : mesh.faces) triangles += f.size();
    EXPECT_EQ(count_cells(g.map).cells[2], triangles) << file;
  }
}

}  // namespace
}  // namespace dartcheck
