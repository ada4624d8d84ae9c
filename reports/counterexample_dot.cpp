#include "reports/counterexample_dot.hpp"

#include <fmt/format.h>

#include "rewriting/graph_derivation.hpp"
#include "reports/dot_text.hpp"
#include "reports/graph_dot.hpp"
#include "reports/rule_dot.hpp"

namespace dartcheck::reports {

namespace {

// One panel: a graph of its own, with the attributes every panel shares.
std::string panel(std::string_view name, std::string_view rankdir, const std::string& body) {
  return fmt::format(
      "digraph {} {{\n  rankdir={}; newrank=true; fontname=\"Helvetica\"; labelloc=t;\n"
      "  node [shape=circle, fontname=\"Helvetica\", fontsize=10, width=0.3]; edge [fontname=\"Helvetica\", fontsize=9];\n{}}}\n",
      quote(name), rankdir, body);
}

}  // namespace

CounterexampleFigure counterexample_figure(const Rule& rule, const ArcWords& words, const std::vector<RuleWitness>& witnesses,
                                           const CounterexamplePicture& p, const JerboaLabels* labels) {
  CounterexampleFigure f;
  std::string caption = fmt::format("<tr><td><b>{}</b></td></tr>", html_text(p.title));
  for (const auto& text : p.captions)
    for (const auto& line : caption_lines(text)) caption += fmt::format(R"(<tr><td><font color="{}">{}</font></td></tr>)", deleted_color, html_text(line));
  f.head = fmt::format(
      "digraph {} {{\n  fontname=\"Helvetica\"; labelloc=t; labeljust=l;\n"
      "  label=<<table border=\"0\" cellspacing=\"1\">{}<tr><td align=\"left\">{}</td></tr></table>>;\n}}\n",
      quote(p.title), caption, rule_legend(rule.model(), !witnesses.empty(), {}, true));
  // Maps are drawn top to bottom: their panels stay narrow, so that G and
  // H fit side by side; the rule keeps L beside R.
  GraphPicture g{"G:", fmt::format("G: host map, {} dart{}", p.host->size(), p.host->size() == 1 ? "" : "s"), {}, p.match_label, p.match_tags,
                 match_fill, match_line};
  g.highlight.resize(p.host->size());
  for (std::size_t d = 0; d < p.match_tags.size() && d < g.highlight.size(); ++d) g.highlight[d] = !p.match_tags[d].empty();
  f.host = panel("G", "TB", graph_cluster(to_graph(*p.host), p.host->model(), g));
  if (p.result) {
    GraphPicture h{"H:", fmt::format("H: result, {} dart{}", p.result->size(), p.result->size() == 1 ? "" : "s"), p.broken, p.broken_label,
                   p.result_tags, broken_fill, broken_line};
    f.result = panel("H", "TB", graph_cluster(to_graph(*p.result), p.result->model(), h));
  } else {
    f.result = panel("H", "TB",
                     fmt::format("  subgraph \"cluster_H:\" {{\n    label=\"H\"; color=\"#9e9e9e\";\n    \"H:none\" [shape=note, label={}];\n  }}\n",
                                 quote("H has no dense form:\n" + p.no_result)));
  }
  f.rule = panel("rule", "LR", rule_cluster(rule, words, witnesses, "rule:", labels));
  return f;
}

}  // namespace dartcheck::reports
