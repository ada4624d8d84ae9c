#include "rewriting/term_eval.hpp"

#include <algorithm>
#include <unordered_map>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace dartcheck {

TermEvaluator::TermEvaluator(const EmbeddedMap& g) : g_(g), outer_(g.map), inner_(g.map) {}

const Embedding* TermEvaluator::embedding(const std::string& name, std::size_t* index) const {
  for (std::size_t k = 0; k < g_.embeddings.size(); ++k)
    if (g_.embeddings[k].signature.name == name) {
      if (index) *index = k;
      return &g_.embeddings[k];
    }
  return nullptr;
}

// --- Compilation ---------------------------------------------------------

// Resolves the node term t (a variable followed by alpha_i's) into s.slot
// and the links appended to out; false (and a fail step's message in
// out.failures_) when it cannot be.
bool TermEvaluator::emit_node(const Term& t, std::span<const std::string> names, CompiledTerm& out, CompiledTerm::Step& s) {
  if (t.kind == Term::Kind::variable) {
    for (std::size_t k = 0; k < names.size(); ++k)
      if (names[k] == t.name) {
        s.slot = static_cast<std::uint32_t>(k);
        return true;
      }
    out.failures_.push_back(fmt::format("node variable '{}' is not bound", t.name));
    return false;
  }
  // t is x.alpha_i (the checker admits no other Node term).
  if (!emit_node(t.args[0], names, out, s)) return false;
  if (!g_.map.model().contains(t.dim)) {
    out.failures_.push_back(fmt::format("alpha{} is not a dimension of the map", t.dim));
    return false;
  }
  out.links_.push_back({t.dim, &t});
  return true;
}

// The node an access, collect or each starts from, as s's binding and
// links [first, last); false, with s a fail step, when it cannot be.
bool TermEvaluator::emit_start(const Term& node, std::span<const std::string> names, CompiledTerm& out, CompiledTerm::Step& s) {
  s.first = static_cast<std::uint32_t>(out.links_.size());
  if (!emit_node(node, names, out, s)) {
    s.op = CompiledTerm::Step::Op::fail;
    s.target = static_cast<std::uint32_t>(out.failures_.size() - 1);
    return false;
  }
  s.last = static_cast<std::uint32_t>(out.links_.size());
  return true;
}

void TermEvaluator::emit(const Term& t, std::span<const std::string> names, CompiledTerm& out) {
  using Op = CompiledTerm::Step::Op;
  CompiledTerm::Step s;
  s.term = &t;
  auto fail = [&](std::string why) {
    out.failures_.push_back(std::move(why));
    s.op = Op::fail;
    s.target = static_cast<std::uint32_t>(out.failures_.size() - 1);
    out.steps_.push_back(s);
  };
  switch (t.kind) {
    case Term::Kind::literal:
    case Term::Kind::parameter:
      s.op = Op::literal;
      break;
    case Term::Kind::access:
    case Term::Kind::collect: {
      s.op = t.kind == Term::Kind::access ? Op::access : Op::collect;
      if (!emit_start(t.args[0], names, out, s)) break;
      std::size_t e = 0;
      if (!embedding(t.name, &e)) return fail(fmt::format("the map has no embedding '{}'", t.name));
      s.target = static_cast<std::uint32_t>(s.op == Op::access ? e : memo_for(t.name, e, t.orbit));
      break;
    }
    case Term::Kind::variable:
    case Term::Kind::neighbour:
      return fail(fmt::format("'{}' is a node, not a value", t.str()));
    case Term::Kind::call:
      if (!t.function) return fail(fmt::format("'{}' was not type-checked", t.str()));
      for (const Term& a : t.args) emit(a, names, out);
      s.op = Op::call;
      s.target = static_cast<std::uint32_t>(t.args.size());
      break;
    case Term::Kind::list:
      for (const Term& a : t.args) emit(a, names, out);
      s.op = Op::list;
      s.first = static_cast<std::uint32_t>(t.args.size());
      s.target = scratch_memo(t);
      break;
    case Term::Kind::each: {
      s.op = Op::each;
      if (!emit_start(t.args[0], names, out, s)) break;
      std::vector<std::string> inner(names.begin(), names.end());
      inner.push_back(t.name);
      std::vector<Dim> sub;  // <s> ∩ <o>: the sub-orbits inside the orbit
      for (Dim i : t.sub_orbit)
        if (std::find(t.orbit.begin(), t.orbit.end(), i) != t.orbit.end()) sub.push_back(i);
      CompiledTerm::Body b{std::make_unique<CompiledTerm>(), dims_generators(t.orbit), dims_generators(sub)};
      // The body is compiled into its own program: it runs once per dart.
      b.program->root_ = &t.args[1];
      emit(t.args[1], inner, *b.program);
      s.body = static_cast<std::uint32_t>(out.bodies_.size());
      out.bodies_.push_back(std::move(b));
      s.target = scratch_memo(t);
      break;
    }
  }
  out.steps_.push_back(s);
}

std::uint32_t TermEvaluator::scratch_memo(const Term& owner) {
  for (std::size_t k = 0; k < memo_.size(); ++k)
    if (memo_[k].owner == &owner) return static_cast<std::uint32_t>(k);
  CollectMemo m{{}, static_cast<std::size_t>(-1), {}, {}, {}, {}, {}, {0}};
  m.owner = &owner;
  memo_.push_back(std::move(m));
  return static_cast<std::uint32_t>(memo_.size() - 1);
}

void TermEvaluator::compile(const Term& t, std::span<const std::string> names, CompiledTerm& out) {
  out.steps_.clear();
  out.links_.clear();
  out.failures_.clear();
  out.bodies_.clear();
  out.root_ = &t;
  emit(t, names, out);
}

// --- Collects --------------------------------------------------------------

void collect_orbit_values(const Map& map, const Embedding& e, std::span<const Dart> orbit, std::span<const OrbitWord> inner,
                          OrbitWalker& inner_walker, std::vector<std::uint64_t>& done_bits, std::vector<Value>& out, const std::string& name,
                          const std::vector<Dim>& dims) {
  const std::size_t first = out.size();
  if (done_bits.size() * 64 < map.size()) done_bits.resize((map.size() + 63) / 64, 0);
  auto done = [&](Dart x) { return (done_bits[x >> 6] >> (x & 63)) & 1U; };
  auto mark = [&](Dart x) { done_bits[x >> 6] |= std::uint64_t{1} << (x & 63); };
  // Every dart marked is in the orbit (the pi-orbits lie inside it).
  struct Unmark {
    std::vector<std::uint64_t>& bits;
    std::span<const Dart> darts;
    ~Unmark() {
      for (Dart x : darts) bits[x >> 6] &= ~(std::uint64_t{1} << (x & 63));
    }
  } const unmark{done_bits, orbit};
  // The pi-orbit of x inside the <o'>-orbit, through <o> ∩ <o'>. The
  // common cases are read off the links: no common dimension (x alone),
  // or one dimension i whose link is an involution at x ({x, alpha_i(x)}:
  // every G-map dimension); otherwise the orbit is walked.
  const bool none_common = inner.empty(), one_letter = inner.size() == 1 && inner[0].size() == 1;
  const Dim i = one_letter ? inner[0][0] : 0;
  // A pi-orbit's value is that of its smallest labeled dart: on a
  // consistent G every labeled dart has it; on one that is not, the
  // choice does not depend on the dart a walk of <o'> meets first (the
  // evaluator walks breadth first, compiled rules a face as alternating
  // links), so both read the same value.
  for (Dart x : orbit) {
    if (done(x)) continue;
    const Value* v = nullptr;
    if (none_common) {
      v = e.value(x);
    } else if (const Dart y = one_letter ? map.link(i, x) : no_dart; one_letter && (y == no_dart || y == x || map.link(i, y) == x)) {
      mark(x);
      v = e.value(x);
      if (y != no_dart && y != x) {
        mark(y);
        if (const Value* w = e.value(y); w && (!v || y < x)) v = w;
      }
    } else {
      Dart smallest = no_dart;
      for (Dart z : inner_walker.orbit(x, inner)) {
        mark(z);
        if (const Value* w = e.value(z); w && z < smallest) {
          v = w;
          smallest = z;
        }
      }
    }
    if (!v) {
      out.resize(first);
      throw EvaluationError(fmt::format("{}<{}>: the {}-orbit of dart {} has no value", name, fmt::join(dims, ","), name, x));
    }
    out.push_back(*v);
  }
  // A multiset has no order; a canonical one makes every function of it
  // (center's floating-point sum) the same from whichever dart of the
  // orbit the traversal starts.
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(), [](const Value& a, const Value& b) { return value_less(a, b); });
}

void each_values(std::vector<Value>& values, std::span<const Dart> orbit, bool per_sub, std::span<const OrbitWord> sub, OrbitWalker& walker,
                 const std::string& text, const std::vector<Dim>& sub_dims) {
  if (per_sub) {
    // One value per <s>-orbit: every dart of it must give the same one.
    std::unordered_map<Dart, std::size_t> at;
    for (std::size_t k = 0; k < orbit.size(); ++k) at.emplace(orbit[k], k);
    std::vector<Value> one;
    std::vector<std::size_t> members;  // positions in `orbit` of one <s>-orbit
    auto walk = [&](std::size_t k) -> const std::vector<std::size_t>& {
      members.clear();
      for (Dart z : walker.orbit(orbit[k], sub)) members.push_back(at.at(z));
      return members;
    };
    for_each_class(orbit.size(), IndexRange<std::size_t>{orbit.size()}, walk, [&](std::size_t k, const std::vector<std::size_t>& same) {
      for (std::size_t j : same)
        if (!(values[j] == values[k]))
          throw EvaluationError(
              fmt::format("{}: the body gives {} at dart {} and {} at dart {} of one <{}>-orbit: its value depends on the dart "
                          "Jerboa's traversal picks",
                          text, values[k].str(), orbit[k], values[j].str(), orbit[j], fmt::join(sub_dims, ",")));
      one.push_back(values[k]);
    });
    values = std::move(one);
  }
  std::sort(values.begin(), values.end(), [](const Value& x, const Value& y) { return value_less(x, y); });
}

std::size_t TermEvaluator::memo_for(const std::string& name, std::size_t e, const std::vector<Dim>& orbit) {
  for (std::size_t k = 0; k < memo_.size(); ++k)
    if (memo_[k].embedding == e && memo_[k].name == name && memo_[k].orbit == orbit) return k;
  std::vector<Dim> within;  // <o> ∩ <o'>: the pi-orbits inside the <o'>-orbit
  for (Dim i : g_.embeddings[e].signature.orbit)
    if (std::find(orbit.begin(), orbit.end(), i) != orbit.end()) within.push_back(i);
  memo_.push_back(CollectMemo{name, e, orbit, dims_generators(orbit), dims_generators(within), {}, {}, {0}});
  return memo_.size() - 1;
}

std::uint32_t TermEvaluator::collect_bag(CollectMemo& memo, Dart d) {
  if (const std::uint32_t k = memorise_ ? memo.bag_of.get(d) : DartTable::none; k != DartTable::none) return k;
  if (!memorise_ && memo.last_dart == d) return memo.last_bag;
  const Embedding& e = g_.embeddings[memo.embedding];
  if (d != outer_dart_ || memo.orbit != outer_orbit_) {
    outer_last_ = outer_.orbit(d, memo.outer);  // valid until outer_'s next walk
    outer_dart_ = d;
    outer_orbit_ = memo.orbit;
  }
  const std::span<const Dart> orbit = outer_last_;
  std::vector<Value>& out = memo.elements;
  collect_orbit_values(g_.map, e, orbit, memo.inner, inner_, done_, out, memo.name, memo.orbit);
  const auto k = static_cast<std::uint32_t>(memo.start.size() - 1);
  memo.start.push_back(static_cast<std::uint32_t>(out.size()));
  if (memorise_)
    for (Dart x : orbit) memo.bag_of.set(x, k);
  memo.last_dart = d;
  memo.last_bag = k;
  return k;
}

std::span<const Value> TermEvaluator::collect(const std::string& name, const std::vector<Dim>& orbit, Dart d) {
  std::size_t e = 0;
  if (!embedding(name, &e)) throw EvaluationError(fmt::format("the map has no embedding '{}'", name));
  CollectMemo& memo = memo_[memo_for(name, e, orbit)];
  if (!memorise_) memo.empty();
  return memo.bag(collect_bag(memo, d));
}

void TermEvaluator::forget() {
  for (CollectMemo& m : memo_) {
    m.bag_of.clear();
    m.empty();
  }
  outer_dart_ = no_dart;
}

void TermEvaluator::memorise(bool on) {
  if (on != memorise_) forget();
  memorise_ = on;
}

// --- Running ---------------------------------------------------------------

Dart TermEvaluator::node(const CompiledTerm& c, const CompiledTerm::Step& s, std::span<const Dart> darts) const {
  Dart d = darts[s.slot];
  for (std::uint32_t k = s.first; k < s.last; ++k) {
    const CompiledTerm::Link& l = c.links_[k];
    const Dart n = g_.map.link(l.dim, d);
    if (n == no_dart) throw EvaluationError(fmt::format("{}: dart {} has no {}-arc", l.term->str(), d, l.dim));
    d = n;
  }
  return d;
}

Value TermEvaluator::value(const CompiledTerm& c, std::span<const Dart> darts) {
  stack_.clear();
  // Without a memo, the multisets of the last call are no longer lent;
  // each and list bags are never memorised.
  for (CollectMemo& m : memo_)
    if (!memorise_ || m.embedding == static_cast<std::size_t>(-1)) m.empty();
  return run(c, darts);
}

std::uint32_t TermEvaluator::each_bag(const CompiledTerm& c, const CompiledTerm::Step& s, std::span<const Dart> darts) {
  const CompiledTerm::Body& b = c.bodies_[s.body];
  const Term& t = *s.term;
  // A copy: the body's collects walk with outer_ too.
  const std::vector<Dart> orbit = [&] {
    const auto o = outer_.orbit(node(c, s, darts), b.outer);
    return std::vector<Dart>(o.begin(), o.end());
  }();
  outer_dart_ = no_dart;
  std::vector<Dart> bound(darts.begin(), darts.end());
  bound.push_back(no_dart);
  std::vector<Value> values;
  values.reserve(orbit.size());
  for (Dart x : orbit) {
    bound.back() = x;
    values.push_back(run(*b.program, bound));
  }
  each_values(values, orbit, t.per_sub, b.sub, inner_, t.str(), t.sub_orbit);
  CollectMemo& m = memo_[s.target];
  m.elements.insert(m.elements.end(), values.begin(), values.end());
  m.start.push_back(static_cast<std::uint32_t>(m.elements.size()));
  return static_cast<std::uint32_t>(m.start.size() - 2);
}

Value TermEvaluator::run(const CompiledTerm& c, std::span<const Dart> darts) {
  using Op = CompiledTerm::Step::Op;
  const std::size_t base = stack_.size();
  for (const CompiledTerm::Step& s : c.steps_) {
    switch (s.op) {
      case Op::literal:
        stack_.push_back({s.term->literal});
        break;
      case Op::access: {
        const Dart d = node(c, s, darts);
        const Value* v = g_.embeddings[s.target].value(d);
        if (!v) throw EvaluationError(fmt::format("{}: dart {} has no {} value", s.term->str(), d, s.term->name));
        stack_.push_back({*v});
        break;
      }
      case Op::collect: {
        const Dart d = node(c, s, darts);
        stack_.push_back({{}, s.target, collect_bag(memo_[s.target], d)});
        break;
      }
      case Op::call: {
        // Every argument is evaluated (and every collect memorised), so
        // the multisets can be lent by address for the call.
        const std::size_t from = stack_.size() - s.target;
        args_.clear();
        for (std::size_t k = from; k < stack_.size(); ++k) {
          const Entry& a = stack_[k];
          if (a.memo == DartTable::none)
            args_.emplace_back(a.value);
          else
            args_.emplace_back(memo_[a.memo].bag(a.bag));
        }
        const Value r = s.term->function->apply(args_);
        stack_.resize(from);
        stack_.push_back({r});
        break;
      }
      case Op::each: {
        const std::uint32_t k = each_bag(c, s, darts);
        stack_.push_back({{}, s.target, k});
        break;
      }
      case Op::list: {
        // The elements, values and bags alike, as one canonical bag.
        const std::size_t from = stack_.size() - s.first;
        std::vector<Value> bag;
        for (std::size_t k = from; k < stack_.size(); ++k) {
          const Entry& a = stack_[k];
          if (a.memo == DartTable::none) {
            bag.push_back(a.value);
          } else {
            const auto b = memo_[a.memo].bag(a.bag);
            bag.insert(bag.end(), b.begin(), b.end());
          }
        }
        std::sort(bag.begin(), bag.end(), [](const Value& x, const Value& y) { return value_less(x, y); });
        CollectMemo& m = memo_[s.target];
        m.elements.insert(m.elements.end(), bag.begin(), bag.end());
        m.start.push_back(static_cast<std::uint32_t>(m.elements.size()));
        stack_.resize(from);
        stack_.push_back({{}, s.target, static_cast<std::uint32_t>(m.start.size() - 2)});
        break;
      }
      case Op::fail:
        throw EvaluationError(c.failures_[s.target]);
    }
  }
  if (stack_.back().memo != DartTable::none) throw EvaluationError(fmt::format("'{}' is a multiset, not a value", c.root_->str()));
  const Value r = stack_.back().value;
  stack_.resize(base);
  return r;
}

Value TermEvaluator::value(const Term& t, std::span<const std::string> names, std::span<const Dart> darts) {
  compile(t, names, once_);
  return value(once_, darts);
}

}  // namespace dartcheck
