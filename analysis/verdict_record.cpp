#include "analysis/verdict_record.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "core/input_error.hpp"

namespace dartcheck::analysis {

bool matches_record(const CatalogRule& entry, const RuleVerdict& v, const std::vector<EmbeddingCheck>& embedding) {
  std::vector<std::string> got;
  for (const auto& c : v.conditions)
    if (!c.holds) got.push_back(c.name());
  for (const auto& name : failing_names(embedding)) got.push_back(name);
  if (!entry.expected_failures) return got.empty();
  for (const auto& name : *entry.expected_failures)
    if (!v.find(name) && std::none_of(embedding.begin(), embedding.end(), [&](const EmbeddingCheck& e) { return e.name == name; })) {
      const auto& at = entry.verdict_location;
      throw InputError(at.file, at.line, at.column,
                       fmt::format("rule '{}': verdict names '{}', which is not a condition of {}", entry.rule.name(), name, entry.rule.model().name));
    }
  auto want = *entry.expected_failures;
  std::sort(want.begin(), want.end());
  std::sort(got.begin(), got.end());
  return want == got;
}

bool contradicts_record(const CatalogRule& entry, bool broke_a_map) {
  return broke_a_map && entry.expected_failures && entry.expected_failures->empty();
}

std::string contradiction_line(const CatalogRule& entry, const std::string& how) {
  return fmt::format("{}: {}: the catalog records verdict 'consistent', but {}", entry.location.str(), entry.rule.name(), how);
}

std::string contradiction_summary(std::size_t rules) {
  return fmt::format("{} rule{} the verdict the catalog records", rules, rules == 1 ? " contradicts" : "s contradict");
}

}  // namespace dartcheck::analysis
