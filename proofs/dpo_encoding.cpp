#include "proofs/detail/dpo_encoding.hpp"

namespace dartcheck::proofs {

DpoEncoding::DpoEncoding(z3::context& ctx, const Rule& rule, const HostClass& cls, std::size_t max_darts, unsigned rlimit, unsigned timeout_ms,
                         EncodingFault fault)
    : HostEncoding(ctx, rule.model(), cls, max_darts, rule.left().node_count(), max_darts + added_nodes(rule), rlimit, timeout_ms),
      rule_(rule),
      nl_(rule.left().node_count()),
      added_(added_nodes(rule)),
      fault_(fault) {
  hlink_.assign(max_dimension + 1, {});
  encode_match_and_dangling();
  encode_derived();
}

std::size_t DpoEncoding::h_index(NodeId r) const {
  if (rule_.to_left(r) != no_node) return rule_.to_left(r);
  std::size_t a = 0;
  for (NodeId q = 0; q < r; ++q) a += rule_.to_left(q) == no_node;
  return k_ + a;
}

void DpoEncoding::encode_match_and_dangling() {
  const TopoGraph& L = rule_.left();
  for (const auto& a : L.arcs())
    if (has_dim(cls_.symbolic, a.label)) solver_.add(links(a.label)[a.source] == val(a.target));
  if (fault_ == EncodingFault::drop_dangling) return;
  // A deleted node keeps no arc outside m(L): its G-arcs are L's.
  for (NodeId v = 0; v < nl_; ++v) {
    if (rule_.to_right(v) != no_node) continue;
    for (Dim d : rule_.model().dims) {
      if (!has_dim(cls_.symbolic, d)) continue;
      const Exprs& l = links(d);
      if (L.out_arcs(v, d).empty()) solver_.add(l[v] == none());
      for (std::size_t y = 0; y < k_; ++y) {
        bool in_l = false;
        for (ArcId e : L.in_arcs(v, d)) in_l = in_l || L.arc(e).source == y;
        if (!in_l) solver_.add(l[y] != val(v));
      }
    }
  }
}

void DpoEncoding::encode_derived() {
  const TopoGraph &L = rule_.left(), &R = rule_.right();
  for (NodeId r = 0; r < R.node_count(); ++r) r_nodes_.push_back(h_index(r));
  for (Dim d : rule_.model().dims) {
    if (!has_dim(cls_.symbolic, d)) continue;
    const Exprs& l = links(d);
    Exprs& h = hlink_[static_cast<std::size_t>(d)];
    for (std::size_t x = 0; x < k_ + added_; ++x) h.push_back(none());
    // A dart's out-arc in H: its G-arc unless m(L \ K) deletes it, else the
    // arc R adds (the unique one when H satisfies I(d)).
    for (std::size_t x = 0; x < k_; ++x) {
      if (x >= nl_) {
        h[x] = l[x];
        continue;
      }
      const NodeId rx = rule_.to_right(static_cast<NodeId>(x));
      if (rx == no_node) continue;  // deleted: no dart of H
      bool deleted_out = false;
      for (ArcId e = 0; e < L.arc_count(); ++e)
        if (L.arc(e).source == x && L.arc(e).label == d && !rule_.preserved_left_arc(e)) deleted_out = true;
      z3::expr added = none();
      for (ArcId e = 0; e < R.arc_count(); ++e)
        if (R.arc(e).source == rx && R.arc(e).label == d && !rule_.preserved_right_arc(e)) added = val(h_index(R.arc(e).target));
      h[x] = deleted_out ? added : z3::ite(l[x] != none(), l[x], added);
    }
    for (NodeId r = 0; r < R.node_count(); ++r) {
      if (rule_.to_left(r) != no_node) continue;
      for (ArcId e : R.out_arcs(r, d)) h[h_index(r)] = val(h_index(R.arc(e).target));
    }
  }
}

// I(d) in H at the images of R's nodes (elsewhere H is G, which satisfies
// it): out- and in-arc counts of G-arcs that survive plus R's added arcs.
z3::expr DpoEncoding::incident_violation(Dim d) {
  const TopoGraph &L = rule_.left(), &R = rule_.right();
  const Exprs& l = links(d);
  const bool partial = has_dim(cls_.partial, d);
  z3::expr bad = ctx_.bool_val(false);
  auto wrong = [&](const Exprs& symbolic, std::size_t fixed) {
    return partial ? !(count_is(ctx_, symbolic, 0, fixed) || count_is(ctx_, symbolic, 1, fixed)) : !count_is(ctx_, symbolic, 1, fixed);
  };
  for (NodeId r = 0; r < R.node_count(); ++r) {
    std::size_t out = 0, in = 0;
    for (ArcId e = 0; e < R.arc_count(); ++e) {
      if (R.arc(e).label != d || rule_.preserved_right_arc(e)) continue;
      out += R.arc(e).source == r;
      in += R.arc(e).target == r;
    }
    Exprs gout, gin;
    const NodeId x = rule_.to_left(r);
    if (x != no_node) {
      bool deleted_out = false, deleted_in = false;
      for (ArcId e = 0; e < L.arc_count(); ++e) {
        if (L.arc(e).label != d || rule_.preserved_left_arc(e)) continue;
        deleted_out = deleted_out || L.arc(e).source == x;
        deleted_in = deleted_in || L.arc(e).target == x;
      }
      if (!deleted_out) gout.push_back(l[x] != none());
      if (!deleted_in && !partial) {
        ++in;  // a permutation has an arc into every dart (stated, not left to the solver's pigeonhole)
      } else if (!deleted_in) {
        z3::expr some = ctx_.bool_val(false);
        for (std::size_t y = 0; y < k_; ++y) some = some || l[y] == val(x);
        gin.push_back(some);
      }
    }
    bad = bad || wrong(gout, out) || wrong(gin, in);
  }
  return bad.simplify();
}

z3::expr DpoEncoding::violation(const HConstraint& c) {
  const std::size_t n = k_ + added_;
  z3::expr bad = ctx_.bool_val(false);
  switch (c.kind) {
    case RuleCondition::incident_arcs:
      return incident_violation(c.i);
    case RuleCondition::non_orientation: {
      const Exprs& h = hlink_[static_cast<std::size_t>(c.i)];
      for (std::size_t x : r_nodes_) {
        bad = bad || (h[x] != none() && lookup(h, h[x]) != val(x));
        if (has_dim(cls_.partial, c.i)) {
          // An arc into x with no arc back: x has no out-arc at all.
          z3::expr into = ctx_.bool_val(false);
          for (std::size_t y = 0; y < n; ++y) into = into || h[y] == val(x);
          bad = bad || (h[x] == none() && into);
        }
      }
      return bad;
    }
    case RuleCondition::cycle: {
      const Exprs &hi = hlink_[static_cast<std::size_t>(c.i)], &hj = hlink_[static_cast<std::size_t>(c.j)];
      auto path = [&](std::size_t x, const Exprs& a, const Exprs& b) { return lookup(b, lookup(a, lookup(b, a[x]))); };
      if (has_dim(cls_.partial, c.i) || has_dim(cls_.partial, c.j)) {
        // Partial links are not bijections: check the ijij-path everywhere.
        for (std::size_t x = 0; x < n; ++x)
          if (x >= nl_ || rule_.to_right(static_cast<NodeId>(x)) != no_node)
            bad = bad || ((x < k_ ? active(x) : ctx_.bool_val(true)) && path(x, hi, hj) != val(x));
        return bad;
      }
      for (std::size_t x : r_nodes_) bad = bad || path(x, hi, hj) != val(x) || path(x, hj, hi) != val(x);
      return bad;
    }
    case RuleCondition::no_loop: {
      const Exprs& h = hlink_[static_cast<std::size_t>(c.i)];
      const TopoGraph& R = rule_.right();
      for (ArcId e = 0; e < R.arc_count(); ++e)
        if (R.arc(e).label == c.i && R.arc(e).source == R.arc(e).target && !rule_.preserved_right_arc(e)) return ctx_.bool_val(true);
      for (std::size_t x : r_nodes_) bad = bad || h[x] == val(x);
      return bad;
    }
    default:
      return ctx_.bool_val(false);
  }
}

}  // namespace dartcheck::proofs
