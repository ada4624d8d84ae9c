#include "rewriting/value.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <deque>
#include <mutex>
#include <unordered_map>

#include <fmt/format.h>

namespace dartcheck {

namespace {

constexpr std::array<std::string_view, 9> names = {"point2", "point3", "vector2", "vector3", "color", "real", "integer", "boolean", "string"};

std::string number(double v) {
  // Shortest text that reads back to the same double.
  std::array<char, 32> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return std::string(buf.data(), r.ptr);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

}  // namespace

std::string_view name_of(ValueType t) { return names[static_cast<std::size_t>(t)]; }

std::optional<ValueType> type_by_name(std::string_view name) {
  // Keep only the last component of a Java class name (Jerboa's
  // "fr.ensma....Vec3"), lower-case, drop '_' and a final 'd' after a digit.
  if (const auto dot = name.rfind('.'); dot != std::string_view::npos) name = name.substr(dot + 1);
  std::string k;
  for (char c : name)
    if (c != '_') k += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (k.size() >= 2 && k.back() == 'd' && std::isdigit(static_cast<unsigned char>(k[k.size() - 2]))) k.pop_back();
  if (k == "vec2") k = "vector2";
  if (k == "vec3") k = "vector3";
  if (k == "float" || k == "double") k = "real";
  if (k == "int" || k == "long") k = "integer";
  if (k == "bool") k = "boolean";
  if (k == "colour") k = "color";
  for (std::size_t t = 0; t < names.size(); ++t)
    if (k == names[t]) return static_cast<ValueType>(t);
  return std::nullopt;
}

int coordinates(ValueType t) {
  switch (t) {
    case ValueType::point2:
    case ValueType::vector2:
      return 2;
    case ValueType::point3:
    case ValueType::vector3:
    case ValueType::color:
      return 3;
    default:
      return 0;
  }
}

std::string Sort::str() const {
  if (kind == node) return "Node";
  const std::string t(name_of(type));
  return kind == multiset ? fmt::format("{}•", t) : t;
}

namespace {

// Strings are few (Jerboa's names and tags) and immortal: a deque keeps
// each text at its address, the map finds a text's number. A mutex makes
// interning safe from several threads.
struct InternTable {
  std::mutex lock;
  std::deque<std::string> texts;
  std::unordered_map<std::string_view, std::int64_t> number;
};

InternTable& interned() {
  static InternTable table;
  return table;
}

}  // namespace

Value Value::text(std::string v) {
  InternTable& t = interned();
  const std::scoped_lock hold(t.lock);
  Value r;
  r.type = ValueType::string;
  if (const auto it = t.number.find(v); it != t.number.end()) {
    r.i = it->second;
    return r;
  }
  r.i = static_cast<std::int64_t>(t.texts.size());
  t.texts.push_back(std::move(v));
  t.number.emplace(t.texts.back(), r.i);
  return r;
}

const std::string& Value::string() const {
  static const std::string empty;
  if (type != ValueType::string) return empty;
  InternTable& t = interned();
  const std::scoped_lock hold(t.lock);
  return t.texts[static_cast<std::size_t>(i)];
}

std::string Value::str() const {
  switch (type) {
    case ValueType::real:
      return number(x[0]);
    case ValueType::integer:
      return std::to_string(i);
    case ValueType::boolean:
      return i ? "true" : "false";
    case ValueType::string:
      return fmt::format("\"{}\"", string());
    default:
      break;
  }
  std::vector<std::string> parts;
  for (int k = 0; k < coordinates(type); ++k) parts.push_back(number(x[static_cast<std::size_t>(k)]));
  return fmt::format("{}({})", type == ValueType::color ? "rgb" : "", fmt::join(parts, ", "));
}

std::optional<Value> parse_value(ValueType t, std::string_view text, std::string* why) {
  auto fail = [&](std::string m) -> std::optional<Value> {
    if (why) *why = std::move(m);
    return std::nullopt;
  };
  text = trim(text);
  if (t == ValueType::string) {
    if (text.size() >= 2 && text.front() == '"' && text.back() == '"') text = text.substr(1, text.size() - 2);
    return Value::text(std::string(text));
  }
  if (t == ValueType::boolean) {
    if (text == "true" || text == "1") return Value::boolean(true);
    if (text == "false" || text == "0") return Value::boolean(false);
    return fail(fmt::format("'{}' is not a boolean (true or false)", text));
  }
  if (t == ValueType::integer) {
    std::int64_t v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec != std::errc{} || r.ptr != text.data() + text.size()) return fail(fmt::format("'{}' is not an integer", text));
    return Value::integer(v);
  }
  // Numbers separated by spaces or commas, optionally in () or [] or rgb().
  if (text.starts_with("rgb(")) text.remove_prefix(3);
  if (!text.empty() && (text.front() == '(' || text.front() == '[')) {
    const char close = text.front() == '(' ? ')' : ']';
    if (text.back() != close) return fail(fmt::format("'{}' has no closing '{}'", text, close));
    text = text.substr(1, text.size() - 2);
  }
  std::vector<double> xs;
  std::size_t k = 0;
  while (k < text.size()) {
    while (k < text.size() && (std::isspace(static_cast<unsigned char>(text[k])) || text[k] == ',')) ++k;
    if (k == text.size()) break;
    double v = 0;
    const auto r = std::from_chars(text.data() + k, text.data() + text.size(), v);
    if (r.ec != std::errc{}) return fail(fmt::format("'{}' is not a number", text.substr(k)));
    xs.push_back(v);
    k = static_cast<std::size_t>(r.ptr - text.data());
  }
  const std::size_t want = t == ValueType::real ? 1 : static_cast<std::size_t>(coordinates(t));
  if (xs.size() != want) return fail(fmt::format("a {} has {} coordinate{}, '{}' has {}", t, want, want == 1 ? "" : "s", text, xs.size()));
  if (t == ValueType::real) return Value::real(xs[0]);
  std::array<double, 3> c{};
  std::copy(xs.begin(), xs.end(), c.begin());
  return Value::coords(t, c);
}

}  // namespace dartcheck
