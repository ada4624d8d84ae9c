// The one reader of the orbit-type notation "<0,1>", "<0,_,2>", "⟨21,31⟩"
// (000's Jerboa labels, 004's orbit types, 003's collect orbits): angle
// brackets (ASCII or U+27E8/U+27E9) around comma-separated entries, each a
// run of digits or '_', spaces anywhere. What an entry means (a dimension,
// a hole, an O-map word) is the caller's; the generalized orbit type of
// Jerboa labels (entries are dimensions or '_') is read here too, events'
// orbit kinds (O-map words) in events/orbit_kind.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/model.hpp"

namespace dartcheck {

struct OrbitEntry {
  std::string text;    // digits, or "_"
  std::size_t offset;  // 0-based byte of its first character in the input
};

/// The notation's own error (not the caller's): what() names the text and
/// the 1-based byte; offset() is that byte, 0-based, for a caller that
/// reads the orbit type inside a longer text.
class OrbitNotationError : public AtOffset<ValueError> {
 public:
  using AtOffset::AtOffset;
};

/// Calls `entry` with each entry of `text` as it is read, so that the
/// first error in reading order is the one reported, the caller's (a
/// dimension too large) or the notation's: ValueError
/// "orbit type '<0;1>', at byte 3: expected ',' or '>'".
void read_orbit_entries(std::string_view text, const std::function<void(const OrbitEntry&)>& entry);

/// The entries of `text` in order ("<>" has none); errors as above.
std::vector<OrbitEntry> orbit_entries(std::string_view text);

/// A generalized orbit type: one entry per position, nullopt for the
/// removing symbol '_'.
using OrbitType = std::vector<std::optional<Dim>>;

/// Parses "<0,_,2>" (also with ⟨ ⟩). Throws ValueError naming
/// the byte position of the problem, and when a dimension repeats (a
/// relabeling function is injective, 000 Def. 4.1).
OrbitType parse_orbit_type(std::string_view text);
std::string orbit_type_str(const OrbitType& t);

}  // namespace dartcheck
