// Domain values through fmt (core/formatting.hpp): an enum prints its name
// and a class its str(), with fmt's own width and alignment. The expected
// texts are the spellings the outputs and schemas use (docs/cli.md's
// refusal names, 003's value syntax, 002's conjugate words).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "core/conjugate_words.hpp"
#include "core/formatting.hpp"
#include "io/volume_cells.hpp"
#include "rewriting/match.hpp"
#include "rewriting/value.hpp"

using namespace dartcheck;

TEST(Formatting, EnumsPrintTheirNamesWithWidthAndAlignment) {
  EXPECT_EQ(fmt::format("{}", Refusal::dangling), "dangling");
  EXPECT_EQ(fmt::format("[{:>12}]", Refusal::no_match), "[    no-match]");
  EXPECT_EQ(fmt::format("{:<8}|", ValueType::point2), "point2  |");
  EXPECT_EQ(fmt::format("{}", CellKind::pyramid), "pyramid");
}

TEST(Formatting, ClassesPrintTheirStr) {
  const ConjWord w = ConjWord::of_dims({0, 2});
  EXPECT_EQ(fmt::format("{}", w), w.str());
  EXPECT_EQ(fmt::format("{}", Value::coords(ValueType::point2, {0.5, 0.5, 0})), "(0.5, 0.5)");
}
