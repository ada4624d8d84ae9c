#include "reports/graph_dot.hpp"

#include <fmt/format.h>

#include "reports/dot_text.hpp"

namespace dartcheck::reports {

std::string graph_cluster(const TopoGraph& g, const Model& model, const GraphPicture& p) {
  std::string out = fmt::format("  subgraph {} {{\n    label={}; fontname=\"Helvetica\"; color=\"#9e9e9e\";\n", quote("cluster_" + p.prefix),
                                quote(p.highlight_label.empty() ? p.title : p.title + " (" + p.highlight_label + ")"));
  for (NodeId v = 0; v < g.node_count(); ++v) {
    const bool lit = v < p.highlight.size() && p.highlight[v];
    const bool tagged = v < p.tags.size() && !p.tags[v].empty();
    const std::string pinned = v < p.positions.size() ? fmt::format(", pos=\"{:.4f},{:.4f}!\"", p.positions[v][0], p.positions[v][1]) : "";
    out += fmt::format(
        "    {} [label={}{}{}];\n", quote(p.prefix + g.name(v)), quote(tagged ? g.name(v) + "\n" + p.tags[v] : g.name(v)), pinned,
        lit ? fmt::format(", style=filled, fillcolor=\"{}\", color=\"{}\", penwidth=2, highlight=\"true\"", p.fill, p.line) : "");
  }
  // A non-oriented dimension's arc and its reverse are one edge.
  std::vector<bool> drawn(g.arc_count(), false);
  std::vector<std::size_t> loops(g.node_count(), 0);  // drawn so far per node: each takes the next side
  for (ArcId e = 0; e < g.arc_count(); ++e) {
    if (drawn[e]) continue;
    drawn[e] = true;
    const auto& a = g.arc(e);
    bool pair = false;
    if (model.contains(a.label) && !model.is_oriented(a.label)) {
      if (a.source == a.target) pair = true;
      for (ArcId f = e + 1; f < g.arc_count() && !pair; ++f) {
        const auto& b = g.arc(f);
        if (!drawn[f] && b.label == a.label && b.source == a.target && b.target == a.source) drawn[f] = pair = true;
      }
    }
    const std::string port = a.source == a.target ? fmt::format(":{}", loop_port(loops[a.source]++, false)) : "";
    out += fmt::format("    {}{} -> {}{} [color=\"{}\", fontcolor=\"{}\", label={}{}];\n", quote(p.prefix + g.name(a.source)), port,
                       quote(p.prefix + g.name(a.target)), port, dimension_color(a.label), dimension_color(a.label), quote(std::to_string(a.label)),
                       pair ? ", dir=none" : "");
  }
  return out + "  }\n";
}

std::string graph_dot(const TopoGraph& g, const Model& model, const GraphPicture& p) {
  return fmt::format(
      "digraph {} {{\n  fontname=\"Helvetica\"; node [shape=circle, fontname=\"Helvetica\", fontsize=10, width=0.3]; "
      "edge [fontname=\"Helvetica\", fontsize=9];\n  label=<{}>; labelloc=b;\n{}}}\n",
      quote(p.title), dimension_legend(model), graph_cluster(g, model, p));
}

}  // namespace dartcheck::reports
