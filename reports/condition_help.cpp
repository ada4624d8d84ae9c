#include "reports/condition_help.hpp"

#include <array>
#include <cctype>

#include <fmt/format.h>

namespace dartcheck::reports {

namespace {

// Name families: a prefix up to the opening parenthesis, or a whole word.
struct Family {
  std::string_view prefix;
  ConditionHelp help;
};

constexpr std::array families{
    Family{"I(", {"incident-arcs", "incident arcs: every node of R has one i-arc in and out where its node of L has one", "002 Def. 11, Def. 22"}},
    Family{"dangling(",
           {"dangling", "dangling: a deleted node has no i-arc to the rest of the host (L satisfies I(i) on deleted nodes)", "002 Def. 12"}},
    Family{"O(", {"non-orientation", "non-orientation: the i-arcs of R come in opposite pairs", "002 Def. 13, Def. 24"}},
    Family{"no-loop(", {"no-loop", "no loop: the model's maps are closed, so an added i-arc is never a loop", "the model (closed maps)"}},
    Family{"A(",
           {"embedding-consistency", "embedding consistency: the labeled nodes of one embedding orbit of L, K and R carry one term",
            "003 Theorem 2 (A), Theorem 4"}},
    Family{"B(",
           {"full-match", "full match: a preserved node whose term changes has its R-orbit fully labeled and complete",
            "003 Theorem 2 (B), direct instantiation only"}},
    Family{"label(",
           {"labeling", "labeling: preserved nodes labeled in L stay labeled, added nodes get a term or a labeled orbit", "003 Def. 1, Def. 12"}},
    Family{"defined(",
           {"defined", "defined (Jerboa): an added node's embedding orbit gets a value from a preserved node or an expression",
            "003 Sec. 5.2, Def. 12"}},
    Family{"merge(", {"merge", "merge (Jerboa): orbits of L merged in R need an expression to decide the merged value", "003 Theorem 2 (C)"}},
    Family{"one-value(", {"one-value", "one value (Jerboa): the nodes of one embedding orbit of R carry one expression", "003 Theorem 2 (A)"}},
    Family{"soundness",
           {"soundness", "soundness: a rule judged consistent broke a map, or the solver contradicts a theorem: a defect of dartcheck",
            "dartcheck's own guarantee"}},
    Family{"mismatch",
           {"mismatch", "mismatch: the verdict of this run differs from the one the catalog or baseline records", "the catalog or baseline"}},
};

constexpr ConditionHelp cycle{"cycle", "cycle: for i + 2 <= j, every ijij-path of the result from a node the rule touches comes back to it",
                              "002 Def. 14-16, Def. 25-27"};
constexpr ConditionHelp extended_orbits{"extended-orbits",
                                        "labeling of extended orbits: a preserved node whose embedding orbit gains nodes has a node of K "
                                        "in that orbit labeled in L",
                                        "003 Theorem 2 (C), Theorem 4"};
constexpr ConditionHelp unknown{"jerboa-checks", "an embedding condition of 003 or a Jerboa presence check", "003 Sec. 5-6"};

// "C(0,2)" is the topological cycle condition; "C(pos)" the embedding one.
bool topological_cycle(std::string_view name) {
  if (name.size() < 5 || name.substr(0, 2) != "C(" || name.back() != ')') return false;
  for (char c : name.substr(2, name.size() - 3))
    if (!std::isdigit(static_cast<unsigned char>(c)) && c != ',') return false;
  return name.find(',') != std::string_view::npos;
}

}  // namespace

const ConditionHelp& condition_help(std::string_view name) {
  if (topological_cycle(name)) return cycle;
  if (name.substr(0, 2) == "C(") return extended_orbits;
  for (const Family& f : families)
    if (name.substr(0, f.prefix.size()) == f.prefix) return f.help;
  return unknown;
}

std::string condition_help_uri(std::string_view name) {
  std::string base = DARTCHECK_DOCS_URL;
  if (!base.starts_with("http://") && !base.starts_with("https://")) return {};
  if (base.back() != '/') base += '/';
  return base + "conditions.md#" + std::string(condition_help(name).anchor);
}

std::string condition_help_markdown(std::string_view name) {
  struct Section {
    std::string_view anchor, markdown;
  };
  static constexpr Section sections[] = {
#include "condition_docs.inc"
  };
  const ConditionHelp& help = condition_help(name);
  for (const Section& s : sections)
    if (s.anchor == help.anchor) return std::string(s.markdown);
  return fmt::format("{} ({})", help.summary, help.source);
}

}  // namespace dartcheck::reports
