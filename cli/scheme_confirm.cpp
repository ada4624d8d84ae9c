#include "cli/scheme_confirm.hpp"

#include <algorithm>
#include <random>

#include <fmt/format.h>

#include "checkers/host_search.hpp"
#include "checkers/map_validity.hpp"
#include "core/scheme_application.hpp"
#include "generators/random_maps.hpp"

namespace dartcheck::cli {
namespace {

// The random map generator builds 1-3-G-maps and 2-3-O-maps (closed).
bool generated(const Model& m) {
  for (int n = 1; n <= 3; ++n)
    if (m == Model::gmap(n) || (n >= 2 && m == Model::omap(n))) return true;
  return false;
}

// Recipe k of the search: about k/8 + 1 faces, so hosts grow slowly and the
// first counterexample found is a small one.
Map random_host(const Model& model, std::size_t k) {
  std::mt19937 rng(static_cast<std::uint32_t>(1000 + k));
  return build_random_map(model, draw_recipe(rng, static_cast<std::uint32_t>(1 + k / 8), model.dimension()));
}

// Applies the scheme at every dart of g; records the first broken result.
bool try_host(const CatalogRule& scheme, const Map& g, SchemeSearch& out) {
  ++out.maps;
  out.largest = std::max(out.largest, g.size());
  for (Dart hook = 0; hook < g.size(); ++hook) {
    Map h = g;
    const auto r = apply_scheme(scheme.rule, scheme.words, h, std::span(&hook, 1));
    std::vector<std::string> broken;
    if (r.refusal == Refusal::not_representable) {
      broken.push_back("not-representable");  // H would need two i-arcs at a dart: I(i) breaks
    } else if (r.ok()) {
      ++out.applications;
      for (const auto& v : check_map(h).violations) broken.push_back(constraint_name(v));
    }
    if (broken.empty()) continue;
    std::sort(broken.begin(), broken.end());
    broken.erase(std::unique(broken.begin(), broken.end()), broken.end());
    out.host = g;
    out.hook = hook;
    out.broken = std::move(broken);
    return true;
  }
  return false;
}

}  // namespace

SchemeSearch search_scheme_hosts(const CatalogRule& scheme, const std::vector<Map>& extra, std::size_t random_maps,
                                 std::size_t small_darts) {
  SchemeSearch out;
  const Model& model = scheme.rule.model();
  if (scheme.rule.hooks().size() != 1) {
    out.not_run = fmt::format("L has {} components; scheme application takes one hook (002 Sec. 6.3)", scheme.rule.hooks().size());
    return out;
  }
  std::vector<Map> hosts;
  if (generated(model))
    for (std::size_t k = 0; k < random_maps; ++k) hosts.push_back(random_host(model, k));
  for (const auto& m : extra) hosts.push_back(m);
  std::stable_sort(hosts.begin(), hosts.end(), [](const Map& a, const Map& b) { return a.size() < b.size(); });
  for (const Map& g : hosts)
    if (try_host(scheme, g, out)) return out;
  if (!generated(model)) {
    // Every map of the custom model, smallest first.
    for (std::size_t n = 1; n <= small_darts && !out.host; ++n)
      for_each_small_map(
          model, n,
          [&](const std::vector<std::vector<NodeId>>& sigma) {
            Map g(model, n);
            for (std::size_t k = 0; k < model.dims.size(); ++k)
              for (Dart d = 0; d < n; ++d) g.set_link(model.dims[k], d, sigma[k][d]);
            return !try_host(scheme, g, out);
          },
          20'000);
  }
  return out;
}

std::string describe(const SchemeSearch& s, const std::string& model) {
  if (!s.not_run.empty()) return "model-level search not run: " + s.not_run;
  if (s.host)
    return fmt::format("confirmed: applied at dart {} of a {}-dart {}, it breaks ({})", s.hook, s.host->size(), model, fmt::join(s.broken, ", "));
  if (s.applications == 0) return fmt::format("never applicable on {} {} maps of up to {} darts", s.maps, model, s.largest);
  return fmt::format("no model-level counterexample in {} applications on {} {} maps of up to {} darts", s.applications, s.maps, model,
                     s.largest);
}

}  // namespace dartcheck::cli
