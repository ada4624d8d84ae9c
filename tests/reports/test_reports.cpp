// Pictures: the DOT of every rule with failing conditions highlights the
// checker's witnesses (read back with Graphviz's own parser, cgraph),
// every seed rule and a map render to well-formed SVG with one node per
// rule node or dart (read with pugixml), Jerboa nodes show their orbit
// types, and a counterexample's three panels highlight the match and the
// broken darts.
#include <gtest/gtest.h>

#include <graphviz/cgraph.h>
#include <pugixml.hpp>

#include <algorithm>
#include <array>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "checkers/embedding_conditions.hpp"
#include "checkers/rule_conditions.hpp"
#include "io/catalog.hpp"
#include "rewriting/graph_derivation.hpp"
#include "generators/shapes.hpp"
#include "reports/condition_help.hpp"
#include "reports/counterexample_dot.hpp"
#include "reports/graph_dot.hpp"
#include "reports/dot_text.hpp"
#include "reports/render.hpp"
#include "reports/rule_dot.hpp"
#include "reports/svg_figure.hpp"

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

// The SVG's nodes but a rule picture's two frames (nodes named L:#frame
// and R:#frame, drawn under each side).
std::size_t svg_nodes(const std::string& svg) {
  pugi::xml_document doc;
  const auto r = doc.load_string(svg.c_str());
  EXPECT_TRUE(r) << r.description();
  std::size_t n = 0;
  for (const auto& node : doc.select_nodes("//g[@class='node']"))
    n += !std::string_view(node.node().child_value("title")).ends_with("#frame");
  return n;
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
        for (const auto& a : w.arcs) on_arc = on_arc || (x[0] == w.side && a.find(x.substr(2)) != std::string::npos);
      EXPECT_TRUE(on_arc) << e.rule.name() << ": " << x << " highlighted but in no witness";
    }
    EXPECT_FALSE(lit.empty()) << e.rule.name() << ": a failing rule with nothing highlighted";
  }
  EXPECT_GE(rules, 50);
  EXPECT_GE(with_arcs, 20);
}

// One visual channel per meaning (issue 39): a node's or arc's line style
// says what the rule does to it (deleted: in L only, dashed; added: in R
// only, bold; preserved: solid), an arc's colour is its dimension, and the
// caption names every failing condition. Read back from the DOT with
// cgraph, against the rule's own node and arc sets.
TEST(RuleDot, StyleSaysWhatHappensColourSaysTheDimensionCaptionSaysWhatFails) {
  int edges = 0, captions = 0;
  for (const auto& e : seed_catalog().rules) {
    const RuleVerdict v = check_rule(e.rule, e.words);
    const Graph g = parse(reports::rule_dot(e.rule, e.words, reports::failed_witnesses(v), nullptr, {}, reports::failure_captions(v)));
    ASSERT_TRUE(g) << e.rule.name();
    for (const bool left : {true, false}) {
      const TopoGraph& side = left ? e.rule.left() : e.rule.right();
      const std::string prefix = left ? "L:" : "R:";
      for (NodeId n = 0; n < side.node_count(); ++n) {
        Agnode_t* node = agnode(g.get(), const_cast<char*>((prefix + side.name(n)).c_str()), 0);
        ASSERT_NE(node, nullptr) << e.rule.name() << " " << prefix << side.name(n);
        const bool kept = left ? e.rule.to_right(n) != no_node : e.rule.to_left(n) != no_node;
        const std::string style = agget(node, const_cast<char*>("style"));
        EXPECT_EQ(style.find("dashed") != std::string::npos, left && !kept) << e.rule.name() << " " << prefix << side.name(n) << " " << style;
        EXPECT_EQ(style.find("bold") != std::string::npos, !left && !kept) << e.rule.name() << " " << prefix << side.name(n) << " " << style;
        for (Agedge_t* x = agfstout(g.get(), node); x; x = agnxtout(g.get(), x)) {
          const std::string head = agnameof(aghead(x));
          if (!head.starts_with(prefix)) continue;
          const std::string color = agget(x, const_cast<char*>("color"));
          bool dimension = false;
          for (ArcId a = 0; a < side.arc_count(); ++a) {
            const auto& arc = side.arc(a);
            const bool ends = (side.name(arc.source) == side.name(n) && prefix + side.name(arc.target) == head) ||
                              (side.name(arc.target) == side.name(n) && prefix + side.name(arc.source) == head);
            dimension = dimension || (ends && color.starts_with(std::string(reports::dimension_color(arc.label))));
          }
          EXPECT_TRUE(dimension) << e.rule.name() << ": edge " << prefix << side.name(n) << " -> " << head << " coloured " << color;
          ++edges;
        }
      }
    }
    const std::string label = agget(g.get(), const_cast<char*>("label"));
    for (const auto& c : v.conditions)
      if (!c.holds) {
        EXPECT_NE(label.find("fails " + c.name()), std::string::npos) << e.rule.name() << ": caption does not name " << c.name();
        ++captions;
      }
  }
  EXPECT_GT(edges, 300);
  EXPECT_GT(captions, 40);
}

// Pictures that read at a glance (issue 64 item 11). Property: a caption is
// wrapped, never cut: every failing condition's whole first witness text
// is in the picture's label, word for word, and no caption line is longer
// than 90 columns unless it is one word; a node's loops leave it on
// different sides (Graphviz stacks loops of one side, labels over labels).
TEST(RuleDot, CaptionsWrapAndLoopsSpread) {
  int wrapped = 0, spread = 0;
  for (const auto& e : seed_catalog().rules) {
    const RuleVerdict v = check_rule(e.rule, e.words);
    const std::vector<std::string> captions = reports::failure_captions(v);
    const Graph g = parse(reports::rule_dot(e.rule, e.words, reports::failed_witnesses(v), nullptr, {}, captions));
    ASSERT_TRUE(g) << e.rule.name();
    std::string label = agget(g.get(), const_cast<char*>("label"));
    for (const std::string& caption : captions) {
      const auto lines = reports::caption_lines(caption);
      std::string joined;
      for (const auto& line : lines) {
        EXPECT_TRUE(line.size() <= 90 || line.find(' ') == std::string::npos) << e.rule.name() << ": " << line;
        joined += (joined.empty() ? "" : " ") + line;
      }
      EXPECT_EQ(joined, caption) << e.rule.name();
      wrapped += lines.size() > 1;
      for (const auto& line : lines) EXPECT_NE(label.find(reports::html_text(line)), std::string::npos) << e.rule.name() << ": " << line;
    }
    for (Agnode_t* n = agfstnode(g.get()); n; n = agnxtnode(g.get(), n)) {
      std::vector<std::string> ports;
      for (Agedge_t* x = agfstout(g.get(), n); x; x = agnxtout(g.get(), x))
        if (aghead(x) == agtail(x)) ports.push_back(agget(x, const_cast<char*>("tailport")));
      if (ports.size() < 2 || ports.size() > 4) continue;
      std::sort(ports.begin(), ports.end());
      EXPECT_EQ(std::adjacent_find(ports.begin(), ports.end()), ports.end()) << e.rule.name() << ": " << agnameof(n) << " has two loops on one side";
      ++spread;
    }
  }
  EXPECT_GT(wrapped, 5);  // witnesses of over 90 columns (a W-label's cycle, a path)
  EXPECT_GT(spread, 20);
}

// Embedded rules (issue 8): each node's label lists its terms, one line
// "pi: term" per embedding; the witness nodes of a failing embedding
// condition are highlighted and their lines of that embedding are bold.
TEST(RuleDot, EmbeddedRulesShowTermsAndHighlightFailingOnes) {
  const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/embedding-operations.yaml");
  int failing = 0;
  for (const auto& e : catalog.rules) {
    reports::TermLines lines{&*e.terms, {}};
    std::vector<RuleWitness> witnesses;
    bool required = false;
    for (const auto& c : check_term_conditions(e.rule, e.words, *e.terms))
      if (!c.holds) {
        lines.failing.push_back(c.embedding);
        witnesses.insert(witnesses.end(), c.witnesses.begin(), c.witnesses.end());
        required |= c.required;
      }
    failing += required;
    const std::string dot = reports::rule_dot(e.rule, e.words, witnesses, nullptr, lines);
    const Graph g = parse(dot);
    ASSERT_TRUE(g) << e.rule.name() << "\n" << dot;
    const std::set<std::string> lit = marked(g.get(), "witness");
    for (const auto& [side, terms] : {std::pair{'L', &e.terms->left}, std::pair{'R', &e.terms->right}})
      for (const NodeTerm& t : *terms) {
        const std::string id = std::string(1, side) + ":" + t.node;
        Agnode_t* n = agnode(g.get(), const_cast<char*>(id.c_str()), 0);
        ASSERT_TRUE(n) << e.rule.name() << ": " << id;
        const std::string label = agget(n, const_cast<char*>("label"));
        const std::string line = reports::html_text(t.embedding + ": " + t.term.str());
        EXPECT_NE(label.find(line), std::string::npos) << e.rule.name() << ": " << id << " label " << label << " lacks " << line;
        const bool bold = label.find("<b>" + line + "</b>") != std::string::npos;
        const bool hot = lit.contains(id) && std::find(lines.failing.begin(), lines.failing.end(), t.embedding) != lines.failing.end();
        EXPECT_EQ(bold, hot) << e.rule.name() << ": " << id << " " << line;
      }
    for (const auto& w : witnesses)
      for (const auto& n : w.nodes) EXPECT_TRUE(lit.contains(std::string(1, w.side) + ":" + n)) << e.rule.name() << ": " << n;
    const std::string svg = reports::render(dot, "svg");
    EXPECT_EQ(svg_nodes(svg), e.rule.left().node_count() + e.rule.right().node_count()) << e.rule.name();
  }
  EXPECT_EQ(failing, 18);  // the catalog's rules recorded with failing (required) embedding conditions
}

// L and R read as one picture (issue 64 item 11). Property, on the layout
// Graphviz computes for every seed rule and every embedded rule: a
// preserved node sits at the same place on both sides (R's node is L's
// moved by one vector, the same for every preserved node of the rule, and
// horizontal; within half a point: Graphviz writes positions to 5
// significant digits), R lies right of L, and no two nodes of a side
// overlap.
TEST(RuleDot, PreservedNodesSitAtTheSamePlaceOnBothSides) {
  int preserved = 0;
  const Catalog embedded = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/embedding-operations.yaml");
  for (const Catalog* catalog : {&seed_catalog(), &embedded})
    for (const auto& e : catalog->rules) {
      std::map<std::string, reports::NodePosition> at;
      for (auto& p : reports::node_positions(reports::rule_dot(e.rule, e.words, {}, nullptr, {}, {}), "dot")) at[p.name] = p;
      std::optional<double> dx;
      for (NodeId v = 0; v < e.rule.left().node_count(); ++v) {
        const NodeId w = e.rule.to_right(v);
        if (w == no_node) continue;
        const auto& l = at.at("L:" + e.rule.left().name(v));
        const auto& r = at.at("R:" + e.rule.right().name(w));
        EXPECT_NEAR(r.at[1], l.at[1], 0.5) << e.rule.name() << ": " << e.rule.left().name(v) << " at another height in R";
        if (!dx) dx = r.at[0] - l.at[0];
        EXPECT_NEAR(r.at[0] - l.at[0], *dx, 0.5) << e.rule.name() << ": " << e.rule.left().name(v) << " moved within its side";
        ++preserved;
      }
      for (const char* side : {"L:", "R:"})
        for (const auto& [a, p] : at)
          for (const auto& [b, q] : at)
            if (a < b && a.starts_with(side) && b.starts_with(side) && a.find('#') == std::string::npos && b.find('#') == std::string::npos) {
              EXPECT_TRUE(std::abs(p.at[0] - q.at[0]) * 2 >= (p.width + q.width) * 72 - 0.5 ||
                          std::abs(p.at[1] - q.at[1]) * 2 >= (p.height + q.height) * 72 - 0.5)
                  << e.rule.name() << ": " << a << " and " << b << " overlap";
            }
      double left_max = -1e300, right_min = 1e300;
      for (const auto& [name, p] : at) {
        if (name.starts_with("L:")) left_max = std::max(left_max, p.at[0] + p.width * 36);
        if (name.starts_with("R:")) right_min = std::min(right_min, p.at[0] - p.width * 36);
      }
      EXPECT_LT(left_max, right_min) << e.rule.name() << ": R is not right of L";
    }
  EXPECT_GT(preserved, 200);
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
  EXPECT_THROW(reports::format_of("picture.txt"), ValueError);
  EXPECT_EQ(reports::format_of("x.gv"), "dot");
}

// Jerboa-style schemes show each node's orbit type, and the loops those
// types stand for are left out unless they are witnesses.
TEST(RuleDot, JerboaNodesShowTheirOrbitTypes) {
  int schemes = 0;
  for (const auto& e : seed_catalog().rules) {
    if (!e.jerboa) continue;
    ++schemes;
    const RuleVerdict v = check_rule(e.rule, e.words);
    const Graph g = parse(reports::rule_dot(e.rule, e.words, reports::failed_witnesses(v), &*e.jerboa));
    ASSERT_TRUE(g) << e.rule.name();
    for (bool left : {true, false}) {
      const TopoGraph& side = left ? e.rule.left() : e.rule.right();
      const auto& types = left ? e.jerboa->left : e.jerboa->right;
      ASSERT_EQ(types.size(), side.node_count()) << e.rule.name();
      for (NodeId n = 0; n < side.node_count(); ++n) {
        const std::string id = std::string(left ? "L:" : "R:") + side.name(n);
        Agnode_t* node = agnode(g.get(), const_cast<char*>(id.c_str()), 0);
        ASSERT_NE(node, nullptr) << id;
        EXPECT_EQ(std::string(agget(node, const_cast<char*>("label"))), side.name(n) + "\\n" + orbit_type_str(types[n])) << e.rule.name();
      }
    }
    for (Agnode_t* n = agfstnode(g.get()); n; n = agnxtnode(g.get(), n))
      for (Agedge_t* x = agfstout(g.get(), n); x; x = agnxtout(g.get(), x)) {
        const char* lit = agget(x, const_cast<char*>("witness"));
        const std::string label = agget(x, const_cast<char*>("label"));
        if (aghead(x) == agtail(x) && label.starts_with("(") && !label.starts_with("(ε") && !(lit && std::string(lit) == "true"))
          ADD_FAILURE() << e.rule.name() << ": implicit loop " << label << " at " << agnameof(n) << " drawn";
      }
  }
  EXPECT_GE(schemes, 5);
}

namespace {

// The parts of an svg_figure: each nested <svg> of the root with its
// place, its size and the titles of its nodes.
struct Part {
  double x, y, width, height;
  std::vector<std::string> nodes;
};

std::vector<Part> figure_parts(const std::string& svg) {
  pugi::xml_document doc;
  EXPECT_TRUE(doc.load_string(svg.c_str()));
  std::vector<Part> out;
  for (const auto& n : doc.child("svg").children("svg")) {
    Part p{n.attribute("x").as_double(), n.attribute("y").as_double(), n.attribute("width").as_double(), n.attribute("height").as_double(), {}};
    for (const auto& t : n.select_nodes(".//g[@class='node']/title"))
      if (!std::string_view(t.node().child_value()).ends_with("#frame")) p.nodes.push_back(t.node().child_value());  // not a rule's frame
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace

// The three panels: G with exactly the matched darts filled, H with
// exactly the broken darts filled, the rule with its witnesses; composed
// as one SVG with the head above and G, H, rule left to right, each at its
// natural size, top-aligned and not overlapping (issue 39: the single dot
// layout put the panels at different heights); one SVG node per dart of G
// and H and per rule node, each in its own panel.
TEST(CounterexampleDot, ThreePanelsHighlightMatchAndBrokenDarts) {
  const Map cube = build_shape(Model::gmap(2), parse_shape("cube"));
  const CatalogRule& e = *seed_catalog().find_rule("insert-vertex-sewn-edge/missing-1");
  reports::CounterexamplePicture p;
  p.title = "test";
  p.host = &cube;
  p.match_tags.assign(cube.size(), "");
  p.match_tags[0] = "a";
  p.match_tags[7] = "b";
  p.result = &cube;
  p.broken.assign(cube.size(), false);
  p.broken[2] = p.broken[5] = true;
  const RuleVerdict v = check_rule(e.rule, e.words);
  const auto f = reports::counterexample_figure(e.rule, e.words, reports::failed_witnesses(v), p);
  const Graph host = parse(f.host), result = parse(f.result), rule = parse(f.rule), head = parse(f.head);
  ASSERT_TRUE(host && result && rule && head);
  EXPECT_EQ(marked(host.get(), "highlight"), (std::set<std::string>{"G:0", "G:7"}));
  EXPECT_EQ(marked(result.get(), "highlight"), (std::set<std::string>{"H:2", "H:5"}));
  EXPECT_FALSE(marked(rule.get(), "witness").empty());
  EXPECT_EQ(agnnodes(head.get()), 0);
  EXPECT_EQ(static_cast<std::size_t>(agnnodes(host.get())), cube.size());
  EXPECT_EQ(static_cast<std::size_t>(agnnodes(result.get())), cube.size());

  const std::vector<std::string> panels = {reports::render(f.host, "svg"), reports::render(f.result, "svg"), reports::render(f.rule, "svg")};
  const std::string head_svg = reports::render(f.head, "svg");
  const auto parts = figure_parts(reports::svg_figure(head_svg, panels, 1e6));
  ASSERT_EQ(parts.size(), 4u);
  EXPECT_EQ(parts[0].y, 0);
  EXPECT_TRUE(parts[0].nodes.empty());
  const std::size_t rule_nodes = e.rule.left().node_count() + e.rule.right().node_count();
  const std::array<std::pair<std::string, std::size_t>, 3> expected = {{{"G:", cube.size()}, {"H:", cube.size()}, {"rule:", rule_nodes}}};
  for (std::size_t k = 1; k < 4; ++k) {
    EXPECT_EQ(parts[k].nodes.size(), expected[k - 1].second) << k;
    for (const auto& n : parts[k].nodes) EXPECT_TRUE(n.starts_with(expected[k - 1].first)) << n;
    EXPECT_EQ(parts[k].y, parts[1].y) << "panel " << k << " is not top-aligned";
    EXPECT_GE(parts[k].y, parts[0].height);
    EXPECT_EQ(parts[k].width, reports::svg_size(panels[k - 1]).width);
    if (k > 1) {
      EXPECT_LT(parts[k - 1].x + parts[k - 1].width, parts[k].x);
    }
  }
}

// svg_figure wraps: with rows narrower than two panels, each panel starts
// a row of its own below the previous one, at the left edge.
TEST(SvgFigure, PanelsWiderThanTheRowWrapBelow) {
  const std::string small = reports::render("digraph { a -> b; }", "svg");
  const std::string head = reports::render("digraph { label=\"head\"; }", "svg");
  const double w = reports::svg_size(small).width;
  const auto parts = figure_parts(reports::svg_figure(head, {small, small, small}, 1.5 * w));
  ASSERT_EQ(parts.size(), 4u);
  for (std::size_t k = 1; k < 4; ++k) {
    EXPECT_EQ(parts[k].x, 0) << k;
    EXPECT_EQ(parts[k].nodes.size(), 2u);
    if (k > 1) {
      EXPECT_GT(parts[k].y, parts[k - 1].y + parts[k - 1].height);
    }
  }
  EXPECT_THROW(reports::svg_size("<p>not svg</p>"), std::runtime_error);
}

// SARIF's help (issues 39 and 64): every condition the checkers name on the
// seed and embedding catalogs has a section docs/conditions.md has, which
// SARIF embeds as the rule's help (the page's own text), and the cycle
// condition C(i,j) is told from the embedding condition C(pi) (the
// anchors below are read off the definitions the docs cite).
TEST(ConditionHelp, EveryNamedConditionLinksToItsSectionOfTheDocs) {
  std::ifstream in(std::string(DARTCHECK_SOURCE_DIR) + "/docs/conditions.md");
  const std::string docs((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(docs.empty());
  std::set<std::string> names{"mismatch", "soundness", "defined(pos)", "merge(pos)", "one-value(pos)"};
  for (const auto& e : seed_catalog().rules)
    for (const auto& c : check_rule(e.rule, e.words).conditions) names.insert(c.name());
  const Catalog embedded = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/embedding-operations.yaml");
  for (const auto& e : embedded.rules)
    for (const auto& c : check_term_conditions(e.rule, e.words, *e.terms)) names.insert(c.name());
  for (const auto& name : names) {
    const std::string anchor(reports::condition_help(name).anchor);
    EXPECT_NE(docs.find("<a id=\"" + anchor + "\"></a>"), std::string::npos) << name << " links to #" << anchor << ", not in the docs";
    EXPECT_NE(anchor, "jerboa-checks") << name << " has no section of its own";
    const std::string markdown = reports::condition_help_markdown(name);
    EXPECT_TRUE(markdown.starts_with("### ")) << name << ": its help is not a section of the docs: " << markdown;
    EXPECT_NE(docs.find("<a id=\"" + anchor + "\"></a>\n" + markdown), std::string::npos) << name << ": its help is not its section's text";
  }
  const std::map<std::string, std::string> expected{{"I(1)", "incident-arcs"}, {"dangling(0)", "dangling"},   {"O(2)", "non-orientation"},
                                                    {"C(0,2)", "cycle"},       {"C(pos)", "extended-orbits"}, {"A(pos)", "embedding-consistency"},
                                                    {"B(col)", "full-match"},  {"label(pos)", "labeling"},    {"merge(pos)", "merge"}};
  for (const auto& [name, anchor] : expected) EXPECT_EQ(reports::condition_help(name).anchor, anchor) << name;
  EXPECT_TRUE(names.contains("C(0,2)") && names.contains("A(pos)")) << "the catalogs no longer exercise both C families";
}
