#include <optional>

#include <fmt/format.h>

#include "io/jerboa_jba.hpp"
#include "checkers/map_validity.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "reports/validity_json.hpp"
#include "reports/validity_text.hpp"
#include "analysis/map_sources.hpp"
#include "core/input_error.hpp"
#include "core/terminal.hpp"

namespace dartcheck::cli {

using reports::print_validity;

using namespace analysis;  // the engines the commands call
int validate_map(const ValidateOptions& o) {
  const Model model = command_model(o.model);
  const bool json = o.format == "json";
  // -q: nothing for a valid map; an invalid one's violations (up to
  // --limit) as diagnostic lines on stderr.
  if (!json && terminal().quiet) {
    const bool jba = o.target.ends_with(".jba");
    const std::optional<JbaFile> f = jba ? std::optional(read_jba(o.target)) : std::nullopt;
    const Map map = jba ? f->map : resolve_map(o.target, model, nullptr);
    return reports::print_validity_diagnostics(stderr, o.target, map, check_map(map), o.limit, jba ? &*f : nullptr) ? ok : violation;
  }
  if (o.target.ends_with(".jba")) {
    const JbaFile f = read_jba(o.target);
    const std::string description = fmt::format("{} (Jerboa, written by {})", describe_target(o.target, f.map), f.name);
    if (json) {
      const auto report = check_map(f.map);
      fmt::print("{}\n", reports::validity_json_text(o.target, description, f.map, report, o.limit, &f));
      return reports::consistently_embedded(f, report) ? ok : violation;
    }
    fmt::print("map: {}\n", description);
    return reports::print_jba_validity(stdout, f, o.limit) ? ok : violation;
  }
  const Map map = resolve_map(o.target, model, nullptr);
  const auto report = check_map(map);
  if (json) {
    fmt::print("{}\n", reports::validity_json_text(o.target, describe_target(o.target, map), map, report, o.limit));
  } else {
    fmt::print("map: {}\n", describe_target(o.target, map));
    print_validity(stdout, map, report, o.limit);
  }
  return report.valid() ? ok : violation;
}

}  // namespace dartcheck::cli
