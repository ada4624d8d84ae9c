// The one reader of numbers on the command line (cli/number_options.hpp).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "cli/number_options.hpp"

namespace dartcheck::cli {
namespace {

// Property: every count reads back from its decimal text, and from no
// text with a sign, a space or a base prefix in front.
RC_GTEST_PROP(NumberOptions, CountsReadBackFromDecimalOnly, (std::uint64_t n)) {
  const std::string text = std::to_string(n);
  RC_ASSERT(read_count(text) == std::optional<std::uint64_t>(n));
  for (const char* prefix : {"+", "-", " ", "0x", "\t"}) RC_ASSERT(!read_count(prefix + text).has_value());
  RC_ASSERT(!read_count(text + " ").has_value());
  RC_ASSERT(!read_count(text + "s").has_value());
}

TEST(NumberOptions, CountsAreDecimalAndBounded) {
  EXPECT_EQ(read_count("010"), 10U);  // not octal 8
  EXPECT_EQ(read_count("18446744073709551615"), std::numeric_limits<std::uint64_t>::max());
  EXPECT_FALSE(read_count("18446744073709551616"));  // would wrap
  EXPECT_FALSE(read_count(""));
  EXPECT_FALSE(read_count(" -1"));
  EXPECT_FALSE(read_count("1e3"));
}

// Property: every finite double reads back from its shortest decimal text
// (fmt prints the shortest text that reads back to the same double).
RC_GTEST_PROP(NumberOptions, FiniteRealsReadBack, (double d)) {
  RC_PRE(std::isfinite(d));
  RC_ASSERT(read_real(fmt::format("{}", d)) == std::optional<double>(d));
}

TEST(NumberOptions, RealsAreFiniteAndPlain) {
  EXPECT_EQ(read_real("0.5"), 0.5);
  EXPECT_EQ(read_real("1e3"), 1000.0);
  EXPECT_EQ(read_real("-1"), -1.0);
  for (const char* bad : {"nan", "NaN", "inf", "-inf", "infinity", "0x1p3", " 1", "1 ", "", "1e999", "1,5", "2s"})
    EXPECT_FALSE(read_real(bad)) << bad;
}

}  // namespace
}  // namespace dartcheck::cli
