#include "cli/options.hpp"

#include "analysis/interrupt.hpp"
#include "cli/commands.hpp"
#include "reports/rule_result_text.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/input_error.hpp"

namespace dartcheck::cli {

Model command_model(const std::string& name) {
  const auto model = Model::by_name(name);
  if (!model) throw UsageError(fmt::format("--model: unknown model '{}' (expected {})", name, Model::known_names()));
  return *model;
}

std::optional<Catalog> optional_catalog(const std::string& file) { return file.empty() ? std::nullopt : std::optional<Catalog>(read_catalog(file)); }

void check_hooks(const CatalogRule& rule, const std::vector<Dart>& hooks, const Map& map, const std::string& map_name) {
  const auto& want = rule.rule.hooks();
  if (hooks.size() != want.size()) {
    std::vector<std::string> names;
    for (NodeId h : want) names.push_back(rule.rule.left().name(h));
    throw UsageError(want.empty() ? fmt::format("--hook: rule '{}' has no hook (L is empty or matched as a whole): give no --hook", rule.rule.name())
                                  : fmt::format("--hook: rule '{}' has {} hook{} ({}), {} given: one --hook dart each, in that order",
                                                rule.rule.name(), want.size(), want.size() == 1 ? "" : "s", fmt::join(names, ", "), hooks.size()));
  }
  // A dart the map does not have is a mistake on the command line, not a
  // refusal of the rule (issue 39).
  for (const Dart h : hooks)
    if (h >= map.size())
      throw UsageError(fmt::format("--hook: {} is not a dart of {} ({})", h, printable(map_name),
                                   map.size() == 0 ? std::string("it has no darts") : fmt::format("darts 0 to {}", map.size() - 1)));
}

}  // namespace dartcheck::cli
