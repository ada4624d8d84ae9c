// A counterexample as one picture of three panels (issue "report"): the
// host map G with the match highlighted, the derived graph H with the darts
// that break a constraint highlighted, and the rule with the witnesses of
// its failed conditions. Links are colored by dimension with a legend.
#pragma once

#include <optional>
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

/// G, H and the rule, left to right, with one legend of the dimensions.
std::string counterexample_dot(const Rule& rule, const ArcWords& words, const std::vector<RuleWitness>& witnesses, const CounterexamplePicture& p,
                               const JerboaLabels* labels = nullptr);

}  // namespace dartcheck::reports
