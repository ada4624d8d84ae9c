#include "proofs/dpo_encoding.hpp"

#include <bit>

namespace dartcheck::proofs {

const std::vector<Dart>* SymbolicHost::find(Dim d) const {
  for (const auto& [e, l] : links)
    if (e == d) return &l;
  return nullptr;
}

namespace {

// Sums of 0/1 terms compared with a small constant, as Boolean formulas:
// the counts here are at most a few arcs.
z3::expr count_is(z3::context& ctx, const std::vector<z3::expr>& terms, std::size_t constant, std::size_t n) {
  // n = number of terms known true (static arcs) to add to the symbolic ones.
  if (terms.empty()) return ctx.bool_val(n == constant);
  z3::expr_vector v(ctx);
  for (const auto& t : terms) v.push_back(t);
  if (constant < n) return ctx.bool_val(false);
  const int rest = static_cast<int>(constant - n);
  if (static_cast<std::size_t>(rest) > terms.size()) return ctx.bool_val(false);
  return z3::pbeq(v, std::vector<int>(terms.size(), 1).data(), rest);
}

}  // namespace

DpoEncoding::DpoEncoding(z3::context& ctx, const Rule& rule, const HostClass& cls, std::size_t max_darts, unsigned rlimit, unsigned timeout_ms,
                         EncodingFault fault)
    : ctx_(ctx),
      rule_(rule),
      cls_(cls),
      k_(max_darts),
      nl_(rule.left().node_count()),
      added_(0),
      rlimit_(rlimit),
      fault_(fault),
      solver_(ctx_, "QF_FD"),
      size_(ctx_) {
  for (NodeId r = 0; r < rule.right().node_count(); ++r) added_ += rule.to_left(r) == no_node;
  none_ = k_ + added_;
  width_ = static_cast<unsigned>(std::bit_width(none_));
  z3::params p(ctx_);
  p.set("rlimit", rlimit_);
  if (timeout_ms > 0) p.set("timeout", timeout_ms);
  solver_.set(p);
  link_.assign(max_dimension + 1, {});
  hlink_.assign(max_dimension + 1, {});
  encode_host();
  encode_match_and_dangling();
  encode_derived();
}

z3::expr DpoEncoding::active(std::size_t x) { return x < nl_ ? ctx_.bool_val(true) : z3::ult(val(x), size_); }

z3::expr DpoEncoding::lookup(const Exprs& table, const z3::expr& index) {
  z3::expr r = none();
  for (std::size_t x = table.size(); x-- > 0;) r = z3::ite(index == val(x), table[x], r);
  return r;
}

std::size_t DpoEncoding::h_index(NodeId r) const {
  if (rule_.to_left(r) != no_node) return rule_.to_left(r);
  std::size_t a = 0;
  for (NodeId q = 0; q < r; ++q) a += rule_.to_left(q) == no_node;
  return k_ + a;
}

void DpoEncoding::encode_host() {
  size_ = ctx_.bv_const("size", width_);
  solver_.add(z3::uge(size_, val(nl_)) && z3::ule(size_, val(k_)));
  for (Dim d : rule_.model().dims) {
    if (!has_dim(cls_.symbolic, d)) continue;
    Exprs& l = link_[static_cast<std::size_t>(d)];
    for (std::size_t x = 0; x < k_; ++x) l.push_back(ctx_.bv_const(("link" + std::to_string(d) + "_" + std::to_string(x)).c_str(), width_));
    const bool partial = has_dim(cls_.partial, d);
    for (std::size_t x = 0; x < k_; ++x) {
      const z3::expr in_range = z3::ult(l[x], size_);
      solver_.add(z3::ite(active(x), partial ? (l[x] == none() || in_range) : in_range, l[x] == none()));
      for (std::size_t y = x + 1; y < k_; ++y) solver_.add(z3::implies(l[x] != none(), l[x] != l[y]));
      if (has_dim(cls_.involutive, d)) solver_.add(z3::implies(l[x] != none(), lookup(l, l[x]) == val(x)));
      if (cls_.loop_free) solver_.add(l[x] != val(x));
    }
  }
  for (auto [i, j] : cls_.cycles) {
    const Exprs &li = links(i), &lj = links(j);
    for (std::size_t x = 0; x < k_; ++x)
      solver_.add(z3::implies(active(x), lookup(lj, lookup(li, lookup(lj, li[x]))) == val(x)));
  }
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
    case RuleCondition::incident_arcs: return incident_violation(c.i);
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
    default: return ctx_.bool_val(false);
  }
}

Answer DpoEncoding::run(const Exprs& assumptions, std::vector<std::string>* core) {
  z3::expr_vector a(ctx_);
  for (const auto& e : assumptions) a.push_back(e);
  const z3::check_result r = solver_.check(a);
  if (r == z3::sat) {
    decode(solver_.get_model());
    return Answer::sat;
  }
  if (r == z3::unsat) {
    if (core) {
      core->clear();
      for (const auto& e : solver_.unsat_core()) core->push_back(e.decl().name().str());
    }
    return Answer::unsat;
  }
  return Answer::unknown;
}

Answer DpoEncoding::derivable() {
  last_.clear();
  return run(last_, nullptr);
}

Answer DpoEncoding::breaks(const HConstraint& c, std::vector<std::string>* core) {
  Exprs assumptions;
  const z3::expr broken = ctx_.bool_const(("breaks " + c.name()).c_str());
  solver_.add(z3::implies(broken, violation(c)));
  assumptions.push_back(broken);
  // O and C read H's links as functions: ask among the H satisfying I on
  // those dimensions (Theorems 2-3 assume a D-combinatorial rule).
  if (c.kind == RuleCondition::non_orientation || c.kind == RuleCondition::cycle) {
    for (Dim d : {c.i, c.j}) {
      if (d < 0) continue;
      const z3::expr holds = ctx_.bool_const(("holds " + condition_name(RuleCondition::incident_arcs, d)).c_str());
      solver_.add(z3::implies(holds, !incident_violation(d)));
      assumptions.push_back(holds);
    }
  }
  last_ = assumptions;
  return run(assumptions, core);
}

z3::expr DpoEncoding::follow(z3::expr from, const ConjWord& w) {
  for (std::size_t k = 0; k < w.size(); ++k) {
    const Exprs& l = links(w.dim(k));
    if (!w.bar(k) || !rule_.model().is_oriented(w.dim(k))) {
      from = lookup(l, from);
      continue;
    }
    z3::expr source = none();  // the dart whose link is `from`
    for (std::size_t y = l.size(); y-- > 0;) source = z3::ite(from != none() && l[y] == from, val(y), source);
    from = source;
  }
  return from;
}

Answer DpoEncoding::separates(const ConjWord& a, const ConjWord& b) {
  const z3::expr apart = ctx_.bool_const(("separates " + a.str() + " " + b.str()).c_str());
  solver_.add(z3::implies(apart, follow(val(0), a) != follow(val(0), b)));
  last_ = {apart};
  return run(last_, nullptr);
}

bool DpoEncoding::minimize() {
  while (host_.size > nl_) {
    solver_.push();
    solver_.add(z3::ult(size_, val(host_.size)));
    const SymbolicHost best = host_;
    const Answer a = run(last_, nullptr);
    solver_.pop();
    if (a == Answer::unsat) return true;
    if (a == Answer::unknown) {
      host_ = best;
      return false;
    }
  }
  return true;
}

void DpoEncoding::decode(const z3::model& m) {
  host_ = {};
  host_.size = m.eval(size_, true).get_numeral_uint64();
  for (Dim d : rule_.model().dims) {
    if (!has_dim(cls_.symbolic, d)) continue;
    std::vector<Dart> l(host_.size, no_dart);
    for (std::size_t x = 0; x < host_.size; ++x) {
      const std::uint64_t v = m.eval(links(d)[x], true).get_numeral_uint64();
      l[x] = v == none_ ? no_dart : static_cast<Dart>(v);
    }
    host_.links.emplace_back(d, std::move(l));
  }
}

}  // namespace dartcheck::proofs
