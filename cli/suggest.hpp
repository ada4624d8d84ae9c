// What the argument parser's errors become: one "error:" line, with the
// closest command or option when the user mistyped one, and `help [CMD]`.
// Free of CLI11 (command_line.cpp, its one includer, fills the table), so these
// messages are plain functions of names.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dartcheck::cli {

/// The names the parser knows: its commands, the long options each
/// accepts (global ones included, with their "--"), and the help texts.
struct CommandTable {
  std::vector<std::string> commands;
  std::map<std::string, std::vector<std::string>, std::less<>> options;  // "" = no command
  std::function<std::string(std::string_view command)> help;             // "" = the whole tool
};

/// `dartcheck help` and `dartcheck help CMD`: prints the help and returns
/// the exit status (2 for an unknown CMD); nullopt when argv is not a help
/// request.
std::optional<int> help_request(const CommandTable& table, int argc, char** argv);

/// Prints the parser's error `what` as "error: ..." on stderr, naming the
/// closest command or option to a mistyped one; returns the exit status 2.
int report_parse_error(const CommandTable& table, std::string_view what, int argc, char** argv);

}  // namespace dartcheck::cli
