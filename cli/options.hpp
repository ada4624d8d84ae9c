// Checks of command-line options that several commands share.
#pragma once

#include <string>

#include "io/catalog.hpp"

namespace dartcheck::cli {

/// Reads the catalog a command works on, after checking --format (text or
/// json) and that --rule, if given, names one of its rules.
Catalog read_command_catalog(const std::string& file, const std::string& rule, const std::string& format);

/// Seconds in "30s", "500ms", "2m", "1h" or a bare number of seconds;
/// InputError naming `option` otherwise.
double parse_duration(const std::string& text, const std::string& option);

}  // namespace dartcheck::cli
