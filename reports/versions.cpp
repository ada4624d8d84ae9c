#include "reports/versions.hpp"

#include <fmt/format.h>
#include <graphviz/graphviz_version.h>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include "proofs/solver_types.hpp"
#include "querymodify/orientation.hpp"

namespace dartcheck::reports {

std::vector<std::pair<std::string, std::string>> library_versions() {
  return {
      {"Z3", proofs::solver_version()},
      {"Graphviz", PACKAGE_VERSION},
      {"GMP", querymodify::exact_arithmetic_version()},
      {"fmt", fmt::format("{}.{}.{}", FMT_VERSION / 10000, FMT_VERSION / 100 % 100, FMT_VERSION % 100)},
      {"nlohmann::json", fmt::format("{}.{}.{}", NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR, NLOHMANN_JSON_VERSION_PATCH)},
      {"pugixml", fmt::format("{}.{}", PUGIXML_VERSION / 1000, PUGIXML_VERSION / 10 % 100)},
      {"yaml-cpp", DARTCHECK_YAML_CPP_VERSION},
  };
}

std::string dartcheck_version() { return DARTCHECK_VERSION; }

}  // namespace dartcheck::reports
