// The libraries dartcheck was built with, for `dartcheck --version`.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace dartcheck::reports {

/// (library, version) pairs: the versions of the headers compiled against,
/// and for Z3 and GMP the version of the library loaded.
std::vector<std::pair<std::string, std::string>> library_versions();

/// dartcheck's own version (the project's, as CMake knows it).
std::string dartcheck_version();

}  // namespace dartcheck::reports
