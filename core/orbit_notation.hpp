// The one reader of the orbit-type notation "<0,1>", "<0,_,2>", "⟨21,31⟩"
// (000's Jerboa labels, 004's orbit types, 003's collect orbits): angle
// brackets (ASCII or U+27E8/U+27E9) around comma-separated entries, each a
// run of digits or '_', spaces anywhere. What an entry means (a dimension,
// a hole, an O-map word) is the caller's: rewriting/jerboa_scheme and
// events/orbit_kind interpret the entries this returns.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace dartcheck {

struct OrbitEntry {
  std::string text;    // digits, or "_"
  std::size_t offset;  // 0-based byte of its first character in the input
};

/// Calls `entry` with each entry of `text` as it is read, so that the
/// first error in reading order is the one reported, the caller's (a
/// dimension too large) or the notation's: std::invalid_argument
/// "orbit type '<0;1>', at byte 3: expected ',' or '>'".
void read_orbit_entries(std::string_view text, const std::function<void(const OrbitEntry&)>& entry);

/// The entries of `text` in order ("<>" has none); errors as above.
std::vector<OrbitEntry> orbit_entries(std::string_view text);

}  // namespace dartcheck
