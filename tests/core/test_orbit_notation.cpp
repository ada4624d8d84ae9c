// The orbit-type notation read once for every caller (Jerboa labels, event
// orbit types): entries and their byte offsets counted by hand.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "core/orbit_notation.hpp"

using namespace dartcheck;

TEST(OrbitNotation, EntriesWithTheirOffsets) {
  const auto e = orbit_entries("<0, _ ,12>");
  ASSERT_EQ(e.size(), 3U);
  EXPECT_EQ(e[0].text, "0");
  EXPECT_EQ(e[0].offset, 1U);
  EXPECT_EQ(e[1].text, "_");
  EXPECT_EQ(e[1].offset, 4U);
  EXPECT_EQ(e[2].text, "12");
  EXPECT_EQ(e[2].offset, 7U);
  EXPECT_TRUE(orbit_entries("< >").empty());
}

TEST(OrbitNotation, MathematicalAngleBrackets) {
  // U+27E8 is three bytes: '2' starts at byte 3, '3' at byte 6.
  const auto e = orbit_entries("\u27e821,31\u27e9");
  ASSERT_EQ(e.size(), 2U);
  EXPECT_EQ(e[0].text, "21");
  EXPECT_EQ(e[0].offset, 3U);
  EXPECT_EQ(e[1].text, "31");
  EXPECT_EQ(e[1].offset, 6U);
}

TEST(OrbitNotation, ErrorsNameTheByte) {
  auto error = [](const char* text) {
    try {
      orbit_entries(text);
    } catch (const ValueError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(error("<0;1>"), "orbit type '<0;1>', at byte 3: expected ',' or '>'");
  EXPECT_EQ(error("0,1>"), "orbit type '0,1>', at byte 1: expected '<' or '⟨'");
  EXPECT_EQ(error("<0,,1>"), "orbit type '<0,,1>', at byte 4: expected a dimension or '_'");
  EXPECT_EQ(error("<0,1> x"), "orbit type '<0,1> x', at byte 7: unexpected text after the orbit type");
  EXPECT_EQ(error("<0,1"), "orbit type '<0,1', at byte 5: expected ',' or '>'");
}
