// Embedding values (003 Sec. 3.4): the carrier sets of the user types an
// embedding pi : <o> -> tau may take, and their multisets tau• (the result
// of a collect operator). Values compare exactly: two darts of one orbit
// agree when the same term gave both, bit for bit.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/formatting.hpp"

namespace dartcheck {

/// The value types of the signature (003 Sec. 3.4 names point_2D,
/// vector_2D, color; Sec. 9.2 adds point_3D, boolean, string).
enum class ValueType : std::uint8_t { point2, point3, vector2, vector3, color, real, integer, boolean, string };

std::string_view name_of(ValueType t);
/// "point2", "point_2D", "Point2" ... (case and '_' ignored, "2d" = "2"),
/// "float"/"double" = real, "int" = integer, "bool" = boolean.
std::optional<ValueType> type_by_name(std::string_view name);
/// Number of coordinates of a geometric type (color: 3), 0 otherwise.
int coordinates(ValueType t);

/// A sort of the term language: a value type, its multiset, or Node.
struct Sort {
  enum Kind : std::uint8_t { value, multiset, node } kind = value;
  ValueType type = ValueType::real;
  static Sort of(ValueType t) { return {value, t}; }
  static Sort bag(ValueType t) { return {multiset, t}; }
  static Sort node_sort() { return {node, ValueType::real}; }
  std::string str() const;
  friend bool operator==(const Sort&, const Sort&) = default;
};

/// 40 bytes and trivially copyable: pools of values move with memmove and
/// compare member by member. A string is interned, so `i` is its number in
/// a process-wide table and equal strings have equal numbers.
struct Value {
  ValueType type = ValueType::real;
  std::array<double, 3> x{};  // coordinates; real in x[0]
  std::int64_t i = 0;         // integer, boolean; a string's intern number

  // Inline: compiled terms (rewriting/algebra.hpp) build values in loops.
  static Value real(double v) { return {ValueType::real, {v, 0, 0}, 0}; }
  static Value integer(std::int64_t v) { return {ValueType::integer, {}, v}; }
  static Value boolean(bool v) { return {ValueType::boolean, {}, v ? 1 : 0}; }
  static Value text(std::string v);
  static Value coords(ValueType t, std::array<double, 3> c) { return {t, c, 0}; }

  /// The text of a string value (empty for other types).
  const std::string& string() const;

  /// "(0.5, 0.5)" for points and vectors, "rgb(1, 0, 0)" for colors,
  /// the number, true/false, or the quoted string.
  std::string str() const;
  friend bool operator==(const Value&, const Value&) = default;
};
static_assert(std::is_trivially_copyable_v<Value>);

/// A strict order on values of one type: coordinates, then the integer,
/// then a string's text (not its intern number, which depends on the
/// order strings were first met).
/// Inline and spelt out: every collect sorts its multiset with it (a call
/// per comparison was a tenth of a compiled face triangulation). It is
/// std::tie(type, x, i)'s order exactly: the first coordinate that is not
/// == decides by <, so a NaN there gives false both ways, as tuple's
/// three-way comparison does.
inline bool value_less(const Value& a, const Value& b) {
  if (a.type != b.type) return a.type < b.type;
  if (a.type == ValueType::string) [[unlikely]]
    return a.string() < b.string();
  for (std::size_t k = 0; k < 3; ++k)
    if (a.x[k] != b.x[k]) return a.x[k] < b.x[k];
  return a.i < b.i;
}

/// Parses a value of type t from text: "1 2", "1, 2", "(1, 2)", "[1,2]"
/// for coordinates; a number, true/false, or any text for strings.
/// Returns nullopt (and the reason) when the text is not such a value.
std::optional<Value> parse_value(ValueType t, std::string_view text, std::string* why = nullptr);

// fmt::format("{}", x) prints x.str() (core/formatting.hpp).
template <>
inline constexpr bool formatted_by_str<Sort> = true;
template <>
inline constexpr bool formatted_by_str<Value> = true;

}  // namespace dartcheck
