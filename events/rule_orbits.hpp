// Rule orbits X<o>(n) and their completeness (004 Sec. 2.2).
//
// The <o>-orbit of node n in a side X of a rule gathers the nodes joined to
// n by explicit arcs labeled in <o>; implicit links are loops and never
// join two nodes. The orbit is complete when every node has, for every
// generator of <o>, an explicit arc or an implicit link: then it matches
// whole <o>-orbits of the map, not parts of them.
#pragma once

#include <string>
#include <vector>

#include "events/event_rule.hpp"
#include "events/orbit_kind.hpp"

namespace dartcheck::events {

struct RuleOrbit {
  std::vector<NodeId> nodes;  // ascending
  bool complete = true;
  /// Why not complete: "n0 has no 2-link", one per node and generator.
  std::vector<std::string> missing;
};

struct SideOrbits {
  std::vector<RuleOrbit> orbits;  // in order of their smallest node
  std::vector<int> orbit_of;      // per node
};

/// Where the w-path from v along explicit arcs ends: the last node it
/// reaches and how many letters it followed (w.size() when the whole path
/// is in the pattern; fewer when it leaves the pattern there).
struct ExplicitPathEnd {
  NodeId node;
  std::size_t letters;
  friend bool operator==(const ExplicitPathEnd&, const ExplicitPathEnd&) = default;
};
ExplicitPathEnd follow_explicit(const EventSide& side, NodeId v, const OrbitWord& w);

/// The <o>-orbits of one side of `r`.
SideOrbits side_orbits(const EventRule& r, const EventSide& side, const OrbitKind& kind);

/// True when dimension `label` of an implicit link belongs to <o>.
inline bool in_kind(const OrbitKind& kind, const std::optional<Dim>& label) { return label && has_dim(kind.dims(), *label); }

}  // namespace dartcheck::events
