#include "cli/number_options.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "core/input_error.hpp"

namespace dartcheck::cli {

std::optional<std::uint64_t> read_count(std::string_view text) {
  std::uint64_t v = 0;
  if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v, 10);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return v;
}

std::optional<double> read_real(std::string_view text) {
  double v = 0;
  // from_chars takes "inf" and "nan" too, and a leading '-' but no '+'.
  if (text.empty() || text.find_first_not_of("0123456789.eE+-") != std::string_view::npos) return std::nullopt;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v, std::chars_format::general);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

CLI::Validator count_option(std::uint64_t low, std::uint64_t high) {
  const std::string range = high == std::numeric_limits<std::uint64_t>::max() ? fmt::format("a whole number >= {}", low)
                                                                              : fmt::format("a whole number from {} to {}", low, high);
  return CLI::Validator(
      [=](std::string& text) {
        const auto v = read_count(text);
        if (!v || *v < low || *v > high) return fmt::format("expected {}, got '{}'", range, printable(text));
        text = std::to_string(*v);  // plain decimal for CLI11's conversion
        return std::string();
      },
      high == std::numeric_limits<std::uint64_t>::max() ? fmt::format("COUNT>={}", low) : fmt::format("COUNT in [{},{}]", low, high));
}

CLI::Validator real_option(double low, double high) {
  return CLI::Validator(
      [=](std::string& text) {
        const auto v = read_real(text);
        if (!v || *v < low || *v > high) return fmt::format("expected a number from {} to {}, got '{}'", low, high, printable(text));
        return std::string();
      },
      fmt::format("NUMBER in [{},{}]", low, high));
}

}  // namespace dartcheck::cli
