#include "inference/kappa_graph.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace dartcheck::inference {

KappaGraph::KappaGraph(Map before, Map after, std::vector<Dart> kappa)
    : before_(std::move(before)), after_(std::move(after)), kappa_(std::move(kappa)), inverse_(after_.size(), no_dart) {
  kappa_.resize(before_.size(), no_dart);
  for (Dart x = 0; x < kappa_.size(); ++x)
    if (kappa_[x] != no_dart) {
      inverse_[kappa_[x]] = x;
      ++preserved_;
    }
}

std::string KappaGraph::name(Dart u) const { return fmt::format("{}:{}", in_before(u) ? 'G' : 'H', local(u)); }

namespace {

// Sets κ(x) = y, refusing a second image for x or a second preimage for y.
void associate(std::vector<Dart>& kappa, std::vector<Dart>& inverse, Dart x, Dart y) {
  if (x >= kappa.size()) throw ValueError(fmt::format("kappa: dart {} is not a dart of the before map ({} darts)", x, kappa.size()));
  if (y >= inverse.size()) throw ValueError(fmt::format("kappa: dart {} is not a dart of the after map ({} darts)", y, inverse.size()));
  if (kappa[x] == y) return;
  if (kappa[x] != no_dart) throw ValueError(fmt::format("kappa maps before dart {} to both {} and {}", x, kappa[x], y));
  if (inverse[y] != no_dart) throw ValueError(fmt::format("kappa is not injective: before darts {} and {} both map to {}", inverse[y], x, y));
  kappa[x] = y;
  inverse[y] = x;
}

// Walks <o>(x) in G and <o>(y) in H in parallel (the same letters from
// both starts) and associates the darts reached together.
void associate_orbits(const Map& g, const Map& h, const KappaSpec::OrbitPair& p, std::vector<Dart>& kappa, std::vector<Dart>& inverse) {
  for (Dim d : p.orbit)
    if (!g.model().contains(d)) throw ValueError(fmt::format("kappa: dimension {} is not a dimension of {}", d, g.model().name));
  if (p.before >= g.size() || p.after >= h.size())
    throw ValueError(
        fmt::format("kappa: orbit pair ({}, {}) names a dart outside the maps ({} and {} darts)", p.before, p.after, g.size(), h.size()));
  std::vector<Dart> seen_g(g.size(), no_dart), seen_h(h.size(), no_dart);
  std::vector<std::pair<Dart, Dart>> queue{{p.before, p.after}};
  seen_g[p.before] = p.after;
  seen_h[p.after] = p.before;
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const auto [x, y] = queue[k];
    for (Dim d : p.orbit) {
      const Dart nx = g.link(d, x), ny = h.link(d, y);
      if (nx == no_dart || ny == no_dart) throw ValueError(fmt::format("kappa: dart {} or {} has no {}-link", x, y, d));
      const bool new_x = seen_g[nx] == no_dart, new_y = seen_h[ny] == no_dart;
      if (new_x != new_y || (!new_x && (seen_g[nx] != ny || seen_h[ny] != nx)))
        throw ValueError(fmt::format("kappa: the orbits of before dart {} and after dart {} differ in shape: their {}-links from {} and {} disagree",
                                     p.before, p.after, d, x, y));
      if (new_x) {
        seen_g[nx] = ny;
        seen_h[ny] = nx;
        queue.emplace_back(nx, ny);
      }
    }
  }
  for (const auto& [x, y] : queue) associate(kappa, inverse, x, y);
}

}  // namespace

KappaGraph make_kappa_graph(Map before, Map after, const KappaSpec& spec) {
  const Model& m = before.model();
  if (!(m == after.model()))
    throw ValueError(fmt::format("the before map is a {} and the after map a {}: an example is one model", m.name, after.model().name));
  if (!m.is_generalized() || m.non_oriented != m.dim_set() || m.partial != 0)
    throw ValueError(fmt::format("{} is not an n-G-map model: inference by folding (000) is defined on G-maps", m.name));
  for (std::size_t k = 0; k < m.dims.size(); ++k)
    if (m.dims[k] != static_cast<Dim>(k)) throw ValueError(fmt::format("{} is not an n-G-map model (dimensions 0..n)", m.name));
  std::vector<Dart> kappa(before.size(), no_dart), inverse(after.size(), no_dart);
  if (spec.identity)
    for (Dart x = 0; x < std::min(before.size(), after.size()); ++x) associate(kappa, inverse, x, x);
  // An entry's error at the entry's position, when it is known.
  auto at = [](const std::vector<SourceLocation>& where, std::size_t k, const ValueError& e) {
    if (k < where.size()) throw InputError(where[k].file, where[k].line, where[k].column, e.what());
    throw;
  };
  for (std::size_t k = 0; k < spec.pairs.size(); ++k) try {
      associate(kappa, inverse, spec.pairs[k].first, spec.pairs[k].second);
    } catch (const ValueError& e) {
      at(spec.pair_locations, k, e);
    }
  for (std::size_t k = 0; k < spec.orbits.size(); ++k) try {
      associate_orbits(before, after, spec.orbits[k], kappa, inverse);
    } catch (const ValueError& e) {
      at(spec.orbit_locations, k, e);
    }
  return KappaGraph(std::move(before), std::move(after), std::move(kappa));
}

}  // namespace dartcheck::inference
