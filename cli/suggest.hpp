// What the argument parser's errors become: one "error:" line, with the
// closest command or option when the user mistyped one, and `help [CMD]`.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>

namespace dartcheck::cli {

/// `dartcheck help` and `dartcheck help CMD`: prints the help and returns
/// the exit status (2 for an unknown CMD); nullopt when argv is not a help
/// request.
std::optional<int> help_request(const CLI::App& app, int argc, char** argv);

/// Prints `e` as "error: ..." on stderr (help and --version on stdout),
/// naming the closest command or option to a mistyped one; returns the
/// exit status (0 for help and version, 2 otherwise).
int report_parse_error(const CLI::App& app, const CLI::ParseError& e, int argc, char** argv);

}  // namespace dartcheck::cli
