#include "checkers/embedding_consistency.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "core/orbit.hpp"

namespace dartcheck {

std::string OrbitConflict::describe(const std::string& name, const std::vector<Dim>& orbit) const {
  std::vector<std::string> vs;
  for (const auto& [d, v] : values) vs.push_back(fmt::format("{} at dart {}", v, d));
  std::string s = fmt::format("{}-orbit <{}> of dart {} ({} darts)", name, fmt::join(orbit, ","), dart, size);
  if (values.size() > 1) s += fmt::format(" has {} values: {}", values.size(), fmt::join(vs, ", "));
  if (!unlabeled.empty()) {
    std::vector<Dart> shown(unlabeled.begin(), unlabeled.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(unlabeled.size(), 8)));
    s += fmt::format("{} {} dart{} without a value ({}{})", values.size() > 1 ? "; and" : " has", unlabeled.size(), unlabeled.size() == 1 ? "" : "s",
                     fmt::join(shown, ", "), unlabeled.size() > shown.size() ? ", ..." : "");
  }
  return s;
}

namespace {

// `text(d)`: the value of dart d as text, or nullopt.
template <class Text>
EmbeddingConsistency check_orbits(const Map& map, const std::string& name, const std::vector<Dim>& orbit_type, Text text,
                                  const std::vector<std::pair<Dart, std::string>>& reassigned, bool total) {
  EmbeddingConsistency out{name, 0, 0, {}};
  const auto gens = dims_generators(orbit_type);
  OrbitWalker walker(map);
  for_each_orbit(walker, map, gens, [&](Dart d, const std::vector<Dart>& orbit) {
    ++out.orbits;
    OrbitConflict c{d, orbit.size(), {}, {}};
    auto note = [&](Dart x, const std::string& v) {
      if (std::none_of(c.values.begin(), c.values.end(), [&](const auto& p) { return p.second == v; })) c.values.emplace_back(x, v);
    };
    for (Dart x : orbit) {
      if (auto v = text(x))
        note(x, *v);
      else
        c.unlabeled.push_back(x);
    }
    for (const auto& [x, v] : reassigned)
      if (std::find(orbit.begin(), orbit.end(), x) != orbit.end()) note(x, v);
    if (!c.values.empty()) ++out.labeled;
    if (c.values.size() > 1 || (!c.unlabeled.empty() && (total || !c.values.empty()))) out.conflicts.push_back(std::move(c));
  });
  return out;
}

}  // namespace

EmbeddingConsistency check_embedding(const Map& map, const MapEmbedding& e) {
  auto text = [&](Dart x) -> std::optional<std::string> {
    if (x < e.values.size() && e.values[x]) return fmt::format("\"{}\"", *e.values[x]);
    return std::nullopt;
  };
  std::vector<std::pair<Dart, std::string>> reassigned;
  for (const auto& [d, v] : e.reassigned) reassigned.emplace_back(d, fmt::format("\"{}\"", v));
  return check_orbits(map, e.name, e.orbit, text, reassigned, false);
}

EmbeddingConsistency check_embedding(const Map& map, const Embedding& e, bool total) {
  auto text = [&](Dart x) -> std::optional<std::string> {
    if (const Value* v = e.value(x)) return v->str();
    return std::nullopt;
  };
  return check_orbits(map, e.signature.name, e.signature.orbit, text, {}, total);
}

}  // namespace dartcheck
