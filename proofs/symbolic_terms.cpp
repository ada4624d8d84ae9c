#include "proofs/symbolic_terms.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "core/orbit.hpp"

namespace dartcheck::proofs {

std::uint32_t SymPool::intern(SymExpr e, const std::string& key) {
  if (const auto it = by_key_.find(key); it != by_key_.end()) return it->second;
  const auto k = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back(std::move(e));
  keys_.push_back(key);
  by_key_.emplace(key, k);
  return k;
}

std::uint32_t SymPool::unknown(const std::string& embedding, ValueType type, std::uint32_t orbit, Dart first) {
  const auto [it, fresh] = unknown_of_.try_emplace({embedding, orbit}, static_cast<std::uint32_t>(unknowns_.size()));
  if (fresh) unknowns_.push_back({embedding, type, first});
  SymExpr e;
  e.kind = SymExpr::Kind::unknown;
  e.type = type;
  e.unknown = it->second;
  return intern(std::move(e), fmt::format("u{}", it->second));
}

std::uint32_t SymPool::literal(const Value& v) {
  SymExpr e;
  e.kind = SymExpr::Kind::literal;
  e.type = v.type;
  e.literal = v;
  return intern(std::move(e), fmt::format("{}:{}", name_of(v.type), v.str()));
}

std::uint32_t SymPool::call(const Function* f, std::vector<std::uint32_t> args, std::vector<std::vector<std::uint32_t>> bags,
                            std::vector<bool> is_bag) {
  for (auto& b : bags) std::sort(b.begin(), b.end());
  std::string key = fmt::format("{}/{}(", f->name, fmt::ptr(f));
  for (std::size_t k = 0; k < args.size(); ++k) {
    if (is_bag[k])
      key += fmt::format("{{{}}}", fmt::join(bags[k], " "));
    else
      key += fmt::format("#{}", args[k]);
    key += ',';
  }
  SymExpr e;
  e.kind = SymExpr::Kind::call;
  e.type = f->result.type;
  e.function = f;
  e.args = std::move(args);
  e.bags = std::move(bags);
  e.is_bag = std::move(is_bag);
  return intern(std::move(e), key + ")");
}

std::string SymPool::str(std::uint32_t k) const {
  const SymExpr& e = nodes_[k];
  switch (e.kind) {
    case SymExpr::Kind::unknown:
      return fmt::format("u{}", e.unknown);
    case SymExpr::Kind::literal:
      return e.literal.str();
    case SymExpr::Kind::call:
      break;
  }
  std::vector<std::string> parts;
  for (std::size_t a = 0; a < e.args.size(); ++a) {
    if (!e.is_bag[a]) {
      parts.push_back(str(e.args[a]));
      continue;
    }
    std::vector<std::string> elements;
    for (std::uint32_t x : e.bags[a]) elements.push_back(str(x));
    parts.push_back(fmt::format("{{{}}}", fmt::join(elements, ", ")));
  }
  return fmt::format("{}({})", e.function->name, fmt::join(parts, ", "));
}

SymbolicEvaluator::SymbolicEvaluator(const Map& g, const std::vector<EmbeddingSignature>& embeddings, SymPool& pool)
    : g_(g), embeddings_(embeddings), pool_(pool) {
  for (const EmbeddingSignature& e : embeddings) {
    const OrbitPartition p = partition_orbits(g, dims_generators(e.orbit));
    orbit_.push_back(p.of);
    first_.push_back(p.first);
  }
}

const EmbeddingSignature& SymbolicEvaluator::signature(const std::string& embedding) const {
  for (const EmbeddingSignature& e : embeddings_)
    if (e.name == embedding) return e;
  throw NotEncoded(fmt::format("no embedding {} among the rule's", embedding));
}

std::uint32_t SymbolicEvaluator::orbit_of(const std::string& embedding, Dart d) const {
  const auto k = static_cast<std::size_t>(&signature(embedding) - embeddings_.data());
  return orbit_[k][d];
}

std::uint32_t SymbolicEvaluator::value_at(const std::string& embedding, Dart d) {
  const EmbeddingSignature& e = signature(embedding);
  const auto k = static_cast<std::size_t>(&e - embeddings_.data());
  const std::uint32_t o = orbit_[k][d];
  return pool_.unknown(embedding, e.type, o, first_[k][o]);
}

std::uint32_t SymbolicEvaluator::value(const Term& t, const std::vector<std::string>& names, const std::vector<Dart>& darts) {
  scope_.clear();
  for (std::size_t k = 0; k < names.size() && k < darts.size(); ++k) scope_.emplace_back(names[k], darts[k]);
  const Result r = eval(t);
  if (r.is_dart || r.is_bag) throw NotEncoded(fmt::format("{} is not a value", t.str()));
  return r.value;
}

namespace {

// The darts of the orbit of d under `dims`, in BFS order.
std::vector<Dart> orbit_darts(const Map& g, Dart d, const std::vector<Dim>& dims) {
  OrbitWalker w(g);
  return w.orbit(d, dims_generators(dims));
}

std::vector<Dim> meet(const std::vector<Dim>& a, const std::vector<Dim>& b) {
  std::vector<Dim> out;
  for (Dim i : a)
    if (std::find(b.begin(), b.end(), i) != b.end()) out.push_back(i);
  return out;
}

// One dart per orbit of `inner` inside `orbit`, in the orbit's order.
std::vector<std::vector<Dart>> sub_orbits(const Map& g, const std::vector<Dart>& orbit, const std::vector<Dim>& inner) {
  std::vector<std::vector<Dart>> out;
  for_each_class(
      g.size(), orbit, [&](Dart d) { return orbit_darts(g, d, inner); }, [&](Dart, const std::vector<Dart>& sub) { out.push_back(sub); });
  return out;
}

}  // namespace

SymbolicEvaluator::Result SymbolicEvaluator::eval_each(const Term& t) {
  Result r;
  const std::vector<Dart> orbit = orbit_darts(g_, eval(t.args[0]).dart, t.orbit);
  r.is_bag = true;
  auto body = [&](Dart d) {
    scope_.emplace_back(t.name, d);
    Result x = eval(t.args[1]);
    scope_.pop_back();
    return x;
  };
  auto add = [&](const Result& x) {
    if (x.is_bag)
      r.bag.insert(r.bag.end(), x.bag.begin(), x.bag.end());
    else
      r.bag.push_back(x.value);
  };
  if (!t.per_sub) {
    for (Dart d : orbit) add(body(d));
    return r;
  }
  for (const auto& sub : sub_orbits(g_, orbit, meet(t.sub_orbit, t.orbit))) {
    const Result first = body(sub.front());
    for (std::size_t k = 1; k < sub.size(); ++k) {
      const Result other = body(sub[k]);
      if (other.is_bag != first.is_bag || other.value != first.value || other.bag != first.bag)
        throw NotEncoded(fmt::format("{}: the body is not one expression on a <{}>-orbit", t.str(), fmt::join(t.sub_orbit, ",")));
    }
    add(first);
  }
  return r;
}

SymbolicEvaluator::Result SymbolicEvaluator::eval_call(const Term& t) {
  Result r;
  if (!t.function) throw NotEncoded(fmt::format("{}: not type-checked", t.str()));
  std::vector<std::uint32_t> args;
  std::vector<std::vector<std::uint32_t>> bags;
  std::vector<bool> is_bag;
  for (const Term& a : t.args) {
    Result x = eval(a);
    args.push_back(x.value);
    is_bag.push_back(x.is_bag);
    bags.push_back(std::move(x.bag));
  }
  // The library's averages refuse an empty multiset, whatever the values.
  for (std::size_t k = 0; k < args.size(); ++k)
    if (is_bag[k] && bags[k].empty() && t.function->name != "count" && t.function->name != "sum")
      throw NoValue(fmt::format("{} of an empty multiset", t.function->name));
  r.value = pool_.call(t.function, std::move(args), std::move(bags), std::move(is_bag));
  return r;
}

SymbolicEvaluator::Result SymbolicEvaluator::eval(const Term& t) {
  Result r;
  switch (t.kind) {
    case Term::Kind::variable:
      for (auto it = scope_.rbegin(); it != scope_.rend(); ++it)
        if (it->first == t.name) {
          r.is_dart = true;
          r.dart = it->second;
          return r;
        }
      throw NotEncoded(fmt::format("{} is not bound", t.name));
    case Term::Kind::parameter:
    case Term::Kind::literal:
      r.value = pool_.literal(t.literal);
      return r;
    case Term::Kind::neighbour: {
      const Result x = eval(t.args[0]);
      const Dart d = g_.link(t.dim, x.dart);
      if (d == no_dart) throw NoValue(fmt::format("{}: dart {} has no {}-neighbour", t.str(), x.dart, t.dim));
      r.is_dart = true;
      r.dart = d;
      return r;
    }
    case Term::Kind::access:
      r.value = value_at(t.name, eval(t.args[0]).dart);
      return r;
    case Term::Kind::collect: {
      const EmbeddingSignature& e = signature(t.name);
      r.is_bag = true;
      for (const auto& sub : sub_orbits(g_, orbit_darts(g_, eval(t.args[0]).dart, t.orbit), meet(e.orbit, t.orbit)))
        r.bag.push_back(value_at(t.name, sub.front()));
      return r;
    }
    case Term::Kind::list:
      r.is_bag = true;
      for (const Term& a : t.args) {
        const Result x = eval(a);
        if (x.is_bag)
          r.bag.insert(r.bag.end(), x.bag.begin(), x.bag.end());
        else
          r.bag.push_back(x.value);
      }
      return r;
    case Term::Kind::each:
      return eval_each(t);
    case Term::Kind::call:
      return eval_call(t);
  }
  throw NotEncoded(fmt::format("{}: unknown term kind", t.str()));
}

}  // namespace dartcheck::proofs
