#include "rewriting/term_eval.hpp"

#include <algorithm>
#include <tuple>

#include <fmt/format.h>

namespace dartcheck {

TermEvaluator::TermEvaluator(const EmbeddedMap& g) : g_(g), outer_(g.map), inner_(g.map) {}

const Embedding& TermEvaluator::embedding(const std::string& name) const {
  const Embedding* e = g_.find(name);
  if (!e) throw EvaluationError(fmt::format("the map has no embedding '{}'", name));
  return *e;
}

Dart TermEvaluator::node(const Term& t, std::span<const std::string> names, std::span<const Dart> darts) {
  if (t.kind == Term::Kind::variable) {
    for (std::size_t k = 0; k < names.size(); ++k)
      if (names[k] == t.name) return darts[k];
    throw EvaluationError(fmt::format("node variable '{}' is not bound", t.name));
  }
  // t is x.alpha_i (the checker admits no other Node term).
  const Dart d = node(t.args[0], names, darts);
  if (!g_.map.model().contains(t.dim)) throw EvaluationError(fmt::format("alpha{} is not a dimension of the map", t.dim));
  const Dart n = g_.map.link(t.dim, d);
  if (n == no_dart) throw EvaluationError(fmt::format("{}: dart {} has no {}-arc", t.str(), d, t.dim));
  return n;
}

Multiset& TermEvaluator::collect_memo(const std::string& name, const std::vector<Dim>& orbit, Dart d) {
  const Embedding& e = embedding(name);
  auto memo = std::find_if(memo_.begin(), memo_.end(), [&](const CollectMemo& m) { return m.embedding == name && m.orbit == orbit; });
  if (memo == memo_.end()) {
    std::vector<Dim> within;  // <o> ∩ <o'>: the pi-orbits inside the <o'>-orbit
    for (Dim i : e.signature.orbit)
      if (std::find(orbit.begin(), orbit.end(), i) != orbit.end()) within.push_back(i);
    memo = memo_.insert(memo_.end(), CollectMemo{name, orbit, dims_generators(orbit), dims_generators(within), {}, {}});
  }
  if (const std::uint32_t k = memo->bag_of.get(d); k != DartTable::none) return memo->bags[k];

  orbit_ = outer_.orbit(d, memo->outer);  // copied: the inner walks reuse no state of it
  Multiset out;
  const DartTable::ClearOnExit emptied{done_};
  for (Dart x : orbit_) {
    if (done_.get(x) != DartTable::none) continue;
    const auto& piece = inner_.orbit(x, memo->inner);
    const Value* v = nullptr;
    for (Dart y : piece) {
      done_.set(y, 1);
      if (!v) v = e.value(y);
    }
    if (!v) throw EvaluationError(fmt::format("{}<{}>: the {}-orbit of dart {} has no value", name, fmt::join(orbit, ","), name, x));
    out.push_back(*v);
  }
  // A multiset has no order; a canonical one makes every function of it
  // (center's floating-point sum) the same from whichever dart of the
  // orbit the traversal starts.
  std::sort(out.begin(), out.end(), value_less);
  const auto k = static_cast<std::uint32_t>(memo->bags.size());
  memo->bags.push_back(std::move(out));
  for (Dart x : orbit_) memo->bag_of.set(x, k);
  return memo->bags.back();
}

void TermEvaluator::forget() {
  for (CollectMemo& m : memo_) {
    m.bag_of.clear();
    m.bags.clear();
  }
}

Operand TermEvaluator::eval(const Term& t, std::span<const std::string> names, std::span<const Dart> darts) {
  switch (t.kind) {
    case Term::Kind::literal:
    case Term::Kind::parameter: return t.literal;
    case Term::Kind::access: {
      const Dart d = node(t.args[0], names, darts);
      const Value* v = embedding(t.name).value(d);
      if (!v) throw EvaluationError(fmt::format("{}: dart {} has no {} value", t.str(), d, t.name));
      return *v;
    }
    case Term::Kind::collect: return collect_memo(t.name, t.orbit, node(t.args[0], names, darts));
    case Term::Kind::variable:
    case Term::Kind::neighbour: throw EvaluationError(fmt::format("'{}' is a node, not a value", t.str()));
    case Term::Kind::call: break;
  }
  if (!t.function) throw EvaluationError(fmt::format("'{}' was not type-checked", t.str()));
  // A collect argument lends its memorised multiset to the call (moved in
  // and back) instead of copying it. The arguments are evaluated first
  // (memorising every collect), then the multisets are lent: no collect
  // runs while one is out, and one lent twice is copied the second time.
  std::vector<Operand> args(t.args.size());
  for (std::size_t k = 0; k < t.args.size(); ++k) {
    const Term& a = t.args[k];
    if (a.kind == Term::Kind::collect) collect_memo(a.name, a.orbit, node(a.args[0], names, darts));
    else args[k] = eval(a, names, darts);
  }
  std::vector<std::pair<std::size_t, Multiset*>> lent;
  for (std::size_t k = 0; k < t.args.size(); ++k) {
    const Term& a = t.args[k];
    if (a.kind != Term::Kind::collect) continue;
    Multiset& m = collect_memo(a.name, a.orbit, node(a.args[0], names, darts));
    if (const auto it = std::find_if(lent.begin(), lent.end(), [&](const auto& x) { return x.second == &m; }); it != lent.end()) {
      args[k] = std::get<Multiset>(args[it->first]);  // m itself is out
      continue;
    }
    lent.emplace_back(k, &m);
    args[k] = std::move(m);
  }
  struct GiveBack {
    std::vector<Operand>& args;
    std::vector<std::pair<std::size_t, Multiset*>>& lent;
    ~GiveBack() {
      for (auto [k, m] : lent) *m = std::move(std::get<Multiset>(args[k]));
    }
  } give_back{args, lent};
  return t.function->apply(args);
}

Value TermEvaluator::value(const Term& t, std::span<const std::string> names, std::span<const Dart> darts) {
  Operand r = eval(t, names, darts);
  if (auto* v = std::get_if<Value>(&r)) return std::move(*v);
  throw EvaluationError(fmt::format("'{}' is a multiset, not a value", t.str()));
}

}  // namespace dartcheck
