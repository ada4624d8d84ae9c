// Jerboa's expressions read as terms (io/jerboa_expression): the reader's
// term against a hand translation of the Java, for expressions of the two
// shipped modelers and for the constructs they use; the read terms
// evaluated against a direct evaluation of the Java on random maps; the
// subdivision rules of JerboaRebuilt.jme applied to the unit cube against
// positions derived by hand; opaque expressions and bad input.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <set>

#include "core/input_error.hpp"
#include "generators/random_embedding.hpp"
#include "generators/random_maps.hpp"
#include "io/catalog.hpp"
#include "io/jerboa_expression.hpp"
#include "io/jerboa_jba.hpp"
#include "io/jerboa_modeler.hpp"
#include "rewriting/application.hpp"
#include "rewriting/term_eval.hpp"

using namespace dartcheck;

namespace {

const std::string samples = std::string(DARTCHECK_SOURCE_DIR) + "/../shared/jerboa-samples/";
const std::string rebuilt = std::string(DARTCHECK_SOURCE_DIR) + "/tests/data/jerboa-rebuild/JerboaRebuilt.jme";

const Catalog& modeler1() {
  static const Catalog c = read_jme(rebuilt);
  return c;
}
const Catalog& modeler2() {
  static const Catalog c = read_jme(samples + "JerboaRebuilt2.jme");
  return c;
}

// The term of rule's expression on `node`, and a hand translation parsed
// and checked in the same scope.
struct Read {
  const Term* term = nullptr;
  Term hand;
};
Read read(const Catalog& c, const std::string& rule, const std::string& node, const std::string& embedding, const std::string& hand) {
  Read r;
  const CatalogRule* cr = c.find_rule(rule);
  EXPECT_NE(cr, nullptr) << rule;
  if (!cr) return r;
  for (const auto& x : cr->expressions)
    if (x.node == node && x.embedding == embedding) r.term = x.term ? &*x.term : nullptr;
  EXPECT_NE(r.term, nullptr) << rule << " " << node << ": not read";
  EXPECT_TRUE(cr->terms) << rule;
  if (!cr->terms) return r;
  TermScope scope{&cr->rule.model(), &cr->terms->embeddings, cr->rule.left().names(), cr->terms->parameters, nullptr};
  r.hand = parse_term(hand);
  check_term(r.hand, scope);
  return r;
}

}  // namespace

// 32 expressions of JerboaRebuilt.jme and JerboaRebuilt2.jme, translated
// by hand from the Java (Jerboa's Vec3 and the float literals' widening:
// 0.4f is 0.4000000059604645 as a double).
TEST(JerboaExpressions, ModelersReadAsTheHandTranslations) {
  struct Case {
    const Catalog& (*catalog)();
    const char *rule, *node, *embedding, *hand;
  };
  const Case cases[] = {
      {modeler1, "InsertVertex", "n2", "pos", "mid(n0.pos, n1.pos)"},
      {modeler1, "CreateCorner2D", "n1", "pos", "point3(1, 1, 0)"},
      {modeler1, "CreateDart", "n0", "pos", "point3(0.5, 0, 0.5)"},
      {modeler1, "ChamferCorner", "n1", "pos", "segment(n0.pos, n0.alpha0.pos, weight)"},
      {modeler1, "EdgeCollapse", "n1", "pos", "barycenter(pos<0,2,3>(n0))"},
      {modeler1, "ExtrudeEdge", "n1", "pos", "addn(n0.pos, 0, 1, 0)"},
      {modeler1, "TriangulateFace", "n2", "pos", "barycenter(pos<0,1>(n0))"},
      {modeler1, "EdgeFlip", "n13", "pos", "n7.pos"},
      {modeler1, "TriangulateVolume", "n3", "pos", "barycenter(pos<0,1,2>(n0))"},
      {modeler1, "PierceFace", "n2", "pos", "segment(n0.pos, barycenter(pos<0,1,3>(n0)), 0.4000000059604645)"},
      {modeler1, "InsertVertexUnfoldedV2", "n3", "pos", "barycenter(pos<0>(n0))"},
      {modeler1, "MakeFaceBlue", "n0", "color", "color(0, 0, 255)"},
      {modeler1, "FaceA3ToPyramid", "n1", "pos", "addn(barycenter(pos<0,1>(n0)), 0, 0, 1)"},
      {modeler1, "SubdivQuad", "n1", "pos", "segment(n0.pos, n0.alpha0.pos, 0.5)"},
      {modeler1, "SubdivQuad", "n3", "pos", "barycenter(pos<0,1>(n0))"},
      {modeler1, "TriPlusVerts", "n2", "pos", "segment(n0.pos, barycenter(pos<0,1>(n0)), 0.5)"},
      {modeler1, "CatmullClark", "n1", "pos",
       "div(addn(addn(mul(addn(n0.pos, n0.alpha0.pos), 0.5), barycenter(pos<0,1>(n0))), barycenter(pos<0,1>(n0.alpha2))), 3.0)"},
      {modeler1, "CatmullClark", "n0", "pos",
       "div(addn(addn(mul(div(addn(point3(0.0, 0.0, 0.0), sum(each(edge in <1,2>_<2>(n0): div(addn(edge.alpha0.pos, edge.pos), 2.0)))),"
       " count(each(d in <1,2>_<2>(n0): 0))), 2), barycenter(each(face in <1,2>(n0): barycenter(pos<0,1>(face))))),"
       " mul(n0.pos, count(each(d in <1,2>_<2>(n0): 0)) - 3)), count(each(d in <1,2>_<2>(n0): 0)))"},
      {modeler1, "DooSabin", "n0", "pos", "barycenter([barycenter(pos<0,1>(n0)), barycenter(pos<0>(n0)), barycenter(pos<0>(n0.alpha1)), n0.pos])"},
      {modeler1, "SplitVertex", "n0", "pos", "segment(n0.pos, n0.alpha0.pos, 0.33000001311302185)"},
      {modeler1, "InsertBorderEdge", "n1", "pos", "segment(n0.pos, n0.alpha0.pos, 0.30000001192092896)"},
      {modeler1, "ExtrudeIndependentFaceWithSide", "n4", "pos", "addn(n1.pos, 0, side, 0)"},
      {modeler1, "ExtrudeFaceToPyramid", "n3", "pos", "addn(barycenter(pos<0,1>(n0)), 0.0, height, 0.0)"},
      {modeler1, "ExtrudeVertexToBranch", "n12", "pos", "addn(n1.pos, -0.5, 0.5, 0.0)"},
      {modeler1, "VertexDualToFace", "n2", "pos", "point3(x(center) - vOffset, y(center), z(center) - vOffset)"},
      {modeler1, "CreateTriangle", "n5", "pos", "point3(1.0, 0.0, 0.5)"},
      {modeler2, "ChanfreinCoin2D", "n2", "pos", "segment(n0.pos, n0.alpha0.pos, weight)"},
      {modeler2, "VertexCollapse", "n2", "pos", "mid(n0.pos, n1.pos)"},
      {modeler2, "ExtrudeIndependantFace", "n3", "pos", "addn(n0.pos, 0, 0, 1)"},
      {modeler2, "InsertVertex", "n2", "pos", "mid(n0.pos, n1.pos)"},
      {modeler2, "CreateCorner2D", "n6", "pos", "point3(0.5, 1.5, 0)"},
      {modeler2, "ExtrudeEdge", "n3", "pos", "addn(n0.pos, 0, 1, 0)"},
  };
  std::size_t compared = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(fmt::format("{} {} {}", c.rule, c.node, c.embedding));
    const Read r = read(c.catalog(), c.rule, c.node, c.embedding, c.hand);
    if (!r.term) continue;
    EXPECT_TRUE(r.term->same(r.hand)) << "read: " << r.term->str() << "\nhand: " << r.hand.str();
    ++compared;
  }
  EXPECT_GE(compared, 32U);
}

// Constructs the modelers use in other combinations: locals, widening,
// casts, loops that build lists and sums, '@' chains, comments.
TEST(JerboaExpressions, ConstructsReadAsTheHandTranslations) {
  const Model model = Model::gmap(3);
  JerboaScope scope{&model, {{"pos", ValueType::point3, {1, 2, 3}}, {"col", ValueType::color, {0, 1}}}, {"n0", "n1"}, {{"w", Value::real(0.25)}}, {}};
  TermScope ts{&model, &scope.embeddings, scope.nodes, scope.parameters, nullptr};
  struct Case {
    const char *java, *hand;
  };
  const Case cases[] = {
      {"float f = 2; return n0.pos.mul(f);", "mul(n0.pos, real(2))"},
      {"int k = 3; return n0.pos.div(k - 1);", "div(n0.pos, 3 - 1)"},
      {"double d = (double) 3; return n0.pos.mul(d * w);", "mul(n0.pos, real(3) * w)"},
      {"return n0@2@1.pos;", "n0.alpha2.alpha1.pos"},
      {"return n0.alpha(2).pos;", "n0.alpha2.pos"},
      {"// the middle\nreturn /* of the edge */ Vec3.mid(n0.pos, n0@0.pos);", "mid(n0.pos, n0.alpha0.pos)"},
      {"List<Vec3> l = new ArrayList<>();\nfor (JerboaDart d : <0,1>(n0)) { l.add(d.pos); }\nVec3 r = new Vec3(); r.barycenter(l); return r;",
       "barycenter(each(d in <0,1>(n0): d.pos))"},
      {"Vec3 s = new Vec3();\nfor (JerboaDart e : <0,1>_<1>(n0)) s = s.addn(e.pos);\nreturn s;", "addn(point3(0.0, 0.0, 0.0), sum(each(e in <0,1>_<1>(n0): e.pos)))"},
      {"float t = 0;\nfor (JerboaDart e : <1,2>(n0)) { t += 1; }\nreturn n0.pos.mul(t);", "mul(n0.pos, real(0) + sum(each(e in <1,2>(n0): 1)))"},
      {"JerboaList<@ebd<pos>> l;\nl.add(n0.pos); l.add(n1.pos);\nVec3 r = new Vec3(); r.barycenter(l); return r;", "barycenter([n0.pos, n1.pos])"},
      {"JerboaDarts ds = <0,1>_<0>(n0);\nreturn n0.pos.mul(ds.size());", "mul(n0.pos, count(each(d in <0,1>_<0>(n0): 0)))"},
      {"return new Vec3(-0.5f, 2.0, 1e-1);", "point3(-0.5, 2.0, 0.1)"},
      // Java's integer literals: hexadecimal, octal (a leading 0), underscores.
      {"return n0.pos.mul(0x10 + 010 + 1_0);", "mul(n0.pos, 16 + 8 + 10)"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.java);
    const ReadExpression r = read_jerboa_expression(c.java, scope, ValueType::point3);
    ASSERT_TRUE(r.term) << r.reason;
    Term hand = parse_term(c.hand);
    check_term(hand, ts);
    EXPECT_TRUE(r.term->same(hand)) << "read: " << r.term->str() << "\nhand: " << hand.str();
  }
}

// Outside the part that is read: opaque, with the reason and where.
TEST(JerboaExpressions, OutsideThePartIsOpaqueWithItsReason) {
  const Model model = Model::gmap(3);
  JerboaScope scope{&model, {{"pos", ValueType::point3, {1, 2, 3}}}, {"n0"}, {}, {"ctl"}};
  struct Case {
    const char *java, *reason;
    std::size_t offset;
  };
  const Case cases[] = {
      {"return n0.pos.rotate(1);", "calls Vec3.rotate", 14},
      {"if (true) return n0.pos; return n0.pos;", "uses 'if'", 0},
      {"return Vec3.mid(n0.pos, new Vec3(Math.sqrt(2), 0, 0));", "calls Math.sqrt", 38},
      {"return gmap.getNode(0).pos;", "reads Jerboa's runtime object 'gmap'", 7},
      {"Vec3 r = n0.pos; for (JerboaDart d : <0>(n0)) r = d.pos; return r;", "assigns 'r' in its loop: its value would be the last iteration's", 17},
      {"return n0.pos.mul(ctl);", "reads the parameter 'ctl', whose type or value dartcheck does not read", 18},
      {"Vec3 r = new Vec3(); r.barycenter(<0,1>_pos(n0));", "has no return statement", 49},
      {"return \"x\";", "uses a string or character literal", 7},
      {"return n0.pos.addn(1, 2);", "calls Vec3.addn", 14},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.java);
    const ReadExpression r = read_jerboa_expression(c.java, scope, ValueType::point3);
    EXPECT_FALSE(r.term);
    EXPECT_EQ(r.reason, c.reason);
    EXPECT_EQ(r.offset, c.offset);
  }
}

// What no Jerboa editor accepts: an error at the offending character.
TEST(JerboaExpressions, CodeNoModelerAcceptsIsAnError) {
  const Model model = Model::gmap(3);
  JerboaScope scope{&model, {{"pos", ValueType::point3, {1, 2, 3}}}, {"n0"}, {{"w", Value::real(1)}}, {}};
  struct Case {
    const char *java, *message;
    std::size_t offset;
  };
  const Case cases[] = {
      {"return (n0.pos;", "not Java: '(' is never closed", 7},
      {"return n0.pos); }", "not Java: ')' closes nothing", 13},
      {"return n0.pos # 2;", "not Java: unexpected character '#'", 14},
      {"return n0.foo;", "n0.foo: the modeler declares no embedding 'foo' (embeddings: pos)", 10},
      {"return n0@4.pos;", "n0@4: 4 is not a dimension of the model 3-gmap", 10},
      {"return n0.pos.mul(weight);", "'weight' is neither a variable, a node of the left side (n0) nor a parameter of the rule", 18},
      {"return <0,7>_pos(n0);", "orbit type: 7 is not a dimension of the model 3-gmap", 10},
      {"return \"abc;", "not Java: a string literal that is never closed", 7},
      {"return n0.pos.mul(079);", "not Java: '079' is not an octal number", 18},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.java);
    try {
      read_jerboa_expression(c.java, scope, ValueType::point3);
      ADD_FAILURE() << "read without an error";
    } catch (const JerboaCodeError& e) {
      EXPECT_EQ(std::string(e.what()), c.message);
      EXPECT_EQ(e.offset(), c.offset);
    }
  }
}

// Integers are exact: past 64 bits a term has no value (found by
// fuzz_jerboa_expression as a signed overflow, undefined behaviour, in
// 0775*050*...*0777777079).
TEST(JerboaExpressions, IntegerOverflowHasNoValue) {
  const Model model = Model::gmap(3);
  JerboaScope scope{&model, {{"pos", ValueType::point3, {1, 2, 3}}}, {"n0"}, {}, {}};
  EmbeddedMap g(Map(model, 1));
  g.add_embedding(scope.embeddings[0]);
  g.label_orbit(0, 0, Value::coords(ValueType::point3, {1, 2, 3}));
  TermEvaluator ev(g);
  const std::vector<std::string> names{"n0"};
  const std::vector<Dart> darts{0};
  for (const char* java : {"return n0.pos.mul(9223372036854775807 * 2);", "return n0.pos.mul(-9223372036854775807 - 2);",
                           "return n0.pos.mul(9223372036854775807 + 1);"}) {
    SCOPED_TRACE(java);
    const ReadExpression r = read_jerboa_expression(java, scope, ValueType::point3);
    ASSERT_TRUE(r.term) << r.reason;
    EXPECT_THROW(ev.value(*r.term, names, darts), EvaluationError);
  }
  const ReadExpression fine = read_jerboa_expression("return n0.pos.mul(3037000499 * 3037000499);", scope, ValueType::point3);
  ASSERT_TRUE(fine.term);
  EXPECT_EQ(ev.value(*fine.term, names, darts).x[0], 9223372030926249001.0);
}

// In a .jme, the error names the rule, the node and the file position of
// the offending character (line 3 of the expression's text: after two
// lines and an entity, &lt;, that the file spells with four characters).
TEST(JerboaExpressions, ErrorsInAModelerNameRuleNodeAndPosition) {
  std::string text;
  {
    std::ifstream in(samples + "JerboaRebuilt2.jme", std::ios::binary);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string from = "return Vec3.mid(n0.pos, n1.pos);";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, from.size(), "Vec3 a = new Vec3(); // &lt;1&gt;\nVec3 b = a;\n  return a.addn(n0.bad);");
  const auto p = std::filesystem::temp_directory_path() / fmt::format("dartcheck-jme-expr-{}.jme", ::getpid());
  std::ofstream(p, std::ios::binary) << text;
  std::size_t line = 1, column = 1;
  const std::size_t bad = text.find("n0.bad") + 3;
  for (std::size_t k = 0; k < bad; ++k) {
    column = text[k] == '\n' ? 1 : column + 1;
    line += text[k] == '\n';
  }
  try {
    read_jme(p.string());
    ADD_FAILURE() << "read without an error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), static_cast<int>(line));
    EXPECT_EQ(e.column(), static_cast<int>(column));
    EXPECT_NE(std::string(e.what()).find("rule 'InsertVertex', node 'n2', expression for pos: n0.bad: the modeler declares no embedding 'bad'"),
              std::string::npos)
        << e.what();
  }
  std::filesystem::remove(p);
}

// --- The read terms against the Java they come from -------------------------

namespace {

using P = std::array<double, 3>;

// The Java of the modelers, evaluated directly on a map: Jerboa's
// traversals (every dart of an orbit, breadth first from the start; one
// dart per sub-orbit) and Vec3's arithmetic, in the Java's order, in
// double precision. Independent of the term evaluator: its own walks.
struct Java {
  const Map& map;
  std::function<P(Dart)> pos;

  std::vector<Dart> orbit(Dart d, const std::vector<Dim>& dims) const {
    std::vector<Dart> out{d};
    std::set<Dart> seen{d};
    for (std::size_t k = 0; k < out.size(); ++k)
      for (Dim i : dims) {
        const Dart n = map.link(i, out[k]);
        if (n != no_dart && seen.insert(n).second) out.push_back(n);
      }
    return out;
  }
  // One dart per <sub>-orbit inside the <dims>-orbit of d.
  std::vector<Dart> per_sub(Dart d, const std::vector<Dim>& dims, const std::vector<Dim>& sub) const {
    std::vector<Dart> out;
    std::set<Dart> covered;
    for (Dart x : orbit(d, dims)) {
      if (covered.count(x)) continue;
      out.push_back(x);
      for (Dart y : orbit(x, sub)) covered.insert(y);
    }
    return out;
  }
  // <dims>_pos(d): one position per vertex (<1,2,3> ∩ dims) of the orbit.
  std::vector<P> collect(Dart d, const std::vector<Dim>& dims) const {
    std::vector<Dim> sub;
    for (Dim i : dims)
      if (i >= 1) sub.push_back(i);
    std::vector<P> out;
    for (Dart x : per_sub(d, dims, sub)) out.push_back(pos(x));
    return out;
  }
  static P barycenter(const std::vector<P>& l) {
    P r{0, 0, 0};
    for (const P& v : l)
      for (int k = 0; k < 3; ++k) r[k] += v[k];
    for (int k = 0; k < 3; ++k) r[k] /= static_cast<double>(l.size());
    return r;
  }
  static P addn(P a, P b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
  static P mul(P a, double m) { return {a[0] * m, a[1] * m, a[2] * m}; }
  static P div(P a, double m) { return {a[0] / m, a[1] / m, a[2] / m}; }
  static P segment(P a, P b, double w) { return {a[0] + (b[0] - a[0]) * w, a[1] + (b[1] - a[1]) * w, a[2] + (b[2] - a[2]) * w}; }

  P catmull_clark_vertex(Dart n0) const {
    std::vector<P> faces;
    for (Dart face : orbit(n0, {1, 2})) faces.push_back(barycenter(collect(face, {0, 1})));
    const P f = barycenter(faces);
    const std::vector<Dart> edges = per_sub(n0, {1, 2}, {2});
    const int k = static_cast<int>(edges.size());
    P r{0, 0, 0};
    for (Dart edge : edges) r = addn(r, div(addn(pos(map.link(0, edge)), pos(edge)), 2.0));
    r = div(r, k);
    return div(addn(addn(mul(r, 2), f), mul(pos(n0), k - 3)), k);
  }
  P catmull_clark_edge(Dart n0) const {
    const P fp0 = barycenter(collect(n0, {0, 1})), fp1 = barycenter(collect(map.link(2, n0), {0, 1}));
    return div(addn(addn(mul(addn(pos(n0), pos(map.link(0, n0))), 0.5), fp0), fp1), 3.0);
  }
  P doo_sabin(Dart n0) const {
    const std::vector<P> l{barycenter(collect(n0, {0, 1})), barycenter(collect(n0, {0})), barycenter(collect(map.link(1, n0), {0})), pos(n0)};
    return barycenter(l);
  }
};

bool close(const Value& v, const P& p) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(v.x[k] - p[k]) > 1e-12 * (1 + std::abs(p[k]))) return false;
  return true;
}

const Term& term_of(const char* rule, const char* node) {
  for (const auto& x : modeler1().find_rule(rule)->expressions)
    if (x.node == node) return *x.term;
  throw std::logic_error("no such expression");
}

}  // namespace

// Property: on every map, at every dart, a read term has the value the
// Java expression computes (Jerboa's traversal order against the term's
// canonical multisets: equal up to the sums' rounding, 1e-12 relative).
// Random closed 3-G-maps of up to 12 faces, random positions per vertex.
TEST(JerboaExpressions, ReadTermsComputeWhatTheJavaComputes) {
  std::mt19937 rng(20261128);
  const Model model = Model::gmap(3);
  const EmbeddingSignature pos{"pos", ValueType::point3, {1, 2, 3}};
  struct Expression {
    const char *rule, *node;
    std::function<P(const Java&, Dart)> java;
  };
  const double w = static_cast<double>(0.5F);
  const std::vector<Expression> expressions{
      {"SubdivQuad", "n1", [&](const Java& j, Dart d) { return Java::segment(j.pos(d), j.pos(j.map.link(0, d)), w); }},
      {"SubdivQuad", "n3", [](const Java& j, Dart d) { return Java::barycenter(j.collect(d, {0, 1})); }},
      {"InsertVertex", "n2", [](const Java& j, Dart d) { return Java::div(Java::addn(j.pos(d), j.pos(j.map.link(0, d))), 2); }},
      {"CatmullClark", "n0", [](const Java& j, Dart d) { return j.catmull_clark_vertex(d); }},
      {"CatmullClark", "n1", [](const Java& j, Dart d) { return j.catmull_clark_edge(d); }},
      {"DooSabin", "n0", [](const Java& j, Dart d) { return j.doo_sabin(d); }},
      {"PierceFace", "n2",
       [](const Java& j, Dart d) { return Java::segment(j.pos(d), Java::barycenter(j.collect(d, {0, 1, 3})), static_cast<double>(0.4F)); }},
      {"TriangulateVolume", "n3", [](const Java& j, Dart d) { return Java::barycenter(j.collect(d, {0, 1, 2})); }},
  };
  std::size_t compared = 0;
  for (int round = 0; round < 40; ++round) {
    Map m = build_random_map(model, draw_recipe(rng, static_cast<std::uint32_t>(1 + round % 12), 3));
    if (m.size() == 0) continue;
    const EmbeddedMap g = embed_randomly(std::move(m), {pos}, rng);
    TermEvaluator ev(g);
    const Java java{g.map, [&](Dart d) {
                      const Value* v = g.embeddings[0].value(d);
                      return P{v->x[0], v->x[1], v->x[2]};
                    }};
    for (const auto& e : expressions) {
      const Term& t = term_of(e.rule, e.node);
      const auto names = modeler1().find_rule(e.rule)->rule.left().names();
      for (Dart d = 0; d < g.map.size(); d += 3) {
        // n0 (and InsertVertex's n1, its 0-neighbour) bound at d.
        std::vector<Dart> darts(names.size(), d);
        for (std::size_t k = 0; k < names.size(); ++k)
          if (names[k] == "n1") darts[k] = g.map.link(0, d);
        Value v;
        try {
          v = ev.value(t, names, darts);
        } catch (const EvaluationError& x) {
          ADD_FAILURE() << e.rule << " " << e.node << " at dart " << d << ": " << x.what();
          continue;
        }
        const P want = e.java(java, d);
        EXPECT_TRUE(close(v, want)) << e.rule << " " << e.node << " at dart " << d << ": term " << v.str() << ", Java " << want[0] << " "
                                    << want[1] << " " << want[2];
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 2000U);
}

// --- The subdivision rules on the unit cube ----------------------------------

namespace {

// cube.jba with its `point` positions as the modeler's `pos`, and the
// modeler's other embeddings (color per face, norm per dart) drawn.
EmbeddedMap unit_cube(const CatalogRule& rule, std::mt19937& rng) {
  const JbaFile f = read_jba(samples + "cube.jba");
  EmbeddedMap g(f.map);
  for (const auto& sig : rule.terms->embeddings) {
    if (sig.name == "pos") {
      MapEmbedding m = f.embeddings[0];
      EXPECT_EQ(m.name, "point");
      m.type = "point3";
      std::string why;
      auto e = typed_embedding(m, &why);
      EXPECT_TRUE(e) << why;
      e->signature.name = "pos";
      g.embeddings.push_back(std::move(*e));
    } else {
      g.embeddings.push_back(embed_randomly(g.map, {sig}, rng).embeddings[0]);
    }
  }
  return g;
}

// The positions of H's vertices (one per <1,2,3>-orbit), sorted; every
// dart of a vertex must hold its vertex's value.
std::vector<P> vertex_positions(const EmbeddedMap& h) {
  const Embedding* pos = h.find("pos");
  std::vector<P> out;
  std::vector<bool> seen(h.map.size());
  for (Dart d = 0; d < h.map.size(); ++d) {
    if (seen[d]) continue;
    std::vector<Dart> orbit{d};
    seen[d] = true;
    for (std::size_t k = 0; k < orbit.size(); ++k)
      for (Dim i : {1, 2, 3}) {
        const Dart n = h.map.link(i, orbit[k]);
        if (!seen[n]) {
          seen[n] = true;
          orbit.push_back(n);
        }
      }
    const Value* v = pos->value(d);
    EXPECT_NE(v, nullptr) << "dart " << d;
    if (!v) continue;
    for (Dart x : orbit) EXPECT_EQ(*pos->value(x), *v) << "dart " << x << " of the vertex of dart " << d;
    out.push_back({v->x[0], v->x[1], v->x[2]});
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Every point whose coordinates are drawn from `values`, kept by `keep`.
std::vector<P> grid(const std::vector<double>& values, const std::function<bool(const P&)>& keep) {
  std::vector<P> out;
  for (double x : values)
    for (double y : values)
      for (double z : values)
        if (keep({x, y, z})) out.push_back({x, y, z});
  std::sort(out.begin(), out.end());
  return out;
}

void expect_positions(const std::vector<P>& got, const std::vector<P>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t k = 0; k < got.size(); ++k)
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[k][i], want[k][i], 1e-12) << "vertex " << k;
}

EmbeddedMap applied_everywhere(const char* rule_name) {
  const CatalogRule& rule = *modeler1().find_rule(rule_name);
  std::mt19937 rng(7);
  EmbeddedMap g = unit_cube(rule, rng);
  const std::vector<Dart> hook{0};  // the hook orbit <0,1,2,3>: the whole cube
  const auto r = Applier(rule).apply(g, hook);
  EXPECT_TRUE(r.ok()) << r.why;
  return g;
}

}  // namespace

// SubdivQuad: each face into four quads; new vertices at the edges'
// segmentABByWeight(a, b, 0.5f) (the midpoints) and the faces' barycenters.
// The unit cube's 26 points of {0, 1/2, 1}^3 but its center.
TEST(JerboaSubdivision, SubdivQuadOnTheCubeGivesMidpointsAndFaceCenters) {
  const EmbeddedMap h = applied_everywhere("SubdivQuad");
  EXPECT_EQ(h.map.size(), 192U);
  expect_positions(vertex_positions(h), grid({0, 0.5, 1}, [](const P& p) { return !(p[0] == 0.5 && p[1] == 0.5 && p[2] == 0.5); }));
}

// This modeler's Catmull-Clark: a corner (valence k = 3) moves to
// (2R + F + (k-3)P)/k with F the mean of its 3 face centers and R of its 3
// edge midpoints: (0,0,0) -> F = (1/3,1/3,1/3), R = (1/6,1/6,1/6), so
// (2/9, 2/9, 2/9). An edge point is ((P0+P1)/2 + F0 + F1)/3 (not the
// textbook's (P0+P1+F0+F1)/4): edge (0,0,0)-(1,0,0), faces y=0 and z=0:
// ((1/2,0,0) + (1/2,0,1/2) + (1/2,1/2,0))/3 = (1/2, 1/6, 1/6). Face
// points are the face centers.
TEST(JerboaSubdivision, CatmullClarkOnTheCubeGivesThisModelersPoints) {
  const EmbeddedMap h = applied_everywhere("CatmullClark");
  EXPECT_EQ(h.map.size(), 192U);
  std::vector<P> want = grid({2.0 / 9, 7.0 / 9}, [](const P&) { return true; });  // 8 corners
  for (const P& e : grid({0.5, 1.0 / 6, 5.0 / 6}, [](const P& p) {  // 12 edge points: one coordinate 1/2
         return (p[0] == 0.5) + (p[1] == 0.5) + (p[2] == 0.5) == 1;
       }))
    want.push_back(e);
  for (const P& f : grid({0, 0.5, 1}, [](const P& p) {  // 6 face centers: two coordinates 1/2
         return (p[0] == 0.5) + (p[1] == 0.5) + (p[2] == 0.5) == 2;
       }))
    want.push_back(f);
  std::sort(want.begin(), want.end());
  ASSERT_EQ(want.size(), 26U);
  expect_positions(vertex_positions(h), want);
}

// Doo-Sabin: each corner of each face becomes the mean of the face
// center, the two edge midpoints at the corner and the corner: corner
// (0,0,0) of face z=0 -> ((1/2,1/2,0) + (1/2,0,0) + (0,1/2,0) + 0)/4 =
// (1/4, 1/4, 0). 24 points: one coordinate 0 or 1, two in {1/4, 3/4}.
TEST(JerboaSubdivision, DooSabinOnTheCubeGivesTheCornerPoints) {
  const EmbeddedMap h = applied_everywhere("DooSabin");
  EXPECT_EQ(h.map.size(), 192U);
  expect_positions(vertex_positions(h), grid({0, 0.25, 0.75, 1}, [](const P& p) {
                     const int plane = (p[0] == 0 || p[0] == 1) + (p[1] == 0 || p[1] == 1) + (p[2] == 0 || p[2] == 1);
                     return plane == 1;
                   }));
}

// TriangulateFace at each of the six faces (its hook orbit <0,1> is one
// face; darts of G keep their ids, as no node of L is deleted): the 8
// corners and the 6 face centers.
TEST(JerboaSubdivision, TriangulateFaceAtEveryFaceAddsTheFaceCenters) {
  const CatalogRule& rule = *modeler1().find_rule("TriangulateFace");
  std::mt19937 rng(7);
  EmbeddedMap g = unit_cube(rule, rng);
  std::vector<Dart> faces;  // a dart per face of the cube
  std::vector<bool> seen(g.map.size());
  for (Dart d = 0; d < g.map.size(); ++d) {
    if (seen[d]) continue;
    faces.push_back(d);
    std::vector<Dart> f{d};
    seen[d] = true;
    for (std::size_t k = 0; k < f.size(); ++k)
      for (Dim i : {0, 1})
        if (const Dart n = g.map.link(i, f[k]); !seen[n]) {
          seen[n] = true;
          f.push_back(n);
        }
  }
  ASSERT_EQ(faces.size(), 6U);
  for (Dart f : faces) {
    const std::vector<Dart> hook{f};
    const auto r = Applier(rule).apply(g, hook);
    ASSERT_TRUE(r.ok()) << r.why;
  }
  EXPECT_EQ(g.map.size(), 48U * 3);  // each dart of a face gets two more
  expect_positions(vertex_positions(g), grid({0, 0.5, 1}, [](const P& p) {
                     const int halves = (p[0] == 0.5) + (p[1] == 0.5) + (p[2] == 0.5);
                     return halves == 0 || halves == 2;
                   }));
}
