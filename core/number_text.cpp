#include "core/number_text.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "core/input_error.hpp"

namespace dartcheck {

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

double parse_duration(const std::string& text, const std::string& option) {
  // The number, then a unit: "30s", "500ms", "2m", "1h", or bare seconds.
  const std::size_t split = text.find_first_not_of("0123456789.eE+-");
  const std::string unit = split == std::string::npos ? "" : text.substr(split);
  const auto v = read_real(std::string_view(text).substr(0, split == std::string::npos ? text.size() : split));
  const double scale = unit.empty() || unit == "s" ? 1 : unit == "ms" ? 1e-3 : unit == "m" || unit == "min" ? 60 : unit == "h" ? 3600 : -1;
  if (!v || scale < 0 || !(*v > 0))
    throw UsageError(fmt::format("{}: expected a positive duration such as 30s, 500ms or 2m, got '{}'", option, printable(text)));
  // A deadline is a clock reading plus the duration: keep it far from
  // overflow (steady_clock counts nanoseconds in 64 bits, about 292 years).
  if (*v * scale > max_duration_seconds)
    throw UsageError(fmt::format("{}: at most {} s (31 days), got '{}'", option, max_duration_seconds, printable(text)));
  return *v * scale;
}

}  // namespace dartcheck
