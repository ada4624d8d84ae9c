// dartcheck's command line, as main() runs it.
#pragma once

#include <string>

namespace dartcheck::cli {

/// Parses `argv`, runs the command it names and returns the exit status
/// (cli/commands.hpp). `version` is what --version prints after
/// "dartcheck ": the release and the git revision.
int run_command_line(int argc, char** argv, const std::string& version);

}  // namespace dartcheck::cli
