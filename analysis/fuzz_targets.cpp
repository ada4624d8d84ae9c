#include "analysis/fuzz_targets.hpp"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/map_sources.hpp"
#include "checkers/map_validity.hpp"
#include "core/input_error.hpp"

namespace dartcheck::analysis {

namespace {

// The user's maps, built once per model that the fuzzed rules rewrite.
std::vector<Map> given_maps(const std::vector<std::string>& targets, const std::vector<Model>& models, const Catalog& catalog) {
  std::vector<Map> out;
  if (models.empty()) return out;  // a catalog without rules: nothing to fuzz
  for (const auto& t : targets) {
    const auto ext = std::filesystem::path(t).extension().string();
    if (ext == ".yaml" || ext == ".yml" || ext == ".jba") {
      out.push_back(resolve_map(t, models.front(), &catalog));  // the file names its model (a .jba its dimension)
      continue;
    }
    std::vector<std::string> why;
    std::size_t built = 0;
    for (const Model& m : models) {
      try {
        out.push_back(resolve_map(t, m, &catalog));
        ++built;
      } catch (const InputError& e) {
        why.push_back(fmt::format("{}: {}", m.name, e.what()));
      }
    }
    if (built == 0) throw UsageError(fmt::format("--maps {}: not built for any model of the rules ({})", t, fmt::join(why, "; ")));
    for (const auto& w : why) fmt::print(stderr, "note: --maps {} is not used for {}\n", t, w);
  }
  for (const Map& m : out) require_valid_map(m, fmt::format("--maps: a given {} of {} darts", m.model().name, m.size()), "fuzzing needs valid hosts");
  return out;
}

}  // namespace

FuzzTargets fuzz_targets(const Catalog& catalog, const std::string& rule, const std::vector<std::string>& maps) {
  FuzzTargets t;
  std::vector<Model> models;
  for (const auto& e : catalog.rules) {
    if (!rule.empty() && e.rule.name() != rule) continue;
    t.rules.push_back(&e);
    t.entries.push_back(&e);
    if (std::find(models.begin(), models.end(), e.rule.model()) == models.end()) models.push_back(e.rule.model());
  }
  for (const auto& s : catalog.maps)
    if (std::find(models.begin(), models.end(), s.model) != models.end()) t.seeds.push_back(build_source(s));
  for (auto& m : given_maps(maps, models, catalog)) t.seeds.push_back(std::move(m));
  return t;
}

}  // namespace dartcheck::analysis
