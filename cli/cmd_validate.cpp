#include <fmt/format.h>

#include "checkers/map_validity.hpp"
#include "cli/commands.hpp"
#include "cli/report_text.hpp"
#include "cli/resolve.hpp"
#include "core/input_error.hpp"

namespace dartcheck::cli {

int validate_map(const ValidateOptions& o) {
  const auto model = Model::by_name(o.model);
  if (!model) throw InputError("<command line>", 0, 0, fmt::format("--model: unknown model '{}' (expected {})", o.model, Model::known_names()));
  const Map map = resolve_map(o.target, *model, nullptr);
  fmt::print("map: {}\n", describe_target(o.target, map));
  const auto report = check_map(map);
  print_validity(stdout, map, report, o.limit);
  return report.valid() ? ok : violation;
}

}  // namespace dartcheck::cli
