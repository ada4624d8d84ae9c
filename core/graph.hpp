// Small labeled multigraphs (002 Def. 1): the representation of rule sides
// and pattern graphs. Nodes have names; arcs have a source, a target and a
// label, and parallel arcs with the same label are kept, because a rule may
// break the incident arcs constraint and the checker has to see it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dartcheck {

using NodeId = std::uint32_t;
using ArcId = std::uint32_t;

template <class Label>
struct Arc {
  NodeId source;
  NodeId target;
  Label label;
  friend bool operator==(const Arc&, const Arc&) = default;
};

/// A Σ-labeled multigraph with named nodes. Node and arc ids are dense
/// indices in insertion order; lookups by name are linear, which is right
/// for graphs of a few dozen nodes.
template <class Label>
class LabeledGraph {
 public:
  NodeId add_node(std::string name) {
    names_.push_back(std::move(name));
    return static_cast<NodeId>(names_.size() - 1);
  }
  ArcId add_arc(NodeId s, NodeId t, Label l) {
    arcs_.push_back({s, t, std::move(l)});
    return static_cast<ArcId>(arcs_.size() - 1);
  }

  std::size_t node_count() const { return names_.size(); }
  std::size_t arc_count() const { return arcs_.size(); }
  const std::string& name(NodeId v) const { return names_[v]; }
  const std::vector<std::string>& names() const { return names_; }
  const Arc<Label>& arc(ArcId e) const { return arcs_[e]; }
  const std::vector<Arc<Label>>& arcs() const { return arcs_; }

  std::optional<NodeId> find(std::string_view name) const {
    for (NodeId v = 0; v < names_.size(); ++v)
      if (names_[v] == name) return v;
    return std::nullopt;
  }

  /// Arcs with the given source (resp. target) and label.
  std::vector<ArcId> out_arcs(NodeId v, const Label& l) const { return select(v, l, true); }
  std::vector<ArcId> in_arcs(NodeId v, const Label& l) const { return select(v, l, false); }

  friend bool operator==(const LabeledGraph&, const LabeledGraph&) = default;

 private:
  std::vector<ArcId> select(NodeId v, const Label& l, bool out) const {
    std::vector<ArcId> r;
    for (ArcId e = 0; e < arcs_.size(); ++e)
      if ((out ? arcs_[e].source : arcs_[e].target) == v && arcs_[e].label == l) r.push_back(e);
    return r;
  }

  std::vector<std::string> names_;
  std::vector<Arc<Label>> arcs_;
};

/// A D-topological graph: arcs labeled by dimensions (002 Def. 6).
using TopoGraph = LabeledGraph<int>;

}  // namespace dartcheck
