#include <fmt/format.h>

#include "io/jerboa_jba.hpp"
#include "checkers/map_validity.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "reports/validity_text.hpp"
#include "analysis/map_sources.hpp"
#include "core/input_error.hpp"

namespace dartcheck::cli {

using reports::print_validity;

using namespace analysis;  // the engines the commands call
int validate_map(const ValidateOptions& o) {
  const Model model = command_model(o.model);
  if (o.target.ends_with(".jba")) {
    const JbaFile f = read_jba(o.target);
    fmt::print("map: {} (Jerboa, written by {})\n", describe_target(o.target, f.map), f.name);
    return reports::print_jba_validity(stdout, f, o.limit) ? ok : violation;
  }
  const Map map = resolve_map(o.target, model, nullptr);
  fmt::print("map: {}\n", describe_target(o.target, map));
  const auto report = check_map(map);
  print_validity(stdout, map, report, o.limit);
  return report.valid() ? ok : violation;
}

}  // namespace dartcheck::cli
