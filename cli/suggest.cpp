#include "cli/suggest.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <string_view>
#include <vector>

#include "core/input_error.hpp"

namespace dartcheck::cli {
namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

void suggest_subcommand(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return;
  const std::string_view typed = argv[1];
  std::string best;
  std::size_t best_distance = 3;  // farther than this is no suggestion
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (sub->get_name() == typed) return;
    const std::size_t d = edit_distance(typed, sub->get_name());
    if (d < best_distance || (d == best_distance && best.empty())) {
      best = sub->get_name();
      best_distance = d;
    }
  }
  if (!best.empty()) fmt::print(stderr, "'{}' is not a dartcheck command; did you mean '{}'?\n", printable(typed), best);
}

}  // namespace dartcheck::cli
