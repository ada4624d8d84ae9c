// Pictures: the DOT of every rule with failing conditions highlights the
// checker's witnesses (read back with Graphviz's own parser, cgraph), and
// every seed rule and a map render to well-formed SVG with one node per
// rule node or dart (read with pugixml).
#include <gtest/gtest.h>

#include <graphviz/cgraph.h>
#include <pugixml.hpp>

#include <memory>
#include <set>

#include "checkers/rule_conditions.hpp"
#include "core/catalog.hpp"
#include "core/graph_derivation.hpp"
#include "generators/shapes.hpp"
#include "reports/graph_dot.hpp"
#include "reports/render.hpp"
#include "reports/rule_dot.hpp"

using namespace dartcheck;

namespace {

const Catalog& seed_catalog() {
  static const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  return c;
}

using Graph = std::unique_ptr<Agraph_t, int (*)(Agraph_t*)>;

Graph parse(const std::string& dot) { return Graph(agmemread(dot.c_str()), agclose); }

// Names of the nodes (and "source->target" of the edges) that carry
// attr="true".
std::set<std::string> marked(Agraph_t* g, const char* attr) {
  std::set<std::string> out;
  for (Agnode_t* n = agfstnode(g); n; n = agnxtnode(g, n)) {
    const char* v = agget(n, const_cast<char*>(attr));
    if (v && std::string(v) == "true") out.insert(agnameof(n));
    for (Agedge_t* e = agfstout(g, n); e; e = agnxtout(g, e)) {
      const char* ev = agget(e, const_cast<char*>(attr));
      if (ev && std::string(ev) == "true") out.insert(std::string(agnameof(agtail(e))) + "->" + agnameof(aghead(e)));
    }
  }
  return out;
}

std::size_t svg_nodes(const std::string& svg) {
  pugi::xml_document doc;
  const auto r = doc.load_string(svg.c_str());
  EXPECT_TRUE(r) << r.description();
  return doc.select_nodes("//g[@class='node']").size();
}

}  // namespace

// Every node a witness names, on its side, is highlighted; so is every
// arc a witness names (when the arc is drawn: completion arcs of the
// cycle condition are not); nothing else is.
TEST(RuleDot, BrokenVariantsHighlightTheirWitnesses) {
  int rules = 0, with_arcs = 0;
  for (const auto& e : seed_catalog().rules) {
    const RuleVerdict v = check_rule(e.rule, e.words);
    if (v.consistent()) continue;
    ++rules;
    const auto witnesses = reports::failed_witnesses(v);
    const Graph g = parse(reports::rule_dot(e.rule, e.words, witnesses));
    ASSERT_TRUE(g) << e.rule.name();
    const std::set<std::string> lit = marked(g.get(), "witness");
    std::set<std::string> named;
    for (const auto& w : witnesses)
      for (const auto& n : w.nodes) {
        const std::string id = std::string(1, w.side) + ":" + n;
        named.insert(id);
        EXPECT_TRUE(lit.contains(id)) << e.rule.name() << ": witness node " << id << " not highlighted";
      }
    bool arcs = false;
    for (const auto& x : lit) arcs = arcs || x.find("->") != std::string::npos;
    with_arcs += arcs;
    for (const auto& x : lit) {
      if (x.find("->") != std::string::npos) continue;
      // A highlighted node is named by a witness or lies on a witness arc.
      bool on_arc = named.contains(x);
      for (const auto& w : witnesses)
        for (const auto& a : w.arcs)
          on_arc = on_arc || (x[0] == w.side && a.find(x.substr(2)) != std::string::npos);
      EXPECT_TRUE(on_arc) << e.rule.name() << ": " << x << " highlighted but in no witness";
    }
    EXPECT_FALSE(lit.empty()) << e.rule.name() << ": a failing rule with nothing highlighted";
  }
  EXPECT_GE(rules, 50);
  EXPECT_GE(with_arcs, 20);
}

TEST(RuleSvg, EverySeedRuleRendersWithOneNodePerRuleNode) {
  for (const auto& e : seed_catalog().rules) {
    const std::string svg = reports::render(reports::rule_dot(e.rule, e.words), "svg");
    EXPECT_EQ(svg_nodes(svg), e.rule.left().node_count() + e.rule.right().node_count()) << e.rule.name();
  }
}

// A G-map's links are involutions: each pair of darts is one undirected
// edge, and each dart one node.
TEST(MapSvg, CubeRendersOneNodePerDartAndOneEdgePerPair) {
  const Map cube = build_shape(Model::gmap(2), parse_shape("cube"));
  const TopoGraph g = to_graph(cube);
  reports::GraphPicture p;
  p.title = "cube";
  const std::string dot = reports::graph_dot(g, cube.model(), p);
  const Graph parsed = parse(dot);
  ASSERT_TRUE(parsed);
  EXPECT_EQ(static_cast<std::size_t>(agnnodes(parsed.get())), cube.size());
  std::size_t pairs = 0;
  for (const auto& a : g.arcs()) pairs += a.source <= a.target;  // one per involution pair, loops once
  EXPECT_EQ(static_cast<std::size_t>(agnedges(parsed.get())), pairs);
  EXPECT_EQ(svg_nodes(reports::render(dot, "svg")), cube.size());
}

TEST(Render, BadDotAndUnknownFormatAreErrorsNotCrashes) {
  EXPECT_THROW(reports::render("digraph { a -> ", "svg"), std::runtime_error);
  EXPECT_THROW(reports::render("digraph { a -> b }", "nosuchformat"), std::runtime_error);
  EXPECT_THROW(reports::format_of("picture.txt"), std::invalid_argument);
  EXPECT_EQ(reports::format_of("x.gv"), "dot");
}
