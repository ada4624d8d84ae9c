// Domain values through fmt: `fmt::format("{}", refusal)` prints an enum
// of the papers' vocabulary by its name, and a value that spells itself
// (a conjugate word, a term, a value, a source location) by its str().
//
// An enum opts in by declaring `name_of(E)` in its namespace (found by
// argument-dependent lookup): Refusal, ValueType, Event, Certainty,
// Status, Agreement, Reading, FailureKind, FuzzClass, CellKind. A class
// opts in by specialising `formatted_by_str` to true next to it.
#pragma once

#include <concepts>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include <fmt/format.h>

namespace dartcheck {

/// An enum with a name: `name_of(e)` found by argument-dependent lookup.
template <class T>
concept NamedEnum = std::is_enum_v<T> && requires(T t) {
  { name_of(t) } -> std::convertible_to<std::string_view>;
};

/// The inverse of name_of over the values 0..last of an enum numbered
/// from 0 (reading back what a record wrote by name), or nullopt.
template <NamedEnum E>
std::optional<E> named(std::string_view name, E last) {
  using U = std::underlying_type_t<E>;
  for (U k = 0; k <= static_cast<U>(last); ++k)
    if (name_of(static_cast<E>(k)) == name) return static_cast<E>(k);
  return std::nullopt;
}

/// A class that prints as its str(); specialised to true by each class.
template <class T>
inline constexpr bool formatted_by_str = false;

}  // namespace dartcheck

template <class T>
struct fmt::formatter<T, char, std::enable_if_t<dartcheck::NamedEnum<T>>> : fmt::formatter<std::string_view> {
  auto format(T value, fmt::format_context& ctx) const { return fmt::formatter<std::string_view>::format(std::string_view(name_of(value)), ctx); }
};

template <class T>
struct fmt::formatter<T, char, std::enable_if_t<dartcheck::formatted_by_str<T>>> : fmt::formatter<std::string_view> {
  auto format(const T& value, fmt::format_context& ctx) const {
    const std::string text = value.str();
    return fmt::formatter<std::string_view>::format(text, ctx);
  }
};
