#include "cli/suggest.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <string_view>
#include <vector>

#include "core/closest_name.hpp"
#include "core/input_error.hpp"

namespace dartcheck::cli {
namespace {

std::vector<std::string> command_names(const CLI::App& app) {
  std::vector<std::string> out;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) out.push_back(sub->get_name());
  return out;
}

const CLI::App* command_named(const CLI::App& app, std::string_view name) {
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->get_name() == name) return sub;
  return nullptr;
}

// The long option names a command accepts: its own and the global ones.
std::vector<std::string> option_names(const CLI::App& app, const CLI::App* command) {
  std::vector<std::string> out;
  for (const CLI::App* a : {&app, command}) {
    if (!a) continue;
    for (const CLI::Option* o : a->get_options())
      for (const auto& n : o->get_lnames()) out.push_back("--" + n);
  }
  return out;
}

}  // namespace

std::optional<int> help_request(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || std::string_view(argv[1]) != "help") return std::nullopt;
  if (argc == 2) {
    fmt::print("{}", app.help());
    return 0;
  }
  if (const CLI::App* sub = command_named(app, argv[2])) {
    fmt::print("{}", sub->help());
    return 0;
  }
  const std::string best = closest_name(argv[2], command_names(app));
  fmt::print(stderr, "error: 'help {}': no such command{}\n", printable(argv[2]), best.empty() ? "" : fmt::format("; did you mean '{}'?", best));
  return 2;
}

int report_parse_error(const CLI::App& app, const CLI::ParseError& e, int argc, char** argv) {
  if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
  const CLI::App* command = argc > 1 ? command_named(app, argv[1]) : nullptr;
  // A mistyped command: the suggestion is the whole message.
  if (argc > 1 && argv[1][0] != '-' && !command) {
    const std::string best = closest_name(argv[1], command_names(app));
    fmt::print(stderr, "error: '{}' is not a dartcheck command{} (dartcheck --help lists them)\n", printable(argv[1]),
               best.empty() ? "" : fmt::format("; did you mean '{}'?", best));
    return 2;
  }
  if (argc < 2) {
    fmt::print(stderr, "error: no command given (dartcheck --help lists them)\n");
    return 2;
  }
  // A mistyped option: name the closest the command accepts.
  for (int k = 2; k < argc; ++k) {
    const std::string_view arg = argv[k];
    if (!arg.starts_with("--") || std::string(e.what()).find(std::string(arg.substr(0, arg.find('=')))) == std::string::npos) continue;
    const std::string typed(arg.substr(0, arg.find('=')));
    const auto names = option_names(app, command);
    if (std::find(names.begin(), names.end(), typed) != names.end()) continue;
    const std::string best = closest_name(typed, names);
    fmt::print(stderr, "error: {}: unknown option {}{} (dartcheck help {} lists them)\n", command ? command->get_name() : "dartcheck",
               printable(typed), best.empty() ? "" : fmt::format("; did you mean {}?", best), command ? command->get_name() : "");
    return 2;
  }
  fmt::print(stderr, "error: {}{}\n", command ? command->get_name() + ": " : "", printable(e.what()));
  return 2;
}

}  // namespace dartcheck::cli
