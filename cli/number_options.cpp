#include "cli/number_options.hpp"

#include <fmt/format.h>

#include "core/input_error.hpp"

namespace dartcheck::cli {

NumberCheck count_option(std::uint64_t low, std::uint64_t high) {
  const std::string range = high == std::numeric_limits<std::uint64_t>::max() ? fmt::format("a whole number >= {}", low)
                                                                              : fmt::format("a whole number from {} to {}", low, high);
  return NumberCheck{[=](std::string& text) {
                       const auto v = read_count(text);
                       if (!v || *v < low || *v > high) return fmt::format("expected {}, got '{}'", range, printable(text));
                       text = std::to_string(*v);  // plain decimal for CLI11's conversion
                       return std::string();
                     },
                     high == std::numeric_limits<std::uint64_t>::max() ? fmt::format("COUNT>={}", low) : fmt::format("COUNT in [{},{}]", low, high)};
}

NumberCheck real_option(double low, double high) {
  return NumberCheck{[=](std::string& text) {
                       const auto v = read_real(text);
                       if (!v || *v < low || *v > high) return fmt::format("expected a number from {} to {}, got '{}'", low, high, printable(text));
                       return std::string();
                     },
                     fmt::format("NUMBER in [{},{}]", low, high)};
}

}  // namespace dartcheck::cli
