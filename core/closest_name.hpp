// "Did you mean": the name a user most likely meant when they mistyped one
// (a command, an option, a catalog key).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace dartcheck {

/// The Levenshtein distance between `a` and `b`.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The name of `names` closest to `typed`: within edit distance 2, or
/// one that `typed` (3 characters or more) begins; empty when none is.
std::string closest_name(std::string_view typed, const std::vector<std::string>& names);

}  // namespace dartcheck
