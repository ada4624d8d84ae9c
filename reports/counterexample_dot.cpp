#include "reports/counterexample_dot.hpp"

#include <fmt/format.h>

#include "rewriting/graph_derivation.hpp"
#include "reports/dot_text.hpp"
#include "reports/graph_dot.hpp"
#include "reports/rule_dot.hpp"

namespace dartcheck::reports {

std::string counterexample_dot(const Rule& rule, const ArcWords& words, const std::vector<RuleWitness>& witnesses, const CounterexamplePicture& p,
                               const JerboaLabels* labels) {
  GraphPicture g{"G:", fmt::format("G: host map, {} dart{}", p.host->size(), p.host->size() == 1 ? "" : "s"), {}, p.match_label, p.match_tags};
  g.highlight.resize(p.host->size());
  for (std::size_t d = 0; d < p.match_tags.size() && d < g.highlight.size(); ++d) g.highlight[d] = !p.match_tags[d].empty();
  const TopoGraph host = to_graph(*p.host);
  std::string body = graph_cluster(host, p.host->model(), g);
  std::optional<TopoGraph> result;
  if (p.result) {
    result = to_graph(*p.result);
    GraphPicture h{"H:", fmt::format("H: result, {} dart{}", p.result->size(), p.result->size() == 1 ? "" : "s"), p.broken, p.broken_label,
                   p.result_tags};
    body += graph_cluster(*result, p.result->model(), h);
  } else {
    body += fmt::format("  subgraph \"cluster_H:\" {{\n    label=\"H\"; color=\"#9e9e9e\";\n    \"H:none\" [shape=note, label={}];\n  }}\n",
                        quote("H has no dense form:\n" + p.no_result));
  }
  body += rule_cluster(rule, words, witnesses, "rule:", labels);
  // Left to right G, H, rule: invisible separator nodes ranked after every
  // node of one panel and before every node of the next (weight 0, so the
  // panels' own layouts are untouched).
  std::vector<std::string> panels[3];
  for (NodeId v = 0; v < host.node_count(); ++v) panels[0].push_back("G:" + host.name(v));
  if (result) {
    for (NodeId v = 0; v < result->node_count(); ++v) panels[1].push_back("H:" + result->name(v));
  } else {
    panels[1].push_back("H:none");
  }
  for (NodeId v = 0; v < rule.left().node_count(); ++v) panels[2].push_back("rule:L:" + rule.left().name(v));
  for (NodeId v = 0; v < rule.right().node_count(); ++v) panels[2].push_back("rule:R:" + rule.right().name(v));
  for (int k = 0; k < 2; ++k) {
    const std::string sep = fmt::format("sep{}", k);
    body += fmt::format("  {} [shape=point, style=invis, width=0];\n", quote(sep));
    for (const auto& n : panels[k]) body += fmt::format("  {} -> {} [style=invis, weight=0];\n", quote(n), quote(sep));
    for (const auto& n : panels[k + 1]) body += fmt::format("  {} -> {} [style=invis, weight=0];\n", quote(sep), quote(n));
  }
  std::string caption = fmt::format("<tr><td><b>{}</b></td></tr>", html_text(p.title));
  for (const auto& line : p.captions) caption += fmt::format(R"(<tr><td><font color="{}">{}</font></td></tr>)", deleted_color, html_text(line));
  return fmt::format(
      "digraph {} {{\n  rankdir=LR; newrank=true; fontname=\"Helvetica\"; labelloc=t;\n"
      "  label=<<table border=\"0\" cellspacing=\"1\">{}<tr><td>{}</td></tr></table>>;\n"
      "  node [shape=circle, fontname=\"Helvetica\", fontsize=10, width=0.3]; edge [fontname=\"Helvetica\", fontsize=9];\n{}}}\n",
      quote(p.title), caption, rule_legend(rule.model(), !witnesses.empty(), {}), body);
}

}  // namespace dartcheck::reports
