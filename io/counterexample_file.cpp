#include "io/counterexample_file.hpp"

#include <yaml-cpp/yaml.h>

namespace dartcheck {

std::string counterexample_file_text(const CounterexampleFile& f) {
  YAML::Emitter y;
  y << YAML::BeginMap;
  y << YAML::Key << "rule" << YAML::Value << f.rule;
  y << YAML::Key << "catalog" << YAML::Value << f.catalog;
  for (const auto& [k, v] : f.fields) y << YAML::Key << k << YAML::Value << v;
  y << YAML::Key << "static_failures" << YAML::Value << YAML::Flow << f.static_failures;
  y << YAML::Key << "host" << YAML::Value << f.host;
  y << YAML::Key << "host_darts" << YAML::Value << f.host_darts;
  y << YAML::Key << "hooks" << YAML::Value << YAML::Flow << f.hooks;
  if (!f.match.empty()) {
    y << YAML::Key << "match" << YAML::Value << YAML::Flow << YAML::BeginMap;
    for (const auto& [node, dart] : f.match) y << YAML::Key << node << YAML::Value << dart;
    y << YAML::EndMap;
  }
  if (!f.result.empty()) y << YAML::Key << "result" << YAML::Value << f.result;
  y << YAML::Key << "broken" << YAML::Value << YAML::Flow << f.broken;
  if (!f.not_representable.empty()) y << YAML::Key << "not_representable" << YAML::Value << f.not_representable;
  if (!f.event_contradictions.empty()) y << YAML::Key << "event_contradictions" << YAML::Value << f.event_contradictions;
  y << YAML::Key << "violations" << YAML::Value << YAML::BeginSeq;
  for (const auto& v : f.violations)
    y << YAML::Flow << YAML::BeginMap << YAML::Key << "dart" << YAML::Value << v.dart << YAML::Key << "constraint" << YAML::Value << v.constraint
      << YAML::Key << "what" << YAML::Value << v.what << YAML::EndMap;
  y << YAML::EndSeq;
  y << YAML::Key << "origin" << YAML::Value << f.origin;
  y << YAML::Key << "minimal" << YAML::Value << f.minimal;
  y << YAML::Key << "replay" << YAML::Value << f.replay;
  y << YAML::EndMap;
  return std::string(y.c_str()) + "\n";
}

}  // namespace dartcheck
