#include "events/orbit_kind.hpp"

#include "core/error.hpp"
#include "core/orbit_notation.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace dartcheck::events {

bool OrbitKind::single_letters() const {
  return std::all_of(generators.begin(), generators.end(), [](const OrbitWord& w) { return w.size() == 1; });
}

DimSet OrbitKind::dims() const {
  DimSet s = 0;
  for (const OrbitWord& w : generators)
    if (w.size() == 1) s |= dim_bit(w[0]);
  return s;
}

std::string OrbitKind::str() const {
  std::string out = "<";
  for (std::size_t k = 0; k < generators.size(); ++k) {
    if (k) out += ',';
    for (Dim d : generators[k]) out += std::to_string(d);
  }
  return out + '>';
}

std::vector<OrbitEntry> orbit_kind_entries(std::string_view text) {
  std::vector<OrbitEntry> entries = orbit_entries(text);  // ValueError with the byte
  if (entries.empty()) throw ValueError(fmt::format("orbit type '{}' is empty: give at least one dimension", text));
  return entries;
}

OrbitKind parse_orbit_kind(std::string_view text, const Model& model) {
  const std::vector<OrbitEntry> entries = orbit_kind_entries(text);
  OrbitKind kind;
  for (const OrbitEntry& e : entries) {
    const std::string& entry = e.text;
    if (entry == "_") throw ValueError(fmt::format("orbit type '{}': entry '{}' is not a dimension", text, entry));
    OrbitWord w;
    if (model.is_generalized()) {
      // G-maps: an entry is one dimension (10-15 have two digits).
      if (entry.size() > 2) throw ValueError(fmt::format("orbit type '{}': '{}' is not a dimension", text, entry));
      w.push_back(std::stoi(entry));
    } else {
      // O-maps: a word of one-digit dimensions ("21": along 2, then 1).
      for (char c : entry) w.push_back(c - '0');
    }
    for (Dim d : w)
      if (!model.contains(d)) throw ValueError(fmt::format("orbit type '{}': {} is not a dimension of {}", text, d, model.name));
    if (std::find(kind.generators.begin(), kind.generators.end(), w) != kind.generators.end())
      throw ValueError(fmt::format("orbit type '{}': '{}' repeats", text, entry));
    kind.generators.push_back(std::move(w));
  }
  std::sort(kind.generators.begin(), kind.generators.end(),
            [](const OrbitWord& a, const OrbitWord& b) { return a.size() != b.size() ? a.size() < b.size() : a < b; });
  return kind;
}

std::vector<OrbitKind> all_orbit_kinds(const Model& model) {
  std::vector<OrbitKind> out;
  const std::size_t n = model.dims.size();
  for (std::uint32_t mask = 1; mask < (1U << n); ++mask) {
    OrbitKind k;
    for (std::size_t i = 0; i < n; ++i)
      if (mask >> i & 1U) k.generators.push_back({model.dims[i]});
    out.push_back(std::move(k));
  }
  // By size, then lexicographically: <0>, <1>, <2>, <0,1>, ... as Table 1.
  std::stable_sort(out.begin(), out.end(), [](const OrbitKind& a, const OrbitKind& b) { return a.generators.size() < b.generators.size(); });
  // O-map vertices (dimensions 1..n): words j1. Other models without 0
  // (002's plain D-graphs) have no vertex orbit.
  if (!model.is_generalized() && model.dims.front() == 1 && model.dimension() >= 2) out.push_back({cell_generators(model, 0)});
  return out;
}

}  // namespace dartcheck::events
