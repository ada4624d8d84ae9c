#include "rewriting/term_functions.hpp"

#include <cmath>

#include <fmt/format.h>

namespace dartcheck {

namespace {

using VT = ValueType;
const Value& val(std::span<const Operand> a, std::size_t k) { return value_arg(a, k); }
std::span<const Value> bag(std::span<const Operand> a, std::size_t k) { return multiset_arg(a, k); }

Value combine(VT t, const Value& p, double a, const Value& q, double b) {
  std::array<double, 3> c{};
  for (std::size_t k = 0; k < 3; ++k) c[k] = a * p.x[k] + b * q.x[k];
  return Value::coords(t, c);
}

Value average(VT t, std::span<const Value> m, const char* what) {
  if (m.empty()) throw EvaluationError(fmt::format("{} of an empty multiset", what));
  std::array<double, 3> c{};
  for (const Value& v : m)
    for (std::size_t k = 0; k < 3; ++k) c[k] += v.x[k];
  for (double& x : c) x /= static_cast<double>(m.size());
  return Value::coords(t, c);
}

FunctionRegistry make_builtin() {
  FunctionRegistry r;
  const Sort real = Sort::of(VT::real), integer = Sort::of(VT::integer), color = Sort::of(VT::color);
  r.add("real", {integer}, real, [](auto a) { return Value::real(static_cast<double>(val(a, 0).i)); });

  // Constructors.
  for (VT t : {VT::point2, VT::vector2})
    r.add(std::string(type_name(t)), {real, real}, Sort::of(t), [t](auto a) { return Value::coords(t, {val(a, 0).x[0], val(a, 1).x[0], 0}); });
  for (VT t : {VT::point3, VT::vector3, VT::color})
    r.add(std::string(type_name(t)), {real, real, real}, Sort::of(t), [t](auto a) {
      return Value::coords(t, {val(a, 0).x[0], val(a, 1).x[0], val(a, 2).x[0]});
    });

  // Point and vector arithmetic, in 2D and 3D.
  for (const auto& types : {std::pair{VT::point2, VT::vector2}, std::pair{VT::point3, VT::vector3}}) {
    const VT p = types.first, v = types.second;  // named: clang 14 cannot capture structured bindings
    const Sort P = Sort::of(p), V = Sort::of(v);
    r.add("+", {P, V}, P, [p](auto a) { return combine(p, val(a, 0), 1, val(a, 1), 1); });
    r.add("+", {V, V}, V, [v](auto a) { return combine(v, val(a, 0), 1, val(a, 1), 1); });
    r.add("-", {P, V}, P, [p](auto a) { return combine(p, val(a, 0), 1, val(a, 1), -1); });
    r.add("-", {P, P}, V, [v](auto a) { return combine(v, val(a, 0), 1, val(a, 1), -1); });
    r.add("-", {V, V}, V, [v](auto a) { return combine(v, val(a, 0), 1, val(a, 1), -1); });
    r.add("-", {V}, V, [v](auto a) { return combine(v, val(a, 0), -1, val(a, 0), 0); });
    r.add("*", {real, V}, V, [v](auto a) { return combine(v, val(a, 1), val(a, 0).x[0], val(a, 1), 0); });
    r.add("*", {V, real}, V, [v](auto a) { return combine(v, val(a, 0), val(a, 1).x[0], val(a, 0), 0); });
    r.add("/", {V, real}, V, [v](auto a) { return combine(v, val(a, 0), 1 / val(a, 1).x[0], val(a, 0), 0); });
    r.add("midpoint", {P, P}, P, [p](auto a) { return combine(p, val(a, 0), 0.5, val(a, 1), 0.5); });
    // 003 Sec. 9.1: the weighted barycenter of two positions.
    r.add("barycenter", {P, real, P, real}, P, [p](auto a) {
      const double wa = val(a, 1).x[0], wb = val(a, 3).x[0];
      if (wa + wb == 0) throw EvaluationError("barycenter with weights summing to 0");
      return combine(p, val(a, 0), wa / (wa + wb), val(a, 2), wb / (wa + wb));
    });
    r.add("center", {Sort::bag(p)}, P, [p](auto a) { return average(p, bag(a, 0), "center"); });
    r.add("length", {V}, real, [](auto a) {
      const auto& x = val(a, 0).x;
      return Value::real(std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]));
    });
  }
  // Colors: the average (003 Sec. 3.4 "mix : color x color -> color").
  r.add("mix", {color, color}, color, [](auto a) { return combine(VT::color, val(a, 0), 0.5, val(a, 1), 0.5); });
  r.add("mix", {Sort::bag(VT::color)}, color, [](auto a) { return average(VT::color, bag(a, 0), "mix"); });

  // Scalars.
  r.add("+", {real, real}, real, [](auto a) { return Value::real(val(a, 0).x[0] + val(a, 1).x[0]); });
  r.add("-", {real, real}, real, [](auto a) { return Value::real(val(a, 0).x[0] - val(a, 1).x[0]); });
  r.add("*", {real, real}, real, [](auto a) { return Value::real(val(a, 0).x[0] * val(a, 1).x[0]); });
  r.add("/", {real, real}, real, [](auto a) { return Value::real(val(a, 0).x[0] / val(a, 1).x[0]); });
  r.add("-", {real}, real, [](auto a) { return Value::real(-val(a, 0).x[0]); });
  r.add("+", {integer, integer}, integer, [](auto a) { return Value::integer(val(a, 0).i + val(a, 1).i); });
  r.add("-", {integer, integer}, integer, [](auto a) { return Value::integer(val(a, 0).i - val(a, 1).i); });
  r.add("*", {integer, integer}, integer, [](auto a) { return Value::integer(val(a, 0).i * val(a, 1).i); });
  r.add("-", {integer}, integer, [](auto a) { return Value::integer(-val(a, 0).i); });
  r.add("/", {integer, integer}, integer, [](auto a) {
    if (val(a, 1).i == 0) throw EvaluationError("integer division by 0");
    return Value::integer(val(a, 0).i / val(a, 1).i);
  });
  r.add("sum", {Sort::bag(VT::real)}, real, [](auto a) {
    double s = 0;
    for (const Value& v : bag(a, 0)) s += v.x[0];
    return Value::real(s);
  });
  r.add("sum", {Sort::bag(VT::integer)}, integer, [](auto a) {
    std::int64_t s = 0;
    for (const Value& v : bag(a, 0)) s += v.i;
    return Value::integer(s);
  });
  for (int t = 0; t <= static_cast<int>(VT::string); ++t)
    r.add("count", {Sort::bag(static_cast<VT>(t))}, integer, [](auto a) { return Value::integer(static_cast<std::int64_t>(bag(a, 0).size())); });
  return r;
}

}  // namespace

std::string Function::profile() const {
  std::string r = name + " : ";
  for (std::size_t k = 0; k < params.size(); ++k) r += (k ? " x " : "") + params[k].str();
  return r + " -> " + result.str();
}

const FunctionRegistry& FunctionRegistry::builtin() {
  static const FunctionRegistry r = make_builtin();
  return r;
}

void FunctionRegistry::add(std::string name, std::vector<Sort> params, Sort result, std::function<Value(std::span<const Operand>)> apply) {
  for (Function& f : functions_)
    if (f.name == name && f.params == params) {
      f.result = result;
      f.apply = std::move(apply);
      return;
    }
  functions_.push_back({std::move(name), std::move(params), result, std::move(apply)});
}

const Function* FunctionRegistry::find(const std::string& name, const std::vector<Sort>& args) const {
  for (const Function& f : functions_)
    if (f.name == name && f.params == args) return &f;
  return nullptr;
}

std::vector<const Function*> FunctionRegistry::overloads(const std::string& name) const {
  std::vector<const Function*> r;
  for (const Function& f : functions_)
    if (f.name == name) r.push_back(&f);
  return r;
}

}  // namespace dartcheck
