#include "analysis/counterexample_files.hpp"

#include <filesystem>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "io/map_io.hpp"

namespace dartcheck::analysis {

std::string file_stem(const std::string& name) {
  std::string s = name;
  for (char& c : s)
    if (c == '/' || c == '\\' || c == ' ') c = '.';
  return s;
}

namespace {

std::string replay_command(ReplayCommand what, const std::string& catalog, const std::string& rule, const std::string& host,
                           const std::vector<Dart>& hooks) {
  std::string cmd = fmt::format("dartcheck {} {} --rule {} --map {}", what == ReplayCommand::apply ? "apply" : "events", catalog, rule, host);
  for (Dart h : hooks) cmd += fmt::format(" --hook {}", h);
  if (what == ReplayCommand::events) cmd += " --dynamic";
  return cmd;
}

}  // namespace

std::string write_counterexample(const std::string& dir, const std::string& stem_name, const std::string& catalog, const std::string& rule,
                                 const std::vector<std::pair<std::string, std::string>>& fields, const std::vector<std::string>& static_failures,
                                 const Counterexample& cx, ReplayCommand what) {
  ensure_directory(dir);
  const std::string stem = (std::filesystem::path(dir) / stem_name).string();
  write_file(stem + ".host.yaml", map_to_yaml(cx.host));
  if (cx.result) write_file(stem + ".result.yaml", map_to_yaml(*cx.result));
  const std::string replay = replay_command(what, catalog, rule, stem + ".host.yaml", cx.hooks);
  YAML::Emitter y;
  y << YAML::BeginMap;
  y << YAML::Key << "rule" << YAML::Value << rule;
  y << YAML::Key << "catalog" << YAML::Value << catalog;
  for (const auto& [k, v] : fields) y << YAML::Key << k << YAML::Value << v;
  y << YAML::Key << "static_failures" << YAML::Value << YAML::Flow << static_failures;
  y << YAML::Key << "host" << YAML::Value << stem + ".host.yaml";
  y << YAML::Key << "host_darts" << YAML::Value << cx.host.size();
  y << YAML::Key << "hooks" << YAML::Value << YAML::Flow << cx.hooks;
  if (!cx.match.empty()) {
    y << YAML::Key << "match" << YAML::Value << YAML::Flow << YAML::BeginMap;
    for (const auto& [node, dart] : cx.match) y << YAML::Key << node << YAML::Value << dart;
    y << YAML::EndMap;
  }
  if (cx.result) y << YAML::Key << "result" << YAML::Value << stem + ".result.yaml";
  y << YAML::Key << "broken" << YAML::Value << YAML::Flow << cx.broken();
  if (!cx.unrepresentable.empty()) y << YAML::Key << "not_representable" << YAML::Value << cx.unrepresentable;
  if (!cx.event_contradictions.empty()) y << YAML::Key << "event_contradictions" << YAML::Value << cx.event_contradictions;
  y << YAML::Key << "violations" << YAML::Value << YAML::BeginSeq;
  for (const auto& v : cx.violations) {
    y << YAML::Flow << YAML::BeginMap << YAML::Key << "dart" << YAML::Value << v.element << YAML::Key << "constraint" << YAML::Value
      << constraint_name(v) << YAML::Key << "what" << YAML::Value << describe(v, fmt::format("dart {}", v.element)) << YAML::EndMap;
  }
  y << YAML::EndSeq;
  y << YAML::Key << "origin" << YAML::Value << cx.origin;
  y << YAML::Key << "minimal" << YAML::Value << cx.minimal;
  y << YAML::Key << "replay" << YAML::Value << replay;
  y << YAML::EndMap;
  write_file(stem + ".counterexample.yaml", std::string(y.c_str()) + "\n");
  return replay;
}

}  // namespace dartcheck::analysis
