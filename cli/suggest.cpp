#include "cli/suggest.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "core/closest_name.hpp"
#include "core/input_error.hpp"

namespace dartcheck::cli {
namespace {

bool is_command(const CommandTable& table, std::string_view name) {
  return std::find(table.commands.begin(), table.commands.end(), name) != table.commands.end();
}

// CLI11's refusal of a value outside an option's choices ends in
// "VALUE not in {a,b,c}": the closest choice, as for commands and options.
std::string choice_suggestion(std::string_view what) {
  const std::size_t not_in = what.rfind(" not in {");
  if (not_in == std::string_view::npos || what.back() != '}') return "";
  const std::size_t start = what.rfind(' ', not_in - 1);
  const std::string_view typed = what.substr(start == std::string_view::npos ? 0 : start + 1, not_in - (start == std::string_view::npos ? 0 : start + 1));
  std::vector<std::string> choices;
  std::string_view list = what.substr(not_in + 9, what.size() - not_in - 10);
  while (!list.empty()) {
    const std::size_t comma = list.find(',');
    choices.emplace_back(list.substr(0, comma));
    list = comma == std::string_view::npos ? std::string_view{} : list.substr(comma + 1);
  }
  const std::string best = closest_name(typed, choices);
  return best.empty() ? "" : fmt::format("; did you mean '{}'?", best);
}

}  // namespace

std::optional<int> help_request(const CommandTable& table, int argc, char** argv) {
  if (argc < 2 || std::string_view(argv[1]) != "help") return std::nullopt;
  if (argc == 2 || is_command(table, argv[2])) {
    fmt::print("{}", table.help(argc == 2 ? "" : argv[2]));
    return 0;
  }
  const std::string best = closest_name(argv[2], table.commands);
  fmt::print(stderr, "dartcheck: error: 'help {}': no such command{}\n", printable(argv[2]), best.empty() ? "" : fmt::format("; did you mean '{}'?", best));
  return 2;
}

int report_parse_error(const CommandTable& table, std::string_view what, int argc, char** argv) {
  // The command: the first argument that names one (global options may come before it).
  std::string command;
  for (int k = 1; k < argc && command.empty(); ++k)
    if (is_command(table, argv[k])) command = argv[k];
  // A mistyped command: the suggestion is the whole message.
  if (argc > 1 && argv[1][0] != '-' && command.empty()) {
    const std::string best = closest_name(argv[1], table.commands);
    fmt::print(stderr, "dartcheck: error: '{}' is not a dartcheck command{} (dartcheck --help lists them)\n", printable(argv[1]),
               best.empty() ? "" : fmt::format("; did you mean '{}'?", best));
    return 2;
  }
  // A mistyped option: name the closest the command accepts.
  static const std::vector<std::string> none;
  const auto known = table.options.find(command);
  const std::vector<std::string>& names = known == table.options.end() ? none : known->second;
  for (int k = 1; k < argc; ++k) {
    const std::string_view arg = argv[k];
    const std::string typed(arg.substr(0, arg.find('=')));
    // Without a command CLI11 says only that one is missing: name the
    // unknown option first.
    if (!arg.starts_with("--") || (!command.empty() && what.find(typed) == std::string_view::npos)) continue;
    if (std::find(names.begin(), names.end(), typed) != names.end()) continue;
    const std::string best = closest_name(typed, names);
    fmt::print(stderr, "dartcheck: error: {}unknown option {}{} ({} lists them)\n", command.empty() ? "" : command + ": ", printable(typed),
               best.empty() ? "" : fmt::format("; did you mean {}?", best), command.empty() ? "dartcheck --help" : "dartcheck help " + command);
    return 2;
  }
  if (command.empty()) {
    fmt::print(stderr, "dartcheck: error: no command given (dartcheck --help lists them)\n");
    return 2;
  }
  fmt::print(stderr, "dartcheck: error: {}: {}{}\n", command, printable(what), choice_suggestion(what));
  return 2;
}

}  // namespace dartcheck::cli
