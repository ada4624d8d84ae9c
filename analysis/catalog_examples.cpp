#include "analysis/catalog_examples.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "checkers/map_validity.hpp"
#include "core/isomorphism.hpp"
#include "core/orbit.hpp"
#include "rewriting/application.hpp"

namespace dartcheck::analysis {

namespace {

const Map& built_map(const Catalog& catalog, const std::vector<Map>& built, const std::string& name) {
  std::size_t index = 0;
  while (catalog.maps[index].name != name) ++index;  // the catalog reader checked the name
  return built[index];
}

}  // namespace

ExampleOutcome run_example(const Catalog& catalog, const std::vector<Map>& built, const CatalogRule& r, const Example& e) {
  Map host = built_map(catalog, built, e.map);
  const auto result = Applier(r).apply(host, e.hooks);
  if (result.refusal != Refusal::none) return {std::string(name_of(result.refusal)), result.why};
  const auto report = check_map(host);
  if (!report.valid())
    return {"invalid", fmt::format("{} violations, first: dart {} {}", report.violations.size(), report.violations[0].element,
                                   constraint_name(report.violations[0]))};
  ExampleOutcome out{"valid", fmt::format("{} darts", host.size())};
  if (e.cells) {
    const auto cells = count_cells(host).cells;
    if (cells != *e.cells) return {"wrong cells", fmt::format("cells {} expected {}", fmt::join(cells, ","), fmt::join(*e.cells, ","))};
  }
  if (!e.isomorphic_to.empty()) {
    const Map& target = built_map(catalog, built, e.isomorphic_to);
    if (!isomorphic(host, target)) return {"not isomorphic", fmt::format("H is not isomorphic to map {} ({} darts)", e.isomorphic_to, target.size())};
    out.detail += fmt::format(", isomorphic to {}", e.isomorphic_to);
  }
  return out;
}

}  // namespace dartcheck::analysis
