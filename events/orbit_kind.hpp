// Orbit types for event detection (004 Sec. 2.1): the set of link labels
// an orbit follows. For G-maps a generator is a dimension; for O-maps a
// vertex needs composed links (002 Sec. 3.3), so a generator is a word of
// dimensions, "21" for the dart reached along 2 then 1.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/model.hpp"
#include "core/orbit.hpp"
#include "core/orbit_notation.hpp"

namespace dartcheck::events {

struct OrbitKind {
  std::vector<OrbitWord> generators;
  /// Every generator is a single dimension (G-map orbit types, and the
  /// O-map face and edge orbits).
  bool single_letters() const;
  /// The dimensions of the single-letter generators, as a mask.
  DimSet dims() const;
  /// "<0,1>", "<21,31>".
  std::string str() const;
  friend bool operator==(const OrbitKind&, const OrbitKind&) = default;
};

/// Parses "<0,1>" (or "<21,31>" on an O-map): entries separated by commas,
/// each a dimension of the model (G-maps) or a word of one-digit
/// dimensions (O-maps). Throws ValueError naming the entry.
OrbitKind parse_orbit_kind(std::string_view text, const Model& model);

/// The entries of an orbit type, whatever the model: the syntax that
/// parse_orbit_kind checks first (ValueError naming the byte,
/// or an empty type), so that a command refuses a malformed --orbit once,
/// before any work, and skips only the rules whose model it does not fit.
std::vector<OrbitEntry> orbit_kind_entries(std::string_view text);

/// The orbit types `events` analyses by default: every non-empty subset
/// of D for a G-map (004 Table 1 lists them for n = 2); for an O-map the
/// non-empty subsets of D plus the vertex orbit <21,...,n1> (002 Sec. 3.3).
std::vector<OrbitKind> all_orbit_kinds(const Model& model);

}  // namespace dartcheck::events
