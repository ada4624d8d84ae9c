#include "inference/folding.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>

namespace dartcheck::inference {

const char* name_of(FailureKind k) {
  switch (k) {
    case FailureKind::arc:
      return "arc failure";
    case FailureKind::instantiation:
      return "instantiation failure";
    case FailureKind::relabeling:
      return "relabeling failure";
    case FailureKind::undecided:
      return "undecided position";
    case FailureKind::unreached:
      return "unreached dart";
    case FailureKind::shared:
      return "shared failure";
  }
  return "?";
}

const std::vector<Dart>& orbit_darts(OrbitWalker& walker, const std::vector<Dim>& orbit, Dart start) {
  const auto generators = dims_generators(orbit);
  return walker.orbit(start, generators);
}

std::vector<Dart> orbit_darts(const Map& g, const std::vector<Dim>& orbit, Dart start) {
  OrbitWalker walker(g);
  return orbit_darts(walker, orbit, start);
}

FoldScratch::FoldScratch(const KappaGraph& graph) : walker(graph.before()), owner(graph.size(), -1), position(graph.size(), 0) {}

namespace {

std::string dim_name(Dim d) { return d == kappa_arc ? std::string("κ") : std::to_string(d); }

// One run of the folding. Nodes own their darts: owner_[u] is the node of
// dart u of κ(G, H) (-1 if none yet) and position_[u] its q, so that
// "(b, m') for which b?" is one lookup. The tables are the scratch's; the
// run resets the darts it owned when it ends.
class Folder {
 public:
  Folder(const KappaGraph& g, const std::vector<Dim>& orbit, const FoldOptions& options, FoldScratch& scratch)
      : g_(g), orbit_(orbit), options_(options), n_(g.model().dimension()), scratch_(scratch), owner_(scratch.owner), position_(scratch.position) {}
  ~Folder() {
    for (Dart u : owned_) owner_[u] = -1, position_[u] = 0;
  }
  Folder(const Folder&) = delete;
  Folder& operator=(const Folder&) = delete;

  FoldResult run(Dart start) {
    // Step 1: the orbit graph G<o>(a) and the hook.
    const std::vector<Dart> darts = orbit_darts(scratch_.walker, orbit_, start);
    k_ = darts.size();
    scheme_.orbit = orbit_;
    SchemeNode hook;
    hook.label.assign(orbit_.begin(), orbit_.end());
    hook.darts = darts;
    add_node(std::move(hook));
    note_hook_like(0);
    // The orbit's links as positions: neighbour_[q * r + p] is the position
    // of the o_p-neighbour of b_q.
    const std::size_t r = orbit_.size();
    neighbour_.resize(k_ * r);
    for (std::size_t q = 0; q < k_; ++q)
      for (std::size_t p = 0; p < r; ++p) neighbour_[q * r + p] = position_[g_.link(orbit_[p], darts[q])];
    explicit_.assign(static_cast<std::size_t>(n_ + 2), -1);
    // Step 2: breadth-first over the nodes of S.
    for (std::size_t m = 0; m < scheme_.nodes.size(); ++m)
      if (!build_arcs(static_cast<int>(m))) return failed();
    // Every dart of κ(G, H) must be reached; the scan runs only when not.
    for (Dart u = 0; owned_.size() < g_.size() && u < g_.size(); ++u)
      if (owner_[u] < 0) {
        fail(FailureKind::unreached, 0, 0, u,
             fmt::format("dart {} is not reached from the hook: κ(G, H) is not connected (the example must be one connected piece, "
                         "before and after joined by preserved darts)",
                         g_.name(u)));
        return failed();
      }
    return {std::move(scheme_), std::nullopt, std::move(hook_like_)};
  }

 private:
  Dart dart(int m, std::size_t q) const { return scheme_.nodes[static_cast<std::size_t>(m)].darts[q]; }
  Dart link(Dim d, Dart u) const { return d == kappa_arc ? g_.kappa(u) : g_.link(d, u); }

  void add_node(SchemeNode node) {
    const int m = static_cast<int>(scheme_.nodes.size());
    for (std::size_t q = 0; q < node.darts.size(); ++q) {
      owner_[node.darts[q]] = m;
      position_[node.darts[q]] = static_cast<std::uint32_t>(q);
      owned_.push_back(node.darts[q]);
    }
    scheme_.nodes.push_back(std::move(node));
    explicit_.resize(scheme_.nodes.size() * static_cast<std::size_t>(n_ + 2), -1);
  }

  FoldResult failed() { return {std::nullopt, std::move(failure_), std::move(hook_like_)}; }

  // A node of L labelled as the hook (o_p -> o_p at every position): its
  // darts are a <o>-orbit of G whose folding is this one re-rooted. If an
  // earlier folding failed through it, this one fails too.
  bool note_hook_like(int m) {
    const SchemeNode& node = scheme_.nodes[static_cast<std::size_t>(m)];
    if (options_.strict || node.after || !std::equal(orbit_.begin(), orbit_.end(), node.label.begin(), node.label.end())) return true;
    hook_like_.insert(hook_like_.end(), node.darts.begin(), node.darts.end());
    const auto& failed = scratch_.failed_from;
    if (m == 0 || failed.empty() || failed[node.darts[0]] == no_dart) return true;
    return fail(FailureKind::shared, m, 0, node.darts[0],
                fmt::format("node n{} is the {}-orbit of {}, which the folding from start {} built with the same label and then failed: "
                            "hooked at n{} this folding is that one, so it fails too (000 Sec. 10.3)",
                            m, orbit_type_str(OrbitType(orbit_.begin(), orbit_.end())), g_.name(node.darts[0]), failed[node.darts[0]], m));
  }

  bool fail(FailureKind kind, int node, Dim d, Dart u, std::string text) {
    failure_ = FoldFailure{kind, node, d, u, std::move(text)};
    return false;
  }

  // The explicit-arc slot of (m, d): d in 0..n, κ last.
  int& arc_slot(int m, Dim d) {
    return explicit_[static_cast<std::size_t>(m) * static_cast<std::size_t>(n_ + 2) + static_cast<std::size_t>(d == kappa_arc ? n_ + 1 : d)];
  }

  // Step 2.1: the explicit arcs of m, on every dimension its label does
  // not produce, and on κ.
  bool build_arcs(int m) {
    DimSet in_label = 0;
    for (const auto& j : scheme_.nodes[static_cast<std::size_t>(m)].label)
      if (j) in_label |= dim_bit(*j);
    for (Dim d = 0; d <= n_ + 1; ++d) {
      const Dim dim = d > n_ ? kappa_arc : d;
      if (dim != kappa_arc && has_dim(in_label, dim)) continue;
      if (!build_arc(m, dim)) return false;
    }
    return true;
  }

  bool build_arc(int m, Dim d) {
    const Dart a = dart(m, 0);
    const Dart x = link(d, a);
    if (x == no_dart) {
      // Only κ can be absent: m is not preserved (deleted or added), and
      // none of its darts may be.
      for (std::size_t q = 1; q < k_; ++q)
        if (const Dart y = link(d, dart(m, q)); y != no_dart)
          return fail(FailureKind::instantiation, m, d, dart(m, q),
                      fmt::format("node n{}: {} has no κ-link but {} is preserved as {}: the node is preserved for some darts only", m, g_.name(a),
                                  g_.name(dart(m, q)), g_.name(y)));
      return true;
    }
    if (owner_[x] >= 0) {
      const int target = owner_[x];
      if (position_[x] != 0)
        return fail(FailureKind::arc, m, d, a,
                    fmt::format("node n{}: the {}-link {} - {} joins the copy of b_0 to the copy of b_{} in node n{}: no explicit arc "
                                "instantiates it (arc failure)",
                                m, dim_name(d), g_.name(a), g_.name(x), position_[x], target));
      // Arc addition: every dart of m must be d-linked to its counterpart.
      for (std::size_t q = 1; q < k_; ++q)
        if (const Dart y = link(d, dart(m, q)); y != dart(target, q))
          return fail(FailureKind::instantiation, m, d, dart(m, q),
                      fmt::format("node n{}: the {}-arc n{} - n{} folds {} - {}, but {} is {}-linked to {} instead of {} (instantiation failure)", m,
                                  dim_name(d), m, target, g_.name(a), g_.name(x), g_.name(dart(m, q)), dim_name(d),
                                  y == no_dart ? std::string("nothing") : g_.name(y), g_.name(dart(target, q))));
      if (arc_slot(m, d) < 0) {
        arc_slot(m, d) = target;
        arc_slot(target, d) = m;
        scheme_.arcs.push_back({m, target, d});
      }
      return true;
    }
    // Arc extension: a new node made of the d-neighbours of m's darts.
    SchemeNode v;
    v.after = d == kappa_arc ? !scheme_.nodes[static_cast<std::size_t>(m)].after : scheme_.nodes[static_cast<std::size_t>(m)].after;
    v.darts.resize(k_);
    for (std::size_t q = 0; q < k_; ++q) {
      const Dart y = link(d, dart(m, q));
      if (y == no_dart || owner_[y] >= 0)
        return fail(FailureKind::instantiation, m, d, dart(m, q),
                    fmt::format("node n{}: {} is {}-linked to the new dart {}, but {} is {}-linked to {} (instantiation failure)", m, g_.name(a),
                                dim_name(d), g_.name(x), g_.name(dart(m, q)), dim_name(d),
                                y == no_dart ? std::string("nothing") : fmt::format("{}, a dart of node n{}", g_.name(y), owner_[y])));
      v.darts[q] = y;
    }
    const int id = static_cast<int>(scheme_.nodes.size());
    add_node(std::move(v));
    arc_slot(m, d) = id;
    arc_slot(id, d) = m;
    scheme_.arcs.push_back({m, id, d});
    return build_label(id) && note_hook_like(id);
  }

  // The first dart of node v where relabeling position p to j fails, or
  // no_dart if it holds everywhere.
  Dart relabeling_breaks(int v, std::size_t p, Dim j) const {
    const std::size_t r = orbit_.size();
    for (std::size_t q = 0; q < k_; ++q)
      if (g_.link(j, dart(v, q)) != dart(v, neighbour_[q * r + p])) return dart(v, q);
    return no_dart;
  }

  // Step 2.2: the label of the new node v, position by position.
  bool build_label(int v) {
    const std::size_t r = orbit_.size();
    OrbitType label(r);
    DimSet used = 0;
    const Dart a = dart(v, 0);
    for (std::size_t p = 0; p < r; ++p) {
      const Dim i = orbit_[p];
      const Dart target = dart(v, neighbour_[p]);  // (b_i, v)
      std::vector<Dim> candidates;
      if (!has_dim(used, i) && g_.link(i, a) == target) candidates.push_back(i);
      for (Dim j = 0; j <= n_; ++j)
        if (j != i && !has_dim(used, j) && g_.link(j, a) == target) candidates.push_back(j);
      bool undecided = true;
      for (std::size_t q = 0; q < k_ && undecided; ++q) undecided = neighbour_[q * r + p] == q;
      if (undecided && !options_.strict && options_.undecided != UndecidedPolicy::keep) {
        if (options_.undecided == UndecidedPolicy::fail)
          return fail(FailureKind::undecided, v, i, a,
                      fmt::format("node n{}: every {}-link of the hook orbit is a loop, so the example does not say what the operation does "
                                  "with {}-links at position {} of {} (use --undecided keep or free, or an example with a non-loop {}-link)",
                                  v, i, i, p, orbit_type_str(OrbitType(orbit_.begin(), orbit_.end())), i));
        scheme_.undecided.push_back({v, p, std::nullopt});
        continue;  // '_': the loops become explicit loop arcs in Step 2.1
      }
      std::optional<Dim> chosen;
      Dart first_break = no_dart;
      Dim first_j = 0;
      for (Dim j : candidates) {
        const Dart breaks = relabeling_breaks(v, p, j);
        if (breaks == no_dart) {
          chosen = j;
          break;
        }
        if (first_break == no_dart) {
          first_break = breaks;
          first_j = j;
        }
        if (options_.strict) break;
      }
      // Outside strict mode, a position no relabeling fits is deleted: its
      // links become explicit arcs, which Step 2.1 checks on every dart.
      if (!chosen && first_break != no_dart && options_.strict) {
        const Dart q = position_[first_break];
        return fail(FailureKind::relabeling, v, i, first_break,
                    fmt::format("node n{}: relabeling {} -> {} holds at {} but not at {}: its {}-link does not reach {}, the copy of "
                                "the {}-neighbour of b_{} (relabeling failure)",
                                v, i, first_j, g_.name(a), g_.name(first_break), first_j, g_.name(dart(v, neighbour_[q * r + p])), i, q));
      }
      if (undecided) scheme_.undecided.push_back({v, p, chosen});
      if (chosen) {
        label[p] = *chosen;
        used |= dim_bit(*chosen);
      }
    }
    scheme_.nodes[static_cast<std::size_t>(v)].label = std::move(label);
    return true;
  }

  const KappaGraph& g_;
  const std::vector<Dim>& orbit_;
  FoldOptions options_;
  Dim n_;
  std::size_t k_ = 0;
  FoldScratch& scratch_;
  std::vector<int>& owner_;
  std::vector<std::uint32_t>& position_;
  std::vector<Dart> owned_;  // the darts whose owner_ this run set
  std::vector<std::uint32_t> neighbour_;
  std::vector<int> explicit_;
  GraphScheme scheme_;
  std::optional<FoldFailure> failure_;
  std::vector<Dart> hook_like_;
};

}  // namespace

FoldResult fold(const KappaGraph& graph, const std::vector<Dim>& orbit, Dart start, const FoldOptions& options, FoldScratch& scratch) {
  return Folder(graph, orbit, options, scratch).run(start);
}

FoldResult fold(const KappaGraph& graph, const std::vector<Dim>& orbit, Dart start, const FoldOptions& options) {
  FoldScratch scratch(graph);
  return fold(graph, orbit, start, options, scratch);
}

}  // namespace dartcheck::inference
