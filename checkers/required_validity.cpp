#include <fmt/format.h>
#include <fmt/ranges.h>

#include "checkers/map_validity.hpp"
#include "core/input_error.hpp"

namespace dartcheck {

void require_valid_map(const Map& map, std::string_view subject, std::string_view why) {
  const auto report = check_map(map);
  if (report.valid()) return;
  std::vector<std::string> lines;
  for (std::size_t k = 0; k < report.violations.size() && k < 5; ++k)
    lines.push_back(describe(report.violations[k], fmt::format("dart {}", report.violations[k].element)));
  throw UsageError(fmt::format("{}: not a valid {} ({} violation{}: {}{}): {}", subject, map.model().name, report.violations.size(),
                               report.violations.size() == 1 ? "" : "s", fmt::join(lines, "; "), report.violations.size() > 5 ? "; ..." : "", why));
}

}  // namespace dartcheck
