// The pi-orbits of one side of an instantiated rule scheme (002 Def. 19):
// instance (x, p), node x of the side in pattern copy p, is joined to
// (y, p·w) by each arc x -(w, i)-> y with i in pi's orbit <o>. An embedded
// application evaluates one term per class (003 Thm 4) and writes each
// class as one orbit of H. A DPO rule is a scheme with one pattern copy.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "rewriting/rule.hpp"
#include "rewriting/pattern_graphs.hpp"

namespace dartcheck {

/// The classes, numbered 0 .. count - 1: instance (x, p) is in class
/// of(x, p). Nodes of one group share a table: id[group_of[x]][p].
struct InstantiatedClasses {
  std::vector<std::uint32_t> group_of;
  std::vector<std::vector<std::uint32_t>> id;
  std::uint32_t count = 0;
  /// Whether they were computed per pattern copy (one walk over the
  /// pattern per group of nodes) rather than per instance.
  bool by_pattern = false;
  std::uint32_t of(NodeId x, std::size_t p) const { return id[group_of[x]][p]; }

  /// Working memory of the computation, kept between calls.
  struct Scratch {
    std::vector<std::uint32_t> up, number;
    std::vector<std::pair<ArcId, int>> shifted;
    std::vector<std::vector<int>> group_words;
  } scratch;
};

/// A caller's numbering of one group's classes in place of the walk:
/// given the group, the nodes' groups and the group's steps (pattern
/// generators), it either fills id (one entry per pattern copy, numbers
/// from count on, count advanced) and returns true, or returns false and
/// the group is walked. The numbering may split a class (the embedded
/// application's kept-label shortcut numbers one class per copy where
/// every copy of a class has one value).
using GroupNumbering = std::function<bool(std::uint32_t group, const std::vector<std::uint32_t>& group_of, const std::vector<int>& steps,
                                          std::vector<std::uint32_t>& id, std::uint32_t& count)>;

/// The classes of `side` (with its arcs' words) instantiated on `pattern`
/// (null for a DPO rule: one copy) for the orbit <o>. `out` keeps its
/// memory for the next call. With `numbering`, a group it numbers is not
/// walked (only when the classes are found by groups, `by_pattern`).
void instantiated_classes(const TopoGraph& side, const std::vector<ConjWord>& words, const PatternGraphs* pattern, const std::vector<Dim>& orbit,
                          InstantiatedClasses& out, const GroupNumbering* numbering = nullptr);

/// The same classes by the definition: one union-find over every
/// instance (each node its own group). The reference for tests.
void instantiated_classes_by_instance(const TopoGraph& side, const std::vector<ConjWord>& words, const PatternGraphs* pattern,
                                      const std::vector<Dim>& orbit, InstantiatedClasses& out);

}  // namespace dartcheck
