// Counts in sentences: "1 rule", "2 rules", "1 analysis", "3 analyses".
#pragma once

#include <string>
#include <string_view>

#include <fmt/format.h>

namespace dartcheck {

/// "n word" with the plural when n != 1 (`plural` defaults to word + "s").
inline std::string counted(std::size_t n, std::string_view singular, std::string_view plural = {}) {
  if (n == 1) return fmt::format("1 {}", singular);
  return plural.empty() ? fmt::format("{} {}s", n, singular) : fmt::format("{} {}", n, plural);
}

}  // namespace dartcheck
