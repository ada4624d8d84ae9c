#include "proofs/detail/host_encoding.hpp"

#include <bit>

namespace dartcheck::proofs {

const std::vector<Dart>* SymbolicHost::find(Dim d) const {
  for (const auto& [e, l] : links)
    if (e == d) return &l;
  return nullptr;
}

std::size_t added_nodes(const Rule& rule) {
  std::size_t n = 0;
  for (NodeId r = 0; r < rule.right().node_count(); ++r) n += rule.to_left(r) == no_node;
  return n;
}

z3::expr count_is(z3::context& ctx, const std::vector<z3::expr>& terms, std::size_t constant, std::size_t fixed) {
  if (terms.empty()) return ctx.bool_val(fixed == constant);
  if (constant < fixed || constant - fixed > terms.size()) return ctx.bool_val(false);
  z3::expr_vector v(ctx);
  for (const auto& t : terms) v.push_back(t);
  return z3::pbeq(v, std::vector<int>(terms.size(), 1).data(), static_cast<int>(constant - fixed));
}

HostEncoding::HostEncoding(z3::context& ctx, const Model& model, const HostClass& cls, std::size_t max_darts, std::size_t min_darts,
                           std::size_t index_bound, unsigned rlimit, unsigned timeout_ms)
    : ctx_(ctx),
      model_(model),
      cls_(cls),
      k_(max_darts),
      min_darts_(min_darts),
      solver_(ctx_, "QF_FD"),
      width_(static_cast<unsigned>(std::bit_width(index_bound))),
      none_(index_bound),
      size_(ctx_) {
  z3::params p(ctx_);
  p.set("rlimit", rlimit);
  if (timeout_ms > 0) p.set("timeout", timeout_ms);
  // Z3 would take SIGINT itself during a check (and answer "unknown", which
  // read as "rlimit reached"); dartcheck's handler decides, and interrupts
  // the context (rule_prover's SolverWatch).
  p.set("ctrl_c", false);
  solver_.set(p);
  link_.assign(max_dimension + 1, {});
  encode_host();
}

z3::expr HostEncoding::active(std::size_t x) { return x < min_darts_ ? ctx_.bool_val(true) : z3::ult(val(x), size_); }

z3::expr HostEncoding::lookup(const Exprs& table, const z3::expr& index) {
  z3::expr r = none();
  for (std::size_t x = table.size(); x-- > 0;) r = z3::ite(index == val(x), table[x], r);
  return r;
}

void HostEncoding::encode_host() {
  size_ = ctx_.bv_const("size", width_);
  solver_.add(z3::uge(size_, val(min_darts_)) && z3::ule(size_, val(k_)));
  for (Dim d : model_.dims) {
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
    for (std::size_t x = 0; x < k_; ++x) solver_.add(z3::implies(active(x), lookup(lj, lookup(li, lookup(lj, li[x]))) == val(x)));
  }
}

z3::expr HostEncoding::follow(z3::expr from, const ConjWord& w) {
  for (std::size_t k = 0; k < w.size(); ++k) {
    const Exprs& l = links(w.dim(k));
    if (!w.bar(k) || !model_.is_oriented(w.dim(k))) {
      from = lookup(l, from);
      continue;
    }
    z3::expr source = none();  // the dart whose link is `from`
    for (std::size_t y = l.size(); y-- > 0;) source = z3::ite(from != none() && l[y] == from, val(y), source);
    from = source;
  }
  return from;
}

Answer HostEncoding::run(const Exprs& assumptions, std::vector<std::string>* core) {
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

Answer HostEncoding::derivable() {
  last_.clear();
  return run(last_, nullptr);
}

Answer HostEncoding::breaks(const HConstraint& c, std::vector<std::string>* core) {
  Exprs assumptions;
  const z3::expr broken = ctx_.bool_const(("breaks " + c.name()).c_str());
  solver_.add(z3::implies(broken, violation(c)));
  assumptions.push_back(broken);
  // O and C read H's links as functions: ask among the H satisfying I on
  // those dimensions (the theorems assume a D-combinatorial rule).
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

Answer HostEncoding::separates(const ConjWord& a, const ConjWord& b) {
  const z3::expr apart = ctx_.bool_const(("separates " + a.str() + " " + b.str()).c_str());
  solver_.add(z3::implies(apart, follow(val(0), a) != follow(val(0), b)));
  last_ = {apart};
  return run(last_, nullptr);
}

bool HostEncoding::minimize() {
  while (host_.size > min_darts_) {
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

void HostEncoding::decode(const z3::model& m) {
  host_ = {};
  host_.size = m.eval(size_, true).get_numeral_uint64();
  for (Dim d : model_.dims) {
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
