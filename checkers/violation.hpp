// What a dynamic check reports: every failing dart (or node) with the
// constraint of 002 Def. 9 and the dimension(s) that fail.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/model.hpp"

namespace dartcheck {

enum class Constraint : std::uint8_t {
  incident_out,     // I(i): not the source of exactly one i-arc
  incident_in,      // I(i): not the target of exactly one i-arc
  non_orientation,  // O(i): an incident i-arc has no reverse arc
  cycle,            // C(i,j): not the source of an ijij-cycle
  loop,             // closed G-maps: the i-arc is a loop
  foreign_label,    // an arc labeled i, with i not in D
  predecessor,      // I(i), as stored: the recorded i-predecessor is not the source of the arc in
};

inline constexpr std::uint32_t no_element = 0xffffffffU;

/// One failing element. `element` is a dart of a map or a node of a graph;
/// `count` is the number of arcs found for the incident-arcs constraint,
/// or the recorded predecessor for `predecessor` (whose `j` is then the
/// true source of the arc in, or -1 when no arc comes in).
struct Violation {
  Constraint constraint;
  Dim i;
  Dim j = -1;
  std::uint32_t element;
  std::uint32_t count = 0;
  friend bool operator==(const Violation&, const Violation&) = default;
  friend auto operator<=>(const Violation&, const Violation&) = default;
};

/// "I(2)", "O(1)", "C(0,2)", "no-loop(2)".
std::string constraint_name(const Violation& v);
/// A sentence for a person, naming the element with `element_name`.
std::string describe(const Violation& v, const std::string& element_name);

struct ValidityReport {
  std::string model;
  std::size_t elements = 0;
  std::vector<Violation> violations;  // sorted by element, then constraint
  bool valid() const { return violations.empty(); }
};

}  // namespace dartcheck
