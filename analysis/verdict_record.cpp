#include "analysis/verdict_record.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "core/input_error.hpp"
#include "io/baseline.hpp"

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
      throw InputError(
          at.file, at.line, at.column,
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

std::vector<std::string> apply_baseline(Catalog& catalog, const std::string& file) {
  std::vector<std::string> mismatches;
  const Baseline b = read_baseline(file);
  auto skipped = [&](const std::string& name) {
    return std::any_of(catalog.skipped.begin(), catalog.skipped.end(), [&](const SkippedRule& s) { return s.name == name; });
  };
  for (const auto& e : b.entries) {
    CatalogRule* r = nullptr;
    for (auto& x : catalog.rules)
      if (x.rule.name() == e.rule) r = &x;
    if (!r && !skipped(e.rule))
      throw InputError(e.location.file, e.location.line, e.location.column,
                       fmt::format("the baseline names rule '{}', which {} does not have", e.rule, catalog.file));
    if (r && !e.failures)
      mismatches.push_back(fmt::format("{}: the baseline records rule '{}' as not checked, but it is read now", e.location.str(), e.rule));
    else if (r)
      r->expected_failures = e.failures, r->verdict_location = e.location, r->expected_solver = e.solver, r->solver_location = e.solver_location;
    if (!r && e.failures)
      mismatches.push_back(fmt::format("{}: the baseline records a verdict for rule '{}', which is not checked now", e.location.str(), e.rule));
  }
  for (const auto& s : catalog.skipped)
    if (!b.find(s.name))
      mismatches.push_back(fmt::format("rule '{}' is not checked ({}) and the baseline {} does not record it", s.name, s.why, file));
  return mismatches;
}

}  // namespace dartcheck::analysis
