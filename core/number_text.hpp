// Numbers as users write them (options, shard headers): one reader for
// every count, real and duration. std::from_chars and CLI11 alone take
// "010" for octal 8, " -1" for 2^64 - 1 in an unsigned, "nan" and "inf"
// for reals; these refuse all of that.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace dartcheck {

/// Decimal digits only (no sign, space or base prefix; "010" is ten);
/// nullopt otherwise or beyond 2^64 - 1.
std::optional<std::uint64_t> read_count(std::string_view text);

/// A finite real in decimal or scientific notation ("0.5", "1e3"); nullopt
/// for anything else (nan, inf, hex, spaces, a trailing unit).
std::optional<double> read_real(std::string_view text);

/// The longest duration an option takes: 31 days.
inline constexpr double max_duration_seconds = 31 * 24 * 3600;

/// Seconds in "30s", "500ms", "2m", "1h" or a bare number of seconds, at
/// most max_duration_seconds; InputError naming `option` otherwise (nan,
/// inf, zero, negative, an unknown unit).
double parse_duration(const std::string& text, const std::string& option);

}  // namespace dartcheck
