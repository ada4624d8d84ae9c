// The arithmetic of the built-in algebra (003 Sec. 3.4, core of
// rewriting/term_functions.cpp), one inline function per operation. The
// interpreter's registry calls these functions, and the C++ that `dartcheck
// compile` generates calls the same ones (each built-in Function carries its
// call as text), so a compiled term computes the interpreter's value with the
// same floating-point operations in the same order: equal bit for bit under
// one set of compiler flags.
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>

#include "core/error.hpp"
#include "rewriting/value.hpp"

namespace dartcheck {

/// Thrown by a function that has no value at its arguments (center of an
/// empty multiset); evaluation reports it with the term.
class EvaluationError : public Error {
 public:
  using Error::Error;
};

namespace algebra {

/// a·p + b·q coordinate by coordinate, as type t: every point and vector
/// operation is one of these (a sum has a = b = 1, a negation b = 0).
inline Value combine(ValueType t, const Value& p, double a, const Value& q, double b) {
  std::array<double, 3> c{};
  for (std::size_t k = 0; k < 3; ++k) c[k] = a * p.x[k] + b * q.x[k];
  return Value::coords(t, c);
}

/// The mean of a multiset's coordinates (center, mix); `what` names the
/// function in the error of an empty multiset.
inline Value average(ValueType t, std::span<const Value> m, const char* what) {
  if (m.empty()) throw EvaluationError(std::string(what) + " of an empty multiset");
  std::array<double, 3> c{};
  for (const Value& v : m)
    for (std::size_t k = 0; k < 3; ++k) c[k] += v.x[k];
  for (double& x : c) x /= static_cast<double>(m.size());
  return Value::coords(t, c);
}

/// 003 Sec. 9.1: the barycenter of p and q with weights wa and wb.
inline Value barycenter(ValueType t, const Value& p, const Value& wa, const Value& q, const Value& wb) {
  const double a = wa.x[0], b = wb.x[0];
  if (a + b == 0) throw EvaluationError("barycenter with weights summing to 0");
  return combine(t, p, a / (a + b), q, b / (a + b));
}

inline Value length(const Value& v) { return Value::real(std::sqrt(v.x[0] * v.x[0] + v.x[1] * v.x[1] + v.x[2] * v.x[2])); }
inline Value to_real(const Value& i) { return Value::real(static_cast<double>(i.i)); }
inline Value coords(ValueType t, const Value& a, const Value& b) { return Value::coords(t, {a.x[0], b.x[0], 0}); }
inline Value coords(ValueType t, const Value& a, const Value& b, const Value& c) { return Value::coords(t, {a.x[0], b.x[0], c.x[0]}); }

inline Value real_plus(const Value& a, const Value& b) { return Value::real(a.x[0] + b.x[0]); }
inline Value real_minus(const Value& a, const Value& b) { return Value::real(a.x[0] - b.x[0]); }
inline Value real_times(const Value& a, const Value& b) { return Value::real(a.x[0] * b.x[0]); }
inline Value real_divided(const Value& a, const Value& b) { return Value::real(a.x[0] / b.x[0]); }
inline Value real_negated(const Value& a) { return Value::real(-a.x[0]); }
// Integers are exact: a result past 64 bits has no value (an error, not
// the undefined behaviour of a signed overflow).
[[noreturn]] inline void integer_overflow(const char* op) { throw EvaluationError(std::string("integer overflow in ") + op); }
inline Value integer_plus(const Value& a, const Value& b) {
  std::int64_t r = 0;
  if (__builtin_add_overflow(a.i, b.i, &r)) [[unlikely]]
    integer_overflow("+");
  return Value::integer(r);
}
inline Value integer_minus(const Value& a, const Value& b) {
  std::int64_t r = 0;
  if (__builtin_sub_overflow(a.i, b.i, &r)) [[unlikely]]
    integer_overflow("-");
  return Value::integer(r);
}
inline Value integer_times(const Value& a, const Value& b) {
  std::int64_t r = 0;
  if (__builtin_mul_overflow(a.i, b.i, &r)) [[unlikely]]
    integer_overflow("*");
  return Value::integer(r);
}
inline Value integer_negated(const Value& a) {
  std::int64_t r = 0;
  if (__builtin_sub_overflow(std::int64_t{0}, a.i, &r)) [[unlikely]]
    integer_overflow("unary -");
  return Value::integer(r);
}
inline Value integer_divided(const Value& a, const Value& b) {
  if (b.i == 0) throw EvaluationError("integer division by 0");
  if (b.i == -1) return integer_negated(a);  // INT64_MIN / -1 overflows
  return Value::integer(a.i / b.i);
}

inline Value real_sum(std::span<const Value> m) {
  double s = 0;
  for (const Value& v : m) s += v.x[0];
  return Value::real(s);
}
inline Value integer_sum(std::span<const Value> m) {
  std::int64_t s = 0;
  for (const Value& v : m)
    if (__builtin_add_overflow(s, v.i, &s)) [[unlikely]]
      throw EvaluationError("integer overflow in sum");
  return Value::integer(s);
}
inline Value count(std::span<const Value> m) { return Value::integer(static_cast<std::int64_t>(m.size())); }

// Jerboa's Vec3 arithmetic (docs/jerboa-expressions.md), coordinate by
// coordinate with Java's operations in Java's order, in double precision
// (Jerboa's Vec3 rounds each result to float).

/// p + q (Vec3.addn(Vec3)).
inline Value plus(ValueType t, const Value& p, const Value& q) { return Value::coords(t, {p.x[0] + q.x[0], p.x[1] + q.x[1], p.x[2] + q.x[2]}); }
/// p + (dx, dy, dz) (Vec3.addn(dx, dy, dz)).
inline Value shifted(ValueType t, const Value& p, const Value& dx, const Value& dy, const Value& dz) {
  return Value::coords(t, {p.x[0] + dx.x[0], p.x[1] + dy.x[0], p.x[2] + dz.x[0]});
}
/// p * k (Vec3.mul(k)).
inline Value scaled(ValueType t, const Value& p, const Value& k) { return Value::coords(t, {p.x[0] * k.x[0], p.x[1] * k.x[0], p.x[2] * k.x[0]}); }
/// p / k (Vec3.div(k)): a division, not a product by 1/k.
inline Value divided(ValueType t, const Value& p, const Value& k) { return Value::coords(t, {p.x[0] / k.x[0], p.x[1] / k.x[0], p.x[2] / k.x[0]}); }
/// (a + b) / 2 (Vec3.mid).
inline Value mid(ValueType t, const Value& a, const Value& b) {
  return Value::coords(t, {(a.x[0] + b.x[0]) / 2, (a.x[1] + b.x[1]) / 2, (a.x[2] + b.x[2]) / 2});
}
/// a + (b - a) * w (Vec3.segmentABByWeight).
inline Value segment(ValueType t, const Value& a, const Value& b, const Value& w) {
  std::array<double, 3> c{};
  for (std::size_t k = 0; k < 3; ++k) c[k] = a.x[k] + (b.x[k] - a.x[k]) * w.x[0];
  return Value::coords(t, c);
}
/// The coordinate sum of a multiset (a loop accumulating with addn).
inline Value coordinate_sum(ValueType t, std::span<const Value> m) {
  std::array<double, 3> c{};
  for (const Value& v : m)
    for (std::size_t k = 0; k < 3; ++k) c[k] += v.x[k];
  return Value::coords(t, c);
}
/// Coordinate k of p (Vec3.x(), .y(), .z()).
inline Value coordinate(const Value& p, std::size_t k) { return Value::real(p.x[k]); }

}  // namespace algebra
}  // namespace dartcheck
