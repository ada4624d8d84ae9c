#include "reports/validity_json.hpp"

#include <fmt/format.h>

#include "checkers/embedding_consistency.hpp"
#include "core/orbit.hpp"
#include "reports/json_document.hpp"

namespace dartcheck::reports {

Json validity_document(const std::string& target, const std::string& description, const Map& map, const ValidityReport& report,
                       std::size_t limit, const JbaFile* jba) {
  Json doc = json_document("validate-map");
  doc["map"] = target;
  doc["description"] = description;
  doc["model"] = map.model().name;
  doc["darts"] = map.size();
  Json links = Json::array();
  for (const LinkCount& c : count_links(map)) links.push_back(Json{{"dim", c.dim}, {"arcs", c.arcs}, {"loops", c.loops}});
  doc["links"] = std::move(links);
  doc["valid"] = report.valid();
  // Cells are counted on valid maps only, as the text does: the orbits of
  // an invalid map are not its cells.
  if (report.valid()) {
    const CellCounts c = count_cells(map);
    Json cells{{"counts", c.cells}, {"components", c.components}};
    if (c.cells.size() == 3) cells["euler_characteristic"] = c.euler();
    doc["cells"] = std::move(cells);
  } else {
    doc["cells"] = nullptr;
  }
  doc["violation_count"] = report.violations.size();
  Json violations = Json::array();
  const std::size_t shown = limit == 0 ? report.violations.size() : std::min(limit, report.violations.size());
  for (std::size_t k = 0; k < shown; ++k) {
    const auto& v = report.violations[k];
    violations.push_back(Json{{"dart", v.element}, {"constraint", constraint_name(v)}, {"message", describe(v, fmt::format("dart {}", v.element))}});
  }
  doc["violations"] = std::move(violations);
  if (jba) {
    bool consistent = true;
    Json embeddings = Json::array();
    for (const auto& e : jba->embeddings) {
      const auto c = check_embedding(jba->map, e);
      Json conflicts = Json::array();
      for (std::size_t k = 0; k < c.conflicts.size() && (limit == 0 || k < limit); ++k) conflicts.push_back(c.conflicts[k].describe(e));
      embeddings.push_back(Json{{"name", e.name},
                                {"orbit", e.orbit},
                                {"type", e.type},
                                {"orbits", c.orbits},
                                {"with_value", c.labeled},
                                {"inconsistent", c.conflicts.size()},
                                {"conflicts", std::move(conflicts)}});
      consistent = consistent && c.consistent();
    }
    doc["jerboa"] = Json{{"modeler", jba->name}, {"embeddings", std::move(embeddings)}, {"consistently_embedded", report.valid() && consistent}};
  }
  return doc;
}

std::string validity_json_text(const std::string& target, const std::string& description, const Map& map, const ValidityReport& report,
                               std::size_t limit, const JbaFile* jba) {
  return json_text(validity_document(target, description, map, report, limit, jba));
}

}  // namespace dartcheck::reports
