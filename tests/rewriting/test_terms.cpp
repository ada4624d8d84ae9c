// The term language of embedded rules (003 Sec. 6): canonical text and
// syntactic equality, error offsets, user functions, and collect operators
// against a brute-force traversal.
#include <algorithm>
#include <fstream>
#include <limits>
#include <numeric>
#include <optional>
#include <random>
#include <set>
#include <tuple>

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
#include "core/limits.hpp"
#include "io/mesh_io.hpp"
#include "core/orbit.hpp"
#include "core/orbit_notation.hpp"
#include "rewriting/term_eval.hpp"
#include "generators/mesh_map.hpp"
#include "generators/random_embedding.hpp"
#include "generators/random_maps.hpp"
#include "generators/random_rules.hpp"
#include "tests/embedding_support.hpp"

namespace dartcheck {
namespace {

using namespace testing_support;

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
  EXPECT_EQ(error_offset("a.pos + * b"), 8u);        // '*' where a term starts
  EXPECT_EQ(error_offset("midpoint(a.pos, "), 16u);  // the end of the term
  EXPECT_EQ(error_offset("c.pos"), 0u);              // not a node of L
  EXPECT_EQ(error_offset("a.color"), 2u);            // no such embedding
  EXPECT_EQ(error_offset("a.alpha7.pos"), 2u);       // not a dimension of a 2-G-map
  EXPECT_EQ(error_offset("mix(a.col, a.pos)"), 0u);  // no profile color x point2
  EXPECT_EQ(error_offset("center(a.pos)"), 0u);      // center takes a multiset
  EXPECT_EQ(error_offset("a.pos $ b"), 6u);
  EXPECT_EQ(error_offset("pos<0,x>(a)"), 6u);
  try {
    checked("mix(a.col, a.pos)");
  } catch (const TermError& e) {
    EXPECT_NE(std::string(e.what()).find("mix : color x color -> color"), std::string::npos) << e.what();
  }
}

// Issue 21: terms that overflowed the stack (thousands of parentheses or
// unary minus signs), a dimension that ended in "error: stoi", and terms
// longer than the limit; each is a TermError at its offset.
std::string parse_error(const std::string& text) {
  try {
    parse_term(text);
  } catch (const TermError& e) {
    return fmt::format("{}: {}", e.offset(), e.what());
  }
  return "no error";
}

TEST(Terms, HostileTermsStopAtTheLimits) {
  const std::string parens = std::string(30000, '(') + "a" + std::string(30000, ')');
  EXPECT_NE(parse_error(parens).find("the term's nesting: 257 is over the limit of 256"), std::string::npos) << parse_error(parens).substr(0, 80);
  EXPECT_EQ(parse_error(parens).rfind("256:", 0), 0u);  // the 257th '('
  const std::string minus = std::string(60000, '-') + "a";
  EXPECT_EQ(parse_error(minus).rfind("255: the term's nesting: 257", 0), 0u) << parse_error(minus).substr(0, 80);
  // The depth of the tree, not only the parser's nesting: a+a+...+a is a
  // left comb as deep as it has operators.
  std::string sum = "a";
  for (int k = 0; k < 255; ++k) sum += "+a";
  EXPECT_EQ(parse_error(sum), "no error");  // depth 256
  EXPECT_NE(parse_error(sum + "+a").find("over the limit"), std::string::npos);
  std::string dots = "a";
  for (int k = 0; k < 300; ++k) dots += ".alpha0";
  EXPECT_NE(parse_error(dots).find("over the limit"), std::string::npos);
  // Raised, the same sum parses (limits are per process, set by the CLI).
  const Limits saved = limits();
  limits().term_depth = 100000;
  std::string long_sum = "a";
  for (int k = 0; k < 20000; ++k) long_sum += "+a";
  EXPECT_EQ(parse_error(long_sum), "no error");
  limits() = saved;
  EXPECT_NE(parse_error(long_sum).find("the term's nesting: 257 is over the limit"), std::string::npos) << parse_error(long_sum).substr(0, 80);
  limits().term_length = 1000;
  EXPECT_EQ(parse_error(long_sum), "1000: the term's length: 40001 is over the limit of 1000 (raise it with --limit-term-length)");
  limits() = saved;

  EXPECT_EQ(parse_error("pos<99999999999>(a)"), "4: '99999999999' in the orbit type of 'pos' is not a dimension (0 to 15)");
  EXPECT_EQ(parse_error("pos<0,16>(a)").rfind("6: ", 0), 0u);
  EXPECT_EQ(parse_error(std::string("a + \x01")), "4: unexpected character '\\x01'");
}

// A collect's orbit type is read as every orbit type of a catalog
// (core/orbit_notation: commas, spaces around them), kept as a sorted set;
// what the notation refuses, or what an orbit cannot hold ('_', a repeat),
// is an error at the '<' or at the entry, never dropped.
TEST(Terms, CollectOrbitTypesAreOrbitNotation) {
  EXPECT_EQ(parse_term("mid<1, 0>(pos)").str(), "mid<0,1>(pos)");
  EXPECT_EQ(parse_term("mid<>(pos)").str(), "mid<>(pos)");
  EXPECT_EQ(parse_error("mid<0,0>(pos)"), "6: dimension 0 appears twice in the orbit type of 'mid'");
  EXPECT_EQ(parse_error("mid<0,_>(pos)"), "6: '_' in the orbit type of 'mid' is not a dimension: an orbit removes none");
  EXPECT_EQ(parse_error("mid<0 1>(pos)"), "6: the orbit type of 'mid': orbit type '<0 1>', at byte 4: expected ',' or '>'");
  EXPECT_EQ(parse_error("mid<0,1(pos)"), "3: '<' is never closed by '>'");
  for (const char* text : {"<0,1>", "<2>", "< 0 , 3 >"}) {
    const OrbitType core = parse_orbit_type(text);
    std::vector<Dim> dims;
    for (const auto& d : core) dims.push_back(*d);
    std::sort(dims.begin(), dims.end());
    EXPECT_EQ(parse_term(fmt::format("mid{}(pos)", text)).orbit, dims) << text;
  }
}

TEST(Terms, UserFunctionsRegisteredWithTheirProfile) {
  FunctionRegistry f = FunctionRegistry::builtin();
  f.add("scale", {Sort::of(ValueType::point2), Sort::of(ValueType::real)}, Sort::of(ValueType::point2), [](std::span<const Operand> a) {
    const Value& p = std::get<Value>(a[0]);
    const double s = value_arg(a, 1).x[0];
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
  EXPECT_THROW(checked("scale(a.pos, 2)"), TermError);                                // unknown to the built-in registry
}

// A call lends a memorised multiset to its function instead of copying it:
// one multiset passed twice, and a collect that a later argument reads
// again, must reach the function whole, and stay whole for the next call.
TEST(Terms, CollectArgumentsReachFunctionsWholeWhenRepeated) {
  FunctionRegistry f = FunctionRegistry::builtin();
  const Sort bag = Sort::bag(ValueType::point2), real = Sort::of(ValueType::real), point = Sort::of(ValueType::point2);
  // sizes(m1, m2) = |m1| + 10 |m2|; size_at(m, p) = |m| + p.x.
  f.add("sizes", {bag, bag}, real,
        [](std::span<const Operand> a) { return Value::real(static_cast<double>(multiset_arg(a, 0).size() + 10 * multiset_arg(a, 1).size())); });
  f.add("size_at", {bag, point}, real,
        [](std::span<const Operand> a) { return Value::real(static_cast<double>(multiset_arg(a, 0).size()) + value_arg(a, 1).x[0]); });
  // A triangle face: 6 darts, three corners (pos on <1,2>) at x = 0, 3, 6.
  EmbeddedMap g(Map(Model::gmap(2), 6));
  for (Dart k = 0; k < 3; ++k) {
    g.map.sew(0, 2 * k, 2 * k + 1);
    g.map.sew(1, 2 * k + 1, (2 * k + 2) % 6);
  }
  for (Dart d = 0; d < 6; ++d) g.map.sew(2, d, d);
  g.add_embedding(signatures[0]);
  for (Dart d = 0; d < 6; ++d) g.embeddings[0].set(d, Value::coords(ValueType::point2, {3.0 * (((d + 1) / 2) % 3), 0, 0}));
  TermEvaluator ev(g);
  const std::vector<std::string> names{"a"};
  const std::vector<Dart> darts{0};
  for (int twice = 0; twice < 2; ++twice) {
    EXPECT_EQ(ev.value(checked("sizes(pos<0,1>(a), pos<0,1>(a))", {"a"}, &f), names, darts), Value::real(33));
    EXPECT_EQ(ev.value(checked("size_at(pos<0,1>(a), center(pos<0,1>(a)))", {"a"}, &f), names, darts), Value::real(6));  // 3 + (0+3+6)/3
    EXPECT_EQ(ev.collect("pos", {0, 1}, 0).size(), 3u);
  }
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
  // Def. 9: pi<o'>(v) = the labels of the quotient by pi of <o'>(v). On
  // 2-G-maps (every dimension an involution: the evaluator reads a one-
  // dimension pi-orbit off the links) and on 2-O-maps (alpha_1 a
  // permutation: its cycles are longer than two, and are walked); with
  // the memo (default) and without (one evaluation per orbit).
  std::mt19937 rng(7);
  const std::vector<EmbeddingSignature> oriented = {{"face", ValueType::real, {1}}, {"edge", ValueType::integer, {2}}};
  std::size_t compared = 0;
  for (const Model& model : {Model::gmap(2), Model::omap(2)}) {
    const auto& sigs = model.is_oriented(1) ? oriented : signatures;
    for (int round = 0; round < 200; ++round) {
      const EmbeddedMap g = embed_randomly(build_random_map(model, draw_recipe(rng, 1 + round % 6, 2)), sigs, rng);
      TermEvaluator ev(g);
      ev.memorise(round % 2 == 0);
      for (int k = 0; k < 5; ++k) {
        const Dart d = std::uniform_int_distribution<Dart>(0, static_cast<Dart>(g.map.size() - 1))(rng);
        std::vector<Dim> o2;
        for (Dim i : model.dims)
          if (rng() % 2) o2.push_back(i);
        for (const Embedding& e : g.embeddings) {
          const std::span<const Value> m = ev.collect(e.signature.name, o2, d);
          std::multiset<std::string> got;
          for (const Value& v : m) got.insert(v.str());
          ASSERT_EQ(got, brute_collect(g, e, o2, d)) << model.name << ": " << e.signature.name << " at dart " << d;
          ++compared;
        }
      }
    }
  }
  EXPECT_EQ(compared, 4000u);
}

}  // namespace
}  // namespace dartcheck

// value_less is spelt out for speed; the order it must keep is the one
// collects were sorted by before (std::tie(type, x, i), strings by text),
// since a center's floating-point sum depends on the order. Checked on
// every pair of a set of values with ties, signed zeros, infinities and
// NaNs in each coordinate, of several types.
TEST(Terms, ValueOrderIsTheTupleOrder) {
  using namespace dartcheck;
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const std::vector<double> xs = {-inf, -1.5, -0.0, 0.0, 1e-300, 1.5, inf, nan};
  std::vector<Value> values;
  for (const ValueType t : {ValueType::point2, ValueType::point3, ValueType::real})
    for (double a : xs)
      for (double b : {0.0, nan, 2.0})
        for (double c : {-0.0, 1.0}) values.push_back(Value::coords(t, {a, b, c}));
  for (std::int64_t i : {-3, 0, 7}) values.push_back(Value::integer(i));
  values.push_back(Value::text("b"));
  values.push_back(Value::text("a"));
  values.push_back(Value::boolean(true));
  std::size_t pairs = 0, less = 0;
  for (const Value& a : values)
    for (const Value& b : values) {
      const bool expected = a.type == ValueType::string && b.type == ValueType::string ? a.string() < b.string()
                                                                                        : std::tie(a.type, a.x, a.i) < std::tie(b.type, b.x, b.i);
      ASSERT_EQ(value_less(a, b), expected) << a.str() << " < " << b.str();
      ++pairs;
      less += expected;
    }
  EXPECT_GT(pairs, 20000U);
  EXPECT_GT(less, pairs / 4);  // the order is not trivially false
}
