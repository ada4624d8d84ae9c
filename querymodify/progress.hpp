// What a long recombination says while it runs: the stage, and in the
// candidate search how far it is (the search on 460k tetrahedra takes
// about half a minute). The library only calls it; the command prints.
#pragma once

#include <cstddef>
#include <functional>
#include <string_view>

namespace dartcheck::querymodify {

/// Called as each stage starts ("searching hex candidates", 0, 0) and
/// during a counted one (done of total units, e.g. vertices).
using Progress = std::function<void(std::string_view stage, std::size_t done, std::size_t total)>;

}  // namespace dartcheck::querymodify
