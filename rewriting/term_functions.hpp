// The user signature Omega_pi and its algebra (003 Sec. 3.4): function
// names with a profile s1 x ... x sm -> s and their implementation. The
// built-in algebra covers the paper's examples (point/vector arithmetic,
// midpoint, center, barycenter, mix) and scalar arithmetic; a modeler
// registers its own functions with `add`.
#pragma once

#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "rewriting/algebra.hpp"
#include "rewriting/value.hpp"

namespace dartcheck {

/// An argument of a function: a value, or the elements of a multiset the
/// evaluator lends for the time of the call (its memorised collect:
/// nothing is copied).
using Operand = std::variant<Value, std::span<const Value>>;

/// Argument k of a function as the sort its profile declares.
inline const Value& value_arg(std::span<const Operand> a, std::size_t k) { return std::get<Value>(a[k]); }
inline std::span<const Value> multiset_arg(std::span<const Operand> a, std::size_t k) { return std::get<std::span<const Value>>(a[k]); }

struct Function {
  std::string name;
  std::vector<Sort> params;
  Sort result;
  std::function<Value(std::span<const Operand>)> apply;
  /// The same function as a C++ expression for `dartcheck compile`, its
  /// arguments written {0}, {1}, ... (fmt syntax): a call of
  /// rewriting/algebra.hpp, which `apply` calls too. Empty for a function a
  /// modeler registers (its body is not known as C++).
  std::string cpp;
  std::string profile() const;  // "midpoint : point2 x point2 -> point2"
};

class FunctionRegistry {
 public:
  /// The built-in algebra.
  static const FunctionRegistry& builtin();
  FunctionRegistry() = default;

  /// Registers an overload; a second one with the same name and
  /// parameters replaces the first. `result` must be a value sort.
  void add(std::string name, std::vector<Sort> params, Sort result, std::function<Value(std::span<const Operand>)> apply, std::string cpp = {});

  /// The overload of `name` whose parameters equal `args`, or nullptr.
  const Function* find(const std::string& name, const std::vector<Sort>& args) const;
  /// Every overload of `name` (for error messages).
  std::vector<const Function*> overloads(const std::string& name) const;

 private:
  std::vector<Function> functions_;
};

}  // namespace dartcheck
