#include "core/error.hpp"
#include "proofs/detail/scheme_encoding.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace dartcheck::proofs {
std::string scheme_out_of_scope(const Rule& core) {
  if (core.left().node_count() != 1)
    return fmt::format(
        "rule scheme whose L has {} nodes and {} hook{}: the solver encodes schemes whose L is one hook node with loops "
        "(002 Sec. 10); `dartcheck fuzz` checks the others",
        core.left().node_count(), core.hooks().size(), core.hooks().size() == 1 ? "" : "s");
  return {};
}

SchemeEncoding::SchemeEncoding(z3::context& ctx, const Rule& core, const ArcWords& words, const HostClass& cls, std::size_t max_darts,
                               unsigned rlimit, unsigned timeout_ms)
    : HostEncoding(ctx, core.model(), cls, max_darts, 1, max_darts * (1 + added_nodes(core)), rlimit, timeout_ms),
      core_(core),
      words_(words),
      hook_kept_(core.to_right(0) != no_node),
      blocks_(1 + added_nodes(core)),
      np_(ctx_) {
  if (!scheme_out_of_scope(core).empty()) throw ValueError(scheme_out_of_scope(core));
  if (cls.symbolic != core.model().dim_set()) throw ValueError("a scheme's host class must encode every dimension");
  std::size_t next = 1;
  for (NodeId y = 0; y < core.right().node_count(); ++y) block_.push_back(core.to_left(y) == no_node ? next++ : 0);
  hlink_.assign(max_dimension + 1, {});
  hblocks_.assign(max_dimension + 1, {});
  arcs_.assign(max_dimension + 1, {});
  encode_pattern_and_match();
  encode_derived();
}

z3::expr SchemeEncoding::shift(std::size_t x, const ConjWord& w) {
  if (w.empty()) return val(x);
  return shift_[static_cast<std::size_t>(std::find(gens_.begin(), gens_.end(), w) - gens_.begin())][x];
}

z3::expr SchemeEncoding::index(std::size_t block, const z3::expr& dart) {
  if (block == 0) return dart;
  return z3::ite(dart == none(), none(), dart + val(block * k_));
}

z3::expr SchemeEncoding::present_at(const z3::expr& t) {
  z3::expr host = z3::ult(t, size_) && (hook_kept_ ? ctx_.bool_val(true) : z3::uge(t, np_));
  z3::expr added = ctx_.bool_val(false);
  for (std::size_t b = 1; b < blocks_; ++b) added = added || (z3::uge(t, val(b * k_)) && z3::ult(t, np_ + val(b * k_)));
  return host || added;
}

void SchemeEncoding::encode_pattern_and_match() {
  const ConjugateRewriting rw(core_.model());
  const TopoGraph& L = core_.left();
  // The generators of P_v: every word of the scheme and its conjugate; the
  // L-words (those that connect ι(L, P_v)) come first.
  std::size_t l_gens = 0;
  for (const auto* ws : {&words_.left, &words_.right}) {
    for (const auto& w : *ws)
      for (const ConjWord& x : {w, rw.conjugate(w)})
        if (!x.empty() && std::find(gens_.begin(), gens_.end(), x) == gens_.end()) gens_.push_back(x);
    if (ws == &words_.left) l_gens = gens_.size();
  }
  for (std::size_t g = 0; g < gens_.size(); ++g) {
    shift_.emplace_back();
    for (std::size_t x = 0; x < k_; ++x) {
      z3::expr s = ctx_.bv_const(fmt::format("shift{}_{}", g, x).c_str(), width_);
      solver_.add(s == follow(val(x), gens_[g]));
      shift_.back().push_back(s);
    }
  }
  np_ = ctx_.bv_const("pattern", width_);
  solver_.add(z3::uge(np_, val(1)) && z3::ule(np_, size_));
  for (std::size_t x = 0; x < k_; ++x) {
    for (std::size_t g = 0; g < gens_.size(); ++g) solver_.add(z3::implies(in_pattern(x), z3::ult(shift_[g][x], np_)));
    if (x == 0) continue;
    z3::expr reached = ctx_.bool_val(false);
    for (std::size_t e = 0; e < x; ++e)
      for (std::size_t g = 0; g < l_gens; ++g) reached = reached || shift_[g][e] == val(x);
    solver_.add(z3::implies(in_pattern(x), reached));
  }
  // The match: every loop (w, d) of L instantiates to p -d-> p·w.
  for (ArcId e = 0; e < L.arc_count(); ++e)
    for (std::size_t x = 0; x < k_; ++x) solver_.add(z3::implies(in_pattern(x), links(L.arc(e).label)[x] == shift(x, arc_word(words_.left, e))));
  // Dangling: a deleted hook's darts keep no arc of a dimension L has no
  // loop of (the loops' instances are all the arcs of the others: they
  // map P_v into itself injectively, hence onto).
  if (hook_kept_) return;
  for (Dim d : core_.model().dims) {
    if (!L.out_arcs(0, d).empty()) continue;
    for (std::size_t x = 0; x < k_; ++x) {
      solver_.add(z3::implies(in_pattern(x), links(d)[x] == none()));
      solver_.add(!z3::ult(links(d)[x], np_));
    }
  }
}

void SchemeEncoding::encode_derived() {
  const TopoGraph &L = core_.left(), &R = core_.right();
  const std::size_t n = blocks_ * k_;
  for (std::size_t x = 0; x < k_; ++x) present_.push_back(active(x) && (hook_kept_ ? ctx_.bool_val(true) : !in_pattern(x)));
  for (std::size_t b = 1; b < blocks_; ++b)
    for (std::size_t p = 0; p < k_; ++p) present_.push_back(in_pattern(p));
  for (std::size_t x = hook_kept_ ? 0 : k_; x < n; ++x) touched_.push_back(x);
  for (Dim d : core_.model().dims) {
    auto& arcs = arcs_[static_cast<std::size_t>(d)];
    bool deleted = false;
    for (ArcId e = 0; e < L.arc_count(); ++e) deleted |= L.arc(e).label == d && !core_.preserved_left_arc(e);
    // The host's arcs, less the instances of L \ K.
    const Exprs& l = links(d);
    for (std::size_t x = 0; x < k_; ++x)
      arcs.push_back({x, present_[x] && l[x] != none() && (deleted ? !in_pattern(x) : ctx_.bool_val(true)), l[x], 0});
    // The instances of R \ K.
    for (ArcId e = 0; e < R.arc_count(); ++e) {
      const auto& a = R.arc(e);
      if (a.label != d || core_.preserved_right_arc(e)) continue;
      const std::size_t from = block_[a.source], to = block_[a.target];
      for (std::size_t p = 0; p < k_; ++p) arcs.push_back({from * k_ + p, in_pattern(p), index(to, shift(p, arc_word(words_.right, e))), to});
    }
    Exprs& h = hlink_[static_cast<std::size_t>(d)];
    h.assign(n, none());
    auto& hb = hblocks_[static_cast<std::size_t>(d)];
    hb.assign(n, 0);
    for (auto c = arcs.rbegin(); c != arcs.rend(); ++c) {
      h[c->source] = z3::ite(c->present, c->target, h[c->source]);
      hb[c->source] |= 1U << c->block;
    }
  }
}

z3::expr SchemeEncoding::hlookup(Dim d, const z3::expr& t, std::uint32_t& blocks) {
  const Exprs& h = hlink_[static_cast<std::size_t>(d)];
  const auto& hb = hblocks_[static_cast<std::size_t>(d)];
  z3::expr r = none();
  std::uint32_t out = 0;
  for (std::size_t b = 0; b < blocks_; ++b) {
    if (!(blocks >> b & 1U)) continue;
    for (std::size_t x = b * k_; x < (b + 1) * k_; ++x) {
      r = z3::ite(t == val(x), h[x], r);
      out |= hb[x];
    }
  }
  blocks = out;
  return r;
}

// I(d) at the touched darts, from the candidates: one out-arc and one
// in-arc (at most one of each on partial dimensions); and no arc into a
// dart H does not have. A touched pattern dart is only present (hence
// only counted) below np, and so is its block's added dart.
z3::expr SchemeEncoding::incident_violation(Dim d) {
  const auto& arcs = arcs_[static_cast<std::size_t>(d)];
  const bool partial = has_dim(cls_.partial, d);
  auto wrong = [&](const Exprs& terms) {
    return partial ? !(count_is(ctx_, terms, 0, 0) || count_is(ctx_, terms, 1, 0)) : !count_is(ctx_, terms, 1, 0);
  };
  z3::expr bad = ctx_.bool_val(false);
  for (std::size_t x : touched_) {
    Exprs out, in;
    for (const auto& c : arcs) {
      if (c.source == x) out.push_back(c.present);
      if (c.block == x / k_) in.push_back(c.present && c.target == val(x));
    }
    bad = bad || (present_[x] && (wrong(out) || wrong(in)));
  }
  for (const auto& c : arcs) bad = bad || (c.present && !present_at(c.target));
  return bad;
}

z3::expr SchemeEncoding::violation(const HConstraint& c) {
  z3::expr bad = ctx_.bool_val(false);
  const std::size_t n = present_.size();
  switch (c.kind) {
    case RuleCondition::incident_arcs:
      return incident_violation(c.i);
    case RuleCondition::non_orientation: {
      const Exprs& h = hlink_[static_cast<std::size_t>(c.i)];
      for (std::size_t x : touched_) {
        std::uint32_t blocks = hblocks_[static_cast<std::size_t>(c.i)][x];
        bad = bad || (present_[x] && h[x] != none() && hlookup(c.i, h[x], blocks) != val(x));
        if (!has_dim(cls_.partial, c.i)) continue;
        // An arc into x with no arc back: x has no out-arc at all.
        z3::expr into = ctx_.bool_val(false);
        for (const auto& a : arcs_[static_cast<std::size_t>(c.i)]) into = into || (a.present && a.target == val(x));
        bad = bad || (present_[x] && h[x] == none() && into);
      }
      return bad;
    }
    case RuleCondition::cycle: {
      auto path = [&](std::size_t x, Dim a, Dim b) {
        std::uint32_t blocks = hblocks_[static_cast<std::size_t>(a)][x];
        z3::expr t = hlink_[static_cast<std::size_t>(a)][x];
        for (Dim e : {b, a, b}) t = hlookup(e, t, blocks);
        return t;
      };
      // The ijij-path closes at every dart, as check_graph reads C(i,j).
      for (std::size_t x = 0; x < n; ++x) bad = bad || (present_[x] && path(x, c.i, c.j) != val(x));
      return bad;
    }
    case RuleCondition::no_loop:
      for (const auto& a : arcs_[static_cast<std::size_t>(c.i)]) bad = bad || (a.present && a.target == val(a.source));
      return bad;
    default:
      return bad;
  }
}

}  // namespace dartcheck::proofs
