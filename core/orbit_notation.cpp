#include "core/orbit_notation.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace dartcheck {

void read_orbit_entries(std::string_view text, const std::function<void(const OrbitEntry&)>& entry) {
  auto fail = [&](std::size_t pos, std::string_view what) {
    throw OrbitNotationError(pos, fmt::format("orbit type '{}', at byte {}: {}", text, pos + 1, what));
  };
  std::size_t i = 0;
  auto skip_spaces = [&] {
    while (i < text.size() && text[i] == ' ') ++i;
  };
  auto take = [&](std::string_view s) {
    if (text.substr(i).starts_with(s)) {
      i += s.size();
      return true;
    }
    return false;
  };
  skip_spaces();
  if (!take("<") && !take("\u27e8")) fail(i, "expected '<' or '⟨'");
  skip_spaces();
  if (!take(">") && !take("\u27e9")) {
    for (;;) {
      skip_spaces();
      const std::size_t start = i;
      if (take("_")) {
        entry({"_", start});
      } else if (i < text.size() && text[i] >= '0' && text[i] <= '9') {
        while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
        entry({std::string(text.substr(start, i - start)), start});
      } else {
        fail(i, "expected a dimension or '_'");
      }
      skip_spaces();
      if (take(",")) continue;
      if (take(">") || take("\u27e9")) break;
      fail(i, "expected ',' or '>'");
    }
  }
  skip_spaces();
  if (i != text.size()) fail(i, "unexpected text after the orbit type");
}

std::vector<OrbitEntry> orbit_entries(std::string_view text) {
  std::vector<OrbitEntry> out;
  read_orbit_entries(text, [&](const OrbitEntry& e) { out.push_back(e); });
  return out;
}

OrbitType parse_orbit_type(std::string_view text) {
  OrbitType t;
  read_orbit_entries(text, [&](const OrbitEntry& e) {
    auto fail = [&](std::string_view what) {
      throw ValueError(fmt::format("orbit type '{}', at byte {}: {}", text, e.offset + e.text.size(), what));
    };
    if (e.text == "_") {
      t.emplace_back(std::nullopt);
      return;
    }
    // Saturated: any number above max_dimension is refused (found by
    // fuzz_word: "09999999999" overflowed int).
    int d = 0;
    for (char c : e.text) d = std::min(d * 10 + (c - '0'), 10 * max_dimension);
    if (d > max_dimension) fail(fmt::format("dimension {} is above {}", e.text, max_dimension));
    if (std::find(t.begin(), t.end(), std::optional<Dim>(static_cast<Dim>(d))) != t.end())
      fail(fmt::format("dimension {} appears twice (a relabeling is injective)", d));
    t.emplace_back(static_cast<Dim>(d));
  });
  return t;
}

std::string orbit_type_str(const OrbitType& t) {
  std::string s = "<";
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (k) s += ',';
    s += t[k] ? std::to_string(*t[k]) : "_";
  }
  return s + ">";
}

}  // namespace dartcheck
