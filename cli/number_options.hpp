// Numbers on the command line: one reader for every count, real and
// duration of every option. CLI11's own conversion takes "010" for octal
// 8, " -1" for 2^64 - 1 in an unsigned option, "nan" and "inf" for reals,
// and wraps what does not fit; these checks run on the text first, refuse
// all of that with the accepted range, and hand CLI11 the number in plain
// decimal.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>

#include <CLI/CLI.hpp>

namespace dartcheck::cli {

/// Decimal digits only (no sign, space or base prefix; "010" is ten);
/// nullopt otherwise or beyond 2^64 - 1.
std::optional<std::uint64_t> read_count(std::string_view text);

/// A finite real in decimal or scientific notation ("0.5", "1e3"); nullopt
/// for anything else (nan, inf, hex, spaces, a trailing unit).
std::optional<double> read_real(std::string_view text);

/// The check of a count option: a count from `low` to `high`. It rewrites
/// the text, so give it with `->transform()` (CLI11 drops what `->check()`
/// changes).
CLI::Validator count_option(std::uint64_t low = 0, std::uint64_t high = std::numeric_limits<std::uint64_t>::max());

/// The check of a real option: a finite real from `low` to `high`.
CLI::Validator real_option(double low, double high);

}  // namespace dartcheck::cli
