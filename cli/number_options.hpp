// Numbers on the command line: CLI11's own conversion takes "010" for
// octal 8, " -1" for 2^64 - 1 in an unsigned option, "nan" and "inf" for
// reals, and wraps what does not fit; these checks read the text with
// core/number_text first, refuse all of that with the accepted range, and
// hand CLI11 the number in plain decimal.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <string>

#include "core/number_text.hpp"

namespace dartcheck::cli {

/// A check of an option's text for CLI11's Validator (built in command_line.cpp,
/// the one file that includes CLI11): `check` returns the error or "" and
/// may rewrite the text; `name` is the type shown in --help.
struct NumberCheck {
  std::function<std::string(std::string&)> check;
  std::string name;
};

/// The check of a count option: a count from `low` to `high`. It rewrites
/// the text, so give it with `->transform()` (CLI11 drops what `->check()`
/// changes).
NumberCheck count_option(std::uint64_t low = 0, std::uint64_t high = std::numeric_limits<std::uint64_t>::max());

/// The check of a real option: a finite real from `low` to `high`.
NumberCheck real_option(double low, double high);

}  // namespace dartcheck::cli
