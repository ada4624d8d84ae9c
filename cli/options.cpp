#include "cli/options.hpp"

#include "analysis/interrupt.hpp"
#include "cli/commands.hpp"
#include "cli/number_options.hpp"
#include "reports/rule_result_text.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/input_error.hpp"

namespace dartcheck::cli {

Catalog read_command_catalog(const std::string& file, const std::string& rule, const std::string& format) {
  if (format != "text" && format != "json")
    throw InputError("<command line>", 0, 0, fmt::format("--format: expected text or json, got '{}'", format));
  Catalog catalog = read_catalog(file);
  if (!rule.empty() && !catalog.find_rule(rule))
    throw InputError("<command line>", 0, 0, fmt::format("--rule: no rule named '{}' in {}", rule, file));
  return catalog;
}

campaign::Shard command_shard(const std::string& text) { return text.empty() ? campaign::Shard{} : campaign::parse_shard(text); }

double parse_duration(const std::string& text, const std::string& option) {
  // The number, then a unit: "30s", "500ms", "2m", "1h", or bare seconds.
  const std::size_t split = text.find_first_not_of("0123456789.eE+-");
  const std::string unit = split == std::string::npos ? "" : text.substr(split);
  const auto v = read_real(std::string_view(text).substr(0, split == std::string::npos ? text.size() : split));
  const double scale = unit.empty() || unit == "s" ? 1 : unit == "ms" ? 1e-3 : unit == "m" || unit == "min" ? 60 : unit == "h" ? 3600 : -1;
  if (!v || scale < 0 || !(*v > 0))
    throw InputError("<command line>", 0, 0,
                     fmt::format("{}: expected a positive duration such as 30s, 500ms or 2m, got '{}'", option, printable(text)));
  // A deadline is a clock reading plus the duration: keep it far from
  // overflow (steady_clock counts nanoseconds in 64 bits, about 292 years).
  if (*v * scale > max_duration_seconds)
    throw InputError("<command line>", 0, 0, fmt::format("{}: at most {} s (31 days), got '{}'", option, max_duration_seconds, printable(text)));
  return *v * scale;
}

void check_hooks(const CatalogRule& rule, const std::vector<Dart>& hooks, const Map& map, const std::string& map_name) {
  const auto& want = rule.rule.hooks();
  if (hooks.size() != want.size()) {
    std::vector<std::string> names;
    for (NodeId h : want) names.push_back(rule.rule.left().name(h));
    throw InputError("<command line>", 0, 0,
                     want.empty() ? fmt::format("--hook: rule '{}' has no hook (L is empty or matched as a whole): give no --hook", rule.rule.name())
                                  : fmt::format("--hook: rule '{}' has {} hook{} ({}), {} given: one --hook dart each, in that order",
                                                rule.rule.name(), want.size(), want.size() == 1 ? "" : "s", fmt::join(names, ", "), hooks.size()));
  }
  // A dart the map does not have is a mistake on the command line, not a
  // refusal of the rule (issue 39).
  for (const Dart h : hooks)
    if (h >= map.size())
      throw InputError("<command line>", 0, 0,
                       fmt::format("--hook: {} is not a dart of {} ({})", h, printable(map_name),
                                   map.size() == 0 ? std::string("it has no darts") : fmt::format("darts 0 to {}", map.size() - 1)));
}

int finish_run(const std::vector<analysis::RuleResult>& results, const std::vector<std::string>& baseline_mismatches, std::size_t selected) {
  for (const auto& m : baseline_mismatches) fmt::print(stderr, "baseline: {}\n", printable(m));
  for (const auto& line : reports::mismatch_lines(results)) fmt::print(stderr, "{}\n", line);
  const auto counts = analysis::count_results(results);
  if (analysis::interrupted())
    fmt::print(stderr, "interrupted: {} of {} rule{} finished; the results above are theirs\n", results.size(), selected, selected == 1 ? "" : "s");
  if (counts.unsound || counts.events_contradicted) return soundness_bug;
  if (analysis::interrupted()) return analysis::interrupted_exit;
  return counts.mismatches + baseline_mismatches.size() > 0 ? violation : ok;
}

}  // namespace dartcheck::cli
