#include "core/orbit_notation.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace dartcheck {

void read_orbit_entries(std::string_view text, const std::function<void(const OrbitEntry&)>& entry) {
  auto fail = [&](std::size_t pos, std::string_view what) {
    throw std::invalid_argument(fmt::format("orbit type '{}', at byte {}: {}", text, pos + 1, what));
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

}  // namespace dartcheck
