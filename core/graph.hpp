// Small labeled multigraphs (002 Def. 1): the representation of rule sides
// and pattern graphs. Nodes have names; arcs have a source, a target and a
// label, and parallel arcs with the same label are kept, because a rule may
// break the incident arcs constraint and the checker has to see it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
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
/// indices in insertion order. Names and incident arcs are indexed as the
/// graph is built, so lookups cost what they return: inferred rules have
/// thousands of nodes (000 Sec. 8.3 wants the whole inference linear).
template <class Label>
class LabeledGraph {
 public:
  NodeId add_node(std::string name) {
    const auto v = static_cast<NodeId>(names_.size());
    by_name_.emplace(name, v);  // the first node of a name, as find() says
    names_.push_back(std::move(name));
    out_.emplace_back();
    in_.emplace_back();
    return v;
  }
  ArcId add_arc(NodeId s, NodeId t, Label l) {
    const auto e = static_cast<ArcId>(arcs_.size());
    arcs_.push_back({s, t, std::move(l)});
    out_[s].push_back(e);
    in_[t].push_back(e);
    return e;
  }

  std::size_t node_count() const { return names_.size(); }
  std::size_t arc_count() const { return arcs_.size(); }
  const std::string& name(NodeId v) const { return names_[v]; }
  const std::vector<std::string>& names() const { return names_; }
  const Arc<Label>& arc(ArcId e) const { return arcs_[e]; }
  const std::vector<Arc<Label>>& arcs() const { return arcs_; }

  /// The first node named `name`.
  std::optional<NodeId> find(std::string_view name) const {
    const auto it = by_name_.find(std::string(name));
    if (it == by_name_.end()) return std::nullopt;
    return it->second;
  }

  /// Arcs with the given source (resp. target), in id order.
  const std::vector<ArcId>& out_arcs(NodeId v) const { return out_[v]; }
  const std::vector<ArcId>& in_arcs(NodeId v) const { return in_[v]; }
  /// Arcs with the given source (resp. target) and label, in id order.
  std::vector<ArcId> out_arcs(NodeId v, const Label& l) const { return select(out_[v], l); }
  std::vector<ArcId> in_arcs(NodeId v, const Label& l) const { return select(in_[v], l); }

  // The indexes follow from names and arcs in insertion order.
  friend bool operator==(const LabeledGraph& a, const LabeledGraph& b) { return a.names_ == b.names_ && a.arcs_ == b.arcs_; }

 private:
  std::vector<ArcId> select(const std::vector<ArcId>& arcs, const Label& l) const {
    std::vector<ArcId> r;
    for (ArcId e : arcs)
      if (arcs_[e].label == l) r.push_back(e);
    return r;
  }

  std::vector<std::string> names_;
  std::vector<Arc<Label>> arcs_;
  std::unordered_map<std::string, NodeId> by_name_;
  std::vector<std::vector<ArcId>> out_, in_;
};

/// A D-topological graph: arcs labeled by dimensions (002 Def. 6).
using TopoGraph = LabeledGraph<int>;

}  // namespace dartcheck
