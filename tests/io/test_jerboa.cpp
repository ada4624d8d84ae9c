// Jerboa's own files: the sample modeler (.jme) read as rule schemes, its
// verdicts against hand derivations from the file and against the dynamic
// checker, the embedding-presence checks, the YAML round trip, the sample
// G-maps (.jba) and their corruptions, and bad input.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "checkers/embedding_consistency.hpp"
#include "checkers/embedding_conditions.hpp"
#include "checkers/embedding_presence.hpp"
#include "checkers/map_validity.hpp"
#include "analysis/fuzz.hpp"
#include "io/catalog.hpp"
#include "io/catalog_writer.hpp"
#include "core/input_error.hpp"
#include "io/jerboa_jba.hpp"
#include "io/jerboa_modeler.hpp"
#include "core/orbit.hpp"
#include "generators/shapes.hpp"

using namespace dartcheck;
namespace fs = std::filesystem;

namespace {

const std::string samples = std::string(DARTCHECK_SOURCE_DIR) + "/../shared/jerboa-samples/";

const Catalog& modeler() {
  static const Catalog c = read_jme(samples + "JerboaRebuilt2.jme");
  return c;
}

std::string slurp(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Writes `text` to a temporary file with the given extension.
std::string temp_file(const std::string& text, const std::string& ext) {
  static int n = 0;
  const fs::path p = fs::temp_directory_path() / fmt::format("dartcheck-jerboa-{}-{}{}", ::getpid(), n++, ext);
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

std::vector<std::string> failures(const CatalogRule& r) {
  std::vector<std::string> out;
  for (const auto& c : check_rule(r.rule, r.words).conditions)
    if (!c.holds) out.push_back(c.name());
  return out;
}

std::set<std::string> arcs(const TopoGraph& g, const std::vector<ConjWord>& words) {
  std::set<std::string> out;
  for (ArcId e = 0; e < g.arc_count(); ++e) {
    const auto& a = g.arc(e);
    out.insert(fmt::format("{} -{}:{}-> {}", g.name(a.source), arc_word(words, e).str(), a.label, g.name(a.target)));
  }
  return out;
}

}  // namespace

// Read from the file by hand: 17 rules, 3-G-maps, one embedding pos <1,2,3>.
// InsertVertex: L = n0 <2,3> -0- n1 <2,3> with n0 the hook, so each L node
// carries the implicit (2,2) and (3,3) loops plus the explicit 0-pair.
TEST(Jme, SampleModelerReadsAsJerboaSchemes) {
  const Catalog& c = modeler();
  EXPECT_EQ(c.modeler, "JerboaRebuilt");
  ASSERT_EQ(c.rules.size(), 17U);
  EXPECT_TRUE(c.skipped.empty());
  ASSERT_EQ(c.embeddings.size(), 1U);
  EXPECT_EQ(c.embeddings[0].name, "pos");
  EXPECT_EQ(c.embeddings[0].orbit, (std::vector<Dim>{1, 2, 3}));
  const CatalogRule& iv = *c.find_rule("InsertVertex");
  EXPECT_EQ(iv.rule.model().name, "3-gmap");
  EXPECT_TRUE(iv.words.scheme);
  EXPECT_EQ(arcs(iv.rule.left(), iv.words.left),
            (std::set<std::string>{"n0 -2:2-> n0", "n0 -3:3-> n0", "n1 -2:2-> n1", "n1 -3:3-> n1", "n0 -ε:0-> n1", "n1 -ε:0-> n0"}));
  ASSERT_EQ(iv.expressions.size(), 1U);
  EXPECT_EQ(iv.expressions[0].node, "n2");
  EXPECT_EQ(iv.expressions[0].code, "return Vec3.mid(n0.pos, n1.pos);");
  // Creation rules have no hook and the empty orbit type: plain DPO rules.
  const CatalogRule& cd = *c.find_rule("CreateDart");
  EXPECT_FALSE(cd.words.scheme);
  EXPECT_EQ(cd.rule.left().node_count(), 0U);
  EXPECT_EQ(arcs(cd.rule.right(), cd.words.right), (std::set<std::string>{"n0 -ε:0-> n0", "n0 -ε:1-> n0", "n0 -ε:2-> n0", "n0 -ε:3-> n0"}));
  // Two hooks, in <paramstopo> order.
  const CatalogRule& sew = *c.find_rule("SewA2");
  ASSERT_EQ(sew.rule.hooks().size(), 2U);
  EXPECT_EQ(sew.rule.left().name(sew.rule.hooks()[1]), "n1");
  // ChanfreinCoin2D's embedding parameter, <paramebd name="weight"
  // type="float">1</paramebd>, is read as the rule's parameter.
  const CatalogRule& ch = *c.find_rule("ChanfreinCoin2D");
  ASSERT_TRUE(ch.terms);
  EXPECT_EQ(ch.terms->parameters.at("weight"), Value::real(1));
  // Every expression of the file is read (18, counted with grep '<expr').
  std::size_t read = 0, all = 0;
  for (const auto& r : c.rules)
    for (const auto& x : r.expressions) {
      ++all;
      read += x.read();
    }
  EXPECT_EQ(all, 18U);
  EXPECT_EQ(read, 18U);
}

// The rules Jerboa ships as working operations pass the topological
// conditions, except two findings, each settled by the dynamic checker:
// ExtrudeEdge adds a 1- and a 3-arc at n0 whose 1- and 3-links L leaves
// unmatched (n0 is labeled <0>, with only an explicit 2-loop), so H has two
// 1-arcs at the hook: fuzz confirms it on a 1-dart map. DeleteFace deletes
// the <0,1,3> orbit without its 2-arcs (dangling(2)); every match is then
// refused, so no map is ever broken.
TEST(Jme, ShippedRulesPassOrAreSettledDynamically) {
  const Catalog& c = modeler();
  for (const char* name :
       {"InsertVertex", "SewA2", "UnSewA2", "CreateEdge", "CreateSquareFace", "RemoveEdge", "ExtrudeFaceEdge", "ExtrudeIndependantFace",
        "ExtrudeVolumeFace", "MergeEdge", "InsertEdge", "VertexCollapse", "ChanfreinCoin2D", "CreateCorner2D", "CreateDart"})
    EXPECT_TRUE(failures(*c.find_rule(name)).empty()) << name;
  EXPECT_EQ(failures(*c.find_rule("ExtrudeEdge")), (std::vector<std::string>{"I(1)", "I(3)"}));
  EXPECT_EQ(failures(*c.find_rule("DeleteFace")), (std::vector<std::string>{"dangling(2)"}));

  analysis::FuzzOptions o;
  o.runs = 3000;
  o.max_darts = 32;
  const auto extrude = analysis::fuzz_rule(*c.find_rule("ExtrudeEdge"), {}, o);
  ASSERT_TRUE(extrude.counterexample);
  EXPECT_EQ(extrude.verdict, analysis::FuzzClass::confirmed);
  Map scratch(Model::gmap(3));
  Refusal refusal = Refusal::none;
  EXPECT_TRUE(analysis::apply_and_check(*c.find_rule("ExtrudeEdge"), extrude.counterexample->host, extrude.counterexample->hooks, scratch, refusal));
  const auto del = analysis::fuzz_rule(*c.find_rule("DeleteFace"), {}, o);
  EXPECT_EQ(del.verdict, analysis::FuzzClass::unconfirmed);
  EXPECT_EQ(del.applications, 0U);
  // Every rule judged consistent, topology and values (003 Theorem 4 on
  // the read terms), survives the fuzzer, which computes the values.
  for (const auto& r : c.rules) {
    ASSERT_TRUE(r.terms) << r.rule.name();
    const bool embedding_holds = failing_names(check_term_conditions(r.rule, r.words, *r.terms)).empty();
    const auto verdict = analysis::fuzz_rule(r, {}, o).verdict;
    EXPECT_NE(verdict, analysis::FuzzClass::soundness_bug) << r.rule.name();
    if (failures(r).empty() && embedding_holds) {
      EXPECT_EQ(verdict, analysis::FuzzClass::consistent) << r.rule.name();
    }
  }
  // SewA2 joins two vertices of two volumes, each with its own position,
  // and computes none: the fuzzer finds the two values in one orbit.
  const auto sew = analysis::fuzz_rule(*c.find_rule("SewA2"), {}, o);
  EXPECT_EQ(sew.verdict, analysis::FuzzClass::confirmed);
  ASSERT_TRUE(sew.counterexample);
  EXPECT_EQ(sew.counterexample->broken_embeddings, (std::vector<std::string>{"pos"}));
}

// Presence checks, derived by hand from the file. pos is <1,2,3>.
// InsertVertex: added n2 -1- n3 form one pos-orbit (the 0-arcs to n0, n1
// do not count): no preserved node, but n2 carries an expression: holds.
// SewA2: n0 and n1 are separate pos-orbits of L, joined by the new 2-arc
// in R, with no expression: merge fails.
TEST(Jme, EmbeddingPresenceChecks) {
  const Catalog& c = modeler();
  auto check = [&](const CatalogRule& r) { return failing_names(check_embedding_presence(r.rule, r.words, c.embeddings, r.expressions)); };
  EXPECT_TRUE(check(*c.find_rule("InsertVertex")).empty());
  EXPECT_EQ(check(*c.find_rule("SewA2")), (std::vector<std::string>{"merge(pos)"}));
  // Without its expression InsertVertex's new vertex has no position.
  CatalogRule bare = *c.find_rule("InsertVertex");
  bare.expressions.clear();
  const auto v = check_embedding_presence(bare.rule, bare.words, c.embeddings, bare.expressions);
  ASSERT_EQ(failing_names(v), (std::vector<std::string>{"defined(pos)"}));
  EXPECT_EQ(v[0].witnesses.at(0).nodes, (std::vector<std::string>{"n2", "n3"}));
  // Two different expressions in one orbit.
  CatalogRule two = *c.find_rule("InsertVertex");
  two.expressions.push_back({"n3", "pos", "return n1.pos;", {}, std::nullopt, {}, {}});
  EXPECT_EQ(check(two), (std::vector<std::string>{"one-value(pos)"}));
  // An expression on one node of the merged orbit settles SewA2.
  CatalogRule sewn = *c.find_rule("SewA2");
  sewn.expressions.push_back({"n0", "pos", "return n0.pos;", {}, std::nullopt, {}, {}});
  EXPECT_TRUE(check(sewn).empty());
}

// .jme -> YAML -> catalog: the same nodes, arcs (with words), hooks,
// orbit types, expressions and caveats, hence the same verdicts.
TEST(Jme, YamlRoundTripIsIdentical) {
  const Catalog& c = modeler();
  const Catalog back = read_catalog(temp_file(catalog_yaml(c), ".yaml"));
  ASSERT_EQ(back.rules.size(), c.rules.size());
  EXPECT_EQ(back.modeler, c.modeler);
  ASSERT_EQ(back.embeddings.size(), c.embeddings.size());
  EXPECT_EQ(back.embeddings[0].orbit, c.embeddings[0].orbit);
  for (std::size_t k = 0; k < c.rules.size(); ++k) {
    const auto &a = c.rules[k], &b = back.rules[k];
    SCOPED_TRACE(a.rule.name());
    EXPECT_EQ(b.rule.name(), a.rule.name());
    EXPECT_EQ(arcs(b.rule.left(), b.words.left), arcs(a.rule.left(), a.words.left));
    EXPECT_EQ(arcs(b.rule.right(), b.words.right), arcs(a.rule.right(), a.words.right));
    EXPECT_EQ(b.rule.hooks(), a.rule.hooks());
    EXPECT_EQ(b.words.scheme, a.words.scheme);
    EXPECT_EQ(b.jerboa.has_value(), a.jerboa.has_value());
    if (a.jerboa && b.jerboa) {
      EXPECT_EQ(b.jerboa->right, a.jerboa->right);
    }
    EXPECT_EQ(b.expressions.size(), a.expressions.size());
    EXPECT_EQ(b.caveats, a.caveats);
    EXPECT_EQ(failures(b), failures(a));
    EXPECT_EQ(failing_names(check_embedding_presence(b.rule, b.words, back.embeddings, b.expressions)),
              failing_names(check_embedding_presence(a.rule, a.words, c.embeddings, a.expressions)));
  }
}

// Cells counted by hand from the shapes: a square pyramid, a cube, and a
// 4x4x4-vertex frame of 20 cubes (27 minus the centre and the 6 face
// centres). Each vertex has one position: pos-orbits = vertices.
TEST(Jba, SampleMapsAreValidEmbeddedThreeGmaps) {
  struct Expect {
    const char* file;
    std::size_t darts;
    std::vector<std::size_t> cells;
  };
  for (const auto& x :
       {Expect{"pyramid.jba", 32, {5, 8, 5, 1}}, Expect{"cube.jba", 48, {8, 12, 6, 1}}, Expect{"cube-frame.jba", 960, {64, 144, 96, 20}}}) {
    const JbaFile f = read_jba(samples + x.file);
    EXPECT_EQ(f.map.size(), x.darts) << x.file;
    EXPECT_TRUE(check_map(f.map).valid()) << x.file;
    EXPECT_EQ(count_cells(f.map).cells, x.cells) << x.file;
    for (const auto& e : f.embeddings) {
      const auto r = check_embedding(f.map, e);
      EXPECT_TRUE(r.consistent()) << x.file << " " << e.name;
      if (e.orbit == std::vector<Dim>{1, 2, 3}) {
        EXPECT_EQ(r.labeled, x.cells[0]) << x.file;
      }
    }
  }
}

// The writer: read, write, read again gives the same map (dart for dart:
// the sample files number their darts 0..n-1 in order) and the same
// value on every dart of every embedding; so does a map with an orbit of
// two values (the writer keeps both records) and one with unlabeled darts.
TEST(Jba, WriterRoundTrips) {
  for (const char* file : {"pyramid.jba", "cube.jba", "cube-frame.jba"}) {
    const JbaFile f = read_jba(samples + file);
    std::ostringstream out;
    write_jba(out, f, "out.jba");
    const JbaFile g = read_jba(temp_file(out.str(), ".jba"));
    EXPECT_TRUE(g.map == f.map) << file;
    ASSERT_EQ(g.embeddings.size(), f.embeddings.size()) << file;
    for (std::size_t k = 0; k < f.embeddings.size(); ++k) {
      EXPECT_EQ(g.embeddings[k].name, f.embeddings[k].name);
      EXPECT_EQ(g.embeddings[k].type, f.embeddings[k].type);
      EXPECT_EQ(g.embeddings[k].orbit, f.embeddings[k].orbit);
      EXPECT_EQ(g.embeddings[k].values, f.embeddings[k].values) << file << " " << f.embeddings[k].name;
    }
  }
  JbaFile f = read_jba(samples + std::string("cube.jba"));
  f.embeddings[0].values[0] = "9 9 9";  // dart 0's vertex now has two values
  f.embeddings[0].values[1].reset();    // and dart 1 none
  std::ostringstream out;
  write_jba(out, f, "out.jba");
  const JbaFile g = read_jba(temp_file(out.str(), ".jba"));
  EXPECT_EQ(g.embeddings[0].values, f.embeddings[0].values);
  // Only n-G-maps with every link fit the format.
  JbaFile o{"x", build_shape(Model::omap(2), {"cube", {}}), {}, {}};
  std::ostringstream sink;
  EXPECT_THROW(write_jba(sink, o, "o.jba"), InputError);
}

// Corruptions: one alpha_2 link redirected breaks the involution; one
// dart of a vertex moved to another value gives that orbit two values.
TEST(Jba, CorruptionsAreReported) {
  std::string text = slurp(samples + "cube.jba");
  // Dart 0's line "0 1 7 8 0": alpha_2 of 0 becomes 9 (9's alpha_2 is 14).
  std::string broken = replace_once(text, "\n0 1 7 8 0\n", "\n0 1 7 9 0\n");
  ASSERT_NE(broken, text);
  const JbaFile f = read_jba(temp_file(broken, ".jba"));
  EXPECT_FALSE(check_map(f.map).valid());
  // The first point record lists dart 0's vertex; give it its own value.
  std::string moved = replace_once(text, "\n0 8 9 14 13 7 \n0.0 0.0 0.0\n", "\n0 8 9 14 13 \n0.0 0.0 0.0\n7\n9.0 9.0 9.0\n");
  moved = replace_once(moved, "point 8", "point 9");
  ASSERT_NE(moved, text);
  const JbaFile g = read_jba(temp_file(moved, ".jba"));
  EXPECT_TRUE(check_map(g.map).valid());
  const auto r = check_embedding(g.map, g.embeddings[0]);
  ASSERT_EQ(r.conflicts.size(), 1U);
  EXPECT_EQ(r.conflicts[0].values.size(), 2U);
  EXPECT_EQ(r.conflicts[0].size, 6U);
}

namespace {

// The error's position for a corrupted sample, or "no error".
std::string error_of(const std::string& text, const std::string& ext) {
  try {
    if (ext == ".jme")
      read_jme(temp_file(text, ext));
    else
      read_jba(temp_file(text, ext));
  } catch (const InputError& e) {
    return fmt::format("{}:{}: {}", e.line(), e.column(), e.what());
  }
  return "no error";
}

}  // namespace

TEST(Jme, BadInputNamesThePosition) {
  const std::string text = slurp(samples + "JerboaRebuilt2.jme");
  EXPECT_NE(error_of(text.substr(0, text.size() / 2), ".jme").find("malformed XML"), std::string::npos);
  const auto orbit = error_of(replace_once(text, R"(orbit="2,3" kind="HOOK")", R"(orbit="2,x" kind="HOOK")"), ".jme");
  EXPECT_NE(orbit.find("unknown entry 'x'"), std::string::npos) << orbit;
  EXPECT_EQ(orbit.rfind("17:", 0), 0U) << orbit;  // MergeEdge's hook is on line 17
  const auto arc = error_of(replace_once(text, R"(<arc dim="0" a="n0" b="n1")", R"(<arc dim="0" a="n0" b="n9")"), ".jme");
  EXPECT_NE(arc.find("names node 'n9'"), std::string::npos) << arc;
  const auto dim = error_of(replace_once(text, R"(<arc dim="0" a="n0" b="n1")", R"(<arc dim="7" a="n0" b="n1")"), ".jme");
  EXPECT_NE(dim.find("arc dimension 7 is out of range"), std::string::npos) << dim;
  const auto modeler_dim = error_of(replace_once(text, R"(dimension="3")", R"(dimension="three")"), ".jme");
  EXPECT_NE(modeler_dim.find("modeler dimension"), std::string::npos) << modeler_dim;
  // Not errors: a multiplicity and a script skip their rule, a
  // precondition becomes a caveat.
  const Catalog m = read_jme(temp_file(replace_once(text, R"(multiplicity="{1}")", R"(multiplicity="{1,2}")"), ".jme"));
  ASSERT_EQ(m.skipped.size(), 1U);
  EXPECT_EQ(m.skipped[0].name, "MergeEdge");
  EXPECT_NE(m.skipped[0].why.find("multiplicity {1,2}"), std::string::npos);
  EXPECT_EQ(m.rules.size(), 16U);
  const Catalog p = read_jme(temp_file(replace_once(text, "<precondition></precondition>", "<precondition>return true;</precondition>"), ".jme"));
  ASSERT_EQ(p.rules.size(), 17U);
  ASSERT_FALSE(p.rules[0].caveats.empty());  // MergeEdge now has a precondition
  EXPECT_NE(p.rules[0].caveats[0].find("precondition"), std::string::npos);
  const Catalog s = read_jme(temp_file(replace_once(text, "</rules>", R"(<script name="Explode"><content>x</content></script></rules>)"), ".jme"));
  ASSERT_EQ(s.skipped.size(), 1U);
  EXPECT_EQ(s.skipped[0].name, "Explode");
  EXPECT_EQ(s.rules.size(), 17U);
}

TEST(Jba, BadInputNamesTheLine) {
  const std::string text = slurp(samples + "pyramid.jba");
  const auto dim = error_of(replace_once(text, "dimension 3", "dimension x"), ".jba");
  EXPECT_NE(dim.find("dimension: expected an integer, got 'x'"), std::string::npos) << dim;
  const auto link = error_of(replace_once(text, "\n0 7 1 12 0\n", "\n0 7 1 99 0\n"), ".jba");
  EXPECT_NE(link.find("names dart 99"), std::string::npos) << link;
  EXPECT_EQ(link.rfind("9:", 0), 0U) << link;  // dart 0 is on line 9
  const auto orbit = error_of(replace_once(text, "<a1, a2, a3>", "<a1, b2, a3>"), ".jba");
  EXPECT_NE(orbit.find("unknown entry 'b2'"), std::string::npos) << orbit;
  const auto cut = error_of(text.substr(0, text.find("\n20 ")), ".jba");
  EXPECT_NE(cut.find("the file ends"), std::string::npos) << cut;
}

// Issue 21: a rule whose nodes are all labeled '_' in every position (a
// rule on single darts, as real modelers write them) is the plain DPO rule
// on darts, not a skipped rule; a '_' hook with other labels stays skipped.
TEST(Jme, UnderscoreLabelsEverywhereArePlainRulesOnDarts) {
  const std::string text = slurp(samples + "JerboaRebuilt2.jme");
  const auto begin = text.find(R"(<rule name="MergeEdge")"), end = text.find("</rule>", begin);
  std::string merge = text.substr(begin, end - begin);
  std::string darts = merge;
  for (std::size_t at; (at = darts.find(R"(orbit="2,3")")) != std::string::npos;) darts.replace(at, 11, R"(orbit="-1,-1")");
  const Catalog c = read_jme(temp_file(text.substr(0, begin) + darts + text.substr(end), ".jme"));
  EXPECT_TRUE(c.skipped.empty());
  const CatalogRule* r = c.find_rule("MergeEdge");
  ASSERT_NE(r, nullptr);
  EXPECT_FALSE(r->jerboa.has_value());
  EXPECT_FALSE(r->words.scheme);
  // The file's explicit arcs only (3 pairs in L, 1 in R): no implicit loop.
  EXPECT_EQ(r->rule.left().node_count(), 4U);
  EXPECT_EQ(r->rule.right().node_count(), 2U);
  EXPECT_EQ(r->rule.left().arc_count(), 6U);
  EXPECT_EQ(r->rule.right().arc_count(), 2U);

  std::string mixed = merge;
  mixed.replace(mixed.find(R"(orbit="2,3" kind="HOOK")"), 11, R"(orbit="-1,-1")");
  const Catalog m = read_jme(temp_file(text.substr(0, begin) + mixed + text.substr(end), ".jme"));
  ASSERT_EQ(m.skipped.size(), 1U);
  EXPECT_NE(m.skipped[0].why.find("with '_'"), std::string::npos) << m.skipped[0].why;
}
