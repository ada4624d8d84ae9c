#include "core/limits.hpp"

#include <fmt/format.h>

namespace dartcheck {

Limits& limits() {
  static Limits l;
  return l;
}

std::string over_limit(const char* what, std::size_t value, std::size_t limit, const char* option) {
  return fmt::format("{}: {} is over the limit of {} (raise it with {})", what, value, limit, option);
}

}  // namespace dartcheck
