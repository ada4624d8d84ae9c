#include "proofs/detail/value_encoding.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

namespace dartcheck::proofs {

ValueEncoding::ValueEncoding(z3::context& ctx, const SymPool& pool, Reading reading) : ctx_(ctx), pool_(pool), reading_(reading), premises_(ctx) {}

int ValueEncoding::width(ValueType t) const {
  if (reading_ == Reading::uninterpreted) return 1;
  return coordinates(t) > 0 ? 3 : 1;
}

z3::sort ValueEncoding::component_sort(ValueType t) {
  if (reading_ == Reading::uninterpreted) return ctx_.int_sort();
  switch (t) {
    case ValueType::integer:
    case ValueType::string:
      return ctx_.int_sort();
    case ValueType::boolean:
      return ctx_.bool_sort();
    default:
      return ctx_.real_sort();
  }
}

const z3::expr_vector& ValueEncoding::encode(std::uint32_t k) {
  if (memo_.size() <= k) memo_.resize(pool_.size());
  if (memo_[k]) return *memo_[k];
  const SymExpr& e = pool_.at(k);
  z3::expr_vector v = e.kind == SymExpr::Kind::unknown ? unknown(e) : e.kind == SymExpr::Kind::literal ? literal(e.literal) : call(e);
  memo_[k] = v;
  return *memo_[k];
}

z3::expr_vector ValueEncoding::unknown(const SymExpr& e) {
  if (unknowns_.size() <= e.unknown) unknowns_.resize(pool_.unknowns().size());
  if (unknowns_[e.unknown]) return *unknowns_[e.unknown];
  z3::expr_vector v(ctx_);
  const z3::sort s = component_sort(e.type);
  for (int c = 0; c < width(e.type); ++c) {
    // A 2D point's third coordinate is 0, as every operation keeps it.
    if (reading_ == Reading::arithmetic && c == 2 && coordinates(e.type) == 2)
      v.push_back(ctx_.real_val(0));
    else
      v.push_back(ctx_.constant(fmt::format("u{}_{}", e.unknown, c).c_str(), s));
  }
  unknowns_[e.unknown] = v;
  return v;
}

z3::expr_vector ValueEncoding::literal(const Value& x) {
  z3::expr_vector v(ctx_);
  if (reading_ == Reading::uninterpreted) {
    // Distinct literals are distinct values: constants below every
    // unknown's reach would forbid an unknown equal to a literal, so they
    // are plain integers that unknowns may also take.
    const std::string key = fmt::format("{}:{}", name_of(x.type), x.str());
    auto it = std::find(literals_.begin(), literals_.end(), key);
    if (it == literals_.end()) it = literals_.insert(literals_.end(), key);
    v.push_back(ctx_.int_val(static_cast<std::int64_t>(-1'000'000 - (it - literals_.begin()))));
    return v;
  }
  // Z3 reads decimals, not exponents: a double in fixed notation is its
  // exact value (every double is a finite decimal); a non-finite literal
  // has no real value and is a constant of its own.
  auto real = [&](double d) {
    if (!std::isfinite(d)) {
      uninterpreted_.insert(fmt::format("the literal {} (not a real number)", d));
      return ctx_.real_const(fmt::format("literal_{}", d).c_str());
    }
    const std::string shortest = fmt::format("{}", d);
    return ctx_.real_val((shortest.find_first_of("eE") == std::string::npos ? shortest : fmt::format("{:.1100f}", d)).c_str());
  };
  switch (x.type) {
    case ValueType::integer:
    case ValueType::string:
      v.push_back(ctx_.int_val(x.i));
      break;
    case ValueType::boolean:
      v.push_back(ctx_.bool_val(x.i != 0));
      break;
    case ValueType::real:
      v.push_back(real(x.x[0]));
      break;
    default:
      for (int c = 0; c < 3; ++c) v.push_back(real(x.x[static_cast<std::size_t>(c)]));
  }
  return v;
}

z3::expr ValueEncoding::equal(std::uint32_t a, std::uint32_t b) {
  const z3::expr_vector &x = encode(a), &y = encode(b);
  z3::expr_vector same(ctx_);
  for (unsigned c = 0; c < x.size() && c < y.size(); ++c) same.push_back(x[c] == y[c]);
  return z3::mk_and(same);
}

namespace {

// Sorts integers by a network of compare-exchanges: the multiset's
// canonical order, whatever order its elements were met in.
z3::expr_vector sorted(z3::context& ctx, std::vector<z3::expr> v) {
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = 0; j + 1 < v.size() - i; ++j) {
      const z3::expr lo = z3::ite(v[j] <= v[j + 1], v[j], v[j + 1]);
      const z3::expr hi = z3::ite(v[j] <= v[j + 1], v[j + 1], v[j]);
      v[j] = lo;
      v[j + 1] = hi;
    }
  z3::expr_vector out(ctx);
  for (const auto& x : v) out.push_back(x);
  return out;
}

}  // namespace

z3::expr_vector ValueEncoding::opaque(const SymExpr& e) {
  // One uninterpreted symbol per overload, bag size and result coordinate.
  z3::sort_vector domain(ctx_);
  z3::expr_vector args(ctx_);
  std::string name = fmt::format("{}#{}", e.function->name, fmt::ptr(e.function));
  for (std::size_t a = 0; a < e.args.size(); ++a) {
    if (!e.is_bag[a]) {
      for (const auto& c : encode(e.args[a])) {
        domain.push_back(c.get_sort());
        args.push_back(c);
      }
      continue;
    }
    name += fmt::format("/{}", e.bags[a].size());
    // Coordinate by coordinate in the arithmetic reading; the multiset's
    // order is canonical only in the uninterpreted one (one integer each).
    std::vector<z3::expr> elements;
    for (std::uint32_t x : e.bags[a])
      for (const auto& c : encode(x)) elements.push_back(c);
    const bool sortable = reading_ == Reading::uninterpreted;
    const z3::expr_vector ordered = sortable ? sorted(ctx_, elements) : [&] {
      z3::expr_vector v(ctx_);
      for (const auto& c : elements) v.push_back(c);
      return v;
    }();
    for (const auto& c : ordered) {
      domain.push_back(c.get_sort());
      args.push_back(c);
    }
  }
  z3::expr_vector out(ctx_);
  for (int c = 0; c < width(e.type); ++c) {
    const z3::func_decl f = ctx_.function(fmt::format("{}_{}", name, c).c_str(), domain, component_sort(e.type));
    out.push_back(f(args));
  }
  return out;
}

z3::expr_vector ValueEncoding::call(const SymExpr& e) {
  if (reading_ == Reading::uninterpreted) return opaque(e);
  bool done = true;
  z3::expr_vector v = arithmetic(e, done);
  if (done) return v;
  uninterpreted_.insert(fmt::format("{} ({})", e.function->profile(), v.empty() ? "no arithmetic encoding" : "a multiset of unordered coordinates"));
  return opaque(e);
}

z3::expr_vector ValueEncoding::arithmetic(const SymExpr& e, bool& done) {
  const Function& f = *e.function;
  const std::string& n = f.name;
  const std::size_t m = e.args.size();
  auto arg = [&](std::size_t k) -> const z3::expr_vector& { return encode(e.args[k]); };
  auto type_of = [&](std::size_t k) { return f.params[k].type; };
  auto geometric = [&](std::size_t k) { return !e.is_bag[k] && coordinates(type_of(k)) > 0; };
  auto scalar = [&](std::size_t k) { return arg(k)[0]; };
  auto as_real = [&](const z3::expr& x) { return x.is_int() ? z3::to_real(x) : x; };
  z3::expr_vector out(ctx_);
  auto coords = [&](auto fn) {
    for (unsigned c = 0; c < 3; ++c) out.push_back(fn(c));
    return out;
  };
  auto nonzero = [&](const z3::expr& x, const char* why) {
    premises_.push_back(x != ctx_.real_val(0));
    if (why) uninterpreted_.insert(why);
  };
  const bool geo_result = coordinates(f.result.type) > 0;
  // Multisets: their elements' coordinates summed, and their size.
  auto bag_sum = [&](std::size_t k, unsigned c) {
    z3::expr s = f.result.type == ValueType::integer ? ctx_.int_val(0) : ctx_.real_val(0);
    for (std::uint32_t x : e.bags[k]) s = s + encode(x)[c];
    return s;
  };
  if (m == 1 && e.is_bag[0]) {
    const auto size = static_cast<int>(e.bags[0].size());
    if (n == "count") return out.push_back(ctx_.int_val(size)), out;
    if (n == "sum") return geo_result ? coords([&](unsigned c) { return bag_sum(0, c); }) : (out.push_back(bag_sum(0, 0)), out);
    if (n == "center" || n == "barycenter" || n == "mix") return coords([&](unsigned c) { return bag_sum(0, c) / ctx_.real_val(size); });
    done = false;
    return out;
  }
  if (std::any_of(e.is_bag.begin(), e.is_bag.end(), [](bool b) { return b; })) {
    done = false;
    return out;
  }
  if (geo_result) {
    if ((n == "+" || n == "addn") && m == 2) return coords([&](unsigned c) { return arg(0)[c] + arg(1)[c]; });
    if (n == "-" && m == 2) return coords([&](unsigned c) { return arg(0)[c] - arg(1)[c]; });
    if (n == "-" && m == 1) return coords([&](unsigned c) { return -arg(0)[c]; });
    if ((n == "*" || n == "mul") && m == 2)
      return geometric(0) ? coords([&](unsigned c) { return arg(0)[c] * scalar(1); }) : coords([&](unsigned c) { return scalar(0) * arg(1)[c]; });
    if ((n == "/" || n == "div") && m == 2) {
      nonzero(scalar(1), "division of coordinates: hosts whose divisor is 0 are excluded (the double gives an infinity)");
      return coords([&](unsigned c) { return arg(0)[c] / scalar(1); });
    }
    if ((n == "midpoint" || n == "mid" || n == "mix") && m == 2)
      return coords([&](unsigned c) { return (arg(0)[c] + arg(1)[c]) / ctx_.real_val(2); });
    if (n == "segment" && m == 3) return coords([&](unsigned c) { return arg(0)[c] + (arg(1)[c] - arg(0)[c]) * scalar(2); });
    if (n == "addn" && m == 4) return coords([&](unsigned c) { return arg(0)[c] + scalar(c + 1); });
    if (n == "barycenter" && m == 4) {
      const z3::expr total = scalar(1) + scalar(3);
      nonzero(total, nullptr);  // the library refuses weights summing to 0
      return coords([&](unsigned c) { return arg(0)[c] * (scalar(1) / total) + arg(2)[c] * (scalar(3) / total); });
    }
    if (n == std::string(name_of(f.result.type)))  // a constructor
      return coords([&](unsigned c) { return c < m ? scalar(c) : ctx_.real_val(0); });
    done = false;
    return out;
  }
  if ((n == "x" || n == "y" || n == "z") && m == 1) return out.push_back(arg(0)[static_cast<unsigned>(n[0] - 'x')]), out;
  if (n == "real" && m == 1) return out.push_back(as_real(scalar(0))), out;
  const bool integer = f.result.type == ValueType::integer;
  if (f.result.type == ValueType::real || integer) {
    if (n == "+" && m == 2) return out.push_back(scalar(0) + scalar(1)), out;
    if (n == "-" && m == 2) return out.push_back(scalar(0) - scalar(1)), out;
    if (n == "-" && m == 1) return out.push_back(-scalar(0)), out;
    if (n == "*" && m == 2) return out.push_back(scalar(0) * scalar(1)), out;
    if (n == "/" && m == 2 && !integer) {
      nonzero(scalar(1), "real division: hosts whose divisor is 0 are excluded (the double gives an infinity)");
      return out.push_back(scalar(0) / scalar(1)), out;
    }
  }
  done = false;
  return out;
}

Value ValueEncoding::decode(const z3::model& m, std::uint32_t u) {
  const Unknown& x = pool_.unknowns()[u];
  Value v;
  v.type = x.type;
  if (u >= unknowns_.size() || !unknowns_[u]) return v;
  const z3::expr_vector& c = *unknowns_[u];
  auto number = [&](const z3::expr& e) {
    std::string s;
    const z3::expr r = m.eval(e, true);
    if (!r.is_numeral(s, 30)) return 0.0;
    if (!s.empty() && s.back() == '?') s.pop_back();  // an algebraic number, cut
    return std::stod(s);
  };
  switch (x.type) {
    case ValueType::integer:
    case ValueType::string:
      v.i = static_cast<std::int64_t>(number(c[0]));
      if (x.type == ValueType::string) {
        // A string literal's integer is its intern number: the same text.
        const std::int64_t i = v.i;
        v = Value::text(fmt::format("value {}", i));
        for (std::uint32_t k = 0; k < pool_.size(); ++k)
          if (const SymExpr& l = pool_.at(k); l.kind == SymExpr::Kind::literal && l.literal.type == ValueType::string && l.literal.i == i)
            v = l.literal;
      }
      break;
    case ValueType::boolean:
      v.i = m.eval(c[0], true).is_true() ? 1 : 0;
      break;
    case ValueType::real:
      v.x[0] = number(c[0]);
      break;
    default:
      for (unsigned k = 0; k < 3; ++k) v.x[k] = number(c[k]);
  }
  return v;
}

z3::expr_vector ValueEncoding::small_integers(std::int64_t bound) {
  z3::expr_vector out(ctx_);
  for (std::size_t u = 0; u < unknowns_.size(); ++u) {
    if (!unknowns_[u]) continue;
    for (const auto& c : *unknowns_[u]) {
      if (!c.is_const() || c.is_numeral() || !c.is_real()) continue;
      const z3::expr i = ctx_.int_const(fmt::format("{}_int", c.decl().name().str()).c_str());
      out.push_back(c == z3::to_real(i));
      out.push_back(i >= ctx_.int_val(-bound) && i <= ctx_.int_val(bound));
    }
  }
  return out;
}

}  // namespace dartcheck::proofs
