// A counterexample as a figure of three panels (issue "report"): the host
// map G with the match highlighted, the derived graph H with the darts
// that break a constraint highlighted, and the rule with the witnesses of
// its failed conditions; above them a head with the title, what fails and
// one legend. Each panel is its own picture (issue 39), so that they are
// laid out top-aligned side by side (svg_figure, or a page's flex row)
// at their natural sizes.
#pragma once

#include <string>
#include <vector>

#include "checkers/rule_conditions.hpp"
#include "rewriting/jerboa_scheme.hpp"
#include "core/map.hpp"
#include "rewriting/rule.hpp"

namespace dartcheck::reports {

struct CounterexamplePicture {
  std::string title;
  const Map* host = nullptr;
  std::vector<std::string> match_tags;   // per dart of G: what it matches ("a", "hook", ...), empty if untouched
  std::string match_label;               // what the filled darts of G are
  const Map* result = nullptr;           // H; null when H has no dense form
  std::vector<bool> broken;              // per dart of H
  std::vector<std::string> result_tags;  // per dart of H: e.g. its value in a conflicting orbit, may be empty
  std::string broken_label;              // which constraints, for the panel's title
  std::string no_result;                 // why H is not drawn, when result is null
  std::vector<std::string> captions;     // under the title: what H breaks, where; the failing conditions
};

/// The figure's four DOT pictures. Node ids: "G:" + dart, "H:" + dart,
/// "rule:L:" / "rule:R:" + node name.
struct CounterexampleFigure {
  std::string head;  // title, captions and legend; no nodes
  std::string host;
  std::string result;
  std::string rule;
};

CounterexampleFigure counterexample_figure(const Rule& rule, const ArcWords& words, const std::vector<RuleWitness>& witnesses,
                                           const CounterexamplePicture& p, const JerboaLabels* labels = nullptr);

}  // namespace dartcheck::reports
