#include "analysis/counterexample_files.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "io/counterexample_file.hpp"
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
  CounterexampleFile file{rule,
                          catalog,
                          fields,
                          static_failures,
                          stem + ".host.yaml",
                          cx.host.size(),
                          cx.hooks,
                          cx.match,
                          cx.result ? stem + ".result.yaml" : "",
                          cx.broken(),
                          cx.unrepresentable,
                          cx.event_contradictions,
                          {},
                          cx.origin,
                          cx.minimal,
                          replay};
  for (const auto& v : cx.violations) file.violations.push_back({v.element, constraint_name(v), describe(v, fmt::format("dart {}", v.element))});
  write_file(stem + ".counterexample.yaml", counterexample_file_text(file));
  return replay;
}

}  // namespace dartcheck::analysis
