// Checks of command-line options that several commands share.
#pragma once

#include <chrono>
#include <string>

#include "analysis/rule_result.hpp"
#include "campaign/shard.hpp"
#include "io/catalog.hpp"

namespace dartcheck::cli {

/// Reads the catalog a command works on, after checking --format (text or
/// json) and that --rule, if given, names one of its rules.
Catalog read_command_catalog(const std::string& file, const std::string& rule, const std::string& format);

/// --shard K/N (the whole run when `text` is empty).
campaign::Shard command_shard(const std::string& text);

/// Wall-clock seconds since `start`.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The longest duration an option takes: 31 days.
inline constexpr double max_duration_seconds = 31 * 24 * 3600;

/// Seconds in "30s", "500ms", "2m", "1h" or a bare number of seconds, at
/// most max_duration_seconds; InputError naming `option` otherwise (nan,
/// inf, zero, negative, an unknown unit).
double parse_duration(const std::string& text, const std::string& option);

/// --hook gives one dart per hook of the rule (none for a rule without
/// hooks), each a dart of the map; InputError naming the hooks or the
/// dart otherwise.
void check_hooks(const CatalogRule& rule, const std::vector<Dart>& hooks, const Map& map, const std::string& map_name);

/// The end of a run of check, fuzz, prove or report: prints the baseline's
/// disagreements and every mismatch line on stderr, says how many of
/// `selected` rules finished if a signal stopped the run, and returns the
/// exit status (3 a soundness bug, 130 interrupted, 1 a mismatch, 0).
int finish_run(const std::vector<analysis::RuleResult>& results, const std::vector<std::string>& baseline_mismatches, std::size_t selected);

}  // namespace dartcheck::cli
