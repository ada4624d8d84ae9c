// dartcheck: checks modeling operations on G-maps and O-maps. The one file
// that sees the git revision (rebuilt at each commit): the command line
// itself is cli/command_line.cpp.
#include <string>

#include "cli/command_line.hpp"
#include "revision.hpp"

int main(int argc, char** argv) {
  return dartcheck::cli::run_command_line(argc, argv, std::string(DARTCHECK_VERSION) + " (" + DARTCHECK_REVISION + ")");
}
