#include <fmt/format.h>

#include "io/jerboa_jba.hpp"
#include "checkers/map_validity.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "reports/json_document.hpp"
#include "reports/validity_json.hpp"
#include "reports/validity_text.hpp"
#include "analysis/map_sources.hpp"
#include "core/input_error.hpp"

namespace dartcheck::cli {

using reports::print_validity;

using namespace analysis;  // the engines the commands call
int validate_map(const ValidateOptions& o) {
  const Model model = command_model(o.model);
  const bool json = o.format == "json";
  if (o.target.ends_with(".jba")) {
    const JbaFile f = read_jba(o.target);
    const std::string description = fmt::format("{} (Jerboa, written by {})", describe_target(o.target, f.map), f.name);
    if (json) {
      const reports::Json doc = reports::validity_document(o.target, description, f.map, check_map(f.map), o.limit, &f);
      fmt::print("{}\n", reports::json_text(doc));
      return doc["jerboa"]["consistently_embedded"].get<bool>() ? ok : violation;
    }
    fmt::print("map: {}\n", description);
    return reports::print_jba_validity(stdout, f, o.limit) ? ok : violation;
  }
  const Map map = resolve_map(o.target, model, nullptr);
  const auto report = check_map(map);
  if (json) {
    fmt::print("{}\n", reports::json_text(reports::validity_document(o.target, describe_target(o.target, map), map, report, o.limit)));
  } else {
    fmt::print("map: {}\n", describe_target(o.target, map));
    print_validity(stdout, map, report, o.limit);
  }
  return report.valid() ? ok : violation;
}

}  // namespace dartcheck::cli
