// "did you mean 'check'?" for a mistyped subcommand.
#pragma once

#include <CLI/CLI.hpp>

namespace dartcheck::cli {

/// When argv[1] names no subcommand of `app`, prints the closest one (by
/// edit distance) on stderr, if any is close.
void suggest_subcommand(const CLI::App& app, int argc, char** argv);

}  // namespace dartcheck::cli
