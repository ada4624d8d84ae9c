#include "rewriting/term_functions.hpp"

#include <fmt/format.h>

namespace dartcheck {

namespace {

using VT = ValueType;
const Value& val(std::span<const Operand> a, std::size_t k) { return value_arg(a, k); }
std::span<const Value> bag(std::span<const Operand> a, std::size_t k) { return multiset_arg(a, k); }

// A value type as C++ code, for the calls `dartcheck compile` writes.
std::string cpp_type(VT t) { return fmt::format("dartcheck::ValueType::{}", t); }
std::string cpp_call(std::string_view f, std::string_view args) { return fmt::format("dartcheck::algebra::{}({})", f, args); }

using namespace algebra;

// point2(x, y), vector3(x, y, z), color(r, g, b), ...
void add_constructors(FunctionRegistry& r) {
  const Sort real = Sort::of(VT::real);
  for (VT t : {VT::point2, VT::vector2})
    r.add(
        std::string(name_of(t)), {real, real}, Sort::of(t), [t](auto a) { return coords(t, val(a, 0), val(a, 1)); },
        cpp_call("coords", cpp_type(t) + ", {0}, {1}"));
  for (VT t : {VT::point3, VT::vector3, VT::color})
    r.add(
        std::string(name_of(t)), {real, real, real}, Sort::of(t), [t](auto a) { return coords(t, val(a, 0), val(a, 1), val(a, 2)); },
        cpp_call("coords", cpp_type(t) + ", {0}, {1}, {2}"));
}

// Point and vector arithmetic, in 2D and 3D: a·x + b·y (combine).
void add_point_arithmetic(FunctionRegistry& r) {
  const Sort real = Sort::of(VT::real);
  for (const auto& types : {std::pair{VT::point2, VT::vector2}, std::pair{VT::point3, VT::vector3}}) {
    const VT p = types.first, v = types.second;  // named: clang 14 cannot capture structured bindings
    const Sort P = Sort::of(p), V = Sort::of(v);
    const std::string tp = cpp_type(p), tv = cpp_type(v);
    r.add(
        "+", {P, V}, P, [p](auto a) { return combine(p, val(a, 0), 1, val(a, 1), 1); }, cpp_call("combine", tp + ", {0}, 1, {1}, 1"));
    r.add(
        "+", {V, V}, V, [v](auto a) { return combine(v, val(a, 0), 1, val(a, 1), 1); }, cpp_call("combine", tv + ", {0}, 1, {1}, 1"));
    r.add(
        "-", {P, V}, P, [p](auto a) { return combine(p, val(a, 0), 1, val(a, 1), -1); }, cpp_call("combine", tp + ", {0}, 1, {1}, -1"));
    r.add(
        "-", {P, P}, V, [v](auto a) { return combine(v, val(a, 0), 1, val(a, 1), -1); }, cpp_call("combine", tv + ", {0}, 1, {1}, -1"));
    r.add(
        "-", {V, V}, V, [v](auto a) { return combine(v, val(a, 0), 1, val(a, 1), -1); }, cpp_call("combine", tv + ", {0}, 1, {1}, -1"));
    r.add(
        "-", {V}, V, [v](auto a) { return combine(v, val(a, 0), -1, val(a, 0), 0); }, cpp_call("combine", tv + ", {0}, -1, {0}, 0"));
    r.add(
        "*", {real, V}, V, [v](auto a) { return combine(v, val(a, 1), val(a, 0).x[0], val(a, 1), 0); },
        cpp_call("combine", tv + ", {1}, ({0}).x[0], {1}, 0"));
    r.add(
        "*", {V, real}, V, [v](auto a) { return combine(v, val(a, 0), val(a, 1).x[0], val(a, 0), 0); },
        cpp_call("combine", tv + ", {0}, ({1}).x[0], {0}, 0"));
    r.add(
        "/", {V, real}, V, [v](auto a) { return combine(v, val(a, 0), 1 / val(a, 1).x[0], val(a, 0), 0); },
        cpp_call("combine", tv + ", {0}, 1 / ({1}).x[0], {0}, 0"));
    r.add(
        "midpoint", {P, P}, P, [p](auto a) { return combine(p, val(a, 0), 0.5, val(a, 1), 0.5); }, cpp_call("combine", tp + ", {0}, 0.5, {1}, 0.5"));
    r.add(
        "barycenter", {P, real, P, real}, P, [p](auto a) { return barycenter(p, val(a, 0), val(a, 1), val(a, 2), val(a, 3)); },
        cpp_call("barycenter", tp + ", {0}, {1}, {2}, {3}"));
    r.add(
        "center", {Sort::bag(p)}, P, [p](auto a) { return average(p, bag(a, 0), "center"); }, cpp_call("average", tp + ", {0}, \"center\""));
    r.add(
        "length", {V}, real, [](auto a) { return length(val(a, 0)); }, cpp_call("length", "{0}"));
  }
}

// Jerboa's Vec3 methods (docs/jerboa-expressions.md): Vec3 is read as a
// point3 (a position) and its methods as coordinate arithmetic on points,
// vectors and colors alike, as Java computes them.
void add_vec3_methods(FunctionRegistry& r) {
  const Sort real = Sort::of(VT::real);
  for (VT t : {VT::point3, VT::vector3, VT::color}) {
    const Sort P = Sort::of(t);
    const std::string tt = cpp_type(t);
    r.add(
        "addn", {P, P}, P, [t](auto a) { return plus(t, val(a, 0), val(a, 1)); }, cpp_call("plus", tt + ", {0}, {1}"));
    r.add(
        "addn", {P, real, real, real}, P, [t](auto a) { return shifted(t, val(a, 0), val(a, 1), val(a, 2), val(a, 3)); },
        cpp_call("shifted", tt + ", {0}, {1}, {2}, {3}"));
    r.add(
        "mul", {P, real}, P, [t](auto a) { return scaled(t, val(a, 0), val(a, 1)); }, cpp_call("scaled", tt + ", {0}, {1}"));
    r.add(
        "div", {P, real}, P, [t](auto a) { return divided(t, val(a, 0), val(a, 1)); }, cpp_call("divided", tt + ", {0}, {1}"));
    r.add(
        "mid", {P, P}, P, [t](auto a) { return mid(t, val(a, 0), val(a, 1)); }, cpp_call("mid", tt + ", {0}, {1}"));
    r.add(
        "segment", {P, P, real}, P, [t](auto a) { return segment(t, val(a, 0), val(a, 1), val(a, 2)); },
        cpp_call("segment", tt + ", {0}, {1}, {2}"));
    r.add(
        "barycenter", {Sort::bag(t)}, P, [t](auto a) { return average(t, bag(a, 0), "barycenter"); },
        cpp_call("average", tt + ", {0}, \"barycenter\""));
    r.add(
        "sum", {Sort::bag(t)}, P, [t](auto a) { return coordinate_sum(t, bag(a, 0)); }, cpp_call("coordinate_sum", tt + ", {0}"));
    for (std::size_t k = 0; k < 3; ++k)
      r.add(
          std::string(1, "xyz"[k]), {P}, real, [k](auto a) { return coordinate(val(a, 0), k); }, cpp_call("coordinate", fmt::format("{{0}}, {}", k)));
  }
}

// Colors: the average (003 Sec. 3.4 "mix : color x color -> color"), and
// the arithmetic, sums and counts of scalars.
void add_colors_and_scalars(FunctionRegistry& r) {
  const Sort real = Sort::of(VT::real), integer = Sort::of(VT::integer), color = Sort::of(VT::color);
  const std::string tc = cpp_type(VT::color);
  r.add(
      "mix", {color, color}, color, [](auto a) { return combine(VT::color, val(a, 0), 0.5, val(a, 1), 0.5); },
      cpp_call("combine", tc + ", {0}, 0.5, {1}, 0.5"));
  r.add(
      "mix", {Sort::bag(VT::color)}, color, [](auto a) { return average(VT::color, bag(a, 0), "mix"); }, cpp_call("average", tc + ", {0}, \"mix\""));

  // Scalars.
  r.add(
      "+", {real, real}, real, [](auto a) { return real_plus(val(a, 0), val(a, 1)); }, cpp_call("real_plus", "{0}, {1}"));
  r.add(
      "-", {real, real}, real, [](auto a) { return real_minus(val(a, 0), val(a, 1)); }, cpp_call("real_minus", "{0}, {1}"));
  r.add(
      "*", {real, real}, real, [](auto a) { return real_times(val(a, 0), val(a, 1)); }, cpp_call("real_times", "{0}, {1}"));
  r.add(
      "/", {real, real}, real, [](auto a) { return real_divided(val(a, 0), val(a, 1)); }, cpp_call("real_divided", "{0}, {1}"));
  r.add(
      "-", {real}, real, [](auto a) { return real_negated(val(a, 0)); }, cpp_call("real_negated", "{0}"));
  r.add(
      "+", {integer, integer}, integer, [](auto a) { return integer_plus(val(a, 0), val(a, 1)); }, cpp_call("integer_plus", "{0}, {1}"));
  r.add(
      "-", {integer, integer}, integer, [](auto a) { return integer_minus(val(a, 0), val(a, 1)); }, cpp_call("integer_minus", "{0}, {1}"));
  r.add(
      "*", {integer, integer}, integer, [](auto a) { return integer_times(val(a, 0), val(a, 1)); }, cpp_call("integer_times", "{0}, {1}"));
  r.add(
      "-", {integer}, integer, [](auto a) { return integer_negated(val(a, 0)); }, cpp_call("integer_negated", "{0}"));
  r.add(
      "/", {integer, integer}, integer, [](auto a) { return integer_divided(val(a, 0), val(a, 1)); }, cpp_call("integer_divided", "{0}, {1}"));
  r.add(
      "sum", {Sort::bag(VT::real)}, real, [](auto a) { return real_sum(bag(a, 0)); }, cpp_call("real_sum", "{0}"));
  r.add(
      "sum", {Sort::bag(VT::integer)}, integer, [](auto a) { return integer_sum(bag(a, 0)); }, cpp_call("integer_sum", "{0}"));
  for (int t = 0; t <= static_cast<int>(VT::string); ++t)
    r.add(
        "count", {Sort::bag(static_cast<VT>(t))}, integer, [](auto a) { return count(bag(a, 0)); }, cpp_call("count", "{0}"));
}

// Every function calls rewriting/algebra.hpp, and its `cpp` text is that
// same call with the arguments as {0}, {1}, ... .
FunctionRegistry make_builtin() {
  FunctionRegistry r;
  r.add(
      "real", {Sort::of(VT::integer)}, Sort::of(VT::real), [](auto a) { return to_real(val(a, 0)); }, cpp_call("to_real", "{0}"));
  add_constructors(r);
  add_point_arithmetic(r);
  add_vec3_methods(r);
  add_colors_and_scalars(r);
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

void FunctionRegistry::add(std::string name, std::vector<Sort> params, Sort result, std::function<Value(std::span<const Operand>)> apply,
                           std::string cpp) {
  for (Function& f : functions_)
    if (f.name == name && f.params == params) {
      f.result = result;
      f.apply = std::move(apply);
      f.cpp = std::move(cpp);
      return;
    }
  functions_.push_back({std::move(name), std::move(params), result, std::move(apply), std::move(cpp)});
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
